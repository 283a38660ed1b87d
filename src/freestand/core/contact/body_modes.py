"""The choice of the contact mode of one body, and its impact law (compiled).

One enumeration serves both levels, as the planar kernel
(:mod:`freestand.core.contact.engine`) does for stacks:

- **acceleration level** (a state): the candidates are the patches whose
  points all touch (gap within ``gap_tol``, gap velocity within
  ``velocity_tol``), then FREE; each with its tangential state (stick while
  the slip velocity is within ``velocity_tol``; then slip, kinetic along the
  slip velocity, or starting from rest in the direction of the fixed point
  ``u = s'(u) / |s'(u)|``, the slip acceleration under the friction it
  produces). A candidate is admissible when its normal forces are
  compressive (a FACE's centre of pressure inside the base), its sticking
  friction inside the static cone or limit surface, and every touching point
  it does not hold accelerates away. Choice rule: static friction holds
  where it can, then the most closed patch (FACE, EDGE, POINT, FREE).
- **velocity level** (an impact): the same candidates among the touching
  points, impulses instead of forces, velocities after the impact instead of
  accelerations: plastic at the patch's points (their normal velocity after
  is zero), every other touching point separates, the tangential impulse
  sticks inside the static cone or slides with the kinetic one. An impulse at
  one point conserves the angular momentum about it; in a plane this is
  Housner's law (1963).

A cylinder's flat base offers FACE and POINT about one rim point: at a state,
the rim point the base is turning about (its normal velocity the smallest)
or, from rest, the point towards which the FACE's centre of pressure left the
base; after a landing, the rim point about which the body turns after the
impact (its angular velocity after has no radial component there, found by
a 1-D root search started opposite the point it landed from).
"""

from __future__ import annotations

import math

from freestand.core.contact.body_kernel import (
    D_ONSET,
    D_PSI,
    D_SLIP,
    E_INTACT,
    EDGE,
    FACE,
    FREE,
    M_INDEX,
    M_KIND,
    M_SLIP,
    MAX_CANDIDATES,
    P_GRAVITY,
    P_HALF_X,
    P_MASS,
    P_MU_KINETIC,
    P_SHAPE,
    POINT,
    SC_ACC,
    SC_ANGLES,
    SC_BASE,
    SC_CENTRE,
    SC_DIR,
    SC_EDGE,
    SC_EXCLUDED,
    SC_INDICES,
    SC_INV,
    SC_JACOBIAN,
    SC_KINDS,
    SC_LAM,
    SC_NBIAS,
    SC_NORMAL,
    SC_ONSET,
    SC_POINTS,
    SC_ROT,
    SC_SACC,
    SC_START,
    SC_STORED,
    SC_SVEL,
    SC_TANGENT,
    SC_TBIAS,
    SC_TOUCHING,
    SC_WORK,
    SHAPE_BOX,
    apply_inverse_mass,
    arm,
    corner_gap,
    cross,
    friction_margin,
    normal_margin,
    prepare,
    rim_contact,
    scratch_rows,
    sin_tilt,
    tangential_velocity,
)
from freestand.core.contact.body_solve import slide_edge_on_terms, solve_patch, unit_slip
from freestand.core.contact.body_stick_bounds import stick_impact_excluded
from freestand.core.contact.compiled import kernel
from freestand.core.contact.regula_falsi import narrowed, retained_scale
from freestand.core.contact.slip_law import SLIP_FLOOR
from freestand.core.contact.vectors import leading_length

ACCELERATION = 0
VELOCITY = 1
RELATIVE_TOLERANCE = 1e-9
ONSET_ITERATIONS = 20  # fixed-point iterations before the fallbacks
ONSET_SCAN = 72  # directions sampled on the circle (a point's slip onset)
ONSET_NEWTON = 30  # Newton iterations from the fixed point's start
ONSET_HALVINGS = 12  # step halvings before Newton is taken to have stalled
KINETIC_PASSES = 3  # solves of a kinetic slip, its stored direction the last one's own slip
PIVOT_ITERATIONS = 60  # regula falsi steps of a landed cylinder's pivot search at most

NONE_ADMISSIBLE = -1
SLIPS_FROM_REST = -2  # a chatter's look (:func:`chatter_look`): a patch could only slip from rest


@kernel(cache=True, error_model="numpy", _nrt=False)
def _row_rate(rows, bias, k, x, use_bias):
    total = bias[k] if use_bias else 0.0
    for i in range(6):
        total += rows[i, k] * x[i]
    return total


@kernel(cache=True, error_model="numpy", _nrt=False)
def _point_normal_rate(y, d, x, level):
    """Normal acceleration (level 0) or velocity after (level 1) of the point at arm d."""
    if level == VELOCITY:
        cx, cy, cz = cross(x[3], x[4], x[5], d[0], d[1], d[2])
        return x[2] + cz
    wx, wy, wz = y[10], y[11], y[12]
    ux, uy, uz = cross(wx, wy, wz, d[0], d[1], d[2])
    _, _, cz = cross(wx, wy, wz, ux, uy, uz)
    _, _, az = cross(x[3], x[4], x[5], d[0], d[1], d[2])
    return x[2] + az + cz


@kernel(cache=True, error_model="numpy", _nrt=False)
def _others_separate(par, y, sc, kind, index, psi, touching, level, tolerance):
    """True when every touching point the patch does not hold moves away (>= -tolerance)."""
    rot = sc[SC_ROT]
    x = sc[SC_ACC]
    d = sc[SC_POINTS][1]
    if par[P_SHAPE] == SHAPE_BOX:
        for k in range(4):
            if not touching[k]:
                continue
            if kind == FACE or (kind == POINT and index == k):
                continue
            if kind == EDGE and (k == index or k == (index + 1) % 4):
                continue
            corner_gap(par, y, rot, k, d)
            if _point_normal_rate(y, d, x, level) < -tolerance:
                return False
        return True
    if kind == POINT and touching[0]:
        radius = par[P_HALF_X]
        for step in (1, 2, 3):
            angle = psi + 0.5 * math.pi * step
            arm(par, rot, radius * math.cos(angle), radius * math.sin(angle), 0.0, d)
            if _point_normal_rate(y, d, x, level) < -tolerance:
                return False
    if kind == FREE:
        if touching[0]:
            # a flat base may not be left to fall through the support
            radius = par[P_HALF_X]
            for k in range(4):
                angle = 0.5 * math.pi * k
                arm(par, rot, radius * math.cos(angle), radius * math.sin(angle), 0.0, d)
                if _point_normal_rate(y, d, x, level) < -tolerance:
                    return False
        if touching[4]:
            # the touching rim point (psi from touching_points)
            radius = par[P_HALF_X]
            arm(par, rot, radius * math.cos(psi), radius * math.sin(psi), 0.0, d)
            if _point_normal_rate(y, d, x, level) < -tolerance:
                return False
    return True


