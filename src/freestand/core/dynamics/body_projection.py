"""The 3-D engine's projection: a held contact's state set back onto its constraints.

After a step, the held patch's gaps and normal velocities drift from zero by
the integrator's error; :func:`drifted` says when they have drifted past a
small part of the tolerances, and :func:`project` sets them back (a FACE flat
on the support, an EDGE's two corners on it, a POINT on it, their normal
velocities zero). :func:`lean_comes_flat` tells a rolling cylinder whose lean
whirls within ``PIVOT_LEAN`` of flat that it lands, and :func:`turn` turns
the state's attitude by a rotation vector. Called by the loop
(:mod:`freestand.core.dynamics.body_engine`) and the remedy
(:mod:`freestand.core.dynamics.body_remedy`).
"""

from __future__ import annotations

import math

from freestand.core.contact.body_kernel import (
    D_ONSET,
    D_PSI,
    EDGE,
    FACE,
    FREE,
    M_INDEX,
    M_KIND,
    M_SLIP,
    P_HALF_X,
    P_SHAPE,
    PIVOT_LEAN,
    POINT,
    SC_ARMS,
    SC_DIR,
    SC_NORMAL,
    SC_PROBE,
    SC_ROT,
    SC_SVEL,
    SC_TANGENT,
    SHAPE_BOX,
    arm,
    corner_gap,
    cross,
    pivot_direction,
    quaternion_product,
    rotation_matrix,
    row_counts,
    solve_mode,
    tangential_velocity,
)
from freestand.core.contact.body_solve import prepare_held
from freestand.core.contact.compiled import kernel
from freestand.core.contact.vectors import norm2
from freestand.core.dynamics.body_step import (
    PLANAR_PASS,
    _normalise,
)

FLAT_ROUND_OFF = 1e-13  # [m, m/s, rad/s, -] a sliding flat base's drift left to round-off
DRIFT_FRACTION = 1e-3  # an EDGE's or POINT's drift above this part of a tolerance is projected


@kernel(cache=True, error_model="numpy", _nrt=False)
def lean_comes_flat(par, y, mode, sc):
    """True when a rolling cylinder's lean whirls within ``PIVOT_LEAN`` of flat, closing.

    There the rim point it rolls on is kept
    (:func:`~freestand.core.contact.body_kernel.pivot_direction`): a lean that
    whirls past the vertical at about ``PIVOT_LEAN`` would swing round the
    rim about a point that is no longer the lowest (the rolling disc's finite
    time singularity, Le Saux et al. 2005). The base is then flat to 2 R
    PIVOT_LEAN: it lands (:func:`resolve`). A lean heading for the vertical
    (to pass it within ``PLANAR_PASS`` of ``PIVOT_LEAN``, as in a plane) is
    located by the landing function instead, and a lean growing from flat is
    not closing. ``sc`` holds the rotation at y (the step's end, solved by
    the event functions of :func:`~freestand.core.dynamics.body_events.locate`).
    """
    if par[P_SHAPE] == SHAPE_BOX or mode[M_KIND] != POINT:
        return False
    rot = sc[SC_ROT]
    ex, ey = rot[0, 2], rot[1, 2]
    if ex * ex + ey * ey > PIVOT_LEAN * PIVOT_LEAN:
        return False
    ux, uy, _ = cross(y[10], y[11], y[12], ex, ey, rot[2, 2])
    if ex * ux + ey * uy >= 0.0:
        return False
    # the distance at which the lean passes the vertical, |e_h x e_h'| / |e_h'|
    return abs(ex * uy - ey * ux) > PLANAR_PASS * PIVOT_LEAN * norm2(ux, uy)


@kernel(cache=True, error_model="numpy", _nrt=False)
def flatten(par, y, rot, d):
    """The base flat on the support: the tilt removed (a pure yaw), the base centre at z = 0.

    ``d`` (3) is work space.
    """
    size = math.hypot(y[3], y[6])
    y[3] /= size
    y[4] = 0.0
    y[5] = 0.0
    y[6] /= size
    rotation_matrix(y, rot)
    arm(par, rot, 0.0, 0.0, 0.0, d)
    y[2] -= y[2] + d[2]


