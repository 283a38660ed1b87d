"""The impact law rules out a sticking FACE or EDGE by closed form only where its solve fails (#18).

A rocking box that lands flat touches at its four corners: the impact law
tries the FACE sticking, then each EDGE, each a solve of 5 or 6 rows
(:func:`~freestand.core.contact.body_modes.impact`). The FACE and the edge
the box turned about are never admissible there. Their velocity after is
known in closed form (zero; a turn about the edge,
:func:`~freestand.core.contact.body_stick_bounds.edge_turn`), and so are a
lower bound on the friction their impulse needs and the other corners'
normal velocities after (:func:`stick_impact_excluded`).

Checked here: the closed form is the solve's velocity after; a candidate
ruled out is never one the solve admits (random bodies, poses and
velocities); at a rocking cabinet's landing the FACE and the old pivot are
ruled out, and the law takes the landing edge with Housner's ratio of
angular velocities, ``1 - 3/2 sin^2 alpha`` (Housner 1963).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from freestand.core.body import Body, Box, Cylinder
from freestand.core.contact.body_kernel import (
    DATA_SIZE,
    EDGE,
    FACE,
    FREE,
    M_INDEX,
    M_KIND,
    M_SLIP,
    P_HALF_X,
    P_MASS,
    SC_ACC,
    SC_BASE,
    SC_DIR,
    SC_TOUCHING,
    body_parameters,
    new_scratch,
    prepare,
    rotation_matrix,
)
from freestand.core.contact.body_modes import (
    RELATIVE_TOLERANCE,
    VELOCITY,
    _solve,
    candidate_speed,
    impact,
    touching_points,
    try_mode,
)
from freestand.core.contact.body_stick_bounds import edge_turn, stick_impact_excluded
from freestand.core.model import Friction

GAP_TOLERANCE = 1e-7  # [m] the engine's default
# the closed form against the solve of the same rows: both to round-off
CLOSED_FORM_TOLERANCE = 1e-10


def _box(size, mass, mu, centre=None):
    return Body("box", Box(tuple(size)), mass, Friction(mu, mu), centre=centre)


def _pose(par, yaw, tilt, azimuth):
    """Yawed, then tilted about a horizontal axis; the lowest corner on the support."""
    q_yaw = np.array([math.cos(0.5 * yaw), 0.0, 0.0, math.sin(0.5 * yaw)])
    axis = (math.cos(azimuth), math.sin(azimuth))
    q_tilt = np.array([math.cos(0.5 * tilt), math.sin(0.5 * tilt) * axis[0],
                       math.sin(0.5 * tilt) * axis[1], 0.0])  # fmt: skip
    w1, x1, y1, z1 = q_tilt
    w2, x2, y2, z2 = q_yaw
    y = np.zeros(13)
    y[3:7] = (w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
              w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2)  # fmt: skip
    rot = np.empty((3, 3))
    rotation_matrix(y, rot)
    lowest = min(
        (rot @ (np.array([sx * par[P_HALF_X], sy * par[P_HALF_X + 1], 0.0]) - par[19:22]))[2]
        for sx in (-1.0, 1.0)
        for sy in (-1.0, 1.0)
    )
    y[2] = -lowest
    return y


def _instant(body, y):
    """The instant's rotation and inverse inertia, its base the velocity before (as the impact
    law sets it; the record plays no part at the velocity level)."""
    par = body_parameters(body, 9.81)
    sc = new_scratch()
    prepare(par, np.zeros((3, 2)), 1.0, 0.0, y, FREE, 0, 0.0, sc)
    sc[SC_BASE][:] = y[7:13]
    return par, sc


def _scales(par, y):
    """The impact law's tolerances (body_modes.impact)."""
    speed = max(np.linalg.norm(y[7:10]) + par[P_HALF_X] * np.linalg.norm(y[10:13]), 1e-6)
    return RELATIVE_TOLERANCE * par[P_MASS] * speed, RELATIVE_TOLERANCE * speed


def _admissible(par, y, sc, kind, index, touching):
    """The candidate's own test: its sticking solve at the velocity level (body_modes.try_mode)."""
    data = np.zeros(DATA_SIZE)
    return try_mode(par, y, sc, kind, index, 0.0, 0, VELOCITY, touching, 0.0, _scales(par, y),
                    data)  # fmt: skip


bodies = st.builds(
    _box,
    st.tuples(st.floats(0.2, 3.0), st.floats(0.2, 3.0), st.floats(0.2, 6.0)),
    st.floats(10.0, 1e5),
    st.floats(0.1, 2.0),
)
# [m/s] and [rad/s]; below 1e-9 zero (a scale of round-off far under the floats' own)
velocities = st.lists(st.floats(-2.0, 2.0).map(lambda v: 0.0 if abs(v) < 1e-9 else v),
                      min_size=6, max_size=6)  # fmt: skip


@settings(max_examples=150, deadline=None)
@given(bodies, st.floats(-math.pi, math.pi), st.floats(0.0, 0.2), st.floats(-math.pi, math.pi),
       velocities, st.integers(0, 3))  # fmt: skip
