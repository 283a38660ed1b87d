"""The compiled contact problem of one rigid body on the flat support (3-D).

The body (:class:`freestand.core.body.Body`, a box or a cylinder) has the
state ``y = (r, q, v, omega)``: the centre of gravity r [m], the orientation
as a unit quaternion q = (w, x, y, z) [-] (body frame to support frame), the
velocity v [m/s] of G and the angular velocity omega [rad/s], both in the
support's frame (x, y horizontal, z up; ``docs/nomenclature.md``). The
generalised acceleration ``x'' = (a, alpha)`` obeys Newton-Euler with the
contact wrench::

    M x'' = f_0 + W lambda + friction,  M = diag(m 1, I_w),  I_w = R I R^T
    f_0 = (m g_e, -omega x I_w omega),  g_e = (-a_x, -a_y, -(g - a_v))

(a_v the downward support acceleration; the support's motion enters as the
inertial force, as in the planar engine).

**Contact patches.** What touches the support is one *patch*:

========  ==================================  ====================  =================
patch     when                                normal rows           tangential rows
========  ==================================  ====================  =================
FACE      the base lies flat                  3: z of the base      3: horizontal
                                              centre, tilt about    velocity at the
                                              x and y               centre of pressure,
                                                                    twist
EDGE      two adjacent corners (box)          2: the corners' z     3: as FACE, at its
                                                                    centre of pressure
POINT     one corner, or the lowest rim       1                     2: the material
          point (cylinder)                                          point's horizontal
                                                                    velocity (rolling)
FREE      nothing                             0                     0
========  ==================================  ====================  =================

A row is a generalised direction ``w`` (6,) with the row's acceleration
``w . x'' + b`` (``b`` its velocity-product bias); a point row at the arm d
from G in direction e is ``w = (e, d x e)``, ``b = e . (omega x (omega x d))``,
an angular row about e is ``w = (0, e)``. The twist row of a FACE or EDGE is
``(0, rho e_z)`` so that its velocity ``rho omega_z`` and its multiplier
(torque / rho) are in m/s and N.

**Friction** (Coulomb, static mu_0 to hold, kinetic mu to slide). POINT: the
circular cone ``|f_t| <= mu_0 N``, sliding ``f_t = -mu N s/|s|`` (s the slip
velocity; maximal dissipation). FACE and EDGE: force and twist torque about
the centre of pressure c, with the ellipsoidal limit surface of Howe and
Cutkosky 1996 (Int. J. Robotics Research 15(6), 557-572): with the scaled
slip velocity ``s = (v_c,x, v_c,y, rho omega_z)`` (v_c of the material point
at c) and ``f_t = (F_x, F_y, T_c / rho)``, hold while ``|f_t| <= mu_0 N`` and
slide with ``f_t = -mu N s/|s|``. The pressure is taken uniform over the
effective area, the largest part of the contact concentric with c (Meyerhof
1953, Proc. 3rd Int. Conf. Soil Mech. Found. Eng. 1, 440-445), and ``rho``
is that area's mean distance from c (Goyal, Ruina and Papadopoulos 1991,
Wear 143, 307-330; :func:`effective_twist_radius`): the pure-twist limit
torque is ``mu N rho`` and pure translation is Coulomb's circular cone
exactly. The tangential rows sit at the *friction centre*
(``sc[SC_CENTRE]``), which :func:`solve_patch` moves to c.

**The rolling rim point.** A tilted cylinder touches at the lowest point of
its base circle, ``s* = -R (R_31, R_32, 0) / sin(tilt)`` in the body frame.
It moves along the rim; by the envelope theorem the gap's rate is the
material point's, and its second derivative gets the extra term
``-R (e_z . (omega x R t))^2 / sin(tilt)`` (t the rim tangent at s*), the
tangential rows ``e . (omega x R s*')`` with ``s*' = R psi' t``,
``psi' = -e_z . (omega x R t) / sin(tilt)``.

Everything here is compiled (numba) and works on fixed-size arrays; the
Python side builds the parameter vector with :func:`body_parameters`.
Functions that allocate nothing are compiled without numba's reference
counting (``_nrt=False``), as the planar engine's: the arrays they touch (the
scratch, ``new_scratch``) are owned by their caller for the whole call, and
counting the references of the scratch's arrays at every call (two atomic
operations each) took 40 % of a sliding cask's time. They never allocate nor
return an array of their own. The allocating ones say ``_nrt=True``, so that
they do not inherit the setting of a caller that has it off.
"""

from __future__ import annotations

import math

import numpy as np

from freestand.core.body import Body, Box
from freestand.core.contact.compiled import kernel
from freestand.core.contact.engine import (
    held_products,
    solve_in_place,
    solve_symmetric_in_place,
)
from freestand.core.contact.face_friction import (
    CENTRE_TOLERANCE,
    body_horizontal,
    face_twist_radius,
    model_centre,
    rectangle_twist_radius,
)
from freestand.core.contact.slip_law import SLIP_FLOOR, pulled_unit
from freestand.core.contact.vectors import norm2

# --- the parameter vector -----------------------------------------------------------------------

P_MASS = 0
P_INERTIA = 1  # 9 values, body frame, about G, row-major
P_INVERSE = 10  # 9 values, the inverse
P_CENTRE = 19  # 3 values, G in the body frame
P_SHAPE = 22  # 0 box, 1 cylinder
P_HALF_X = 23  # box half-width b_x, or the cylinder's radius R
P_HALF_Y = 24  # box half-width b_y, or R
P_MU_STATIC = 25
P_MU_KINETIC = 26
P_RHO_FACE = 27  # twist radius of the whole base about its centre [m]
P_GRAVITY = 28
P_HEIGHT = 29
P_RESTITUTION = 30  # factor on the velocity after an impact [-] (1: plastic)
P_SIZE = 31

SHAPE_BOX = 0
SHAPE_CYLINDER = 1

# --- patches and modes ---------------------------------------------------------------------------

FREE = 0
POINT = 1
EDGE = 2
FACE = 3
PATCH_NAMES = ("free", "point", "edge", "face")

# mode (int64, 3): patch kind, index (corner or edge of a box), tangential state
M_KIND = 0
M_INDEX = 1
M_SLIP = 2  # 0 stick, 1 slip
# mode data (float64, DATA_SIZE): rim angle psi of a cylinder's pivot [rad], slip direction
# (3), 1.0 where the slip starts from rest (its onset direction; 0.0 for a slip under way),
# and the step's slip floor [m/s] (0.0: SLIP_FLOOR; see unit_slip)
D_PSI = 0
D_SLIP = 1
D_ONSET = 4
D_FLOOR = 5
DATA_SIZE = 6
MAX_CANDIDATES = 9  # candidate patches of a contact mode at most (body_modes.candidates)

STATE_SIZE = 13  # r (3), q (4), v (3), omega (3)

# row scratch: W (6, 6) columns, bias (6); normal rows first, then tangential ones
TILT_EPSILON = 1e-9  # sin(tilt) below which a cylinder counts as flat for its rim point
PIVOT_LEAN = 1e-6  # sin(tilt) below which a rocking cylinder keeps its rim point (pivot_direction)
RHO_FLOOR = 1e-9  # smallest twist radius of a FACE or EDGE, relative to the base's half-width [-]
CENTRE_ITERATIONS = 12  # most solves of a sliding FACE or EDGE to settle its friction centre
CENTRE_ROUNDOFF = 1e-9  # or a FACE's move below this that no longer shrinks (the solve's round-off)
CRAMER_CONDITION = 1e-8  # |det| / Hadamard's bound above which solve_small uses Cramer's rule
EDGE_ITERATIONS = 60  # most trial centres of a sliding EDGE (each a 2 x 2 system, edge_share)


def annulus_twist_radius(radius: float, inner_radius: float = 0.0) -> float:
    """Mean distance [m] from the centre of an annulus: (2/3)(R^3 - r^3)/(R^2 - r^2)."""
    return 2.0 / 3.0 * (radius**3 - inner_radius**3) / (radius**2 - inner_radius**2)


def body_parameters(body: Body, gravity: float, restitution: float = 1.0) -> np.ndarray:
    """The parameter vector of the compiled kernel for ``body`` (SI units).

    ``restitution`` [-] multiplies the body's velocity after each impact (1:
    the plastic impact law; the planar engine's factor, ``docs/timehistory.md``),
    but for a turn the impact leaves
    (:func:`~freestand.core.contact.body_impulse.restitution_velocity`).
    """
    out = np.zeros(P_SIZE)
    out[P_MASS] = body.mass
    inertia = np.asarray(body.inertia, dtype=float)
    out[P_INERTIA : P_INERTIA + 9] = inertia.reshape(-1)
    out[P_INVERSE : P_INVERSE + 9] = np.linalg.inv(inertia).reshape(-1)
    out[P_CENTRE : P_CENTRE + 3] = body.centre
    shape = body.shape
    if isinstance(shape, Box):
        half_x, half_y = 0.5 * shape.size[0], 0.5 * shape.size[1]
        out[P_SHAPE] = SHAPE_BOX
        out[P_RHO_FACE] = float(rectangle_twist_radius(half_x, half_y))
    else:
        half_x = half_y = shape.radius
        out[P_SHAPE] = SHAPE_CYLINDER
        out[P_RHO_FACE] = annulus_twist_radius(shape.radius, shape.inner_radius)
    out[P_HALF_X] = half_x
    out[P_HALF_Y] = half_y
    out[P_MU_STATIC] = body.friction.static
    out[P_MU_KINETIC] = body.friction.kinetic
    out[P_GRAVITY] = gravity
    out[P_HEIGHT] = shape.height
    out[P_RESTITUTION] = restitution
    return out


# --- small vector algebra ------------------------------------------------------------------------


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def cross(a0, a1, a2, b0, b1, b2):
    """a x b as a tuple."""
    return a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0


