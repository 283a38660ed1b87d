"""The friction of a flat base: its twist radius, and where a twisting slide's friction acts.

A base flat on the support slides with its friction ``-mu N u`` at the
centre of pressure c and a twist torque ``-mu N u_t rho`` about it, where u
is the direction of ``(w(c), omega_z rho(c))``, w(c) the horizontal slip
velocity of the base's material point at c, and rho(c) the twist radius of
the effective area about c (Meyerhof 1953; ``body_kernel.effective_twist_radius``).
The friction's moment about the horizontal axes through G does not depend
on where in the base plane it acts, so the centre of pressure is affine in
the friction's horizontal direction::

    p = a + mu h u_xy                                              (1)

(h the height of G above the base; a from the other loads, found from any
one solve as ``p_0 - mu h u_0``). With w(c) = w(a) + omega_z e_z x (c - a),
the consistent centre c = p is one equation in one unknown
(:func:`twisting_centre`). These functions are pure geometry on floats [m,
m/s, rad/s], for the 3-D kernel (``body_kernel``).
"""

from __future__ import annotations

import math

import numba as nb

from freestand.core.contact.regula_falsi import narrowed
from freestand.core.contact.vectors import norm2

#: most trials of :func:`twisting_centre`'s root search (Anderson-Bjorck; some 6-12 are used)
CENTRE_TRIALS = 80


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def rectangle_twist_radius(half_x: float, half_y: float) -> float:
    """Mean distance [m] from the centre of the rectangle |x| <= p, |y| <= q.

    ``(2 p q d + p^3 ln((q + d)/p) + q^3 ln((p + d)/q)) / (6 p q)``,
    ``d = sqrt(p^2 + q^2)``: the pure-twist friction torque of a uniformly
    loaded rectangle is mu N times this (Goyal, Ruina and Papadopoulos 1991).
    A side below 1e-9 of the other is a line: half its half-length.
    """
    p, q = half_x, half_y
    if p <= 0.0 and q <= 0.0:
        return 0.0
    if q <= 1e-9 * p:
        return 0.5 * p
    if p <= 1e-9 * q:
        return 0.5 * q
    d = norm2(p, q)
    integral = 2.0 * p * q * d + p**3 * math.log((q + d) / p) + q**3 * math.log((p + d) / q)
    return integral / (6.0 * p * q)


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def face_twist_radius(box, half_x, half_y, rho_face, floor, cx, cy):
    """Twist radius rho [m] of a flat base whose centre of pressure is (cx, cy) [m].

    The pressure uniform over the effective area concentric with the centre
    of pressure (Meyerhof 1953): for a box (``box`` True, half-sides
    ``half_x``, ``half_y``) the rectangle of half-sides ``b_x - |c_x|``,
    ``b_y - |c_y|``; for a disc or annulus of radius ``half_x`` the base
    shrunk about the centre by ``1 - |c|/R`` (``rho_face``: the whole base's
    rho). On a box's side the side's segment (an edge's rho, a quarter of
    its length where c is at its middle); zero at a corner and on the rim:
    floored at ``floor``. Off the base, the value at the nearest point of
    the base's boundary: rho is continuous in c everywhere, so that a centre
    of pressure off the base (a slide that is not admissible) is found as
    such by the search of :func:`twisting_centre`.
    """
    if box:
        p = max(half_x - abs(cx), 0.0)
        q = max(half_y - abs(cy), 0.0)
        return max(rectangle_twist_radius(p, q), floor)
    return max(rho_face * (1.0 - norm2(cx, cy) / half_x), floor)


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def twisting_centre(ax, ay, wx, wy, twist, omega, lever, box, half_x, half_y, rho_face, floor):
    """The consistent friction centre (cx, cy) [m] of a base sliding and twisting, from (1).

    ``(ax, ay)``: a of (1) [m]; ``(wx, wy)``: the slip velocity w(a) [m/s];
    ``omega``: omega_z [rad/s]; ``lever``: mu h [m]; the rest the base's
    shape (:func:`face_twist_radius`); all in one frame turned about the
    vertical (the body's). u is the direction of ``(w(c), omega rho(c) +
    twist)`` (``twist`` [m/s]: 0 for the slip's own direction; a constant
    added to the slip, as ``body_kernel.unit_slip`` adds its pull towards the
    stored direction, enters as a shifted w(a) and this). With c - a = k
    w(c) (k > 0) and w(c) = w(a) + omega e_z x (c - a), ``w(c) = cos(phi)
    R(phi) w(a)`` for ``tan(phi) = omega k``: c runs on the circle through a
    and the instant centre of the base's motion, ``c(phi) = a + (sin(phi) /
    omega) R(phi) w(a)``, and ``k = mu h / |(w(c), omega rho(c) + twist)|``
    becomes, with psi = |phi| in [0, pi/2],::

        g(psi) = sin(psi) sqrt(cos(psi)^2 |w(a)|^2 + (omega rho(c) + twist)^2)
                 - mu h |omega| cos(psi) = 0,

    negative at 0 and not negative at pi/2: a root bracketed, found by
    regula falsi with Anderson and Bjorck's scaling (``regula_falsi``) to the
    bracket's round-off. Without twist, ``c = a + mu h w / |(w, twist)|``.
    """
    speed = norm2(wx, wy)
    size = abs(omega)
    if lever * size <= 1e-14 * speed:  # no turn to speak of: u is w(a)'s direction
        total = norm2(speed, twist)
        if total <= 0.0:
            return ax, ay
        return ax + lever * wx / total, ay + lever * wy / total
    turn = 1.0 if omega > 0.0 else -1.0
    low, high = 0.0, 0.5 * math.pi
    g_low = -lever * size
    g_high = _centre_residual(high, ax, ay, wx, wy, twist, omega, turn, lever, box, half_x,
                              half_y, rho_face, floor)  # fmt: skip
    best, best_g = high, g_high
    side = 0
    for _ in range(CENTRE_TRIALS):
        if g_high == 0.0:
            break
        middle = low - g_low * (high - low) / (g_high - g_low)
        if not low < middle < high:
            middle = 0.5 * (low + high)
        if middle <= low or middle >= high:
            break
        g = _centre_residual(middle, ax, ay, wx, wy, twist, omega, turn, lever, box, half_x,
                             half_y, rho_face, floor)  # fmt: skip
        if abs(g) < abs(best_g):
            best, best_g = middle, g
        if g == 0.0:
            break
        low, high, g_low, g_high, side = narrowed(g > 0.0, middle, g, low, high, g_low, g_high,
                                                  side)  # fmt: skip
    return _circle_point(best, ax, ay, wx, wy, size, turn)


@nb.njit(cache=True, inline="always", error_model="numpy", _nrt=False)
def _circle_point(psi, ax, ay, wx, wy, size, turn):
    """c(psi) = a + (sin(psi) / |omega|) R(turn psi) w(a) (:func:`twisting_centre`)."""
    s, c = math.sin(psi), math.cos(psi)
    reach = s / size
    return ax + reach * (c * wx - turn * s * wy), ay + reach * (turn * s * wx + c * wy)


@nb.njit(cache=True, error_model="numpy", _nrt=False)
def _centre_residual(psi, ax, ay, wx, wy, twist, omega, turn, lever, box, half_x, half_y,
                     rho_face, floor):  # fmt: skip
    """g(psi) of :func:`twisting_centre` [m/s]."""
    size = abs(omega)
    cx, cy = _circle_point(psi, ax, ay, wx, wy, size, turn)
    rho = face_twist_radius(box, half_x, half_y, rho_face, floor, cx, cy)
    s, c = math.sin(psi), math.cos(psi)
    spin = omega * rho + twist
    return s * math.sqrt(c * c * (wx * wx + wy * wy) + spin * spin) - lever * size * c