@kernel(cache=True, error_model="numpy", _nrt=False)
def _solve(par, y, sc, level, slip, direction, n_normal, n_tangent):
    """The mode on the scratch's rows, sliding along ``direction`` (friction about the CoP)."""
    return solve_patch(par, y, sc, level == ACCELERATION, slip, direction, False, sc[SC_CENTRE],
                       n_normal, n_tangent, False)  # fmt: skip


@kernel(cache=True, error_model="numpy", _nrt=False)
def _tangential_rate(sc, n_tangent, level, out):
    """Slip acceleration (level 0) or slip velocity after (level 1) of the tangential rows."""
    size = 0.0
    for k in range(n_tangent):
        out[k] = _row_rate(sc[SC_TANGENT], sc[SC_TBIAS], k, sc[SC_ACC], level == ACCELERATION)
        size += out[k] ** 2
    return math.sqrt(size)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _onset_rate(par, y, sc, level, n_normal, n_tangent, direction, reuse_terms):
    """Slip rate under the kinetic friction along ``-direction``: (along, across, size).

    ``along`` is its component along the direction, ``across`` the length of
    the rest, ``size`` its length; ``size`` is -1 when the mode's system is
    singular. The rate itself is left in ``sc[SC_SACC]``. ``reuse_terms``: an
    EDGE's solve on the terms of its centre's search that the solve before it
    on the same rows left (``body_solve.slide_edge_on_terms``; the same
    solution to the last bit), where they are intact; else computed anew.
    """
    rate = sc[SC_SACC]
    if reuse_terms and n_normal == 2 and sc[SC_EDGE][2, E_INTACT] == 1.0:
        centre = sc[SC_CENTRE]
        centre[5] = 0.0  # as solve_patch
        ok = slide_edge_on_terms(par, y, sc, level == ACCELERATION, direction, False, centre,
                                 n_normal, n_tangent)  # fmt: skip
    else:
        ok = _solve(par, y, sc, level, 1, direction, n_normal, n_tangent)
    if not ok:
        return 0.0, 0.0, -1.0
    size = _tangential_rate(sc, n_tangent, level, rate)
    along = 0.0
    for k in range(n_tangent):
        along += rate[k] * direction[k]
    across = 0.0
    for k in range(n_tangent):
        across += (rate[k] - along * direction[k]) ** 2
    return along, math.sqrt(across), size


@kernel(cache=True, error_model="numpy", _nrt=False)
def _onset_consistent(along, across, size, rate_tol):
    return size >= 0.0 and across <= rate_tol + 1e-10 * size and along >= -rate_tol


@kernel(cache=True, error_model="numpy", _nrt=False)
def _point_fixed_point(par, y, sc, level, n_normal, direction, rate_tol):
    """A point's fixed-point iteration ``u <- s'(u) / |s'(u)|`` from ``direction``, on the
    closed form (:func:`point_slip_terms`, in the scratch); 1 where it settles on a
    consistent onset (then confirmed by a solve, which the scratch holds), -1 where
    D(u) = 0 (singular), else 0.

    The iteration of :func:`_slip_onset`, at no solve: its 20 solves were
    most of a point's failed onset at an impact once the scan was closed too.
    """
    terms = sc[SC_ONSET]
    mu = par[P_MU_KINETIC]
    for _ in range(ONSET_ITERATIONS):
        rx, ry = point_slip_rate(terms, mu, direction[0], direction[1])
        if not math.isfinite(rx):
            return -1
        size = math.hypot(rx, ry)
        along = rx * direction[0] + ry * direction[1]
        across = abs(ry * direction[0] - rx * direction[1])
        if _onset_consistent(along, across, size, rate_tol):
            along, across, size = _onset_rate(par, y, sc, level, n_normal, 2, direction, False)
            return 1 if _onset_consistent(along, across, size, rate_tol) else 0
        if size == 0.0:
            return 0
        direction[0] = rx / size
        direction[1] = ry / size
    return 0


@kernel(cache=True, error_model="numpy", _nrt=False)
def _onset_on_circle(par, y, sc, level, n_normal, start, direction, rate_tol):
    """Two tangential rows (a point): the onset angle by a scan and regula falsi.

    f(theta) = u_perp . s'(u), u = (cos theta, sin theta), changes sign at every
    direction the slip rate is parallel to; of those where it points along u
    (kappa >= 0, confirmed by a solve), the one nearest ``start`` is
    returned. f is the closed form of :func:`point_slip_terms` (no solve):
    the 73 solves of the scan and the some 8 of each root took 170-230 of
    the 550-610 solves of a sliding, rocking cabinet's impact at which no
    candidate of the impact law was admissible (two touching corners). The
    terms must be in the scratch.
    """
    mu = par[P_MU_KINETIC]
    theta0 = math.atan2(start[1], start[0])
    best = -1.0
    best_theta = 0.0
    previous = 0.0
    for i in range(ONSET_SCAN + 1):
        theta = theta0 + 2.0 * math.pi * i / ONSET_SCAN
        value = point_slip_sign(sc[SC_ONSET], mu, theta)
        if i > 0 and value * previous <= 0.0:
            root = _onset_root(sc[SC_ONSET], mu, theta - 2.0 * math.pi / ONSET_SCAN, theta,
                               previous, value)  # fmt: skip
            direction[0] = math.cos(root)
            direction[1] = math.sin(root)
            along, across, size = _onset_rate(par, y, sc, level, n_normal, 2, direction, False)
            distance = abs(math.atan2(math.sin(root - theta0), math.cos(root - theta0)))
            if _onset_consistent(along, across, size, rate_tol) and (best < 0.0 or distance < best):
                best = distance
                best_theta = root
        previous = value
    if best < 0.0:
        return False
    direction[0] = math.cos(best_theta)
    direction[1] = math.sin(best_theta)
    along, across, size = _onset_rate(par, y, sc, level, n_normal, 2, direction, False)
    return True