@kernel(cache=True, error_model="numpy", _nrt=False)
def rotation_matrix(y, out):
    """The rotation matrix R (3, 3) of the unit quaternion ``y[3:7]`` (w, x, y, z)."""
    w, x, yy, z = y[3], y[4], y[5], y[6]
    out[0, 0] = 1.0 - 2.0 * (yy * yy + z * z)
    out[0, 1] = 2.0 * (x * yy - w * z)
    out[0, 2] = 2.0 * (x * z + w * yy)
    out[1, 0] = 2.0 * (x * yy + w * z)
    out[1, 1] = 1.0 - 2.0 * (x * x + z * z)
    out[1, 2] = 2.0 * (yy * z - w * x)
    out[2, 0] = 2.0 * (x * z - w * yy)
    out[2, 1] = 2.0 * (yy * z + w * x)
    out[2, 2] = 1.0 - 2.0 * (x * x + yy * yy)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def world_inverse_inertia(par, rot, out):
    """I_w^-1 = R I^-1 R^T (3, 3) [1/(kg m^2)]: T = R I^-1, then T R^T (symmetric)."""
    for i in range(3):
        r0, r1, r2 = rot[i, 0], rot[i, 1], rot[i, 2]
        t0 = r0 * par[P_INVERSE] + r1 * par[P_INVERSE + 3] + r2 * par[P_INVERSE + 6]
        t1 = r0 * par[P_INVERSE + 1] + r1 * par[P_INVERSE + 4] + r2 * par[P_INVERSE + 7]
        t2 = r0 * par[P_INVERSE + 2] + r1 * par[P_INVERSE + 5] + r2 * par[P_INVERSE + 8]
        for j in range(i, 3):
            total = t0 * rot[j, 0] + t1 * rot[j, 1] + t2 * rot[j, 2]
            out[i, j] = total
            out[j, i] = total


@kernel(cache=True, error_model="numpy", _nrt=False)
def arm(par, rot, sx, sy, sz, out):
    """d = R (s - c) [m]: from G to the body-frame point s, in the support frame."""
    px = sx - par[P_CENTRE]
    py = sy - par[P_CENTRE + 1]
    pz = sz - par[P_CENTRE + 2]
    for i in range(3):
        out[i] = rot[i, 0] * px + rot[i, 1] * py + rot[i, 2] * pz


@kernel(cache=True, error_model="numpy", _nrt=False)
def sin_tilt(rot):
    """sin of the tilt (angle of the body's z axis from the vertical) [-]."""
    return math.sqrt(rot[2, 0] ** 2 + rot[2, 1] ** 2)


@kernel(cache=True, error_model="numpy", _nrt=False)
def box_corner(par, k):
    """Base corner k (0..3, counter-clockwise from (+b_x, +b_y)) in the body frame."""
    sx = par[P_HALF_X] if k == 0 or k == 3 else -par[P_HALF_X]
    sy = par[P_HALF_Y] if k == 0 or k == 1 else -par[P_HALF_Y]
    return sx, sy


@kernel(cache=True, error_model="numpy", _nrt=False)
def lowest_rim_angle(rot, psi_stored):
    """Body-frame angle [rad] of the cylinder's lowest rim point (the stored one when flat)."""
    if sin_tilt(rot) <= PIVOT_LEAN:
        return psi_stored
    return math.atan2(-rot[2, 1], -rot[2, 0])


# --- support motion -----------------------------------------------------------------------------


@kernel(cache=True, error_model="numpy", _nrt=False)
def support_acceleration(record, dt, t):
    """(a_x, a_y, a_v) [m/s^2] at ``t`` [s]: linear between samples, zero outside.

    ``record`` is (3, n): x, y and the downward vertical acceleration a_v.
    """
    count = record.shape[1]
    position = t / dt
    if position < 0.0 or position > count - 1:
        return 0.0, 0.0, 0.0
    index = min(int(position), count - 2)
    f = position - index
    a_x = (1.0 - f) * record[0, index] + f * record[0, index + 1]
    a_y = (1.0 - f) * record[1, index] + f * record[1, index + 1]
    a_v = (1.0 - f) * record[2, index] + f * record[2, index + 1]
    return a_x, a_y, a_v


@kernel(cache=True, error_model="numpy", _nrt=False)
def applied_wrench(par, y, inv_inertia, rot, a_x, a_y, a_v, out):
    """f_0 = (m g_e, -omega x I_w omega) (6,) [N, N m]."""
    m = par[P_MASS]
    out[0] = -m * a_x
    out[1] = -m * a_y
    out[2] = -m * (par[P_GRAVITY] - a_v)
    # I_w omega = R I R^T omega
    wx, wy, wz = y[10], y[11], y[12]
    bx = rot[0, 0] * wx + rot[1, 0] * wy + rot[2, 0] * wz
    by = rot[0, 1] * wx + rot[1, 1] * wy + rot[2, 1] * wz
    bz = rot[0, 2] * wx + rot[1, 2] * wy + rot[2, 2] * wz
    hx = par[P_INERTIA] * bx + par[P_INERTIA + 1] * by + par[P_INERTIA + 2] * bz
    hy = par[P_INERTIA + 3] * bx + par[P_INERTIA + 4] * by + par[P_INERTIA + 5] * bz
    hz = par[P_INERTIA + 6] * bx + par[P_INERTIA + 7] * by + par[P_INERTIA + 8] * bz
    lx = rot[0, 0] * hx + rot[0, 1] * hy + rot[0, 2] * hz
    ly = rot[1, 0] * hx + rot[1, 1] * hy + rot[1, 2] * hz
    lz = rot[2, 0] * hx + rot[2, 1] * hy + rot[2, 2] * hz
    gx, gy, gz = cross(wx, wy, wz, lx, ly, lz)
    out[3] = -gx
    out[4] = -gy
    out[5] = -gz


@kernel(cache=True, error_model="numpy", _nrt=False)
def apply_inverse_mass(par, inv_inertia, w, out):
    """M^-1 w (6,)."""
    inv_m = 1.0 / par[P_MASS]
    out[0] = w[0] * inv_m
    out[1] = w[1] * inv_m
    out[2] = w[2] * inv_m
    for i in range(3):
        out[3 + i] = inv_inertia[i, 0] * w[3] + inv_inertia[i, 1] * w[4] + inv_inertia[i, 2] * w[5]


# --- rows of a patch ----------------------------------------------------------------------------


@kernel(cache=True, error_model="numpy", _nrt=False)
def point_velocity(y, d, e0, e1, e2):
    """e . (v + omega x d) [m/s]: the velocity of the material point at arm d along e."""
    cx, cy, cz = cross(y[10], y[11], y[12], d[0], d[1], d[2])
    return e0 * (y[7] + cx) + e1 * (y[8] + cy) + e2 * (y[9] + cz)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _point_row(y, d, e0, e1, e2, column, rows, bias, k):
    """Row k: the point at arm d along the unit e.

    ``w = (e, d x e)``, bias ``e . (omega x (omega x d))`` plus ``column``.
    """
    rows[0, k] = e0
    rows[1, k] = e1
    rows[2, k] = e2
    tx, ty, tz = cross(d[0], d[1], d[2], e0, e1, e2)
    rows[3, k] = tx
    rows[4, k] = ty
    rows[5, k] = tz
    wx, wy, wz = y[10], y[11], y[12]
    ux, uy, uz = cross(wx, wy, wz, d[0], d[1], d[2])
    cx, cy, cz = cross(wx, wy, wz, ux, uy, uz)
    bias[k] = e0 * cx + e1 * cy + e2 * cz + column


@kernel(cache=True, error_model="numpy", _nrt=False)
def _angular_row(e0, e1, e2, rows, bias, k):
    """Row k: the angular velocity about the unit e, ``w = (0, e)``, no bias."""
    for i in range(3):
        rows[i, k] = 0.0
    rows[3, k] = e0
    rows[4, k] = e1
    rows[5, k] = e2
    bias[k] = 0.0


@kernel(cache=True, error_model="numpy", _nrt=False)
def rim_terms(par, y, rot, cos_psi, sin_psi):
    """The moving rim point's extra acceleration terms (z, x, y) [m/s^2] (rim angle psi).

    With t the rim tangent at the contact point, ``psi' = -e_z.(omega x R t)/sigma``
    and ``R s*' = R_b psi' R t``: the terms are ``omega x (R s*')``; zero when
    the base is flat (the contact point then does not move). ``sigma =
    -(R_31 cos psi + R_32 sin psi)`` is sin(tilt) at the lowest rim point and
    -sin(tilt) at the highest (the continuation past a landing, :func:`pivot_direction`).
    """
    if sin_tilt(rot) <= PIVOT_LEAN:
        return 0.0, 0.0, 0.0
    s = -(rot[2, 0] * cos_psi + rot[2, 1] * sin_psi)
    tx = -sin_psi
    ty = cos_psi
    t0 = rot[0, 0] * tx + rot[0, 1] * ty
    t1 = rot[1, 0] * tx + rot[1, 1] * ty
    t2 = rot[2, 0] * tx + rot[2, 1] * ty
    wx, wy, wz = y[10], y[11], y[12]
    cx, cy, cz = cross(wx, wy, wz, t0, t1, t2)
    rate = -cz / s
    scale = par[P_HALF_X] * rate
    ex, ey, ez = cross(wx, wy, wz, scale * t0, scale * t1, scale * t2)
    return ez, ex, ey


