"""Compiled event-driven time history of a planar stack (the general path's engine).

This module holds the whole loop of :func:`freestand.core.dynamics.timehistory.simulate_general`
in numba: the held-mode dynamics, RK4 steps, event detection and location,
impacts, the choice of the next contact mode, the projection onto the closed
contacts, overturning and the recording of the history. Python is called only
between chunks of simulated time (for a progress report and to grow the
history buffers), never per step.

The physics is the one documented in :mod:`freestand.core.dynamics.timehistory` and
``docs/timehistory.md``; the instantaneous contact problem (at a state, or
at velocity level for an impact) is solved by the one compiled contact kernel
of :mod:`freestand.core.contact.engine` (mode enumeration, admissibility,
static-friction break-away test, relaxation, choice rule and deduplication, on
the Delassus matrix ``W = J M^-1 J^T``), the same that ``screen``, ``map`` and
``sample`` use.

The loop
--------
:func:`run` is a short loop over named phases, each a compiled function that
reads and writes the simulation's :data:`State` (kept by the caller between
calls) and the :data:`Loop` scratch arrays of the call:

- :func:`advance`: one RK4 step of the held contact mode, or a rest segment;
- :func:`locate`: the earliest event of that step, on its interpolant, then
  to the time tolerance on RK4 states;
- :func:`resolve`: at the event, the impact, the next contact mode and the
  projection onto the closed contacts, or the remedy (a stretch of
  velocity-impulse time stepping: :func:`advance_stretch`,
  :func:`resolve_stretch`);
- :func:`record`: the state as a row of the history (events: :func:`_event`).

Functions that allocate nothing are compiled without numba's reference
counting (``_nrt=False``): the arrays they touch are owned by :func:`run` or
its caller for the whole call, and counting the references of every array
taken from a tuple (two atomic operations each) cost more than the
arithmetic of a step. They never allocate (numba refuses to compile that) nor
return an array. The allocating ones (the contact problem at events:
:func:`_settle`; the time stepping; the loop's set-up) keep it.

Codes used by the kernels
-------------------------
sliding (per block)
    0 free, 1 none, 2 no-right, 3 no-left.
tangential state of a mode
    0 free (no contact closed), 1 stick, 2 slide +x, 3 slide -x, 4 kinetic
    (already sliding: kinetic friction against the slip velocity).
event kinds
    :data:`EVENT_KINDS`.
motions
    :data:`MOTION_NAMES`.
"""

from __future__ import annotations

import math
from collections import namedtuple

import numba as nb
import numpy as np

from freestand.core.contact.engine import (  # noqa: F401  (re-exported for the callers' buffers)
    INFO_SIZE,
    MAX_DISTINCT,
    RELATIVE_TOLERANCE,
    accelerations,
    contact_accelerations,
    contact_work,
    delassus,
    held_products,
    solve_contact_problem,
    solve_contact_states,
    solve_in_place,
    solve_states_into,
    solve_symmetric_in_place,
)
from freestand.core.dynamics.time_stepping import (
    UNBOUNDED_FRICTION,
    impulse_step,
    kinetic_energy,
)

#: Event kinds, indexed by the kernel's event codes.
EVENT_KINDS = (
    "start",
    "impact",
    "tangential-impact",
    "lift-off",
    "slip",
    "slip-stop",
    "stop-impact",
    "overturn",
    "time-stepping",
    "resume",
)
START, IMPACT, TANGENTIAL_IMPACT, LIFT_OFF, SLIP, SLIP_STOP, STOP_IMPACT, OVERTURN = range(8)
#: A stretch of velocity-impulse time stepping begins (no consistent event-driven
#: mode: :mod:`freestand.core.dynamics.time_stepping`); events resume.
TIME_STEPPING, RESUME = 8, 9
#: Priority of simultaneous events (lower first): overturn, impact, stop-impact,
#: lift-off, slip, slip-stop.
_PRIORITY = np.array([9, 1, 9, 3, 4, 5, 2, 0, 9, 9], dtype=np.int64)

#: Motions of a block relative to the body below, indexed by the kernel's codes.
MOTION_NAMES = ("rest", "slide", "rock", "slide-rock", "free-flight", "overturned")

#: Kernel outcome codes.
RUNNING, COMPLETED, FAILED, BUFFER_FULL, CHUNK_DONE = range(5)

#: Failure causes (message templates filled by the caller).
FAILURES = (
    "",
    "singular contact mode",
    "impact problem inconsistent",
    "contact problem inconsistent",
    "contact problem inconsistent (also after a tangential impact)",
    "events repeat without progress",
    "more than the allowed number of events",
    "events accumulate in a burst",
)
(
    NO_FAILURE,
    SINGULAR_MODE,
    IMPACT_INCONSISTENT,
    CONTACT_INCONSISTENT,
    CONTACT_INCONSISTENT_AFTER,
    STALLED,
    TOO_MANY_EVENTS,
    BURST,
) = range(8)

#: The stack, made by :func:`freestand.core.dynamics.timehistory.engine_model`:
#: ``geometry`` (B, 7) (:func:`freestand.core.dynamics.timehistory.stack_geometry`),
#: ``masses`` (2, 3 B) rows ``MASS`` and ``INVERSE_MASS`` (the diagonal of M and of
#: M^-1), ``properties`` (6, B) rows ``MU_S``, ``MU_K`` (friction coefficients),
#: ``RESTITUTION`` (factor on the post-impact relative velocity), ``BASE_LEFT``,
#: ``BASE_RIGHT``, ``BASE_LEVEL`` (the base's ends and level [m]), and ``codes`` (B)
#: the sliding codes.
Model = namedtuple("Model", ("geometry", "masses", "properties", "codes"))
MASS, INVERSE_MASS = range(2)
MU_S, MU_K, RESTITUTION, BASE_LEFT, BASE_RIGHT, BASE_LEVEL = range(6)

# --- parameter vector layout (float64) ---------------------------------------------------------
P_GRAVITY, P_TOL_GAP, P_TOL_VEL, P_TOL_SLIDE, P_TIME_TOL = range(5)
P_FORCE_EVENT, P_GAP_EVENT, P_EXC_END, P_END, P_STEP, P_EXC_DT = range(5, 11)
#: 1: stop at the first instant after the excitation's end at which the stack rests
P_UNTIL_REST = 11
#: Time [s] from which the support no longer accelerates (every later sample zero)
P_QUIET = 12
P_SIZE = 13

# --- integer state vector layout (int64) -------------------------------------------------------
S_ACTIVE, S_STATUS, S_FAILURE, S_STEPS, S_CONTACT_SOLVES, S_IMPACT_SOLVES = range(6)
S_AMBIGUOUS, S_ROWS, S_EVENTS, S_STALLED, S_BREAK, S_STARTED = range(6, 12)
#: 1 when the run stopped because the stack was at rest after the excitation (P_UNTIL_REST)
S_AT_REST = 12
#: 1 while a stretch of time stepping runs; its steps; stretches and their steps in all
S_STEPPING, S_STRETCH_STEPS, S_STRETCHES, S_STEPPED = range(13, 17)
#: Impacts whose enumerated state raised the kinetic energy, solved again dissipatively
S_DISSIPATIVE_IMPACTS = 17
#: Stretches begun per cause (indexed by the failure code it replaced: FAILURES)
S_REMEDY = 18
#: Zeno sequences of impacts summed (the impact after which the interface lands: :func:`_land`)
S_ZENO = S_REMEDY + len(FAILURES)
#: Events of the current burst (:func:`_in_burst`); the stretches begun by bursts since the
#: last quiet spell; the least steps of the current stretch (:func:`_stretch_length`)
S_BURST, S_BURST_STRETCHES, S_STRETCH_LENGTH = S_ZENO + 1, S_ZENO + 2, S_ZENO + 3
#: Impacts in a row on a moving support whose next flight stays within the gap tolerance
S_LOW_FLIGHTS = S_ZENO + 4
S_SIZE = S_ZENO + 5

# --- float state vector layout -----------------------------------------------------------------
F_TIME, F_MAX_PENETRATION, F_MAX_PROJECTION = range(3)
#: Time spent time stepping [s]; the largest ratio T(v+)/T(v_f) of a step's impulses
F_STEPPED_TIME, F_ENERGY_RATIO = 3, 4
#: Time [s] of the last event resolved, or of the start or the last resume (:func:`_in_burst`)
F_LAST_EVENT = 5
F_SIZE = 6

# --- history and event buffers (made by the caller, grown between calls) ------------------------
#: ``rec``: ``(time (rows,), values (rows, B, R_SIZE))``, per block the coordinates
#: ``R_Q`` (3), rates ``R_QD`` (3), normal forces ``R_NORMAL`` (2), tangential force,
#: relative rotation and slide.
R_Q, R_QD, R_NORMAL, R_TANGENTIAL, R_ROTATION, R_SLIDE = 0, 3, 6, 8, 9, 10
R_SIZE = 11
#: ``ev``: ``(time (rows,), codes (rows, EV_MOTIONS + B) int, velocities (rows, 2, B, 3))``:
#: kind, interface, contact, status (1: ambiguous), blocks before and after, then each
#: block's motion code; the rates before (``[:, 0]``) and after (``[:, 1]``).
EV_MOTIONS = 6

#: Step of the time stepping remedy [s] (at most the engine's step cap).
STEPPING_STEP = 1e-4
#: Steps of a stretch before events are tried again.
STRETCH_STEPS = 20
#: A burst of events: more than :data:`BURST_EVENTS` events in a row, each within
#: :data:`BURST_INTERVAL` [s] (a stretch's least length) of the one before (or of the
#: resume of events), begins a stretch (:func:`_in_burst`). At the default tolerances a
#: homogeneous block's impacts settling on a rigid base come at most about 36 in a row
#: so close (Housner's ratio against the velocity tolerance, whatever the slenderness;
#: 33 at most over the random-stack sweep, and the end stop's chatter 51, which the
#: stall guard takes first).
BURST_INTERVAL = STRETCH_STEPS * STEPPING_STEP
BURST_EVENTS = 200
#: While the support moves, an interface lands after more than this many impacts in a row
#: whose next flight stays within the gap tolerance (:func:`_settle`). At the default
#: tolerances a homogeneous block settling on a rigid base has at most about 36 such
#: flights in a row (from a flight of 0.1 micrometre to an impact slower than the velocity
#: tolerance, by Housner's ratio, whatever the slenderness).
LOW_FLIGHTS = 100
#: The least length of a burst's stretch doubles with each burst that follows the resume
#: of the one before without a quiet spell, up to this many times (:func:`_stretch_length`)
BURST_DOUBLINGS = 10
#: Relative rise of the kinetic energy [-] an impact's state may show (round-off).
ENERGY_SLACK = 1e-9
#: A Zeno sequence of impacts on a quiet support is summed to its accumulation instant
#: once its next flight rises at most this fraction [-] of the interface's largest lift
#: so far (:func:`_zeno_end`)
ZENO_FRACTION = 1e-3


# --- excitation ---------------------------------------------------------------------------------


@nb.njit(cache=True, inline="always", _nrt=False)
def _support(horizontal, vertical, dt, t):
    """(a_h, a_v) [m/s^2] at ``t`` [s]: linear between samples, zero outside the record."""
    count = horizontal.shape[0]
    position = t / dt
    if position < 0.0 or position > count - 1:
        return 0.0, 0.0
    index = min(int(position), count - 2)
    fraction = position - index
    a_h = (1.0 - fraction) * horizontal[index] + fraction * horizontal[index + 1]
    a_v = (1.0 - fraction) * vertical[index] + fraction * vertical[index + 1]
    return a_h, a_v


# --- kinematics ---------------------------------------------------------------------------------


@nb.njit(cache=True, inline="always", _nrt=False)
def kinematics(geometry, active, q, qd, gap, gap_velocity, slip_velocity, rotation, jn, bn, jt, bt,
               slide=None, first=0):  # fmt: skip
    """Gaps, relative velocities, Jacobians and velocity terms of the first ``active`` blocks.

    Same equations as :func:`freestand.core.dynamics.timehistory.stack_kinematics`
    (``q``, ``qd`` flat, 3 per block; ``jn``, ``jt`` of shape (B, 2, 3 B),
    only the columns of the interface's two blocks are written and the
    others must be zero). With ``slide`` (B,) also the slide of each
    interface's left contact along the lower surface from the lower body's
    material point it started on, ``t . (P_L - X_L)``. Interfaces below
    ``first`` are left as they are.
    """
    for i in range(first, active):
        cxu = geometry[i, 0]
        czu = geometry[i, 1]
        gxu = cxu + q[3 * i]
        gzu = czu + q[3 * i + 1]
        phi_u = q[3 * i + 2]
        vxu = qd[3 * i]
        vzu = qd[3 * i + 1]
        omega_u = qd[3 * i + 2]
        if i == 0:
            gxl = 0.0
            gzl = 0.0
            phi_l = 0.0
            vxl = 0.0
            vzl = 0.0
            omega_l = 0.0
            nx, nz = 0.0, 1.0
            tx, tz = 1.0, 0.0
            spx, spz = 0.0, geometry[i, 6]
        else:
            cxl = geometry[i - 1, 0]
            czl = geometry[i - 1, 1]
            gxl = cxl + q[3 * i - 3]
            gzl = czl + q[3 * i - 2]
            phi_l = q[3 * i - 1]
            vxl = qd[3 * i - 3]
            vzl = qd[3 * i - 2]
            omega_l = qd[3 * i - 1]
            sl = math.sin(phi_l)
            cl = math.cos(phi_l)
            nx, nz = -sl, cl
            tx, tz = cl, sl
            dz = geometry[i, 6] - czl
            spx = gxl - sl * dz
            spz = gzl + cl * dz
        rotation[i] = phi_u - phi_l
        c1u = -2.0 * math.sin(0.5 * phi_u) ** 2
        su = math.sin(phi_u)
        for c in range(2):
            rx = geometry[i, 2 + 2 * c]
            rz = geometry[i, 3 + 2 * c]
            dx = rx - cxu
            dzz = rz - czu
            px = rx + q[3 * i] + c1u * dx - su * dzz
            pz = rz + q[3 * i + 1] + su * dx + c1u * dzz
            aux = px - gxu
            auz = pz - gzu
            pdx = vxu - omega_u * auz
            pdz = vzu + omega_u * aux
            alx = px - gxl
            alz = pz - gzl
            wx = pdx - vxl + omega_l * alz
            wz = pdz - vzl - omega_l * alx
            gap[i, c] = nx * (px - spx) + nz * (pz - spz)
            gap_velocity[i, c] = nx * wx + nz * wz
            slip_velocity[i, c] = tx * wx + tz * wz
            if slide is not None and c == 0:
                if i:
                    cxl = geometry[i - 1, 0]
                    czl = geometry[i - 1, 1]
                    c1l = -2.0 * math.sin(0.5 * phi_l) ** 2
                    sl_ = math.sin(phi_l)
                    ex = rx - cxl
                    ez = rz - czl
                    mx = rx + q[3 * i - 3] + c1l * ex - sl_ * ez
                    mz = rz + q[3 * i - 2] + sl_ * ex + c1l * ez
                else:
                    mx = rx
                    mz = rz
                slide[i] = tx * (px - mx) + tz * (pz - mz)
            relx = pdx - vxl
            relz = pdz - vzl
            for k in range(2):
                if k == 0:
                    d0, d1 = nx, nz
                else:
                    d0, d1 = tx, tz
                jac_u = -d0 * auz + d1 * aux
                bias = (
                    -(omega_u**2) * (d0 * aux + d1 * auz)
                    - omega_l * (-d0 * relz + d1 * relx)
                    + omega_l * (-d1 * wx + d0 * wz)
                )
                if k == 0:
                    jn[i, c, 3 * i] = d0
                    jn[i, c, 3 * i + 1] = d1
                    jn[i, c, 3 * i + 2] = jac_u
                    bn[i, c] = bias
                else:
                    jt[i, c, 3 * i] = d0
                    jt[i, c, 3 * i + 1] = d1
                    jt[i, c, 3 * i + 2] = jac_u
                    bt[i, c] = bias
                if i:
                    jac_l = -(-d0 * alz + d1 * alx)
                    if k == 0:
                        jn[i, c, 3 * i - 3] = -d0
                        jn[i, c, 3 * i - 2] = -d1
                        jn[i, c, 3 * i - 1] = jac_l
                    else:
                        jt[i, c, 3 * i - 3] = -d0
                        jt[i, c, 3 * i - 2] = -d1
                        jt[i, c, 3 * i - 1] = jac_l


