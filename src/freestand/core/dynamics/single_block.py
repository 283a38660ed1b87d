"""Exact equations of one rigid block on a rigid support: the fast time-history path.

A single block on the support under a sampled record either rests, rocks
without slipping, or slides without lifting off, as long as the assumptions
of each motion hold; each of these motions has an exact equation that is
integrated far faster than the general stack path
(:func:`freestand.core.dynamics.timehistory.simulate_general`):

* rocking about either lower contact with impacts (Housner 1963; Zhang and
  Makris 2001): the compiled integrator of
  :mod:`freestand.core.rocking.integrator`, with the vertical record entering
  as the effective gravity ``g - a_v(t)``;
* sliding without rotation (Newmark 1965): the exact event-driven solver of
  :mod:`freestand.core.dynamics.sliding`.

Each result is checked against the assumptions that make it a solution of the
full problem (the same contact problem as the general path):

rocking (or rest)
    the normal force stays non-negative, ``N = m (a_Gz + g - a_v) >= 0`` (no
    free flight), and the friction the motion needs stays in the static cone,
    ``|T| <= mu_0 N`` with ``T = m (a_Gx + a_h)`` (no slip; an end stop or
    ``sliding = "none"`` supplies the force the way it blocks), at every
    integration step, and the impulses at every impact lie in the static cone;
sliding
    ``g - a_v > 0`` throughout and neither lower contact unloads: with the
    friction force ``T`` (``m a_h`` while sticking, ``-sgn(s') mu N`` while
    sliding) the moment balance about the centre of gravity gives
    ``N_left = (b_R N + h T) / (b_L + b_R) >= 0`` and
    ``N_right = (b_L N - h T) / (b_L + b_R) >= 0``; where the block starts to
    slip the static friction ``mu_0 N`` must not lift it, ``mu_0 h <= b`` on
    that side. Sliding against an end stop is left to the general path.

When neither motion passes, the caller (the front end
:func:`freestand.core.dynamics.timehistory.simulate`) runs the general path and
reports the failed assumption in ``diagnostics.fallback``.

References
----------
.. [1] G. W. Housner, Bull. Seismol. Soc. Am. 53(2), 403-417, 1963.
.. [2] J. Zhang and N. Makris, J. Eng. Mech. 127(5), 473-483, 2001.
.. [3] N. M. Newmark, Geotechnique 15(2), 139-160, 1965.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numba as nb
import numpy as np

from freestand.core.contact.screening import GRAVITY
from freestand.core.dynamics.results import (
    EVENT_TOLERANCE,
    UPLIFT_GAP_FRACTION,
    ContactTolerances,
    SupportMotion,
    TimeHistoryDiagnostics,
    TimeHistoryEvent,
    TimeHistoryResult,
    _peak_magnitude,
)
from freestand.core.dynamics.sliding import slide_block
from freestand.core.model import Block, Sliding, Stack
from freestand.core.motion.ground_motion import GroundMotion
from freestand.core.rocking.integrator import SampledAcceleration, largest_step
from freestand.core.rocking.integrator import simulate as simulate_rocking
from freestand.core.rocking.properties import RockingBlock


@dataclass(frozen=True)
class SingleBlockAttempt:
    """Outcome of the single-block path.

    Attributes
    ----------
    result : TimeHistoryResult or None
        The motion, when the assumptions of rest, rocking or sliding held;
        None otherwise.
    checks : tuple of str
        The assumptions checked, in words, with what was found.
    failure : str
        The assumption that failed (empty when ``result`` is given).
    """

    result: TimeHistoryResult | None
    checks: tuple[str, ...]
    failure: str


@dataclass(frozen=True)
class _Geometry:
    mass: float
    inertia: float
    half_left: float  # b_L = x_G - x_left [m]
    half_right: float  # b_R = x_right - x_G [m]
    height: float  # h = z_G - base level [m]

    @classmethod
    def of(cls, block: Block) -> _Geometry:
        return cls(
            block.mass,
            block.inertia,
            block.centre[0] - block.base_left,
            block.base_right - block.centre[0],
            block.centre[1] - block.base_level,
        )

    @property
    def width(self) -> float:
        return self.half_left + self.half_right


def _allows_violation(sliding: Sliding, needed: np.ndarray, limit: np.ndarray, tol: float):
    """Where the needed tangential force leaves the static cone the way the interface can slide.

    ``needed > limit`` slides the block to -x, ``needed < -limit`` to +x.
    """
    bad = np.zeros(needed.shape, dtype=bool)
    if sliding.allows(-1):
        bad |= needed > limit + tol
    if sliding.allows(+1):
        bad |= needed < -limit - tol
    return bad


def _support(excitation: SupportMotion, time: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(a_h, a_v) [m/s^2] at ``time`` [s], linear between samples, zero after the record."""
    grid = np.arange(excitation.horizontal.size) * excitation.time_step
    a_h = np.interp(time, grid, excitation.horizontal, left=0.0, right=0.0)
    if excitation.vertical is None:
        return a_h, np.zeros_like(a_h)
    return a_h, np.interp(time, grid, excitation.vertical, left=0.0, right=0.0)