@kernel(cache=True, error_model="numpy", _nrt=False)
def patch_rows(par, y, sc, kind, index, cos_psi, sin_psi):
    """Fill the rows of a patch in the scratch ``sc``; returns (normal rows, tangential rows).

    A cylinder's POINT is its rim point at the body-frame angle psi, given
    by ``cos_psi`` and ``sin_psi`` (:func:`pivot_direction`).

    At the rotation ``sc[SC_ROT]``. ``sc[SC_NORMAL]`` (6, 3) and
    ``sc[SC_TANGENT]`` (6, 3) hold the rows as columns, ``sc[SC_NBIAS]`` and
    ``sc[SC_TBIAS]`` their biases, ``sc[SC_ARMS]`` (4, 3) the arms of the
    patch's points: the normal points (EDGE: its two corners; POINT: the
    point; FACE: the base centre) then, in row 3, the friction centre of the
    tangential rows. A FACE's or EDGE's tangential rows are at its friction
    centre ``sc[SC_CENTRE]`` (body-frame base x, y [m] and the twist radius
    rho [m], see :func:`move_friction_centre`).
    """
    rot, normal, nbias, arms = sc[SC_ROT], sc[SC_NORMAL], sc[SC_NBIAS], sc[SC_ARMS]
    tangent, tbias = sc[SC_TANGENT], sc[SC_TBIAS]
    if kind == FREE:
        return row_counts(FREE)
    if kind == POINT:
        d = arms[3]
        if par[P_SHAPE] == SHAPE_BOX:
            sx, sy = box_corner(par, index)
            arm(par, rot, sx, sy, 0.0, arms[0])
            zt, xt, yt = 0.0, 0.0, 0.0
        else:
            radius = par[P_HALF_X]
            arm(par, rot, radius * cos_psi, radius * sin_psi, 0.0, arms[0])
            zt, xt, yt = rim_terms(par, y, rot, cos_psi, sin_psi)
        for i in range(3):
            d[i] = arms[0, i]
        _point_row(y, arms[0], 0.0, 0.0, 1.0, zt, normal, nbias, 0)
        _point_row(y, d, 1.0, 0.0, 0.0, xt, tangent, tbias, 0)
        _point_row(y, d, 0.0, 1.0, 0.0, yt, tangent, tbias, 1)
        return row_counts(POINT)
    if kind == EDGE:
        ax, ay = box_corner(par, index)
        bx, by = box_corner(par, (index + 1) % 4)
        arm(par, rot, ax, ay, 0.0, arms[0])
        arm(par, rot, bx, by, 0.0, arms[1])
        _point_row(y, arms[0], 0.0, 0.0, 1.0, 0.0, normal, nbias, 0)
        _point_row(y, arms[1], 0.0, 0.0, 1.0, 0.0, normal, nbias, 1)
    else:  # FACE
        arm(par, rot, 0.0, 0.0, 0.0, arms[0])
        _point_row(y, arms[0], 0.0, 0.0, 1.0, 0.0, normal, nbias, 0)
        _angular_row(1.0, 0.0, 0.0, normal, nbias, 1)
        _angular_row(0.0, 1.0, 0.0, normal, nbias, 2)
    tangent_rows(par, y, sc)
    return row_counts(kind)


@kernel(cache=True, error_model="numpy", _nrt=False)
def row_counts(kind):
    """(normal rows, tangential rows) of a patch of ``kind`` (the module's table)."""
    if kind == FREE:
        return 0, 0
    if kind == POINT:
        return 1, 2
    return (2, 3) if kind == EDGE else (3, 3)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def tangent_rows(par, y, sc):
    """A FACE's or EDGE's tangential rows at its friction centre, in the scratch ``sc``.

    The horizontal velocity of the material point at the centre
    ``sc[SC_CENTRE]`` (its arm in ``sc[SC_ARMS][3]``), then the twist
    ``(0, rho e_z)`` with rho = ``centre[2]``.
    """
    centre, tangent, tbias, d = sc[SC_CENTRE], sc[SC_TANGENT], sc[SC_TBIAS], sc[SC_ARMS][3]
    arm(par, sc[SC_ROT], centre[0], centre[1], 0.0, d)
    _point_row(y, d, 1.0, 0.0, 0.0, 0.0, tangent, tbias, 0)
    _point_row(y, d, 0.0, 1.0, 0.0, 0.0, tangent, tbias, 1)
    _angular_row(0.0, 0.0, centre[2], tangent, tbias, 2)


# --- the friction centre of a FACE or EDGE ---------------------------------------------------


@kernel(cache=True, error_model="numpy", _nrt=False)
def effective_twist_radius(par, kind, index, cx, cy):
    """Twist radius rho [m] of a FACE or EDGE whose centre of pressure is (cx, cy).

    The pressure is taken uniform over the *effective area*, the largest part
    of the contact concentric with the centre of pressure (Meyerhof 1953):
    for a box face the rectangle of half-sides ``b_x - |c_x|``, ``b_y -
    |c_y|``, for an edge of half-length ``L/2`` the segment of half-length
    ``L/2 - |e|`` (e the offset along it), for a disc or annulus the base
    shrunk about the centre by ``1 - |c|/R``. rho is the mean distance of
    that area from its centre: the full base's at the centre, an edge's
    (``L/4``) when the centre of pressure reaches a side, zero at a corner or
    on the rim, so that the friction of a FACE, an EDGE and a POINT agree
    where one becomes the other. Floored at ``RHO_FLOOR`` times the base's
    half-width so that the twist row stays a row.
    """
    floor = RHO_FLOOR * par[P_HALF_X]
    if kind == FACE:
        return face_twist_radius(par[P_SHAPE] == SHAPE_BOX, par[P_HALF_X], par[P_HALF_Y],
                                 par[P_RHO_FACE], floor, cx, cy)  # fmt: skip
    if kind == EDGE:
        ax, ay = box_corner(par, index)
        bx, by = box_corner(par, (index + 1) % 4)
        if ay == by:  # an edge along x
            half, offset = 0.5 * abs(bx - ax), cx - 0.5 * (ax + bx)
        else:
            half, offset = 0.5 * abs(by - ay), cy - 0.5 * (ay + by)
        return max(0.5 * (half - abs(offset)), floor)
    return 0.0


@kernel(cache=True, error_model="numpy", _nrt=False)
def reset_friction_centre(par, kind, index, centre):
    """The friction centre at the patch's geometric centre (the base centre, an edge's midpoint).

    ``centre`` (5,): x, y [m] in the body frame's base plane, rho [m], then the
    patch's kind and index (as floats), which :func:`solve_patch` reads.
    """
    centre[3] = kind
    centre[4] = index
    centre[0] = 0.0
    centre[1] = 0.0
    if kind == EDGE:
        ax, ay = box_corner(par, index)
        bx, by = box_corner(par, (index + 1) % 4)
        centre[0] = 0.5 * (ax + bx)
        centre[1] = 0.5 * (ay + by)
    centre[2] = effective_twist_radius(par, kind, index, centre[0], centre[1])


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def on_base(par, cx, cy):
    """A body-frame base point (cx, cy) [m] kept on the base (a box's rectangle, a disc)."""
    if par[P_SHAPE] == SHAPE_BOX:
        bx, by = par[P_HALF_X], par[P_HALF_Y]
        return min(max(cx, -bx), bx), min(max(cy, -by), by)
    size = norm2(cx, cy)
    if size > par[P_HALF_X]:
        return cx * par[P_HALF_X] / size, cy * par[P_HALF_X] / size
    return cx, cy


@kernel(cache=True, error_model="numpy", _nrt=False)
def move_friction_centre(par, rot, kind, index, lam, centre):
    """Move the friction centre to the patch's centre of pressure; returns how far [m].

    The centre of pressure of the normal multipliers ``lam`` (FACE: from N
    and its couples; EDGE: ``(N_a a + N_b b) / N`` of its corners), kept on
    the contact; unchanged while N <= 0. Sets ``centre`` = (x, y, rho).
    """
    if kind == FACE:
        n = lam[0]
        if n <= 0.0:
            return 0.0
        cx, cy = face_centre_of_pressure(rot, lam)
        cx, cy = on_base(par, cx, cy)
    elif kind == EDGE:
        n = lam[0] + lam[1]
        if n <= 0.0:
            return 0.0
        share = min(max(lam[1] / n, 0.0), 1.0)
        ax, ay = box_corner(par, index)
        bx, by = box_corner(par, (index + 1) % 4)
        cx = ax + share * (bx - ax)
        cy = ay + share * (by - ay)
    else:
        return 0.0
    moved = norm2(cx - centre[0], cy - centre[1])
    centre[0] = cx
    centre[1] = cy
    centre[2] = effective_twist_radius(par, kind, index, cx, cy)
    return moved


@kernel(cache=True, error_model="numpy", _nrt=False)
def centre_stick_friction(par, rot, kind, index, n_normal, lam, centre):
    """A sticking FACE's or EDGE's friction, solved on rows at ``centre``, about its CoP.

    The force is the same; the twist torque about the new centre is
    ``T' = T - (delta x F)_z`` (delta the horizontal move of the centre), its
    multiplier ``T' / rho'``. ``centre`` is moved (:func:`move_friction_centre`).
    """
    old_x, old_y, old_rho = centre[0], centre[1], centre[2]
    move_friction_centre(par, rot, kind, index, lam, centre)
    sx = centre[0] - old_x
    sy = centre[1] - old_y
    dx = rot[0, 0] * sx + rot[0, 1] * sy
    dy = rot[1, 0] * sx + rot[1, 1] * sy
    force_x = lam[n_normal]
    force_y = lam[n_normal + 1]
    torque = lam[n_normal + 2] * old_rho - (dx * force_y - dy * force_x)
    lam[n_normal + 2] = torque / centre[2]


@kernel(cache=True, error_model="numpy", _nrt=False)
def normal_total(kind, lam):
    """The patch's total normal force N [N] from its normal multipliers."""
    if kind == POINT:
        return lam[0]
    if kind == EDGE:
        return lam[0] + lam[1]
    if kind == FACE:
        return lam[0]
    return 0.0


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def tangential_velocity(y, tangent, n_tangent, out):
    """The tangential rows' velocities s (scaled slip velocity) [m/s]."""
    for k in range(n_tangent):
        total = 0.0
        for i in range(3):
            total += tangent[i, k] * y[7 + i] + tangent[3 + i, k] * y[10 + i]
        out[k] = total
    return n_tangent


# --- the solve of one mode ----------------------------------------------------------------------