@kernel(cache=True, error_model="numpy", _nrt=False)
def point_slip_terms(par, sc, level):
    """A POINT's slip rate as a closed function of its friction's direction, in ``sc[SC_ONSET]``.

    On the point's rows J (normal n, tangential x and y; the scratch's), with
    the Delassus matrix W = J M^-1 J^T [1/kg] (``docs/nomenclature.md``;
    Acary and Brogliato 2008, Numerical Methods for Nonsmooth Dynamical
    Systems, ch. 5) and b the rows' rates without the contact (``J base``
    plus the biases at the acceleration level [m/s^2]; ``J v^-`` at the
    velocity level [m/s]),
    the kinetic friction ``-mu N u`` and the held normal row give
    ``N(u) = -b_n / D(u)``, ``D(u) = W_nn - mu W_nt . u``, and the slip rate
    (acceleration, or velocity after)

        s'(u) = b_t + N(u) (W_tn - mu W_tt u) = (c + K u) / D(u),

    ``c = W_nn b_t - b_n W_tn``, ``K u = mu (b_n W_tt u - (W_nt . u) b_t)``:
    what :func:`_onset_rate`'s solve gives (:func:`~freestand.core.contact.body_kernel.solve_mode`,
    one held row), to round-off. Rows of ``sc[SC_ONSET]``: (c_x, c_y, W_nn),
    (K_00, K_01, W_nt,x), (K_10, K_11, W_nt,y).
    """
    normal, nbias, tangent, tbias = sc[SC_NORMAL], sc[SC_NBIAS], sc[SC_TANGENT], sc[SC_TBIAS]
    inv, base, work = sc[SC_INV], sc[SC_BASE], sc[SC_WORK]
    # q_r = M^-1 w_r in rows 0-2 of the solve's work array (free between solves), w_r in 3-5
    q = work[0:3]
    for r in range(3):
        rows, column = (normal, 0) if r == 0 else (tangent, r - 1)
        for i in range(6):
            work[3 + r, i] = rows[i, column]
        apply_inverse_mass(par, inv, work[3 + r], q[r])
    use_bias = level == ACCELERATION
    b_n = _row_rate(normal, nbias, 0, base, False) + (nbias[0] if use_bias else 0.0)
    b_x = _row_rate(tangent, tbias, 0, base, False) + (tbias[0] if use_bias else 0.0)
    b_y = _row_rate(tangent, tbias, 1, base, False) + (tbias[1] if use_bias else 0.0)
    # W_rs = w_r . q_s, the rows' responses to each other's unit multipliers
    w_nn = _row_rate(normal, nbias, 0, q[0], False)
    w_nx = _row_rate(normal, nbias, 0, q[1], False)
    w_ny = _row_rate(normal, nbias, 0, q[2], False)
    w_xn = _row_rate(tangent, tbias, 0, q[0], False)
    w_yn = _row_rate(tangent, tbias, 1, q[0], False)
    w_xx = _row_rate(tangent, tbias, 0, q[1], False)
    w_xy = _row_rate(tangent, tbias, 0, q[2], False)
    w_yx = _row_rate(tangent, tbias, 1, q[1], False)
    w_yy = _row_rate(tangent, tbias, 1, q[2], False)
    mu = par[P_MU_KINETIC]
    terms = sc[SC_ONSET]
    terms[0, 0] = w_nn * b_x - b_n * w_xn
    terms[0, 1] = w_nn * b_y - b_n * w_yn
    terms[0, 2] = w_nn
    terms[1, 0] = mu * (b_n * w_xx - w_nx * b_x)
    terms[1, 1] = mu * (b_n * w_xy - w_ny * b_x)
    terms[1, 2] = w_nx
    terms[2, 0] = mu * (b_n * w_yx - w_nx * b_y)
    terms[2, 1] = mu * (b_n * w_yy - w_ny * b_y)
    terms[2, 2] = w_ny


@kernel(cache=True, error_model="numpy", _nrt=False)
def point_slip_rate(terms, mu, ux, uy):
    """s'(u) = (c + K u) / D(u) of :func:`point_slip_terms` (``terms``) at the unit (ux, uy);
    NaN where D(u) = 0 (the mode's system singular)."""
    d = terms[0, 2] - mu * (terms[1, 2] * ux + terms[2, 2] * uy)
    if d == 0.0:
        return math.nan, math.nan
    rx = terms[0, 0] + terms[1, 0] * ux + terms[1, 1] * uy
    ry = terms[0, 1] + terms[2, 0] * ux + terms[2, 1] * uy
    return rx / d, ry / d


@kernel(cache=True, error_model="numpy", _nrt=False)
def point_slip_sign(terms, mu, theta):
    """f(theta) = u_perp . s'(u) of :func:`point_slip_terms` (``terms``); NaN where D(u) = 0."""
    ux, uy = math.cos(theta), math.sin(theta)
    rx, ry = point_slip_rate(terms, mu, ux, uy)
    return ux * ry - uy * rx


