"""Fragility campaigns: probability of each outcome against ground-motion intensity.

See :mod:`freestand.core.sweeps.fragility.fit` (lognormal fits),
:mod:`freestand.core.sweeps.fragility.intensity` (intensity measures),
:mod:`freestand.core.sweeps.fragility.outcomes` (damage states) and
:mod:`freestand.core.sweeps.fragility.campaign` (the simulations).
"""
