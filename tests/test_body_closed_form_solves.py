"""The closed-form solves of four modes against the general one on their rows (#18).

``solve_mode`` solves a sticking POINT (a cylinder's rim point rolling, a
box's corner held) about the point, on its inertia there
(``body_kernel.solve_sticking_point``), a sticking EDGE (a box rocking on
it) by the null-space method on its hinge (``body_kernel.solve_sticking_edge``),
a sticking FACE by back substitution on its six rows
(``body_kernel.solve_sticking_face``), and a sliding FACE (a flat base sliding and twisting, its friction at its
centre of pressure) by eliminating its normal force
(``body_kernel.solve_sliding_face``), rather than on their rows in general
(``solve_held_rows``). Each must agree with
the general solve to round-off for any body, state and load, at the
acceleration level and at the velocity level (an impact).
"""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from freestand.core.body import Body, Box, Cylinder
from freestand.core.contact import body_kernel as bk
from freestand.core.contact import body_solve
from freestand.core.dynamics import body_step
from freestand.core.model import Friction

G = 9.81
BODIES = (
    Body("box", Box((1.0, 0.6, 2.0)), 400.0, Friction(0.5, 0.5)),
    Body("off-centre box", Box((0.4, 1.3, 0.8)), 25.0, Friction(0.9, 0.7), (0.05, -0.2, 0.3)),
    Body("cylinder", Cylinder(0.4, 3.0), 2000.0, Friction(0.5, 0.5)),
    Body("hollow cask", Cylinder(1.7, 6.0, 1.2), 1.8e5, Friction(0.3, 0.3)),
)


def _moving(rng, y):
    """Random velocities in the state y [m/s, rad/s] (its attitude the caller's); a random
    support acceleration [m/s^2], as a record of two samples."""
    y[7:10] = rng.normal(size=3)
    y[10:13] = rng.normal(size=3) * 3.0
    return rng.normal(size=(3, 2)) * 5.0


def _turned_at_random(which, seed):
    """(parameters of body ``which``, the seed's generator, a state at rest at a random
    attitude)."""
    par = bk.body_parameters(BODIES[which], G)
    rng = np.random.default_rng(seed)
    y = np.zeros(bk.STATE_SIZE)
    quaternion = rng.normal(size=4)
    y[3:7] = quaternion / np.linalg.norm(quaternion)
    return par, rng, y


def _closed_and_general(closed, general):
    """((acc, lam) of the closed-form solve, (acc, lam) of the general one); each solve is a
    function of the arrays it fills, and must succeed."""
    results = []
    for solve in (closed, general):
        acc, lam = np.zeros(6), np.zeros(6)
        assert solve(acc, lam)
        results.append((acc, lam))
    return results


@settings(max_examples=200, deadline=None)
@given(
    st.integers(0, len(BODIES) - 1), st.integers(0, 3), st.integers(0, 2**32 - 1),
    st.booleans(),
)  # fmt: skip
def test_a_sticking_point_is_solved_as_on_its_rows(which, corner, seed, acceleration):
    par, rng, y = _turned_at_random(which, seed)
    record = _moving(rng, y)
    psi = float(rng.uniform(-np.pi, np.pi))  # a cylinder's rim point
    sc = bk.new_scratch()
    bk.prepare(par, record, 1.0, 0.5, y, bk.POINT, corner, psi, sc)
    # the acceleration level from M^-1 f_0, the velocity level from the velocity before
    base = sc[bk.SC_BASE].copy() if acceleration else y[7:13].copy()
    (acc, lam), (acc_rows, lam_rows) = _closed_and_general(
        lambda acc, lam: bk.solve_sticking_point(par, sc, base, acceleration, acc, lam),
        lambda acc, lam: bk.solve_held_rows(
            par, sc, base, acceleration, 0, np.zeros(3), 1, 2, acc, lam
        ),
    )
    lam, lam_rows = lam[:3], lam_rows[:3]
    # tolerance: round-off of the two orders of the same products, relative to the largest
    # term (the accelerations or velocities, the forces or impulses)
    scale = np.max(np.abs(acc_rows)) + np.max(np.abs(base)) + G
    np.testing.assert_allclose(acc, acc_rows, rtol=0.0, atol=1e-12 * scale)
    np.testing.assert_allclose(lam, lam_rows, rtol=0.0, atol=1e-12 * np.max(np.abs(lam_rows)))
    # the held rows: the point's acceleration (or velocity after) is zero along z, x and y
    rows = np.column_stack([sc[bk.SC_NORMAL][:, 0], sc[bk.SC_TANGENT][:, :2]])
    bias = np.array([sc[bk.SC_NBIAS][0], *sc[bk.SC_TBIAS][:2]]) if acceleration else 0.0
    np.testing.assert_allclose(rows.T @ acc + bias, 0.0, atol=1e-11 * scale)