@kernel(cache=True, error_model="numpy", _nrt=False)
def _level_edge(par, y, rot, index, probe):
    """An EDGE's two corners set on the support: their difference by a turn, then their mean.

    The turn phi is about the horizontal axis n across the edge (``n = e_z x
    u / |u_h|``, u the edge from its first corner to its second) through the
    edge's midpoint M, which moves corner B by ``phi n x (B - M)`` and A by
    its opposite: ``phi = -(g_B - g_A) / (n x u)_z``; the centre of gravity
    moves by ``phi n x (G - M)``. Then the mean gap is taken out by a
    vertical shift. A vertical shift alone, this projection before
    2026-11-29, left the corners' difference to grow from step to step: a
    slender random box with a non-principal inertia rocking on an edge at 6
    rad/s under 7 g (the benchmark's ``robust_case`` 1186 under its record
    times 23) drifted to +-2e-6 m in 20 ms, and its run ended `failed` (the
    contact lost). ``rot`` the rotation at y (updated here); ``probe`` (3, 6)
    work space.
    """
    a, b = probe[0], probe[1]
    g0, _ = corner_gap(par, y, rot, index, a)
    g1, _ = corner_gap(par, y, rot, (index + 1) % 4, b)
    ux, uy = b[0] - a[0], b[1] - a[1]
    length = norm2(ux, uy)
    if length > 0.0 and g1 != g0:
        nx, ny = -uy / length, ux / length
        phi = (g1 - g0) / length  # -(g1 - g0) / (n x u)_z, (n x u)_z = -|u_h|
        # G - M = -(a + b) / 2 (a, b the corners' arms from G)
        gx, gy, gz = cross(phi * nx, phi * ny, 0.0, -0.5 * (a[0] + b[0]), -0.5 * (a[1] + b[1]),
                           -0.5 * (a[2] + b[2]))  # fmt: skip
        y[0] += gx
        y[1] += gy
        y[2] += gz
        turn(y, phi * nx, phi * ny, 0.0)
        rotation_matrix(y, rot)
        g0, _ = corner_gap(par, y, rot, index, a)
        g1, _ = corner_gap(par, y, rot, (index + 1) % 4, b)
    y[2] -= 0.5 * (g0 + g1)


@kernel(cache=True, error_model="numpy", _nrt=False)
def project(par, record, dt, t, y, mode, data, sc, settle_below=0.0):
    """Remove the drift of the held rows: positions on the support, their velocities zero.

    A slip starting from rest (``data[D_ONSET]``, the mode's choice; its
    speed within ``settle_below`` [m/s], the event's velocity tolerance) has
    its residual slip velocity removed too: the residual's direction is
    round-off, and the kinetic friction would follow it rather than the
    onset's direction until the slip has grown. A slip under way is never
    settled, however slow on the held rows: at rest in its own, kinetic
    direction, where static friction would hold, its friction would push
    the body and feed it energy.

    FACE: the tilt is removed (a pure yaw) and the base set on the support;
    EDGE: both corners set on the support (:func:`_level_edge`); POINT: the
    centre of gravity shifted vertically by the point's gap. Velocities: the
    least-kinetic-energy change that makes the held rows' velocities vanish
    (a plastic impact on the held rows), on the rows at the patch's
    geometric centre (a sticking patch's rows hold it still about any
    centre). The scratch is left with those rows, not a solve: every caller
    solves the mode at the projected state next.
    """
    kind = mode[M_KIND]
    if kind == FREE:
        return
    rot = sc[SC_ROT]
    rotation_matrix(y, rot)
    probe = sc[SC_PROBE]
    d = probe[0]
    if kind == FACE:
        flatten(par, y, rot, d)
    elif kind == EDGE:
        _level_edge(par, y, rot, mode[M_INDEX], probe)
    elif par[P_SHAPE] == SHAPE_BOX:
        g0, _ = corner_gap(par, y, rot, mode[M_INDEX], d)
        y[2] -= g0
    else:
        cos_psi, sin_psi = pivot_direction(par, rot, kind, data[D_PSI], sc)
        radius = par[P_HALF_X]
        arm(par, rot, radius * cos_psi, radius * sin_psi, 0.0, d)
        y[2] -= y[2] + d[2]
    # the held rows at the projected state (every caller solves the mode there next)
    n_normal, n_tangent = prepare_held(par, record, dt, t, y, mode, data, sc)
    base, after, lam = probe[0], probe[1], probe[2]  # the velocity before, after; impulses
    for i in range(6):
        base[i] = y[7 + i]
    held_tangent = n_tangent if mode[M_SLIP] == 0 else 0
    if held_tangent == 0 and settle_below > 0.0 and data[D_ONSET] == 1.0:
        svel = sc[SC_SVEL]
        tangential_velocity(y, sc[SC_TANGENT], n_tangent, svel)
        speed = 0.0
        for k in range(n_tangent):
            speed += svel[k] ** 2
        if math.sqrt(speed) <= settle_below:
            held_tangent = n_tangent
    if solve_mode(par, sc, base, False, 0, sc[SC_DIR], n_normal, held_tangent, after, lam):
        for i in range(6):
            y[7 + i] = after[i]


