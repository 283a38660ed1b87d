"""A FACE's or EDGE's friction about its centre of pressure (#18).

The 3-D kernel takes the friction of a flat base or a box's edge about the
contact's centre of pressure, with the pressure uniform over the effective
area concentric with it (Meyerhof 1953; ``body_kernel.effective_twist_radius``).
Checked here: the twist radius of a FACE, an EDGE and a POINT agree where one
patch becomes the other; moving the friction centre keeps the friction's
wrench; a body at rest needs no twist torque wherever its centre of gravity
lies (so it slides at ``mu_0 (g - a_v)`` in every direction); a body sliding
flat gets no twist from its friction; a sliding patch's rows settle at its
centre of pressure; a sliding, twisting face's solve obeys Newton and Euler
with its friction at the centre of pressure of its own normal force; a slip
onset's edge solves on the terms it keeps are its solves anew.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, example, given, settings
from hypothesis import strategies as st

from freestand.core.body import Body, Box, Cylinder
from freestand.core.contact import body_kernel as bk
from freestand.core.contact import body_modes, body_solve
from freestand.core.contact import face_friction as ff
from freestand.core.contact.slip_law import SLIP_FLOOR
from freestand.core.dynamics.body_history import initial_state
from freestand.core.model import Friction

G = 9.81  # [m/s^2]
BOX = Body("box", Box((1.0, 0.6, 2.0)), 400.0, Friction(0.5, 0.5))


def rho(body, kind, index, cx, cy):
    par = bk.body_parameters(body, G)
    return bk.effective_twist_radius(par, kind, index, cx, cy)


def test_a_face_s_twist_radius_is_the_whole_base_s_at_its_centre():
    assert rho(BOX, bk.FACE, 0, 0.0, 0.0) == pytest.approx(bk.rectangle_twist_radius(0.5, 0.3))
    disc = Body("disc", Cylinder(0.8, 1.0), 100.0, Friction(0.5, 0.5))
    assert rho(disc, bk.FACE, 0, 0.0, 0.0) == pytest.approx(2.0 / 3.0 * 0.8)
    # a line's mean distance from its midpoint: a quarter of its length
    assert bk.rectangle_twist_radius(0.5, 0.0) == 0.25
    assert bk.rectangle_twist_radius(0.5, 1e-7) == pytest.approx(0.25, rel=1e-6)


@pytest.mark.parametrize("along", [0.0, 0.1, -0.27, 0.45])
def test_a_face_becomes_its_edge_and_an_edge_its_corner(along):
    # edge 0 joins corners 0 (+b_x, +b_y) and 1 (-b_x, +b_y): along x at y = +b_y
    edge = rho(BOX, bk.EDGE, 0, along, 0.3)
    assert edge == pytest.approx(0.5 * (0.5 - abs(along)), rel=1e-12)
    # a face whose centre of pressure approaches that side: the edge's (the effective
    # rectangle thins to a segment; tolerance: its width 2e-9 m shifts the mean distance
    # by less than 1e-8 m)
    assert rho(BOX, bk.FACE, 0, along, 0.3 - 1e-9) == pytest.approx(edge, abs=1e-8)
    # edge 1 (corners 1 and 2) runs along y at x = -b_x
    assert rho(BOX, bk.EDGE, 1, -0.5, 0.6 * along) == pytest.approx(0.5 * (0.3 - 0.6 * abs(along)))


def test_at_a_corner_or_on_the_rim_nothing_is_left_to_twist_on():
    floor = bk.RHO_FLOOR * 0.5
    assert rho(BOX, bk.EDGE, 0, 0.5, 0.3) == pytest.approx(floor)
    assert rho(BOX, bk.FACE, 0, 0.5, 0.3) == pytest.approx(floor)
    disc = Body("disc", Cylinder(0.8, 1.0), 100.0, Friction(0.5, 0.5))
    assert rho(disc, bk.FACE, 0, 0.8 * math.cos(1.0), 0.8 * math.sin(1.0)) < 1e-8


@settings(max_examples=40, deadline=None)
@given(
    st.tuples(*[st.floats(-1e3, 1e3) for _ in range(3)]),
    st.tuples(st.floats(-0.45, 0.45), st.floats(-0.28, 0.28)),  # inside the 1.0 x 0.6 base
    st.floats(-math.pi, math.pi),
)
def test_moving_the_friction_centre_keeps_the_friction_s_wrench(friction, to, yaw):
    """T' = T - (delta x F)_z: the same force and moment about any point."""
    par = bk.body_parameters(BOX, G)
    y = initial_state(BOX)
    y[3], y[6] = math.cos(0.5 * yaw), math.sin(0.5 * yaw)  # turned about the vertical
    rot = np.empty((3, 3))
    bk.rotation_matrix(y, rot)
    centre = np.zeros(5)
    bk.reset_friction_centre(par, bk.FACE, 0, centre)
    # the normal multipliers (N, M_x, M_y) of a centre of pressure at `to` (body frame)
    n = 3000.0
    px = rot[0, 0] * to[0] + rot[0, 1] * to[1]
    py = rot[1, 0] * to[0] + rot[1, 1] * to[1]
    lam = np.array([n, n * py, -n * px, *friction])
    before = lam.copy()
    bk.centre_stick_friction(par, rot, bk.FACE, 0, 3, lam, centre)
    assert centre[:2] == pytest.approx(to, abs=1e-12)
    assert lam[3:5] == pytest.approx(before[3:5], abs=0.0)
    # moment about the base centre of (F at the centre, T) and of (F at c, T')
    torque_before = before[5] * bk.rectangle_twist_radius(0.5, 0.3)
    torque_after = lam[5] * centre[2] + (px * lam[4] - py * lam[3])
    assert torque_after == pytest.approx(torque_before, abs=1e-9 * (1.0 + abs(torque_before)))