def _message(end_time: float, overturned: bool) -> str:
    if overturned:
        return f"every block overturned (by t = {end_time:.6g} s)"
    return f"simulated to t = {end_time:.6g} s"


def _rest_outcome(result: TimeHistoryResult, resting: bool, excitation_end: float):
    """Status and message of a run asked to go on until rest (see ``simulate``'s ``until_rest``).

    ``"completed"`` when the block overturned or rests after the excitation's
    end, ``"capped"`` when it still moves at the end of the simulated time.
    """
    end_time = float(result.time[-1])
    if result.overturned.all():
        return result
    if resting and end_time >= excitation_end:
        return replace(result, message=f"at rest at t = {end_time:.6g} s")
    return replace(
        result, status="capped", message=f"still moving at the cap, t = {end_time:.6g} s"
    )


@nb.njit(cache=True)
def _rocking_state(theta, omega, side, a_h, g_eff, mass, inertia, half_left, half_right, height,
                   out):  # fmt: skip
    """Displacement, velocity and contact forces of the rocking (or resting) block per sample.

    ``out[k]``: centre displacement (x, z) [m] and velocity (x, z) [m/s], tangential and
    normal force on the block [N], normal force at the left and right contact [N]. About
    the pivot of side s (r the vector from the pivot to the centre, rotated by theta):
    ``I_O theta'' = m R (-s g' sin(alpha - s theta) + a_h cos(alpha - s theta))`` (Zhang
    and Makris 2001, with g' = g - a_v), ``a_G = theta'' perp(r) - omega^2 r``,
    ``T = m (a_Gx + a_h)``, ``N = m (a_Gz + g')``, all on the pivot; at rest
    (s = 0) the moment balance about the centre shares N between the contacts.
    """
    width = half_left + half_right
    for k in range(theta.shape[0]):
        s = side[k]
        if s == 0.0:
            tangential = mass * a_h[k]
            normal = mass * g_eff[k]
            right = (half_left * normal - height * tangential) / width
            out[k, 0] = 0.0
            out[k, 1] = 0.0
            out[k, 2] = 0.0
            out[k, 3] = 0.0
            out[k, 4] = tangential
            out[k, 5] = normal
            out[k, 6] = normal - right
            out[k, 7] = right
            continue
        r0x = half_left if s > 0.0 else -half_right
        c = math.cos(theta[k])
        sn = math.sin(theta[k])
        rx = c * r0x - sn * height
        rz = sn * r0x + c * height
        radius = math.hypot(r0x, height)
        alpha = math.atan2(abs(r0x), height)
        phase = alpha - s * theta[k]
        w = omega[k]
        acc = (
            mass
            * radius
            / (inertia + mass * radius * radius)
            * (-s * g_eff[k] * math.sin(phase) + a_h[k] * math.cos(phase))
        )
        tangential = mass * (-acc * rz - w * w * rx + a_h[k])
        normal = mass * (acc * rx - w * w * rz + g_eff[k])
        out[k, 0] = rx - r0x
        out[k, 1] = rz - height
        out[k, 2] = -w * rz
        out[k, 3] = w * rx
        out[k, 4] = tangential
        out[k, 5] = normal
        out[k, 6] = normal if s > 0.0 else 0.0
        out[k, 7] = 0.0 if s > 0.0 else normal


