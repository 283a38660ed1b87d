"""How the support itself vibrates: the bridge beam with its parked cart."""
