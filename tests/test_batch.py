"""The batch solver gives the same answers as the case-by-case solver.

Random stacks of 1-3 blocks (any sliding restriction, centres inside or
outside their bases, friction 0-1.5, excitations including a_ver >= g) are
solved by :func:`freestand.core.contact.batch.solve_batch` and
:func:`freestand.core.contact.batch.solve_excitation_plane` and compared with
:func:`freestand.core.contact.screening.initial_motion`: status (incl. ambiguous and
inconsistent), every block's motion, pivot and slide direction, every
admissible state, and accelerations and forces.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from freestand.core.contact.batch import (
    MOTIONS,
    STATUS_NAMES,
    BatchStack,
    CaseInputs,
    Parameter,
    case_inputs,
    solve_batch,
    solve_excitation_plane,
)
from freestand.core.contact.screening import initial_motion
from freestand.core.model import Block, Friction, Sliding, Stack

GRAVITY = 9.81
# Tolerances: the batch solver eliminates the accelerations (Schur complement)
# while the case-by-case solver solves the full system with LAPACK; both are
# exact up to rounding, so 1e-7 of the problem's scale is a tight bound.
ACCELERATION_TOLERANCE = 1e-7  # [m/s^2 or rad/s^2] relative to max(|a|, g)
FORCE_TOLERANCE = 1e-7  # [N] relative to the total weight m g


def random_stack(rng: np.random.Generator, blocks: int | None = None, sliding=None) -> Stack:
    """A random stack: widths, heights, centres, masses, friction and restrictions."""
    count = int(rng.integers(1, 4)) if blocks is None else blocks
    result = []
    level = 0.0
    for i in range(count):
        left = rng.uniform(-2.0, 1.0)
        right = left + rng.uniform(0.2, 3.0)
        centre_z = level + rng.uniform(0.1, 3.0)
        centre_x = rng.uniform(left - 0.5, right + 0.5)
        static = rng.uniform(0.0, 1.5)
        restriction = (
            Sliding(rng.choice(["free", "none", "no-right", "no-left"]))
            if sliding is None
            else sliding[i]
        )
        result.append(
            Block(
                name=f"b{i}",
                mass=rng.uniform(1.0, 1000.0),
                inertia=rng.uniform(0.1, 500.0),
                centre=(centre_x, centre_z),
                base_left=left,
                base_right=right,
                base_level=level,
                friction=Friction(static, static * rng.uniform(0.3, 1.0)),
                sliding=restriction,
            )
        )
        level = centre_z + rng.uniform(0.05, 1.5)
    return Stack("random", tuple(result))


def batch_of(stacks: list[Stack], horizontal, vertical, sense: int) -> CaseInputs:
    """Stack the numbers of several stacks of one structure into one batch."""
    parts = [BatchStack.from_stack(stack) for stack in stacks]
    first = parts[0]
    arrays = {name: np.concatenate([getattr(p, name) for p in parts]) for name in BatchStack.ARRAYS}
    return CaseInputs(
        stack=BatchStack(names=first.names, sliding=first.sliding, **arrays),
        horizontal=np.asarray(horizontal, dtype=float),
        vertical=np.asarray(vertical, dtype=float),
        sense=sense,
    )


def states_of(alternative) -> tuple:
    return tuple((s.motion, s.pivot, s.slide_direction) for s in alternative)


def assert_same(result, case: int, reference, stack: Stack) -> None:
    """Case ``case`` of a BatchResult equals an InitialMotion."""
    assert STATUS_NAMES[result.status[case]] == reference.status
    expected = [states_of(alternative) for alternative in reference.alternatives]
    if reference.status == "free-flight":
        assert all(MOTIONS[m].value == "free-flight" for m in result.motion[case])
    else:
        assert result.admissible_count[case] == len(expected)
        got = result.alternative_states(case)
        assert got == expected[: len(got)]
    if not reference.blocks:
        assert np.all(result.motion[case] == -1)
        return
    scale_a = max(GRAVITY, abs(reference.horizontal))
    weight = sum(block.mass for block in stack.blocks) * max(
        GRAVITY, abs(reference.horizontal), abs(GRAVITY - reference.vertical)
    )
    for b, state in enumerate(reference.blocks):
        assert MOTIONS[result.motion[case, b]] is state.motion
        pivot = {-1: "left", 1: "right", 0: None}[int(result.pivot[case, b])]
        assert pivot == state.pivot
        assert result.slide_direction[case, b] == state.slide_direction
        expected_a = (state.acceleration_x, state.acceleration_z, state.angular_acceleration)
        np.testing.assert_allclose(
            result.acceleration[case, b], expected_a, rtol=0, atol=ACCELERATION_TOLERANCE * scale_a
        )
        expected_f = (state.base_normal_left, state.base_normal_right, state.base_tangential)
        np.testing.assert_allclose(
            result.base_force[case, b], expected_f, rtol=0, atol=FORCE_TOLERANCE * weight
        )


def check_structure(rng: np.random.Generator, blocks: int, variants: int) -> list[str]:
    sliding = [Sliding(rng.choice(["free", "none", "no-right", "no-left"])) for _ in range(blocks)]
    stacks = [random_stack(rng, blocks, sliding) for _ in range(variants)]
    horizontal = rng.uniform(0.0, 20.0, variants)
    vertical = rng.uniform(-5.0, 11.0, variants)
    sense = int(rng.choice([1, -1]))
    result = solve_batch(batch_of(stacks, horizontal, vertical, sense), GRAVITY)
    statuses = []
    for case, stack in enumerate(stacks):
        reference = initial_motion(stack, horizontal[case], vertical[case], sense, GRAVITY)
        assert_same(result, case, reference, stack)
        statuses.append(reference.status)
    # The excitation plane of the first stack gives the same answers too.
    plane = solve_excitation_plane(stacks[0], sense * horizontal, vertical, GRAVITY)
    for case in range(variants):
        reference = initial_motion(stacks[0], horizontal[case], vertical[case], sense, GRAVITY)
        assert_same(plane, case, reference, stacks[0])
    return statuses


@settings(
    max_examples=40,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
@given(seed=st.integers(0, 2**32 - 1), blocks=st.integers(1, 3))
def test_batch_equals_case_by_case(seed, blocks):
    check_structure(np.random.default_rng(seed), blocks, variants=6 if blocks == 3 else 12)


def test_random_batches_cover_ambiguous_and_inconsistent_cases():
    """A fixed set of random batches that contains every status."""
    rng = np.random.default_rng(20240611)
    statuses = []
    for _ in range(30):
        statuses += check_structure(rng, int(rng.integers(1, 3)), variants=12)
    for _ in range(3):
        statuses += check_structure(rng, 3, variants=6)
    assert {"unique", "ambiguous", "inconsistent", "free-flight"} <= set(statuses)


def test_varied_parameters_match_modified_stacks():
    """case_inputs applies parameters as a modified model would hold them."""
    rng = np.random.default_rng(7)
    stack = random_stack(rng, 2, [Sliding.FREE, Sliding.FREE])
    count = 10
    static = rng.uniform(0.1, 0.6, count)
    shift = rng.normal(0.0, 0.2, count)
    factor = rng.uniform(0.5, 2.0, count)
    inputs = case_inputs(
        stack,
        3.0,
        1.0,
        -1,
        [
            (Parameter("friction.static"), static),
            (Parameter("centre.x", "b1", "add"), shift),
            (Parameter("mass", "b0", "scale"), factor),
        ],
        count,
    )
    result = solve_batch(inputs, GRAVITY)
    for case in range(count):
        blocks = []
        for b, block in enumerate(stack.blocks):
            ratio = block.friction.kinetic / block.friction.static
            blocks.append(
                Block(
                    name=block.name,
                    mass=block.mass * (factor[case] if b == 0 else 1.0),
                    inertia=block.inertia,
                    centre=(block.centre[0] + (shift[case] if b == 1 else 0.0), block.centre[1]),
                    base_left=block.base_left,
                    base_right=block.base_right,
                    base_level=block.base_level,
                    friction=Friction(static[case], static[case] * ratio),
                    sliding=block.sliding,
                )
            )
        modified = Stack("modified", tuple(blocks))
        assert_same(result, case, initial_motion(modified, 3.0, 1.0, -1, GRAVITY), modified)


def test_kinetic_friction_never_exceeds_static():
    stack = random_stack(np.random.default_rng(3), 2, [Sliding.FREE, Sliding.FREE])
    values = np.linspace(0.0, 1.0, 11)
    inputs = case_inputs(stack, 1.0, 0.0, 1, [(Parameter("friction.kinetic", "b0"), values)], 11)
    assert np.all(inputs.stack.kinetic_friction <= inputs.stack.static_friction)


def test_invalid_inputs_are_flagged_not_solved():
    stack = random_stack(np.random.default_rng(4), 1, [Sliding.FREE])
    inputs = case_inputs(stack, 1.0, 0.0, 1, [(Parameter("mass"), np.array([-1.0, 5.0]))], 2)
    result = solve_batch(inputs, GRAVITY)
    assert [result.status_name(0), result.status_name(1)][0] == "invalid"
    assert result.status_name(1) in ("unique", "ambiguous")


def test_unknown_parameter_is_rejected():
    with pytest.raises(ValueError):
        Parameter("colour")
    with pytest.raises(ValueError):
        Parameter("horizontal", block="cart")