@kernel(cache=True, error_model="numpy", _nrt=False)
def drifted(par, y, mode, sc, gap_tol, velocity_tol):
    """True where the held rows have drifted enough to be projected (:func:`project`).

    ``sc`` holds the held mode solved at (t, y) (the step's end, solved by
    the event functions of :func:`~freestand.core.dynamics.body_events.locate`).
    A flat, sliding base's held rows are its height, its tilt and their
    rates, whose accelerations the mode holds at zero: RK4 keeps them at
    zero to round-off, ``FLAT_ROUND_OFF`` on each. An EDGE's or POINT's
    rows drift with the step's truncation error: they are projected where a
    held point's gap exceeds ``DRIFT_FRACTION`` of the gap tolerance
    ``gap_tol`` [m] (the planar engine's rule) or a held row's velocity
    ``DRIFT_FRACTION`` of ``velocity_tol`` [m/s] (a rolling rim point's
    creep: a drift the gap would not show). Below, the drift stays far
    inside the tolerances within which a point counts as touching and at
    rest, and the projection's two solves (its own, and the next step's
    start) are saved: the step's start is the solve the scratch holds. A
    rolling cylinder's rows drifted by 1e-11 m and 2e-9 m/s per step (the
    medians of the benchmark's slender cylinder). A FREE body holds no row;
    a sticking FACE that moves is always projected.
    """
    kind = mode[M_KIND]
    if kind == FREE:
        return False
    arms = sc[SC_ARMS]  # the held points' arms at (t, y); a FACE's first is its base centre
    if kind == FACE:
        if mode[M_SLIP] != 1:
            return True
        if max(abs(y[4]), abs(y[5]), abs(y[9]), abs(y[10]), abs(y[11])) > FLAT_ROUND_OFF:
            return True
        return abs(y[2] + arms[0, 2]) > FLAT_ROUND_OFF
    n_normal, n_tangent = row_counts(kind)
    speeds = sc[SC_PROBE][1]
    for r in range(n_normal):
        if abs(y[2] + arms[r, 2]) > DRIFT_FRACTION * gap_tol:
            return True
    held = tangential_velocity(y, sc[SC_NORMAL], n_normal, speeds)
    if mode[M_SLIP] == 0:
        held += tangential_velocity(y, sc[SC_TANGENT], n_tangent, speeds[n_normal:])
    for r in range(held):
        if abs(speeds[r]) > DRIFT_FRACTION * velocity_tol:
            return True
    return False


@kernel(cache=True, error_model="numpy", _nrt=False)
def turn(y, ax, ay, az):
    """Turn the orientation quaternion y[3:7] by the rotation vector (ax, ay, az) [rad] (world)."""
    angle = math.sqrt(ax * ax + ay * ay + az * az)
    if angle == 0.0:
        return
    c = math.cos(0.5 * angle)
    f = math.sin(0.5 * angle) / angle
    y[3], y[4], y[5], y[6] = quaternion_product(c, f * ax, f * ay, f * az, y[3], y[4], y[5],
                                                y[6])  # fmt: skip
    _normalise(y)
