"""The compiled solver of the instantaneous contact problem of a planar stack.

One kernel serves every use of the contact problem: the screening of a stack at
rest (:func:`freestand.core.contact.screening.initial_motion`, a batch of one),
the batch solves of :mod:`freestand.core.contact.batch` (``map``, ``sample``) and
the time history (:mod:`freestand.core.dynamics.engine`, at a state in motion).
The problem and its description types are those of
:mod:`freestand.core.contact.problem`; :mod:`freestand.core.contact.modes` keeps
an independent numpy implementation used only by the tests as a reference.

At an instant the generalised accelerations ``qdd`` and the contact forces
obey (notation in ``docs/nomenclature.md``, paper section 3)::

    M qdd = f + sum_i ( J_nL,i^T N_L,i + J_nR,i^T N_R,i + J_t,i^T T_i )
    gap acceleration    a_n,c = J_n,c qdd + b_n,c         (each contact c)
    slip acceleration   a_t,i = J_t,i qdd + b_t,i         (each interface i)

with ``N_c >= 0``, ``a_n,c >= 0``, ``N_c a_n,c = 0`` and Coulomb friction per
interface (stick while ``|T_i| <= mu_0 (N_L,i + N_R,i)``, else slide with
``T_i = -mu sgn(a_t,i) (N_L,i + N_R,i)``). ``M`` is diagonal (each block's
coordinates are its centre of gravity and its rotation), so the accelerations
are eliminated on the Delassus matrix ``W = J M^-1 J^T``::

    qdd = M^-1 (f + J^T Lambda),   a = J qdd + b = W Lambda + h,   h = J M^-1 f + b

In a contact mode the unknowns are the normal forces of the closed contacts
and the tangential forces of the sticking interfaces (a sliding interface has
``T = -d mu (N_L + N_R)``); its equations are the zero gap acceleration of each
closed contact and the zero slip acceleration of each sticking interface: the
Schur complement of the full system ``[M -J^T; J 0]``, singular together with it.

The modes are enumerated (per interface: both contacts closed, left only, right
only, none; for each, stick before slide right before slide left; an already
sliding interface has one kinetic state), the last interface varying fastest.
A mode is admissible when its solution satisfies every inequality with the
tolerance ``RELATIVE_TOLERANCE`` scaled by the problem's force and acceleration
scales. Static and kinetic friction (paper 3.1.2.1 a, b): a mode in which an
interface starts sliding from rest is physical only if it still slides that
way with the static coefficient acting (break-away test); when no admissible
mode passes it the admissible ones are accepted (``relaxed``). Choice rule:
most sticking interfaces, then fewest open contacts, then enumeration order;
solutions equal within ten times the tolerances are one state. Several
distinct states make the problem *ambiguous*, none *inconsistent*; both are
reported.

Codes
-----
sliding (per interface)
    0 free, 1 none, 2 no-right, 3 no-left (an unengaged end stop is free).
tangential state of a mode
    0 free (no contact closed), 1 stick, 2 slide +x, 3 slide -x, 4 kinetic
    (already sliding: kinetic friction against the slip velocity).
"""

from __future__ import annotations

from collections import namedtuple

import numba as nb
import numpy as np

from freestand.core.contact.problem import (
    RELATIVE_TOLERANCE,
    ContactDiagnostics,
    ContactProblem,
    ContactResult,
    ContactSolution,
    InterfaceMode,
    Tangential,
)
from freestand.core.model import Sliding

__all__ = ["MAX_DISTINCT", "RELATIVE_TOLERANCE", "solve", "solve_contact_problem"]

#: Largest number of distinct admissible states kept per solve.
MAX_DISTINCT = 16

#: Most local modes of one interface (four contact states, up to three tangential ones).
MAX_LOCAL = 10

#: Entries of the ``info`` vector of :func:`solve_contact_states`.
INFO_MODES, INFO_SINGULAR, INFO_KINETIC_ONLY, INFO_RELAXED = range(4)
INFO_SIZE = 4

_SLIDING_CODES = {Sliding.FREE: 0, Sliding.NONE: 1, Sliding.NO_RIGHT: 2, Sliding.NO_LEFT: 3}


@nb.njit(cache=True, inline="always")
def solve_in_place(matrix, rhs, k):
    """Solve the leading k x k system ``matrix x = rhs`` in place (x in ``rhs``).

    Gaussian elimination with partial pivoting on the small systems of one
    contact mode (at most three unknowns per interface); ``matrix`` is
    overwritten. Returns False for an exactly singular system (the mode is
    then not a solution).
    """
    for p in range(k):
        pivot = p
        largest = abs(matrix[p, p])
        for r in range(p + 1, k):
            if abs(matrix[r, p]) > largest:
                largest = abs(matrix[r, p])
                pivot = r
        if largest == 0.0:
            return False
        if pivot != p:
            for j in range(k):
                tmp = matrix[p, j]
                matrix[p, j] = matrix[pivot, j]
                matrix[pivot, j] = tmp
            tmp = rhs[p]
            rhs[p] = rhs[pivot]
            rhs[pivot] = tmp
        for r in range(p + 1, k):
            factor = matrix[r, p] / matrix[p, p]
            if factor != 0.0:
                for j in range(p + 1, k):
                    matrix[r, j] -= factor * matrix[p, j]
                rhs[r] -= factor * rhs[p]
    for p in range(k - 1, -1, -1):
        total = rhs[p]
        for j in range(p + 1, k):
            total -= matrix[p, j] * rhs[j]
        rhs[p] = total / matrix[p, p]
    return True


