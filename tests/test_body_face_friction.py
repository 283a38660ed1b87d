"""Where a sliding, twisting flat base's friction acts: ``face_friction`` (#18).

The centre of pressure of a flat base sliding with its friction ``-mu N u``
is ``a + mu h u_xy`` (``face_friction``'s (1)); the friction centre c must
be that centre of pressure, with u the direction of the slip ``(w(c),
omega_z rho(c))`` there. Checked: the closed form's root satisfies that
equation for any slip, turn and lever; the twist radius is continuous in
the centre of pressure, on, at and off the base.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from freestand.core.contact import face_friction as ff

BOX = (True, 0.5, 0.3, ff.rectangle_twist_radius(0.5, 0.3), 5e-10)  # a 1.0 x 0.6 m base
DISC = (False, 0.5, 0.5, 2.0 / 3.0 * 0.5, 5e-10)  # a disc of radius 0.5 m


def _slip(ax, ay, wx, wy, twist, omega, box, cx, cy):
    """The slip at c: ``w(c) = w(a) + omega e_z x (c - a)`` and its twist ``omega rho + twist``."""
    sx = wx - omega * (cy - ay)
    sy = wy + omega * (cx - ax)
    return sx, sy, omega * ff.face_twist_radius(*box[:4], box[4], cx, cy) + twist


def _speed(bound):
    # [m/s, rad/s] zero below 1e-12 (a slip or turn that small has no direction in the kernel
    # either: its slip floor is 1e-6 m/s; and its squares would underflow)
    return st.floats(-bound, bound).map(lambda v: 0.0 if abs(v) < 1e-12 else v)


@settings(max_examples=200, deadline=None)
@given(
    st.booleans(), st.floats(-0.4, 0.4), st.floats(-0.25, 0.25), _speed(2.0), _speed(2.0),
    _speed(3.0), st.floats(0.01, 0.6), _speed(0.5),
)  # fmt: skip
@example(True, 0.0, 0.0, 0.05, 0.0, 1.0, 0.24, 0.0)  # omega b ten times the slip
@example(True, 0.1, -0.2, 0.0, 0.0, 0.5, 0.3, 0.0)  # a pure twist: c = a
@example(False, 0.2, 0.1, 1e-3, 2e-3, 0.0, 0.3, 0.0)  # no twist: c = a + mu h w/|w|
def test_the_closed_form_s_centre_is_its_own_centre_of_pressure(
    box, ax, ay, wx, wy, omega, lever, twist
):
    # c - a = mu h s_xy / |s|, checked as |s| (c - a) = mu h s_xy [m^2/s]: near the instant
    # centre (the slip at c some 1e-10 m/s) its direction is round-off's. Tolerance: the
    # root on the angle psi is found to round-off, c to some 1e-15 m
    shape = BOX if box else DISC
    cx, cy = ff.twisting_centre(ax, ay, wx, wy, twist, omega, lever, *shape)
    sx, sy, s_twist = _slip(ax, ay, wx, wy, twist, omega, shape, cx, cy)
    size = math.sqrt(sx * sx + sy * sy + s_twist * s_twist)
    scale = 1.0 + math.hypot(wx, wy) + abs(omega) + abs(twist)
    assert (size * (cx - ax), size * (cy - ay)) == pytest.approx(
        (lever * sx, lever * sy), abs=1e-12 * scale
    )


def test_a_box_s_twist_radius_is_continuous_across_its_sides():
    # the effective rectangle of half-sides b - |c| thins to the side's segment at a side,
    # whose mean distance from the centre of pressure at its middle is a quarter of its
    # length; off the base, the value at the nearest point of the side
    box = BOX[:4] + (BOX[4],)
    side = ff.face_twist_radius(*box, 0.0, 0.3)
    assert side == pytest.approx(0.25)  # a quarter of the 1.0 m side
    assert ff.face_twist_radius(*box, 0.0, 0.3 - 1e-12) == pytest.approx(side, abs=1e-9)
    assert ff.face_twist_radius(*box, 0.0, 0.7) == side
    assert ff.face_twist_radius(*box, 0.2, -0.5) == ff.face_twist_radius(*box, 0.2, -0.3)
    assert ff.face_twist_radius(*box, 0.9, 0.9) == BOX[4]  # beyond a corner: the floor
    disc = DISC[:4] + (DISC[4],)
    assert ff.face_twist_radius(*disc, 0.0, 0.0) == pytest.approx(1.0 / 3.0)
    assert ff.face_twist_radius(*disc, 0.6, 0.0) == DISC[4]  # off the rim: the floor
