"""Sliding of one rigid block on a rigid horizontal support under a record.

The block (mass m) rests on a support with horizontal acceleration a_h(t)
(+x) and downward acceleration a_v(t) (see
:mod:`freestand.core.motion.ground_motion`). The normal force is N = m (g - a_v).
With s the displacement of the block relative to the support (+x) and Coulomb
friction (paper section 3.1.2.1; Newmark 1965):

- stick (s' = 0) while |a_h| <= mu_0 (g - a_v): the friction force m a_h
  carries the block with the support;
- slip starts when |a_h| > mu_0 (g - a_v), in the direction -sgn(a_h)
  (the block lags behind the support);
- while sliding in direction d = sgn(s'),
  s'' = -a_h - d mu (g - a_v), with the kinetic coefficient mu <= mu_0;
- when s' returns to zero the block sticks if |a_h| <= mu_0 (g - a_v) there,
  otherwise it slides on in the direction -sgn(a_h).

The record is piecewise linear, so on each step a_h and a_v are linear in t:
the sliding velocity is a quadratic and the displacement a cubic in t, and the
stick/slip thresholds are linear in t. The solver therefore finds every event
(slip start, velocity zero) as the root of a linear or quadratic polynomial
and advances the state exactly between events: there is no time-step error
beyond the piecewise-linear representation of the record.

When g - a_v <= 0 the support no longer presses on the block (it would leave
the support); the solver then takes the friction as zero, keeps the block on
the support horizontally, and reports the time spent so in
``SlidingResult.contact_lost_time``.

After the record the support comes to rest (the record is followed by zero
samples) and the solver goes on until the block stops, unless the kinetic
friction is zero.

References
----------
Newmark, N. M. (1965). Effects of earthquakes on dams and embankments.
Geotechnique 15(2), 139-160.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numba
import numpy as np

from freestand.core.motion.ground_motion import GroundMotion

# indices into the statistics array of the kernel
_S_MAX_ABS = 0
_S_FRICTION_WORK = 1
_S_BASE_WORK = 2
_S_SLIDING_TIME = 3
_S_SLIP_STARTS = 4
_S_STICKS = 5
_S_REVERSALS = 6
_S_CONTACT_LOST = 7
_S_EVENT_LIMIT = 8
_S_FIRST_SLIP = 9
_S_LAST_STOP = 10
_N_STATS = 11

_MAX_EVENTS_PER_SEGMENT = 64


@numba.njit(cache=True)
def _first_zero_after(v, c0, c1, span, tiny):
    """Smallest delta in [0, span] where v + c0 delta + c1 delta^2 / 2 reaches zero.

    When v = 0 (the motion starts) the trivial root 0 and roots below ``tiny`` are skipped.
    Returns -1 if there is none.
    """
    best = -1.0
    if v == 0.0:
        # roots 0 and -2 c0 / c1: the motion starts from rest
        if c1 != 0.0:
            r = -2.0 * c0 / c1
            if r > tiny and r <= span:
                best = r
        return best
    if c1 == 0.0:
        if c0 != 0.0:
            r = -v / c0
            if r >= 0.0 and r <= span:
                best = r
        return best
    half = 0.5 * c1
    disc = c0 * c0 - 4.0 * half * v
    if disc < 0.0:
        return best
    sq = math.sqrt(disc)
    q = -0.5 * (c0 + sq) if c0 >= 0.0 else -0.5 * (c0 - sq)
    # q != 0 here: q = 0 would need c0 = 0 and disc = -2 c1 v = 0, i.e. v = 0
    r1 = q / half
    r2 = v / q
    for r in (r1, r2):
        if r >= 0.0 and r <= span and (best < 0.0 or r < best):
            best = r
    return best


@numba.njit(cache=True)
def _slide_kernel(ah, av, dt, g, mu_s, mu_k, s0, v0, mode0, t0, out_s, out_v, stats):
    """Exact event-driven sliding over a piecewise-linear record.

    Fills ``out_s``/``out_v`` at the samples, accumulates ``stats`` and returns
    the final (s, v, mode).
    """
    n = ah.size
    s = s0
    v = v0
    mode = mode0
    out_s[0] = s
    out_v[0] = v
    for i in range(n - 1):
        ah0 = ah[i]
        kh = (ah[i + 1] - ah0) / dt
        av0 = av[i]
        kv = (av[i + 1] - av0) / dt
        # split the step where the normal force g - a_v changes sign
        n0 = g - av0
        n1 = g - av[i + 1]
        bounds = np.empty(3)
        bounds[0] = 0.0
        n_bounds = 1
        if (n0 > 0.0) != (n1 > 0.0) and n0 != n1:
            tz = n0 / (n0 - n1) * dt
            if tz > 0.0 and tz < dt:
                bounds[n_bounds] = tz
                n_bounds += 1
        bounds[n_bounds] = dt
        n_bounds += 1
        for b in range(n_bounds - 1):
            tau = bounds[b]
            tau_end = bounds[b + 1]
            mid = 0.5 * (tau + tau_end)
            contact = (n0 - kv * mid) > 0.0
            ms = mu_s if contact else 0.0
            mk = mu_k if contact else 0.0
            if not contact:
                stats[_S_CONTACT_LOST] += tau_end - tau
            tiny = 1e-12 * dt
            events = 0
            while tau < tau_end:
                events += 1
                if events > _MAX_EVENTS_PER_SEGMENT:
                    stats[_S_EVENT_LIMIT] += 1.0
                    break
                if mode == 0:
                    # f_plus = a_h - ms N > 0: slip backwards (d = -1)
                    # f_minus = -a_h - ms N > 0: slip forwards (d = +1)
                    a_plus = ah0 - ms * (g - av0)
                    b_plus = kh + ms * kv
                    a_minus = -ah0 - ms * (g - av0)
                    b_minus = -kh + ms * kv
                    t_slip = tau_end + 1.0
                    d_slip = 0
                    f = a_plus + b_plus * tau
                    if f > 0.0 or (f == 0.0 and b_plus > 0.0):
                        t_slip = tau
                        d_slip = -1
                    elif b_plus > 0.0:
                        r = -a_plus / b_plus
                        if r < tau_end:
                            t_slip = max(r, tau)
                            d_slip = -1
                    f = a_minus + b_minus * tau
                    if f > 0.0 or (f == 0.0 and b_minus > 0.0):
                        if tau < t_slip:
                            t_slip = tau
                            d_slip = 1
                    elif b_minus > 0.0:
                        r = -a_minus / b_minus
                        if r < tau_end and max(r, tau) < t_slip:
                            t_slip = max(r, tau)
                            d_slip = 1
                    if d_slip == 0:
                        tau = tau_end
                    else:
                        tau = t_slip
                        mode = d_slip
                        stats[_S_SLIP_STARTS] += 1.0
                        if stats[_S_FIRST_SLIP] < 0.0:
                            stats[_S_FIRST_SLIP] = t0 + i * dt + tau
                else:
                    d = float(mode)
                    p0 = -ah0 - d * mk * (g - av0)
                    p1 = -kh + d * mk * kv
                    c0 = p0 + p1 * tau
                    c1 = p1
                    span = tau_end - tau
                    if v == 0.0 and d * c0 < 0.0 and d * c0 > -1e-12 * (g + abs(ah0)):
                        c0 = 0.0  # round-off at the exact slip start
                    if v == 0.0 and (d * c0 < 0.0 or (c0 == 0.0 and d * c1 <= 0.0)):
                        # cannot move this way after all: stick, re-examine
                        mode = 0
                        if abs(ah0 + kh * tau) <= ms * (g - av0 - kv * tau):
                            stats[_S_STICKS] += 1.0
                            stats[_S_LAST_STOP] = t0 + i * dt + tau
                            continue
                        mode = -1 if ah0 + kh * tau > 0.0 else 1
                        continue
                    delta = _first_zero_after(v, c0, c1, span, tiny)
                    step = span if delta < 0.0 else delta
                    # exact integrals over the sub-interval
                    nn0 = g - av0 - kv * tau
                    v_int = v * step + c0 * step**2 / 2.0 + c1 * step**3 / 6.0
                    v_int2 = v * step**2 / 2.0 + c0 * step**3 / 3.0 + c1 * step**4 / 8.0
                    stats[_S_FRICTION_WORK] += d * mk * (nn0 * v_int - kv * v_int2)
                    stats[_S_BASE_WORK] += -((ah0 + kh * tau) * v_int + kh * v_int2)
                    stats[_S_SLIDING_TIME] += step
                    s += v_int
                    tau += step
                    if delta < 0.0:
                        v = v + c0 * step + c1 * step**2 / 2.0
                        if d * v < 0.0:
                            v = 0.0
                        tau = tau_end
                    else:
                        v = 0.0
                        if abs(s) > stats[_S_MAX_ABS]:
                            stats[_S_MAX_ABS] = abs(s)
                        a_now = ah0 + kh * tau
                        if abs(a_now) <= ms * (g - av0 - kv * tau):
                            mode = 0
                            stats[_S_STICKS] += 1.0
                            stats[_S_LAST_STOP] = t0 + i * dt + tau
                        else:
                            new_mode = -1 if a_now > 0.0 else 1
                            if new_mode != mode:
                                stats[_S_REVERSALS] += 1.0
                            mode = new_mode
        out_s[i + 1] = s
        out_v[i + 1] = v
        if abs(s) > stats[_S_MAX_ABS]:
            stats[_S_MAX_ABS] = abs(s)
    return s, v, mode


@dataclass(frozen=True)
class SlidingResult:
    """Time history and summary of a block sliding on a rigid support.

    Parameters
    ----------
    time : numpy.ndarray
        Sample times [s] (the record, then zeros until the block stops).
    displacement : numpy.ndarray
        Displacement of the block relative to the support s [m], +x.
    velocity : numpy.ndarray
        Relative velocity s' [m/s].
    max_slide : float
        Largest |s| over the whole history, events between samples included [m].
    residual_slide : float
        Relative displacement when the block has come to rest after the
        record [m] (signed; the last value if it never stops).
    status : str
        ``"no sliding"``, ``"slid and stopped"`` or ``"still sliding"``
        (zero kinetic friction: the block never stops).
    sliding_time : float
        Total time spent sliding [s].
    slip_starts : int
        Number of stick-to-slip transitions [-].
    reversals : int
        Number of direct reversals of the sliding direction [-].
    first_slip_time : float
        Time of the first slip [s] (nan if none).
    stop_time : float
        Time of the last stick [s] (nan if it never stuck after sliding).
    friction_work : float
        Energy dissipated by friction per unit mass, int mu N/m |s'| dt [J/kg].
    base_work : float
        Work of the inertial force per unit mass, -int a_h s' dt [J/kg]; equals
        ``friction_work`` plus the final kinetic energy s'^2 / 2 per unit mass.
    contact_lost_time : float
        Time with g - a_v <= 0 [s], during which friction is taken as zero.
    record_duration : float
        Duration of the record proper [s].
    messages : tuple of str
        Warnings (contact lost, event limit reached, still sliding).
    """

    time: np.ndarray
    displacement: np.ndarray
    velocity: np.ndarray
    max_slide: float
    residual_slide: float
    status: str
    sliding_time: float
    slip_starts: int
    reversals: int
    first_slip_time: float
    stop_time: float
    friction_work: float
    base_work: float
    contact_lost_time: float
    record_duration: float
    messages: tuple[str, ...] = ()
    metadata: dict = field(default_factory=dict, compare=False)


def slide_block(
    motion: GroundMotion,
    static_friction: float,
    kinetic_friction: float | None = None,
    *,
    gravity: float = 9.81,
    until_rest: bool = True,
    max_extension: float = 600.0,
) -> SlidingResult:
    """Slide a rigid block on a rigid horizontal support under a record.

    Parameters
    ----------
    motion : GroundMotion
        Support accelerations: horizontal a_h [m/s^2] (+x) and downward a_v
        [m/s^2] (zero if absent).
    static_friction : float
        Static coefficient mu_0 [-]: slip starts when |a_h| > mu_0 (g - a_v).
    kinetic_friction : float, optional
        Kinetic coefficient mu [-], 0 <= mu <= mu_0 (default mu_0).
    gravity : float, optional
        g [m/s^2] (default 9.81).
    until_rest : bool, optional
        After the record, follow the block with the support at rest until it
        stops (default True).
    max_extension : float, optional
        Longest such follow-up [s] (default 600 s).

    Returns
    -------
    SlidingResult
        Relative displacement and velocity at the samples, peak and residual
        slide, and what happened.

    Notes
    -----
    Stick while |a_h| <= mu_0 (g - a_v); slide with
    s'' = -a_h - sgn(s') mu (g - a_v) (Coulomb friction; Newmark 1965). Events
    are roots of linear and quadratic polynomials on each linear record
    segment, so the solution is exact for the piecewise-linear record.
    """
    mu_s = float(static_friction)
    mu_k = mu_s if kinetic_friction is None else float(kinetic_friction)
    if not (mu_s >= 0 and math.isfinite(mu_s)):
        raise ValueError(f"static friction must be non-negative, got {static_friction!r}")
    if not (0 <= mu_k <= mu_s):
        raise ValueError(
            f"kinetic friction must satisfy 0 <= mu <= mu_0 = {mu_s}, got {kinetic_friction!r}"
        )
    if not (gravity > 0 and math.isfinite(gravity)):
        raise ValueError(f"gravity must be positive, got {gravity!r}")
    dt = motion.dt
    ah = np.ascontiguousarray(motion.horizontal, dtype=float)
    av = (
        np.zeros_like(ah)
        if motion.vertical is None
        else np.ascontiguousarray(motion.vertical, dtype=float)
    )
    # the record is followed by one zero sample (the support comes to rest)
    ah = np.append(ah, 0.0)
    av = np.append(av, 0.0)
    n = ah.size
    out_s = np.zeros(n)
    out_v = np.zeros(n)
    stats = np.zeros(_N_STATS)
    stats[_S_FIRST_SLIP] = -1.0
    stats[_S_LAST_STOP] = -1.0
    s, v, mode = _slide_kernel(
        ah, av, dt, gravity, mu_s, mu_k, 0.0, 0.0, 0, 0.0, out_s, out_v, stats
    )
    displacement = [out_s]
    velocity = [out_v]
    messages = []
    if until_rest and mode != 0:
        if mu_k > 0:
            t_stop = abs(v) / (mu_k * gravity)
            if t_stop > max_extension:
                messages.append(
                    f"the block would need {t_stop:.3g} s to stop, more than max_extension"
                )
            n_extra = int(math.ceil(min(t_stop, max_extension) / dt)) + 2
            zeros = np.zeros(n_extra + 1)
            ext_s = np.zeros(n_extra + 1)
            ext_v = np.zeros(n_extra + 1)
            s, v, mode = _slide_kernel(
                zeros, zeros, dt, gravity, mu_s, mu_k, s, v, mode, (n - 1) * dt, ext_s, ext_v, stats
            )
            displacement.append(ext_s[1:])
            velocity.append(ext_v[1:])
    displacement = np.concatenate(displacement)
    velocity = np.concatenate(velocity)
    time = np.arange(displacement.size) * dt
    slip_starts = int(stats[_S_SLIP_STARTS])
    if slip_starts == 0:
        status = "no sliding"
    elif mode == 0:
        status = "slid and stopped"
    else:
        status = "still sliding"
        messages.append(
            "the block is still sliding at the end"
            + (" (zero kinetic friction never stops it)" if mu_k == 0 else "")
        )
    if stats[_S_CONTACT_LOST] > 0:
        messages.append(
            f"the downward support acceleration reached g for {stats[_S_CONTACT_LOST]:.3g} s: "
            "the block would leave the support; friction taken as zero then"
        )
    if stats[_S_EVENT_LIMIT] > 0:
        messages.append(
            f"{int(stats[_S_EVENT_LIMIT])} step(s) reached the event limit "
            f"({_MAX_EVENTS_PER_SEGMENT}); results there are approximate"
        )
    return SlidingResult(
        time=time,
        displacement=displacement,
        velocity=velocity,
        max_slide=float(max(stats[_S_MAX_ABS], np.max(np.abs(displacement)))),
        residual_slide=float(s),
        status=status,
        sliding_time=float(stats[_S_SLIDING_TIME]),
        slip_starts=slip_starts,
        reversals=int(stats[_S_REVERSALS]),
        first_slip_time=float(stats[_S_FIRST_SLIP]) if stats[_S_FIRST_SLIP] >= 0 else math.nan,
        stop_time=float(stats[_S_LAST_STOP]) if stats[_S_LAST_STOP] >= 0 else math.nan,
        friction_work=float(stats[_S_FRICTION_WORK]),
        base_work=float(stats[_S_BASE_WORK]),
        contact_lost_time=float(stats[_S_CONTACT_LOST]),
        record_duration=motion.duration,
        messages=tuple(messages),
        metadata={"record": motion.name, "static_friction": mu_s, "kinetic_friction": mu_k},
    )


@dataclass(frozen=True)
class PulseSlide:
    """Closed-form sliding of a block under a rectangular pulse.

    Parameters
    ----------
    slides : bool
        Whether the pulse exceeds the static threshold mu_0 (g - a_v).
    displacement : float
        Final relative displacement [m], opposite in sign to the pulse.
    velocity_at_pulse_end : float
        Relative velocity when the pulse ends [m/s].
    stop_time : float
        Time the block stops [s] (0 if it never slides).
    """

    slides: bool
    displacement: float
    velocity_at_pulse_end: float
    stop_time: float


def rectangular_pulse_slide(
    amplitude: float,
    duration: float,
    static_friction: float,
    kinetic_friction: float | None = None,
    *,
    gravity: float = 9.81,
    vertical: float = 0.0,
) -> PulseSlide:
    """Closed-form slide of a block at rest under a rectangular pulse.

    Parameters
    ----------
    amplitude : float
        Pulse acceleration a [m/s^2] (either sign), acting for 0 <= t <= t_1.
    duration : float
        Pulse duration t_1 [s].
    static_friction : float
        mu_0 [-].
    kinetic_friction : float, optional
        mu [-] (default mu_0).
    gravity : float, optional
        g [m/s^2].
    vertical : float, optional
        Constant downward support acceleration a_v [m/s^2] acting during the
        pulse only (default 0), 0 <= a_v < g.

    Returns
    -------
    PulseSlide
        With N_1 = g - a_v during the pulse: if |a| <= mu_0 N_1 nothing moves.
        Otherwise the block slides with relative acceleration
        |a| - mu N_1 for t_1, reaching v_1 = (|a| - mu N_1) t_1, then
        decelerates at mu g and stops at t_1 + v_1 / (mu g):

            |s| = (|a| - mu N_1) t_1^2 / 2 + v_1^2 / (2 mu g).

        For a_v = 0 this is Newmark's (1965) result
        |s| = a t_1^2 (a - mu g) / (2 mu g) = V^2 / (2 g N) (1 - N / A),
        with V = a t_1, A = a / g, N = mu.
    """
    mu_s = float(static_friction)
    mu_k = mu_s if kinetic_friction is None else float(kinetic_friction)
    if not (0 <= mu_k <= mu_s):
        raise ValueError("friction coefficients must satisfy 0 <= mu <= mu_0")
    if not (0 <= vertical < gravity):
        raise ValueError("the downward acceleration must satisfy 0 <= a_v < g")
    if duration <= 0:
        raise ValueError("the pulse duration must be positive")
    a = abs(float(amplitude))
    n1 = gravity - vertical
    if a <= mu_s * n1:
        return PulseSlide(False, 0.0, 0.0, 0.0)
    if mu_k == 0:
        raise ValueError("with zero kinetic friction the block never stops")
    relative = a - mu_k * n1
    v1 = relative * duration
    slide = 0.5 * relative * duration**2 + v1**2 / (2.0 * mu_k * gravity)
    sign = -math.copysign(1.0, amplitude)
    return PulseSlide(
        True,
        sign * slide,
        sign * v1,
        duration + v1 / (mu_k * gravity),
    )
