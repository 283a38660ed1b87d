"""The instantaneous contact problem of a planar rigid-block stack.

At an instant the generalised accelerations ``qdd`` of the blocks and the
contact forces obey (notation in ``docs/nomenclature.md``)::

    M qdd = f + sum_i ( J_nL,i^T N_L,i + J_nR,i^T N_R,i + J_t,i^T T_i )
    gap acceleration    a_n,c = J_n,c qdd + b_n,c         (each contact c)
    slip acceleration   a_t,i = J_t,i qdd + b_t,i         (each interface i)

with the unilateral conditions ``N_c >= 0``, ``a_n,c >= 0``, ``N_c a_n,c = 0``
and Coulomb friction at each interface: it *sticks* (``a_t,i = 0``) while
``|T_i| <= mu_0 (N_L,i + N_R,i)``, or it *slides* with ``T_i = -mu sgn(a_t,i)
(N_L,i + N_R,i)``. This is the linear complementarity problem of the paper's
section 3 written for any number of blocks: the paper's case analysis
(3.1.1.1 ... 3.1.2.3) is one branch each of it.

The problem is solved exactly by enumerating the contact modes: for every
combination of (closed/open) contacts and (stick/slide right/slide left)
interfaces the equations are linear; a mode is *admissible* when its solution
satisfies all the inequalities. Every admissible solution is returned, so
that ambiguous problems (several consistent states, e.g. Painleve-type
situations) and inconsistent ones (none) are reported rather than hidden.

Friction is lumped per interface: both contacts of an interface lie on one
line of the lower body, so the tangential forces act along that line and only
their sum matters for the motion (the paper's ``CD_y = C_y + D_y``).

Static and kinetic friction (paper section 3.1.2.1, a and b): an interface
that is at rest slides only when static friction cannot hold it. A sliding
state of such an interface is admissible only if it also slides the same way
when the *static* coefficient acts on it (the friction at its largest cannot
stop it); it then slides with the kinetic coefficient. Interfaces that are
already sliding (time-history) act with the kinetic coefficient against their
sliding velocity.

Choice among admissible states (documented rule): static friction holds
where it can (most sticking interfaces), then the fewest separations (most
closed contacts), then the order of enumeration.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from enum import IntEnum

import numpy as np

from freestand.core.model import Sliding

#: Relative tolerance for the admissibility inequalities and for telling
#: solutions apart (scaled by the problem's force and acceleration scales).
RELATIVE_TOLERANCE = 1e-9


class Tangential(IntEnum):
    """Tangential state of an interface in a contact mode."""

    #: No contact closed: no tangential force.
    FREE = 0
    #: The interface holds: no relative tangential acceleration.
    STICK = 1
    #: Starts sliding to the right (+x along the lower surface).
    SLIDE_POSITIVE = 2
    #: Starts sliding to the left.
    SLIDE_NEGATIVE = 3
    #: Already sliding (non-zero slip velocity): kinetic friction against it.
    KINETIC = 4


@dataclass(frozen=True)
class InterfaceMode:
    """Contact mode of one interface.

    Parameters
    ----------
    left_closed, right_closed : bool
        Whether the left/right contact carries force (gap acceleration zero).
    tangential : Tangential
        Tangential state.
    """

    left_closed: bool
    right_closed: bool
    tangential: Tangential

    @property
    def closed_count(self) -> int:
        """Number of closed contacts (0, 1 or 2)."""
        return int(self.left_closed) + int(self.right_closed)

    @property
    def slide_direction(self) -> int:
        """+1 or -1 for a starting slide, 0 otherwise."""
        if self.tangential is Tangential.SLIDE_POSITIVE:
            return 1
        if self.tangential is Tangential.SLIDE_NEGATIVE:
            return -1
        return 0


@dataclass(frozen=True)
class Interface:
    """Kinematics and friction of one interface at the current instant.

    The interface joins an upper block to the body below (a block or the
    support) through a left and a right contact.

    Parameters
    ----------
    normal_jacobian : numpy.ndarray
        Shape (2, n): rows mapping ``qdd`` [m/s^2, rad/s^2] to the gap
        accelerations [m/s^2] of the left and right contacts.
    normal_bias : numpy.ndarray
        Shape (2,): velocity-dependent part of the gap accelerations [m/s^2]
        (zero at rest).
    tangential_jacobian : numpy.ndarray
        Shape (2, n): rows mapping ``qdd`` to the slip acceleration [m/s^2] of
        the upper block relative to the lower one at the left and right
        contact, along the lower surface.
    tangential_bias : numpy.ndarray
        Shape (2,): velocity-dependent part of the slip accelerations [m/s^2].
    static_friction, kinetic_friction : float
        Coulomb coefficients mu_0 and mu [-].
    sliding : Sliding
        Sliding restriction (free, none, end stop).
    active : tuple of bool
        Whether each contact is touching and not separating (may carry
        force). Inactive contacts are open.
    slip_velocity : float
        Current slip velocity [m/s]; non-zero means the interface slides with
        kinetic friction against it.
    stop_engaged : bool
        For an end stop (``no-right``/``no-left``): whether the block is at
        the stop, so that the stop can push it back.
    """

    normal_jacobian: np.ndarray
    normal_bias: np.ndarray
    tangential_jacobian: np.ndarray
    tangential_bias: np.ndarray
    static_friction: float
    kinetic_friction: float
    sliding: Sliding = Sliding.FREE
    active: tuple[bool, bool] = (True, True)
    slip_velocity: float = 0.0
    stop_engaged: bool = True

    def effective_sliding(self) -> Sliding:
        """The sliding restriction in force now (a stop acts only when engaged)."""
        if self.sliding in (Sliding.NO_LEFT, Sliding.NO_RIGHT) and not self.stop_engaged:
            return Sliding.FREE
        return self.sliding

    def modes(self) -> list[InterfaceMode]:
        """All contact modes this interface can be in, in enumeration order.

        Order: both contacts closed, left only, right only, none; for each,
        stick before slide right before slide left.
        """
        left_active, right_active = self.active
        normal_states = [
            (left, right)
            for left, right in ((True, True), (True, False), (False, True), (False, False))
            if (left <= left_active) and (right <= right_active)
        ]
        sliding = self.effective_sliding()
        result = []
        for left, right in normal_states:
            if not (left or right):
                result.append(InterfaceMode(False, False, Tangential.FREE))
                continue
            if self.slip_velocity != 0.0 and sliding is not Sliding.NONE:
                result.append(InterfaceMode(left, right, Tangential.KINETIC))
                continue
            result.append(InterfaceMode(left, right, Tangential.STICK))
            if sliding.allows(+1):
                result.append(InterfaceMode(left, right, Tangential.SLIDE_POSITIVE))
            if sliding.allows(-1):
                result.append(InterfaceMode(left, right, Tangential.SLIDE_NEGATIVE))
        return result


@dataclass(frozen=True)
class ContactProblem:
    """The instantaneous contact problem of a stack.

    Parameters
    ----------
    mass_matrix : numpy.ndarray
        Shape (n, n), generalised mass matrix [kg, kg m^2].
    applied_force : numpy.ndarray
        Shape (n,), generalised applied forces [N, N m] (weights, inertial
        forces of the support motion, velocity terms).
    interfaces : tuple of Interface
        One per interface, bottom to top.
    force_scale : float
        A typical force [N] (e.g. the total weight) for tolerances.
    acceleration_scale : float
        A typical acceleration [m/s^2] (e.g. g) for tolerances.
    """

    mass_matrix: np.ndarray
    applied_force: np.ndarray
    interfaces: tuple[Interface, ...]
    force_scale: float = 1.0
    acceleration_scale: float = 1.0

    @property
    def size(self) -> int:
        """Number of generalised coordinates n."""
        return int(self.applied_force.shape[0])


@dataclass(frozen=True)
class ContactSolution:
    """One consistent state of the contact problem.

    Attributes
    ----------
    modes : tuple of InterfaceMode
        Mode of each interface.
    acceleration : numpy.ndarray
        Generalised accelerations qdd, shape (n,).
    normal_force : numpy.ndarray
        Shape (I, 2): normal force [N] at the left and right contact of each
        interface, on the upper body.
    tangential_force : numpy.ndarray
        Shape (I,): total tangential force [N] on the upper body along the
        lower surface (+x at rest); friction and end-stop reaction together.
    gap_acceleration : numpy.ndarray
        Shape (I, 2): gap accelerations [m/s^2] (zero where closed).
    slip_acceleration : numpy.ndarray
        Shape (I,): slip acceleration [m/s^2] of each interface at its closed
        contact (the left one when both are closed or both open).
    residual : float
        Largest equation residual of the linear solve, relative to the
        force scale [-].
    """

    modes: tuple[InterfaceMode, ...]
    acceleration: np.ndarray
    normal_force: np.ndarray
    tangential_force: np.ndarray
    gap_acceleration: np.ndarray
    slip_acceleration: np.ndarray
    residual: float

    @property
    def sticking_count(self) -> int:
        """Number of interfaces that hold by friction."""
        return sum(mode.tangential is Tangential.STICK for mode in self.modes)

    @property
    def open_count(self) -> int:
        """Number of open contacts."""
        return sum(2 - mode.closed_count for mode in self.modes)


@dataclass(frozen=True)
class ContactDiagnostics:
    """How a contact problem was solved.

    Attributes
    ----------
    modes_tried : int
        Number of contact modes enumerated.
    singular_modes : int
        Modes whose linear system was singular (skipped).
    kinetic_only_modes : int
        Modes consistent with kinetic friction that static friction could have
        held (not physical from rest; not admissible).
    relaxed : bool
        True when no mode passed the static-friction test and the
        kinetic-only modes were accepted instead.
    rule : str
        The rule used to choose among admissible states.
    """

    modes_tried: int
    singular_modes: int
    kinetic_only_modes: int
    relaxed: bool
    rule: str = "static friction holds where it can, then fewest separations"


@dataclass(frozen=True)
class ContactResult:
    """Outcome of :func:`solve_contact`.

    Attributes
    ----------
    status : str
        ``"unique"`` (one admissible state), ``"ambiguous"`` (several distinct
        admissible states; ``chosen`` by the documented rule) or
        ``"inconsistent"`` (none; ``chosen`` is None).
    chosen : ContactSolution or None
        The state picked by the rule.
    admissible : tuple of ContactSolution
        All distinct admissible states, the chosen one first.
    diagnostics : ContactDiagnostics
    """

    status: str
    chosen: ContactSolution | None
    admissible: tuple[ContactSolution, ...]
    diagnostics: ContactDiagnostics = field(repr=False)

    @property
    def ambiguous(self) -> bool:
        """Whether more than one distinct state is admissible."""
        return self.status == "ambiguous"


def _reference_contact(mode: InterfaceMode) -> int:
    """Index (0 left, 1 right) of the contact whose slip defines the interface's."""
    return 1 if (mode.right_closed and not mode.left_closed) else 0


