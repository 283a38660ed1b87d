"""Exact nonlinear rocking of a rigid block with impacts (numba-compiled).

The block of :class:`freestand.core.rocking.properties.RockingBlock` rocks about ``pivot``
(rotation theta > 0) or about ``other_pivot`` (theta < 0). About the pivot of
side s = sgn(theta), with b_s, h_s, R_s, alpha_s, I_s its geometry and
inertia, the equation of motion is the equation of Zhang and Makris (2001,
eqs. 10-12) generalised to two different pivots:

    I_s theta'' = m R_s [ -s g' sin(alpha_s - s theta) + u''(t) cos(alpha_s - s theta) ],

with g' = g - a_v the effective gravity and u''(t) the support acceleration
counted positive when its inertial force points from the centre of gravity
towards ``pivot`` (Zhang and Makris's sign is the opposite, theta -> -theta).
Rocking starts from rest when u'' > g' tan(alpha_+) (about ``pivot``) or
u'' < -g' tan(alpha_-) (about ``other_pivot``). When theta returns to zero the
block impacts on the other pivot; the angular velocity is multiplied by the
ratio from conservation of angular momentum about the new pivot (Housner 1963,
eq. 4; :meth:`RockingBlock.restitution_onto`).

Integration: classical fourth-order Runge-Kutta with a fixed step, steps cut to
land exactly on the end of the pulse (and on the samples of a record), and the
instants of impact and of the start of rocking located exactly (regula falsi
on the Runge-Kutta step map, bisection on the excitation).

Overturning: while the excitation acts, the block has overturned only when it
lies on its side (s theta >= pi/2); passing |theta| = alpha is not enough, as
the rest of the pulse may bring it back. Once the excitation has ended the
motion is free and the outcome follows from energy: the block overturns if it
reaches the position of no return (s theta = alpha_s) with energy to spare,
possibly after an impact (impacts only remove energy).

References
----------
.. [1] G. W. Housner, Bull. Seismol. Soc. Am. 53(2), 403-417, 1963.
.. [2] J. Zhang and N. Makris, "Rocking response of free-standing blocks under
   cycloidal pulses", J. Eng. Mech. 127(5), 473-483, 2001.
.. [3] N. Makris and Y. Roussos, Geotechnique 50(3), 243-262, 2000.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numba as nb
import numpy as np

from freestand.core.rocking.amplitude_search import lowest_overturning_amplitude
from freestand.core.rocking.properties import RockingBlock
from freestand.errors import FreestandError

#: Pulse kinds and their integer codes in the compiled code.
PULSE_KINDS = {"rectangular": 0, "half-sine": 1, "one-sine": 2, "one-cosine": 3}
_RECORD = 4
_NONE = 5

#: Default time step as a fraction of the shortest time scale (1/p, pulse length / 400).
_STEPS_PER_PULSE = 400.0
_STEP_TIMES_P = 0.02

_HALF_PI = 0.5 * math.pi


# ------------------------------------------------------------------------------------
# compiled kernels
# ------------------------------------------------------------------------------------
@nb.njit(cache=True, inline="always")
def _interpolate(values, dt, t):
    """Linear interpolation of samples ``values`` spaced ``dt`` [s] at time ``t`` [s]."""
    n = values.shape[0]
    x = t / dt
    i = int(math.floor(x))
    if i < 0:
        i = 0
    if i > n - 2:
        i = n - 2
    frac = x - i
    return values[i] + frac * (values[i + 1] - values[i])


@nb.njit(cache=True)
def _accel(kind, exc, rec, t, in_pulse):
    """Support acceleration [m/s^2] at time t (zero once the excitation has ended)."""
    if not in_pulse:
        return 0.0
    amp = exc[0]
    w = exc[1]
    if kind == 0:
        return amp
    if kind == 1 or kind == 2:
        return amp * math.sin(w * t)
    if kind == 3:
        return amp * math.cos(w * t)
    if kind == 4:
        return _interpolate(rec, exc[3], t)
    return 0.0


@nb.njit(cache=True, inline="always")
def _gravity(par, exc, vrec, t, in_pulse):
    """Effective gravity g' = g - a_v(t) [m/s^2]; a_v from the vertical record, if any."""
    if vrec.shape[0] == 0 or not in_pulse:
        return par[0]
    return par[0] - _interpolate(vrec, exc[3], t)


@nb.njit(cache=True, inline="always")
def _starts(tan_p, tan_m, a, g):
    """Side (+1, -1) on which a support acceleration ``a`` starts rocking from rest, 0 if none.

    tan_p, tan_m: tan(alpha) about the pivot and the other pivot [-]; g = g' [m/s^2].
    """
    if a > g * tan_p:
        return 1
    if a < -g * tan_m:
        return -1
    return 0


@nb.njit(cache=True)
def _rhs(par, side, theta, a, g):
    """Angular acceleration [rad/s^2] on ``side`` (+1 pivot, -1 other pivot); g = g' [m/s^2]."""
    if side > 0:
        k = par[1]
        al = par[2]
    else:
        k = par[5]
        al = par[6]
    phi = al - side * theta
    return k * (-side * g * math.sin(phi) + a * math.cos(phi))


