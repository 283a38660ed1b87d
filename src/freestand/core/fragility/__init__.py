"""Fragility campaigns: probability of each outcome against ground-motion intensity.

See :mod:`freestand.core.fragility.fit` (lognormal fits),
:mod:`freestand.core.fragility.intensity` (intensity measures),
:mod:`freestand.core.fragility.outcomes` (damage states) and
:mod:`freestand.core.fragility.campaign` (the simulations).
"""
