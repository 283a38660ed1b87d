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
(``sc[SC_CENTRE]``), which
:func:`~freestand.core.contact.body_solve.solve_patch` moves to c (the held
mode's solve and the state's rate are :mod:`freestand.core.contact.body_solve`'s).

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

import functools
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
    face_twist_radius,
    rectangle_twist_radius,
)
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
# the step's slip floor [m/s] (0.0: SLIP_FLOOR; see unit_slip), and a flat base's slow slip
# pulled along the step (1.0, else 0.0) with its rate without friction [m/s^2] at the
# step's start (3; body_step.start_pulled_slip)
D_PSI = 0
D_SLIP = 1
D_ONSET = 4
D_FLOOR = 5
D_PULL = 6
D_PULL_FREE = 7
DATA_SIZE = 10
MAX_CANDIDATES = 9  # candidate patches of a contact mode at most (body_modes.candidates)

STATE_SIZE = 13  # r (3), q (4), v (3), omega (3)

# row scratch: W (6, 6) columns, bias (6); normal rows first, then tangential ones
TILT_EPSILON = 1e-9  # sin(tilt) below which a cylinder counts as flat for its rim point
PIVOT_LEAN = 1e-6  # sin(tilt) below which a rocking cylinder keeps its rim point (pivot_direction)
RHO_FLOOR = 1e-9  # smallest twist radius of a FACE or EDGE, relative to the base's half-width [-]
CENTRE_ITERATIONS = 12  # most solves of a sliding FACE or EDGE to settle its friction centre
CENTRE_ROUNDOFF = 1e-9  # or a FACE's move below this that no longer shrinks (the solve's round-off)
CRAMER_CONDITION = 1e-8  # |det| / Hadamard's bound above which solve_small uses Cramer's rule
ADJUGATE_CONDITION = 1e-2  # det / its diagonal's product above which I_P is solved by adjugate
EDGE_ITERATIONS = 60  # most trial centres of a sliding EDGE (each a 2 x 2 system, edge_share)


def annulus_twist_radius(radius: float, inner_radius: float = 0.0) -> float:
    """Mean distance [m] from the centre of an annulus: (2/3)(R^3 - r^3)/(R^2 - r^2)."""
    return 2.0 / 3.0 * (radius**3 - inner_radius**3) / (radius**2 - inner_radius**2)


def body_parameters(body: Body, gravity: float, restitution: float = 1.0) -> np.ndarray:
    """The parameter vector of the compiled kernel for ``body`` (SI units), a copy.

    ``restitution`` [-] multiplies the body's velocity after each impact (1:
    the plastic impact law; the planar engine's factor, ``docs/timehistory.md``),
    but for a turn the impact leaves
    (:func:`~freestand.core.contact.body_impulse.restitution_velocity`).

    Kept on the body for each ``(gravity, restitution)``: a body is immutable
    (its inertia read-only, :class:`~freestand.core.body.Body`), and a
    campaign asks for the same body's parameters at every run. Building them
    took 7 us warm and 74 us where another program's run had left numpy out
    of the caches, as the 3-D speed benchmark's runs alternate with MuJoCo's.
    """
    kept = vars(body).setdefault("_kernel_parameters", {})
    key = (float(gravity), float(restitution))
    if key not in kept:
        kept[key] = _parameters(body, *key)
    return kept[key].copy()


def _parameters(body: Body, gravity: float, restitution: float) -> np.ndarray:
    """:func:`body_parameters`, built."""
    inertia = np.asarray(body.inertia, dtype=float).reshape(-1).tolist()
    out = [0.0] * P_SIZE  # Python floats, one array at the end (item by item, 35 us cold)
    out[P_MASS] = body.mass
    out[P_INERTIA : P_INERTIA + 9] = inertia
    out[P_INVERSE : P_INVERSE + 9] = _inverse_inertia(tuple(inertia))
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
    return np.array(out, dtype=float)


@functools.lru_cache(maxsize=64)
def _inverse_inertia(inertia: tuple) -> tuple:
    """I^-1 [1/(kg m^2)] of the body-frame inertia ``inertia`` (its 9 entries, row-major).

    Kept for the bodies last asked for: a campaign simulates the same body
    many times, and ``numpy.linalg.inv``'s path through LAPACK cost some 13
    us of a run warm and 30 us more where another program's run had left it
    out of the caches (the 3-D benchmark's runs, alternated with MuJoCo's:
    about 3 % of a slender cylinder's 10 s).
    """
    return tuple(np.linalg.inv(np.array(inertia).reshape(3, 3)).reshape(-1).tolist())


# --- small vector algebra ------------------------------------------------------------------------


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def cross(a0, a1, a2, b0, b1, b2):
    """a x b as a tuple."""
    return a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0


