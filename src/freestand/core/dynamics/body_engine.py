"""The compiled event-driven time history of one rigid body on the support (3-D).

The loop has the shape of the planar engine (:mod:`freestand.core.dynamics.engine`):
``run`` repeats four named phases until the end time:

- :func:`advance`: one RK4 step of the held contact mode (the contact forces
  solved at every stage by :func:`freestand.core.contact.body_kernel.rate`),
  or nothing while the body rests flat and sticks (its contact multipliers
  are then affine in the support's accelerations, and a step is decided by
  its ends: :func:`rest_step`);
- :func:`locate`: the event functions at the step's end against its start;
  when one changed sign, the earliest crossing by Anderson and Bjorck's
  variant of regula falsi on RK4 states from the step's start, to
  ``EVENT_TIME`` [s], its first trials seeded by the crossing on the step's
  cubic interpolant (:func:`interpolated_crossing`);
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

import numba as nb
import numpy as np

from freestand.core.contact.body_impulse import MAX_POINTS, base_points, velocity_impact
from freestand.core.contact.body_kernel import (
    D_FLOOR,
    D_ONSET,
    D_PSI,
    D_SLIP,
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
    P_RESTITUTION,
    P_SHAPE,
    PIVOT_LEAN,
    POINT,
    SC_ACC,
    SC_BASE,
    SC_CENTRE,
    SC_DIR,
    SC_INV,
    SC_LAM,
    SC_PROBE,
    SC_ROT,
    SC_SVEL,
    SC_TANGENT,
    SC_TBIAS,
    SHAPE_BOX,
    SLIP_FLOOR,
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
    prepare_held,
    rate,
    reset_friction_centre,
    rotation_matrix,
    row_acceleration,
    row_counts,
    sin_tilt,
    solve_at,
    solve_at_centre,
    solve_mode,
    state_rate,
    support_acceleration,
    tangential_velocity,
)
from freestand.core.contact.body_modes import (
    ACCELERATION,
    MAX_CANDIDATES,
    NONE_ADMISSIBLE,
    candidates,
    impact,
    select_mode,
    touching_points,
)
from freestand.core.contact.regula_falsi import narrowed

EVENT_TIME = 1e-11  # [s] width of the bracket of a located event
GAP_SLACK = 1e-12  # [m] a released point may sit this far below the support
LANDING_SLACK = 1e-12  # [-] a landed cylinder's lean may sit this far past its pivot's side
MAX_EVENT_FUNCTIONS = 8
INTERPOLANT_TRIALS = 40  # most trials of an event's search on the step's cubic interpolant
INTERPOLANT_TIME = 1e-10  # [s] width of its bracket that ends that search
SEED_TRIALS = 4  # most seeded trials of an event's search on RK4 states (locate)
SEED_OFFSET = 0.45  # a seeded trial lies this part of EVENT_TIME beyond its estimated crossing
CLOSING_OVERSHOOT = 1.25  # a step ends this far past a gap's predicted closing [-]
WHIRL_ANGLE = 0.1  # [rad] largest turn of a rolling cylinder's lean in one step
TILT_FRACTION = 0.5  # a whirling lean covers at most this part of its way to the vertical in a step
RISE_LEAN = 2.0 * PIVOT_LEAN  # sin(tilt) a step from below PIVOT_LEAN rises to at most
PLANAR_PASS = 0.1  # a lean predicted to pass within this part of PIVOT_LEAN lands as in a plane [-]
LEAN_TRUST = 1e-4  # sin(tilt) below which the lean's predicted passing distance is trusted [-]
ROUND_OFF_PASS = 1e-12  # a passing distance below this is a planar motion's round-off [-]
SLIP_FRACTION = 0.5  # a step lasts at most this part of a slip's time scale |s| / |s'|
FACE_TURN = 0.3  # [rad] a flat base's slip turns by about this much at most in a step
SLIP_MIN_STEP = 1e-4  # [s] the slip's time scale bounds no step below this
FACE_MIN_STEP = 3e-4  # [s] a flat base's turn bounds no step below this
FLOOR_STABILITY = 2.0  # h lambda of a flat base's slip turning at its floor (RK4: stable to 2.78)
STRETCH_STEP = 1e-4  # [s] step of the velocity-level time stepping (the remedy)
STRETCH_CHECK = 16  # a stretch looks for a consistent mode at its steps 1, 2, 4, 8, 16, 32, 48, ...
STRETCH_IMPACT = 10.0  # a stretch's point approaching faster than this times g h lands [-]
CHATTER_WINDOW = 1e-3  # [s] slip restarts or remedies closer than this in time are a chatter
CHATTER_COUNT = 3  # this many in a row start a chatter stretch of the remedy
FACE_CHATTER_WINDOW = 1e-6  # [s] a FACE's slip restarts closer than this in time are a chatter
MIN_STEP = 1e-9  # [s] the smallest step the closing prediction may ask for
FLAT_ROUND_OFF = 1e-13  # [m, m/s, rad/s, -] a sliding flat base's drift left to round-off

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

# function kinds (what a crossing means)
FN_NORMAL = 0
FN_FRICTION = 1
FN_SLIP_STOP = 2
FN_GAP = 3
FN_LANDING = 4
FN_TILT = 5

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


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _normalise(y):
    size = math.sqrt(y[3] ** 2 + y[4] ** 2 + y[5] ** 2 + y[6] ** 2)
    for i in range(3, 7):
        y[i] /= size


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _rk4(par, record, dt, t, h, y, mode, data, sc, k, out):
    """One RK4 step of the held mode over h from (t, y) into ``out``; False if singular.

    ``k[0]`` holds y' at (t, y) already: the first stage does not depend on
    h, and the step and the trials of :func:`locate` share it.
    """
    stage = k[4]
    ok = True
    for i in range(STATE_SIZE):
        stage[i] = y[i] + 0.5 * h * k[0, i]
    ok &= rate(par, record, dt, t + 0.5 * h, stage, mode, data, sc, k[1])
    for i in range(STATE_SIZE):
        stage[i] = y[i] + 0.5 * h * k[1, i]
    ok &= rate(par, record, dt, t + 0.5 * h, stage, mode, data, sc, k[2])
    for i in range(STATE_SIZE):
        stage[i] = y[i] + h * k[2, i]
    ok &= rate(par, record, dt, t + h, stage, mode, data, sc, k[3])
    for i in range(STATE_SIZE):
        out[i] = y[i] + h / 6.0 * (k[0, i] + 2.0 * k[1, i] + 2.0 * k[2, i] + k[3, i])
    _normalise(out)
    return ok


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def resting(mode, y, velocity_tol):
    """True while the body sits flat, sticks and does not move (not integrated)."""
    if mode[M_KIND] != FACE or mode[M_SLIP] != 0:
        return False
    for i in range(7, 13):
        if abs(y[i]) > 1e-14:
            return False
    return True


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def advance(par, record, dt, t, h, y, mode, data, sc, k, out, velocity_tol):
    """Phase 1: the state at t + h in ``out`` (RK4, or unchanged at rest); False if singular.

    The scratch holds the held mode solved at (t, y) (:func:`start_functions`
    at the step's start): the first stage is read from it.
    """
    if resting(mode, y, velocity_tol):
        for i in range(STATE_SIZE):
            out[i] = y[i]
        return True
    state_rate(y, sc[SC_ACC], k[0])
    return _rk4(par, record, dt, t, h, y, mode, data, sc, k, out)


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def references(par, record, dt, t, y, mode, data, sc, ref, solved=False):
    """The step's references: the slip direction (3) and the pivot's horizontal direction (2).

    The slip direction is the slip velocity's at the held patch's centre of
    pressure at (t, y), or the stored one while the slip is slower than
    ``SLIP_FLOOR`` or the last step's floor (:func:`slip_floor`). Returns the
    normal and tangential rows of the slip's solve where the scratch holds
    the held mode solved at (t, y) as with the references stored: its solve
    read no stored direction (:func:`slip_direction`), or the stored one is
    kept; else (0, -1).
    ``solved``: the scratch holds the held mode solved at (t, y) already (a
    step's end left unprojected, :func:`drifted`, whose event functions left
    the slip velocity in the scratch), and it is not solved again.
    """
    rot = sc[SC_ROT]
    rotation_matrix(y, rot)
    for i in range(5):
        ref[i] = 0.0
    if mode[M_KIND] == POINT and par[P_SHAPE] != SHAPE_BOX:
        # the step's pivot: the lowest rim point (kept on its side within the step)
        psi = lowest_rim_angle(rot, data[D_PSI])
        data[D_PSI] = psi
        probe = sc[SC_PROBE]
        d, c = probe[0], probe[1]
        radius = par[P_HALF_X]
        # horizontal direction of the pivot from the base centre
        arm(par, rot, radius * math.cos(psi), radius * math.sin(psi), 0.0, d)
        arm(par, rot, 0.0, 0.0, 0.0, c)
        px = d[0] - c[0]
        py = d[1] - c[1]
        size = math.hypot(px, py)
        ref[3] = px / size
        ref[4] = py / size
    if mode[M_SLIP] == 0:
        return 0, -1
    if solved:
        n_normal, n_tangent = row_counts(mode[M_KIND])
        size = _size(sc[SC_SVEL], n_tangent)
    else:
        size, n_normal, n_tangent = slip_velocity(par, record, dt, t, y, mode, data, sc)
    svel = sc[SC_SVEL]
    floor = max(SLIP_FLOOR, data[D_FLOOR])  # the last step's (slip_floor)
    for i in range(n_tangent):
        ref[i] = svel[i] / size if size > floor else data[D_SLIP + i]
        data[D_SLIP + i] = ref[i]
    return n_normal, n_tangent if size <= floor or sc[SC_CENTRE][5] == 0.0 else -1


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def event_functions(par, record, dt, t, y, mode, data, sc, ref, values, kinds):
    """The event functions at (t, y) in the held mode (>= 0 while it holds); their count."""
    ok, n_normal, n_tangent = solve_at(par, record, dt, t, y, mode, data, sc)
    return event_values(par, y, mode, sc, ref, n_normal, n_tangent, values, kinds)


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def start_functions(par, record, dt, t, y, mode, data, sc, ref, values, kinds, solved=False):
    """A step's references (:func:`references`) and event functions at its start (t, y).

    One solve where the slip's references made it (none where the scratch
    holds it, ``solved``); returns the functions' count.
    """
    n_normal, n_tangent = references(par, record, dt, t, y, mode, data, sc, ref, solved)
    if n_tangent < 0:
        return event_functions(par, record, dt, t, y, mode, data, sc, ref, values, kinds)
    return event_values(par, y, mode, sc, ref, n_normal, n_tangent, values, kinds)


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def event_values(par, y, mode, sc, ref, n_normal, n_tangent, values, kinds):
    """The event functions of the held mode solved in the scratch at (t, y); their count."""
    rot = sc[SC_ROT]
    lam = sc[SC_LAM]
    kind = mode[M_KIND]
    count = 0
    if kind != FREE:
        values[count] = normal_margin(par, rot, kind, lam)
        kinds[count] = FN_NORMAL
        count += 1
        if mode[M_SLIP] == 0:
            values[count] = friction_margin(par, n_normal, n_tangent, lam)
            kinds[count] = FN_FRICTION
            count += 1
        else:
            svel = sc[SC_SVEL]
            tangential_velocity(y, sc[SC_TANGENT], n_tangent, svel)
            along = 0.0
            for i in range(n_tangent):
                along += svel[i] * ref[i]
            values[count] = along
            kinds[count] = FN_SLIP_STOP
            count += 1
    d = sc[SC_PROBE][0]
    if par[P_SHAPE] == SHAPE_BOX:
        for c in range(4):
            if kind == FACE or (kind == POINT and mode[M_INDEX] == c):
                continue
            if kind == EDGE and (mode[M_INDEX] == c or (mode[M_INDEX] + 1) % 4 == c):
                continue
            g, _ = corner_gap(par, y, rot, c, d)
            values[count] = g
            kinds[count] = FN_GAP
            count += 1
    elif kind == POINT:
        values[count] = rot[0, 2] * ref[3] + rot[1, 2] * ref[4]
        kinds[count] = FN_LANDING
        count += 1
    elif kind == FREE:
        radius = par[P_HALF_X]
        s = sin_tilt(rot)
        c0 = sc[SC_PROBE][1]
        arm(par, rot, 0.0, 0.0, 0.0, c0)
        values[count] = y[2] + c0[2] - radius * s
        kinds[count] = FN_GAP
        count += 1
    values[count] = rot[2, 2]  # cos(tilt): overturned at pi/2
    kinds[count] = FN_TILT
    count += 1
    return count


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _closing_time(value, rate_, acceleration):
    """Earliest t > 0 with value + rate t + acceleration t^2 / 2 = 0 [s]; inf if none."""
    if acceleration == 0.0:
        return -value / rate_ if rate_ < 0.0 else math.inf
    discriminant = rate_ * rate_ - 2.0 * acceleration * value
    if discriminant < 0.0:
        return math.inf
    root = math.sqrt(discriminant)
    best = math.inf
    for t in ((-rate_ - root) / acceleration, (-rate_ + root) / acceleration):
        if 0.0 < t < best:
            best = t
    return best


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def closing_step(par, y, mode, sc, ref):
    """Largest step [s] that cannot step over the closing of a gap and its reopening.

    A point that lifts by a little flies for a short time (a cylinder rocking
    by 1e-4 rad lands again within some 10 ms): a step longer than the flight
    would see the gap open at both its ends and miss the impact. Each gap (a
    box corner not held) and a rolling cylinder's landing function f is
    predicted by its Taylor polynomial f + f' t + f'' t^2 / 2 (f'' from the
    held mode's accelerations in ``sc``, which :func:`start_functions` just
    solved); the step ends ``CLOSING_OVERSHOOT`` past its earliest zero, so
    that :func:`locate` brackets the crossing. A rolling cylinder's lean (the
    horizontal projection of its axis) turns at ``|e_h x e_h'| / |e_h|^2``,
    which grows as 1/tilt near flat: :func:`_whirl_step` bounds the step there.
    Below ``PIVOT_LEAN`` the cylinder turns about its stored rim point, above
    it about the lowest one
    (:func:`~freestand.core.contact.body_kernel.pivot_direction`): a step
    from below ends about where an upper bound of the lean,
    ``|e_h| + |e_h'| t + |e_h''| t^2 / 2``,
    reaches ``RISE_LEAN``, so that the rim point's change falls between steps,
    not inside RK4's stages (a 5 ms step from 3e-7 to 2.7e-6 once set a
    slender cylinder rolling that lands at fine steps).
    """
    rot = sc[SC_ROT]
    x = sc[SC_ACC]
    kind = mode[M_KIND]
    wx, wy, wz = y[10], y[11], y[12]
    earliest = math.inf
    if mode[M_SLIP] == 1:
        earliest = _slip_turn_time(par, mode, sc)
    d = sc[SC_PROBE][0]
    if par[P_SHAPE] == SHAPE_BOX:
        if kind == FACE:
            return max(earliest, MIN_STEP)
        for c in range(4):
            if kind == POINT and mode[M_INDEX] == c:
                continue
            if kind == EDGE and (mode[M_INDEX] == c or (mode[M_INDEX] + 1) % 4 == c):
                continue
            g, gv = corner_gap(par, y, rot, c, d)
            ux, uy, uz = cross(wx, wy, wz, d[0], d[1], d[2])
            _, _, cz = cross(wx, wy, wz, ux, uy, uz)
            _, _, az = cross(x[3], x[4], x[5], d[0], d[1], d[2])
            earliest = min(earliest, _closing_time(max(g, 0.0), gv, x[2] + az + cz))
    elif kind == POINT:
        ex, ey, ez = rot[0, 2], rot[1, 2], rot[2, 2]
        ux, uy, uz = cross(wx, wy, wz, ex, ey, ez)
        cx, cy, _ = cross(wx, wy, wz, ux, uy, uz)
        ax, ay, _ = cross(x[3], x[4], x[5], ex, ey, ez)
        value = ex * ref[3] + ey * ref[4]
        slope = ux * ref[3] + uy * ref[4]
        curvature = (ax + cx) * ref[3] + (ay + cy) * ref[4]
        landing = _closing_time(max(value, 0.0), slope, curvature)
        lean = math.sqrt(ex * ex + ey * ey)
        areal = abs(ex * uy - ey * ux)
        if lean <= PIVOT_LEAN:
            # the rim point is the stored one up to PIVOT_LEAN, the lowest one above it: a
            # step ends about where the lean rises past RISE_LEAN (an upper bound of |e_h|)
            rise = _closing_time(lean - RISE_LEAN, math.hypot(ux, uy),
                                 math.hypot(ax + cx, ay + cy))  # fmt: skip
            earliest = min(earliest, rise)
        if lean > PIVOT_LEAN and landing < math.inf:
            landing_speed = abs(slope + curvature * landing)
            # the lean's side component where it meets the vertical plane of the pivot
            side = (-ex * ref[4] + ey * ref[3]) + (-ux * ref[4] + uy * ref[3]) * landing + 0.5 * (
                -(ax + cx) * ref[4] + (ay + cy) * ref[3]) * landing * landing  # fmt: skip
            limit = _whirl_step(lean, areal, landing, landing_speed, abs(side))
            if limit < math.inf:
                return max(min(limit, CLOSING_OVERSHOOT * earliest), MIN_STEP)
        earliest = min(earliest, landing)
        if lean > PIVOT_LEAN and areal > 0.0:
            # a wobbling cylinder: its rim point swings by at most WHIRL_ANGLE in a step
            return max(min(CLOSING_OVERSHOOT * earliest, WHIRL_ANGLE * lean * lean / areal),
                       MIN_STEP)  # fmt: skip
    return max(CLOSING_OVERSHOOT * earliest, MIN_STEP)


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _slip_turn_time(par, mode, sc):
    """Time [s] in which a slip's velocity could stop or turn: |s| / |s'| times SLIP_FRACTION.

    The kinetic friction follows the slip's direction, which turns quickly as
    the slip slows down (with an edge's twist as one of its components): on a
    rocking edge or point a step longer than the slip's own time scale makes
    RK4 oscillate from step to step and gain energy. A flat base's direction
    is not coupled to a rotation: its steps are bounded by the turn alone,
    ``FACE_TURN |s| / |s'_perp|`` (s' across s; a slip slowing along its own
    direction stops at the located slip-stop event; a slip from rest, slower
    than ``SLIP_FLOOR``, grows along its onset's direction). Unbounded, a sliding
    cask's 5 ms steps missed the quick turns of its slow slips: its path
    strayed 2.5 mm from a 0.1 ms run over 20 s (a 65 mm slide); bounded, 0.5
    mm, at 27 % more steps. ``sc`` holds the rows and accelerations that
    :func:`start_functions` just solved. A flat base's step is also bounded
    by RK4's stability on the rate at which friction turns a slow slip,
    ``FLOOR_STABILITY |s| / slip_stiffness`` (:func:`slip_floor`): unbounded,
    a slip across the force grew from round-off (a squat cylinder pushed at 1
    rad from its axes slid 1.8 % too far); bounded, the cask's path stays
    0.05 mm from a 0.1 ms run's, where the turn bound alone left 0.47 mm.
    Not below ``SLIP_MIN_STEP``: a slip
    that dies away without reversing would otherwise take ever shorter steps
    (its energy is then negligible); a flat base's not below ``FACE_MIN_STEP``,
    whose slow creeps (0.1 mm/s for 10 ms, the support driving across them)
    took a quarter of the cask's steps at 0.1 ms; at that floor a slower slip
    keeps its step's starting direction (:func:`slip_floor`).
    """
    kind = mode[M_KIND]
    n_tangent = 2 if kind == POINT else 3
    svel = sc[SC_SVEL]
    speed = 0.0
    change = 0.0
    along = 0.0
    for k in range(n_tangent):
        rate_ = row_acceleration(sc[SC_TANGENT], sc[SC_TBIAS], k, sc[SC_ACC])
        speed += svel[k] ** 2
        change += rate_**2
        along += rate_ * svel[k]
    if kind == FACE:
        # the turn only: s' across s; a slip from rest grows along its onset's direction
        if speed <= SLIP_FLOOR * SLIP_FLOOR:
            return math.inf
        change = max(change - along * along / speed, 0.0)
        limit = FLOOR_STABILITY * math.sqrt(speed) / slip_stiffness(par, sc)
        if change > 0.0:
            limit = min(limit, FACE_TURN * math.sqrt(speed / change))
        return max(limit, FACE_MIN_STEP) / CLOSING_OVERSHOOT
    if change == 0.0:
        return math.inf
    limit = SLIP_FRACTION * math.sqrt(speed / change)
    return max(limit, SLIP_MIN_STEP) / CLOSING_OVERSHOOT


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def slip_floor(par, mode, sc, h):
    """The speed [m/s] below which a flat base's slip keeps its step's starting direction.

    A slip's direction u = s/|s| turns at ``slip_stiffness / |s|`` (the
    kinetic friction pushes a slip's component across u back at that rate):
    a stiff rate where the slip is slow, on which RK4's explicit stages are
    unstable beyond ``h lambda = 2.78``. A slip across the force then grows
    from round-off instead of dying out, step by step: a squat cylinder
    pushed by one sine cycle at 1 rad from its axes slid 1.8 % further than
    along them, with a sideways speed of 4 mm/s (0 along them, by symmetry).
    A flat base's steps are bounded so that ``h lambda <= FLOOR_STABILITY``
    (:func:`_slip_turn_time`) down to ``FACE_MIN_STEP``; below that, and on a
    slip's first step from rest, the slip slower than this floor (the speed
    at which ``h lambda = FLOOR_STABILITY``) is pulled to the step's starting
    direction (:func:`~freestand.core.contact.body_kernel.unit_slip`), which
    RK4 integrates stably, and the next step keeps that direction as its
    reference while the slip stays below the floor (:func:`references`: the
    step-by-step update to ``s/|s|`` is an explicit step on the same rate).
    A FACE only (an edge's or point's slip steps are bounded by its time
    scale, ``SLIP_FRACTION``); 0.0 (``SLIP_FLOOR``) otherwise. ``sc`` holds
    the step's start solved (:func:`start_functions`). Returns [m/s].
    """
    if mode[M_KIND] != FACE or mode[M_SLIP] != 1:
        return 0.0
    return slip_stiffness(par, sc) * h / FLOOR_STABILITY


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def slip_stiffness(par, sc):
    """``mu N max(1/m, rho^2 (I^-1)_zz)`` [m/s^2]: a flat base's slip of speed |s| turns at
    this / |s|.

    The friction's largest acceleration per unit of its direction, on the
    FACE's rows and solution in the scratch (N its normal force, rho its
    twist radius): a horizontal force moves G by 1/m (the held tilt takes
    its moment), the twist row ``(0, rho e_z)`` by ``rho^2 (I^-1)_zz``.
    """
    rho = sc[SC_CENTRE][2]
    largest = max(1.0 / par[P_MASS], rho * rho * sc[SC_INV][2, 2])
    return par[P_MU_KINETIC] * max(sc[SC_LAM][0], 0.0) * largest + 1e-300


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _whirl_step(lean, areal, landing_time, landing_speed, distance):
    """Largest step [s] of a rolling cylinder whose lean whirls; inf when it lands as in a plane.

    The lean e_h (the horizontal projection of the axis, |e_h| = sin(tilt))
    is predicted by its Taylor polynomial to reach the vertical plane of the
    pivot in ``landing_time`` [s] at ``landing_speed`` [1/s], passing the
    vertical at ``distance`` (its side component there). Where it passes,
    the rolling point swings round the rim at ``landing_speed / distance``
    [rad/s]. Within ``PIVOT_LEAN`` of flat the body lands as in a plane (the
    contact point keeps its side,
    :func:`~freestand.core.contact.body_kernel.pivot_direction`): the step may cross the
    landing when the lean is predicted to pass within ``PLANAR_PASS`` of
    ``PIVOT_LEAN`` (so that the rim point's jump to its stored angle there is
    at most asin(PLANAR_PASS)) and the prediction is trusted: the motion is
    planar to round-off, or the lean is below ``LEAN_TRUST`` (a prediction
    from further away may be off by more than ``PIVOT_LEAN``: friction turns
    the lean's sweep). Otherwise a step turns the lean by at most
    ``WHIRL_ANGLE`` now (at ``areal / lean^2`` [rad/s], ``areal`` = |e_h x
    e_h'| [1/s]) and covers at most ``TILT_FRACTION`` of the time left to the
    approach plus ``WHIRL_ANGLE`` of the swing there: the steps shrink
    geometrically to the approach and resolve it (the contact lifts off there,
    the lean passes over, or it lands as in a plane once trusted).
    """
    if landing_speed == 0.0:
        return math.inf
    trusted = lean <= LEAN_TRUST or distance <= ROUND_OFF_PASS
    if trusted and distance <= PLANAR_PASS * PIVOT_LEAN:
        return math.inf
    limit = TILT_FRACTION * landing_time + WHIRL_ANGLE * distance / landing_speed
    if areal > 0.0:
        limit = min(limit, WHIRL_ANGLE * lean * lean / areal)
    return limit


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _levels(par, n, start_values, kinds, levels):
    """Level below which each event function fires; NaN for a function that cannot fire.

    A force margin fires when it falls below ``-slack`` having started above
    it, the slack being the admissibility tolerance (a mode is chosen within
    it); the tilt function likewise with no slack. A gap fires when it falls
    ``GAP_SLACK`` below the lower of zero and its value at the step's start:
    a point released at an event may sit the held rows' drift (some 1e-11 m)
    below the support, and it must still be caught when it comes back down.
    The landing function likewise, ``LANDING_SLACK`` below: a cylinder that
    has just landed leans by round-off, to either side of its new pivot, and
    may rock back within the step (a decaying sequence of landings), or
    within ``PIVOT_LEAN`` of flat tilt away from the pivot it keeps there.
    """
    for i in range(n):
        if kinds[i] == FN_GAP:
            levels[i] = min(start_values[i], 0.0) - GAP_SLACK
            continue
        if kinds[i] == FN_LANDING:
            levels[i] = min(start_values[i], 0.0) - LANDING_SLACK
            continue
        slack = 0.0
        if kinds[i] == FN_NORMAL or kinds[i] == FN_FRICTION:
            slack = 1e-9 * par[P_MASS] * par[P_GRAVITY]
        levels[i] = -slack if start_values[i] >= -slack else math.nan
    return n


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _fired(n, values, levels, prefer):
    """Index of an event function below its level (``prefer`` if it is one), or -1."""
    if prefer >= 0 and values[prefer] < levels[prefer]:
        return prefer
    for i in range(n):
        if values[i] < levels[i]:
            return i
    return -1


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _trial_time(low, high, g_low, g_high):
    """Next trial [s] of the search: the secant root, kept half a tolerance inside."""
    if g_low > 0.0 and g_high < 0.0:
        x = low + g_low * (high - low) / (g_low - g_high)
    else:
        x = 0.5 * (low + high)
    return min(max(x, low + 0.5 * EVENT_TIME), high - 0.5 * EVENT_TIME)


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _hermite_state(h, tau, y, rate_start, end, rate_end, out):
    """The step's cubic Hermite interpolant at t + tau in ``out`` (its quaternion normalised).

    ``y(t + s h) = h00 y_0 + h10 h y'_0 + h01 y_1 + h11 h y'_1`` with
    ``h00 = 2 s^3 - 3 s^2 + 1``, ``h10 = s^3 - 2 s^2 + s``, ``h01 = 3 s^2 - 2 s^3``,
    ``h11 = s^3 - s^2`` (Hairer, Norsett and Wanner, Solving ODEs I, 1993,
    II.6: the dense output of order 3 of a one-step method from its ends).
    """
    s = tau / h
    s2 = s * s
    s3 = s2 * s
    a = 2.0 * s3 - 3.0 * s2 + 1.0
    b = (s3 - 2.0 * s2 + s) * h
    c = 3.0 * s2 - 2.0 * s3
    d = (s3 - s2) * h
    for i in range(STATE_SIZE):
        out[i] = a * y[i] + b * rate_start[i] + c * end[i] + d * rate_end[i]
    _normalise(out)


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _function_value(par, record, dt, t, y, mode, data, sc, ref, values, kinds, target):
    """The event function ``target`` at (t, y).

    A gap, a landing or the tilt depends on the state alone: it is taken
    without a solve (the other entries of ``values`` are then the last
    solve's and are not read). A force margin or a slip is solved for.
    """
    kind = kinds[target]
    if kind == FN_GAP or kind == FN_LANDING or kind == FN_TILT:
        rotation_matrix(y, sc[SC_ROT])
        n_normal, n_tangent = row_counts(mode[M_KIND])
        event_values(par, y, mode, sc, ref, n_normal, n_tangent, values, kinds)
    else:
        event_functions(par, record, dt, t, y, mode, data, sc, ref, values, kinds)
    return values[target]


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def interpolated_crossing(par, record, dt, t, h, y, end, mode, data, sc, k, ref, values, kinds,
                          level, target, g_start, g_end, trial):  # fmt: skip
    """The crossing of event function ``target`` on the step's cubic interpolant.

    The search of :func:`locate` (Anderson and Bjorck's regula falsi) on
    the function at :func:`_hermite_state`'s states (``k[0]`` and ``k[1]``
    the rates at the step's ends), to ``INTERPOLANT_TIME``: one solve per
    trial for a force margin, none for a gap, a landing or the tilt, where
    a trial on true RK4 states costs four. ``g_start`` and ``g_end`` are the
    function less its ``level`` at the step's ends (positive, negative).
    Returns the crossing's time from t [s] and the function's rate of fall
    there [units/s] (the secant of the last two trials; positive, or NaN
    where the search found none). The interpolant is of third order where
    RK4 is of fourth: its crossing starts the search on RK4 states, it is
    not the event.
    """
    low = 0.0
    high = h
    g_low = g_start
    g_high = g_end
    last, g_last = h, g_end  # the last two trials, for the rate
    previous, g_previous = 0.0, g_start
    side = 0
    for _ in range(INTERPOLANT_TRIALS):
        if high - low <= INTERPOLANT_TIME:
            break
        middle = _trial_time(low, high, g_low, g_high)
        _hermite_state(h, middle, y, k[0], end, k[1], trial)
        g = _function_value(par, record, dt, t + middle, trial, mode, data, sc, ref, values,
                            kinds, target) - level  # fmt: skip
        if not math.isfinite(g):
            return 0.0, math.nan
        previous, g_previous = last, g_last
        last, g_last = middle, g
        low, high, g_low, g_high, side = narrowed(g < 0.0, middle, g, low, high, g_low, g_high,
                                                  side)  # fmt: skip
    rate_ = (g_previous - g_last) / (last - previous) if last != previous else math.nan
    return 0.5 * (low + high), rate_ if rate_ > 0.0 else math.nan


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _seeded_trial(last, g_last, previous, g_previous, rate_, low, high):
    """The next seeded trial of :func:`locate` [s from the step's start], or NaN.

    From the last trial on RK4 states (at ``last``, the followed function
    less its level ``g_last`` there) the crossing is estimated by a Newton
    step, ``r = last + g_last / rate``, the rate of fall being the secant of
    the last two trials (``previous``, NaN before the second) or else the
    interpolant's ``rate_``; the trial lies ``SEED_OFFSET`` of an
    ``EVENT_TIME`` beyond r, seen from the last trial. Where the estimates
    are that close, each trial crosses over and the bracket closes in two
    or three. NaN where no rate is known or the trial falls outside the
    bracket (low, high).
    """
    if math.isfinite(previous) and previous != last:
        secant = (g_previous - g_last) / (last - previous)
        if secant > 0.0:
            rate_ = secant
    if not rate_ > 0.0:
        return math.nan
    direction = 1.0 if g_last >= 0.0 else -1.0
    x = last + g_last / rate_ + SEED_OFFSET * direction * EVENT_TIME
    return x if low < x < high else math.nan


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def locate(par, record, dt, t, h, y, mode, data, sc, k, ref, start_values, count, trial,
           values, kinds, bracket, out):  # fmt: skip
    """Phase 2: the earliest crossing of an event function within the step.

    ``out`` holds the state at t + h; ``start_values`` the functions at t.
    Returns (step taken [s], kind of the function that fired or -1, RK4
    trials made). On an event, ``out`` holds the state just after the
    crossing (within ``EVENT_TIME``).

    The crossing is bracketed on true RK4 states from the step's start by
    Anderson and Bjorck's variant of regula falsi on the function that fired
    (:mod:`~freestand.core.contact.regula_falsi`; superlinear, each end of the
    bracket moves; the Illinois variant of Dowell and Jarratt 1971 took 10.5
    trials per event of a rocking cabinet, this 9.4), each trial kept
    half a tolerance inside the bracket so that it closes to ``EVENT_TIME``
    once the root is found; a trial at which another function has fired
    becomes the bracket's end and that function the one followed. About eight
    trials instead of the bisection's thirty; with the seeds below, three or
    four for a gap (a rocking cabinet under a record: 4.6 per event, its
    slip-stops' eight included).

    The first trials are seeded: the crossing is found first on the step's
    cubic interpolant (:func:`interpolated_crossing`, at one solve or none
    per trial), tried on RK4 states, and then a Newton step from there is
    tried just past it, from each side in turn (:func:`_seeded_trial`);
    where the seeds do not close the bracket, the regula falsi goes on from
    it. A slip-stop is not seeded: the friction's direction has kinks
    within such a step (where the slip crosses its floor and turns against
    the stored direction, :func:`~freestand.core.contact.body_kernel.slip_direction`),
    and the cubic through the step's ends missed the cask's stops by up to
    3e-5 s.
    ``bracket`` (3, ``MAX_EVENT_FUNCTIONS``) is work space: the functions'
    levels and their values at the bracket's ends.
    """
    n = event_functions(par, record, dt, t + h, out, mode, data, sc, ref, values, kinds)
    levels, low_values, high_values = bracket[0], bracket[1], bracket[2]
    _levels(par, n, start_values, kinds, levels)
    target = _fired(n, values, levels, -1)
    if target < 0:
        return h, -1, 0
    for i in range(n):
        low_values[i] = start_values[i]
        high_values[i] = values[i]
    low = 0.0
    high = h
    g_low = low_values[target] - levels[target]
    g_high = high_values[target] - levels[target]
    # the crossing on the step's cubic interpolant seeds the search on RK4 states
    first, rate_ = 0.0, math.nan
    if kinds[target] != FN_SLIP_STOP:
        # (not a slip-stop: the friction's direction has kinks within its step, see above)
        state_rate(out, sc[SC_ACC], k[1])  # y' at the step's end (k[1] is free until a trial)
        first, rate_ = interpolated_crossing(par, record, dt, t, h, y, out, mode, data, sc, k, ref,
                                             values, kinds, levels[target], target, g_low,
                                             g_high, trial)  # fmt: skip
    seeding = math.isfinite(rate_) and 0.0 < first < h
    seeded = 0
    last, g_last, previous, g_previous = first, 0.0, math.nan, 0.0
    side = 0
    trials = 0
    for _ in range(200):
        if high - low <= EVENT_TIME:
            break
        trials += 1
        middle = math.nan
        if seeding and seeded == 0:
            middle = min(max(first, 0.5 * EVENT_TIME), h - 0.5 * EVENT_TIME)
        elif seeding and seeded < SEED_TRIALS:
            middle = _seeded_trial(last, g_last, previous, g_previous, rate_, low, high)
        if seeding and math.isnan(middle):
            # the seeds are spent: the regula falsi from the bracket's ends, unscaled
            seeding = False
            side = 0
            g_low = low_values[target] - levels[target]
            g_high = high_values[target] - levels[target]
        if math.isnan(middle):
            middle = _trial_time(low, high, g_low, g_high)
        _rk4(par, record, dt, t, middle, y, mode, data, sc, k, trial)
        event_functions(par, record, dt, t + middle, trial, mode, data, sc, ref, values, kinds)
        fired = _fired(n, values, levels, target)
        if seeding:
            seeded += 1
            previous, g_previous = (last if seeded > 1 else math.nan), g_last
            last, g_last = middle, values[target] - levels[target]
            seeding = fired < 0 or fired == target  # another function fired: no more seeds
        if fired >= 0:
            for i in range(n):
                high_values[i] = values[i]
            for i in range(STATE_SIZE):
                out[i] = trial[i]
        else:
            for i in range(n):
                low_values[i] = values[i]
        if fired >= 0 and fired != target:
            # another function fired first: it is followed, from the bracket's low end
            target = fired
            side = 0
            high = middle
            g_low = low_values[target] - levels[target]
            g_high = high_values[target] - levels[target]
        else:
            g_trial = values[target] - levels[target]
            low, high, g_low, g_high, side = narrowed(fired >= 0, middle, g_trial, low, high,
                                                      g_low, g_high, side)  # fmt: skip
    # the solve at the event's state (the caller's next phase reads the scratch)
    event_functions(par, record, dt, t + high, out, mode, data, sc, ref, values, kinds)
    return high, kinds[target], trials


@nb.njit(cache=True, error_model="numpy", _nrt=False)
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


@nb.njit(cache=True, error_model="numpy", _nrt=False)
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


@nb.njit(cache=True, error_model="numpy", _nrt=False)
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
    EDGE and POINT: the centre of gravity shifted vertically by the held
    points' mean gap. Velocities: the least-kinetic-energy change that makes
    the held rows' velocities vanish (a plastic impact on the held rows), on
    the rows at the patch's geometric centre (a sticking patch's rows hold
    it still about any centre). The scratch is left with those rows, not a
    solve: every caller solves the mode at the projected state next.
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
        g0, _ = corner_gap(par, y, rot, mode[M_INDEX], d)
        g1, _ = corner_gap(par, y, rot, (mode[M_INDEX] + 1) % 4, d)
        y[2] -= 0.5 * (g0 + g1)
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


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def drifted(par, y, mode, sc):
    """False where a sliding FACE's held rows have drifted by round-off only (no projection).

    A flat base's held rows are its height, its tilt and their rates, whose
    accelerations the mode holds at zero: RK4 keeps them at zero to
    round-off, and :func:`project` (two more solves) would change nothing
    that matters. Any other mode's rows drift with the step's truncation
    error. The round-off allowed is ``FLAT_ROUND_OFF`` on each of them.
    """
    if mode[M_KIND] != FACE or mode[M_SLIP] != 1:
        return True
    if max(abs(y[4]), abs(y[5]), abs(y[9]), abs(y[10]), abs(y[11])) > FLAT_ROUND_OFF:
        return True
    rot = sc[SC_ROT]
    rotation_matrix(y, rot)
    d = sc[SC_PROBE][0]
    arm(par, rot, 0.0, 0.0, 0.0, d)
    return abs(y[2] + d[2]) > FLAT_ROUND_OFF


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _post_record_fall(par, y, mode, sc):
    """True when, without excitation, a pivoting body is past its top: tilting and falling."""
    if mode[M_KIND] != POINT and mode[M_KIND] != EDGE:
        return False
    rot = sc[SC_ROT]
    rotation_matrix(y, rot)
    # d(cos tilt)/dt = (omega x e_3)_z
    rate_cos = y[10] * rot[1, 2] - y[11] * rot[0, 2]
    return rate_cos < 0.0 and y[9] < 0.0


@nb.njit(cache=True, error_model="numpy", _nrt=True)
def resolve(par, record, dt, t, y, mode, data, sc, gap_tol, velocity_tol, which, istate):
    """Phase 3: the impact (a gap closed) and the next contact mode; the event kind."""
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
        prepare(par, record, dt, t, y, FREE, 0, 0.0, sc)
        after = np.empty(6)
        chosen = impact(par, y, sc, gap_tol, data[D_PSI], mode, data, after)
        if chosen == NONE_ADMISSIBLE:
            # no candidate of the impact law: the velocity-level impact at the base points
            arms = np.empty((MAX_POINTS, 3))
            count = base_points(par, y, rot, data[D_PSI], gap_tol, arms)
            for i in range(6):
                after[i] = y[7 + i]
            velocity_impact(par, sc[SC_INV], arms, count, par[P_MU_KINETIC], after,
                            np.zeros((MAX_POINTS, 3)))  # fmt: skip
            istate[I_REMEDIES] += 1
            event = EV_REMEDY
        else:
            istate[I_IMPACTS] += 1
            event = EV_IMPACT
        # the restitution factor on the velocity after (relative to the support)
        for i in range(6):
            y[7 + i] = par[P_RESTITUTION] * after[i]
    excluded = np.array([-1, 0, 0], dtype=np.int64)
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


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _set_free(mode):
    """The mode FREE (a stretch of the remedy runs with it: no contact held)."""
    mode[M_KIND] = FREE
    mode[M_INDEX] = 0
    mode[M_SLIP] = 0


@nb.njit(cache=True, error_model="numpy", _nrt=True)
def advance_stretch(par, record, dt, t, h, y, data, sc, gap_tol, force, impulses):
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
    by this step's.
    """
    prepare(par, record, dt, t + h, y, FREE, 0, 0.0, sc)
    rot = sc[SC_ROT]
    velocity = np.empty(6)
    for i in range(6):
        velocity[i] = y[7 + i] + h * sc[SC_BASE][i]
    free = np.empty(3)
    for i in range(3):
        free[i] = velocity[i]
    arms = np.empty((MAX_POINTS, 3))
    reach = gap_tol + h * _fall_speed(velocity, par)
    count = base_points(par, y, rot, data[D_PSI], reach, arms)
    approach = 0.0  # the fastest approach of a base point [m/s]
    for p in range(count):
        _, _, uz = cross(velocity[3], velocity[4], velocity[5], arms[p, 0], arms[p, 1], arms[p, 2])
        approach = max(approach, -(velocity[2] + uz))
    velocity_impact(par, sc[SC_INV], arms, count, par[P_MU_KINETIC], velocity, impulses)
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


@nb.njit(cache=True, error_model="numpy", _nrt=False)
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


@nb.njit(cache=True, error_model="numpy", _nrt=False)
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


@nb.njit(cache=True, error_model="numpy", _nrt=False)
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


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def held_row(par, y, sc, reach, velocity_tol, force, patch, row, out_mode, out_force):
    """Row ``row`` of a stretch of the remedy: the patch it holds and its contact force.

    The patch is the one the time stepping holds (:func:`touched_patch`, not
    FREE, which the engine's mode is during a stretch); the force is
    ``force`` = (N, |f_t|) [N], the step's impulses over its length;
    ``patch`` (3, int) is work space.
    """
    touched_patch(par, y, sc[SC_ROT], reach, velocity_tol, patch)
    for i in range(3):
        out_mode[row, i] = patch[i]
    out_force[row, 0] = force[0]
    out_force[row, 1] = force[1]


@nb.njit(cache=True, error_model="numpy", _nrt=False)
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


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _event(t, kind, before, after, count, ev_time, ev_kind, ev_before, ev_after):
    if count < ev_time.shape[0]:
        ev_time[count] = t
        ev_kind[count] = kind
        ev_before[count] = before
        ev_after[count] = after
    return count + 1


@nb.njit(cache=True, error_model="numpy", _nrt=True)
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


@nb.njit(cache=True, error_model="numpy", _nrt=False)
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


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def rest_step(par, record, dt, t, h, rest, rot, lam, centre):
    """A step of the resting mode over h (within one segment of the record).

    The margins are concave in the multipliers (a minimum of linear ones, or
    ``R N - |M|``, ``mu N - |F|``), which are linear in time over a
    segment: where both ends hold, the whole step holds. Otherwise the
    crossing is bisected to EVENT_TIME. Returns (step taken, kind fired or -1).
    """
    slack = 1e-9 * par[P_MASS] * par[P_GRAVITY]
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


@nb.njit(cache=True, error_model="numpy", _nrt=False)
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


@nb.njit(cache=True, error_model="numpy", _nrt=True)
def _stretch(par, record, dt, t, h, y, mode, data, sc, gap_tol, velocity_tol, istate, force,
             impulses):  # fmt: skip
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
    advance_stretch(par, record, dt, t, h, y, data, sc, gap_tol, force, impulses)
    hovering = _settle(par, y, sc, data, force[2], gap_tol, velocity_tol)
    istate[I_STRETCH_STEPS] += 1
    steps = istate[I_STRETCH]
    istate[I_STRETCH] += 1
    early = istate[I_CHATTER] == 0 and steps & (steps - 1) == 0
    if not early and steps % STRETCH_CHECK != 0:
        _set_free(mode)
        return t + h
    none = np.array([-1, 0, 0], dtype=np.int64)
    found = select_mode(par, record, dt, t + h, y, sc, gap_tol, velocity_tol, mode, data, none)
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


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _horizontal_speed(y, d):
    """Horizontal speed [m/s] of the material point at arm d."""
    return math.hypot(point_velocity(y, d, 1.0, 0.0, 0.0), point_velocity(y, d, 0.0, 1.0, 0.0))


@nb.njit(cache=True, error_model="numpy", _nrt=True)
def touched_patch(par, y, rot, reach, velocity_tol, patch):
    """The patch a time-stepped state touches, as (kind, index, slip) in ``patch``.

    The most closed candidate (:func:`freestand.core.contact.body_modes.candidates`)
    of the base points that touch within ``reach`` [m] of the support, not
    moving away faster than ``velocity_tol`` [m/s]
    (:func:`~freestand.core.contact.body_modes.touching_points`); FREE where
    none does. It slips where a touching point's horizontal speed exceeds
    ``velocity_tol``. The rows a stretch of the remedy records say which
    contact the time stepping held, not FREE. Returns the kind.
    """
    touching = np.zeros(5, dtype=np.bool_)
    psi = touching_points(par, y, rot, reach, velocity_tol, ACCELERATION, touching)
    kinds = np.zeros(MAX_CANDIDATES + 1, dtype=np.int64)
    indices = np.zeros(MAX_CANDIDATES + 1, dtype=np.int64)
    angles = np.zeros(MAX_CANDIDATES + 1)
    patch[0], patch[1], patch[2] = FREE, 0, 0
    if candidates(par, touching, psi, kinds, indices, angles) == 0:
        return FREE
    patch[0], patch[1] = kinds[0], indices[0]
    d = np.empty(3)
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


@nb.njit(cache=True, error_model="numpy", _nrt=True)
def _settle(par, y, sc, data, reach, gap_tol, velocity_tol):
    """Lower the body onto the base points a stretch holds above the support; True if any stay.

    A point that closed within a step of the remedy is held where it
    stopped, up to ``reach`` [m] above the support, its normal velocity
    zero (within ``velocity_tol`` [m/s]). The body is shifted down by the
    smallest such gap, but never by more than the lowest base point's gap
    (a point rising from the support stays on or above it). Returns True
    when a held point stays more than ``gap_tol`` above the support.
    """
    rot = sc[SC_ROT]
    rotation_matrix(y, rot)
    d = np.empty(3)
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
        return False
    shift = min(held, lowest)
    if shift > 0.0:
        y[2] -= shift
    return held - max(shift, 0.0) > gap_tol


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def watch_chatter(t, before, event, mode, istate, chatter):
    """Count an EDGE's or FACE's slip restarts and remedies; start a chatter's stretch at the third.

    A restart is a slip-stop after which the patch slips again from rest
    (the event ``EV_STICK`` with a sliding mode). ``chatter`` holds the last
    one's time [s] and how many followed each other within the window
    (``CHATTER_WINDOW`` for an EDGE, whose onset direction at its friction
    limit is unstable; ``FACE_CHATTER_WINDOW`` for a FACE, whose restarts
    are the support's acceleration hovering at the friction limit, each a
    real stick and slip, except where they follow each other within
    microseconds: no slip from rest lasts there); at ``CHATTER_COUNT`` the
    remedy's time stepping takes over (:func:`_start_chatter`). Returns the
    event's kind.
    """
    if before < EDGE or not (event == EV_REMEDY or (event == EV_STICK and mode[M_SLIP] == 1)):
        return event
    window = CHATTER_WINDOW if before == EDGE else FACE_CHATTER_WINDOW
    chatter[1] = chatter[1] + 1.0 if t - chatter[0] < window else 1.0
    chatter[0] = t
    if chatter[1] < CHATTER_COUNT:
        return event
    chatter[1] = 0.0
    return _start_chatter(mode, istate, event)


@nb.njit(cache=True, error_model="numpy", _nrt=False)
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


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def slip_velocity(par, record, dt, t, y, mode, data, sc):
    """The held patch's slip velocity at (t, y), at its centre of pressure, in ``sc[SC_SVEL]``.

    The mode is solved there (:func:`solve_at`, its rows left in the
    scratch). Returns (its speed [m/s], the patch's normal rows, its tangential rows).
    """
    ok, n_normal, n_tangent = solve_at(par, record, dt, t, y, mode, data, sc)
    svel = sc[SC_SVEL]
    tangential_velocity(y, sc[SC_TANGENT], n_tangent, svel)
    return _size(svel, n_tangent), n_normal, n_tangent


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _size(vector, count):
    """The length of the first ``count`` components of ``vector``."""
    size = 0.0
    for k in range(count):
        size += vector[k] ** 2
    return math.sqrt(size)


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _rest(par, record, dt, breaks, h_max, t_end, gap_tol, velocity_tol, t, y, mode, data, sc,
          rest, istate, ev_time, ev_kind, ev_before, ev_after):  # fmt: skip
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
                        istate)  # fmt: skip
        istate[I_EVENTS] = _event(t, event, before, mode[M_KIND], istate[I_EVENTS], ev_time,
                                  ev_kind, ev_before, ev_after)  # fmt: skip
        solve_at(par, record, dt, t, y, mode, data, sc)
    return t


@nb.njit(cache=True, error_model="numpy", _nrt=True)
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
    ref = np.zeros(5)
    start_values = np.zeros(MAX_EVENT_FUNCTIONS)
    values = np.zeros(MAX_EVENT_FUNCTIONS)
    kinds = np.zeros(MAX_EVENT_FUNCTIONS, dtype=np.int64)
    bracket = np.zeros((3, MAX_EVENT_FUNCTIONS))
    capacity = out_t.shape[0]
    rest = np.zeros((4, 6))
    rest_ready = False
    force = np.zeros(3)  # a stretch's mean contact force (normal, |tangential|) [N], reach [m]
    patch = np.zeros(3, dtype=np.int64)  # the patch a stretch's step held
    impulses = np.zeros((MAX_POINTS, 3))  # a stretch's step's impulses: the next one's start
    chatter = np.array([-math.inf, 0.0])  # the last slip restart's time [s], restarts in a row
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
                         gap_tol, velocity_tol, istate, force, impulses)  # fmt: skip
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
                      data, sc, rest, istate, ev_time, ev_kind, ev_before, ev_after)  # fmt: skip
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
            count = start_functions(par, record_, dt, t, y, mode, data, sc, ref, start_values,
                                    kinds)  # fmt: skip
        fresh = False
        h = min(_next_end(t, breaks, h_max, t_end) - t, closing_step(par, y, mode, sc, ref))
        data[D_FLOOR] = slip_floor(par, mode, sc, h)
        advance(par, record_, dt, t, h, y, mode, data, sc, k, out, velocity_tol)
        h, which, trials = locate(par, record_, dt, t, h, y, mode, data, sc, k, ref, start_values,
                                  count, trial, values, kinds, bracket, out)  # fmt: skip
        istate[I_TRIALS] += trials
        t += h
        for i in range(STATE_SIZE):
            y[i] = out[i]
        istate[I_STEPS] += 1
        if which < 0 and _lean_comes_flat(par, y, mode, sc):
            which = FN_LANDING
        if which >= 0:
            before = mode[M_KIND]
            event = resolve(par, record_, dt, t, y, mode, data, sc, gap_tol, velocity_tol,
                            which, istate)  # fmt: skip
            event = watch_chatter(t, before, event, mode, istate, chatter)
            after = mode[M_KIND]
            if event == EV_REMEDY and after == FREE:
                after = touched_patch(par, y, sc[SC_ROT], gap_tol, velocity_tol, patch)
            istate[I_EVENTS] = _event(t, event, before, after, istate[I_EVENTS], ev_time, ev_kind,
                                      ev_before, ev_after)  # fmt: skip
            if event == EV_OVERTURN:
                solve_at(par, record_, dt, t, y, mode, data, sc)
                record(t, y, mode, sc, istate[I_RECORDS], out_t, out_y, out_mode, out_force)
                istate[I_RECORDS] += 1
                istate[I_STATUS] = STATUS_OVERTURNED
                return t
        elif not resting(mode, y, velocity_tol):
            if drifted(par, y, mode, sc):
                project(par, record_, dt, t, y, mode, data, sc)
            else:
                solved = True  # locate's solve at the step's end: the state is unchanged
        if istate[I_STRETCH] == 0 and not resting(mode, y, velocity_tol):
            # the next step's references and event functions: their solve is the record's
            count = start_functions(par, record_, dt, t, y, mode, data, sc, ref, start_values,
                                    kinds, solved)  # fmt: skip
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