# --- the time history ---------------------------------------------------------------------------


#: Work arrays of the kernels (kinematics and the held mode's solve), made by :func:`_work`;
#: a few packed arrays, so that a call passes few arguments:
#:
#: - ``jacobian`` (2, B, 2, 3 B): the gap (``[0]``) and slip (``[1]``) rows of each
#:   interface's left and right contact (only the columns of the interface's two
#:   blocks are written; the others stay zero);
#: - ``contact`` (6, B, 2), rows ``GAP``, ``GAP_VELOCITY``, ``SLIP_VELOCITY``,
#:   ``GAP_BIAS``, ``SLIP_BIAS`` (the velocity terms b_n, b_t) of each contact and
#:   ``FRICTION`` (kinetic coefficient, 0) of each interface in the held mode;
#: - ``blockwise`` (4, B): ``ROTATION`` (relative rotation of each interface) and the
#:   slide rates ``K2S``, ``K3S``, ``K4S`` of the RK4 stages;
#: - ``vectors`` (10, 3 B): ``RHS``, ``COEFF``, ``FREE`` (free accelerations) and the
#:   RK4 stages ``QS``, ``VS``, ``K2A``, ``K3A``, ``K4A``, ``K2V``, ``K3V``;
#: - ``matrices`` (3, 3 B, 3 B): ``MATRIX``, ``ROWS`` (the held mode's equations) and
#:   ``FORCE_G`` (M^-1 G of its unknowns).
Work = namedtuple("Work", ("jacobian", "contact", "blockwise", "vectors", "matrices"))
GAP, GAP_VELOCITY, SLIP_VELOCITY, GAP_BIAS, SLIP_BIAS, FRICTION, IMPACT_LEVEL = range(7)
ROTATION, K2S, K3S, K4S = range(4)
RHS, COEFF, FREE, QS, VS, K2A, K3A, K4A, K2V, K3V = range(10)
MATRIX, ROWS, FORCE_G = range(3)


@nb.njit(cache=True, _nrt=True)
def _work(count):
    """The :data:`Work` arrays for a stack of ``count`` blocks."""
    n = 3 * count
    return Work(
        np.zeros((2, count, 2, n)),
        np.zeros((7, count, 2)),
        np.zeros((4, count)),
        np.zeros((10, n)),
        np.zeros((3, n, n)),
    )


@nb.njit(cache=True, inline="always", _nrt=False)
def _kinematics_into(model, active, q, qd, work, first):
    """:func:`kinematics` of the first ``active`` blocks into ``work``, from interface ``first``."""
    contact = work.contact
    kinematics(
        model.geometry, active, q, qd, contact[GAP], contact[GAP_VELOCITY], contact[SLIP_VELOCITY],
        work.blockwise[ROTATION], work.jacobian[0], contact[GAP_BIAS], work.jacobian[1],
        contact[SLIP_BIAS], None, first,
    )  # fmt: skip


@nb.njit(cache=True, _nrt=False)
def _kin(model, active, q, qd, work):
    """:func:`kinematics` of the first ``active`` blocks into ``work``."""
    _kinematics_into(model, active, q, qd, work, 0)


@nb.njit(cache=True, _nrt=False)
def _free_acceleration(model, active, a_h, a_v, gravity, out):
    for i in range(active):
        out[3 * i] = -a_h
        out[3 * i + 1] = -(gravity - a_v)
        out[3 * i + 2] = 0.0


@nb.njit(cache=True, _nrt=False)
def _evaluate(model, exc, params, active, t, q, qd, mode, work, qdd, lam, first=0):
    """Accelerations and forces of the held mode at a state; kinematics left in ``work``."""
    horizontal, vertical = exc
    a_h, a_v = _support(horizontal, vertical, params[P_EXC_DT], t)
    free = work.vectors[FREE]
    effective_gravity = params[P_GRAVITY] - a_v
    for i in range(active):
        free[3 * i] = -a_h
        free[3 * i + 1] = -effective_gravity
        free[3 * i + 2] = 0.0
    _kinematics_into(model, active, q, qd, work, first)
    return _held_solve(active, model.masses[INVERSE_MASS], work, mode, qdd, lam, first)


@nb.njit(cache=True, inline="always", _nrt=False)
def _reference(mode, i):
    return 1 if (mode[i, 1] == 1 and mode[i, 0] == 0) else 0


@nb.njit(cache=True, _nrt=False)
def _slide_rate(active, mode, slip_velocity, out):
    for i in range(active):
        out[i] = slip_velocity[i, _reference(mode, i)]


@nb.njit(cache=True, _nrt=False)
def _rk4(model, exc, params, active, t, q, qd, slide, h, mode, k1a, k1s, work, out_q, out_qd,
         out_slide, lam, first=0):  # fmt: skip
    """One RK4 step of the held mode from ``t`` over ``h``; False for a singular mode."""
    n = 3 * active
    qs = work.vectors[QS]
    vs = work.vectors[VS]
    k2a = work.vectors[K2A]
    k3a = work.vectors[K3A]
    k4a = work.vectors[K4A]
    k2v = work.vectors[K2V]
    k3v = work.vectors[K3V]
    k2s = work.blockwise[K2S]
    k3s = work.blockwise[K3S]
    k4s = work.blockwise[K4S]
    for c in range(n):
        qs[c] = q[c] + 0.5 * h * qd[c]
        k2v[c] = qd[c] + 0.5 * h * k1a[c]
    if not _evaluate(model, exc, params, active, t + 0.5 * h, qs, k2v, mode, work, k2a, lam, first):
        return False
    _slide_rate(active, mode, work.contact[SLIP_VELOCITY], k2s)
    for c in range(n):
        qs[c] = q[c] + 0.5 * h * k2v[c]
        k3v[c] = qd[c] + 0.5 * h * k2a[c]
    if not _evaluate(model, exc, params, active, t + 0.5 * h, qs, k3v, mode, work, k3a, lam, first):
        return False
    _slide_rate(active, mode, work.contact[SLIP_VELOCITY], k3s)
    for c in range(n):
        qs[c] = q[c] + h * k3v[c]
        vs[c] = qd[c] + h * k3a[c]
    if not _evaluate(model, exc, params, active, t + h, qs, vs, mode, work, k4a, lam, first):
        return False
    _slide_rate(active, mode, work.contact[SLIP_VELOCITY], k4s)
    for c in range(n):
        out_q[c] = q[c] + h / 6.0 * (qd[c] + 2.0 * k2v[c] + 2.0 * k3v[c] + vs[c])
        out_qd[c] = qd[c] + h / 6.0 * (k1a[c] + 2.0 * k2a[c] + 2.0 * k3a[c] + k4a[c])
    for i in range(active):
        out_slide[i] = slide[i] + h / 6.0 * (k1s[i] + 2.0 * k2s[i] + 2.0 * k3s[i] + k4s[i])
    return True


@nb.njit(cache=True, inline="always", _nrt=False)
def _engaged(sliding, slide, tolerance):
    if sliding == 2:
        return slide >= -tolerance
    if sliding == 3:
        return slide <= tolerance
    return True


@nb.njit(cache=True, _nrt=False)
def _fired(model, params, active, mode, directions, lam, slide, work, found):
    """The earliest-priority event that fired at a state (kind, interface, contact) or kind -1.

    ``found`` (4,) int receives it, and the number of event conditions that hold.
    """
    mu_s = model.properties[MU_S]
    sliding_codes = model.codes
    gap = work.contact[GAP]
    gap_velocity = work.contact[GAP_VELOCITY]
    slip_velocity = work.contact[SLIP_VELOCITY]
    rotation = work.blockwise[ROTATION]
    force_event = params[P_FORCE_EVENT]
    level = work.contact[IMPACT_LEVEL]
    tol_slide = params[P_TOL_SLIDE]
    tol_vel = params[P_TOL_VEL]
    best = 100
    fired = 0
    found[0] = -1
    found[1] = -1
    found[2] = -1
    for i in range(active):
        for c in range(2):
            if mode[i, c] == 1 and lam[i, c] < -force_event:
                fired += 1
                if _PRIORITY[LIFT_OFF] < best:
                    best = _PRIORITY[LIFT_OFF]
                    found[0], found[1], found[2] = LIFT_OFF, i, c
            if mode[i, c] == 0 and gap[i, c] < level[i, c] and gap_velocity[i, c] < 0.0:
                fired += 1
                if _PRIORITY[IMPACT] < best:
                    best = _PRIORITY[IMPACT]
                    found[0], found[1], found[2] = IMPACT, i, c
        sliding = sliding_codes[i]
        if (sliding == 2 or sliding == 3) and not _engaged(sliding, slide[i], tol_slide):
            sliding = 0
        if mode[i, 2] == 1 and sliding != 1:
            limit = mu_s[i] * (lam[i, 0] + lam[i, 1]) + force_event
            tangential = lam[i, 2]
            if (sliding != 2 and -tangential > limit) or (sliding != 3 and tangential > limit):
                fired += 1
                if _PRIORITY[SLIP] < best:
                    best = _PRIORITY[SLIP]
                    found[0], found[1], found[2] = SLIP, i, -1
        reference = _reference(mode, i)
        slip = slip_velocity[i, reference]
        if directions[i] != 0 and directions[i] * slip < -1e-3 * tol_vel:
            fired += 1
            if _PRIORITY[SLIP_STOP] < best:
                best = _PRIORITY[SLIP_STOP]
                found[0], found[1], found[2] = SLIP_STOP, i, -1
        code = sliding_codes[i]
        if (code == 2 and slide[i] > tol_slide and slip > tol_vel) or (
            code == 3 and slide[i] < -tol_slide and slip < -tol_vel
        ):
            fired += 1
            if _PRIORITY[STOP_IMPACT] < best:
                best = _PRIORITY[STOP_IMPACT]
                found[0], found[1], found[2] = STOP_IMPACT, i, -1
        if abs(rotation[i]) >= 0.5 * math.pi:
            fired += 1
            if _PRIORITY[OVERTURN] < best:
                best = _PRIORITY[OVERTURN]
                found[0], found[1], found[2] = OVERTURN, i, -1
    found[3] = fired
    return found[0] >= 0


@nb.njit(cache=True, _nrt=True)
def _least_squares(rows, m, n, inverse_mass, values, out):
    """``out[:m]``: the least-squares solution of ``(J M^-1 J^T) x = values`` (rank-deficient)."""
    jac = rows[:m, :n].copy()
    weighted = jac * inverse_mass[:n]
    solution = np.linalg.lstsq(weighted @ jac.T, values[:m].copy())[0]
    for r in range(m):
        out[r] = solution[r]


@nb.njit(cache=True, _nrt=False)
def _min_norm_correction(rows, m, n, inverse_mass, values, system, rhs, out):
    """``out = M^-1 J^T (J M^-1 J^T)^-1 values``: the smallest correction in the mass metric.

    Gaussian elimination with partial pivoting on the small symmetric system;
    a rank-deficient system (redundant rows) falls back to least squares.
    """
    for r in range(m):
        rhs[r] = values[r]
        for s in range(r, m):
            total = 0.0
            for col in range(n):
                total += rows[r, col] * inverse_mass[col] * rows[s, col]
            system[r, s] = total
            system[s, r] = total
    scale = 0.0
    for r in range(m):
        scale = max(scale, abs(system[r, r]))
    singular = False
    for p in range(m):
        pivot = p
        largest = abs(system[p, p])
        for r in range(p + 1, m):
            if abs(system[r, p]) > largest:
                largest = abs(system[r, p])
                pivot = r
        if largest <= 1e-12 * scale:
            singular = True
            break
        if pivot != p:
            for j in range(m):
                tmp = system[p, j]
                system[p, j] = system[pivot, j]
                system[pivot, j] = tmp
            tmp = rhs[p]
            rhs[p] = rhs[pivot]
            rhs[pivot] = tmp
        for r in range(p + 1, m):
            factor = system[r, p] / system[p, p]
            if factor != 0.0:
                for j in range(p + 1, m):
                    system[r, j] -= factor * system[p, j]
                rhs[r] -= factor * rhs[p]
    if singular:
        _least_squares(rows, m, n, inverse_mass, values, rhs)
    else:
        for p in range(m - 1, -1, -1):
            total = rhs[p]
            for j in range(p + 1, m):
                total -= system[p, j] * rhs[j]
            rhs[p] = total / system[p, p]
    for col in range(n):
        total = 0.0
        for r in range(m):
            total += rows[r, col] * rhs[r]
        out[col] = inverse_mass[col] * total


@nb.njit(cache=True, _nrt=False)
def _project(model, active, q, qd, mode, work, fstate):
    """Put the closed contacts back on their surfaces (positions, then velocities).

    Gauss-Newton in the mass metric (three iterations at most), then the
    velocities projected onto the closed normals and the sticking tangents.
    """
    n = 3 * active
    inverse_mass = model.masses[INVERSE_MASS]
    rows = work.matrices[ROWS]
    values = work.vectors[RHS]
    system = work.matrices[MATRIX]
    rhs = work.vectors[COEFF]
    correction = work.vectors[FREE]
    for _ in range(3):
        _kin(model, active, q, qd, work)
        m = 0
        largest = 0.0
        for i in range(active):
            for c in range(2):
                if mode[i, c] == 1:
                    for col in range(n):
                        rows[m, col] = work.jacobian[0][i, c, col]
                    values[m] = work.contact[GAP][i, c]
                    if -values[m] > fstate[F_MAX_PENETRATION]:
                        fstate[F_MAX_PENETRATION] = -values[m]
                    largest = max(largest, abs(values[m]))
                    m += 1
        if m == 0:
            return
        if largest <= 1e-14:
            break
        _min_norm_correction(rows, m, n, inverse_mass, values, system, rhs, correction)
        for col in range(n):
            if abs(correction[col]) > fstate[F_MAX_PROJECTION]:
                fstate[F_MAX_PROJECTION] = abs(correction[col])
            q[col] -= correction[col]
    _kin(model, active, q, qd, work)
    m = 0
    for i in range(active):
        for c in range(2):
            if mode[i, c] == 1:
                for col in range(n):
                    rows[m, col] = work.jacobian[0][i, c, col]
                m += 1
        if mode[i, 2] == 1 and mode[i, 0] + mode[i, 1] > 0:
            reference = _reference(mode, i)
            for col in range(n):
                rows[m, col] = work.jacobian[1][i, reference, col]
            m += 1
    if m == 0:
        return
    for r in range(m):
        total = 0.0
        for col in range(n):
            total += rows[r, col] * qd[col]
        values[r] = total
    _min_norm_correction(rows, m, n, inverse_mass, values, system, rhs, correction)
    for col in range(n):
        qd[col] -= correction[col]


@nb.njit(cache=True, _nrt=False)
def _lower_contact(gap, i):
    return 0 if gap[i, 0] <= gap[i, 1] else 1