@settings(max_examples=200, deadline=None)
@given(st.integers(0, len(BODIES) - 1), st.integers(0, 2**32 - 1), st.booleans(), st.booleans())
def test_a_sliding_face_is_solved_as_on_its_rows(which, seed, acceleration, flat):
    body = BODIES[which]
    par = bk.body_parameters(body, G)
    rng = np.random.default_rng(seed)
    y = np.zeros(bk.STATE_SIZE)
    if flat:  # a yaw only, as a FACE slides; otherwise any attitude (the algebra holds for any)
        yaw = rng.uniform(-np.pi, np.pi)
        y[3:7] = np.cos(yaw / 2), 0.0, 0.0, np.sin(yaw / 2)
    else:
        quaternion = rng.normal(size=4)
        y[3:7] = quaternion / np.linalg.norm(quaternion)
    record = _moving(rng, y)
    sc = bk.new_scratch()
    bk.prepare(par, record, 1.0, 0.5, y, bk.FACE, 0, 0.0, sc)
    # the friction centre somewhere on the base, off its centre (the CoP's twist terms)
    centre = sc[bk.SC_CENTRE]
    centre[0], centre[1] = rng.uniform(-0.9, 0.9, size=2) * par[bk.P_HALF_X : bk.P_HALF_Y + 1]
    centre[2] = bk.effective_twist_radius(par, bk.FACE, 0, centre[0], centre[1])
    bk.tangent_rows(par, y, sc)
    direction = rng.normal(size=3)
    direction /= np.linalg.norm(direction)
    base = sc[bk.SC_BASE].copy() if acceleration else y[7:13].copy()
    (acc, lam), (acc_rows, lam_rows) = _closed_and_general(
        lambda acc, lam: bk.solve_sliding_face(par, sc, base, acceleration, direction, acc, lam),
        lambda acc, lam: bk.solve_held_rows(
            par, sc, base, acceleration, 1, direction, 3, 3, acc, lam
        ),
    )
    # tolerance: round-off of an elimination against Cramer's rule on the same 3 x 3 system,
    # relative to the largest term (the accelerations or velocities; N and its couples, whose
    # lever arms are the base's half-widths)
    scale = np.max(np.abs(acc_rows)) + np.max(np.abs(base)) + G
    np.testing.assert_allclose(acc, acc_rows, rtol=0.0, atol=1e-11 * scale)
    force = abs(lam_rows[0]) + np.max(np.abs(lam_rows[1:3])) / par[bk.P_HALF_X]
    np.testing.assert_allclose(lam[0], lam_rows[0], rtol=0.0, atol=1e-11 * force)
    np.testing.assert_allclose(lam[1:3], lam_rows[1:3], rtol=0.0,
                               atol=1e-11 * force * par[bk.P_HALF_X])  # fmt: skip
    np.testing.assert_allclose(lam[3:6], lam_rows[3:6], rtol=0.0, atol=1e-11 * force)
    # the held rows: the base centre's vertical acceleration and the tilt rates' vanish
    rows = sc[bk.SC_NORMAL][:, :3]
    bias = sc[bk.SC_NBIAS][:3] if acceleration else 0.0
    np.testing.assert_allclose(rows.T @ acc + bias, 0.0, atol=1e-10 * scale)


@settings(max_examples=200, deadline=None)
@given(st.integers(0, len(BODIES) - 1), st.integers(0, 2**32 - 1), st.booleans(), st.booleans())
def test_a_sticking_face_is_solved_as_on_its_rows(which, seed, acceleration, centred):
    par, rng, y = _turned_at_random(which, seed)  # any attitude: the algebra holds for any
    record = _moving(rng, y)
    sc = bk.new_scratch()
    bk.prepare(par, record, 1.0, 0.5, y, bk.FACE, 0, 0.0, sc)
    if not centred:  # the friction centre off the base centre, as a CoP puts it
        centre = sc[bk.SC_CENTRE]
        centre[0], centre[1] = rng.uniform(-0.9, 0.9, size=2) * par[bk.P_HALF_X : bk.P_HALF_Y + 1]
        centre[2] = bk.effective_twist_radius(par, bk.FACE, 0, centre[0], centre[1])
        bk.tangent_rows(par, y, sc)
    base = sc[bk.SC_BASE].copy() if acceleration else y[7:13].copy()
    (acc, lam), (acc_rows, lam_rows) = _closed_and_general(
        lambda acc, lam: bk.solve_sticking_face(par, sc, base, acceleration, acc, lam),
        lambda acc, lam: bk.solve_held_rows(
            par, sc, base, acceleration, 0, np.zeros(3), 3, 3, acc, lam
        ),
    )
    # tolerance: round-off of back substitution against L D L^T on the same 6 x 6 system,
    # relative to the largest term (the accelerations or velocities; the forces, and the
    # couples over the base's half-width)
    scale = np.max(np.abs(acc_rows)) + np.max(np.abs(base)) + G
    np.testing.assert_allclose(acc, acc_rows, rtol=0.0, atol=1e-11 * scale)
    arm = par[bk.P_HALF_X]
    force = np.max(np.abs(lam_rows[[0, 3, 4]])) + np.max(np.abs(lam_rows[[1, 2, 5]])) / arm
    np.testing.assert_allclose(lam[[0, 3, 4]], lam_rows[[0, 3, 4]], rtol=0.0, atol=1e-11 * force)
    np.testing.assert_allclose(lam[[1, 2]], lam_rows[[1, 2]], rtol=0.0, atol=1e-11 * force * arm)
    np.testing.assert_allclose(lam[5], lam_rows[5], rtol=0.0, atol=1e-11 * force)
    # the six held rows: every motion of the base vanishes
    rows = np.column_stack([sc[bk.SC_NORMAL][:, :3], sc[bk.SC_TANGENT][:, :3]])
    bias = np.r_[sc[bk.SC_NBIAS][:3], sc[bk.SC_TBIAS][:3]] if acceleration else 0.0
    np.testing.assert_allclose(rows.T @ acc + bias, 0.0, atol=1e-10 * scale)