@nb.njit(cache=True, inline="always")
def held_products(rows, forces, matrix, k, c0, n, lower):
    """``matrix[r, j] = rows[r] . forces[j]`` over the columns c0..n-1, for r, j < k.

    The held mode's matrix ``J_r M^-1 G_j^T`` of a contact problem (``forces``
    holding ``M^-1 G_j^T``); ``lower``: only its lower triangle (j <= r), for
    :func:`solve_symmetric_in_place`.
    """
    for r in range(k):
        for j in range(r + 1 if lower else k):
            total = 0.0
            for col in range(c0, n):
                total += rows[r, col] * forces[j, col]
            matrix[r, j] = total


@nb.njit(cache=True, inline="always")
def solve_symmetric_in_place(matrix, rhs, k):
    """Solve ``matrix x = rhs`` for a symmetric positive definite leading k x k block.

    ``L D L^T`` factorisation (no pivoting, no square root) from the lower
    triangle, which it overwrites; ``x`` in ``rhs``. Returns False, with
    ``rhs`` untouched, when a pivot is not positive (the matrix is not
    positive definite: solve it with :func:`solve_in_place` instead).
    """
    for j in range(k):
        d = matrix[j, j]
        for p in range(j):
            d -= matrix[j, p] * matrix[j, p] * matrix[p, p]
        if not d > 0.0:
            return False
        matrix[j, j] = d
        for i in range(j + 1, k):
            total = matrix[i, j]
            for p in range(j):
                total -= matrix[i, p] * matrix[j, p] * matrix[p, p]
            matrix[i, j] = total / d
    for i in range(k):
        total = rhs[i]
        for p in range(i):
            total -= matrix[i, p] * rhs[p]
        rhs[i] = total
    for i in range(k):
        rhs[i] /= matrix[i, i]
    for i in range(k - 1, -1, -1):
        total = rhs[i]
        for p in range(i + 1, k):
            total -= matrix[p, i] * rhs[p]
        rhs[i] = total
    return True


@nb.njit(cache=True, inline="always")
def _row(i, kind, reference):
    """Row of the 4-per-interface Delassus matrix: gap left, gap right, slip left, slip right."""
    if kind < 2:
        return 4 * i + kind
    return 4 * i + 2 + reference


@nb.njit(cache=True, _nrt=False)
def delassus(active, inverse_mass, free_acc, jn, bn, jt, bt, w, h):
    """``W = J M^-1 J^T`` and ``h = J M^-1 f + b`` over the rows (gap L, gap R, slip L, slip R).

    Each interface's rows involve only its two blocks' columns, so the product is
    accumulated over those six columns.
    """
    rows = 4 * active
    for r in range(rows):
        i = r // 4
        kind = r % 4
        jr = jn[i, kind] if kind < 2 else jt[i, kind - 2]
        br = bn[i, kind] if kind < 2 else bt[i, kind - 2]
        start = 3 * i - 3 if i else 0
        total = br
        for col in range(start, 3 * i + 3):
            total += jr[col] * free_acc[col]
        h[r] = total
        for s in range(r, rows):
            k = s // 4
            if k > i + 1:
                w[r, s] = 0.0
                w[s, r] = 0.0
                continue
            kind_s = s % 4
            js = jn[k, kind_s] if kind_s < 2 else jt[k, kind_s - 2]
            lo = max(start, 3 * k - 3 if k else 0)
            hi = min(3 * i + 3, 3 * k + 3)
            total = 0.0
            for col in range(lo, hi):
                total += jr[col] * js[col] * inverse_mass[col]
            w[r, s] = total
            w[s, r] = total


@nb.njit(cache=True, inline="always")
def _slide_coefficient(left, right, tangential, mu):
    """Reference contact and friction coefficient ``-d mu`` of an interface's local mode.

    The reference contact (0 left, 1 right: right only when the left one is open)
    carries the tangential row; ``d`` is the sliding direction (+1, -1; for an
    already sliding interface the sign of its slip velocity ``mu[1]``; 0 when
    sticking or free) and ``mu[0]`` the coefficient of the sliding interface.
    """
    reference = 1 if (right == 1 and left == 0) else 0
    direction = 0.0
    if tangential == 2:
        direction = 1.0
    elif tangential == 3:
        direction = -1.0
    elif tangential == 4:
        direction = mu[1]  # sign of the slip velocity
    return reference, -direction * mu[0]


