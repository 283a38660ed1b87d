"""Time-history simulation of a planar stack of rigid blocks.

Every block moves in the plane (x, z, phi) under the horizontal and vertical
support accelerations, with unilateral contacts, Coulomb friction (static to
hold, kinetic to slide), impacts, free flight and overturning.

Frame and coordinates: the support's translating frame (see
:mod:`freestand.core.screening`). The generalised coordinates of block ``i``
are ``q_i = (u_x, u_z, phi)``: the displacement [m] of its centre of gravity
from its position at rest and its rotation [rad] about it, counter-clockwise
positive. The support acceleration ``a_h(t)`` [m/s^2] (+x) acts as the
inertial force ``-m a_h`` and the downward support acceleration ``a_v(t)``
reduces the weight to ``m (g - a_v)``.

The instantaneous contact problem is the one of :mod:`freestand.core.contact`
(the screening engine's), built at a general configuration with the velocity
terms (:func:`contact_problem_in_motion`). The integration is event-driven:

* the contact mode chosen by :func:`~freestand.core.contact.solve_contact` is
  held while the smooth dynamics of that mode are integrated with fixed-step
  Runge-Kutta (RK4) steps;
* events end a step and are located by bisection: a gap closing (impact), a
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

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace

import numba as nb
import numpy as np

from freestand.core.contact import (
    ContactProblem,
    Interface,
    InterfaceMode,
    Tangential,
    solve_contact,
)
from freestand.core.model import Sliding, Stack
from freestand.core.screening import GRAVITY

#: Events on forces fire below ``-EVENT_TOLERANCE * force scale`` (larger than
#: the contact solver's tolerance, so that the state found by bisection is
#: unambiguous for the solver).
EVENT_TOLERANCE = 1e-7

#: A contact has lifted off (``uplift``) when its gap exceeds this fraction of
#: the base width of its interface [-]: 1 micrometre per metre of base. Smaller
#: openings (a contact mode that opens for an instant at round-off level) are
#: not a physical lift-off.
UPLIFT_GAP_FRACTION = 1e-6


# --- excitation ---------------------------------------------------------------------------------


@dataclass(frozen=True)
class SupportMotion:
    """Support accelerations sampled at a constant time step, piecewise linear in time.

    Parameters
    ----------
    time_step : float
        Sampling interval dt [s], positive.
    horizontal : numpy.ndarray
        Horizontal support acceleration a_h [m/s^2] at ``k dt``, +x positive.
    vertical : numpy.ndarray or None
        Downward support acceleration a_v [m/s^2] at ``k dt`` (the weight is
        ``m (g - a_v)``); None for none. Same length as ``horizontal``.

    Notes
    -----
    Before the first and after the last sample the accelerations are zero.
    """

    time_step: float
    horizontal: np.ndarray
    vertical: np.ndarray | None = None

    def __post_init__(self) -> None:
        if not (self.time_step > 0.0 and math.isfinite(self.time_step)):
            raise ValueError(f"time_step must be positive, not {self.time_step!r}")
        horizontal = np.asarray(self.horizontal, dtype=float)
        if horizontal.ndim != 1 or horizontal.size < 2:
            raise ValueError("horizontal must be a 1-D array of at least 2 samples")
        object.__setattr__(self, "horizontal", horizontal)
        if self.vertical is not None:
            vertical = np.asarray(self.vertical, dtype=float)
            if vertical.shape != horizontal.shape:
                raise ValueError(
                    f"vertical has {vertical.size} samples, horizontal {horizontal.size}; "
                    "give both at the same instants"
                )
            object.__setattr__(self, "vertical", vertical)

    @property
    def duration(self) -> float:
        """Time of the last sample [s]."""
        return (self.horizontal.size - 1) * self.time_step

    def __call__(self, time: float) -> tuple[float, float]:
        """(a_h, a_v) [m/s^2] at ``time`` [s] by linear interpolation."""
        position = time / self.time_step
        if position < 0.0 or position > self.horizontal.size - 1:
            return 0.0, 0.0
        index = min(int(position), self.horizontal.size - 2)
        fraction = position - index
        a_h = (1.0 - fraction) * self.horizontal[index] + fraction * self.horizontal[index + 1]
        if self.vertical is None:
            return float(a_h), 0.0
        a_v = (1.0 - fraction) * self.vertical[index] + fraction * self.vertical[index + 1]
        return float(a_h), float(a_v)


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


@nb.njit(cache=True)
def _kinematics_kernel(
    geometry, q, qd, gap, gap_velocity, slip_velocity, slide, rotation, jn, bn, jt, bt
):
    """Fill the arrays of :class:`StackKinematics` (see :func:`stack_kinematics`)."""
    count = geometry.shape[0]
    for i in range(count):
        cxu = geometry[i, 0]
        czu = geometry[i, 1]
        gxu = cxu + q[i, 0]
        gzu = czu + q[i, 1]
        phi_u = q[i, 2]
        vxu = qd[i, 0]
        vzu = qd[i, 1]
        omega_u = qd[i, 2]
        if i == 0:
            cxl = 0.0
            czl = 0.0
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
            gxl = cxl + q[i - 1, 0]
            gzl = czl + q[i - 1, 1]
            phi_l = q[i - 1, 2]
            vxl = qd[i - 1, 0]
            vzl = qd[i - 1, 1]
            omega_l = qd[i - 1, 2]
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
        c1l = -2.0 * math.sin(0.5 * phi_l) ** 2
        sl_ = math.sin(phi_l)
        for c in range(2):
            rx = geometry[i, 2 + 2 * c]
            rz = geometry[i, 3 + 2 * c]
            # P = X + u + (R - I)(X - C): exactly X at rest
            dx = rx - cxu
            dzz = rz - czu
            px = rx + q[i, 0] + c1u * dx - su * dzz
            pz = rz + q[i, 1] + su * dx + c1u * dzz
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
            if c == 0:
                if i:
                    ex = rx - cxl
                    ez = rz - czl
                    mx = rx + q[i - 1, 0] + c1l * ex - sl_ * ez
                    mz = rz + q[i - 1, 1] + sl_ * ex + c1l * ez
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
                # d . perp(a) with perp(x, z) = (-z, x)
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
    q = np.ascontiguousarray(position, dtype=float).reshape(count, 3)
    qd = np.ascontiguousarray(velocity, dtype=float).reshape(count, 3)
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
    _kinematics_kernel(
        geometry, q, qd, gap, gap_velocity, slip_velocity, slide, rotation,
        normal_jacobian, normal_bias, tangential_jacobian, tangential_bias,
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


@dataclass(frozen=True)
class ContactTolerances:
    """Tolerances that decide the contact state from the kinematics.

    Parameters
    ----------
    gap : float
        A contact with ``gap <= gap`` [m] touches.
    velocity : float
        A touching contact is active when its gap velocity is ``<= velocity``
        [m/s]; a slip velocity within ``velocity`` counts as zero (the
        interface may stick).
    slide : float
        An end stop is engaged when the slide is within ``slide`` [m] of the
        parking position.
    """

    gap: float = 1e-7
    velocity: float = 1e-4
    slide: float = 1e-7


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
        position. At rest this is :func:`~freestand.core.screening.contact_problem_at_rest`.
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
        Solve with :func:`~freestand.core.contact.solve_contact`; the chosen
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


@dataclass(frozen=True)
class TimeHistoryEvent:
    """One event of a simulation.

    Attributes
    ----------
    time : float
        Time [s].
    kind : str
        ``"start"``, ``"impact"`` (a gap closed), ``"tangential-impact"`` (no
        consistent sliding state: a velocity jump in which sliding contacts
        may stick resolves it, Painleve's paradox), ``"lift-off"`` (a normal
        force reached zero), ``"slip"`` (static friction could no longer
        hold), ``"slip-stop"`` (a slip velocity reached zero), ``"stop-impact"``
        (a block slid back onto its end stop), ``"overturn"``.
    interface : int
        Interface (= upper block index) concerned, -1 for none.
    contact : int
        0 left, 1 right, -1 for the whole interface.
    motions : tuple of str
        Motion of every block relative to the body below after the event
        (``rest``, ``slide``, ``rock``, ``slide-rock``, ``free-flight``,
        ``overturned``).
    velocity_before, velocity_after : numpy.ndarray
        Shape (B, 3): generalised velocities [m/s, rad/s] across the event
        (they differ at impacts).
    status : str
        Status of the contact solve after the event (``unique``,
        ``ambiguous``).
    """

    time: float
    kind: str
    interface: int
    contact: int
    motions: tuple[str, ...]
    velocity_before: np.ndarray = field(repr=False)
    velocity_after: np.ndarray = field(repr=False)
    status: str = "unique"


@dataclass(frozen=True)
class TimeHistoryDiagnostics:
    """How a simulation went.

    Attributes
    ----------
    time_step : float
        Integration step [s].
    steps : int
        Accepted steps.
    contact_solves : int
        Complete contact problems solved (start, events).
    impact_solves : int
        Impact problems solved.
    ambiguous_solves : int
        Contact or impact solves with several admissible states (the
        documented rule chose).
    max_penetration : float
        Largest penetration [m] found at an accepted step (before the
        projection back onto the contact).
    max_projection : float
        Largest position correction [m, rad] of the projection onto the closed
        contacts.
    method : str
        The path that produced the result: ``"general"`` (event-driven stack
        path), ``"single-block rocking"``, ``"single-block sliding"`` or
        ``"single-block rest"`` (the exact single-block equations, see
        :mod:`freestand.core.single_block`).
    checks : tuple of str
        The assumptions of a single-block path, as verified, in words.
    fallback : str
        Why the single-block path was not used (its failed assumption), if
        it was tried; empty otherwise.
    """

    time_step: float
    steps: int
    contact_solves: int
    impact_solves: int
    ambiguous_solves: int
    max_penetration: float
    max_projection: float
    method: str = "general"
    checks: tuple[str, ...] = ()
    fallback: str = ""


@dataclass(frozen=True)
class TimeHistoryResult:
    """Outcome of :func:`simulate`.

    Attributes
    ----------
    configuration : str
        Stack name.
    block_names : tuple of str
        Bottom to top.
    status : str
        ``"completed"`` (to the requested duration, or until every block
        overturned) or ``"failed"`` (see ``message``; the arrays hold the
        motion up to the failure).
    message : str
        What happened, in words.
    time : numpy.ndarray
        Shape (K,), non-decreasing [s]; an event appears as two rows at the
        same time (before and after).
    position, velocity : numpy.ndarray
        Shape (K, B, 3): ``(u_x, u_z, phi)`` [m, m, rad] of every block (its
        centre's displacement from rest relative to the support, its rotation)
        and their rates; NaN after the block overturned.
    normal_force : numpy.ndarray
        Shape (K, B, 2): normal force [N] on each block at its left and right
        lower contact.
    tangential_force : numpy.ndarray
        Shape (K, B): tangential force [N] on each block from the body below,
        along that body's surface.
    relative_rotation : numpy.ndarray
        Shape (K, B): rotation [rad] of each block relative to the body below.
    slide : numpy.ndarray
        Shape (K, B): slide [m] of each block along the body below from its
        starting position.
    events : tuple of TimeHistoryEvent
    max_rotation : numpy.ndarray
        Shape (B,): largest ``|relative rotation|`` [rad], refined between
        the steps by cubic Hermite interpolation.
    max_slide : numpy.ndarray
        Shape (B,): largest ``|slide|`` [m] per interface.
    uplift : numpy.ndarray
        Shape (B,), bool: a contact of the interface lifted off by more than
        :data:`UPLIFT_GAP_FRACTION` of the interface's base width (a
        momentary lift-off at round-off level does not count).
    free_flight : numpy.ndarray
        Shape (B,), bool: the block left the body below, both contacts open
        by more than that gap.
    overturned : numpy.ndarray
        Shape (B,), bool.
    overturn_time : numpy.ndarray
        Shape (B,): time of overturning [s], NaN if none.
    diagnostics : TimeHistoryDiagnostics
    max_lift : numpy.ndarray
        Shape (B,): largest gap [m] opened at a contact of each interface
        (the larger of the two contacts' gaps; 0 for none).
    """

    configuration: str
    block_names: tuple[str, ...]
    status: str
    message: str
    time: np.ndarray = field(repr=False)
    position: np.ndarray = field(repr=False)
    velocity: np.ndarray = field(repr=False)
    normal_force: np.ndarray = field(repr=False)
    tangential_force: np.ndarray = field(repr=False)
    relative_rotation: np.ndarray = field(repr=False)
    slide: np.ndarray = field(repr=False)
    events: tuple[TimeHistoryEvent, ...] = field(repr=False)
    max_rotation: np.ndarray
    max_slide: np.ndarray
    uplift: np.ndarray
    free_flight: np.ndarray
    overturned: np.ndarray
    overturn_time: np.ndarray
    diagnostics: TimeHistoryDiagnostics = field(repr=False)
    max_lift: np.ndarray | None = None

    def block_index(self, name: str) -> int:
        """Index of the block called ``name``."""
        return self.block_names.index(name)

    def events_of(self, kind: str) -> tuple[TimeHistoryEvent, ...]:
        """The events of one kind, in time order."""
        return tuple(event for event in self.events if event.kind == kind)


# --- simulation ---------------------------------------------------------------------------------


def _motion(mode: InterfaceMode) -> str:
    closed = mode.closed_count
    sliding = mode.tangential in (
        Tangential.SLIDE_POSITIVE,
        Tangential.SLIDE_NEGATIVE,
        Tangential.KINETIC,
    )
    if closed == 2:
        return "slide" if sliding else "rest"
    if closed == 1:
        return "slide-rock" if sliding else "rock"
    return "free-flight"


def _reference(mode: InterfaceMode) -> int:
    return 1 if (mode.right_closed and not mode.left_closed) else 0


@dataclass
class _Held:
    """The contact mode held during a step."""

    modes: tuple[InterfaceMode, ...]
    directions: tuple[int, ...]

    def __post_init__(self) -> None:
        # per interface: left closed, right closed, tangential state (FREE 0,
        # STICK 1, SLIDE 2), slide direction; for the compiled evaluation
        self.codes = np.array(
            [
                (
                    float(mode.left_closed),
                    float(mode.right_closed),
                    0.0 if mode.tangential is Tangential.FREE
                    else 1.0 if mode.tangential is Tangential.STICK
                    else 2.0,
                    float(mode.slide_direction),
                )
                for mode in self.modes
            ],
            dtype=float,
        ).reshape(-1, 4)  # fmt: skip


@nb.njit(cache=True)
def _held_system(geometry, inertia, kinetic, codes, q, qd, inertial, effective_gravity, kin_out,
                 jn, bn, jt, bt, matrix, rhs):  # fmt: skip
    """Kinematics and the linear system of a held contact mode (see ``assemble_mode``).

    ``inertia`` (B, 3): m, m, Theta_S per block; ``kinetic`` (B,): mu;
    ``kin_out`` (B, 7): gap (2), gap velocity (2), slip velocity (2), rotation.
    The slide (column of the kinematics) is not needed here.
    """
    count = geometry.shape[0]
    n = 3 * count
    slide = np.empty(count)
    gap = kin_out[:, 0:2]
    gap_velocity = kin_out[:, 2:4]
    slip_velocity = kin_out[:, 4:6]
    rotation = np.empty(count)
    _kinematics_kernel(geometry, q, qd, gap, gap_velocity, slip_velocity, slide, rotation,
                       jn, bn, jt, bt)  # fmt: skip
    kin_out[:, 6] = rotation
    matrix[:, :] = 0.0
    rhs[:] = 0.0
    for i in range(count):
        for k in range(3):
            matrix[3 * i + k, 3 * i + k] = inertia[i, k]
        rhs[3 * i] = inertia[i, 0] * inertial
        rhs[3 * i + 1] = -inertia[i, 0] * effective_gravity
    for i in range(count):
        column = n + 3 * i
        left = codes[i, 0] > 0.5
        right = codes[i, 1] > 0.5
        reference = 1 if (right and not left) else 0
        for r in range(n):
            matrix[r, column] = -jn[i, 0, r]
            matrix[r, column + 1] = -jn[i, 1, r]
            matrix[r, column + 2] = -jt[i, reference, r]
        for side in range(2):
            row = column + side
            if codes[i, side] > 0.5:
                for r in range(n):
                    matrix[row, r] = jn[i, side, r]
                rhs[row] = -bn[i, side]
            else:
                matrix[row, column + side] = 1.0
        row = column + 2
        state = codes[i, 2]
        if state < 0.5:
            matrix[row, column + 2] = 1.0
        elif state < 1.5:
            for r in range(n):
                matrix[row, r] = jt[i, reference, r]
            rhs[row] = -bt[i, reference]
        else:
            # T + direction * mu * (N_L + N_R) = 0: friction opposes the slip
            matrix[row, column + 2] = 1.0
            matrix[row, column] = codes[i, 3] * kinetic[i]
            matrix[row, column + 1] = codes[i, 3] * kinetic[i]


class _Simulation:
    def __init__(
        self,
        stack: Stack,
        excitation: Excitation,
        gravity: float,
        tolerances: ContactTolerances,
        time_tolerance: float,
        excitation_end: float,
    ):
        self.full = stack
        self.stack = stack
        self.geometry = stack_geometry(stack)
        self.inertia = np.array([[b.mass, b.mass, b.inertia] for b in stack.blocks]).reshape(-1, 3)
        self.kinetic = np.array([b.friction.kinetic for b in stack.blocks])
        self.active_count = len(stack.blocks)
        self.excitation = excitation
        self.gravity = gravity
        self.tol = tolerances
        self.time_tolerance = time_tolerance
        self.excitation_end = excitation_end
        total_mass = sum(block.mass for block in stack.blocks)
        self.force_event = EVENT_TOLERANCE * total_mass * gravity
        self.gap_event = 1e-3 * tolerances.gap
        self.contact_solves = 0
        self.impact_solves = 0
        self.ambiguous = 0
        self.max_penetration = 0.0
        self.max_projection = 0.0

    # dynamics of the held mode
    def kinematics(self, q, qd, slide):
        """Kinematics with the accumulated slide of the simulation."""
        return replace(stack_kinematics(self.stack, q, qd, self.geometry), slide=slide)

    def evaluate(self, time: float, q: np.ndarray, qd: np.ndarray, slide, held: _Held):
        """(qdd, forces (B, 3), kinematics) of the held mode: compiled ``assemble_mode``."""
        a_h, a_v = self.excitation(time)
        count = self.active_count
        n = 3 * count
        kin_out = np.empty((count, 7))
        jn = np.zeros((count, 2, n))
        jt = np.zeros((count, 2, n))
        bn = np.empty((count, 2))
        bt = np.empty((count, 2))
        matrix = np.empty((2 * n, 2 * n))
        rhs = np.empty(2 * n)
        _held_system(
            self.geometry, self.inertia, self.kinetic, held.codes,
            np.ascontiguousarray(q).reshape(count, 3), np.ascontiguousarray(qd).reshape(count, 3),
            -a_h, self.gravity - a_v, kin_out, jn, bn, jt, bt, matrix, rhs,
        )  # fmt: skip
        solution = np.linalg.solve(matrix, rhs)
        kin = StackKinematics(
            gap=kin_out[:, 0:2],
            gap_velocity=kin_out[:, 2:4],
            slip_velocity=kin_out[:, 4:6],
            slide=slide,
            rotation=kin_out[:, 6],
            normal_jacobian=jn,
            normal_bias=bn,
            tangential_jacobian=jt,
            tangential_bias=bt,
        )
        return solution[:n], solution[n:].reshape(-1, 3), kin, None

    @staticmethod
    def slide_rate(kin: StackKinematics, held: _Held) -> np.ndarray:
        """Slip velocity at the contact that defines each interface's slide [m/s]."""
        return np.array(
            [kin.slip_velocity[i, _reference(mode)] for i, mode in enumerate(held.modes)]
        )

    def rk4(self, time, q, qd, slide, h, held, first):
        """One RK4 step of the held mode; ``first`` = (qdd, slide rate) at the start."""
        k1v = qd
        k1a, k1s = first
        k2v = qd + 0.5 * h * k1a
        k2a, _, kin, _ = self.evaluate(time + 0.5 * h, q + 0.5 * h * k1v, k2v, slide, held)
        k2s = self.slide_rate(kin, held)
        k3v = qd + 0.5 * h * k2a
        k3a, _, kin, _ = self.evaluate(time + 0.5 * h, q + 0.5 * h * k2v, k3v, slide, held)
        k3s = self.slide_rate(kin, held)
        k4v = qd + h * k3a
        k4a, _, kin, _ = self.evaluate(time + h, q + h * k3v, k4v, slide, held)
        k4s = self.slide_rate(kin, held)
        q_new = q + h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v)
        qd_new = qd + h / 6.0 * (k1a + 2 * k2a + 2 * k3a + k4a)
        slide_new = slide + h / 6.0 * (k1s + 2 * k2s + 2 * k3s + k4s)
        return q_new, qd_new, slide_new

    def fired(self, kin: StackKinematics, forces, problem, held: _Held) -> list:
        events = []
        for i, (block, mode) in enumerate(zip(self.stack.blocks, held.modes, strict=True)):
            closed = (mode.left_closed, mode.right_closed)
            for c in range(2):
                if closed[c] and forces[i, c] < -self.force_event:
                    events.append(("lift-off", i, c))
                if (
                    not closed[c]
                    and kin.gap[i, c] < -self.gap_event
                    and kin.gap_velocity[i, c] < 0.0
                ):
                    events.append(("impact", i, c))
            sliding = block.sliding
            if sliding in (Sliding.NO_LEFT, Sliding.NO_RIGHT) and not _stop_engaged(
                sliding, float(kin.slide[i]), self.tol.slide
            ):
                sliding = Sliding.FREE
            if mode.tangential is Tangential.STICK and sliding is not Sliding.NONE:
                limit = block.friction.static * (forces[i, 0] + forces[i, 1]) + self.force_event
                tangential = forces[i, 2]
                if (sliding is not Sliding.NO_RIGHT and -tangential > limit) or (
                    sliding is not Sliding.NO_LEFT and tangential > limit
                ):
                    events.append(("slip", i, -1))
            direction = held.directions[i]
            # a slip velocity reversing by more than a small fraction of the zero
            # tolerance (a slide that starts from rest begins at round-off)
            reverse = -1e-3 * self.tol.velocity
            if direction and direction * kin.slip_velocity[i, _reference(mode)] < reverse:
                events.append(("slip-stop", i, -1))
            slide = kin.slide[i]
            slip = kin.slip_velocity[i, _reference(mode)]
            if (
                block.sliding is Sliding.NO_RIGHT
                and slide > self.tol.slide
                and slip > self.tol.velocity
            ) or (
                block.sliding is Sliding.NO_LEFT
                and slide < -self.tol.slide
                and slip < -self.tol.velocity
            ):
                events.append(("stop-impact", i, -1))
            if abs(kin.rotation[i]) >= 0.5 * math.pi:
                events.append(("overturn", i, -1))
        return events

    def project(self, q, qd, held: _Held):
        """Put the closed contacts back on their surfaces (positions and velocities)."""
        mass = np.concatenate([[b.mass, b.mass, b.inertia] for b in self.stack.blocks])
        inverse_mass = 1.0 / mass
        for _ in range(3):
            kin = stack_kinematics(self.stack, q, qd, self.geometry)
            rows, values = [], []
            for i, mode in enumerate(held.modes):
                for c, closed in enumerate((mode.left_closed, mode.right_closed)):
                    if closed:
                        rows.append(kin.normal_jacobian[i, c])
                        values.append(kin.gap[i, c])
            if not rows:
                return q, qd
            jac = np.array(rows)
            gaps = np.array(values)
            self.max_penetration = max(self.max_penetration, float(-gaps.min(initial=0.0)))
            if np.max(np.abs(gaps)) <= 1e-14:
                break
            weighted = jac * inverse_mass
            correction = weighted.T @ np.linalg.lstsq(weighted @ jac.T, gaps, rcond=None)[0]
            self.max_projection = max(self.max_projection, float(np.max(np.abs(correction))))
            q = q - correction
        kin = stack_kinematics(self.stack, q, qd, self.geometry)
        rows = []
        for i, mode in enumerate(held.modes):
            for c, closed in enumerate((mode.left_closed, mode.right_closed)):
                if closed:
                    rows.append(kin.normal_jacobian[i, c])
            if mode.tangential is Tangential.STICK and mode.closed_count:
                rows.append(kin.tangential_jacobian[i, _reference(mode)])
        jac = np.array(rows)
        weighted = jac * inverse_mass
        qd = qd - weighted.T @ np.linalg.lstsq(weighted @ jac.T, jac @ qd, rcond=None)[0]
        return q, qd

    def needs_impact(self, kin: StackKinematics) -> bool:
        for i, block in enumerate(self.stack.blocks):
            for c in range(2):
                approach = kin.gap_velocity[i, c]
                if kin.gap[i, c] <= self.tol.gap and approach < -self.tol.velocity:
                    return True
                if kin.gap[i, c] < -self.gap_event and approach < 0.0:
                    return True
            engaged = _stop_engaged(block.sliding, float(kin.slide[i]), self.tol.slide)
            slip = kin.slip_velocity[i, _lower_contact(kin, i)]
            if engaged and (
                (block.sliding is Sliding.NO_RIGHT and slip > self.tol.velocity)
                or (block.sliding is Sliding.NO_LEFT and slip < -self.tol.velocity)
            ):
                if min(kin.gap[i]) <= self.tol.gap:
                    return True
        return False

    def impact(self, q, qd, kin, allow_stick=False):
        problem = impact_problem(
            self.stack, q, qd, self.tol, kinematics=kin, allow_stick=allow_stick
        )
        result = solve_contact(problem)
        self.impact_solves += 1
        if result.chosen is None:
            return None, result.status
        if result.ambiguous:
            self.ambiguous += 1
        # An engaged end stop must stop the slide into it: among the admissible
        # states prefer (in the solver's order) one that does.
        for solution in result.admissible:
            after = qd + solution.acceleration
            if not self.into_stop(
                replace(stack_kinematics(self.stack, q, after, self.geometry), slide=kin.slide)
            ):
                return after, result.status
        return qd + result.chosen.acceleration, result.status

    def into_stop(self, kin: StackKinematics) -> bool:
        """Whether a block at its engaged end stop still slides into it."""
        for i, block in enumerate(self.stack.blocks):
            if not _stop_engaged(block.sliding, float(kin.slide[i]), self.tol.slide):
                continue
            slip = kin.slip_velocity[i, _lower_contact(kin, i)]
            if (block.sliding is Sliding.NO_RIGHT and slip > self.tol.velocity) or (
                block.sliding is Sliding.NO_LEFT and slip < -self.tol.velocity
            ):
                return True
        return False

    def select(self, time, q, qd, slide):
        """Solve the contact problem at a state; return the mode to hold."""
        a_h, a_v = self.excitation(time)
        kin = self.kinematics(q, qd, slide)
        problem = contact_problem_in_motion(
            self.stack, q, qd, -a_h, a_v, self.gravity, self.tol, kinematics=kin
        )
        result = solve_contact(problem)
        self.contact_solves += 1
        if result.chosen is None:
            return None, result.status
        if result.ambiguous:
            self.ambiguous += 1
        modes = []
        directions = []
        for interface, mode in zip(problem.interfaces, result.chosen.modes, strict=True):
            if mode.tangential is Tangential.KINETIC:
                direction = int(np.sign(interface.slip_velocity))
                tangential = (
                    Tangential.SLIDE_POSITIVE if direction > 0 else Tangential.SLIDE_NEGATIVE
                )
                mode = InterfaceMode(mode.left_closed, mode.right_closed, tangential)
            directions.append(mode.slide_direction)
            modes.append(mode)
        return _Held(tuple(modes), tuple(directions)), result.status

    def overturned_after_excitation(self, qd, kin) -> int:
        """Lowest block past its overturning angle that cannot come back (-1 if none)."""
        qdr = qd.reshape(-1, 3)
        for i, block in enumerate(self.stack.blocks):
            rotation = float(kin.rotation[i])
            omega = float(qdr[i, 2] - (qdr[i - 1, 2] if i else 0.0))
            height = block.centre[1] - block.base_level
            if rotation > 0.0:
                lever, away = block.centre[0] - block.base_left, omega >= 0.0
            else:
                lever, away = block.base_right - block.centre[0], omega <= 0.0
            critical = math.atan2(lever, height)
            if abs(rotation) <= critical:
                continue
            radius = math.hypot(lever, height)
            inertia = block.inertia + block.mass * radius**2
            barrier = (
                block.mass * self.gravity * radius * (1.0 - math.cos(abs(rotation) - critical))
            )
            if away or 0.5 * inertia * omega**2 < barrier:
                return i
        return -1


