"""The 3-D engine's ``advance`` phase: one RK4 step of the held contact mode.

:func:`advance` takes one RK4 step of the held mode (the contact forces
solved at every stage by :func:`freestand.core.contact.body_solve.rate`);
:func:`start_functions` and :func:`event_functions` give a step's references
(the slip's direction, the pivot's) and its event functions, each >= 0
while the mode holds (:func:`event_values`); :func:`closing_step`,
:func:`slip_floor` and the slip's and whirl's time scales bound the step's
length. The loop that calls them is :func:`freestand.core.dynamics.body_engine.run`;
the event search on these functions, :mod:`freestand.core.dynamics.body_events`.
"""

from __future__ import annotations

import math

from freestand.core.contact.body_kernel import (
    D_FLOOR,
    D_PSI,
    D_PULL,
    D_PULL_FREE,
    D_SLIP,
    EDGE,
    FACE,
    FREE,
    M_INDEX,
    M_KIND,
    M_SLIP,
    P_GRAVITY,
    P_HALF_X,
    P_INERTIA,
    P_MASS,
    P_MU_KINETIC,
    P_SHAPE,
    PIVOT_LEAN,
    POINT,
    SC_ACC,
    SC_ARMS,
    SC_CENTRE,
    SC_DIR,
    SC_INV,
    SC_LAM,
    SC_PROBE,
    SC_ROT,
    SC_SACC,
    SC_SVEL,
    SC_TANGENT,
    SC_TBIAS,
    SHAPE_BOX,
    STATE_SIZE,
    arm,
    corner_gap,
    cross,
    friction_margin,
    kinetic_energy,
    normal_margin,
    pivot_direction,
    rotation_matrix,
    row_acceleration,
    row_counts,
    sin_tilt,
    store_lowest_rim_angle,
    stored_direction,
    support_acceleration,
    tangential_velocity,
)
from freestand.core.contact.body_solve import (
    closed_form,
    rate,
    solve_at,
    state_rate,
    sticking_solve,
)
from freestand.core.contact.compiled import kernel
from freestand.core.contact.slip_law import SLIP_FLOOR
from freestand.core.contact.vectors import leading_length, norm2
from freestand.core.dynamics.body_hinge import hinge_rk4

MAX_EVENT_FUNCTIONS = 8
REF_SIZE = 6  # a step's references (:func:`references`): slip direction, pivot, stop speed
REF_STOP = 5  # the speed [m/s] at which a flat slip stops (0.0: where it reverses only)
CLOSING_OVERSHOOT = 1.25  # a step ends this far past a gap's predicted closing [-]
WHIRL_ANGLE = 0.1  # [rad] largest turn of a rolling cylinder's lean in one step
TILT_FRACTION = 0.5  # a whirling lean covers at most this part of its way to the vertical in a step
RISE_LEAN = 2.0 * PIVOT_LEAN  # sin(tilt) a step from below PIVOT_LEAN rises to at most
PLANAR_PASS = 0.1  # a lean predicted to pass within this part of PIVOT_LEAN lands as in a plane [-]
LEAN_TRUST = 1e-4  # sin(tilt) below which the lean's predicted passing distance is trusted [-]
ROUND_OFF_PASS = 1e-12  # a passing distance below this is a planar motion's round-off [-]
SLIP_FRACTION = 0.5  # a step lasts at most this part of a slip's time scale |s| / |s'|
FACE_TURN = 0.3  # [rad] a flat base's slip turns by about this much at most in a step
STOP_TURN = 0.5  # a slip-stop fires where s turned beyond arccos(-STOP_TURN) = 120 deg from r
SLIP_MIN_STEP = 1e-4  # [s] the slip's time scale bounds no step below this
FACE_MIN_STEP = 3e-4  # [s] a flat base's turn bounds no step below this
STRAIGHT_SLIP = 1e-9  # a slip whose rate across its velocity is below this part keeps its line
ONSET_STEP = 1e-3  # [s] a flat base's slip from rest steps at most this far
FLOOR_STABILITY = 2.0  # h lambda of a flat base's slip turning at its floor (RK4: stable to 2.78)
ENERGY_GROWTH = 2.0  # a step's sqrt(kinetic energy) may grow by this times its bound at most
MIN_STEP = 1e-9  # [s] the smallest step the closing prediction may ask for
TURN_ANGLE = 0.03  # [rad] largest turn of the body in one step (turn_step)
NEAR_FLAT_STEP = 1e-3  # [s] longest step of a cylinder on its rim within PIVOT_LEAN of flat

# function kinds (what a crossing means)
FN_NORMAL = 0
FN_FRICTION = 1
FN_SLIP_STOP = 2
FN_GAP = 3
FN_LANDING = 4
FN_TILT = 5


@kernel(cache=True, error_model="numpy", _nrt=False)
def _normalise(y):
    size = math.sqrt(y[3] ** 2 + y[4] ** 2 + y[5] ** 2 + y[6] ** 2)
    for i in range(3, 7):
        y[i] /= size