@nb.njit(cache=True)
def _rk4(par, kind, exc, rec, vrec, side, t, theta, omega, h, in_pulse):
    a0 = _accel(kind, exc, rec, t, in_pulse)
    am = _accel(kind, exc, rec, t + 0.5 * h, in_pulse)
    a1 = _accel(kind, exc, rec, t + h, in_pulse)
    if vrec.shape[0] > 0 and in_pulse:
        g0 = _gravity(par, exc, vrec, t, in_pulse)
        gm = _gravity(par, exc, vrec, t + 0.5 * h, in_pulse)
        g1 = _gravity(par, exc, vrec, t + h, in_pulse)
    else:
        g0 = gm = g1 = par[0]
    k1t = omega
    k1w = _rhs(par, side, theta, a0, g0)
    k2t = omega + 0.5 * h * k1w
    k2w = _rhs(par, side, theta + 0.5 * h * k1t, am, gm)
    k3t = omega + 0.5 * h * k2w
    k3w = _rhs(par, side, theta + 0.5 * h * k2t, am, gm)
    k4t = omega + h * k3w
    k4w = _rhs(par, side, theta + h * k3t, a1, g1)
    th = theta + h / 6.0 * (k1t + 2.0 * k2t + 2.0 * k3t + k4t)
    om = omega + h / 6.0 * (k1w + 2.0 * k2w + 2.0 * k3w + k4w)
    return th, om


@nb.njit(cache=True)
def _side_params(par, side):
    if side > 0:
        return par[2], par[3], par[4]
    return par[6], par[7], par[8]


@nb.njit(cache=True)
def _free_decision(par, theta, omega):
    """Outcome of free rocking (no excitation) from (theta, omega).

    Returns (overturned, margin); margin is the largest ratio of the kinetic
    energy at theta = 0 on a side to the energy barrier of that side (>= 1 means
    overturning).
    """
    g = par[0]
    if theta > 0.0:
        s = 1
    elif theta < 0.0:
        s = -1
    elif omega > 0.0:
        s = 1
    elif omega < 0.0:
        s = -1
    else:
        return False, 0.0
    al, R, J = _side_params(par, s)
    phi = s * theta
    v = s * omega
    e_top = g * R
    e_rest = g * R * math.cos(al)
    energy = 0.5 * J * v * v + g * R * math.cos(al - phi)
    margin = (energy - e_rest) / (e_top - e_rest)
    if phi >= al:
        if v >= 0.0 or energy <= e_top:
            return True, max(margin, 1.0)
    elif v > 0.0 and energy > e_top:
        return True, margin
    ke0 = energy - e_rest
    if ke0 < 0.0:
        ke0 = 0.0
    w0 = math.sqrt(2.0 * ke0 / J)
    # at most two more impacts matter: each impact removes energy
    for _ in range(2):
        e = par[9] if s > 0 else par[10]
        if e <= 0.0:
            return False, margin
        w0 = e * w0
        s = -s
        al, R, J = _side_params(par, s)
        ratio = 0.5 * J * w0 * w0 / (g * R * (1.0 - math.cos(al)))
        if ratio > margin:
            margin = ratio
        if ratio > 1.0:
            return True, margin
    return False, margin


@nb.njit(cache=True, inline="always")
def _keep(hist_t, hist_th, hist_om, n_hist, t, theta, omega):
    """Write (t, theta, omega) at row ``n_hist`` of the history while it has room; the new count."""
    if n_hist < hist_t.shape[0]:
        hist_t[n_hist] = t
        hist_th[n_hist] = theta
        hist_om[n_hist] = omega
        return n_hist + 1
    return n_hist


