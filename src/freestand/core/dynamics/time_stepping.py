"""Velocity-impulse time stepping (Moreau-Jean): the engine's remedy where events fail.

The event-driven engine (:mod:`freestand.core.dynamics.engine`) needs, after
every event, a contact mode consistent with the unilateral and Coulomb
conditions at acceleration level. Rigid contact with friction does not always
have one: a block rocking or sliding on a rough contact may jam (Painleve's
paradox: no mode, or no mode after a tangential impact), and impacts or
chattering against an end stop may accumulate to a persistent contact in
finite time (a Zeno point), which events resolved one by one never pass. For a
short stretch the engine then integrates with Moreau's midpoint scheme at the
level of velocities and impulses (Moreau 1988; Jean 1999; the scheme of
Siconos' ``MoreauJeanOSI``), which has a solution at every step, and returns
to events as soon as an event-driven mode is consistent again.

One step of length ``h`` from ``(q, v)`` at time ``t``::

    q_m  = q + h/2 v                                  (midpoint)
    v_f  = v + h M^-1 f(t + h/2)                      (free velocity)
    M (v+ - v_f) = sum_c ( J_n,c^T P_n,c + J_t,c^T P_t,c )
    0 <= P_n,c  _|_  J_n,c v+ >= 0                    (each contact c of the index set)
    |P_t,c| <= mu P_n,c,  P_t,c J_t,c v+ <= 0, and J_t,c v+ = 0 while |P_t,c| < mu P_n,c
    q+ = q_m + h/2 v+

with the Jacobians taken at ``q_m`` and the index set the contacts whose gap,
predicted to the step's end, closes. The plastic impact law at velocity level
(``J_n v+ >= 0``) is the Newton law with zero restitution; an interface with
``sliding = "none"`` has unbounded friction, an engaged end stop bounds the
slip one way.

The impulses are found by projected Gauss-Seidel on ``W = J M^-1 J^T``
(Jean 1999) inside fixed-point iterations on the friction bounds: for given
bounds each contact's normal, then tangential impulse is the exact minimiser
of the kinetic energy ``T(v) = 1/2 v^T M v`` over its interval with the others
fixed, so ``T(v+) <= T(v_f)``: the contact impulses never create energy
(:func:`impulse_step` returns the ratio, checked by the caller and
reported).

References
----------
Moreau, J. J. (1988). Unilateral contact and dry friction in finite freedom
dynamics. In *Nonsmooth Mechanics and Applications*, CISM 302, 1-82.
Jean, M. (1999). The non-smooth contact dynamics method. *Computer Methods in
Applied Mechanics and Engineering* 177, 235-257.
Acary, V. and Brogliato, B. (2008). *Numerical Methods for Nonsmooth Dynamical
Systems*, Springer, chapter 10.
"""

from __future__ import annotations

import numba as nb
import numpy as np

#: Friction coefficient standing for the unbounded friction of ``sliding = "none"``
#: and for an engaged end stop [-]: large enough that the tangential impulse never
#: reaches it in a step, finite so that an opening contact carries none.
UNBOUNDED_FRICTION = 1e6

#: Sweeps of projected Gauss-Seidel at most per step.
MAX_SWEEPS = 400

#: Relative change of the impulses [-] below which the sweeps stop.
SWEEP_TOLERANCE = 1e-12

#: Fixed-point iterations on the friction bounds at most per step.
MAX_FIXED_POINT = 30

#: Relative change of the normal impulses [-] below which the fixed point stops.
FIXED_POINT_TOLERANCE = 1e-9


@nb.njit(cache=True)
def kinetic_energy(inverse_mass, v, n):
    """T = 1/2 sum_k v_k^2 / Minv_k [J] of the first ``n`` coordinates (M diagonal)."""
    total = 0.0
    for k in range(n):
        total += 0.5 * v[k] * v[k] / inverse_mass[k]
    return total


@nb.njit(cache=True)
def _dot(row, v, n):
    total = 0.0
    for k in range(n):
        total += row[k] * v[k]
    return total


@nb.njit(cache=True)
def _weight(row, inverse_mass, n):
    total = 0.0
    for k in range(n):
        total += row[k] * row[k] * inverse_mass[k]
    return total


@nb.njit(cache=True)
def _apply(row, inverse_mass, impulse, v, n):
    for k in range(n):
        v[k] += inverse_mass[k] * row[k] * impulse


