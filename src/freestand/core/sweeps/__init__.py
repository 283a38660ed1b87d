"""How likely, over many cases: mode maps, Monte Carlo and fragility campaigns."""