@nb.njit(cache=True)
def _simulate(
    par,
    kind,
    exc,
    rec,
    vrec,
    theta0,
    omega0,
    t_stop,
    h_max,
    decide,
    hist_t,
    hist_th,
    hist_om,
    imp_log,
    lift_log,
    rest_speed,
    rest_after,
    out,
):
    """Integrate the rocking motion; see :func:`simulate` for the meaning.

    out: [overturned, t_overturned, max|theta|, impacts, margin, rocked,
    theta, omega, t, n_history, uplift time, status, n_lift]; status 0 rest,
    1 rocking, 2 overturned, 3 decided safe after the excitation. vrec: the
    downward support acceleration a_v [m/s^2] at the record's samples (empty
    for none); lift_log: (time, side) of every start of rocking from rest;
    rest_speed: angular velocity [rad/s] after an impact below which the block
    settles (0 for the default, 1e-6 of the speed that overturns it);
    rest_after: time [s] from which the integration stops as soon as the
    block rests once the excitation has ended (inf: never).
    """
    g = par[0]
    tan_p = math.tan(par[2])
    tan_m = math.tan(par[6])
    has_vertical = vrec.shape[0] > 0
    dur = exc[2]
    rec_dt = exc[3]
    t = 0.0
    theta = theta0
    omega = omega0
    in_pulse = kind != 5 and dur > 0.0
    resting = theta == 0.0 and omega == 0.0
    # set when a start of rocking was undone (its flight too short to resolve): the
    # block then rests for the step even if the excitation still exceeds the threshold
    settled = False
    side = 1
    if theta < 0.0 or (theta == 0.0 and omega < 0.0):
        side = -1
    n_hist = 0
    n_imp = 0
    n_imp_max = imp_log.shape[0]
    n_lift = 0
    n_lift_max = lift_log.shape[0]
    max_abs = abs(theta)
    rocked = not resting
    t_uplift = 0.0 if rocked else math.nan
    overturned = False
    t_over = math.nan
    margin = 0.0
    status = 0
    # below these angular velocities after an impact (1e-6 of the speed that
    # carries the block over the barrier of that side) the impacts accumulate
    # (Zeno): the block settles on its base
    w_rest_p = 1e-6 * math.sqrt(2.0 * g * par[3] * (1.0 - math.cos(par[2])) / par[4])
    w_rest_m = 1e-6 * math.sqrt(2.0 * g * par[7] * (1.0 - math.cos(par[6])) / par[8])
    if rest_speed > 0.0:
        w_rest_p = rest_speed
        w_rest_m = rest_speed
    n_hist = _keep(hist_t, hist_th, hist_om, n_hist, t, theta, omega)
    while True:
        if in_pulse and t >= dur * (1.0 - 1e-13):
            in_pulse = False
            t = dur
        if decide and not in_pulse:
            if resting:
                status = 0
                margin = 0.0
            else:
                overturned, margin = _free_decision(par, theta, omega)
                status = 2 if overturned else 3
                if overturned:
                    t_over = math.nan
            break
        if t >= t_stop * (1.0 - 1e-13):
            status = 0 if resting else 1
            break
        if resting and not in_pulse and t >= rest_after:
            status = 0
            break
        t_target = t_stop
        if in_pulse and dur < t_target:
            t_target = dur
        h = min(h_max, t_target - t)
        if kind == 4 and in_pulse:
            node = (math.floor(t / rec_dt * (1.0 + 1e-13)) + 1.0) * rec_dt
            if node - t < 1e-9 * rec_dt:
                node += rec_dt
            if node - t < h:
                h = node - t
        if h <= 0.0:
            h = t_target - t
            if h <= 0.0:
                t = t_target
                continue
        if resting:
            a_now = _accel(kind, exc, rec, t, in_pulse)
            g_now = _gravity(par, exc, vrec, t, in_pulse) if has_vertical else g
            s_now = _starts(tan_p, tan_m, a_now, g_now)
            if s_now != 0 and settled:
                # the excitation barely exceeds the threshold: rest for the step (starting
                # again at once would undo the same start forever)
                settled = False
                t = t + h
                n_hist = _keep(hist_t, hist_th, hist_om, n_hist, t, theta, omega)
                continue
            settled = False
            if s_now != 0:
                side = s_now
                resting = False
                if not rocked:
                    rocked = True
                    t_uplift = t
                if n_lift < n_lift_max:
                    lift_log[n_lift, 0] = t
                    lift_log[n_lift, 1] = side
                n_lift += 1
                continue
            a_end = _accel(kind, exc, rec, t + h, in_pulse)
            g_end = _gravity(par, exc, vrec, t + h, in_pulse) if has_vertical else g
            if _starts(tan_p, tan_m, a_end, g_end) != 0:
                lo = t
                hi = t + h
                for _ in range(200):
                    mid = 0.5 * (lo + hi)
                    if mid <= lo or mid >= hi:
                        break
                    am = _accel(kind, exc, rec, mid, in_pulse)
                    if _starts(tan_p, tan_m, am, _gravity(par, exc, vrec, mid, in_pulse)) != 0:
                        hi = mid
                    else:
                        lo = mid
                t = hi
                a_on = _accel(kind, exc, rec, t, in_pulse)
                side = 1 if a_on > 0.0 else -1
                resting = False
                if not rocked:
                    rocked = True
                    t_uplift = t
                if n_lift < n_lift_max:
                    lift_log[n_lift, 0] = t
                    lift_log[n_lift, 1] = side
                n_lift += 1
                n_hist = _keep(hist_t, hist_th, hist_om, n_hist, t, theta, omega)
                continue
            t = t + h
            n_hist = _keep(hist_t, hist_th, hist_om, n_hist, t, theta, omega)
            continue
        th1, om1 = _rk4(par, kind, exc, rec, vrec, side, t, theta, omega, h, in_pulse)
        if side * th1 < 0.0:
            # impact within the step: find the first zero of theta in (0, h]
            lo = 0.0
            if side * theta <= 0.0:
                # starting at theta = 0 (just after an impact or uplift): find a
                # point inside the step where the block is off its base
                acc0 = _rhs(
                    par,
                    side,
                    theta,
                    _accel(kind, exc, rec, t, in_pulse),
                    _gravity(par, exc, vrec, t, in_pulse),
                )
                guess = h
                if side * acc0 < 0.0 and omega != 0.0:
                    guess = min(h, -2.0 * omega / acc0)
                found = False
                trial = 0.5 * guess
                for _ in range(60):
                    tht, _omt = _rk4(
                        par, kind, exc, rec, vrec, side, t, theta, omega, trial, in_pulse
                    )
                    if side * tht > 0.0:
                        found = True
                        break
                    trial *= 0.5
                if not found:
                    # flight too short to resolve: the block settles on its base
                    resting = True
                    settled = True
                    theta = 0.0
                    omega = 0.0
                    continue
                lo = trial
            hi = h
            th_lo, _w = _rk4(par, kind, exc, rec, vrec, side, t, theta, omega, lo, in_pulse)
            if lo == 0.0:
                th_lo = theta
            th_hi = th1
            side_lo = 0
            tau = hi
            for _ in range(100):
                tau = (lo * th_hi - hi * th_lo) / (th_hi - th_lo)
                if not (lo < tau < hi):
                    tau = 0.5 * (lo + hi)
                th_t, _w = _rk4(par, kind, exc, rec, vrec, side, t, theta, omega, tau, in_pulse)
                if th_t == 0.0 or hi - lo < 1e-15 * h:
                    break
                if side * th_t > 0.0:
                    lo = tau
                    th_lo = th_t
                    if side_lo == 1:
                        th_hi *= 0.5
                    side_lo = 1
                else:
                    hi = tau
                    th_hi = th_t
                    if side_lo == -1:
                        th_lo *= 0.5
                    side_lo = -1
                if abs(th_t) < 1e-16:
                    break
            _th, w_before = _rk4(par, kind, exc, rec, vrec, side, t, theta, omega, tau, in_pulse)
            e = par[9] if side > 0 else par[10]
            w_after = e * w_before if e > 0.0 else 0.0
            t = t + tau
            if n_imp < n_imp_max:
                imp_log[n_imp, 0] = t
                imp_log[n_imp, 1] = w_before
                imp_log[n_imp, 2] = w_after
            n_imp += 1
            theta = 0.0
            side = -side
            omega = w_after
            if abs(omega) <= (w_rest_p if side > 0 else w_rest_m):
                omega = 0.0
                resting = True
        else:
            t = t + h
            theta = th1
            omega = om1
        if abs(theta) > max_abs:
            max_abs = abs(theta)
        n_hist = _keep(hist_t, hist_th, hist_om, n_hist, t, theta, omega)
        if side * theta >= _HALF_PI:
            overturned = True
            t_over = t
            margin = 2.0
            status = 2
            break
    out[0] = 1.0 if overturned else 0.0
    out[1] = t_over
    out[2] = max_abs
    out[3] = n_imp
    out[4] = margin
    out[5] = 1.0 if rocked else 0.0
    out[6] = theta
    out[7] = omega
    out[8] = t
    out[9] = n_hist
    out[10] = t_uplift
    out[11] = status
    out[12] = n_lift