def _peak_magnitude(time: np.ndarray, value: np.ndarray, rate: np.ndarray) -> float:
    """Largest ``|value|`` of a sampled motion, refined between samples.

    Where the rate changes sign inside a step the cubic Hermite interpolant
    of (value, rate) at the step ends gives the turning point, so the peak is
    found to the integration accuracy rather than to the sampling.
    """
    finite = np.isfinite(value) & np.isfinite(rate)
    peak = float(np.max(np.abs(value[finite]), initial=0.0))
    with np.errstate(invalid="ignore"):
        turning = finite[:-1] & finite[1:] & (rate[:-1] * rate[1:] < 0.0)
    k = np.flatnonzero(turning)
    h = time[k + 1] - time[k]
    k, h = k[h > 0.0], h[h > 0.0]
    if k.size == 0:
        return peak
    y0, y1, m0, m1 = value[k], value[k + 1], rate[k] * h, rate[k + 1] * h
    # p(s) = y0 + m0 s + (3 (y1 - y0) - 2 m0 - m1) s^2 + (2 (y0 - y1) + m0 + m1) s^3
    c2 = 3.0 * (y1 - y0) - 2.0 * m0 - m1
    c3 = 2.0 * (y0 - y1) + m0 + m1
    # roots of p'(s) = 3 c3 s^2 + 2 c2 s + m0 in the stable form q = -(b + sgn(b) sqrt(d)) / 2
    a, b = 3.0 * c3, 2.0 * c2
    with np.errstate(all="ignore"):
        root = np.sqrt(b * b - 4.0 * a * m0)
        q = -0.5 * (b + np.where(b >= 0.0, root, -root))
        for s in (q / a, m0 / q):
            inside = np.isfinite(s) & (s > 0.0) & (s < 1.0)
            if inside.any():
                x = s[inside]
                candidate = y0[inside] + (m0[inside] + (c2[inside] + c3[inside] * x) * x) * x
                peak = max(peak, float(np.max(np.abs(candidate))))
    return peak


