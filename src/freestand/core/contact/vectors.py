"""Small vector helpers of the compiled contact kernels.

glibc's ``hypot`` guards against overflow and underflow at several times the
cost of a square root, and a sliding base called it at every solve (8 % of a
sliding cask's time). The kernels' lengths (forces, velocities, offsets in SI
units) lie far from both limits, so :func:`norm2` takes the square root.
Likewise ``sincos`` reduces its argument for any angle; a rocking box's turn
in one step is small, and :func:`cos_sin` sums its Taylor series there.
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


#: largest |x| [rad] at which :func:`cos_sin` sums the series (the first term left out,
#: x^14 / 14! and x^15 / 15!, below 1e-25 of the result there)
SERIES_ANGLE = 0.1
#: the series' coefficients (-1)^k / (2k + 1)! and (-1)^k / (2k)!, k = 1..6
_SIN = tuple((-1.0) ** k / math.factorial(2 * k + 1) for k in range(1, 7))
_COS = tuple((-1.0) ** k / math.factorial(2 * k) for k in range(1, 7))


@nb.njit(cache=True, inline="always", error_model="numpy", _nrt=False)
def cos_sin(x: float) -> tuple[float, float]:
    """(cos x, sin x) of an angle x [rad]; for |x| <= ``SERIES_ANGLE`` their Taylor series.

    ``sin x = x + x z (s_1 + z (s_2 + ... + z s_6))`` and ``cos x = 1 + z (c_1 + ...
    + z c_6)``, z = x^2, by Horner's rule: within a unit in the last place of the
    libm values; otherwise libm's.
    """
    if not abs(x) <= SERIES_ANGLE:
        return math.cos(x), math.sin(x)
    s1, s2, s3, s4, s5, s6 = _SIN
    c1, c2, c3, c4, c5, c6 = _COS
    z = x * x
    sine = x + x * z * (s1 + z * (s2 + z * (s3 + z * (s4 + z * (s5 + z * s6)))))
    cosine = 1.0 + z * (c1 + z * (c2 + z * (c3 + z * (c4 + z * (c5 + z * c6)))))
    return cosine, sine
