"""The points' contact problem solved by a semi-smooth Newton method (compiled).

The velocity-level contact problem at n points
(:mod:`freestand.core.contact.body_impulse`): impulses ``P`` (x, y, n per
point, 3n) and the points' velocities after, ``u = free + W P`` (``W`` the
3n x 3n Delassus matrix, ``free`` the velocities before), such that at every
point

- ``P_n >= 0``, ``u_n >= 0`` and ``P_n u_n = 0`` (plastic, unilateral);
- ``|P_t| <= mu P_n``; inside the cone the point sticks, ``u_t = 0``; a point
  that slips has ``P_t = -mu P_n u_t / |u_t|`` (Coulomb's law on the circular
  cone, friction opposite the slip).

These laws are the zeros of Alart and Curnier's function (P. Alart,
A. Curnier, A mixed formulation for frictional contact problems prone to
Newton like solution methods, Comput. Methods Appl. Mech. Engrg. 92 (1991)
353-375), per point with scalars ``rho_n, rho_t > 0`` [kg]:

    F_n = P_n - max(0, P_n - rho_n u_n)
    F_t = P_t - proj(P_t - rho_t u_t, disc of radius mu max(0, P_n - rho_n u_n))

piecewise smooth, solved by Newton's method with its generalised Jacobian
and a backtracking line search on ``|F|^2``. ``W`` is singular where
impulses can move between points without moving the body (an edge's two
corners pushing along it, a flat base's corners): each step is the
least-squares one with no component along those directions (regularised
normal equations), so the impulses stay nearest the start along them.
Started from the projected Gauss-Seidel sweeps' impulses it finishes,
quadratically, what the sweeps approach linearly.
"""

from __future__ import annotations

import numba as nb
import numpy as np

from freestand.core.contact.engine import solve_symmetric_in_place
from freestand.core.contact.vectors import norm2

NEWTON_ITERATIONS = 30  # at most
LINE_SEARCH_HALVINGS = 30  # a step halved at most this many times
SUFFICIENT_DECREASE = 1e-4  # Armijo's constant on |F|^2
STALL_HALVINGS = 4  # a step halved this many times or more is a stalled iteration...
STALL_ITERATIONS = 5  # ...and this many stalled iterations in a row end the search
REGULARISATION = 1e-13  # of the Newton step's normal equations, relative to their largest term


