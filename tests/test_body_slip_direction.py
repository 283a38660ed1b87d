"""The sliding direction of the 3-D kernel is continuous in the slip velocity (#18).

``body_solve.slip_direction`` gives the kinetic friction's direction u from
the slip velocity s and the stored direction r (the slip's at the step's
start): s / |s| while s points on r's side and is faster than ``SLIP_FLOOR``;
past r's side its component along r reflected; below the floor pulled to r.
It used to take r itself wherever ``s . r <= 0``: at a two-dimensional slip's
stop (s across r) u swung by 90 degrees between two RK4 stages, the slip-stop
function jumped by 1e-3 m/s inside the bracket, and locating the jump took a
sliding cask 30 to 80 RK4 trials per event (two thirds of its solves).
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from freestand.core.contact import body_kernel, body_solve
from freestand.core.contact.slip_law import SLIP_FLOOR

FLOOR = SLIP_FLOOR

# the tangential rows of these tests read the slip velocity s from the state's v
ROWS = np.zeros((6, 3))
ROWS[:3, :3] = np.eye(3)


def direction(slip, stored) -> tuple[np.ndarray, bool]:
    """(u, own) for the slip velocity ``slip`` (3,) and the unit stored direction ``stored``."""
    y = np.zeros(body_kernel.STATE_SIZE)
    y[3] = 1.0
    y[7:10] = slip
    data = np.zeros(body_kernel.DATA_SIZE)
    data[body_kernel.D_SLIP : body_kernel.D_SLIP + 3] = stored
    u = np.zeros(3)
    own = body_solve.slip_direction(y, 3, data, ROWS, np.zeros(3), u)
    return u, bool(own)


def unit(angle_a: float, angle_b: float) -> np.ndarray:
    return np.array([math.cos(angle_a) * math.cos(angle_b), math.sin(angle_a) * math.cos(angle_b),
                     math.sin(angle_b)])  # fmt: skip


angles = st.floats(-math.pi, math.pi)


@settings(max_examples=200, deadline=None)
@given(a=angles, b=angles, speed=st.floats(2.0 * FLOOR, 10.0), turn=st.floats(0.0, 1.5))
def test_a_slip_on_the_stored_side_slides_along_its_own_velocity(a, b, speed, turn):
    stored = unit(a, b)
    slip = speed * unit(a + turn, b)  # less than 90 degrees from the stored direction
    u, own = direction(slip, stored)
    assert own
    np.testing.assert_allclose(u, slip / speed, atol=1e-15)


@settings(max_examples=200, deadline=None)
@given(a=angles, b=angles, along=st.floats(-10.0, 10.0))
def test_a_slip_along_the_stored_direction_keeps_its_side(a, b, along):
    # a planar slip: through zero the friction keeps decelerating it, as a planar block's
    stored = unit(a, b)
    u, _ = direction(along * stored, stored)
    np.testing.assert_allclose(u, stored, atol=1e-12)


@settings(max_examples=300, deadline=None)
@given(a=angles, b=angles, c=angles, d=angles, speed=st.floats(0.0, 1e-3),
       across=st.floats(-1.0, 1.0))  # fmt: skip
def test_the_direction_is_continuous_in_the_slip_velocity(a, b, c, d, speed, across):
    # slip velocities near the stored side's edge (s . r = 0) and near the floor: a change of
    # s by eps turns u by at most about 2 eps / max(|s|, SLIP_FLOOR)
    stored = unit(a, b)
    slip = speed * unit(c, d)
    slip -= (slip @ stored - across * FLOOR) * stored  # s . r within the floor of zero
    eps = 1e-3 * FLOOR
    u, _ = direction(slip, stored)
    for k in range(3):
        step = np.zeros(3)
        step[k] = eps
        moved, _ = direction(slip + step, stored)
        scale = max(np.linalg.norm(slip), FLOOR)
        assert np.linalg.norm(moved - u) <= 4.0 * eps / scale


def test_the_stored_side_edge_no_longer_swings_the_direction():
    # s across r: u is s's own direction on both sides of s . r = 0 (r itself before)
    stored = np.array([1.0, 0.0, 0.0])
    before, own_before = direction(np.array([1e-9, 1e-3, 0.0]), stored)
    after, own_after = direction(np.array([-1e-9, 1e-3, 0.0]), stored)
    assert own_before and not own_after
    np.testing.assert_allclose(before, [0.0, 1.0, 0.0], atol=1e-5)
    np.testing.assert_allclose(after, [0.0, 1.0, 0.0], atol=1e-5)
    assert after[0] > 0.0  # past r's side the component along r is reflected onto it


def test_a_slip_at_rest_takes_the_stored_direction():
    stored = np.array([0.6, 0.0, 0.8])
    u, own = direction(np.zeros(3), stored)
    assert not own
    np.testing.assert_allclose(u, stored, atol=1e-15)