@kernel(cache=True, error_model="numpy", _nrt=False)
def _rk4(par, record, dt, t, h, y, mode, data, sc, k, out):
    """One RK4 step of the held mode over h from (t, y) into ``out``; False if singular.

    ``k[0]`` holds y' at (t, y) already: the first stage does not depend on
    h, and the step and the trials of :func:`~freestand.core.dynamics.body_events.locate` share it.
    A box's sticking EDGE is stepped in its one coordinate, the turn about
    the edge (:func:`~freestand.core.dynamics.body_hinge.hinge_rk4`): ``k``
    beyond ``k[0]`` is then left as it was.
    """
    if mode[M_KIND] == EDGE and mode[M_SLIP] == 0 and par[P_SHAPE] == SHAPE_BOX:
        return hinge_rk4(par, record, dt, t, h, y, mode[M_INDEX], out)
    stage = k[4]
    ok = True
    pulled = data[D_PULL] == 1.0
    for i in range(STATE_SIZE):
        stage[i] = y[i] + 0.5 * h * k[0, i]
    if pulled:
        pulled_direction(record, dt, t, 0.5 * h, data)
    ok &= rate(par, record, dt, t + 0.5 * h, stage, mode, data, sc, k[1])
    for i in range(STATE_SIZE):
        stage[i] = y[i] + 0.5 * h * k[1, i]
    ok &= rate(par, record, dt, t + 0.5 * h, stage, mode, data, sc, k[2])
    for i in range(STATE_SIZE):
        stage[i] = y[i] + h * k[2, i]
    if pulled:
        pulled_direction(record, dt, t, h, data)
    ok &= rate(par, record, dt, t + h, stage, mode, data, sc, k[3])
    for i in range(STATE_SIZE):
        out[i] = y[i] + h / 6.0 * (k[0, i] + 2.0 * k[1, i] + 2.0 * k[2, i] + k[3, i])
    _normalise(out)
    return ok


@kernel(cache=True, error_model="numpy", _nrt=False)
def resting(mode, y, velocity_tol):
    """True while the body sits flat, sticks and does not move (not integrated)."""
    if mode[M_KIND] != FACE or mode[M_SLIP] != 0:
        return False
    for i in range(7, 13):
        if abs(y[i]) > 1e-14:
            return False
    return True


@kernel(cache=True, error_model="numpy", _nrt=False)
def advance(par, record, dt, t, h, y, mode, data, sc, k, out, velocity_tol):
    """Phase 1: the state at t + h in ``out`` (RK4, or unchanged at rest); False if singular.

    The scratch holds the held mode solved at (t, y) (:func:`start_functions`
    at the step's start): the first stage is read from it.
    """
    if resting(mode, y, velocity_tol):
        for i in range(STATE_SIZE):
            out[i] = y[i]
        return True
    if data[D_PULL] == 1.0:
        # a slow flat base's slip: its first stage along its direction at the start
        pulled_direction(record, dt, t, 0.0, data)
        rate(par, record, dt, t, y, mode, data, sc, k[0])
    else:
        state_rate(y, sc[SC_ACC], k[0])
    return _rk4(par, record, dt, t, h, y, mode, data, sc, k, out)


@kernel(cache=True, error_model="numpy", _nrt=False)
def references(par, record, dt, t, y, mode, data, sc, ref, stop_speed, solved=False):
    """The step's references: the slip direction (3), the pivot's horizontal direction (2) and
    the speed at which the slip stops (1).

    The slip direction is the slip velocity's at the held patch's centre of
    pressure at (t, y), or the stored one while the slip is slower than
    ``SLIP_FLOOR`` or the last step's floor (:func:`slip_floor`); an EDGE's
    there is the direction its solve took, the slip pulled to the stored
    one. Returns the
    normal and tangential rows of the slip's solve where the scratch holds
    the held mode solved at (t, y) as with the references stored: its solve
    read no stored direction
    (:func:`~freestand.core.contact.body_solve.slip_direction`), or the
    stored one is kept; else (0, -1).
    ``ref[REF_STOP]`` is ``stop_speed`` [m/s] (the velocity tolerance, within
    which a slip counts as zero) where a flat base's slip starts the step
    faster than that and turns (:func:`slip_turns`), else 0.0:
    :func:`event_values` then also stops the slip where its speed falls to
    it. A slip that starts slower (from rest, after an onset) stops where it
    reverses only, and so does a slip that keeps its line (Newmark's block:
    stopped at the tolerance, squat bodies under one horizontal component of
    a record slid up to 2e-4 of their slide short of it), an edge's and a
    point's, whose steps the slip's own time scale bounds (a point's, also
    RK4's stability on its turn: :func:`_slip_turn_time`; stopped at the
    tolerance too, the 3-D benchmark's rocking cabinet took 19 % more steps).
    ``solved``: the scratch holds the held mode solved at (t, y) already (a
    step's end left unprojected,
    :func:`~freestand.core.dynamics.body_projection.drifted`, whose event
    functions left the slip velocity in the scratch), and it is not solved
    again; a sticking mode's rows are then returned too, unless a rolling
    cylinder's pivot, moved to the lowest rim point, is not the one solved
    for (the lowest point's opposite, past a landing).
    """
    rot = sc[SC_ROT]
    if not solved:
        rotation_matrix(y, rot)  # (solved: the scratch's, at y)
    for i in range(REF_SIZE):
        ref[i] = 0.0
    if mode[M_KIND] == POINT and par[P_SHAPE] != SHAPE_BOX:
        # the step's pivot: the lowest rim point (kept on its side within the step)
        held_cos, held_sin = pivot_direction(par, rot, POINT, data[D_PSI], sc)  # the solve's
        psi = store_lowest_rim_angle(rot, data[D_PSI], sc)
        data[D_PSI] = psi
        cos_psi, sin_psi = pivot_direction(par, rot, POINT, psi, sc)
        solved = solved and cos_psi == held_cos and sin_psi == held_sin
        probe = sc[SC_PROBE]
        d, c = probe[0], probe[1]
        radius = par[P_HALF_X]
        # horizontal direction of the pivot from the base centre
        cos_stored, sin_stored = stored_direction(psi, sc)  # cos psi, sin psi, kept
        arm(par, rot, radius * cos_stored, radius * sin_stored, 0.0, d)
        arm(par, rot, 0.0, 0.0, 0.0, c)
        px = d[0] - c[0]
        py = d[1] - c[1]
        size = norm2(px, py)
        ref[3] = px / size
        ref[4] = py / size
    if mode[M_SLIP] == 0:
        return row_counts(mode[M_KIND]) if solved else (0, -1)
    if solved:
        n_normal, n_tangent = row_counts(mode[M_KIND])
        size = leading_length(sc[SC_SVEL], n_tangent)
    else:
        size, n_normal, n_tangent = slip_velocity(par, record, dt, t, y, mode, data, sc)
    svel = sc[SC_SVEL]
    floor = max(SLIP_FLOOR, data[D_FLOOR])  # the last step's (slip_floor)
    for i in range(n_tangent):
        if size > floor:
            ref[i] = svel[i] / size
        elif mode[M_KIND] == EDGE:
            ref[i] = sc[SC_DIR][i]  # the solve's direction, pulled to the reference
        else:
            ref[i] = data[D_SLIP + i]
        data[D_SLIP + i] = ref[i]
    if mode[M_KIND] == FACE and size > stop_speed and slip_turns(sc, n_tangent):
        ref[REF_STOP] = stop_speed
    # an EDGE's reference below its floor moved to the direction its solve took: that solve
    # is kept as the step's first stage (solved again with the moved reference, the 3-D
    # benchmark's cabinet at its default step took other remedies and rocked to 0.164 rad,
    # where 0.5 ms steps give 0.074 and MuJoCo 0.075: not understood)
    return n_normal, n_tangent if size <= floor or sc[SC_CENTRE][5] == 0.0 else -1


