"""Physics that every screening result must satisfy (random stacks of 1-4 blocks).

Each check recomputes the quantity from the block geometry and the reported
forces and accelerations, independently of the solver's own matrices:
Newton-Euler equilibrium of every block, non-negative normal forces,
complementarity (open contacts do not approach, closed ones do not separate),
sticking interfaces inside the static cone, sliding ones on the kinetic cone
against the slip.
"""

from __future__ import annotations

import math

from hypothesis import HealthCheck, given, settings

from freestand.core.contact.screening import Motion, initial_motion
from freestand.core.model import Sliding
from tests.strategies import excitations, stacks

G = 9.81
SETTINGS = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _point_acceleration(state, block, point):
    """Acceleration (x, z) of the material point of ``block`` at ``point`` (at rest)."""
    dx, dz = point[0] - block.centre[0], point[1] - block.centre[1]
    eps = state.angular_acceleration
    return state.acceleration_x - eps * dz, state.acceleration_z + eps * dx


def _checks(stack, case, horizontal, vertical, sense):
    blocks, states = stack.blocks, case.blocks
    weight_scale = sum(b.mass for b in blocks) * max(math.hypot(horizontal, G - vertical), 1.0)
    force_tol = 1e-7 * weight_scale
    accel_tol = 1e-7 * max(math.hypot(horizontal, G - vertical), 1.0)
    for i, (block, state) in enumerate(zip(blocks, states, strict=True)):
        # Forces on this block: from below (its base) and from the block above.
        fx = block.mass * sense * horizontal + state.base_tangential
        fz = -block.mass * (G - vertical) + state.base_normal_left + state.base_normal_right
        (xl, zl), (xr, zr) = block.contacts
        moment = (
            (xl - block.centre[0]) * state.base_normal_left
            + (xr - block.centre[0]) * state.base_normal_right
            - (zl - block.centre[1]) * state.base_tangential
        )
        if i + 1 < len(blocks):
            above, above_state = blocks[i + 1], states[i + 1]
            (ul, uz), (ur, _) = above.contacts
            fx -= above_state.base_tangential
            fz -= above_state.base_normal_left + above_state.base_normal_right
            moment -= (
                (ul - block.centre[0]) * above_state.base_normal_left
                + (ur - block.centre[0]) * above_state.base_normal_right
                - (uz - block.centre[1]) * above_state.base_tangential
            )
        # Newton-Euler equilibrium with the reported accelerations.
        assert abs(fx - block.mass * state.acceleration_x) <= force_tol
        assert abs(fz - block.mass * state.acceleration_z) <= force_tol
        size = max(abs(block.base_right - block.base_left), abs(block.centre[1]), 1.0)
        assert abs(moment - block.inertia * state.angular_acceleration) <= force_tol * size * 4
        # Unilateral contacts and complementarity.
        below = (blocks[i - 1], states[i - 1]) if i else None
        normal_sum = state.base_normal_left + state.base_normal_right
        for point, normal in zip(
            block.contacts, (state.base_normal_left, state.base_normal_right), strict=True
        ):
            assert normal >= -force_tol
            ax, az = _point_acceleration(state, block, point)
            if below:
                bx, bz = _point_acceleration(below[1], below[0], point)
                ax, az = ax - bx, az - bz
            assert az >= -accel_tol  # open contacts never approach
            if normal > force_tol:
                assert abs(az) <= accel_tol  # loaded contacts stay closed
        # Friction.
        tangential = state.base_tangential
        if state.motion in (Motion.REST, Motion.ROCK):
            limit = block.friction.static * normal_sum + force_tol
            if block.sliding is Sliding.FREE:
                assert abs(tangential) <= limit
            elif block.sliding is Sliding.NO_RIGHT:
                assert tangential <= limit
            elif block.sliding is Sliding.NO_LEFT:
                assert -tangential <= limit
        if state.motion in (Motion.SLIDE, Motion.SLIDE_ROCK):
            assert block.sliding.allows(state.slide_direction)
            expected = -state.slide_direction * block.friction.kinetic * normal_sum
            assert abs(tangential - expected) <= force_tol
        if state.motion is Motion.FREE_FLIGHT:
            assert abs(normal_sum) <= force_tol and abs(tangential) <= force_tol


@SETTINGS
@given(stack=stacks(max_blocks=3), excitation=excitations())
def test_every_state_satisfies_the_physics(stack, excitation):
    horizontal, vertical, sense = excitation
    case = initial_motion(stack, horizontal, vertical, sense, G)
    assert case.status in ("unique", "ambiguous", "inconsistent")
    for alternative in case.alternatives:
        _checks(
            stack,
            case.__class__(**{**case.__dict__, "blocks": alternative}),
            horizontal,
            vertical,
            sense,
        )


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(stack=stacks(max_blocks=4), excitation=excitations())
def test_four_block_stacks(stack, excitation):
    horizontal, vertical, sense = excitation
    case = initial_motion(stack, horizontal, vertical, sense, G)
    for alternative in case.alternatives:
        _checks(
            stack,
            case.__class__(**{**case.__dict__, "blocks": alternative}),
            horizontal,
            vertical,
            sense,
        )


@SETTINGS
@given(stack=stacks(max_blocks=3), excitation=excitations())
def test_mirror_symmetry(stack, excitation):
    """Mirroring the stack (x -> -x) and the sense mirrors the answer."""
    from dataclasses import replace

    from freestand.core.model import Stack

    horizontal, vertical, sense = excitation
    swap = {Sliding.NO_LEFT: Sliding.NO_RIGHT, Sliding.NO_RIGHT: Sliding.NO_LEFT}
    mirrored = Stack(
        "mirror",
        tuple(
            replace(
                b,
                centre=(-b.centre[0], b.centre[1]),
                base_left=-b.base_right,
                base_right=-b.base_left,
                sliding=swap.get(b.sliding, b.sliding),
            )
            for b in stack.blocks
        ),
    )
    case = initial_motion(stack, horizontal, vertical, sense, G)
    image = initial_motion(mirrored, horizontal, vertical, -sense, G)
    assert case.status == image.status
    if case.status != "unique":
        return
    for a, b in zip(case.blocks, image.blocks, strict=True):
        assert a.motion is b.motion
        assert a.slide_direction == -b.slide_direction
        assert {None: None, "left": "right", "right": "left"}[a.pivot] == b.pivot
        scale = 1e-6 * max(1.0, abs(a.base_normal_left) + abs(a.base_normal_right))
        assert abs(a.base_normal_left - b.base_normal_right) <= scale
        assert abs(a.acceleration_x + b.acceleration_x) <= 1e-6 * max(1.0, abs(a.acceleration_x))