@kernel(cache=True, error_model="numpy", _nrt=False)
def rotation_matrix(y, out):
    """The rotation matrix R (3, 3) of the unit quaternion ``y[3:7]`` (w, x, y, z)."""
    (out[0, 0], out[0, 1], out[0, 2], out[1, 0], out[1, 1], out[1, 2], out[2, 0], out[2, 1],
     out[2, 2]) = quaternion_rotation(y[3], y[4], y[5], y[6])  # fmt: skip


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def quaternion_rotation(w, x, y, z):
    """The rotation matrix of the unit quaternion (w, x, y, z), row by row, as nine scalars
    (:func:`rotation_matrix`'s entries; a loop over many states keeps them in registers)."""
    return (1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y),
            2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x),
            2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y))  # fmt: skip


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def quaternion_product(a0, a1, a2, a3, b0, b1, b2, b3):
    """The quaternion product a b of (w, x, y, z) quaternions, as four scalars: b turned by a
    where a is a rotation in the support's frame."""
    return (a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3,
            a0 * b1 + a1 * b0 + a2 * b3 - a3 * b2,
            a0 * b2 - a1 * b3 + a2 * b0 + a3 * b1,
            a0 * b3 + a1 * b2 - a2 * b1 + a3 * b0)  # fmt: skip


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def world_inverse_inertia(par, rot, out):
    """I_w^-1 = R I^-1 R^T (3, 3) [1/(kg m^2)] (:func:`rotated_tensor`)."""
    rotated_tensor(par, P_INVERSE, rot, out)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def world_inertia(par, rot, out):
    """I_w = R I R^T (3, 3) [kg m^2] (:func:`rotated_tensor`)."""
    rotated_tensor(par, P_INERTIA, rot, out)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def rotated_tensor(par, offset, rot, out):
    """R S R^T (3, 3) of the body-frame tensor S in ``par[offset:offset + 9]`` (row-major):
    T = R S, then T R^T (S symmetric, so is the result)."""
    for i in range(3):
        r0, r1, r2 = rot[i, 0], rot[i, 1], rot[i, 2]
        t0 = r0 * par[offset] + r1 * par[offset + 3] + r2 * par[offset + 6]
        t1 = r0 * par[offset + 1] + r1 * par[offset + 4] + r2 * par[offset + 7]
        t2 = r0 * par[offset + 2] + r1 * par[offset + 5] + r2 * par[offset + 8]
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
def applied_wrench(par, y, rot, a_x, a_y, a_v, out):
    """f_0 = (m g_e, -omega x I_w omega) (6,) [N, N m]."""
    m = par[P_MASS]
    out[0] = -m * a_x
    out[1] = -m * a_y
    out[2] = -m * (par[P_GRAVITY] - a_v)
    wx, wy, wz = y[10], y[11], y[12]
    lx, ly, lz = world_inertia_times(par, rot, wx, wy, wz)
    gx, gy, gz = cross(wx, wy, wz, lx, ly, lz)
    out[3] = -gx
    out[4] = -gy
    out[5] = -gz


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def body_inertia_times(par, bx, by, bz):
    """I b [kg m^2 * b's unit] for b = (bx, by, bz) in the body frame, as a tuple."""
    hx = par[P_INERTIA] * bx + par[P_INERTIA + 1] * by + par[P_INERTIA + 2] * bz
    hy = par[P_INERTIA + 3] * bx + par[P_INERTIA + 4] * by + par[P_INERTIA + 5] * bz
    hz = par[P_INERTIA + 6] * bx + par[P_INERTIA + 7] * by + par[P_INERTIA + 8] * bz
    return hx, hy, hz


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def world_inertia_times(par, rot, x, y, z):
    """I_w v = R I R^T v [kg m^2 * v's unit] for v = (x, y, z) in the support frame, as a tuple."""
    bx = rot[0, 0] * x + rot[1, 0] * y + rot[2, 0] * z
    by = rot[0, 1] * x + rot[1, 1] * y + rot[2, 1] * z
    bz = rot[0, 2] * x + rot[1, 2] * y + rot[2, 2] * z
    hx, hy, hz = body_inertia_times(par, bx, by, bz)
    return (rot[0, 0] * hx + rot[0, 1] * hy + rot[0, 2] * hz,
            rot[1, 0] * hx + rot[1, 1] * hy + rot[1, 2] * hz,
            rot[2, 0] * hx + rot[2, 1] * hy + rot[2, 2] * hz)  # fmt: skip


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
    _point_row_at(d, e0, e1, e2, centripetal(y, d), column, rows, bias, k)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def centripetal(y, d):
    """``omega x (omega x d)`` [m/s^2]: the centripetal acceleration of the point at arm d."""
    wx, wy, wz = y[10], y[11], y[12]
    ux, uy, uz = cross(wx, wy, wz, d[0], d[1], d[2])
    return cross(wx, wy, wz, ux, uy, uz)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _point_row_at(d, e0, e1, e2, acceleration, column, rows, bias, k):
    """:func:`_point_row` with the point's centripetal acceleration given (:func:`centripetal`):
    the rows of one point along several axes compute it once."""
    _point_axis_row(d, e0, e1, e2, rows, k)
    bias[k] = _point_bias(e0, e1, e2, acceleration, column)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _point_axis_row(d, e0, e1, e2, rows, k):
    """Row k without its bias: the point at arm d along the unit e, ``w = (e, d x e)``."""
    rows[0, k] = e0
    rows[1, k] = e1
    rows[2, k] = e2
    tx, ty, tz = cross(d[0], d[1], d[2], e0, e1, e2)
    rows[3, k] = tx
    rows[4, k] = ty
    rows[5, k] = tz


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _point_bias(e0, e1, e2, acceleration, column):
    """A point row's bias along the unit e: ``e . acceleration`` plus ``column``."""
    cx, cy, cz = acceleration
    return e0 * cx + e1 * cy + e2 * cz + column


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
def patch_rows(par, y, sc, kind, index, cos_psi, sin_psi, tangential=True):
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
    rho [m], see :func:`move_friction_centre`). ``tangential`` False: a FACE's or
    EDGE's tangential rows are left as they were (a sliding EDGE's solve
    computes them at the centre of pressure it finds, ``body_solve._slide_edge``).
    """
    rot, normal, nbias, arms = sc[SC_ROT], sc[SC_NORMAL], sc[SC_NBIAS], sc[SC_ARMS]
    tangent = sc[SC_TANGENT]
    if kind == FREE:
        return row_counts(FREE)
    if kind == POINT:
        point_arm_and_biases(par, y, sc, index, cos_psi, sin_psi)
        d = arms[3]
        _point_axis_row(d, 0.0, 0.0, 1.0, normal, 0)
        _point_axis_row(d, 1.0, 0.0, 0.0, tangent, 0)
        _point_axis_row(d, 0.0, 1.0, 0.0, tangent, 1)
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
    if tangential:
        tangent_rows(par, y, sc)
    return row_counts(kind)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def point_arm_and_biases(par, y, sc, index, cos_psi, sin_psi):
    """A POINT's arm and its three rows' biases in the scratch, not the rows themselves.

    The arm d from G (``sc[SC_ARMS][0]`` and ``[3]``) of corner ``index`` of
    a box or of the rim point at psi (``cos_psi``, ``sin_psi``) of a
    cylinder, and the biases of its rows along the support's z, x and y
    (``sc[SC_NBIAS][0]``, ``sc[SC_TBIAS][0:2]``): the centripetal
    acceleration and a rolling rim point's extra terms (:func:`rim_terms`).
    All that the sticking POINT's closed form reads of its rows
    (:func:`sticking_point_from_force`); :func:`patch_rows` adds the rows.
    """
    rot, arms = sc[SC_ROT], sc[SC_ARMS]
    if par[P_SHAPE] == SHAPE_BOX:
        sx, sy = box_corner(par, index)
        arm(par, rot, sx, sy, 0.0, arms[0])
        zt, xt, yt = 0.0, 0.0, 0.0
    else:
        radius = par[P_HALF_X]
        arm(par, rot, radius * cos_psi, radius * sin_psi, 0.0, arms[0])
        zt, xt, yt = rim_terms(par, y, rot, cos_psi, sin_psi)
    d = arms[3]
    for i in range(3):
        d[i] = arms[0, i]
    acceleration = centripetal(y, d)
    sc[SC_NBIAS][0] = _point_bias(0.0, 0.0, 1.0, acceleration, zt)
    sc[SC_TBIAS][0] = _point_bias(1.0, 0.0, 0.0, acceleration, xt)
    sc[SC_TBIAS][1] = _point_bias(0.0, 1.0, 0.0, acceleration, yt)


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
    acceleration = centripetal(y, d)
    _point_row_at(d, 1.0, 0.0, 0.0, acceleration, 0.0, tangent, tbias, 0)
    _point_row_at(d, 0.0, 1.0, 0.0, acceleration, 0.0, tangent, tbias, 1)
    _angular_row(0.0, 0.0, centre[2], tangent, tbias, 2)


# --- the friction centre of a FACE or EDGE ---------------------------------------------------


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
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
        return edge_twist_radius(par, index, cx, cy)[0]
    return 0.0


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def edge_twist_radius(par, index, cx, cy):
    """:func:`effective_twist_radius` of EDGE ``index`` and its rate along the edge:
    (rho [m], d rho / d sigma [m]) at the centre of pressure (cx, cy), sigma its share
    from the edge's first corner. ``rho = max((L/2 - |e|) / 2, floor)``, e the offset
    from the edge's middle, so the rate is ``-sign(e) L / 2`` with L signed along the
    edge's axis, and zero where rho is floored or e is zero."""
    floor = RHO_FLOOR * par[P_HALF_X]
    ax, ay = box_corner(par, index)
    bx, by = box_corner(par, (index + 1) % 4)
    if ay == by:  # an edge along x
        half, offset, length = 0.5 * abs(bx - ax), cx - 0.5 * (ax + bx), bx - ax
    else:
        half, offset, length = 0.5 * abs(by - ay), cy - 0.5 * (ay + by), by - ay
    rho = 0.5 * (half - abs(offset))
    if not rho > floor or offset == 0.0:
        return max(rho, floor), 0.0
    return rho, -0.5 * length if offset > 0.0 else 0.5 * length


