"""The 3-D body model and its screening from rest: validation, defaults, invariants (#18)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from freestand.core.body import Body, Box, Cylinder, base_ray_distance
from freestand.core.contact import body_kernel as bk
from freestand.core.contact.body_kernel import body_parameters
from freestand.core.contact.body_screening import initial_motion, screen_directions
from freestand.core.contact.screening import Motion
from freestand.core.model import Friction
from freestand.errors import FreestandError

FRICTION = Friction(0.5, 0.4)


def test_homogeneous_inertia_defaults():
    box = Body("box", Box((1.0, 2.0, 3.0)), 12.0, FRICTION)
    assert np.allclose(np.diag(box.inertia), [4.0 + 9.0, 1.0 + 9.0, 1.0 + 4.0])
    assert box.centre == (0.0, 0.0, 1.5)
    solid = Body("cask", Cylinder(1.0, 3.0), 12.0, FRICTION)
    assert np.allclose(np.diag(solid.inertia), [12 * (3 + 9) / 12, 12 * (3 + 9) / 12, 6.0])
    hollow = Body("pipe", Cylinder(1.0, 3.0, inner_radius=0.5), 12.0, FRICTION)
    assert hollow.inertia[2, 2] == pytest.approx(0.5 * 12.0 * 1.25)


@pytest.mark.parametrize(
    ("make", "message"),
    [
        (lambda: Box((1.0, -2.0, 1.0)), "size"),
        (lambda: Box((1.0, 2.0)), "size"),
        (lambda: Cylinder(1.0, 2.0, inner_radius=1.0), "inner_radius"),
        (lambda: Cylinder(0.0, 2.0), "radius"),
        (lambda: Body("b", Box((1, 1, 1)), -1.0, FRICTION), "mass"),
        (lambda: Body("b", Box((1, 1, 1)), 1.0, FRICTION, centre=(2.0, 0.0, 0.5)), "over the base"),
        (lambda: Body("b", Box((1, 1, 1)), 1.0, FRICTION, centre=(0.0, 0.0, -0.5)), "centre z"),
        (lambda: Body("b", Box((1, 1, 1)), 1.0, FRICTION, inertia=[1.0, -1.0, 1.0]), "positive"),
        (
            lambda: Body(
                "b", Box((1, 1, 1)), 1.0, FRICTION, inertia=[[1, 0.5, 0], [0, 1, 0], [0, 0, 1]]
            ),
            "symmetric",
        ),
    ],
)
def test_invalid_bodies_are_refused_with_the_field(make, message):
    with pytest.raises(FreestandError, match=message):
        make()


def test_ray_distance_from_an_offset_centre():
    box = Box((2.0, 1.0, 1.0))
    assert base_ray_distance(box, (0.5, 0.0), (1.0, 0.0)) == pytest.approx(0.5)
    assert base_ray_distance(box, (0.5, 0.0), (-1.0, 0.0)) == pytest.approx(1.5)
    disc = Cylinder(1.0, 1.0)
    assert base_ray_distance(disc, (0.5, 0.0), (0.0, 1.0)) == pytest.approx(math.sqrt(0.75))


def test_screen_directions_every_15_degrees_by_default():
    states = screen_directions(Body("b", Box((1, 1, 2)), 100.0, FRICTION), 3.0)
    assert len(states) == 24
    assert [round(math.degrees(s.direction)) for s in states[:3]] == [0, 15, 30]


def test_free_flight_when_weightless():
    state = initial_motion(Body("b", Box((1, 1, 2)), 100.0, FRICTION), 1.0, 0.0, vertical=9.81)
    assert state.motion is Motion.FREE_FLIGHT


cylinders = st.builds(
    lambda r, h, mu, ratio: Body("c", Cylinder(r, h), 1000.0, Friction(mu, mu * ratio)),
    st.floats(0.2, 2.0), st.floats(0.3, 6.0), st.floats(0.1, 1.0), st.floats(0.5, 1.0),
)  # fmt: skip


@settings(max_examples=60, deadline=None)
@given(body=cylinders, horizontal=st.floats(0.0, 15.0), vertical=st.floats(-4.0, 4.0),
       phi=st.floats(0.0, 2 * math.pi))  # fmt: skip
def test_cylinder_screening_is_invariant_under_rotation(body, horizontal, vertical, phi):
    reference = initial_motion(body, horizontal, 0.0, vertical)
    turned = initial_motion(body, horizontal, phi, vertical)
    assert turned.motion == reference.motion
    assert turned.uplift_threshold == pytest.approx(reference.uplift_threshold, rel=1e-12)
    assert turned.normal_force == pytest.approx(reference.normal_force, rel=1e-9, nan_ok=True)
    c, s = math.cos(phi), math.sin(phi)
    fx, fy = reference.tangential_force
    rotated = (c * fx - s * fy, s * fx + c * fy)
    assert turned.tangential_force == pytest.approx(rotated, abs=1e-6, nan_ok=True)


boxes = st.builds(
    lambda lx, ly, lz, mu: Body("b", Box((lx, ly, lz)), 500.0, Friction(mu, 0.8 * mu)),
    st.floats(0.2, 3.0), st.floats(0.2, 3.0), st.floats(0.2, 5.0), st.floats(0.1, 1.0),
)  # fmt: skip


@settings(max_examples=60, deadline=None)
@given(body=boxes, horizontal=st.floats(0.0, 15.0), phi=st.floats(0.0, 2 * math.pi))
def test_centred_box_screening_is_symmetric_under_reversal(body, horizontal, phi):
    forward = initial_motion(body, horizontal, phi)
    backward = initial_motion(body, horizontal, phi + math.pi)
    assert forward.motion == backward.motion
    assert forward.uplift_threshold == pytest.approx(backward.uplift_threshold, rel=1e-12)
    assert forward.tangential_force == pytest.approx(
        tuple(-f for f in backward.tangential_force), abs=1e-6, nan_ok=True
    )


def test_a_body_is_immutable_and_keeps_its_kernel_parameters():
    # the inertia is a read-only copy (a body does not change), so the kernel's parameters
    # are kept on the body for each (gravity, restitution): the same values, a fresh array
    # each call (the caller's to keep), another array for another gravity or restitution
    given = np.diag([10.0, 20.0, 30.0])
    body = Body("b", Box((1.0, 0.6, 2.0)), 400.0, Friction(0.5, 0.5), inertia=given)
    given[0, 0] = 99.0  # the caller's array is not the body's
    assert body.inertia[0, 0] == 10.0
    with pytest.raises(ValueError):
        body.inertia[0, 0] = 1.0
    first, again = body_parameters(body, 9.81), body_parameters(body, 9.81)
    assert first is not again and np.array_equal(first, again)
    first[:] = 0.0  # a copy: the kept parameters stay
    assert np.array_equal(body_parameters(body, 9.81), again)
    assert body_parameters(body, 9.81, 0.5)[bk.P_RESTITUTION] == 0.5
    assert body_parameters(body, 1.62)[bk.P_GRAVITY] == 1.62
    default = Body("b", Cylinder(0.5, 1.0), 100.0, Friction(0.3, 0.3))
    assert not default.inertia.flags.writeable