@kernel(cache=True, error_model="numpy", _nrt=False)
def solve_mode(par, sc, base, use_bias, slip, direction, n_normal, n_tangent, acc, lam):
    """Solve the contact problem of one mode on the scratch's rows; False when singular.

    Held rows: the normal rows, and the tangential rows when sticking. A
    sliding patch carries ``f_t = -mu N u`` (``direction`` = u, unit, on the
    tangential rows), which adds ``-mu u`` to every normal column.

    Acceleration level (``use_bias``): ``base = M^-1 f_0``, the held rows'
    accelerations ``w . x'' + b`` vanish, ``acc = x''`` and ``lam`` are forces.
    Velocity level (an impact, no bias): ``base`` is the velocity before, the
    held rows' velocities after vanish, ``acc`` is the velocity after and
    ``lam`` are impulses [N s]. ``lam`` holds the normal multipliers, then
    the tangential ones (sticking, or ``-mu N u`` when sliding). The rows,
    the inverse inertia and the work arrays are the scratch's ``sc``.

    A sliding FACE's friction acts at its centre of pressure, ``N p = (-M_y,
    M_x)`` from its couples: the twist of that offset is linear in the
    multipliers (:func:`face_offset_torques`), and one solve places the
    friction at the centre of pressure of its own solution, where its
    tangential rows (``sc[SC_CENTRE]``) are elsewhere.
    """
    inv, normal, nbias, tangent, tbias = (sc[SC_INV], sc[SC_NORMAL], sc[SC_NBIAS], sc[SC_TANGENT],
                                          sc[SC_TBIAS])  # fmt: skip
    work, matrix, rhs = sc[SC_WORK], sc[SC_MATRIX], sc[SC_RHS]
    mu = par[P_MU_KINETIC]
    inv_m = 1.0 / par[P_MASS]
    held = n_normal + (n_tangent if slip == 0 else 0)
    face_slide = slip == 1 and n_normal == 3
    torques = face_offset_torques(sc, mu, direction) if face_slide else (0.0, 0.0, 0.0)
    # the held rows w_r, work[0:held], and rhs = -(w_r . base + b_r)
    for r in range(held):
        row = work[r]
        if r < n_normal:
            for i in range(6):
                row[i] = normal[i, r]
            bias = nbias[r]
        else:
            for i in range(6):
                row[i] = tangent[i, r - n_normal]
            bias = tbias[r - n_normal]
        total = bias if use_bias else 0.0
        for i in range(6):
            total += row[i] * base[i]
        rhs[r] = -total
    # M^-1 times each multiplier's generalised force, work[7 + j]: its row, and on a sliding
    # patch's normal columns the friction -mu u (a FACE's couples carry none)
    col = work[6]
    for j in range(held):
        for i in range(6):
            col[i] = work[j, i]
        if slip == 1 and j < n_normal and (j == 0 or n_normal == 2):
            for k in range(n_tangent):
                for i in range(6):
                    col[i] -= mu * direction[k] * tangent[i, k]
        out = work[7 + j]
        out[0] = col[0] * inv_m
        out[1] = col[1] * inv_m
        out[2] = col[2] * inv_m
        twist = col[5] + (torques[j] if face_slide else 0.0)
        for i in range(3):
            out[3 + i] = inv[i, 0] * col[3] + inv[i, 1] * col[4] + inv[i, 2] * twist
    if held > 0 and not _solve_held(work, matrix, rhs, held, slip == 0):
        return False
    minv = base
    for i in range(6):
        acc[i] = minv[i]
    for j in range(held):
        lam[j] = rhs[j]
        for i in range(6):
            acc[i] += rhs[j] * work[7 + j, i]
    if slip == 1:
        total = normal_total_rows(n_normal, lam)
        for k in range(n_tangent):
            lam[n_normal + k] = -mu * total * direction[k]
    return True


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _solve_held(work, matrix, rhs, held, symmetric):
    """The held rows' system ``(w_r . M^-1 g_j) x = rhs`` solved in place; False if singular.

    ``work[r]`` holds row r, ``work[7 + j]`` M^-1 times multiplier j's
    generalised force (:func:`solve_mode`). Symmetric (no sliding patch:
    ``g_j = w_j``) and larger than 3 x 3 (a sticking EDGE or FACE): its
    lower triangle by ``L D L^T``
    (:func:`freestand.core.contact.engine.solve_symmetric_in_place`), as the
    planar engine's held modes; where that finds it not positive definite,
    and otherwise, the whole matrix by :func:`solve_small`.
    """
    rows, forces = work[:held], work[7 : 7 + held]
    if symmetric and held > 3:
        held_products(rows, forces, matrix, held, 0, 6, True)
        if solve_symmetric_in_place(matrix, rhs, held):
            return True
    held_products(rows, forces, matrix, held, 0, 6, False)
    return solve_small(matrix, rhs, held)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def solve_small(matrix, rhs, k):
    """Solve the leading k x k system ``matrix x = rhs`` in place (x in ``rhs``); False if singular.

    Up to three unknowns (a POINT's, an EDGE's normal rows, a FACE's, a
    sliding patch's) by Cramer's rule, ``x_i = det(A_i) / det(A)`` with the
    cofactors of A, where ``|det(A)|`` is at least ``CRAMER_CONDITION``
    times Hadamard's bound, the product of the rows' lengths (the rows are
    far from dependent: the closed form's error is then round-off times a
    moderate condition number); otherwise, and for larger systems, Gaussian
    elimination with partial pivoting
    (:func:`freestand.core.contact.engine.solve_in_place`, which the planar
    engine shares). A 3 x 3 system took half of a solve's arithmetic in the
    pivoting loop. ``matrix`` is overwritten only by the elimination.
    """
    if k == 1:
        if matrix[0, 0] == 0.0:
            return False
        rhs[0] /= matrix[0, 0]
        return True
    if k == 2:
        a, b, c, d = matrix[0, 0], matrix[0, 1], matrix[1, 0], matrix[1, 1]
        det = a * d - b * c
        if abs(det) > CRAMER_CONDITION * norm2(a, b) * norm2(c, d):
            x0 = (d * rhs[0] - b * rhs[1]) / det
            rhs[1] = (a * rhs[1] - c * rhs[0]) / det
            rhs[0] = x0
            return True
    elif k == 3:
        a00, a01, a02 = matrix[0, 0], matrix[0, 1], matrix[0, 2]
        a10, a11, a12 = matrix[1, 0], matrix[1, 1], matrix[1, 2]
        a20, a21, a22 = matrix[2, 0], matrix[2, 1], matrix[2, 2]
        c00 = a11 * a22 - a12 * a21
        c01 = a12 * a20 - a10 * a22
        c02 = a10 * a21 - a11 * a20
        det = a00 * c00 + a01 * c01 + a02 * c02
        bound = (math.sqrt(a00 * a00 + a01 * a01 + a02 * a02)
                 * math.sqrt(a10 * a10 + a11 * a11 + a12 * a12)
                 * math.sqrt(a20 * a20 + a21 * a21 + a22 * a22))  # fmt: skip
        if abs(det) > CRAMER_CONDITION * bound:
            b0, b1, b2 = rhs[0], rhs[1], rhs[2]
            # x = adj(A) b / det, adj(A) the transposed cofactors
            rhs[0] = (c00 * b0 + (a02 * a21 - a01 * a22) * b1 + (a01 * a12 - a02 * a11) * b2) / det
            rhs[1] = (c01 * b0 + (a00 * a22 - a02 * a20) * b1 + (a02 * a10 - a00 * a12) * b2) / det
            rhs[2] = (c02 * b0 + (a01 * a20 - a00 * a21) * b1 + (a00 * a11 - a01 * a10) * b2) / det
            return True
    return solve_in_place(matrix, rhs, k)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def face_offset_torques(sc, mu, direction):
    """A sliding FACE's twist [N m] per unit of its multipliers N, M_x, M_y from its CoP's offset.

    The friction ``-mu N u`` at the centre of pressure p (horizontal, from
    the base centre, ``N p = (-M_y, M_x)``, :func:`face_centre_of_pressure`)
    twists the body by ``(p x f)_z = mu (u_x M_x + u_y M_y)``. The tangential
    rows at the friction centre c (``sc[SC_CENTRE]``) carry ``mu N (u_x c_y -
    u_y c_x)`` of it in N's column; the three terms put the friction at p
    instead: ``-mu (u_x c_y - u_y c_x)`` on N, ``mu u_x`` on M_x, ``mu u_y``
    on M_y (u = ``direction``, world x and y; the base flat, c turned by its
    yaw).
    """
    centre, rot = sc[SC_CENTRE], sc[SC_ROT]
    cx = rot[0, 0] * centre[0] + rot[0, 1] * centre[1]
    cy = rot[1, 0] * centre[0] + rot[1, 1] * centre[1]
    ux, uy = direction[0], direction[1]
    return -mu * (ux * cy - uy * cx), mu * ux, mu * uy


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def normal_total_rows(n_normal, lam):
    """Total normal force of a patch from its row count (3 rows: FACE, lam[0])."""
    if n_normal == 2:
        return lam[0] + lam[1]
    if n_normal >= 1:
        return lam[0]
    return 0.0


@kernel(cache=True, error_model="numpy", _nrt=False)
def row_acceleration(rows, bias, k, acc):
    """w_k . x'' + b_k [m/s^2]."""
    total = bias[k]
    for i in range(6):
        total += rows[i, k] * acc[i]
    return total


# --- admissibility -------------------------------------------------------------------------------


@kernel(cache=True, error_model="numpy", _nrt=False)
def face_centre_of_pressure(rot, lam):
    """Centre of pressure (body frame x, y) [m] of a FACE from (N, M_x, M_y)."""
    n = lam[0]
    if n <= 0.0:
        return 0.0, 0.0
    px = -lam[2] / n
    py = lam[1] / n
    # the body is flat: its frame is a rotation about z
    return rot[0, 0] * px + rot[1, 0] * py, rot[0, 1] * px + rot[1, 1] * py


@kernel(cache=True, error_model="numpy", _nrt=False)
def normal_margin(par, rot, kind, lam):
    """The smallest normal admissibility margin of a patch [N] (>= 0 admissible).

    POINT: N; EDGE: both corner forces; FACE: N and the centre of pressure
    inside the base, as ``b N - |moment|`` per side (box) or ``R N - |M|``
    (disc), linear in the multipliers.
    """
    if kind == POINT:
        return lam[0]
    if kind == EDGE:
        return min(lam[0], lam[1])
    if kind == FACE:
        n = lam[0]
        # moments about the base centre in the body frame
        mx = rot[0, 0] * lam[1] + rot[1, 0] * lam[2]
        my = rot[0, 1] * lam[1] + rot[1, 1] * lam[2]
        if par[P_SHAPE] == SHAPE_BOX:
            return min(n, par[P_HALF_X] * n - abs(my), par[P_HALF_Y] * n - abs(mx))
        return min(n, par[P_HALF_X] * n - norm2(mx, my))
    return 0.0


@kernel(cache=True, error_model="numpy", _nrt=False)
def friction_margin(par, n_normal, n_tangent, lam):
    """mu_0 N - |f_t| [N] of a sticking patch (>= 0 holds)."""
    total = normal_total_rows(n_normal, lam)
    size = 0.0
    for k in range(n_tangent):
        size += lam[n_normal + k] ** 2
    return par[P_MU_STATIC] * total - math.sqrt(size)