@settings(max_examples=200, deadline=None)
@given(
    st.integers(0, 1), st.integers(0, 3), st.integers(0, 2**32 - 1), st.booleans(), st.booleans(),
)  # fmt: skip
def test_a_sticking_edge_is_solved_as_on_its_rows(which, edge, seed, acceleration, on_base):
    body = BODIES[which]  # the boxes
    par = bk.body_parameters(body, G)
    rng = np.random.default_rng(seed)
    y = np.zeros(bk.STATE_SIZE)
    if on_base:  # tilted about the edge's own axis after a yaw, as an EDGE rocks
        ax, ay = bk.box_corner(par, edge)
        bx, by = bk.box_corner(par, (edge + 1) % 4)
        axis = np.array([bx - ax, by - ay, 0.0]) / np.hypot(bx - ax, by - ay)
        yaw, tilt = rng.uniform(-np.pi, np.pi), rng.uniform(0.0, 1.2)
        about = np.r_[np.cos(tilt / 2), np.sin(tilt / 2) * axis]  # body-frame tilt, then yaw
        turn = np.array([np.cos(yaw / 2), 0.0, 0.0, np.sin(yaw / 2)])
        w0, v0 = turn[0], turn[1:]
        w1, v1 = about[0], about[1:]
        y[3:7] = np.r_[w0 * w1 - v0 @ v1, w0 * v1 + w1 * v0 + np.cross(v0, v1)]
    else:  # any attitude: the algebra holds for any
        quaternion = rng.normal(size=4)
        y[3:7] = quaternion / np.linalg.norm(quaternion)
    record = _moving(rng, y)
    sc = bk.new_scratch()
    bk.prepare(par, record, 1.0, 0.5, y, bk.EDGE, edge, 0.0, sc)
    base = sc[bk.SC_BASE].copy() if acceleration else y[7:13].copy()
    (acc, lam), (acc_rows, lam_rows) = _closed_and_general(
        lambda acc, lam: bk.solve_sticking_edge(par, sc, base, acceleration, acc, lam),
        lambda acc, lam: bk.solve_held_rows(
            par, sc, base, acceleration, 0, np.zeros(3), 2, 3, acc, lam
        ),
    )
    lam, lam_rows = lam[:5], lam_rows[:5]
    # tolerance: round-off of the null-space method against L D L^T on the 5 x 5 system, relative
    # to the largest term (the accelerations or velocities; the forces or impulses, the twist's
    # over its radius, which is of the base's size)
    scale = np.max(np.abs(acc_rows)) + np.max(np.abs(base)) + G
    np.testing.assert_allclose(acc, acc_rows, rtol=0.0, atol=1e-11 * scale)
    np.testing.assert_allclose(lam, lam_rows, rtol=0.0, atol=1e-10 * np.max(np.abs(lam_rows)))
    # the held rows: the corners' vertical, the centre's horizontal and the twist rates vanish
    rows = np.column_stack([sc[bk.SC_NORMAL][:, :2], sc[bk.SC_TANGENT][:, :3]])
    bias = np.r_[sc[bk.SC_NBIAS][:2], sc[bk.SC_TBIAS][:3]] if acceleration else 0.0
    np.testing.assert_allclose(rows.T @ acc + bias, 0.0, atol=1e-10 * scale)