@nb.njit(cache=True, _nrt=False)
def solve_mode(active, w, h, mode, mu, lam, a, matrix, rhs, index, coeff, full,
               with_accelerations=True):  # fmt: skip
    """Forces ``lam`` (N_L, N_R, T per interface) and contact accelerations of one mode.

    ``mode`` (B, 3): left closed, right closed, tangential code; ``mu`` the
    coefficient of the sliding interfaces (kinetic, or static for the
    break-away test). ``a`` (B, 3): gap accelerations left, right and the slip
    acceleration at the reference contact. Returns False for a singular mode.
    """
    k = 0
    for i in range(active):
        tangential = mode[i, 2]
        reference, friction = _slide_coefficient(mode[i, 0], mode[i, 1], tangential, mu[i])
        for side in range(2):
            if mode[i, side] == 1:
                index[k] = 4 * i + side
                coeff[k] = friction
                k += 1
        if tangential == 1:
            index[k] = 4 * i + 2 + reference
            coeff[k] = 0.0
            k += 1
    for r in range(k):
        row = index[r]
        rhs[r] = -h[row]
        for j in range(k):
            column = index[j]
            value = w[row, column]
            if coeff[j] != 0.0:
                i = column // 4
                reference = 1 if (mode[i, 1] == 1 and mode[i, 0] == 0) else 0
                value += coeff[j] * w[row, 4 * i + 2 + reference]
            matrix[r, j] = value
    if not solve_in_place(matrix, rhs, k):
        return False
    # forces: 4 slots per interface (N_L, N_R, T at slip L, T at slip R)
    for r in range(4 * active):
        full[r] = 0.0
    for j in range(k):
        column = index[j]
        full[column] += rhs[j]
        if coeff[j] != 0.0:
            i = column // 4
            reference = 1 if (mode[i, 1] == 1 and mode[i, 0] == 0) else 0
            full[4 * i + 2 + reference] += coeff[j] * rhs[j]
    for i in range(active):
        lam[i, 0] = full[4 * i]
        lam[i, 1] = full[4 * i + 1]
        lam[i, 2] = full[4 * i + 2] + full[4 * i + 3]
    if not with_accelerations:
        return True
    contact_accelerations(active, w, h, mode, full, a)
    return True


@nb.njit(cache=True, _nrt=False)
def contact_accelerations(active, w, h, mode, full, a):
    """Gap accelerations (left, right) and slip acceleration of every interface, ``W lam + h``."""
    for i in range(active):
        reference = 1 if (mode[i, 1] == 1 and mode[i, 0] == 0) else 0
        for kind in range(3):
            row = _row(i, kind, reference)
            total = h[row]
            for s in range(4 * active):
                total += w[row, s] * full[s]
            a[i, kind] = total
        if mode[i, 0] == 1:
            a[i, 0] = 0.0
        if mode[i, 1] == 1:
            a[i, 1] = 0.0


@nb.njit(cache=True, _nrt=False)
def accelerations(active, inverse_mass, free_acc, jn, jt, mode, lam, qdd):
    """``qdd = M^-1 f + M^-1 J^T Lambda`` (the tangential force along the reference row)."""
    n = 3 * active
    for c in range(n):
        qdd[c] = 0.0
    for i in range(active):
        reference = 1 if (mode[i, 1] == 1 and mode[i, 0] == 0) else 0
        start = 3 * i - 3 if i else 0
        for col in range(start, 3 * i + 3):
            qdd[col] += (
                jn[i, 0, col] * lam[i, 0]
                + jn[i, 1, col] * lam[i, 1]
                + jt[i, reference, col] * lam[i, 2]
            )
    for c in range(n):
        qdd[c] = free_acc[c] + inverse_mass[c] * qdd[c]


@nb.njit(cache=True, _nrt=False)
def _local_modes(active_left, active_right, kinetic, sliding, out):
    """Modes of one interface in the order of ``Interface.modes``; returns their count.

    ``sliding`` is the effective restriction (an unengaged stop is free).
    """
    count = 0
    for state in range(4):
        left = 1 if state < 2 else 0
        right = 1 if state == 0 or state == 2 else 0
        if left > active_left or right > active_right:
            continue
        if left == 0 and right == 0:
            out[count, 0] = 0
            out[count, 1] = 0
            out[count, 2] = 0
            count += 1
            continue
        if kinetic and sliding != 1:
            out[count, 0] = left
            out[count, 1] = right
            out[count, 2] = 4
            count += 1
            continue
        out[count, 0] = left
        out[count, 1] = right
        out[count, 2] = 1
        count += 1
        if sliding == 0 or sliding == 3:
            out[count, 0] = left
            out[count, 1] = right
            out[count, 2] = 2
            count += 1
        if sliding == 0 or sliding == 2:
            out[count, 0] = left
            out[count, 1] = right
            out[count, 2] = 3
            count += 1
    return count