@kernel(cache=True, error_model="numpy", _nrt=False)
def _onset_root(terms, mu, low, high, f_low, f_high):
    """The root of :func:`point_slip_sign` in [low, high] (its values there f_low, f_high, of
    opposite signs or zero) to 1e-14 rad.

    Regula falsi, Anderson and Bjorck's variant (BIT 12, 1972: the retained
    end's value scaled by ``1 - f_new / f_old``, else halved), bisecting
    where a value is not finite (D(u) = 0, a singular system); some 8
    evaluations per root where bisection took 47.
    """
    if f_low == 0.0:
        return low
    if f_high == 0.0:
        return high
    side = 0
    for _ in range(60):
        if high - low < 1e-14:
            break
        middle = 0.5 * (low + high)
        if math.isfinite(f_low) and math.isfinite(f_high) and f_low != f_high:
            middle = min(max(low - f_low * (high - low) / (f_high - f_low), low), high)
        if not low < middle < high:
            middle = 0.5 * (low + high)
        f_mid = point_slip_sign(terms, mu, middle)
        if f_mid == 0.0:
            return middle
        if f_mid * f_low < 0.0:
            if side == -1:
                f_low *= retained_scale(f_mid, f_high)
            side = -1
            high, f_high = middle, f_mid
        else:
            if side == 1:
                f_high *= retained_scale(f_mid, f_low)
            side = 1
            low, f_low = middle, f_mid
    return 0.5 * (low + high)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _tangent_basis(u, e1, e2):
    """Two unit vectors completing the unit 3-vector ``u`` to an orthonormal basis."""
    ax, ay, az = (1.0, 0.0, 0.0) if abs(u[0]) < 0.9 else (0.0, 1.0, 0.0)
    dot = ax * u[0] + ay * u[1] + az * u[2]
    e1[0], e1[1], e1[2] = ax - dot * u[0], ay - dot * u[1], az - dot * u[2]
    size = math.sqrt(e1[0] ** 2 + e1[1] ** 2 + e1[2] ** 2)
    for k in range(3):
        e1[k] /= size
    e2[0], e2[1], e2[2] = cross(u[0], u[1], u[2], e1[0], e1[1], e1[2])


@kernel(cache=True, error_model="numpy", _nrt=False)
def _onset_newton(par, y, sc, level, n_normal, direction, rate_tol, iterations):
    """Three tangential rows: Newton on the slip rate's misfit to u, from ``direction``.

    u(a, b) = normalise(u + a e1 + b e2) with (e1, e2) across u; the residual
    ``g(a, b) = (e1 . m, e2 . m)`` of the misfit ``m = s' - |s'| u`` (s' the
    slip rate at u(a, b), :func:`_misfit`; zero exactly where the onset is
    consistent, ``s' = kappa u`` with kappa >= 0) is driven to zero with a
    finite-difference Jacobian and step halving on ``|m|``, at most
    ``iterations`` steps; where ``ONSET_HALVINGS`` halvings find no smaller
    misfit Newton has stalled (the next iteration would start from the same
    u: such stalls went on for all 30 iterations, 430 solves, where no
    consistent onset exists). True when consistent (``direction`` holds u).

    At the iterate g is the rate's part across u, and near a consistent
    onset the Jacobian is that of the part across u of the rate at u(a, b)
    itself: Newton converges quadratically. Near a u where the rate points
    against it (``kappa < 0``: the friction would drive the slip it opposes)
    the step is ``(kappa - |s'|) J^-1`` times the distance, and ``|m| = 2
    |s'|`` is largest there: the search leaves it. Where it stalls with the
    rate against u, or stands where ``s' = kappa u`` with kappa < 0, it takes
    the fixed point's step ``u = s' / |s'|`` (:func:`_rate_direction`).

    The components of s' itself along e1, e2 (this engine until 2026-12-07)
    left out the turn of the projection with u: Newton converged only
    linearly, by ``kappa / J`` a step, 0.5 to 0.6 where the slip's rate was
    comparable to its Jacobian, and ran out of its iterations short of
    onsets that exist: 505 of 804 Newton searches failed over 300 random
    bodies under the benchmark's records (``robust_case``), 9 of 579 now, and
    the chatter's remedy stood in 342 times, 183 now.
    """
    onset = sc[SC_ONSET]
    e1, e2, trial = onset[0], onset[1], onset[2]
    jac = sc[SC_JACOBIAN]
    for _ in range(iterations):
        along, across, size = _onset_rate(par, y, sc, level, n_normal, 3, direction, True)
        if size < 0.0:
            return False
        if _onset_consistent(along, across, size, rate_tol):
            return True
        _tangent_basis(direction, e1, e2)
        r1, r2 = _misfit(sc, e1, e2, direction, size)  # s' . e_j at u itself
        if _onset_consistent(-along, across, size, rate_tol):
            _rate_direction(direction, e1, e2, along, r1, r2, size)  # s' = kappa u, kappa < 0
            continue
        misfit = math.hypot(across, size - along)  # |m|
        h = 1e-7
        for j in range(2):
            for k in range(3):
                trial[k] = direction[k] + h * (e1[k] if j == 0 else e2[k])
            _normalise3(trial)
            _, _, size_trial = _onset_rate(par, y, sc, level, n_normal, 3, trial, True)
            f1, f2 = _misfit(sc, e1, e2, trial, size_trial)
            jac[0, j] = (f1 - r1) / h
            jac[1, j] = (f2 - r2) / h
        det = jac[0, 0] * jac[1, 1] - jac[0, 1] * jac[1, 0]
        if det == 0.0 or not math.isfinite(det):
            return False
        da = -(jac[1, 1] * r1 - jac[0, 1] * r2) / det
        db = -(-jac[1, 0] * r1 + jac[0, 0] * r2) / det
        factor = 1.0
        decreased = False
        for _ in range(ONSET_HALVINGS):
            for k in range(3):
                trial[k] = direction[k] + factor * (da * e1[k] + db * e2[k])
            _normalise3(trial)
            along_trial, across_trial, size_trial = _onset_rate(par, y, sc, level, n_normal, 3,
                                                                trial, True)  # fmt: skip
            if math.hypot(across_trial, size_trial - along_trial) < misfit:
                decreased = True
                break
            factor *= 0.5
        if decreased:
            for k in range(3):
                direction[k] = trial[k]
        elif along < 0.0:  # stalled where the rate points against u
            _rate_direction(direction, e1, e2, along, r1, r2, size)
        else:
            break  # stalled: no step along Newton's direction lowers the misfit
    along, across, size = _onset_rate(par, y, sc, level, n_normal, 3, direction, True)
    return _onset_consistent(along, across, size, rate_tol)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _misfit(sc, e1, e2, u, size):
    """``(e1 . m, e2 . m)``, ``m = s' - |s'| u`` the slip rate's misfit to u (``size = |s'|``;
    s' in ``sc[SC_SACC]``), on the fixed e1, e2 of a Newton iteration (:func:`_onset_newton`)."""
    rate = sc[SC_SACC]
    f1 = rate[0] * e1[0] + rate[1] * e1[1] + rate[2] * e1[2]
    f2 = rate[0] * e2[0] + rate[1] * e2[1] + rate[2] * e2[2]
    return (f1 - size * (u[0] * e1[0] + u[1] * e1[1] + u[2] * e1[2]),
            f2 - size * (u[0] * e2[0] + u[1] * e2[1] + u[2] * e2[2]))  # fmt: skip