def work_fields(points: int) -> list[tuple]:
    """The fields of :func:`solve_alart_curnier`'s work record for up to ``points`` points.

    Part of the caller's work record (numpy's structured dtype): allocated
    once, the solve then needs numba's reference counting nowhere, which a
    rocking cabinet's time stepping (thousands of solves) paid at every call.
    The matrices are flat (3n)^2 buffers, viewed as (3n, 3n) for n points.
    """
    n3 = 3 * points
    return [
        ("ac_rho_n", "f8", points), ("ac_rho_t", "f8", points), ("ac_residual", "f8", n3),
        ("ac_jacobian", "f8", n3 * n3), ("ac_trial", "f8", n3), ("ac_trial_residual", "f8", n3),
        ("ac_trial_jacobian", "f8", n3 * n3), ("ac_normal", "f8", n3 * n3), ("ac_step", "f8", n3),
    ]  # fmt: skip


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def largest_tangential_eigenvalue(w):
    """The larger eigenvalue of a point's symmetric 2 x 2 tangential block W_tt [1/kg].

    ``w``: the point's Delassus block (its first two rows and columns are
    the tangential ones). One over it is the scalar step ``rho_t`` of the
    sweeps and of Alart and Curnier's function.
    """
    half_trace = 0.5 * (w[0, 0] + w[1, 1])
    half_difference = 0.5 * (w[0, 0] - w[1, 1])
    return half_trace + norm2(half_difference, 0.5 * (w[0, 1] + w[1, 0]))


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _point_function(p, mu, rho_n, rho_t, delassus, impulses, speeds, residual, jacobian):
    """The point's three rows of F and of its generalised Jacobian dF/dP."""
    n3 = impulses.shape[0]
    r = 3 * p
    # normal: F_n = rho_n u_n where the projected normal a = P_n - rho_n u_n is positive
    projected_normal = impulses[r + 2] - rho_n * speeds[r + 2]
    for column in range(n3):
        jacobian[r + 2, column] = 0.0
    if projected_normal > 0.0:
        residual[r + 2] = rho_n * speeds[r + 2]
        for column in range(n3):
            jacobian[r + 2, column] = rho_n * delassus[r + 2, column]
    else:
        residual[r + 2] = impulses[r + 2]
        jacobian[r + 2, r + 2] = 1.0
        projected_normal = 0.0
    # tangential: z = P_t - rho_t u_t projected on the disc of radius mu a
    radius = mu * projected_normal
    zx = impulses[r] - rho_t * speeds[r]
    zy = impulses[r + 1] - rho_t * speeds[r + 1]
    size = norm2(zx, zy)
    if size <= radius:
        # inside: F_t = P_t - z = rho_t u_t
        residual[r] = rho_t * speeds[r]
        residual[r + 1] = rho_t * speeds[r + 1]
        for i in range(2):
            for column in range(n3):
                jacobian[r + i, column] = rho_t * delassus[r + i, column]
        return
    if size == 0.0:
        residual[r] = impulses[r]
        residual[r + 1] = impulses[r + 1]
        for i in range(2):
            for column in range(n3):
                jacobian[r + i, column] = 1.0 if column == r + i else 0.0
        return
    # outside: F_t = P_t - radius z / |z|
    ex = zx / size
    ey = zy / size
    residual[r] = impulses[r] - radius * ex
    residual[r + 1] = impulses[r + 1] - radius * ey
    bend = radius / size  # d(z/|z|)/dz = (I - e e^T) / |z|
    for column in range(n3):
        dzx = (1.0 if column == r else 0.0) - rho_t * delassus[r, column]
        dzy = (1.0 if column == r + 1 else 0.0) - rho_t * delassus[r + 1, column]
        # the radius mu a: d a / dP = e_n - rho_n W_n where a > 0
        dradius = 0.0
        if projected_normal > 0.0:
            dradius = mu * ((1.0 if column == r + 2 else 0.0) - rho_n * delassus[r + 2, column])
        along = ex * dzx + ey * dzy
        unit_x = 1.0 if column == r else 0.0
        unit_y = 1.0 if column == r + 1 else 0.0
        jacobian[r, column] = unit_x - ex * dradius - bend * (dzx - ex * along)
        jacobian[r + 1, column] = unit_y - ey * dradius - bend * (dzy - ey * along)


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _function(count, mu, rho_n, rho_t, delassus, free, impulses, speeds, residual, jacobian):
    """F and its generalised Jacobian at the impulses; ``speeds`` = free + W P. Returns |F|^2."""
    n3 = 3 * count
    for row in range(n3):
        speed = free[row]
        for column in range(n3):
            speed += delassus[row, column] * impulses[column]
        speeds[row] = speed
    for p in range(count):
        _point_function(p, mu, rho_n[p], rho_t[p], delassus, impulses, speeds, residual, jacobian)
    norm = 0.0
    for row in range(n3):
        norm += residual[row] ** 2
    return norm


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _least_squares_step(jacobian, residual, normal, step):
    """The Newton step ``-J^+ F`` in ``step``, by the normal equations regularised by
    ``REGULARISATION``.

    ``(J^T J + lambda I) s = -J^T F`` with lambda ``REGULARISATION`` times
    the largest diagonal of ``J^T J``: where J is singular (impulses moving
    between points without moving the body) the step's component along its
    null space vanishes, as the minimum-norm least-squares step's does, at a
    tenth of the cost of a singular value decomposition. Solved in place by
    ``L D L^T`` (``normal`` is work space); where round-off leaves a pivot
    that is not positive, by LU with pivoting.
    """
    n = jacobian.shape[0]
    largest = 0.0
    for i in range(n):
        for j in range(i + 1):
            total = 0.0
            for r in range(n):
                total += jacobian[r, i] * jacobian[r, j]
            normal[i, j] = total
            normal[j, i] = total
        largest = max(largest, normal[i, i])
        total = 0.0
        for r in range(n):
            total -= jacobian[r, i] * residual[r]
        step[i] = total
    for i in range(n):
        normal[i, i] += REGULARISATION * largest + 1e-300
    if solve_symmetric_in_place(normal, step, n):
        return
    _least_squares_by_lu(jacobian, residual, REGULARISATION * largest + 1e-300, step)


