"""The direction of a slip's kinetic friction, with its pull towards a stored direction.

The 3-D kernel's kinetic friction acts against u, the slip velocity's own
direction while the slip is fast enough and on the stored direction's side;
a slip that has turned against the stored direction r, or is slower than a
floor, is pulled towards r (``body_solve.slip_direction`` gives the why).
u is the direction of ``s + beta(s) r`` with one pull law,
:func:`slip_pull`, for every patch (a point's, an edge's and a face's
slip, and a sliding face's model of its friction centre,
``face_friction``).
"""

from __future__ import annotations

import math

import numba as nb

#: [m/s] below which a slip velocity has no direction of its own: a slip this slow keeps the
#: direction it started with (or had at its step's start). Above the residue (some 1e-11
#: m/s) that the drift projection leaves in the rows of a slip starting from rest, and above
#: the micro-slips of an edge at its friction limit, whose direction swings within
#: microseconds (the friction's direction moves the centre of pressure along the edge, and
#: with it the slip velocity there); 1e-9 m/s let them turn it.
SLIP_FLOOR = 1e-6


@nb.njit(cache=True, inline="always", error_model="numpy", _nrt=False)
def slip_pull(along: float, size: float, floor: float) -> float:
    """beta(s) = |s . r| - s . r + max(floor - |s|, 0) [m/s]: the pull towards r.

    ``along`` = s . r, ``size`` = |s|. Zero while the slip points on r's side
    (s . r > 0) faster than ``floor``: u is then s's own direction. Past r's
    side the component along r is reflected; below the floor, u is pulled to
    r (u = r at s = 0).
    """
    return abs(along) - along + max(floor - size, 0.0)


@nb.njit(cache=True, inline="always", error_model="numpy", _nrt=False)
def pulled_unit(svel, n_tangent, reference, start, floor, direction):
    """u = w / |w|, ``w = s + beta(s) r``, into ``direction``; False where beta > 0.

    s: ``svel[:n_tangent]`` [m/s]; r: ``reference[start:start + n_tangent]``
    (unit); ``floor`` [m/s] of :func:`slip_pull`. r itself where w vanishes.
    """
    size = 0.0
    along = 0.0
    for k in range(n_tangent):
        size += svel[k] ** 2
        along += svel[k] * reference[start + k]
    size = math.sqrt(size)
    if size > floor and along > 0.0:
        for k in range(n_tangent):
            direction[k] = svel[k] / size
        return True
    extra = slip_pull(along, size, floor)
    length = 0.0
    for k in range(n_tangent):
        direction[k] = svel[k] + extra * reference[start + k]
        length += direction[k] ** 2
    length = math.sqrt(length)
    for k in range(n_tangent):
        direction[k] = direction[k] / length if length > 0.0 else reference[start + k]
    return False
