"""Response spectra by the exact piecewise-linear recursion (Nigam and Jennings 1969).

Cross-checks against independent solutions of
u'' + 2 zeta omega u' + omega^2 u = -a_g(t):

- the closed-form step coefficients against the matrix exponential of the
  augmented linear system;
- a sine input against the analytic solution (transient + steady state, then
  free vibration);
- a random record against a direct high-resolution integration
  (scipy ``solve_ivp``, DOP853, tight tolerances, on the linearly interpolated
  record), including oscillator periods of 1-10 time steps and frequencies in
  any order.

Known faults of public codes this guards against (see docs/records.md): the
PGA returned for periods below 6 dt, and no refinement when periods are given
in descending order.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp
from scipy.linalg import expm

from freestand.core.motion.response_spectrum import (
    _closed_form_coefficients,
    nigam_jennings_coefficients,
    oscillator_response,
    response_spectrum,
    spectral_response,
)
from freestand.core.motion.spectra import Spectrum


def _expm_coefficients(omega, zeta, h):
    m = np.array(
        [[0, 1, 0, 0], [-(omega**2), -2 * zeta * omega, -1, 0], [0, 0, 0, 1], [0, 0, 0, 0.0]]
    )
    e = expm(m * h)
    a = e[:2, :2]
    b = np.column_stack([e[:2, 2] - e[:2, 3] / h, e[:2, 3] / h])
    return a, b


@pytest.mark.parametrize("zeta", [0.0, 0.02, 0.05, 0.2, 0.7, 0.95])
@pytest.mark.parametrize("omega_h", [0.1, 0.3, 1.0, 3.0, 10.0, 40.0])
def test_closed_form_coefficients_match_matrix_exponential(zeta, omega_h):
    h = 0.005
    omega = omega_h / h
    a_ref, b_ref = _expm_coefficients(omega, zeta, h)
    c = np.array(_closed_form_coefficients(omega, zeta, h))
    a = c[:4].reshape(2, 2)
    b = c[4:].reshape(2, 2)
    # tolerance: round-off only, relative to the largest entry of each row
    # (velocity rows are omega times larger than displacement rows)
    for got, ref in ((a, a_ref), (b, b_ref)):
        scale = np.max(np.abs(ref), axis=1, keepdims=True)
        assert np.all(np.abs(got - ref) <= 1e-11 * scale)


@pytest.mark.parametrize("frequency", [1e-3, 0.05, 1.0, 10.0, 100.0])
def test_public_coefficients_exact_for_all_steps(frequency):
    """The public coefficients switch to the matrix exponential for small omega h."""
    h = 0.005
    a_ref, b_ref = _expm_coefficients(2 * math.pi * frequency, 0.05, h)
    a, b = nigam_jennings_coefficients(frequency, 0.05, h)
    # tolerance: 1e-11 of the row scale (round-off)
    for got, ref in ((a, a_ref), (b, b_ref)):
        scale = np.max(np.abs(ref), axis=1, keepdims=True)
        assert np.all(np.abs(got - ref) <= 1e-11 * scale)


# --------------------------------------------------------------- sine input


def _sine_solution(amplitude, forcing_omega, omega, zeta, t_end):
    """Analytic u(t) for a_g = A sin(W t) on [0, t_end], free vibration after."""
    w, W, z = omega, forcing_omega, zeta
    wd = w * math.sqrt(1 - z * z)
    det = (w * w - W * W) ** 2 + (2 * z * w * W) ** 2
    c = -amplitude * (w * w - W * W) / det
    d = amplitude * 2 * z * w * W / det
    e = -d
    f = (z * w * e - W * c) / wd

    def forced(t):
        return (
            c * np.sin(W * t)
            + d * np.cos(W * t)
            + np.exp(-z * w * t) * (e * np.cos(wd * t) + f * np.sin(wd * t))
        )

    def forced_velocity(t):
        decay = np.exp(-z * w * t)
        return (
            c * W * np.cos(W * t)
            - d * W * np.sin(W * t)
            + decay
            * ((-z * w * e + wd * f) * np.cos(wd * t) + (-z * w * f - wd * e) * np.sin(wd * t))
        )

    u_end = float(forced(t_end))
    v_end = float(forced_velocity(t_end))

    def u(t):
        t = np.asarray(t, dtype=float)
        tau = t - t_end
        free = np.exp(-z * w * tau) * (
            u_end * np.cos(wd * tau) + (v_end + z * w * u_end) / wd * np.sin(wd * tau)
        )
        return np.where(t <= t_end, forced(np.minimum(t, t_end)), free)

    return u


SINE_AMPLITUDE = 2.0  # m/s^2
SINE_FREQUENCY = 1.5  # Hz
SINE_CYCLES = 2
SINE_DT = 0.002  # s: forcing sampled 333 times per cycle


def _sine_record():
    t_end = SINE_CYCLES / SINE_FREQUENCY
    n = int(round(t_end / SINE_DT)) + 1
    t = np.arange(n) * SINE_DT
    return t, SINE_AMPLITUDE * np.sin(2 * math.pi * SINE_FREQUENCY * t), t_end


@pytest.mark.parametrize("frequency", [0.5, 1.5, 6.0])
def test_time_history_matches_analytic_sine_solution(frequency):
    t, a, t_end = _sine_record()
    omega = 2 * math.pi * frequency
    exact = _sine_solution(SINE_AMPLITUDE, 2 * math.pi * SINE_FREQUENCY, omega, 0.05, t_end)
    response = oscillator_response(a, frequency, 0.05, SINE_DT)
    u_ref = exact(t)
    # tolerance: the record is the sine joined by straight lines; that changes
    # the forcing by up to A (W dt)^2 / 8 = 4.4e-5 A, so 2e-4 of the peak
    assert np.max(np.abs(response.displacement - u_ref)) <= 2e-4 * np.max(np.abs(u_ref))


@pytest.mark.parametrize("frequency", [0.3, 1.5, 5.0, 40.0, 150.0, 400.0])
def test_spectrum_matches_analytic_sine_peak(frequency):
    """Includes oscillator periods of 12.5, 3.3 and 1.25 time steps."""
    t, a, t_end = _sine_record()
    omega = 2 * math.pi * frequency
    exact = _sine_solution(SINE_AMPLITUDE, 2 * math.pi * SINE_FREQUENCY, omega, 0.05, t_end)
    period = 1 / frequency
    dense = np.arange(0.0, t_end + period, min(period / 400, SINE_DT / 10))
    psa_ref = omega**2 * np.max(np.abs(exact(dense)))
    psa = spectral_response(a, SINE_DT, [frequency], 0.05).pseudo_acceleration[0]
    # tolerance: 5e-4 relative, from the straight-line representation of the
    # sine (4.4e-5 of the forcing) and the dense-grid peak of the reference
    assert psa == pytest.approx(psa_ref, rel=5e-4)


# ------------------------------------------------------ direct integration

RECORD_DT = 0.01  # s: coarse on purpose, so that short periods are few steps


def _random_record(seed=7, duration=2.0):
    rng = np.random.default_rng(seed)
    n = int(round(duration / RECORD_DT)) + 1
    t = np.arange(n) * RECORD_DT
    envelope = np.minimum(1.0, t / 0.5) * np.exp(-0.5 * np.maximum(t - 1.5, 0))
    return rng.normal(0.0, 2.0, n) * envelope


def _direct_peak(acceleration, dt, frequency, zeta):
    """max |u| by solve_ivp on the linearly interpolated record (+ one free period)."""
    omega = 2 * math.pi * frequency
    n = acceleration.size
    times = np.arange(n + 1) * dt
    values = np.append(acceleration, 0.0)  # the record is followed by rest
    t_end = times[-1] + 1.0 / frequency

    def rhs(t, y):
        a_g = np.interp(t, times, values, right=0.0)
        return [y[1], -a_g - 2 * zeta * omega * y[1] - omega**2 * y[0]]

    solution = solve_ivp(
        rhs,
        (0.0, t_end),
        [0.0, 0.0],
        method="DOP853",
        rtol=1e-11,
        atol=1e-14,
        max_step=dt / 2,
        dense_output=True,
    )
    assert solution.success
    grid = np.arange(0.0, t_end, min(dt, 1.0 / frequency) / 200)
    return np.max(np.abs(solution.sol(grid)[0]))


DIRECT_FREQUENCIES = [60.0, 0.7, 12.0, 90.0, 3.0, 25.0, 40.0]  # any order; T = 1.1 .. 143 dt


@pytest.fixture(scope="module")
def direct_reference():
    acceleration = _random_record()
    peaks = [_direct_peak(acceleration, RECORD_DT, f, 0.05) for f in DIRECT_FREQUENCIES]
    return acceleration, np.array(peaks)


def test_spectrum_matches_direct_integration(direct_reference):
    acceleration, peaks = direct_reference
    response = spectral_response(acceleration, RECORD_DT, DIRECT_FREQUENCIES, 0.05)
    # tolerance: 2e-5 relative; both solve the same piecewise-linear problem,
    # the reference to rtol 1e-11 with its peak read on a grid of T/200 or dt/200
    np.testing.assert_allclose(response.displacement, peaks, rtol=2e-5)


def test_short_periods_are_not_the_pga(direct_reference):
    """Below 6 dt the spectrum is resolved, not replaced by the peak ground acceleration."""
    acceleration, peaks = direct_reference
    pga = np.max(np.abs(acceleration))
    f = np.array(DIRECT_FREQUENCIES)
    short = 1.0 / f < 6 * RECORD_DT
    assert np.count_nonzero(short) >= 3
    psa = spectral_response(acceleration, RECORD_DT, f, 0.05).pseudo_acceleration
    psa_ref = (2 * math.pi * f) ** 2 * peaks
    np.testing.assert_allclose(psa[short], psa_ref[short], rtol=2e-5)  # as above
    # the exact answer differs from the PGA by more than 10 % here
    assert np.all(np.abs(psa_ref[short] / pga - 1) > 0.1)


def test_without_substeps_short_periods_are_wrong(direct_reference):
    """Sub-stepping matters: one step per sample misses short-period peaks."""
    acceleration, peaks = direct_reference
    coarse = spectral_response(
        acceleration, RECORD_DT, DIRECT_FREQUENCIES, 0.05, min_steps_per_period=1
    )
    assert np.max(np.abs(coarse.displacement / peaks - 1)) > 1e-2


def test_frequency_order_does_not_matter():
    acceleration = _random_record(seed=3)
    f = np.array(DIRECT_FREQUENCIES)
    ascending = spectral_response(acceleration, RECORD_DT, np.sort(f), 0.05)
    descending = spectral_response(acceleration, RECORD_DT, np.sort(f)[::-1], 0.05)
    shuffled = spectral_response(acceleration, RECORD_DT, f, 0.05)
    order = np.argsort(f)
    # exact: every frequency is computed on its own
    np.testing.assert_array_equal(descending.displacement[::-1], ascending.displacement)
    np.testing.assert_array_equal(shuffled.displacement[order], ascending.displacement)
    np.testing.assert_array_equal(descending.substeps[::-1], ascending.substeps)
    spectrum = response_spectrum(acceleration, RECORD_DT, f[::-1], 0.05)
    assert isinstance(spectrum, Spectrum)
    np.testing.assert_array_equal(spectrum.frequency, np.sort(f))
    np.testing.assert_array_equal(spectrum.acceleration, ascending.pseudo_acceleration)


def test_spectrum_is_a_shared_spectrum_type():
    acceleration = _random_record(seed=4)
    spectrum = response_spectrum(acceleration, RECORD_DT, damping=0.02, component="vertical")
    assert spectrum.direction == "vertical"
    assert spectrum.damping == 0.02
    assert np.all(np.diff(spectrum.frequency) > 0)
    # rigid limit: far above the record's content PSA tends to the PGA;
    # tolerance 1 % at 100 Hz for a record sampled at 100 Hz
    pga = np.max(np.abs(acceleration))
    assert spectrum.acceleration_at(100.0) == pytest.approx(pga, rel=0.05)


@settings(max_examples=25, deadline=None)
@given(
    seed=st.integers(0, 2**16),
    factor=st.floats(-5.0, 5.0).filter(lambda x: abs(x) > 1e-3),
    zeta=st.sampled_from([0.0, 0.02, 0.05, 0.1]),
)
def test_spectrum_is_linear_and_symmetric_in_the_record(seed, factor, zeta):
    """SD(c a_g) = |c| SD(a_g): the oscillator is linear and the peak takes |.|."""
    acceleration = _random_record(seed=seed, duration=1.0)
    f = [0.5, 4.0, 30.0, 120.0]
    base = spectral_response(acceleration, RECORD_DT, f, zeta)
    scaled = spectral_response(factor * acceleration, RECORD_DT, f, zeta)
    # tolerance: round-off only
    np.testing.assert_allclose(scaled.displacement, abs(factor) * base.displacement, rtol=1e-10)