@nb.njit(cache=True)
def _outcome(par, kind, exc, rec, h_max):
    """(overturned, margin) for one excitation (decide mode, no history)."""
    ht = np.empty(0)
    hth = np.empty(0)
    hom = np.empty(0)
    imp = np.empty((0, 3))
    lift = np.empty((0, 2))
    out = np.empty(13)
    _simulate(
        par, kind, exc, rec, np.empty(0), 0.0, 0.0, exc[2], h_max, True, ht, hth, hom, imp, lift,
        0.0, math.inf, out,
    )  # fmt: skip
    return out[0] > 0.5, out[4]


@nb.njit(cache=True)
def _pulse_exc(kind, amp, omega):
    exc = np.zeros(4)
    exc[0] = amp
    exc[1] = omega
    if kind == 1:
        exc[2] = math.pi / omega
    else:
        exc[2] = 2.0 * math.pi / omega
    return exc


@nb.njit(cache=True)
def _pulse_outcome(context, amplitude):
    """(overturned, margin) under the pulse of ``amplitude`` [m/s^2] (decide mode).

    ``context`` = (par, kind, omega, h_max); the simulator of
    :func:`freestand.core.rocking.amplitude_search.lowest_overturning_amplitude`.
    """
    par, kind, omega, h_max = context
    return _outcome(par, kind, _pulse_exc(kind, amplitude, omega), np.empty(0), h_max)


@nb.njit(cache=True, parallel=True)
def _min_amplitude_many(par, kind, omegas, a_lo, a_his, ratio, rel_tol, h_maxs, result, status):
    for i in nb.prange(omegas.shape[0]):
        context = (par, kind, omegas[i], h_maxs[i])
        a, s = lowest_overturning_amplitude(_pulse_outcome, context, a_lo, a_his[i], ratio, rel_tol)
        result[i] = a
        status[i] = s


@nb.njit(cache=True)
def _rect_overturns(par, amp, duration, h_max):
    exc = np.zeros(4)
    exc[0] = amp
    exc[2] = duration
    ov, _m = _outcome(par, 0, exc, np.empty(0), h_max)
    return ov


