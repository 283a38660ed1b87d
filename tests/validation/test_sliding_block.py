"""Sliding of a rigid block on a rigid horizontal support (Coulomb friction).

Validation cases:

- rectangular pulse, block at rest: closed-form sliding displacement
  |s| = a t1^2 (a - mu g) / (2 mu g) (Newmark 1965, Geotechnique 15(2),
  139-160; the V^2 / (2 g N) (1 - N / A) of his rectangular-pulse analysis),
  also with a downward support acceleration during the pulse;
- a block below the sliding threshold mu_0 (g - a_v) does not move;
- work balance (property test): the work of the inertial force equals the
  energy dissipated by friction plus the kinetic energy left, computed
  independently from the output time histories.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from freestand.core.dynamics.sliding import rectangular_pulse_slide, slide_block
from freestand.core.motion.ground_motion import (
    GroundMotion,
    rectangular_pulse,
    synthetic_ground_motion,
)

G = 9.81


def test_closed_form_is_newmark():
    a, t1, mu = 0.5 * G, 0.5, 0.25
    closed = rectangular_pulse_slide(a, t1, 0.3, mu)
    newmark = a * t1**2 * (a - mu * G) / (2 * mu * G)
    v_ground = a * t1
    assert -closed.displacement == pytest.approx(newmark, rel=1e-14)
    assert -closed.displacement == pytest.approx(
        v_ground**2 / (2 * G * mu) * (1 - mu / (a / G)), rel=1e-14
    )
    assert closed.stop_time == pytest.approx(a * t1 / (mu * G), rel=1e-14)


@pytest.mark.parametrize("sign", [1.0, -1.0])
@pytest.mark.parametrize(
    "amplitude_g, duration, mu_static, mu_kinetic",
    [(0.5, 0.5, 0.3, 0.25), (0.8, 0.2, 0.5, 0.5), (0.3, 1.0, 0.2, 0.1)],
)
def test_rectangular_pulse_matches_closed_form(sign, amplitude_g, duration, mu_static, mu_kinetic):
    dt = 1e-4
    a = sign * amplitude_g * G
    closed = rectangular_pulse_slide(a, duration, mu_static, mu_kinetic)
    motion = rectangular_pulse(a, duration, dt, total_duration=closed.stop_time + 0.5)
    result = slide_block(motion, mu_static, mu_kinetic)
    assert result.status == "slid and stopped"
    assert result.slip_starts == 1
    assert result.reversals == 0
    # tolerance: the sampled pulse ends with a one-step ramp that adds the
    # impulse a dt / 2; its effect on displacement and stop time is of order
    # dt / t1 (2e-4 .. 5e-4 here), so 3 dt / t1 relative
    rel = 3 * dt / duration
    assert result.residual_slide == pytest.approx(closed.displacement, rel=rel)
    assert result.max_slide == pytest.approx(abs(closed.displacement), rel=rel)
    assert result.stop_time == pytest.approx(closed.stop_time, rel=rel)
    assert math.copysign(1, result.residual_slide) == -sign  # block lags behind
    # the velocity at the end of the pulse
    i1 = int(round(duration / dt))
    assert result.velocity[i1] == pytest.approx(closed.velocity_at_pulse_end, rel=rel)


def test_rectangular_pulse_error_is_first_order_in_dt():
    """The only error is the ramp at the end of the sampled pulse: O(dt)."""
    closed = rectangular_pulse_slide(0.5 * G, 0.5, 0.3, 0.25)
    errors = []
    for dt in (1e-3, 1e-4):
        motion = rectangular_pulse(0.5 * G, 0.5, dt, total_duration=1.5)
        errors.append(abs(slide_block(motion, 0.3, 0.25).residual_slide - closed.displacement))
    # tolerance: ratio 10 for first order, within 5 %
    assert errors[0] / errors[1] == pytest.approx(10.0, rel=0.05)


def test_rectangular_pulse_with_downward_acceleration():
    """N = m (g - a_v) during the pulse lowers the threshold and the friction."""
    dt, t1, a, a_v = 1e-4, 0.4, 0.28 * G, 0.2 * G
    closed = rectangular_pulse_slide(a, t1, 0.3, 0.25, vertical=a_v)
    assert closed.slides  # 0.28 g > 0.3 (g - 0.2 g) = 0.24 g, though below 0.3 g
    assert not rectangular_pulse_slide(a, t1, 0.3, 0.25).slides
    motion = rectangular_pulse(a, t1, dt, total_duration=closed.stop_time + 0.5)
    vertical = np.where(motion.horizontal != 0.0, a_v, 0.0)
    result = slide_block(motion.with_vertical(vertical), 0.3, 0.25)
    # tolerance: as for the horizontal pulse, 3 dt / t1 relative
    assert result.residual_slide == pytest.approx(closed.displacement, rel=3 * dt / t1)
    assert slide_block(motion, 0.3, 0.25).status == "no sliding"


@pytest.mark.parametrize("ratio", [0.5, 0.9, 0.999])
def test_below_threshold_no_motion(ratio):
    mu0 = 0.3
    motion = rectangular_pulse(ratio * mu0 * G, 0.5, 1e-3, total_duration=1.0)
    result = slide_block(motion, mu0, 0.2)
    assert result.status == "no sliding"
    assert result.slip_starts == 0
    # exact: nothing moves at all
    assert np.all(result.displacement == 0.0)
    assert np.all(result.velocity == 0.0)
    assert result.max_slide == 0.0
    assert result.friction_work == 0.0


def test_record_below_threshold_no_motion():
    motion = synthetic_ground_motion().scaled_to_peak(0.199 * G)
    result = slide_block(motion.with_vertical(None), 0.2, 0.15)
    assert result.status == "no sliding"
    assert np.all(result.displacement == 0.0)
    # a steady downward support acceleration of 0.05 g lowers the threshold to
    # 0.2 x 0.95 g = 0.19 g, below the horizontal peak
    downward = np.full(motion.n_samples, 0.05 * G)
    assert slide_block(motion.with_vertical(downward), 0.2, 0.15).status == "slid and stopped"


def test_contact_loss_is_reported():
    dt = 1e-3
    n = 1001
    t = np.arange(n) * dt
    horizontal = 0.5 * G * np.sin(2 * np.pi * 2 * t)
    vertical = np.where((t > 0.3) & (t < 0.35), 1.2 * G, 0.0)
    result = slide_block(GroundMotion(dt, horizontal, vertical), 0.3, 0.3)
    assert result.contact_lost_time > 0.03
    assert any("leave the support" in m for m in result.messages)


def test_zero_kinetic_friction_keeps_sliding():
    motion = rectangular_pulse(0.2 * G, 0.1, 1e-3, total_duration=0.5)
    result = slide_block(motion, 0.1, 0.0)
    assert result.status == "still sliding"
    assert result.velocity[-1] == pytest.approx(-(0.2 * G) * 0.1, rel=0.02)


def _trapezoid(y, dt):
    return float(np.sum(0.5 * (y[:-1] + y[1:])) * dt)


@settings(max_examples=30, deadline=None)
@given(
    amplitudes=st.lists(st.floats(0.05, 0.6), min_size=3, max_size=3),
    frequencies=st.lists(st.floats(0.5, 8.0), min_size=3, max_size=3),
    phases=st.lists(st.floats(0.0, 2 * math.pi), min_size=3, max_size=3),
    mu_static=st.floats(0.05, 0.5),
    kinetic_ratio=st.floats(0.3, 1.0),
    vertical_amplitude=st.floats(0.0, 0.5),
)
def test_work_balance(
    amplitudes, frequencies, phases, mu_static, kinetic_ratio, vertical_amplitude
):
    """W_base = W_friction + s'^2/2 at the end, all per unit mass.

    W_base = -int a_h s' dt and W_friction = mu int (g - a_v) |s'| dt are
    integrated here from the output samples (trapezoid rule), independently
    of the solver's own event-exact integrals, which must agree too.
    """
    dt = 5e-4
    duration = 3.0
    t = np.arange(int(duration / dt) + 1) * dt
    taper = np.sin(np.pi * t / duration) ** 2
    horizontal = (
        G
        * taper
        * sum(
            a * np.sin(2 * np.pi * f * t + p)
            for a, f, p in zip(amplitudes, frequencies, phases, strict=True)
        )
    )
    vertical = vertical_amplitude * G * taper * np.sin(2 * np.pi * 7.0 * t)
    mu_kinetic = kinetic_ratio * mu_static
    result = slide_block(GroundMotion(dt, horizontal, vertical), mu_static, mu_kinetic)
    assert result.friction_work >= 0.0
    # solver's own integrals: exact balance up to round-off
    kinetic_end = 0.5 * result.velocity[-1] ** 2
    scale = max(result.base_work, 1e-12)
    assert result.base_work == pytest.approx(result.friction_work + kinetic_end, abs=1e-9 * scale)
    # independent integrals from the samples (record followed by rest)
    n = result.time.size
    ah = np.zeros(n)
    av = np.zeros(n)
    ah[: t.size] = horizontal
    av[: t.size] = vertical
    w_base = _trapezoid(-ah * result.velocity, dt)
    w_friction = _trapezoid(mu_kinetic * (G - av) * np.abs(result.velocity), dt)
    # tolerance: trapezoid rule on piecewise-smooth samples with kinks at the
    # stick/slip events, O(dt^2): 1e-3 of the work plus 1e-7 J/kg
    tol = 1e-3 * max(abs(w_base), abs(w_friction)) + 1e-7
    assert w_base == pytest.approx(result.base_work, abs=tol)
    assert w_friction == pytest.approx(result.friction_work, abs=tol)
    # the block ends at rest (kinetic friction > 0)
    assert result.velocity[-1] == 0.0


def _small_step_slide(motion, mu_static, mu_kinetic, substeps):
    """Independent reference: explicit small steps with stick/slip switching, O(h)."""
    h = motion.dt / substeps
    n_fine = (motion.n_samples - 1) * substeps + 1
    t = np.arange(n_fine) * h
    ah = motion.horizontal_at(t)
    av = motion.vertical_at(t)
    s = v = 0.0
    s_max = 0.0
    for k in range(n_fine - 1):
        a_mid = 0.5 * (ah[k] + ah[k + 1])
        n_mid = G - 0.5 * (av[k] + av[k + 1])
        if v == 0.0:
            if abs(a_mid) <= mu_static * n_mid:
                continue
            direction = -np.sign(a_mid)
        else:
            direction = np.sign(v)
        acc = -a_mid - direction * mu_kinetic * n_mid
        v_new = v + acc * h
        if v != 0.0 and np.sign(v_new) != direction:
            fraction = v / (v - v_new)  # stop inside the step
            s += 0.5 * v * fraction * h
            v = 0.0
        else:
            s += 0.5 * (v + v_new) * h
            v = v_new
        s_max = max(s_max, abs(s))
    return s, s_max


def test_matches_small_step_integration():
    """A record with stick, slip and reversals against an independent small-step solver."""
    dt = 2e-3
    t = np.arange(1001) * dt
    horizontal = (
        G
        * np.sin(np.pi * t / 2.0) ** 2
        * (0.45 * np.sin(2 * np.pi * 1.3 * t) + 0.3 * np.sin(2 * np.pi * 3.1 * t + 1.0))
    )
    vertical = 0.2 * G * np.sin(2 * np.pi * 5.0 * t)
    motion = GroundMotion(dt, horizontal, vertical)
    result = slide_block(motion, 0.3, 0.22, until_rest=False)
    assert result.slip_starts >= 2
    s_ref, s_max_ref = _small_step_slide(motion, 0.3, 0.22, substeps=100)
    # tolerance: the reference is first order in its step h = dt / 100 (switching
    # inside a step); 1e-3 of the peak slide
    assert result.displacement[-1] == pytest.approx(s_ref, abs=1e-3 * s_max_ref)
    assert result.max_slide == pytest.approx(s_max_ref, rel=1e-3)
