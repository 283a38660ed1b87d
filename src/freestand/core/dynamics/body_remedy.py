"""The 3-D engine's remedy: velocity-level time stepping where no event-driven mode goes on.

Where no contact mode is consistent (Painleve), where an edge's slip at its
friction limit restarts again and again (a chatter), or where impacts
accumulate (Zeno), the loop (:mod:`freestand.core.dynamics.body_engine`)
hands the body to a *stretch* of Moreau-Jean time stepping
(:func:`stretch_step`, :func:`advance_stretch`: plastic impulses at the base
points with Coulomb friction on the circular cone,
:mod:`freestand.core.contact.body_impulse`), which looks for a consistent
mode again as it goes and ends where one exists. :func:`watch_chatter`
counts the restarts and impacts that start a chatter's stretch;
:func:`held_row` and :func:`stretch_start_row` record which patch the time
stepping held. ``docs/three-d.md``, "Remedies".
"""

from __future__ import annotations

import math

from freestand.core.contact.body_impulse import (
    base_points,
    velocity_impact,
)
from freestand.core.contact.body_kernel import (
    D_PSI,
    EDGE,
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
    SC_ANGLES,
    SC_BASE,
    SC_EXCLUDED,
    SC_INDICES,
    SC_INV,
    SC_KINDS,
    SC_POINTS,
    SC_ROT,
    SC_TOUCHING,
    SHAPE_BOX,
    arm,
    corner_gap,
    cross,
    lowest_rim_angle,
    point_velocity,
    prepare,
    rotation_matrix,
)
from freestand.core.contact.body_modes import (
    ACCELERATION,
    candidates,
    chatter_look,
    clear_candidates,
    no_exclusion,
    select_mode,
    touching_points,
)
from freestand.core.contact.compiled import kernel
from freestand.core.dynamics.body_projection import (
    project,
    turn,
)
from freestand.core.dynamics.body_state import (
    EV_IMPACT,
    EV_REMEDY,
    EV_STICK,
    I_CHATTER,
    I_RECORDS,
    I_REMEDIES,
    I_STRETCH,
    I_STRETCH_STEPS,
)
from freestand.core.dynamics.body_step import slip_velocity

STRETCH_STEP = 1e-4  # [s] step of the velocity-level time stepping (the remedy)
STRETCH_CHECK = 16  # a stretch looks for a consistent mode at its steps 1, 2, 4, 8, 16, 32, 48, ...
STRETCH_IMPACT = 10.0  # a stretch's point approaching faster than this times g h lands [-]
CHATTER_WINDOW = 1e-3  # [s] slip restarts or remedies closer than this in time are a chatter
CHATTER_COUNT = 3  # this many in a row start a chatter stretch of the remedy
FACE_CHATTER_WINDOW = 1e-6  # [s] a FACE's slip restarts closer than this in time are a chatter
IMPACT_WINDOW = 1e-4  # [s] impacts closer than this in time (the remedy's step) accumulate
IMPACT_COUNT = 10  # this many accumulating impacts in a row start a stretch of the remedy


@kernel(cache=True, error_model="numpy", _nrt=False)
def set_free(mode):
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
    turn(y, velocity[3] * h, velocity[4] * h, velocity[5] * h)
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
def stretch_start_row(par, y, sc, gap_tol, velocity_tol, istate, force, patch,
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
def stretch_step(par, record, dt, t, h, y, mode, data, sc, gap_tol, velocity_tol, istate, force,
             impulses, work):  # fmt: skip
    """One step of the remedy; it ends where a consistent mode exists again. Returns t + h.

    The search for a consistent mode (:func:`select_mode`, whose slip onsets
    are costly where none exists) is made at the stretch's steps 1, 2, 4, 8
    and then every ``STRETCH_CHECK``: a short stretch stays short, and a long
    one lasts at most ``STRETCH_CHECK`` steps more than it must (a valid
    time-stepping solution all along). After each step the base points it
    holds above the support are set on it (:func:`_settle`). A chatter's stretch
    (:func:`_start_chatter`) looks every ``STRETCH_CHECK`` steps only, and
    goes on where a patch could only slip from rest (its speed within
    ``velocity_tol``; :func:`~freestand.core.contact.body_modes.chatter_look`,
    which does not seek that slip's onset, and a slip under way whose
    centre of pressure moves within ``velocity_tol``): that slip would
    chatter again.
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
        set_free(mode)
        return t + h
    if istate[I_CHATTER] == 1:
        # a chatter's stretch goes on while its patch could only slip from rest
        found = chatter_look(par, record, dt, t + h, y, sc, gap_tol, velocity_tol, mode, data)
    else:
        no_exclusion(sc)
        found = select_mode(par, record, dt, t + h, y, sc, gap_tol, velocity_tol, mode, data,
                            sc[SC_EXCLUDED])  # fmt: skip
    if found >= 0 and hovering and mode[M_KIND] == FREE:
        found = -1  # a point the stretch holds is still above the support: not a flight
    if found >= 0 and istate[I_CHATTER] == 1 and mode[M_SLIP] == 1:
        # a slip under way at its rows' centre, but from rest at its centre of pressure
        speed, _, _ = slip_velocity(par, record, dt, t + h, y, mode, data, sc)
        found = -1 if speed <= velocity_tol else 0
    if found >= 0:
        istate[I_STRETCH] = 0
        istate[I_CHATTER] = 0
        project(par, record, dt, t + h, y, mode, data, sc)
    else:
        set_free(mode)
    return t + h


@kernel(cache=True, error_model="numpy", _nrt=False)
def _horizontal_speed(y, d):
    """Horizontal speed [m/s] of the material point at arm d."""
    return math.hypot(point_velocity(y, d, 1.0, 0.0, 0.0), point_velocity(y, d, 0.0, 1.0, 0.0))


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
def set_on_support(par, y, sc, data, work):
    """The body raised so that no base point lies below the support (:func:`_settle` holding
    none): where a stretch starts at an event of a held mode, whose state a step's end has
    not projected (its held points within RK4's drift of the support)."""
    _settle(par, y, sc, data, -math.inf, 0.0, 0.0, work)


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
    another contact holds (:func:`stretch_step`).
    """
    if istate[I_STRETCH] == 0:
        istate[I_STRETCH] = 1
        if event != EV_REMEDY:
            istate[I_REMEDIES] += 1
    istate[I_CHATTER] = 1
    set_free(mode)
    return EV_REMEDY