def _stick_at_rest(body, acceleration, direction):
    """The FACE's sticking solution under a steady support acceleration; (holds, lam, centre)."""
    par = bk.body_parameters(body, G)
    record = np.zeros((3, 2))
    record[0, :] = acceleration * math.cos(direction)
    record[1, :] = acceleration * math.sin(direction)
    sc = bk.new_scratch()
    mode = np.array([bk.FACE, 0, 0], dtype=np.int64)
    ok, n_normal, n_tangent = body_solve.solve_at(par, record, 1.0, 0.0, initial_state(body), mode,
                                          np.zeros(bk.DATA_SIZE), sc)  # fmt: skip
    assert ok
    margin = bk.friction_margin(par, n_normal, n_tangent, sc[bk.SC_LAM])
    return margin, sc[bk.SC_LAM].copy(), sc[bk.SC_CENTRE].copy()


@settings(max_examples=30, deadline=None)
@given(
    st.floats(-0.1, 0.1), st.floats(-0.05, 0.05), st.floats(0.3, 0.6), st.floats(0.0, 2 * math.pi)
)
def test_at_rest_the_load_passes_through_the_centre_of_pressure(gx, gy, gz, direction):
    """No twist torque at rest, wherever G lies: the slide starts at mu_0 g in every direction.

    About the base centre a centre of gravity off it needs the twist
    ``((G - o) x F)_z``; about the centre of pressure, which lies on the load's
    line of action, none (the margin is then mu_0 N - |F| to round-off).
    """
    # the centre of pressure lies mu h_G <= 0.18 m from G's projection, inside the base for
    # every G drawn (0.25 m from the long sides at least): the base slides before it lifts
    mu = 0.3
    body = Body("squat", Box((1.0, 0.6, 2.0)), 400.0, Friction(mu, mu), centre=(gx, gy, gz))
    for factor, holds in ((0.999, True), (1.001, False)):
        margin, lam, centre = _stick_at_rest(body, factor * mu * G, direction)
        assert abs(lam[5] * centre[2]) < 1e-9 * 400.0 * G  # the twist torque about c [N m]
        assert (margin >= 0.0) is holds
        assert margin == pytest.approx(mu * lam[0] - math.hypot(lam[3], lam[4]), abs=1e-9)


@settings(max_examples=30, deadline=None)
@given(
    st.floats(-0.15, 0.15), st.floats(-0.1, 0.1), st.floats(0.0, 2 * math.pi),
    st.floats(0.0, 2 * math.pi), st.floats(0.0, 2.0),
)  # fmt: skip
def test_a_body_sliding_flat_gets_no_twist_from_its_friction(gx, gy, slide, push, size):
    """The friction force passes through the centre of pressure: no yaw, however G lies.

    A base sliding flat along ``slide`` under a support acceleration along
    ``push`` (not parallel): the centre of pressure settles on the line of
    the friction force through G, so the twist acceleration is zero and the
    rows sit at the centre of pressure.
    """
    body = Body("squat", Box((1.0, 0.6, 2.0)), 400.0, Friction(0.3, 0.3), centre=(gx, gy, 0.6))
    par = bk.body_parameters(body, G)
    record = np.zeros((3, 2))
    record[0, :] = size * math.cos(push)
    record[1, :] = size * math.sin(push)
    y = initial_state(body)
    y[7], y[8] = 0.2 * math.cos(slide), 0.2 * math.sin(slide)
    sc = bk.new_scratch()
    mode = np.array([bk.FACE, 0, 1], dtype=np.int64)
    data = np.zeros(bk.DATA_SIZE)
    data[1], data[2] = math.cos(slide), math.sin(slide)
    ok, _, _ = body_solve.solve_at(par, record, 1.0, 0.0, y, mode, data, sc)
    assert ok
    acc, lam, centre = sc[bk.SC_ACC], sc[bk.SC_LAM], sc[bk.SC_CENTRE]
    assert abs(acc[5]) < 1e-9  # no twist acceleration [rad/s^2]
    assert np.abs(acc[3:5]).max() < 1e-9  # and it stays flat
    cx, cy = bk.face_centre_of_pressure(sc[bk.SC_ROT], lam)
    assert (centre[0], centre[1]) == pytest.approx((cx, cy), abs=1e-9)
    # its friction is the kinetic one against the slide
    assert math.hypot(lam[3], lam[4]) == pytest.approx(0.3 * lam[0], rel=1e-9)