@nb.njit(cache=True, parallel=True)
def _rect_duration_many(par, amps, t_guess, h_p, rel_tol, result):
    thr = par[0] * math.tan(par[2])
    for i in nb.prange(amps.shape[0]):
        amp = amps[i]
        if not amp > thr:
            result[i] = math.inf
            continue
        lo = 0.0
        hi = t_guess[i]
        found = False
        for _ in range(80):
            h = min(hi / _STEPS_PER_PULSE, h_p)
            if _rect_overturns(par, amp, hi, h):
                found = True
                break
            lo = hi
            hi = 2.0 * hi
        if not found:
            result[i] = math.inf
            continue
        for _ in range(200):
            if hi - lo <= rel_tol * hi:
                break
            mid = 0.5 * (lo + hi)
            h = min(mid / _STEPS_PER_PULSE, h_p)
            if _rect_overturns(par, amp, mid, h):
                hi = mid
            else:
                lo = mid
        result[i] = hi


# ------------------------------------------------------------------------------------
# Python API
# ------------------------------------------------------------------------------------
def block_parameters(block: RockingBlock) -> np.ndarray:
    """Flat parameter vector of ``block`` for the compiled kernels.

    [g', mR/I and alpha, R, I/m about ``pivot``, the same about
    ``other_pivot``, restitution onto the other pivot, onto ``pivot``].
    """
    plus = block.about("pivot")
    minus = block.about("other")
    m = block.mass
    return np.array(
        [
            block.effective_gravity,
            m * plus.R / plus.inertia_about_pivot,
            plus.alpha,
            plus.R,
            plus.inertia_about_pivot / m,
            m * minus.R / minus.inertia_about_pivot,
            minus.alpha,
            minus.R,
            minus.inertia_about_pivot / m,
            block.restitution_onto("other"),
            block.restitution_onto("pivot"),
        ]
    )


@dataclass(frozen=True)
class Pulse:
    """A single acceleration pulse of the support.

    Parameters
    ----------
    kind : str
        ``"rectangular"`` (a for 0 <= t <= duration), ``"half-sine"``
        (a sin(omega t), 0 <= t <= pi/omega), ``"one-sine"`` (Zhang and Makris
        2001 type A, a sin(omega t), 0 <= t <= 2 pi/omega) or ``"one-cosine"``
        (type B, a cos(omega t), 0 <= t <= 2 pi/omega).
    amplitude : float
        Peak acceleration a [m/s^2]; positive tips the block over ``pivot``.
    frequency : float, optional
        f = omega / (2 pi) [Hz] of the sine (not for ``"rectangular"``).
    duration : float, optional
        Duration [s] of a rectangular pulse.
    """

    kind: str
    amplitude: float
    frequency: float | None = None
    duration: float | None = None

    def __post_init__(self) -> None:
        if self.kind not in PULSE_KINDS:
            raise FreestandError(
                f"unknown pulse kind {self.kind!r}; use one of {', '.join(PULSE_KINDS)}",
                field="pulse",
            )
        if self.kind == "rectangular":
            if self.duration is None or not self.duration > 0:
                raise FreestandError(
                    f"a rectangular pulse needs a positive duration, got {self.duration!r}",
                    field="duration",
                )
        elif self.frequency is None or not self.frequency > 0:
            raise FreestandError(
                f"a {self.kind} pulse needs a positive frequency [Hz], got {self.frequency!r}",
                field="frequency",
            )

    @property
    def omega(self) -> float:
        """Angular frequency [rad/s] (0 for a rectangular pulse)."""
        return 0.0 if self.kind == "rectangular" else 2 * math.pi * float(self.frequency)

    @property
    def length(self) -> float:
        """Time the pulse lasts [s]."""
        if self.kind == "rectangular":
            return float(self.duration)
        if self.kind == "half-sine":
            return math.pi / self.omega
        return 2 * math.pi / self.omega


@dataclass(frozen=True)
class SampledAcceleration:
    """A support acceleration record, linear between uniformly spaced samples.

    Parameters
    ----------
    values : numpy.ndarray
        Acceleration samples [m/s^2] at t = 0, dt, 2 dt, ...; positive tips the
        block over ``pivot``. Zero after the last sample.
    dt : float
        Sample spacing [s].
    vertical : numpy.ndarray, optional
        Downward support acceleration a_v [m/s^2] at the same instants (the
        weight becomes m (g' - a_v(t)), g' the block's effective gravity);
        zero after the last sample. None for none.

    Notes
    -----
    With a vertical record the equation of motion is that of the module notes
    with g' replaced by ``g' - a_v(t)``, and rocking starts from rest when
    ``|u''| > (g' - a_v(t)) tan(alpha)`` on that side. While ``g' - a_v`` is
    not positive the block would leave its base (free flight), which this
    equation does not describe: check for it before relying on the result.
    """

    values: np.ndarray
    dt: float
    vertical: np.ndarray | None = None

    def __post_init__(self) -> None:
        v = np.ascontiguousarray(self.values, dtype=float)
        if v.ndim != 1 or v.size < 2 or not np.all(np.isfinite(v)):
            raise ValueError("values must be a finite 1-D array of at least two samples")
        if not self.dt > 0:
            raise ValueError(f"dt must be positive, got {self.dt!r}")
        object.__setattr__(self, "values", v)
        if self.vertical is not None:
            w = np.ascontiguousarray(self.vertical, dtype=float)
            if w.shape != v.shape or not np.all(np.isfinite(w)):
                raise ValueError(
                    f"vertical must be finite with the {v.size} samples of values, "
                    f"got shape {w.shape}"
                )
            object.__setattr__(self, "vertical", w)

    @property
    def length(self) -> float:
        """Duration of the record [s]."""
        return (self.values.size - 1) * self.dt