@nb.njit(cache=True, _nrt=False)
def forces_admissible(active, mode, sliding, mu_static, lam, force_tol):
    """Force inequalities of a mode's solution ``lam`` (B, 3): finite, ``N >= 0`` where
    closed, ``|T| <= mu_0 (N_L + N_R)`` where sticking (an engaged end stop adds an
    unbounded reaction on its side)."""
    for i in range(active):
        for c in range(3):
            if not np.isfinite(lam[i, c]):
                return False
        for side in range(2):
            if mode[i, side] == 1 and lam[i, side] < -force_tol:
                return False
        if mode[i, 2] == 1 and sliding[i] != 1:
            limit = mu_static[i] * (lam[i, 0] + lam[i, 1]) + force_tol
            force = lam[i, 2]
            if sliding[i] != 2 and -force > limit:
                return False
            if sliding[i] != 3 and force > limit:
                return False
    return True


@nb.njit(cache=True, _nrt=False)
def accelerations_admissible(active, mode, contact_active, a, accel_tol):
    """Acceleration inequalities of a mode's contact accelerations ``a`` (B, 3: gap left,
    gap right, slip): finite, ``a_n >= 0`` at the open touching contacts, slip in the
    direction of a starting slide."""
    for i in range(active):
        for c in range(3):
            if not np.isfinite(a[i, c]):
                return False
    for i in range(active):
        for side in range(2):
            if mode[i, side] != 1 and contact_active[i, side] and a[i, side] < -accel_tol:
                return False
        tangential = mode[i, 2]
        if tangential == 2 or tangential == 3:
            direction = 1.0 if tangential == 2 else -1.0
            if direction * a[i, 2] < -accel_tol:
                return False
    return True


@nb.njit(cache=True, _nrt=False)
def slides_with_static(active, mode, a_static, accel_tol):
    """Break-away test: the starting slides still slide with ``mu_0`` acting."""
    for i in range(active):
        tangential = mode[i, 2]
        if tangential == 2 or tangential == 3:
            direction = 1.0 if tangential == 2 else -1.0
            if direction * a_static[i, 2] < -accel_tol:
                return False
    return True


@nb.njit(cache=True, _nrt=False)
def choose(order, candidate, physical, lam_all, qdd_all, force_tol, accel_tol, kept):
    """Choice rule, relaxation and deduplication over solved modes.

    ``order`` lists the modes by the choice rule; ``lam_all`` (K, B, 3) and
    ``qdd_all`` (K, n) their solutions. Fills ``kept`` with the distinct states'
    mode indices in that order and returns ``(distinct count, relaxed)``.
    """
    any_physical = False
    any_candidate = False
    for combo in range(candidate.shape[0]):
        if candidate[combo]:
            any_candidate = True
            if physical[combo]:
                any_physical = True
    relaxed = (not any_physical) and any_candidate
    blocks = lam_all.shape[1]
    n = qdd_all.shape[1]
    distinct = 0
    lam_tol = 10.0 * force_tol
    qdd_tol = 10.0 * accel_tol
    for position in range(order.shape[0]):
        combo = order[position]
        if not candidate[combo]:
            continue
        if not (physical[combo] or relaxed):
            continue
        new = True
        for kq in range(distinct):
            other = kept[kq]
            differs = False
            for i in range(blocks):
                for c in range(3):
                    if abs(lam_all[combo, i, c] - lam_all[other, i, c]) > lam_tol:
                        differs = True
            if not differs:
                for c in range(n):
                    if abs(qdd_all[combo, c] - qdd_all[other, c]) > qdd_tol:
                        differs = True
            if not differs:
                new = False
                break
        if not new:
            continue
        kept[distinct] = combo
        distinct += 1
    return distinct, relaxed


@nb.njit(cache=True, _nrt=False)
def _local_unknowns(active, local, local_count, mu, count, index, slip_row, coeff):
    """The unknowns of every local mode, as :func:`solve_mode` orders them.

    For interface ``i`` and local mode ``m``: ``count[i, m]`` unknowns, each with its
    Delassus row (= column) ``index``, the slip row ``slip_row`` along which a
    sliding interface's friction acts and the coefficient ``coeff = -d mu`` on it
    (0 for a sticking or free interface).
    """
    for i in range(active):
        for m in range(local_count[i]):
            tangential = local[i, m, 2]
            reference, friction = _slide_coefficient(
                local[i, m, 0], local[i, m, 1], tangential, mu[i]
            )
            k = 0
            for side in range(2):
                if local[i, m, side] == 1:
                    index[i, m, k] = 4 * i + side
                    slip_row[i, m, k] = 4 * i + 2 + reference
                    coeff[i, m, k] = friction
                    k += 1
            if tangential == 1:
                index[i, m, k] = 4 * i + 2 + reference
                slip_row[i, m, k] = 4 * i + 2 + reference
                coeff[i, m, k] = 0.0
                k += 1
            count[i, m] = k


