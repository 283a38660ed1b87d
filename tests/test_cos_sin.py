"""The kernels' small-angle cosine and sine agree with libm's to a unit in the last place.

:func:`freestand.core.contact.vectors.cos_sin` sums the Taylor series of cos
and sin to x^12 and x^13 for |x| <= ``SERIES_ANGLE`` (0.1 rad; a rocking
box's turn in one step of its hinge), and calls libm beyond: the terms left
out are below 1e-25 of the result (Abramowitz and Stegun 1964, 4.3.65-66),
so the sums carry the round-off of Horner's rule alone.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from freestand.core.contact.vectors import SERIES_ANGLE, cos_sin

ULP = 1.0  # units in the last place of libm's value (itself within 1 ulp of the truth)


def _ulps(value: float, reference: float) -> float:
    return abs(value - reference) / np.spacing(max(abs(reference), 1e-300))


@given(st.floats(-SERIES_ANGLE, SERIES_ANGLE, allow_subnormal=False))
def test_the_series_is_libms_cosine_and_sine_within_an_ulp(x: float) -> None:
    cosine, sine = cos_sin(x)
    assert _ulps(cosine, math.cos(x)) <= ULP
    assert _ulps(sine, math.sin(x)) <= ULP


@given(st.floats(-100.0, 100.0))
def test_beyond_the_series_it_is_libms(x: float) -> None:
    if abs(x) > SERIES_ANGLE:
        assert cos_sin(x) == (math.cos(x), math.sin(x))


def test_the_series_is_exact_at_zero_and_odd() -> None:
    assert cos_sin(0.0) == (1.0, 0.0)
    for x in np.linspace(1e-6, SERIES_ANGLE, 101):
        c_plus, s_plus = cos_sin(float(x))
        c_minus, s_minus = cos_sin(float(-x))
        assert c_plus == c_minus and s_plus == -s_minus
