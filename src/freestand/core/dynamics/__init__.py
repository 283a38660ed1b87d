"""What happens over time: stack time histories and single-block fast paths."""