# --- scratch, the state's rate ------------------------------------------------------------------

SC_ROT = 0
SC_INV = 1
SC_F0 = 2
SC_BASE = 3
SC_NORMAL = 4
SC_NBIAS = 5
SC_TANGENT = 6
SC_TBIAS = 7
SC_ARMS = 8
SC_WORK = 9
SC_MATRIX = 10
SC_RHS = 11
SC_ACC = 12
SC_LAM = 13
SC_SVEL = 14
SC_SACC = 15
SC_DIR = 16
SC_CENTRE = 17  # the friction centre of the rows: base x, y [m] (body frame), rho [m]; kind, index;
# then 1.0 where the last solve's slip direction was the stored one at any of its centres
SC_PROBE = 18  # (3, 6) work outside a solve: arms of probed points, a projection's velocities
SC_EDGE = 19  # (3, 10) a sliding EDGE's terms of its centre's search (:func:`edge_slide_terms`);
# a sliding FACE's last centres and their centres of pressure (:func:`_slide_face`)
SC_RIM = 20  # (4,) the stored rim angle's cosine and sine: set (1.0), psi [rad], cos, sin
# the choice of a mode's and an impact's work (body_modes, body_engine): no allocation there
SC_TOUCHING = 21  # (5,) 0 or 1 (numba has no bool arrays in records): the touching points
SC_KINDS = 22  # (MAX_CANDIDATES + 1,) int: the candidates' kinds, indices and rim angles
SC_INDICES = 23
SC_ANGLES = 24
SC_POINTS = 25  # (3, 3) arms of probed points: touching_points, _others_separate, touched_patch
SC_STORED = 26  # (DATA_SIZE,) a kinetic candidate's stored slip (body_modes.try_mode)
SC_START = 27  # (3,) a slip onset's start (try_mode)
SC_ONSET = 28  # (3, 3) an onset's Newton: the basis across u, the trial u
SC_JACOBIAN = 29  # (2, 2) the onset Newton's Jacobian
SC_EXCLUDED = 30  # (3,) int: the mode a selection excludes (body_modes.select_mode)
SC_AFTER = 31  # (6,) an impact's velocity after (body_engine.resolve)

# the columns of ``sc[SC_EDGE]``'s rows 0 and 1 (one per corner's normal row r, q_r = M^-1 w_r)
E_A0 = 0  # w_r . M^-1 w_0
E_A1 = 1  # w_r . M^-1 w_1
E_RHS = 2  # -(w_r . base + b_r)
E_QX = 3  # q_r's force along x, y: the friction's horizontal force
E_QY = 4
E_QT = 5  # q_r's moment about z: the twist's torque
E_AX = 6  # (q_r's moment x d_a), x and y: the friction's moment at the first corner
E_AY = 7
E_BX = 8  # (q_r's moment x d_b), x and y: at the second corner
E_BY = 9
# row 2: the corners' horizontal velocities (a x, a y, b x, b y) [m/s], then omega_z [rad/s]


#: the scratch's fields, in the order of the SC_* indices: one record, passed to a compiled
#: function as one pointer (a tuple of its 19 arrays was passed as some 150 words, at every call)
SCRATCH_DTYPE = np.dtype(
    [
        ("rot", "f8", (3, 3)), ("inv", "f8", (3, 3)), ("f0", "f8", 6), ("base", "f8", 6),
        ("normal", "f8", (6, 3)), ("nbias", "f8", 3), ("tangent", "f8", (6, 3)),
        ("tbias", "f8", 3), ("arms", "f8", (4, 3)), ("work", "f8", (13, 6)),
        ("matrix", "f8", (6, 6)), ("rhs", "f8", 6), ("acc", "f8", 6), ("lam", "f8", 6),
        ("svel", "f8", 3), ("sacc", "f8", 3), ("dir", "f8", 3), ("centre", "f8", 6),
        ("probe", "f8", (3, 6)), ("edge", "f8", (3, 10)), ("rim", "f8", 4),
        ("touching", "u1", 5), ("kinds", "i8", MAX_CANDIDATES + 1),
        ("indices", "i8", MAX_CANDIDATES + 1), ("angles", "f8", MAX_CANDIDATES + 1),
        ("points", "f8", (3, 3)), ("stored", "f8", DATA_SIZE), ("start", "f8", 3),
        ("onset", "f8", (3, 3)), ("jacobian", "f8", (2, 2)), ("excluded", "i8", 3),
        ("after", "f8", 6),
    ],
    align=True,
)  # fmt: skip


def new_scratch() -> np.void:
    """The work arrays of the kernel, as one record (``sc[SC_ROT]``, ... see the SC_* indices).

    A view of a one-element structured array (``SCRATCH_DTYPE``), which it
    keeps alive; a compiled function receives it as a pointer to its data.
    """
    return np.zeros(1, dtype=SCRATCH_DTYPE)[0]


@kernel(cache=True, error_model="numpy", _nrt=False)
def pivot_direction(par, rot, kind, psi_stored, sc):
    """(cos psi, sin psi) of the rim point a cylinder's POINT rolls on; (1, 0) for other patches.

    psi is the body-frame angle of the lowest rim point,
    ``(cos psi, sin psi) = -(R_31, R_32) / sin(tilt)``, while it lies on the
    side of the stored angle ``psi_stored`` (the pivot at the step's start);
    past a landing (the axis has crossed the vertical within a step) the
    highest rim point, which continues the rocking about the same side
    smoothly, as a planar block's rotation continues through zero about its
    corner until the landing is located. Within ``PIVOT_LEAN`` of flat (the
    opposite edge within 2 R 1e-6 of the support) the stored angle: there
    the lowest point's direction is set by round-off and, where the lean
    passes the vertical at a distance, swings round the rim faster than any
    step follows; the body rocks about the stored rim point, as a planar
    block about its corner. The cosine and sine come from the rotation, the
    stored angle's from the scratch (:func:`stored_direction`, once per
    stored angle): no trigonometry per solve.
    """
    if kind != POINT or par[P_SHAPE] != SHAPE_CYLINDER:
        return 1.0, 0.0
    cos_stored, sin_stored = stored_direction(psi_stored, sc)
    s = sin_tilt(rot)
    if s <= PIVOT_LEAN:
        return cos_stored, sin_stored
    c = -rot[2, 0] / s
    n = -rot[2, 1] / s
    if c * cos_stored + n * sin_stored < 0.0:
        return -c, -n
    return c, n


@kernel(cache=True, error_model="numpy", _nrt=False)
def stored_direction(psi, sc):
    """(cos psi, sin psi) of a stored rim angle, kept in ``sc[SC_RIM]`` for the next call."""
    rim = sc[SC_RIM]
    if rim[0] != 1.0 or rim[1] != psi:
        rim[0] = 1.0
        rim[1] = psi
        rim[2] = math.cos(psi)
        rim[3] = math.sin(psi)
    return rim[2], rim[3]


@kernel(cache=True, error_model="numpy", _nrt=False)
def prepare(par, record, dt, t, y, kind, index, psi, sc):
    """Rotation, inverse inertia, applied wrench, M^-1 f_0 and the patch's rows at ``t``.

    ``psi`` [rad]: a cylinder's POINT's rim angle. Returns (normal rows,
    tangential rows).
    """
    rotation_matrix(y, sc[SC_ROT])
    prepare_load(par, record, dt, t, y, sc)
    cos_psi, sin_psi = 1.0, 0.0
    if kind == POINT and par[P_SHAPE] == SHAPE_CYLINDER:
        cos_psi, sin_psi = math.cos(psi), math.sin(psi)
    return scratch_rows(par, y, kind, index, cos_psi, sin_psi, sc)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def prepare_load(par, record, dt, t, y, sc):
    """Inverse inertia, applied wrench and M^-1 f_0 at ``t``, at the rotation ``sc`` holds."""
    rot, inv, f0 = sc[SC_ROT], sc[SC_INV], sc[SC_F0]
    world_inverse_inertia(par, rot, inv)
    a_x, a_y, a_v = support_acceleration(record, dt, t)
    applied_wrench(par, y, inv, rot, a_x, a_y, a_v, f0)
    apply_inverse_mass(par, inv, f0, sc[SC_BASE])


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def scratch_rows(par, y, kind, index, cos_psi, sin_psi, sc):
    """The patch's rows (:func:`patch_rows`) in the scratch, at the rotation it holds.

    The friction centre starts at the patch's geometric centre
    (:func:`reset_friction_centre`). Returns (normal rows, tangential rows).
    """
    centre = sc[SC_CENTRE]
    reset_friction_centre(par, kind, index, centre)
    return patch_rows(par, y, sc, kind, index, cos_psi, sin_psi)


@kernel(cache=True, error_model="numpy", _nrt=False)
def solve_patch(par, y, sc, use_bias, slip, direction, kinetic, stored, n_normal, n_tangent):
    """Solve a mode on the rows in the scratch, its friction about the centre of pressure.

    A FACE's or EDGE's friction acts about its centre of pressure, with the
    twist radius of its effective area (:func:`effective_twist_radius`).
    Sticking, the rows' centre does not change the solution (every point of
    the patch is held): one solve, then the friction is expressed about the
    centre of pressure (:func:`centre_stick_friction`). Sliding, the friction
    ``-mu N u`` acts at the centre of pressure, which the solution moves: a
    FACE's solve places it there itself, and is solved again only where its
    slip direction or twist radius differ there (:func:`_slide_face`); an
    EDGE's centre is found by a secant on its share along the edge, then
    solved once (:func:`_slide_edge`); to ``CENTRE_TOLERANCE``, at most
    ``CENTRE_ITERATIONS`` solves or ``EDGE_ITERATIONS`` shares. ``kinetic``:
    the slip direction u is the slip velocity's at each centre
    (:func:`slip_direction`, ``stored`` its fallback, as mode data); else u
    is ``direction`` as given. The patch is the one whose rows the scratch
    holds (``sc[SC_CENTRE][3:5]``, :func:`scratch_rows`); the rows and
    ``sc[SC_CENTRE]`` are left at the final centre, and ``sc[SC_CENTRE][5]``
    is 1.0 where the stored direction was read (at any centre), else 0.0.
    False when a system is singular.
    """
    centre = sc[SC_CENTRE]
    kind = int(centre[3])
    index = int(centre[4])
    centre[5] = 0.0
    if kind != FACE and kind != EDGE:
        return _solve_at_rows(par, y, sc, use_bias, slip, direction, kinetic, stored, n_normal,
                              n_tangent)  # fmt: skip
    if kind == EDGE and slip == 1:
        return _slide_edge(par, y, sc, use_bias, direction, kinetic, stored, n_normal, n_tangent)
    if slip == 1:
        return _slide_face(par, y, sc, use_bias, direction, kinetic, stored, n_normal, n_tangent)
    if not _solve_at_rows(par, y, sc, use_bias, slip, direction, kinetic, stored, n_normal,
                          n_tangent):  # fmt: skip
        return False
    centre_stick_friction(par, sc[SC_ROT], kind, index, n_normal, sc[SC_LAM], centre)
    tangent_rows(par, y, sc)
    return True


