"""Physics that must always hold for the rocking block and its integrator."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from freestand.core.model import Block, Friction
from freestand.core.rocking.integrator import (
    Pulse,
    SampledAcceleration,
    exact_minimum_overturning_amplitude,
    rocking_energy,
    simulate,
)
from freestand.core.rocking.properties import RockingBlock
from freestand.errors import FreestandError

blocks = st.builds(
    lambda b1, b2, h, mass, k: RockingBlock(
        mass, k * mass * (max(b1, b2) ** 2 + h**2) / 3, (-b1, -h), (b2, -h)
    ),
    st.floats(0.05, 0.5),
    st.floats(0.05, 0.5),
    st.floats(0.3, 2.0),
    st.floats(1.0, 1e5),
    st.floats(0.3, 1.5),
)


@given(st.floats(0.05, 1.0), st.floats(0.2, 3.0))
def test_restitution_of_a_homogeneous_rectangle(b, h):
    block = RockingBlock.rectangle(10.0, b, h)
    expected = 1 - 1.5 * math.sin(block.alpha) ** 2  # Housner 1963, eq. 4
    assert block.restitution == pytest.approx(expected, rel=1e-12, abs=1e-14)
    assert block.computed_restitution("pivot") == pytest.approx(expected, rel=1e-12, abs=1e-14)


@settings(max_examples=25, deadline=None)
@given(blocks, st.floats(0.3, 0.95))
def test_energy_is_conserved_between_impacts_and_the_impact_ratio_is_the_restitution(block, start):
    theta0 = start * block.alpha
    result = simulate(block, None, theta0=theta0, t_end=8 * 2 * math.pi / block.p, history=True)
    # (an off-centre block may overturn over its other, lower-barrier side)
    energy = rocking_energy(block, result.rotation, result.angular_velocity)
    at_impact = np.nonzero(result.rotation == 0.0)[0]
    bounds = [0, *at_impact.tolist(), len(energy)]
    for lo, hi in zip(bounds[:-1], bounds[1:], strict=True):
        seg = energy[lo:hi]
        if seg.size > 1:
            # RK4 with 0.02/p steps: relative drift far below 1e-8
            assert np.ptp(seg) <= 1e-8 * abs(seg[0])
    log = result.impact_log
    assert log.shape[0] >= 1
    ratios = log[:, 2] / log[:, 1]
    expected = [
        block.restitution_onto("other") if i % 2 == 0 else block.restitution_onto("pivot")
        for i in range(log.shape[0])
    ]
    expected = np.maximum(expected, 0.0)
    np.testing.assert_allclose(ratios[: len(expected)], expected, rtol=1e-12)


@settings(max_examples=40, deadline=None)
@given(
    blocks,
    st.sampled_from(["rectangular", "half-sine", "one-sine", "one-cosine"]),
    st.floats(0.0, 0.999),
    st.floats(0.1, 10.0),
)
def test_below_the_static_threshold_the_block_never_rocks(block, kind, fraction, frequency):
    thr = min(block.about("pivot").uplift_threshold, block.about("other").uplift_threshold)
    pulse = (
        Pulse(kind, fraction * thr, duration=1 / frequency)
        if kind == "rectangular"
        else Pulse(kind, fraction * thr, frequency=frequency)
    )
    result = simulate(block, pulse)
    assert not result.rocked
    assert result.max_abs_rotation == 0.0 and result.impacts == 0
    assert result.status == "rest"


def test_general_restitution_from_angular_momentum():
    # off-centre centre of gravity: conservation of angular momentum about the
    # new pivot, written out by hand
    m, inertia = 100.0, 12.0
    block = RockingBlock(m, inertia, (-0.2, -1.0), (0.5, -1.0))
    r_old, r_new = np.array([0.2, 1.0]), np.array([-0.5, 1.0])
    expected = (inertia + m * r_old @ r_new) / (inertia + m * r_new @ r_new)
    assert block.restitution == pytest.approx(expected, rel=1e-14)
    back = (inertia + m * r_old @ r_new) / (inertia + m * r_old @ r_old)
    assert block.restitution_onto("pivot") == pytest.approx(back, rel=1e-14)
    assert block.about("other").R == pytest.approx(math.hypot(0.5, 1.0))
    assert block.about("other").uplift_threshold == pytest.approx(9.81 * 0.5)
    assert (
        RockingBlock(m, inertia, (-0.2, -1.0), (0.5, -1.0), restitution_override=0.9).restitution
        == 0.9
    )


def test_vertical_acceleration_reduces_the_weight():
    block = RockingBlock.rectangle(1.0, 0.2, 0.6, vertical_acceleration=2.35)
    assert block.uplift_threshold == pytest.approx((9.81 - 2.35) / 3)
    assert block.p == pytest.approx(math.sqrt(3 * (9.81 - 2.35) / (4 * block.R)))


def test_unknown_pivot_is_a_freestand_error():
    block = RockingBlock.rectangle(1.0, 0.2, 0.6)
    with pytest.raises(FreestandError, match="unknown pivot 'middle'"):
        block.about("middle")
    model_block = Block("cart", 25600, 124100, (0.0, 4.03), -1.33, 1.33, 1.2, Friction(0.25, 0.2))
    with pytest.raises(FreestandError, match="'left' or 'right'"):
        RockingBlock.from_block(model_block, "centre")
    cart = RockingBlock.from_block(model_block, "right")
    assert cart.p == pytest.approx(1.449, abs=1e-3)
    assert cart.pivot == pytest.approx((1.33, -2.83))


def test_block_may_pass_alpha_during_a_pulse_and_come_back():
    # one-sine pulse (Zhang and Makris type A): the second half brings the
    # block back although it passed the point of no return of free rocking
    block = RockingBlock.rectangle(1.0, 0.2, 0.6)
    result = simulate(block, Pulse("one-sine", 0.7276 * 9.81, frequency=1.0))
    assert result.max_abs_rotation > 1.5 * block.alpha
    assert not result.overturned


def test_sampled_record_reproduces_the_analytic_pulse():
    block = RockingBlock.rectangle(1.0, 0.2, 0.6)
    amplitude, f = 0.56 * 9.81, 1.0
    dt = 0.5 / 4000
    t = np.arange(0, 4001) * dt
    record = SampledAcceleration(amplitude * np.sin(2 * np.pi * f * t), dt)
    a = simulate(block, Pulse("half-sine", amplitude, frequency=f), t_end=1.5)
    b = simulate(block, record, t_end=1.5)
    # linear interpolation of the samples: error O(dt^2), about 1e-6 here
    assert b.max_abs_rotation == pytest.approx(a.max_abs_rotation, rel=1e-4)
    assert b.impacts == a.impacts


@pytest.mark.parametrize("slenderness", [0.1, 0.03, 0.01])
def test_exact_limit_approaches_the_linearised_one_for_slender_blocks(slenderness):
    block = RockingBlock.rectangle(1.0, slenderness * 1.0, 1.0)
    f = np.array([0.3, 1.0, 3.0]) * block.p / (2 * np.pi)  # omega/p = 0.3, 1, 3
    exact = exact_minimum_overturning_amplitude(block, "half-sine", f).amplitude
    linear = block.makris_roussos_half_sine_amplitude(f)
    # the difference is of order alpha^2 (tan(alpha)/alpha - 1 = alpha^2/3)
    assert np.max(np.abs(exact / linear - 1)) < 0.5 * block.alpha**2 + 2e-6


def test_overturned_block_lies_on_its_side():
    block = RockingBlock.rectangle(1.0, 0.2, 0.6)
    result = simulate(block, Pulse("half-sine", 0.6 * 9.81, frequency=1.0), history=True)
    assert result.overturned and result.status == "overturned"
    assert result.rotation[-1] >= math.pi / 2
    assert result.time_overturned == result.time[-1]
    decided = simulate(block, Pulse("half-sine", 0.6 * 9.81, frequency=1.0), decide=True)
    assert decided.overturned and decided.margin >= 1


def test_a_pulse_that_just_reaches_the_uplift_threshold_ends():
    # b / h = 0.5: the threshold (g - a_v) b / h is a round-off above g tan(alpha), so the
    # pulse's peak starts rocking that cannot be resolved within a step; the block rests
    # for the step instead of undoing the same start forever (the scan of the exact
    # limit starts at this amplitude)
    block = RockingBlock.rectangle(1.0, 0.5, 1.0)
    result = simulate(block, Pulse("half-sine", block.uplift_threshold, frequency=4.0),
                      decide=True)  # fmt: skip
    assert not result.overturned
    limit = exact_minimum_overturning_amplitude(block, "half-sine", 4.0, scan_ratio=1.05)
    assert limit.found and limit.amplitude > block.uplift_threshold
