"""When a rocking block falls: rocking properties, its integrator, overturning limits."""