@kernel(cache=True, error_model="numpy", _nrt=False)
def _rate_direction(u, e1, e2, along, r1, r2, size):
    """u <- s' / |s'|, the fixed point's step, from s' = along u + r1 e1 + r2 e2 (|s'| = size)."""
    for k in range(3):
        u[k] = (along * u[k] + r1 * e1[k] + r2 * e2[k]) / size


@kernel(cache=True, error_model="numpy", _nrt=False)
def _normalise3(u):
    size = math.sqrt(u[0] ** 2 + u[1] ** 2 + u[2] ** 2)
    for k in range(3):
        u[k] /= size


@kernel(cache=True, error_model="numpy", _nrt=False)
def _slip_onset(par, y, sc, level, n_normal, n_tangent, start, direction, rate_tol):
    """Direction u of a slip starting from rest; True when consistent.

    The slip acceleration under the friction ``-mu N u`` it produces must lie
    along u: ``s'(u) = kappa u`` with ``kappa >= 0`` (within ``rate_tol``;
    kappa is near zero at the very onset). First the fixed-point iteration
    ``u <- s'(u)/|s'(u)|`` from ``start`` (the sticking friction reversed);
    where it does not settle (it can cycle), a point's angle by a scan and
    bisection, an edge's or face's u (with twist) by Newton from ``start``
    (:func:`_onset_newton`). Where Newton fails the candidate is not
    admissible. A further Newton search from the best of 128 directions
    sampled on the sphere (this engine until 2026-12-01) never found an
    onset where this one had not: 0 of 483 searches over 630 runs of random
    bodies, the strong records and the 3-D benchmark's campaign, at the
    acceleration and the velocity level; it took about a quarter of the
    rocking cabinet's compiled loop, some 1,000 solves for each failed onset
    of a face at an impact.
    """
    rate = sc[SC_SACC]
    for k in range(n_tangent):
        direction[k] = start[k]
    if n_tangent == 2:
        point_slip_terms(par, sc, level)
        settled = _point_fixed_point(par, y, sc, level, n_normal, direction, rate_tol)
        if settled != 0:
            return settled > 0
        return _onset_on_circle(par, y, sc, level, n_normal, start, direction, rate_tol)
    for i in range(ONSET_ITERATIONS):
        along, across, size = _onset_rate(par, y, sc, level, n_normal, n_tangent, direction, i > 0)
        if size < 0.0:
            return False
        if _onset_consistent(along, across, size, rate_tol):
            return True
        if size == 0.0:
            break
        for k in range(n_tangent):
            direction[k] = rate[k] / size
    return _onset_newton(par, y, sc, level, n_normal, _restart(start, direction), rate_tol,
                         ONSET_NEWTON)  # fmt: skip


@kernel(cache=True, error_model="numpy", _nrt=False)
def _restore_own_slip(sc, n_tangent, stored):
    """Whether a kinetic solve's friction was pulled off its own slip at its centre; if so,
    the slip's direction there becomes the stored one (``stored[D_SLIP:]``), to solve again.

    The slip law (``body_solve.unit_slip``) gives u along the slip velocity s
    at the centre found (``sc[SC_SVEL]``, as the solve left it) while s points
    on the stored direction r's side, and else pulls it towards r. The selection's r is the slip
    at the rows' first centre (an edge's middle, the base's centre), but the
    step starts from r = s / |s| at the centre of pressure
    (``body_step.references``): a mode admissible only under the first pull
    is one the step's own solve does not find (an edge sliding at the friction
    limit, its corner forces +11 and +135 N at the selection and -3.9 kN at
    the step's start). Not pulled, or s within ``SLIP_FLOOR``: False.
    """
    svel = sc[SC_SVEL]
    if unit_slip(svel, n_tangent, stored, sc[SC_DIR]):  # the solve's own u: not pulled
        return False
    size = leading_length(svel, n_tangent)
    if size <= SLIP_FLOOR:
        return False
    for k in range(n_tangent):
        stored[D_SLIP + k] = svel[k] / size
    return True


@kernel(cache=True, error_model="numpy", _nrt=False)
def _restart(start, direction):
    for k in range(3):
        direction[k] = start[k]
    return direction


@kernel(cache=True, error_model="numpy", _nrt=False)
def candidate_speed(par, y, sc, kind, index, psi):
    """A candidate's rows in the scratch and its slip speed [m/s] at their centre.

    The scaled slip velocity s of the tangential rows at the rows' centre
    (an edge's middle, the base's centre; the rim point psi [rad]) in
    ``sc[SC_SVEL]``. Returns (normal rows, tangential rows, |s|).
    """
    n_normal, n_tangent = scratch_rows(par, y, kind, index, math.cos(psi), math.sin(psi), sc)
    svel = sc[SC_SVEL]
    tangential_velocity(y, sc[SC_TANGENT], n_tangent, svel)
    return n_normal, n_tangent, leading_length(svel, n_tangent)


