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
the consistent centre c = p is one equation in one unknown for the slip's
own direction (:func:`twisting_centre`); where u is pulled towards a stored
direction (``slip_law``), a problem in the plane on the same model
(:func:`model_centre`). These functions work on floats [m, m/s, rad/s] and
small arrays, for the 3-D kernel (``body_kernel``).

The model is the tuple ``(a_x, a_y, p_x, p_y, w_x, w_y, mu h)``: a, a point
p and the slip velocity w(p) there, in the body frame; the base is ``(box,
half_x, half_y, rho_face, rho_floor)`` (:func:`face_twist_radius`).
"""

from __future__ import annotations

import math

from freestand.core.contact.compiled import kernel
from freestand.core.contact.regula_falsi import narrowed
from freestand.core.contact.slip_law import pulled_unit, slip_pull
from freestand.core.contact.vectors import norm2

#: most trials of :func:`twisting_centre`'s root search (Anderson-Bjorck; some 10-15 are used)
CENTRE_TRIALS = 80
#: most Newton steps of :func:`model_newton` (each three evaluations of the model, no solve)
MODEL_ITERATIONS = 30
#: most trials of :func:`pulled_centre`'s search on the pull towards the stored direction
PULL_TRIALS = 80
#: a friction centre's settling: |F(c) - c| (a move) below this times the half-width [-]
CENTRE_TOLERANCE = 1e-12


@kernel(cache=True, error_model="numpy", _nrt=False)
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


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
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


@kernel(cache=True, error_model="numpy", _nrt=False)
def twisting_centre(ax, ay, wx, wy, twist, omega, lever, box, half_x, half_y, rho_face, floor):
    """The consistent friction centre (cx, cy) [m] of a base sliding and twisting, from (1).

    ``(ax, ay)``: a of (1) [m]; ``(wx, wy)``: the slip velocity w(a) [m/s];
    ``omega``: omega_z [rad/s]; ``lever``: mu h [m]; the rest the base's
    shape (:func:`face_twist_radius`); all in one frame turned about the
    vertical (the body's). u is the direction of ``(w(c), omega rho(c) +
    twist)`` (``twist`` [m/s]: 0 for the slip's own direction; a constant
    added to the slip, as ``body_solve.unit_slip`` adds its pull towards the
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


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _circle_point(psi, ax, ay, wx, wy, size, turn):
    """c(psi) = a + (sin(psi) / |omega|) R(turn psi) w(a) (:func:`twisting_centre`)."""
    s, c = math.sin(psi), math.cos(psi)
    reach = s / size
    return ax + reach * (c * wx - turn * s * wy), ay + reach * (turn * s * wx + c * wy)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _centre_residual(psi, ax, ay, wx, wy, twist, omega, turn, lever, box, half_x, half_y,
                     rho_face, floor):  # fmt: skip
    """g(psi) of :func:`twisting_centre` [m/s]."""
    size = abs(omega)
    cx, cy = _circle_point(psi, ax, ay, wx, wy, size, turn)
    rho = face_twist_radius(box, half_x, half_y, rho_face, floor, cx, cy)
    s, c = math.sin(psi), math.cos(psi)
    spin = omega * rho + twist
    return s * math.sqrt(c * c * (wx * wx + wy * wy) + spin * spin) - lever * size * c


@kernel(cache=True, error_model="numpy", _nrt=False)
def model_centre(model, base, rot, omega, stored, start, floor, s, u):
    """c = F(c) = a + mu h u(c) on the model; (cx, cy, settled) [m], body frame.

    u(c) is the direction of ``s(c) + beta r`` (``slip_law.pulled_unit``; r
    the stored direction ``stored[start:start + 3]``, world, ``floor`` its
    floor [m/s]). First the closed form's root for beta = 0 (the slip's own
    direction, :func:`pulled_twisting_centre`); where u is not the slip's
    own there (a slip slower than the floor, or turned against r), Newton's
    method (:func:`model_newton`) from p, then from ``a + mu h r`` (where r
    would put it); then the bracketed search on beta (:func:`pulled_centre`).
    ``rot``: the body's rotation (a turn about the vertical), ``omega``
    omega_z [rad/s]; ``s``, ``u`` (3,) work arrays. Settled where
    |F(c) - c| is below ``CENTRE_TOLERANCE`` of the half-width; else p.
    """
    ax, ay, px, py, wx, wy, lever = model
    tolerance = CENTRE_TOLERANCE * base[1]
    args = (model, base, rot, omega, stored, start, floor, s, u)
    cx, cy = pulled_twisting_centre(model, base, rot, omega, stored, start, 0.0)
    fx, fy = model_map(args, cx, cy)
    if norm2(fx - cx, fy - cy) <= tolerance:
        return cx, cy, True
    cx, cy, settled = model_newton(args, px, py)
    if settled:
        return cx, cy, True
    r_x, r_y = body_horizontal(rot, stored[start], stored[start + 1])
    cx, cy, settled = model_newton(args, ax + lever * r_x, ay + lever * r_y)
    if settled:
        return cx, cy, True
    return pulled_centre(args)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def body_horizontal(rot, x, y):
    """A world horizontal vector's body-frame (x, y), the body turned about the vertical."""
    return rot[0, 0] * x + rot[1, 0] * y, rot[0, 1] * x + rot[1, 1] * y


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _base_twist_radius(base, cx, cy):
    """:func:`face_twist_radius` of the base tuple at (cx, cy)."""
    box, half_x, half_y, rho_face, rho_floor = base
    return face_twist_radius(box, half_x, half_y, rho_face, rho_floor, cx, cy)


@kernel(cache=True, error_model="numpy", _nrt=False)
def pulled_twisting_centre(model, base, rot, omega, stored, start, beta):
    """The centre c = a + mu h u(c) for u the direction of ``s(c) + beta r`` (a fixed beta).

    A constant ``beta r`` added to the slip shifts w(a) by ``beta r_xy`` and
    the twist by ``beta r_t``: :func:`twisting_centre`'s closed form.
    """
    ax, ay, px, py, wx, wy, lever = model
    box, half_x, half_y, rho_face, rho_floor = base
    r_x, r_y = body_horizontal(rot, stored[start], stored[start + 1])
    # the slip velocity at a: w(p) + omega e_z x (a - p)
    w_x = wx - omega * (ay - py) + beta * r_x
    w_y = wy + omega * (ax - px) + beta * r_y
    return twisting_centre(ax, ay, w_x, w_y, beta * stored[start + 2], omega, lever, box, half_x,
                           half_y, rho_face, rho_floor)  # fmt: skip


@kernel(cache=True, error_model="numpy", _nrt=False)
def pulled_centre(args):
    """c = F(c) by a bracketed search on the pull beta; (cx, cy, settled) (:func:`model_centre`).

    u is the direction of ``s + beta(s) r`` (``slip_law.slip_pull``). For a
    fixed beta the centre is :func:`pulled_twisting_centre`'s; the search is
    on ``beta - beta(s(c(beta)))``, not positive at 0 and positive at ``2
    s_max + floor`` (s_max bounding |s| over the disc |c - a| <= mu h):
    regula falsi with Anderson and Bjorck's scaling, until |F(c) - c| is
    below ``CENTRE_TOLERANCE`` of the half-width, or the bracket's round-off.
    ``args``: :func:`model_centre`'s (model, base, rot, omega, stored,
    start, floor, s, u).
    """
    model, base, rot, omega, stored, start, floor, s, u = args
    ax, ay, px, py, wx, wy, lever = model
    reach = norm2(wx - omega * (ay - py), wy + omega * (ax - px)) + abs(omega) * (lever + base[3])
    low, high = 0.0, 2.0 * reach + floor
    g_low = -_pull_at(args, 0.0)[0]
    g_high = high - _pull_at(args, high)[0]
    side = 0
    tolerance = CENTRE_TOLERANCE * base[1]
    for _ in range(PULL_TRIALS):
        middle = low - g_low * (high - low) / (g_high - g_low)
        if not low < middle < high:
            middle = 0.5 * (low + high)
        if middle <= low or middle >= high:
            break
        pull, cx, cy = _pull_at(args, middle)
        fx, fy = model_map(args, cx, cy)
        if norm2(fx - cx, fy - cy) <= tolerance:
            return cx, cy, True
        g = middle - pull
        low, high, g_low, g_high, side = narrowed(g > 0.0, middle, g, low, high, g_low, g_high,
                                                  side)  # fmt: skip
    return px, py, False


@kernel(cache=True, error_model="numpy", _nrt=False)
def _pull_at(args, beta):
    """(beta(s(c)), cx, cy): the pull at the centre c of a fixed ``beta``, and c."""
    model, base, rot, omega, stored, start, floor, s, u = args
    ax, ay, px, py, wx, wy, lever = model
    cx, cy = pulled_twisting_centre(model, base, rot, omega, stored, start, beta)
    _slip_at(args, cx, cy)
    along = s[0] * stored[start] + s[1] * stored[start + 1] + s[2] * stored[start + 2]
    size = math.sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2])
    return slip_pull(along, size, floor), cx, cy


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _slip_at(args, cx, cy):
    """The slip at c into ``s`` (world): w(p) + omega e_z x (c - p) turned from the body
    frame, then omega rho(c)."""
    model, base, rot, omega, stored, start, floor, s, u = args
    ax, ay, px, py, wx, wy, lever = model
    bx, by = wx - omega * (cy - py), wy + omega * (cx - px)
    s[0] = rot[0, 0] * bx + rot[0, 1] * by
    s[1] = rot[1, 0] * bx + rot[1, 1] * by
    s[2] = omega * _base_twist_radius(base, cx, cy)


