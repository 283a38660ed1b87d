"""Closed forms that rule out a sticking impact before its solve (the impact law's candidates).

The impact law (:func:`~freestand.core.contact.body_modes.impact`) tries its
candidates in order, the sticking ones first: a FACE, then each EDGE whose
corners touch. A rocking box that lands flat touches at its four corners;
the FACE's sticking impact is never admissible there (it would stop the body
outright, which needs more friction than the landing's normal impulse
gives), nor is the EDGE the box turned about before (its landing corners
would go on through the support), nor a short EDGE (its friction). Each of
these solves its 5 or 6 rows and fails: about half of the impact law's
work at a rocking cabinet's landing.

A sticking impact's velocity after is known without its rows:

- FACE: zero (relative to the support); the impulse is ``-M x``.
- EDGE: a turn about the edge's horizontal direction ``e`` (its corners'
  normal velocities, its midpoint's horizontal velocity and the twist
  held), whose rate conserves the momentum along that motion:
  ``x+ = s u``, ``u = (c x e, e)`` (c the arm of the edge's midpoint),
  ``s = u^T M x- / u^T M u`` (the impulses do no work on u; Brach 1991,
  the impulse-momentum law of a constrained impact).

From the impulse ``M (x+ - x-)``, its horizontal force and its normal force
give a lower bound on the friction's violation (the twist only adds to
|f_t|), a FACE's normal moments its centre of pressure, and an EDGE's other
touching corners their normal velocities after. A candidate is ruled out
only where one of these fails by more than ``STICK_ROUNDOFF`` of its own
scale beyond the test's tolerance: the candidate's solve would fail that
test too, so the law takes the same candidate, to the last bit.
"""

from __future__ import annotations

import math

from freestand.core.contact.body_kernel import (
    EDGE,
    FACE,
    P_HALF_X,
    P_HALF_Y,
    P_MASS,
    P_MU_STATIC,
    SC_POINTS,
    SC_ROT,
    arm,
    box_corner,
    normal_margin,
    world_inertia_times,
)
from freestand.core.contact.compiled import kernel

STICK_ROUNDOFF = 1e-6  # a test's slack beyond its tolerance, relative to its own scale [-]


@kernel(cache=True, error_model="numpy", _nrt=False)
def stick_impact_excluded(par, y, sc, kind, index, touching, force_tol, rate_tol):
    """True where a FACE's or EDGE's sticking impact at (t, y) is provably not admissible.

    ``touching`` the touching points' flags (box corners 0-3), ``force_tol``
    [N s] and ``rate_tol`` [m/s] the impact law's tolerances. ``sc`` holds
    the instant's rotation; its probed points' rows (``SC_POINTS``) are
    used as work. Any other candidate: False (not ruled out).
    """
    if kind == FACE:
        return _face_excluded(par, y, sc, force_tol)
    if kind == EDGE:
        return _edge_excluded(par, y, sc, index, touching, force_tol, rate_tol)
    return False


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _friction_fails(par, px, py, pz, force_tol):
    """mu_0 P_z - |P_h| below -(tolerance + slack): the impulse P [N s] needs more friction
    than its normal part gives (the patch's |f_t| is at least |P_h|)."""
    horizontal = math.sqrt(px * px + py * py)
    normal = par[P_MU_STATIC] * pz
    slack = force_tol + STICK_ROUNDOFF * (abs(normal) + horizontal)
    return normal - horizontal < -slack