@kernel(cache=True, error_model="numpy", _nrt=False)
def try_mode(par, y, sc, kind, index, psi, slip, level, touching, velocity_tol, scales, data):
    """Solve a candidate mode and test it; True when admissible (its u and psi in ``data``).

    ``data[D_ONSET]`` is 1.0 where the mode slips from rest (its speed within
    ``velocity_tol``: the onset direction of :func:`_slip_onset`) and 0.0
    otherwise, a slip under way following its own velocity.

    ``scales`` = (force, rate) tolerances of the admissibility tests [N or N s,
    m/s^2 or m/s]. The candidate's rows are built here; ``sc`` must hold the
    rotation, inverse inertia and base of the instant.
    """
    rot = sc[SC_ROT]
    n_normal, n_tangent, speed = candidate_speed(par, y, sc, kind, index, psi)
    svel = sc[SC_SVEL]
    direction = sc[SC_DIR]
    force_tol, rate_tol = scales[0], scales[1]
    onset = not (level == ACCELERATION and speed > velocity_tol)  # at rest: a slip from rest
    if kind != FREE and slip == 0:
        if not onset:
            return False
        if not _solve(par, y, sc, level, 0, direction, n_normal, n_tangent):
            return False
        if friction_margin(par, n_normal, n_tangent, sc[SC_LAM]) < -force_tol:
            return False
    elif kind != FREE:
        if not onset:
            # kinetic: along the slip velocity at the centre of pressure, which the step's
            # start (body_step.references) stores as its own direction
            stored = sc[SC_STORED]
            stored[:] = 0.0
            for k in range(n_tangent):
                stored[D_SLIP + k] = svel[k] / speed
            for _ in range(KINETIC_PASSES):
                if not solve_patch(par, y, sc, True, 1, direction, True, stored, n_normal,
                                   n_tangent, False):  # fmt: skip
                    return False
                if not _restore_own_slip(sc, n_tangent, stored):
                    break
        else:
            # the friction the patch would need to stick, reversed, starts the search
            start = sc[SC_START]
            start[:] = 0.0
            if _solve(par, y, sc, level, 0, direction, n_normal, n_tangent):
                size = 0.0
                for k in range(n_tangent):
                    size += sc[SC_LAM][n_normal + k] ** 2
                size = math.sqrt(size)
                for k in range(n_tangent):
                    start[k] = -sc[SC_LAM][n_normal + k] / size if size > 0.0 else 0.0
                if size == 0.0:
                    start[0] = 1.0
            elif speed > 0.0:
                for k in range(n_tangent):
                    start[k] = svel[k] / speed
            else:
                start[0] = 1.0
            if not _slip_onset(par, y, sc, level, n_normal, n_tangent, start, direction, rate_tol):
                return False
    else:
        acc = sc[SC_ACC]
        base = sc[SC_BASE]
        for i in range(6):
            acc[i] = base[i]
    if kind != FREE and normal_margin(par, rot, kind, sc[SC_LAM]) < -force_tol:
        return False
    if not _others_separate(par, y, sc, kind, index, psi, touching, level, rate_tol):
        return False
    data[D_PSI] = psi
    for k in range(3):
        data[D_SLIP + k] = direction[k] if (slip == 1 and k < n_tangent) else 0.0
    data[D_ONSET] = 1.0 if (kind != FREE and slip == 1 and onset) else 0.0
    return True


@kernel(cache=True, error_model="numpy", _nrt=False)
def touching_points(par, y, sc, gap_tol, velocity_tol, level, touching):
    """Flags of the touching points: box corners 0-3; cylinder: 4 = the rim's lowest point,
    0 = the whole base flat. Returns the rim angle of the lowest point (cylinder).

    At the rotation ``sc[SC_ROT]``.
    """
    rot = sc[SC_ROT]
    d = sc[SC_POINTS][0]
    for k in range(5):
        touching[k] = False
    if par[P_SHAPE] == SHAPE_BOX:
        for k in range(4):
            g, gv = corner_gap(par, y, rot, k, d)
            touching[k] = g <= gap_tol and (level == VELOCITY or gv <= velocity_tol)
        return 0.0
    g, gv, psi = rim_contact(par, y, rot, gap_tol, d)
    touching[4] = g <= gap_tol and (level == VELOCITY or gv <= velocity_tol)
    flat = g + 2.0 * par[P_HALF_X] * sin_tilt(rot) <= gap_tol
    if touching[4] and flat:
        # the whole base: every point's normal velocity within the tolerance
        speed = math.hypot(y[10], y[11]) * par[P_HALF_X]
        touching[0] = level == VELOCITY or (gv <= velocity_tol and speed <= velocity_tol)
    return psi


@kernel(cache=True, error_model="numpy", _nrt=False)
def clear_candidates(sc):
    """Zero the scratch's candidate kinds, indices and rim angles (:func:`candidates`)."""
    kinds, indices, angles = sc[SC_KINDS], sc[SC_INDICES], sc[SC_ANGLES]
    for c in range(MAX_CANDIDATES + 1):
        kinds[c] = 0
        indices[c] = 0
        angles[c] = 0.0


@kernel(cache=True, error_model="numpy", _nrt=False)
def candidates(par, touching, psi, kinds, indices, angles):
    """The candidate patches, most closed first; returns their count."""
    count = 0
    if par[P_SHAPE] == SHAPE_BOX:
        if touching[0] and touching[1] and touching[2] and touching[3]:
            kinds[count] = FACE
            count += 1
        for k in range(4):
            if touching[k] and touching[(k + 1) % 4]:
                kinds[count] = EDGE
                indices[count] = k
                count += 1
        for k in range(4):
            if touching[k]:
                kinds[count] = POINT
                indices[count] = k
                count += 1
        return count
    if touching[0]:
        kinds[count] = FACE
        count += 1
    if touching[4]:
        kinds[count] = POINT
        angles[count] = psi
        count += 1
    return count


@kernel(cache=True, error_model="numpy", _nrt=False)
def _face_pivot(par, y, sc):
    """Rim angle towards which a FACE solution's centre of pressure leaves the disc."""
    rot = sc[SC_ROT]
    n_normal, n_tangent = scratch_rows(par, y, FACE, 0, 1.0, 0.0, sc)
    if not _solve(par, y, sc, ACCELERATION, 0, sc[SC_DIR], n_normal, n_tangent):
        return 0.0, False
    lam = sc[SC_LAM]
    px = -lam[2]
    py = lam[1]
    if math.hypot(px, py) == 0.0:
        return 0.0, False
    bx = rot[0, 0] * px + rot[1, 0] * py
    by = rot[0, 1] * px + rot[1, 1] * py
    return math.atan2(by, bx), True


@kernel(cache=True, error_model="numpy", _nrt=False)
def select_mode(par, record, dt, t, y, sc, gap_tol, velocity_tol, mode, data, excluded):
    """Choose the contact mode at (t, y) (acceleration level); fills ``mode`` and ``data``.

    ``excluded`` = (kind, index, slip states): a mode whose margin has just
    crossed zero at this event (its test is then within round-off of the
    limit and must not hold it); slip states 2 excludes both tangential
    states, kind -1 none. Returns the index of the chosen candidate, or
    NONE_ADMISSIBLE.
    """
    return _select(par, record, dt, t, y, sc, gap_tol, velocity_tol, mode, data, excluded, False)