@kernel(cache=True, error_model="numpy", _nrt=False)
def reset_friction_centre(par, kind, index, centre):
    """The friction centre at the patch's geometric centre (the base centre, an edge's midpoint).

    ``centre`` (5,): x, y [m] in the body frame's base plane, rho [m], then the
    patch's kind and index (as floats), which
    :func:`~freestand.core.contact.body_solve.solve_patch` reads.
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

    A sticking POINT (a rim point rolling, a corner held), a sticking EDGE
    (all five rows held: a box rocking on it), a sticking FACE (all six held)
    and a sliding FACE (a flat base sliding) by their closed forms
    (:func:`solve_sticking_point`, :func:`solve_sticking_edge`,
    :func:`solve_sticking_face`, :func:`solve_sliding_face`), any other mode
    on its rows (:func:`solve_held_rows`; an EDGE whose tangential rows are
    not held too, as a projection of a sliding one holds its normal rows
    alone); arguments and results as the latter's.
    """
    if slip == 0 and n_normal == 1 and n_tangent == 2:
        return solve_sticking_point(par, sc, base, use_bias, acc, lam)
    if slip == 0 and n_normal == 2 and n_tangent == 3:
        return solve_sticking_edge(par, sc, base, use_bias, acc, lam)
    if slip == 0 and n_normal == 3 and n_tangent == 3:
        return solve_sticking_face(par, sc, base, use_bias, acc, lam)
    if slip == 1 and n_normal == 3:
        return solve_sliding_face(par, sc, base, use_bias, direction, acc, lam)
    return solve_held_rows(par, sc, base, use_bias, slip, direction, n_normal, n_tangent, acc,
                           lam)  # fmt: skip


