"""Property tests: spectrum bounds, floor filter linearity, baseline correction."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from freestand.core.motion.ground_motion import GroundMotion, baseline_correct
from freestand.core.motion.response_spectrum import SpectrumPlan, floor_motion, spectral_response

records = arrays(
    float,
    st.integers(20, 200),
    elements=st.floats(-10.0, 10.0, allow_nan=False, allow_infinity=False),
)


@settings(max_examples=40, deadline=None)
@given(records, st.sampled_from([0.0, 0.02, 0.05, 0.2]))
def test_plan_spectrum_equals_the_general_one_and_bounds_hold(a, damping):
    frequencies = np.array([0.3, 1.0, 4.0, 17.0, 60.0])
    plan = SpectrumPlan.build(frequencies, 0.01, damping)
    full, in_record = plan.pseudo_acceleration_bounds(a)
    reference = spectral_response(a, 0.01, frequencies, damping).pseudo_acceleration
    assert np.array_equal(full, reference)
    assert np.all(in_record <= full)


@settings(max_examples=40, deadline=None)
@given(records, st.floats(-3.0, 3.0).filter(lambda x: abs(x) > 1e-3))
def test_floor_motion_is_linear_and_filters_only_the_horizontal(a, factor):
    motion = GroundMotion(0.01, a, np.flip(a))
    floor = floor_motion(motion, 2.5, 0.05)
    scaled = floor_motion(motion.scaled(factor), 2.5, 0.05)
    scale = max(1.0, float(np.max(np.abs(floor.horizontal))))
    assert np.allclose(scaled.horizontal, factor * floor.horizontal, atol=1e-12 * scale)
    assert np.array_equal(floor.vertical, motion.vertical)
    assert floor.dt == motion.dt and floor.n_samples == motion.n_samples


@settings(max_examples=40, deadline=None)
@given(records)
def test_baseline_correction_ends_at_rest(a):
    dt = 0.01
    t = np.arange(a.size) * dt
    weight = np.sin(np.pi * t / t[-1]) ** 2 + 1e-3
    corrected = GroundMotion(dt, baseline_correct(a, dt, weight))
    scale = dt * a.size * (1.0 + float(np.max(np.abs(a))))
    assert abs(corrected.velocity()[-1]) < 1e-9 * scale
    assert abs(corrected.displacement()[-1]) < 1e-9 * scale * dt * a.size
