"""The compiled event-driven time history of one rigid body on the support (3-D).

The loop has the shape of the planar engine (:mod:`freestand.core.dynamics.engine`):
:func:`run` repeats four named phases until the end time, each in a module
of its own where it is more than a few lines:

- ``advance`` (:mod:`freestand.core.dynamics.body_step`): one RK4 step of
  the held contact mode (the contact forces solved at every stage by
  :func:`freestand.core.contact.body_solve.rate`), its references and
  event functions, or nothing while the body rests flat and sticks (its
  contact multipliers are then affine in the support's accelerations, and a
  step is decided by its ends: :func:`rest_step`);
- ``locate`` (:mod:`freestand.core.dynamics.body_events`): the event
  functions at the step's end against its start; when one changed sign, the
  earliest crossing by Anderson and Bjorck's variant of regula falsi on RK4
  states from the step's start, to ``EVENT_TIME`` [s], its first trials
  seeded by the crossing on the step's cubic interpolant;
- :func:`resolve`: at an event, the impact law where a gap closed, then the
  contact mode of the new state (:func:`freestand.core.contact.body_modes.select_mode`),
  and the drift of the held rows projected out; where no mode exists, or an
  edge's slip keeps restarting from rest (:func:`watch_chatter`), a stretch
  of velocity-level time stepping (:func:`_stretch`);
- :func:`record`: the state and contact force written to the output buffers.

Event functions (each must stay >= 0 in the held mode): the normal margin of
the patch (N, the corner forces, a FACE's centre of pressure inside the
base), the friction margin of a sticking patch (``mu_0 N - |f_t|``), the slip
velocity along its direction at the step's start (a sliding patch), the gap of
each base corner not held (box), the landing of a cylinder on its base (its
axis's tilt vector along the pivot's direction: ``sin(tilt)`` in a plane),
and the tilt below pi/2.

As in the kernel (:mod:`freestand.core.contact.body_kernel`), the phases that
allocate nothing are compiled without reference counting (``_nrt=False``);
their work arrays (the scratch, the event functions' bracket) are
:func:`run`'s.
"""

from __future__ import annotations

import math

import numpy as np

from freestand.core.contact.body_impulse import (
    IMPULSE_WORK_DTYPE,
    MAX_POINTS,
    base_points,
    restitution_velocity,
    velocity_impact,
)
from freestand.core.contact.body_kernel import (
    D_FLOOR,
    D_ONSET,
    D_PSI,
    EDGE,
    FACE,
    FREE,
    M_INDEX,
    M_KIND,
    M_SLIP,
    P_CENTRE,
    P_GRAVITY,
    P_HALF_X,
    P_HALF_Y,
    P_MASS,
    P_MU_KINETIC,
    P_SHAPE,
    PIVOT_LEAN,
    POINT,
    SC_AFTER,
    SC_ANGLES,
    SC_ARMS,
    SC_BASE,
    SC_CENTRE,
    SC_DIR,
    SC_EXCLUDED,
    SC_INDICES,
    SC_INV,
    SC_KINDS,
    SC_LAM,
    SC_NORMAL,
    SC_POINTS,
    SC_PROBE,
    SC_ROT,
    SC_SVEL,
    SC_TANGENT,
    SC_TOUCHING,
    SHAPE_BOX,
    STATE_SIZE,
    arm,
    centre_stick_friction,
    corner_gap,
    cross,
    flat_gap,
    friction_margin,
    lowest_rim_angle,
    normal_margin,
    normal_total_rows,
    pivot_direction,
    point_velocity,
    prepare,
    reset_friction_centre,
    rotation_matrix,
    row_counts,
    solve_mode,
    support_acceleration,
    tangential_velocity,
)
from freestand.core.contact.body_modes import (
    ACCELERATION,
    NONE_ADMISSIBLE,
    candidates,
    clear_candidates,
    impact,
    select_mode,
    touching_points,
)
from freestand.core.contact.body_solve import prepare_held, solve_at, solve_at_centre
from freestand.core.contact.compiled import kernel
from freestand.core.dynamics.body_events import (
    EVENT_TIME,
    MARGIN_SLACK,
    inconsistent_start,
    locate,
)
from freestand.core.dynamics.body_step import (
    FN_FRICTION,
    FN_GAP,
    FN_LANDING,
    FN_NORMAL,
    FN_SLIP_STOP,
    FN_TILT,
    MAX_EVENT_FUNCTIONS,
    PLANAR_PASS,
    REF_SIZE,
    _normalise,
    advance,
    closing_step,
    energy_jump,
    may_pass_a_pole,
    resting,
    slip_floor,
    slip_velocity,
    start_functions,
    turn_step,
)

STRETCH_STEP = 1e-4  # [s] step of the velocity-level time stepping (the remedy)
STRETCH_CHECK = 16  # a stretch looks for a consistent mode at its steps 1, 2, 4, 8, 16, 32, 48, ...
STRETCH_IMPACT = 10.0  # a stretch's point approaching faster than this times g h lands [-]
CHATTER_WINDOW = 1e-3  # [s] slip restarts or remedies closer than this in time are a chatter
CHATTER_COUNT = 3  # this many in a row start a chatter stretch of the remedy
FACE_CHATTER_WINDOW = 1e-6  # [s] a FACE's slip restarts closer than this in time are a chatter
IMPACT_WINDOW = 1e-4  # [s] impacts closer than this in time (the remedy's step) accumulate
IMPACT_COUNT = 10  # this many accumulating impacts in a row start a stretch of the remedy
FLAT_ROUND_OFF = 1e-13  # [m, m/s, rad/s, -] a sliding flat base's drift left to round-off
DRIFT_FRACTION = 1e-3  # an EDGE's or POINT's drift above this part of a tolerance is projected