# the slide's cases where the Anderson mixing of the centres alone wandered (12 solves, and
# the rows up to 4e-5 m from the centre of pressure): a spin of 1 rad/s at ten times the slip
# (omega_z b ~ 0.5 m/s), and a cylinder whose slip at its base centre is against the stored
# direction
@settings(max_examples=40, deadline=None)
@given(
    st.booleans(), st.floats(-0.15, 0.15), st.floats(-0.1, 0.1), st.floats(0.0, 2 * math.pi),
    st.floats(0.05, 0.5), st.floats(0.0, 2 * math.pi), st.floats(-2.0, 2.0),
    st.floats(0.0, 2 * math.pi), st.floats(0.0, 3.0),
)  # fmt: skip
@example(False, 0.125, 0.0, 2.0, 0.0546875, 0.25, 1.0, 0.0, 0.0)
@example(True, -0.1315, -0.0754, 6.1168, 0.0817, 5.2934, 1.9466, 1.0191, 2.1122)
def test_a_sliding_twisting_face_s_friction_acts_at_its_own_centre_of_pressure(
    cylinder, gx, gy, yaw, speed, slide, spin, push, size
):
    """Newton and Euler hold with the friction at the centre of pressure of the solve's own N.

    A flat base sliding and twisting (the slip direction then depends on
    where the friction acts) under a horizontal push: the solve's friction
    centre is the centre of pressure of its normal multipliers, and its
    accelerations are those of the applied load, the normal force and
    couples, and the friction ``-mu N u`` with its twist, applied there
    (``body_kernel.face_offset_torques`` places the friction in one solve).
    """
    _check_twisting_slide(cylinder, gx, gy, yaw, speed, slide, spin, push, size, 0.0)


@settings(max_examples=40, deadline=None)
@given(
    st.booleans(), st.floats(-0.15, 0.15), st.floats(-0.1, 0.1), st.floats(0.0, 2 * math.pi),
    st.floats(1e-5, 1e-3), st.floats(0.0, 2 * math.pi), st.floats(-0.01, 0.01),
    st.floats(0.0, 2 * math.pi), st.floats(0.0, 3.0), st.floats(1e-4, 2e-3),
)  # fmt: skip
def test_a_slow_twisting_slide_s_friction_acts_at_its_own_centre_of_pressure(
    cylinder, gx, gy, yaw, speed, slide, spin, push, size, floor
):
    """The same below the step's slip floor, where u is pulled towards the stored direction.

    A slip slower than the floor (``body_solve.unit_slip``; the engine's
    ``slip_floor``) turns to the stored direction, so u(c) is no longer the
    slip's own direction: the friction centre is found on the same model by
    Newton's method (``face_friction.model_centre``). Speeds of 1e-5 to
    1e-3 m/s with twists of up to 0.01 rad/s (``omega_z b`` up to 5e-3 m/s),
    as a cabinet's slide near its stop.
    """
    _check_twisting_slide(cylinder, gx, gy, yaw, speed, slide, spin, push, size, floor)