#: Work arrays of :func:`solve_states_into`, made by :func:`contact_work` for ``B``
#: interfaces (``S = 4 B`` Delassus rows, ``n = 3 B`` coordinates) and a capacity of
#: ``K`` admissible modes:
#:
#: - ``w`` (S, S) the Delassus matrix; ``vectors`` (5, S): ``V_H`` (its free term),
#:   ``V_FULL`` (the forces of a mode on the Delassus rows), and on their first ``n``
#:   entries ``V_RHS``, ``V_COEFF``, ``V_QDD``; ``matrix`` (n, n) a mode's equations;
#: - ``friction`` (2, B, 2): the kinetic coefficient and slip sign of each interface
#:   (``[0]``) and the coefficients of the break-away test (``[1]``); ``forces``
#:   (4, B, 3): a mode's forces, contact accelerations, and both again with static
#:   friction (break-away test); ``mode`` (B, 3) int;
#: - ``local`` (3, B, MAX_LOCAL, 3) int: each interface's local modes and, per local
#:   mode, the Delassus rows and slip rows of its unknowns; ``local_coeff`` (B,
#:   MAX_LOCAL, 3) their friction coefficients; ``local_unknowns`` (B, MAX_LOCAL) int
#:   their number;
#:   ``digits`` (2, B) int: each interface's local-mode count and current local mode;
#:   ``gather`` (2, n) int: a mode's unknowns' rows and slip rows;
#: - ``cand_lam``, ``cand_acc`` (K, B, 3), ``cand_qdd`` (K, n): the admissible modes;
#:   ``cand_codes`` (4, K) int: their choice keys, enumeration indices, order and
#:   the kept distinct ones; ``cand_flags`` (2, K) bool: physical (break-away test
#:   passed) and candidate.
ContactWork = namedtuple(
    "ContactWork",
    (
        "w", "vectors", "matrix", "friction", "forces", "mode", "local", "local_coeff",
        "local_unknowns", "digits", "gather", "cand_lam", "cand_acc", "cand_qdd", "cand_codes",
        "cand_flags",
    ),
)  # fmt: skip
V_H, V_FULL, V_RHS, V_COEFF, V_QDD = range(5)


@nb.njit(cache=True, _nrt=True)
def contact_work(count, capacity):
    """The :data:`ContactWork` arrays for ``count`` interfaces and ``capacity`` modes."""
    size = 4 * count
    n = 3 * count
    return ContactWork(
        np.zeros((size, size)),
        np.zeros((5, size)),
        np.zeros((n, n)),
        np.zeros((2, count, 2)),
        np.zeros((4, count, 3)),
        np.zeros((count, 3), dtype=np.int64),
        np.zeros((3, count, MAX_LOCAL, 3), dtype=np.int64),
        np.zeros((count, MAX_LOCAL, 3)),
        np.zeros((count, MAX_LOCAL), dtype=np.int64),
        np.zeros((2, count), dtype=np.int64),
        np.zeros((2, n), dtype=np.int64),
        np.zeros((capacity, count, 3)),
        np.zeros((capacity, count, 3)),
        np.zeros((capacity, n)),
        np.zeros((4, capacity), dtype=np.int64),
        np.zeros((2, capacity), dtype=np.bool_),
    )


@nb.njit(cache=True, _nrt=False)
def _sort_by_key(keys, count, order):
    """``order[:count]``: the indices of ``keys[:count]`` by increasing key (distinct keys)."""
    for position in range(count):
        order[position] = position
    for position in range(1, count):
        current = order[position]
        key = keys[current]
        j = position - 1
        while j >= 0 and keys[order[j]] > key:
            order[j + 1] = order[j]
            j -= 1
        order[j + 1] = current


@nb.njit(cache=True, _nrt=True)
def solve_contact_states(
    active,
    inverse_mass,
    free_acc,
    jn,
    bn,
    jt,
    bt,
    contact_active,
    slip,
    sliding,
    mu_static,
    mu_kinetic,
    force_tol,
    accel_tol,
    out_modes,
    out_qdd,
    out_lam,
    out_acc,
    out_index,
    info,
):
    """Every consistent state of the contact problem: the one contact kernel.

    Parameters
    ----------
    active : int
        Number of interfaces (blocks) B.
    inverse_mass, free_acc : numpy.ndarray
        Shape (3 B,): diagonal of ``M^-1`` [1/kg, 1/(kg m^2)] and free acceleration
        ``M^-1 f`` [m/s^2, rad/s^2].
    jn, jt : numpy.ndarray
        Shape (B, 2, 3 B): gap and slip rows of the left and right contact of each
        interface [-, m]; ``bn``, ``bt`` (B, 2) their velocity terms [m/s^2].
    contact_active : numpy.ndarray
        Shape (B, 2) bool: contacts touching and not separating.
    slip : numpy.ndarray
        Shape (B,): slip velocity [m/s] (non-zero: kinetic friction against it).
    sliding : numpy.ndarray
        Shape (B,) int64: effective sliding restriction codes.
    mu_static, mu_kinetic : numpy.ndarray
        Shape (B,): friction coefficients mu_0, mu [-].
    force_tol, accel_tol : float
        Absolute tolerances [N], [m/s^2] (``RELATIVE_TOLERANCE`` times the scales).
    out_modes, out_qdd, out_lam, out_acc, out_index : numpy.ndarray
        Shapes (K, B, 3) int64, (K, 3 B), (K, B, 3), (K, B, 3), (K,) int64: mode,
        accelerations, forces (N_L, N_R, T) [N], contact accelerations (gap left,
        gap right, slip at the reference contact) [m/s^2] and enumeration index of
        the first K distinct admissible states, in the order of the choice rule.
    info : numpy.ndarray
        Shape (:data:`INFO_SIZE`,) int64: modes tried, singular modes, kinetic-only
        modes (failing the break-away test), relaxed (0/1).

    Returns
    -------
    int
        Number of distinct admissible states (0: inconsistent, more than one:
        ambiguous); only the first K are written.

    Notes
    -----
    :func:`solve_states_into` on work arrays made here, with room for 16
    admissible modes, then four times more as long as they do not fit.
    """
    capacity = 16
    while True:
        work = contact_work(active, capacity)
        distinct = solve_states_into(
            work, active, inverse_mass, free_acc, jn, bn, jt, bt, contact_active, slip,
            sliding, mu_static, mu_kinetic, force_tol, accel_tol, out_modes, out_qdd, out_lam,
            out_acc, out_index, info,
        )  # fmt: skip
        if distinct >= 0:
            return distinct
        capacity *= 4


