"""Rocking of a single rigid block: Housner (1963) impact law, free rocking, overturning.

Sources:
- G. W. Housner (1963), "The behavior of inverted pendulum structures during
  earthquakes", Bull. Seismol. Soc. Am. 53(2), 403-417: eq. 4, the angular
  velocity ratio at impact from the conservation of angular momentum about
  the new pivot, ``1 - 2 m R^2 sin^2(alpha) / I_O`` (= ``1 - 1.5 sin^2(alpha)``
  for a homogeneous rectangle); eq. 9, the shortest rectangular pulse that
  overturns a slender block, ``t1 = ln[A / (A - 1)] / p`` with
  ``A = a / (g alpha)`` and ``p^2 = m g R / I_O`` (linearised).
- Between impacts the free rocking of the exact (non-linear) equation
  (Zhang and Makris 2001, J. Eng. Mech. 127(5), eqs. 10-12) conserves
  ``E = I_O omega^2 / 2 + m g R cos(alpha - |theta|)``; the time from a
  turning point theta_m to the impact follows by quadrature.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

from freestand.core.dynamics.timehistory import simulate
from freestand.core.model import Block, Friction, Stack

G = 9.81


def homogeneous_block(half_width: float, half_height: float, mass: float = 500.0) -> Block:
    return Block(
        name="block",
        mass=mass,
        inertia=mass * (half_width**2 + half_height**2) / 3.0,
        centre=(0.0, half_height),
        base_left=-half_width,
        base_right=half_width,
        base_level=0.0,
        friction=Friction(1.0, 1.0),  # enough friction for pure rocking (no slip at impacts)
    )


def tilted(block: Block, angle: float) -> np.ndarray:
    pivot = np.array([block.base_left, 0.0])  # angle > 0: on the left corner
    arm = np.array(block.centre) - pivot
    c, s = math.cos(angle), math.sin(angle)
    moved = pivot + np.array([c * arm[0] - s * arm[1], s * arm[0] + c * arm[1]])
    return np.array([*(moved - np.array(block.centre)), angle])


def quarter_cycle(theta_max: float, alpha: float, radius: float, inertia_pivot: float, m: float):
    """Time [s] from the turning point theta_max to theta = 0 (exact free rocking)."""

    def integrand(u):  # theta = theta_max - u^2 removes the 1/sqrt singularity
        theta = theta_max - u * u
        drop = math.cos(alpha - theta_max) - math.cos(alpha - theta)
        return 2.0 * u / math.sqrt(2.0 * m * G * radius * drop / inertia_pivot)

    return quad(integrand, 0.0, math.sqrt(theta_max), epsabs=1e-13, epsrel=1e-12)[0]


@pytest.mark.parametrize("half_width, half_height", [(0.2, 0.6), (0.25, 1.0), (0.5, 0.8)])
def test_free_rocking_follows_housner_impacts_and_conserves_energy(half_width, half_height):
    block = homogeneous_block(half_width, half_height)
    m = block.mass
    alpha = math.atan(half_width / half_height)
    radius = math.hypot(half_width, half_height)
    inertia_pivot = block.inertia + m * radius**2
    ratio = 1.0 - 1.5 * math.sin(alpha) ** 2  # Housner 1963 eq. 4, homogeneous rectangle
    theta0 = 0.8 * alpha
    result = simulate(
        Stack("one", (block,)),
        lambda t: (0.0, 0.0),
        3.0,
        initial_position=tilted(block, theta0),
    )
    assert result.status == "completed"
    impacts = result.events_of("impact")
    assert len(impacts) >= 3

    # angular-velocity ratio at every impact: the impact law reproduces eq. 4 to round-off
    # (all but the last, where the sequence's tail is summed and the block lands at rest:
    # after 5 impacts for the squattest block)
    located = [event for event in impacts if event.motions != ("rest",)]
    assert len(located) >= 3
    for event in located[:6]:
        before, after = event.velocity_before[0, 2], event.velocity_after[0, 2]
        assert after / before == pytest.approx(ratio, rel=1e-9)
        # the new pivot does not slip, the old one lifts: rotation about the new corner only
        assert abs(event.velocity_after[0, 1]) > 0.0

    # impact times and velocities against the exact free-rocking quadrature
    time, theta_max = 0.0, theta0
    for event in impacts[:3]:
        time += quarter_cycle(theta_max, alpha, radius, inertia_pivot, m)
        omega_in = math.sqrt(2 * m * G * radius * (math.cos(alpha - theta_max) - math.cos(alpha)))
        omega_in /= math.sqrt(inertia_pivot)
        # events are located to 1e-9 s; RK4 at 1 ms: 1e-6 relative on times and velocities
        assert event.time == pytest.approx(time, rel=1e-6)
        assert abs(event.velocity_before[0, 2]) == pytest.approx(omega_in, rel=1e-6)
        omega_out = ratio * omega_in
        rise = inertia_pivot * omega_out**2 / (2 * m * G * radius)
        theta_max = alpha - math.acos(math.cos(alpha) + rise)
        time += quarter_cycle(theta_max, alpha, radius, inertia_pivot, m)

    # energy conserved between impacts (to 1e-8 relative with RK4 at 1 ms)
    v = result.velocity[:, 0]
    energy = 0.5 * m * (v[:, 0] ** 2 + v[:, 1] ** 2) + 0.5 * block.inertia * v[:, 2] ** 2
    energy += m * G * (half_height + result.position[:, 0, 1])
    impact_times = [event.time for event in impacts]
    edges = [0.0, *impact_times, result.time[-1] + 1.0]
    for start, stop in zip(edges[:-1], edges[1:], strict=True):
        inside = (result.time > start) & (result.time < stop)
        if inside.sum() > 2:
            spread = np.ptp(energy[inside])
            assert spread <= 1e-8 * energy[0]


@pytest.mark.parametrize("amplitude_ratio", [2.0, 4.0])
def test_rectangular_pulse_overturning_duration_housner(amplitude_ratio):
    """Housner eq. 9 for a slender block (alpha = 0.05): 1 % shorter stays, 1 % longer overturns.

    Eq. 9 is linearised; for alpha = 0.05 rad the exact equation differs by
    O(alpha^2) ~ 0.1 %, inside the +-1 % bracket.
    """
    block = homogeneous_block(0.05, 1.0, mass=100.0)
    alpha = math.atan(0.05)
    radius = math.hypot(0.05, 1.0)
    p = math.sqrt(3 * G / (4 * radius))
    critical = math.log(amplitude_ratio / (amplitude_ratio - 1.0)) / p
    amplitude = amplitude_ratio * G * alpha
    stack = Stack("slender", (block,))
    outcomes = {}
    for factor in (0.99, 1.01):
        duration = factor * critical
        result = simulate(
            stack,
            lambda t, d=duration: (amplitude if t < d else 0.0, 0.0),
            6.0,
            excitation_end=duration,
        )
        assert result.status == "completed"
        outcomes[factor] = result
    assert not outcomes[0.99].overturned[0]
    assert outcomes[0.99].max_rotation[0] < alpha
    assert outcomes[1.01].overturned[0]
    # declared only after the pulse, never at |theta| = alpha during it
    assert outcomes[1.01].overturn_time[0] > 1.01 * critical
    assert outcomes[1.01].events[-1].kind == "overturn"


def test_block_lying_on_its_side_is_overturned_while_excitation_acts():
    """A long strong pulse tips the block over: reported when |phi| reaches pi/2."""
    block = homogeneous_block(0.1, 0.5, mass=50.0)
    result = simulate(Stack("one", (block,)), lambda t: (0.6 * G, 0.0), 3.0)
    assert result.overturned[0]
    assert result.events[-1].kind == "overturn"
    rotation = result.relative_rotation[:, 0]
    assert np.nanmax(np.abs(rotation)) == pytest.approx(0.5 * math.pi, abs=1e-6)
    assert np.all(np.isnan(result.position[result.time > result.overturn_time[0], 0]))