def _rocking(
    stack: Stack,
    excitation: SupportMotion,
    end: float,
    excitation_end: float,
    max_step: float,
    gravity: float,
    until_rest: bool = False,
) -> tuple[TimeHistoryResult | None, list[str], str]:
    """Rest or rocking without slip; (result or None, checks, failure)."""
    block = stack.blocks[0]
    geo = _Geometry.of(block)
    rocking_block = RockingBlock.from_block(block, "left", gravity=gravity)
    record = SampledAcceleration(
        excitation.horizontal, excitation.time_step, vertical=excitation.vertical
    )
    step = largest_step(rocking_block)
    step = step if max_step is None else min(max_step, step)
    capacity = int(end / step) + 2 * excitation.horizontal.size + 1000
    # the block settles when its corners land slower than the general path's
    # contact velocity tolerance
    rest_speed = ContactTolerances().velocity / geo.width
    while True:
        motion = simulate_rocking(
            rocking_block,
            record,
            t_end=end,
            history=True,
            max_step=step,
            max_history=capacity,
            rest_angular_velocity=rest_speed,
            stop_at_rest_after=excitation_end if until_rest else math.inf,
        )
        if motion.time.size < capacity:
            break
        capacity *= 4
    t, theta, omega = motion.time, motion.rotation, motion.angular_velocity
    # the general path's judgement once the excitation is over: past the
    # overturning angle and unable to come back (module notes of timehistory)
    overturned = motion.overturned
    overturn_time = motion.time_overturned if overturned else math.nan
    first = int(np.searchsorted(t, excitation_end))
    if first < t.size and not overturned:
        th, om = theta[first:], omega[first:]
        lever = np.where(th > 0.0, geo.half_left, geo.half_right)
        away = np.where(th > 0.0, om >= 0.0, om <= 0.0)
        critical = np.arctan2(lever, geo.height)
        radius = np.hypot(lever, geo.height)
        inertia_pivot = geo.inertia + geo.mass * radius**2
        barrier = geo.mass * gravity * radius * (1.0 - np.cos(np.abs(th) - critical))
        gone = (np.abs(th) > critical) & (away | (0.5 * inertia_pivot * om**2 < barrier))
        if gone.any():
            last = first + int(np.argmax(gone))
            t, theta, omega = t[: last + 1], theta[: last + 1], omega[: last + 1]
            overturned, overturn_time = True, float(t[-1])

    a_h, a_v = _support(excitation, t)
    g_eff = gravity - a_v
    side = np.sign(theta)
    side = np.where(side == 0.0, np.sign(omega), side)
    lifts = motion.uplift_log
    if lifts.size:
        # at the located instant a resting block starts to rock (the excitation crossing
        # its uplift threshold between samples, or a block settling at an impact while
        # the excitation is beyond the threshold) it already rocks on that side with
        # omega = 0: its forces are those of the pivot, not the rest moment balance
        starting = (side == 0.0) & np.isin(t, lifts[:, 0])
        if starting.any():
            order = np.searchsorted(lifts[:, 0], t[starting])
            side[starting] = np.sign(lifts[np.minimum(order, len(lifts) - 1), 1])
    resting = side == 0.0
    state = np.empty((t.size, 8))
    _rocking_state(
        theta, omega, side, a_h, g_eff, geo.mass, geo.inertia, geo.half_left, geo.half_right,
        geo.height, state,
    )  # fmt: skip
    tangential, normal, normal_left, normal_right = (
        state[:, 4],
        state[:, 5],
        state[:, 6],
        state[:, 7],
    )

    force_tol = EVENT_TOLERANCE * geo.mass * gravity
    checks = []
    unloaded = resting & (np.minimum(normal_left, normal_right) < -force_tol)
    if unloaded.any():
        k = int(np.argmax(unloaded))
        return None, checks, f"a contact unloads at rest at t = {t[k]:.6g} s"
    if np.any(normal < -force_tol):
        k = int(np.argmax(normal < -force_tol))
        return (
            None,
            checks,
            f"rocking: the normal force becomes negative at t = {t[k]:.6g} s (free flight)",
        )
    checks.append(f"rocking: normal force >= 0 throughout (least {np.min(normal):.6g} N)")
    bad = _allows_violation(block.sliding, tangential, block.friction.static * normal, force_tol)
    if bad.any():
        k = int(np.argmax(bad))
        return (
            None,
            checks,
            f"rocking: friction needed {tangential[k]:.6g} N exceeds mu_0 N = "
            f"{block.friction.static * normal[k]:.6g} N at t = {t[k]:.6g} s (the block slips)",
        )
    with np.errstate(divide="ignore", invalid="ignore"):
        usage = np.abs(tangential) / normal
    if block.sliding is Sliding.NONE:
        checks.append("rocking: sliding = none, friction unlimited")
    else:
        checks.append(
            f"rocking: |T| <= mu_0 N throughout (largest |T|/N {np.nanmax(usage, initial=0.0):.4g},"
            f" mu_0 = {block.friction.static:g})"
        )
    impacts = motion.impact_log
    impacts = impacts[impacts[:, 0] <= t[-1]] if impacts.size else impacts
    if impacts.size:
        time_impact, w_before, w_after = impacts.T
        old_left = w_before < 0.0  # returning from theta > 0: it was on the left pivot
        old_x = np.where(old_left, geo.half_left, -geo.half_right)
        new_x = np.where(old_left, -geo.half_right, geo.half_left)
        # impulse of the support = m (v_G+ - v_G-), v_G = omega perp(r)
        impulse_x = geo.mass * geo.height * (w_before - w_after)
        impulse_z = geo.mass * (w_after * new_x - w_before * old_x)
        scale = 1e-9 * geo.mass * np.abs(w_before) * np.hypot(old_x, geo.height)
        bad = (impulse_z < -scale) | _allows_violation(
            block.sliding, impulse_x, block.friction.static * impulse_z, scale
        )
        if bad.any():
            k = int(np.argmax(bad))
            return (
                None,
                checks,
                f"rocking: the impulse at the impact at t = {time_impact[k]:.6g} s is outside "
                "the static friction cone (the block slips at impact)",
            )
    if impacts.size:
        checks.append(f"rocking: {len(impacts)} impact impulses inside the static friction cone")

    # results in the general path's form
    width = geo.width
    phi = theta
    position = np.stack([state[:, 0], state[:, 1], phi], axis=1)
    velocity = np.stack([state[:, 2], state[:, 3], omega], axis=1)
    peak = float(np.max(np.abs(theta), initial=0.0))
    max_lift = width * math.sin(min(peak, 0.5 * math.pi))
    rocked = motion.rocked and max_lift > UPLIFT_GAP_FRACTION * width
    events = [TimeHistoryEvent(0.0, "start", -1, -1, ("rest",), np.zeros((1, 3)), np.zeros((1, 3)))]
    lifts = motion.uplift_log
    for time_lift, lift_side in lifts[lifts[:, 0] <= t[-1]] if lifts.size else lifts:
        events.append(
            TimeHistoryEvent(
                float(time_lift),
                "lift-off",
                0,
                1 if lift_side > 0 else 0,
                ("rock",),
                np.zeros((1, 3)),
                np.zeros((1, 3)),
            )
        )
    jumps = np.zeros((2, len(impacts), 1, 3))
    if len(impacts):
        jumps[0, :, 0, 2] = impacts[:, 1]
        jumps[1, :, 0, 2] = impacts[:, 2]
    for j, (time_impact, w_before, w_after) in enumerate(impacts.tolist()):
        events.append(
            TimeHistoryEvent(
                time_impact,
                "impact",
                0,
                1 if w_before < 0.0 else 0,
                ("rock",) if w_after != 0.0 else ("rest",),
                jumps[0, j],
                jumps[1, j],
            )
        )
    if overturned:
        events.append(
            TimeHistoryEvent(
                float(t[-1]), "overturn", 0, -1, ("overturned",), velocity[-1:], velocity[-1:0]
            )
        )
    events.sort(key=lambda event: event.time)
    method = "single-block rocking" if motion.rocked else "single-block rest"
    result = TimeHistoryResult(
        configuration=stack.name,
        block_names=(block.name,),
        status="completed",
        message=_message(float(t[-1]), overturned),
        time=t,
        position=position.reshape(-1, 1, 3),
        velocity=velocity.reshape(-1, 1, 3),
        normal_force=np.stack([normal_left, normal_right], axis=1).reshape(-1, 1, 2),
        tangential_force=tangential.reshape(-1, 1),
        relative_rotation=theta.reshape(-1, 1),
        slide=np.zeros((t.size, 1)),
        events=tuple(events),
        max_rotation=np.array([_peak_magnitude(t, theta, omega)]),
        max_slide=np.zeros(1),
        uplift=np.array([rocked]),
        free_flight=np.zeros(1, dtype=bool),
        overturned=np.array([overturned]),
        overturn_time=np.array([overturn_time]),
        diagnostics=TimeHistoryDiagnostics(
            time_step=step,
            steps=int(t.size),
            contact_solves=0,
            impact_solves=len(impacts),
            ambiguous_solves=0,
            max_penetration=0.0,
            max_projection=0.0,
            method=method,
            checks=tuple(checks),
        ),
        max_lift=np.array([max_lift if motion.rocked else 0.0]),
    )
    if until_rest:
        result = _rest_outcome(result, bool(resting[-1]), excitation_end)
    return result, checks, ""