@kernel(cache=True, error_model="numpy", _nrt=False)
def slip_turns(sc, n_tangent):
    """Whether a flat base's slip turns: its rate s' has a part across its velocity s.

    ``|s' - (s' . u) u| > STRAIGHT_SLIP |s'|``, u = s / |s|, from the held
    mode's solve in the scratch (its slip velocity and accelerations) at the
    step's start. A slip that keeps its line (a flat base under one
    horizontal component, in any direction, as Newmark's block) has none but
    round-off.
    """
    svel, rate = sc[SC_SVEL], sc[SC_SACC]
    speed = leading_length(svel, n_tangent)
    if speed == 0.0:
        return False
    along = 0.0
    for k in range(n_tangent):
        rate[k] = row_acceleration(sc[SC_TANGENT], sc[SC_TBIAS], k, sc[SC_ACC])
        along += rate[k] * svel[k] / speed
    across = 0.0
    for k in range(n_tangent):
        across += (rate[k] - along * svel[k] / speed) ** 2
    return math.sqrt(across) > STRAIGHT_SLIP * leading_length(rate, n_tangent)


@kernel(cache=True, error_model="numpy", _nrt=False)
def event_functions(par, record, dt, t, y, mode, data, sc, ref, values, kinds):
    """The event functions at (t, y) in the held mode (>= 0 while it holds); their count.

    A sticking POINT (a rim point rolling, a corner pivoting) or EDGE (a box
    rocking) is solved by its closed form on the applied wrench
    (:func:`~freestand.core.contact.body_solve.sticking_solve`, an RK4
    stage's solve, an EDGE's friction then about its centre of pressure):
    its multipliers and accelerations are
    :func:`~freestand.core.contact.body_solve.solve_at`'s to round-off,
    without the world inverse inertia and ``M^-1 f_0``, which nothing reads
    before the next full solve (an impact's and a projection's prepare their
    own). A rolling cylinder's step end and event trials cost about 420
    cycles so where a stage costs 225: the benchmark's slender cylinder
    under its 10 s record took some 10 % less time (thread time, best of 30:
    1.60-1.66 ms where it took 1.78). Of the 294 runs of
    ``benchmarks/body_sweep.py`` 253 are identical to the last bit and none
    changed status; a strong record's box that overturns slid 0.717 m, as at
    0.5 and 0.1 ms steps (0.716), where the full solve's round-off had taken
    it to 0.980 m.
    """
    if closed_form(mode):
        sticking_solve(par, record, dt, t, y, mode, data, sc)
        n_normal, n_tangent = row_counts(mode[M_KIND])
        return event_values(par, y, mode, sc, ref, n_normal, n_tangent, values, kinds)
    ok, n_normal, n_tangent = solve_at(par, record, dt, t, y, mode, data, sc)
    return event_values(par, y, mode, sc, ref, n_normal, n_tangent, values, kinds)


@kernel(cache=True, error_model="numpy", _nrt=False)
def start_functions(par, record, dt, t, y, mode, data, sc, ref, stop_speed, values, kinds,
                    solved=False):  # fmt: skip
    """A step's references (:func:`references`) and event functions at its start (t, y).

    One solve where the slip's references made it (none where the scratch
    holds it, ``solved``). A rolling cylinder's end is solved at its lowest
    rim point already (:func:`~freestand.core.contact.body_kernel.pivot_direction`
    reads it from the rotation; the stored angle picks its side only): where
    the scratch holds the solve for the other side of the rim, the closed
    form on its rotation and applied wrench, which are the state's, to the
    last bit. A guard: none of the 294 runs of ``benchmarks/body_sweep.py``
    takes it (counted in the compiled loop). ``stop_speed`` [m/s]:
    :func:`references`'. Returns the functions' count.
    """
    n_normal, n_tangent = references(par, record, dt, t, y, mode, data, sc, ref, stop_speed,
                                     solved)  # fmt: skip
    if n_tangent < 0 and solved and closed_form(mode):
        # the scratch's solve was for the rim's other side: its rotation and applied wrench are
        # the state's, the rows at the stored pivot are solved again
        sticking_solve(par, record, dt, t, y, mode, data, sc, True)
        n_normal, n_tangent = row_counts(mode[M_KIND])
    elif n_tangent < 0:
        return event_functions(par, record, dt, t, y, mode, data, sc, ref, values, kinds)
    return event_values(par, y, mode, sc, ref, n_normal, n_tangent, values, kinds)