@kernel(cache=True, error_model="numpy", _nrt=False)
def _slide_face(par, y, sc, use_bias, direction, kinetic, stored, n_normal, n_tangent):
    """A sliding FACE solved with its friction at its centre of pressure (:func:`solve_patch`).

    Each solve places the friction at the centre of pressure of its own
    normal multipliers (:func:`face_offset_torques`), with the slip
    direction u and twist radius rho of the centre c it starts from; its
    centre of pressure F(c) ends the search where u and ``u_t rho`` are
    the same there (:func:`_face_friction_kept`): at once without twist. A
    twist turns the slip across the base (by about ``omega_z b / |s|``):
    where u is the slip velocity's own direction, c = F(c) is then one
    equation in one unknown, and otherwise a small problem in the plane,
    solved without a solve (:func:`_predicted_centre`); the next solve
    confirms it.
    Where the body's inertia couples twist and tilt (F is then not the
    affine map the prediction takes), or the prediction does not settle,
    c = F(c) is found by Anderson's mixing of the last three centres (D. G.
    Anderson, J. ACM 12 (1965) 547-560; :func:`_anderson_centre`), which
    alone wandered at ``omega_z b ~ |s|``. F(c) is the centre of pressure itself, off the
    base where it lies there: such a slide is not admissible
    (:func:`normal_margin`), and it is found as such without the search
    creeping along the base's side. ``history`` rows: the last centres and
    their F.
    """
    centre, rot, lam = sc[SC_CENTRE], sc[SC_ROT], sc[SC_LAM]
    history = sc[SC_EDGE]  # (3, 10): free while a FACE slides; rows (x, y, F_x, F_y)
    last = math.inf
    for iteration in range(CENTRE_ITERATIONS):
        if not _solve_at_rows(par, y, sc, use_bias, 1, direction, kinetic, stored, n_normal,
                              n_tangent):  # fmt: skip
            return False
        ux, uy, twist = _face_friction(sc, kinetic, direction)
        row = history[iteration % 3]
        row[0], row[1] = centre[0], centre[1]
        moved = _move_to_pressure_centre(par, rot, lam, centre)
        if moved <= CENTRE_TOLERANCE * par[P_HALF_X]:
            return True
        if moved <= CENTRE_ROUNDOFF * par[P_HALF_X] and moved >= last:
            return True
        last = moved
        tangent_rows(par, y, sc)
        if _face_friction_kept(par, y, sc, kinetic, stored, n_tangent, ux, uy, twist, direction):
            return True
        row[2], row[3] = centre[0], centre[1]
        if iteration == 0 and kinetic:
            _predicted_centre(par, y, sc, stored, ux, uy)
            tangent_rows(par, y, sc)
        elif iteration > 0:
            _anderson_centre(par, history, iteration, centre)
            tangent_rows(par, y, sc)
    return True


@kernel(cache=True, error_model="numpy", _nrt=False)
def _move_to_pressure_centre(par, rot, lam, centre):
    """A sliding FACE's friction centre to its centre of pressure, on or off the base; how far [m].

    Unchanged while N <= 0. Sets ``centre`` = (x, y, rho).
    """
    if lam[0] <= 0.0:
        return 0.0
    cx, cy = face_centre_of_pressure(rot, lam)
    moved = norm2(cx - centre[0], cy - centre[1])
    centre[0] = cx
    centre[1] = cy
    centre[2] = effective_twist_radius(par, FACE, 0, cx, cy)
    return moved


@kernel(cache=True, error_model="numpy", _nrt=False)
def _predicted_centre(par, y, sc, stored, ux, uy):
    """A sliding, twisting FACE's consistent friction centre, predicted from one solve.

    The solve put its friction along (``ux``, ``uy``) (world) and found its
    centre of pressure p (``sc[SC_CENTRE]``, where the slip velocity is
    ``sc[SC_SVEL]``). The centre of pressure is then ``a + mu h u(c)`` for
    any u, a = p - mu h u (body frame; ``face_friction``'s (1), exact where
    the body's principal axes include the vertical), and the slip velocity
    at c is the base's rigid field's: c = F(c) needs no further solve
    (``face_friction.model_centre``: a closed form for the slip's own
    direction, else Newton's method and a bracketed search on the pull
    towards the stored direction). Sets ``sc[SC_CENTRE]`` to the centre
    found, and leaves it at p where none settles.
    """
    centre = sc[SC_CENTRE]
    base = (par[P_SHAPE] == SHAPE_BOX, par[P_HALF_X], par[P_HALF_Y], par[P_RHO_FACE],
            RHO_FLOOR * par[P_HALF_X])  # fmt: skip
    floor = max(SLIP_FLOOR, stored[D_FLOOR])
    cx, cy, settled = model_centre(face_model(par, sc, ux, uy), base, sc[SC_ROT], y[12], stored,
                                   D_SLIP, floor, sc[SC_SVEL], sc[SC_DIR])  # fmt: skip
    if settled:
        centre[0] = cx
        centre[1] = cy
        centre[2] = effective_twist_radius(par, FACE, 0, cx, cy)


@kernel(cache=True, error_model="numpy", _nrt=False)
def face_model(par, sc, ux, uy):
    """The model of a sliding FACE's centre of pressure from one solve (:func:`_predicted_centre`).

    (a_x, a_y, p_x, p_y, w_x, w_y, mu h) [m, m/s] in the body frame: p the
    solve's centre of pressure (``sc[SC_CENTRE]``, the slip velocity there
    ``sc[SC_SVEL]``, w its horizontal part), its friction along (``ux``,
    ``uy``) (world), ``a = p - mu h u``: ``face_friction``'s model.
    """
    centre, rot, svel = sc[SC_CENTRE], sc[SC_ROT], sc[SC_SVEL]
    lever = par[P_MU_KINETIC] * par[P_CENTRE + 2]
    px, py = centre[0], centre[1]
    u_x, u_y = body_horizontal(rot, ux, uy)
    wx, wy = body_horizontal(rot, svel[0], svel[1])
    return (px - lever * u_x, py - lever * u_y, px, py, wx, wy, lever)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _anderson_centre(par, history, iteration, centre):
    """The next trial centre of c = F(c) by Anderson's mixing of the last iterates.

    ``history[iteration % 3]`` is the newest (x, y, F_x, F_y), the rows
    before it the older (two, or one at the second iterate). With the
    residuals r = F(c) - c: ``c' = F_n - sum_j gamma_j (F_n - F_j)``, gamma
    minimising ``|r_n - sum_j gamma_j (r_n - r_j)|`` (exact for an affine F
    in the plane from three iterates); sets ``centre`` (x, y, rho).
    """
    new = history[iteration % 3]
    rx, ry = new[2] - new[0], new[3] - new[1]
    a = history[(iteration - 1) % 3]
    ax, ay = rx - (a[2] - a[0]), ry - (a[3] - a[1])
    gamma_a, gamma_b = 0.0, 0.0
    if iteration >= 2:
        b = history[(iteration - 2) % 3]
        bx, by = rx - (b[2] - b[0]), ry - (b[3] - b[1])
        determinant = ax * by - ay * bx
        if determinant != 0.0:
            gamma_a = (rx * by - ry * bx) / determinant
            gamma_b = (ax * ry - ay * rx) / determinant
        cx = new[2] - gamma_a * (new[2] - a[2]) - gamma_b * (new[2] - b[2])
        cy = new[3] - gamma_a * (new[3] - a[3]) - gamma_b * (new[3] - b[3])
    if iteration < 2 or determinant == 0.0:
        denominator = ax * ax + ay * ay
        if denominator <= 0.0:
            return
        gamma_a = (ax * rx + ay * ry) / denominator
        cx = new[2] - gamma_a * (new[2] - a[2])
        cy = new[3] - gamma_a * (new[3] - a[3])
    centre[0] = cx
    centre[1] = cy
    centre[2] = effective_twist_radius(par, FACE, 0, cx, cy)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _face_friction_kept(par, y, sc, kinetic, stored, n_tangent, ux, uy, twist, direction):
    """Whether a sliding FACE's solve holds at its moved friction centre (:func:`solve_patch`).

    The solve put the friction ``-mu N u`` at its own centre of pressure
    (:func:`face_offset_torques`), with u and the twist radius rho of the
    centre it started from: it holds where, at the centre of pressure (the
    rows' new centre), u (``kinetic``: the slip velocity's there,
    :func:`slip_direction`, which leaves it in ``sc[SC_DIR]``; else
    ``direction``) and ``u_t rho`` change by no more than
    ``CENTRE_TOLERANCE`` (of the half-width for the twist): a slide without
    twist, in one solve. ``ux, uy, twist``: the solve's u_x, u_y and u_t rho.
    """
    if kinetic and not slip_direction(y, n_tangent, stored, sc[SC_TANGENT], sc[SC_SVEL],
                                      sc[SC_DIR]):  # fmt: skip
        sc[SC_CENTRE][5] = 1.0
    now_x, now_y, now_twist = _face_friction(sc, kinetic, direction)
    return (
        abs(now_x - ux) <= CENTRE_TOLERANCE
        and abs(now_y - uy) <= CENTRE_TOLERANCE
        and abs(now_twist - twist) <= CENTRE_TOLERANCE * par[P_HALF_X]
    )


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _face_friction(sc, kinetic, direction):
    """A sliding FACE's u_x, u_y and u_t rho at its friction centre (kinetic: sc[SC_DIR])."""
    rho = sc[SC_CENTRE][2]
    if kinetic:
        u = sc[SC_DIR]
        return u[0], u[1], u[2] * rho
    return direction[0], direction[1], direction[2] * rho


