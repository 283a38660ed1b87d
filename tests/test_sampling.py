"""Monte Carlo sweeps, distributions and binomial intervals."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from freestand.core.contact.batch import Parameter
from freestand.core.contact.screening import initial_motion
from freestand.core.model import Excitation
from freestand.core.sweeps.sampling import (
    Fixed,
    LogNormal,
    Normal,
    Triangular,
    TruncatedNormal,
    Uniform,
    Variation,
    clopper_pearson_interval,
    draw_samples,
    monte_carlo,
    wilson_interval,
)
from freestand.io.model_file import load_model

MODEL = load_model(__file__.rsplit("/tests/", 1)[0] + "/examples/crane.toml")


def test_zero_spread_gives_probability_one_for_the_single_case_answer():
    """A degenerate distribution (zero spread) reproduces the case-by-case answer."""
    variations = [
        Variation(Parameter("friction.static"), Normal(0.25, 0.0)),
        Variation(Parameter("centre.x", "cart", "add"), Uniform(0.0, 0.0)),
    ]
    sweep = monte_carlo(
        MODEL.configurations, MODEL.excitations, variations, 500, seed=1, gravity=MODEL.gravity
    )
    assert len(sweep.cases) == 3 * 2 * 2
    for case in sweep.cases:
        stack = MODEL.configuration(case.configuration)
        excitation = next(e for e in MODEL.excitations if e.name == case.excitation)
        reference = initial_motion(
            stack, excitation.horizontal, excitation.vertical, case.sense, MODEL.gravity
        )
        for state in reference.blocks:
            item = case.probability(state.name, state.motion.value)
            assert item.probability == 1.0
            assert item.count == item.total == 500
            assert item.high == 1.0
        assert len(case.states) == 1
        assert case.statuses[0].outcome == reference.status


def test_probabilities_add_up_and_intervals_contain_them():
    variations = [
        Variation(Parameter("horizontal"), Uniform(0.0, 6.0)),
        Variation(Parameter("friction.static", "cart"), Uniform(0.1, 0.4)),
    ]
    sweep = monte_carlo(
        [MODEL.configuration("x-z cart right")],
        [MODEL.excitations[0]],
        variations,
        4000,
        seed=3,
        gravity=MODEL.gravity,
        senses=(-1,),
    )
    (case,) = sweep.cases
    for block in ("bridge", "cart"):
        items = [m for m in case.motions if m.block == block]
        assert sum(m.probability for m in items) == pytest.approx(1.0)
        for m in items:
            assert m.low <= m.probability <= m.high
    cart_slides = case.probability("cart", "slide").probability
    # The cart slides (away from the stop) where a_hor > mu_0 (g - a_ver)
    # (rigid bodies, paper section 3.2): estimate that by hand from the samples.
    horizontal, static = sweep.samples
    expected = np.mean(horizontal > static * (MODEL.gravity - MODEL.excitations[0].vertical))
    assert cart_slides == pytest.approx(expected, abs=0.01)


def test_same_seed_same_samples_and_independent_streams():
    a = [Variation(Parameter("mass"), Normal(1.0, 0.1))]
    b = a + [Variation(Parameter("inertia"), Uniform(1.0, 2.0))]
    first = draw_samples(a, 100, seed=9)
    again = draw_samples(b, 100, seed=9)
    np.testing.assert_array_equal(first[0], again[0])


@pytest.mark.parametrize(
    "distribution",
    [
        Fixed(2.0),
        Uniform(1.0, 3.0),
        Normal(2.0, 0.5),
        TruncatedNormal(2.0, 1.0, 1.5, 2.5),
        Triangular(1.0, 1.5, 3.0),
        LogNormal(2.0, 0.2),
    ],
)
def test_distributions_have_their_support_and_centre(distribution):
    values = distribution.sample(np.random.default_rng(0), 20000)
    assert values.shape == (20000,)
    assert abs(np.median(values) - 2.0) < 0.1 or isinstance(distribution, Triangular)
    if isinstance(distribution, TruncatedNormal):
        assert values.min() >= 1.5 and values.max() <= 2.5


def test_invalid_distribution_arguments_raise():
    with pytest.raises(ValueError):
        Uniform(2.0, 1.0)
    with pytest.raises(ValueError):
        Normal(0.0, -1.0)


def test_wilson_interval_known_value():
    # Brown, Cai & DasGupta (2001): k = 0, n = 20 -> Wilson upper bound 0.161 at 95 %.
    low, high = wilson_interval(0, 20, 0.95)
    assert low == 0.0
    assert high == pytest.approx(0.1611, abs=2e-4)
    low, high = wilson_interval(20, 20, 0.95)
    assert high == 1.0


def test_clopper_pearson_known_value():
    # Exact interval for k = 0, n = 20 at 95 %: upper = 1 - 0.025^(1/20) = 0.1684.
    low, high = clopper_pearson_interval(0, 20, 0.95)
    assert low == 0.0
    assert high == pytest.approx(1 - 0.025 ** (1 / 20), rel=1e-9)


@given(st.integers(1, 10_000), st.floats(0.0, 1.0), st.sampled_from([0.8, 0.9, 0.95, 0.99]))
def test_intervals_contain_the_estimate(n, fraction, confidence):
    k = int(round(fraction * n))
    for interval in (wilson_interval, clopper_pearson_interval):
        low, high = interval(k, n, confidence)
        assert 0.0 <= low <= k / n <= high <= 1.0


def test_excitation_variation_acts_on_each_excitation():
    variations = [Variation(Parameter("horizontal", operation="scale"), Fixed(0.0))]
    sweep = monte_carlo(
        [MODEL.configuration("y-z")],
        [Excitation("a", 5.0, 1.0), Excitation("b", 9.0, 1.0)],
        variations,
        10,
        gravity=MODEL.gravity,
        senses=(1,),
    )
    for case in sweep.cases:
        assert case.probability("bridge", "rest").probability == 1.0