def _check_twisting_slide(cylinder, gx, gy, yaw, speed, slide, spin, push, size, floor):
    shape = Cylinder(0.5, 2.0) if cylinder else Box((1.0, 0.6, 2.0))
    body = Body("flat", shape, 400.0, Friction(0.3, 0.3), centre=(gx, gy, 0.8))
    par = bk.body_parameters(body, G)
    record = np.zeros((3, 2))
    record[0, :] = size * math.cos(push)
    record[1, :] = size * math.sin(push)
    y = initial_state(body)
    y[3], y[6] = math.cos(0.5 * yaw), math.sin(0.5 * yaw)
    y[7], y[8], y[12] = speed * math.cos(slide), speed * math.sin(slide), spin
    sc = bk.new_scratch()
    mode = np.array([bk.FACE, 0, 1], dtype=np.int64)
    data = np.zeros(bk.DATA_SIZE)
    data[bk.D_SLIP], data[bk.D_SLIP + 1] = math.cos(slide), math.sin(slide)
    data[bk.D_FLOOR] = floor
    ok, n_normal, n_tangent = body_solve.solve_at(par, record, 1.0, 0.0, y, mode, data, sc)
    assert ok
    acc, lam, centre = sc[bk.SC_ACC], sc[bk.SC_LAM], sc[bk.SC_CENTRE]
    # a flat base only where it is one: N > 0 and the centre of pressure inside the base
    assume(bk.normal_margin(par, sc[bk.SC_ROT], bk.FACE, lam) > 1e-6 * lam[0])
    cx, cy = bk.face_centre_of_pressure(sc[bk.SC_ROT], lam)
    assert (centre[0], centre[1]) == pytest.approx((cx, cy), abs=1e-9)  # [m]
    # M acc = f_0 + the normal rows' forces + the friction's on the rows at the centre
    force = sc[bk.SC_F0].copy()
    for r in range(n_normal):
        force += lam[r] * sc[bk.SC_NORMAL][:, r]
    for k in range(n_tangent):
        force += lam[n_normal + k] * sc[bk.SC_TANGENT][:, k]
    expected = np.concatenate((force[:3] / body.mass, sc[bk.SC_INV] @ force[3:]))
    assert acc == pytest.approx(expected, abs=1e-9)  # [m/s^2, rad/s^2]
    # the friction is the kinetic one, against the slip at that centre (below the floor,
    # against the slip pulled towards the stored direction: unit_slip's u)
    slip = sc[bk.SC_SVEL][:n_tangent]
    friction = lam[n_normal : n_normal + n_tangent]
    assert np.linalg.norm(friction) == pytest.approx(0.3 * lam[0], rel=1e-9)
    direction = slip / np.linalg.norm(slip)
    if floor > 0.0:
        body_solve.unit_slip(slip.copy(), n_tangent, data, direction)
    assert friction / np.linalg.norm(friction) == pytest.approx(-direction, abs=1e-9)


def test_a_patch_s_kind_is_the_one_its_rows_were_built_for():
    par = bk.body_parameters(BOX, G)
    sc = bk.new_scratch()
    y = initial_state(BOX)
    bk.prepare(par, np.zeros((3, 2)), 1.0, 0.0, y, bk.EDGE, 2, 0.0, sc)
    centre = sc[bk.SC_CENTRE]
    assert (centre[3], centre[4]) == (bk.EDGE, 2)
    assert (centre[0], centre[1]) == (0.0, -0.3)  # edge 2's midpoint
    assert centre[2] == pytest.approx(0.25)


#: hypothesis's strategies for :func:`tilted_box`'s tilt [rad], yaw [rad], velocities and push
TILTED_BOX = dict(
    tilt=st.floats(0.01, 0.4), yaw=st.floats(-0.3, 0.3),
    velocity=st.lists(st.floats(-0.5, 0.5), min_size=6, max_size=6),
    push=st.lists(st.floats(-6.0, 6.0), min_size=3, max_size=3),
)  # fmt: skip


def tilted_box(tilt, yaw, velocity, push, box=BOX):
    """(parameters, state, record) of ``box`` tilted by ``tilt`` [rad] about its x axis onto
    edge 2, turned by ``yaw`` [rad], with the velocities ``velocity`` (6,) and a constant
    support acceleration ``push`` (3,) [m/s^2]."""
    par = bk.body_parameters(box, G)
    y = initial_state(box, (tilt, 0.0))
    y[3:7] = (y[3] * math.cos(0.5 * yaw), y[4] * math.cos(0.5 * yaw),
              y[4] * math.sin(0.5 * yaw), y[3] * math.sin(0.5 * yaw))  # fmt: skip
    y[7:13] = velocity
    return par, y, np.repeat(np.asarray(push)[:, None], 2, axis=1)