# event kinds
EV_START = 0
EV_IMPACT = 1
EV_LIFT_OFF = 2
EV_SLIP = 3
EV_STICK = 4
EV_OVERTURN = 5
EV_REMEDY = 6
EV_LANDING_MISS = 7
EVENT_KINDS = ("start", "impact", "lift-off", "slip", "stick", "overturn", "remedy", "pass-over")

# istate
I_RECORDS = 0
I_EVENTS = 1
I_STATUS = 2
I_STEPS = 3
I_REMEDIES = 4
I_IMPACTS = 5
I_STRETCH = 6  # while a stretch of time stepping runs (the remedy): its steps so far + 1; else 0
I_STRETCH_STEPS = 7
I_CHATTER = 8  # 1 while the stretch is a chatter's: it ends on a stick or a slip of speed
I_TRIALS = 9  # RK4 trials of the event searches (locate)
I_SIZE = 10

STATUS_RUNNING = 0
STATUS_COMPLETED = 1
STATUS_OVERTURNED = 2
STATUS_BUFFER_FULL = 3


@kernel(cache=True, error_model="numpy", _nrt=False)
def _lean_comes_flat(par, y, mode, sc):
    """True when a rolling cylinder's lean whirls within ``PIVOT_LEAN`` of flat, closing.

    There the rim point it rolls on is kept
    (:func:`~freestand.core.contact.body_kernel.pivot_direction`): a lean that
    whirls past the vertical at about ``PIVOT_LEAN`` would swing round the
    rim about a point that is no longer the lowest (the rolling disc's finite
    time singularity, Le Saux et al. 2005). The base is then flat to 2 R
    PIVOT_LEAN: it lands (:func:`resolve`). A lean heading for the vertical
    (to pass it within ``PLANAR_PASS`` of ``PIVOT_LEAN``, as in a plane) is
    located by the landing function instead, and a lean growing from flat is
    not closing.
    """
    if par[P_SHAPE] == SHAPE_BOX or mode[M_KIND] != POINT:
        return False
    rot = sc[SC_ROT]
    rotation_matrix(y, rot)
    ex, ey = rot[0, 2], rot[1, 2]
    if ex * ex + ey * ey > PIVOT_LEAN * PIVOT_LEAN:
        return False
    ux, uy, _ = cross(y[10], y[11], y[12], ex, ey, rot[2, 2])
    if ex * ux + ey * uy >= 0.0:
        return False
    # the distance at which the lean passes the vertical, |e_h x e_h'| / |e_h'|
    return abs(ex * uy - ey * ux) > PLANAR_PASS * PIVOT_LEAN * math.hypot(ux, uy)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _flatten(par, y, rot, d):
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
    length = math.hypot(ux, uy)
    if length > 0.0 and g1 != g0:
        nx, ny = -uy / length, ux / length
        phi = (g1 - g0) / length  # -(g1 - g0) / (n x u)_z, (n x u)_z = -|u_h|
        # G - M = -(a + b) / 2 (a, b the corners' arms from G)
        gx, gy, gz = cross(phi * nx, phi * ny, 0.0, -0.5 * (a[0] + b[0]), -0.5 * (a[1] + b[1]),
                           -0.5 * (a[2] + b[2]))  # fmt: skip
        y[0] += gx
        y[1] += gy
        y[2] += gz
        _turn(y, phi * nx, phi * ny, 0.0)
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
        _flatten(par, y, rot, d)
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
def _post_record_fall(par, y, mode, sc):
    """True when, without excitation, a pivoting body is past its top: tilting and falling."""
    if mode[M_KIND] != POINT and mode[M_KIND] != EDGE:
        return False
    rot = sc[SC_ROT]
    rotation_matrix(y, rot)
    # d(cos tilt)/dt = (omega x e_3)_z
    rate_cos = y[10] * rot[1, 2] - y[11] * rot[0, 2]
    return rate_cos < 0.0 and y[9] < 0.0


@kernel(cache=True, error_model="numpy", _nrt=False)
def resolve(par, record, dt, t, y, mode, data, sc, gap_tol, velocity_tol, which, istate, work):
    """Phase 3: the impact (a gap closed) and the next contact mode; the event kind.

    ``work``: the impulses' work record
    (:data:`~freestand.core.contact.body_impulse.IMPULSE_WORK_DTYPE`).
    """
    event = EV_LIFT_OFF
    if which == FN_FRICTION:
        event = EV_SLIP
    elif which == FN_SLIP_STOP:
        event = EV_STICK
    elif which == FN_TILT:
        return EV_OVERTURN
    rot = sc[SC_ROT]
    if which == FN_LANDING:
        # the base lands where it is flat: to the gap tolerance, or leaning by less than
        # PIVOT_LEAN (where the body turns about its stored rim point, as a planar block);
        # otherwise the lean passes over the vertical beside the pivot (it whirls)
        rotation_matrix(y, rot)
        gap = flat_gap(par, y, rot)
        if gap > gap_tol + 2.0 * par[P_HALF_X] * PIVOT_LEAN:
            event = EV_LANDING_MISS
            which = -1
        elif gap > gap_tol:
            _flatten(par, y, rot, sc[SC_PROBE][0])
    if which == FN_GAP or which == FN_LANDING:
        held_before = mode[M_KIND] != FREE
        prepare(par, record, dt, t, y, FREE, 0, 0.0, sc)
        after = sc[SC_AFTER]
        chosen = impact(par, y, sc, gap_tol, data[D_PSI], mode, data, after)
        arms = work["arms"]
        count = base_points(par, y, rot, data[D_PSI], gap_tol, arms, work)
        if chosen == NONE_ADMISSIBLE:
            # no candidate of the impact law: the velocity-level impact at the base points
            for i in range(6):
                after[i] = y[7 + i]
            start = work["zeros"]
            start[:, :] = 0.0
            velocity_impact(par, sc[SC_INV], arms, count, par[P_MU_KINETIC], after, start,
                            work)  # fmt: skip
            istate[I_REMEDIES] += 1
            event = EV_REMEDY
        else:
            istate[I_IMPACTS] += 1
            event = EV_IMPACT
        # the restitution factor on the velocity after (relative to the support)
        restitution_velocity(par, sc[SC_INV], arms, count, held_before, after, work)
        for i in range(6):
            y[7 + i] = after[i]
    _no_exclusion(sc)
    excluded = sc[SC_EXCLUDED]
    if which == FN_NORMAL:
        excluded[0] = mode[M_KIND]
        excluded[1] = mode[M_INDEX]
        excluded[2] = 2
    elif which == FN_FRICTION:
        excluded[0] = mode[M_KIND]
        excluded[1] = mode[M_INDEX]
    chosen = select_mode(par, record, dt, t, y, sc, gap_tol, velocity_tol, mode, data, excluded)
    if chosen == NONE_ADMISSIBLE:
        # no consistent mode (Painleve): a stretch of velocity-level time stepping
        istate[I_REMEDIES] += 1
        istate[I_STRETCH] = 1
        _set_free(mode)
        return EV_REMEDY
    project(par, record, dt, t, y, mode, data, sc, velocity_tol)
    return event