def assemble_mode(
    problem: ContactProblem, modes: tuple[InterfaceMode, ...], use_static: bool
) -> tuple[np.ndarray, np.ndarray]:
    """Linear system ``A y = r`` of one contact mode.

    ``y = [qdd, (N_L, N_R, T) per interface]``; the rows are the equations of
    motion, then per interface the two normal conditions (closed: gap
    acceleration zero; open: force zero) and the tangential one (stick, slide
    with friction against the slip, or no force).

    With ``use_static`` the sliding interfaces that start from rest act with
    their static coefficient (the break-away test), otherwise kinetic.
    """
    n = problem.size
    count = len(problem.interfaces)
    size = n + 3 * count
    matrix = np.zeros((size, size))
    rhs = np.zeros(size)
    matrix[:n, :n] = problem.mass_matrix
    rhs[:n] = problem.applied_force
    for index, (interface, mode) in enumerate(zip(problem.interfaces, modes, strict=True)):
        column = n + 3 * index
        reference = _reference_contact(mode)
        matrix[:n, column] = -interface.normal_jacobian[0]
        matrix[:n, column + 1] = -interface.normal_jacobian[1]
        matrix[:n, column + 2] = -interface.tangential_jacobian[reference]
        for side, closed in enumerate((mode.left_closed, mode.right_closed)):
            row = column + side
            if closed:
                matrix[row, :n] = interface.normal_jacobian[side]
                rhs[row] = -interface.normal_bias[side]
            else:
                matrix[row, column + side] = 1.0
        row = column + 2
        tangential = mode.tangential
        if tangential is Tangential.FREE:
            matrix[row, column + 2] = 1.0
        elif tangential is Tangential.STICK:
            matrix[row, :n] = interface.tangential_jacobian[reference]
            rhs[row] = -interface.tangential_bias[reference]
        else:
            if tangential is Tangential.KINETIC:
                direction = float(np.sign(interface.slip_velocity))
                coefficient = interface.kinetic_friction
            else:
                direction = float(mode.slide_direction)
                coefficient = (
                    interface.static_friction if use_static else interface.kinetic_friction
                )
            # T + direction * mu * (N_L + N_R) = 0: friction opposes the slip.
            matrix[row, column + 2] = 1.0
            matrix[row, column] = direction * coefficient
            matrix[row, column + 1] = direction * coefficient
    return matrix, rhs


