"""A Zeno tail of impacts is summed once the support no longer accelerates (issue #19).

After an impact whose opening contact cannot rise beyond the gap tolerance
before falling back, every later flight of the sequence would be lower still:
the interface lands on both contacts there (``diagnostics.zeno_landings``).
"""

from __future__ import annotations

import math

import numpy as np

from freestand.core.dynamics.results import SupportMotion
from freestand.core.dynamics.timehistory import simulate
from freestand.core.model import Block, Friction, Sliding, Stack

HALF_WIDTH, HALF_HEIGHT, MASS = 0.2, 1.0, 1000.0
BLOCK = Block(
    "block", MASS, MASS * ((2 * HALF_WIDTH) ** 2 + (2 * HALF_HEIGHT) ** 2) / 12.0,
    (0.0, HALF_HEIGHT), -HALF_WIDTH, HALF_WIDTH, 0.0, Friction(1.0, 1.0), Sliding.FREE,
)  # fmt: skip
STACK = Stack("one", (BLOCK,))


def kinetic_energy(velocity: np.ndarray) -> float:
    vx, vz, omega = velocity[0]
    return 0.5 * MASS * (vx**2 + vz**2) + 0.5 * BLOCK.inertia * omega**2


def free_rocking(duration: float = 9.0):
    omega = -0.3  # [rad/s] about the right corner
    velocity = np.array([[-omega * HALF_HEIGHT, omega * HALF_WIDTH, omega]])
    return simulate(STACK, lambda t: (0.0, 0.0), duration, method="general",
                    initial_velocity=velocity)  # fmt: skip


def test_free_rocking_lands_once_at_rest_without_gaining_energy():
    result = free_rocking()
    assert result.diagnostics.zeno_landings == 1
    impacts = result.events_of("impact")
    last = impacts[-1]
    assert last.motions == ("rest",)
    assert kinetic_energy(last.velocity_after) <= kinetic_energy(last.velocity_before)
    # from the landing on nothing moves (the rest state's 1e-9 m/s, rad/s)
    assert np.abs(result.velocity[result.time > last.time]).max() < 1e-9


def test_no_landing_while_the_support_still_moves():
    # the same block on a support that keeps shaking gently (far below uplift): the
    # sequence is resolved impact by impact, as before
    dt = 0.01
    time = np.arange(0.0, 9.0 + dt, dt)
    shaking = 0.05 * np.sin(2.0 * math.pi * 3.0 * time)
    omega = -0.3
    velocity = np.array([[-omega * HALF_HEIGHT, omega * HALF_WIDTH, omega]])
    result = simulate(STACK, SupportMotion(dt, shaking), method="general",
                      initial_velocity=velocity)  # fmt: skip
    assert result.status == "completed"
    assert result.diagnostics.zeno_landings == 0
    assert len(result.events_of("impact")) > 60


def rocking_pair() -> tuple[Stack, SupportMotion]:
    """Two blocks (the upper one sticks) under a 1 Hz half-sine, then a still support."""
    lower = Block.rectangle("lower", 0.6, 2.0, 1200.0, Friction(0.8, 0.7))
    upper = Block.rectangle("upper", 0.4, 1.2, 400.0, Friction(0.8, 0.7), level=2.0)
    dt = 0.005
    time = np.arange(0.0, 10.0 + dt, dt)
    pulse = np.where(time < 0.5, 1.2 * 9.81 * 0.3 * np.sin(2.0 * math.pi * time), 0.0)
    return Stack("pair", (lower, upper)), SupportMotion(dt, pulse)


def test_a_rocking_pair_lands_at_the_accumulation_of_its_impacts():
    # the pair rocks as one: once the flights rise less than 1e-3 of the largest lift,
    # the tail is summed and the pair lands at the instant the resolved impacts'
    # intervals accumulate at
    result = simulate(*rocking_pair(), 10.0)
    assert result.status == "completed"
    assert result.diagnostics.zeno_landings == 1
    impacts = result.events_of("impact")
    landing = impacts[-1]
    assert landing.motions == ("rest", "rest")
    times = np.array([event.time for event in impacts[:-1]])
    last, before = np.diff(times)[-1], np.diff(times)[-2]
    ratio = last / before  # the intervals fall geometrically (0.9365)
    accumulation = times[-1] + last * ratio / (1.0 - ratio)
    # measured: 9.268264 s against 9.268233 s extrapolated from the last two intervals
    # (0.30 s after the last resolved impact): within 1e-3 of that remaining time
    assert abs(landing.time - accumulation) <= 1e-3 * (accumulation - times[-1])
    # from the landing on nothing moves (round-off of the projection)
    assert np.abs(landing.velocity_after).max() < 1e-12
    assert np.abs(result.velocity[result.time >= landing.time]).max() < 1e-12


def test_the_tail_is_resolved_when_it_would_outlast_the_run():
    # the same pair run to 9.2 s, before its accumulation instant: no landing, every
    # impact of the tail located
    result = simulate(*rocking_pair(), 9.2)
    assert result.diagnostics.zeno_landings == 0
    assert len(result.events_of("impact")) > 70
