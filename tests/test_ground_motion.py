"""GroundMotion records, pulses, scaling and interpolation."""

from __future__ import annotations

import numpy as np
import pytest

from freestand.core.motion.ground_motion import (
    GroundMotion,
    combine_components,
    half_sine_pulse,
    one_cosine_pulse,
    one_sine_pulse,
    rectangular_pulse,
    resample,
    synthetic_ground_motion,
)
from freestand.core.motion.response_spectrum import spectral_response

G = 9.81


def test_basic_properties():
    motion = GroundMotion(0.01, [0.0, 1.0, -3.0, 2.0], [0.0, 0.5, 0.2, -0.1], name="x")
    assert motion.n_samples == 4
    assert motion.duration == pytest.approx(0.03)
    np.testing.assert_allclose(motion.time, [0, 0.01, 0.02, 0.03])
    assert motion.peak_horizontal == 3.0
    assert motion.peak_vertical == 0.5
    assert motion.peak_downward == 0.5
    with pytest.raises(ValueError):
        motion.horizontal[0] = 1.0  # frozen arrays


@pytest.mark.parametrize(
    "kwargs",
    [
        {"dt": 0.0, "horizontal": [0, 1]},
        {"dt": 0.01, "horizontal": [1.0]},
        {"dt": 0.01, "horizontal": [0, np.nan]},
        {"dt": 0.01, "horizontal": [0, 1], "vertical": [0, 1, 2]},
    ],
)
def test_invalid_records(kwargs):
    with pytest.raises(ValueError):
        GroundMotion(**kwargs)


def test_velocity_and_displacement_exact_for_constant_acceleration():
    motion = GroundMotion(0.1, np.full(11, 2.0))
    t = motion.time
    # exact for the piecewise-linear record: round-off only
    np.testing.assert_allclose(motion.velocity(), 2.0 * t, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(motion.displacement(), t**2, rtol=1e-12, atol=1e-15)


def test_velocity_and_displacement_exact_for_ramp():
    motion = GroundMotion(0.1, np.arange(11) * 0.1 * 3.0)  # a = 3 t
    t = motion.time
    np.testing.assert_allclose(motion.velocity(), 1.5 * t**2, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(motion.displacement(), 0.5 * t**3, rtol=1e-12, atol=1e-15)


def test_interpolation():
    motion = GroundMotion(0.1, [0.0, 1.0, 3.0], [1.0, 1.0, 1.0])
    assert motion.horizontal_at(0.05) == pytest.approx(0.5)
    assert motion.horizontal_at(0.15) == pytest.approx(2.0)
    values = motion.horizontal_at([-0.1, 0.2, 0.25, 0.3, 1.0])
    np.testing.assert_allclose(values, [0, 3, 1.5, 0, 0], atol=1e-12)  # round-off in t / dt
    assert motion.vertical_at(0.25) == pytest.approx(0.5)
    assert GroundMotion(0.1, [0.0, 1.0]).vertical_at(0.05) == 0.0


def test_scaled_to_peak():
    motion = synthetic_ground_motion(duration=3.0)
    scaled = motion.scaled_to_peak(0.4 * G)
    assert scaled.peak_horizontal == pytest.approx(0.4 * G, rel=1e-12)
    factor = 0.4 * G / motion.peak_horizontal
    np.testing.assert_allclose(scaled.vertical, motion.vertical * factor, rtol=1e-12)
    assert scaled.metadata["scale_factor"] == pytest.approx(factor)
    vertical = motion.scaled_to_peak(0.1 * G, component="vertical")
    assert vertical.peak_vertical == pytest.approx(0.1 * G, rel=1e-12)


def test_scaled_to_spectral():
    motion = synthetic_ground_motion(duration=3.0)
    scaled = motion.scaled_to_spectral(1.0 * G, 2.0, 0.05)
    psa = spectral_response(scaled, None, [2.0], 0.05).pseudo_acceleration[0]
    # linear oscillator: exact up to round-off
    assert psa == pytest.approx(1.0 * G, rel=1e-10)


def test_rectangular_pulse():
    motion = rectangular_pulse(2.0, 0.5, 0.01, total_duration=1.0)
    assert motion.n_samples == 101
    assert np.all(motion.horizontal[:51] == 2.0)
    assert np.all(motion.horizontal[51:] == 0.0)


@pytest.mark.parametrize(
    "factory, cycles, start",
    [(half_sine_pulse, 0.5, 0.0), (one_sine_pulse, 1.0, 0.0), (one_cosine_pulse, 1.0, 1.0)],
)
def test_sine_pulses(factory, cycles, start):
    by_frequency = factory(3.0, frequency=2.0, dt=0.001, total_duration=2.0)
    by_duration = factory(3.0, duration=cycles / 2.0, dt=0.001, total_duration=2.0)
    np.testing.assert_array_equal(by_frequency.horizontal, by_duration.horizontal)
    a = by_frequency.horizontal
    n_pulse = int(round(cycles / 2.0 / 0.001))
    assert a[0] == pytest.approx(3.0 * start)
    assert np.max(np.abs(a)) == pytest.approx(3.0, rel=1e-6)
    assert np.all(a[n_pulse + 1 :] == 0.0)
    assert by_frequency.duration == pytest.approx(2.0)
    with pytest.raises(ValueError):
        factory(3.0, frequency=2.0, duration=0.5, dt=0.001)
    with pytest.raises(ValueError):
        factory(3.0, frequency=2.0, dt=0.001, total_duration=0.1)


def test_resample_exact_on_finer_multiple():
    a = np.array([0.0, 1.0, -1.0, 2.0])
    fine = resample(a, 0.02, 0.005)
    assert fine.size == 13
    np.testing.assert_allclose(fine[::4], a)
    np.testing.assert_allclose(fine[1:4], [0.25, 0.5, 0.75])


def test_combine_components_rule():
    motion = combine_components([1.0, 2.0, 3.0, 4.0, 5.0], 0.01, [0.0, 2.0], 0.02)
    assert motion.dt == 0.01
    np.testing.assert_allclose(motion.vertical, [0.0, 1.0, 2.0, 0.0, 0.0])
    assert "padded with 2 zeros" in motion.metadata["combination"]


def test_synthetic_record_is_deterministic_and_at_rest_at_the_end():
    a = synthetic_ground_motion(duration=5.0)
    b = synthetic_ground_motion(duration=5.0)
    np.testing.assert_array_equal(a.horizontal, b.horizontal)
    assert a.peak_horizontal == pytest.approx(0.25 * G, rel=1e-12)
    # baseline correction: the ground ends at rest where it started (round-off)
    assert abs(a.velocity()[-1]) < 1e-12
    assert abs(a.displacement()[-1]) < 1e-12
