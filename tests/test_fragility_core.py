"""Fragility core: intensity measures, outcomes, task enumeration, fit invariants."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from freestand.core.model import Block, Friction, Sliding, Stack
from freestand.core.motion.ground_motion import half_sine_pulse, synthetic_ground_motion
from freestand.core.motion.response_spectrum import spectral_response
from freestand.core.sweeps.fragility.campaign import Campaign, run_tasks
from freestand.core.sweeps.fragility.fit import fit_fragility
from freestand.core.sweeps.fragility.intensity import IntensityMeasure, intensity, rocking_threshold
from freestand.core.sweeps.fragility.outcomes import Outcome
from freestand.io.parameters import parse_variation

BLOCK = Block("block", 500.0, 266.6666666666667, (0.0, 1.2), -0.4, 0.4, 0.0,
              Friction(2.0, 2.0), Sliding.NONE)  # fmt: skip
STACK = Stack("block", (BLOCK,))
RECORD = synthetic_ground_motion(seed=3, duration=4.0)


@pytest.mark.parametrize(
    "measure",
    [
        IntensityMeasure("pga"),
        IntensityMeasure("pgv"),
        IntensityMeasure("sa", 2.5, 0.02),
        IntensityMeasure("pga-alpha", block="block"),
    ],  # fmt: skip
)
def test_scaling_a_record_to_a_level_gives_that_level(measure):
    value = intensity(RECORD, measure, STACK)
    scaled = RECORD.scaled(7.0 / value)
    # every IM is linear in the record: one factor reaches the level exactly
    assert intensity(scaled, measure, STACK) == pytest.approx(7.0, rel=1e-12)


def test_intensity_values():
    sa = intensity(RECORD, IntensityMeasure("sa", 2.5, 0.02), STACK)
    expected = spectral_response(RECORD, None, [2.5], 0.02).pseudo_acceleration[0]
    assert sa == expected
    # g tan(alpha) of a 0.8 m x 2.4 m block: g b / h = 9.81 / 3
    assert rocking_threshold(STACK, None) == pytest.approx(9.81 * 0.4 / 1.2)
    ratio = intensity(RECORD, IntensityMeasure("pga-alpha"), STACK)
    assert ratio == pytest.approx(RECORD.peak_horizontal / (9.81 / 3))


def test_outcomes_from_peak_values():
    values = {
        "cart.overturned": np.array([0.0, 0.0, 1.0]),
        "cart.max_rotation": np.array([0.01, 0.2, 1.5]),
        "cart.max_slide": np.array([0.0, 0.06, np.nan]),
        "cart.uplift": np.array([0.0, 1.0, 1.0]),
        "cart.flight": np.array([0.0, 0.0, 1.0]),
        "cart.alpha": np.array([0.3, 0.3, 0.3]),
    }
    assert Outcome("rotation", "cart", 0.5, "alpha").occurred(values).tolist() == [0, 1, 1]
    assert Outcome("rotation", "cart", 0.25, "rad").occurred(values).tolist() == [0, 0, 1]
    assert Outcome("slide", "cart", 0.05, "m").occurred(values).tolist() == [0, 1, 0]
    assert Outcome("overturn", "cart").occurred(values).tolist() == [0, 0, 1]
    assert Outcome("flight", "cart").occurred(values).tolist() == [0, 0, 1]
    assert Outcome("slide", "cart", 0.05, "m").name == "cart slides > 0.05 m"
    with pytest.raises(ValueError):
        Outcome("slide", "cart")


def test_rows_do_not_depend_on_how_the_tasks_are_cut():
    motions = tuple(half_sine_pulse(1.0, frequency=f, dt=0.002) for f in (2.0, 3.0))
    campaign = Campaign(
        STACK, motions, IntensityMeasure("pga"), np.array([2.0, 5.0]),
        variations=(parse_variation("block.mass*=uniform(0.5,1.5)"),), samples=3,
        polarities=(1, -1), outcomes=(Outcome("uplift", "block"),), free_time=1.0,
    )  # fmt: skip
    assert campaign.size == 24
    tasks = {campaign.task(i) for i in range(campaign.size)}
    assert len(tasks) == 24  # every (record, level, sample, polarity) once
    whole = run_tasks(campaign, 0, 24)
    pieces = [run_tasks(campaign, a, b) for a, b in ((10, 24), (0, 3), (3, 10))]
    for name, values in whole.items():
        joined = np.concatenate([pieces[1][name], pieces[2][name], pieces[0][name]])
        assert joined.tolist() == values.tolist() or np.array_equal(joined, values, True)
    # both polarities share their inputs (common random numbers); samples differ
    mass = whole["input:block.mass (x factor)"]
    assert mass[0] == mass[1] and mass[0] != mass[2]
    assert set(whole["status"]) <= {"completed", "capped"}  # 1 s after a pulse: some rock on


@settings(max_examples=30, deadline=None)
@given(
    factor=st.floats(0.01, 100.0),
    counts=st.lists(st.integers(0, 10), min_size=5, max_size=5),
)
def test_fit_scales_with_the_intensity(factor, counts):
    """Rescaling the IM axis rescales the median and leaves beta unchanged."""
    levels = np.array([1.0, 2.0, 3.0, 4.0, 5.0])
    counts = np.sort(np.array(counts))
    first = fit_fragility(levels, counts, np.full(5, 10), bootstrap=0)
    second = fit_fragility(levels * factor, counts, np.full(5, 10), bootstrap=0)
    assert first.fitted == second.fitted
    if first.fitted:
        assert second.median == pytest.approx(first.median * factor, rel=1e-6)
        assert second.beta == pytest.approx(first.beta, rel=1e-6)
