"""The held mode's solve at an instant: a sliding patch's friction at its centre of pressure.

:func:`solve_at` solves the contact problem of the held mode at (t, y) and
:func:`rate` gives the state's rate from it, for the integrator's stages.
The rows, the solve of one mode (:func:`~freestand.core.contact.body_kernel.solve_mode`)
and the scratch are :mod:`freestand.core.contact.body_kernel`'s; here a FACE's
or an EDGE's kinetic friction is placed at the centre of pressure of its own
solution (:func:`solve_patch`: a FACE's by one solve and its prediction of
the twisting centre, an EDGE's by a secant on its share along the edge) and
the slip direction is read from the slip velocity there
(:func:`slip_direction`). Compiled without numba's reference counting, as
the kernel.
"""

from __future__ import annotations

import math

from freestand.core.contact.body_kernel import (
    CENTRE_ITERATIONS,
    CENTRE_ROUNDOFF,
    D_FLOOR,
    D_PSI,
    D_SLIP,
    E_A0,
    E_A1,
    E_AX,
    E_AY,
    E_BX,
    E_BY,
    E_INTACT,
    E_QT,
    E_QX,
    E_QY,
    E_RHS,
    EDGE,
    EDGE_ITERATIONS,
    FACE,
    M_INDEX,
    M_KIND,
    M_SLIP,
    P_CENTRE,
    P_HALF_X,
    P_HALF_Y,
    P_MASS,
    P_MU_KINETIC,
    P_RHO_FACE,
    P_SHAPE,
    POINT,
    RHO_FLOOR,
    SC_ACC,
    SC_ARMS,
    SC_BASE,
    SC_CENTRE,
    SC_DIR,
    SC_EDGE,
    SC_F0,
    SC_INV,
    SC_LAM,
    SC_NBIAS,
    SC_NORMAL,
    SC_ROT,
    SC_SHARE,
    SC_SVEL,
    SC_TANGENT,
    SC_WORK,
    SHAPE_BOX,
    apply_inverse_mass,
    box_corner,
    centre_stick_friction,
    cross,
    edge_twist_radius,
    effective_twist_radius,
    face_centre_of_pressure,
    pivot_direction,
    point_arm_and_biases,
    point_velocity,
    prepare_load,
    prepare_wrench,
    rotation_matrix,
    scratch_rows,
    solve_mode,
    sticking_edge_from_force,
    sticking_point_from_force,
    tangent_rows,
    tangential_velocity,
)
from freestand.core.contact.compiled import kernel
from freestand.core.contact.face_friction import CENTRE_TOLERANCE, body_horizontal, model_centre
from freestand.core.contact.slip_law import SLIP_FLOOR, pulled_unit, slip_pull
from freestand.core.contact.vectors import leading_length, norm2

# the slopes of g = F(sigma) - sigma that a sliding EDGE's next search starts from (below
# -1 where F falls, above where it rises; outside: the fixed point's step, slope -1)
SLOPE_LOW = -100.0
SLOPE_HIGH = -0.01


