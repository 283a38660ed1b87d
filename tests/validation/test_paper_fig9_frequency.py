"""Paper section 6 and Fig. 9: vertical frequency of the crane bridge against the cart position.

Data (paper section 6): l = 9.8 m, I_y = 0.014 m^4, E = 2.1e11 N/m^2,
m1 = 16600 kg (bridge), m2 = 25600 kg (cart), parking 1.33 m <= d <= l - 1.33 m.
The paper reports its frequencies to 0.1 Hz, so the tolerance on every paper
number is half of that, 0.05 Hz, except for the 21.6 Hz of the bare bridge:
eq. 2 gives 21.548 Hz, i.e. 21.55 Hz to two decimals, which the paper rounds
up to 21.6 Hz (double rounding; with the m1 = 16575 kg that its force tables
suggest, crane-model.md, it is 21.564 Hz). That number is checked to 0.3 %.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from freestand.core.motion.spectra import Spectrum
from freestand.core.structure.beam import (
    SimplySupportedBeam,
    bare_beam_frequency,
    dunkerley_frequency,
    exact_frequency,
    frequency_sweep,
    jump_check,
    load_flexibility,
    spring_mass_frequency,
)

SPAN = 9.8
PARKING = (1.33, SPAN - 1.33)
PAPER_ROUNDING = 0.05  # Hz: the paper gives one decimal
BARE_BRIDGE_TOLERANCE = 0.003  # relative: 21.548 Hz reported as 21.6 Hz (see above)


@pytest.fixture(scope="module")
def bridge() -> SimplySupportedBeam:
    return SimplySupportedBeam(
        span=SPAN, youngs_modulus=2.1e11, second_moment=0.014, mass=16600.0, load_mass=25600.0
    )


@pytest.fixture(scope="module")
def vertical_stand_in() -> Spectrum:
    """A vertical 5 % spectrum shaped like the paper's Fig. 5 reading: ZPA 2.35 m/s^2
    (the vertical acceleration of paper section 4) and a plateau at g from 8 to 12 Hz."""
    return Spectrum(
        frequency=np.array([0.1, 1.0, 8.0, 12.0, 33.0, 100.0]),
        acceleration=np.array([0.2, 3.0, 9.81, 9.81, 2.35, 2.35]),
        damping=0.05,
        direction="vertical",
        label="stand-in vertical spectrum, plateau 1.0 g at 8-12 Hz",
    )


def test_eq2_as_printed_is_angular(bridge):
    # Paper eq. 2 with i = 1 gives 135.4 rad/s; the paper's "21.6 Hz" is that over 2 pi.
    printed = math.pi**2 * math.sqrt(0.014 * 2.1e11 / (16600.0 * SPAN**3))
    assert printed == pytest.approx(135.39, abs=0.01)  # rad/s, rounding of the check value
    assert printed / (2 * math.pi) == pytest.approx(21.6, rel=BARE_BRIDGE_TOLERANCE)
    assert printed / (2 * math.pi) == pytest.approx(21.55, abs=0.005)
    assert bare_beam_frequency(bridge) == pytest.approx(printed / (2 * math.pi), rel=1e-14)


def test_eq3_is_the_flexibility_at_the_cart(bridge):
    # Mid-span: k = l^3 / (48 E I), the textbook deflection per unit central load [m/N].
    expected = SPAN**3 / (48 * 2.1e11 * 0.014)
    assert load_flexibility(bridge, SPAN / 2) == pytest.approx(expected, rel=1e-14)
    # Paper eq. 4 over 2 pi at mid-span: 12.18 Hz (rounding of our own check value).
    assert spring_mass_frequency(bridge, SPAN / 2) == pytest.approx(12.18, abs=0.005)


def test_dunkerley_at_the_supports_is_21_6_hz(bridge):
    # Paper 6.1: 21.6 Hz at d = 0 and d = l; the cart has no effect there.
    assert dunkerley_frequency(bridge, 0.0) == pytest.approx(21.6, rel=BARE_BRIDGE_TOLERANCE)
    assert dunkerley_frequency(bridge, SPAN) == pytest.approx(21.6, rel=BARE_BRIDGE_TOLERANCE)
    assert dunkerley_frequency(bridge, 0.0) == bare_beam_frequency(bridge)


def test_dunkerley_at_mid_span_is_10_6_hz(bridge):
    # Paper 6.1: 10.6 Hz at d = l / 2, the lowest value.
    assert dunkerley_frequency(bridge, SPAN / 2) == pytest.approx(10.6, abs=PAPER_ROUNDING)


def test_dunkerley_at_the_outmost_parking_position_is_16_6_hz(bridge):
    # crane-model.md: about 16.6 Hz with the cart's centre 1.33 m from a support.
    assert dunkerley_frequency(bridge, 1.33) == pytest.approx(16.6, abs=PAPER_ROUNDING)
    assert dunkerley_frequency(bridge, SPAN - 1.33) == pytest.approx(16.6, abs=PAPER_ROUNDING)


def test_parking_range_frequencies_lie_between_10_6_and_18_hz(bridge):
    # Paper 6.1: 10.6 Hz < alpha < 18 Hz for 1.33 m < d < l - 1.33 m (Dunkerley).
    # The paper's 18 Hz is a rounded-up bound: the highest value is 16.6 Hz.
    sweep = frequency_sweep(bridge, points=197, parking=PARKING)
    low, high = sweep.frequency_range(PARKING)
    assert low == pytest.approx(10.6, abs=PAPER_ROUNDING)
    assert high == pytest.approx(16.6, abs=PAPER_ROUNDING)
    assert 10.55 < low and high < 18.0
    # Over the whole span the curve spans 10.6-21.6 Hz, lowest at mid-span (Fig. 9).
    assert sweep.dunkerley.max() == pytest.approx(21.6, rel=BARE_BRIDGE_TOLERANCE)
    assert sweep.position[np.argmin(sweep.dunkerley)] == pytest.approx(SPAN / 2)


def test_exact_solution_for_the_crane(bridge):
    # The exact continuous-beam values (docs/frequency.md); Dunkerley is 0.13 %
    # low at mid-span and 3.0 % low at 1.33 m. Tolerances: rounding of the quoted values.
    assert exact_frequency(bridge, SPAN / 2) == pytest.approx(10.6174, abs=5e-5)
    assert exact_frequency(bridge, 1.33) == pytest.approx(17.0931, abs=5e-5)
    assert exact_frequency(bridge, 0.0) == pytest.approx(21.5477, abs=5e-5)
    sweep = frequency_sweep(bridge, points=197, parking=PARKING)
    assert np.all(sweep.exact >= sweep.dunkerley)
    assert sweep.shortfall[sweep.within(PARKING)].max() == pytest.approx(0.0300, abs=5e-4)


def test_cart_may_jump_when_parked_near_mid_span(bridge, vertical_stand_in):
    # Paper 6.1: vertical amplification up to g in 8-12 Hz, frequencies 10.6-18 Hz
    # in the parking range: the cart may jump when parked near mid-span.
    sweep = frequency_sweep(bridge, points=197, parking=PARKING)
    check = jump_check(sweep, vertical_stand_in, 9.81, parking=PARKING, basis="dunkerley")
    assert check.status == "jump possible"
    assert SPAN / 2 in check.positions_at_risk
    assert check.minimum_margin <= 1e-9 * 9.81
    ((first, last),) = check.risk_intervals
    # Dunkerley's frequency is 12 Hz (end of the plateau) at about 3 m from a support.
    assert first == pytest.approx(3.0, abs=0.06)
    assert last == pytest.approx(SPAN - 3.0, abs=0.06)
    # At the outmost parking positions (16.6 Hz) the spectrum is well below g.
    ends = np.isin(sweep.position, PARKING)
    assert not check.at_risk[ends].any()
    assert np.all(check.ratio[ends] < 0.7)
    # The band basis (default) flags at least the positions Dunkerley's does.
    band = jump_check(sweep, vertical_stand_in, 9.81, parking=PARKING)
    assert np.all(band.at_risk >= check.at_risk)