@dataclass(frozen=True)
class RockingResult:
    """What happened to a block under one excitation.

    Parameters
    ----------
    overturned : bool
        Whether the block overturned.
    status : str
        ``"rest"`` (at rest at the end), ``"rocking"`` (still rocking at the
        end of the simulated time), ``"overturned"`` or ``"safe"`` (decided
        from energy once the excitation had ended, without further
        integration).
    time_overturned : float
        Time the block came to lie on its side, |theta| = pi/2 [s]; NaN if it
        did not overturn or if the outcome was decided from energy.
    time_uplift : float
        Time rocking started [s]; NaN if it never did.
    rocked : bool
        Whether the block left its rest position.
    max_abs_rotation : float
        Largest |theta| reached [rad].
    impacts : int
        Number of impacts.
    margin : float
        Largest ratio, after the excitation, of the kinetic energy at
        theta = 0 to the energy barrier of the side it rocks on [-]; >= 1 for
        overturning, 2 when the block came to lie on its side.
    final_time, final_rotation, final_angular_velocity : float
        State at the end [s, rad, rad/s].
    time, rotation, angular_velocity : numpy.ndarray or None
        History at every step [s, rad, rad/s] if requested.
    impact_log : numpy.ndarray or None
        One row per impact: time [s], angular velocity before and after
        [rad/s] (if a history was requested).
    uplift_log : numpy.ndarray or None
        One row per start of rocking from rest: time [s] and side (+1 about
        ``pivot``, -1 about ``other_pivot``) (if a history was requested).
    """

    overturned: bool
    status: str
    time_overturned: float
    time_uplift: float
    rocked: bool
    max_abs_rotation: float
    impacts: int
    margin: float
    final_time: float
    final_rotation: float
    final_angular_velocity: float
    time: np.ndarray | None = None
    rotation: np.ndarray | None = None
    angular_velocity: np.ndarray | None = None
    impact_log: np.ndarray | None = None
    uplift_log: np.ndarray | None = None


_STATUS = {0: "rest", 1: "rocking", 2: "overturned", 3: "safe"}


def _excitation_arrays(excitation) -> tuple[int, np.ndarray, np.ndarray, np.ndarray]:
    if excitation is None:
        return _NONE, np.zeros(4), np.empty(0), np.empty(0)
    if isinstance(excitation, Pulse):
        exc = np.array([excitation.amplitude, excitation.omega, excitation.length, 0.0])
        return PULSE_KINDS[excitation.kind], exc, np.empty(0), np.empty(0)
    if isinstance(excitation, SampledAcceleration):
        exc = np.array([0.0, 0.0, excitation.length, excitation.dt])
        vertical = np.empty(0) if excitation.vertical is None else excitation.vertical
        return _RECORD, exc, excitation.values, vertical
    raise TypeError(
        f"excitation must be a Pulse, a SampledAcceleration or None, not {excitation!r}"
    )


def largest_step(block: RockingBlock) -> float:
    """Largest step [s] that resolves the rocking: 0.02 / p, p the larger of both pivots."""
    return _STEP_TIMES_P / max(block.about("pivot").p, block.about("other").p)


def default_step(block: RockingBlock, excitation=None) -> float:
    """Default fixed time step [s]: 0.02 / p and 1/400 of a pulse, whichever is smaller."""
    h = largest_step(block)
    if isinstance(excitation, Pulse):
        h = min(h, excitation.length / _STEPS_PER_PULSE)
    if isinstance(excitation, SampledAcceleration):
        h = min(h, excitation.dt / 4.0)
    return h


