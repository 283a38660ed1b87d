"""Time-history simulation of a planar stack of rigid blocks.

Every block moves in the plane (x, z, phi) under the horizontal and vertical
support accelerations, with unilateral contacts, Coulomb friction (static to
hold, kinetic to slide), impacts, free flight and overturning.

Frame and coordinates: the support's translating frame (see
:mod:`freestand.core.contact.screening`). The generalised coordinates of block ``i``
are ``q_i = (u_x, u_z, phi)``: the displacement [m] of its centre of gravity
from its position at rest and its rotation [rad] about it, counter-clockwise
positive. The support acceleration ``a_h(t)`` [m/s^2] (+x) acts as the
inertial force ``-m a_h`` and the downward support acceleration ``a_v(t)``
reduces the weight to ``m (g - a_v)``.

The instantaneous contact problem is the one of :mod:`freestand.core.contact.problem`
(the screening engine's, solved by the compiled kernel of
:mod:`freestand.core.contact.engine`), built at a general configuration with the
velocity terms (:func:`contact_problem_in_motion`). The integration is event-driven and
runs compiled, the whole loop in :mod:`freestand.core.dynamics.engine`:

* the contact mode chosen by the kernel
  (:func:`~freestand.core.contact.engine.solve_contact_states`) is held while the
  smooth dynamics of that mode are integrated with Runge-Kutta (RK4) steps
  of at most :func:`default_step` under a sampled record (ending where its
  slope changes, :func:`record_breaks`) or ``max_step`` under a function;
  phases in which the whole stack rests on the support are not integrated
  (the forces are linear in the support accelerations);
* events end a step and are located to ``time_tolerance`` (regula falsi,
  Illinois variant, on the step's Hermite interpolant, Newton steps for a
  closing gap, then a checked bracket of RK4 states; bisection as fallback):
  a gap closing (impact: at zero where it was open by more than the event's
  slack, 1e-3 of the touching tolerance, at the step's start), a
  normal force reaching zero (lift-off), a slip velocity reaching zero
  (possible stick or reversal), a sticking interface's friction reaching the
  static cone (slip), a block sliding back onto its end stop, a block lying on
  its side;
* at an event the contact problem is solved again; at an impact the velocity
  jump is solved first (:func:`impact_problem`); a contact problem with no
  consistent state (Painleve's paradox) is resolved by a tangential impact,
  the same velocity-level problem in which sliding contacts may stick.

Impact law (Newton-type, perfectly plastic, as Housner 1963 assumes): the
contacts that touch receive impulses ``Lambda >= 0`` with post-impact normal
velocities ``v_n+ >= 0`` and ``Lambda v_n+ = 0`` (a closing contact stops),
``M (qd+ - qd-) = J^T Lambda``; the tangential impulse sticks
(``v_t+ = 0``) while inside the static cone ``|Lambda_t| <= mu_0 Lambda_n``,
else it slides with the kinetic coefficient. This is the same complementarity
problem as the one on accelerations (``qdd -> qd+ - qd-``, forces ->
impulses, bias -> pre-impact velocities) and is solved by the same solver.
For a single block rocking on a rigid base it is exactly Housner's
conservation of angular momentum about the new pivot, angular-velocity ratio
``1 - 2 m R^2 sin^2(alpha) / I_O`` (Housner 1963, eq. 4).

Overturning: a block is overturned when its rotation relative to the body
below reaches pi/2 (it lies on its side), or, once the excitation has ended,
when it is past its overturning angle (its centre beyond the pivot) and
cannot come back: it rotates away from upright, or its kinetic energy of
rotation about the pivot is below the potential-energy barrier
``m g (R - z_G)``, the body below being taken as fixed for this judgement.
Overturning is never declared at ``|phi| = alpha`` while the excitation
acts. An overturned block and the blocks on it are removed from the
simulation (their loads on the blocks below vanish; their states are NaN
from then on).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace

import numba as nb
import numpy as np

from freestand.core.contact.problem import ContactProblem, Interface
from freestand.core.contact.screening import GRAVITY
from freestand.core.dynamics import engine
from freestand.core.dynamics.results import (
    EVENT_TOLERANCE,
    METHODS,
    UPLIFT_GAP_FRACTION,
    ContactTolerances,
    SupportMotion,
    TimeHistoryDiagnostics,
    TimeHistoryEvent,
    TimeHistoryResult,
    history_peaks,
)
from freestand.core.model import Sliding, Stack

# --- excitation ---------------------------------------------------------------------------------

#: Default cap [s] on the time simulated after the excitation's end with ``until_rest``.
FREE_TIME = 10.0


Excitation = Callable[[float], tuple[float, float]]


# --- kinematics ---------------------------------------------------------------------------------


@dataclass(frozen=True)
class StackKinematics:
    """Contact kinematics of a stack at a configuration and velocity.

    Index ``[i, c]``: interface ``i`` (below block ``i``), contact ``c``
    (0 left, 1 right; the upper block's lower corners, body-fixed).

    Attributes
    ----------
    gap : numpy.ndarray
        Shape (I, 2): ``g = n . (P - Q)`` [m], n the rotated normal of the lower
        surface, P the contact point, Q a point of the lower surface.
    gap_velocity : numpy.ndarray
        Shape (I, 2): ``n . w`` [m/s], w the velocity of P relative to the
        coincident point of the lower body.
    slip_velocity : numpy.ndarray
        Shape (I, 2): ``t . w`` [m/s], t the rotated tangent of the lower surface.
    slide : numpy.ndarray
        Shape (I,): ``t . (P_L - X_L)`` [m], how far the left contact has slid
        along the lower surface from the lower body's material point it
        started on (0 at rest; its time derivative is the slip velocity).
    rotation : numpy.ndarray
        Shape (I,): rotation of each block relative to the body below [rad].
    normal_jacobian, tangential_jacobian : numpy.ndarray
        Shape (I, 2, n): rows of the gap and slip accelerations in ``qdd``.
    normal_bias, tangential_bias : numpy.ndarray
        Shape (I, 2): velocity terms of the gap and slip accelerations [m/s^2].
    """

    gap: np.ndarray
    gap_velocity: np.ndarray
    slip_velocity: np.ndarray
    slide: np.ndarray
    rotation: np.ndarray
    normal_jacobian: np.ndarray
    normal_bias: np.ndarray
    tangential_jacobian: np.ndarray
    tangential_bias: np.ndarray


def stack_geometry(stack: Stack) -> np.ndarray:
    """Geometry of a stack for :func:`stack_kinematics`, shape (B, 7).

    Per block: centre (x, z) [m], left contact (x, z) [m], right contact
    (x, z) [m], base level [m].
    """
    return np.array(
        [
            [*block.centre, *block.contacts[0], *block.contacts[1], block.base_level]
            for block in stack.blocks
        ],
        dtype=float,
    ).reshape(-1, 7)


def stack_kinematics(
    stack: Stack,
    position: np.ndarray,
    velocity: np.ndarray,
    geometry: np.ndarray | None = None,
) -> StackKinematics:
    """Gaps, relative velocities, Jacobians and velocity terms of every contact.

    Parameters
    ----------
    stack : Stack
        Blocks bottom to top.
    position : numpy.ndarray
        Shape (B, 3) or (3 B,): ``(u_x [m], u_z [m], phi [rad])`` of each block,
        the displacement of its centre from rest and its rotation.
    velocity : numpy.ndarray
        Same shape: ``(v_x [m/s], v_z [m/s], omega [rad/s])``.
    geometry : numpy.ndarray, optional
        :func:`stack_geometry` of the stack, if already at hand.

    Returns
    -------
    StackKinematics

    Notes
    -----
    For the contact point P of the upper body u on the surface of the lower
    body l (normal n, tangent t rotating with l; the support has
    ``n = (0, 1)``, ``t = (1, 0)``) with ``perp(x, z) = (-z, x)`` and
    ``w = Pdot - V_l - omega_l perp(P - G_l)``::

        gap acceleration = J_n qdd + b_n,
        J_n = [.., (n_x, n_z, n . perp(P - G_u)) for u, (-n_x, -n_z, -n . perp(P - G_l)) for l ..]
        b_n = -omega_u^2 n . (P - G_u) - omega_l n . perp(Pdot - V_l) + omega_l perp(n) . w

    and likewise with t for the slip acceleration. At rest (q = 0, qd = 0)
    the rows are those of the screening engine.
    """
    count = len(stack.blocks)
    if geometry is None:
        geometry = stack_geometry(stack)
    q = np.ascontiguousarray(position, dtype=float).reshape(-1)
    qd = np.ascontiguousarray(velocity, dtype=float).reshape(-1)
    size = 3 * count
    gap = np.empty((count, 2))
    gap_velocity = np.empty((count, 2))
    slip_velocity = np.empty((count, 2))
    slide = np.empty(count)
    rotation = np.empty(count)
    normal_jacobian = np.zeros((count, 2, size))
    tangential_jacobian = np.zeros((count, 2, size))
    normal_bias = np.empty((count, 2))
    tangential_bias = np.empty((count, 2))
    engine.kinematics(
        geometry, count, q, qd, gap, gap_velocity, slip_velocity, rotation,
        normal_jacobian, normal_bias, tangential_jacobian, tangential_bias, slide,
    )  # fmt: skip
    return StackKinematics(
        gap=gap,
        gap_velocity=gap_velocity,
        slip_velocity=slip_velocity,
        slide=slide,
        rotation=rotation,
        normal_jacobian=normal_jacobian,
        normal_bias=normal_bias,
        tangential_jacobian=tangential_jacobian,
        tangential_bias=tangential_bias,
    )


def _lower_contact(kin: StackKinematics, interface: int) -> int:
    """The contact (0 left, 1 right) with the smaller gap: the one whose slip counts."""
    return 0 if kin.gap[interface, 0] <= kin.gap[interface, 1] else 1


def _stop_engaged(sliding: Sliding, slide: float, tolerance: float) -> bool:
    if sliding is Sliding.NO_RIGHT:
        return slide >= -tolerance
    if sliding is Sliding.NO_LEFT:
        return slide <= tolerance
    return True


def contact_problem_in_motion(
    stack: Stack,
    position: np.ndarray,
    velocity: np.ndarray,
    inertial_acceleration: float,
    vertical: float,
    gravity: float = GRAVITY,
    tolerances: ContactTolerances | None = None,
    kinematics: StackKinematics | None = None,
) -> ContactProblem:
    """Build the contact problem of a stack at a general configuration and velocity.

    Parameters
    ----------
    stack : Stack
        Blocks bottom to top.
    position, velocity : numpy.ndarray
        Shape (B, 3) or (3 B,): ``(u_x [m], u_z [m], phi [rad])`` and their
        rates [m/s, rad/s] of each block (see :func:`stack_kinematics`).
    inertial_acceleration : float
        Signed horizontal inertial acceleration [m/s^2], ``-a_h`` for a
        support acceleration a_h.
    vertical : float
        Downward support acceleration a_v [m/s^2].
    gravity : float, optional
        g [m/s^2].
    tolerances : ContactTolerances, optional
    kinematics : StackKinematics, optional
        Precomputed kinematics at this state.

    Returns
    -------
    ContactProblem
        With the velocity terms; a contact is active when it touches and does
        not separate; the slip velocity is that of the contact with the smaller gap (zero
        within the tolerance, and always zero where sliding is impossible);
        an end stop is engaged when the block is back at its parking
        position. At rest this is :func:`~freestand.core.contact.screening.contact_problem_at_rest`.
    """
    tolerances = tolerances or ContactTolerances()
    kin = kinematics or stack_kinematics(stack, position, velocity)
    count = len(stack.blocks)
    size = 3 * count
    mass_matrix = np.zeros((size, size))
    applied = np.zeros(size)
    effective_gravity = gravity - vertical
    interfaces = []
    for i, block in enumerate(stack.blocks):
        mass_matrix[3 * i, 3 * i] = block.mass
        mass_matrix[3 * i + 1, 3 * i + 1] = block.mass
        mass_matrix[3 * i + 2, 3 * i + 2] = block.inertia
        applied[3 * i] = block.mass * inertial_acceleration
        applied[3 * i + 1] = -block.mass * effective_gravity
        active = tuple(
            bool(kin.gap[i, c] <= tolerances.gap and kin.gap_velocity[i, c] <= tolerances.velocity)
            for c in range(2)
        )
        slip = float(kin.slip_velocity[i, _lower_contact(kin, i)])
        if abs(slip) <= tolerances.velocity or block.sliding is Sliding.NONE:
            slip = 0.0
        interfaces.append(
            Interface(
                normal_jacobian=kin.normal_jacobian[i],
                normal_bias=kin.normal_bias[i],
                tangential_jacobian=kin.tangential_jacobian[i],
                tangential_bias=kin.tangential_bias[i],
                static_friction=block.friction.static,
                kinetic_friction=block.friction.kinetic,
                sliding=block.sliding,
                active=active,
                slip_velocity=slip,
                stop_engaged=_stop_engaged(block.sliding, float(kin.slide[i]), tolerances.slide),
            )
        )
    total_mass = sum(block.mass for block in stack.blocks)
    acceleration_scale = max(float(np.hypot(inertial_acceleration, effective_gravity)), 1e-12)
    return ContactProblem(
        mass_matrix=mass_matrix,
        applied_force=applied,
        interfaces=tuple(interfaces),
        force_scale=total_mass * acceleration_scale,
        acceleration_scale=acceleration_scale,
    )


def impact_problem(
    stack: Stack,
    position: np.ndarray,
    velocity: np.ndarray,
    tolerances: ContactTolerances | None = None,
    kinematics: StackKinematics | None = None,
    allow_stick: bool = False,
) -> ContactProblem:
    """The velocity-jump (impact) problem of a stack, in the contact solver's form.

    Unknowns: the velocity jump ``dqd = qd+ - qd-`` [m/s, rad/s] (in place of
    ``qdd``) and the normal and tangential impulses [N s] (in place of the
    forces) of every touching contact::

        M dqd = sum J^T Lambda,  v_n+ = J_n dqd + J_n qd- >= 0,  Lambda_n >= 0,
        Lambda_n v_n+ = 0,  stick v_t+ = 0 while |Lambda_t| <= mu_0 Lambda_n

    Perfectly plastic (no rebound), Newton-type; for a single block it is
    Housner's (1963, eq. 4) conservation of angular momentum about the new
    pivot.

    Parameters
    ----------
    stack : Stack
    position, velocity : numpy.ndarray
        State just before the impact (see :func:`stack_kinematics`).
    tolerances : ContactTolerances, optional
    kinematics : StackKinematics, optional
    allow_stick : bool, optional
        Let sliding contacts stick (static cone) instead of taking the kinetic
        impulse against their slip: the tangential impact that resolves a
        Painleve-type inconsistency of the contact problem.

    Returns
    -------
    ContactProblem
        Solve with :func:`~freestand.core.contact.engine.solve`; the chosen
        solution's ``acceleration`` is the velocity jump, its forces the
        impulses.
    """
    tolerances = tolerances or ContactTolerances()
    kin = kinematics or stack_kinematics(stack, position, velocity)
    qd = np.asarray(velocity, dtype=float).reshape(-1)
    count = len(stack.blocks)
    size = 3 * count
    mass_matrix = np.zeros((size, size))
    interfaces = []
    speeds = [tolerances.velocity]
    for i, block in enumerate(stack.blocks):
        mass_matrix[3 * i, 3 * i] = block.mass
        mass_matrix[3 * i + 1, 3 * i + 1] = block.mass
        mass_matrix[3 * i + 2, 3 * i + 2] = block.inertia
        normal_velocity = kin.normal_jacobian[i] @ qd
        tangential_velocity = kin.tangential_jacobian[i] @ qd
        speeds.extend(np.abs(normal_velocity))
        speeds.extend(np.abs(tangential_velocity))
        engaged = _stop_engaged(block.sliding, float(kin.slide[i]), tolerances.slide)
        slip = float(kin.slip_velocity[i, _lower_contact(kin, i)])
        effective = block.sliding
        if effective in (Sliding.NO_LEFT, Sliding.NO_RIGHT) and not engaged:
            effective = Sliding.FREE
        if (
            allow_stick
            or abs(slip) <= tolerances.velocity
            or not effective.allows(int(np.sign(slip)))
        ):
            slip = 0.0
        interfaces.append(
            Interface(
                normal_jacobian=kin.normal_jacobian[i],
                normal_bias=normal_velocity,
                tangential_jacobian=kin.tangential_jacobian[i],
                tangential_bias=tangential_velocity,
                static_friction=block.friction.static,
                kinetic_friction=block.friction.kinetic,
                sliding=block.sliding,
                active=tuple(bool(kin.gap[i, c] <= tolerances.gap) for c in range(2)),
                slip_velocity=slip,
                stop_engaged=engaged,
            )
        )
    speed_scale = float(max(speeds))
    total_mass = sum(block.mass for block in stack.blocks)
    return ContactProblem(
        mass_matrix=mass_matrix,
        applied_force=np.zeros(size),
        interfaces=tuple(interfaces),
        force_scale=total_mass * speed_scale,
        acceleration_scale=speed_scale,
    )


# --- results ------------------------------------------------------------------------------------


# --- simulation ---------------------------------------------------------------------------------


#: Order in which simultaneous events are reported.
_EVENT_PRIORITY = ("overturn", "impact", "stop-impact", "lift-off", "slip", "slip-stop")


def simulate(
    stack: Stack,
    excitation: SupportMotion | Excitation,
    duration: float | None = None,
    *,
    method: str = "auto",
    max_step: float | None = None,
    gravity: float = GRAVITY,
    initial_position: np.ndarray | None = None,
    initial_velocity: np.ndarray | None = None,
    excitation_end: float | None = None,
    tolerances: ContactTolerances | None = None,
    time_tolerance: float = 1e-9,
    max_events: int = 100_000,
    restitution: float | Sequence[float] | None = None,
    progress: Callable[[float], None] | None = None,
    until_rest: bool = False,
    free_time: float = FREE_TIME,
) -> TimeHistoryResult:
    """Simulate the planar motion of a stack under support accelerations (front end).

    Parameters
    ----------
    stack, excitation, duration, gravity, initial_position,
    initial_velocity, excitation_end, tolerances, time_tolerance, max_events
        As for :func:`simulate_general`.
    max_step : float, optional
        Largest integration step [s]; by default, under a sampled record,
        0.02 / p for both paths (:func:`default_step`; the steps also end
        where the record's slope changes), and 1 ms for the general path
        driven by a function.
    restitution : float or sequence of float, optional
        Factor [-] in [0, 1] on the post-impact velocity of each interface's
        upper block relative to the body below (one value, or one per
        block); 1 (default) keeps the plastic impact law (Housner's for one
        block). With a factor below 1 the general path is used.
    progress : callable, optional
        Called with the fraction [-] of the duration simulated, about 100
        times during a general-path simulation.
    method : str, optional
        ``"general"``: the event-driven stack path (:func:`simulate_general`).
        ``"single-block"``: the exact single-block equations
        (:func:`freestand.core.dynamics.single_block.simulate_single_block`) for one
        block on the support under a :class:`SupportMotion`, starting at rest;
        when their assumptions fail (slide-rock, free flight, sliding against
        an end stop) the general path runs instead and
        ``diagnostics.fallback`` says why. ``"auto"`` (default): the
        single-block path wherever it applies, else the general path.
    until_rest : bool, optional
        Go on after the excitation until the stack is back at rest, every
        block has overturned, or the cap (see :func:`simulate_general`).
    free_time : float, optional
        With ``until_rest``, the cap [s] after the excitation's end when no
        ``duration`` is given (default :data:`FREE_TIME`).

    Returns
    -------
    TimeHistoryResult
        ``diagnostics.method`` names the path that produced it.
    """
    if method not in METHODS:
        raise ValueError(f"unknown method {method!r}; use one of {', '.join(METHODS)}")
    general = dict(
        max_step=max_step,
        gravity=gravity,
        initial_position=initial_position,
        initial_velocity=initial_velocity,
        excitation_end=excitation_end,
        tolerances=tolerances,
        time_tolerance=time_tolerance,
        max_events=max_events,
        restitution=restitution,
        progress=progress,
        until_rest=until_rest,
        free_time=free_time,
    )
    plastic = restitution is None or bool(np.all(np.asarray(restitution, dtype=float) == 1.0))
    if method == "general" or (method == "auto" and not plastic):
        return simulate_general(stack, excitation, duration, **general)
    at_rest = all(
        value is None or not np.any(np.asarray(value, dtype=float))
        for value in (initial_position, initial_velocity)
    )
    applicable = len(stack.blocks) == 1 and isinstance(excitation, SupportMotion) and at_rest
    if not applicable:
        if method == "single-block":
            raise ValueError(
                "the single-block path needs a stack of one block, a sampled SupportMotion "
                "and a start at rest; use method='general' or 'auto'"
            )
        return simulate_general(stack, excitation, duration, **general)
    from freestand.core.dynamics.single_block import simulate_single_block

    if until_rest:
        exc_end = excitation.duration if excitation_end is None else float(excitation_end)
        cap = _rest_cap(exc_end, duration, free_time)
    else:
        cap = duration
    attempt = simulate_single_block(
        stack,
        excitation,
        cap,
        max_step=max_step,
        gravity=gravity,
        excitation_end=excitation_end,
        until_rest=until_rest,
    )
    if attempt.result is not None:
        return attempt.result
    result = simulate_general(stack, excitation, duration, **general)
    return replace(
        result,
        diagnostics=replace(result.diagnostics, checks=attempt.checks, fallback=attempt.failure),
    )


def simulate_general(
    stack: Stack,
    excitation: SupportMotion | Excitation,
    duration: float | None = None,
    *,
    max_step: float | None = None,
    gravity: float = GRAVITY,
    initial_position: np.ndarray | None = None,
    initial_velocity: np.ndarray | None = None,
    excitation_end: float | None = None,
    tolerances: ContactTolerances | None = None,
    time_tolerance: float = 1e-9,
    max_events: int = 100_000,
    restitution: float | Sequence[float] | None = None,
    progress: Callable[[float], None] | None = None,
    until_rest: bool = False,
    free_time: float = FREE_TIME,
) -> TimeHistoryResult:
    """Simulate the planar motion of a stack under support accelerations (general path).

    Parameters
    ----------
    stack : Stack
        Blocks bottom to top, at rest in their model positions at ``q = 0``.
    excitation : SupportMotion or callable
        The support accelerations: a :class:`SupportMotion` (sampled,
        piecewise linear) or a function ``t [s] -> (a_h [m/s^2], a_v [m/s^2])``
        with a_h horizontal (+x) and a_v downward.
    duration : float, optional
        End time [s]; by default the end of a :class:`SupportMotion`. Required
        for a callable.
    max_step : float, optional
        Largest integration step [s]. With a :class:`SupportMotion` by
        default :func:`default_step`, and steps also end where the record's
        slope changes (:func:`record_breaks`); with a function 1 ms by
        default, the steps dividing the duration evenly.
    gravity : float, optional
        g [m/s^2].
    initial_position, initial_velocity : numpy.ndarray, optional
        Shape (B, 3) or (3 B,): initial ``(u_x, u_z, phi)`` [m, m, rad] and
        rates; zero (rest) by default. The initial position must not
        penetrate.
    excitation_end : float, optional
        Time [s] after which the excitation is over, for the overturning
        judgement (see the module notes); by default the end of a
        :class:`SupportMotion`, or ``duration`` for a callable.
    tolerances : ContactTolerances, optional
    time_tolerance : float, optional
        Events are located to this time [s] by bisection.
    max_events : int, optional
        The simulation fails (reported) after this many events.
    restitution : float or sequence of float, optional
        Factor [-] in [0, 1] on the post-impact velocity of each interface's
        upper block relative to the body below, applied where the interface
        took an impulse; 1 (default): the plastic impact law.
    progress : callable, optional
        ``progress(fraction)`` is called with the fraction [-] of the
        duration simulated, about every 1 % of it, and with 1 at the end.
    until_rest : bool, optional
        Go on after the excitation's end (``excitation_end``; the excitation
        is zero after it) until the stack is back at rest, or every block has
        overturned, or the cap: ``duration`` when given, else
        ``excitation_end + free_time``. At rest means the rest state: every
        interface sticks with both contacts closed (the held contact mode)
        and no coordinate moves faster than 1e-9 [m/s, rad/s] (impacts and
        slips slower than ``tolerances.velocity`` end in this state); it is
        checked at every step after the excitation's end. Status
        ``"completed"`` (at rest, message ``"at rest at t = ..."``, or
        every block overturned) or ``"capped"`` (still moving at the cap).
    free_time : float, optional
        The cap [s] after the excitation's end when no ``duration`` is given
        (default :data:`FREE_TIME`, 10 s).

    Returns
    -------
    TimeHistoryResult
    """
    count = len(stack.blocks)
    if count == 0:
        raise ValueError("the stack has no block")
    sampled = isinstance(excitation, SupportMotion)
    if sampled:
        end = excitation.duration if duration is None else float(duration)
        if excitation_end is None:
            excitation_end = excitation.duration
    else:
        if duration is None:
            raise ValueError("give the duration [s] of a simulation driven by a function")
        end = float(duration)
        if excitation_end is None:
            excitation_end = end
        if until_rest:
            function = excitation
            stop = float(excitation_end)

            def excitation(time: float) -> tuple[float, float]:
                return function(time) if time <= stop else (0.0, 0.0)

    if until_rest:
        end = _rest_cap(float(excitation_end), duration, free_time)
    if not end > 0.0:
        raise ValueError(f"duration must be positive, not {end!r}")
    if max_step is not None and not max_step > 0.0:
        raise ValueError(f"max_step must be positive, not {max_step!r}")
    factors = _restitution_factors(restitution, count)
    tolerances = tolerances or ContactTolerances()
    if sampled:
        step = default_step(stack, gravity) if max_step is None else float(max_step)
        dt = excitation.time_step
        # fresh, writeable copies: one compiled signature whatever the caller's arrays
        horizontal = np.array(excitation.horizontal, dtype=float)
        vertical = (
            np.zeros_like(horizontal)
            if excitation.vertical is None
            else np.array(excitation.vertical, dtype=float)
        )
        breaks = record_breaks(dt, horizontal, vertical)
        if breaks.size > 8.0 * breaks[-1] / step + 1.0:
            # a record whose slope changes at nearly every sample, sampled far finer
            # than the step: steps of at most 8 samples, across its kinks
            step = min(step, 8.0 * dt)
            breaks = breaks[-1:]
    else:
        # a function: fixed steps; sampled at the step ends and midpoints, where
        # RK4 evaluates it, and linear in between (for event location only)
        max_step = 1e-3 if max_step is None else float(max_step)
        steps_count = max(1, math.ceil(end / max_step - 1e-9))
        step = end / steps_count
        dt = 0.5 * step
        times = np.arange(2 * steps_count + 1) * dt
        values = np.array([excitation(float(t)) for t in times], dtype=float).reshape(-1, 2)
        horizontal = np.array(values[:, 0])
        vertical = np.array(values[:, 1])
        breaks = np.arange(1, steps_count + 1) * step
    q = np.zeros(3 * count) if initial_position is None else np.array(initial_position, float)
    qd = np.zeros(3 * count) if initial_velocity is None else np.array(initial_velocity, float)
    q = np.ascontiguousarray(q.reshape(-1), dtype=float).copy()
    qd = np.ascontiguousarray(qd.reshape(-1), dtype=float).copy()
    if q.size != 3 * count or qd.size != 3 * count:
        raise ValueError(f"initial position and velocity need {3 * count} values (3 per block)")

    model = engine_model(stack, factors)
    _load_engine()
    total_mass = sum(block.mass for block in stack.blocks)
    params = np.zeros(engine.P_SIZE)
    params[engine.P_GRAVITY] = gravity
    params[engine.P_TOL_GAP] = tolerances.gap
    params[engine.P_TOL_VEL] = tolerances.velocity
    params[engine.P_TOL_SLIDE] = tolerances.slide
    params[engine.P_TIME_TOL] = time_tolerance
    params[engine.P_FORCE_EVENT] = EVENT_TOLERANCE * total_mass * gravity
    params[engine.P_GAP_EVENT] = 1e-3 * tolerances.gap
    params[engine.P_EXC_END] = excitation_end
    params[engine.P_END] = end
    params[engine.P_STEP] = step
    params[engine.P_EXC_DT] = dt
    params[engine.P_UNTIL_REST] = 1.0 if until_rest else 0.0
    params[engine.P_QUIET] = quiet_from(dt, horizontal, vertical)
    istate = np.zeros(engine.S_SIZE, dtype=np.int64)
    istate[engine.S_ACTIVE] = count
    fstate = np.zeros(engine.F_SIZE)
    flags = np.zeros((6, count))
    flags[3] = np.nan
    slide = np.zeros(count)
    mode = np.zeros((count, 3), dtype=np.int64)
    directions = np.zeros(count, dtype=np.int64)
    rows = int(min(end / step * 1.1 + 2 * np.count_nonzero(breaks < end) + 64, 1_000_000))
    rec = _record_buffers(rows, count)
    ev = _event_buffers(256, count)
    chunk = end / 100.0 if progress is not None else math.inf
    exc = (horizontal, vertical)
    while True:
        chunk_end = fstate[engine.F_TIME] + chunk
        outcome = engine.run(
            model, exc, breaks, params, step, max_events, chunk_end, q, qd, slide, mode,
            directions, istate, fstate, flags, rec, ev,
        )  # fmt: skip
        if outcome == engine.BUFFER_FULL:
            used = int(istate[engine.S_ROWS])
            if used + 4 > rec[0].shape[0]:
                rec = _grow(rec, 2 * rec[0].shape[0])
            if int(istate[engine.S_EVENTS]) + 4 > ev[0].shape[0]:
                ev = _grow(ev, 2 * ev[0].shape[0])
            continue
        if outcome == engine.CHUNK_DONE:
            progress(min(fstate[engine.F_TIME] / end, 1.0))
            continue
        break
    if progress is not None:
        progress(1.0)
    result = _result(stack, count, end, step, max_events, istate, fstate, flags, rec, ev, outcome)
    if until_rest and result.status == "completed" and not result.overturned.all():
        if istate[engine.S_AT_REST]:
            message = f"at rest at t = {fstate[engine.F_TIME]:.6g} s"
            if result.overturned.any():
                message += result.message[result.message.find(";") :]
            result = replace(result, message=message)
        else:
            result = replace(
                result,
                status="capped",
                message=f"still moving at the cap, t = {fstate[engine.F_TIME]:.6g} s",
            )
    return result


@functools.cache
def _load_engine() -> int:
    """Once per process, the engine's hot kernels from numba's cache before its loop.

    See :func:`freestand.core.dynamics.engine.load_cached_kernels`: the loop
    then calls their own compiled code, 5-15 % faster than its copies.
    Returns the number of overloads loaded.
    """
    return engine.load_cached_kernels(engine.HOT_KERNELS)


def _rest_cap(excitation_end: float, duration: float | None, free_time: float) -> float:
    """End [s] of a run that goes on until rest: ``duration``, else the excitation's end + cap."""
    if duration is not None:
        return float(duration)
    if not (free_time >= 0.0 and math.isfinite(free_time)):
        raise ValueError(f"free_time must be a finite time >= 0 [s], not {free_time!r}")
    return excitation_end + free_time


def default_step(stack: Stack, gravity: float = GRAVITY) -> float:
    """Default largest step [s] of the general path under a sampled record.

    ``0.05 / p``, with ``p = sqrt(m g R / I_O)`` the largest rocking frequency
    parameter of the stack's blocks about either lower contact (Housner 1963),
    and at most 20 ms. RK4's error per step scales as ``(p h)^5``: about
    3e-7 of the motion's scale per step (the single-block integrator, whose
    step is 0.02 / p, converges to 1e-10 rad at such steps). Steps also end
    where the record's slope changes (see :func:`record_breaks`).
    """
    largest = 0.0
    for block in stack.blocks:
        height = block.centre[1] - block.base_level
        for lever in (block.centre[0] - block.base_left, block.base_right - block.centre[0]):
            radius = math.hypot(lever, height)
            inertia = block.inertia + block.mass * radius**2
            largest = max(largest, math.sqrt(block.mass * gravity * radius / inertia))
    return min(0.05 / largest, 0.02) if largest > 0.0 else 0.02


def record_breaks(time_step: float, *components: np.ndarray) -> np.ndarray:
    """Times [s] at which the piecewise-linear record changes slope, and its end.

    A sample is a break point when the second difference of any component
    (horizontal and vertical; x, y and vertical in 3-D) is not zero (beyond
    1e-12 of the component's peak). Steps end there, so that RK4 never steps
    across a kink: sliding under a piecewise-linear record is then integrated
    exactly, and a record resampled finely from a coarser one costs no more
    steps than the coarse one.
    """
    return record_row_breaks(float(time_step), np.array(components, dtype=float))


@nb.njit(cache=True, error_model="numpy")
def record_row_breaks(time_step, record):
    """:func:`record_breaks` of the components in the rows of ``record`` (C, n), in one call.

    ``time_step`` [s]; returns the times [s] of the break points, ascending.
    """
    count = record.shape[1]
    kinks = np.zeros(count, dtype=np.bool_)
    for row in range(record.shape[0]):
        _mark_kinks(record[row], kinks)
    kinks[count - 1] = True
    breaks = np.empty(np.count_nonzero(kinks))
    found = 0
    for i in range(count):
        if kinks[i]:
            breaks[found] = i * time_step
            found += 1
    return breaks


@nb.njit(cache=True, error_model="numpy")
def _mark_kinks(values, kinks):
    """Set ``kinks[i]`` where the second difference of ``values`` at i exceeds 1e-12 of its peak.

    One pass for the peak, one for the differences (:func:`record_breaks`;
    in numpy, its temporary arrays took 50 us of a 3-D run's 3 ms).
    """
    scale = 0.0
    for value in values:
        scale = max(scale, abs(value))
    scale = max(scale, 1e-300)
    for i in range(1, values.size - 1):
        if abs(values[i + 1] - 2.0 * values[i] + values[i - 1]) > 1e-12 * scale:
            kinks[i] = True


def quiet_from(time_step: float, horizontal: np.ndarray, vertical: np.ndarray) -> float:
    """Time [s] from which the support no longer accelerates: every later sample is zero.

    The samples are joined by straight lines (zero after the last), so the
    support is still from the sample after the last non-zero one; 0 for a
    record of zeros.
    """
    moving = np.flatnonzero((horizontal != 0.0) | (vertical != 0.0))
    return float((moving[-1] + 1) * time_step) if moving.size else 0.0


def engine_model(stack: Stack, restitution: np.ndarray) -> engine.Model:
    """The arrays of :mod:`freestand.core.dynamics.engine` describing a stack."""
    mass = np.array([[b.mass, b.mass, b.inertia] for b in stack.blocks], dtype=float).reshape(-1)
    codes = {Sliding.FREE: 0, Sliding.NONE: 1, Sliding.NO_RIGHT: 2, Sliding.NO_LEFT: 3}
    properties = np.array(
        [
            [b.friction.static for b in stack.blocks],
            [b.friction.kinetic for b in stack.blocks],
            restitution,
            [b.base_left for b in stack.blocks],
            [b.base_right for b in stack.blocks],
            [b.base_level for b in stack.blocks],
        ],
        dtype=float,
    )
    return engine.Model(
        geometry=stack_geometry(stack),
        masses=np.array([mass, 1.0 / mass]),
        properties=properties,
        codes=np.array([codes[b.sliding] for b in stack.blocks], dtype=np.int64),
    )


def _restitution_factors(restitution, count: int) -> np.ndarray:
    if restitution is None:
        return np.ones(count)
    values = np.broadcast_to(np.asarray(restitution, dtype=float), (count,)).copy()
    if not np.all((values >= 0.0) & (values <= 1.0)):
        raise ValueError(
            "restitution factors must lie in [0, 1] (1: the plastic impact law), "
            f"not {restitution!r}"
        )
    return values


def _record_buffers(rows: int, count: int) -> tuple:
    return (np.empty(rows), np.empty((rows, count, engine.R_SIZE)))


def _event_buffers(rows: int, count: int) -> tuple:
    return (
        np.empty(rows),
        np.empty((rows, engine.EV_MOTIONS + count), dtype=np.int64),
        np.empty((rows, 2, count, 3)),
    )


def _grow(buffers: tuple, rows: int) -> tuple:
    grown = []
    for array in buffers:
        bigger = np.empty((rows, *array.shape[1:]), dtype=array.dtype)
        bigger[: array.shape[0]] = array
        grown.append(bigger)
    return tuple(grown)


@nb.njit(cache=True)
def _history_columns(values, rows):
    """The first ``rows`` rows of the engine's history buffer, one array per quantity.

    ``values`` (capacity, B, :data:`~freestand.core.dynamics.engine.R_SIZE`);
    returns position, velocity (rows, B, 3), normal forces (rows, B, 2),
    tangential force, relative rotation and slide (rows, B): contiguous
    copies, in one pass (numpy's copies of the interleaved columns cost several
    times more).
    """
    count = values.shape[1]
    position = np.empty((rows, count, 3))
    velocity = np.empty((rows, count, 3))
    normal = np.empty((rows, count, 2))
    tangential = np.empty((rows, count))
    rotation = np.empty((rows, count))
    slide = np.empty((rows, count))
    for row in range(rows):
        for i in range(count):
            for c in range(3):
                position[row, i, c] = values[row, i, engine.R_Q + c]
                velocity[row, i, c] = values[row, i, engine.R_QD + c]
            normal[row, i, 0] = values[row, i, engine.R_NORMAL]
            normal[row, i, 1] = values[row, i, engine.R_NORMAL + 1]
            tangential[row, i] = values[row, i, engine.R_TANGENTIAL]
            rotation[row, i] = values[row, i, engine.R_ROTATION]
            slide[row, i] = values[row, i, engine.R_SLIDE]
    return position, velocity, normal, tangential, rotation, slide


def _painleve_reason(stack: Stack, position: np.ndarray, velocity: np.ndarray) -> str:
    """Why no contact mode is consistent at the last recorded state, in words.

    No mode satisfies the unilateral and Coulomb conditions together, and the
    tangential impact that should resolve it (Painleve's paradox: a block
    sliding on one corner, the friction force raising the normal load faster
    than it can support it) finds no velocity jump that does: the rigid-body
    model with Coulomb friction has no solution there. Names the interfaces
    that slide on one contact, with their rotation and friction.
    """
    if position.shape[0] == 0:
        return ""
    q = position[-1].reshape(-1)
    qd = velocity[-1].reshape(-1)
    active = int(np.count_nonzero(np.isfinite(q)) // 3)
    reason = (
        " (no contact mode satisfies the unilateral and Coulomb conditions and no "
        "tangential impact resolves it: a Painleve-type inconsistency of the rigid-body "
        "model with Coulomb friction"
    )
    if active == 0:
        return reason + ")"
    sub = Stack(stack.name, stack.blocks[:active])
    kin = stack_kinematics(sub, q[: 3 * active], qd[: 3 * active])
    tol = ContactTolerances()
    found = []
    for i, block in enumerate(sub.blocks):
        touching = kin.gap[i] <= tol.gap
        slip = kin.slip_velocity[i, _lower_contact(kin, i)]
        if touching.sum() == 1 and block.sliding is Sliding.NONE:
            # unbounded friction: the pivot unloads (N -> 0) while the rocking still
            # needs a tangential force there; free flight would press the corner into the
            # base, and sliding (the limit of a finite mu, which slips just before) is
            # excluded: no contact mode is consistent
            found.append(
                f"{block.name} rocks on one contact with sliding = 'none' (unbounded "
                f"friction), rotated {kin.rotation[i]:.3g} rad on the body below: its pivot "
                "unloads while carrying a tangential force, and it may neither slide nor "
                "fly; give the interface a finite friction (sliding = 'free') to let it "
                "slip there"
            )
        elif touching.sum() == 1 and abs(slip) > tol.velocity:
            found.append(
                f"{block.name} slides on one contact at {slip:.3g} m/s, rotated "
                f"{kin.rotation[i]:.3g} rad on the body below, mu_0 = "
                f"{block.friction.static:.3g}, mu = {block.friction.kinetic:.3g}"
            )
    if found:
        reason += "; " + "; ".join(found)
    return reason + ")"


def _result(stack, count, end, step, max_events, istate, fstate, flags, rec, ev, outcome):
    rows = int(istate[engine.S_ROWS])
    time = fstate[engine.F_TIME]
    times = rec[0][:rows].copy()
    position, velocity, normal, tangential, rotation, slides = _history_columns(rec[1], rows)
    events = []
    count_events = int(istate[engine.S_EVENTS])
    velocity_before = ev[2][:count_events, 0].copy()
    velocity_after = ev[2][:count_events, 1].copy()
    motion_names: dict[tuple[int, ...], tuple[str, ...]] = {}
    codes_of = ev[1][:count_events]
    # every event's (B, 3) rows as views, taken at once; cut to the active blocks
    # only where blocks have overturned
    for event_time, codes, motions, rows_before, rows_after in zip(
        ev[0][:count_events].tolist(),
        codes_of[:, : engine.EV_MOTIONS].tolist(),
        map(tuple, codes_of[:, engine.EV_MOTIONS :].tolist()),
        list(velocity_before),
        list(velocity_after),
        strict=True,
    ):
        kind, interface, contact, status, before, after = codes
        names = motion_names.get(motions)
        if names is None:
            names = motion_names[motions] = tuple(engine.MOTION_NAMES[m] for m in motions)
        events.append(
            TimeHistoryEvent._from_engine(
                event_time,
                engine.EVENT_KINDS[kind],
                interface,
                contact,
                names,
                rows_before if before == count else rows_before[:before],
                rows_after if after == count else rows_after[:after],
                "ambiguous" if status else "unique",
            )
        )
    overturned = flags[2] > 0.5
    overturn_time = flags[3].copy()
    status = "completed"
    message = ""
    if outcome == engine.FAILED:
        status = "failed"
        failure = int(istate[engine.S_FAILURE])
        if failure == engine.SINGULAR_MODE:
            message = f"singular contact mode at t = {time:.6g} s"
        elif failure == engine.STALLED:
            kind = events[-1].kind if events else "event"
            message = f"events repeat without progress at t = {time:.9g} s ({kind})"
        elif failure == engine.TOO_MANY_EVENTS:
            message = f"more than {max_events} events by t = {time:.6g} s"
        else:
            where = "at t = 0" if time == 0.0 else f"at t = {time:.6g} s"
            message = f"{where}: {engine.FAILURES[failure]}"
            if failure in (engine.CONTACT_INCONSISTENT, engine.CONTACT_INCONSISTENT_AFTER):
                message += _painleve_reason(stack, position, velocity)
    elif overturned.all():
        message = f"every block overturned (by t = {np.nanmax(overturn_time):.6g} s)"
    else:
        message = f"simulated to t = {time:.6g} s"
        if overturned.any():
            names = ", ".join(b.name for b, o in zip(stack.blocks, overturned, strict=True) if o)
            message += f"; overturned: {names}"
    stretches = tuple(
        (engine.FAILURES[cause], int(istate[engine.S_REMEDY + cause]))
        for cause in range(1, len(engine.FAILURES))
        if istate[engine.S_REMEDY + cause] > 0
    )
    stepped_time = float(fstate[engine.F_STEPPED_TIME])
    if stretches and status != "failed":
        total = sum(number for _, number in stretches)
        message += (
            f"; time stepping over {stepped_time:.3g} s in {total} stretch"
            f"{'es' if total > 1 else ''} where events could not continue "
            f"({', '.join(f'{cause}: {number}' for cause, number in stretches)})"
        )
    max_lift = flags[4].copy()
    max_flight = flags[5].copy()
    lift_threshold = UPLIFT_GAP_FRACTION * np.array(
        [block.base_right - block.base_left for block in stack.blocks]
    )
    uplift = (flags[0] > 0.5) & (max_lift > lift_threshold)
    free_flight = (flags[1] > 0.5) & (max_flight > lift_threshold)
    relative_rate = velocity[:, :, 2].copy()
    relative_rate[:, 1:] -= velocity[:, :-1, 2]
    max_rotation, max_slide = history_peaks(times, rotation, relative_rate, slides)
    return TimeHistoryResult(
        configuration=stack.name,
        block_names=tuple(block.name for block in stack.blocks),
        status=status,
        message=message,
        time=times,
        position=position,
        velocity=velocity,
        normal_force=normal,
        tangential_force=tangential,
        relative_rotation=rotation,
        slide=slides,
        events=tuple(events),
        max_rotation=max_rotation,
        max_slide=max_slide,
        uplift=uplift,
        free_flight=free_flight,
        overturned=overturned,
        overturn_time=overturn_time,
        diagnostics=TimeHistoryDiagnostics(
            time_step=step,
            steps=int(istate[engine.S_STEPS]),
            contact_solves=int(istate[engine.S_CONTACT_SOLVES]),
            impact_solves=int(istate[engine.S_IMPACT_SOLVES]),
            ambiguous_solves=int(istate[engine.S_AMBIGUOUS]),
            max_penetration=float(fstate[engine.F_MAX_PENETRATION]),
            max_projection=float(fstate[engine.F_MAX_PROJECTION]),
            stepped_time=stepped_time,
            stretches=stretches,
            energy_ratio=float(fstate[engine.F_ENERGY_RATIO]),
            dissipative_impacts=int(istate[engine.S_DISSIPATIVE_IMPACTS]),
            zeno_landings=int(istate[engine.S_ZENO]),
        ),
        max_lift=max_lift,
    )