def _sliding(
    stack: Stack,
    excitation: SupportMotion,
    end: float,
    gravity: float,
    excitation_end: float = math.inf,
    until_rest: bool = False,
) -> tuple[TimeHistoryResult | None, list[str], str]:
    """Sliding without rotation; (result or None, checks, failure)."""
    block = stack.blocks[0]
    geo = _Geometry.of(block)
    checks: list[str] = []
    if block.sliding is not Sliding.FREE:
        return None, checks, f"sliding: the interface is '{block.sliding}' (end stop)"
    dt = excitation.time_step
    last = math.ceil(end / dt - 1e-9)
    count = last + 1
    horizontal = np.zeros(count)
    vertical = np.zeros(count)
    used = min(count, excitation.horizontal.size)
    horizontal[:used] = excitation.horizontal[:used]
    if excitation.vertical is not None:
        vertical[:used] = excitation.vertical[:used]
    motion = GroundMotion(dt, horizontal, vertical if excitation.vertical is not None else None)
    mu_s, mu_k = block.friction.static, block.friction.kinetic
    sliding = slide_block(motion, mu_s, mu_k, gravity=gravity, until_rest=False)
    if sliding.contact_lost_time > 0.0:
        return None, checks, "sliding: g - a_v reaches zero (free flight)"
    if any("event limit" in message for message in sliding.messages):
        return None, checks, "sliding: event limit of the sliding solver reached"
    t = sliding.time[:count]
    s = sliding.displacement[:count]
    v = sliding.velocity[:count]
    if t[-1] > end * (1.0 + 1e-12):
        # the last sample lies past the end: cubic Hermite of (s, v) at the end
        h = t[-1] - t[-2]
        x = (end - t[-2]) / h
        y0, y1, m0, m1 = s[-2], s[-1], v[-2] * h, v[-1] * h
        s_end = (
            (2 * x**3 - 3 * x**2 + 1) * y0
            + (x**3 - 2 * x**2 + x) * m0
            + (-2 * x**3 + 3 * x**2) * y1
            + (x**3 - x**2) * m1
        )
        v_end = v[-2] + x * (v[-1] - v[-2])
        t, s, v = t.copy(), s.copy(), v.copy()
        t[-1], s[-1], v[-1] = end, s_end, v_end
    if until_rest:
        # once the excitation is over a block that has stopped stays at rest
        stopped = np.flatnonzero((t >= excitation_end) & (v == 0.0))
        if stopped.size:
            last = int(stopped[0])
            t, s, v = t[: last + 1], s[: last + 1], v[: last + 1]
    a_h, a_v = _support(excitation, t)
    normal = geo.mass * (gravity - a_v)
    direction = np.sign(v)
    tangential = np.where(
        direction != 0.0,
        -direction * mu_k * normal,
        np.clip(geo.mass * a_h, -mu_s * normal, mu_s * normal),
    )
    normal_right = (geo.half_left * normal - geo.height * tangential) / geo.width
    normal_left = normal - normal_right
    force_tol = EVENT_TOLERANCE * geo.mass * gravity
    lowest = np.minimum(normal_left, normal_right)
    if np.any(lowest < -force_tol):
        k = int(np.argmax(lowest < -force_tol))
        return None, checks, f"sliding: a contact unloads at t = {t[k]:.6g} s (the block lifts)"
    if np.any(v < 0.0) and mu_s * geo.height > geo.half_left:
        return None, checks, "sliding: static friction at a slip start to -x lifts the block"
    if np.any(v > 0.0) and mu_s * geo.height > geo.half_right:
        return None, checks, "sliding: static friction at a slip start to +x lifts the block"
    checks.append(
        f"sliding: both contacts loaded throughout (least {float(np.min(lowest)):.6g} N), "
        "g - a_v > 0"
    )
    events = [TimeHistoryEvent(0.0, "start", -1, -1, ("rest",), np.zeros((1, 3)), np.zeros((1, 3)))]
    moving = direction != 0.0
    for k in np.flatnonzero(moving[1:] != moving[:-1]) + 1:
        kind = "slip" if moving[k] else "slip-stop"
        events.append(
            TimeHistoryEvent(
                float(t[k]),
                kind,
                0,
                -1,
                ("slide",) if moving[k] else ("rest",),
                np.array([[v[k - 1], 0.0, 0.0]]),
                np.array([[v[k], 0.0, 0.0]]),
            )
        )
    position = np.zeros((t.size, 1, 3))
    position[:, 0, 0] = s
    velocity = np.zeros((t.size, 1, 3))
    velocity[:, 0, 0] = v
    slid = sliding.slip_starts > 0
    result = TimeHistoryResult(
        configuration=stack.name,
        block_names=(block.name,),
        status="completed",
        message=_message(float(t[-1]), False),
        time=t,
        position=position,
        velocity=velocity,
        normal_force=np.stack([normal_left, normal_right], axis=1).reshape(-1, 1, 2),
        tangential_force=tangential.reshape(-1, 1),
        relative_rotation=np.zeros((t.size, 1)),
        slide=s.reshape(-1, 1),
        events=tuple(events),
        max_rotation=np.zeros(1),
        max_slide=np.array([_peak_magnitude(t, s, v)]),
        uplift=np.zeros(1, dtype=bool),
        free_flight=np.zeros(1, dtype=bool),
        overturned=np.zeros(1, dtype=bool),
        overturn_time=np.full(1, np.nan),
        diagnostics=TimeHistoryDiagnostics(
            time_step=dt,
            steps=int(t.size),
            contact_solves=0,
            impact_solves=0,
            ambiguous_solves=0,
            max_penetration=0.0,
            max_projection=0.0,
            method="single-block sliding" if slid else "single-block rest",
            checks=tuple(checks),
        ),
        max_lift=np.zeros(1),
    )
    if until_rest:
        result = _rest_outcome(result, bool(v[-1] == 0.0), excitation_end)
    return result, checks, ""