def simulate(
    block: RockingBlock,
    excitation: Pulse | SampledAcceleration | None,
    *,
    t_end: float | None = None,
    theta0: float = 0.0,
    omega0: float = 0.0,
    history: bool = False,
    max_step: float | None = None,
    decide: bool = False,
    max_history: int = 2_000_000,
    max_impact_log: int = 100_000,
    max_uplift_log: int = 100_000,
    rest_angular_velocity: float = 0.0,
    stop_at_rest_after: float = math.inf,
) -> RockingResult:
    """Rocking response of ``block`` to a support acceleration.

    Parameters
    ----------
    block : RockingBlock
        The block.
    excitation : Pulse or SampledAcceleration or None
        Support acceleration (zero after its end); None for free rocking.
    t_end : float, optional
        End of the simulation [s]; by default the end of the excitation plus
        ten periods 2 pi / p of free rocking.
    theta0, omega0 : float, optional
        Initial rotation [rad] and angular velocity [rad/s].
    history : bool, optional
        Keep the state at every step (rest included) and logs of impacts and
        of starts of rocking.
    max_step : float, optional
        Time step [s] (default :func:`default_step`).
    decide : bool, optional
        Stop as soon as the excitation has ended and decide the outcome from
        energy (faster; no time of overturning).
    max_history, max_impact_log, max_uplift_log : int, optional
        Capacity of the history and of the logs (later entries are dropped).
    rest_angular_velocity : float, optional
        The block settles on its base when its angular velocity after an
        impact is at most this [rad/s]; 0 (default) for 1e-6 of the angular
        velocity that carries it over its energy barrier.
    stop_at_rest_after : float, optional
        Stop at the first instant at or after this time [s], once the
        excitation has ended, at which the block rests on its base (status
        ``"rest"``); by default never (inf).

    Returns
    -------
    RockingResult
    """
    kind, exc, rec, vrec = _excitation_arrays(excitation)
    par = block_parameters(block)
    length = exc[2] if excitation is not None else 0.0
    if t_end is None:
        t_end = length + 10 * 2 * math.pi / block.p
    if not t_end > 0:
        raise ValueError(f"t_end must be positive, got {t_end!r}")
    h = default_step(block, excitation) if max_step is None else float(max_step)
    n_hist = max_history if history else 0
    ht = np.empty(n_hist)
    hth = np.empty(n_hist)
    hom = np.empty(n_hist)
    imp = np.empty((max_impact_log if history else 0, 3))
    lift = np.empty((max_uplift_log if history else 0, 2))
    out = np.empty(13)
    _simulate(
        par, kind, exc, rec, vrec, float(theta0), float(omega0), float(t_end), h, decide,
        ht, hth, hom, imp, lift, float(rest_angular_velocity), float(stop_at_rest_after), out,
    )  # fmt: skip
    n = int(out[9])
    n_imp = int(out[3])
    return RockingResult(
        overturned=bool(out[0] > 0.5),
        status=_STATUS[int(out[11])],
        time_overturned=float(out[1]),
        time_uplift=float(out[10]),
        rocked=bool(out[5] > 0.5),
        max_abs_rotation=float(out[2]),
        impacts=n_imp,
        margin=float(out[4]),
        final_time=float(out[8]),
        final_rotation=float(out[6]),
        final_angular_velocity=float(out[7]),
        time=ht[:n].copy() if history else None,
        rotation=hth[:n].copy() if history else None,
        angular_velocity=hom[:n].copy() if history else None,
        impact_log=imp[: min(n_imp, imp.shape[0])].copy() if history else None,
        uplift_log=lift[: min(int(out[12]), lift.shape[0])].copy() if history else None,
    )


def rocking_energy(block: RockingBlock, rotation, angular_velocity) -> np.ndarray:
    """Mechanical energy of the rocking block about its current pivot [J].

    E = 1/2 I_s omega^2 + m g' R_s cos(alpha_s - s theta), s = sgn(theta)
    (at theta = 0, the side the block moves to: sgn(omega)), the potential
    measured from the pivot level (constant between impacts under free
    rocking).
    """
    th = np.asarray(rotation, dtype=float)
    om = np.asarray(angular_velocity, dtype=float)
    plus, minus = block.about("pivot"), block.about("other")
    pos = (th > 0) | ((th == 0) & (om >= 0))
    inertia = np.where(pos, plus.inertia_about_pivot, minus.inertia_about_pivot)
    R = np.where(pos, plus.R, minus.R)
    al = np.where(pos, plus.alpha, minus.alpha)
    s = np.where(pos, 1.0, -1.0)
    return 0.5 * inertia * om**2 + block.mass * block.effective_gravity * R * np.cos(al - s * th)


def exact_rectangular_duration(
    block: RockingBlock, amplitude: np.ndarray | float, *, rel_tol: float = 1e-7
) -> np.ndarray | float:
    """Shortest rectangular pulse of amplitude a that overturns the block, exact.

    Parameters
    ----------
    block : RockingBlock
        The block; the pulse tips it over ``pivot``.
    amplitude : float or array_like
        Pulse acceleration a [m/s^2].
    rel_tol : float, optional
        Relative tolerance of the bisection on the duration [-].

    Returns
    -------
    float or numpy.ndarray
        Duration t1 [s] from the nonlinear equation of motion (the energy at
        the end of the pulse grows with its duration, so bisection applies);
        ``inf`` where a <= g' tan(alpha) (the block does not uplift).
        Compare :meth:`RockingBlock.housner_rectangular_duration` (paper
        Fig. 6).
    """
    a = np.atleast_1d(np.asarray(amplitude, dtype=float)).ravel()
    par = block_parameters(block)
    guess = np.asarray(block.housner_rectangular_duration(a), dtype=float)
    guess = np.where(np.isfinite(guess) & (guess > 0), guess, 1.0 / block.p)
    h_p = _STEP_TIMES_P / max(block.about("pivot").p, block.about("other").p)
    result = np.empty(a.size)
    _rect_duration_many(par, a, guess, h_p, rel_tol, result)
    return float(result[0]) if np.ndim(amplitude) == 0 else result.reshape(np.shape(amplitude))


