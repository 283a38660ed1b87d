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
- solved by projected Gauss-Seidel over the points (Jean 1999; each point's
  normal impulse projected on ``P_n >= 0``, then its tangential impulse
  minimising the point's sliding velocity, projected radially onto the disc
  of radius ``mu P_n``), sweeping the points forwards and backwards in turn
  (symmetric Gauss-Seidel): always in one order, the sweeps could cycle
  where many points touch and the base twists (a flat cylinder's eight rim
  points, ``tests/test_body_impulse.py``).

Every update lowers or keeps the kinetic energy for the frictionless part;
the friction projection does not guarantee it, so the result is checked: a
solution that would raise the kinetic energy is replaced by the frictionless
one (:func:`point_impulses` with ``mu = 0``), which never does. References:
J. J. Moreau, Unilateral contact and dry friction in finite freedom
dynamics, CISM 302 (1988); M. Jean, The non-smooth contact dynamics method,
Comput. Methods Appl. Mech. Engrg. 177 (1999) 235-257.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from freestand.core.contact.body_kernel import (
    P_HALF_X,
    P_MASS,
    P_SHAPE,
    SHAPE_BOX,
    arm,
    box_corner,
    cross,
    lowest_rim_angle,
)

MAX_POINTS = 8
RIM_POINTS = 8  # a cylinder's base as this many rim points, from the lowest one
#: Projected Gauss-Seidel sweeps at most. They converge linearly; where a cylinder's eight
#: rim points all touch, with friction near 1 and a tilting twist, slowly: 400 sweeps left
#: a point approaching at 4e-3 of the speed, 1000 at 1e-4, 20,000 at 5e-12.
SWEEPS = 1000
SWEEP_TOLERANCE = 1e-12  # relative change of the velocity that ends the sweeps


@nb.njit(cache=True, error_model="numpy", _nrt=True)
def base_points(par, y, rot, psi_stored, gap_limit, arms):
    """The base points within ``gap_limit`` [m] of the support: their arms from G in ``arms``.

    Returns their count. A box's corners; a cylinder's rim at ``RIM_POINTS``
    angles starting from its lowest point.
    """
    count = 0
    d = np.empty(3)
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


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _apply(par, inv_inertia, d, px, py, pz, velocity):
    """velocity += M^-1 J^T P for the impulse P at arm d."""
    m = par[P_MASS]
    velocity[0] += px / m
    velocity[1] += py / m
    velocity[2] += pz / m
    tx, ty, tz = cross(d[0], d[1], d[2], px, py, pz)
    for i in range(3):
        velocity[3 + i] += inv_inertia[i, 0] * tx + inv_inertia[i, 1] * ty + inv_inertia[i, 2] * tz


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _point_speed(velocity, d):
    """(u_x, u_y, u_n) of the point at arm d."""
    cx, cy, cz = cross(velocity[3], velocity[4], velocity[5], d[0], d[1], d[2])
    return velocity[0] + cx, velocity[1] + cy, velocity[2] + cz


@nb.njit(cache=True, error_model="numpy", _nrt=True)
def _delassus(par, inv_inertia, d, out):
    """The point's 3 x 3 Delassus matrix W = J M^-1 J^T (columns: unit impulses x, y, n)."""
    probe = np.zeros(6)
    for k in range(3):
        for i in range(6):
            probe[i] = 0.0
        _apply(par, inv_inertia, d, 1.0 if k == 0 else 0.0, 1.0 if k == 1 else 0.0,
               1.0 if k == 2 else 0.0, probe)  # fmt: skip
        ux, uy, un = _point_speed(probe, d)
        out[0, k] = ux
        out[1, k] = uy
        out[2, k] = un


@nb.njit(cache=True, error_model="numpy", _nrt=True)
def kinetic_energy(par, inv_inertia, velocity):
    """(1/2) m |v|^2 + (1/2) omega . I_w omega [J] (I_w from its inverse)."""
    m = par[P_MASS]
    inertia = np.linalg.inv(inv_inertia)
    rotational = 0.0
    for i in range(3):
        for j in range(3):
            rotational += velocity[3 + i] * inertia[i, j] * velocity[3 + j]
    return 0.5 * m * (velocity[0] ** 2 + velocity[1] ** 2 + velocity[2] ** 2) + 0.5 * rotational


