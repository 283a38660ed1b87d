"""What happens at an instant: the contact problem of a stack, screening from rest."""