@kernel(cache=True, error_model="numpy", _nrt=False)
def solve_patch(par, y, sc, use_bias, slip, direction, kinetic, stored, n_normal, n_tangent, stage):
    """Solve a mode on the rows in the scratch, its friction about the centre of pressure.

    A FACE's or EDGE's friction acts about its centre of pressure, with the
    twist radius of its effective area (:func:`effective_twist_radius`).
    Sticking, the rows' centre does not change the solution (every point of
    the patch is held): one solve, then the friction is expressed about the
    centre of pressure (:func:`centre_stick_friction`). Sliding, the friction
    ``-mu N u`` acts at the centre of pressure, which the solution moves: a
    FACE's solve places it there itself, and is solved again only where its
    slip direction or twist radius differ there (:func:`_slide_face`); an
    EDGE's centre is found by a secant on its share along the edge, whose
    2 x 2 system gives the solution there (:func:`_slide_edge`); to
    ``CENTRE_TOLERANCE``, at most ``CENTRE_ITERATIONS`` solves or
    ``EDGE_ITERATIONS`` shares. ``kinetic``:
    the slip direction u is the slip velocity's at each centre
    (:func:`slip_direction`, ``stored`` its fallback, as mode data); else u
    is ``direction`` as given. The patch is the one whose rows the scratch
    holds (``sc[SC_CENTRE][3:5]``, :func:`scratch_rows`); the rows and
    ``sc[SC_CENTRE]`` are left at the final centre, and ``sc[SC_CENTRE][5]``
    is 1.0 where the stored direction was read (at any centre), else 0.0.
    ``stage``: an RK4 stage's solve, which reads the accelerations alone: a
    sliding FACE's rows and slip direction are then left at the centre of its
    last solve where its slip direction provably holds at its centre of
    pressure (:func:`_kept_by_bound`). False when a system is singular.
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
        return _slide_face(par, y, sc, use_bias, direction, kinetic, stored, n_normal, n_tangent,
                           stage)  # fmt: skip
    if not _solve_at_rows(par, y, sc, use_bias, slip, direction, kinetic, stored, n_normal,
                          n_tangent):  # fmt: skip
        return False
    centre_stick_friction(par, sc[SC_ROT], kind, index, n_normal, sc[SC_LAM], centre)
    tangent_rows(par, y, sc)
    return True


@kernel(cache=True, error_model="numpy", _nrt=False)
def _slide_face(par, y, sc, use_bias, direction, kinetic, stored, n_normal, n_tangent, stage):
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
    their F. An RK4 stage (``stage``) skips the check at the centre of
    pressure where :func:`_kept_by_bound` proves that it holds.
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
        rho = centre[2]
        moved = _move_to_pressure_centre(par, rot, lam, centre)
        if moved <= CENTRE_TOLERANCE * par[P_HALF_X]:
            return True
        if moved <= CENTRE_ROUNDOFF * par[P_HALF_X] and moved >= last:
            return True
        last = moved
        if stage and kinetic and _kept_by_bound(par, y, sc, stored, moved, rho):
            return True
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
def _kept_by_bound(par, y, sc, stored, moved, rho):
    """Whether a sliding FACE's slip direction provably holds at its centre of pressure.

    The solve took u from the slip velocity s at its centre c (``sc[SC_SVEL]``,
    twist radius ``rho`` [m]) and moved the centre ``moved`` [m] to the
    centre of pressure p (``sc[SC_CENTRE]``, twist radius rho_p). There the
    slip velocity is ``s' = s + ((omega x (p - c))_x, (omega x (p - c))_y,
    (rho_p - rho) omega_z)``, within ``B = |omega| moved + |rho_p - rho|
    |omega_z|`` of s. Where both lie on the slip law's own side (``|s| >
    floor + B`` and ``s . r > 2 B``, r the stored direction, each with
    1e-12 |s| to spare: u = s / |s|, u' = s' / |s'|,
    :func:`slip_direction`), ``|u' - u| <= 2 B / |s|``, and the check of
    :func:`_face_friction_kept` (u and ``u_t rho`` within ``CENTRE_TOLERANCE``,
    the twist's of the half-width) holds where half its tolerances bound
    those changes (the other half covers the round-off of the check's own
    arithmetic, some 1e-16). An RK4 stage reads the accelerations alone,
    which the check does not change where it holds: it is skipped there,
    and the rows and the slip direction are left at the solve's centre, not
    moved to the centre of pressure. r is a unit vector (the step's stored
    direction), so ``s' . r >= s . r - B``.
    """
    svel = sc[SC_SVEL]
    size = leading_length(svel, 3)
    along = svel[0] * stored[D_SLIP] + svel[1] * stored[D_SLIP + 1] + svel[2] * stored[D_SLIP + 2]
    omega_z = abs(y[12])
    change = abs(sc[SC_CENTRE][2] - rho)
    bound = math.sqrt(y[10] ** 2 + y[11] ** 2 + y[12] ** 2) * moved + change * omega_z
    floor = max(SLIP_FLOOR, stored[D_FLOOR])
    slack = 1e-12 * size  # the round-off of s and s' as the check computes them, with room
    if not (size > floor + bound + slack and along > 2.0 * bound + slack):
        return False
    turn = 2.0 * bound / size  # |u' - u|
    twist = turn * sc[SC_CENTRE][2] + change * abs(svel[2]) / size  # |u'_t rho_p - u_t rho|
    return turn <= 0.5 * CENTRE_TOLERANCE and twist <= 0.5 * CENTRE_TOLERANCE * par[P_HALF_X]


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
    in [0, 1], and the root of ``g = F(sigma) - sigma`` is found by Newton's
    method on F' in closed form (kinetic: :func:`_kinetic_share`; 2.9 shares
    per solve of the benchmark's sliding cabinet where the secant took 3.6)
    or else the secant method, safeguarded by bisection on the bracket that
    the signs of g keep (g(0) >= 0 >= g(1): a root always lies inside). The
    search starts at this edge's last settled share, a secant's first step
    along the slope g had there (``sc[SC_SHARE]``; an RK4 stage's centre
    lies near the last stage's: 3.6 shares per solve of that cabinet where
    the edge's middle and the fixed point's step, sigma = F(sigma), took
    4.8); else at the middle with that step, and again there where F has
    no centre of pressure at the last share. Each F(sigma) is a 2 x 2 system
    whose terms were computed once (:func:`edge_share`): the search costs
    less than one full solve. At the root the same system gives the
    solution (:func:`_edge_solution`; kinetic, from the closed form's own
    terms there, :func:`_edge_forces`); a full solve is made only where the
    search ends elsewhere (F has no centre of pressure or no solution, and
    the solve then says so; or it ran out of trials). Solving the settled
    share's rows again took 4.5 % of the 3-D benchmark's rocking cabinet.
    Solving the full system at each trial took 7.5 solves per slide on
    average, up to ``CENTRE_ITERATIONS``, more than half of a rocking
    cabinet's solves: the map F is rough where the slip turns at the centre.
    """
    edge_slide_terms(par, y, sc, use_bias)
    return slide_edge_on_terms(par, y, sc, use_bias, direction, kinetic, stored, n_normal,
                               n_tangent)  # fmt: skip


@kernel(cache=True, error_model="numpy", _nrt=False)
def slide_edge_on_terms(par, y, sc, use_bias, direction, kinetic, stored, n_normal, n_tangent):
    """:func:`_slide_edge` on the terms the scratch holds (:func:`edge_slide_terms`).

    The terms depend on the state and the EDGE's normal rows alone, not on
    the friction's direction or centre: a slip onset's search, which solves
    the same rows under many directions
    (:func:`~freestand.core.contact.body_modes._slip_onset`), computes them
    once. ``sc[SC_EDGE][2, E_INTACT]`` is left 0.0 where the search ended in
    the full solve, whose work arrays hold q_r
    (:func:`~freestand.core.contact.body_kernel.solve_held_rows`): the terms
    must then be computed again.
    """
    centre = sc[SC_CENTRE]
    index = int(centre[4])
    ax, ay = box_corner(par, index)
    bx, by = box_corner(par, (index + 1) % 4)
    length = math.sqrt((bx - ax) ** 2 + (by - ay) ** 2)
    tolerance = CENTRE_TOLERANCE * par[P_HALF_X] / length  # on sigma
    middle = ((centre[0] - ax) * (bx - ax) + (centre[1] - ay) * (by - ay)) / (length * length)
    share = middle
    last = sc[SC_SHARE]
    slope = -1.0  # g's slope: the fixed point's step where none is known
    warm = last[0] == index + 1.0
    if warm:  # this edge's last settled share and slope
        share, slope = last[1], last[2]
    low, high = 0.0, 1.0
    previous, g_previous = math.nan, math.nan
    floor = max(SLIP_FLOOR, stored[D_FLOOR]) if kinetic else SLIP_FLOOR  # (unit_slip's)
    i = 0
    newton = math.nan  # g's slope at the share, where known in closed form (kinetic)
    c0, c1, size, det = 0.0, 0.0, 0.0, 0.0
    while i < EDGE_ITERATIONS:
        if kinetic:
            value, newton, pulled, c0, c1, size, det = _kinetic_share(
                par, sc[SC_EDGE], index, share, stored, floor
            )
            newton -= 1.0
            if pulled:
                centre[5] = 1.0  # the stored direction read (edge_share's flag)
        else:
            value = edge_share(par, sc, index, share, direction, False, stored)
        g = value - share
        if warm and g != g:  # no centre of pressure at the last share: from the centre's
            warm, slope, i = False, -1.0, 0
            share = middle
            continue
        if not abs(g) > tolerance:  # settled, or no centre of pressure (NaN)
            break
        if g > 0.0:
            low = max(low, share)
        else:
            high = min(high, share)
        if newton < 0.0:  # Newton's step, on g's slope in closed form
            following = share - g / newton
        elif i > 0 and g != g_previous:  # the secant's step
            following = share - g * (share - previous) / (g - g_previous)
        else:  # the first: along the last search's slope (or the fixed point's)
            following = share - g / slope
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
        i += 1
    _edge_centre(par, index, share, ax, ay, bx, by, centre)
    tangent_rows(par, y, sc)
    if kinetic:  # s and u at the share last tried, as edge_share leaves them
        _slip_at(sc[SC_EDGE], share, centre[2], stored, sc[SC_SVEL], sc[SC_DIR])
    if not abs(g) <= tolerance:
        sc[SC_EDGE][2, E_INTACT] = 0.0
        return _solve_at_rows(par, y, sc, use_bias, 1, direction, kinetic, stored, n_normal,
                              n_tangent)  # fmt: skip
    # settled at the share last tried: its system gives the solution; the next search
    # starts there, along g's last slope (Newton's or the last secant's)
    if newton < 0.0:
        slope = newton
    elif i > 0 and g != g_previous:
        slope = (g - g_previous) / (share - previous)
    if SLOPE_LOW < slope < SLOPE_HIGH:
        last[0], last[1], last[2] = index + 1.0, share, slope
    if kinetic:  # the settled share's system, from its closed form's terms
        edge = sc[SC_EDGE]
        a00, a01, a10, a11 = edge[0, E_A0], edge[0, E_A1], edge[1, E_A0], edge[1, E_A1]
        rhs0, rhs1 = edge[0, E_RHS], edge[1, E_RHS]
        first = rhs0 * (a11 * size - c1) - rhs1 * (a01 * size - c0)  # N_0 det |w|
        second = (a00 * size - c0) * rhs1 - (a10 * size - c1) * rhs0  # N_1 det |w|
        return _edge_forces(par, sc, first / det, second / det, sc[SC_DIR])
    return _edge_solution(par, sc, share, direction)


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
    velocity[E_INTACT] = 1.0


@kernel(cache=True, error_model="numpy", _nrt=False)
def edge_share(par, sc, index, share, direction, kinetic, stored):
    """F(sigma): the centre of pressure's share along a sliding EDGE with its friction at sigma.

    The 2 x 2 system of the corners' normal forces N_0, N_1, with ``-mu N u``
    at the point at ``share`` sigma of the edge, from the terms of
    :func:`edge_slide_terms`: ``(A - mu c 1^T) N = rhs``, ``c_r = q_r . G``
    (G the generalised force of u there, twist radius rho at sigma). u is
    ``direction``, or (``kinetic``) the slip velocity's there
    (:func:`unit_slip`, ``stored`` its fallback; flagged in
    ``sc[SC_CENTRE][5]`` where read; the slip velocity and u left in the
    scratch), whose F is :func:`_kinetic_share`'s closed form of the same
    system. Returns ``N_1 / (N_0 + N_1)`` in [0, 1]; NaN where the system is
    singular or N_0 + N_1 <= 0 (no centre of pressure).
    """
    edge = sc[SC_EDGE]
    ax, ay = box_corner(par, index)
    bx, by = box_corner(par, (index + 1) % 4)
    rho = effective_twist_radius(par, EDGE, index, ax + share * (bx - ax), ay + share * (by - ay))
    if kinetic:
        if not _slip_at(edge, share, rho, stored, sc[SC_SVEL], sc[SC_DIR]):
            sc[SC_CENTRE][5] = 1.0
        value = _kinetic_share(par, edge, index, share, stored, max(SLIP_FLOOR, stored[D_FLOOR]))[0]
        return value
    return _edge_share_along(par, edge, share, rho, direction)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _kinetic_share(par, edge, index, share, stored, floor):
    """:func:`edge_share`'s kinetic F(sigma) in closed form, with its slope and its system's terms.

    Cramer's sum ``N_0 det + N_1 det = r_0 (A_11 - A_10) + r_1 (A_00 - A_01) = D`` does
    not depend on the friction (it moves both columns alike), so ``F = (S - r_1 c_0 + r_0
    c_1) / D`` with ``S = A_00 r_1 - A_10 r_0``, and ``det = det A - c_0 (A_11 - A_10) -
    c_1 (A_00 - A_01)``; ``c_r = mu q_r . G(u)`` is linear in u = w / |w| (w the slip
    velocity at sigma, pulled to r: ``slip_law.pulled_unit``), and each term is taken
    times |w|. One division where the 2 x 2 system and u took four, nothing written to
    the scratch: F as :func:`_edge_share_along` gives it, to round-off.

    F is of degree 0 in w, and the slip s is affine in sigma on each half of the edge
    (its twist part ``rho omega_z``, rho of :func:`effective_twist_radius`): F' in
    closed form, ``(second' - F total') / total`` with ``total = D |w|``, ``second = S
    |w| - r_1 c_0 |w| + r_0 c_1 |w|``, ``|w|' = w . w' / |w|`` and, where w was pulled
    to r, ``w' = s' + beta' r``, ``beta' = sign(s . r) s' . r - s' . r - |s|'`` (the
    last term below the floor); zero where F is clamped to the edge. Newton's method
    on it took 2.9 shares per solve of the benchmark's sliding cabinet (whose slip is
    pulled at 95 % of them) where the secant took 3.6.

    Returns (F [-], F' [-], True where u was pulled to the stored r (:func:`unit_slip`
    with ``floor`` [m/s]), ``c_0 |w|``, ``c_1 |w|``, |w| [m/s], ``det |w|``): the system
    at sigma, whose solution :func:`slide_edge_on_terms` takes from them.
    """
    ax, ay = box_corner(par, index)
    bx, by = box_corner(par, (index + 1) % 4)
    rho, twist = edge_twist_radius(par, index, ax + share * (bx - ax), ay + share * (by - ay))
    velocity = edge[2]
    w0 = velocity[0] + share * (velocity[2] - velocity[0])
    w1 = velocity[1] + share * (velocity[3] - velocity[1])
    w2 = rho * velocity[4]
    d0, d1, d2 = velocity[2] - velocity[0], velocity[3] - velocity[1], twist * velocity[4]  # s'
    size = math.sqrt(w0 * w0 + w1 * w1 + w2 * w2)
    r0, r1, r2 = stored[D_SLIP], stored[D_SLIP + 1], stored[D_SLIP + 2]
    along = w0 * r0 + w1 * r1 + w2 * r2
    pulled = not (size > floor and along > 0.0)
    if pulled:  # w = s + beta r, w' = s' + beta' r (slip_pull)
        extra = slip_pull(along, size, floor)
        rate_ = d0 * r0 + d1 * r1 + d2 * r2
        pull = (rate_ if along > 0.0 else -rate_) - rate_
        if size < floor and size > 0.0:
            pull -= (w0 * d0 + w1 * d1 + w2 * d2) / size
        w0, w1, w2 = w0 + extra * r0, w1 + extra * r1, w2 + extra * r2
        d0, d1, d2 = d0 + pull * r0, d1 + pull * r1, d2 + pull * r2
        size = math.sqrt(w0 * w0 + w1 * w1 + w2 * w2)
        if not size > 0.0:
            w0, w1, w2, size = r0, r1, r2, 1.0
            d0, d1, d2 = 0.0, 0.0, 0.0
    mu = par[P_MU_KINETIC]
    slip = (w0, w1, w2)
    c0 = mu * _friction_term(edge[0], share, rho, slip)  # c_r |w|
    c1 = mu * _friction_term(edge[1], share, rho, slip)
    a00, a01, a10, a11 = edge[0, E_A0], edge[0, E_A1], edge[1, E_A0], edge[1, E_A1]
    rhs0, rhs1 = edge[0, E_RHS], edge[1, E_RHS]
    whole = rhs0 * (a11 - a10) + rhs1 * (a00 - a01)  # D
    total = whole * size  # D |w|
    det = (a00 * a11 - a01 * a10) * size - c0 * (a11 - a10) - c1 * (a00 - a01)  # det |w|
    if det == 0.0 or not total * det > 0.0:
        return math.nan, math.nan, pulled, c0, c1, size, det
    plain = a00 * rhs1 - a10 * rhs0  # S
    second = plain * size - rhs1 * c0 + rhs0 * c1  # N_1 det |w|
    inverse = 1.0 / total
    value = second * inverse
    if not 0.0 <= value <= 1.0:
        return min(max(value, 0.0), 1.0), 0.0, pulled, c0, c1, size, det
    dsize = (w0 * d0 + w1 * d1 + w2 * d2) / size
    dc0 = mu * _friction_slope(edge[0], share, rho, twist, slip, d0, d1, d2)
    dc1 = mu * _friction_slope(edge[1], share, rho, twist, slip, d0, d1, d2)
    dsecond = plain * dsize - rhs1 * dc0 + rhs0 * dc1
    return value, (dsecond - value * whole * dsize) * inverse, pulled, c0, c1, size, det


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _friction_slope(row, share, rho, twist, w, dv0, dv1, dw2):
    """d/dsigma of :func:`_friction_term` times |w| (its w = (w_0, w_1, rho omega_z)), with
    ``twist`` rho' and w' = (dv0, dv1, dw2)."""
    mx = row[E_AX] + share * (row[E_BX] - row[E_AX])
    my = row[E_AY] + share * (row[E_BY] - row[E_AY])
    return ((row[E_BX] - row[E_AX]) * w[0] + (row[E_BY] - row[E_AY]) * w[1]
            + twist * row[E_QT] * w[2] + (row[E_QX] + mx) * dv0 + (row[E_QY] + my) * dv1
            + rho * row[E_QT] * dw2)  # fmt: skip


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _slip_at(edge, share, rho, stored, svel, direction):
    """The slip velocity s at ``share`` (twist radius ``rho`` [m]) into ``svel``, u into
    ``direction`` (:func:`unit_slip`): what :func:`edge_share` leaves there. Returns
    :func:`unit_slip`'s flag (False where u was pulled to the stored direction)."""
    velocity = edge[2]
    svel[0] = velocity[0] + share * (velocity[2] - velocity[0])
    svel[1] = velocity[1] + share * (velocity[3] - velocity[1])
    svel[2] = rho * velocity[4]
    return unit_slip(svel, 3, stored, direction)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _edge_share_along(par, edge, share, rho, u):
    """:func:`edge_share` with the friction along the unit ``u`` (tangential rows)."""
    det, first, second = _edge_normals(par, edge, share, rho, u)
    if det == 0.0 or not (first + second) / det > 0.0:
        return math.nan
    return min(max(second / (first + second), 0.0), 1.0)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _edge_normals(par, edge, share, rho, u):
    """A sliding EDGE's corner forces with ``-mu N u`` at ``share``: (det, N_0 det, N_1 det).

    Cramer's rule on ``(A - mu c 1^T) N = rhs`` (:func:`edge_share`), the
    terms of :func:`edge_slide_terms`; rho [m] the twist radius there.
    """
    mu = par[P_MU_KINETIC]
    c0 = mu * _friction_term(edge[0], share, rho, u)
    c1 = mu * _friction_term(edge[1], share, rho, u)
    k00 = edge[0, E_A0] - c0
    k01 = edge[0, E_A1] - c0
    k10 = edge[1, E_A0] - c1
    k11 = edge[1, E_A1] - c1
    r0, r1 = edge[0, E_RHS], edge[1, E_RHS]
    det = k00 * k11 - k01 * k10
    return det, r0 * k11 - k01 * r1, k00 * r1 - k10 * r0


@kernel(cache=True, error_model="numpy", _nrt=False)
def _edge_solution(par, sc, share, u):
    """A sliding EDGE's solution at the share its search settled on, from its 2 x 2 system.

    The corner forces N_r of :func:`_edge_normals`, then ``x'' = base +
    sum_r N_r (q_r - mu M^-1 G)`` with ``q_r = M^-1 w_r``
    (:func:`edge_slide_terms`) and ``G = sum_k u_k t_k`` the generalised force
    of the unit friction ``u`` on the tangential rows t_k, which the scratch
    holds at the friction centre there (``sc[SC_CENTRE]``, :func:`tangent_rows`):
    what :func:`~freestand.core.contact.body_kernel.solve_mode` gives on the
    EDGE's rows, to round-off, without assembling and solving them again.
    Fills ``sc[SC_ACC]`` and ``sc[SC_LAM]`` as it does; False where the system
    is singular.
    """
    det, first, second = _edge_normals(par, sc[SC_EDGE], share, sc[SC_CENTRE][2], u)
    if det == 0.0:
        return False
    return _edge_forces(par, sc, first / det, second / det, u)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _edge_forces(par, sc, n0, n1, u):
    """:func:`_edge_solution` from the corner forces N_0, N_1 [N] and the unit friction u."""
    tangent, work = sc[SC_TANGENT], sc[SC_WORK]
    q, force, response = work[0:2], work[6], work[7]  # the solve's work rows 6 and 7 are free
    for i in range(6):
        force[i] = u[0] * tangent[i, 0] + u[1] * tangent[i, 1] + u[2] * tangent[i, 2]
    apply_inverse_mass(par, sc[SC_INV], force, response)
    friction = par[P_MU_KINETIC] * (n0 + n1)
    acc, lam, base = sc[SC_ACC], sc[SC_LAM], sc[SC_BASE]
    for i in range(6):
        acc[i] = base[i] + n0 * q[0, i] + n1 * q[1, i] - friction * response[i]
    lam[0], lam[1] = n0, n1
    for k in range(3):
        lam[2 + k] = -friction * u[k]
    return True


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
def prepare_held(par, record, dt, t, y, mode, data, sc, tangential=True):
    """:func:`prepare` for the held mode at (t, y), its pivot at the stored rim angle's point
    (``tangential`` as in :func:`held_rows`)."""
    rotation_matrix(y, sc[SC_ROT])
    prepare_load(par, record, dt, t, y, sc)
    return held_rows(par, y, mode, data, sc, tangential)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def held_rows(par, y, mode, data, sc, tangential=True):
    """The held mode's rows at the rotation the scratch holds, its pivot at the stored rim
    angle's point (:func:`prepare_held`, :func:`sticking_stage`); (normal, tangential) rows.
    ``tangential`` False: a FACE's or EDGE's tangential rows not computed
    (``body_kernel.patch_rows``)."""
    kind = mode[M_KIND]
    cos_psi, sin_psi = pivot_direction(par, sc[SC_ROT], kind, data[D_PSI], sc)
    return scratch_rows(par, y, kind, mode[M_INDEX], cos_psi, sin_psi, sc, tangential)


@kernel(cache=True, error_model="numpy", _nrt=False)
def solve_at(par, record, dt, t, y, mode, data, sc):
    """Solve the held mode at (t, y): fills sc[SC_ACC] and sc[SC_LAM]; False if singular.

    A sliding patch slides along its slip velocity (:func:`slip_direction`)
    and its friction acts about its centre of pressure (:func:`solve_patch`).
    Returns (ok, normal rows, tangential rows).
    """
    return _solve_held_mode(par, record, dt, t, y, mode, data, sc, False)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _solve_held_mode(par, record, dt, t, y, mode, data, sc, stage):
    """:func:`solve_at`; ``stage``: an RK4 stage's, which reads the accelerations alone
    (:func:`solve_patch`). A sliding EDGE's tangential rows are computed by its solve alone,
    at the centre of pressure it finds (:func:`_slide_edge`), not first at its midpoint."""
    sliding_edge = mode[M_KIND] == EDGE and mode[M_SLIP] == 1
    n_normal, n_tangent = prepare_held(par, record, dt, t, y, mode, data, sc, not sliding_edge)
    ok = solve_patch(par, y, sc, True, mode[M_SLIP], sc[SC_DIR], mode[M_SLIP] == 1, data,
                     n_normal, n_tangent, stage)  # fmt: skip
    return ok, n_normal, n_tangent


@kernel(cache=True, error_model="numpy", _nrt=False)
def solve_at_centre(par, record, dt, t, y, mode, data, sc):
    """A sticking mode solved with its rows at the patch's geometric centre.

    The multipliers are then linear in the applied load (the rest phase's
    unit solutions, ``body_engine.rest_prepare``); :func:`centre_stick_friction`
    expresses their friction about the centre of pressure. The accelerations
    are :func:`solve_at`'s to the last bit (an RK4 stage's solve, :func:`rate`). Returns
    (ok, normal rows, tangential rows).
    """
    n_normal, n_tangent = prepare_held(par, record, dt, t, y, mode, data, sc)
    ok = _solve_scratch(par, sc, True, 0, sc[SC_DIR], n_normal, n_tangent)
    return ok, n_normal, n_tangent


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def closed_form(mode):
    """Whether the held mode is solved by its closed form (:func:`sticking_stage`): a sticking
    POINT or EDGE."""
    return mode[M_SLIP] == 0 and (mode[M_KIND] == POINT or mode[M_KIND] == EDGE)


@kernel(cache=True, error_model="numpy", _nrt=False)
def sticking_stage(par, record, dt, t, y, mode, data, sc, rows=True):
    """A sticking POINT's or EDGE's accelerations at (t, y) in ``sc[SC_ACC]``; False if singular.

    Its closed form in force form (``body_kernel.sticking_point_from_force``,
    ``sticking_edge_from_force``) on the applied wrench f_0 alone: what
    :func:`solve_at_centre` gives to round-off without the world inverse
    inertia and ``M^-1 f_0``, which an RK4 stage does not read (the
    scratch's ``SC_INV`` and ``SC_BASE`` are left as they were: every
    stage is followed by a full solve before anything reads them). The
    stage of a rolling cylinder or a rocking box is its most frequent solve.
    ``rows`` False (an RK4 stage's, :func:`rate`): a POINT's arm and its rows'
    biases alone (``body_kernel.point_arm_and_biases``), all its closed form
    reads, not its rows, which nothing reads before the step's end is solved
    in full (the scratch's rows are left as they were): the same
    accelerations and forces to the last bit.
    """
    rotation_matrix(y, sc[SC_ROT])
    prepare_wrench(par, record, dt, t, y, sc)
    return _sticking_on_load(par, y, mode, data, sc, rows)


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _sticking_on_load(par, y, mode, data, sc, rows=True):
    """:func:`sticking_stage` at the rotation and applied wrench the scratch holds: the held
    rows (a POINT's arm and biases alone where not ``rows``), then the closed form."""
    f0 = sc[SC_F0]
    if rows or mode[M_KIND] != POINT:
        held_rows(par, y, mode, data, sc)
    else:
        cos_psi, sin_psi = pivot_direction(par, sc[SC_ROT], POINT, data[D_PSI], sc)
        point_arm_and_biases(par, y, sc, mode[M_INDEX], cos_psi, sin_psi)
    force = (f0[0], f0[1], f0[2], f0[3], f0[4], f0[5])
    if mode[M_KIND] == POINT:
        return sticking_point_from_force(par, sc, force, True, sc[SC_ACC], sc[SC_LAM])
    return sticking_edge_from_force(par, sc, force, True, sc[SC_ACC], sc[SC_LAM])


@kernel(cache=True, error_model="numpy", _nrt=False)
def sticking_solve(par, record, dt, t, y, mode, data, sc, loaded=False):
    """A sticking POINT's or EDGE's :func:`solve_at` on its closed form; False if singular.

    :func:`sticking_stage`, then, an EDGE's, its friction expressed about its
    centre of pressure and its tangential rows moved there, as
    :func:`solve_patch` does after its solve
    (``body_kernel.centre_stick_friction``, ``tangent_rows``): the
    multipliers, accelerations and rows of :func:`solve_at` to round-off,
    without the world inverse inertia and ``M^-1 f_0`` (``SC_INV``,
    ``SC_BASE``), which an impact, a projection and a choice of mode prepare
    for themselves. ``loaded``: the scratch holds the rotation and the
    applied wrench at (t, y) already (a step's end solved for another pivot
    of a rolling cylinder's rim): only the rows and the closed form are
    computed, to the same last bit.
    """
    if loaded:
        ok = _sticking_on_load(par, y, mode, data, sc)
    else:
        ok = sticking_stage(par, record, dt, t, y, mode, data, sc)
    if mode[M_KIND] == EDGE:
        centre = sc[SC_CENTRE]
        centre[5] = 0.0  # as solve_patch: no stored direction read
        centre_stick_friction(par, sc[SC_ROT], EDGE, mode[M_INDEX], 2, sc[SC_LAM], centre)
        tangent_rows(par, y, sc)
    return ok


@kernel(cache=True, error_model="numpy", _nrt=False)
def rate(par, record, dt, t, y, mode, data, sc, ydot):
    """y' of the held mode at (t, y); False when the mode's system is singular.

    ``r' = v``, ``q' = (0, omega) q / 2`` (omega in the support frame),
    ``(v', omega') = x''``. A sticking POINT or EDGE is solved by its closed
    form on the applied wrench alone (:func:`sticking_stage`; a POINT on its
    arm and biases, without its rows), any other
    sticking mode at its rows' centre (:func:`solve_at_centre`): their
    accelerations are those of :func:`solve_at`, to round-off and to the
    last bit, which only expresses the forces about the centre of pressure
    after the same solve; an integrator's stage reads none of them.
    """
    if closed_form(mode):
        ok = sticking_stage(par, record, dt, t, y, mode, data, sc, False)
    elif mode[M_SLIP] == 0:
        ok, _, _ = solve_at_centre(par, record, dt, t, y, mode, data, sc)
    else:
        ok, _, _ = _solve_held_mode(par, record, dt, t, y, mode, data, sc, True)
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