@nb.njit(cache=True, _nrt=False)
def solve_states_into(
    work,
    active,
    inverse_mass,
    free_acc,
    jn,
    bn,
    jt,
    bt,
    contact_active,
    slip,
    sliding,
    mu_static,
    mu_kinetic,
    force_tol,
    accel_tol,
    out_modes,
    out_qdd,
    out_lam,
    out_acc,
    out_index,
    info,
):
    """:func:`solve_contact_states` on the :data:`ContactWork` arrays ``work``.

    Allocates nothing. Returns -1 when more modes are admissible than ``work``
    has room for (nothing useful is written then: solve again with more room).
    """
    n = 3 * active
    size = 4 * active
    capacity = work.cand_codes.shape[1]
    w = work.w
    h = work.vectors[V_H]
    full = work.vectors[V_FULL]
    rhs = work.vectors[V_RHS]
    coeff = work.vectors[V_COEFF]
    qdd = work.vectors[V_QDD]
    matrix = work.matrix
    mu = work.friction[0]
    mu_break = work.friction[1]
    lam = work.forces[0]
    a = work.forces[1]
    lam_static = work.forces[2]
    a_static = work.forces[3]
    mode = work.mode
    local = work.local[0]
    local_index = work.local[1]
    local_slip_row = work.local[2]
    local_unknowns = work.local_unknowns
    local_coeff = work.local_coeff
    local_count = work.digits[0]
    digits = work.digits[1]
    index = work.gather[0]
    slip_row = work.gather[1]
    cand_lam = work.cand_lam
    cand_acc = work.cand_acc
    cand_qdd = work.cand_qdd
    cand_key = work.cand_codes[0]
    cand_combo = work.cand_codes[1]
    order = work.cand_codes[2]
    kept = work.cand_codes[3]
    cand_physical = work.cand_flags[0]
    candidate = work.cand_flags[1]
    delassus(active, inverse_mass, free_acc, jn, bn, jt, bt, w, h)
    total = 1
    for i in range(active):
        local_count[i] = _local_modes(
            1 if contact_active[i, 0] else 0,
            1 if contact_active[i, 1] else 0,
            slip[i] != 0.0,
            sliding[i],
            local[i],
        )
        total *= local_count[i]
    for i in range(active):
        sign = 1.0 if slip[i] > 0.0 else (-1.0 if slip[i] < 0.0 else 0.0)
        mu[i, 0] = mu_kinetic[i]
        mu[i, 1] = sign
        mu_break[i, 0] = mu_kinetic[i] if slip[i] != 0.0 else mu_static[i]
        mu_break[i, 1] = sign
    # the unknowns of every local mode, so that a mode's system is gathered from W
    # without decoding the mode again (the values and order of solve_mode)
    _local_unknowns(
        active, local, local_count, mu, local_unknowns, local_index, local_slip_row, local_coeff
    )
    # only the admissible modes (candidates) are kept, in enumeration order
    candidates = 0
    for i in range(active):
        digits[i] = 0
    singular = 0
    kinetic_only = 0
    for combo in range(total):
        if combo:
            # itertools.product order: the last interface varies fastest
            i = active - 1
            digits[i] += 1
            while digits[i] == local_count[i]:
                digits[i] = 0
                i -= 1
                digits[i] += 1
        sticking = 0
        opened = 0
        has_slide = False
        k = 0
        for i in range(active):
            m = digits[i]
            mode[i, 0] = local[i, m, 0]
            mode[i, 1] = local[i, m, 1]
            tangential = local[i, m, 2]
            mode[i, 2] = tangential
            if tangential == 1:
                sticking += 1
            elif tangential == 2 or tangential == 3:
                has_slide = True
            opened += 2 - mode[i, 0] - mode[i, 1]
            for j in range(local_unknowns[i, m]):
                index[k] = local_index[i, m, j]
                slip_row[k] = local_slip_row[i, m, j]
                coeff[k] = local_coeff[i, m, j]
                k += 1
        # the mode's equations: solve_mode's system, gathered
        for r in range(k):
            row = index[r]
            rhs[r] = -h[row]
            for j in range(k):
                value = w[row, index[j]]
                if coeff[j] != 0.0:
                    value += coeff[j] * w[row, slip_row[j]]
                matrix[r, j] = value
        if not solve_in_place(matrix, rhs, k):
            singular += 1
            continue
        # a closed contact's normal force is its own unknown: most modes fail on its
        # sign, seen before the forces are gathered (forces_admissible repeats it)
        pulls = False
        for j in range(k):
            if (index[j] & 3) < 2 and rhs[j] < -force_tol:
                pulls = True
                break
        if pulls:
            continue
        for r in range(size):
            full[r] = 0.0
        for j in range(k):
            full[index[j]] += rhs[j]
            if coeff[j] != 0.0:
                full[slip_row[j]] += coeff[j] * rhs[j]
        for i in range(active):
            lam[i, 0] = full[4 * i]
            lam[i, 1] = full[4 * i + 1]
            lam[i, 2] = full[4 * i + 2] + full[4 * i + 3]
        # the inequalities on the forces first (most modes fail there), then the
        # contact accelerations
        if not forces_admissible(active, mode, sliding, mu_static, lam, force_tol):
            continue
        contact_accelerations(active, w, h, mode, full, a)
        if not accelerations_admissible(active, mode, contact_active, a, accel_tol):
            continue
        accelerations(active, inverse_mass, free_acc, jn, jt, mode, lam, qdd)
        ok = True
        for c in range(n):
            if not np.isfinite(qdd[c]):
                ok = False
        if not ok:
            continue
        physical = True
        if has_slide:
            physical = False
            if solve_mode(
                active, w, h, mode, mu_break, lam_static, a_static, matrix, rhs, index, coeff,
                full,
            ):  # fmt: skip
                physical = slides_with_static(active, mode, a_static, accel_tol)
            if not physical:
                kinetic_only += 1
        if candidates == capacity:
            return -1
        for i in range(active):
            for c in range(3):
                cand_lam[candidates, i, c] = lam[i, c]
                cand_acc[candidates, i, c] = a[i, c]
        for c in range(n):
            cand_qdd[candidates, c] = qdd[c]
        cand_key[candidates] = ((active - sticking) * (2 * active + 1) + opened) * total + combo
        cand_combo[candidates] = combo
        cand_physical[candidates] = physical
        candidate[candidates] = True
        candidates += 1
    # the choice rule's order among the candidates (keys: fewest non-sticking
    # interfaces, then fewest open contacts, then enumeration order)
    _sort_by_key(cand_key, candidates, order)
    distinct, relaxed = choose(
        order[:candidates],
        candidate[:candidates],
        cand_physical[:candidates],
        cand_lam[:candidates],
        cand_qdd[:candidates],
        force_tol,
        accel_tol,
        kept,
    )
    for position in range(min(distinct, out_modes.shape[0])):
        slot = kept[position]
        combo = cand_combo[slot]
        out_index[position] = combo
        rest = combo
        for i in range(active - 1, -1, -1):
            digits[i] = rest % local_count[i]
            rest //= local_count[i]
        for i in range(active):
            for c in range(3):
                out_modes[position, i, c] = local[i, digits[i], c]
                out_lam[position, i, c] = cand_lam[slot, i, c]
                out_acc[position, i, c] = cand_acc[slot, i, c]
        for c in range(n):
            out_qdd[position, c] = cand_qdd[slot, c]
    info[INFO_MODES] = total
    info[INFO_SINGULAR] = singular
    info[INFO_KINETIC_ONLY] = kinetic_only
    info[INFO_RELAXED] = 1 if relaxed else 0
    return distinct