@kernel(cache=True, error_model="numpy", _nrt=False)
def event_values(par, y, mode, sc, ref, n_normal, n_tangent, values, kinds):
    """The event functions of the held mode solved in the scratch at (t, y); their count.

    A slip stops where its velocity s turns against the step's reference
    direction r (``s . r = 0``) or, a flat base's, where the step armed it
    (:func:`references`), where its speed falls to ``ref[REF_STOP]``, the
    velocity tolerance within which a slip counts as zero: the function is
    ``min(s . r, |s| - ref[REF_STOP])``. A slow slip that turns as it dies
    out (a flat base under two components whose force nears the kinetic
    friction) may pass its stop beside r by the step's truncation error
    without ``s . r`` changing sign; the speed catches it, and the mode is
    chosen again there (sticking where static friction holds). Every other
    slip's function is ``s . r + STOP_TURN |s|``: it stops where s has
    turned more than 120 degrees from r, and a slip that keeps its line
    (not armed, :func:`references`) exactly where it reverses, at zero. A
    slip from rest where the friction limit is grazed (the onset's
    acceleration zero to round-off) grows in a direction of its own, across
    r: ``s . r`` alone fired a stop there at once, again and again (the 3-D
    benchmark's rocking cabinet, whose edge the chatter's remedy then held
    for 90 ms; ``docs/three-d.md``).
    """
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
            if ref[REF_STOP] > 0.0:
                along = min(along, leading_length(svel, n_tangent) - ref[REF_STOP])
            else:
                along += STOP_TURN * leading_length(svel, n_tangent)
            values[count] = along
            kinds[count] = FN_SLIP_STOP
            count += 1
    d = sc[SC_PROBE][0]
    if par[P_SHAPE] == SHAPE_BOX:
        for c in range(4):
            if corner_held(mode, c):
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


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def corner_held(mode, c):
    """Whether a box's base corner c is held by the mode's patch (a FACE's four, an EDGE's two,
    a POINT's one): it has no gap function (:func:`event_values`, :func:`closing_step`)."""
    kind, index = mode[M_KIND], mode[M_INDEX]
    if kind == FACE or (kind == POINT and index == c):
        return True
    return kind == EDGE and (index == c or (index + 1) % 4 == c)


@kernel(cache=True, error_model="numpy", _nrt=False)
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


@kernel(cache=True, error_model="numpy", _nrt=False)
def turn_step(y):
    """Largest step [s] that turns the body by at most ``TURN_ANGLE``: ``TURN_ANGLE / |omega|``.

    RK4's error in the attitude, and in where a rolling rim point is, grows
    as ``(|omega| h)^5`` a step, whatever the rocking frequency that sets the
    default step (:func:`~freestand.core.dynamics.body_history.default_body_step`):
    a spinning body needs steps of its own. Thin cylinders started in Le
    Saux et al.'s steady rolling (``tests/validation/test_body_rolling_disc.py``),
    40 of them at random (R 0.1-1 m, tilt 0.2-1.45 rad, precession 1-8 rad/s,
    spin up to 35 rad/s), kept their tilt over ten turns to 1.4e-4 rad at the
    default step; to 6.5e-7 with this bound (1.1e-7 at 0.02 rad, 5.8e-6 at
    0.05). Under records a body turns at a few rad/s at most until it falls:
    the bound leaves those steps alone.
    """
    rate = math.sqrt(y[10] * y[10] + y[11] * y[11] + y[12] * y[12])
    return TURN_ANGLE / rate if rate > 0.0 else math.inf


@kernel(cache=True, error_model="numpy", _nrt=False)
def closing_step(par, y, mode, sc, ref, pulled):
    """Largest step [s] that cannot step over the closing of a gap and its reopening.

    ``pulled``: a flat base's slow slip driven on by the support is pulled
    to the direction of its rate without friction (:func:`slow_face_slip`);
    its turn does not bound the step (:func:`_slip_turn_time`).

    A point that lifts by a little flies for a short time (a cylinder rocking
    by 1e-4 rad lands again within some 10 ms): a step longer than the flight
    would see the gap open at both its ends and miss the impact. Each gap (a
    box corner not held) and a rolling cylinder's landing function f is
    predicted by its Taylor polynomial f + f' t + f'' t^2 / 2 (f'' from the
    held mode's accelerations in ``sc``, which :func:`start_functions` just
    solved); the step ends ``CLOSING_OVERSHOOT`` past its earliest zero, so
    that :func:`~freestand.core.dynamics.body_events.locate` brackets the
    crossing. A rolling cylinder's lean (the
    horizontal projection of its axis) turns at ``|e_h x e_h'| / |e_h|^2``,
    which grows as 1/tilt near flat: :func:`_whirl_step` bounds the step there.
    Below ``PIVOT_LEAN`` the cylinder turns about its stored rim point, above
    it about the lowest one
    (:func:`~freestand.core.contact.body_kernel.pivot_direction`): a step
    from below ends about where an upper bound of the lean,
    ``|e_h| + |e_h'| t + |e_h''| t^2 / 2``,
    reaches ``RISE_LEAN``, so that the rim point's change falls between steps,
    not inside RK4's stages (a 5 ms step from 3e-7 to 2.7e-6 once set a
    slender cylinder rolling that lands at fine steps), and after at most
    ``NEAR_FLAT_STEP``: the bound takes the accelerations at the step's
    start, and a record's growing force once lifted a slender cylinder from
    4e-8 to 3e-6 in a 10 ms step, past the 10 ms in which, at fine steps,
    its lean turns with the two components below ``PIVOT_LEAN``: the
    benchmark's 20 s run took another branch, its slide 14 % and its twist
    9 % off those of steps of 1 ms to 0.1 ms, which agree within about 2 %;
    now within 2.5 % and 5 %).
    """
    rot = sc[SC_ROT]
    x = sc[SC_ACC]
    kind = mode[M_KIND]
    wx, wy, wz = y[10], y[11], y[12]
    earliest = math.inf
    if mode[M_SLIP] == 1:
        earliest = _slip_turn_time(par, mode, sc, pulled)
    d = sc[SC_PROBE][0]
    if par[P_SHAPE] == SHAPE_BOX:
        if kind == FACE:
            return max(earliest, MIN_STEP)
        for c in range(4):
            if corner_held(mode, c):
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
            earliest = min(earliest, rise, NEAR_FLAT_STEP / CLOSING_OVERSHOOT)
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


