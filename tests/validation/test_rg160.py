"""US NRC Regulatory Guide 1.60 design response spectra: control points.

RG 1.60 (Rev. 2), Tables 1 (horizontal) and 2 (vertical): amplification of the
PGA at A = 33 Hz, B = 9 Hz, C = 2.5 Hz (horizontal) / 3.5 Hz (vertical), and
of the 36 in displacement per 1 g at D = 0.25 Hz.
"""

import math

import numpy as np
import pytest

from freestand.core.spectra import RG160_FACTORS, rg160_spectrum
from freestand.errors import FreestandError
from freestand.io.spectrum_file import parse_spectrum_option, parse_spectrum_sections

G = 9.81
CONTROL = {"horizontal": (33.0, 9.0, 2.5, 0.25), "vertical": (33.0, 9.0, 3.5, 0.25)}


@pytest.mark.parametrize("direction", ["horizontal", "vertical"])
@pytest.mark.parametrize("damping_percent", [0.5, 2.0, 5.0, 7.0, 10.0])
def test_control_points(direction, damping_percent):
    pga = 0.3 * G
    s = rg160_spectrum(pga, damping_percent / 100, direction)
    fa, fb, fc, fd = CONTROL[direction]
    a, b, c, d = RG160_FACTORS[direction][damping_percent]
    # exact at the tabulated control points (floating point only)
    assert s.acceleration_at(fa) == pytest.approx(a * pga, rel=1e-12)
    assert s.acceleration_at(fb) == pytest.approx(b * pga, rel=1e-12)
    assert s.acceleration_at(fc) == pytest.approx(c * pga, rel=1e-12)
    disp = d * 36 * 0.0254 * pga / G
    assert s.acceleration_at(fd) == pytest.approx((2 * math.pi * fd) ** 2 * disp, rel=1e-12)
    # equal to the PGA above 33 Hz, constant displacement below 0.25 Hz
    assert s.acceleration_at(60.0) == pytest.approx(pga, rel=1e-12)
    f = 0.15
    assert s.acceleration_at(f) / (2 * math.pi * f) ** 2 == pytest.approx(disp, rel=1e-12)
    # straight line on log-log axes between B and C
    fm = math.sqrt(fb * fc)
    assert s.acceleration_at(fm) == pytest.approx(math.sqrt(b * c) * pga, rel=1e-12)


def test_published_5_percent_values():
    # the 5 % horizontal factors 2.61 (B) and 3.13 (C), the vertical 2.98 (C)
    h = rg160_spectrum(G, 0.05, "horizontal")
    v = rg160_spectrum(G, 0.05, "vertical")
    assert h.acceleration_at(9.0) / G == pytest.approx(2.61)
    assert h.acceleration_at(2.5) / G == pytest.approx(3.13)
    assert v.acceleration_at(3.5) / G == pytest.approx(2.98)


def test_linear_in_pga():
    a = rg160_spectrum(0.1 * G, 0.02)
    b = rg160_spectrum(0.3 * G, 0.02)
    f = np.geomspace(0.1, 100, 50)
    np.testing.assert_allclose(b.acceleration_at(f), 3 * a.acceleration_at(f), rtol=1e-12)


def test_untabulated_damping_is_rejected():
    with pytest.raises(ValueError, match="tabulates"):
        rg160_spectrum(G, 0.03)
    with pytest.raises(FreestandError, match=r"3 % damping.*0.5 %, 2 %, 5 %, 7 %, 10 %"):
        parse_spectrum_option("rg1.60:pga=0.3g,damping=3%")
    with pytest.raises(FreestandError) as err:
        parse_spectrum_sections(
            [{"name": "s", "kind": "rg1.60", "pga": "0.3 g", "damping": 0.04}],
            source="model.toml", base_dir=".", gravity=G,
        )  # fmt: skip
    assert err.value.field == "spectrum[0].damping"


def test_option_and_section_give_the_same_spectrum():
    a = parse_spectrum_option("rg1.60:pga=0.3g,damping=5%,direction=vertical")
    section = {"name": "v", "kind": "rg1.60", "pga": "0.3 g", "damping": "5 %"}
    section["direction"] = "vertical"
    b = parse_spectrum_sections([section], source="m.toml", base_dir=".", gravity=G)["v"]
    np.testing.assert_array_equal(a.acceleration, b.acceleration)
    assert a.direction == "vertical" and a.damping == 0.05