@kernel(cache=True, error_model="numpy", _nrt=False)
def chatter_look(par, record, dt, t, y, sc, gap_tol, velocity_tol, mode, data):
    """:func:`select_mode` in a chatter's stretch of the remedy, which a slip from rest continues.

    The candidates in :func:`select_mode`'s order, none excluded; a candidate
    that could only slip from rest (its speed within ``velocity_tol`` at its
    rows' centre) is passed over, its onset not sought (:func:`_slip_onset`:
    tens of solves where none exists, most of a chatter's look). Where a
    later candidate or the flight is admissible, the onsets passed over are
    sought then (:func:`_onset_of_skipped`). Returns :func:`select_mode`'s
    choice, except ``SLIPS_FROM_REST`` where that would be a slip from rest,
    or nothing after candidates passed over: the stretch goes on either way
    (:func:`~freestand.core.dynamics.body_remedy.stretch_step`), as such a
    slip would chatter again. ``mode`` is then not set (``data`` holds an onset's
    where one was sought and found).
    """
    no_exclusion(sc)
    return _select(par, record, dt, t, y, sc, gap_tol, velocity_tol, mode, data,
                   sc[SC_EXCLUDED], True)  # fmt: skip


@kernel(cache=True, error_model="numpy", _nrt=False)
def no_exclusion(sc):
    """The scratch's excluded mode (:func:`select_mode`) set to none: (-1, 0, 0)."""
    excluded = sc[SC_EXCLUDED]
    excluded[0], excluded[1], excluded[2] = -1, 0, 0


@kernel(cache=True, error_model="numpy", _nrt=False)
def _select(par, record, dt, t, y, sc, gap_tol, velocity_tol, mode, data, excluded, chatter):
    """:func:`select_mode`, or with ``chatter`` :func:`chatter_look`."""
    prepare(par, record, dt, t, y, FREE, 0, 0.0, sc)
    touching = sc[SC_TOUCHING]
    psi = touching_points(par, y, sc, gap_tol, velocity_tol, ACCELERATION, touching)
    clear_candidates(sc)
    kinds, indices, angles = sc[SC_KINDS], sc[SC_INDICES], sc[SC_ANGLES]
    count = candidates(par, touching, psi, kinds, indices, angles)
    if par[P_SHAPE] != SHAPE_BOX and touching[0]:
        speed = math.hypot(y[10], y[11]) * par[P_HALF_X]
        if speed <= velocity_tol:
            angle, found = _face_pivot(par, y, sc)
            if found:
                angles[1] = angle
    force_tol = RELATIVE_TOLERANCE * par[P_MASS] * par[P_GRAVITY]
    scales = (force_tol, RELATIVE_TOLERANCE * par[P_GRAVITY])
    skipped = 0  # a chatter's look: the candidates at rest whose onset it has not sought
    for slip in (0, 1):
        for c in range(count):
            if (
                kinds[c] == excluded[0]
                and indices[c] == excluded[1]
                and (excluded[2] == 2 or excluded[2] == slip)
            ):
                continue
            if chatter and slip == 1:
                _, _, speed = candidate_speed(par, y, sc, kinds[c], indices[c], angles[c])
                if speed <= velocity_tol:
                    skipped |= 1 << c
                    continue
            if try_mode(par, y, sc, kinds[c], indices[c], angles[c], slip, ACCELERATION,
                        touching, velocity_tol, scales, data):  # fmt: skip
                if skipped != 0 and _onset_of_skipped(par, y, sc, skipped, touching, velocity_tol,
                                                      scales, data, kinds[c], indices[c],
                                                      angles[c], slip):  # fmt: skip
                    return SLIPS_FROM_REST
                mode[M_KIND] = kinds[c]
                mode[M_INDEX] = indices[c]
                mode[M_SLIP] = slip
                return c
    if try_mode(par, y, sc, FREE, 0, psi, 0, ACCELERATION, touching, velocity_tol, scales, data):
        if skipped != 0 and _onset_of_skipped(par, y, sc, skipped, touching, velocity_tol,
                                              scales, data, FREE, 0, psi, 0):  # fmt: skip
            return SLIPS_FROM_REST
        mode[M_KIND] = FREE
        mode[M_INDEX] = 0
        mode[M_SLIP] = 0
        return count
    return SLIPS_FROM_REST if skipped != 0 else NONE_ADMISSIBLE


@kernel(cache=True, error_model="numpy", _nrt=False)
def _onset_of_skipped(par, y, sc, skipped, touching, velocity_tol, scales, data, kind, index,
                      psi, slip):  # fmt: skip
    """Whether a candidate a chatter's look skipped (a bit of ``skipped``) slips from rest.

    The look (:func:`chatter_look`) has found the mode (``kind``, ``index``,
    rim angle ``psi``, ``slip``) admissible after candidates at rest whose
    onset it did not seek: the first of them whose onset is consistent would
    have been :func:`select_mode`'s choice. Their onsets are sought here, in
    order; where none is consistent, the mode found is solved again, so that
    the scratch and ``data`` hold its solution.
    """
    kinds, indices, angles = sc[SC_KINDS], sc[SC_INDICES], sc[SC_ANGLES]
    c = 0
    while skipped >> c != 0:
        if (skipped >> c) & 1 and try_mode(par, y, sc, kinds[c], indices[c], angles[c], 1,
                                            ACCELERATION, touching, velocity_tol, scales,
                                            data):  # fmt: skip
            return True
        c += 1
    try_mode(par, y, sc, kind, index, psi, slip, ACCELERATION, touching, velocity_tol, scales,
             data)  # fmt: skip
    return False


