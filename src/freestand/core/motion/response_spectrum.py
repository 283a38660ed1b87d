"""Response spectra of acceleration records by the exact piecewise-linear recursion.

A linear single-degree-of-freedom oscillator of natural frequency f (circular
frequency omega = 2 pi f) and damping ratio zeta on a support with
acceleration a_g(t) obeys, for its displacement u relative to the support,

    u'' + 2 zeta omega u' + omega^2 u = -a_g(t).

A record is a sequence of samples a_g(t_i), t_i = i dt, joined by straight
lines. On each straight segment the equation has a closed-form solution, so
the state (u, u') is advanced from one sample to the next by an exact linear
recursion (Nigam and Jennings 1969):

    [u_{i+1}, u'_{i+1}] = A [u_i, u'_i] + B [a_i, a_{i+1}],

with the 2 x 2 matrices A and B depending only on omega, zeta and the step.

The recursion is exact at the samples for any step, but the peak of the
response can fall between samples. When the oscillator period is short
against the time step, each step is therefore divided into sub-steps: the
excitation stays on the same straight segment, so the sub-steps are exact as
well and the peak is sampled finely. A step is split into
``ceil(min_steps_per_period * dt / T)`` sub-steps. Where the response turns
between two sub-steps, its peak is taken on the cubic Hermite interpolant of
the exact values and derivatives at the two ends (error of order
(omega h)^4 / 384 instead of (omega h)^2 / 8 for the end values alone).
Frequencies may be given in any order; each is treated on its own.

After the last sample the support is taken to come to rest (the record is
followed by zeros, the last sample ramping to zero over one step) and the free
vibration of the oscillator is followed for one more period, which contains the
largest free-vibration peak.

References
----------
Nigam, N. C. and Jennings, P. C. (1969). Calculation of response spectra from
strong-motion earthquake records. Bulletin of the Seismological Society of
America 59(2), 909-922.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numba
import numpy as np

from freestand.core.motion.spectra import Spectrum

#: Default number of sub-steps per oscillator period below which a step is divided.
MIN_STEPS_PER_PERIOD = 20


#: Below this omega * h the closed-form coefficients lose digits to cancellation
#: (terms of order 1 / (omega^3 h)) and the matrix exponential is used instead.
_CLOSED_FORM_MIN_OMEGA_STEP = 0.1


@numba.njit(cache=True)
def _closed_form_coefficients(omega, zeta, h):
    """Coefficients (a11, a12, a21, a22, b11, b12, b21, b22) of one step ``h``.

    Nigam and Jennings (1969), eqs. 6-7, for u'' + 2 zeta omega u' + omega^2 u
    = -a_g(t) with a_g linear over the step.
    """
    root = math.sqrt(1.0 - zeta * zeta)
    omega_d = omega * root
    decay = math.exp(-zeta * omega * h)
    sin_d = math.sin(omega_d * h)
    cos_d = math.cos(omega_d * h)

    a11 = decay * (zeta / root * sin_d + cos_d)
    a12 = decay * sin_d / omega_d
    a21 = -omega / root * decay * sin_d
    a22 = decay * (cos_d - zeta / root * sin_d)

    w2 = omega * omega
    w3 = w2 * omega
    c1 = (2.0 * zeta * zeta - 1.0) / (w2 * h)
    c2 = 2.0 * zeta / (w3 * h)
    # derivative terms of the (cos, sin) combinations
    cos_minus = cos_d - zeta / root * sin_d
    sin_plus = omega_d * sin_d + zeta * omega * cos_d

    b11 = decay * ((c1 + zeta / omega) * sin_d / omega_d + (c2 + 1.0 / w2) * cos_d) - c2
    b12 = -decay * (c1 * sin_d / omega_d + c2 * cos_d) - 1.0 / w2 + c2
    b21 = decay * ((c1 + zeta / omega) * cos_minus - (c2 + 1.0 / w2) * sin_plus) + 1.0 / (w2 * h)
    b22 = -decay * (c1 * cos_minus - c2 * sin_plus) - 1.0 / (w2 * h)
    return a11, a12, a21, a22, b11, b12, b21, b22


def _exponential_coefficients(omega, zeta, h):
    """The same coefficients from the matrix exponential of the augmented system.

    The state (u, u', a_g, a_g') of a linearly varying excitation obeys
    z' = M z with constant M, so one step is z(h) = expm(M h) z(0), exact and
    free of cancellation for small omega h.
    """
    from scipy.linalg import expm

    matrix = np.array(
        [
            [0.0, 1.0, 0.0, 0.0],
            [-omega * omega, -2.0 * zeta * omega, -1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
            [0.0, 0.0, 0.0, 0.0],
        ]
    )
    e = expm(matrix * h)
    return (
        e[0, 0],
        e[0, 1],
        e[1, 0],
        e[1, 1],
        e[0, 2] - e[0, 3] / h,
        e[0, 3] / h,
        e[1, 2] - e[1, 3] / h,
        e[1, 3] / h,
    )


def _step_coefficients(omega: float, zeta: float, h: float) -> tuple[float, ...]:
    """Exact one-step coefficients: closed form, or matrix exponential for small omega h."""
    if omega * h >= _CLOSED_FORM_MIN_OMEGA_STEP:
        return tuple(float(c) for c in _closed_form_coefficients(omega, zeta, h))
    return tuple(float(c) for c in _exponential_coefficients(omega, zeta, h))


@numba.njit(cache=True)
def _cubic_extreme(y0, y1, d0, d1, h):
    """Largest |p(s)| at the interior extrema of the cubic Hermite interpolant.

    p matches the values y0, y1 and the slopes d0, d1 at the ends of a step of
    length h; its error is of order h^4, so the peak between two sub-steps is
    found to about (omega h)^4 / 384 of the amplitude instead of the
    (omega h)^2 / 8 of the end values alone.
    """
    c1 = h * d0
    c2 = -3.0 * y0 - 2.0 * h * d0 + 3.0 * y1 - h * d1
    c3 = 2.0 * y0 + h * d0 - 2.0 * y1 + h * d1
    qa = 3.0 * c3
    qb = 2.0 * c2
    best = 0.0
    roots = np.empty(2)
    n_roots = 0
    if qa == 0.0:
        if qb != 0.0:
            roots[0] = -c1 / qb
            n_roots = 1
    else:
        disc = qb * qb - 4.0 * qa * c1
        if disc >= 0.0:
            sq = math.sqrt(disc)
            roots[0] = (-qb - sq) / (2.0 * qa)
            roots[1] = (-qb + sq) / (2.0 * qa)
            n_roots = 2
    for r in range(n_roots):
        x = roots[r]
        if 0.0 < x < 1.0:
            value = abs(y0 + x * (c1 + x * (c2 + x * c3)))
            if value > best:
                best = value
    return best


@numba.njit(cache=True, inline="always")
def nigam_jennings_step(coefficients, u, v, p0, p1):
    """One exact step of the piecewise-linear recursion: ``(u1, v1)``.

    ``[u1, v1] = A [u, v] + B [p0, p1]`` (Nigam and Jennings 1969, eqs. 6-7),
    with ``coefficients`` the eight entries ``(a11, a12, a21, a22, b11, b12,
    b21, b22)`` of A and B for the step (:func:`nigam_jennings_coefficients`),
    ``u`` [m] and ``v`` [m/s] the relative displacement and velocity at its
    start and ``p0``, ``p1`` [m/s^2] the support acceleration at its ends.
    """
    u1 = coefficients[0] * u + coefficients[1] * v + coefficients[4] * p0 + coefficients[5] * p1
    v1 = coefficients[2] * u + coefficients[3] * v + coefficients[6] * p0 + coefficients[7] * p1
    return u1, v1


@numba.njit(cache=True, inline="always")
def record_segment(acceleration, i):
    """Support accelerations [m/s^2] at both ends of record step ``i``.

    The record's samples joined by straight lines; after the last sample the
    support comes to rest, its acceleration ramping to zero over one step.
    """
    a_end = acceleration[i + 1] if i + 1 < acceleration.size else 0.0
    return acceleration[i], a_end


@numba.njit(cache=True, inline="always")
def substep_loads(a_start, a_end, substeps, j):
    """Support accelerations [m/s^2] at both ends of sub-step ``j`` of a record step.

    The step from ``a_start`` to ``a_end`` divided into ``substeps`` equal
    sub-steps on its straight segment (exact for the recursion).
    """
    slope = (a_end - a_start) / substeps
    return a_start + slope * j, a_start + slope * (j + 1)


@numba.njit(cache=True, inline="always")
def peak_between(peak, y0, y1, d0, d1, h):
    """``peak`` raised to ``|y1|``, and to the extreme of the cubic Hermite interpolant
    (:func:`_cubic_extreme`) where ``y`` turns within the sub-step of ``h`` [s]
    (its rates ``d0``, ``d1`` at the ends differ in sign)."""
    x = abs(y1)
    if d0 * d1 < 0.0:
        x = max(x, _cubic_extreme(y0, y1, d0, d1, h))
    return x if x > peak else peak


@numba.njit(cache=True, inline="always")
def _displacement_substep(coefficients, h, u, v, p0, p1, peak_u):
    """One sub-step of the recursion and the displacement peak: ``(u1, v1, peak_u)``."""
    u1, v1 = nigam_jennings_step(coefficients, u, v, p0, p1)
    return u1, v1, peak_between(peak_u, u, u1, v, v1, h)


@numba.njit(cache=True, inline="always")
def _response_substep(coefficients, h, c, w2, u, v, p0, p1, pu, pv, pa):
    """One sub-step of the recursion and the peaks of |u|, |u'| and |u'' + a_g|
    (``c = 2 zeta omega``, ``w2 = omega^2``): ``(u1, v1, pu, pv, pa)``."""
    u1, v1, pu = _displacement_substep(coefficients, h, u, v, p0, p1, pu)
    # relative acceleration u'' and absolute acceleration A = u'' + a_g, with A'
    ur0 = -p0 - c * v - w2 * u
    ur1 = -p1 - c * v1 - w2 * u1
    abs0 = -(c * v + w2 * u)
    abs1 = -(c * v1 + w2 * u1)
    dabs0 = -(c * ur0 + w2 * v)
    dabs1 = -(c * ur1 + w2 * v1)
    pv = peak_between(pv, v, v1, ur0, ur1, h)
    pa = peak_between(pa, abs0, abs1, dabs0, dabs1, h)
    return u1, v1, pu, pv, pa


@numba.njit(cache=True)
def _peak_response_kernel(acceleration, dt, omegas, zeta, coefficients, substeps, free_steps):
    """Peaks of |u|, |u'| and |u'' + a_g| for each circular frequency.

    ``coefficients[k]`` holds the eight step coefficients for the sub-step
    ``dt / substeps[k]``; ``free_steps[k]`` sub-steps of free vibration follow
    the record. Between sub-steps, a peak (sign change of the derivative) is
    located on the cubic Hermite interpolant of the exact end values and
    derivatives.
    """
    n_freq = omegas.size
    peak_u = np.zeros(n_freq)
    peak_v = np.zeros(n_freq)
    peak_abs = np.zeros(n_freq)
    for k in range(n_freq):
        omega = omegas[k]
        m = substeps[k]
        h = dt / m
        c = 2.0 * zeta * omega
        w2 = omega * omega
        u = 0.0
        v = 0.0
        pu = 0.0
        pv = 0.0
        pa = 0.0
        # the record, then one step ramping its last sample to zero, then free vibration
        for i in range(acceleration.size):
            a_start, a_end = record_segment(acceleration, i)
            for j in range(m):
                p0, p1 = substep_loads(a_start, a_end, m, j)
                u, v, pu, pv, pa = _response_substep(coefficients[k], h, c, w2, u, v, p0, p1,
                                                     pu, pv, pa)  # fmt: skip
        for _ in range(free_steps[k]):
            u, v, pu, pv, pa = _response_substep(coefficients[k], h, c, w2, u, v, 0.0, 0.0, pu,
                                                 pv, pa)  # fmt: skip
        peak_u[k] = pu
        peak_v[k] = pv
        peak_abs[k] = pa
    return peak_u, peak_v, peak_abs


@numba.njit(cache=True, parallel=True)
def _peak_displacement_kernel(acceleration, dt, omegas, coefficients, substeps, free_steps):
    """Peaks of |u| only, for each circular frequency, frequencies in parallel.

    The same recursion and the same cubic peak search between sub-steps as
    :func:`_peak_response_kernel` (so the same values of max |u|), without the
    velocity and absolute-acceleration peaks: the inner loop of spectral
    matching, which needs only the pseudo-acceleration. Returns the peak over
    the record and its free vibration, and the peak over the record alone
    (up to the end of the last sample's ramp to zero).
    """
    n_freq = omegas.size
    peak_u = np.zeros(n_freq)
    peak_u_record = np.zeros(n_freq)
    for k in numba.prange(n_freq):
        m = substeps[k]
        h = dt / m
        u = 0.0
        v = 0.0
        pu = 0.0
        for i in range(acceleration.size):
            a_start, a_end = record_segment(acceleration, i)
            for j in range(m):
                p0, p1 = substep_loads(a_start, a_end, m, j)
                u, v, pu = _displacement_substep(coefficients[k], h, u, v, p0, p1, pu)
        peak_u_record[k] = pu
        for _ in range(free_steps[k]):
            u, v, pu = _displacement_substep(coefficients[k], h, u, v, 0.0, 0.0, pu)
        peak_u[k] = pu
    return peak_u, peak_u_record


@numba.njit(cache=True)
def _history_kernel(acceleration, coefficients):
    """Relative displacement and velocity at the samples (exact recursion)."""
    n = acceleration.size
    u = np.zeros(n)
    v = np.zeros(n)
    for i in range(n - 1):
        u[i + 1], v[i + 1] = nigam_jennings_step(
            coefficients, u[i], v[i], acceleration[i], acceleration[i + 1]
        )
    return u, v


def nigam_jennings_coefficients(
    frequency: float, damping: float, step: float
) -> tuple[np.ndarray, np.ndarray]:
    """The matrices A and B of one exact step of the piecewise-linear recursion.

    Parameters
    ----------
    frequency : float
        Oscillator natural frequency f [Hz], positive.
    damping : float
        Damping ratio zeta [-], ``0 <= zeta < 1``.
    step : float
        Step h [s], positive.

    Returns
    -------
    A, B : numpy.ndarray
        2 x 2 arrays such that ``[u1, v1] = A @ [u0, v0] + B @ [a0, a1]`` for
        ``u'' + 2 zeta omega u' + omega^2 u = -a_g(t)`` with ``a_g`` going
        linearly from ``a0`` to ``a1`` over the step (Nigam and Jennings 1969,
        eqs. 6-7).
    """
    _check_damping(damping)
    if not (frequency > 0 and step > 0):
        raise ValueError("frequency and step must be positive")
    c = _step_coefficients(2.0 * math.pi * frequency, float(damping), float(step))
    return np.array([[c[0], c[1]], [c[2], c[3]]]), np.array([[c[4], c[5]], [c[6], c[7]]])


@dataclass(frozen=True)
class SpectralResponse:
    """Peak responses of linear oscillators to one record.

    All arrays are in the order of the requested frequencies (any order).

    Parameters
    ----------
    frequency : numpy.ndarray
        Oscillator natural frequencies f [Hz], as requested.
    damping : float
        Damping ratio zeta [-].
    displacement : numpy.ndarray
        Spectral displacement S_d = max |u| [m].
    relative_velocity : numpy.ndarray
        Peak relative velocity max |u'| [m/s].
    absolute_acceleration : numpy.ndarray
        Peak absolute acceleration max |u'' + a_g| [m/s^2].
    substeps : numpy.ndarray
        Sub-steps per record step used for each frequency [-].
    dt : float
        Time step of the record [s].
    """

    frequency: np.ndarray
    damping: float
    displacement: np.ndarray
    relative_velocity: np.ndarray
    absolute_acceleration: np.ndarray
    substeps: np.ndarray
    dt: float

    @property
    def circular_frequency(self) -> np.ndarray:
        """omega = 2 pi f [rad/s]."""
        return 2.0 * np.pi * self.frequency

    @property
    def pseudo_velocity(self) -> np.ndarray:
        """Pseudo-velocity PSV = omega S_d [m/s]."""
        return self.circular_frequency * self.displacement

    @property
    def pseudo_acceleration(self) -> np.ndarray:
        """Pseudo-acceleration PSA = omega^2 S_d [m/s^2]."""
        return self.circular_frequency**2 * self.displacement


@dataclass(frozen=True)
class OscillatorResponse:
    """Time history of one linear oscillator at the record samples.

    Parameters
    ----------
    time : numpy.ndarray
        t_i = i dt [s].
    displacement : numpy.ndarray
        Relative displacement u [m].
    velocity : numpy.ndarray
        Relative velocity u' [m/s].
    absolute_acceleration : numpy.ndarray
        u'' + a_g = -(2 zeta omega u' + omega^2 u) [m/s^2].
    frequency : float
        Natural frequency [Hz].
    damping : float
        Damping ratio [-].
    """

    time: np.ndarray
    displacement: np.ndarray
    velocity: np.ndarray
    absolute_acceleration: np.ndarray
    frequency: float
    damping: float
    metadata: dict = field(default_factory=dict, compare=False)


@dataclass(frozen=True)
class SpectrumPlan:
    """Step coefficients of the recursion for fixed frequencies, step and damping.

    Building the coefficients costs more than one pass over a short record at
    low frequencies (matrix exponential); a plan computes them once, so that
    many records of the same step (spectral matching, record suites) reuse them.

    Parameters
    ----------
    frequency : numpy.ndarray
        Oscillator natural frequencies f [Hz].
    dt : float
        Record time step [s].
    damping : float
        Damping ratio zeta [-].
    omegas, coefficients, substeps, free_steps : numpy.ndarray
        omega = 2 pi f [rad/s], the eight step coefficients per frequency for
        the sub-step dt / substeps, the sub-steps per record step [-] and the
        free-vibration sub-steps after the record [-].
    """

    frequency: np.ndarray
    dt: float
    damping: float
    omegas: np.ndarray
    coefficients: np.ndarray
    substeps: np.ndarray
    free_steps: np.ndarray

    @classmethod
    def build(
        cls,
        frequencies,
        dt: float,
        damping: float = 0.05,
        min_steps_per_period: int = MIN_STEPS_PER_PERIOD,
        free_vibration: bool = True,
    ) -> SpectrumPlan:
        """Coefficients for ``frequencies`` [Hz] at step ``dt`` [s] and ``damping`` [-]."""
        _check_damping(damping)
        f = np.ascontiguousarray(np.atleast_1d(np.asarray(frequencies, dtype=float)))
        if f.ndim != 1 or f.size == 0 or not np.all(np.isfinite(f)) or np.any(f <= 0):
            raise ValueError("frequencies must be a non-empty 1-D array of positive values")
        if not (dt > 0 and math.isfinite(dt)):
            raise ValueError(f"dt must be positive and finite, got {dt!r}")
        if min_steps_per_period < 1:
            raise ValueError("min_steps_per_period must be at least 1")
        omegas = 2.0 * np.pi * f
        substeps = np.maximum(1, np.ceil(min_steps_per_period * dt * f - 1e-9)).astype(np.int64)
        if free_vibration:
            free_steps = np.ceil(1.0 / (f * (dt / substeps))).astype(np.int64) + 1
        else:
            free_steps = np.zeros(f.size, dtype=np.int64)
        coefficients = np.array(
            [
                _step_coefficients(w, float(damping), dt / m)
                for w, m in zip(omegas, substeps, strict=True)
            ]
        )
        return cls(f, float(dt), float(damping), omegas, coefficients, substeps, free_steps)

    def peaks(self, acceleration: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Peaks of |u| [m], |u'| [m/s] and |u'' + a_g| [m/s^2] under ``acceleration``."""
        return _peak_response_kernel(
            np.ascontiguousarray(acceleration, dtype=float),
            self.dt,
            self.omegas,
            self.damping,
            self.coefficients,
            self.substeps,
            self.free_steps,
        )

    def pseudo_acceleration(self, acceleration: np.ndarray) -> np.ndarray:
        """PSA = omega^2 max|u| [m/s^2] at each frequency of the plan.

        Only the displacement peaks are followed (frequencies in parallel).
        """
        return self.pseudo_acceleration_bounds(acceleration)[0]

    def pseudo_acceleration_bounds(self, acceleration: np.ndarray) -> tuple[np.ndarray, ...]:
        """PSA [m/s^2] with the free vibration after the record, and over the record alone.

        Spectra computed without following the free vibration (a common
        simplification) lie between the two; acceptance checks that hold for
        the second as a lower bound and the first as an upper bound hold for
        either convention.
        """
        peak_u, peak_u_record = _peak_displacement_kernel(
            np.ascontiguousarray(acceleration, dtype=float),
            self.dt,
            self.omegas,
            self.coefficients,
            self.substeps,
            self.free_steps,
        )
        w2 = self.omegas**2
        return w2 * peak_u, w2 * peak_u_record


def _check_damping(damping: float) -> None:
    if not (0.0 <= damping < 1.0):
        raise ValueError(f"damping ratio must satisfy 0 <= damping < 1, got {damping!r}")


#: Components of a record a spectrum can be taken of (x, y, vertical).
_COMPONENTS = ("horizontal", "horizontal_y", "vertical")


def _is_record(value) -> bool:
    """A record in the sense of :class:`freestand.core.motion.ground_motion.GroundMotion`.

    Read by its attributes (``dt``, ``horizontal``, ``vertical``, ``name``),
    so that spectra need not import the record type that uses them.
    """
    return all(hasattr(value, name) for name in ("dt", "horizontal", "vertical", "name"))


def _record_arrays(motion_or_array, dt, component):
    if _is_record(motion_or_array):
        if dt is not None and not math.isclose(dt, motion_or_array.dt, rel_tol=1e-12):
            raise ValueError(f"dt={dt!r} differs from the motion's dt={motion_or_array.dt!r}")
        motion = motion_or_array
        if component not in _COMPONENTS:
            raise ValueError(
                f"component must be one of {', '.join(_COMPONENTS)}, got {component!r}"
            )
        acceleration = getattr(motion, component, None)
        if acceleration is None:
            raise ValueError(f"motion {motion.name!r} has no {component} component")
        return np.ascontiguousarray(acceleration, dtype=float), float(motion.dt), motion.name
    if dt is None:
        raise ValueError("dt is required when the record is given as an array")
    acceleration = np.ascontiguousarray(np.asarray(motion_or_array, dtype=float))
    if acceleration.ndim != 1 or acceleration.size < 2:
        raise ValueError("the acceleration record must be a 1-D array of at least 2 samples")
    if not np.all(np.isfinite(acceleration)):
        raise ValueError("the acceleration record contains non-finite values")
    if not (dt > 0 and math.isfinite(dt)):
        raise ValueError(f"dt must be positive and finite, got {dt!r}")
    return acceleration, float(dt), ""


def default_frequencies() -> np.ndarray:
    """100 frequencies spaced evenly on a log scale from 0.1 Hz to 100 Hz [Hz]."""
    return np.geomspace(0.1, 100.0, 100)


def spectral_response(
    motion_or_array,
    dt: float | None = None,
    frequencies=None,
    damping: float = 0.05,
    *,
    component: str = "horizontal",
    min_steps_per_period: int = MIN_STEPS_PER_PERIOD,
    free_vibration: bool = True,
) -> SpectralResponse:
    """Peak oscillator responses to a record (exact piecewise-linear recursion).

    Parameters
    ----------
    motion_or_array : GroundMotion or array_like
        The record: a :class:`~freestand.core.motion.ground_motion.GroundMotion` or
        support accelerations a_g(t_i) [m/s^2] at t_i = i dt.
    dt : float, optional
        Time step [s]; required with an array.
    frequencies : array_like, optional
        Oscillator natural frequencies [Hz], positive, in any order
        (default :func:`default_frequencies`).
    damping : float, optional
        Damping ratio zeta [-], ``0 <= zeta < 1`` (default 0.05).
    component : str, optional
        ``"horizontal"`` (x), ``"horizontal_y"`` or ``"vertical"`` component of
        a GroundMotion.
    min_steps_per_period : int, optional
        Each record step is split so that an oscillator period spans at
        least this many sub-steps [-] (default 20).
    free_vibration : bool, optional
        Follow the free vibration for one period after the record (default
        True).

    Returns
    -------
    SpectralResponse
        Peaks in the order of ``frequencies``.

    Notes
    -----
    u'' + 2 zeta omega u' + omega^2 u = -a_g(t), advanced by the exact
    recursion of Nigam and Jennings (1969) over each straight segment of the
    record (sub-divided when omega dt > 2 pi / min_steps_per_period).
    """
    acceleration, dt, _ = _record_arrays(motion_or_array, dt, component)
    _check_damping(damping)
    f = default_frequencies() if frequencies is None else np.asarray(frequencies, dtype=float)
    f = np.atleast_1d(f)
    if f.ndim != 1 or f.size == 0:
        raise ValueError("frequencies must be a non-empty 1-D array")
    if not np.all(np.isfinite(f)) or np.any(f <= 0):
        raise ValueError("frequencies must be positive and finite")
    if min_steps_per_period < 1:
        raise ValueError("min_steps_per_period must be at least 1")
    plan = SpectrumPlan.build(f, dt, damping, min_steps_per_period, free_vibration)
    peak_u, peak_v, peak_abs = plan.peaks(acceleration)
    substeps = plan.substeps
    return SpectralResponse(
        frequency=f.copy(),
        damping=float(damping),
        displacement=peak_u,
        relative_velocity=peak_v,
        absolute_acceleration=peak_abs,
        substeps=substeps,
        dt=dt,
    )


def response_spectrum(
    motion_or_array,
    dt: float | None = None,
    frequencies=None,
    damping: float = 0.05,
    *,
    component: str = "horizontal",
    min_steps_per_period: int = MIN_STEPS_PER_PERIOD,
    free_vibration: bool = True,
    label: str | None = None,
) -> Spectrum:
    """Pseudo-acceleration response spectrum of a record as a :class:`Spectrum`.

    Parameters
    ----------
    motion_or_array : GroundMotion or array_like
        The record (support accelerations [m/s^2] when an array).
    dt : float, optional
        Time step [s]; required with an array.
    frequencies : array_like, optional
        At least two distinct natural frequencies [Hz] in any order
        (default :func:`default_frequencies`); the spectrum is tabulated at
        the sorted distinct values.
    damping : float, optional
        Damping ratio zeta [-], ``0 <= zeta < 1`` (default 0.05).
    component : str, optional
        ``"horizontal"`` (x), ``"horizontal_y"`` or ``"vertical"``; also the
        spectrum's direction (``"horizontal"`` for either horizontal component).
    min_steps_per_period : int, optional
        Minimum sub-steps per oscillator period [-] (default 20).
    free_vibration : bool, optional
        Follow the free vibration for one period after the record.
    label : str, optional
        Spectrum label (default: record name and damping).

    Returns
    -------
    Spectrum
        PSA = omega^2 max|u| [m/s^2] against increasing frequency [Hz];
        ``metadata`` holds the peak relative displacement, velocity, absolute
        acceleration and the sub-step counts.

    Notes
    -----
    Exact piecewise-linear recursion of Nigam and Jennings (1969); see
    :func:`spectral_response`.
    """
    f = default_frequencies() if frequencies is None else np.asarray(frequencies, dtype=float)
    f = np.unique(np.atleast_1d(f))
    if f.size < 2:
        raise ValueError("a response spectrum needs at least two distinct frequencies")
    response = spectral_response(
        motion_or_array,
        dt,
        f,
        damping,
        component=component,
        min_steps_per_period=min_steps_per_period,
        free_vibration=free_vibration,
    )
    _, _, name = _record_arrays(motion_or_array, dt, component)
    if label is None:
        label = f"{name + ' ' if name else ''}PSA {100 * damping:g} % damping ({component})"
    return Spectrum(
        frequency=response.frequency,
        acceleration=response.pseudo_acceleration,
        damping=float(damping),
        direction="vertical" if component == "vertical" else "horizontal",
        label=label,
        metadata={
            "source": "record",
            "method": "Nigam-Jennings 1969 exact piecewise-linear recursion",
            "record": name,
            "dt": response.dt,
            "spectral_displacement": response.displacement,
            "relative_velocity": response.relative_velocity,
            "absolute_acceleration": response.absolute_acceleration,
            "substeps": response.substeps,
        },
    )


def oscillator_response(
    motion_or_array,
    frequency: float,
    damping: float = 0.05,
    dt: float | None = None,
    *,
    component: str = "horizontal",
) -> OscillatorResponse:
    """Time history of one oscillator at the record samples.

    Parameters
    ----------
    motion_or_array : GroundMotion or array_like
        The record (support accelerations [m/s^2] when an array).
    frequency : float
        Natural frequency f [Hz], positive.
    damping : float, optional
        Damping ratio zeta [-], ``0 <= zeta < 1``.
    dt : float, optional
        Time step [s]; required with an array.
    component : str, optional
        ``"horizontal"`` (x), ``"horizontal_y"`` or ``"vertical"`` component of
        a GroundMotion.

    Returns
    -------
    OscillatorResponse
        u, u' and u'' + a_g at t_i = i dt, exact for the piecewise-linear
        record (Nigam and Jennings 1969).
    """
    acceleration, dt, name = _record_arrays(motion_or_array, dt, component)
    _check_damping(damping)
    if not (frequency > 0 and math.isfinite(frequency)):
        raise ValueError(f"frequency must be positive and finite, got {frequency!r}")
    omega = 2.0 * math.pi * frequency
    u, v = _history_kernel(acceleration, np.array(_step_coefficients(omega, float(damping), dt)))
    return OscillatorResponse(
        time=np.arange(acceleration.size) * dt,
        displacement=u,
        velocity=v,
        absolute_acceleration=-(2.0 * damping * omega * v + omega**2 * u),
        frequency=float(frequency),
        damping=float(damping),
        metadata={"record": name},
    )


def floor_motion(
    motion,
    frequency: float,
    damping: float = 0.05,
    *,
    vertical_frequency: float | None = None,
    vertical_damping: float | None = None,
):
    """In-structure (floor) motion: a record filtered by a linear oscillator.

    Equipment standing on a structure that does not interact with it (its
    mass is small against the structure's modal mass) feels the absolute
    acceleration of the structure at its location. When one mode of frequency
    f and damping zeta dominates, that is the absolute acceleration of a linear
    oscillator on the ground:

        u'' + 2 zeta omega u' + omega^2 u = -a_g(t),   a_floor = u'' + a_g
                                                     = -(2 zeta omega u' + omega^2 u),

    computed at the samples by the exact piecewise-linear recursion of Nigam
    and Jennings (1969) (:func:`oscillator_response`). The peak of a_floor is
    the ground's absolute-acceleration spectrum at f, which is the peak the
    paper uses for its horizontally elastic structure (2.5 Hz, 5 %, paper
    section 4).

    Parameters
    ----------
    motion : GroundMotion
        The ground record [m/s^2].
    frequency : float
        Natural frequency of the structure's horizontal mode f [Hz], positive;
        a second horizontal component (y) is filtered by a mode of the same
        frequency and damping.
    damping : float, optional
        Its damping ratio zeta [-] (default 0.05).
    vertical_frequency : float, optional
        Frequency [Hz] of a vertical mode that filters the vertical component;
        by default the vertical component passes unchanged (a structure rigid
        vertically, as the paper's crane support).
    vertical_damping : float, optional
        Damping ratio [-] of the vertical mode (default ``damping``).

    Returns
    -------
    GroundMotion
        The floor motion, same step and length; ``metadata["floor"]`` records
        the filter. The record is not extended: follow it with zeros
        (``with_trailing_zeros``) first to keep the structure's free vibration.
    """
    horizontal = oscillator_response(motion, frequency, damping, component="horizontal")
    horizontal_y = None
    if getattr(motion, "horizontal_y", None) is not None:
        horizontal_y = oscillator_response(
            motion, frequency, damping, component="horizontal_y"
        ).absolute_acceleration
    vertical = motion.vertical
    note = {"frequency": float(frequency), "damping": float(damping)}
    if vertical_frequency is not None and motion.vertical is not None:
        zeta_v = damping if vertical_damping is None else vertical_damping
        vertical = oscillator_response(
            motion, vertical_frequency, zeta_v, component="vertical"
        ).absolute_acceleration
        note.update(vertical_frequency=float(vertical_frequency), vertical_damping=float(zeta_v))
    metadata = dict(motion.metadata)
    metadata["floor"] = note
    name = f"{motion.name} floor {frequency:g} Hz {100 * damping:g} %"
    return motion._replace(
        horizontal=horizontal.absolute_acceleration,
        horizontal_y=horizontal_y,
        vertical=vertical,
        name=name.strip(),
        metadata=metadata,
    )