@settings(max_examples=60, deadline=None)
@given(
    **TILTED_BOX,
    share=st.floats(0.0, 1.0), stored=st.floats(-math.pi, math.pi),
)  # fmt: skip
def test_a_sliding_edge_s_share_map_is_its_full_solve_s(tilt, yaw, velocity, push, share, stored):
    # edge 2 (corners 2 and 3, along x at y = -b_y) tilted down: F(sigma), the centre of
    # pressure's share with the friction at sigma, from the 2 x 2 system of
    # body_solve.edge_share against the full solve on rows built at sigma (tolerance:
    # round-off of two eliminations, 1e-9 of the share)
    par, y, record = tilted_box(tilt, yaw, velocity, push)
    data = np.zeros(bk.DATA_SIZE)
    data[bk.D_SLIP : bk.D_SLIP + 3] = math.cos(stored), math.sin(stored), 0.0
    sc = bk.new_scratch()
    n_normal, n_tangent = bk.prepare(par, record, 1.0, 0.0, y, bk.EDGE, 2, 0.0, sc)
    body_solve.edge_slide_terms(par, y, sc, True)
    direction = np.zeros(3)
    quick = body_solve.edge_share(par, sc, 2, share, direction, True, data)
    quick_direction = sc[bk.SC_DIR].copy()
    ax, ay = bk.box_corner(par, 2)
    bx, by = bk.box_corner(par, 3)
    centre = sc[bk.SC_CENTRE]
    centre[0], centre[1] = ax + share * (bx - ax), ay + share * (by - ay)
    centre[2] = bk.effective_twist_radius(par, bk.EDGE, 2, centre[0], centre[1])
    bk.tangent_rows(par, y, sc)
    # the solution the settled search takes from the same 2 x 2 system (body_solve._edge_solution)
    closed = body_solve._edge_solution(par, sc, share, quick_direction)
    closed_acc, closed_lam = sc[bk.SC_ACC].copy(), sc[bk.SC_LAM].copy()
    u = np.zeros(3)
    body_solve.slip_direction(y, n_tangent, data, sc[bk.SC_TANGENT], np.zeros(3), u)
    assert bk.solve_mode(par, sc, sc[bk.SC_BASE], True, 1, u, n_normal, n_tangent,
                         acc := np.zeros(6), lam := np.zeros(6))  # fmt: skip
    # the closed solution's accelerations and forces are the full solve's (tolerance: the
    # round-off of two eliminations, 1e-9 of g and of m g)
    assert closed
    np.testing.assert_allclose(closed_acc, acc, rtol=0.0, atol=1e-9 * G)
    np.testing.assert_allclose(closed_lam[:5], lam[:5], rtol=0.0, atol=1e-9 * BOX.mass * G)
    total = lam[0] + lam[1]
    if total <= 1e-9 * BOX.mass * G:
        assert math.isnan(quick) or total > 0.0  # no centre of pressure
        return
    assert quick == pytest.approx(min(max(lam[1] / total, 0.0), 1.0), abs=1e-9)


def test_a_sliding_edge_settles_at_its_centre_of_pressure():
    # a tilted box sliding and twisting on edge 2: the solve's friction centre is the
    # centre of pressure of its own normal forces (to CENTRE_TOLERANCE, 1e-12 of b_x)
    par = bk.body_parameters(BOX, G)
    y = initial_state(BOX, (0.2, 0.0))
    y[7:13] = 0.3, -0.1, 0.0, 0.0, 0.0, 0.8
    sc = bk.new_scratch()
    mode = np.array([bk.EDGE, 2, 1], dtype=np.int64)
    data = np.zeros(bk.DATA_SIZE)
    data[bk.D_SLIP] = 1.0
    ok, _, _ = body_solve.solve_at(par, np.zeros((3, 2)), 1.0, 0.0, y, mode, data, sc)
    assert ok
    lam, centre = sc[bk.SC_LAM], sc[bk.SC_CENTRE]
    share = lam[1] / (lam[0] + lam[1])
    assert 0.0 < share < 1.0  # the twist moves it off the midpoint, not to a corner
    assert share != pytest.approx(0.5, abs=1e-3)
    ax, _ = bk.box_corner(par, 2)
    bx, _ = bk.box_corner(par, 3)
    assert centre[0] == pytest.approx(ax + share * (bx - ax), abs=1e-11)


def _first_slide_solve(cylinder, gx, gy, yaw, speed, slide, spin, floor):
    """A twisting slide's first solve, its centre moved to its centre of pressure.

    Returns (body, par, y, data, sc, model, rows) with ``model`` the kernel's
    model of the centre of pressure from that solve (``body_solve.face_model``).
    """
    shape = Cylinder(0.5, 2.0) if cylinder else Box((1.0, 0.6, 2.0))
    body = Body("flat", shape, 400.0, Friction(0.3, 0.3), centre=(gx, gy, 0.8))
    par = bk.body_parameters(body, G)
    y = initial_state(body)
    y[3], y[6] = math.cos(0.5 * yaw), math.sin(0.5 * yaw)
    y[7], y[8], y[12] = speed * math.cos(slide), speed * math.sin(slide), spin
    data = np.zeros(bk.DATA_SIZE)
    data[bk.D_SLIP], data[bk.D_SLIP + 1] = math.cos(slide), math.sin(slide)
    data[bk.D_FLOOR] = floor
    sc = bk.new_scratch()
    rows = bk.prepare(par, np.zeros((3, 2)), 1.0, 0.0, y, bk.FACE, 0, 0.0, sc)
    u = _solve_on_rows(par, y, sc, data, rows)
    cx, cy = bk.face_centre_of_pressure(sc[bk.SC_ROT], sc[bk.SC_LAM])
    _place_centre(par, y, sc, data, rows, cx, cy)
    return body, par, y, data, sc, body_solve.face_model(par, sc, u[0], u[1]), rows


def _solve_on_rows(par, y, sc, data, rows):
    """The kinetic slide's solve on the scratch's rows, u the slip's (unit_slip); returns u."""
    u = np.zeros(3)
    body_solve.slip_direction(y, rows[1], data, sc[bk.SC_TANGENT], sc[bk.SC_SVEL], u)
    assert bk.solve_mode(par, sc, sc[bk.SC_BASE], True, 1, u, rows[0], rows[1], sc[bk.SC_ACC],
                         sc[bk.SC_LAM])  # fmt: skip
    return u