@kernel(cache=True, error_model="numpy", _nrt=False)
def _set_free(mode):
    """The mode FREE (a stretch of the remedy runs with it: no contact held)."""
    mode[M_KIND] = FREE
    mode[M_INDEX] = 0
    mode[M_SLIP] = 0


@kernel(cache=True, error_model="numpy", _nrt=False)
def advance_stretch(par, record, dt, t, h, y, data, sc, gap_tol, force, impulses, work):
    """The remedy's step: one Moreau-Jean step of length h (Jean 1999), in place on ``y``.

    The velocity at t + h is the free one (gravity, the support's inertial
    force, the gyroscopic moment over h) with plastic impulses at the base
    points that are closed or would close within the step
    (:func:`freestand.core.contact.body_impulse.velocity_impact`, the circular
    cone with the kinetic coefficient; never gaining kinetic energy); the
    position follows with that velocity (the rotation exactly, for an
    angular velocity constant over the step). ``force`` receives the mean
    contact force over the step, (normal, |tangential|) [N] (the impulses'
    sum over h; kept from the step before where a base point approached
    faster than ``STRETCH_IMPACT g h``: an impact, as the events keep their
    impulses out of the recorded force), and the reach [m]: points within it
    of the support took part (a point that closed within the step is held
    where it stopped, above the support by up to the reach). ``impulses``
    (``MAX_POINTS``, 3) [N s]: the step before's impulses at its points, the
    start of this step's sweeps (zeros at a stretch's first step); replaced
    by this step's. ``work``: the impulses' work record
    (:data:`~freestand.core.contact.body_impulse.IMPULSE_WORK_DTYPE`).
    """
    prepare(par, record, dt, t + h, y, FREE, 0, 0.0, sc)
    rot = sc[SC_ROT]
    velocity = work["velocity"]
    for i in range(6):
        velocity[i] = y[7 + i] + h * sc[SC_BASE][i]
    free = work["free_velocity"]
    for i in range(3):
        free[i] = velocity[i]
    arms = work["arms"]
    reach = gap_tol + h * _fall_speed(velocity, par)
    count = base_points(par, y, rot, data[D_PSI], reach, arms, work)
    approach = 0.0  # the fastest approach of a base point [m/s]
    for p in range(count):
        _, _, uz = cross(velocity[3], velocity[4], velocity[5], arms[p, 0], arms[p, 1], arms[p, 2])
        approach = max(approach, -(velocity[2] + uz))
    velocity_impact(par, sc[SC_INV], arms, count, par[P_MU_KINETIC], velocity, impulses, work)
    for i in range(3):
        y[i] += h * velocity[i]
    _turn(y, velocity[3] * h, velocity[4] * h, velocity[5] * h)
    for i in range(6):
        y[7 + i] = velocity[i]
    # the impulses' sum over the step, m (v - v_free), as a mean force; a step in which a
    # point lands is an impact, whose impulse the force keeps out (as an event does)
    if approach <= STRETCH_IMPACT * par[P_GRAVITY] * h:
        scale = par[P_MASS] / h
        force[0] = scale * (velocity[2] - free[2])
        force[1] = scale * math.hypot(velocity[0] - free[0], velocity[1] - free[1])
    force[2] = reach


@kernel(cache=True, error_model="numpy", _nrt=False)
def _fall_speed(velocity, par):
    """A bound of the speed [m/s] at which a base point approaches the support.

    ``|v_z| + |omega| r``, r the largest distance from G to the base's
    outline (bounded by its enclosing rectangle's corners): the points that
    can close within a step of the remedy are within its length times this.
    """
    reach_x = par[P_HALF_X] + abs(par[P_CENTRE])
    reach_y = par[P_HALF_Y] + abs(par[P_CENTRE + 1])
    arm_ = math.sqrt(reach_x**2 + reach_y**2 + par[P_CENTRE + 2] ** 2)
    return abs(velocity[2]) + arm_ * math.sqrt(
        velocity[3] ** 2 + velocity[4] ** 2 + velocity[5] ** 2)  # fmt: skip


@kernel(cache=True, error_model="numpy", _nrt=False)
def _turn(y, ax, ay, az):
    """Turn the orientation quaternion y[3:7] by the rotation vector (ax, ay, az) [rad] (world)."""
    angle = math.sqrt(ax * ax + ay * ay + az * az)
    if angle == 0.0:
        return
    c = math.cos(0.5 * angle)
    f = math.sin(0.5 * angle) / angle
    rw, rx, ry, rz = c, f * ax, f * ay, f * az
    w, x, yy, z = y[3], y[4], y[5], y[6]
    y[3] = rw * w - rx * x - ry * yy - rz * z
    y[4] = rw * x + rx * w + ry * z - rz * yy
    y[5] = rw * yy - rx * z + ry * w + rz * x
    y[6] = rw * z + rx * yy - ry * x + rz * w
    _normalise(y)