@kernel(cache=True, error_model="numpy", _nrt=False)
def solve_sticking_point(par, sc, base, use_bias, acc, lam):
    """A sticking POINT's contact problem, the free solution x_0 = ``base``; False if singular.

    :func:`sticking_point_from_force` with the generalised force ``f = M
    x_0`` = (m a_0, I_w alpha_0): the same problem as :func:`solve_held_rows`
    on the point's three rows, to round-off. ``lam`` holds (N, f_x, f_y) [N,
    or N s at the velocity level].
    """
    return sticking_point_from_force(par, sc, free_force(par, sc, base), use_bias, acc, lam)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def free_force(par, sc, base):
    """f = M x_0 = (m a_0, I_w alpha_0) [N, N m; or N s, N m s] of the free solution
    x_0 = ``base``, as a 6-tuple (the closed forms' force form), at the scratch's rotation."""
    mass = par[P_MASS]
    fx, fy, fz = world_inertia_times(par, sc[SC_ROT], base[3], base[4], base[5])
    return (mass * base[0], mass * base[1], mass * base[2], fx, fy, fz)


@kernel(cache=True, error_model="numpy", _nrt=False)
def sticking_point_from_force(par, sc, force, use_bias, acc, lam):
    """A sticking POINT solved about the point (a ball joint); False if singular.

    The point's rows (:func:`patch_rows`: its arm d from G in ``sc[SC_ARMS][3]``,
    the support's z, x and y with their biases b) hold its acceleration
    ``a + alpha x d = -b`` (b zero at the velocity level, ``use_bias``
    False), so ``a = d x alpha - b``. Gauss's principle on the free solution
    x_0 = M^-1 f, ``f`` the 6-tuple (force [N], moment about G [N m]; at the
    acceleration level the applied wrench f_0), leaves the turn about the
    point:

        I_P alpha = f_m + (m b + f_a) x d,   I_P = I_w + m (|d|^2 1 - d d^T)

    (I_P the inertia about the point, Steiner's theorem; Featherstone 2008,
    Rigid Body Dynamics Algorithms, ch. 2), then ``a = d x alpha - b``
    and the contact force ``F = m a - f_a``: ``lam`` = (F_z, F_x, F_y) [N, or
    N s]. I_P is symmetric positive definite: its adjugate
    (:func:`_solve_inertia`, one division) where it is well conditioned,
    else ``L D L^T`` without pivoting
    (:func:`freestand.core.contact.engine.solve_symmetric_in_place`), and
    :func:`solve_small` only where round-off found a pivot not positive. No
    inverse inertia and no ``M^-1 f_0``: an RK4 stage of a rolling cylinder
    (its most frequent solve) gives the wrench alone
    (``body_solve.sticking_stage``).
    """
    rot, arms, matrix, rhs = sc[SC_ROT], sc[SC_ARMS], sc[SC_MATRIX], sc[SC_RHS]
    nbias, tbias = sc[SC_NBIAS], sc[SC_TBIAS]
    mass = par[P_MASS]
    d = (arms[3, 0], arms[3, 1], arms[3, 2])
    b = (tbias[0], tbias[1], nbias[0]) if use_bias else (0.0, 0.0, 0.0)
    _point_inertia(par, rot, d, matrix)
    push = (mass * b[0] + force[0], mass * b[1] + force[1], mass * b[2] + force[2])
    mx, my, mz = cross(push[0], push[1], push[2], d[0], d[1], d[2])
    rhs[0], rhs[1], rhs[2] = force[3] + mx, force[4] + my, force[5] + mz
    if not _solve_inertia(matrix, rhs) and not solve_symmetric_in_place(matrix, rhs, 3):
        _point_inertia(par, rot, d, matrix)
        rhs[0], rhs[1], rhs[2] = force[3] + mx, force[4] + my, force[5] + mz
        if not solve_small(matrix, rhs, 3):
            return False
    ax, ay, az = cross(d[0], d[1], d[2], rhs[0], rhs[1], rhs[2])
    acc[0], acc[1], acc[2] = ax - b[0], ay - b[1], az - b[2]
    acc[3], acc[4], acc[5] = rhs[0], rhs[1], rhs[2]
    lam[0] = mass * acc[2] - force[2]
    lam[1] = mass * acc[0] - force[0]
    lam[2] = mass * acc[1] - force[1]
    return True


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _solve_inertia(matrix, rhs):
    """Solve the symmetric positive definite 3 x 3 ``matrix x = rhs`` by its adjugate; x in ``rhs``.

    ``x = adj(A) rhs / det A``: one division where ``L D L^T`` took six in a
    chain (the sticking point's solve, a rolling cylinder's most frequent).
    :func:`solve_small`'s Cramer's rule, for a symmetric matrix (six
    cofactors, not nine) and under a test made for it.
    Its error grows as ``det A / (a_00 a_11 a_22)`` falls (a positive
    definite matrix's determinant is at most the product of its diagonal,
    Hadamard's bound): some ``10 u / ratio`` relative (u the unit
    round-off), 22 u at 0.1 and 135 u at 0.01, where elimination stays
    near ``u cond(A)``. False, ``rhs`` untouched, where the ratio is below
    ``ADJUGATE_CONDITION``: the caller then factors A.
    """
    a00, a01, a02 = matrix[0, 0], matrix[0, 1], matrix[0, 2]
    a11, a12, a22 = matrix[1, 1], matrix[1, 2], matrix[2, 2]
    c00 = a11 * a22 - a12 * a12
    c01 = a02 * a12 - a01 * a22
    c02 = a01 * a12 - a02 * a11
    det = a00 * c00 + a01 * c01 + a02 * c02
    if not det > ADJUGATE_CONDITION * a00 * a11 * a22:
        return False
    c11 = a00 * a22 - a02 * a02
    c12 = a01 * a02 - a00 * a12
    c22 = a00 * a11 - a01 * a01
    scale = 1.0 / det
    r0, r1, r2 = rhs[0], rhs[1], rhs[2]
    rhs[0] = (c00 * r0 + c01 * r1 + c02 * r2) * scale
    rhs[1] = (c01 * r0 + c11 * r1 + c12 * r2) * scale
    rhs[2] = (c02 * r0 + c12 * r1 + c22 * r2) * scale
    return True


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _point_inertia(par, rot, d, matrix):
    """I_P = I_w + m (|d|^2 1 - d d^T) (3, 3) [kg m^2] into ``matrix``: about the point at arm d."""
    world_inertia(par, rot, matrix)
    mass = par[P_MASS]
    size = d[0] * d[0] + d[1] * d[1] + d[2] * d[2]
    for i in range(3):
        for j in range(i, 3):
            entry = matrix[i, j] - mass * d[i] * d[j]
            if i == j:
                entry += mass * size
            matrix[i, j] = entry
            matrix[j, i] = entry