@nb.njit(cache=True, _nrt=False)
def _needs_impact(model, params, active, slide, work):
    sliding_codes = model.codes
    gap = work.contact[GAP]
    gap_velocity = work.contact[GAP_VELOCITY]
    slip_velocity = work.contact[SLIP_VELOCITY]
    tol_gap = params[P_TOL_GAP]
    tol_vel = params[P_TOL_VEL]
    level = work.contact[IMPACT_LEVEL]  # the step's (_arm_impacts): zero or minus the slack
    for i in range(active):
        for c in range(2):
            approach = gap_velocity[i, c]
            if gap[i, c] <= tol_gap and approach < -tol_vel:
                return True
            if gap[i, c] < level[i, c] and approach < 0.0:
                return True
        code = sliding_codes[i]
        engaged = _engaged(code, slide[i], params[P_TOL_SLIDE])
        slip = slip_velocity[i, _lower_contact(gap, i)]
        if engaged and ((code == 2 and slip > tol_vel) or (code == 3 and slip < -tol_vel)):
            if min(gap[i, 0], gap[i, 1]) <= tol_gap:
                return True
    return False


@nb.njit(cache=True, _nrt=False)
def _into_stop(model, params, active, slide, work):
    """Whether a block at its engaged end stop still slides into it (kinematics in work)."""
    sliding_codes = model.codes
    tol_vel = params[P_TOL_VEL]
    for i in range(active):
        code = sliding_codes[i]
        if not (code == 2 or code == 3):
            continue
        if not _engaged(code, slide[i], params[P_TOL_SLIDE]):
            continue
        slip = work.contact[SLIP_VELOCITY][i, _lower_contact(work.contact[GAP], i)]
        if (code == 2 and slip > tol_vel) or (code == 3 and slip < -tol_vel):
            return True
    return False


@nb.njit(cache=True, _nrt=False)
def _impact(model, params, active, q, qd, slide, allow_stick, work, problem, istate, out_qd):
    """Velocity jump of an impact (the contact problem at velocity level); count or 0.

    Returns the number of distinct admissible states (0: inconsistent). The
    post-impact velocity is written to ``out_qd``; then each interface that
    received an impulse has the velocity of its upper block relative to the
    body below multiplied by its restitution factor (1: the plastic law).
    ``problem``: the :data:`Problem` work arrays.

    A contact sliding before the impact first takes the kinetic impulse
    against its slip (:func:`_impact_jump`). Coulomb's law at velocity level
    (Moreau 1988) admits that impulse only where the slip after keeps its
    direction or stops: where it reversed (:func:`_slip_reversed`), the
    friction would have acted along the slip after it, and the impact is
    solved again with the sliding contacts free to stick (static cone) or
    to slide either way, as the 3-D engine's impact law does
    (:func:`freestand.core.contact.body_modes.impact`). A block landing from
    free flight on one corner with a fast slip took the kinetic impulse and
    came out rocking 27 % faster with its corner slipping backwards, where
    the sticking impulse needed 0.66 of its normal one, inside mu = 0.72.
    """
    count, chosen, coulomb, force_tol = _impact_jump(
        model, params, active, q, qd, slide, allow_stick, work, problem, istate, out_qd
    )
    if count > 0 and not allow_stick and not coulomb:
        if _slip_reversed(model, params, active, q, out_qd, work, problem, chosen):
            count, chosen, coulomb, force_tol = _impact_jump(
                model, params, active, q, qd, slide, True, work, problem, istate, out_qd
            )
            if count == 0:
                # none with sticking either (not seen): the kinetic impulse, as before
                count, chosen, coulomb, force_tol = _impact_jump(
                    model, params, active, q, qd, slide, False, work, problem, istate, out_qd
                )
    if count == 0:
        return 0
    _restitute(model, active, problem.forces[chosen], force_tol, out_qd)
    return count


@nb.njit(cache=True, _nrt=False)
def _slip_reversed(model, params, active, q, out_qd, work, problem, chosen):
    """Whether an impact's kinetic impulse reversed a slip (:func:`_impact`).

    The interfaces that slid before the impact (``problem.blockwise[P_SLIP]``
    non-zero) and stay closed in the chosen state: their slip after, at the
    same contact, against the slip before by more than the velocity tolerance.
    """
    slip = problem.blockwise[P_SLIP]
    modes = problem.modes
    _kin(model, active, q, out_qd, work)  # the gaps are the position's, as before
    for i in range(active):
        if slip[i] == 0.0 or modes[chosen, i, 0] + modes[chosen, i, 1] == 0:
            continue
        after = work.contact[SLIP_VELOCITY][i, _lower_contact(work.contact[GAP], i)]
        if after * slip[i] < 0.0 and abs(after) > params[P_TOL_VEL]:
            return True
    return False


@nb.njit(cache=True, _nrt=False)
def _impact_jump(model, params, active, q, qd, slide, allow_stick, work, problem, istate,
                 out_qd):  # fmt: skip
    """The plastic velocity jump of :func:`_impact` into ``out_qd``, before restitution.

    Returns (count of distinct admissible states, the one chosen, whether the
    dissipative solver of the time stepping gave it: Coulomb's law at
    velocity level already, the force tolerance [N s]).
    """
    n = 3 * active
    mass = model.masses[MASS]
    sliding_codes = model.codes
    _kin(model, active, q, qd, work)
    gap = work.contact[GAP]
    jn = work.jacobian[0]
    jt = work.jacobian[1]
    tol_gap = params[P_TOL_GAP]
    tol_vel = params[P_TOL_VEL]
    bn = problem.terms[0]
    bt = problem.terms[1]
    speed = tol_vel
    for i in range(active):
        for c in range(2):
            vn = 0.0
            vt = 0.0
            for col in range(n):
                vn += jn[i, c, col] * qd[col]
                vt += jt[i, c, col] * qd[col]
            bn[i, c] = vn
            bt[i, c] = vt
            speed = max(speed, abs(vn), abs(vt))
    contact_active = problem.contact_active
    slip = problem.blockwise[P_SLIP]
    sliding = problem.sliding
    total_mass = 0.0
    for i in range(active):
        total_mass += mass[3 * i]
        contact_active[i, 0] = gap[i, 0] <= tol_gap
        contact_active[i, 1] = gap[i, 1] <= tol_gap
        code = sliding_codes[i]
        engaged = _engaged(code, slide[i], params[P_TOL_SLIDE])
        effective = code
        if (code == 2 or code == 3) and not engaged:
            effective = 0
        sliding[i] = effective
        s = work.contact[SLIP_VELOCITY][i, _lower_contact(gap, i)]
        direction = 1 if s > 0.0 else (-1 if s < 0.0 else 0)
        allows = (
            effective == 0
            or (effective == 2 and direction < 0)
            or (effective == 3 and direction > 0)
        )
        if allow_stick or abs(s) <= tol_vel or not allows:
            s = 0.0
        slip[i] = s
    zero = problem.vectors[P_FREE]
    for c in range(n):
        zero[c] = 0.0
    tiny = np.finfo(np.float64).tiny
    force_tol = RELATIVE_TOLERANCE * max(total_mass * speed, tiny)
    accel_tol = RELATIVE_TOLERANCE * max(speed, tiny)
    count = _solve_problem(model, active, zero, bn, bt, work, problem, force_tol, accel_tol)
    jumps = problem.solutions
    impulses = problem.forces
    istate[S_IMPACT_SOLVES] += 1
    if count == 0:
        return 0, 0, False, force_tol
    if count > 1:
        istate[S_AMBIGUOUS] += 1
    chosen = 0
    for k in range(min(count, MAX_DISTINCT)):
        for c in range(n):
            out_qd[c] = qd[c] + jumps[k, c]
        _kin(model, active, q, out_qd, work)
        if not _into_stop(model, params, active, slide, work):
            chosen = k
            break
    for c in range(n):
        out_qd[c] = qd[c] + jumps[chosen, c]
    inverse_mass = model.masses[INVERSE_MASS]
    if kinetic_energy(inverse_mass, out_qd, n) > (1.0 + ENERGY_SLACK) * kinetic_energy(
        inverse_mass, qd, n
    ):
        # the enumerated state's kinetic friction (against the slip before the impact)
        # did positive work: the velocity-level problem by the dissipative solver of the
        # time stepping instead (Coulomb at velocity level, T(v+) <= T(v-))
        _kin(model, active, q, qd, work)
        low = problem.blockwise[P_LOW]
        high = problem.blockwise[P_HIGH]
        _friction_bounds(model, params, active, slide, work, low, high)
        normal = problem.impulses[0]
        tangential = problem.impulses[1]
        _copy(out_qd, qd, n)
        impulse_step(active, inverse_mass, jn, jt, contact_active, low, high, out_qd, normal,
                     tangential)  # fmt: skip
        istate[S_DISSIPATIVE_IMPACTS] += 1
        for i in range(active):
            impulses[chosen, i, 0] = normal[i, 0]
            impulses[chosen, i, 1] = normal[i, 1]
        return count, chosen, True, force_tol
    return count, chosen, False, force_tol


@nb.njit(cache=True, _nrt=False)
def _restitute(model, active, impulses, force_tol, out_qd):
    """Each interface that received an impulse (``impulses`` (B, 3) [N s]): the velocity of
    its upper block relative to the body below times its restitution factor (1: plastic)."""
    restitution = model.properties[RESTITUTION]
    for i in range(active):
        factor = restitution[i]
        if factor == 1.0:
            continue
        impulse = abs(impulses[i, 0]) + abs(impulses[i, 1])
        if impulse <= force_tol:
            continue
        for c in range(3):
            lower = out_qd[3 * i - 3 + c] if i else 0.0
            out_qd[3 * i + c] = lower + factor * (out_qd[3 * i + c] - lower)


@nb.njit(cache=True, _nrt=False)
def _solve_problem(model, active, free, bn, bt, work, problem, force_tol, accel_tol):
    """The contact kernel on the problem set up in ``problem`` (:data:`Problem`).

    Free accelerations ``free``, velocity terms ``bn``, ``bt`` and the
    kinematics in ``work``; the first :data:`MAX_DISTINCT` admissible states go
    to ``problem.modes``, ``solutions``, ``forces``. Returns their count.
    """
    arguments = (
        active, model.masses[INVERSE_MASS], free, work.jacobian[0], bn, work.jacobian[1], bt,
        problem.contact_active, problem.blockwise[P_SLIP], problem.sliding,
        model.properties[MU_S], model.properties[MU_K], force_tol, accel_tol, problem.modes,
        problem.solutions, problem.forces, problem.accelerations, problem.index, problem.info,
    )  # fmt: skip
    count = solve_states_into(problem.contact, *arguments)
    if count < 0:
        # more admissible modes than the work arrays hold: the kernel's own arrays
        count = solve_contact_states(*arguments)
    return count


@nb.njit(cache=True, _nrt=False)
def _select(model, exc, params, active, t, q, qd, slide, work, problem, istate, mode,
            directions):  # fmt: skip
    """Solve the contact problem at a state and set the mode to hold; count (0: none).

    ``problem``: the :data:`Problem` work arrays.
    """
    mass = model.masses[MASS]
    sliding_codes = model.codes
    a_h, a_v = _support(exc[0], exc[1], params[P_EXC_DT], t)
    gravity = params[P_GRAVITY]
    _kin(model, active, q, qd, work)
    gap = work.contact[GAP]
    tol_gap = params[P_TOL_GAP]
    tol_vel = params[P_TOL_VEL]
    contact_active = problem.contact_active
    slip = problem.blockwise[P_SLIP]
    sliding = problem.sliding
    total_mass = 0.0
    for i in range(active):
        total_mass += mass[3 * i]
        for c in range(2):
            closing = work.contact[GAP_VELOCITY][i, c]
            contact_active[i, c] = gap[i, c] <= tol_gap and closing <= tol_vel
        code = sliding_codes[i]
        s = work.contact[SLIP_VELOCITY][i, _lower_contact(gap, i)]
        if abs(s) <= tol_vel or code == 1:
            s = 0.0
        slip[i] = s
        engaged = _engaged(code, slide[i], params[P_TOL_SLIDE])
        sliding[i] = 0 if ((code == 2 or code == 3) and not engaged) else code
    free = problem.vectors[P_FREE]
    _free_acceleration(model, active, a_h, a_v, gravity, free)
    scale = max(math.hypot(a_h, gravity - a_v), 1e-12)
    tiny = np.finfo(np.float64).tiny
    force_tol = RELATIVE_TOLERANCE * max(total_mass * scale, tiny)
    accel_tol = RELATIVE_TOLERANCE * max(scale, tiny)
    count = _solve_problem(model, active, free, work.contact[GAP_BIAS], work.contact[SLIP_BIAS],
                           work, problem, force_tol, accel_tol)  # fmt: skip
    modes = problem.modes
    istate[S_CONTACT_SOLVES] += 1
    if count == 0:
        return 0
    if count > 1:
        istate[S_AMBIGUOUS] += 1
    for i in range(active):
        mode[i, 0] = modes[0, i, 0]
        mode[i, 1] = modes[0, i, 1]
        tangential = modes[0, i, 2]
        if tangential == 4:
            tangential = 2 if slip[i] > 0.0 else 3
        mode[i, 2] = tangential
        directions[i] = 1 if tangential == 2 else (-1 if tangential == 3 else 0)
    return count


@nb.njit(cache=True, _nrt=False)
def _low_flight(params, mode, work, problem, i):
    """The open contact of rocking interface ``i`` whose next flight stays within the gap
    tolerance, or -1.

    After an impact, in the chosen state (``problem``: contact accelerations of
    the first state; kinematics in ``work``), a contact of a rocking interface
    (one contact closed) that touches (gap <= tolerance) and opens at ``v > 0``
    while its gap accelerates back at ``a < 0`` rises by ``v^2 / (2 |a|)``:
    when that is within the gap tolerance the flight, and every later one of
    the Zeno sequence it starts (each lower than the last), is below the
    engine's resolution of a gap.
    """
    if mode[i, 0] + mode[i, 1] != 1:
        return -1
    tol_gap = params[P_TOL_GAP]
    c = 1 if mode[i, 0] == 1 else 0
    opening = work.contact[GAP_VELOCITY][i, c]
    falling = problem.accelerations[0, i, c]
    if work.contact[GAP][i, c] <= tol_gap and opening > 0.0 and falling < 0.0:
        if opening * opening <= -2.0 * falling * tol_gap:
            return c
    return -1


@nb.njit(cache=True, _nrt=False)
def _low_flights(params, active, mode, work, problem):
    """Whether an interface's next flight stays within the gap tolerance (:func:`_low_flight`)."""
    for i in range(active):
        if _low_flight(params, mode, work, problem, i) >= 0:
            return True
    return False


@nb.njit(cache=True, _nrt=False)
def _land(params, active, mode, work, problem):
    """Close the contacts whose next flight stays within the gap tolerance; whether any.

    See :func:`_low_flight`; ``mode`` gets the contacts closed.
    """
    landed = False
    for i in range(active):
        c = _low_flight(params, mode, work, problem, i)
        if c >= 0:
            mode[i, c] = 1
            landed = True
    return landed


@nb.njit(cache=True, _nrt=False)
def _moves_as_one(work, active, rocking, pivot, tolerance):
    """Whether the stack moves as one body rocking on ``pivot`` of interface ``rocking``.

    Every other interface's contacts neither open, close nor slip, and the
    pivot does not slip (relative velocities within ``tolerance`` [m/s];
    kinematics in ``work``).
    """
    gap_velocity = work.contact[GAP_VELOCITY]
    slip_velocity = work.contact[SLIP_VELOCITY]
    for j in range(active):
        for c in range(2):
            if j == rocking and c != pivot:
                continue
            if abs(slip_velocity[j, c]) > tolerance:
                return False
            if j != rocking and abs(gap_velocity[j, c]) > tolerance:
                return False
    return True


