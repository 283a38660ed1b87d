"""The search for the lowest overturning amplitude of a pulse, for any simulator (numba).

Overturning is not monotone in the amplitude of a pulse (Zhang and Makris
2001; Makris and Roussos 2000): a block can overturn after an impact at
amplitudes below those at which it overturns without one, and stronger
pulses can leave it standing. The search therefore marches up in amplitude
from a level at which nothing rocks, refines every local maximum of the
overturning margin by golden-section search (a narrow overturning band
between two grid points), and bisects back to the first overturning
amplitude.

The simulator is a compiled function ``outcome(context, amplitude) ->
(overturned, margin)``: the planar rocking block
(:mod:`freestand.core.rocking.integrator`) and the 3-D body
(:mod:`freestand.core.rocking.body_overturning`) pass their own, with their
parameters in ``context`` (a tuple). ``margin`` is a smooth measure of how
close the pulse came to overturning (the energy left after it over the
energy barrier, >= 1 when it overturns); only its local maxima matter.

The three functions are inlined into their caller (``inline="always"``): the
simulator then stays a compile-time constant there, called directly, and the
caller can be cached (numba does not cache a function that passes a compiled
function on as a run-time value).
"""

from __future__ import annotations

import math

import numba as nb

#: A local maximum of the margin below this is not refined (it is far from overturning).
REFINE_MARGIN = 0.2


@nb.njit(cache=True, inline="always")
def bisect_amplitude(outcome, context, lo, hi, rel_tol):
    """Bisect between a safe amplitude ``lo`` and an overturning one ``hi`` [m/s^2]."""
    for _ in range(200):
        if hi - lo <= rel_tol * hi:
            break
        mid = 0.5 * (lo + hi)
        ov, _m = outcome(context, mid)
        if ov:
            hi = mid
        else:
            lo = mid
    return hi


@nb.njit(cache=True, inline="always")
def _golden_hit(outcome, context, x0, x3):
    """An overturning amplitude in (x0, x3) near the margin's maximum, or -1 if none is found.

    Golden-section search of the margin's maximum, stopped at the first
    amplitude that overturns (at most 40 reductions, or a bracket of 1e-9).
    """
    gr = 0.5 * (math.sqrt(5.0) - 1.0)
    x1 = x3 - gr * (x3 - x0)
    x2 = x0 + gr * (x3 - x0)
    o1, f1 = outcome(context, x1)
    o2, f2 = outcome(context, x2)
    hit = -1.0
    if o1:
        hit = x1
    elif o2:
        hit = x2
    it = 0
    while hit < 0.0 and it < 40 and (x3 - x0) > 1e-9 * x3:
        if f1 >= f2:
            x3 = x2
            x2 = x1
            f2 = f1
            x1 = x3 - gr * (x3 - x0)
            o1, f1 = outcome(context, x1)
            if o1:
                hit = x1
        else:
            x0 = x1
            x1 = x2
            f1 = f2
            x2 = x0 + gr * (x3 - x0)
            o2, f2 = outcome(context, x2)
            if o2:
                hit = x2
        it += 1
    return hit


@nb.njit(cache=True, inline="always")
def lowest_overturning_amplitude(outcome, context, a_lo, a_hi, ratio, rel_tol):
    """Lowest amplitude [m/s^2] for which ``outcome(context, amplitude)`` overturns.

    March up in amplitude by ``ratio`` from ``a_lo`` (no rocking); at the
    first overturning amplitude bisect back to ``rel_tol``. Between grid
    points, a local maximum of the margin above ``REFINE_MARGIN`` is refined
    by golden-section search so that a narrow overturning band below the
    first grid crossing is not missed. Returns (amplitude, status): status 0
    found, 1 none up to ``a_hi`` (amplitude inf).
    """
    a_pp = a_lo
    m_pp = -1.0
    a_p = a_lo
    _ov, m_p = outcome(context, a_lo)
    a = a_lo * ratio
    while a <= a_hi * ratio:
        ov, m = outcome(context, a)
        # a local maximum of the margin at the previous grid point
        if m_p > REFINE_MARGIN and m_p > m_pp and m_p >= m:
            hit = _golden_hit(outcome, context, a_pp, a)
            if hit > 0.0:
                return bisect_amplitude(outcome, context, a_pp, hit, rel_tol), 0
        if ov:
            return bisect_amplitude(outcome, context, a_p, a, rel_tol), 0
        a_pp = a_p
        m_pp = m_p
        a_p = a
        m_p = m
        a = a * ratio
    return math.inf, 1
