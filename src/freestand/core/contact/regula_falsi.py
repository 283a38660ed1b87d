"""The end-value scaling of Anderson and Bjorck's regula falsi, for the compiled root searches.

Regula falsi keeps a bracket [a, b] of a sign change of f and tries the
secant root of its ends. Where the same end is kept twice in a row, plain
regula falsi creeps; Illinois halves the kept end's value, Anderson and
Bjorck (BIT 12, 1972, 503-508) scale it by ``m = 1 - f(c) / f(b)`` (c the
new point, b the end it replaces), or by 1/2 where m is not positive. The
3-D engine's event location (on RK4 states and on the step's interpolant,
:func:`narrowed`) and a point's slip-onset angle use it.
"""

from __future__ import annotations

import math

import numba as nb


@nb.njit(cache=True, inline="always", error_model="numpy", _nrt=False)
def retained_scale(f_new: float, f_old: float) -> float:
    """Factor on the kept end's value: ``1 - f_new / f_old``, 1/2 where that is not positive.

    ``f_new`` is the value at the new point, ``f_old`` the value at the end
    it replaces (same sign); 1/2 also where ``f_old`` is zero or not finite.
    """
    scale = 1.0 - f_new / f_old if f_old != 0.0 and math.isfinite(f_old) else 0.5
    return scale if scale > 0.0 else 0.5


@nb.njit(cache=True, inline="always", error_model="numpy", _nrt=False)
def narrowed(past, middle, g, low, high, g_low, g_high, side):
    """The bracket after a trial at ``middle`` of value ``g``: (low, high, g_low, g_high, side).

    ``past``: the trial lies past the root (it becomes the high end, else the
    low one). The end kept a second time in a row (``side``: -1 where the
    high end moved last, 1 the low one, 0 neither) has its value scaled by
    :func:`retained_scale`.
    """
    if past:
        if side == -1:
            g_low *= retained_scale(g, g_high)
        return low, middle, g_low, g, -1
    if side == 1:
        g_high *= retained_scale(g, g_low)
    return middle, high, g, g_high, 1