@nb.njit(cache=True, _nrt=False)
def _zeno_end(model, exc, params, active, t, q, qd, slide, work, problem, istate, mode,
              lift_peak):  # fmt: skip
    """Accumulation instant [s] of the Zeno sequence an impact starts, or -1 if not summed.

    After an impact on a quiet support (``P_QUIET``), in the chosen state (``mode``;
    contact accelerations of the first state in ``problem``, kinematics in ``work``):
    when every interface sticks, all but one closed on both contacts, and the one
    that rocks opens its contact ``c`` at ``v_1 > 0`` against a gap acceleration
    ``a_1 < 0`` so slowly that the flight rises ``v_1^2 / (2 |a_1|)`` at most
    :data:`ZENO_FRACTION` of the interface's largest lift so far (or the gap
    tolerance), the stack rocks as one rigid body by angles small against its
    slenderness: each flight returns to the flat configuration with the rates
    reversed (one degree of freedom, no loss in flight) after ``2 v / |a|``
    (constant restoring moment: Brogliato 2016, section 1.3.2), and every impact
    is the same linear map of the rates. Two impacts of the reversed rates give
    the other contact's flight (``v_2``, ``a_2``) and the ratio ``rho = v_3 / v_1``
    over a pair of flights (after each, the stack must still move as one body:
    :func:`_moves_as_one`), and the sequence ends at

        t_inf = t + (2 v_1 / |a_1| + 2 v_2 / |a_2|) / (1 - rho)

    (Housner 1963's ``eta^2 = rho`` for one block). The neglected rocking is at
    most :data:`ZENO_FRACTION` of the largest lift, and the constant restoring
    moment errs by about the amplitude over the slenderness (a few 1e-4 of the
    remaining time). ``mode`` gets the contact closed when summed. Either way
    the kinematics in ``work`` and the open contact's acceleration that
    :func:`_land` reads are restored; the trial impacts overwrite the rest of
    ``problem``. Not summed past the run's end.
    """
    tol_gap = params[P_TOL_GAP]
    rocking = -1
    for i in range(active):
        if mode[i, 2] != 1:
            return -1.0
        closed = mode[i, 0] + mode[i, 1]
        if closed == 1 and rocking < 0:
            rocking = i
        elif closed != 2:
            return -1.0
    if rocking < 0:
        return -1.0
    i = rocking
    c = 1 if mode[i, 0] == 1 else 0
    other = 1 - c
    gap = work.contact[GAP]
    gap_velocity = work.contact[GAP_VELOCITY]
    v1 = gap_velocity[i, c]
    a1 = problem.accelerations[0, i, c]
    if not (gap[i, c] <= tol_gap and v1 > 0.0 and a1 < 0.0):
        return -1.0
    if v1 * v1 > -2.0 * a1 * max(tol_gap, ZENO_FRACTION * lift_peak[i]):
        return -1.0
    n = 3 * active
    reversed_ = problem.vectors[P_REVERSED]
    second = problem.vectors[P_SECOND]
    third = problem.vectors[P_THIRD]
    qdd = problem.vectors[P_ZENO_QDD]
    lam = problem.forces[MAX_DISTINCT - 1]
    end = -1.0
    for k in range(n):
        reversed_[k] = -qd[k]
    tol_vel = params[P_TOL_VEL]
    if _impact(model, params, active, q, reversed_, slide, False, work, problem, istate, second):
        # the other contact's flight: rocking on contact c, the held mode swapped
        _kin(model, active, q, second, work)
        v2 = gap_velocity[i, other]
        held = v2 > 0.0 and _moves_as_one(work, active, i, c, tol_vel)
        a2 = 0.0
        if held:
            mode[i, c] = 1
            mode[i, other] = 0
            held = _evaluate(model, exc, params, active, t, q, second, mode, work, qdd, lam)
            mode[i, c] = 0
            mode[i, other] = 1
            a2 = work.contact[GAP_BIAS][i, other]
            for k in range(n):
                a2 += work.jacobian[0][i, other, k] * qdd[k]
                reversed_[k] = -second[k]
        if (
            held
            and a2 < 0.0
            and _impact(
                model, params, active, q, reversed_, slide, False, work, problem, istate, third
            )
        ):
            _kin(model, active, q, third, work)
            ratio = gap_velocity[i, c] / v1
            if 0.0 < ratio < 1.0 and _moves_as_one(work, active, i, other, tol_vel):
                end = t + (-2.0 * v1 / a1 - 2.0 * v2 / a2) / (1.0 - ratio)
    _kin(model, active, q, qd, work)
    problem.accelerations[0, i, c] = a1
    if not (end >= t and end <= params[P_END]):
        return -1.0
    mode[i, c] = 1
    return end


@nb.njit(cache=True, _nrt=False)
def _settle(model, exc, params, active, t, q, qd, slide, work, problem, istate, fstate, mode,
            directions, flags, sum_to_end, result):  # fmt: skip
    """Impact if needed, then the mode to hold, then the projection.

    ``result`` (3,) int: [failure code, impact kind (0 none, IMPACT,
    TANGENTIAL_IMPACT), solve count of the selection]; ``problem``: the
    :data:`Problem` work arrays; ``flags``: the state's flags (uplift and free
    flight raised here, the largest lifts read). With ``sum_to_end`` a Zeno
    sequence that :func:`_zeno_end` can sum moves the state's time to its
    accumulation instant.

    After an impact once the support no longer accelerates (``P_QUIET``), an
    interface whose contact opens so slowly that it cannot rise beyond the gap
    tolerance before it falls back (:func:`_land`) starts a Zeno sequence of
    ever smaller impacts converging on rest: the sequence is summed, the
    contact closed (:func:`_project`: onto both contacts, the relative velocity
    removed in the mass metric, which never raises the kinetic energy) and the
    mode chosen again. While the support moves, the impacts whose next flight
    stays within the gap tolerance are counted in a row (``S_LOW_FLIGHTS``;
    any other impact ends the row), and after more than :data:`LOW_FLIGHTS`
    of them the interface lands in the same way (not summed).
    """
    result[0] = NO_FAILURE
    result[1] = 0
    result[2] = 0
    n = 3 * active
    new_qd = problem.vectors[P_NEW_QD]
    _kin(model, active, q, qd, work)
    if _needs_impact(model, params, active, slide, work):
        if _impact(model, params, active, q, qd, slide, False, work, problem, istate, new_qd) == 0:
            result[0] = IMPACT_INCONSISTENT
            return
        _copy(qd, new_qd, n)
        result[1] = IMPACT
    count = _select(
        model, exc, params, active, t, q, qd, slide, work, problem, istate, mode, directions
    )
    quiet = t >= params[P_QUIET]
    if count > 0 and result[1] == IMPACT and not quiet:
        if _low_flights(params, active, mode, work, problem):
            istate[S_LOW_FLIGHTS] += 1
        else:
            istate[S_LOW_FLIGHTS] = 0
    if count > 0 and result[1] == IMPACT and (quiet or istate[S_LOW_FLIGHTS] > LOW_FLIGHTS):
        end = -1.0
        if sum_to_end and quiet:
            end = _zeno_end(model, exc, params, active, t, q, qd, slide, work, problem, istate,
                            mode, flags[4])  # fmt: skip
        if end >= 0.0 or _land(params, active, mode, work, problem):
            # the rest of a Zeno sequence of impacts, summed: the interfaces land (at
            # the sequence's accumulation instant when it is known)
            _project(model, active, q, qd, mode, work, fstate)
            istate[S_ZENO] += 1
            count = _select(model, exc, params, active, t, q, qd, slide, work, problem, istate,
                            mode, directions)  # fmt: skip
            if end > t:
                fstate[F_TIME] = end
    if count == 0:
        # no consistent sliding state (Painleve-type): a tangential impact at
        # velocity level, in which the sliding contacts may stick
        if _impact(model, params, active, q, qd, slide, True, work, problem, istate, new_qd) == 0:
            result[0] = CONTACT_INCONSISTENT
            return
        _copy(qd, new_qd, n)
        result[1] = TANGENTIAL_IMPACT
        count = _select(
            model, exc, params, active, t, q, qd, slide, work, problem, istate, mode, directions
        )
        if count == 0:
            result[0] = CONTACT_INCONSISTENT_AFTER
            return
    result[2] = count
    _project(model, active, q, qd, mode, work, fstate)
    for i in range(active):
        closed = mode[i, 0] + mode[i, 1]
        if closed < 2:
            flags[0, i] = 1.0
        if closed == 0 and i > 0:
            flags[1, i] = 1.0


@nb.njit(cache=True, _nrt=False)
def _motion_code(mode, i):
    closed = mode[i, 0] + mode[i, 1]
    sliding = mode[i, 2] >= 2
    if closed == 2:
        return 1 if sliding else 0
    if closed == 1:
        return 3 if sliding else 2
    return 4


@nb.njit(cache=True, _nrt=False)
def _overturned_after(model, params, active, qd, work):
    """Lowest block past its overturning angle that cannot come back (-1 if none)."""
    geometry = model.geometry
    mass = model.masses[MASS]
    properties = model.properties
    gravity = params[P_GRAVITY]
    for i in range(active):
        rotation = work.blockwise[ROTATION][i]
        omega = qd[3 * i + 2] - (qd[3 * i - 1] if i else 0.0)
        height = geometry[i, 1] - properties[BASE_LEVEL, i]
        if rotation > 0.0:
            lever = geometry[i, 0] - properties[BASE_LEFT, i]
            away = omega >= 0.0
        else:
            lever = properties[BASE_RIGHT, i] - geometry[i, 0]
            away = omega <= 0.0
        critical = math.atan2(lever, height)
        if abs(rotation) <= critical:
            continue
        radius = math.hypot(lever, height)
        inertia = 1.0 / model.masses[INVERSE_MASS][3 * i + 2] + mass[3 * i] * radius**2
        barrier = mass[3 * i] * gravity * radius * (1.0 - math.cos(abs(rotation) - critical))
        if away or 0.5 * inertia * omega**2 < barrier:
            return i
    return -1


@nb.njit(cache=True, _nrt=False)
def _event(t, kind, interface, contact, status, active_before, active_after, mode, qd_before,
           qd_after, count, ev, istate):  # fmt: skip
    """Append an event; motions of the first ``active_after`` blocks from ``mode``."""
    e = istate[S_EVENTS]
    ev_time, ev_code, ev_velocity = ev
    ev_time[e] = t
    ev_code[e, 0] = kind
    ev_code[e, 1] = interface
    ev_code[e, 2] = contact
    ev_code[e, 3] = status
    ev_code[e, 4] = active_before
    ev_code[e, 5] = active_after
    for i in range(count):
        ev_code[e, EV_MOTIONS + i] = _motion_code(mode, i) if i < active_after else 5
        for c in range(3):
            ev_velocity[e, 0, i, c] = qd_before[3 * i + c] if i < active_before else np.nan
            ev_velocity[e, 1, i, c] = qd_after[3 * i + c] if i < active_after else np.nan
    istate[S_EVENTS] = e + 1


@nb.njit(cache=True, _nrt=False)
def _next_end(t, params, breaks, istate, h_cap):
    """End of the next step: the next break point after ``t``, or ``t + h_cap``, or the end."""
    end = params[P_END]
    k = istate[S_BREAK]
    while k < breaks.shape[0] and breaks[k] <= t + 1e-6 * h_cap:
        k += 1
    istate[S_BREAK] = k
    target = t + h_cap
    if k < breaks.shape[0] and breaks[k] < target:
        target = breaks[k]
    return min(target, end)


@nb.njit(cache=True, _nrt=False)
def _margin(model, params, mode, directions, lam, slide, work, kind, i, c):
    """Signed distance to an event's condition (positive: not fired), for locating it.

    The event functions of :func:`_fired`: a closed contact's normal force,
    an open contact's gap, the friction margin of a sticking interface, a
    sliding interface's slip velocity, the slide past an end stop, the
    rotation to pi/2.
    """
    if kind == LIFT_OFF:
        return lam[i, c] + params[P_FORCE_EVENT]
    if kind == IMPACT:
        return work.contact[GAP][i, c] - work.contact[IMPACT_LEVEL][i, c]
    if kind == SLIP:
        sliding = model.codes[i]
        if (sliding == 2 or sliding == 3) and not _engaged(sliding, slide[i], params[P_TOL_SLIDE]):
            sliding = 0
        limit = model.properties[MU_S][i] * (lam[i, 0] + lam[i, 1]) + params[P_FORCE_EVENT]
        tangential = lam[i, 2]
        worst = -math.inf
        if sliding != 2:
            worst = max(worst, -tangential)
        if sliding != 3:
            worst = max(worst, tangential)
        return limit - worst
    if kind == SLIP_STOP:
        slip = work.contact[SLIP_VELOCITY][i, _reference(mode, i)]
        return directions[i] * slip + 1e-3 * params[P_TOL_VEL]
    if kind == STOP_IMPACT:
        if model.codes[i] == 2:
            return params[P_TOL_SLIDE] - slide[i]
        return slide[i] + params[P_TOL_SLIDE]
    return 0.5 * math.pi - abs(work.blockwise[ROTATION][i])


@nb.njit(cache=True, _nrt=False)
def _hermite(active, q0, v0, a0, s0, r0, q1, v1, a1, s1, r1, h, s, out_q, out_v, out_s):
    """State at ``s`` (fraction of the step) on the step's Hermite interpolants.

    Quintic in the coordinates (position, velocity and acceleration at both
    ends), its derivative for the velocities, cubic for the slides (slide and
    slide rate at both ends).
    """
    s2 = s * s
    s3 = s2 * s
    s4 = s3 * s
    s5 = s4 * s
    h0 = 1.0 - 10.0 * s3 + 15.0 * s4 - 6.0 * s5
    h1 = s - 6.0 * s3 + 8.0 * s4 - 3.0 * s5
    h2 = 0.5 * s2 - 1.5 * s3 + 1.5 * s4 - 0.5 * s5
    h3 = 0.5 * s3 - s4 + 0.5 * s5
    h4 = -4.0 * s3 + 7.0 * s4 - 3.0 * s5
    h5 = 10.0 * s3 - 15.0 * s4 + 6.0 * s5
    d0 = -30.0 * s2 + 60.0 * s3 - 30.0 * s4
    d1 = 1.0 - 18.0 * s2 + 32.0 * s3 - 15.0 * s4
    d2 = s - 4.5 * s2 + 6.0 * s3 - 2.5 * s4
    d3 = 1.5 * s2 - 4.0 * s3 + 2.5 * s4
    d4 = -12.0 * s2 + 28.0 * s3 - 15.0 * s4
    d5 = 30.0 * s2 - 60.0 * s3 + 30.0 * s4
    hh = h * h
    for c in range(3 * active):
        out_q[c] = h0 * q0[c] + h1 * h * v0[c] + h2 * hh * a0[c] + h3 * hh * a1[c]
        out_q[c] += h4 * h * v1[c] + h5 * q1[c]
        out_v[c] = (d0 * q0[c] + d1 * h * v0[c] + d2 * hh * a0[c] + d3 * hh * a1[c]
                    + d4 * h * v1[c] + d5 * q1[c]) / h  # fmt: skip
    c0 = 1.0 - 3.0 * s2 + 2.0 * s3
    c1 = s - 2.0 * s2 + s3
    c2 = -s2 + s3
    c3 = 3.0 * s2 - 2.0 * s3
    for i in range(active):
        out_s[i] = c0 * s0[i] + c1 * h * r0[i] + c2 * h * r1[i] + c3 * s1[i]


