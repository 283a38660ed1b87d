"""Velocity-level contact of one body at its base points: the remedy (compiled).

Where the event-driven contact problem has no consistent mode (the
Painleve-type configurations of rigid contact with friction) or the impact
law of :func:`freestand.core.contact.body_modes.impact` finds no admissible
candidate, the contact is resolved at the velocity level, as Moreau (1988)
and Jean (1999) do (the scheme of Siconos), which always has a solution:

- the base is represented by points (a box's corners; a cylinder's rim at
  ``RIM_POINTS`` angles from its lowest point);
- at each closed point an impulse ``P = (P_x, P_y, P_n)`` with ``P_n >= 0``
  complementary to the normal velocity after, ``u_n >= 0`` (plastic), and the
  tangential impulse in the circular cone ``|P_t| <= mu P_n``;
- friction by Coulomb's law: a point inside the cone sticks, a slipping
  point's tangential impulse is ``-mu P_n u_t / |u_t|`` (opposite its slip
  after; maximum dissipation);
- solved by projected Gauss-Seidel over the points (Jean 1999; each point's
  normal impulse projected on ``P_n >= 0``, then its tangential impulse
  ``P_t - u_t / w_max`` projected radially onto the disc of radius
  ``mu P_n``, ``w_max`` the largest eigenvalue of the point's tangential
  Delassus block: with a scalar step the fixed point is Coulomb's law,
  where the point's full 2 x 2 block would make the friction oppose the
  slip only in that block's metric), sweeping the points
  forwards and backwards in turn (symmetric Gauss-Seidel): always in one
  order, the sweeps could cycle where many points touch and the base twists
  (a flat cylinder's eight rim points, ``tests/test_body_impulse.py``);
- the sweeps converge linearly, and slowly where impulses can move between
  points without moving the body (an edge's two corners pushing along it):
  from the sweeps' impulses after 8, 16, 32, ... sweeps a semi-smooth
  Newton method (:mod:`freestand.core.contact.alart_curnier`) is tried on
  the points that press and, where it fails, on subsets of them
  (:func:`polish_pressed`: Newton's method does not take a pressing point's
  impulse to zero), and its solution taken where it meets every law at
  every point to ``POLISH_TOLERANCE``;
  from a start with impulses (the remedy's step before's) it is tried
  first, before any sweep;
- two points (an edge's corners) that can both stick are solved in closed
  form first (:func:`_two_points_stick`): the body then turns about the
  line through them, and the impulse along that line, which moves nothing,
  is chosen inside both cones.

With Coulomb's law met, a plastic impact never gains kinetic energy (the
change is ``P . u_after - P.W.P / 2 <= 0``); sweeps stopped short of it
might, so the result is checked: a solution that would raise the kinetic
energy is replaced by the frictionless one (:func:`point_impulses` with
``mu = 0``), which never does. References:
J. J. Moreau, Unilateral contact and dry friction in finite freedom
dynamics, CISM 302 (1988); M. Jean, The non-smooth contact dynamics method,
Comput. Methods Appl. Mech. Engrg. 177 (1999) 235-257.
"""

from __future__ import annotations

import math

import numpy as np

from freestand.core.contact.alart_curnier import (
    largest_tangential_eigenvalue,
    solve_alart_curnier,
    work_fields,
)
from freestand.core.contact.body_kernel import (
    P_HALF_X,
    P_MASS,
    P_RESTITUTION,
    P_SHAPE,
    SHAPE_BOX,
    arm,
    box_corner,
    cross,
    lowest_rim_angle,
)
from freestand.core.contact.compiled import kernel
from freestand.core.contact.vectors import norm2

MAX_POINTS = 8
RIM_POINTS = 8  # a cylinder's base as this many rim points, from the lowest one
#: Projected Gauss-Seidel sweeps at most. They converge linearly, and slowly where impulses
#: can move between points without moving the body: an edge's two corners, one sticking just
#: inside the cone, needed some 1300 sweeps before the polish found the solution. They end
#: sooner where they converge or the polish succeeds (on random impacts: 7 sweeps on average).
SWEEPS = 5000
SWEEP_TOLERANCE = 1e-12  # relative change of the velocity that ends the sweeps
POLISH_FROM = 7  # the sweeps' exact polish is tried after sweeps 8, 16, 32, ... (index 2^k - 1)
ENDED_CONVERGED, ENDED_POLISHED, ENDED_EXHAUSTED = 0, 1, 2  # how point_impulses' sweeps ended
ENDED_STUCK = 3  # two points, both sticking: their closed form (_two_points_stick), no sweep
POLISH_TOLERANCE = 1e-10  # the polish's laws, relative to the speed (and to m times it)
SUBSET_POINTS = 4  # where this many points press or fewer, every subset of them is polished