@kernel(cache=True, error_model="numpy", _nrt=False)
def record(t, y, mode, sc, count, out_t, out_y, out_mode, out_force):
    """Phase 4: write the state, the mode and the contact force (N, |f_t|) at row ``count``."""
    out_t[count] = t
    for i in range(STATE_SIZE):
        out_y[count, i] = y[i]
    for i in range(3):
        out_mode[count, i] = mode[i]
    lam = sc[SC_LAM]
    kind = mode[M_KIND]
    n_normal = 1 if kind == POINT else (2 if kind == EDGE else (3 if kind == FACE else 0))
    n_tangent = 2 if kind == POINT else (3 if kind != FREE else 0)
    out_force[count, 0] = normal_total_rows(n_normal, lam)
    size = 0.0
    for k in range(n_tangent):
        size += lam[n_normal + k] ** 2
    out_force[count, 1] = math.sqrt(size)


@kernel(cache=True, error_model="numpy", _nrt=False)
def held_row(par, y, sc, reach, velocity_tol, force, patch, row, out_mode, out_force):
    """Row ``row`` of a stretch of the remedy: the patch it holds and its contact force.

    The patch is the one the time stepping holds (:func:`touched_patch`, not
    FREE, which the engine's mode is during a stretch); the force is
    ``force`` = (N, |f_t|) [N], the step's impulses over its length;
    ``patch`` (3, int) is work space.
    """
    touched_patch(par, y, sc, reach, velocity_tol, patch)
    for i in range(3):
        out_mode[row, i] = patch[i]
    out_force[row, 0] = force[0]
    out_force[row, 1] = force[1]


@kernel(cache=True, error_model="numpy", _nrt=False)
def _stretch_start_row(par, y, sc, gap_tol, velocity_tol, istate, force, patch,
                       out_mode, out_force):  # fmt: skip
    """The row just recorded, where a stretch of the remedy begins: the patch touched.

    Its force is the row's before (the contact force just before the event),
    in ``force`` too: the stretch's steps start from it.
    """
    row = istate[I_RECORDS]
    force[0] = out_force[row - 1, 0] if row > 0 else 0.0
    force[1] = out_force[row - 1, 1] if row > 0 else 0.0
    rotation_matrix(y, sc[SC_ROT])
    held_row(par, y, sc, gap_tol, velocity_tol, force, patch, row, out_mode, out_force)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _event(t, kind, before, after, count, ev_time, ev_kind, ev_before, ev_after):
    if count < ev_time.shape[0]:
        ev_time[count] = t
        ev_kind[count] = kind
        ev_before[count] = before
        ev_after[count] = after
    return count + 1


@kernel(cache=True, error_model="numpy", _nrt=True)
def rest_prepare(par, y, mode, data, sc, rest):
    """Unit solutions of the resting mode: its multipliers are affine in (a_x, a_y, a_v).

    At rest (no velocity) the held rows have no bias and the applied wrench
    is ``m (-a_x, -a_y, -(g - a_v))`` at G: ``lam = rest[0] + a_x rest[1] +
    a_y rest[2] + a_v rest[3]``, with the rows at the base centre
    (:func:`solve_at_centre`; the friction is taken about the centre of
    pressure in :func:`rest_margins`).
    """
    unit = np.zeros((3, 2))
    for j in range(4):
        for i in range(3):
            value = 1.0 if i == j - 1 else 0.0
            unit[i, 0] = value
            unit[i, 1] = value
        solve_at_centre(par, unit, 1.0, 0.0, y, mode, data, sc)
        lam = sc[SC_LAM]
        for i in range(6):
            rest[j, i] = lam[i]
    for j in range(1, 4):
        for i in range(6):
            rest[j, i] -= rest[0, i]


@kernel(cache=True, error_model="numpy", _nrt=False)
def rest_margins(par, record, dt, t, rest, rot, lam, centre):
    """The resting mode's multipliers at t in ``lam``; (normal margin, friction margin).

    The friction is expressed about the centre of pressure
    (:func:`centre_stick_friction`): at rest the load's line of action
    passes through it, so its twist torque vanishes and the friction margin
    is ``mu_0 N - |F|``.
    """
    a_x, a_y, a_v = support_acceleration(record, dt, t)
    for i in range(6):
        lam[i] = rest[0, i] + a_x * rest[1, i] + a_y * rest[2, i] + a_v * rest[3, i]
    reset_friction_centre(par, FACE, 0, centre)
    centre_stick_friction(par, rot, FACE, 0, 3, lam, centre)
    return normal_margin(par, rot, FACE, lam), friction_margin(par, 3, 3, lam)


@kernel(cache=True, error_model="numpy", _nrt=False)
def rest_step(par, record, dt, t, h, rest, rot, lam, centre):
    """A step of the resting mode over h (within one segment of the record).

    The margins are concave in the multipliers (a minimum of linear ones, or
    ``R N - |M|``, ``mu N - |F|``), which are linear in time over a
    segment: where both ends hold, the whole step holds. Otherwise the
    crossing is bisected to EVENT_TIME. Returns (step taken, kind fired or -1).
    """
    slack = MARGIN_SLACK * par[P_MASS] * par[P_GRAVITY]
    normal, friction = rest_margins(par, record, dt, t + h, rest, rot, lam, centre)
    if normal >= -slack and friction >= -slack:
        return h, -1
    low = 0.0
    high = h
    while high - low > EVENT_TIME:
        middle = 0.5 * (low + high)
        normal, friction = rest_margins(par, record, dt, t + middle, rest, rot, lam, centre)
        if normal < -slack or friction < -slack:
            high = middle
        else:
            low = middle
    normal, friction = rest_margins(par, record, dt, t + high, rest, rot, lam, centre)
    return high, FN_NORMAL if normal < -slack else FN_FRICTION