@nb.njit(cache=True, _nrt=False)
def _stuck_below(active, mode, qd):
    """Number of bottom blocks that stick to the support and do not move.

    Their coordinates are not integrated during a step (the RK4 stages solve
    the blocks above them only); the full system is evaluated at the step's
    end, where their own events (lift-off, slip) are checked.
    """
    first = 0
    while first < active:
        if mode[first, 0] != 1 or mode[first, 1] != 1 or mode[first, 2] != 1:
            break
        moving = False
        for c in range(3 * first, 3 * first + 3):
            if abs(qd[c]) > 1e-9:
                moving = True
        if moving:
            break
        first += 1
    return first


@nb.njit(cache=True, _nrt=False)
def _at_rest(active, mode, qd):
    """Whether every interface sticks with both contacts closed and nothing moves."""
    for i in range(active):
        if mode[i, 0] != 1 or mode[i, 1] != 1 or mode[i, 2] != 1:
            return False
    for c in range(3 * active):
        if abs(qd[c]) > 1e-9:
            return False
    return True


@nb.njit(cache=True, _nrt=False)
def _rest_prepare(model, active, q, qd, mode, work, rest, qdd):
    """Forces of the rest mode for unit support loads, for :func:`_rest_forces`.

    At rest nothing moves in the support's frame, so the held mode's forces are
    affine in the free acceleration ``f = (-a_h, -(g - a_v), 0)`` of every block:
    ``lam = lam_0 + (-a_h) (lam_x - lam_0) + (-(g - a_v)) (lam_z - lam_0)``, with
    ``lam_0`` (velocity terms only), ``lam_x``, ``lam_z`` the solutions for
    ``f = 0``, ``f = (1, 0, 0)`` and ``f = (0, 1, 0)``. ``rest`` (3, B, 3) receives
    ``lam_0`` and the two differences; the kinematics stay in ``work``. Returns
    False for a singular mode.
    """
    _kin(model, active, q, qd, work)
    free = work.vectors[FREE]
    for load in range(3):
        for i in range(active):
            free[3 * i] = 1.0 if load == 1 else 0.0
            free[3 * i + 1] = 1.0 if load == 2 else 0.0
            free[3 * i + 2] = 0.0
        if not _held_solve(active, model.masses[INVERSE_MASS], work, mode, qdd, rest[load], 0):
            return False
    for load in (1, 2):
        for i in range(active):
            for c in range(3):
                rest[load, i, c] -= rest[0, i, c]
    return True


@nb.njit(cache=True, _nrt=False)
def _rest_forces(exc, params, active, t, rest, lam):
    """Forces of the rest mode at ``t`` from :func:`_rest_prepare`'s unit solutions."""
    a_h, a_v = _support(exc[0], exc[1], params[P_EXC_DT], t)
    load_x = -a_h
    load_z = -(params[P_GRAVITY] - a_v)
    for i in range(active):
        for c in range(3):
            lam[i, c] = rest[0, i, c] + load_x * rest[1, i, c] + load_z * rest[2, i, c]


# --- the remedy: a stretch of velocity-impulse time stepping ----------------------------------


@nb.njit(cache=True, _nrt=False)
def _friction_bounds(model, params, active, slide, work, low, high):
    """Bounds of each interface's tangential impulse over its normal one, for a step.

    Static friction while the interface does not slip (kinematics in work),
    kinetic while it does; unbounded for ``sliding = "none"`` and, one way,
    at an engaged end stop (see :func:`time_stepping.impulse_step`).
    """
    mu_s = model.properties[MU_S]
    mu_k = model.properties[MU_K]
    codes = model.codes
    for i in range(active):
        slip = work.contact[SLIP_VELOCITY][i, _lower_contact(work.contact[GAP], i)]
        mu = mu_s[i] if abs(slip) <= params[P_TOL_VEL] else mu_k[i]
        low[i] = mu
        high[i] = mu
        code = codes[i]
        if code == 1:
            low[i] = UNBOUNDED_FRICTION
            high[i] = UNBOUNDED_FRICTION
        elif code == 2 and _engaged(code, slide[i], params[P_TOL_SLIDE]):
            low[i] = UNBOUNDED_FRICTION  # the stop pushes back (-x) without bound
        elif code == 3 and _engaged(code, slide[i], params[P_TOL_SLIDE]):
            high[i] = UNBOUNDED_FRICTION


@nb.njit(cache=True, _nrt=True)
def _time_step(model, exc, params, active, t, h, q, qd, slide, work, mode, directions, lam,
               fstate):  # fmt: skip
    """One Moreau-Jean step of ``h`` [s] (:mod:`freestand.core.dynamics.time_stepping`).

    Advances ``q``, ``qd`` and ``slide`` in place; ``lam`` receives the mean
    contact forces over the step (impulses / h) [N], ``mode`` and
    ``directions`` the contacts that carried an impulse and how each
    interface moves. Kinematics at the step's end are left in ``work``.
    """
    n = 3 * active
    inverse_mass = model.masses[INVERSE_MASS]
    midpoint = np.empty(n)
    for k in range(n):
        midpoint[k] = q[k] + 0.5 * h * qd[k]
    _kin(model, active, midpoint, qd, work)
    low = np.empty(active)
    high = np.empty(active)
    _friction_bounds(model, params, active, slide, work, low, high)
    a_h, a_v = _support(exc[0], exc[1], params[P_EXC_DT], t + 0.5 * h)
    velocity = np.empty(n)
    for i in range(active):
        velocity[3 * i] = qd[3 * i] - h * a_h
        velocity[3 * i + 1] = qd[3 * i + 1] - h * (params[P_GRAVITY] - a_v)
        velocity[3 * i + 2] = qd[3 * i + 2]
    closed = np.zeros((active, 2), dtype=np.bool_)
    for i in range(active):
        for c in range(2):
            approach = 0.0
            for k in range(n):
                approach += work.jacobian[0][i, c, k] * velocity[k]
            closed[i, c] = work.contact[GAP][i, c] + 0.5 * h * approach <= params[P_TOL_GAP]
    normal = np.empty((active, 2))
    tangential = np.empty((active, 2))
    ratio = impulse_step(active, inverse_mass, work.jacobian[0], work.jacobian[1], closed, low,
                         high, velocity, normal, tangential)  # fmt: skip
    fstate[F_ENERGY_RATIO] = max(fstate[F_ENERGY_RATIO], ratio)
    for i in range(active):
        reference = _lower_contact(work.contact[GAP], i)
        slip = 0.0
        for k in range(n):
            slip += work.jacobian[1][i, reference, k] * velocity[k]
        slide[i] += h * slip
        carried = 0
        for c in range(2):
            mode[i, c] = 1 if normal[i, c] > 0.0 else 0
            carried += mode[i, c]
        lam[i, 0] = normal[i, 0] / h
        lam[i, 1] = normal[i, 1] / h
        lam[i, 2] = (tangential[i, 0] + tangential[i, 1]) / h
        if carried == 0:
            mode[i, 2] = 0
            directions[i] = 0
        elif abs(slip) <= params[P_TOL_VEL]:
            mode[i, 2] = 1
            directions[i] = 0
        else:
            mode[i, 2] = 2 if slip > 0.0 else 3
            directions[i] = 1 if slip > 0.0 else -1
    for k in range(n):
        q[k] = midpoint[k] + 0.5 * h * velocity[k]
        qd[k] = velocity[k]
    _kin(model, active, q, qd, work)


@nb.njit(cache=True, _nrt=True)
def _try_resume(model, exc, params, active, t, q, qd, slide, work, problem, istate, fstate, mode,
                directions, flags, settle, qdd, lam):  # fmt: skip
    """End the stretch if an event-driven mode is consistent at the state; whether it did.

    The state is left as it was when none is (the attempt works on copies).
    """
    n = 3 * active
    q_saved = q[:n].copy()
    qd_saved = qd[:n].copy()
    slide_saved = slide[:active].copy()
    mode_saved = mode[:active].copy()
    directions_saved = directions[:active].copy()
    _settle(model, exc, params, active, t, q, qd, slide, work, problem, istate, fstate, mode,
            directions, flags, False, settle)  # fmt: skip
    if settle[0] == NO_FAILURE and _evaluate(model, exc, params, active, t, q, qd, mode, work,
                                             qdd, lam):  # fmt: skip
        istate[S_STEPPING] = 0
        return True
    q[:n] = q_saved
    qd[:n] = qd_saved
    slide[:active] = slide_saved
    mode[:active] = mode_saved
    directions[:active] = directions_saved
    _kin(model, active, q, qd, work)
    return False


@nb.njit(cache=True, _nrt=False)
def _overturn_blocks(t, index, active, flags, count):
    """Mark the blocks from ``index`` up overturned at ``t``."""
    for j in range(index, count):
        if flags[2, j] < 0.5:
            flags[2, j] = 1.0
            flags[3, j] = t


# --- the loop's state ---------------------------------------------------------------------------


@nb.njit(cache=True, _nrt=False)
def _copy(destination, source, size):
    """``destination[:size] = source[:size]`` for 1-D arrays."""
    for k in range(size):
        destination[k] = source[k]


@nb.njit(cache=True, _nrt=False)
def _copy_rows(destination, source, rows):
    """``destination[:rows] = source[:rows]`` for 2-D arrays of the same width."""
    for i in range(rows):
        for c in range(destination.shape[1]):
            destination[i, c] = source[i, c]


@nb.njit(cache=True, _nrt=False)
def _copy_state(q, qd, slide, q_from, qd_from, slide_from, active):
    """Coordinates, rates (3 per block) and slides of the first ``active`` blocks."""
    _copy(q, q_from, 3 * active)
    _copy(qd, qd_from, 3 * active)
    _copy(slide, slide_from, active)


#: The simulation's state, kept by the caller between calls of :func:`run`:
#: ``q``, ``qd`` (3 B) coordinates and rates, ``slide`` (B) each interface's
#: slide, the held ``mode`` (B, 3) (left, right contact closed; tangential
#: state) and slide ``directions`` (B), the ``istate`` (``S_*``) and ``fstate``
#: (``F_*``, the time among them) vectors, and ``flags`` (6, B): uplift, free
#: flight, overturned (0 or 1), overturning time [s], largest lift and
#: largest flight gap [m].
State = namedtuple("State", ("q", "qd", "slide", "mode", "directions", "istate", "fstate", "flags"))

#: Scratch arrays of one call of :func:`run`, made by :func:`_loop_arrays`; a few
#: packed arrays, so that a call passes few arguments:
#:
#: - ``vectors`` (10, 3 B): ``QDD`` the held mode's accelerations at the current
#:   time; ``Q1``, ``QD1``, ``QDD1`` the end of the trial step (:func:`advance`),
#:   then the state at the located event (:func:`locate`); ``QM``, ``QDM`` a trial
#:   state inside the step; ``Q_END``, ``QD_END``, ``A_END`` the step's end for its
#:   interpolant; ``BEFORE`` the rates before an event;
#: - ``blockwise`` (5, B): ``RATES`` the slide rates at the current time, ``SLIDE1``,
#:   ``SLIDE_M``, ``SLIDE_END``, ``RATE_END`` as the vectors above;
#: - ``forces`` (8, B, 3) (normal at the left and right contact, tangential) [N]:
#:   ``LAM`` the held mode's forces at the current time, ``LAM1`` at the trial step's
#:   end, ``LAM_LO``, ``LAM_HI``, ``LAM_SAMPLE`` those of a rest segment at its sample
#:   times, and from ``REST`` three rows: the rest mode's forces for unit support
#:   loads (:func:`_rest_prepare`);
#: - ``codes`` (4, 4) int: ``FOUND``, ``FOUND_M`` an event (kind, interface,
#:   contact, number of event conditions that hold) at the step's end and at a trial
#:   state; ``SETTLE`` the outcome of :func:`_settle`; ``STEP``: ``L_REST_READY``
#:   (``REST`` holds the current rest's forces), ``L_RESTING`` (the step is a rest
#:   segment), ``L_FIRST`` (the bottom blocks that stick to the support and are not
#:   integrated).
Loop = namedtuple("Loop", ("vectors", "blockwise", "forces", "codes"))
QDD, Q1, QD1, QDD1, QM, QDM, Q_END, QD_END, A_END, BEFORE = range(10)
RATES, SLIDE1, SLIDE_M, SLIDE_END, RATE_END = range(5)
LAM, LAM1, LAM_LO, LAM_HI, LAM_SAMPLE, REST = range(6)
FOUND, FOUND_M, SETTLE, STEP = range(4)
L_REST_READY, L_RESTING, L_FIRST = range(3)


@nb.njit(cache=True, _nrt=True)
def _loop_arrays(count):
    """The :data:`Loop` scratch arrays for a stack of ``count`` blocks."""
    n = 3 * count
    return Loop(
        np.zeros((10, n)),
        np.zeros((5, count)),
        np.zeros((8, count, 3)),
        np.zeros((4, 4), dtype=np.int64),
    )


#: Work arrays of the contact problem at events (:func:`_settle`, :func:`_impact`,
#: :func:`_select`), made by :func:`_problem_arrays`:
#:
#: - ``contact``: the contact kernel's :data:`~freestand.core.contact.engine.ContactWork`;
#: - ``terms`` (2, B, 2): the velocity terms b_n, b_t of the impact problem (the
#:   contacts' relative velocities);
#: - ``blockwise`` (3, B): ``P_SLIP`` each interface's slip velocity (0: static
#:   friction), ``P_LOW``, ``P_HIGH`` its friction bounds in a dissipative impact;
#: - ``contact_active`` (B, 2) bool, ``sliding`` (B) int: the problem's contacts and
#:   effective sliding codes;
#: - ``vectors`` (6, 3 B): ``P_FREE`` the free accelerations (zero in an impact),
#:   ``P_NEW_QD`` the rates after an impact; ``P_REVERSED``, ``P_SECOND``, ``P_THIRD``,
#:   ``P_ZENO_QDD`` the rates and accelerations of a Zeno sequence's next impacts
#:   (:func:`_zeno_end`);
#: - ``modes``, ``solutions``, ``forces``, ``accelerations``, ``index``, ``info``: the
#:   kernel's first :data:`MAX_DISTINCT` admissible states;
#: - ``impulses`` (2, B, 2): normal and tangential impulses of a dissipative impact.
Problem = namedtuple(
    "Problem",
    (
        "contact", "terms", "blockwise", "contact_active", "sliding", "vectors", "modes",
        "solutions", "forces", "accelerations", "index", "info", "impulses",
    ),
)  # fmt: skip
P_SLIP, P_LOW, P_HIGH = range(3)
P_FREE, P_NEW_QD, P_REVERSED, P_SECOND, P_THIRD, P_ZENO_QDD = range(6)
#: Admissible modes the contact problem's work arrays hold (more: the kernel's own).
PROBLEM_CAPACITY = 64


@nb.njit(cache=True, _nrt=True)
def _problem_arrays(count):
    """The :data:`Problem` work arrays for a stack of ``count`` blocks."""
    n = 3 * count
    return Problem(
        contact_work(count, PROBLEM_CAPACITY),
        np.zeros((2, count, 2)),
        np.zeros((3, count)),
        np.zeros((count, 2), dtype=np.bool_),
        np.zeros(count, dtype=np.int64),
        np.zeros((6, n)),
        np.zeros((MAX_DISTINCT, count, 3), dtype=np.int64),
        np.zeros((MAX_DISTINCT, n)),
        np.zeros((MAX_DISTINCT, count, 3)),
        np.zeros((MAX_DISTINCT, count, 3)),
        np.zeros(MAX_DISTINCT, dtype=np.int64),
        np.zeros(INFO_SIZE, dtype=np.int64),
        np.zeros((2, count, 2)),
    )


