"""3-D body at rest: uplift thresholds per direction and the initial motion (issue #18).

Sources:
- Housner (1963), Bull. Seismol. Soc. Am. 53(2), 403-417: a rigid block starts
  to rock when the resultant of its weight and inertial force leaves its
  base; in 3-D that point moves along the direction of the inertial force, so
  a box of half-widths b_x, b_y with its centre of gravity at height h over
  the base centre lifts at ``a* = (g - a_v) min(b_x/|cos phi|, b_y/|sin phi|) / h``
  and a cylinder of radius R at ``a* = (g - a_v) R / h`` in every direction
  (statics; ``../shared/spec/three-d.md`` "Uplift from rest").
- Planar reduction: along a principal axis the 3-D screening is the planar
  one of the paper's section 3 (``freestand.core.contact.screening``, validated
  against the paper's Tables 2-5): same motion, normal force and angular
  acceleration.
"""

from __future__ import annotations

import itertools
import math

import pytest

from freestand.core.body import Body, Box, Cylinder
from freestand.core.contact.body_screening import initial_motion, uplift_threshold
from freestand.core.contact.screening import Motion
from freestand.core.contact.screening import initial_motion as planar_initial_motion
from freestand.core.model import Block, Friction, Stack

G = 9.81
DIRECTIONS = [math.radians(15 * k) for k in range(24)]
#: closed forms against the implementation: round-off only
TOLERANCE = 1e-12


@pytest.mark.parametrize("vertical", [0.0, 2.5, -2.5])
def test_box_threshold_every_15_degrees(vertical):
    body = Body("cabinet", Box((0.8, 0.5, 2.0)), 400.0, Friction(0.5, 0.4))
    bx, by, h = 0.4, 0.25, 1.0
    for phi in DIRECTIONS:
        c, s = abs(math.cos(phi)), abs(math.sin(phi))
        reach = min(bx / c if c > 1e-15 else math.inf, by / s if s > 1e-15 else math.inf)
        expected = (G - vertical) * reach / h
        assert uplift_threshold(body, phi, vertical) == pytest.approx(expected, rel=TOLERANCE)


def test_square_box_on_the_diagonal_lifts_at_root_two_times_the_axis_value():
    body = Body("square", Box((1.0, 1.0, 3.0)), 400.0, Friction(0.5, 0.4))
    axis = uplift_threshold(body, 0.0)
    diagonal = uplift_threshold(body, math.pi / 4)
    assert diagonal == pytest.approx(math.sqrt(2.0) * axis, rel=TOLERANCE)
    # just above it, it rocks about the corner
    motion = initial_motion(body, 1.01 * diagonal, math.pi / 4)
    assert motion.motion is Motion.ROCK and motion.pivot == "corner -x-y"


@pytest.mark.parametrize("vertical", [0.0, 2.5, -2.5])
def test_cylinder_threshold_is_the_same_in_every_direction(vertical):
    body = Body("cask", Cylinder(1.2, 5.0), 1.2e5, Friction(0.6, 0.5))
    expected = (G - vertical) * 1.2 / 2.5
    for phi in DIRECTIONS:
        assert uplift_threshold(body, phi, vertical) == pytest.approx(expected, rel=TOLERANCE)
        state = initial_motion(body, 1.05 * expected, phi, vertical)
        assert state.motion is Motion.ROCK
        assert state.pivot == f"rim at {round(math.degrees(phi + math.pi)) % 360} deg"


def _planar_block(mass, width, height, inertia, friction):
    return Block("b", mass, inertia, (0.0, 0.5 * height), -0.5 * width, 0.5 * width, 0.0, friction)


@pytest.mark.parametrize(
    ("width", "height", "static", "ratio"),
    list(itertools.product([0.6, 1.2], [1.0, 2.5], [0.2, 0.5, 0.9], [0.6, 1.0])),
)
def test_box_along_x_screens_as_the_planar_block(width, height, static, ratio):
    friction = Friction(static, static * ratio)
    body = Body("b", Box((width, 0.8, height)), 1000.0, friction)
    block = _planar_block(1000.0, width, height, 1000.0 * (width**2 + height**2) / 12, friction)
    slide_rocks = []
    for horizontal, vertical in itertools.product([0.5, 2, 4, 7, 12], [0.0, 3.0, -3.0]):
        # support acceleration along +x (phi = 0): the inertial force along -x (sense -1)
        for phi, sense in ((0.0, -1), (math.pi, 1)):
            state = initial_motion(body, horizontal, phi, vertical)
            planar = planar_initial_motion(Stack("s", (block,)), horizontal, vertical, sense)
            reference = planar.blocks[0]
            assert state.motion == reference.motion
            if state.motion in (Motion.ROCK, Motion.SLIDE_ROCK):
                normal = reference.base_normal_left + reference.base_normal_right
                # the same equations solved two ways: 1e-9 relative (a slide-rock start by
                # the time-history engine's mode choice, the planar one by the paper's kernel)
                assert state.normal_force == pytest.approx(normal, rel=1e-9)
                assert state.angular_acceleration == pytest.approx(
                    abs(reference.angular_acceleration), rel=1e-9
                )
                assert abs(state.tangential_force[0]) == pytest.approx(
                    abs(reference.base_tangential), rel=1e-9
                )
                slide_rocks.append(state.motion is Motion.SLIDE_ROCK)

    # tall blocks with mu_0 = 0.5 (b/h = 0.24, 0.48) start to slide and rock at the larger
    # accelerations (the friction tips them while they slide)
    if (width, height, static, ratio) in {(0.6, 2.5, 0.5, 0.6), (0.6, 2.5, 0.5, 1.0),
                                          (1.2, 2.5, 0.5, 1.0)}:  # fmt: skip
        assert any(slide_rocks)


@pytest.mark.parametrize("phi", [0.3, 1.9, 4.0])
def test_cylinder_in_any_direction_screens_as_the_planar_block_of_its_inertia(phi):
    radius, height, mass = 0.9, 3.0, 5e4
    friction = Friction(0.5, 0.4)
    body = Body("cask", Cylinder(radius, height), mass, friction)
    inertia = mass * (3 * radius**2 + height**2) / 12  # about a diameter through G
    block = _planar_block(mass, 2 * radius, height, inertia, friction)
    for horizontal, vertical in itertools.product([1.0, 3.0, 5.0, 9.0], [0.0, 3.0]):
        state = initial_motion(body, horizontal, phi, vertical)
        reference = planar_initial_motion(Stack("s", (block,)), horizontal, vertical, -1).blocks[0]
        assert state.motion == reference.motion
        if state.motion in (Motion.ROCK, Motion.SLIDE_ROCK):
            assert state.angular_acceleration == pytest.approx(
                abs(reference.angular_acceleration), rel=1e-9
            )
            assert math.hypot(*state.tangential_force) == pytest.approx(
                abs(reference.base_tangential), rel=1e-9
            )


def test_diagonal_slides_as_an_axis_aligned_motion():
    """Circular cone: a squat box slides at the same acceleration in every direction."""
    body = Body("squat", Box((2.0, 2.0, 0.5)), 1000.0, Friction(0.3, 0.25))
    for phi in DIRECTIONS:
        assert initial_motion(body, 0.99 * 0.3 * G, phi).motion is Motion.REST
        state = initial_motion(body, 1.01 * 0.3 * G, phi)
        assert state.motion is Motion.SLIDE
        assert state.slide_direction == pytest.approx((phi + math.pi) % (2 * math.pi))
        assert math.hypot(*state.tangential_force) == pytest.approx(0.25 * 1000.0 * G)
