"""Vertical frequency of a simply supported beam carrying a point mass (paper section 6)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from freestand.core.motion.spectra import Spectrum
from freestand.core.structure.beam import (
    SimplySupportedBeam,
    bare_beam_frequency,
    dunkerley_frequency,
    exact_frequency,
    finite_element_frequency,
    frequency_sweep,
    jump_check,
    spring_mass_frequency,
    static_flexibility,
)
from freestand.errors import FreestandError

CRANE = SimplySupportedBeam(9.8, 2.1e11, 0.014, 16600.0, 25600.0)
CRANE_WITH_INERTIA = SimplySupportedBeam(9.8, 2.1e11, 0.014, 16600.0, 25600.0, 124100.0, 2.83)


def closed_form_frequency(beam: SimplySupportedBeam, position: float) -> float:
    """Independent reference for J = 0: the classical frequency equation.

    With beta^4 = mu omega^2 / (E I), lambda = beta l, r = M / m, xi = a / l,
    eta = 1 - xi:  (r lambda / 2) [sin(lambda xi) sin(lambda eta) / sin(lambda)
    - sinh(lambda xi) sinh(lambda eta) / sinh(lambda)] = 1, first root in (0, pi).
    """
    r = beam.load_mass / beam.mass
    xi = position / beam.span
    eta = 1.0 - xi

    def equation(lam: float) -> float:
        trig = math.sin(lam * xi) * math.sin(lam * eta) / math.sin(lam)
        hyp = math.sinh(lam * xi) * math.sinh(lam * eta) / math.sinh(lam)
        return 0.5 * r * lam * (trig - hyp) - 1.0

    lam = brentq(equation, 1e-3, math.pi * (1 - 1e-12), xtol=1e-15, rtol=1e-15)
    return lam**2 * math.sqrt(beam.bending_stiffness / (beam.mass * beam.span**3)) / (2 * math.pi)


beams = st.builds(
    SimplySupportedBeam,
    span=st.floats(1.0, 50.0),
    youngs_modulus=st.floats(5e9, 3e11),
    second_moment=st.floats(1e-6, 1.0),
    mass=st.floats(1.0, 1e5),
    load_mass=st.floats(0.0, 1e5),
    load_rotary_inertia=st.one_of(st.just(0.0), st.floats(0.0, 1e6)),
    load_height=st.one_of(st.just(0.0), st.floats(-3.0, 3.0)),
)
fractions = st.floats(0.0, 1.0)


@pytest.mark.parametrize("xi", [0.03, 0.1, 0.2, 0.3, 0.4137, 0.5, 0.77, 0.95])
@pytest.mark.parametrize("ratio", [0.05, 0.7, 1.54, 10.0, 60.0])
def test_exact_matches_the_closed_form_equation(xi, ratio):
    beam = SimplySupportedBeam(12.3, 2.0e11, 0.02, 10000.0, 10000.0 * ratio)
    reference = closed_form_frequency(beam, xi * beam.span)
    assert exact_frequency(beam, xi * beam.span) == pytest.approx(reference, rel=1e-10)


def test_zero_load_mass_gives_the_bare_beam():
    beam = SimplySupportedBeam(9.8, 2.1e11, 0.014, 16600.0, 0.0)
    positions = np.linspace(0.0, 9.8, 11)
    assert np.all(exact_frequency(beam, positions) == bare_beam_frequency(beam))
    assert np.all(dunkerley_frequency(beam, positions) == bare_beam_frequency(beam))


def test_cart_on_a_support_gives_the_bare_beam():
    bare = bare_beam_frequency(CRANE)
    for position in (0.0, 9.8, 1e-300, 1e-12, 9.8 - 1e-12):
        assert exact_frequency(CRANE, position) == pytest.approx(bare, rel=1e-13)
    # Close to a support the cart lowers the frequency by O(d^2).
    assert exact_frequency(CRANE, 1e-3) < bare
    assert exact_frequency(CRANE, 1e-3) == pytest.approx(bare, rel=1e-6)


def test_zero_beam_mass_gives_the_spring_mass_frequency():
    beam = SimplySupportedBeam(9.8, 2.1e11, 0.014, 0.0, 25600.0)
    positions = np.array([1e-6, 0.5, 1.33, 4.9, 7.0, 9.8 - 1e-6])
    expected = spring_mass_frequency(beam, positions)
    assert exact_frequency(beam, positions) == pytest.approx(expected, rel=1e-13)
    assert dunkerley_frequency(beam, positions) == pytest.approx(expected, rel=1e-13)
    assert exact_frequency(beam, 0.0) == math.inf


@pytest.mark.parametrize("beam_mass", [1e-12, 1e-6, 1e-3, 1.0])
def test_very_light_beam_tends_to_the_spring_mass_frequency(beam_mass):
    beam = SimplySupportedBeam(9.8, 2.1e11, 0.014, beam_mass, 25600.0)
    positions = np.array([0.01, 1.33, 4.9])
    spring = spring_mass_frequency(beam, positions)
    exact = exact_frequency(beam, positions)
    # Dunkerley <= exact <= spring-mass, and Dunkerley's relative distance from the
    # spring-mass value is (f_2 / f_1)^2 / 2 to first order: the exact value lies in
    # between (slack: rounding).
    gap = 0.5 * (spring / bare_beam_frequency(beam)) ** 2
    assert np.all(exact <= spring * (1 + 1e-14))
    assert np.all(exact >= dunkerley_frequency(beam, positions) * (1 - 1e-14))
    assert np.all(1 - exact / spring <= gap * 1.01 + 1e-14)
    if beam_mass <= 1e-6:
        assert exact == pytest.approx(spring, rel=1e-6)


def test_mid_span_rayleigh_estimate():
    # Textbook (Rayleigh, static deflection shape): M_eff = M + 17/35 m at mid-span;
    # within 0.5 % of the exact value for m / M = 0.65 (tolerance: Rayleigh's error).
    k = 48 * CRANE.bending_stiffness / CRANE.span**3
    rayleigh = math.sqrt(k / (CRANE.load_mass + 17 / 35 * CRANE.mass)) / (2 * math.pi)
    assert exact_frequency(CRANE, 4.9) == pytest.approx(rayleigh, rel=5e-3)
    assert exact_frequency(CRANE, 4.9) <= rayleigh


def test_finite_elements_converge_to_the_exact_value():
    for beam in (CRANE, CRANE_WITH_INERTIA):
        for position in (0.0, 0.05, 1.33, 3.1, 4.9):
            exact = exact_frequency(beam, position)
            errors = [
                finite_element_frequency(beam, position, elements=n) - exact for n in (4, 8, 16, 32)
            ]
            # FE stiffens: it approaches from above, and the error falls at least 8-fold
            # per halving of the mesh (Hermite cubics: about 16-fold) until it reaches
            # rounding level.
            assert all(e >= -1e-9 * exact for e in errors)
            for coarse, fine in zip(errors, errors[1:], strict=False):
                assert fine <= max(coarse / 8.0, 1e-9 * exact)
            assert finite_element_frequency(beam, position, elements=64) == pytest.approx(
                exact, rel=1e-7
            )


def test_finite_elements_with_a_massless_beam():
    beam = SimplySupportedBeam(9.8, 2.1e11, 0.014, 0.0, 25600.0)
    # The cubic interpolation is exact for static point loads: FE gives eq. 4 exactly.
    assert finite_element_frequency(beam, [1.33, 4.9], elements=8) == pytest.approx(
        spring_mass_frequency(beam, [1.33, 4.9]), rel=1e-9
    )


def test_rotary_inertia_lowers_the_frequency():
    positions = np.linspace(0.3, 9.5, 9)
    without = exact_frequency(CRANE, positions)
    with_inertia = exact_frequency(CRANE_WITH_INERTIA, positions)
    assert np.all(with_inertia <= without + 1e-12)
    # At mid-span the first mode has no slope: the rotary inertia does not act on it.
    assert exact_frequency(CRANE_WITH_INERTIA, 4.9) == pytest.approx(
        exact_frequency(CRANE, 4.9), rel=1e-12
    )
    assert CRANE_WITH_INERTIA.effective_rotary_inertia == pytest.approx(
        124100.0 + 25600.0 * 2.83**2
    )


def test_vectorised_and_symmetric():
    positions = np.linspace(0.0, 9.8, 21).reshape(3, 7)
    for function in (dunkerley_frequency, exact_frequency, spring_mass_frequency):
        values = function(CRANE, positions)
        assert values.shape == (3, 7)
        assert isinstance(function(CRANE, 2.0), float)
    flat = np.linspace(0.0, 9.8, 21)
    exact = exact_frequency(CRANE_WITH_INERTIA, flat)
    assert exact == pytest.approx(exact[::-1], rel=1e-12)


def test_static_flexibility_matches_the_finite_element_model():
    # Flexibility [[w/F, w/C], [theta/F, theta/C]] against a 2-element exact static model:
    # the symmetric matrix must be positive definite and reciprocal.
    flexibility = static_flexibility(CRANE, 2.0)
    assert flexibility[0, 1] == flexibility[1, 0]
    assert np.all(np.linalg.eigvalsh(flexibility) > 0)
    # Couple at a support: theta = C l / (3 E I).
    assert static_flexibility(CRANE, 0.0)[1, 1] == pytest.approx(
        9.8 / (3 * CRANE.bending_stiffness)
    )


@settings(max_examples=60, deadline=None)
@given(beam=beams, fraction=fractions)
def test_dunkerley_never_exceeds_exact(beam, fraction):
    position = fraction * beam.span
    dunkerley = dunkerley_frequency(beam, position)
    exact = exact_frequency(beam, position)
    assert dunkerley <= exact * (1 + 1e-12)
    # Adding mass never raises a frequency: the exact value is at most the bare beam's
    # and the load's on the massless beam.
    assert exact <= bare_beam_frequency(beam) * (1 + 1e-12)
    if beam.effective_rotary_inertia == 0:
        assert exact <= spring_mass_frequency(beam, position) * (1 + 1e-12)


@settings(max_examples=15, deadline=None)
@given(beam=beams, fraction=st.floats(0.02, 0.98))
def test_exact_agrees_with_fine_finite_elements(beam, fraction):
    position = fraction * beam.span
    exact = exact_frequency(beam, position)
    assert finite_element_frequency(beam, position, elements=48) == pytest.approx(exact, rel=1e-6)


@pytest.mark.parametrize(
    ("changes", "field"),
    [
        ({"span": 0.0}, "span"),
        ({"span": -1.0}, "span"),
        ({"youngs_modulus": 0.0}, "youngs_modulus"),
        ({"second_moment": -0.1}, "second_moment"),
        ({"mass": -1.0}, "mass"),
        ({"load_mass": -5.0}, "load_mass"),
        ({"load_rotary_inertia": -5.0}, "load_rotary_inertia"),
        ({"load_height": math.nan}, "load_height"),
        ({"mass": 0.0, "load_mass": 0.0}, "mass"),
    ],
)
def test_bad_beam_data_is_rejected(changes, field):
    data = {
        "span": 9.8,
        "youngs_modulus": 2.1e11,
        "second_moment": 0.014,
        "mass": 1.0,
        "load_mass": 1.0,
    } | changes
    with pytest.raises(FreestandError) as info:
        SimplySupportedBeam(**data)
    assert info.value.field == field


@pytest.mark.parametrize("position", [-0.01, 9.81, math.inf, [1.0, 12.0]])
def test_positions_off_the_span_are_rejected(position):
    for function in (dunkerley_frequency, exact_frequency, finite_element_frequency):
        with pytest.raises(FreestandError, match="position") as info:
            function(CRANE, position)
        assert info.value.field == "position"


def test_sweep_adds_the_parking_ends_and_mid_span():
    sweep = frequency_sweep(CRANE, points=10, parking=(1.33, 8.47))
    assert {1.33, 8.47, 4.9} <= set(sweep.position.tolist())
    assert np.all(np.diff(sweep.position) > 0)
    assert sweep.bare_beam == bare_beam_frequency(CRANE)
    assert np.all(sweep.shortfall >= -1e-12)
    with pytest.raises(ValueError, match="parking"):
        sweep.frequency_range((9.0, 9.1))


def test_jump_check_bookkeeping():
    sweep = frequency_sweep(CRANE, points=99)
    spectrum = Spectrum(
        np.array([1.0, 11.0, 11.5, 100.0]),
        np.array([2.0, 12.0, 12.0, 2.0]),
        direction="horizontal",
        label="test",
    )
    check = jump_check(sweep, spectrum, 9.81, parking=(1.33, 8.47), basis="exact")
    assert check.notes and "vertical" in check.notes[0]
    assert not check.considered[0] and check.verdict[0] == "not parked"
    assert check.jump_possible
    assert np.all(check.spectral_acceleration == spectrum.acceleration_at(sweep.exact))
    assert check.ratio == pytest.approx(check.spectral_acceleration / 9.81)
    assert np.all(check.at_risk == (check.considered & (check.ratio >= 1 - 1e-9)))
    assert check.minimum_margin == pytest.approx(check.margin[check.considered].min())
    assert check.minimum_margin < 0
    assert check.risk_intervals[0][0] <= check.minimum_margin_position
    # A weak spectrum: no jump anywhere, positive margin.
    weak = jump_check(sweep, spectrum.scaled(0.5), 9.81)
    assert weak.status == "no jump" and weak.minimum_margin > 0 and weak.risk_intervals == ()
    # The band basis reads the largest S_a between Dunkerley and exact: a peak inside the
    # band counts even when neither end reaches it.
    peak = Spectrum(
        np.array([1.0, 10.609, 10.610, 10.611, 10.612, 100.0]),
        np.array([1.0, 1.0, 20.0, 20.0, 1.0, 1.0]),
        direction="vertical",
    )
    mid = frequency_sweep(CRANE, [4.9])
    assert jump_check(mid, peak, 9.81).at_risk[0]
    assert not jump_check(mid, peak, 9.81, basis="dunkerley").at_risk[0]
    assert not jump_check(mid, peak, 9.81, basis="exact").at_risk[0]
