"""Screening of a 3-D body at rest: its initial motion and uplift threshold per direction.

A body resting flat on the support (issue #18) under a horizontal support
acceleration of magnitude a in direction phi (unit u = (cos phi, sin phi)) and
a downward vertical support acceleration a_v carries, in the support's frame,
the loads m g_e with ``g_e = (-a u, -(g - a_v))`` at its centre of gravity G.

**Uplift** (statics; Housner 1963 in a plane, generalised): the body stays
seated while the line of action of m g_e meets the base plane inside the base.
It meets it at ``G_xy - (h a / (g - a_v)) u``, so uplift begins at::

    a* = (g - a_v) rho(phi) / h

with h the height of G and rho the distance from G_xy along -u to the base's
outline (:func:`freestand.core.body.base_ray_distance`): for a box centred on
its base ``min(b_x / |cos phi|, b_y / |sin phi|)``, for a cylinder R. The body
then rocks about the edge that point crosses (a corner only on the diagonal;
for a cylinder, the tangent to the rim at that point).

**Initial motion** (the complementarity problem at rest, as the planar
screening of the paper's section 3; the choice rule: static friction holds
where it can):

- rest while ``a <= a*`` and ``a <= mu_0 (g - a_v)``;
- rock when ``a > a*`` and rocking about the pivot line with the pivot
  sticking is admissible (static friction holds first): from rest
  (omega = 0) the angular acceleration about the pivot axis e through the
  pivot P is
  ``alpha = e . (d x m g_e) / (e . I_P e)``, d = G - P, I_P = I_G + m (|d|^2 1 - d d^T);
  the contact force ``F = m alpha e x d - m g_e`` must have ``F_z >= 0`` and
  ``|F_xy| <= mu_0 F_z`` (the circular cone);
- otherwise slide (flat) when the base cannot hold, ``a > mu_0 (g - a_v)``
  (break-away with the static coefficient), and the base stays flat while
  sliding: the kinetic friction mu m (g - a_v) at the base, the only
  horizontal force, moves the centre of pressure by ``mu h`` from G_xy
  towards -u whatever a is, which must stay inside the base (``mu h <= rho``);
- slide-rock otherwise (the pivot slides while the body tips; its forces from
  the time-history engine's mode choice, :func:`sliding_pivot`);
- free flight when ``a_v >= g``.

Sliding starts in the direction of the inertial force, -u, and in 3-D its
friction opposes it on the circular cone, so a diagonal motion slides as an
axis-aligned one of the same magnitude.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from freestand.core.body import Body, Box, base_ray_distance
from freestand.core.contact.body_kernel import (
    DATA_SIZE,
    EDGE,
    M_KIND,
    M_SLIP,
    POINT,
    SC_ACC,
    SC_LAM,
    body_parameters,
    new_scratch,
    normal_total,
)
from freestand.core.contact.body_modes import select_mode
from freestand.core.contact.body_solve import solve_at
from freestand.core.contact.screening import GRAVITY, Motion, vertical_label
from freestand.core.dynamics.body_history import initial_state
from freestand.core.dynamics.results import ContactTolerances

#: Relative tolerance [-] of the comparisons with the thresholds (round-off).
THRESHOLD_TOLERANCE = 1e-12


@dataclass(frozen=True)
class BodyInitialMotion:
    """Initial motion of a 3-D body at rest for one horizontal direction.

    Attributes
    ----------
    direction : float
        phi [rad]: direction of the horizontal support acceleration, from +x
        towards +y.
    horizontal, vertical, gravity : float
        a, a_v (downward positive) and g [m/s^2].
    motion : Motion
        rest, slide, rock, slide-rock or free-flight.
    pivot : str or None
        What it rocks about: ``"edge +x"``, ``"edge -y"``, ``"corner +x+y"``,
        ``"rim at 180 deg"``; None when it does not rock.
    slide_direction : float or None
        Direction [rad] of the slide relative to the support (that of the
        inertial force, phi + pi), None when it does not slide.
    uplift_threshold : float
        a* [m/s^2] in this direction (with this a_v).
    slide_threshold : float
        mu_0 (g - a_v) [m/s^2].
    normal_force : float
        N [N] on the body from the support at the instant (the rocking's
        pivot force when it rocks).
    tangential_force : tuple of float
        (F_x, F_y) [N] on the body from the support.
    angular_acceleration : float
        About the pivot axis [rad/s^2] when it rocks, else 0.
    """

    direction: float
    horizontal: float
    vertical: float
    gravity: float
    motion: Motion
    pivot: str | None
    slide_direction: float | None
    uplift_threshold: float
    slide_threshold: float
    normal_force: float
    tangential_force: tuple[float, float]
    angular_acceleration: float


def uplift_threshold(body: Body, direction: float, vertical: float = 0.0,
                     gravity: float = GRAVITY) -> float:  # fmt: skip
    """Horizontal support acceleration a* [m/s^2] at which the body starts to rock.

    ``a* = (g - a_v) rho(phi) / h`` (module docstring); ``direction`` phi
    [rad], ``vertical`` a_v [m/s^2] downward positive, ``gravity`` g [m/s^2].
    Zero when ``a_v >= g`` (weightless: it lifts at once).
    """
    weight = gravity - vertical
    if weight <= 0.0:
        return 0.0
    away = (-math.cos(direction), -math.sin(direction))
    return weight * base_ray_distance(body.shape, body.centre[:2], away) / body.centre_height


def _pivot(body: Body, direction: float) -> tuple[np.ndarray, list[np.ndarray], str]:
    """Pivot point P (3,), candidate axes (unit, horizontal) and a label, for tipping towards -u."""
    w = np.array([-math.cos(direction), -math.sin(direction)])
    origin = np.asarray(body.centre[:2])
    distance = base_ray_distance(body.shape, origin, w)
    point = np.array([*(origin + distance * w), 0.0])
    if not isinstance(body.shape, Box):
        angle = round(math.degrees(math.atan2(point[1], point[0]))) % 360
        return point, [np.array([-w[1], w[0], 0.0])], f"rim at {angle} deg"
    bx, by = 0.5 * body.shape.size[0], 0.5 * body.shape.size[1]
    on_x = abs(abs(point[0]) - bx) <= 1e-9 * bx
    on_y = abs(abs(point[1]) - by) <= 1e-9 * by
    sx = "+x" if point[0] > 0 else "-x"
    sy = "+y" if point[1] > 0 else "-y"
    if on_x and on_y:
        point = np.array([math.copysign(bx, point[0]), math.copysign(by, point[1]), 0.0])
        return (
            point,
            [np.array([0.0, 1.0, 0.0]), np.array([1.0, 0.0, 0.0]), None],
            f"corner {sx}{sy}",
        )
    if on_x:
        return point, [np.array([0.0, 1.0, 0.0])], f"edge {sx}"
    return point, [np.array([1.0, 0.0, 0.0])], f"edge {sy}"


def pivot_label(body: Body, direction: float) -> str:
    """What the body tips about once it lifts under a support acceleration in ``direction`` [rad].

    ``"edge +x"`` (the base edge at x = +l_x/2), ``"corner -x+y"``, ``"rim at 180 deg"``:
    where the line of action of weight and inertial force leaves the base
    (module docstring).
    """
    return _pivot(body, direction)[2]


def _base_points(body: Body) -> np.ndarray:
    if isinstance(body.shape, Box):
        return body.shape.base_corners()
    angles = np.linspace(0.0, 2.0 * math.pi, 73)[:-1]
    radius = body.shape.radius
    return np.column_stack([radius * np.cos(angles), radius * np.sin(angles), 0 * angles])


def _rocking(body: Body, load: np.ndarray, pivot: np.ndarray, axes) -> tuple | None:
    """(alpha vector [rad/s^2], contact force [N]) of the admissible sticking rotation, or None."""
    d = np.asarray(body.centre) - pivot
    inertia = body.inertia + body.mass * (d @ d * np.eye(3) - np.outer(d, d))
    moment = np.cross(d, load)
    points = _base_points(body) - pivot
    scale = np.linalg.norm(moment) / max(np.linalg.eigvalsh(inertia).min(), 1e-300)
    for axis in axes:
        if axis is None:  # rotation about a point (a corner): free angular acceleration
            alpha = np.linalg.solve(inertia, moment)
        else:
            alpha = (axis @ moment) / (axis @ inertia @ axis) * axis
        # every other base point rises (or stays): the gap accelerations (alpha x s)_z >= 0
        rises = np.cross(alpha, points)[:, 2] >= -1e-9 * scale * np.abs(points).max()
        if not rises.all() or np.linalg.norm(alpha) <= 1e-12 * scale:
            continue
        force = body.mass * np.cross(alpha, d) - load
        return alpha, force
    return None


def sliding_pivot(body: Body, horizontal: float, direction: float, vertical: float = 0.0,
                  gravity: float = GRAVITY) -> tuple | None:  # fmt: skip
    """(N [N], (F_x, F_y) [N], |omega'| [rad/s^2]) of a slide-rock start, or None.

    The body at rest under the support acceleration ``horizontal`` [m/s^2]
    along ``direction`` [rad] (and ``vertical`` a_v downward): the contact
    mode the time-history engine starts in
    (:func:`freestand.core.contact.body_modes.select_mode`: the pivot's slip
    direction u with ``s'(u)`` along u and the kinetic friction
    ``-mu N u``), solved for its contact force and angular acceleration.
    None when that mode is not an edge or a point that slides.
    """
    par = body_parameters(body, gravity)
    tolerances = ContactTolerances()
    record = np.zeros((3, 2))
    record[0, :] = horizontal * math.cos(direction)
    record[1, :] = horizontal * math.sin(direction)
    record[2, :] = vertical
    y = initial_state(body)  # flat on the support, at rest
    mode = np.zeros(3, dtype=np.int64)
    data = np.zeros(DATA_SIZE)
    scratch = new_scratch()
    none = np.array([-1, 0, 0], dtype=np.int64)
    chosen = select_mode(par, record, 1.0, 0.0, y, scratch, tolerances.gap, tolerances.velocity,
                         mode, data, none)  # fmt: skip
    if chosen < 0 or mode[M_SLIP] != 1 or mode[M_KIND] not in (EDGE, POINT):
        return None
    solve_at(par, record, 1.0, 0.0, y, mode, data, scratch)
    lam = scratch[SC_LAM]
    n_normal = 1 if mode[M_KIND] == POINT else 2
    force = (float(lam[n_normal]), float(lam[n_normal + 1]))
    return float(normal_total(mode[M_KIND], lam)), force, float(np.linalg.norm(scratch[SC_ACC][3:]))


def initial_motion(
    body: Body, horizontal: float, direction: float, vertical: float = 0.0,
    gravity: float = GRAVITY,
) -> BodyInitialMotion:  # fmt: skip
    """Initial motion of the body at rest (module docstring) for one direction.

    Parameters
    ----------
    body : Body
        The body, flat on the support.
    horizontal : float
        a [m/s^2], >= 0.
    direction : float
        phi [rad] of the support acceleration.
    vertical : float, optional
        a_v [m/s^2], downward positive.
    gravity : float, optional
        g [m/s^2].

    Returns
    -------
    BodyInitialMotion
        For slide-rock the forces and the angular acceleration are the
        engine's starting mode's (:func:`sliding_pivot`); NaN where it has
        none.
    """
    weight = gravity - vertical
    u = np.array([math.cos(direction), math.sin(direction), 0.0])
    slide_threshold = body.friction.static * max(weight, 0.0)

    def state(motion, pivot=None, sliding=False, normal=math.nan, force=(math.nan, math.nan),
              alpha=math.nan):  # fmt: skip
        return BodyInitialMotion(
            direction=direction, horizontal=horizontal, vertical=vertical, gravity=gravity,
            motion=motion, pivot=pivot,
            slide_direction=(direction + math.pi) % (2.0 * math.pi) if sliding else None,
            uplift_threshold=uplift_threshold(body, direction, vertical, gravity),
            slide_threshold=slide_threshold, normal_force=normal,
            tangential_force=(float(force[0]), float(force[1])), angular_acceleration=alpha,
        )  # fmt: skip

    if weight <= 0.0:
        return state(Motion.FREE_FLIGHT, normal=0.0, force=(0.0, 0.0), alpha=0.0)
    load = body.mass * np.array([-horizontal * u[0], -horizontal * u[1], -weight])
    slack = 1.0 + THRESHOLD_TOLERANCE
    tips = horizontal > uplift_threshold(body, direction, vertical, gravity) * slack
    label = _pivot(body, direction)[2]
    if tips:
        pivot, axes, label = _pivot(body, direction)
        rocking = _rocking(body, load, pivot, axes)
        if rocking is not None:
            alpha, force = rocking
            normal = float(force[2])
            if normal >= 0.0 and math.hypot(*force[:2]) <= body.friction.static * normal * slack:
                return state(Motion.ROCK, label, normal=normal, force=force,
                             alpha=float(np.linalg.norm(alpha)))  # fmt: skip
    elif horizontal <= slide_threshold * slack:
        return state(Motion.REST, normal=body.mass * weight, force=-load, alpha=0.0)
    reach = base_ray_distance(body.shape, body.centre[:2], (-u[0], -u[1]))
    friction = body.friction.kinetic * body.mass * weight * u
    stays_flat = body.friction.kinetic * body.centre_height <= reach * slack
    if horizontal > slide_threshold * slack and stays_flat:
        return state(Motion.SLIDE, sliding=True, normal=body.mass * weight, force=friction,
                     alpha=0.0)  # fmt: skip
    start = sliding_pivot(body, horizontal, direction, vertical, gravity)
    if start is None:
        return state(Motion.SLIDE_ROCK, label, sliding=True)
    normal, force, alpha = start
    return state(Motion.SLIDE_ROCK, label, sliding=True, normal=normal, force=force, alpha=alpha)


def screen_directions(
    body: Body, horizontal: float, vertical: float = 0.0, count: int = 24,
    gravity: float = GRAVITY,
) -> tuple[BodyInitialMotion, ...]:  # fmt: skip
    """:func:`initial_motion` for ``count`` directions evenly over 0-360 deg (every 15 deg)."""
    if count < 1:
        raise ValueError(f"count must be at least 1, not {count!r}")
    return tuple(
        initial_motion(body, horizontal, 2.0 * math.pi * k / count, vertical, gravity)
        for k in range(count)
    )


@dataclass(frozen=True)
class BodyScreeningCase:
    """The screening of a 3-D configuration under one excitation: every direction swept.

    The excitation's horizontal components (x, y) give its magnitude
    ``a = sqrt(x^2 + y^2)`` and its own direction ``phi_e = atan2(y, x)``.
    Each direction phi of the sweep is screened under the magnitude a
    (:func:`initial_motion`), so the sweep answers "what if the excitation
    came from there", and ``at_excitation`` is the state in phi_e itself.

    Attributes
    ----------
    configuration, body : str
        Names.
    excitation : str
        The excitation's name (``"<name> (a_v down)"`` when analysed both ways).
    x, y : float
        The excitation's horizontal components [m/s^2].
    horizontal : float
        a = sqrt(x^2 + y^2) [m/s^2].
    excitation_direction : float
        phi_e [rad] in [0, 2 pi).
    vertical, gravity : float
        a_v (downward positive) and g [m/s^2].
    directions : tuple of BodyInitialMotion
        The sweep, evenly over 0-360 deg from +x.
    at_excitation : BodyInitialMotion
        The state in the excitation's own direction.
    """

    configuration: str
    body: str
    excitation: str
    x: float
    y: float
    horizontal: float
    excitation_direction: float
    vertical: float
    gravity: float
    directions: tuple[BodyInitialMotion, ...]
    at_excitation: BodyInitialMotion

    @property
    def lowest_threshold(self) -> BodyInitialMotion:
        """The swept direction with the lowest uplift threshold (the first of equal ones)."""
        return min(self.directions, key=lambda state: state.uplift_threshold)


def screen_body_configuration(
    configuration, excitations, gravity: float = GRAVITY, vertical_senses: str | None = None,
    count: int = 24,
) -> list[BodyScreeningCase]:  # fmt: skip
    """Screen a 3-D configuration under every excitation, ``count`` directions each.

    Parameters
    ----------
    configuration : BodyConfiguration
        One body on the support.
    excitations : sequence of Excitation
        ``horizontal`` is the x component, ``horizontal_y`` the y component
        [m/s^2]; ``vertical`` a_v, downward positive.
    gravity : float, optional
        g [m/s^2].
    vertical_senses : str, optional
        As :func:`freestand.core.contact.screening.screen`: ``"both"``
        analyses a_v downward and upward (cases named ``"<name> (a_v down)"``
        and ``"(a_v up)"``), None follows each excitation's own.
    count : int, optional
        Directions evenly over 0-360 deg (24: every 15 deg).

    Returns
    -------
    list of BodyScreeningCase
        In the order excitation, vertical sense (downward first).
    """
    body = configuration.body
    cases = []
    for excitation in excitations:
        if vertical_senses is not None:
            excitation = replace(excitation, vertical_senses=vertical_senses)
        verticals = excitation.verticals()
        x, y = float(excitation.horizontal), float(excitation.horizontal_y)
        magnitude = math.hypot(x, y)
        own = math.atan2(y, x) % (2.0 * math.pi)
        for vertical in verticals:
            cases.append(
                BodyScreeningCase(
                    configuration=configuration.name, body=body.name,
                    excitation=vertical_label(excitation.name, vertical, len(verticals) > 1),
                    x=x, y=y, horizontal=magnitude, excitation_direction=own,
                    vertical=vertical, gravity=gravity,
                    directions=screen_directions(body, magnitude, vertical, count, gravity),
                    at_excitation=initial_motion(body, magnitude, own, vertical, gravity),
                )
            )  # fmt: skip
    return cases


def threshold_curve(
    body: Body, vertical: float = 0.0, gravity: float = GRAVITY, points: int = 720
) -> tuple[np.ndarray, np.ndarray]:
    """The uplift threshold a*(phi) [m/s^2] as a closed curve, for figures.

    ``points`` directions evenly over 0-360 deg, plus those in which the
    ray from G's projection along -u meets a corner of a box's base (the
    curve's kinks), sorted; the first point is repeated at 2 pi.

    Returns
    -------
    tuple of numpy.ndarray
        Directions phi [rad] and a*(phi) [m/s^2].
    """
    directions = np.linspace(0.0, 2.0 * math.pi, points, endpoint=False)
    if isinstance(body.shape, Box):
        offsets = np.asarray(body.centre[:2]) - body.shape.base_corners()[:, :2]
        kinks = np.arctan2(offsets[:, 1], offsets[:, 0]) % (2.0 * math.pi)
        directions = np.union1d(directions, kinks)
    directions = np.append(directions, 2.0 * math.pi)
    thresholds = np.array([uplift_threshold(body, phi, vertical, gravity) for phi in directions])
    return directions, thresholds
