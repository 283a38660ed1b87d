"""Events of the compiled time history are located to the time tolerance, and the
peaks of a history are refined between its samples (freestand.core.dynamics)."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from freestand.core.dynamics.results import _peak_magnitude
from freestand.core.dynamics.timehistory import (
    SupportMotion,
    simulate,
    stack_kinematics,
)
from freestand.core.model import Block, Friction, Stack

G = 9.81
TIME_TOLERANCE = 1e-9  # simulate's default [s]


def rocking_pair() -> tuple[Stack, SupportMotion]:
    """The two blocks of benchmarks/engine.py (a), 1 Hz half-sine at 1.2 g tan(alpha)."""
    lower = Block.rectangle("lower", 0.6, 2.0, 1200.0, Friction(0.8, 0.7))
    upper = Block.rectangle("upper", 0.4, 1.2, 400.0, Friction(0.8, 0.7), level=2.0)
    dt = 0.005
    t = np.arange(int(round(10.0 / dt)) + 1) * dt
    peak = 1.2 * G * 0.3 / 1.0
    values = np.where(t < 0.5, peak * np.sin(2.0 * math.pi * t), 0.0)
    return Stack("pair", (lower, upper)), SupportMotion(dt, values)


def test_impacts_are_located_to_the_time_tolerance():
    # at each impact the recorded state (before the velocity jump) has its gap just
    # past zero, where the contact was open by more than the event's slack (1e-10 m) at
    # the step's start (every one here): closed within the time tolerance at its closing
    # velocity (Newton steps on the interpolant, then one or two checked RK4 states).
    # Located past the slack instead, the slow impacts came up to 1e-6 s late.
    stack, motion = rocking_pair()
    result = simulate(stack, motion, 10.0, method="general")
    assert result.status == "completed"
    impacts = result.events_of("impact")
    # the rocking's decaying impacts, each located, until the Zeno tail is summed once
    # the support is still and the flights rise less than 1e-3 of the largest lift (51
    # impacts, then the landing at the accumulation instant: docs/timehistory.md)
    assert len(impacts) > 50
    assert result.diagnostics.zeno_landings == 1
    landing = impacts[-1]
    assert landing.motions == ("rest", "rest")
    assert np.abs(result.velocity[result.time >= landing.time]).max() < 1e-12  # at rest
    for event in impacts[:-1]:
        row = int(np.flatnonzero(result.time == event.time)[0])
        kin = stack_kinematics(stack, result.position[row], event.velocity_before)
        gap = kin.gap[event.interface, event.contact]
        closing = -kin.gap_velocity[event.interface, event.contact]
        assert closing > 0.0
        # tolerance: the bracket's width (1e-9 s) at the closing velocity, plus 50 %
        # for the change of that velocity and rounding within it
        assert -1.5 * closing * TIME_TOLERANCE <= gap < 0.0


def _dense_peak(time, value, rate):
    """Reference: max |value| over the samples and over a dense evaluation of the cubic
    Hermite interpolant on every step where the rate changes sign."""
    peak = float(np.max(np.abs(value)))
    s = np.linspace(0.0, 1.0, 20001)
    for k in range(len(time) - 1):
        if rate[k] * rate[k + 1] >= 0.0:
            continue
        h = time[k + 1] - time[k]
        y0, y1, m0, m1 = value[k], value[k + 1], rate[k] * h, rate[k + 1] * h
        p = (
            (2 * s**3 - 3 * s**2 + 1) * y0
            + (s**3 - 2 * s**2 + s) * m0
            + (-2 * s**3 + 3 * s**2) * y1
            + (s**3 - s**2) * m1
        )
        peak = max(peak, float(np.max(np.abs(p))))
    return peak


@settings(max_examples=60, deadline=None)
@given(
    amplitude=st.floats(1e-6, 10.0),
    frequency=st.floats(0.2, 5.0),
    phase=st.floats(0.0, 2.0 * math.pi),
    samples=st.integers(5, 80),
)
def test_peak_is_refined_between_samples(amplitude, frequency, phase, samples):
    # a sine sampled coarsely: the peak is the Hermite interpolant's turning value,
    # not the largest sample (dense evaluation to 1/20000 of a step: its error is
    # below 1e-8 of the amplitude)
    time = np.linspace(0.0, 2.0, samples)
    omega = 2.0 * math.pi * frequency
    value = amplitude * np.sin(omega * time + phase)
    rate = amplitude * omega * np.cos(omega * time + phase)
    reference = _dense_peak(time, value, rate)
    assert math.isclose(_peak_magnitude(time, value, rate), reference, rel_tol=1e-8)


def test_peak_skips_non_finite_samples():
    time = np.array([0.0, 1.0, 2.0, 3.0])
    value = np.array([0.0, np.nan, 2.0, -1.0])
    rate = np.array([1.0, 1.0, 0.0, np.inf])
    assert _peak_magnitude(time, value, rate) == 2.0