@nb.njit(cache=True, _nrt=True)
def solve_contact_problem(
    active,
    inverse_mass,
    free_acc,
    jn,
    bn,
    jt,
    bt,
    contact_active,
    slip,
    sliding,
    mu_static,
    mu_kinetic,
    force_tol,
    accel_tol,
    out_modes,
    out_qdd,
    out_lam,
):
    """:func:`solve_contact_states` without the contact accelerations, indices and counts."""
    count = out_modes.shape[0]
    out_acc = np.empty((count, active, 3))
    out_index = np.empty(count, dtype=np.int64)
    info = np.empty(INFO_SIZE, dtype=np.int64)
    return solve_contact_states(
        active, inverse_mass, free_acc, jn, bn, jt, bt, contact_active, slip, sliding,
        mu_static, mu_kinetic, force_tol, accel_tol, out_modes, out_qdd, out_lam, out_acc,
        out_index, info,
    )  # fmt: skip


def kernel_inputs(problem: ContactProblem) -> tuple:
    """The arrays :func:`solve_contact_states` takes for a :class:`ContactProblem`.

    Parameters
    ----------
    problem : ContactProblem
        Its mass matrix must be diagonal (the coordinates of each block are its
        centre of gravity and its rotation).

    Returns
    -------
    tuple
        ``(active, inverse_mass, free_acc, jn, bn, jt, bt, contact_active, slip,
        sliding, mu_static, mu_kinetic, force_tol, accel_tol)``.
    """
    mass = np.asarray(problem.mass_matrix, dtype=float)
    diagonal = np.diag(mass).copy()
    if np.any(mass - np.diag(diagonal)):
        raise ValueError("the contact kernel needs a diagonal mass matrix")
    inverse_mass = 1.0 / diagonal
    free_acc = inverse_mass * np.asarray(problem.applied_force, dtype=float)
    interfaces = problem.interfaces
    count = len(interfaces)
    n = problem.size
    jn = np.zeros((count, 2, n))
    jt = np.zeros((count, 2, n))
    bn = np.zeros((count, 2))
    bt = np.zeros((count, 2))
    for i, interface in enumerate(interfaces):
        jn[i] = interface.normal_jacobian
        jt[i] = interface.tangential_jacobian
        bn[i] = interface.normal_bias
        bt[i] = interface.tangential_bias
    contact_active = np.array([interface.active for interface in interfaces], dtype=np.bool_)
    contact_active = contact_active.reshape(count, 2)
    slip = np.array([interface.slip_velocity for interface in interfaces], dtype=float)
    sliding = np.array(
        [_SLIDING_CODES[interface.effective_sliding()] for interface in interfaces], dtype=np.int64
    )
    mu_static = np.array([interface.static_friction for interface in interfaces], dtype=float)
    mu_kinetic = np.array([interface.kinetic_friction for interface in interfaces], dtype=float)
    tiny = np.finfo(float).tiny
    force_tol = RELATIVE_TOLERANCE * max(problem.force_scale, tiny)
    accel_tol = RELATIVE_TOLERANCE * max(problem.acceleration_scale, tiny)
    return (
        count, inverse_mass, free_acc, jn, bn, jt, bt, contact_active, slip, sliding,
        mu_static, mu_kinetic, force_tol, accel_tol,
    )  # fmt: skip