@settings(max_examples=150, deadline=None)
@given(
    st.integers(0, len(BODIES) - 1), st.integers(0, 3), st.integers(0, 2**32 - 1), st.booleans(),
)  # fmt: skip
def test_a_sticking_point_or_edges_event_functions_are_the_full_solves(which, index, seed, edge):
    # body_step.event_functions solves a sticking POINT or a box's sticking EDGE by its closed
    # form on the applied wrench (body_solve.sticking_solve), not by solve_at: its event
    # functions (normal and friction margins, the other corners' gaps or the rim's landing,
    # the tilt), its accelerations, multipliers (an EDGE's friction about its centre of
    # pressure) and tangential rows must be solve_at's, to round-off (tolerance as above)
    edge = edge and which < 2  # an EDGE: the boxes'
    par, rng, y = _turned_at_random(which, seed)
    record = _moving(rng, y)
    mode = np.array([bk.EDGE if edge else bk.POINT, index, 0])
    data = np.zeros(bk.DATA_SIZE)
    data[bk.D_PSI] = float(rng.uniform(-np.pi, np.pi))
    ref = np.zeros(body_step.REF_SIZE)
    ref[3:5] = np.cos(data[bk.D_PSI]), np.sin(data[bk.D_PSI])
    values, kinds = np.zeros(body_step.MAX_EVENT_FUNCTIONS), np.zeros(8, dtype=np.int64)
    sc = bk.new_scratch()
    count = body_step.event_functions(par, record, 1.0, 0.5, y, mode, data, sc, ref, values, kinds)
    full = bk.new_scratch()
    _, n_normal, n_tangent = body_solve.solve_at(par, record, 1.0, 0.5, y, mode, data, full)
    expected = np.zeros_like(values)
    expected_kinds = np.zeros_like(kinds)
    assert count == body_step.event_values(par, y, mode, full, ref, n_normal, n_tangent,
                                           expected, expected_kinds)  # fmt: skip
    assert np.array_equal(kinds[:count], expected_kinds[:count])
    scale = np.max(np.abs(full[bk.SC_ACC])) + G
    np.testing.assert_allclose(sc[bk.SC_ACC], full[bk.SC_ACC], rtol=0.0, atol=1e-12 * scale)
    rows = n_normal + n_tangent
    forces = np.max(np.abs(full[bk.SC_LAM][:rows]))
    np.testing.assert_allclose(sc[bk.SC_LAM][:rows], full[bk.SC_LAM][:rows], rtol=0.0,
                               atol=1e-12 * forces)  # fmt: skip
    # the friction centre (x, y, rho [m]) and the tangential rows there
    size = float(par[bk.P_HALF_X])
    np.testing.assert_allclose(sc[bk.SC_CENTRE][:3], full[bk.SC_CENTRE][:3], rtol=0.0,
                               atol=1e-12 * size)  # fmt: skip
    np.testing.assert_allclose(sc[bk.SC_TANGENT][:, :n_tangent], full[bk.SC_TANGENT][:, :n_tangent],
                               rtol=0.0, atol=1e-12 * size)  # fmt: skip
    size = np.max(np.abs(expected[:count])) + forces
    np.testing.assert_allclose(values[:count], expected[:count], rtol=0.0, atol=1e-12 * size)


@settings(max_examples=100, deadline=None)
@given(st.integers(0, len(BODIES) - 1), st.integers(0, 3), st.integers(0, 2**32 - 1), st.booleans())
def test_a_solve_on_the_scratchs_load_is_the_full_closed_form(which, index, seed, edge):
    # body_step.start_functions solves a rolling cylinder's step start, whose end the
    # scratch holds solved for the pivot before, on the scratch's rotation and applied
    # wrench (body_solve.sticking_solve(..., loaded=True)): the same solve to the last bit
    # as one from nothing, for another pivot or index
    edge = edge and which < 2
    par, rng, y = _turned_at_random(which, seed)
    record = _moving(rng, y)
    kind = bk.EDGE if edge else bk.POINT
    data = np.zeros(bk.DATA_SIZE)
    data[bk.D_PSI] = float(rng.uniform(-np.pi, np.pi))
    sc = bk.new_scratch()
    body_solve.sticking_solve(par, record, 1.0, 0.5, y, np.array([kind, index, 0]), data, sc)
    moved = np.array([kind, (index + 1) % 4, 0])
    data[bk.D_PSI] = float(rng.uniform(-np.pi, np.pi))
    assert body_solve.sticking_solve(par, record, 1.0, 0.5, y, moved, data, sc, True)
    fresh = bk.new_scratch()
    assert body_solve.sticking_solve(par, record, 1.0, 0.5, y, moved, data, fresh)
    for field in (bk.SC_ACC, bk.SC_LAM, bk.SC_NORMAL, bk.SC_TANGENT, bk.SC_CENTRE):
        assert np.array_equal(sc[field], fresh[field])
