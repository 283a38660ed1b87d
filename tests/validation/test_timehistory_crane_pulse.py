"""The crane's two-block x-z configurations under a short strong half-sine pulse.

Model: examples/crane.toml (paper section 4, Table 1). Pulse: support
acceleration 10 m/s^2 (about 1 g) as a half sine of 0.3 s, then free
motion. Expected physics (paper section 3: the cart rocks about the wheel on
the side the inertial force pushes to; Housner 1963 for the rocking):

- pushed towards its end stop (the outer end of the bridge) the cart cannot
  slide: it rocks about its outer wheel, lands back on both wheels without
  overturning, and then slides inwards a little after the landing impact
  (friction mu = 0.2 cannot hold the horizontal momentum of the landing);
- the bridge (wheels 9.8 m apart, no sliding along its span) stays put, so the
  cart moves as it would on a rigid support;
- the two end positions are mirror images.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from freestand.core.dynamics.timehistory import simulate
from freestand.core.model import Stack

AMPLITUDE = 10.0  # m/s^2
DURATION = 0.3  # s


def half_sine(sign: float):
    return lambda t: (
        sign * AMPLITUDE * math.sin(math.pi * t / DURATION) if t < DURATION else 0.0,
        0.0,
    )


@pytest.fixture(scope="module")
def cart_right(crane_model):
    stack = crane_model.configuration("x-z cart right")
    # support accelerating to -x: inertial force +x, towards the right end stop
    return stack, simulate(stack, half_sine(-1.0), 2.5, excitation_end=DURATION)


def test_cart_rocks_about_its_outer_wheel_and_comes_back(cart_right):
    stack, result = cart_right
    assert result.status == "completed"
    cart = result.block_index("cart")
    assert not result.overturned.any()
    first = result.events[1]
    assert (first.kind, first.interface, first.contact) == (
        "lift-off",
        cart,
        0,
    )  # inner wheel A lifts
    assert first.motions == ("rest", "rock")
    rotation = result.relative_rotation[:, cart]
    # rocks clockwise about the right (outer) wheel B first: negative rotation; after the
    # landing impact it rocks back on A with less amplitude (energy lost at the impact)
    assert rotation.min() < -0.01
    assert rotation[: np.argmin(rotation)].max() < 1e-12
    assert rotation.max() < 0.5 * -rotation.min()
    assert result.max_rotation[cart] == pytest.approx(-rotation.min())
    alpha = math.atan2(1.90 - 0.57, 4.03 - 1.20)  # overturning angle about B
    assert result.max_rotation[cart] < 0.5 * alpha
    # back on both wheels at the end, at rest
    assert abs(rotation[-1]) < 1e-9
    assert np.max(np.abs(result.velocity[-1])) < 1e-6
    assert result.events[-1].motions == ("rest", "rest")
    # it landed by an impact and slid inwards (away from the stop), never beyond the stop
    assert result.events_of("impact")
    assert result.slide[:, cart].max() <= 1e-7 and result.slide[-1, cart] < -0.01
    # the bridge does not move
    assert np.nanmax(np.abs(result.position[:, 0])) < 1e-9
    assert not result.free_flight.any()


def test_bridge_stays_so_the_cart_moves_as_on_a_rigid_support(crane_model, cart_right):
    stack, result = cart_right
    cart = stack.blocks[1]
    alone = Stack(
        "cart alone",
        (replace(cart, base_level=0.0, centre=(cart.centre[0], cart.centre[1] - cart.base_level)),),
    )
    single = simulate(alone, half_sine(-1.0), 2.5, excitation_end=DURATION)
    # same equations once the bridge is at rest: agreement to the event-location tolerance
    assert single.max_rotation[0] == pytest.approx(result.max_rotation[1], rel=1e-6)
    assert single.slide[-1, 0] == pytest.approx(result.slide[-1, 1], rel=1e-6)


def test_the_two_end_positions_are_mirror_images(crane_model, cart_right):
    _, right = cart_right
    left_stack = crane_model.configuration("x-z cart left")
    left = simulate(left_stack, half_sine(+1.0), 2.5, excitation_end=DURATION)
    assert left.max_rotation[1] == pytest.approx(right.max_rotation[1], rel=1e-9)
    assert left.slide[-1, 1] == pytest.approx(-right.slide[-1, 1], rel=1e-9)
    assert [e.kind for e in left.events] == [e.kind for e in right.events]


def test_time_step_convergence(crane_model):
    """Peak rotation and landing time converge with the step (RK4 between events)."""
    stack = crane_model.configuration("x-z cart right")
    peaks, landings = [], []
    for step in (4e-3, 2e-3, 1e-3):
        result = simulate(stack, half_sine(-1.0), 1.0, max_step=step, excitation_end=DURATION)
        peaks.append(result.max_rotation[1])
        landings.append(result.events_of("impact")[0].time)
    # successive differences shrink at least 8-fold per halving (4th order would give 16)
    assert abs(peaks[1] - peaks[2]) <= abs(peaks[0] - peaks[1]) / 8 + 1e-12
    assert abs(landings[1] - landings[2]) <= abs(landings[0] - landings[1]) / 8 + 1e-9
    assert abs(peaks[1] - peaks[2]) < 1e-7 * peaks[2]
