"""A box's sticking EDGE stepped in its one coordinate: the turn about the held edge.

While both corners of a base edge touch and stick, the box turns about the
line through them, fixed in space and in the body: one degree of freedom,
the angle chi of the turn from the step's start. The moment of the
applied force about that line drives it (Euler's equation about a fixed
axis; the contact forces act on the line and have no moment about it):

    I_u chi'' = u . (r(chi) x F(t)) = cos(chi) F . w - sin(chi) F . r_perp,

u the edge's unit direction, r(chi) the arm from the edge's first corner
to G turned by chi (``r_perp`` its part across u at the start, ``w = u x
r_perp``), ``F = m (-a_x, -a_y, -(g - a_v))`` the gravity and d'Alembert
force of the support's acceleration at G, and ``I_u = u^T I_w u + m
|r_perp|^2`` the moment of inertia about the line (constant: u is fixed in
the body). The gyroscopic moment ``-omega x I_w omega`` has no part along u
when omega is along u. This is the sticking EDGE's closed form
(:func:`freestand.core.contact.body_kernel.sticking_edge_from_force`)
reduced to its free motion: the same accelerations, to round-off, where
the state lies on the hinge. RK4 on (chi, chi') takes a quarter of the
work of RK4 on the 13 states with the closed form at each stage, keeps the
edge's corners where they were (no drift off the held rows for the
projection to take out) and, in a plane, is the planar engine's rocking
integrator (:mod:`freestand.core.rocking.integrator`) about the pivot. The
turns' cosines and sines are their Taylor series within a step's small
turn (``vectors.cos_sin``: five ``sincos`` of libm per step took 3-4 % of a
rocking cabinet's time).
References: Goldstein, Poole and Safko (2002), Classical Mechanics, 3rd
ed., sec. 5.5 (rotation about a fixed axis); ``docs/three-d.md``, "Time
history".
"""

from __future__ import annotations

import math

from freestand.core.contact.body_kernel import (
    P_CENTRE,
    P_GRAVITY,
    P_MASS,
    body_inertia_times,
    box_corner,
    cross,
    quaternion_product,
    quaternion_rotation,
    support_acceleration,
)
from freestand.core.contact.compiled import kernel
from freestand.core.contact.vectors import cos_sin


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _hinge_acceleration(par, record, dt, t, cos_turn, sin_turn, fw_unit, fr_unit):
    """chi'' [rad/s^2] at t and a turn of (cos, sin) chi: the module's equation.

    ``fw_unit`` and ``fr_unit`` are ``w / I_u`` and ``r_perp / I_u``: F . w /
    I_u with ``F = m (-a_x, -a_y, -(g - a_v))``.
    """
    a_x, a_y, a_v = support_acceleration(record, dt, t)
    m = par[P_MASS]
    fx, fy, fz = -m * a_x, -m * a_y, -m * (par[P_GRAVITY] - a_v)
    along_w = fx * fw_unit[0] + fy * fw_unit[1] + fz * fw_unit[2]
    along_r = fx * fr_unit[0] + fy * fr_unit[1] + fz * fr_unit[2]
    return cos_turn * along_w - sin_turn * along_r


