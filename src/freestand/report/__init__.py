"""Reports built from solver results."""