def _place_centre(par, y, sc, data, rows, cx, cy):
    """The rows at the friction centre (cx, cy) and the slip velocity there."""
    centre = sc[bk.SC_CENTRE]
    centre[0], centre[1] = cx, cy
    centre[2] = bk.effective_twist_radius(par, bk.FACE, 0, cx, cy)
    bk.tangent_rows(par, y, sc)
    body_solve.slip_direction(y, rows[1], data, sc[bk.SC_TANGENT], sc[bk.SC_SVEL], np.zeros(3))


@settings(max_examples=40, deadline=None)
@given(
    st.booleans(), st.floats(-0.15, 0.15), st.floats(-0.1, 0.1), st.floats(0.0, 2 * math.pi),
    st.floats(1e-5, 1e-3), st.floats(0.0, 2 * math.pi), st.floats(-0.01, 0.01),
    st.floats(1e-4, 2e-3),
)  # fmt: skip
def test_the_search_on_the_slip_s_pull_finds_the_slow_slide_s_centre(
    cylinder, gx, gy, yaw, speed, slide, spin, floor
):
    """The bracketed search on the pull beta alone settles, and a solve confirms it.

    ``face_friction.pulled_centre`` is the kernel's last resort for a slip
    below its floor (after Newton's method on the same model, which settles
    all but some 1 in 1,000 of these): here it is run on its own from the
    first solve's model, and a solve with the friction at the centre it
    returns has its centre of pressure there (to 1e-9 m).
    """
    _, par, y, data, sc, model, rows = _first_slide_solve(cylinder, gx, gy, yaw, speed, slide,
                                                          spin, floor)  # fmt: skip
    base = (not cylinder, 0.5, 0.5 if cylinder else 0.3, par[bk.P_RHO_FACE], 0.5 * bk.RHO_FLOOR)
    floor_ = max(SLIP_FLOOR, floor)
    args = (model, base, sc[bk.SC_ROT], y[12], data, bk.D_SLIP, floor_, np.zeros(3), np.zeros(3))
    cx, cy, settled = ff.pulled_centre(args)
    assert settled
    _place_centre(par, y, sc, data, rows, cx, cy)
    _solve_on_rows(par, y, sc, data, rows)
    assert bk.face_centre_of_pressure(sc[bk.SC_ROT], sc[bk.SC_LAM]) == pytest.approx(
        (cx, cy), abs=1e-9
    )


@settings(max_examples=60, deadline=None)
@given(
    **TILTED_BOX,
    directions=st.lists(st.floats(-math.pi, math.pi), min_size=2, max_size=8),
    acceleration=st.booleans(), fallback=st.booleans(),
)  # fmt: skip
def test_a_slip_onset_s_edge_solves_on_kept_terms_are_its_solves_anew(
    tilt, yaw, velocity, push, directions, acceleration, fallback
):
    # a slip onset's search (body_modes._slip_onset) solves the same sliding EDGE under many
    # friction directions, on the terms of its centre's search that the first solve left
    # (body_solve.slide_edge_on_terms): each must equal the solve that computes them anew,
    # to the last bit, also after a search that ended in the full solve (its work arrays
    # overwrite the terms: flagged, and computed again)
    par, y, record = tilted_box(tilt, yaw, velocity, push)
    level = body_modes.ACCELERATION if acceleration else body_modes.VELOCITY
    results = []
    for reuse in (False, True):
        sc = bk.new_scratch()
        n_normal, n_tangent = bk.prepare(par, record, 1.0, 0.0, y, bk.EDGE, 2, 0.0, sc)
        if not acceleration:
            sc[bk.SC_BASE][:] = y[7:13]
        rows = []
        for i, angle in enumerate(directions):
            u = np.array([math.cos(angle), math.sin(angle), 0.3 * math.sin(3.0 * angle)])
            u /= np.linalg.norm(u)
            if fallback and i == 1:
                sc[bk.SC_EDGE][2, bk.E_INTACT] = 0.0  # as the full solve leaves it
                sc[bk.SC_WORK][:] = np.nan  # and its work arrays
            rate = body_modes._onset_rate(par, y, sc, level, n_normal, n_tangent, u,
                                          reuse and i > 0)  # fmt: skip
            rows.append((rate, sc[bk.SC_ACC].copy(), sc[bk.SC_LAM].copy(),
                         sc[bk.SC_CENTRE].copy()))  # fmt: skip
        results.append(rows)
    for anew, kept in zip(*results, strict=True):
        assert np.array_equal(np.asarray(anew[0]), np.asarray(kept[0]), equal_nan=True)
        for a, b in zip(anew[1:], kept[1:], strict=True):
            assert np.array_equal(a, b, equal_nan=True)