@kernel(cache=True, error_model="numpy", _nrt=False)
def hinge_rk4(par, record, dt, t, h, y, index, out):
    """One RK4 step over h from (t, y) of a box turning about its base edge ``index``.

    The edge joins the base corners ``index`` and ``index + 1`` (mod 4),
    which stay where they are at (t, y); RK4 on (chi, chi') of the
    module's equation, chi' starting at ``u . omega``; ``out`` gets the
    state at t + h: G turned about the edge, the quaternion turned by chi
    about u (``q = (cos chi/2, sin chi/2 u) q_0``, normalised), ``omega
    = chi' u`` and ``v = omega x r``. Returns True (the equation has no
    singular case: I_u > 0).
    """
    r00, r01, r02, r10, r11, r12, r20, r21, r22 = quaternion_rotation(y[3], y[4], y[5], y[6])
    cx, cy, cz = par[P_CENTRE], par[P_CENTRE + 1], par[P_CENTRE + 2]
    sx, sy = box_corner(par, index)
    ex, ey = box_corner(par, (index + 1) % 4)
    # the first corner's arm from G, d_a = R (s_a - c), and the edge's direction R (s_b - s_a)
    px, py, pz = sx - cx, sy - cy, -cz
    dax = r00 * px + r01 * py + r02 * pz
    day = r10 * px + r11 * py + r12 * pz
    daz = r20 * px + r21 * py + r22 * pz
    bx, by = ex - sx, ey - sy
    length = math.sqrt(bx * bx + by * by)
    ux = (r00 * bx + r01 * by) / length
    uy = (r10 * bx + r11 * by) / length
    uz = (r20 * bx + r21 * by) / length
    # the arm from the edge to G, its part along u and across it, and w = u x r_perp
    along = -(dax * ux + day * uy + daz * uz)
    qx, qy, qz = -dax - along * ux, -day - along * uy, -daz - along * uz
    wx, wy, wz = cross(ux, uy, uz, qx, qy, qz)
    # I_u = b^T I b + m |r_perp|^2, b = R^T u the edge's direction in the body frame
    bu0 = r00 * ux + r10 * uy + r20 * uz
    bu1 = r01 * ux + r11 * uy + r21 * uz
    bu2 = r02 * ux + r12 * uy + r22 * uz
    hu0, hu1, hu2 = body_inertia_times(par, bu0, bu1, bu2)
    inertia = bu0 * hu0 + bu1 * hu1 + bu2 * hu2 + par[P_MASS] * (qx * qx + qy * qy + qz * qz)
    fw = (wx / inertia, wy / inertia, wz / inertia)
    fr = (qx / inertia, qy / inertia, qz / inertia)
    turn, rate = _hinge_steps(par, record, dt, t, h, y[10] * ux + y[11] * uy + y[12] * uz, fw, fr)
    _hinge_state(y, turn, rate, ux, uy, uz, dax, day, daz, along, qx, qy, qz, wx, wy, wz, out)
    return True


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _hinge_steps(par, record, dt, t, h, rate, fw, fr):
    """RK4's four stages on (chi, chi') from (0, ``rate``) over h: (chi, chi') at t + h."""
    k1 = _hinge_acceleration(par, record, dt, t, 1.0, 0.0, fw, fr)
    half = 0.5 * h
    turn2 = half * rate
    rate2 = rate + half * k1
    cos2, sin2 = cos_sin(turn2)
    k2 = _hinge_acceleration(par, record, dt, t + half, cos2, sin2, fw, fr)
    turn3 = half * rate2
    rate3 = rate + half * k2
    cos3, sin3 = cos_sin(turn3)
    k3 = _hinge_acceleration(par, record, dt, t + half, cos3, sin3, fw, fr)
    turn4 = h * rate3
    rate4 = rate + h * k3
    cos4, sin4 = cos_sin(turn4)
    k4 = _hinge_acceleration(par, record, dt, t + h, cos4, sin4, fw, fr)
    turn = h / 6.0 * (rate + 2.0 * rate2 + 2.0 * rate3 + rate4)
    return turn, rate + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _hinge_state(y, turn, rate, ux, uy, uz, dax, day, daz, along, qx, qy, qz, wx, wy, wz, out):
    """The state turned by ``turn`` [rad] about the edge, at the angular rate ``rate`` [rad/s].

    G = P + r(chi), P = G_0 + d_a the edge's first corner and ``r(chi) =
    along u + cos(chi) r_perp + sin(chi) w``; the quaternion turned on
    the left (the support's frame); ``omega = rate u``, ``v = omega x r``.
    """
    c, s = cos_sin(turn)
    rx = along * ux + c * qx + s * wx
    ry = along * uy + c * qy + s * wy
    rz = along * uz + c * qz + s * wz
    out[0] = y[0] + dax + rx
    out[1] = y[1] + day + ry
    out[2] = y[2] + daz + rz
    ch, sh = cos_sin(0.5 * turn)
    q0, q1, q2, q3 = quaternion_product(ch, sh * ux, sh * uy, sh * uz, y[3], y[4], y[5], y[6])
    size = math.sqrt(q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
    out[3], out[4], out[5], out[6] = q0 / size, q1 / size, q2 / size, q3 / size
    ox, oy, oz = rate * ux, rate * uy, rate * uz
    out[7], out[8], out[9] = cross(ox, oy, oz, rx, ry, rz)
    out[10], out[11], out[12] = ox, oy, oz