@kernel(cache=True, error_model="numpy", _nrt=False)
def _face_excluded(par, y, sc, force_tol):
    """A FACE's sticking impact: the impulse -M x, its friction and centre of pressure."""
    m = par[P_MASS]
    px, py, pz = -m * y[7], -m * y[8], -m * y[9]
    if _friction_fails(par, px, py, pz, force_tol):
        return True
    rot = sc[SC_ROT]
    work = sc[SC_POINTS]
    d, lam = work[0], work[2]
    arm(par, rot, 0.0, 0.0, 0.0, d)  # the base centre, where the FACE's rows act
    lx, ly, _ = world_inertia_times(par, rot, y[10], y[11], y[12])
    # the normal rows' multipliers: N = P_z and the moments about the base centre,
    # -I_w omega - d x P (x and y)
    lam[0] = pz
    lam[1] = -lx - (d[1] * pz - d[2] * py)
    lam[2] = -ly - (d[2] * px - d[0] * pz)
    # the margin's terms are b N - |M| [N s m] and N [N s]
    reach = 1.0 + max(par[P_HALF_X], par[P_HALF_Y])
    scale = abs(pz) * reach + abs(lam[1]) + abs(lam[2])
    return normal_margin(par, rot, FACE, lam) < -(force_tol * reach + STICK_ROUNDOFF * scale)


@kernel(cache=True, error_model="numpy", _nrt=False)
def edge_turn(par, y, sc, index):
    """A sticking EDGE's velocity after an impact at (t, y): ``x+ = s u``, u = (c x e, e).

    e the edge's horizontal direction (unit), c the arm of its midpoint [m];
    ``s = u^T M x- / u^T M u`` [rad/s]. Returns (s, u_v (3), e_x, e_y); s
    NaN where the edge has no horizontal direction. ``sc`` holds the
    instant's rotation; ``sc[SC_POINTS][0:2]`` take the corners' arms.
    """
    rot = sc[SC_ROT]
    a, b = sc[SC_POINTS][0], sc[SC_POINTS][1]
    ax, ay = box_corner(par, index)
    bx, by = box_corner(par, (index + 1) % 4)
    arm(par, rot, ax, ay, 0.0, a)
    arm(par, rot, bx, by, 0.0, b)
    ex, ey = b[0] - a[0], b[1] - a[1]
    size = math.sqrt(ex * ex + ey * ey)
    if not size > 0.0:
        return math.nan, 0.0, 0.0, 0.0, 0.0, 0.0
    ex, ey = ex / size, ey / size
    cx, cy, cz = 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])
    # u = (c x e, e): the midpoint held, the corners turning about e
    ux, uy, uz = -cz * ey, cz * ex, cx * ey - cy * ex
    m = par[P_MASS]
    ix, iy, _ = world_inertia_times(par, rot, ex, ey, 0.0)
    lx, ly, _ = world_inertia_times(par, rot, y[10], y[11], y[12])
    along = m * (ux * y[7] + uy * y[8] + uz * y[9]) + ex * lx + ey * ly
    inertia = m * (ux * ux + uy * uy + uz * uz) + ex * ix + ey * iy
    return along / inertia, ux, uy, uz, ex, ey


@kernel(cache=True, error_model="numpy", _nrt=False)
def _edge_excluded(par, y, sc, index, touching, force_tol, rate_tol):
    """An EDGE's sticking impact: the turn about the edge (:func:`edge_turn`), its friction
    and the other touching corners' normal velocities after."""
    s, ux, uy, uz, ex, ey = edge_turn(par, y, sc, index)
    if not math.isfinite(s):
        return False
    m = par[P_MASS]
    if _friction_fails(par, m * (s * ux - y[7]), m * (s * uy - y[8]), m * (s * uz - y[9]),
                       force_tol):  # fmt: skip
        return True
    rot = sc[SC_ROT]
    d = sc[SC_POINTS][2]
    for k in range(4):
        if not touching[k] or k == index or k == (index + 1) % 4:
            continue
        sx, sy = box_corner(par, k)
        arm(par, rot, sx, sy, 0.0, d)
        # the corner's normal velocity after: s (u_v + e x d)_z
        rate = s * (uz + ex * d[1] - ey * d[0])
        reach = abs(s) * (math.sqrt(ux * ux + uy * uy + uz * uz)
                          + math.sqrt(d[0] ** 2 + d[1] ** 2 + d[2] ** 2))  # fmt: skip
        if rate < -(rate_tol + STICK_ROUNDOFF * reach):
            return True
    return False
