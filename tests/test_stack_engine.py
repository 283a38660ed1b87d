"""Tests of the compiled stack engine (freestand.core.dynamics.engine) behind the general path."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from freestand.core.contact.modes import Tangential, solve_contact
from freestand.core.dynamics import engine
from freestand.core.dynamics.timehistory import (
    ContactTolerances,
    SupportMotion,
    _mark_kinks,
    contact_problem_in_motion,
    engine_model,
    record_breaks,
    record_row_breaks,
    simulate,
    stack_kinematics,
)
from freestand.core.model import Block, Friction, Sliding, Stack
from tests.strategies import friction_clear_of_the_tolerance, stacks

G = 9.81
_CODES = {Sliding.FREE: 0, Sliding.NONE: 1, Sliding.NO_RIGHT: 2, Sliding.NO_LEFT: 3}
_TANGENTIAL = {
    Tangential.FREE: 0,
    Tangential.STICK: 1,
    Tangential.SLIDE_POSITIVE: 2,
    Tangential.SLIDE_NEGATIVE: 3,
    Tangential.KINETIC: 4,
}


def rectangle(half_width=0.2, height=1.2, mass=100.0, static=0.8, kinetic=None) -> Block:
    kinetic = static if kinetic is None else kinetic
    return Block(
        "block",
        mass,
        mass * (4 * half_width**2 + height**2) / 12.0,
        (0.0, 0.5 * height),
        -half_width,
        half_width,
        0.0,
        Friction(static, kinetic),
    )


def compiled_solve(stack: Stack, q, qd, inertial: float, vertical: float):
    """The engine's contact solve on the problem ``contact_problem_in_motion`` builds."""
    problem = contact_problem_in_motion(stack, q, qd, inertial, vertical)
    count = len(stack.blocks)
    model = engine_model(stack, np.ones(count))
    kin = stack_kinematics(stack, q, qd)
    free = np.zeros(3 * count)
    free[0::3] = inertial
    free[1::3] = -(G - vertical)
    active = np.array([interface.active for interface in problem.interfaces], dtype=bool)
    slip = np.array([interface.slip_velocity for interface in problem.interfaces])
    sliding = np.array(
        [_CODES[interface.effective_sliding()] for interface in problem.interfaces],
        dtype=np.int64,
    )
    force_tol = engine.RELATIVE_TOLERANCE * problem.force_scale
    accel_tol = engine.RELATIVE_TOLERANCE * problem.acceleration_scale
    modes = np.empty((engine.MAX_DISTINCT, count, 3), dtype=np.int64)
    qdd = np.empty((engine.MAX_DISTINCT, 3 * count))
    lam = np.empty((engine.MAX_DISTINCT, count, 3))
    distinct = engine.solve_contact_problem(
        count, model.masses[engine.INVERSE_MASS], free, kin.normal_jacobian, kin.normal_bias,
        kin.tangential_jacobian, kin.tangential_bias, active, slip, sliding,
        model.properties[engine.MU_S], model.properties[engine.MU_K], force_tol, accel_tol,
        modes, qdd, lam,
    )  # fmt: skip
    return problem, distinct, modes, qdd, lam