@dataclass(frozen=True)
class MinimumAmplitudeResult:
    """Lowest overturning amplitudes of a pulse kind, against frequency.

    Parameters
    ----------
    kind : str
        Pulse kind (see :class:`Pulse`).
    frequency : numpy.ndarray or float
        Pulse frequencies f [Hz] (floats throughout for a scalar frequency).
    amplitude : numpy.ndarray or float
        Lowest overturning amplitude at each frequency [m/s^2]; ``inf`` where
        none was found up to the search limit.
    found : numpy.ndarray
        Whether an overturning amplitude was found (bool).
    search_limit : numpy.ndarray
        Largest amplitude tried at each frequency [m/s^2].
    rel_tol : float
        Relative width of the final bisection bracket [-].
    """

    kind: str
    frequency: np.ndarray
    amplitude: np.ndarray
    found: np.ndarray
    search_limit: np.ndarray
    rel_tol: float


def exact_minimum_overturning_amplitude(
    block: RockingBlock,
    pulse_kind: str,
    frequency: np.ndarray | float,
    *,
    scan_ratio: float | None = None,
    rel_tol: float = 1e-7,
    max_factor: float | None = None,
    step_scale: float = 1.0,
) -> MinimumAmplitudeResult:
    """Lowest amplitude of a pulse that overturns the block, from the exact equation.

    Parameters
    ----------
    block : RockingBlock
        The block; positive pulses tip it over ``pivot``.
    pulse_kind : str
        ``"half-sine"``, ``"one-sine"`` or ``"one-cosine"``.
    frequency : float or array_like
        Pulse frequencies f = omega / (2 pi) [Hz].
    scan_ratio : float, optional
        Ratio between successive amplitudes of the scan [-]; by default 1.002
        for the half-sine and 1.0005 for the one-sine and one-cosine pulses,
        whose overturning amplitudes break into narrow bands for long pulses
        (omega / p < 1). Bands narrower than the ratio can be missed unless the
        margin refinement catches them.
    rel_tol : float, optional
        Relative tolerance of the final bisection [-].
    max_factor : float, optional
        The scan stops at max_factor times Housner's half-sine amplitude (by
        default 10 for the half-sine, 40 for the others, at least 20 times the
        uplift threshold).
    step_scale : float, optional
        Multiplies the default time step (1/400 of the pulse, 0.02 / p) [-];
        for convergence checks.

    Returns
    -------
    MinimumAmplitudeResult

    Notes
    -----
    The amplitudes that overturn need not form one interval (Zhang and Makris
    2001): a block can overturn after an impact at amplitudes below those at
    which it overturns without one, and stronger pulses can leave it standing.
    The scan therefore starts at the uplift threshold (no rocking below),
    steps up by ``scan_ratio``, refines every local maximum of the
    overturning margin (:class:`RockingResult`) by golden-section search to
    catch bands narrower than a step, and bisects to the first overturning
    amplitude (:mod:`freestand.core.rocking.amplitude_search`, shared with the
    3-D body). Frequencies run in parallel (numba prange).
    """
    if pulse_kind not in PULSE_KINDS or pulse_kind == "rectangular":
        raise FreestandError(
            f"unknown pulse kind {pulse_kind!r} for a minimum-amplitude search; use "
            "'half-sine', 'one-sine' or 'one-cosine' (rectangular pulses: "
            "exact_rectangular_duration)",
            field="pulse",
        )
    if scan_ratio is None:
        scan_ratio = 1.002 if pulse_kind == "half-sine" else 1.0005
    if not scan_ratio > 1:
        raise ValueError(f"scan_ratio must exceed 1, got {scan_ratio!r}")
    f = np.atleast_1d(np.asarray(frequency, dtype=float)).ravel()
    if np.any(~(f > 0)) or not np.all(np.isfinite(f)):
        raise ValueError("frequencies must be positive and finite")
    kind = PULSE_KINDS[pulse_kind]
    par = block_parameters(block)
    thr_p = block.about("pivot").uplift_threshold
    thr_m = block.about("other").uplift_threshold
    a_lo = thr_p if pulse_kind == "half-sine" else min(thr_p, thr_m)
    omegas = 2 * np.pi * f
    if max_factor is None:
        max_factor = 10.0 if pulse_kind == "half-sine" else 40.0
    housner = np.asarray(block.housner_half_sine_amplitude(f), dtype=float)
    a_hi = np.maximum(max_factor * housner, 20.0 * a_lo)
    p = max(block.about("pivot").p, block.about("other").p)
    length = np.where(kind == 1, np.pi / omegas, 2 * np.pi / omegas)
    h = step_scale * np.minimum(length / _STEPS_PER_PULSE, _STEP_TIMES_P / p)
    result = np.empty(f.size)
    status = np.empty(f.size, dtype=np.int64)
    _min_amplitude_many(par, kind, omegas, a_lo, a_hi, scan_ratio, rel_tol, h, result, status)
    shape = np.shape(frequency)
    found = status == 0
    if not shape:
        return MinimumAmplitudeResult(
            kind=pulse_kind,
            frequency=float(f[0]),
            amplitude=float(result[0]),
            found=bool(found[0]),
            search_limit=float(a_hi[0]),
            rel_tol=rel_tol,
        )
    return MinimumAmplitudeResult(
        kind=pulse_kind,
        frequency=f.reshape(shape),
        amplitude=result.reshape(shape),
        found=found.reshape(shape),
        search_limit=a_hi.reshape(shape),
        rel_tol=rel_tol,
    )