@nb.njit(cache=True, error_model="numpy", _nrt=True)
def point_impulses(par, inv_inertia, arms, count, mu, velocity, impulses):
    """Plastic impulses at the points with friction on the circular cone; ``velocity`` (6) updated.

    Projected Gauss-Seidel (Jean 1999), its sweeps forwards and backwards in
    turn: per point, the normal impulse that brings its normal velocity to
    zero, kept >= 0; then the tangential impulse that stops its sliding,
    scaled back onto the disc ``|P_t| <= mu P_n``.
    ``impulses`` (at least count, 3) [N s] (x, y, n): on entry the sweeps'
    start, applied to the velocity first (zeros, or an admissible guess,
    ``P_n >= 0`` and ``|P_t| <= mu P_n``, such as the impulses of the step
    before: the sweeps then start near their end); on exit the impulses.
    """
    delassus = np.empty((count, 3, 3))
    scale = 1e-300
    for i in range(6):
        scale = max(scale, abs(velocity[i]))
    for p in range(count):
        _delassus(par, inv_inertia, arms[p], delassus[p])
        _apply(par, inv_inertia, arms[p], impulses[p, 0], impulses[p, 1], impulses[p, 2],
               velocity)  # fmt: skip
    for sweep in range(SWEEPS):
        change = 0.0
        for q in range(count):
            p = q if sweep % 2 == 0 else count - 1 - q
            d = arms[p]
            w = delassus[p]
            ux, uy, un = _point_speed(velocity, d)
            normal = max(0.0, impulses[p, 2] - un / w[2, 2])
            dn = normal - impulses[p, 2]
            impulses[p, 2] = normal
            _apply(par, inv_inertia, d, 0.0, 0.0, dn, velocity)
            change = max(change, abs(dn) / (par[P_MASS] * scale))
            ux, uy, un = _point_speed(velocity, d)
            det = w[0, 0] * w[1, 1] - w[0, 1] * w[1, 0]
            tx = impulses[p, 0] - (w[1, 1] * ux - w[0, 1] * uy) / det
            ty = impulses[p, 1] - (-w[1, 0] * ux + w[0, 0] * uy) / det
            size = math.hypot(tx, ty)
            limit = mu * normal
            if size > limit:
                tx *= limit / size
                ty *= limit / size
            dx = tx - impulses[p, 0]
            dy = ty - impulses[p, 1]
            impulses[p, 0] = tx
            impulses[p, 1] = ty
            _apply(par, inv_inertia, d, dx, dy, 0.0, velocity)
            change = max(change, math.hypot(dx, dy) / (par[P_MASS] * scale))
        if change <= SWEEP_TOLERANCE:
            break


@nb.njit(cache=True, error_model="numpy", _nrt=True)
def velocity_impact(par, inv_inertia, arms, count, mu, velocity, impulses):
    """The velocity after a plastic impact at the points; it never gains energy.

    ``velocity`` (6) is replaced; ``impulses`` (at least count, 3) [N s] holds
    the sweeps' start on entry and the impulses on exit
    (:func:`point_impulses`). Returns True when the frictional solution was
    kept, False when it would have raised the kinetic energy and the
    frictionless one (from zero) was taken instead.
    """
    before = velocity.copy()
    energy_before = kinetic_energy(par, inv_inertia, before)
    point_impulses(par, inv_inertia, arms, count, mu, velocity, impulses)
    if kinetic_energy(par, inv_inertia, velocity) <= energy_before * (1.0 + 1e-12):
        return True
    for i in range(6):
        velocity[i] = before[i]
    for p in range(count):
        for i in range(3):
            impulses[p, i] = 0.0
    point_impulses(par, inv_inertia, arms, count, 0.0, velocity, impulses)
    return False