@nb.njit(cache=True)
def _box_sweeps(active, inverse_mass, jn, jt, closed, bound_low, bound_high, v_free, v,
                normal, tangential):  # fmt: skip
    """Projected Gauss-Seidel from zero impulses, the tangential ones in fixed boxes.

    Each update is the exact minimiser of the kinetic energy over its
    coordinate's interval, so the energy falls monotonically from T(v_f).
    """
    n = 3 * active
    v[:n] = v_free[:n]
    for i in range(active):
        for c in range(2):
            normal[i, c] = 0.0
            tangential[i, c] = 0.0
    scale = 0.0
    for _ in range(MAX_SWEEPS):
        change = 0.0
        for i in range(active):
            for c in range(2):
                if not closed[i, c]:
                    continue
                w_n = _weight(jn[i, c], inverse_mass, n)
                if w_n > 0.0:
                    old = normal[i, c]
                    new = max(0.0, old - _dot(jn[i, c], v, n) / w_n)
                    _apply(jn[i, c], inverse_mass, new - old, v, n)
                    normal[i, c] = new
                    change = max(change, abs(new - old))
                    scale = max(scale, new)
                w_t = _weight(jt[i, c], inverse_mass, n)
                if w_t > 0.0:
                    old = tangential[i, c]
                    new = old - _dot(jt[i, c], v, n) / w_t
                    new = min(max(new, -bound_low[i, c]), bound_high[i, c])
                    _apply(jt[i, c], inverse_mass, new - old, v, n)
                    tangential[i, c] = new
                    change = max(change, abs(new - old))
                    scale = max(scale, abs(new))
        if change <= SWEEP_TOLERANCE * scale:
            break


@nb.njit(cache=True, _nrt=True)
def impulse_step(active, inverse_mass, jn, jt, closed, mu_low, mu_high, v, normal, tangential):
    """Contact impulses of one Moreau-Jean step; the energy ratio ``T(v+)/T(v_f)``.

    Coulomb's cone couples the tangential bound to the normal impulse; it is
    met by fixed-point iterations on the bound (Tresca problems: the bound
    ``mu P_n`` from the previous iterate, a box), each solved by projected
    Gauss-Seidel from zero impulses, which lowers the kinetic energy
    monotonically, so every iterate has ``T(v+) <= T(v_f)`` (Acary and
    Brogliato 2008, section 13.6).

    Parameters
    ----------
    active : int
        Blocks simulated (coordinates ``3 active``).
    inverse_mass : numpy.ndarray
        Diagonal of M^-1 [1/kg, 1/(kg m^2)], (3 B,).
    jn, jt : numpy.ndarray
        Normal and tangential Jacobians of each contact at the midpoint
        [-, m], (B, 2, 3 B).
    closed : numpy.ndarray of bool
        The index set, (B, 2).
    mu_low, mu_high : numpy.ndarray
        Friction bounds of each interface, (B,): the tangential impulse of a
        contact lies in ``[-mu_low P_n, mu_high P_n]`` [-] (equal for
        Coulomb friction; UNBOUNDED_FRICTION one way at an engaged end stop,
        both ways for ``sliding = "none"``).
    v : numpy.ndarray
        In: the free velocity v_f; out: v+ [m/s, rad/s], (3 B,).
    normal, tangential : numpy.ndarray
        Out: the impulses P_n, P_t of each contact [N s], (B, 2).

    Returns
    -------
    float
        ``T(v+) / T(v_f)``, at most 1 up to round-off (1 when T(v_f) = 0).
    """
    n = 3 * active
    v_free = v[:n].copy()
    before = kinetic_energy(inverse_mass, v_free, n)
    bound_low = np.zeros((active, 2))
    bound_high = np.zeros((active, 2))
    previous = np.zeros((active, 2))
    for _ in range(MAX_FIXED_POINT):
        _box_sweeps(active, inverse_mass, jn, jt, closed, bound_low, bound_high, v_free, v,
                    normal, tangential)  # fmt: skip
        change = 0.0
        scale = 0.0
        for i in range(active):
            for c in range(2):
                change = max(change, abs(normal[i, c] - previous[i, c]))
                scale = max(scale, normal[i, c])
                previous[i, c] = normal[i, c]
                bound_low[i, c] = mu_low[i] * normal[i, c]
                bound_high[i, c] = mu_high[i] * normal[i, c]
        if change <= FIXED_POINT_TOLERANCE * scale:
            break
    after = kinetic_energy(inverse_mass, v, n)
    if before <= 0.0:
        return 1.0
    return after / before