@kernel(cache=True, error_model="numpy", _nrt=False)
def solve_sticking_edge(par, sc, base, use_bias, acc, lam):
    """A sticking EDGE's contact problem, the free solution x_0 = ``base``; False if singular.

    :func:`sticking_edge_from_force` with ``f = M x_0`` = (m a_0, I_w alpha_0).
    """
    return sticking_edge_from_force(par, sc, free_force(par, sc, base), use_bias, acc, lam)


@kernel(cache=True, error_model="numpy", _nrt=False)
def sticking_edge_from_force(par, sc, force, use_bias, acc, lam):
    """A sticking EDGE's contact problem on its hinge (null-space method); False if singular.

    The EDGE's five held rows (:func:`patch_rows`) are its corners' vertical
    velocities ``w_r = (e_z, c_r)`` (r = 0, 1), its friction centre's
    horizontal ones ``(e_x, t_0)``, ``(e_y, t_1)`` and the twist ``(0,
    t_2)``, ``t_2 = rho e_z``; held, they leave one motion free, the turn
    about the edge. With x = (a, alpha) (the centre of gravity's
    acceleration, the angular one) and g_k the rows' targets (minus their
    biases ``b_k`` at the acceleration level, ``use_bias``; zero at the
    velocity level), the rows give a from alpha, and on alpha

        k . alpha = g_1 - g_0,   t_2 . alpha = g_4,   k = c_1 - c_0,

    whose least-norm solution ``alpha_p = p k + q t_2`` (the 2 x 2 Gram
    system G of k and t_2) and free direction ``n_alpha = k x t_2`` make
    ``x = x_p + s n``. Gauss's principle on the free solution x_0 = M^-1 f
    (``f`` the 6-tuple force [N] and moment about G [N m]; at the
    acceleration level the applied wrench f_0): the constraint force
    ``M x - f`` lies in the rows' span, orthogonal to n, which fixes

        s = n^T (f - M x_p) / n^T M n,   M = diag(m, m, m, I_w)

    (the null-space method: Nocedal and Wright 2006, Numerical
    Optimization, sec. 16.2), and the multipliers follow from the
    constraint force ``F = M x - f``: the friction (T_0, T_1) = (F_x,
    F_y), N_0 + N_1 = F_z, and (N_1, T_2) from the couple ``N_1 k + T_2
    t_2 = F_m - T_0 t_0 - T_1 t_1 - F_z c_0`` on G again. What
    :func:`solve_held_rows` gives on the same rows, to round-off, without
    its 5 x 5 system and without the inverse inertia: the sticking EDGE is
    a rocking box's most frequent solve. ``lam`` holds (N_0, N_1, T_0, T_1,
    T_2) [N, or N s at the velocity level]; False where G is singular (k
    parallel to t_2).
    """
    normal, tangent, rot = sc[SC_NORMAL], sc[SC_TANGENT], sc[SC_ROT]
    nbias, tbias = sc[SC_NBIAS], sc[SC_TBIAS]
    mass = par[P_MASS]
    g0, g1, g2, g3, g4 = 0.0, 0.0, 0.0, 0.0, 0.0
    if use_bias:
        g0, g1, g2, g3, g4 = -nbias[0], -nbias[1], -tbias[0], -tbias[1], -tbias[2]
    c0 = (normal[3, 0], normal[4, 0], normal[5, 0])
    t0 = (tangent[3, 0], tangent[4, 0], tangent[5, 0])
    t1 = (tangent[3, 1], tangent[4, 1], tangent[5, 1])
    t2 = (tangent[3, 2], tangent[4, 2], tangent[5, 2])
    k = (normal[3, 1] - c0[0], normal[4, 1] - c0[1], normal[5, 1] - c0[2])
    kk, kt, tt = _dot3(k, k), _dot3(k, t2), _dot3(t2, t2)
    det = kk * tt - kt * kt
    if not det > 1e-12 * kk * tt:
        return False
    h = g1 - g0
    p = (tt * h - kt * g4) / det
    q = (kk * g4 - kt * h) / det
    alpha = (p * k[0] + q * t2[0], p * k[1] + q * t2[1], p * k[2] + q * t2[2])
    n_alpha = cross(k[0], k[1], k[2], t2[0], t2[1], t2[2])
    # x_p and n: the rows' forces are e_x, e_y (centre) and e_z (corner 0)
    a_p = (g2 - _dot3(t0, alpha), g3 - _dot3(t1, alpha), g0 - _dot3(c0, alpha))
    n_a = (-_dot3(t0, n_alpha), -_dot3(t1, n_alpha), -_dot3(c0, n_alpha))
    # the residual force of x_p: f - M x_p, its moment part (f_m - I_w alpha_p)
    off_a = (force[0] - mass * a_p[0], force[1] - mass * a_p[1], force[2] - mass * a_p[2])
    inertia_p = world_inertia_times(par, rot, alpha[0], alpha[1], alpha[2])
    off_m = (force[3] - inertia_p[0], force[4] - inertia_p[1], force[5] - inertia_p[2])
    inertia_n = world_inertia_times(par, rot, n_alpha[0], n_alpha[1], n_alpha[2])
    den = mass * _dot3(n_a, n_a) + _dot3(inertia_n, n_alpha)
    if not den > 0.0:
        return False
    s = (_dot3(n_a, off_a) + _dot3(n_alpha, off_m)) / den
    for i in range(3):
        acc[i] = a_p[i] + s * n_a[i]
        acc[3 + i] = alpha[i] + s * n_alpha[i]
    # the constraint force F = M x - f: (s m n_a - off_a, s I_w n_alpha - off_m)
    f_x = s * mass * n_a[0] - off_a[0]
    f_y = s * mass * n_a[1] - off_a[1]
    f_z = s * mass * n_a[2] - off_a[2]
    couple = (s * inertia_n[0] - off_m[0] - f_x * t0[0] - f_y * t1[0] - f_z * c0[0],
              s * inertia_n[1] - off_m[1] - f_x * t0[1] - f_y * t1[1] - f_z * c0[1],
              s * inertia_n[2] - off_m[2] - f_x * t0[2] - f_y * t1[2] - f_z * c0[2])  # fmt: skip
    rk, rt = _dot3(couple, k), _dot3(couple, t2)
    n_1 = (tt * rk - kt * rt) / det
    lam[0] = f_z - n_1
    lam[1] = n_1
    lam[2] = f_x
    lam[3] = f_y
    lam[4] = (kk * rt - kt * rk) / det
    return True


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _dot3(a, b):
    """a . b of two 3-tuples."""
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


