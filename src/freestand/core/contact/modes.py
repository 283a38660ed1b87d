"""Numpy reference solver of the instantaneous contact problem of a planar stack.

An independent implementation kept for the tests (the oracle of the compiled
kernel :mod:`freestand.core.contact.engine`, which every production path uses;
no production module imports this one). The problem types are those of
:mod:`freestand.core.contact.problem`, re-exported here.

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

import numpy as np

from freestand.core.contact.problem import (  # noqa: F401  (re-exported for tests)
    RELATIVE_TOLERANCE,
    ContactDiagnostics,
    ContactProblem,
    ContactResult,
    ContactSolution,
    Interface,
    InterfaceMode,
    Tangential,
)
from freestand.core.model import Sliding


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