@kernel(cache=True, error_model="numpy", _nrt=False)
def _next_end(t, breaks, h_max, t_end):
    """End of the next step: at most h_max, never across a break of the record."""
    end = min(t + h_max, t_end)
    lo = 0
    hi = breaks.shape[0]
    while lo < hi:
        middle = (lo + hi) // 2
        if breaks[middle] <= t + 1e-12:
            lo = middle + 1
        else:
            hi = middle
    if lo < breaks.shape[0] and breaks[lo] < end:
        end = breaks[lo]
    return end


@kernel(cache=True, error_model="numpy", _nrt=False)
def _stretch(par, record, dt, t, h, y, mode, data, sc, gap_tol, velocity_tol, istate, force,
             impulses, work):  # fmt: skip
    """One step of the remedy; it ends where a consistent mode exists again. Returns t + h.

    The search for a consistent mode (:func:`select_mode`, whose slip onsets
    are costly where none exists) is made at the stretch's steps 1, 2, 4, 8
    and then every ``STRETCH_CHECK``: a short stretch stays short, and a long
    one lasts at most ``STRETCH_CHECK`` steps more than it must (a valid
    time-stepping solution all along). After each step the base points it
    holds above the support are set on it (:func:`_settle`). A chatter's stretch
    (:func:`_start_chatter`) looks every ``STRETCH_CHECK`` steps only, and
    goes on where the mode found is a slip from rest (its speed within
    ``velocity_tol``): that slip would chatter again.
    """
    if istate[I_STRETCH] == 1:
        impulses[:, :] = 0.0  # a stretch starts its sweeps from zero
    advance_stretch(par, record, dt, t, h, y, data, sc, gap_tol, force, impulses, work)
    hovering = _settle(par, y, sc, data, force[2], gap_tol, velocity_tol, work)
    istate[I_STRETCH_STEPS] += 1
    steps = istate[I_STRETCH]
    istate[I_STRETCH] += 1
    early = istate[I_CHATTER] == 0 and steps & (steps - 1) == 0
    if not early and steps % STRETCH_CHECK != 0:
        _set_free(mode)
        return t + h
    _no_exclusion(sc)
    found = select_mode(par, record, dt, t + h, y, sc, gap_tol, velocity_tol, mode, data,
                        sc[SC_EXCLUDED])  # fmt: skip
    if found >= 0 and hovering and mode[M_KIND] == FREE:
        found = -1  # a point the stretch holds is still above the support: not a flight
    if found >= 0 and istate[I_CHATTER] == 1 and mode[M_SLIP] == 1:
        # a chatter's stretch goes on while its patch could only slip from rest
        speed, _, _ = slip_velocity(par, record, dt, t + h, y, mode, data, sc)
        found = -1 if speed <= velocity_tol else 0
    if found >= 0:
        istate[I_STRETCH] = 0
        istate[I_CHATTER] = 0
        project(par, record, dt, t + h, y, mode, data, sc)
    else:
        _set_free(mode)
    return t + h


@kernel(cache=True, error_model="numpy", _nrt=False)
def _horizontal_speed(y, d):
    """Horizontal speed [m/s] of the material point at arm d."""
    return math.hypot(point_velocity(y, d, 1.0, 0.0, 0.0), point_velocity(y, d, 0.0, 1.0, 0.0))


@kernel(cache=True, error_model="numpy", _nrt=False)
def _no_exclusion(sc):
    """The scratch's excluded mode (:func:`~freestand.core.contact.body_modes.select_mode`)
    set to none: (-1, 0, 0)."""
    excluded = sc[SC_EXCLUDED]
    excluded[0], excluded[1], excluded[2] = -1, 0, 0


@kernel(cache=True, error_model="numpy", _nrt=False)
def touched_patch(par, y, sc, reach, velocity_tol, patch):
    """The patch a time-stepped state touches, as (kind, index, slip) in ``patch``.

    The most closed candidate (:func:`freestand.core.contact.body_modes.candidates`)
    of the base points that touch within ``reach`` [m] of the support, not
    moving away faster than ``velocity_tol`` [m/s]
    (:func:`~freestand.core.contact.body_modes.touching_points`); FREE where
    none does. It slips where a touching point's horizontal speed exceeds
    ``velocity_tol``. The rows a stretch of the remedy records say which
    contact the time stepping held, not FREE. At the rotation ``sc[SC_ROT]``;
    the candidates in the scratch's work fields. Returns the kind.
    """
    rot = sc[SC_ROT]
    touching = sc[SC_TOUCHING]
    psi = touching_points(par, y, sc, reach, velocity_tol, ACCELERATION, touching)
    clear_candidates(sc)
    kinds, indices, angles = sc[SC_KINDS], sc[SC_INDICES], sc[SC_ANGLES]
    patch[0], patch[1], patch[2] = FREE, 0, 0
    if candidates(par, touching, psi, kinds, indices, angles) == 0:
        return FREE
    patch[0], patch[1] = kinds[0], indices[0]
    d = sc[SC_POINTS][2]
    speed = 0.0  # the fastest horizontal speed of a touching point [m/s]
    if par[P_SHAPE] == SHAPE_BOX:
        for k in range(4):
            if touching[k]:
                corner_gap(par, y, rot, k, d)
                speed = max(speed, _horizontal_speed(y, d))
    else:
        arm(par, rot, par[P_HALF_X] * math.cos(psi), par[P_HALF_X] * math.sin(psi), 0.0, d)
        speed = _horizontal_speed(y, d)
    patch[2] = 1 if speed > velocity_tol else 0
    return patch[0]