@kernel(cache=True, error_model="numpy", _nrt=False)
def model_map(args, cx, cy):
    """F(c) = a + mu h u(c) [m] (body frame); ``args`` :func:`model_centre`'s."""
    model, base, rot, omega, stored, start, floor, s, u = args
    ax, ay, px, py, wx, wy, lever = model
    _slip_at(args, cx, cy)
    pulled_unit(s, 3, stored, start, floor, u)
    u_x, u_y = body_horizontal(rot, u[0], u[1])
    return ax + lever * u_x, ay + lever * u_y


@kernel(cache=True, error_model="numpy", _nrt=False)
def model_newton(args, cx, cy):
    """c = F(c) of :func:`model_map` by Newton's method from (cx, cy); (cx, cy, settled).

    The Jacobian by forward differences (a step of 1e-7 of the half-width),
    the step halved until the residual |F(c) - c| falls (Armijo), at most
    ``MODEL_ITERATIONS`` steps; settled where the residual is below
    ``CENTRE_TOLERANCE`` of the half-width.
    """
    half = args[1][1]
    tolerance = CENTRE_TOLERANCE * half
    h = 1e-7 * half
    fx, fy = model_map(args, cx, cy)
    rx, ry = fx - cx, fy - cy
    for _ in range(MODEL_ITERATIONS):
        size = norm2(rx, ry)
        if size <= tolerance:
            return cx, cy, True
        fx, fy = model_map(args, cx + h, cy)
        j00, j10 = (fx - cx - h - rx) / h, (fy - cy - ry) / h
        fx, fy = model_map(args, cx, cy + h)
        j01, j11 = (fx - cx - rx) / h, (fy - cy - h - ry) / h
        determinant = j00 * j11 - j01 * j10
        if determinant == 0.0:
            return cx, cy, False
        dx = (j01 * ry - j11 * rx) / determinant
        dy = (j10 * rx - j00 * ry) / determinant
        t = 1.0
        while True:
            nx, ny = cx + t * dx, cy + t * dy
            fx, fy = model_map(args, nx, ny)
            qx, qy = fx - nx, fy - ny
            if norm2(qx, qy) < (1.0 - 1e-4 * t) * size or t < 1e-6:
                break
            t *= 0.5
        cx, cy, rx, ry = nx, ny, qx, qy
    return cx, cy, norm2(rx, ry) <= tolerance