_N3 = 3 * MAX_POINTS
#: The impulses' work arrays, one record (:func:`new_impulse_work`): allocated once per run
#: (:func:`freestand.core.dynamics.body_engine.run`), the functions below then allocate
#: nothing and need no reference counting, which a rocking cabinet's time stepping paid at
#: every call. Matrices of the points are flat buffers, viewed as (3n, 3n) or (3n, 6) for n
#: points.
IMPULSE_WORK_DTYPE = np.dtype(
    [
        ("start", "f8", 6), ("before", "f8", 6), ("after", "f8", 6), ("kept", "f8", 6),
        ("probe", "f8", 6), ("point", "f8", 3), ("zeros", "f8", (MAX_POINTS, 3)),
        ("point_delassus", "f8", (MAX_POINTS, 3, 3)), ("stiffness", "f8", MAX_POINTS),
        ("columns", "f8", _N3 * 6), ("delassus", "f8", _N3 * _N3), ("free", "f8", _N3),
        ("speeds", "f8", _N3), ("solution", "f8", _N3), ("order", "i8", MAX_POINTS),
        ("chosen", "i8", MAX_POINTS), ("subset", "f8", (MAX_POINTS, 3)),
        ("trial", "f8", (MAX_POINTS, 3)),
        # a velocity-level step's own (the remedy's, an impact's): its velocity, the free
        # velocity, its base points' arms
        ("velocity", "f8", 6), ("free_velocity", "f8", 3), ("arms", "f8", (MAX_POINTS, 3)),
    ]
    + work_fields(MAX_POINTS),
    align=True,
)  # fmt: skip


def new_impulse_work() -> np.void:
    """A record of ``IMPULSE_WORK_DTYPE`` (a view of a one-element array, which it keeps alive)."""
    return np.zeros(1, dtype=IMPULSE_WORK_DTYPE)[0]


@kernel(cache=True, error_model="numpy", _nrt=False)
def base_points(par, y, rot, psi_stored, gap_limit, arms, work):
    """The base points within ``gap_limit`` [m] of the support: their arms from G in ``arms``.

    Returns their count. A box's corners; a cylinder's rim at ``RIM_POINTS``
    angles starting from its lowest point. ``work``: a record of
    ``IMPULSE_WORK_DTYPE``.
    """
    count = 0
    d = work["point"]
    if par[P_SHAPE] == SHAPE_BOX:
        for k in range(4):
            sx, sy = box_corner(par, k)
            arm(par, rot, sx, sy, 0.0, d)
            if y[2] + d[2] <= gap_limit:
                for i in range(3):
                    arms[count, i] = d[i]
                count += 1
        return count
    radius = par[P_HALF_X]
    lowest = lowest_rim_angle(rot, psi_stored)
    for k in range(RIM_POINTS):
        angle = lowest + 2.0 * math.pi * k / RIM_POINTS
        arm(par, rot, radius * math.cos(angle), radius * math.sin(angle), 0.0, d)
        if y[2] + d[2] <= gap_limit:
            for i in range(3):
                arms[count, i] = d[i]
            count += 1
    return count


@kernel(cache=True, error_model="numpy", _nrt=False)
def _apply(par, inv_inertia, d, px, py, pz, velocity):
    """velocity += M^-1 J^T P for the impulse P at arm d."""
    m = par[P_MASS]
    velocity[0] += px / m
    velocity[1] += py / m
    velocity[2] += pz / m
    tx, ty, tz = cross(d[0], d[1], d[2], px, py, pz)
    for i in range(3):
        velocity[3 + i] += inv_inertia[i, 0] * tx + inv_inertia[i, 1] * ty + inv_inertia[i, 2] * tz