@kernel(cache=True, error_model="numpy", _nrt=False)
def _slip_turn_time(par, mode, sc, pulled):
    """Time [s] in which a slip's velocity could stop or turn: |s| / |s'| times SLIP_FRACTION.

    The kinetic friction follows the slip's direction, which turns quickly as
    the slip slows down (with an edge's twist as one of its components): on a
    rocking edge or point a step longer than the slip's own time scale makes
    RK4 oscillate from step to step and gain energy. A flat base's direction
    is not coupled to a rotation: its steps are bounded by the turn alone,
    ``FACE_TURN |s| / |s'_perp|`` (s' across s; a slip slowing along its own
    direction stops at the located slip-stop event). A flat base's slow slip
    driven on by the support (``pulled``, :func:`slow_face_slip`) is not
    bounded by its turn: each RK4 stage pulls its friction to the direction
    of its rate without friction at the stage's time (:func:`_rk4`), to which
    such a slip turns within a fraction of a millisecond, and the pulled law
    is stable at any step. Any other flat base's step is bounded by its turn,
    and by RK4's stability on the rate at which friction turns a slow slip,
    ``FLOOR_STABILITY |s| / slip_stiffness`` (:func:`slip_floor`), not below
    ``FACE_MIN_STEP``, and a slip from rest slower than ``SLIP_FLOOR`` steps
    at most ``ONSET_STEP``. Bounded so, every slip from rest crept up in some
    twenty steps of 0.3 to 2 ms: 802 of the benchmark cask's 2,862 steps
    under its 10 s record; pulled, it takes 2,310 steps, its peak slide
    64.698 mm where 0.1 ms steps give 64.692 (64.700 bounded) and its path
    within 0.031 mm of theirs (0.027 mm bounded). Pulled instead to the
    slip's predicted direction at the step's end (the implicit step's), the
    friction lagged the turning force: the squat cylinder of
    ``tests/validation/test_body_planar_reduction.py`` under two turning
    components slid 1.2 % short of the point mass on the circular cone (0.75
    % with ``ONSET_STEP`` kept); pulled to the rate's direction, 0.12 %
    (0.09 % bounded). Unbounded and unpulled, a squat cylinder's slip under
    two components came out of its first step 50 deg off and slid 0.43 %
    too far, and a slip across the force grew from round-off (a squat
    cylinder pushed at 1 rad from its axes slid 1.8 % too far). ``sc``
    holds the rows and accelerations that :func:`start_functions` just
    solved.
    A rim point's step is also bounded by RK4's stability on the rate at
    which friction turns its slip, ``FLOOR_STABILITY |s| /
    point_slip_stiffness`` (:func:`slip_floor`). Not below ``SLIP_MIN_STEP``: a slip
    that dies away without reversing would otherwise take ever shorter steps
    (its energy is then negligible); a flat base's faster than its floor not
    below ``FACE_MIN_STEP``.
    A flat base's slip that slows down steps at most ``SLIP_FRACTION`` of its
    time to stop, ``|s| / (-|s|')`` (down to ``SLIP_MIN_STEP``): its steps
    shrink as it nears its stop, where its direction turns. Stepping over the
    stop, RK4 left the turn's residual beside the step's reference (2e-4 m/s
    after a 5 ms step, above the velocity tolerance) and the slip went on in
    that direction where fine steps stop and stick: three of 120 random
    bodies slid 0.5-1 % too far at the default step (1 and 0.5 ms agree to
    1e-6); now within 1e-4 of them, at 3 % more of the cask's steps and no
    more of its time (fewer stops and restarts to locate).
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
        if pulled:
            # pulled to its rate without friction's direction (slow_face_slip), stable at any
            # step; a slip slowing down still steps at most a part of its time to stop
            if along < 0.0 and speed > SLIP_FLOOR * SLIP_FLOOR:
                return max(SLIP_FRACTION * speed / -along, SLIP_MIN_STEP) / CLOSING_OVERSHOOT
            return math.inf
        # the turn only: s' across s; a slip from rest keeps its onset's direction within a
        # step while the support's force turns: a short step
        if speed <= SLIP_FLOOR * SLIP_FLOOR:
            return ONSET_STEP
        change = max(change - along * along / speed, 0.0)
        limit = FLOOR_STABILITY * math.sqrt(speed) / slip_stiffness(par, sc)
        if change > 0.0:
            limit = min(limit, FACE_TURN * math.sqrt(speed / change))
        limit = max(limit, FACE_MIN_STEP)
        if along < 0.0:
            # a slip slowing down: at most a part of its time to stop, |s| / (-|s|')
            limit = min(limit, max(SLIP_FRACTION * speed / -along, SLIP_MIN_STEP))
        return limit / CLOSING_OVERSHOOT
    limit = math.inf
    if kind == POINT:
        # RK4's stability on the rate at which the friction turns the slip, as a flat base's
        limit = FLOOR_STABILITY * math.sqrt(speed) / point_slip_stiffness(par, sc)
    if change > 0.0:
        limit = min(limit, SLIP_FRACTION * math.sqrt(speed / change))
    if limit == math.inf:
        return limit
    return max(limit, SLIP_MIN_STEP) / CLOSING_OVERSHOOT


@kernel(cache=True, error_model="numpy", _nrt=False)
def slip_floor(par, mode, sc, h):
    """The speed [m/s] below which a slip keeps about its step's starting direction.

    A slip's direction u = s/|s| turns at ``slip_stiffness / |s|`` (the
    kinetic friction pushes a slip's component across u back at that rate):
    a stiff rate where the slip is slow, on which RK4's explicit stages are
    unstable beyond ``h lambda = 2.78``. A slip across the force then grows
    from round-off instead of dying out, step by step: a squat cylinder
    pushed by one sine cycle at 1 rad from its axes slid 1.8 % further than
    along them, with a sideways speed of 4 mm/s (0 along them, by symmetry).
    A flat base's steps are bounded so that ``h lambda <= FLOOR_STABILITY``
    (:func:`_slip_turn_time`) down to ``FACE_MIN_STEP``, unless its slow slip
    is driven on (:func:`slow_face_slip`: then each stage pulls it to its
    rate without friction's direction, :func:`pulled_direction`); below
    that, and on a slip's first step from rest, the slip slower than this
    floor (the speed at which ``h lambda = FLOOR_STABILITY``) is pulled to
    the step's starting direction (:func:`~freestand.core.contact.body_solve.unit_slip`), which
    RK4 integrates stably, and the next step keeps that direction as its
    reference while the slip stays below the floor (:func:`references`: the
    step-by-step update to ``s/|s|`` is an explicit step on the same rate).
    A POINT's slip (a rim point) turns likewise, at most at
    :func:`point_slip_stiffness` / |s|, and is bounded and floored the same
    way (its steps down to ``SLIP_MIN_STEP``). Without both a rocking
    cylinder's slow slip on its rim from rest (1e-5 m/s, 0.1 ms steps, h
    lambda about 20) grew a slip across its plane of rocking from 1e-17 to
    1e-8 m/s in three steps: excited along x, it left the plane, rolled and
    twisted (0.35 m across, 0.9 rad) and overturned, where the planar
    engine's block rocks to 0.06 rad. An EDGE's slip (three rows, with the
    twist) is floored too, at :func:`edge_slip_stiffness` h / FLOOR_STABILITY
    with the step it takes (its steps keep the time-scale bound alone: the
    floor makes any step stable, and bounding them as a point's cost a rocking
    cabinet 60 % more time), and below its floor the next step's reference is
    the pulled direction the step started with (:func:`references`), not the
    one kept from before. Unfloored, its slow slip grew a twist from
    round-off (3e-13 to 4e-5 rad/s in 0.5 ms at 0.2 ms steps, a box sliding
    and rocking along its x axis, whose peak tilt then fell 1 % below the
    planar engine's at the default step), or chattered at its friction limit
    into the remedy's time stepping. 0.0 (``SLIP_FLOOR``) for a mode that does not slip. ``sc``
    holds the step's start solved (:func:`start_functions`). Returns [m/s].
    """
    if mode[M_SLIP] != 1:
        return 0.0
    if mode[M_KIND] == FACE:
        return slip_stiffness(par, sc) * h / FLOOR_STABILITY
    if mode[M_KIND] == POINT:
        return point_slip_stiffness(par, sc) * h / FLOOR_STABILITY
    if mode[M_KIND] == EDGE:
        return edge_slip_stiffness(par, sc) * h / FLOOR_STABILITY
    return 0.0


@kernel(cache=True, error_model="numpy", _nrt=False)
def _free_slip_rate(par, sc):
    """A flat base's slip rate a_f [m/s^2] without its friction, from the solve in the scratch.

    The friction's part of the solved slip rate, ``G f``, is taken off it: on
    a flat base the tilt is held, so a horizontal friction (f_x, f_y) at the
    friction centre's arm d and a twist row's ``rho f_t`` move the slip by
    ``f/m`` plus the twist's ``e_z x d`` and ``rho`` times ``tau / I_zz``,
    ``tau = d_x f_y - d_y f_x + rho f_t``. Returns its three components.
    """
    lam, d, rho = sc[SC_LAM], sc[SC_ARMS][3], sc[SC_CENTRE][2]
    fx, fy, ft = lam[3], lam[4], lam[5]
    twist_rate = (d[0] * fy - d[1] * fx + rho * ft) / par[P_INERTIA + 8]
    acc, tangent, tbias = sc[SC_ACC], sc[SC_TANGENT], sc[SC_TBIAS]
    return (row_acceleration(tangent, tbias, 0, acc) - (fx / par[P_MASS] - d[1] * twist_rate),
            row_acceleration(tangent, tbias, 1, acc) - (fy / par[P_MASS] + d[0] * twist_rate),
            row_acceleration(tangent, tbias, 2, acc) - rho * twist_rate)  # fmt: skip


@kernel(cache=True, error_model="numpy", _nrt=False)
def _free_slip_at(record, dt, t, tau, free):
    """A flat base's slip rate without friction tau [s] after t [m/s^2], its three components,
    then the support's vertical acceleration a_v [m/s^2] at t and at t + tau.

    ``free`` is the rate at t (:func:`_free_slip_rate`); the support's
    horizontal acceleration moves it, linear in between (its d'Alembert
    force, ``-m a``, acts at G: the twist's row keeps its rate).
    """
    a_x, a_y, a_v = support_acceleration(record, dt, t)
    b_x, b_y, b_v = support_acceleration(record, dt, t + tau)
    return free[0] - (b_x - a_x), free[1] - (b_y - a_y), free[2], a_v, b_v


@kernel(cache=True, error_model="numpy", _nrt=False)
def _free_slip_excess(par, a_v, fx, fy, ft):
    """How far the slip rate without friction (fx, fy, ft) exceeds the kinetic friction's
    per unit of mass, ``mu (g - a_v)`` [m/s^2], a_v the support's vertical acceleration then
    (a flat base's normal force is the vertical balance's, ``m (g - a_v)``): where it is
    positive the slip is driven on."""
    size = math.sqrt(fx * fx + fy * fy + ft * ft)
    return size - par[P_MU_KINETIC] * (par[P_GRAVITY] - a_v)


@kernel(cache=True, error_model="numpy", _nrt=False)
def pulled_direction(record, dt, t, tau, data):
    """A pulled slow slip's direction tau [s] into its step from t, in ``data[D_SLIP:]``.

    Its rate without friction's there (:func:`_free_slip_at` on the rate at
    the step's start kept in ``data``, :func:`start_pulled_slip`). A slow
    slip driven past the kinetic friction turns to that direction within a
    fraction of a millisecond (its direction's rate across it is that rate's
    part across it over its speed): each RK4 stage's friction is pulled to
    it (:func:`_rk4`), so it follows the support's force as it turns within
    the step, as the slip does.
    """
    fx, fy, ft, _, _ = _free_slip_at(record, dt, t, tau, data[D_PULL_FREE : D_PULL_FREE + 3])
    size = math.sqrt(fx * fx + fy * fy + ft * ft)
    if size > 0.0:
        data[D_SLIP], data[D_SLIP + 1], data[D_SLIP + 2] = fx / size, fy / size, ft / size


@kernel(cache=True, error_model="numpy", _nrt=False)
def slow_face_slip(par, record, dt, t, h, mode, data, sc):
    """Whether a flat base's slip is pulled to its rate without friction over a step of h.

    A FACE's slip slower than the floor of a step of h all along
    (:func:`slip_floor`: ``slip_stiffness h / FLOOR_STABILITY``), driven
    past the kinetic friction at both ends of the step (its rate without
    friction, :func:`_free_slip_at`, larger than ``mu (g - a_v)``), whose
    direction now (from rest, the stored one: its onset's) lies within
    ``FACE_TURN`` of that rate's at the start, which turns by less than
    ``FACE_TURN`` within the step: each stage's friction is then pulled to
    that rate's direction at its time (:func:`start_pulled_slip`), stable
    at any step, and the slip's turn does not bound the step
    (:func:`_slip_turn_time`). A slip that slows down (the friction wins) or
    swings round keeps the steps that RK4's stability on its turn allows.
    The rate without friction at t is left in ``data[D_PULL_FREE:]``, for
    :func:`start_pulled_slip`.
    """
    if mode[M_KIND] != FACE or mode[M_SLIP] != 1:
        return False
    svel = sc[SC_SVEL]
    speed = leading_length(svel, 3)
    if speed > slip_stiffness(par, sc) * h / FLOOR_STABILITY:
        return False
    free = data[D_PULL_FREE : D_PULL_FREE + 3]  # kept for start_pulled_slip
    ax, ay, at = _free_slip_rate(par, sc)
    free[0], free[1], free[2] = ax, ay, at
    bx, by, bt, a_v, b_v = _free_slip_at(record, dt, t, h, free)
    if (
        _free_slip_excess(par, a_v, ax, ay, at) <= 0.0
        or _free_slip_excess(par, b_v, bx, by, bt) <= 0.0
    ):
        return False
    size_a = math.sqrt(ax * ax + ay * ay + at * at)
    size_b = math.sqrt(bx * bx + by * by + bt * bt)
    limit = math.cos(FACE_TURN)
    if ax * bx + ay * by + at * bt < limit * size_a * size_b:
        return False
    if speed > SLIP_FLOOR:
        along = (svel[0] * ax + svel[1] * ay + svel[2] * at) / speed
    else:
        along = data[D_SLIP] * ax + data[D_SLIP + 1] * ay + data[D_SLIP + 2] * at
    return along >= limit * size_a


@kernel(cache=True, error_model="numpy", _nrt=False)
def start_pulled_slip(record, dt, t, h, data, sc):
    """A slow flat base's slip (:func:`slow_face_slip`) pulled along a step of h from t.

    Where its slip is slower than the step's floor ``data[D_FLOOR]``
    (:func:`slip_floor`), ``D_PULL`` is set to 1.0 (its rate without friction
    at t is in ``data[D_PULL_FREE:]``, kept there by :func:`slow_face_slip`
    for the step it judged), and its stored direction set to
    that rate's at t + h: the step's reference, against which its stop is
    found. Each RK4 stage then pulls the friction to that rate's direction
    at its own time (:func:`pulled_direction`). Returns True where it is
    pulled (the start must be solved again).
    """
    if leading_length(sc[SC_SVEL], 3) > data[D_FLOOR]:
        return False
    data[D_PULL] = 1.0  # its rate without friction at t: kept by slow_face_slip
    pulled_direction(record, dt, t, h, data)
    return True


@kernel(cache=True, error_model="numpy", _nrt=False)
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


@kernel(cache=True, error_model="numpy", _nrt=False)
def point_slip_stiffness(par, sc):
    """``mu N tr(W_t M^-1 W_t^T)`` [m/s^2]: a sliding POINT's slip of speed |s| turns at most at
    this / |s|.

    The kinetic friction ``-mu N u`` on the point's two tangential rows W_t
    (in the scratch, with the normal multiplier of its solve): a turn of u by
    d changes the slip's rate by ``mu N W_t M^-1 W_t^T d``, whose largest
    eigenvalue the trace bounds (the point's mobility through the body's
    rotation as well as its translation).
    """
    return par[P_MU_KINETIC] * max(sc[SC_LAM][0], 0.0) * _mobility_trace(par, sc, 2) + 1e-300


@kernel(cache=True, error_model="numpy", _nrt=False)
def edge_slip_stiffness(par, sc):
    """``mu N tr(W_t M^-1 W_t^T)`` [m/s^2]: a sliding EDGE's slip of speed |s| turns at most at
    this / |s|, as a POINT's (:func:`point_slip_stiffness`), on its three tangential rows (the
    slip along x and y at its centre of pressure and the twist), N its two corners' forces.
    """
    lam = sc[SC_LAM]
    return par[P_MU_KINETIC] * max(lam[0] + lam[1], 0.0) * _mobility_trace(par, sc, 3) + 1e-300


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _mobility_trace(par, sc, n_tangent):
    """``tr(W_t M^-1 W_t^T)`` [1/kg] of the first ``n_tangent`` tangential rows in the scratch."""
    tangent, inv = sc[SC_TANGENT], sc[SC_INV]
    inv_m = 1.0 / par[P_MASS]
    trace = 0.0
    for k in range(n_tangent):
        trace += inv_m * (tangent[0, k] ** 2 + tangent[1, k] ** 2 + tangent[2, k] ** 2)
        for i in range(3):
            for j in range(3):
                trace += tangent[3 + i, k] * inv[i, j] * tangent[3 + j, k]
    return trace


@kernel(cache=True, error_model="numpy", _nrt=False)
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


@kernel(cache=True, error_model="numpy", _nrt=False)
def slip_velocity(par, record, dt, t, y, mode, data, sc):
    """The held patch's slip velocity at (t, y), at its centre of pressure, in ``sc[SC_SVEL]``.

    The mode is solved there
    (:func:`~freestand.core.contact.body_solve.solve_at`, its rows left in
    the scratch). Returns (its speed [m/s], the patch's normal rows, its
    tangential rows).
    """
    ok, n_normal, n_tangent = solve_at(par, record, dt, t, y, mode, data, sc)
    svel = sc[SC_SVEL]
    tangential_velocity(y, sc[SC_TANGENT], n_tangent, svel)
    return leading_length(svel, n_tangent), n_normal, n_tangent


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def may_pass_a_pole(mode):
    """Whether the held mode's contact forces can pass a pole: a sliding POINT or EDGE.

    A pole needs the friction of a slip coupled into the normal direction
    (Painleve's paradox): a sticking patch's forces solve a positive definite
    system, and a flat FACE's normal force is the vertical balance's, ``m (g -
    a_v)`` (its friction is horizontal, its moments taken by the held tilt),
    whatever it slides on. Only the modes that can are checked
    (:func:`energy_jump`): the check cost the sliding cask 5 % of its time.
    """
    return mode[M_SLIP] == 1 and (mode[M_KIND] == POINT or mode[M_KIND] == EDGE)


@kernel(cache=True, error_model="numpy", _nrt=False)
def energy_jump(par, record, dt, t, h, y, end, rot, memo):
    """True where a step from (t, ``y``) to (t + h, ``end``) gained more kinetic energy than it can.

    In the support's frame only gravity and the support's d'Alembert force
    ``m (-a_x, -a_y, a_v - g)`` work on the body; a held contact's forces do
    none (its normal velocities vanish) or dissipate (kinetic friction
    opposes the slip). So ``dT/dt <= m A |v_G| <= A sqrt(2 m T)``, A the
    largest ``|(a_x, a_y, g - a_v)|`` over the step (at one of its ends: the
    record is linear within a step), and ``sqrt(T(t + h)) <= sqrt(T(t)) +
    h A sqrt(m / 2)``. A step that exceeds ``ENERGY_GROWTH`` times that
    growth did not follow the held mode's dynamics: it passed a pole of its
    contact forces, where a sliding contact's normal force goes to infinity
    and changes sign (Painleve's paradox; dynamic jamming, Genot and
    Brogliato 1999), and its RK4 stages and event search sampled forces of
    any size (a slender box, 0.14 x 0.22 x 4.9 m, mu 0.63, on a sliding
    corner: 2,400 rad/s at the located lift-off, from 2 rad/s). ``rot``
    (3, 3) is work space. ``memo`` = (time [s], sqrt(T) [J^0.5], A [m/s^2]):
    the step's end, which the next step starts from where its time is t
    (the caller sets the time to NaN where it changes the state at the
    step's end: an event, a projection).
    """
    g = par[P_GRAVITY]
    if memo[0] == t:
        start, load_start = memo[1], memo[2]
    else:
        a_x, a_y, a_v = support_acceleration(record, dt, t)
        load_start = math.sqrt(a_x * a_x + a_y * a_y + (g - a_v) ** 2)
        start = math.sqrt(kinetic_energy(par, y, rot))
    b_x, b_y, b_v = support_acceleration(record, dt, t + h)
    load_end = math.sqrt(b_x * b_x + b_y * b_y + (g - b_v) ** 2)
    finish = math.sqrt(kinetic_energy(par, end, rot))
    memo[0], memo[1], memo[2] = t + h, finish, load_end
    bound = start + ENERGY_GROWTH * h * max(load_start, load_end) * math.sqrt(0.5 * par[P_MASS])
    return finish > bound * (1.0 + 1e-9)