@settings(max_examples=60, deadline=None)
@given(
    stack=stacks(max_blocks=3),
    seed=st.integers(0, 2**31),
    inertial=st.floats(-2.0 * G, 2.0 * G),
    vertical=st.floats(-0.5 * G, 0.9 * G),
)
def test_compiled_contact_solve_agrees_with_the_numpy_oracle(stack, seed, inertial, vertical):
    # random states near rest (contacts touching, small velocities) so that every kind of
    # mode (closed, open, kinetic, starting slides) appears
    assume(friction_clear_of_the_tolerance(stack))  # an exact tie: see the helper
    rng = np.random.default_rng(seed)
    n = 3 * len(stack.blocks)
    q = rng.normal(size=n) * np.tile([1e-9, 1e-9, 1e-9], n // 3)
    qd = rng.normal(size=n) * rng.choice([0.0, 1e-6, 0.05], size=n)
    problem, distinct, modes, qdd, lam = compiled_solve(stack, q, qd, inertial, vertical)
    oracle = solve_contact(problem)
    assert (distinct == 0) == (oracle.status == "inconsistent")
    if distinct == 0:
        return
    assert (distinct > 1) == oracle.ambiguous
    chosen = oracle.chosen
    expected = [
        (int(m.left_closed), int(m.right_closed), _TANGENTIAL[m.tangential]) for m in chosen.modes
    ]
    assert [tuple(int(v) for v in row) for row in modes[0]] == expected
    scale = problem.acceleration_scale
    np.testing.assert_allclose(qdd[0], chosen.acceleration, atol=1e-7 * scale, rtol=1e-7)
    force = problem.force_scale
    np.testing.assert_allclose(lam[0, :, :2], chosen.normal_force, atol=1e-7 * force, rtol=1e-7)
    np.testing.assert_allclose(lam[0, :, 2], chosen.tangential_force, atol=1e-7 * force)


def test_restitution_factor_scales_housners_ratio():
    block = rectangle(0.2, 1.2)
    alpha = math.atan(0.2 / 0.6)
    housner = 1.0 - 1.5 * math.sin(alpha) ** 2  # Housner 1963, eq. 4
    pivot = np.array([block.base_left, 0.0])
    arm = np.array(block.centre) - pivot
    theta = 0.5 * alpha
    c, s = math.cos(theta), math.sin(theta)
    moved = pivot + np.array([c * arm[0] - s * arm[1], s * arm[0] + c * arm[1]])
    start = np.array([*(moved - np.array(block.centre)), theta])
    for factor in (1.0, 0.8):
        result = simulate(
            Stack("one", (block,)), lambda t: (0.0, 0.0), 1.5, initial_position=start,
            restitution=factor,
        )  # fmt: skip
        impact = result.events_of("impact")[0]
        ratio = impact.velocity_after[0, 2] / impact.velocity_before[0, 2]
        assert ratio == pytest.approx(factor * housner, rel=1e-9)


def test_restitution_must_lie_between_zero_and_one():
    with pytest.raises(ValueError, match="restitution"):
        simulate(Stack("one", (rectangle(),)), lambda t: (0.0, 0.0), 0.1, restitution=1.5)


def test_progress_reports_increasing_fractions_up_to_one():
    reports: list[float] = []
    motion = SupportMotion(0.005, np.sin(np.arange(801) * 0.05))
    result = simulate(
        Stack("one", (rectangle(),)), motion, method="general", progress=reports.append
    )
    assert result.status == "completed"
    assert len(reports) >= 10
    assert reports == sorted(reports)
    assert reports[-1] == 1.0


def test_a_resampled_record_has_the_break_points_of_the_coarse_one():
    rng = np.random.default_rng(3)
    coarse = rng.normal(size=41)
    coarse_breaks = record_breaks(0.01, coarse, np.zeros_like(coarse))
    fine_time = np.arange(401) * 0.001
    fine = np.interp(fine_time, np.arange(41) * 0.01, coarse)
    fine_breaks = record_breaks(0.001, fine, np.zeros_like(fine))
    np.testing.assert_allclose(fine_breaks, coarse_breaks, atol=1e-12)


def test_rest_phases_are_not_integrated_and_keep_the_stack_still():
    # a pulse below both thresholds: the stack rests throughout, the forces follow
    block = rectangle(0.3, 1.0, static=0.8)
    motion = SupportMotion(0.01, 0.5 * G * np.sin(np.linspace(0.0, math.pi, 101)))
    result = simulate(Stack("one", (block,)), motion, method="general")
    assert [event.kind for event in result.events] == ["start"]
    assert np.all(result.position == 0.0)
    # the friction force carries the inertial force m a_h at every recorded instant
    a_h = np.array([motion(t)[0] for t in result.time])
    np.testing.assert_allclose(result.tangential_force[:, 0], block.mass * a_h, atol=1e-6)
    assert ContactTolerances().gap > 0.0


def test_forces_at_rest_follow_the_support_accelerations_of_every_sample():
    # two blocks resting throughout under a horizontal and a vertical record: the
    # forces the time history records (from three unit solutions per rest phase) are
    # those of the contact problem solved at each recorded instant
    from freestand.core.contact.engine import solve as solve_kernel
    from freestand.core.dynamics.timehistory import contact_problem_in_motion

    lower = Block.rectangle("lower", 1.2, 1.0, 800.0, Friction(0.8, 0.7))
    upper = Block.rectangle("upper", 0.8, 0.6, 200.0, Friction(0.8, 0.7), level=1.0)
    stack = Stack("pair", (lower, upper))
    rng = np.random.default_rng(3)
    horizontal = 0.15 * G * rng.uniform(-1.0, 1.0, 201)
    vertical = 0.2 * G * rng.uniform(-1.0, 1.0, 201)
    motion = SupportMotion(0.01, horizontal, vertical)
    result = simulate(stack, motion, method="general")
    assert [event.kind for event in result.events] == ["start"]
    rows = np.linspace(0, len(result.time) - 1, 25).astype(int)
    for row in rows:
        a_h, a_v = motion(result.time[row])
        problem = contact_problem_in_motion(stack, np.zeros(6), np.zeros(6), -a_h, a_v, G)
        chosen = solve_kernel(problem).chosen
        # tolerance: round-off of the superposed unit solutions against a direct solve
        # (forces of about 1e4 N)
        np.testing.assert_allclose(result.normal_force[row], chosen.normal_force, atol=1e-7)
        np.testing.assert_allclose(result.tangential_force[row], chosen.tangential_force, atol=1e-7)


@pytest.mark.parametrize(
    ("width", "height", "mass", "level", "field"),
    [
        (0.0, 1.0, 10.0, 0.0, "width"),
        (0.5, -1.0, 10.0, 0.0, "height"),
        (0.5, 1.0, float("nan"), 0.0, "mass"),
        (0.5, 1.0, 10.0, float("inf"), "level"),
    ],
)
def test_rectangle_refuses_impossible_dimensions(width, height, mass, level, field):
    from freestand.errors import FreestandError

    with pytest.raises(FreestandError, match=field):
        Block.rectangle("box", width, height, mass, Friction(0.5, 0.4), level=level)


def test_rectangle_is_a_homogeneous_block():
    box = Block.rectangle("box", 0.6, 2.0, 1200.0, Friction(0.8, 0.7), level=0.5)
    assert box.inertia == 1200.0 * (0.6**2 + 2.0**2) / 12.0
    assert box.centre == (0.0, 1.5)
    assert (box.base_left, box.base_right, box.base_level) == (-0.3, 0.3, 0.5)


@settings(max_examples=200, deadline=None)
@given(st.integers(0, 2**32 - 1), st.integers(2, 60), st.integers(1, 3),
       st.sampled_from([0.005, 0.01, 0.02, 1.0 / 3.0]))  # fmt: skip
def test_the_break_points_in_one_call_are_numpy_s_to_the_bit(seed, count, components, step):
    # record_row_breaks against the kinks marked per component and numpy's flatnonzero times
    # the step: records straight on stretches, with zeros, repeated and tiny values
    rng = np.random.default_rng(seed)
    knots = rng.choice([0.0, 1e-13, 1.0, -2.5], size=(components, count))
    straight = rng.random((components, count)) < 0.5
    scale = rng.normal(size=(components, 1))
    record = np.where(straight, np.linspace(0.0, 1.0, count), knots) * scale
    kinks = np.zeros(count, dtype=bool)
    for values in record:
        _mark_kinks(values.copy(), kinks)
    kinks[-1] = True
    expected = np.flatnonzero(kinks) * step
    for breaks in (record_row_breaks(step, record), record_breaks(step, *record)):
        assert breaks.dtype == expected.dtype and breaks.tobytes() == expected.tobytes()
