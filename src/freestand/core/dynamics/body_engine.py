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
  and the drift of the held rows projected out
  (:mod:`freestand.core.dynamics.body_projection`); where no mode exists, or an
  edge's slip keeps restarting from rest
  (:func:`~freestand.core.dynamics.body_remedy.watch_chatter`), a stretch of
  velocity-level time stepping (:mod:`freestand.core.dynamics.body_remedy`);
- :func:`record`: the state and contact force written to the output buffers.

The event kinds, the counters of ``istate`` and the statuses are
:mod:`freestand.core.dynamics.body_state`'s.

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
    MAX_POINTS,
    base_points,
    restitution_velocity,
    velocity_impact,
)
from freestand.core.contact.body_kernel import (
    D_FLOOR,
    D_PSI,
    D_PULL,
    EDGE,
    FACE,
    FREE,
    M_INDEX,
    M_KIND,
    P_GRAVITY,
    P_HALF_X,
    P_MASS,
    P_MU_KINETIC,
    PIVOT_LEAN,
    POINT,
    SC_AFTER,
    SC_CENTRE,
    SC_EXCLUDED,
    SC_INV,
    SC_LAM,
    SC_PROBE,
    SC_ROT,
    STATE_SIZE,
    centre_stick_friction,
    flat_gap,
    friction_margin,
    normal_margin,
    normal_total_rows,
    prepare,
    reset_friction_centre,
    rotation_matrix,
    support_acceleration,
)
from freestand.core.contact.body_modes import (
    NONE_ADMISSIBLE,
    impact,
    no_exclusion,
    select_mode,
)
from freestand.core.contact.body_solve import solve_at, solve_at_centre
from freestand.core.contact.compiled import kernel
from freestand.core.contact.regula_falsi import narrowed
from freestand.core.dynamics.body_events import (
    EVENT_TIME,
    MARGIN_SLACK,
    inconsistent_start,
    locate,
)
from freestand.core.dynamics.body_projection import (
    drifted,
    flatten,
    lean_comes_flat,
    project,
)
from freestand.core.dynamics.body_remedy import (
    STRETCH_STEP,
    held_row,
    set_free,
    set_on_support,
    stretch_start_row,
    stretch_step,
    touched_patch,
    watch_chatter,
)
from freestand.core.dynamics.body_state import (
    EV_IMPACT,
    EV_LANDING_MISS,
    EV_LIFT_OFF,
    EV_OVERTURN,
    EV_REMEDY,
    EV_SLIP,
    EV_START,
    EV_STICK,
    I_EVENTS,
    I_IMPACTS,
    I_RECORDS,
    I_REMEDIES,
    I_STATUS,
    I_STEPS,
    I_STRETCH,
    I_TRIALS,
    STATUS_BUFFER_FULL,
    STATUS_COMPLETED,
    STATUS_OVERTURNED,
)
from freestand.core.dynamics.body_step import (
    FN_FRICTION,
    FN_GAP,
    FN_LANDING,
    FN_NORMAL,
    FN_SLIP_STOP,
    FN_TILT,
    MAX_EVENT_FUNCTIONS,
    REF_SIZE,
    advance,
    closing_step,
    energy_jump,
    may_pass_a_pole,
    resting,
    slip_floor,
    slow_face_slip,
    start_functions,
    start_pulled_slip,
    turn_step,
)


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
            flatten(par, y, rot, sc[SC_PROBE][0])
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
    no_exclusion(sc)
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
        # no consistent mode (Painleve): a stretch of velocity-level time stepping, from the
        # event's state with no base point below the support (the held points' drift within
        # the step is not projected out at an event: a box sliding on an edge at 6 rad/s
        # under 7 g sank 1e-7 m in a 3.5 ms step, and that row was recorded)
        set_on_support(par, y, sc, data, work)
        istate[I_REMEDIES] += 1
        istate[I_STRETCH] = 1
        set_free(mode)
        return EV_REMEDY
    project(par, record, dt, t, y, mode, data, sc, velocity_tol)
    return event


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
    segment: where both ends hold, the whole step holds. A margin fires
    past the admissibility slack (``MARGIN_SLACK`` m g below zero); then the
    crossing of zero, the threshold, is located to EVENT_TIME
    (:func:`rest_crossing`; ``docs/three-d.md``, "Rest"). Returns (step
    taken, kind fired or -1).
    """
    slack = MARGIN_SLACK * par[P_MASS] * par[P_GRAVITY]
    normal, friction = rest_margins(par, record, dt, t + h, rest, rot, lam, centre)
    if normal >= -slack and friction >= -slack:
        return h, -1
    high, _ = rest_crossing(par, record, dt, t, h, rest, rot, lam, centre, min(normal, friction))
    normal, friction = rest_margins(par, record, dt, t + high, rest, rot, lam, centre)
    return high, FN_NORMAL if normal < 0.0 else FN_FRICTION


@kernel(cache=True, error_model="numpy", _nrt=False)
def rest_crossing(par, record, dt, t, h, rest, rot, lam, centre, g_high):
    """Where in (0, h] a resting margin turns negative, to ``EVENT_TIME`` [s] past it.

    The smaller margin ``g = min(normal, friction)`` (:func:`rest_margins`)
    is negative at h (``g_high``); the bracket [low, high] of its crossing
    of zero is narrowed by Anderson and Bjorck's regula falsi
    (``regula_falsi.narrowed``) until it is ``EVENT_TIME`` wide, and the
    high end returned, as bisection gave it (where g fell below zero before
    the step's start, within the slack, the first trial lies 0.9
    ``EVENT_TIME`` in: below zero there too, that is the end, where
    bisection took some 30 trials to reach the start; else the search goes
    on from it). g is concave over the step: the secant lands short of the
    crossing and the high end's value is scaled down; each trial lies at
    least 0.45 ``EVENT_TIME`` inside the bracket, so that a trial lands
    past a crossing the secant has found; a bisection follows any four
    trials that have not shrunk the bracket to a quarter. The bisection
    alone took some 30 evaluations per rest's end (the benchmark's sliding
    cask ends a rest 30 times in 10 s); the regula falsi takes 2 to 8.
    Returns (the high end [s from t], the trials taken).
    """
    normal, friction = rest_margins(par, record, dt, t, rest, rot, lam, centre)
    g_low = min(normal, friction)
    low, high, side = 0.0, h, 0
    width = h
    trials = 0
    while high - low > EVENT_TIME:
        trials += 1
        bisect = g_low < 0.0 or not g_high < 0.0
        if trials % 4 == 0:
            bisect = bisect or high - low > 0.25 * width
            width = high - low
        if g_low < 0.0 and trials == 1:
            middle = 0.9 * EVENT_TIME  # below zero from the start: is it still, EVENT_TIME in?
        elif bisect:
            middle = 0.5 * (low + high)
        else:
            middle = low + g_low * (high - low) / (g_low - g_high)
            middle = min(max(middle, low + 0.45 * EVENT_TIME), high - 0.45 * EVENT_TIME)
        normal, friction = rest_margins(par, record, dt, t + middle, rest, rot, lam, centre)
        g = min(normal, friction)
        low, high, g_low, g_high, side = narrowed(g < 0.0, middle, g, low, high, g_low, g_high,
                                                  side)  # fmt: skip
    return high, trials


@kernel(cache=True, error_model="numpy", _nrt=False)
def _next_end(t, breaks, h_max, t_end, cursor):
    """End of the next step: at most h_max, never across a break of the record.

    The first break after t (beyond 1e-12 s) is found from the last one's
    index, ``cursor[0]`` (:func:`_first_break_after` at the loop's start),
    moved forwards (or back, were t to move back): t grows from step to
    step, and the search is a step or two where a binary search over the
    record's breaks took a dozen (some 35 ns a step in a compiled loop over
    it: about 0.1 ms of a sliding cask's 2.6 ms under a 10 s record).
    """
    end = min(t + h_max, t_end)
    k = cursor[0]
    count = breaks.shape[0]
    while k < count and breaks[k] <= t + 1e-12:
        k += 1
    while k > 0 and breaks[k - 1] > t + 1e-12:
        k -= 1
    cursor[0] = k
    if k < count and breaks[k] < end:
        end = breaks[k]
    return end


@kernel(cache=True, error_model="numpy", _nrt=False)
def _first_break_after(t, breaks):
    """Index of the first of the ascending ``breaks`` [s] beyond t + 1e-12 s (binary search)."""
    return np.searchsorted(breaks, t + 1e-12, side="right")


@kernel(cache=True, error_model="numpy", _nrt=False)
def _rest(par, record, dt, breaks, h_max, t_end, gap_tol, velocity_tol, t, y, mode, data, sc,
          rest, istate, ev_time, ev_kind, ev_before, ev_after, work, cursor):  # fmt: skip
    """One step of the resting body (:func:`rest_step`) and, where a margin fired, its event.

    Returns t + the step taken; the scratch holds the contact force at it. ``cursor``:
    :func:`_next_end`'s.
    """
    h = _next_end(t, breaks, h_max, t_end, cursor) - t
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
    set_free(mode)
    rotation_matrix(y, sc[SC_ROT])
    after = touched_patch(par, y, sc, gap_tol, velocity_tol, patch)
    istate[I_EVENTS] = _event(t, EV_REMEDY, before, after, istate[I_EVENTS], ev_time, ev_kind,
                              ev_before, ev_after)  # fmt: skip


@kernel(cache=True, error_model="numpy", _nrt=True)
def run(par, record_, dt, breaks, h_max, t_end, record_end, gap_tol, velocity_tol, t, y, mode,
        data, scratch, impulse_work, istate, out_t, out_y, out_mode, out_force, ev_time, ev_kind,
        ev_before, ev_after):  # fmt: skip
    """The loop: advance, locate, resolve, record, from t to t_end.

    ``scratch`` is a one-element array of
    :data:`~freestand.core.contact.body_kernel.SCRATCH_DTYPE`, its record the
    kernel's scratch; ``impulse_work`` one of
    :data:`~freestand.core.contact.body_impulse.IMPULSE_WORK_DTYPE`, its record
    the impulses' work arrays. Both are owned by the caller: a record taken
    from an array the loop allocated itself would point into freed memory, as
    numba frees an array after its last use, not the record's. Returns the
    time reached;
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
    work = impulse_work[0]  # the impulses' work arrays
    fresh = False  # the step's references and event functions at (t, y) are computed
    cursor = np.array([_first_break_after(t, breaks)])  # the next break's index (_next_end)
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
            stretch_start_row(par, y, sc, gap_tol, velocity_tol, istate, force,
                               patch, out_mode, out_force)  # fmt: skip
        istate[I_RECORDS] = 1
        istate[I_EVENTS] = _event(t, EV_START, -1, mode[M_KIND], istate[I_EVENTS], ev_time,
                                  ev_kind, ev_before, ev_after)  # fmt: skip
    while t < t_end - 1e-12:
        if istate[I_RECORDS] >= capacity:
            istate[I_STATUS] = STATUS_BUFFER_FULL
            return t
        if istate[I_STRETCH] >= 1:
            t = stretch_step(par, record_, dt, t, min(STRETCH_STEP, t_end - t), y, mode, data, sc,
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
                      data, sc, rest, istate, ev_time, ev_kind, ev_before, ev_after, work,
                      cursor)  # fmt: skip
            rest_ready = resting(mode, y, velocity_tol)
            record(t, y, mode, sc, istate[I_RECORDS], out_t, out_y, out_mode, out_force)
            if istate[I_STRETCH] == 1:
                stretch_start_row(par, y, sc, gap_tol, velocity_tol, istate, force,
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
            h = min(_next_end(t, breaks, h_max, t_end, cursor) - t, turn_step(y))
            pulled = slow_face_slip(par, record_, dt, t, h, mode, data, sc)
            h = min(h, closing_step(par, y, mode, sc, ref, pulled))
            data[D_FLOOR] = slip_floor(par, mode, sc, h)
            if pulled and start_pulled_slip(record_, dt, t, h, data, sc):
                # a slow flat base's slip driven on, pulled to its rate without friction's
                # direction at each stage: the start solved again
                count = start_functions(par, record_, dt, t, y, mode, data, sc, ref,
                                        velocity_tol, start_values, kinds)  # fmt: skip
            advance(par, record_, dt, t, h, y, mode, data, sc, k, out, velocity_tol)
            h, which, trials = locate(par, record_, dt, t, h, y, mode, data, sc, k, ref,
                                      start_values, count, trial, values, kinds, bracket,
                                      out)  # fmt: skip
            istate[I_TRIALS] += trials
            data[D_PULL] = 0.0
            remedy = may_pass_a_pole(mode) and energy_jump(par, record_, dt, t, h, y, out,
                                                           work_rot, energy)  # fmt: skip
        if remedy:
            _start_remedy(par, t, y, mode, sc, gap_tol, velocity_tol, istate, patch, ev_time,
                          ev_kind, ev_before, ev_after)  # fmt: skip
            solve_at(par, record_, dt, t, y, mode, data, sc)
            istate[I_RECORDS] -= 1  # the row at t, again: the stretch's first
            record(t, y, mode, sc, istate[I_RECORDS], out_t, out_y, out_mode, out_force)
            stretch_start_row(par, y, sc, gap_tol, velocity_tol, istate, force, patch, out_mode,
                               out_force)  # fmt: skip
            istate[I_RECORDS] += 1
            continue
        t += h
        for i in range(STATE_SIZE):
            y[i] = out[i]
        istate[I_STEPS] += 1
        if which < 0 and lean_comes_flat(par, y, mode, sc):
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
            stretch_start_row(par, y, sc, gap_tol, velocity_tol, istate, force,
                               patch, out_mode, out_force)  # fmt: skip
        istate[I_RECORDS] += 1
        if t >= record_end and _post_record_fall(par, y, mode, sc):
            istate[I_EVENTS] = _event(t, EV_OVERTURN, mode[M_KIND], mode[M_KIND], istate[I_EVENTS],
                                      ev_time, ev_kind, ev_before, ev_after)  # fmt: skip
            istate[I_STATUS] = STATUS_OVERTURNED
            return t
    istate[I_STATUS] = STATUS_COMPLETED
    return t