@kernel(cache=True, error_model="numpy", _nrt=False)
def _landing_pivot(par, y, sc, touching, scales, psi0, slip, data):
    """Rim angle about which a landed cylinder turns after the impact (1-D root search).

    f(psi) = omega_h(after) . e_r(psi), the radial component of the angular
    velocity after an impact at the rim point psi, sticking (``slip`` 0) or
    slipping (1, its direction by the velocity-level slip onset to the rate
    tolerance of ``scales``). f is the derivative of the rim's normal
    velocity after, ``v_z + R (omega_x sin phi - omega_y cos phi)`` (phi the
    rim angle in the support's frame), over R: the pivot sought is the rim's
    lowest-moving point, the body turning about the rim's tangent there,
    where f crosses zero upwards (its downward crossing is the highest-moving
    point). From psi0 (opposite the point the body landed from) the next
    guess is the lowest-moving point of the motion after the impact at psi0,
    ``phi = atan2(-omega_x, omega_y)``; from there the crossing is
    bracketed on the side the sign of f gives, in steps doubling up to
    pi/2, and found by Anderson and Bjorck's regula falsi
    (:mod:`~freestand.core.contact.regula_falsi`). Returns the guess where
    no crossing is bracketed (the candidate's test then refuses it).
    Bracketed from psi0 both ways within 0.8 rad, as before, the search took
    the first sign change of either kind and missed the pivot of a sliding
    cylinder's slipping landings, 56 deg and more away.
    """
    rot = sc[SC_ROT]
    yaw = math.atan2(rot[1, 0], rot[0, 0])
    scale = math.hypot(y[10], y[11]) + 1e-300
    f0 = _radial(par, y, sc, touching, scales, psi0, slip, yaw, data)
    if abs(f0) <= 1e-12 * scale:
        return psi0
    x = sc[SC_ACC]
    guess = psi0
    if x[3] != 0.0 or x[4] != 0.0:
        guess = math.atan2(-x[3], x[4]) - yaw
    f_guess = _radial(par, y, sc, touching, scales, guess, slip, yaw, data)
    if abs(f_guess) <= 1e-12 * scale:
        return guess
    # the upward crossing lies above the guess where f < 0 there, below where f > 0
    sign = 1.0 if f_guess < 0.0 else -1.0
    step = 0.05
    while True:
        other = guess + sign * min(step, 0.5 * math.pi)
        f_other = _radial(par, y, sc, touching, scales, other, slip, yaw, data)
        if f_other * f_guess <= 0.0:
            break
        if step >= 0.5 * math.pi:
            return guess
        guess, f_guess = other, f_other
        step *= 2.0
    low, high, f_low, f_high = (guess, other, f_guess, f_other) if sign > 0.0 else (
        other, guess, f_other, f_guess)  # fmt: skip
    side = 0
    for _ in range(PIVOT_ITERATIONS):
        if high - low < 1e-13:
            break
        middle = (low * f_high - high * f_low) / (f_high - f_low)
        if not low < middle < high:
            middle = 0.5 * (low + high)
        f_middle = _radial(par, y, sc, touching, scales, middle, slip, yaw, data)
        if abs(f_middle) <= 1e-12 * scale:
            return middle
        low, high, f_low, f_high, side = narrowed(f_middle > 0.0, middle, f_middle, low, high,
                                                  f_low, f_high, side)  # fmt: skip
    return 0.5 * (low + high)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _radial(par, y, sc, touching, scales, angle, slip, yaw, data):
    """:func:`_landing_pivot`'s f at the rim angle ``angle``; the velocity after in the scratch."""
    try_mode(par, y, sc, POINT, 0, angle, slip, VELOCITY, touching, 0.0, scales, data)
    x = sc[SC_ACC]
    phi = angle + yaw
    return x[3] * math.cos(phi) + x[4] * math.sin(phi)


@kernel(cache=True, error_model="numpy", _nrt=False)
def impact(par, y, sc, gap_tol, psi_before, mode, data, out_velocity):
    """The impact law at (t, y): the velocity after in ``out_velocity`` (6,).

    The candidates (most closed first) sticking, then slipping; the first
    admissible is taken. A cylinder landed flat turns, if not on its base,
    about the rim point where the rim's normal velocity after is lowest
    (:func:`_landing_pivot`), found for a stick impact and, where no sticking
    candidate is admissible, again for a slipping one: the stick impact's
    pivot, used for both before, left the slipping landings of a sliding,
    barely rocking cylinder with no candidate (12 of 37 impacts of a hollow
    cylinder under a two-component record in its first 4.1 s), resolved at
    eight rim points by the remedy's velocity-level impact instead.
    Returns the index of the candidate chosen (its mode in ``mode``/``data``)
    or NONE_ADMISSIBLE. ``sc`` must hold the instant's rotation and inverse
    inertia (:func:`prepare`); the base is set here to the velocity before.
    """
    base = sc[SC_BASE]
    for i in range(6):
        base[i] = y[7 + i]
    touching = sc[SC_TOUCHING]
    psi = touching_points(par, y, sc, gap_tol, 0.0, VELOCITY, touching)
    clear_candidates(sc)
    kinds, indices, angles = sc[SC_KINDS], sc[SC_INDICES], sc[SC_ANGLES]
    count = candidates(par, touching, psi, kinds, indices, angles)
    speed = math.sqrt(y[7] ** 2 + y[8] ** 2 + y[9] ** 2) + par[P_HALF_X] * math.sqrt(
        y[10] ** 2 + y[11] ** 2 + y[12] ** 2)  # fmt: skip
    speed = max(speed, 1e-6)
    scales = (RELATIVE_TOLERANCE * par[P_MASS] * speed, RELATIVE_TOLERANCE * speed)
    landed_flat = par[P_SHAPE] != SHAPE_BOX and touching[0]
    for slip in (0, 1):
        for c in range(count):
            if landed_flat and c == 1:
                # the rim point the body turns about after a stick impact, then after a slipping
                # one: searched only where the base itself (candidate 0) is not admissible
                search_scales = (1e300, 1e300) if slip == 0 else scales
                angles[1] = _landing_pivot(par, y, sc, touching, search_scales,
                                           psi_before + math.pi, slip, data)  # fmt: skip
            if slip == 0 and stick_impact_excluded(par, y, sc, kinds[c], indices[c], touching,
                                                   scales[0], scales[1]):  # fmt: skip
                continue  # its solve would fail too (body_stick_bounds)
            if try_mode(par, y, sc, kinds[c], indices[c], angles[c], slip, VELOCITY, touching,
                        0.0, scales, data):  # fmt: skip
                mode[M_KIND] = kinds[c]
                mode[M_INDEX] = indices[c]
                mode[M_SLIP] = slip
                for i in range(6):
                    out_velocity[i] = sc[SC_ACC][i]
                return c
    return NONE_ADMISSIBLE
