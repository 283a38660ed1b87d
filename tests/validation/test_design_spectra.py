"""Design spectra reproduce their control points.

Sources: US NRC Regulatory Guide 1.60 (Rev. 1, 1973), Tables I and II and
Figs. 1-2 (factors restated in shared/spec/references.md); EN 1998-1:2004
section 3.2.2.2 (eqs. 3.2-3.6, Tables 3.2-3.3) and 3.2.2.3 (eqs. 3.8-3.11,
Table 3.4). Tolerance 1e-9 relative: the spectra are defined by these
numbers exactly.
"""

from __future__ import annotations

import math

import pytest

from freestand.core.motion.design_spectra import (
    RG160_FACTORS,
    crane_stand_in_spectra,
    en1998_damping_correction,
    en1998_spectrum,
    rg160_spectrum,
)

G = 9.81
EXACT = 1e-9  # relative; the spectra are defined by their control points


@pytest.mark.parametrize("direction", ["horizontal", "vertical"])
@pytest.mark.parametrize("damping", [0.005, 0.02, 0.05, 0.07, 0.10])
def test_rg160_control_points(direction, damping):
    pga = 0.3 * G
    spectrum = rg160_spectrum(pga, damping, direction, G)
    a, b, c, d = RG160_FACTORS[direction][round(damping * 100, 6)]
    f_c = 2.5 if direction == "horizontal" else 3.5
    assert spectrum.acceleration_at(33.0) == pytest.approx(a * pga, rel=EXACT)
    assert spectrum.acceleration_at(9.0) == pytest.approx(b * pga, rel=EXACT)
    assert spectrum.acceleration_at(f_c) == pytest.approx(c * pga, rel=EXACT)
    # D: spectral displacement d x 36 in per g of PGA, S_a = (2 pi f)^2 S_d.
    displacement = d * 36 * 0.0254 * pga / G
    assert spectrum.acceleration_at(0.25) == pytest.approx(
        (2 * math.pi * 0.25) ** 2 * displacement, rel=EXACT
    )
    # Constant displacement below D, the PGA above A.
    assert spectrum.acceleration_at(0.1) == pytest.approx(
        (2 * math.pi * 0.1) ** 2 * displacement, rel=1e-6
    )
    assert spectrum.acceleration_at(50.0) == pytest.approx(pga, rel=EXACT)


def test_rg160_is_linear_in_pga():
    assert rg160_spectrum(2 * G).acceleration_at(5.0) == pytest.approx(
        2 * rg160_spectrum(G).acceleration_at(5.0)
    )


def test_rg160_rejects_untabulated_damping():
    with pytest.raises(ValueError, match="tabulates damping"):
        rg160_spectrum(G, 0.03)


@pytest.mark.parametrize("spectrum_type", [1, 2])
@pytest.mark.parametrize("ground", list("ABCDE"))
def test_en1998_horizontal_corners(spectrum_type, ground):
    from freestand.core.motion.design_spectra import EN1998_HORIZONTAL

    ag = 2.5
    soil, t_b, t_c, t_d = EN1998_HORIZONTAL[spectrum_type][ground]
    spectrum = en1998_spectrum(ag, ground, spectrum_type, 0.05)
    plateau = 2.5 * ag * soil  # eta = 1 at 5 %
    assert spectrum.acceleration_at(1 / t_b) == pytest.approx(plateau, rel=EXACT)
    assert spectrum.acceleration_at(1 / t_c) == pytest.approx(plateau, rel=EXACT)
    assert spectrum.acceleration_at(1 / t_d) == pytest.approx(plateau * t_c / t_d, rel=EXACT)
    # T -> 0: a_g S (eq. 3.2); at 100 Hz the ramp has barely started.
    t = 0.01
    assert spectrum.acceleration_at(100.0) == pytest.approx(
        ag * soil * (1 + t / t_b * 1.5), rel=EXACT
    )


@pytest.mark.parametrize(("spectrum_type", "ratio"), [(1, 0.90), (2, 0.45)])
def test_en1998_vertical_plateau(spectrum_type, ratio):
    spectrum = en1998_spectrum(2.0, spectrum_type=spectrum_type, direction="vertical", damping=0.05)
    assert spectrum.acceleration_at(1 / 0.10) == pytest.approx(3.0 * ratio * 2.0, rel=EXACT)
    assert spectrum.acceleration_at(1 / 1.0) == pytest.approx(3.0 * ratio * 2.0 * 0.15, rel=EXACT)


def test_en1998_damping_correction():
    assert en1998_damping_correction(0.05) == pytest.approx(1.0)
    assert en1998_damping_correction(0.02) == pytest.approx(math.sqrt(10 / 7))
    assert en1998_damping_correction(0.50) == 0.55  # lower bound of eq. 3.6


def test_crane_stand_in_is_anchored_to_the_paper_values(crane_model):
    horizontal, vertical = crane_stand_in_spectra()
    assert horizontal.acceleration_at(2.5) == pytest.approx(10.31, rel=1e-9)  # paper section 4
    assert horizontal.acceleration_at(50.0) == pytest.approx(2.70, rel=1e-9)
    assert vertical.acceleration_at(50.0) == pytest.approx(2.35, rel=1e-9)
    assert vertical.acceleration_at(8.0) == pytest.approx(G) and vertical.acceleration_at(
        12.0
    ) == pytest.approx(G)
    # The example file carries the same stand-in, inline (to 4 decimals).
    for builtin, shipped in (
        (horizontal, "horizontal (stand-in)"),
        (vertical, "vertical (stand-in)"),
    ):
        spectrum = crane_model.spectra[shipped]
        assert spectrum.direction == builtin.direction
        for f in (0.1, 0.25, 1.0, 2.5, 9.0, 20.0, 33.0):
            assert spectrum.acceleration_at(f) == pytest.approx(
                builtin.acceleration_at(f), rel=1e-3
            )


def test_shipped_stand_in_csv_files_match_the_builder():
    from pathlib import Path

    from freestand.io.spectrum_input import read_spectrum_csv

    folder = Path(__file__).resolve().parents[2] / "src" / "freestand" / "examples"
    for builtin, name in zip(crane_stand_in_spectra(), ("horizontal", "vertical"), strict=True):
        shipped = read_spectrum_csv(folder / f"crane-spectrum-{name}.csv", direction=name)
        for f in (0.1, 0.25, 1.0, 2.5, 9.0, 20.0, 33.0):
            assert shipped.acceleration_at(f) == pytest.approx(builtin.acceleration_at(f), rel=1e-5)