@kernel(cache=True, error_model="numpy", _nrt=False)
def _point_speed(velocity, d):
    """(u_x, u_y, u_n) of the point at arm d."""
    cx, cy, cz = cross(velocity[3], velocity[4], velocity[5], d[0], d[1], d[2])
    return velocity[0] + cx, velocity[1] + cy, velocity[2] + cz


@kernel(cache=True, error_model="numpy", _nrt=False)
def _delassus(par, inv_inertia, d, out, probe):
    """The point's 3 x 3 Delassus matrix W = J M^-1 J^T (columns: unit impulses x, y, n).

    ``probe`` (6): work space.
    """
    for k in range(3):
        for i in range(6):
            probe[i] = 0.0
        _apply(par, inv_inertia, d, 1.0 if k == 0 else 0.0, 1.0 if k == 1 else 0.0,
               1.0 if k == 2 else 0.0, probe)  # fmt: skip
        ux, uy, un = _point_speed(probe, d)
        out[0, k] = ux
        out[1, k] = uy
        out[2, k] = un


@kernel(cache=True, error_model="numpy", _nrt=False)
def inertia_times(inv_inertia, wx, wy, wz):
    """I_w omega [kg m^2/s] from the inverse ``A = I_w^-1``: ``adj(A) omega / det(A)``.

    The inverse by its cofactors: no factorisation, no allocation.
    """
    a = inv_inertia
    # cofactors of A (adj(A) = C^T; A is symmetric, so is C)
    c00 = a[1, 1] * a[2, 2] - a[1, 2] * a[2, 1]
    c01 = a[1, 2] * a[2, 0] - a[1, 0] * a[2, 2]
    c02 = a[1, 0] * a[2, 1] - a[1, 1] * a[2, 0]
    c10 = a[0, 2] * a[2, 1] - a[0, 1] * a[2, 2]
    c11 = a[0, 0] * a[2, 2] - a[0, 2] * a[2, 0]
    c12 = a[0, 1] * a[2, 0] - a[0, 0] * a[2, 1]
    c20 = a[0, 1] * a[1, 2] - a[0, 2] * a[1, 1]
    c21 = a[0, 2] * a[1, 0] - a[0, 0] * a[1, 2]
    c22 = a[0, 0] * a[1, 1] - a[0, 1] * a[1, 0]
    determinant = a[0, 0] * c00 + a[0, 1] * c01 + a[0, 2] * c02
    return (
        (c00 * wx + c10 * wy + c20 * wz) / determinant,
        (c01 * wx + c11 * wy + c21 * wz) / determinant,
        (c02 * wx + c12 * wy + c22 * wz) / determinant,
    )


@kernel(cache=True, error_model="numpy", _nrt=False)
def kinetic_energy(par, inv_inertia, velocity):
    """(1/2) m |v|^2 + (1/2) omega . I_w omega [J] (I_w from its inverse, :func:`inertia_times`)."""
    wx, wy, wz = velocity[3], velocity[4], velocity[5]
    lx, ly, lz = inertia_times(inv_inertia, wx, wy, wz)
    translational = par[P_MASS] * (velocity[0] ** 2 + velocity[1] ** 2 + velocity[2] ** 2)
    return 0.5 * (translational + wx * lx + wy * ly + wz * lz)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _sweep(par, inv_inertia, arms, count, mu, delassus, stiffness, velocity, impulses, backwards,
           scale):  # fmt: skip
    """One Gauss-Seidel sweep over the points; returns the largest change of velocity / scale.

    Per point: the normal impulse that brings its normal velocity to zero,
    kept >= 0; then the tangential impulse ``P_t - u_t / w_max`` projected
    radially onto the disc ``|P_t| <= mu P_n`` (``w_max`` the largest
    eigenvalue of the point's W_tt, ``stiffness``): with a scalar step the
    fixed point is Coulomb's law itself, friction opposite the slip
    (Jean 1999, the projection with a scalar rho).
    """
    change = 0.0
    for q in range(count):
        p = count - 1 - q if backwards else q
        d = arms[p]
        w = delassus[p]
        ux, uy, un = _point_speed(velocity, d)
        normal = max(0.0, impulses[p, 2] - un / w[2, 2])
        dn = normal - impulses[p, 2]
        impulses[p, 2] = normal
        _apply(par, inv_inertia, d, 0.0, 0.0, dn, velocity)
        change = max(change, abs(dn) / (par[P_MASS] * scale))
        ux, uy, un = _point_speed(velocity, d)
        tx = impulses[p, 0] - ux / stiffness[p]
        ty = impulses[p, 1] - uy / stiffness[p]
        size = norm2(tx, ty)
        limit = mu * normal
        if size > limit:
            tx *= limit / size
            ty *= limit / size
        dx = tx - impulses[p, 0]
        dy = ty - impulses[p, 1]
        impulses[p, 0] = tx
        impulses[p, 1] = ty
        _apply(par, inv_inertia, d, dx, dy, 0.0, velocity)
        change = max(change, norm2(dx, dy) / (par[P_MASS] * scale))
    return change