@kernel(cache=True, error_model="numpy", _nrt=False)
def _settle(par, y, sc, data, reach, gap_tol, velocity_tol, work):
    """Set the body on the base points a stretch holds; True if any stays above the support.

    A point that closed within a step of the remedy is held where it
    stopped, up to ``reach`` [m] above the support, its normal velocity
    zero (within ``velocity_tol`` [m/s]). The body is shifted down by the
    smallest such gap, but never by more than the lowest base point's gap
    (a point rising from the support stays on or above it); and up where
    the lowest base point lies below the support, onto it. The step holds
    the normal velocity of the points at its start; a rim rolling near flat
    moves its lowest point along the rim by ``omega h / tilt``, and the
    next lowest point lies ``R tilt (omega h / tilt)^2 / 2`` lower: a squat
    cylinder (R 1.9 m, mu 1.4) rolling at 1.3 rad/s at 0.025 rad under 4 g
    sank 0.6 um a step until its contact was lost (``robust_case`` 1079 of
    the 3-D benchmark under its record times 14). Returns True when a held
    point stays more than ``gap_tol`` above the support. ``work``: the
    impulses' work record, its ``point`` free here.
    """
    rot = sc[SC_ROT]
    rotation_matrix(y, rot)
    d = work["point"]
    held = math.inf
    lowest = math.inf
    if par[P_SHAPE] == SHAPE_BOX:
        for k in range(4):
            g, rate_ = corner_gap(par, y, rot, k, d)
            lowest = min(lowest, g)
            if g <= reach and abs(rate_) <= velocity_tol:
                held = min(held, g)
    else:
        radius = par[P_HALF_X]
        psi = lowest_rim_angle(rot, data[D_PSI])
        arm(par, rot, radius * math.cos(psi), radius * math.sin(psi), 0.0, d)
        lowest = y[2] + d[2]
        if lowest <= reach and abs(point_velocity(y, d, 0.0, 0.0, 1.0)) <= velocity_tol:
            held = lowest
    if held == math.inf:
        if lowest < 0.0:
            y[2] -= lowest  # a point below the support is set on it
        return False
    shift = min(held, lowest)
    if shift != 0.0:
        y[2] -= shift
    return held - shift > gap_tol


@kernel(cache=True, error_model="numpy", _nrt=False)
def watch_chatter(t, before, event, mode, istate, chatter):
    """Count an EDGE's or FACE's slip restarts and remedies, and impacts; start a chatter's stretch.

    A restart is a slip-stop after which the patch slips again from rest
    (the event ``EV_STICK`` with a sliding mode). ``chatter`` holds the last
    one's time [s] and how many followed each other within the window
    (``CHATTER_WINDOW`` for an EDGE, whose onset direction at its friction
    limit is unstable; ``FACE_CHATTER_WINDOW`` for a FACE, whose restarts
    are the support's acceleration hovering at the friction limit, each a
    real stick and slip, except where they follow each other within
    microseconds: no slip from rest lasts there); at ``CHATTER_COUNT`` the
    remedy's time stepping takes over (:func:`_start_chatter`); ``chatter[0:2]``.

    Impacts likewise, the remedy's velocity-level impacts (:func:`resolve`)
    among them: they can accumulate (Zeno). A near-flat cylinder landed
    within the gap tolerance, with the restitution factor 0, was set at rest
    on its rim point at each landing and landed again 10 microseconds
    later, 500,000 times over a second of record (24 s of computing). Where
    ``IMPACT_COUNT`` impacts follow each other, each within ``IMPACT_WINDOW``
    (the remedy's step) of the last, the time stepping takes such a sequence
    in its stride, impacts included (Moreau's sweeping process;
    ``three-d.md``'s remedies for Zeno); ``chatter[2:4]``. Returns the
    event's kind.
    """
    if event == EV_IMPACT or (event == EV_REMEDY and istate[I_STRETCH] == 0):
        # an impact, or the velocity-level impact where the impact law had no candidate
        if _in_a_row(t, IMPACT_WINDOW, IMPACT_COUNT, chatter, 2, mode, istate, event) != event:
            return EV_REMEDY
    if before < EDGE or not (event == EV_REMEDY or (event == EV_STICK and mode[M_SLIP] == 1)):
        return event
    window = CHATTER_WINDOW if before == EDGE else FACE_CHATTER_WINDOW
    return _in_a_row(t, window, CHATTER_COUNT, chatter, 0, mode, istate, event)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _in_a_row(t, window, limit, chatter, slot, mode, istate, event):
    """Count an occurrence at t; at ``limit`` in a row, each within ``window`` [s], a stretch.

    ``chatter[slot]`` is the last occurrence's time [s], ``chatter[slot + 1]``
    how many followed each other so far (:func:`watch_chatter`). Returns the
    event's kind: a remedy where the chatter's stretch starts (:func:`_start_chatter`).
    """
    chatter[slot + 1] = chatter[slot + 1] + 1.0 if t - chatter[slot] < window else 1.0
    chatter[slot] = t
    if chatter[slot + 1] < limit:
        return event
    chatter[slot + 1] = 0.0
    return _start_chatter(mode, istate, event)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _start_chatter(mode, istate, event):
    """Start a chatter's stretch of the remedy; returns the event's kind (a remedy).

    An edge at its friction limit can have no consistent slip from rest
    that lasts: its onset direction is unstable (the slip veers within
    microseconds and the slip-stop function fires), or none exists (a
    remedy); nor, at times, a flat base landed twisting. Where such
    restarts follow each other within the window of :func:`watch_chatter`,
    the velocity-level time stepping takes over until
    the patch sticks, slips at a speed above the velocity tolerance, or
    another contact holds (:func:`_stretch`).
    """
    if istate[I_STRETCH] == 0:
        istate[I_STRETCH] = 1
        if event != EV_REMEDY:
            istate[I_REMEDIES] += 1
    istate[I_CHATTER] = 1
    _set_free(mode)
    return EV_REMEDY