def solve(problem: ContactProblem) -> ContactResult:
    """Every consistent contact state of a stack at an instant (the compiled kernel).

    Parameters
    ----------
    problem : ContactProblem
        Masses (diagonal mass matrix), applied forces, contact kinematics and
        friction.

    Returns
    -------
    ContactResult
        All distinct admissible states and the one chosen by the rule "static
        friction holds where it can, then fewest separations" (paper section 3;
        module docstring), with the diagnostics of the enumeration.
    """
    inputs = kernel_inputs(problem)
    count, n = inputs[0], problem.size
    capacity = MAX_DISTINCT
    while True:
        modes = np.zeros((capacity, count, 3), dtype=np.int64)
        qdd = np.zeros((capacity, n))
        lam = np.zeros((capacity, count, 3))
        acc = np.zeros((capacity, count, 3))
        index = np.zeros(capacity, dtype=np.int64)
        info = np.zeros(INFO_SIZE, dtype=np.int64)
        distinct = int(solve_contact_states(*inputs, modes, qdd, lam, acc, index, info))
        if distinct <= capacity:
            break
        capacity = distinct
    mass = np.asarray(problem.mass_matrix, dtype=float)
    force_scale = max(problem.force_scale, 1e-300)
    solutions = []
    for k in range(distinct):
        interface_modes = tuple(
            InterfaceMode(bool(left), bool(right), Tangential(int(tangential)))
            for left, right, tangential in modes[k]
        )
        # residual of the equations of motion M qdd = f + J^T Lambda
        generalised = mass @ qdd[k] - problem.applied_force
        for i, (interface, mode) in enumerate(
            zip(problem.interfaces, interface_modes, strict=True)
        ):
            reference = 1 if (mode.right_closed and not mode.left_closed) else 0
            generalised = generalised - (
                interface.normal_jacobian[0] * lam[k, i, 0]
                + interface.normal_jacobian[1] * lam[k, i, 1]
                + interface.tangential_jacobian[reference] * lam[k, i, 2]
            )
        solutions.append(
            ContactSolution(
                modes=interface_modes,
                acceleration=qdd[k].copy(),
                normal_force=lam[k, :, :2].copy(),
                tangential_force=lam[k, :, 2].copy(),
                gap_acceleration=acc[k, :, :2].copy(),
                slip_acceleration=acc[k, :, 2].copy(),
                residual=float(np.max(np.abs(generalised), initial=0.0)) / force_scale,
            )
        )
    diagnostics = ContactDiagnostics(
        modes_tried=int(info[INFO_MODES]),
        singular_modes=int(info[INFO_SINGULAR]),
        kinetic_only_modes=int(info[INFO_KINETIC_ONLY]),
        relaxed=bool(info[INFO_RELAXED]),
    )
    status = "inconsistent" if distinct == 0 else ("unique" if distinct == 1 else "ambiguous")
    return ContactResult(
        status=status,
        chosen=solutions[0] if solutions else None,
        admissible=tuple(solutions),
        diagnostics=diagnostics,
    )