# --- record -------------------------------------------------------------------------------------


@nb.njit(cache=True, _nrt=False)
def record(state, lam, work, rec):
    """Store the state at its time as the next row of the history.

    Reads ``state`` (time, coordinates, rates, slides, active blocks), the
    forces ``lam`` (B, 3) and the relative rotations and gaps in ``work``
    (kinematics of the state). Writes row ``istate[S_ROWS]`` of ``rec``
    (time, q, qd, normal and tangential forces, relative rotation, slide;
    NaN for overturned blocks), raises the largest lift and flight gaps in
    ``flags[4]``, ``flags[5]`` and counts the row.
    """
    istate = state.istate
    row = istate[S_ROWS]
    active = istate[S_ACTIVE]
    count = state.flags.shape[1]
    max_lift = state.flags[4]
    max_flight = state.flags[5]
    rec_time, values = rec
    rec_time[row] = state.fstate[F_TIME]
    gap = work.contact[GAP]
    for i in range(count):
        if i < active:
            top = max(gap[i, 0], gap[i, 1])
            low = min(gap[i, 0], gap[i, 1])
            if top > max_lift[i]:
                max_lift[i] = top
            if low > max_flight[i]:
                max_flight[i] = low
            for c in range(3):
                values[row, i, R_Q + c] = state.q[3 * i + c]
                values[row, i, R_QD + c] = state.qd[3 * i + c]
            values[row, i, R_NORMAL] = lam[i, 0]
            values[row, i, R_NORMAL + 1] = lam[i, 1]
            values[row, i, R_TANGENTIAL] = lam[i, 2]
            values[row, i, R_ROTATION] = work.blockwise[ROTATION][i]
            values[row, i, R_SLIDE] = state.slide[i]
        else:
            for column in range(R_SIZE):
                values[row, i, column] = np.nan
    istate[S_ROWS] = row + 1


@nb.njit(cache=True, _nrt=False)
def _record_event(state, kind, interface, contact, status, active_before, qd_before, ev):
    """Append an event at the state's time (:func:`_event`) with the held mode and rates."""
    _event(state.fstate[F_TIME], kind, interface, contact, status, active_before,
           state.istate[S_ACTIVE], state.mode, qd_before, state.qd, state.flags.shape[1], ev,
           state.istate)  # fmt: skip


@nb.njit(cache=True, _nrt=False)
def _stretch_length(cause, istate):
    """Least number of steps of a stretch begun because of failure code ``cause``.

    :data:`STRETCH_STEPS` (2 ms), and for a burst (:data:`BURST`) twice as
    many for each burst's stretch since the last quiet spell (at most
    2^:data:`BURST_DOUBLINGS` times), so that a stretch comes to outlast a
    chatter that the first ones did not end; counts the burst's stretch in
    ``istate``.
    """
    if cause != BURST:
        return STRETCH_STEPS
    doublings = min(istate[S_BURST_STRETCHES], BURST_DOUBLINGS)
    istate[S_BURST_STRETCHES] += 1
    return STRETCH_STEPS << doublings


@nb.njit(cache=True, _nrt=False)
def _in_burst(t, istate, fstate):
    """Count the event at ``t`` [s] in the burst it continues; whether the burst is too long.

    An event within :data:`BURST_INTERVAL` of the last one (or of the start
    or the resume of events) continues the burst, any other one ends it and
    the run of bursts' stretches with it (a quiet spell). True once the
    burst has more than :data:`BURST_EVENTS` events: events come far faster
    than the stack's motion (a rocking whose flights are below the gap
    tolerance, chatter) and would not end.
    """
    if t - fstate[F_LAST_EVENT] <= BURST_INTERVAL:
        istate[S_BURST] += 1
    else:
        istate[S_BURST] = 0
        istate[S_BURST_STRETCHES] = 0
    fstate[F_LAST_EVENT] = t
    return istate[S_BURST] > BURST_EVENTS


@nb.njit(cache=True, _nrt=False)
def _begin_stretch(cause, state, ev):
    """Switch to time stepping for a stretch, because of failure code ``cause``.

    Sets the stepping flags and counters of ``istate`` (the stall and burst
    counts start again after it; its least length: :func:`_stretch_length`)
    and records a ``time-stepping`` event.
    """
    istate = state.istate
    istate[S_STEPPING] = 1
    istate[S_STRETCH_STEPS] = 0
    istate[S_STRETCH_LENGTH] = _stretch_length(cause, istate)
    istate[S_STRETCHES] += 1
    istate[S_REMEDY + cause] += 1
    istate[S_STALLED] = 0
    istate[S_BURST] = 0
    active = istate[S_ACTIVE]
    _record_event(state, TIME_STEPPING, -1, -1, 0, active, state.qd, ev)


# --- start and stop -----------------------------------------------------------------------------


@nb.njit(cache=True, inline="always", _nrt=False)
def _start(model, exc, params, state, work, loop, problem, rec, ev):
    """Start the simulation (first call) or pick it up where the last call stopped.

    First call: the contact problem at the initial state (impact if needed,
    the mode to hold, projection: :func:`_settle`), its forces, the first row
    and the ``start`` event (and the impact's), or a stretch of time stepping
    when no mode is consistent. Later calls: the kinematics (while time
    stepping) or the held mode's forces and accelerations at the state.
    Writes the forces ``LAM``, accelerations ``QDD`` and slide rates ``RATES`` of
    :data:`Loop`; returns :data:`BUFFER_FULL` when the buffers cannot take the
    first rows, else :data:`RUNNING`.
    """
    qdd = loop.vectors[QDD]
    velocity_before = loop.vectors[BEFORE]
    rates = loop.blockwise[RATES]
    lam = loop.forces[LAM]
    settle = loop.codes[SETTLE]
    q, qd, slide, mode, directions, istate, fstate, flags = state
    count = flags.shape[1]
    active = istate[S_ACTIVE]
    t = fstate[F_TIME]
    for i in range(count):
        work.contact[FRICTION][i, 0] = model.properties[MU_K][i]
        work.contact[FRICTION][i, 1] = 0.0
    if istate[S_STARTED] == 0:
        if rec[0].shape[0] < 4 or ev[0].shape[0] < 4:
            return BUFFER_FULL
        istate[S_STARTED] = 1
        fstate[F_LAST_EVENT] = t
        _copy(velocity_before, qd, qd.shape[0])
        _settle(model, exc, params, active, t, q, qd, slide, work, problem, istate, fstate, mode,
                directions, flags, False, settle)  # fmt: skip
        cause = settle[0]
        status = 1 if settle[2] > 1 else 0
        if cause == NO_FAILURE and not _evaluate(model, exc, params, active, t, q, qd, mode,
                                                 work, qdd, lam):  # fmt: skip
            cause = SINGULAR_MODE
        if cause != NO_FAILURE:
            _kin(model, active, q, qd, work)
            lam[:] = 0.0
        record(state, lam, work, rec)
        _record_event(state, START, -1, -1, status, active, velocity_before, ev)
        if settle[1] != 0:
            _record_event(state, settle[1], -1, -1, status, active, velocity_before, ev)
        if cause != NO_FAILURE:
            _begin_stretch(cause, state, ev)
    elif istate[S_STEPPING] == 1:
        _kin(model, active, q, qd, work)
    elif not _evaluate(model, exc, params, active, t, q, qd, mode, work, qdd, lam):
        _begin_stretch(SINGULAR_MODE, state, ev)
    _slide_rate(active, mode, work.contact[SLIP_VELOCITY], rates)
    return RUNNING


@nb.njit(cache=True, inline="always", _nrt=False)
def _stop(params, chunk_end, state, rows_capacity, events_capacity):
    """Why the loop stops before its next step, or :data:`RUNNING` to go on.

    :data:`COMPLETED` at the end time or once every block has overturned, and
    with ``P_UNTIL_REST`` once the stack rests after the excitation (sets
    ``S_AT_REST``); :data:`CHUNK_DONE` at ``chunk_end``; :data:`BUFFER_FULL`
    when the history or event buffers cannot take the rows of one more step.
    """
    istate = state.istate
    t = state.fstate[F_TIME]
    active = istate[S_ACTIVE]
    end = params[P_END]
    if not (active > 0 and t < end - 1e-12 * max(end, 1.0)):
        return COMPLETED
    if (
        params[P_UNTIL_REST] > 0.0
        and istate[S_STEPPING] == 0
        and t >= params[P_EXC_END]
        and _at_rest(active, state.mode, state.qd)
    ):
        # the excitation is over and every interface sticks closed with nothing
        # moving: the stack stays at rest from here on
        istate[S_AT_REST] = 1
        return COMPLETED
    if t >= chunk_end:
        return CHUNK_DONE
    if istate[S_ROWS] + 4 > rows_capacity or istate[S_EVENTS] + 4 > events_capacity:
        return BUFFER_FULL
    return RUNNING


# --- advance ------------------------------------------------------------------------------------


@nb.njit(cache=True, inline="always", _nrt=False)
def advance(model, exc, params, breaks, h_cap, state, work, loop):
    """One step of the held mode from the state's time ``t``: its length ``h`` [s], or -1.

    The step ends at the next break point of the record, ``t + h_cap`` or
    the end. At rest (every interface sticks closed, nothing moves) the step
    is a rest segment: the state does not change in the support's frame and
    the forces at its end come from the rest mode's unit solutions
    (:func:`_rest_prepare`, once per rest; :func:`_rest_forces`). Otherwise one
    RK4 step of the held mode (bottom blocks stuck to the support not
    integrated: :func:`_stuck_below`) and the held mode's forces at its end.

    Reads ``state`` and the accelerations ``QDD`` and slide rates ``RATES`` at
    ``t`` (:data:`Loop`); writes the step's end to ``Q1``, ``QD1``, ``SLIDE1``,
    ``LAM1``, ``QDD1`` (kinematics of the end in ``work``) and ``STEP`` (resting,
    first integrated block, rest forces ready). The state is not changed.
    Returns -1 when the held mode is singular.
    """
    qdd = loop.vectors[QDD]
    q1 = loop.vectors[Q1]
    qd1 = loop.vectors[QD1]
    qdd1 = loop.vectors[QDD1]
    rates = loop.blockwise[RATES]
    slide1 = loop.blockwise[SLIDE1]
    lam1 = loop.forces[LAM1]
    rest = loop.forces[REST : REST + 3]
    step = loop.codes[STEP]
    q, qd, slide, mode, _, istate, fstate, _ = state
    t = fstate[F_TIME]
    active = istate[S_ACTIVE]
    n = 3 * active
    h = _next_end(t, params, breaks, istate, h_cap) - t
    if h <= 1e-3 * params[P_TIME_TOL]:
        h = h_cap
    resting = _at_rest(active, mode, qd)
    first = _stuck_below(active, mode, qd)
    _arm_impacts(params, active, mode, work)
    step[L_RESTING] = 1 if resting else 0
    step[L_FIRST] = first
    if resting:
        # the whole stack moves with the support: nothing moves in its frame and the
        # forces are affine in the support accelerations (_rest_prepare, once per
        # rest), hence linear in time between two break points; only the end of
        # the segment is evaluated
        _copy_state(q1, qd1, slide1, q, qd, slide, active)
        if step[L_REST_READY] == 0:
            if not _rest_prepare(model, active, q, qd, mode, work, rest, qdd1):
                return -1.0
            step[L_REST_READY] = 1
        _rest_forces(exc, params, active, t + h, rest, lam1)
        qdd1[:n] = 0.0
        return h
    step[L_REST_READY] = 0
    if not _rk4(model, exc, params, active, t, q, qd, slide, h, mode, qdd, rates,
                work, q1, qd1, slide1, lam1, first):  # fmt: skip
        return -1.0
    if not _evaluate(model, exc, params, active, t + h, q1, qd1, mode, work, qdd1,
                     lam1):  # fmt: skip
        return -1.0
    return h


@nb.njit(cache=True, _nrt=False)
def _arm_impacts(params, active, mode, work):
    """Each open contact's impact level [m] for the step from the state in ``work``.

    A contact open at the step's start by more than the gap event's slack
    (``P_GAP_EVENT``) fires, and is located, where its gap reaches zero; one
    within the slack (just lifted, or put back by the projection) where it
    reaches minus the slack, so that round-off does not fire it again.
    Located at minus the slack (1e-10 m by default) wherever they started,
    impacts came late by the slack over the closing speed, 1e-7 to 1e-6 s
    for the slow impacts of a rocking that settles, which a sequence of
    impacts multiplies (the 3-D engine's events, ``body_events``, locate the
    zero).
    """
    gap = work.contact[GAP]
    level = work.contact[IMPACT_LEVEL]
    slack = params[P_GAP_EVENT]
    for i in range(active):
        for c in range(2):
            level[i, c] = 0.0 if mode[i, c] == 0 and gap[i, c] > slack else -slack


@nb.njit(cache=True, inline="always", _nrt=False)
def _take_step(model, exc, params, h, state, work, loop, problem, rec, ev):
    """Accept a step in which no event fired; an outcome code.

    Moves the state to the step's end (``Q1``, ... of :data:`Loop`), puts the closed
    contacts back on their surfaces when they drifted (:func:`_project`), records
    the row and, after the excitation, lets a block past its overturning
    angle fall (:func:`_overturn_after_excitation`).
    """
    qdd = loop.vectors[QDD]
    q1 = loop.vectors[Q1]
    qd1 = loop.vectors[QD1]
    qdd1 = loop.vectors[QDD1]
    rates = loop.blockwise[RATES]
    slide1 = loop.blockwise[SLIDE1]
    lam = loop.forces[LAM]
    lam1 = loop.forces[LAM1]
    step = loop.codes[STEP]
    q, qd, slide, mode, _, istate, fstate, _ = state
    active = istate[S_ACTIVE]
    n = 3 * active
    t = fstate[F_TIME] + h
    fstate[F_TIME] = t
    _copy(qdd, qdd1, n)
    _copy_state(q, qd, slide, q1, qd1, slide1, active)
    _copy_rows(lam, lam1, active)
    _slide_rate(active, mode, work.contact[SLIP_VELOCITY], rates)
    istate[S_STEPS] += 1
    drift = 0.0
    for i in range(active):
        for c in range(2):
            if mode[i, c] == 1:
                drift = max(drift, abs(work.contact[GAP][i, c]))
    if drift > 1e-3 * params[P_TOL_GAP]:
        step[L_REST_READY] = 0
        _project(model, active, q, qd, mode, work, fstate)
        if not _evaluate(model, exc, params, active, t, q, qd, mode, work, qdd, lam):
            _begin_stretch(SINGULAR_MODE, state, ev)
            return RUNNING
        _slide_rate(active, mode, work.contact[SLIP_VELOCITY], rates)
    record(state, lam, work, rec)
    if t >= params[P_EXC_END]:
        return _overturn_after_excitation(model, exc, params, state, work, loop, problem, ev)
    return RUNNING


@nb.njit(cache=True, inline="always", _nrt=False)
def advance_stretch(model, exc, params, h_cap, state, work, loop):
    """One step of the time-stepping remedy (:func:`_time_step`, ``STEPPING_STEP``).

    Advances the state (time, coordinates, rates, slides; the mode and
    directions of the contacts that carried an impulse) and the stepping
    counters; ``LAM`` (:data:`Loop`) receives the step's mean contact forces, ``work``
    the kinematics at its end.
    """
    lam = loop.forces[LAM]
    q, qd, slide, mode, directions, istate, fstate, _ = state
    t = fstate[F_TIME]
    h = min(STEPPING_STEP, h_cap, params[P_END] - t)
    _time_step(model, exc, params, istate[S_ACTIVE], t, h, q, qd, slide, work, mode, directions,
               lam, fstate)  # fmt: skip
    fstate[F_TIME] = t + h
    istate[S_STEPS] += 1
    istate[S_STRETCH_STEPS] += 1
    istate[S_STEPPED] += 1
    fstate[F_STEPPED_TIME] += h