@kernel(cache=True, error_model="numpy", _nrt=False)
def _rest(par, record, dt, breaks, h_max, t_end, gap_tol, velocity_tol, t, y, mode, data, sc,
          rest, istate, ev_time, ev_kind, ev_before, ev_after, work):  # fmt: skip
    """One step of the resting body (:func:`rest_step`) and, where a margin fired, its event.

    Returns t + the step taken; the scratch holds the contact force at it.
    """
    h = _next_end(t, breaks, h_max, t_end) - t
    h, which = rest_step(par, record, dt, t, h, rest, sc[SC_ROT], sc[SC_LAM], sc[SC_CENTRE])
    t += h
    istate[I_STEPS] += 1
    if which >= 0:
        before = mode[M_KIND]
        event = resolve(par, record, dt, t, y, mode, data, sc, gap_tol, velocity_tol, which,
                        istate, work)  # fmt: skip
        istate[I_EVENTS] = _event(t, event, before, mode[M_KIND], istate[I_EVENTS], ev_time,
                                  ev_kind, ev_before, ev_after)  # fmt: skip
        solve_at(par, record, dt, t, y, mode, data, sc)
    return t


@kernel(cache=True, error_model="numpy", _nrt=False)
def _start_remedy(par, t, y, mode, sc, gap_tol, velocity_tol, istate, patch, ev_time, ev_kind,
                  ev_before, ev_after):  # fmt: skip
    """The remedy where the held mode cannot go on from its step's start (t, y): an event at t.

    Either the mode is not admissible there
    (:func:`~freestand.core.dynamics.body_events.inconsistent_start`: a
    force margin below its level, which could not fire), or its step passed
    a pole of its contact forces (:func:`~freestand.core.dynamics.body_step.energy_jump`;
    the step is dropped). The stretch of velocity-level time stepping takes
    over from (t, y), as where no consistent mode exists, until it finds
    one; :func:`run` writes the row recorded at t again as the stretch's
    first. (Its solve is :func:`run`'s: a function of its own that solves
    links the kernel again, 15 s more of compilation.)
    """
    before = mode[M_KIND]
    istate[I_REMEDIES] += 1
    istate[I_STRETCH] = 1
    _set_free(mode)
    rotation_matrix(y, sc[SC_ROT])
    after = touched_patch(par, y, sc, gap_tol, velocity_tol, patch)
    istate[I_EVENTS] = _event(t, EV_REMEDY, before, after, istate[I_EVENTS], ev_time, ev_kind,
                              ev_before, ev_after)  # fmt: skip