def test_an_edges_turn_is_its_solves_velocity_after(body, yaw, tilt, azimuth, velocity, index):
    y = _pose(body_parameters(body, 9.81), yaw, tilt, azimuth)
    y[7:13] = velocity
    par, sc = _instant(body, y)
    s, ux, uy, uz, ex, ey = edge_turn(par, y, sc, index)
    n_normal, n_tangent, _ = candidate_speed(par, y, sc, EDGE, index, 0.0)
    sc[SC_ACC][:] = math.nan
    if not _solve(par, y, sc, VELOCITY, 0, sc[SC_DIR], n_normal, n_tangent):
        return
    closed = s * np.array([ux, uy, uz, ex, ey, 0.0])
    scale = np.linalg.norm(velocity) * (1.0 + np.linalg.norm(body.shape.size))
    np.testing.assert_allclose(closed, sc[SC_ACC], rtol=0.0, atol=CLOSED_FORM_TOLERANCE * scale)


@settings(max_examples=300, deadline=None)
@given(bodies, st.floats(-math.pi, math.pi), st.floats(0.0, 1e-3), st.floats(-math.pi, math.pi),
       velocities, st.lists(st.booleans(), min_size=4, max_size=4), st.booleans())  # fmt: skip
def test_a_candidate_ruled_out_is_never_admissible(body, yaw, tilt, azimuth, velocity, extra,
                                                   falling):  # fmt: skip
    y = _pose(body_parameters(body, 9.81), yaw, tilt, azimuth)
    y[7:13] = velocity
    if falling:
        y[9] = -abs(y[9])
    par, sc = _instant(body, y)
    touching = sc[SC_TOUCHING]
    touching[:] = 0
    touching[:4] = [1 if flag else 0 for flag in extra]
    force_tol, rate_tol = _scales(par, y)
    kinds = [(FACE, 0)] if all(extra) else []
    kinds += [(EDGE, k) for k in range(4) if extra[k] and extra[(k + 1) % 4]]
    for kind, index in kinds:
        if stick_impact_excluded(par, y, sc, kind, index, touching, force_tol, rate_tol):
            assert not _admissible(par, y, sc, kind, index, touching), (kind, index)


def _rocking_landing(body, omega):
    """A box rocking about its edge 1 (corners 1-2, x = -b_x) that lands flat on edge 3."""
    par = body_parameters(body, 9.81)
    y = _pose(par, 0.0, 0.0, 0.0)
    pivot = np.array([-par[P_HALF_X], 0.0, 0.0]) - par[19:22]  # from G to the old pivot's line
    w = np.array([0.0, omega, 0.0])  # turning down onto x = +b_x
    y[7:10] = np.cross(w, -pivot)
    y[10:13] = w
    par, sc = _instant(body, y)
    return par, y, sc


def test_a_rocking_cabinet_lands_on_its_edge_with_housners_ratio():
    # the benchmark's cabinet turned a quarter: its long edges along y, at x = +-0.3 m
    body = _box((0.6, 1.0, 2.0), 400.0, 0.5)
    par, y, sc = _rocking_landing(body, 0.05)
    touching = sc[SC_TOUCHING]
    touching_points(par, y, sc, GAP_TOLERANCE, 0.0, VELOCITY, touching)
    assert list(touching[:4]) == [1, 1, 1, 1]
    force_tol, rate_tol = _scales(par, y)
    # the FACE (it would stop the body) and the old pivot (corners 1-2) are ruled out
    assert stick_impact_excluded(par, y, sc, FACE, 0, touching, force_tol, rate_tol)
    assert stick_impact_excluded(par, y, sc, EDGE, 1, touching, force_tol, rate_tol)
    assert not stick_impact_excluded(par, y, sc, EDGE, 3, touching, force_tol, rate_tol)
    # the law takes the first admissible candidate in its order: the landing edge 3
    first = next(c for c in [(FACE, 0)] + [(EDGE, k) for k in range(4)]
                 if _admissible(par, y, sc, *c, touching))  # fmt: skip
    assert first == (EDGE, 3)
    mode = np.zeros(3, dtype=np.int64)
    after = np.zeros(6)
    impact(par, y, sc, GAP_TOLERANCE, 0.0, mode, np.zeros(DATA_SIZE), after)
    assert (mode[M_KIND], mode[M_INDEX], mode[M_SLIP]) == (EDGE, 3, 0)
    sin_alpha = 0.3 / math.hypot(0.3, 1.0)
    # Housner's plastic impact of a homogeneous block (to the round-off of the solve)
    assert after[4] / y[11] == pytest.approx(1.0 - 1.5 * sin_alpha**2, rel=1e-12)


def test_a_cylinder_landing_flat_rules_out_its_base_only_where_it_would_fail():
    body = Body("cylinder", Cylinder(0.4, 3.0), 2000.0, Friction(0.5, 0.5))
    y = np.zeros(13)
    y[3] = 1.0
    y[2] = 1.5
    y[7:13] = (0.3, 0.0, -0.05, 0.0, 0.2, 0.0)
    par, sc = _instant(body, y)
    touching = sc[SC_TOUCHING]
    touching[:] = 0
    touching[0] = 1
    force_tol, rate_tol = _scales(par, y)
    assert stick_impact_excluded(par, y, sc, FACE, 0, touching, force_tol, rate_tol)
    assert not _admissible(par, y, sc, FACE, 0, touching)
    y[7:13] = (0.0, 0.0, -0.05, 0.0, 0.0, 0.0)  # straight down: the base stops, admissible
    par, sc = _instant(body, y)
    assert not stick_impact_excluded(par, y, sc, FACE, 0, touching, force_tol, rate_tol)
    assert _admissible(par, y, sc, FACE, 0, touching)