@kernel(cache=True, error_model="numpy", _nrt=False)
def solve_sticking_face(par, sc, base, use_bias, acc, lam):
    """A sticking FACE's contact problem by back substitution on its rows; False if singular.

    The FACE's six rows (:func:`patch_rows`) hold every motion: the base
    centre's vertical ``(e_z, c_0)``, the tilt rates ``(0, e_x)``, ``(0,
    e_y)``, the friction centre's horizontals ``(e_x, c_1)``, ``(e_y, c_2)``
    and the twist ``(0, rho e_z)``. With the targets g_k (minus the rows'
    biases at the acceleration level, ``use_bias``; zero at the velocity
    level) the angular part follows from the angular rows and the linear
    part from the point rows:

        alpha = (g_1, g_2, g_5 / rho),   a = (g_3, g_4, g_0) - (c_1, c_2, c_0) . alpha,

    and the multipliers from the constraint force ``F = M (x - x_0)``, x_0 =
    ``base`` (``J^T lam = F``, J the rows): the friction (T_0, T_1) = (F_x,
    F_y), N_0 = F_z, and the couples N_1, N_2 and the twist's T_2 from the
    moment ``F_m - N_0 c_0 - T_0 c_1 - T_1 c_2`` along e_x, e_y and rho e_z.
    What :func:`solve_held_rows` gives on the same rows to round-off,
    without its 6 x 6 system: the FACE is the first candidate of every
    impact of a box's edge that lands while the other edge holds
    (:func:`~freestand.core.contact.body_modes.impact`). ``lam`` holds (N_0,
    N_1, N_2, T_0, T_1, T_2) [N, N m; or N s, N m s]; False where the twist
    radius is not positive.
    """
    normal, tangent, nbias, tbias = sc[SC_NORMAL], sc[SC_TANGENT], sc[SC_NBIAS], sc[SC_TBIAS]
    rho = tangent[5, 2]
    if not rho > 0.0:
        return False
    g = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    if use_bias:
        g = (-nbias[0], -nbias[1], -nbias[2], -tbias[0], -tbias[1], -tbias[2])
    c0 = (normal[3, 0], normal[4, 0], normal[5, 0])
    c1 = (tangent[3, 0], tangent[4, 0], tangent[5, 0])
    c2 = (tangent[3, 1], tangent[4, 1], tangent[5, 1])
    alpha = (g[1], g[2], g[5] / rho)
    acc[0] = g[3] - _dot3(c1, alpha)
    acc[1] = g[4] - _dot3(c2, alpha)
    acc[2] = g[0] - _dot3(c0, alpha)
    acc[3], acc[4], acc[5] = alpha
    mass = par[P_MASS]
    f_x = mass * (acc[0] - base[0])
    f_y = mass * (acc[1] - base[1])
    f_z = mass * (acc[2] - base[2])
    mx, my, mz = world_inertia_times(par, sc[SC_ROT], alpha[0] - base[3], alpha[1] - base[4],
                                     alpha[2] - base[5])  # fmt: skip
    lam[0] = f_z
    lam[1] = mx - (f_z * c0[0] + f_x * c1[0] + f_y * c2[0])
    lam[2] = my - (f_z * c0[1] + f_x * c1[1] + f_y * c2[1])
    lam[3] = f_x
    lam[4] = f_y
    lam[5] = (mz - (f_z * c0[2] + f_x * c1[2] + f_y * c2[2])) / rho
    return True


