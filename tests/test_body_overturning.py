"""The 3-D body's pulse overturning search (core): geometry, bad input, what it reports."""

import math

import numpy as np
import pytest

from freestand.core.body import Body, Box, Cylinder
from freestand.core.model import Friction
from freestand.core.rocking.body_overturning import (
    body_overturning_limits,
    excitation_plane_block,
    tipping_distance,
)
from freestand.errors import FreestandError

FRICTION = Friction(0.8, 0.7)
CABINET = Body("cabinet", Box((0.8, 0.5, 2.0)), 500.0, FRICTION)


def test_tipping_distance_is_the_nearest_point_of_the_base_outline():
    assert tipping_distance(CABINET) == pytest.approx(math.hypot(0.25, 1.0), rel=1e-12)
    cask = Body("cask", Cylinder(0.5, 2.0), 1000.0, FRICTION, centre=(0.1, 0.0, 0.9))
    assert tipping_distance(cask) == pytest.approx(math.hypot(0.4, 0.9), rel=1e-12)


def test_the_excitation_plane_of_a_box_along_y_is_its_y_z_rectangle():
    block = excitation_plane_block(CABINET, 0.5 * math.pi)
    assert block.pivot == pytest.approx((0.25, -1.0))
    assert block.other_pivot == pytest.approx((-0.25, -1.0))
    assert block.inertia == pytest.approx(500.0 * (0.5**2 + 2.0**2) / 12.0)


def test_the_curve_says_what_it_computed():
    calls = []
    curve = body_overturning_limits(CABINET, [1.0], 90.0, scan_ratio=1.1, rel_tol=1e-3,
                                    operating_amplitude=8.0, progress=lambda: calls.append(1))  # fmt: skip
    assert calls == [1]
    assert curve.pivot == "edge -y"
    assert curve.uplift_threshold == pytest.approx(9.81 * 0.25 / 1.0)
    assert curve.found.all() and curve.amplitude[0] > curve.uplift_threshold
    assert curve.simulations[0] > 3 and curve.failed[0] == 0
    assert curve.remedies.shape == curve.stretch_steps.shape == (1,)
    assert np.isfinite(curve.limits.operating_frequency["exact-3d"])


@pytest.mark.parametrize(
    ("options", "text"),
    [
        ({"kind": "square"}, "unknown pulse kind"),
        ({"vertical_acceleration": 9.81}, "weight"),
    ],
)
def test_bad_options_are_refused_by_name(options, text):
    with pytest.raises(FreestandError, match=text):
        body_overturning_limits(CABINET, [1.0], 0.0, **options)


@pytest.mark.parametrize("frequency", [[], [0.0], [2.0, 1.0], [math.nan]])
def test_frequencies_must_be_increasing_positive_and_finite(frequency):
    with pytest.raises(ValueError, match="frequency"):
        body_overturning_limits(CABINET, frequency, 0.0)