@settings(max_examples=60, deadline=None)
@given(
    **TILTED_BOX,
    last=st.floats(0.0, 1.0), slope=st.floats(-100.0, -0.01), edge=st.sampled_from([2, 0]),
)  # fmt: skip
def test_a_sliding_edge_s_search_from_its_last_share_settles_where_one_from_its_middle_does(
    tilt, yaw, velocity, push, last, slope, edge
):
    # the search starts at the edge's last settled share and slope (sc[SC_SHARE]), any of
    # them, or another edge's (edge 0 stored, edge 2 solved: from the middle): the same
    # centre of pressure to the search's tolerance (CENTRE_TOLERANCE of b_x, on a 1 m edge
    # 5e-13 of its share), so the same solution to the round-off of the 2 x 2 system
    par, y, record = tilted_box(tilt, yaw, velocity, push)
    mode = np.array([bk.EDGE, 2, 1], dtype=np.int64)
    data = np.zeros(bk.DATA_SIZE)
    data[bk.D_SLIP] = 1.0
    solutions = []
    for stored in (None, (edge + 1.0, last, slope)):
        sc = bk.new_scratch()
        if stored is not None:
            sc[bk.SC_SHARE][:] = stored
        ok, _, _ = body_solve.solve_at(par, record, 1.0, 0.0, y, mode, data, sc)
        solutions.append((ok, sc[bk.SC_ACC].copy(), sc[bk.SC_LAM].copy(), sc[bk.SC_CENTRE].copy(),
                          sc[bk.SC_SHARE].copy()))  # fmt: skip
    (ok_middle, acc_middle, lam_middle, centre_middle, kept), (ok, acc, lam, centre, _) = solutions
    assert ok == ok_middle
    if not ok:
        return
    np.testing.assert_allclose(centre[:3], centre_middle[:3], rtol=0.0, atol=1e-11)
    np.testing.assert_allclose(acc, acc_middle, rtol=0.0, atol=1e-9 * G)
    np.testing.assert_allclose(lam[:5], lam_middle[:5], rtol=0.0, atol=1e-9 * BOX.mass * G)
    # a settled search keeps its share and slope for the next (edge 2 stored as 3.0)
    if kept[0] != 0.0:
        ax, _ = bk.box_corner(par, 2)
        bx, _ = bk.box_corner(par, 3)
        assert kept[0] == 3.0
        assert ax + kept[1] * (bx - ax) == pytest.approx(centre_middle[0], abs=1e-12)
        assert body_solve.SLOPE_LOW < kept[2] < body_solve.SLOPE_HIGH


@settings(max_examples=80, deadline=None)
@given(
    **TILTED_BOX,
    share=st.floats(0.0, 1.0), stored=st.floats(-math.pi, math.pi),
    floor=st.sampled_from([SLIP_FLOOR, 1e-3, 0.1, 1.0]),
)  # fmt: skip
def test_a_sliding_edge_s_closed_form_share_is_its_2x2_system_s(
    tilt, yaw, velocity, push, share, stored, floor
):
    # F(sigma) of the kinetic search (body_solve._kinetic_share: Cramer's sum is the same
    # for any friction, each term times |w|) against edge_share's 2 x 2 system with u =
    # w / |w| (tolerance: the round-off of the two forms, 1e-12 of the share), and whether
    # u was pulled to the stored direction (floors up to 1 m/s: pulled at most shares)
    par, data, sc = _edge_terms(tilt, yaw, velocity, push, stored, floor)
    closed, _, pulled, *_ = body_solve._kinetic_share(par, sc[bk.SC_EDGE], 2, share, data, floor)
    # the 2 x 2 system at u, the slip velocity's at sigma (unit_slip)
    rho = _edge_rho(par, share)
    u = np.zeros(3)
    own = body_solve._slip_at(sc[bk.SC_EDGE], share, rho, data, np.zeros(3), u)
    system = body_solve._edge_share_along(par, sc[bk.SC_EDGE], share, rho, u)
    assert pulled == (not own)
    assert math.isnan(closed) == math.isnan(system)  # no centre of pressure: both say so
    if math.isnan(system):
        return
    assert closed == pytest.approx(system, abs=1e-12)