@kernel(cache=True, error_model="numpy", _nrt=False)
def solve_sliding_face(par, sc, base, use_bias, direction, acc, lam):
    """A sliding FACE's contact problem by elimination of its normal force; False if singular.

    The FACE's normal rows (:func:`patch_rows`) are the base centre's
    vertical velocity ``w_0 = (e_z, c)``, ``c = d x e_z`` (d the base
    centre's arm, ``c_z = 0``), and the tilt rates ``w_1 = (0, e_x)``,
    ``w_2 = (0, e_y)``. Its multipliers N, M_x, M_y act through ``g_0 = w_0
    - mu sum_k u_k t_k`` (the friction ``-mu N u`` on the tangential rows
    t_k, which carry no vertical force) and ``g_1 = (0, e_x)``, ``g_2 = (0,
    e_y)``, each with its twist from the centre of pressure's offset
    (:func:`face_offset_torques`). Only g_0 has a vertical force, so the
    combination ``w_0 - c_x w_1 - c_y w_2 = (e_z, 0)`` of the held rows
    gives N alone, and the tilt rows then the couples:

        N = m (r_0 - c_x r_1 - c_y r_2),
        [(A g_1)_x (A g_2)_x; (A g_1)_y (A g_2)_y] (M_x, M_y)
            = (r_1, r_2) - N ((A g_0)_x, (A g_0)_y)

    with ``A = I_w^-1`` (the scratch's inverse inertia) on the rotational
    parts and ``r_k = -(w_k . base + b_k)`` (the biases ``b_k`` at the
    acceleration level, ``use_bias``). What :func:`solve_held_rows` gives on
    the same rows by Cramer's rule on the 3 x 3 system, to round-off, with a
    2 x 2 one (:func:`solve_small`). ``direction`` is u (u_x, u_y, u_t);
    ``acc = base + N M^-1 g_0 + M_x M^-1 g_1 + M_y M^-1 g_2``; ``lam`` holds
    (N, M_x, M_y, -mu N u) [N, N m, or N s and N m s at the velocity level].
    """
    inv, normal, nbias, tangent = sc[SC_INV], sc[SC_NORMAL], sc[SC_NBIAS], sc[SC_TANGENT]
    matrix, rhs = sc[SC_MATRIX], sc[SC_RHS]
    mu = par[P_MU_KINETIC]
    mass = par[P_MASS]
    c_x, c_y = normal[3, 0], normal[4, 0]
    r0 = -(base[2] + c_x * base[3] + c_y * base[4])
    r1 = -base[3]
    r2 = -base[4]
    if use_bias:
        r0 -= nbias[0]
        r1 -= nbias[1]
        r2 -= nbias[2]
    n = mass * (r0 - c_x * r1 - c_y * r2)
    t0, t1, t2 = face_offset_torques(sc, mu, direction)
    # g_0's force (-mu u_x, -mu u_y, 1) and couple: c minus the friction's moment, and the twist
    g3 = c_x - mu * (direction[0] * tangent[3, 0] + direction[1] * tangent[3, 1]
                     + direction[2] * tangent[3, 2])  # fmt: skip
    g4 = c_y - mu * (direction[0] * tangent[4, 0] + direction[1] * tangent[4, 1]
                     + direction[2] * tangent[4, 2])  # fmt: skip
    g5 = normal[5, 0] + t0 - mu * (direction[0] * tangent[5, 0] + direction[1] * tangent[5, 1]
                                   + direction[2] * tangent[5, 2])  # fmt: skip
    a0 = (inv[0, 0] * g3 + inv[0, 1] * g4 + inv[0, 2] * g5,
          inv[1, 0] * g3 + inv[1, 1] * g4 + inv[1, 2] * g5,
          inv[2, 0] * g3 + inv[2, 1] * g4 + inv[2, 2] * g5)  # fmt: skip
    # A g_1 and A g_2: A's columns x and y, each with the twist t1, t2 of A's column z
    a1 = (inv[0, 0] + t1 * inv[0, 2], inv[1, 0] + t1 * inv[1, 2], inv[2, 0] + t1 * inv[2, 2])
    a2 = (inv[0, 1] + t2 * inv[0, 2], inv[1, 1] + t2 * inv[1, 2], inv[2, 1] + t2 * inv[2, 2])
    matrix[0, 0], matrix[0, 1] = a1[0], a2[0]
    matrix[1, 0], matrix[1, 1] = a1[1], a2[1]
    rhs[0] = r1 - n * a0[0]
    rhs[1] = r2 - n * a0[1]
    if not solve_small(matrix, rhs, 2):
        return False
    m_x, m_y = rhs[0], rhs[1]
    inv_m = 1.0 / mass
    acc[0] = base[0] - n * mu * direction[0] * inv_m
    acc[1] = base[1] - n * mu * direction[1] * inv_m
    acc[2] = base[2] + n * inv_m
    for i in range(3):
        acc[3 + i] = base[3 + i] + n * a0[i] + m_x * a1[i] + m_y * a2[i]
    lam[0], lam[1], lam[2] = n, m_x, m_y
    for k in range(3):
        lam[3 + k] = -mu * n * direction[k]
    return True


