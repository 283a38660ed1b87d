"""Intensity of two horizontal components independent of their orientation (Boore 2010).

A record's two horizontal components a_x(t), a_y(t) describe one horizontal
ground motion; the values a single component gives (its PGA, its spectral
ordinate) depend on the direction the instrument happened to be turned to.
Boore (2010) defines measures that do not:

- the **rotated time series** at angle theta,

      a_theta(t) = a_x(t) cos theta + a_y(t) sin theta,

  the motion along the direction theta from x (counter-clockwise seen from
  above, towards y); theta and theta + 180 deg give the same series with the
  opposite sign, so the non-redundant angles are 0 <= theta < 180 deg;
- the peak of a measure over time at each angle (PGA, PGV, or the peak
  oscillator response for Sa), and **RotDnn**, the nn-th percentile of those
  peaks over the angles: RotD50 the median, RotD100 the largest, RotD00 the
  smallest.

The oscillator response is linear in the record, so the response to a_theta
is u_theta(t) = u_x(t) cos theta + u_y(t) sin theta: the two components'
responses are computed once (the exact piecewise-linear recursion of
:mod:`freestand.core.motion.response_spectrum`, on the same sub-steps, with
the free vibration after the record) and combined at every angle; the peak
of each u_theta between two sub-steps is found on the cubic Hermite
interpolant of its values and rates, as for one component. For a single
component (a_y = 0) RotD100 of Sa is the component's own Sa.

The angles are those of Boore (2010): 0 to 179 deg at 1 deg steps (180
angles; a finer step may be asked for). RotD50 is the median of the peaks at
those angles, the mean of the two middle values of the 180 sorted peaks
(:func:`numpy.percentile`, linear interpolation).

The geometric mean of the two components' measures, sqrt(IM_x IM_y), the
measure most ground-motion models used before RotD50, is given as well.

References
----------
Boore, D. M. (2010). Orientation-independent, nongeometric-mean measures of
seismic intensity from two horizontal components of motion. Bulletin of the
Seismological Society of America 100(4), 1830-1835.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from freestand.core.motion.response_spectrum import (
    SpectrumPlan,
    nigam_jennings_step,
    peak_between,
    record_segment,
    substep_loads,
)

#: Boore's (2010) angle step [deg] over the non-redundant angles 0 <= theta < 180 deg.
ANGLE_STEP = 1.0


def rotation_angles(step: float = ANGLE_STEP) -> np.ndarray:
    """The non-redundant rotation angles 0, step, ..., < 180 deg, in radians [rad].

    Parameters
    ----------
    step : float, optional
        Angle step [deg] (default 1 deg, Boore 2010); must divide 180 deg
        into a whole number of steps.
    """
    if not (step > 0 and math.isfinite(step)):
        raise ValueError(f"the angle step must be positive, not {step!r} deg")
    count = 180.0 / step
    if abs(count - round(count)) > 1e-9 * count:
        raise ValueError(f"an angle step of {step:g} deg does not divide 180 deg")
    return np.deg2rad(np.arange(int(round(count))) * step)


def _check_pair(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    x = np.ascontiguousarray(x, dtype=float)
    y = np.ascontiguousarray(y, dtype=float)
    if x.ndim != 1 or x.shape != y.shape or x.size < 2:
        raise ValueError("the two horizontal components must be 1-D arrays of the same length")
    return x, y


@numba.njit(cache=True)
def _sample_peaks_kernel(x, y, cosines, sines):
    """max_i |x_i cos theta + y_i sin theta| for each angle."""
    peaks = np.zeros(cosines.size)
    for k in range(cosines.size):
        c = cosines[k]
        s = sines[k]
        best = 0.0
        for i in range(x.size):
            value = abs(c * x[i] + s * y[i])
            if value > best:
                best = value
        peaks[k] = best
    return peaks


def peaks_over_angles(x, y, angles: np.ndarray | None = None) -> np.ndarray:
    """Peak of the rotated series max_t |x cos theta + y sin theta| at each angle.

    Parameters
    ----------
    x, y : array_like
        The two horizontal components at the same samples (accelerations
        [m/s^2] for PGA, velocities [m/s] for PGV).
    angles : numpy.ndarray, optional
        Rotation angles theta [rad] (default :func:`rotation_angles`).

    Returns
    -------
    numpy.ndarray
        The peak at each angle, in the unit of ``x``. The peak of a
        piecewise-linear series is at a sample, so this is exact for
        accelerations; velocities are taken at the samples, as the planar
        PGV is.
    """
    x, y = _check_pair(x, y)
    angles = rotation_angles() if angles is None else np.asarray(angles, dtype=float)
    return _sample_peaks_kernel(x, y, np.cos(angles), np.sin(angles))


@numba.njit(cache=True)
def _spectral_peaks_kernel(x, y, dt, coefficients, substeps, free_steps, cosines, sines):
    """max_t |u_theta(t)| of one oscillator under the rotated series, for each angle.

    The responses u_x, u_y (and rates v_x, v_y) to the two components are
    advanced together by the exact recursion over ``substeps`` sub-steps per
    record step, then ``free_steps`` sub-steps of free vibration; at every
    sub-step each angle's u_theta = u_x cos + u_y sin is compared with its
    peak, and where v_theta changes sign the peak between the sub-steps is
    taken on the cubic Hermite interpolant (as in the one-component kernel).
    """
    n = x.size
    m = substeps
    h = dt / m
    n_angles = cosines.size
    peaks = np.zeros(n_angles)
    ux = 0.0
    vx = 0.0
    uy = 0.0
    vy = 0.0
    for step in range(n * m + free_steps):
        if step < n * m:
            i = step // m
            j = step - i * m
            x0, x1 = record_segment(x, i)
            y0, y1 = record_segment(y, i)
            px0, px1 = substep_loads(x0, x1, m, j)
            py0, py1 = substep_loads(y0, y1, m, j)
        else:
            px0 = 0.0
            px1 = 0.0
            py0 = 0.0
            py1 = 0.0
        ux1, vx1 = nigam_jennings_step(coefficients, ux, vx, px0, px1)
        uy1, vy1 = nigam_jennings_step(coefficients, uy, vy, py0, py1)
        for k in range(n_angles):
            c = cosines[k]
            s = sines[k]
            u0 = c * ux + s * uy
            u1 = c * ux1 + s * uy1
            v0 = c * vx + s * vy
            v1 = c * vx1 + s * vy1
            peaks[k] = peak_between(peaks[k], u0, u1, v0, v1, h)
        ux = ux1
        vx = vx1
        uy = uy1
        vy = vy1
    return peaks


def spectral_peaks_over_angles(
    x,
    y,
    dt: float,
    frequency: float,
    damping: float = 0.05,
    angles: np.ndarray | None = None,
    *,
    min_steps_per_period: int | None = None,
    free_vibration: bool = True,
) -> np.ndarray:
    """Pseudo-acceleration omega^2 max_t |u_theta(t)| of one oscillator at each angle.

    Parameters
    ----------
    x, y : array_like
        The two horizontal support accelerations [m/s^2] at t_i = i dt.
    dt : float
        Time step [s].
    frequency : float
        Oscillator natural frequency f [Hz].
    damping : float, optional
        Damping ratio zeta [-] (default 0.05).
    angles : numpy.ndarray, optional
        Rotation angles theta [rad] (default :func:`rotation_angles`).
    min_steps_per_period : int, optional
        Sub-steps per oscillator period at least [-] (default that of
        :func:`~freestand.core.motion.response_spectrum.spectral_response`).
    free_vibration : bool, optional
        Follow the free vibration for one period after the record (default
        True, as the one-component spectrum).

    Returns
    -------
    numpy.ndarray
        PSA_theta = omega^2 max_t |u_x(t) cos theta + u_y(t) sin theta|
        [m/s^2] at each angle: the pseudo-acceleration of the rotated series
        a_theta (Boore 2010), from the two responses computed once.
    """
    x, y = _check_pair(x, y)
    angles = rotation_angles() if angles is None else np.asarray(angles, dtype=float)
    options = {} if min_steps_per_period is None else {"min_steps_per_period": min_steps_per_period}
    plan = SpectrumPlan.build([frequency], dt, damping, free_vibration=free_vibration, **options)
    peaks = _spectral_peaks_kernel(
        x,
        y,
        float(dt),
        np.ascontiguousarray(plan.coefficients[0], dtype=float),
        int(plan.substeps[0]),
        int(plan.free_steps[0]),
        np.cos(angles),
        np.sin(angles),
    )
    return plan.omegas[0] ** 2 * peaks


def percentile_over_angles(peaks: np.ndarray, percentile: float) -> float:
    """RotDnn: the ``percentile``-th percentile [-] of the peaks over the angles.

    50 gives RotD50 (the median), 100 RotD100 (the largest), 0 RotD00.
    """
    if not 0.0 <= percentile <= 100.0:
        raise ValueError(f"percentile must lie in [0, 100], not {percentile!r}")
    return float(np.percentile(np.asarray(peaks, dtype=float), percentile))


def geometric_mean(first: float, second: float) -> float:
    """sqrt(first second): the geometric mean of the two components' measures."""
    return math.sqrt(float(first) * float(second))
