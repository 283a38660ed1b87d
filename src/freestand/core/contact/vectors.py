"""Small vector helpers of the compiled contact kernels.

glibc's ``hypot`` guards against overflow and underflow at several times the
cost of a square root, and a sliding base called it at every solve (8 % of a
sliding cask's time). The kernels' lengths (forces, velocities, offsets in SI
units) lie far from both limits, so :func:`norm2` takes the square root.
"""

from __future__ import annotations

import math

import numba as nb


@nb.njit(cache=True, inline="always", error_model="numpy", _nrt=False)
def norm2(a: float, b: float) -> float:
    """sqrt(a^2 + b^2), the length of the 2-vector (a, b)."""
    return math.sqrt(a * a + b * b)


@nb.njit(cache=True, inline="always", error_model="numpy", _nrt=False)
def leading_length(vector, count: int) -> float:
    """The length of the first ``count`` components of ``vector``."""
    size = 0.0
    for k in range(count):
        size += vector[k] ** 2
    return math.sqrt(size)