@kernel(cache=True, error_model="numpy", _nrt=True)
def run(par, record_, dt, breaks, h_max, t_end, record_end, gap_tol, velocity_tol, t, y, mode,
        data, scratch, istate, out_t, out_y, out_mode, out_force, ev_time, ev_kind, ev_before,
        ev_after):  # fmt: skip
    """The loop: advance, locate, resolve, record, from t to t_end.

    ``scratch`` is a one-element array of
    :data:`~freestand.core.contact.body_kernel.SCRATCH_DTYPE`, its record the
    kernel's scratch, owned by the caller. Returns the time reached;
    ``istate[I_STATUS]`` says why it stopped (completed, overturned, or the
    output buffer full: call again with larger buffers from the returned time
    and state).
    """
    sc = scratch[0]
    k = np.zeros((5, STATE_SIZE))
    out = np.zeros(STATE_SIZE)
    trial = np.zeros(STATE_SIZE)
    ref = np.zeros(REF_SIZE)
    start_values = np.zeros(MAX_EVENT_FUNCTIONS)
    values = np.zeros(MAX_EVENT_FUNCTIONS)
    kinds = np.zeros(MAX_EVENT_FUNCTIONS, dtype=np.int64)
    bracket = np.zeros((3, MAX_EVENT_FUNCTIONS))
    capacity = out_t.shape[0]
    rest = np.zeros((4, 6))
    work_rot = np.zeros((3, 3))
    energy = np.array([math.nan, 0.0, 0.0])  # the last step's end for energy_jump
    rest_ready = False
    force = np.zeros(3)  # a stretch's mean contact force (normal, |tangential|) [N], reach [m]
    patch = np.zeros(3, dtype=np.int64)  # the patch a stretch's step held
    impulses = np.zeros((MAX_POINTS, 3))  # a stretch's step's impulses: the next one's start
    # the last slip restart's time [s], restarts in a row; the same for impacts (watch_chatter)
    chatter = np.array([-math.inf, 0.0, -math.inf, 0.0])
    work_record = np.zeros(1, dtype=IMPULSE_WORK_DTYPE)
    work = work_record[0]  # the impulses' work arrays, allocated once
    fresh = False  # the step's references and event functions at (t, y) are computed
    count = 0
    if istate[I_RECORDS] == 0:
        none = np.array([-1, 0, 0], dtype=np.int64)
        if select_mode(par, record_, dt, t, y, sc, gap_tol, velocity_tol, mode, data, none) < 0:
            mode[M_KIND] = FREE
            istate[I_STRETCH] = 1
            istate[I_REMEDIES] += 1
        solve_at(par, record_, dt, t, y, mode, data, sc)
        record(t, y, mode, sc, 0, out_t, out_y, out_mode, out_force)
        if istate[I_STRETCH] == 1:
            _stretch_start_row(par, y, sc, gap_tol, velocity_tol, istate, force,
                               patch, out_mode, out_force)  # fmt: skip
        istate[I_RECORDS] = 1
        istate[I_EVENTS] = _event(t, EV_START, -1, mode[M_KIND], istate[I_EVENTS], ev_time,
                                  ev_kind, ev_before, ev_after)  # fmt: skip
    while t < t_end - 1e-12:
        if istate[I_RECORDS] >= capacity:
            istate[I_STATUS] = STATUS_BUFFER_FULL
            return t
        if istate[I_STRETCH] >= 1:
            t = _stretch(par, record_, dt, t, min(STRETCH_STEP, t_end - t), y, mode, data, sc,
                         gap_tol, velocity_tol, istate, force, impulses, work)  # fmt: skip
            solve_at(par, record_, dt, t, y, mode, data, sc)
            row = istate[I_RECORDS]
            record(t, y, mode, sc, row, out_t, out_y, out_mode, out_force)
            if istate[I_STRETCH] >= 1:
                held_row(par, y, sc, force[2], velocity_tol, force, patch, row, out_mode,
                         out_force)  # fmt: skip
            istate[I_RECORDS] += 1
            if sc[SC_ROT][2, 2] <= 0.0:
                istate[I_EVENTS] = _event(t, EV_OVERTURN, FREE, FREE, istate[I_EVENTS], ev_time,
                                          ev_kind, ev_before, ev_after)  # fmt: skip
                istate[I_STATUS] = STATUS_OVERTURNED
                return t
            continue
        if resting(mode, y, velocity_tol):
            if not rest_ready:
                rest_prepare(par, y, mode, data, sc, rest)
                rotation_matrix(y, sc[SC_ROT])
                rest_ready = True
            t = _rest(par, record_, dt, breaks, h_max, t_end, gap_tol, velocity_tol, t, y, mode,
                      data, sc, rest, istate, ev_time, ev_kind, ev_before, ev_after,
                      work)  # fmt: skip
            rest_ready = resting(mode, y, velocity_tol)
            record(t, y, mode, sc, istate[I_RECORDS], out_t, out_y, out_mode, out_force)
            if istate[I_STRETCH] == 1:
                _stretch_start_row(par, y, sc, gap_tol, velocity_tol, istate, force,
                                   patch, out_mode, out_force)  # fmt: skip
            istate[I_RECORDS] += 1
            continue
        rest_ready = False
        solved = False
        if not fresh:
            count = start_functions(par, record_, dt, t, y, mode, data, sc, ref, velocity_tol,
                                    start_values, kinds)  # fmt: skip
        fresh = False
        # the held mode not admissible at its start, or its step past a pole: the remedy
        remedy = inconsistent_start(par, count, start_values, kinds) >= 0
        if not remedy:
            h = min(_next_end(t, breaks, h_max, t_end) - t, closing_step(par, y, mode, sc, ref),
                    turn_step(y))  # fmt: skip
            data[D_FLOOR] = slip_floor(par, mode, sc, h)
            advance(par, record_, dt, t, h, y, mode, data, sc, k, out, velocity_tol)
            h, which, trials = locate(par, record_, dt, t, h, y, mode, data, sc, k, ref,
                                      start_values, count, trial, values, kinds, bracket,
                                      out)  # fmt: skip
            istate[I_TRIALS] += trials
            remedy = may_pass_a_pole(mode) and energy_jump(par, record_, dt, t, h, y, out,
                                                           work_rot, energy)  # fmt: skip
        if remedy:
            _start_remedy(par, t, y, mode, sc, gap_tol, velocity_tol, istate, patch, ev_time,
                          ev_kind, ev_before, ev_after)  # fmt: skip
            solve_at(par, record_, dt, t, y, mode, data, sc)
            istate[I_RECORDS] -= 1  # the row at t, again: the stretch's first
            record(t, y, mode, sc, istate[I_RECORDS], out_t, out_y, out_mode, out_force)
            _stretch_start_row(par, y, sc, gap_tol, velocity_tol, istate, force, patch, out_mode,
                               out_force)  # fmt: skip
            istate[I_RECORDS] += 1
            continue
        t += h
        for i in range(STATE_SIZE):
            y[i] = out[i]
        istate[I_STEPS] += 1
        if which < 0 and _lean_comes_flat(par, y, mode, sc):
            which = FN_LANDING
        if which >= 0:
            before = mode[M_KIND]
            event = resolve(par, record_, dt, t, y, mode, data, sc, gap_tol, velocity_tol,
                            which, istate, work)  # fmt: skip
            event = watch_chatter(t, before, event, mode, istate, chatter)
            after = mode[M_KIND]
            if event == EV_REMEDY and after == FREE:
                after = touched_patch(par, y, sc, gap_tol, velocity_tol, patch)
            istate[I_EVENTS] = _event(t, event, before, after, istate[I_EVENTS], ev_time, ev_kind,
                                      ev_before, ev_after)  # fmt: skip
            if event == EV_OVERTURN:
                solve_at(par, record_, dt, t, y, mode, data, sc)
                record(t, y, mode, sc, istate[I_RECORDS], out_t, out_y, out_mode, out_force)
                istate[I_RECORDS] += 1
                istate[I_STATUS] = STATUS_OVERTURNED
                return t
        elif not resting(mode, y, velocity_tol):
            if drifted(par, y, mode, sc, gap_tol, velocity_tol):
                project(par, record_, dt, t, y, mode, data, sc)
            else:
                solved = True  # locate's solve at the step's end: the state is unchanged
        if not solved:
            energy[0] = math.nan  # the state changed at the step's end: energy_jump's start anew
        if istate[I_STRETCH] == 0 and not resting(mode, y, velocity_tol):
            # the next step's references and event functions: their solve is the record's
            count = start_functions(par, record_, dt, t, y, mode, data, sc, ref, velocity_tol,
                                    start_values, kinds, solved)  # fmt: skip
            fresh = True
        else:
            solve_at(par, record_, dt, t, y, mode, data, sc)
        record(t, y, mode, sc, istate[I_RECORDS], out_t, out_y, out_mode, out_force)
        if istate[I_STRETCH] == 1:
            _stretch_start_row(par, y, sc, gap_tol, velocity_tol, istate, force,
                               patch, out_mode, out_force)  # fmt: skip
        istate[I_RECORDS] += 1
        if t >= record_end and _post_record_fall(par, y, mode, sc):
            istate[I_EVENTS] = _event(t, EV_OVERTURN, mode[M_KIND], mode[M_KIND], istate[I_EVENTS],
                                      ev_time, ev_kind, ev_before, ev_after)  # fmt: skip
            istate[I_STATUS] = STATUS_OVERTURNED
            return t
    istate[I_STATUS] = STATUS_COMPLETED
    return t