@kernel(cache=True, error_model="numpy", _nrt=False)
def solve_held_rows(par, sc, base, use_bias, slip, direction, n_normal, n_tangent, acc, lam):
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
SC_EDGE = 19  # (3, 10) a sliding EDGE's terms of its centre's search (body_solve.edge_slide_terms);
# a sliding FACE's last centres and their centres of pressure (body_solve._slide_face)
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
SC_SHARE = 32  # (3,) a sliding EDGE's last settled centre: its index + 1 (0: none), share, slope

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
E_INTACT = 5  # row 2: 1.0 while rows 0-1 and q_r (``sc[SC_WORK][0:2]``) hold the terms


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
        ("after", "f8", 6), ("share", "f8", 3),
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
def store_lowest_rim_angle(rot, psi_stored, sc):
    """:func:`lowest_rim_angle`, its cosine and sine kept for :func:`stored_direction`.

    Tilted, they are the rotation's ``-(R_31, R_32) / sin(tilt)`` (equal to
    ``cos psi`` and ``sin psi`` to round-off), not computed again from the
    angle: a rolling cylinder stores a new angle at every step.
    """
    s = sin_tilt(rot)
    if s <= PIVOT_LEAN:
        return psi_stored
    psi = math.atan2(-rot[2, 1], -rot[2, 0])
    rim = sc[SC_RIM]
    rim[0] = 1.0
    rim[1] = psi
    rim[2] = -rot[2, 0] / s
    rim[3] = -rot[2, 1] / s
    return psi


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
    prepare_wrench(par, record, dt, t, y, sc)
    world_inverse_inertia(par, rot, inv)
    apply_inverse_mass(par, inv, f0, sc[SC_BASE])


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def prepare_wrench(par, record, dt, t, y, sc):
    """The applied wrench f_0 at ``t`` in ``sc[SC_F0]``, at the rotation ``sc`` holds
    (:func:`applied_wrench`): all a solve in force form needs of the load."""
    a_x, a_y, a_v = support_acceleration(record, dt, t)
    applied_wrench(par, y, sc[SC_ROT], a_x, a_y, a_v, sc[SC_F0])


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def scratch_rows(par, y, kind, index, cos_psi, sin_psi, sc, tangential=True):
    """The patch's rows (:func:`patch_rows`, ``tangential`` as there) in the scratch, at the
    rotation it holds.

    The friction centre starts at the patch's geometric centre
    (:func:`reset_friction_centre`). Returns (normal rows, tangential rows).
    """
    centre = sc[SC_CENTRE]
    reset_friction_centre(par, kind, index, centre)
    return patch_rows(par, y, sc, kind, index, cos_psi, sin_psi, tangential)


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