@kernel(cache=True, error_model="numpy", _nrt=False)
def polish(par, inv_inertia, arms, count, mu, start, impulses, velocity, scale, work):
    """The exact impulses from the sweeps', taken where they obey the laws.

    The points' Delassus matrix W (3n x 3n) and velocities before (from
    ``start``, the velocity before any impulse) are formed and the problem
    solved exactly from the sweeps' impulses by a semi-smooth Newton method
    (:func:`freestand.core.contact.alart_curnier.solve_alart_curnier`). Where the
    solution obeys every law to ``POLISH_TOLERANCE`` of the speed (and of
    m times it for impulses; ``scale`` [m/s] the largest component of
    ``start``), it replaces ``impulses`` and ``velocity`` and True is
    returned; otherwise both are left as they are and False is returned.
    ``work``: a record of ``IMPULSE_WORK_DTYPE``.
    """
    n3 = 3 * count
    # the body's velocity change per unit impulse (rows), the points' velocities per impulse
    columns = work["columns"][: n3 * 6].reshape((n3, 6))
    columns[:, :] = 0.0
    delassus = work["delassus"][: n3 * n3].reshape((n3, n3))
    free = work["free"][:n3]
    speeds = work["speeds"][:n3]
    solution = work["solution"][:n3]  # from the sweeps' impulses
    for j in range(n3):
        _apply(par, inv_inertia, arms[j // 3], 1.0 if j % 3 == 0 else 0.0,
               1.0 if j % 3 == 1 else 0.0, 1.0 if j % 3 == 2 else 0.0, columns[j])  # fmt: skip
        solution[j] = impulses[j // 3, j % 3]
    for p in range(count):
        before = _point_speed(start, arms[p])
        for i in range(3):
            free[3 * p + i] = before[i]
        for j in range(n3):
            speed = _point_speed(columns[j], arms[p])
            for i in range(3):
                delassus[3 * p + i, j] = speed[i]
    velocity_tolerance = POLISH_TOLERANCE * scale
    impulse_tolerance = POLISH_TOLERANCE * par[P_MASS] * scale
    if not solve_alart_curnier(count, mu, delassus, free, solution, velocity_tolerance,
                               impulse_tolerance, speeds, work):  # fmt: skip
        return False
    for i in range(6):
        velocity[i] = start[i]
    for j in range(n3):
        impulses[j // 3, j % 3] = solution[j]
        for i in range(6):
            velocity[i] += columns[j, i] * solution[j]
    return True


@kernel(cache=True, error_model="numpy", _nrt=False)
def polish_pressed(par, inv_inertia, arms, count, mu, start, impulses, velocity, scale, work):
    """:func:`polish` on the points that press, then on their subsets; True where one is found.

    On the points with a normal impulse in the sweeps' ``impulses`` (every
    point where all press or none does: :func:`polish`), then on their
    subsets, largest first: every subset where up to ``SUBSET_POINTS``
    press, else the strongest ones (by normal impulse) of each size. A solution on a
    subset is taken where the points left out, with no impulse, do not
    approach the support after it (a normal velocity of at least
    ``-POLISH_TOLERANCE`` times ``scale``): it then obeys every law at every
    point. Newton's method does not take a point's impulse to zero from a
    start where it presses (the kink of Alart and Curnier's function): a
    near-flat cylinder landing on its eight rim points, whose solution has
    one point pressing, failed every polish on all eight and on the two
    that pressed after the early sweeps (the other one the stronger there),
    and the sweeps took 116 sweeps and 0.4 ms to converge; that point alone
    is solved at once. ``impulses`` and ``velocity`` are set only where a
    solution is found (as :func:`polish`). ``work``: a record of
    ``IMPULSE_WORK_DTYPE``.
    """
    pressing = 0
    for p in range(count):
        if impulses[p, 2] > 0.0:
            pressing += 1
    if pressing == count or pressing == 0:
        if polish(par, inv_inertia, arms, count, mu, start, impulses, velocity, scale, work):
            return True
    order = work["order"]
    _order_by_pressing(impulses, count, order)
    subset, trial, chosen, after = work["subset"], work["trial"], work["chosen"], work["after"]
    every = pressing <= SUBSET_POINTS
    for size in range(min(pressing, count - 1), 0, -1):
        for mask in range(1, 1 << pressing if every else 2):
            if every and _bits(mask) != size:
                continue
            k = 0
            for j in range(pressing):
                # the mask's points (every subset), or the strongest size points
                if (every and (mask >> j) & 1) or (not every and j < size):
                    chosen[k] = order[j]
                    k += 1
            for q in range(size):
                for i in range(3):
                    subset[q, i] = arms[chosen[q], i]
                    trial[q, i] = impulses[chosen[q], i]
            if not polish(par, inv_inertia, subset, size, mu, start, trial, after, scale, work):
                continue
            if not _left_out_separate(arms, count, chosen, size, after,
                                      POLISH_TOLERANCE * scale):  # fmt: skip
                continue
            for p in range(count):
                for i in range(3):
                    impulses[p, i] = 0.0
            for q in range(size):
                for i in range(3):
                    impulses[chosen[q], i] = trial[q, i]
            for i in range(6):
                velocity[i] = after[i]
            return True
    return False


@kernel(cache=True, error_model="numpy", _nrt=False)
def _order_by_pressing(impulses, count, order):
    """The points 0..count-1 by decreasing normal impulse into ``order[:count]``.

    ``numpy.argsort(-impulses[:count, 2])`` as numba sorts up to 15 keys
    (a stable insertion sort, NaN last), with no array allocated.
    """
    for i in range(count):
        order[i] = i
    for i in range(1, count):
        k = order[i]
        v = -impulses[k, 2]
        j = i
        while j > 0:
            w = -impulses[order[j - 1], 2]
            if not (v < w or (math.isnan(w) and not math.isnan(v))):
                break
            order[j] = order[j - 1]
            j -= 1
        order[j] = k


@kernel(cache=True, error_model="numpy", _nrt=False)
def _bits(mask):
    """The number of set bits of ``mask``."""
    total = 0
    while mask:
        total += mask & 1
        mask >>= 1
    return total


@kernel(cache=True, error_model="numpy", _nrt=False)
def _left_out_separate(arms, count, chosen, size, velocity, tolerance):
    """Whether the points not in ``chosen[:size]`` have a normal velocity of at least -tolerance."""
    for p in range(count):
        left_out = True
        for q in range(size):
            if chosen[q] == p:
                left_out = False
        if left_out:
            _, _, un = _point_speed(velocity, arms[p])
            if un < -tolerance:
                return False
    return True


@kernel(cache=True, error_model="numpy", _nrt=False)
def _warm(impulses, count):
    """Whether a start of the sweeps has a normal impulse at any of its ``count`` points."""
    for p in range(count):
        if impulses[p, 2] != 0.0:
            return True
    return False


@kernel(cache=True, error_model="numpy", _nrt=False)
def _cone_interval(ox, oy, on, ux, uy, un, mu):
    """The interval of s [N s] where ``P = o + s u`` lies in the cone ``|P_t| <= mu P_n``.

    ``o`` = (ox, oy, on) (x, y, n), ``u`` a unit vector. The cone's quadratic
    ``|P_t(s)|^2 - mu^2 P_n(s)^2 <= 0`` on the nappe ``P_n >= 0``; (lo, hi)
    with lo > hi where the line misses it, or where ``u`` lies inside the
    double cone (the interval would be unbounded: never for two points on the
    support, whose line is nearly horizontal).
    """
    a = ux * ux + uy * uy - mu * mu * un * un
    b = ox * ux + oy * uy - mu * mu * on * un
    c = ox * ox + oy * oy - mu * mu * on * on
    discriminant = b * b - a * c
    if not (a > 0.0 and discriminant >= 0.0):
        return 1.0, -1.0
    root = math.sqrt(discriminant)
    lo, hi = (-b - root) / a, (-b + root) / a
    if on + 0.5 * (lo + hi) * un < 0.0:  # the lower nappe
        return 1.0, -1.0
    return lo, hi


@kernel(cache=True, error_model="numpy", _nrt=False)
def _two_points_stick(par, inv_inertia, arms, mu, velocity, impulses, work):
    """Two points that both stick, in closed form; False (nothing changed) where they cannot.

    With both points at rest after the impact the body turns about the line
    through them (arms a, b from G, axis u = (a - b)/|a - b|): the velocity
    after is that turn's part of the velocity before in the kinetic
    energy's metric (:func:`turn_about_line`; a plastic impact, it never
    gains energy). The impulse ``M (v+ - v)`` = (F, T about G) splits into
    ``P_a + P_b = F``, ``a x P_a + b x P_b = T``: ``P_a = ((T - b x F) x (a
    - b)) / |a - b|^2 + s u`` for any s, which moves nothing (W is singular
    along u). The points stick where an s puts both impulses in their cones
    (:func:`_cone_interval`); s is then the start's own (``impulses`` on
    entry: the step before's), kept in both intervals. That solves the
    impact's laws exactly (Moreau 1988): normal impulses >= 0 where the
    points are at rest, tangential ones in the circular cone. ``velocity``
    (6) and ``impulses`` (2, 3) are replaced where True. ``work``: a record
    of ``IMPULSE_WORK_DTYPE``.
    """
    if not mu > 0.0:
        return False
    a, b = arms[0], arms[1]
    dx, dy, dz = a[0] - b[0], a[1] - b[1], a[2] - b[2]
    length = math.sqrt(dx * dx + dy * dy + dz * dz)
    if length == 0.0:
        return False
    ux, uy, uz = dx / length, dy / length, dz / length
    after = work["after"]
    turn_about_line(par, inv_inertia, arms, 2, velocity, after)
    m = par[P_MASS]
    fx, fy, fz = m * (after[0] - velocity[0]), m * (after[1] - velocity[1]), m * (
        after[2] - velocity[2])  # fmt: skip
    tx, ty, tz = inertia_times(inv_inertia, after[3] - velocity[3], after[4] - velocity[4],
                               after[5] - velocity[5])  # fmt: skip
    bx, by, bz = cross(b[0], b[1], b[2], fx, fy, fz)
    px, py, pz = cross(tx - bx, ty - by, tz - bz, dx, dy, dz)
    scale = 1.0 / (length * length)
    ax, ay, an = px * scale, py * scale, pz * scale  # P_a at s = 0
    lo_a, hi_a = _cone_interval(ax, ay, an, ux, uy, uz, mu)
    # P_b = F - P_a = (F - P_a(0)) - s u: s in -[lo_b, hi_b]
    lo_b, hi_b = _cone_interval(fx - ax, fy - ay, fz - an, ux, uy, uz, mu)
    lo, hi = max(lo_a, -hi_b), min(hi_a, -lo_b)
    if not lo <= hi:
        return False
    if _warm(impulses, 2):
        s = (impulses[0, 0] - ax) * ux + (impulses[0, 1] - ay) * uy + (impulses[0, 2] - an) * uz
        s = min(max(s, lo), hi)
    else:
        s = 0.5 * (lo + hi)
    impulses[0, 0], impulses[0, 1], impulses[0, 2] = ax + s * ux, ay + s * uy, an + s * uz
    impulses[1, 0], impulses[1, 1], impulses[1, 2] = fx - impulses[0, 0], fy - impulses[0, 1], (
        fz - impulses[0, 2])  # fmt: skip
    for i in range(6):
        velocity[i] = after[i]
    return True


@kernel(cache=True, error_model="numpy", _nrt=False)
def point_impulses(par, inv_inertia, arms, count, mu, velocity, impulses, work):
    """Plastic impulses at the points with Coulomb friction on the circular cone.

    ``velocity`` (6) is updated. Projected Gauss-Seidel (Jean 1999), its
    sweeps forwards and backwards in turn (:func:`_sweep`); at sweeps 8, 16,
    32, ... that have not converged, the exact solution is sought by Newton's
    method from the sweeps' impulses (:func:`polish_pressed`) and, where it
    satisfies the laws, taken: the sweeps converge linearly, and slowly where impulses can move
    between points without moving the body (an edge's two corners pushing
    along it).
    ``impulses`` (at least count, 3) [N s] (x, y, n): on entry the sweeps'
    start, applied to the velocity first (zeros, or an admissible guess,
    ``P_n >= 0`` and ``|P_t| <= mu P_n``, such as the impulses of the step
    before: the sweeps then start near their end); on exit the impulses.
    A start with a normal impulse is polished first, before any sweep: a
    stretch of the remedy on an edge starts each step from the step before's
    impulses, from which Newton's method mostly converges in one or two
    iterations (a rocking cabinet's stretches under a record: 1,067 of
    1,096 such starts), where the sweeps alone do not converge (the edge's
    corners: a singular W) and eight of them came before every polish.
    Two points that can both stick are solved in closed form first
    (:func:`_two_points_stick`; no sweep, ``ENDED_STUCK``).
    Returns the number of sweeps made (0: polished from the start) and how
    they ended: ``ENDED_CONVERGED``
    (the sweeps' change fell below ``SWEEP_TOLERANCE``), ``ENDED_POLISHED``
    or ``ENDED_EXHAUSTED`` (``SWEEPS`` made: the laws are met only as far as
    the sweeps came). ``work``: a record of ``IMPULSE_WORK_DTYPE``.
    """
    if count == 2 and _two_points_stick(par, inv_inertia, arms, mu, velocity, impulses, work):
        return 0, ENDED_STUCK
    start = work["start"]
    delassus = work["point_delassus"]
    stiffness = work["stiffness"]
    scale = 1e-300
    for i in range(6):
        start[i] = velocity[i]
        scale = max(scale, abs(velocity[i]))
    for p in range(count):
        _delassus(par, inv_inertia, arms[p], delassus[p], work["probe"])
        stiffness[p] = largest_tangential_eigenvalue(delassus[p])
        _apply(par, inv_inertia, arms[p], impulses[p, 0], impulses[p, 1], impulses[p, 2],
               velocity)  # fmt: skip
    if _warm(impulses, count) and polish(par, inv_inertia, arms, count, mu, start, impulses,
                                          velocity, scale, work):  # fmt: skip
        return 0, ENDED_POLISHED
    for sweep in range(SWEEPS):
        change = _sweep(par, inv_inertia, arms, count, mu, delassus, stiffness, velocity,
                        impulses, sweep % 2 == 1, scale)  # fmt: skip
        if change <= SWEEP_TOLERANCE:
            return sweep + 1, ENDED_CONVERGED
        if sweep >= POLISH_FROM and (sweep & (sweep + 1)) == 0:
            if polish_pressed(par, inv_inertia, arms, count, mu, start, impulses, velocity,
                              scale, work):  # fmt: skip
                return sweep + 1, ENDED_POLISHED
    return SWEEPS, ENDED_EXHAUSTED


@kernel(cache=True, error_model="numpy", _nrt=False)
def velocity_impact(par, inv_inertia, arms, count, mu, velocity, impulses, work):
    """The velocity after a plastic impact at the points; it never gains energy.

    ``velocity`` (6) is replaced; ``impulses`` (at least count, 3) [N s] holds
    the sweeps' start on entry and the impulses on exit
    (:func:`point_impulses`). Returns True when the frictional solution was
    kept, False when it would have raised the kinetic energy and the
    frictionless one (from zero) was taken instead. ``work``: a record of
    ``IMPULSE_WORK_DTYPE``.
    """
    before = work["before"]
    for i in range(6):
        before[i] = velocity[i]
    energy_before = kinetic_energy(par, inv_inertia, before)
    point_impulses(par, inv_inertia, arms, count, mu, velocity, impulses, work)
    if kinetic_energy(par, inv_inertia, velocity) <= energy_before * (1.0 + 1e-12):
        return True
    for i in range(6):
        velocity[i] = before[i]
    for p in range(count):
        for i in range(3):
            impulses[p, i] = 0.0
    point_impulses(par, inv_inertia, arms, count, 0.0, velocity, impulses, work)
    return False


@kernel(cache=True, error_model="numpy", _nrt=False)
def turn_about_line(par, inv_inertia, arms, count, velocity, out):
    """The part of ``velocity`` that turns about the line through two base points; else zero.

    With exactly two points (arms ``d_1``, ``d_2`` from G [m]) the body can turn
    about the line through them with both fixed: ``s = (d_1 x a, a)`` per unit
    of angular velocity [rad/s], ``a = (d_2 - d_1) / |d_2 - d_1|``. ``out`` (6)
    receives the kinetic metric's projection of ``velocity`` on it,
    ``s (s^T M v) / (s^T M s)``, ``M = diag(m 1, I_w)``: the remainder
    ``v - out`` is M-orthogonal to it, so the kinetic energy splits into the
    two parts' energies. With any other number of points (none, one, or
    three and more, which no turn leaves all fixed: a box's corners, rim
    points, never three on a line) ``out`` is zero. The restitution factor
    acts on the remainder only (:func:`restitution_velocity`).
    """
    for i in range(6):
        out[i] = 0.0
    if count != 2:
        return
    ax = arms[1, 0] - arms[0, 0]
    ay = arms[1, 1] - arms[0, 1]
    az = arms[1, 2] - arms[0, 2]
    size = math.sqrt(ax * ax + ay * ay + az * az)
    if size == 0.0:
        return
    ax, ay, az = ax / size, ay / size, az / size
    sx, sy, sz = cross(arms[0, 0], arms[0, 1], arms[0, 2], ax, ay, az)
    lx, ly, lz = inertia_times(inv_inertia, ax, ay, az)
    m = par[P_MASS]
    along = m * (sx * velocity[0] + sy * velocity[1] + sz * velocity[2]) + (
        lx * velocity[3] + ly * velocity[4] + lz * velocity[5])  # fmt: skip
    norm = m * (sx * sx + sy * sy + sz * sz) + lx * ax + ly * ay + lz * az
    rate = along / norm
    out[0], out[1], out[2] = rate * sx, rate * sy, rate * sz
    out[3], out[4], out[5] = rate * ax, rate * ay, rate * az


@kernel(cache=True, error_model="numpy", _nrt=False)
def restitution_velocity(par, inv_inertia, arms, count, held_before, velocity, work):
    """The restitution factor e on the velocity after an impact (in place): ``v_k + e (v - v_k)``.

    ``velocity`` (6) is the plastic impact's velocity after, relative to the
    support; ``arms`` (count, 3) [m] the base points touching at the impact
    (:func:`base_points`); ``held_before``: the body was on the support
    before it (not in flight).
    In a plane the factor multiplies the whole velocity after (``e`` times
    Housner's angular velocity, as the planar engine's factor,
    ``docs/timehistory.md``). In 3-D a box turning on a corner
    whose neighbour lands (the two corners of an edge: a fall over that edge
    with a little wobble) would lose the fall's velocity at every such
    landing, though its turn about the edge through the two points neither
    stops nor reverses: a slender box with e = 0.8 (random seed 1692 of
    ``benchmarks/mujoco_body.py``'s robustness sample) took 8.7 s to fall
    over, through 2,766 such landings, where e = 1 took 4.2 s; now 4.6 s. So
    ``v_k``, the turn about the line through the pivot held before and the
    corner landing (:func:`turn_about_line`: exactly two corners touching,
    the box on the support before), is kept, and the factor acts on the
    rest, M-orthogonal to it; ``v_k = 0`` in a plane (two points of a
    planar block's section fix it), after a flight (no pivot before), and
    where three or more corners touch, so the planar law is unchanged. The
    kinetic energy after is ``T_k + e^2 (T - T_k) <= T``. A cylinder's
    tilted base touches at one rim point, and its impacts are flat
    landings: the planar law (its rim points sampled within the gap
    tolerance of a nearly flat base, two of them, are not a pivot and a
    landing point). ``work``: a record of ``IMPULSE_WORK_DTYPE``.
    """
    e = par[P_RESTITUTION]
    if e == 1.0:
        return
    kept = work["kept"]
    for i in range(6):
        kept[i] = 0.0
    if held_before and par[P_SHAPE] == SHAPE_BOX:
        turn_about_line(par, inv_inertia, arms, count, velocity, kept)
    for i in range(6):
        velocity[i] = kept[i] + e * (velocity[i] - kept[i])