@nb.njit(cache=True, error_model="numpy", _nrt=True)
def _least_squares_by_lu(jacobian, residual, shift, step):
    """:func:`_least_squares_step`'s ``(J^T J + shift I) s = -J^T F`` by LU with pivoting.

    A function of its own: its arrays need numba's reference counting, which
    would otherwise cost every call of the step (a rocking cabinet's time
    stepping makes thousands).
    """
    n = jacobian.shape[0]
    matrix = jacobian.T @ jacobian
    for i in range(n):
        matrix[i, i] += shift
    step[:] = np.linalg.solve(matrix, -(jacobian.T @ residual))


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def obeys_laws(count, mu, impulses, speeds, velocity_tolerance, impulse_tolerance):
    """Whether impulses and the points' velocities satisfy the contact laws, to the tolerances."""
    for p in range(count):
        r = 3 * p
        normal = impulses[r + 2]
        if normal < -impulse_tolerance or speeds[r + 2] < -velocity_tolerance:
            return False
        if normal > impulse_tolerance and speeds[r + 2] > velocity_tolerance:
            return False  # complementarity
        tangential = norm2(impulses[r], impulses[r + 1])
        if tangential > mu * max(normal, 0.0) + impulse_tolerance:
            return False
        slip = norm2(speeds[r], speeds[r + 1])
        if tangential < mu * normal - impulse_tolerance and slip > velocity_tolerance:
            return False  # inside the cone, the point sticks
        if slip > velocity_tolerance:
            # friction opposite the slip, on the cone's edge: P_t = -mu P_n u_t / |u_t|; the
            # slip's direction known to velocity_tolerance / |u_t| (a slip just past the
            # tolerance has barely a direction)
            excess_x = impulses[r] + mu * normal * speeds[r] / slip
            excess_y = impulses[r + 1] + mu * normal * speeds[r + 1] / slip
            allowed = impulse_tolerance + mu * normal * velocity_tolerance / slip
            if norm2(excess_x, excess_y) > allowed:
                return False
    return True


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def solve_alart_curnier(count, mu, delassus, free, impulses, velocity_tolerance,
                        impulse_tolerance, speeds, work):  # fmt: skip
    """The exact impulses from a start near them; returns whether they obey the laws.

    ``delassus`` (3n, 3n) [1/kg] the points' velocities per unit impulse,
    ``free`` (3n) [m/s] their velocities before, ``impulses`` (3n) [N s] the
    start, replaced by the solution (where found; with P_n >= 0 and
    ``|P_t| <= mu P_n`` restored where round-off below the tolerances left
    them just out); ``speeds`` (3n) [m/s] receives the velocities after.
    ``rho_n = 1 / W_nn`` and ``rho_t`` one over the larger eigenvalue of the
    point's W_tt (the sweeps' steps). Newton's iterations stop where
    ``|F|`` falls to ``impulse_tolerance``; the solution is then checked
    against the laws themselves (:func:`obeys_laws`). They also stop where
    ``STALL_ITERATIONS`` in a row each halved their step ``STALL_HALVINGS``
    times or more: the start is then outside the method's quadratic basin
    (a flat cylinder's eight rim points from the sweeps' early impulses
    crept on for hundreds of evaluations of F and failed; every solve of a
    rocking cabinet's that succeeds halves its steps at most three times in
    a row), and the caller's sweeps go on. ``work``: a record with the
    fields of :func:`work_fields` for at least ``count`` points.
    """
    n3 = 3 * count
    rho_n = work["ac_rho_n"][:count]
    rho_t = work["ac_rho_t"][:count]
    for p in range(count):
        r = 3 * p
        rho_n[p] = 1.0 / delassus[r + 2, r + 2]
        rho_t[p] = 1.0 / largest_tangential_eigenvalue(delassus[r : r + 2, r : r + 2])
    residual = work["ac_residual"][:n3]
    jacobian = work["ac_jacobian"][: n3 * n3].reshape((n3, n3))
    trial = work["ac_trial"][:n3]
    trial_residual = work["ac_trial_residual"][:n3]
    trial_jacobian = work["ac_trial_jacobian"][: n3 * n3].reshape((n3, n3))
    normal = work["ac_normal"][: n3 * n3].reshape((n3, n3))
    step = work["ac_step"][:n3]
    norm = _function(count, mu, rho_n, rho_t, delassus, free, impulses, speeds, residual, jacobian)
    stalled = 0
    current = True  # ``speeds`` are the velocities after the impulses (the last F evaluated)
    for _iteration in range(NEWTON_ITERATIONS):
        if norm <= impulse_tolerance**2:
            break
        _least_squares_step(jacobian, residual, normal, step)
        fraction = 1.0
        accepted = False
        halvings = 0
        for _halving in range(LINE_SEARCH_HALVINGS):
            for j in range(n3):
                trial[j] = impulses[j] + fraction * step[j]
            trial_norm = _function(count, mu, rho_n, rho_t, delassus, free, trial, speeds,
                                   trial_residual, trial_jacobian)  # fmt: skip
            if trial_norm <= (1.0 - 2.0 * SUFFICIENT_DECREASE * fraction) * norm:
                accepted = True
                break
            fraction *= 0.5
            halvings += 1
        stalled = stalled + 1 if halvings >= STALL_HALVINGS else 0
        current = False  # ``speeds`` now of the last trial
        if not accepted or stalled >= STALL_ITERATIONS:
            break
        for j in range(n3):
            impulses[j] = trial[j]
            residual[j] = trial_residual[j]
            for column in range(n3):
                jacobian[j, column] = trial_jacobian[j, column]
        norm = trial_norm
        current = True  # the trial taken
    if not current:
        _function(count, mu, rho_n, rho_t, delassus, free, impulses, speeds, residual, jacobian)
    if not obeys_laws(count, mu, impulses, speeds, velocity_tolerance, impulse_tolerance):
        return False
    for p in range(count):
        r = 3 * p
        normal = max(0.0, impulses[r + 2])
        tangential = norm2(impulses[r], impulses[r + 1])
        if tangential > mu * normal:
            impulses[r] *= mu * normal / tangential
            impulses[r + 1] *= mu * normal / tangential
        impulses[r + 2] = normal
    return True
