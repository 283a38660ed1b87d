"""EN 1998-1:2004 elastic response spectra, section 3.2.2: control points.

Horizontal (eqs. 3.2-3.5, Tables 3.2/3.3) and vertical (eqs. 3.8-3.11,
Table 3.4), with the damping correction eta = sqrt(10 / (5 + xi)) >= 0.55.
"""

import math

import pytest

from freestand.core.spectra import (
    EN1998_HORIZONTAL,
    en1998_acceleration,
    en1998_damping_correction,
    en1998_spectrum,
)
from freestand.errors import FreestandError
from freestand.io.spectrum_file import parse_spectrum_option

G = 9.81


@pytest.mark.parametrize("spectrum_type", [1, 2])
@pytest.mark.parametrize("ground", ["A", "B", "C", "D", "E"])
def test_horizontal_control_points(spectrum_type, ground):
    ag = 0.25 * G
    s, tb, tc, td = EN1998_HORIZONTAL[spectrum_type][ground]
    spec = en1998_spectrum(ag, ground, spectrum_type, 0.05)
    # exact formulas; tolerance: log-log interpolation between 400 points
    # does not enter at the corners, which are tabulated exactly
    assert spec.acceleration_at(1 / tb) == pytest.approx(2.5 * ag * s, rel=1e-12)
    assert spec.acceleration_at(1 / tc) == pytest.approx(2.5 * ag * s, rel=1e-12)
    assert spec.acceleration_at(1 / td) == pytest.approx(2.5 * ag * s * tc / td, rel=1e-12)
    assert en1998_acceleration(0.0, ag, ground, spectrum_type) == pytest.approx(ag * s)
    assert en1998_acceleration(2 * td, ag, ground, spectrum_type) == pytest.approx(
        2.5 * ag * s * tc * td / (2 * td) ** 2
    )
    t = 0.5 * tb
    assert en1998_acceleration(t, ag, ground, spectrum_type) == pytest.approx(
        ag * s * (1 + 0.5 * 1.5)
    )


@pytest.mark.parametrize(("spectrum_type", "ratio"), [(1, 0.90), (2, 0.45)])
def test_vertical_control_points(spectrum_type, ratio):
    ag = 0.3 * G
    avg = ratio * ag
    assert en1998_acceleration(0.1, ag, spectrum_type=spectrum_type, direction="vertical") == (
        pytest.approx(3.0 * avg)
    )
    assert en1998_acceleration(0.0, ag, spectrum_type=spectrum_type, direction="vertical") == (
        pytest.approx(avg)
    )
    assert en1998_acceleration(2.0, ag, spectrum_type=spectrum_type, direction="vertical") == (
        pytest.approx(3.0 * avg * 0.15 * 1.0 / 4.0)
    )


def test_damping_correction_and_importance():
    assert en1998_damping_correction(0.05) == 1.0
    assert en1998_damping_correction(0.10) == pytest.approx(math.sqrt(10 / 15))
    assert en1998_damping_correction(0.30) == 0.55  # lower bound
    plateau = en1998_acceleration(0.3, G, "A", 1, 0.10, importance=1.4)
    assert plateau == pytest.approx(2.5 * 1.4 * G * math.sqrt(10 / 15))


def test_option_string():
    s = parse_spectrum_option("en1998:type=1,ground=B,ag=0.25g,damping=5%")
    assert s.acceleration_at(2.5) == pytest.approx(2.5 * 1.2 * 0.25 * G)
    with pytest.raises(FreestandError, match="ground"):
        parse_spectrum_option("en1998:type=1,ground=F,ag=0.25g")
    with pytest.raises(FreestandError, match="type"):
        parse_spectrum_option("en1998:type=3,ground=B,ag=0.25g")
