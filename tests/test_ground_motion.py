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


# ------------------------------------------------------- two horizontal components


def _pair(n=400, dt=0.01, seed=3):
    rng = np.random.default_rng(seed)
    return GroundMotion(
        dt, rng.normal(size=n), rng.normal(size=n) * 0.5, name="pair",
        horizontal_y=rng.normal(size=n) * 0.8,
    )  # fmt: skip


def test_second_horizontal_component_is_carried_through():
    motion = _pair()
    assert motion.components == ("horizontal", "horizontal_y", "vertical")
    assert motion.peak_horizontal_y == pytest.approx(np.max(np.abs(motion.horizontal_y)))
    scaled = motion.scaled(2.0)
    np.testing.assert_array_equal(scaled.horizontal_y, 2.0 * motion.horizontal_y)
    longer = motion.with_trailing_zeros(motion.duration + 1.0)
    assert longer.horizontal_y.size == longer.horizontal.size == motion.n_samples + 100
    assert np.all(longer.horizontal_y[motion.n_samples :] == 0.0)
    assert motion.horizontal_y_at(0.005) == pytest.approx(
        0.5 * (motion.horizontal_y[0] + motion.horizontal_y[1])
    )
    np.testing.assert_array_equal(motion.component("horizontal_y"), motion.horizontal_y)
    peak = motion.scaled_to_peak(1.0, component="horizontal_y")
    assert peak.peak_horizontal_y == pytest.approx(1.0)
    assert motion.with_horizontal_y(None).components == ("horizontal", "vertical")
    with pytest.raises(ValueError, match="same length"):
        GroundMotion(0.01, [0.0, 1.0], horizontal_y=[0.0, 1.0, 2.0])
    with pytest.raises(ValueError, match="no horizontal_y"):
        GroundMotion(0.01, [0.0, 1.0]).component("horizontal_y")


def test_a_planar_record_is_unchanged():
    motion = GroundMotion(0.01, [0.0, 1.0, -2.0], [0.0, 0.1, 0.2])
    assert motion.horizontal_y is None and motion.peak_horizontal_y is None
    assert motion.components == ("horizontal", "vertical")
    assert motion.scaled(3.0).horizontal_y is None
    assert motion.with_trailing_zeros(1.0).horizontal_y is None
    np.testing.assert_array_equal(motion.horizontal_y_at([0.0, 0.01]), [0.0, 0.0])


def test_rotation_of_the_horizontal_pair():
    motion = _pair()
    quarter = motion.rotated(np.pi / 2)
    # x' = y and y' = -x after a quarter turn (counter-clockwise seen from above)
    np.testing.assert_allclose(quarter.horizontal, motion.horizontal_y, atol=1e-15)
    np.testing.assert_allclose(quarter.horizontal_y, -motion.horizontal, atol=1e-15)
    np.testing.assert_array_equal(quarter.vertical, motion.vertical)
    # rotations compose and keep the horizontal magnitude at every instant
    composed = motion.rotated(0.3).rotated(0.5)
    direct = motion.rotated(0.8)
    np.testing.assert_allclose(composed.horizontal, direct.horizontal, atol=1e-14)
    np.testing.assert_allclose(composed.horizontal_y, direct.horizontal_y, atol=1e-14)
    assert composed.metadata["rotation"] == pytest.approx(0.8)
    np.testing.assert_allclose(
        np.hypot(direct.horizontal, direct.horizontal_y),
        np.hypot(motion.horizontal, motion.horizontal_y),
        rtol=1e-13,
    )
    # a record with one horizontal component moves along x: its rotation has both
    planar = GroundMotion(0.01, [0.0, 1.0, -2.0])
    turned = planar.rotated(np.pi / 6)
    np.testing.assert_allclose(turned.horizontal, np.cos(np.pi / 6) * planar.horizontal)
    np.testing.assert_allclose(turned.horizontal_y, -np.sin(np.pi / 6) * planar.horizontal)


def test_combine_three_components():
    x = np.arange(5.0)
    y = np.arange(9.0) * 0.5  # finer step, longer
    v = np.arange(3.0)
    motion = combine_components(x, 0.02, v, 0.02, horizontal_y=y, horizontal_y_dt=0.01)
    assert motion.dt == 0.01 and motion.n_samples == 9
    np.testing.assert_allclose(motion.horizontal, np.arange(9.0) * 0.5)
    np.testing.assert_allclose(motion.horizontal_y, y)
    np.testing.assert_allclose(motion.vertical[:5], [0, 0.5, 1, 1.5, 2])
    assert motion.metadata["combination"] == (
        "horizontal resampled from dt=0.02 s to 0.01 s; vertical resampled from dt=0.02 s to "
        "0.01 s; vertical padded with 4 zeros"
    )
    only_y = combine_components(x, 0.02, horizontal_y=x[:3], horizontal_y_dt=0.02)
    assert only_y.vertical is None and only_y.horizontal_y.size == 5


def test_floor_motion_filters_both_horizontal_components():
    from freestand.core.motion.response_spectrum import floor_motion

    motion = _pair()
    floor = floor_motion(motion, 2.5, 0.05)
    alone = floor_motion(GroundMotion(motion.dt, motion.horizontal_y), 2.5, 0.05)
    np.testing.assert_allclose(floor.horizontal_y, alone.horizontal, rtol=1e-12, atol=1e-12)
    np.testing.assert_array_equal(floor.vertical, motion.vertical)