@kernel(cache=True, error_model="numpy", _nrt=False)
def _solve_at_rows(par, y, sc, use_bias, slip, direction, kinetic, stored, n_normal, n_tangent):
    """One solve on the scratch's rows (:func:`solve_patch`'s u); flags a stored direction read."""
    if kinetic:
        own = sc[SC_DIR]
        if not slip_direction(y, n_tangent, stored, sc[SC_TANGENT], sc[SC_SVEL], own):
            sc[SC_CENTRE][5] = 1.0
        return _solve_scratch(par, sc, use_bias, slip, own, n_normal, n_tangent)
    return _solve_scratch(par, sc, use_bias, slip, direction, n_normal, n_tangent)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _slide_edge(par, y, sc, use_bias, direction, kinetic, stored, n_normal, n_tangent):
    """A sliding EDGE solved with its friction at its centre of pressure (:func:`solve_patch`).

    The centre is the share sigma in [0, 1] along the edge (from its first
    corner); the solve at sigma puts the centre of pressure at F(sigma), also
    in [0, 1], and the root of ``g = F(sigma) - sigma`` is found by the
    secant method, safeguarded by bisection on the bracket that the signs of
    g keep (g(0) >= 0 >= g(1): a root always lies inside). The first step
    is the fixed point's, sigma = F(sigma). Each F(sigma) is a 2 x 2 system
    whose terms were computed once (:func:`edge_share`): the search costs
    less than one full solve, which is made once, at the root (or where
    F has no centre of pressure or no solution: the solve then says so).
    Solving the full system at each trial took 7.5 solves per slide on
    average, up to ``CENTRE_ITERATIONS``, more than half of a rocking
    cabinet's solves: the map F is rough where the slip turns at the centre.
    """
    centre = sc[SC_CENTRE]
    index = int(centre[4])
    ax, ay = box_corner(par, index)
    bx, by = box_corner(par, (index + 1) % 4)
    length = math.sqrt((bx - ax) ** 2 + (by - ay) ** 2)
    tolerance = CENTRE_TOLERANCE * par[P_HALF_X] / length  # on sigma
    share = ((centre[0] - ax) * (bx - ax) + (centre[1] - ay) * (by - ay)) / (length * length)
    edge_slide_terms(par, y, sc, use_bias)
    low, high = 0.0, 1.0
    previous, g_previous = math.nan, math.nan
    for i in range(EDGE_ITERATIONS):
        g = edge_share(par, sc, index, share, direction, kinetic, stored) - share
        if not abs(g) > tolerance:  # settled, or no centre of pressure (NaN)
            break
        if g > 0.0:
            low = max(low, share)
        else:
            high = min(high, share)
        following = share + g  # the fixed point's step
        if i > 0 and g != g_previous:
            following = share - g * (share - previous) / (g - g_previous)
        # inside the bracket; at its end only where that end is the edge's corner, not yet
        # tried (a corner that lifts: the centre of pressure reaches it, g = 1 - sigma)
        if not low < following < high:
            if following >= high and high == 1.0 and share < 1.0:
                following = 1.0
            elif following <= low and low == 0.0 and share > 0.0:
                following = 0.0
            else:
                following = 0.5 * (low + high)
        previous, g_previous = share, g
        share = following
    _edge_centre(par, index, share, ax, ay, bx, by, centre)
    tangent_rows(par, y, sc)
    return _solve_at_rows(par, y, sc, use_bias, 1, direction, kinetic, stored, n_normal,
                          n_tangent)  # fmt: skip


@kernel(cache=True, error_model="numpy", _nrt=False)
def edge_slide_terms(par, y, sc, use_bias):
    """The terms of a sliding EDGE's systems at any centre, in ``sc[SC_EDGE]`` (see E_*).

    On the EDGE's rows in the scratch: its corners' normal rows w_r, their
    ``q_r = M^-1 w_r`` (in ``sc[SC_WORK][0:2]``), ``A_rj = w_r . q_j``, the
    right-hand sides, and the terms that give ``q_r . G`` for the friction's
    generalised force G at any point of the edge; then the corners'
    horizontal velocities and omega_z, whose blend is the slip velocity
    there. A point row is linear in its arm (``w = (e, d x e)``), and
    ``q . (d x h) = h . (q x d)``: at the share sigma everything is a blend
    of the two corners' terms, save the twist radius.
    """
    edge, normal, nbias, arms, base, q = (sc[SC_EDGE], sc[SC_NORMAL], sc[SC_NBIAS], sc[SC_ARMS],
                                          sc[SC_BASE], sc[SC_WORK])  # fmt: skip
    inv = sc[SC_INV]
    inv_m = 1.0 / par[P_MASS]
    for r in range(2):
        for i in range(3):
            q[r, i] = normal[i, r] * inv_m
            q[r, 3 + i] = (inv[i, 0] * normal[3, r] + inv[i, 1] * normal[4, r]
                           + inv[i, 2] * normal[5, r])  # fmt: skip
    for r in range(2):
        row = edge[r]
        total = nbias[r] if use_bias else 0.0
        row[E_A0] = 0.0
        row[E_A1] = 0.0
        for i in range(6):
            row[E_A0] += normal[i, r] * q[0, i]
            row[E_A1] += normal[i, r] * q[1, i]
            total += normal[i, r] * base[i]
        row[E_RHS] = -total
        row[E_QX] = q[r, 0]
        row[E_QY] = q[r, 1]
        row[E_QT] = q[r, 5]
        da, db = arms[0], arms[1]
        row[E_AX], row[E_AY], _ = cross(q[r, 3], q[r, 4], q[r, 5], da[0], da[1], da[2])
        row[E_BX], row[E_BY], _ = cross(q[r, 3], q[r, 4], q[r, 5], db[0], db[1], db[2])
    velocity = edge[2]
    for c in range(2):
        d = arms[c]
        velocity[2 * c] = point_velocity(y, d, 1.0, 0.0, 0.0)
        velocity[2 * c + 1] = point_velocity(y, d, 0.0, 1.0, 0.0)
    velocity[4] = y[12]


@kernel(cache=True, error_model="numpy", _nrt=False)
def edge_share(par, sc, index, share, direction, kinetic, stored):
    """F(sigma): the centre of pressure's share along a sliding EDGE with its friction at sigma.

    The 2 x 2 system of the corners' normal forces N_0, N_1, with ``-mu N u``
    at the point at ``share`` sigma of the edge, from the terms of
    :func:`edge_slide_terms`: ``(A - mu c 1^T) N = rhs``, ``c_r = q_r . G``
    (G the generalised force of u there, twist radius rho at sigma). u is
    ``direction``, or (``kinetic``) the slip velocity's there
    (:func:`unit_slip`, ``stored`` its fallback; flagged in
    ``sc[SC_CENTRE][5]`` where read). Returns ``N_1 / (N_0 + N_1)`` in [0, 1];
    NaN where the system is singular or N_0 + N_1 <= 0 (no centre of pressure).
    """
    edge = sc[SC_EDGE]
    ax, ay = box_corner(par, index)
    bx, by = box_corner(par, (index + 1) % 4)
    rho = effective_twist_radius(par, EDGE, index, ax + share * (bx - ax), ay + share * (by - ay))
    if kinetic:
        velocity, svel, own = edge[2], sc[SC_SVEL], sc[SC_DIR]
        svel[0] = velocity[0] + share * (velocity[2] - velocity[0])
        svel[1] = velocity[1] + share * (velocity[3] - velocity[1])
        svel[2] = rho * velocity[4]
        if not unit_slip(svel, 3, stored, own):
            sc[SC_CENTRE][5] = 1.0
        return _edge_share_along(par, edge, share, rho, own)
    return _edge_share_along(par, edge, share, rho, direction)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _edge_share_along(par, edge, share, rho, u):
    """:func:`edge_share` with the friction along the unit ``u`` (tangential rows)."""
    mu = par[P_MU_KINETIC]
    c0 = mu * _friction_term(edge[0], share, rho, u)
    c1 = mu * _friction_term(edge[1], share, rho, u)
    k00 = edge[0, E_A0] - c0
    k01 = edge[0, E_A1] - c0
    k10 = edge[1, E_A0] - c1
    k11 = edge[1, E_A1] - c1
    r0, r1 = edge[0, E_RHS], edge[1, E_RHS]
    det = k00 * k11 - k01 * k10
    first = r0 * k11 - k01 * r1  # N_0 det
    second = k00 * r1 - k10 * r0  # N_1 det
    if det == 0.0 or not (first + second) / det > 0.0:
        return math.nan
    return min(max(second / (first + second), 0.0), 1.0)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _friction_term(row, share, rho, u):
    """``q_r . G``: corner r's normal row's response to the friction's unit force u at sigma."""
    mx = row[E_AX] + share * (row[E_BX] - row[E_AX])
    my = row[E_AY] + share * (row[E_BY] - row[E_AY])
    return u[0] * (row[E_QX] + mx) + u[1] * (row[E_QY] + my) + u[2] * rho * row[E_QT]