#: Order in which simultaneous events are reported.
_EVENT_PRIORITY = ("overturn", "impact", "stop-impact", "lift-off", "slip", "slip-stop")


#: Solvers of :func:`simulate`.
METHODS = ("auto", "general", "single-block")


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
) -> TimeHistoryResult:
    """Simulate the planar motion of a stack under support accelerations (front end).

    Parameters
    ----------
    stack, excitation, duration, gravity, initial_position,
    initial_velocity, excitation_end, tolerances, time_tolerance, max_events
        As for :func:`simulate_general`.
    max_step : float, optional
        Largest integration step [s]; by default 1 ms for the general path
        and 0.02 / p for the single-block rocking integrator (whose steps
        also end on every record sample).
    method : str, optional
        ``"general"``: the event-driven stack path (:func:`simulate_general`).
        ``"single-block"``: the exact single-block equations
        (:func:`freestand.core.single_block.simulate_single_block`) for one
        block on the support under a :class:`SupportMotion`, starting at rest;
        when their assumptions fail (slide-rock, free flight, sliding against
        an end stop) the general path runs instead and
        ``diagnostics.fallback`` says why. ``"auto"`` (default): the
        single-block path wherever it applies, else the general path.

    Returns
    -------
    TimeHistoryResult
        ``diagnostics.method`` names the path that produced it.
    """
    if method not in METHODS:
        raise ValueError(f"unknown method {method!r}; use one of {', '.join(METHODS)}")
    general = dict(
        max_step=1e-3 if max_step is None else max_step,
        gravity=gravity,
        initial_position=initial_position,
        initial_velocity=initial_velocity,
        excitation_end=excitation_end,
        tolerances=tolerances,
        time_tolerance=time_tolerance,
        max_events=max_events,
    )
    if method == "general":
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
    from freestand.core.single_block import simulate_single_block

    attempt = simulate_single_block(
        stack,
        excitation,
        duration,
        max_step=max_step,
        gravity=gravity,
        excitation_end=excitation_end,
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
    max_step: float = 1e-3,
    gravity: float = GRAVITY,
    initial_position: np.ndarray | None = None,
    initial_velocity: np.ndarray | None = None,
    excitation_end: float | None = None,
    tolerances: ContactTolerances | None = None,
    time_tolerance: float = 1e-9,
    max_events: int = 100_000,
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
        Largest integration step [s]. With a :class:`SupportMotion` the step
        divides the sampling interval (every sample is a step end).
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

    Returns
    -------
    TimeHistoryResult
    """
    count = len(stack.blocks)
    if count == 0:
        raise ValueError("the stack has no block")
    if isinstance(excitation, SupportMotion):
        end = excitation.duration if duration is None else float(duration)
        if excitation_end is None:
            excitation_end = excitation.duration
        substeps = max(1, math.ceil(excitation.time_step / max_step - 1e-9))
        step = excitation.time_step / substeps
    else:
        if duration is None:
            raise ValueError("give the duration [s] of a simulation driven by a function")
        end = float(duration)
        if excitation_end is None:
            excitation_end = end
        step = end / max(1, math.ceil(end / max_step - 1e-9))
    if not (end > 0.0 and step > 0.0):
        raise ValueError(f"duration must be positive, not {end!r}")
    tolerances = tolerances or ContactTolerances()
    sim = _Simulation(stack, excitation, gravity, tolerances, time_tolerance, excitation_end)

    q = np.zeros(3 * count) if initial_position is None else np.array(initial_position, float)
    qd = np.zeros(3 * count) if initial_velocity is None else np.array(initial_velocity, float)
    q = q.reshape(-1).copy()
    qd = qd.reshape(-1).copy()
    if q.size != 3 * count or qd.size != 3 * count:
        raise ValueError(f"initial position and velocity need {3 * count} values (3 per block)")

    times: list[float] = []
    positions: list[np.ndarray] = []
    velocities: list[np.ndarray] = []
    normals: list[np.ndarray] = []
    tangentials: list[np.ndarray] = []
    rotations: list[np.ndarray] = []
    slides: list[np.ndarray] = []
    events: list[TimeHistoryEvent] = []
    uplift = np.zeros(count, dtype=bool)
    free_flight = np.zeros(count, dtype=bool)
    overturned = np.zeros(count, dtype=bool)
    overturn_time = np.full(count, np.nan)
    max_lift = np.zeros(count)
    max_flight = np.zeros(count)

    def record(time, q, qd, forces, kin):
        active = sim.active_count
        gaps = kin.gap[:active]
        np.maximum(max_lift[:active], gaps.max(axis=1), out=max_lift[:active])
        np.maximum(max_flight[:active], gaps.min(axis=1), out=max_flight[:active])
        position = np.full((count, 3), np.nan)
        velocity = np.full((count, 3), np.nan)
        normal = np.full((count, 2), np.nan)
        tangential = np.full(count, np.nan)
        rotation = np.full(count, np.nan)
        slide = np.full(count, np.nan)
        position[:active] = q.reshape(-1, 3)
        velocity[:active] = qd.reshape(-1, 3)
        normal[:active] = forces[:, :2]
        tangential[:active] = forces[:, 2]
        rotation[:active] = kin.rotation
        slide[:active] = kin.slide
        times.append(time)
        positions.append(position)
        velocities.append(velocity)
        normals.append(normal)
        tangentials.append(tangential)
        rotations.append(rotation)
        slides.append(slide)

    def motions(held):
        names = [_motion(mode) for mode in held.modes] if held else []
        names += ["overturned"] * (count - len(names))
        return tuple(names)

    def settle(time, q, qd, slide):
        """Impact if needed, then choose the mode; returns (held, q, qd, status, impact kind)."""
        kin = sim.kinematics(q, qd, slide)
        impacted = ""
        if sim.needs_impact(kin):
            qd_new, status = sim.impact(q, qd, kin)
            if qd_new is None:
                return None, q, qd, f"impact problem {status}", impacted
            qd, impacted = qd_new, "impact"
        held, status = sim.select(time, q, qd, slide)
        if held is None:
            # No consistent sliding state (Painleve-type): resolve it by a tangential
            # impact at velocity level, in which the sliding contacts may stick.
            kin = sim.kinematics(q, qd, slide)
            qd_new, impact_status = sim.impact(q, qd, kin, allow_stick=True)
            if qd_new is None:
                return None, q, qd, f"contact problem {status}", impacted
            qd, impacted = qd_new, "tangential-impact"
            held, status = sim.select(time, q, qd, slide)
            if held is None:
                return (
                    None,
                    q,
                    qd,
                    f"contact problem {status} (also after a tangential impact)",
                    impacted,
                )
        q, qd = sim.project(q, qd, held)
        for i, mode in enumerate(held.modes):
            if mode.closed_count < 2:
                uplift[i] = True
            if mode.closed_count == 0 and i > 0:
                free_flight[i] = True
        return held, q, qd, status, impacted

    def remove_from(index, time):
        overturned[index:] = True
        overturn_time[index:] = np.where(
            np.isnan(overturn_time[index:]), time, overturn_time[index:]
        )
        sim.active_count = index
        sim.stack = Stack(stack.name, stack.blocks[:index])
        sim.geometry = sim.geometry[:index]
        sim.inertia = sim.inertia[:index]
        sim.kinetic = sim.kinetic[:index]

    status = "completed"
    message = ""
    time = 0.0
    slide = np.zeros(count)
    initial_velocity_blocks = qd.reshape(-1, 3).copy()
    held, q, qd, solve_status, start_impact = settle(time, q, qd, slide)
    if held is None:
        status, message = "failed", f"at t = 0: {solve_status}"
    else:
        qdd, forces, kin, _ = sim.evaluate(time, q, qd, slide, held)
        rates = (qdd, sim.slide_rate(kin, held))
        record(time, q, qd, forces, kin)
        events.append(
            TimeHistoryEvent(
                time,
                "start",
                -1,
                -1,
                motions(held),
                initial_velocity_blocks,
                qd.reshape(-1, 3).copy(),
                solve_status,
            )
        )
        if start_impact:
            events.append(
                TimeHistoryEvent(
                    time,
                    start_impact,
                    -1,
                    -1,
                    motions(held),
                    initial_velocity_blocks,
                    qd.reshape(-1, 3).copy(),
                    solve_status,
                )
            )
    steps = 0
    stalled = 0
    while status == "completed" and sim.active_count and time < end - 1e-12 * max(end, 1.0):
        grid = (math.floor(time / step + 1e-6) + 1) * step
        h = min(grid, end) - time
        if h <= 1e-3 * time_tolerance:
            h = step
        try:
            q1, qd1, slide1 = sim.rk4(time, q, qd, slide, h, held, rates)
            qdd1, forces1, kin1, problem1 = sim.evaluate(time + h, q1, qd1, slide1, held)
        except np.linalg.LinAlgError:
            status, message = "failed", f"singular contact mode at t = {time:.6g} s"
            break
        fired = sim.fired(kin1, forces1, problem1, held)
        if not fired:
            time += h
            q, qd, slide = q1, qd1, slide1
            rates = (qdd1, sim.slide_rate(kin1, held))
            steps += 1
            closed_gaps = [
                abs(kin1.gap[i, c])
                for i, mode in enumerate(held.modes)
                for c, closed in enumerate((mode.left_closed, mode.right_closed))
                if closed
            ]
            if closed_gaps and max(closed_gaps) > 1e-3 * tolerances.gap:
                q, qd = sim.project(q, qd, held)
                qdd, forces1, kin1, _ = sim.evaluate(time, q, qd, slide, held)
                rates = (qdd, sim.slide_rate(kin1, held))
            record(time, q, qd, forces1, kin1)
            if time >= excitation_end:
                index = sim.overturned_after_excitation(qd, kin1)
                if index >= 0:
                    remove_from(index, time)
                    events.append(
                        TimeHistoryEvent(
                            time,
                            "overturn",
                            index,
                            -1,
                            motions(
                                None
                                if index == 0
                                else _Held(held.modes[:index], held.directions[:index])
                            ),
                            qd.reshape(-1, 3),
                            qd.reshape(-1, 3)[:index],
                        )
                    )
                    if sim.active_count == 0:
                        break
                    q, qd, slide = q[: 3 * index], qd[: 3 * index], slide[:index]
                    held, q, qd, solve_status, _ = settle(time, q, qd, slide)
                    if held is None:
                        status, message = "failed", f"at t = {time:.6g} s: {solve_status}"
                        break
                    qdd, _, kin, _ = sim.evaluate(time, q, qd, slide, held)
                    rates = (qdd, sim.slide_rate(kin, held))
            continue
        # locate the earliest event by bisection
        low, high = 0.0, h
        state = (q1, qd1, slide1, forces1, kin1, fired)
        while high - low > time_tolerance:
            middle = 0.5 * (low + high)
            qm, qdm, slide_m = sim.rk4(time, q, qd, slide, middle, held, rates)
            _, forces_m, kin_m, problem_m = sim.evaluate(time + middle, qm, qdm, slide_m, held)
            fired_m = sim.fired(kin_m, forces_m, problem_m, held)
            if fired_m:
                high, state = middle, (qm, qdm, slide_m, forces_m, kin_m, fired_m)
            else:
                low = middle
        q, qd, slide, forces, kin, fired = state
        time += high
        steps += 1
        stalled = stalled + 1 if high <= 2.0 * time_tolerance else 0
        if stalled > 50:
            status = "failed"
            message = f"events repeat without progress at t = {time:.9g} s ({fired[0][0]})"
            break
        record(time, q, qd, forces, kin)
        kind, interface, contact = min(fired, key=lambda e: _EVENT_PRIORITY.index(e[0]))
        velocity_before = qd.reshape(-1, 3).copy()
        if kind == "overturn":
            remove_from(interface, time)
            if sim.active_count == 0:
                events.append(
                    TimeHistoryEvent(
                        time,
                        kind,
                        interface,
                        contact,
                        motions(None),
                        velocity_before,
                        velocity_before[:0],
                    )
                )
                break
            q, qd, slide = q[: 3 * interface], qd[: 3 * interface], slide[:interface]
        held, q, qd, solve_status, impacted = settle(time, q, qd, slide)
        if held is None:
            status, message = "failed", f"at t = {time:.6g} s: {solve_status}"
            break
        if impacted == "tangential-impact" or (
            impacted and kind not in ("impact", "stop-impact", "overturn")
        ):
            kind = impacted
        events.append(
            TimeHistoryEvent(
                time,
                kind,
                interface,
                contact,
                motions(held),
                velocity_before,
                qd.reshape(-1, 3).copy(),
                solve_status,
            )
        )
        if len(events) > max_events:
            status, message = "failed", f"more than {max_events} events by t = {time:.6g} s"
            break
        try:
            qdd, forces, kin, _ = sim.evaluate(time, q, qd, slide, held)
            rates = (qdd, sim.slide_rate(kin, held))
        except np.linalg.LinAlgError:
            status, message = "failed", f"singular contact mode at t = {time:.6g} s"
            break
        record(time, q, qd, forces, kin)

    if status == "completed":
        if overturned.all():
            message = f"every block overturned (by t = {np.nanmax(overturn_time):.6g} s)"
        else:
            message = f"simulated to t = {time:.6g} s"
            if overturned.any():
                names = ", ".join(
                    b.name for b, o in zip(stack.blocks, overturned, strict=True) if o
                )
                message += f"; overturned: {names}"
    lift_threshold = UPLIFT_GAP_FRACTION * np.array(
        [block.base_right - block.base_left for block in stack.blocks]
    )
    uplift &= max_lift > lift_threshold
    free_flight &= max_flight > lift_threshold
    rotation_array = np.array(rotations) if rotations else np.zeros((0, count))
    slide_array = np.array(slides) if slides else np.zeros((0, count))
    time_array = np.array(times)
    velocity_array = np.array(velocities).reshape(-1, count, 3)
    relative_rate = velocity_array[:, :, 2].copy()
    relative_rate[:, 1:] -= velocity_array[:, :-1, 2]
    with np.errstate(all="ignore"):
        max_rotation = np.array(
            [
                _peak_magnitude(time_array, rotation_array[:, i], relative_rate[:, i])
                for i in range(count)
            ]
        )
        max_slide = np.nan_to_num(np.nanmax(np.abs(slide_array), axis=0, initial=0.0))
    return TimeHistoryResult(
        configuration=stack.name,
        block_names=tuple(block.name for block in stack.blocks),
        status=status,
        message=message,
        time=np.array(times),
        position=np.array(positions).reshape(-1, count, 3),
        velocity=np.array(velocities).reshape(-1, count, 3),
        normal_force=np.array(normals).reshape(-1, count, 2),
        tangential_force=np.array(tangentials).reshape(-1, count),
        relative_rotation=rotation_array,
        slide=slide_array,
        events=tuple(events),
        max_rotation=max_rotation,
        max_slide=max_slide,
        uplift=uplift,
        free_flight=free_flight,
        overturned=overturned,
        overturn_time=overturn_time,
        diagnostics=TimeHistoryDiagnostics(
            time_step=step,
            steps=steps,
            contact_solves=sim.contact_solves,
            impact_solves=sim.impact_solves,
            ambiguous_solves=sim.ambiguous,
            max_penetration=sim.max_penetration,
            max_projection=sim.max_projection,
        ),
        max_lift=max_lift,
    )