@settings(max_examples=80, deadline=None)
@given(
    **TILTED_BOX,
    share=st.floats(0.01, 0.99), stored=st.floats(-math.pi, math.pi),
    floor=st.sampled_from([SLIP_FLOOR, 1e-3, 0.1, 1.0]),
)  # fmt: skip
def test_a_sliding_edge_s_closed_form_slope_is_its_share_s_derivative(
    tilt, yaw, velocity, push, share, stored, floor
):
    # F'(sigma), the Newton step's slope of the kinetic search (body_solve._kinetic_share,
    # its slip pulled to the stored direction or not), against F's central difference over
    # 2e-6 of the edge where F is smooth there: both ends pulled alike, neither clamped to
    # the edge, away from the twist radius's kink at the middle. Tolerance 1e-4 of the
    # slope (or 1e-6 absolute): the difference's truncation (F''' step^2 / 6) and its
    # round-off (some 1e-16 / step, 1e-10)
    par, data, sc = _edge_terms(tilt, yaw, velocity, push, stored, floor)
    step = 1e-6
    value, slope, pulled, *_ = body_solve._kinetic_share(par, sc[bk.SC_EDGE], 2, share, data,
                                                         floor)  # fmt: skip
    ends = [body_solve._kinetic_share(par, sc[bk.SC_EDGE], 2, share + s, data, floor)
            for s in (-step, step)]  # fmt: skip
    assume(math.isfinite(value) and all(math.isfinite(end[0]) for end in ends))
    assume(0.0 < value < 1.0 and all(0.0 < end[0] < 1.0 for end in ends))
    assume(all(end[2] == pulled for end in ends) and abs(share - 0.5) > 2.0 * step)
    # the pull's floor bends F where |s| crosses it: both ends on the same side of it
    sizes = [_slip_speed(sc, share + s, par) for s in (-step, 0.0, step)]
    assume(all(size > floor for size in sizes) or all(size < floor for size in sizes))
    difference = (ends[1][0] - ends[0][0]) / (2.0 * step)
    assert slope == pytest.approx(difference, rel=1e-4, abs=1e-6)


def _slip_speed(sc, share, par):
    """|s| at ``share`` of edge 2 (the scratch's terms), its twist part rho omega_z."""
    v = sc[bk.SC_EDGE][2]
    return math.hypot(v[0] + share * (v[2] - v[0]), v[1] + share * (v[3] - v[1]),
                      _edge_rho(par, share) * v[4])  # fmt: skip


def _edge_terms(tilt, yaw, velocity, push, stored, floor):
    """The tilted box sliding on edge 2 (:func:`tilted_box`): its parameters, the mode data
    (stored slip direction at angle ``stored``, floor ``floor`` [m/s]) and the scratch with
    the edge's terms (``body_solve.edge_slide_terms``)."""
    par, y, record = tilted_box(tilt, yaw, velocity, push)
    data = np.zeros(bk.DATA_SIZE)
    data[bk.D_SLIP : bk.D_SLIP + 3] = math.cos(stored), math.sin(stored), 0.0
    data[bk.D_FLOOR] = floor
    sc = bk.new_scratch()
    bk.prepare(par, record, 1.0, 0.0, y, bk.EDGE, 2, 0.0, sc)
    body_solve.edge_slide_terms(par, y, sc, True)
    return par, data, sc


def _edge_rho(par, share):
    """Edge 2's twist radius [m] with its centre of pressure at ``share``."""
    ax, ay = bk.box_corner(par, 2)
    bx, by = bk.box_corner(par, 3)
    return bk.effective_twist_radius(par, bk.EDGE, 2, ax + share * (bx - ax),
                                     ay + share * (by - ay))  # fmt: skip


@settings(max_examples=60, deadline=None)
@given(**TILTED_BOX, stored=st.floats(-math.pi, math.pi), floor=st.sampled_from([SLIP_FLOOR, 0.1]))
def test_a_kinetic_edge_s_solution_is_its_2x2_system_s_at_the_settled_share(
    tilt, yaw, velocity, push, stored, floor
):
    # the kinetic search's solution comes from its last closed form's terms (c_r |w|, |w|,
    # det |w|; body_solve._edge_forces): the same accelerations and forces as the 2 x 2
    # system solved again at the share it settled on, with its u (body_solve._edge_solution).
    # Tolerance 1e-9 of g and of m g: the round-off of the two forms
    par, y, record = tilted_box(tilt, yaw, velocity, push)
    mode = np.array([bk.EDGE, 2, 1], dtype=np.int64)
    data = np.zeros(bk.DATA_SIZE)
    data[bk.D_SLIP : bk.D_SLIP + 3] = math.cos(stored), math.sin(stored), 0.0
    data[bk.D_FLOOR] = floor
    sc = bk.new_scratch()
    ok, _, _ = body_solve.solve_at(par, record, 1.0, 0.0, y, mode, data, sc)
    assume(ok and sc[bk.SC_EDGE][2, bk.E_INTACT] == 1.0)  # settled (not the full solve)
    acc, lam = sc[bk.SC_ACC].copy(), sc[bk.SC_LAM].copy()
    ax, _ = bk.box_corner(par, 2)
    bx, _ = bk.box_corner(par, 3)
    share = (sc[bk.SC_CENTRE][0] - ax) / (bx - ax)
    assert body_solve._edge_solution(par, sc, share, sc[bk.SC_DIR].copy())
    np.testing.assert_allclose(acc, sc[bk.SC_ACC], rtol=0.0, atol=1e-9 * G)
    np.testing.assert_allclose(lam[:5], sc[bk.SC_LAM][:5], rtol=0.0, atol=1e-9 * BOX.mass * G)