@kernel(cache=True, error_model="numpy", _nrt=False)
def _edge_centre(par, index, share, ax, ay, bx, by, centre):
    """The friction centre at ``share`` along the edge from (ax, ay) to (bx, by), with its rho."""
    centre[0] = ax + share * (bx - ax)
    centre[1] = ay + share * (by - ay)
    centre[2] = effective_twist_radius(par, EDGE, index, centre[0], centre[1])


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _solve_scratch(par, sc, use_bias, slip, direction, n_normal, n_tangent):
    """:func:`solve_mode` on the scratch's rows and work arrays, sliding along ``direction``."""
    return solve_mode(par, sc, sc[SC_BASE], use_bias, slip, direction, n_normal, n_tangent,
                      sc[SC_ACC], sc[SC_LAM])  # fmt: skip


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def slip_direction(y, n_tangent, data, tangent, svel, direction):
    """The sliding direction u: the slip velocity's while it points on the stored one's side.

    The stored direction r (``data[D_SLIP:]``, the slip's direction at the
    step's start) keeps its side where the slip velocity s has turned
    against it (``s . r < 0``) or has almost none: the kinetic friction then
    goes on decelerating the slip through zero, as a planar block's friction
    keeps its sign within a step, until the slip-stop event is located.
    Without it the friction flips with the velocity inside an RK4 step and
    the stages cancel: the slip freezes at a small constant velocity.

    u = w / |w| with ``w = s + (|s . r| - s . r + max(SLIP_FLOOR - |s|, 0)) r``:
    the slip velocity's own direction while ``s . r > 0`` and ``|s| >
    SLIP_FLOOR``; past the stored side its component along r reflected (the
    friction still opposes the slip across r); below the floor pulled to r
    (u = r at s = 0). u is continuous in s: a slip stop's event function is
    then continuous in RK4's step, and its crossing is found in a few
    trials. Taking r itself wherever ``s . r <= 0`` swung u by 90 degrees
    at a two-dimensional slip's stop (where s is across r) and made the
    event function jump by 1e-3 m/s inside the bracket: regula falsi crept
    on the jump for 30 to 80 trials. A slip along r (a planar one) slides
    along r either way. The floor is ``SLIP_FLOOR``, or a flat base's
    step's ``data[D_FLOOR]`` where larger (the engine's ``slip_floor``: the
    speed below which RK4 could not follow the slip's turn stably).

    On the tangential rows ``tangent`` (their velocities written to ``svel``);
    ``data`` the mode data; u is written to ``direction``. Returns False
    where u depends on the stored direction (anything but ``s / |s|``).
    """
    tangential_velocity(y, tangent, n_tangent, svel)
    return unit_slip(svel, n_tangent, data, direction)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def unit_slip(svel, n_tangent, data, direction):
    """u from the slip velocity s (``svel``) and the stored r (``data[D_SLIP:]``): see
    :func:`slip_direction` and ``slip_law.pulled_unit``, with the floor ``max(SLIP_FLOOR,
    data[D_FLOOR])``. Returns False where u depends on r."""
    floor = max(SLIP_FLOOR, data[D_FLOOR])
    return pulled_unit(svel, n_tangent, data, D_SLIP, floor, direction)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def prepare_held(par, record, dt, t, y, mode, data, sc):
    """:func:`prepare` for the held mode at (t, y), its pivot at the stored rim angle's point."""
    kind = mode[M_KIND]
    rot = sc[SC_ROT]
    rotation_matrix(y, rot)
    prepare_load(par, record, dt, t, y, sc)
    cos_psi, sin_psi = pivot_direction(par, rot, kind, data[D_PSI], sc)
    return scratch_rows(par, y, kind, mode[M_INDEX], cos_psi, sin_psi, sc)


@kernel(cache=True, error_model="numpy", _nrt=False)
def solve_at(par, record, dt, t, y, mode, data, sc):
    """Solve the held mode at (t, y): fills sc[SC_ACC] and sc[SC_LAM]; False if singular.

    A sliding patch slides along its slip velocity (:func:`slip_direction`)
    and its friction acts about its centre of pressure (:func:`solve_patch`).
    Returns (ok, normal rows, tangential rows).
    """
    n_normal, n_tangent = prepare_held(par, record, dt, t, y, mode, data, sc)
    ok = solve_patch(par, y, sc, True, mode[M_SLIP], sc[SC_DIR], mode[M_SLIP] == 1, data,
                     n_normal, n_tangent)  # fmt: skip
    return ok, n_normal, n_tangent


@kernel(cache=True, error_model="numpy", _nrt=False)
def solve_at_centre(par, record, dt, t, y, mode, data, sc):
    """A sticking mode solved with its rows at the patch's geometric centre.

    The multipliers are then linear in the applied load (the rest phase's
    unit solutions, ``body_engine.rest_prepare``); :func:`centre_stick_friction`
    expresses their friction about the centre of pressure. Returns
    (ok, normal rows, tangential rows).
    """
    n_normal, n_tangent = prepare_held(par, record, dt, t, y, mode, data, sc)
    ok = _solve_scratch(par, sc, True, 0, sc[SC_DIR], n_normal, n_tangent)
    return ok, n_normal, n_tangent


@kernel(cache=True, error_model="numpy", _nrt=False)
def rate(par, record, dt, t, y, mode, data, sc, ydot):
    """y' of the held mode at (t, y); False when the mode's system is singular.

    ``r' = v``, ``q' = (0, omega) q / 2`` (omega in the support frame),
    ``(v', omega') = x''``.
    """
    ok, _, _ = solve_at(par, record, dt, t, y, mode, data, sc)
    state_rate(y, sc[SC_ACC], ydot)
    return ok


@kernel(cache=True, error_model="numpy", _nrt=False)
def state_rate(y, acc, ydot):
    """y' from the state and the accelerations ``acc`` = (v', omega') of a solve (:func:`rate`)."""
    for i in range(3):
        ydot[i] = y[7 + i]
        ydot[7 + i] = acc[i]
        ydot[10 + i] = acc[3 + i]
    wx, wy, wz = y[10], y[11], y[12]
    q0, q1, q2, q3 = y[3], y[4], y[5], y[6]
    cx, cy, cz = cross(wx, wy, wz, q1, q2, q3)
    ydot[3] = -0.5 * (wx * q1 + wy * q2 + wz * q3)
    ydot[4] = 0.5 * (q0 * wx + cx)
    ydot[5] = 0.5 * (q0 * wy + cy)
    ydot[6] = 0.5 * (q0 * wz + cz)


# --- gaps of the base ---------------------------------------------------------------------------


@kernel(cache=True, error_model="numpy", _nrt=False)
def corner_gap(par, y, rot, k, d):
    """(gap [m], gap velocity [m/s]) of the box's base corner k; its arm in ``d``."""
    sx, sy = box_corner(par, k)
    arm(par, rot, sx, sy, 0.0, d)
    return y[2] + d[2], point_velocity(y, d, 0.0, 0.0, 1.0)


@kernel(cache=True, error_model="numpy", _nrt=False)
def slowest_rim_angle(y, rot):
    """Body-frame angle [rad] of the rim point of a flat base with the smallest normal velocity.

    ``(cos phi, sin phi) = (omega_y, -omega_x) / |omega_h|`` in the support
    frame, ``phi`` minus the body's yaw (0 when the body does not turn about
    a horizontal axis): the point about which it starts to rock.
    """
    wx, wy = y[10], y[11]
    size = math.hypot(wx, wy)
    if size == 0.0:
        return 0.0
    phi = math.atan2(-wx / size, wy / size)
    return phi - math.atan2(rot[1, 0], rot[0, 0])


@kernel(cache=True, error_model="numpy", _nrt=False)
def rim_gap(par, y, rot, d):
    """(gap [m], gap velocity [m/s], psi) of the cylinder's lowest rim point; arm in ``d``.

    Flat base (sin(tilt) below ``TILT_EPSILON``): the rim point whose normal
    velocity is the smallest (:func:`slowest_rim_angle`).
    """
    radius = par[P_HALF_X]
    s = sin_tilt(rot)
    if s > TILT_EPSILON:
        psi = math.atan2(-rot[2, 1], -rot[2, 0])
    else:
        psi = slowest_rim_angle(y, rot)
    arm(par, rot, radius * math.cos(psi), radius * math.sin(psi), 0.0, d)
    return y[2] + d[2], point_velocity(y, d, 0.0, 0.0, 1.0), psi


@kernel(cache=True, error_model="numpy", _nrt=False)
def rim_contact(par, y, rot, gap_tol, d):
    """(gap [m], gap velocity [m/s], psi) of the rim point that touches; arm in ``d``.

    The lowest rim point (:func:`rim_gap`); when the whole rim lies within
    ``gap_tol`` [m] of the support, the one with the smallest normal velocity
    (:func:`slowest_rim_angle`): a cylinder that has just landed leans by
    round-off towards the side it came from, and rocks about the other.
    Taking the lowest point there saw that point rise and left the body in
    free flight until the other point hit again, microseconds later.
    """
    g, gv, psi = rim_gap(par, y, rot, d)
    if g + 2.0 * par[P_HALF_X] * sin_tilt(rot) <= gap_tol:
        radius = par[P_HALF_X]
        psi = slowest_rim_angle(y, rot)
        arm(par, rot, radius * math.cos(psi), radius * math.sin(psi), 0.0, d)
        g, gv = y[2] + d[2], point_velocity(y, d, 0.0, 0.0, 1.0)
    return g, gv, psi


@kernel(cache=True, error_model="numpy", _nrt=True)
def flat_gap(par, y, rot):
    """Largest gap [m] of the base's outline.

    Box: its highest corner; cylinder: 2 R sin(tilt) above the lowest rim point.
    """
    if par[P_SHAPE] == SHAPE_BOX:
        d = np.empty(3)
        highest = -1e300
        for k in range(4):
            g, _ = corner_gap(par, y, rot, k, d)
            highest = max(highest, g)
        return highest
    d = np.empty(3)
    g, _, _ = rim_gap(par, y, rot, d)
    return g + 2.0 * par[P_HALF_X] * sin_tilt(rot)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def kinetic_energy(par, y, rot):
    """(1/2) m |v|^2 + (1/2) omega_b . I omega_b [J] of the state (omega_b = R^T omega, body frame).

    ``rot`` (3, 3) is work space (the state's rotation is written to it).
    """
    rotation_matrix(y, rot)
    kinetic = 0.5 * par[P_MASS] * (y[7] ** 2 + y[8] ** 2 + y[9] ** 2)
    b0 = rot[0, 0] * y[10] + rot[1, 0] * y[11] + rot[2, 0] * y[12]
    b1 = rot[0, 1] * y[10] + rot[1, 1] * y[11] + rot[2, 1] * y[12]
    b2 = rot[0, 2] * y[10] + rot[1, 2] * y[11] + rot[2, 2] * y[12]
    for i in range(3):
        bi = b0 if i == 0 else (b1 if i == 1 else b2)
        for j in range(3):
            bj = b0 if j == 0 else (b1 if j == 1 else b2)
            kinetic += 0.5 * bi * par[P_INERTIA + 3 * i + j] * bj
    return kinetic


@kernel(cache=True, error_model="numpy", _nrt=True)
def energy(par, y):
    """Kinetic plus potential energy m g z_G [J] in the support's frame (no excitation)."""
    return kinetic_energy(par, y, np.empty((3, 3))) + par[P_MASS] * par[P_GRAVITY] * y[2]