def _solve_batch(matrices: np.ndarray, rhs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Solve a stack of linear systems; return solutions and a mask of solvable ones."""
    solvable = np.ones(matrices.shape[0], dtype=bool)
    try:
        return np.linalg.solve(matrices, rhs[..., None])[..., 0], solvable
    except np.linalg.LinAlgError:
        solutions = np.zeros_like(rhs)
        for k in range(matrices.shape[0]):
            try:
                solutions[k] = np.linalg.solve(matrices[k], rhs[k])
            except np.linalg.LinAlgError:
                solvable[k] = False
        return solutions, solvable


def _unpack(problem: ContactProblem, modes, solution: np.ndarray, residual: float):
    n = problem.size
    count = len(problem.interfaces)
    acceleration = solution[:n]
    forces = solution[n:].reshape(count, 3) if count else np.zeros((0, 3))
    gap = np.zeros((count, 2))
    slip = np.zeros(count)
    for index, (interface, mode) in enumerate(zip(problem.interfaces, modes, strict=True)):
        gap[index] = interface.normal_jacobian @ acceleration + interface.normal_bias
        reference = _reference_contact(mode)
        slip[index] = (
            interface.tangential_jacobian[reference] @ acceleration
            + interface.tangential_bias[reference]
        )
    for index, mode in enumerate(modes):
        if mode.left_closed:
            gap[index, 0] = 0.0
        if mode.right_closed:
            gap[index, 1] = 0.0
    return ContactSolution(
        modes=tuple(modes),
        acceleration=acceleration.copy(),
        normal_force=forces[:, :2].copy(),
        tangential_force=forces[:, 2].copy(),
        gap_acceleration=gap,
        slip_acceleration=slip,
        residual=residual,
    )


def _admissible(
    problem: ContactProblem, solution: ContactSolution, force_tol: float, accel_tol: float
) -> bool:
    """Whether a mode's solution satisfies every inequality (kinetic friction)."""
    for index, (interface, mode) in enumerate(zip(problem.interfaces, solution.modes, strict=True)):
        normal = solution.normal_force[index]
        for side, closed in enumerate((mode.left_closed, mode.right_closed)):
            if closed and normal[side] < -force_tol:
                return False
            if (
                not closed
                and interface.active[side]
                and solution.gap_acceleration[index, side] < -accel_tol
            ):
                return False
        total_normal = normal[0] + normal[1]
        tangential = solution.tangential_force[index]
        if mode.tangential is Tangential.STICK:
            limit = interface.static_friction * total_normal + force_tol
            sliding = interface.effective_sliding()
            if sliding is Sliding.NONE:
                continue
            # An engaged end stop adds an unbounded reaction on its side.
            if sliding is not Sliding.NO_RIGHT and -tangential > limit:
                return False
            if sliding is not Sliding.NO_LEFT and tangential > limit:
                return False
        elif mode.tangential in (Tangential.SLIDE_POSITIVE, Tangential.SLIDE_NEGATIVE):
            if mode.slide_direction * solution.slip_acceleration[index] < -accel_tol:
                return False
    return True


def _slides_with_static_friction(
    problem: ContactProblem, solution: ContactSolution, accel_tol: float
) -> bool:
    """Whether the interfaces that start sliding still slide with mu_0 acting."""
    for index, mode in enumerate(solution.modes):
        if (
            mode.slide_direction
            and mode.slide_direction * solution.slip_acceleration[index] < -accel_tol
        ):
            return False
    return True


def _distinct(a: ContactSolution, b: ContactSolution, force_tol: float, accel_tol: float) -> bool:
    if np.max(np.abs(a.normal_force - b.normal_force), initial=0.0) > 10 * force_tol:
        return True
    if np.max(np.abs(a.tangential_force - b.tangential_force), initial=0.0) > 10 * force_tol:
        return True
    return bool(np.max(np.abs(a.acceleration - b.acceleration), initial=0.0) > 10 * accel_tol)


def solve_contact(problem: ContactProblem) -> ContactResult:
    """Find every consistent contact state of a stack at an instant.

    Parameters
    ----------
    problem : ContactProblem
        Masses, applied forces, contact kinematics and friction.

    Returns
    -------
    ContactResult
        All distinct admissible states and the one chosen by the rule
        "static friction holds where it can, then fewest separations".

    Notes
    -----
    The number of modes is at most 10 per interface (4 normal states x
    stick/slide right/slide left, less the impossible ones), so a stack of
    four blocks has at most 10^4 small linear systems, solved in one
    vectorised call.
    """
    per_interface = [interface.modes() for interface in problem.interfaces]
    combinations = list(itertools.product(*per_interface))
    force_tol = RELATIVE_TOLERANCE * max(problem.force_scale, np.finfo(float).tiny)
    accel_tol = RELATIVE_TOLERANCE * max(problem.acceleration_scale, np.finfo(float).tiny)
    systems = [assemble_mode(problem, modes, use_static=False) for modes in combinations]
    matrices = np.array([system[0] for system in systems])
    rhs = np.array([system[1] for system in systems])
    solutions, solvable = _solve_batch(matrices, rhs)
    residuals = np.max(np.abs(np.einsum("kij,kj->ki", matrices, solutions) - rhs), axis=1)

    candidates: list[ContactSolution] = []
    for k, modes in enumerate(combinations):
        if not solvable[k] or not np.all(np.isfinite(solutions[k])):
            continue
        solution = _unpack(
            problem, modes, solutions[k], residuals[k] / max(problem.force_scale, 1e-300)
        )
        if _admissible(problem, solution, force_tol, accel_tol):
            candidates.append(solution)

    # Break-away test for interfaces that start sliding from rest.
    physical: list[ContactSolution] = []
    kinetic_only = 0
    for solution in candidates:
        if not any(mode.slide_direction for mode in solution.modes):
            physical.append(solution)
            continue
        matrix, rhs_static = assemble_mode(problem, solution.modes, use_static=True)
        try:
            static = np.linalg.solve(matrix, rhs_static)
        except np.linalg.LinAlgError:
            kinetic_only += 1
            continue
        static_solution = _unpack(problem, solution.modes, static, 0.0)
        if _slides_with_static_friction(problem, static_solution, accel_tol):
            physical.append(solution)
        else:
            kinetic_only += 1

    relaxed = False
    if not physical and candidates:
        physical, relaxed = candidates, True

    ordered = sorted(
        enumerate(physical), key=lambda item: (-item[1].sticking_count, item[1].open_count, item[0])
    )
    distinct: list[ContactSolution] = []
    for _, solution in ordered:
        if all(_distinct(solution, kept, force_tol, accel_tol) for kept in distinct):
            distinct.append(solution)

    diagnostics = ContactDiagnostics(
        modes_tried=len(combinations),
        singular_modes=int(np.count_nonzero(~solvable)),
        kinetic_only_modes=kinetic_only,
        relaxed=relaxed,
    )
    if not distinct:
        status = "inconsistent"
    elif len(distinct) == 1:
        status = "unique"
    else:
        status = "ambiguous"
    return ContactResult(
        status=status,
        chosen=distinct[0] if distinct else None,
        admissible=tuple(distinct),
        diagnostics=diagnostics,
    )