def simulate_single_block(
    stack: Stack,
    excitation: SupportMotion,
    duration: float | None = None,
    *,
    max_step: float | None = None,
    gravity: float = GRAVITY,
    excitation_end: float | None = None,
    until_rest: bool = False,
) -> SingleBlockAttempt:
    """Time history of one block on the support from the exact rocking or sliding equations.

    Parameters
    ----------
    stack : Stack
        One block on the support (base level 0), at rest at ``t = 0``.
    excitation : SupportMotion
        Horizontal a_h [m/s^2] (+x) and downward a_v [m/s^2] support
        accelerations, linear between samples, zero after the record.
    duration : float, optional
        End time [s]; by default the end of the record.
    max_step : float, optional
        Largest step [s] of the rocking integrator; by default 0.02 / p (p
        the larger frequency parameter of the two pivots). Steps also end on
        every record sample, and at impacts and starts of rocking, located
        exactly. The sliding solver is exact for the piecewise-linear record
        and needs no step.
    gravity : float, optional
        g [m/s^2].
    excitation_end : float, optional
        Time [s] after which the overturning judgement of the general path
        applies (a block past its overturning angle that cannot come back has
        overturned); by default the end of the record.
    until_rest : bool, optional
        Stop at the first instant after ``excitation_end`` at which the block
        rests on the support (both contacts closed, no motion: a rocking
        block settles when its angular velocity after an impact is below
        :class:`~freestand.core.dynamics.results.ContactTolerances` ``velocity
        / base width``, a sliding block when its slip velocity is zero);
        ``duration`` is then the cap. Status ``"completed"`` (at rest, or
        overturned) or ``"capped"`` (still moving at the cap).

    Returns
    -------
    SingleBlockAttempt
        With a :class:`~freestand.core.dynamics.timehistory.TimeHistoryResult` in the
        general path's form when the rocking (or rest) motion or the sliding
        motion satisfies its assumptions (see the module notes); the failed
        assumptions otherwise.

    Notes
    -----
    Rocking: ``I_O theta'' = m R [-s (g - a_v) sin(alpha - s theta) + a_h
    cos(alpha - s theta)]`` about the left contact (theta > 0, s = +1) or
    the right one, Housner's impact about the new pivot (Housner 1963, eq. 4;
    Zhang and Makris 2001, eqs. 10-12). Sliding: ``s'' = -a_h - sgn(s') mu
    (g - a_v)`` (Newmark 1965). The assumptions are checked at every step of
    the rocking integrator and at every record sample of the sliding solver;
    the sliding path's events are reported at the first sample after them.
    """
    if len(stack.blocks) != 1:
        raise ValueError(f"the single-block path needs one block, not {len(stack.blocks)}")
    block = stack.blocks[0]
    end = excitation.duration if duration is None else float(duration)
    if not end > 0.0:
        raise ValueError(f"duration must be positive, not {end!r}")
    if excitation_end is None:
        excitation_end = excitation.duration
    geo = _Geometry.of(block)
    if not (geo.half_left > 0.0 and geo.half_right > 0.0 and geo.height > 0.0):
        return SingleBlockAttempt(
            None, (), "the centre of gravity is not above the base (no rest position)"
        )
    result, checks, failure = _rocking(
        stack, excitation, end, excitation_end, max_step, gravity, until_rest
    )
    if result is not None:
        return SingleBlockAttempt(result, tuple(checks), "")
    result, sliding_checks, sliding_failure = _sliding(
        stack, excitation, end, gravity, excitation_end, until_rest
    )
    checks = [*checks, f"failed: {failure}", *sliding_checks]
    if result is not None:
        result = replace(result, diagnostics=replace(result.diagnostics, checks=tuple(checks)))
        return SingleBlockAttempt(result, tuple(checks), "")
    return SingleBlockAttempt(None, tuple(checks), f"{failure}; {sliding_failure}")