# --- locate -------------------------------------------------------------------------------------


@nb.njit(cache=True, _nrt=False)
def _bracket_at_rest(model, exc, params, h, state, work, loop):
    """Bracket (low, high) [s from t] of the earliest event of a rest segment.

    At rest only force margins can cross (lift-off, slip); they are linear
    between the excitation's samples, so the segment is first narrowed to
    the samples around the first that fires, then the crossing interpolated
    and checked on both sides within the time tolerance. Writes the event
    that fires to ``FOUND`` (:data:`Loop`) when a check finds it.
    """
    lam = loop.forces[LAM]
    lam1 = loop.forces[LAM1]
    found = loop.codes[FOUND]
    found_m = loop.codes[FOUND_M]
    lam_hi = loop.forces[LAM_HI]
    lam_lo = loop.forces[LAM_LO]
    lam_sample = loop.forces[LAM_SAMPLE]
    rest = loop.forces[REST : REST + 3]
    _, _, slide, mode, directions, istate, fstate, _ = state
    t = fstate[F_TIME]
    active = istate[S_ACTIVE]
    time_tol = params[P_TIME_TOL]
    seg_lo = 0.0
    seg_hi = h
    _copy_rows(lam_lo, lam, active)
    _copy_rows(lam_hi, lam1, active)
    dt_exc = params[P_EXC_DT]
    k_sample = math.floor(t / dt_exc + 1e-9) + 1
    while k_sample * dt_exc < t + h - 1e-6 * time_tol:
        tm = k_sample * dt_exc - t
        _rest_forces(exc, params, active, t + tm, rest, lam_sample)
        if _fired(model, params, active, mode, directions, lam_sample, slide, work, found_m):
            seg_hi = tm
            _copy_rows(lam_hi, lam_sample, active)
            break
        seg_lo = tm
        _copy_rows(lam_lo, lam_sample, active)
        k_sample += 1
    earliest = seg_hi
    for i in range(active):
        for kind in (LIFT_OFF, SLIP):
            for c in range(2 if kind == LIFT_OFF else 1):
                g1 = _margin(model, params, mode, directions, lam_hi, slide, work, kind, i,
                             c if kind == LIFT_OFF else -1)  # fmt: skip
                if g1 >= 0.0:
                    continue
                g0 = _margin(model, params, mode, directions, lam_lo, slide, work, kind, i,
                             c if kind == LIFT_OFF else -1)  # fmt: skip
                crossing = seg_lo
                if g0 > 0.0:
                    crossing = seg_lo + (seg_hi - seg_lo) * g0 / (g0 - g1)
                earliest = min(earliest, crossing)
    low = max(0.0, earliest - time_tol)
    high = min(h, earliest + time_tol)
    if low > 0.0:
        _rest_forces(exc, params, active, t + low, rest, lam1)
        if _fired(model, params, active, mode, directions, lam1, slide, work, found_m):
            # the margins were not linear over the segment: search [0, low]
            _copy(found, found_m, 4)
            return 0.0, low
    if high < h:
        _rest_forces(exc, params, active, t + high, rest, lam1)
        if _fired(model, params, active, mode, directions, lam1, slide, work, found_m):
            # located to the tolerance; events crossing within it are taken as
            # simultaneous (reported by priority, as at a jump of the excitation)
            _copy(found, found_m, 4)
            return max(0.0, high - 0.5 * time_tol), high
        return high, h
    return low, high


@nb.njit(cache=True, _nrt=False)
def _bracket_on_interpolant(model, exc, params, h, state, work, loop):
    """Bracket (low, high, g_low, g_high) of the earliest event of an RK4 step.

    The event's function (:func:`_margin`) is followed on the step's quintic
    Hermite interpolant (positions, velocities and accelerations at both
    ends; one evaluation per trial) by the Illinois variant of regula falsi,
    with Newton steps on an impact's gap and bisection while an open contact
    still rises; then a bracket of true RK4 states around the root, checked.
    ``g_low``, ``g_high``: the function at the bracket's ends (NaN where not
    known). Reads the step's end in ``Q1``, ... and the event in ``FOUND``
    (:data:`Loop`); a checked RK4 state that fires replaces them.
    """
    qdd = loop.vectors[QDD]
    q1 = loop.vectors[Q1]
    qd1 = loop.vectors[QD1]
    qdd1 = loop.vectors[QDD1]
    qm = loop.vectors[QM]
    qdm = loop.vectors[QDM]
    q_end = loop.vectors[Q_END]
    qd_end = loop.vectors[QD_END]
    a_end = loop.vectors[A_END]
    rates = loop.blockwise[RATES]
    slide1 = loop.blockwise[SLIDE1]
    slide_m = loop.blockwise[SLIDE_M]
    slide_end = loop.blockwise[SLIDE_END]
    rate_end = loop.blockwise[RATE_END]
    lam1 = loop.forces[LAM1]
    step = loop.codes[STEP]
    found = loop.codes[FOUND]
    found_m = loop.codes[FOUND_M]
    q, qd, slide, mode, directions, istate, fstate, _ = state
    t = fstate[F_TIME]
    active = istate[S_ACTIVE]
    n = 3 * active
    time_tol = params[P_TIME_TOL]
    first = step[L_FIRST]
    q1, qd1, slide1, lam1, qdd1 = (
        q1,
        qd1,
        slide1,
        lam1,
        qdd1,
    )
    qm, qdm, slide_m = qm, qdm, slide_m
    low = 0.0
    high = h
    g_high = _margin(model, params, mode, directions, lam1, slide1, work, found[0], found[1],
                     found[2])  # fmt: skip
    # the step's end, for the interpolant below
    _copy_state(
        q_end,
        qd_end,
        slide_end,
        q1,
        qd1,
        slide1,
        active,
    )
    _copy(a_end, qdd1, n)
    _slide_rate(active, mode, work.contact[SLIP_VELOCITY], rate_end)
    _evaluate(model, exc, params, active, t, q, qd, mode, work, qdd1, lam1)
    g_low = _margin(model, params, mode, directions, lam1, slide, work, found[0], found[1],
                    found[2])  # fmt: skip
    if not (g_low > 0.0 and g_high < 0.0):
        return low, high, g_low, g_high
    # the event's time on the step's quintic Hermite interpolant (positions,
    # velocities and accelerations at both ends): one evaluation per trial;
    # then a bracket of true RK4 states around it, checked
    a = 0.0
    b = h
    ga = g_low
    gb = g_high
    last = 0
    # the margins of impacts, slip stops, stop impacts and overturning are
    # kinematic: the held mode's forces are not needed to evaluate them,
    # and an impact's gap has its rate at hand (Newton's step)
    kinematic = found[0] != LIFT_OFF and found[0] != SLIP
    impact = found[0] == IMPACT
    newton = math.nan
    # an open contact that still rises at the step's start comes down within
    # it: bisection while the left end rises (regula falsi creeps there)
    rising = impact and work.contact[GAP_VELOCITY][found[1], found[2]] >= 0.0
    for _ in range(60):
        if b - a <= 0.1 * time_tol:
            break
        x = newton
        if not (x > a and x < b):
            if rising:
                x = 0.5 * (a + b)
            else:
                x = a + ga * (b - a) / (ga - gb)
        x = min(max(x, a + 0.01 * time_tol), b - 0.01 * time_tol)
        _hermite(active, q, qd, qdd, slide, rates, q_end, qd_end, a_end,
                 slide_end, rate_end, h, x / h, qm, qdm, slide_m)  # fmt: skip
        if kinematic:
            _kin(model, active, qm, qdm, work)
        else:
            _evaluate(model, exc, params, active, t + x, qm, qdm, mode, work, qdd1, lam1)
        gx = _margin(model, params, mode, directions, lam1, slide_m, work, found[0], found[1],
                     found[2])  # fmt: skip
        newton = math.nan
        if impact:
            rate = work.contact[GAP_VELOCITY][found[1], found[2]]
            if gx >= 0.0:
                rising = rate >= 0.0
            if rate < 0.0:
                newton = x - gx / rate
                if abs(newton - x) <= 0.01 * time_tol:
                    # converged: the root within a hundredth of the tolerance
                    a = max(a, newton - 0.05 * time_tol)
                    b = min(b, newton + 0.05 * time_tol)
                    break
        if gx < 0.0:
            b = x
            gb = gx
            if last == 1:
                ga *= 0.5
            last = 1
        else:
            a = x
            ga = gx
            if last == -1:
                gb *= 0.5
            last = -1
    upper = min(h, b + 0.45 * time_tol)
    lower = max(0.0, upper - 0.9 * time_tol)
    if not (upper < high and lower > low):
        return low, high, g_low, g_high
    ok = _rk4(model, exc, params, active, t, q, qd, slide, upper, mode, qdd, rates,
              work, qm, qdm, slide_m, lam1, first)  # fmt: skip
    ok = ok and _evaluate(model, exc, params, active, t + upper, qm, qdm, mode, work, qdd1, lam1)
    if ok and _fired(model, params, active, mode, directions, lam1, slide_m, work, found_m):
        high = upper
        _copy_state(q1, qd1, slide1, qm, qdm, slide_m, active)
        if found_m[0] != found[0] or found_m[1] != found[1] or found_m[2] != found[2]:
            g_low = math.nan
        _copy(found, found_m, 4)
        g_high = _margin(model, params, mode, directions, lam1, slide_m, work, found[0],
                         found[1], found[2])  # fmt: skip
        rate = work.contact[GAP_VELOCITY][found[1], found[2]] if found[0] == IMPACT else 0.0
        if found[3] == 1 and rate < 0.0 and (upper - g_high / rate >= lower + 0.05 * time_tol):
            # the impact alone fired, and its gap, closing at this rate, was
            # still open at ``lower`` (linear over the tolerance)
            low = lower
            g_low = g_high - rate * (upper - lower)
            ok = False
        else:
            ok = _rk4(model, exc, params, active, t, q, qd, slide, lower, mode, qdd,
                      rates, work, qm, qdm, slide_m, lam1, first)  # fmt: skip
            ok = ok and _evaluate(model, exc, params, active, t + lower, qm, qdm, mode, work,
                                  qdd1, lam1)  # fmt: skip
        if ok and not _fired(model, params, active, mode, directions, lam1, slide_m, work,
                             found_m):  # fmt: skip
            low = lower
            g_low = _margin(model, params, mode, directions, lam1, slide_m, work, found[0],
                            found[1], found[2])  # fmt: skip
        elif ok:
            high = lower
            _copy_state(q1, qd1, slide1, qm, qdm, slide_m, active)
            _copy(found, found_m, 4)
            g_low = math.nan
    elif ok:
        low = upper
        g_low = _margin(model, params, mode, directions, lam1, slide_m, work, found[0], found[1],
                        found[2])  # fmt: skip
    return low, high, g_low, g_high


@nb.njit(cache=True, inline="always", _nrt=False)
def locate(model, exc, params, h, state, work, loop):
    """Time [s from t] of the earliest event of the step, to the time tolerance; -1 if singular.

    An event fired at the step's end (``FOUND`` of :data:`Loop`). A bracket [low, high]
    (not fired, fired) is found on the step's interpolant
    (:func:`_bracket_on_interpolant`) or, for a rest segment, between the
    excitation's samples (:func:`_bracket_at_rest`), then cut to the time
    tolerance on true RK4 states by the Illinois variant of regula falsi on the
    event's function (bisection while that function is not known on both
    sides). Writes the state at the event (the first RK4 state found to fire,
    at ``high``) to ``Q1``, ``QD1``, ``SLIDE1`` and the event to ``FOUND``; the
    state itself is not changed.
    """
    qdd = loop.vectors[QDD]
    q1 = loop.vectors[Q1]
    qd1 = loop.vectors[QD1]
    qdd1 = loop.vectors[QDD1]
    qm = loop.vectors[QM]
    qdm = loop.vectors[QDM]
    rates = loop.blockwise[RATES]
    slide1 = loop.blockwise[SLIDE1]
    slide_m = loop.blockwise[SLIDE_M]
    lam1 = loop.forces[LAM1]
    step = loop.codes[STEP]
    found = loop.codes[FOUND]
    trial = loop.codes[FOUND_M]
    if step[L_RESTING] == 1:
        low, high = _bracket_at_rest(model, exc, params, h, state, work, loop)
        # a bracket of at most twice the tolerance: bisection
        g_high = -1.0
        g_low = math.nan
    else:
        low, high, g_low, g_high = _bracket_on_interpolant(model, exc, params, h, state, work,
                                                           loop)  # fmt: skip
    # what follows (RK4 states, the event's settling) leaves other kinematics in work
    step[L_REST_READY] = 0
    q, qd, slide, mode, directions, istate, fstate, _ = state
    t = fstate[F_TIME]
    active = istate[S_ACTIVE]
    time_tol = params[P_TIME_TOL]
    side = 0
    while high - low > time_tol:
        width = high - low
        if g_low > 0.0 and g_high < 0.0:
            middle = low + g_low * width / (g_low - g_high)
            middle = min(max(middle, low + 0.01 * time_tol), high - 0.01 * time_tol)
        else:
            middle = 0.5 * (low + high)
        if not _rk4(model, exc, params, active, t, q, qd, slide, middle, mode, qdd,
                    rates, work, qm, qdm, slide_m, lam1,
                    step[L_FIRST]):  # fmt: skip
            return -1.0
        if not _evaluate(model, exc, params, active, t + middle, qm, qdm, mode, work,
                         qdd1, lam1):  # fmt: skip
            return -1.0
        if _fired(
            model,
            params,
            active,
            mode,
            directions,
            lam1,
            slide_m,
            work,
            trial,
        ):
            high = middle
            _copy_state(
                q1,
                qd1,
                slide1,
                qm,
                qdm,
                slide_m,
                active,
            )
            if trial[0] != found[0] or trial[1] != found[1] or trial[2] != found[2]:
                g_low = math.nan  # another event: its function is not known at low
                side = 0
            _copy(found, trial, 4)
            g_high = _margin(model, params, mode, directions, lam1, slide_m, work,
                             found[0], found[1], found[2])  # fmt: skip
            if side == 1:
                g_low *= 0.5
            side = 1
        else:
            low = middle
            g_low = _margin(model, params, mode, directions, lam1, slide_m, work,
                            found[0], found[1], found[2])  # fmt: skip
            if side == -1:
                g_high *= 0.5
            side = -1
    return high


# --- resolve ------------------------------------------------------------------------------------


