"""Unit and property tests of the time-history simulation (freestand.core.dynamics.timehistory)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from freestand.core.contact.modes import solve_contact
from freestand.core.contact.screening import contact_problem_at_rest
from freestand.core.dynamics.results import TimeHistoryEvent, _peak_magnitude
from freestand.core.dynamics.timehistory import (
    ContactTolerances,
    SupportMotion,
    contact_problem_in_motion,
    impact_problem,
    simulate,
    stack_kinematics,
)
from freestand.core.model import Block, Friction, Sliding, Stack
from tests.strategies import stacks

G = 9.81


def rectangle(half_width=0.2, height=1.2, mass=100.0, static=0.8, kinetic=None, name="block"):
    """A homogeneous rectangular block standing on the support."""
    kinetic = static if kinetic is None else kinetic
    h = 0.5 * height
    return Block(
        name=name,
        mass=mass,
        inertia=mass * (4 * half_width**2 + height**2) / 12.0,
        centre=(0.0, h),
        base_left=-half_width,
        base_right=half_width,
        base_level=0.0,
        friction=Friction(static, kinetic),
    )


def tilted(block: Block, angle: float) -> np.ndarray:
    """q of a block rotated by ``angle`` about its left (angle > 0) or right corner."""
    pivot = np.array([block.base_left if angle > 0 else block.base_right, block.base_level])
    centre = np.array(block.centre)
    arm = centre - pivot
    c, s = math.cos(angle), math.sin(angle)
    moved = pivot + np.array([c * arm[0] - s * arm[1], s * arm[0] + c * arm[1]])
    return np.array([*(moved - centre), angle])


# --- contact problem at a general state -----------------------------------------------------------


def _finite_difference_check(stack: Stack, seed: int) -> None:
    rng = np.random.default_rng(seed)
    n = 3 * len(stack.blocks)
    q0 = rng.normal(size=n) * np.tile([0.05, 0.05, 0.2], n // 3)
    v0 = rng.normal(size=n)
    a0 = rng.normal(size=n) * 5.0
    h = 1e-5

    def at(t):
        return stack_kinematics(stack, q0 + v0 * t + 0.5 * a0 * t * t, v0 + a0 * t)

    k0, kp, km = at(0.0), at(h), at(-h)
    scale = 1.0 + np.max(np.abs(v0)) ** 2 + np.max(np.abs(a0))
    # second-order central differences: error ~ h^2 * third derivative; 1e-6 relative is ample
    tolerance = 1e-6 * scale
    gap_acc = np.einsum("icn,n->ic", k0.normal_jacobian, a0) + k0.normal_bias
    slip_acc = np.einsum("icn,n->ic", k0.tangential_jacobian, a0) + k0.tangential_bias
    np.testing.assert_allclose((kp.gap - km.gap) / (2 * h), k0.gap_velocity, atol=tolerance)
    np.testing.assert_allclose(
        (kp.slide - km.slide) / (2 * h), k0.slip_velocity[:, 0], atol=tolerance
    )
    np.testing.assert_allclose(
        (kp.gap_velocity - km.gap_velocity) / (2 * h), gap_acc, atol=tolerance
    )
    np.testing.assert_allclose(
        (kp.slip_velocity - km.slip_velocity) / (2 * h), slip_acc, atol=tolerance
    )


def test_jacobians_and_velocity_terms_match_finite_differences(crane_model):
    for index, stack in enumerate(crane_model.configurations):
        _finite_difference_check(stack, seed=index)


@settings(max_examples=40, deadline=None)
@given(stack=stacks(max_blocks=3), seed=st.integers(0, 2**31))
def test_jacobians_match_finite_differences_for_random_stacks(stack, seed):
    _finite_difference_check(stack, seed)


@pytest.mark.parametrize("inertial", [0.0, 2.7, -10.31])
@pytest.mark.parametrize("vertical", [0.0, 2.35])
def test_at_rest_reproduces_the_screening_problem_exactly(crane_model, inertial, vertical):
    for stack in crane_model.configurations:
        n = 3 * len(stack.blocks)
        moving = contact_problem_in_motion(
            stack, np.zeros(n), np.zeros(n), inertial, vertical, crane_model.gravity
        )
        rest = contact_problem_at_rest(stack, inertial, vertical, crane_model.gravity)
        assert np.array_equal(moving.mass_matrix, rest.mass_matrix)
        assert np.array_equal(moving.applied_force, rest.applied_force)
        assert moving.force_scale == rest.force_scale
        assert moving.acceleration_scale == rest.acceleration_scale
        for a, b in zip(moving.interfaces, rest.interfaces, strict=True):
            for name in (
                "normal_jacobian",
                "normal_bias",
                "tangential_jacobian",
                "tangential_bias",
            ):
                assert np.array_equal(getattr(a, name), getattr(b, name)), name
            assert (a.static_friction, a.kinetic_friction) == (
                b.static_friction,
                b.kinetic_friction,
            )
            assert (a.sliding, a.active, a.slip_velocity, a.stop_engaged) == (
                b.sliding,
                b.active,
                b.slip_velocity,
                b.stop_engaged,
            )
        chosen_a = solve_contact(moving).chosen
        chosen_b = solve_contact(rest).chosen
        assert chosen_a.modes == chosen_b.modes


def test_contact_flags_follow_the_state():
    block = rectangle()
    stack = Stack("one", (block,))
    q = tilted(block, 0.05)
    # rocking about the left corner, the right corner up: only the left contact touches
    problem = contact_problem_in_motion(stack, q, np.zeros(3), 0.0, 0.0)
    assert problem.interfaces[0].active == (True, False)
    # the same position, separating from the support: nothing is active
    problem = contact_problem_in_motion(stack, q, np.array([0.0, 0.1, 0.0]), 0.0, 0.0)
    assert problem.interfaces[0].active == (False, False)
    # a sliding block reports its slip velocity; a tiny one counts as zero
    moving = contact_problem_in_motion(stack, np.zeros(3), np.array([0.3, 0.0, 0.0]), 0.0, 0.0)
    assert moving.interfaces[0].slip_velocity == pytest.approx(0.3)
    tiny = contact_problem_in_motion(stack, np.zeros(3), np.array([1e-9, 0.0, 0.0]), 0.0, 0.0)
    assert tiny.interfaces[0].slip_velocity == 0.0


def test_end_stop_engaged_only_at_the_parking_position():
    block = Block(
        "cart", 10.0, 1.0, (0.0, 0.5), -0.5, 0.5, 0.0, Friction(0.2, 0.2), Sliding.NO_RIGHT
    )
    stack = Stack("stop", (block,))
    at_stop = contact_problem_in_motion(stack, np.zeros(3), np.zeros(3), 5.0, 0.0)
    away = contact_problem_in_motion(stack, np.array([-0.1, 0, 0]), np.zeros(3), 5.0, 0.0)
    assert at_stop.interfaces[0].stop_engaged
    assert not away.interfaces[0].stop_engaged
    # pushed right at the stop: held; pushed right away from it: slides
    assert solve_contact(at_stop).chosen.modes[0].slide_direction == 0
    assert solve_contact(away).chosen.modes[0].slide_direction == 1


def test_impact_problem_of_a_landing_block_stops_it():
    """A flat block falling onto the support stops (perfectly plastic)."""
    stack = Stack("one", (rectangle(),))
    result = solve_contact(impact_problem(stack, np.zeros(3), np.array([0.0, -1.0, 0.0])))
    velocity_after = np.array([0.0, -1.0, 0.0]) + result.chosen.acceleration
    np.testing.assert_allclose(velocity_after, 0.0, atol=1e-12)
    assert result.chosen.normal_force.sum() == pytest.approx(100.0)  # impulse m v [N s]


# --- support motion ---------------------------------------------------------------------------------


def test_support_motion_is_piecewise_linear_and_zero_outside():
    motion = SupportMotion(0.1, np.array([0.0, 1.0, -1.0]), np.array([0.0, 2.0, 0.0]))
    assert motion.duration == pytest.approx(0.2)
    assert motion(0.05) == pytest.approx((0.5, 1.0))
    assert motion(0.15) == pytest.approx((0.0, 1.0))
    assert motion(0.2) == pytest.approx((-1.0, 0.0))
    assert motion(-0.01) == (0.0, 0.0)
    assert motion(0.3) == (0.0, 0.0)
    with pytest.raises(ValueError, match="vertical"):
        SupportMotion(0.1, np.zeros(3), np.zeros(4))
    with pytest.raises(ValueError, match="time_step"):
        SupportMotion(0.0, np.zeros(3))


# --- simulation -----------------------------------------------------------------------------------


def test_block_below_uplift_and_sliding_thresholds_does_not_move():
    """tan(alpha) = 1/3 and mu_0 = 0.8: a 0.25 g sine moves nothing."""
    stack = Stack("one", (rectangle(half_width=0.2, height=1.2),))
    record = 0.25 * G * np.sin(2 * math.pi * 2.0 * np.arange(0, 2.0, 0.005))
    result = simulate(stack, SupportMotion(0.005, record))
    assert result.status == "completed"
    assert np.max(np.abs(result.position)) < 1e-12  # m, rad: round-off only
    assert result.max_rotation[0] < 1e-12
    assert not result.uplift[0] and not result.overturned[0]
    assert [event.kind for event in result.events] == ["start"]
    # the base carries the weight and the inertial force
    np.testing.assert_allclose(result.normal_force[:, 0].sum(axis=1), 100.0 * G, rtol=1e-9)


def test_result_shapes_and_lookup(crane_model):
    stack = crane_model.configuration("x-z cart right")
    result = simulate(stack, lambda t: (0.0, 0.0), 0.05)
    k = result.time.size
    assert result.position.shape == (k, 2, 3)
    assert result.normal_force.shape == (k, 2, 2)
    assert result.tangential_force.shape == (k, 2)
    assert result.block_index("cart") == 1
    assert result.time[-1] == pytest.approx(0.05)
    assert result.diagnostics.steps == 50


def test_events_and_peaks_of_the_front_end_match_their_plain_definitions(crane_model):
    # the result is built by compiled passes and a fast event constructor: they give
    # what the dataclass's constructor, numpy's copies and the per-column peaks give
    stack = crane_model.configuration("x-z cart right")
    motion = SupportMotion(0.01, 6.0 * np.sin(np.linspace(0.0, 12.0, 201)))
    result = simulate(stack, motion)
    assert len(result.events) >= 5
    for event in result.events:
        fields = [getattr(event, name) for name in TimeHistoryEvent.__dataclass_fields__]
        plain = TimeHistoryEvent(*fields)
        assert plain == event and repr(plain) == repr(event)
        with pytest.raises(AttributeError):
            event.kind = "impact"
    for quantity in (result.position, result.velocity, result.normal_force, result.slide):
        assert quantity.flags.c_contiguous
    rate = result.velocity[:, :, 2].copy()
    rate[:, 1:] -= result.velocity[:, :-1, 2]
    for i in range(2):
        peak = _peak_magnitude(result.time, result.relative_rotation[:, i], rate[:, i])
        assert result.max_rotation[i] == peak
    assert np.array_equal(result.max_slide, np.nanmax(np.abs(result.slide), axis=0))


def test_energy_never_grows_without_excitation():
    """Free motion from a tilt: plastic impacts and friction only dissipate."""
    for angle, static in ((0.1, 0.8), (-0.15, 0.3), (0.25, 1.0)):
        block = rectangle(half_width=0.25, height=1.0, static=static)
        stack = Stack("one", (block,))
        result = simulate(stack, lambda t: (0.0, 0.0), 1.5, initial_position=tilted(block, angle))
        v = result.velocity[:, 0]
        z = block.centre[1] + result.position[:, 0, 1]
        energy = 0.5 * block.mass * (v[:, 0] ** 2 + v[:, 1] ** 2)
        energy += 0.5 * block.inertia * v[:, 2] ** 2 + block.mass * G * z
        # RK4 at 1 ms keeps the energy to 1e-7 relative between impacts
        assert np.all(np.diff(energy) <= 1e-7 * energy[0])
        assert energy[-1] < energy[0]


def test_vertical_acceleration_beyond_g_gives_free_flight_and_landing():
    """a_v > g for 50 ms lifts the block (weight m (g - a_v) < 0); it lands again."""
    stack = Stack("one", (rectangle(),))
    result = simulate(stack, lambda t: (0.0, 1.5 * G if 0.1 <= t < 0.15 else 0.0), 0.5)
    assert result.status == "completed"
    kinds = [event.kind for event in result.events]
    assert "lift-off" in kinds and "impact" in kinds
    assert result.uplift[0]
    assert np.max(result.position[:, 0, 1]) > 0.0
    assert abs(result.position[-1, 0, 1]) < 1e-9  # back on the support


def test_simulation_requires_a_duration_for_a_function():
    with pytest.raises(ValueError, match="duration"):
        simulate(Stack("one", (rectangle(),)), lambda t: (0.0, 0.0))


def test_custom_tolerances_are_used():
    stack = Stack("one", (rectangle(),))
    result = simulate(
        stack, lambda t: (0.0, 0.0), 0.01, tolerances=ContactTolerances(gap=1e-6, velocity=1e-3)
    )
    assert result.status == "completed"


def test_painleve_inconsistency_is_resolved_by_a_tangential_impact():
    """A thin rod leaning 30 degrees from vertical, its lower end sliding at 1 m/s with
    mu = 1.5: no sliding state is consistent (Painleve's paradox); a velocity jump in
    which the end sticks resolves it, dissipating energy."""
    rod = Block(
        "rod", 10.0, 10.0 * (4e-4 + 4.0) / 12.0, (0.0, 1.0), -0.01, 0.01, 0.0, Friction(1.6, 1.5)
    )
    stack = Stack("rod", (rod,))
    q0 = tilted(rod, math.radians(30.0))
    qd0 = np.array([1.0, 0.0, 0.0])
    assert solve_contact(contact_problem_in_motion(stack, q0, qd0, 0.0, 0.0)).status == (
        "inconsistent"
    )
    result = simulate(stack, lambda t: (0.0, 0.0), 0.05, initial_position=q0, initial_velocity=qd0)
    assert result.status == "completed"
    jump = result.events_of("tangential-impact")
    assert len(jump) == 1 and jump[0].time == 0.0
    after = jump[0].velocity_after.reshape(-1)
    kin = stack_kinematics(stack, q0, after)
    assert abs(kin.slip_velocity[0, 0]) < 1e-9  # the end sticks
    assert kin.gap_velocity[0, 0] > -1e-9  # and does not penetrate

    def kinetic(v):
        return 0.5 * rod.mass * (v[0] ** 2 + v[1] ** 2) + 0.5 * rod.inertia * v[2] ** 2

    assert kinetic(after) < kinetic(qd0)
    assert result.events[0].motions == ("rock",)


def test_a_corner_landing_with_a_fast_slip_sticks_where_the_cone_holds_it():
    """A block landing from free flight on its right corner, the corner slipping at 0.28 m/s:
    the sticking impulse needs 0.66 of the normal one, inside mu = 0.72, so the corner sticks
    (Coulomb's law at velocity level, Moreau 1988; the 3-D engine's impact law). The kinetic
    impulse against the slip before (what the engine took) reversed the corner's slip to
    -0.09 m/s and left the block rocking 27 % faster."""
    b, h, mass, mu = 1.5, 2.9, 5000.0, 0.72
    block = rectangle(0.5 * b, h, mass, static=mu)
    angle = -0.0065  # rad: the right corner is the lower one
    q0 = np.array([0.0, -0.5 * h - math.sin(angle) * 0.5 * b + math.cos(angle) * 0.5 * h, angle])
    qd0 = np.array([0.376, -0.171, -0.0663])
    arm = np.array(
        [
            math.cos(angle) * 0.5 * b + math.sin(angle) * 0.5 * h,
            math.sin(angle) * 0.5 * b - math.cos(angle) * 0.5 * h,
        ]
    )  # the corner from the centre of gravity [m]

    def corner_velocity(qd):
        return qd[:2] + qd[2] * np.array([-arm[1], arm[0]])

    # the sticking impulse P: the corner's velocity after is zero
    compliance = np.array(
        [
            [1 / mass + arm[1] ** 2 / block.inertia, -arm[0] * arm[1] / block.inertia],
            [-arm[0] * arm[1] / block.inertia, 1 / mass + arm[0] ** 2 / block.inertia],
        ]
    )
    impulse = np.linalg.solve(compliance, -corner_velocity(qd0))
    assert 0.6 < abs(impulse[0]) / impulse[1] < mu  # inside the cone
    expected = qd0 + np.array(
        [*(impulse / mass), (arm[0] * impulse[1] - arm[1] * impulse[0]) / block.inertia]
    )
    stack = Stack("one", (block,))
    assert stack_kinematics(stack, q0, qd0).gap[0, 1] == pytest.approx(0.0, abs=1e-15)
    result = simulate(
        stack, SupportMotion(0.005, np.zeros(3)), 0.01, initial_position=q0, initial_velocity=qd0
    )
    assert result.status == "completed"
    landing = result.events_of("impact")[0]
    assert landing.time == 0.0
    after = landing.velocity_after.reshape(-1)
    np.testing.assert_allclose(after, expected, rtol=1e-9, atol=1e-12)  # round-off
    assert abs(stack_kinematics(stack, q0, after).slip_velocity[0, 1]) < 1e-12  # it sticks


@settings(max_examples=15, deadline=None)
@given(
    half_width=st.floats(0.1, 1.0),
    height=st.floats(0.3, 3.0),
    static=st.floats(0.1, 1.0),
    kinetic_ratio=st.floats(0.6, 1.0),
    amplitude=st.floats(0.0, 2.0),
    period=st.floats(0.1, 1.0),
    vertical=st.floats(0.0, 0.5),
)
def test_single_block_under_a_pulse_stays_physical(
    half_width, height, static, kinetic_ratio, amplitude, period, vertical
):
    """Any homogeneous block under a half-sine pulse: no tension, no penetration."""
    block = rectangle(half_width, height, static=static, kinetic=static * kinetic_ratio)

    def pulse(t):
        if t >= period:
            return 0.0, 0.0
        shape = math.sin(math.pi * t / period)
        return amplitude * G * shape, vertical * G * shape

    result = simulate(Stack("one", (block,)), pulse, 1.0)
    assert result.status == "completed", result.message
    weight = block.mass * G
    normal = result.normal_force[np.isfinite(result.normal_force)]
    assert normal.min(initial=0.0) > -1e-6 * weight  # unilateral contacts never pull
    assert result.diagnostics.max_penetration < 1e-6  # m
    tangential = np.abs(result.tangential_force[:, 0])
    total = result.normal_force[:, 0].sum(axis=1)
    finite = np.isfinite(tangential) & np.isfinite(total)
    # friction inside the static cone (the solver's tolerance aside)
    assert np.all(tangential[finite] <= static * total[finite] + 1e-6 * weight)