@nb.njit(cache=True, inline="always", _nrt=False)
def resolve(model, exc, params, max_events, h, state, work, loop, problem, rec, ev):
    """Move to the located event ``h`` [s] after t and resolve it; an outcome code.

    The state moves to the event (``Q1``, ... of :data:`Loop`; :func:`locate`), which is
    recorded; an overturned block and those above it leave the stack; then the
    impact if one is needed, the next contact mode and the projection onto the
    closed contacts (:func:`_settle`), the event, and the new mode's forces,
    recorded. Remedies: where events repeat without progress (more than 50
    steps of at most twice the time tolerance) or come in a burst
    (:func:`_in_burst`), no mode is consistent or the new mode is singular, a
    stretch of time stepping begins (:func:`_begin_stretch`). Returns
    :data:`COMPLETED` when every block has overturned, :data:`FAILED` after
    more than ``max_events`` events, else :data:`RUNNING`.
    """
    qdd = loop.vectors[QDD]
    q1 = loop.vectors[Q1]
    qd1 = loop.vectors[QD1]
    rates = loop.blockwise[RATES]
    slide1 = loop.blockwise[SLIDE1]
    lam = loop.forces[LAM]
    found = loop.codes[FOUND]
    settle = loop.codes[SETTLE]
    velocity_before = loop.vectors[BEFORE]
    q, qd, slide, mode, directions, istate, fstate, flags = state
    active = istate[S_ACTIVE]
    count = flags.shape[1]
    n = 3 * active
    _copy_state(q, qd, slide, q1, qd1, slide1, active)
    t = fstate[F_TIME] + h
    fstate[F_TIME] = t
    istate[S_STEPS] += 1
    if h <= 2.0 * params[P_TIME_TOL]:
        istate[S_STALLED] += 1
    else:
        istate[S_STALLED] = 0
    if istate[S_STALLED] > 50:
        _begin_stretch(STALLED, state, ev)
        return RUNNING
    if _in_burst(t, istate, fstate):
        _begin_stretch(BURST, state, ev)
        return RUNNING
    # state at the event (kinematics and forces of the held mode)
    _evaluate(model, exc, params, active, t, q, qd, mode, work, qdd, lam)
    record(state, lam, work, rec)
    kind = found[0]
    interface = found[1]
    contact = found[2]
    _copy(velocity_before, qd, n)
    before = active
    if kind == OVERTURN:
        _overturn_blocks(t, interface, active, flags, count)
        active = interface
        istate[S_ACTIVE] = active
        if active == 0:
            _record_event(state, kind, interface, contact, 0, before, velocity_before, ev)
            return COMPLETED
    _settle(model, exc, params, active, t, q, qd, slide, work, problem, istate, fstate, mode,
            directions, flags, True, settle)  # fmt: skip
    t = fstate[F_TIME]  # the accumulation instant of a summed Zeno sequence
    if settle[0] != NO_FAILURE:
        _begin_stretch(settle[0], state, ev)
        return RUNNING
    impacted = settle[1]
    if impacted == TANGENTIAL_IMPACT or (
        impacted != 0 and kind != IMPACT and kind != STOP_IMPACT and kind != OVERTURN
    ):
        kind = impacted
    _record_event(state, kind, interface, contact, 1 if settle[2] > 1 else 0, before,
                  velocity_before, ev)  # fmt: skip
    if istate[S_EVENTS] > max_events:
        istate[S_FAILURE] = TOO_MANY_EVENTS
        return FAILED
    if not _evaluate(model, exc, params, active, t, q, qd, mode, work, qdd, lam):
        _begin_stretch(SINGULAR_MODE, state, ev)
        return RUNNING
    _slide_rate(active, mode, work.contact[SLIP_VELOCITY], rates)
    record(state, lam, work, rec)
    return RUNNING


@nb.njit(cache=True, _nrt=False)
def _overturn_after_excitation(model, exc, params, state, work, loop, problem, ev):
    """After the excitation, a block past its overturning angle that cannot come back falls.

    The block and those above it leave the stack (an ``overturn`` event), the
    rest settles into its next mode (:func:`_settle`; a stretch of time
    stepping if none is consistent). Returns :data:`COMPLETED` when no block
    is left, else :data:`RUNNING`.
    """
    qdd = loop.vectors[QDD]
    rates = loop.blockwise[RATES]
    lam = loop.forces[LAM]
    settle = loop.codes[SETTLE]
    step = loop.codes[STEP]
    velocity_before = loop.vectors[BEFORE]
    q, qd, slide, mode, directions, istate, fstate, flags = state
    active = istate[S_ACTIVE]
    index = _overturned_after(model, params, active, qd, work)
    if index < 0:
        return RUNNING
    t = fstate[F_TIME]
    n = 3 * active
    step[L_REST_READY] = 0
    _copy(velocity_before, qd, n)
    _overturn_blocks(t, index, active, flags, flags.shape[1])
    istate[S_ACTIVE] = index
    _record_event(state, OVERTURN, index, -1, 0, active, velocity_before, ev)
    active = index
    if active == 0:
        return COMPLETED
    _copy(velocity_before, qd, 3 * active)
    _settle(model, exc, params, active, t, q, qd, slide, work, problem, istate, fstate, mode,
            directions, flags, False, settle)  # fmt: skip
    if settle[0] != NO_FAILURE:
        _begin_stretch(settle[0], state, ev)
        return RUNNING
    if not _evaluate(model, exc, params, active, t, q, qd, mode, work, qdd, lam):
        _begin_stretch(SINGULAR_MODE, state, ev)
        return RUNNING
    _slide_rate(active, mode, work.contact[SLIP_VELOCITY], rates)
    return RUNNING


@nb.njit(cache=True, inline="always", _nrt=False)
def resolve_stretch(model, exc, params, state, work, loop, problem, rec, ev):
    """After a step of time stepping: overturning, and the return to events.

    A block whose rotation reaches pi/2 overturns with those above it. After
    the stretch's least length (``S_STRETCH_LENGTH`` steps:
    :func:`_stretch_length`) the event-driven contact problem is tried at
    every step at the state (:func:`_try_resume`); when a mode is consistent
    the stretch ends with a ``resume`` event, from which a burst is counted
    again, and the state is recorded again.
    """
    qdd = loop.vectors[QDD]
    rates = loop.blockwise[RATES]
    lam = loop.forces[LAM]
    settle = loop.codes[SETTLE]
    step = loop.codes[STEP]
    velocity_before = loop.vectors[BEFORE]
    q, qd, slide, mode, directions, istate, fstate, flags = state
    t = fstate[F_TIME]
    active = istate[S_ACTIVE]
    for i in range(active):
        if abs(work.blockwise[ROTATION][i]) >= 0.5 * math.pi:
            _copy(velocity_before, qd, 3 * active)
            _overturn_blocks(t, i, active, flags, flags.shape[1])
            istate[S_ACTIVE] = i
            _record_event(state, OVERTURN, i, -1, 0, active, velocity_before, ev)
            active = i
            break
    if active > 0 and istate[S_STRETCH_STEPS] >= istate[S_STRETCH_LENGTH]:
        _copy(velocity_before, qd, 3 * active)
        if _try_resume(model, exc, params, active, t, q, qd, slide, work, problem, istate, fstate,
                       mode, directions, flags, settle, qdd, lam):  # fmt: skip
            step[L_REST_READY] = 0
            fstate[F_LAST_EVENT] = t
            _record_event(state, RESUME, -1, -1, 1 if settle[2] > 1 else 0, active,
                          velocity_before, ev)  # fmt: skip
            _slide_rate(active, mode, work.contact[SLIP_VELOCITY], rates)
            record(state, lam, work, rec)


# --- the loop -----------------------------------------------------------------------------------


def load_cached_kernels(kernels) -> int:
    """Load the compiled code of ``kernels`` from numba's cache; how many overloads.

    numba's cached ``run`` carries a copy of every function it calls, linked
    to a callee's own compiled code only where that code is already loaded
    when ``run``'s is. The copies measure slower: a process that loads the
    engine from the cache ran (a) of ``benchmarks/engine.py`` in 3.13 ms of
    CPU, the process that compiled it (whose callees were loaded first) in
    2.72 ms (docs/benchmarks.md). Loading the hot callees first, leaves
    first, gives the second figure from the cache; the results are the same
    (same code). Only signatures already in the cache are loaded (nothing is
    compiled here); a cache numba cannot read, or one of another layout, loads
    nothing, which is harmless.
    """
    loaded = 0
    for kernel in kernels:
        try:
            cache = kernel._cache
            codegen = kernel.targetctx.codegen()
            for key in cache._cache_file._load_index():
                signature = key[0]
                # only entries this process can load: same code, same CPU
                if signature in kernel.overloads or cache._index_key(signature, codegen) != key:
                    continue
                kernel.compile(signature)
                loaded += 1
        except Exception:  # noqa: BLE001  (numba's private cache layout: best effort)
            continue
    return loaded


@nb.njit(cache=True, _nrt=True)
def run(model, exc, breaks, params, h_cap, max_events, chunk_end, q, qd, slide, mode, directions,
        istate, fstate, flags, rec, ev):  # fmt: skip
    """Advance the simulation until the end, a failure, full buffers or ``chunk_end``.

    Resumable: every piece of the loop's state lives in the arguments
    (:data:`State`: ``q``, ``qd`` (3 B), ``slide`` (B), the held ``mode``
    (B, 3) and slide ``directions`` (B), ``istate``/``fstate`` counters,
    ``flags`` (uplift, free flight, overturned as floats, overturn time, max
    lift, max flight: (6, B))); ``rec`` and ``ev`` receive the history and
    the events. Each pass of the loop is one step: a step of the held mode
    (:func:`advance`); if an event fired in it, its time (:func:`locate`) and
    what follows it (:func:`resolve`), else the step taken; the state is
    recorded (:func:`record`). While no event-driven mode is consistent, a
    step of time stepping instead (:func:`advance_stretch`,
    :func:`resolve_stretch`). Returns the outcome code.
    """
    count = model.geometry.shape[0]
    state = State(q, qd, slide, mode, directions, istate, fstate, flags)
    return _loop(model, exc, breaks, params, h_cap, max_events, chunk_end, state, _work(count),
                 _loop_arrays(count), _problem_arrays(count), rec, ev)  # fmt: skip


@nb.njit(cache=True, _nrt=False)
def _loop(model, exc, breaks, params, h_cap, max_events, chunk_end, state, work, loop, problem,
          rec, ev):  # fmt: skip
    """The loop of :func:`run` on its :data:`State` and its :data:`Work`, :data:`Loop` and
    :data:`Problem` arrays."""
    slide1 = loop.blockwise[SLIDE1]
    lam = loop.forces[LAM]
    lam1 = loop.forces[LAM1]
    found = loop.codes[FOUND]
    istate = state.istate
    outcome = _start(model, exc, params, state, work, loop, problem, rec, ev)
    while outcome == RUNNING:
        outcome = _stop(params, chunk_end, state, rec[0].shape[0], ev[0].shape[0])
        if outcome != RUNNING:
            break
        if istate[S_STEPPING] == 1:
            advance_stretch(model, exc, params, h_cap, state, work, loop)
            record(state, lam, work, rec)
            resolve_stretch(model, exc, params, state, work, loop, problem, rec, ev)
            continue
        h = advance(model, exc, params, breaks, h_cap, state, work, loop)
        if h < 0.0:
            _begin_stretch(SINGULAR_MODE, state, ev)
        elif not _fired(model, params, istate[S_ACTIVE], state.mode, state.directions, lam1,
                        slide1, work, found):  # fmt: skip
            outcome = _take_step(model, exc, params, h, state, work, loop, problem, rec, ev)
        else:
            h = locate(model, exc, params, h, state, work, loop)
            if h < 0.0:
                _begin_stretch(SINGULAR_MODE, state, ev)
            else:
                outcome = resolve(
                    model, exc, params, max_events, h, state, work, loop, problem, rec, ev
                )
    istate[S_STATUS] = outcome
    return outcome


@nb.njit(cache=True, inline="always", _nrt=False)
def _solve_held(row_j, force_g, matrix, rhs, k, c0, n, symmetric):
    """The held mode's ``k`` equations ``(J_r M^-1 G_j^T) x = rhs``, solved in place.

    Symmetric (no sliding interface): its lower triangle by ``L D L^T``
    (:func:`~freestand.core.contact.engine.solve_symmetric_in_place`), and by
    Gaussian elimination when that finds it not positive definite; otherwise
    Gaussian elimination with partial pivoting. False when singular.
    """
    if symmetric:
        held_products(row_j, force_g, matrix, k, c0, n, True)
        if solve_symmetric_in_place(matrix, rhs, k):
            return True
    held_products(row_j, force_g, matrix, k, c0, n, False)
    return solve_in_place(matrix, rhs, k)


@nb.njit(cache=True, inline="always", _nrt=False)
def _held_solve(active, inverse_mass, work, mode, qdd, lam, first=0):
    """Forces and accelerations of a held mode, without the contact accelerations.

    The unknowns ``x_j`` are the closed contacts' normal forces and the
    sticking interfaces' tangential forces; each acts along
    ``G_j = J_j + c_j J_t`` (``c_j = -d mu`` carries a sliding interface's
    friction). Equations: zero gap acceleration at the closed contacts and
    zero slip acceleration at the sticking interfaces,
    ``sum_j (J_r M^-1 G_j^T) x_j = -(J_r M^-1 f + b_r)``; then
    ``qdd = M^-1 (f + sum_j G_j^T x_j)``, with ``f`` the free accelerations
    ``work.vectors[FREE]`` and the kinematics in ``work``. Returns False when
    singular.

    With ``first`` > 0 the blocks below ``first`` are held fixed (they stick to
    the support, nothing moves): only the interfaces from ``first`` up and
    the coordinates of their upper blocks take part; the others get no
    acceleration and their forces are not computed (zero).
    """
    free = work.vectors[FREE]
    jn = work.jacobian[0]
    jt = work.jacobian[1]
    bn = work.contact[GAP_BIAS]
    bt = work.contact[SLIP_BIAS]
    mu = work.contact[FRICTION]
    row_j = work.matrices[ROWS]
    force_g = work.matrices[FORCE_G]
    matrix = work.matrices[MATRIX]
    coeff = work.vectors[COEFF]
    rhs = work.vectors[RHS]
    n = 3 * active
    c0 = 3 * first
    k = 0
    for i in range(active):
        lam[i, 0] = 0.0
        lam[i, 1] = 0.0
        lam[i, 2] = 0.0
    # without a sliding interface every unknown acts along its own row (G_j = J_j):
    # the system J M^-1 J^T is symmetric, positive definite unless singular
    symmetric = True
    for i in range(first, active):
        if mode[i, 2] == 2 or mode[i, 2] == 3:
            symmetric = False
    for i in range(first, active):
        tangential = mode[i, 2]
        reference = 1 if (mode[i, 1] == 1 and mode[i, 0] == 0) else 0
        direction = 0.0
        if tangential == 2:
            direction = 1.0
        elif tangential == 3:
            direction = -1.0
        c_slide = -direction * mu[i, 0]
        for side in range(2):
            if mode[i, side] == 1:
                total = bn[i, side]
                for col in range(c0, n):
                    value = jn[i, side, col]
                    row_j[k, col] = value
                    force_g[k, col] = inverse_mass[col] * (value + c_slide * jt[i, reference, col])
                    total += value * free[col]
                rhs[k] = -total
                coeff[k] = 3 * i + side
                k += 1
        if tangential == 1:
            total = bt[i, reference]
            for col in range(c0, n):
                value = jt[i, reference, col]
                row_j[k, col] = value
                force_g[k, col] = inverse_mass[col] * value
                total += value * free[col]
            rhs[k] = -total
            coeff[k] = 3 * i + 2
            k += 1
    if not _solve_held(row_j, force_g, matrix, rhs, k, c0, n, symmetric):
        return False
    for c in range(n):
        qdd[c] = free[c] if c >= c0 else 0.0
    for j in range(k):
        x = rhs[j]
        slot = int(coeff[j])
        i = slot // 3
        kind = slot % 3
        lam[i, kind] += x
        if kind < 2:
            tangential = mode[i, 2]
            if tangential == 2:
                lam[i, 2] -= mu[i, 0] * x
            elif tangential == 3:
                lam[i, 2] += mu[i, 0] * x
        for col in range(c0, n):
            qdd[col] += force_g[j, col] * x
    return True


#: The engine's hot callees, leaves first (``perf``: the contact problem at events and
#: the held mode's evaluations), loaded before :func:`run` (:func:`load_cached_kernels`)
HOT_KERNELS = (
    delassus,
    contact_accelerations,
    solve_states_into,
    _kin,
    _evaluate,
    _rk4,
    _loop,
)
