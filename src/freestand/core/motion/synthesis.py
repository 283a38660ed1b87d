"""Stochastic seed ground motions: the model of Rezaeian and Der Kiureghian (2010).

A seed record is a time-modulated, filtered white noise whose filter changes in
time, so that both its intensity and its frequency content evolve as in a
recorded accelerogram (Rezaeian and Der Kiureghian 2010, eqs. 2-6):

    x(t) = q(t) / sigma_h(t) * sum_{tau_i <= t} h(t - tau_i; omega_f(tau_i), zeta_f) w_i,

    sigma_h(t)^2 = sum_{tau_i <= t} h(t - tau_i; omega_f(tau_i), zeta_f)^2,

with w_i independent standard normal pulses at the samples tau_i = i dt, the
impulse response of a damped oscillator (the pseudo-acceleration filter)

    h(t; omega_f, zeta_f) = omega_f / sqrt(1 - zeta_f^2) exp(-zeta_f omega_f t)
                            sin(omega_f sqrt(1 - zeta_f^2) t),   t >= 0,

a filter frequency that drifts linearly in time,
omega_f(tau) = 2 pi [f_mid + f' (tau - t_mid)], and the gamma time envelope

    q(t) = t^(alpha_2 - 1) exp(-alpha_3 t)   (scaled to a peak of 1).

The normalisation by sigma_h makes the envelope q(t) the standard deviation of
the process. Low frequencies are removed as in the model's high-pass step (here
a zero-phase Butterworth filter) so that velocity and displacement do not drift.

References
----------
Rezaeian, S. and Der Kiureghian, A. (2010). Simulation of synthetic ground
motions for specified earthquake and site characteristics. Earthquake
Engineering and Structural Dynamics 39(10), 1155-1180.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numba
import numpy as np

#: Amplitude e^{-zeta omega t} below which the impulse response is cut off [-].
_IMPULSE_CUTOFF = 1e-3


@dataclass(frozen=True)
class SeedParameters:
    """Parameters of one seed record (Rezaeian and Der Kiureghian 2010).

    Parameters
    ----------
    alpha2 : float
        Shape exponent of the gamma envelope q(t) = t^(alpha2 - 1) exp(-alpha3 t) [-].
    alpha3 : float
        Decay rate of the envelope [1/s]; its peak is at (alpha2 - 1) / alpha3.
    mid_frequency : float
        Filter frequency f_mid at the time ``mid_time`` [Hz].
    frequency_slope : float
        Rate of change f' of the filter frequency [Hz/s] (negative: the
        content softens with time, as in recorded motions).
    filter_damping : float
        Filter damping ratio zeta_f [-].
    mid_time : float
        Time t_mid at which the filter frequency is f_mid [s].
    highpass_frequency : float
        Corner of the zero-phase 4th-order Butterworth high-pass [Hz].
    """

    alpha2: float
    alpha3: float
    mid_frequency: float
    frequency_slope: float
    filter_damping: float
    mid_time: float
    highpass_frequency: float = 0.1

    def envelope(self, time: np.ndarray) -> np.ndarray:
        """q(t) scaled to a peak of 1 [-] at ``time`` [s]."""
        t = np.asarray(time, dtype=float)
        peak_time = (self.alpha2 - 1.0) / self.alpha3
        log_q = (self.alpha2 - 1.0) * np.log(np.maximum(t, 1e-300) / peak_time) - self.alpha3 * (
            t - peak_time
        )
        return np.where(t > 0, np.exp(log_q), 0.0)

    def filter_frequency(self, time: np.ndarray, nyquist: float) -> np.ndarray:
        """f_f(t) = f_mid + f' (t - t_mid) [Hz], kept between 0.3 Hz and 0.4 / dt."""
        f = self.mid_frequency + self.frequency_slope * (np.asarray(time) - self.mid_time)
        return np.clip(f, 0.3, 0.8 * nyquist)


def draw_seed_parameters(
    rng: np.random.Generator, duration: float, *, direction: str = "horizontal"
) -> SeedParameters:
    """Random parameters of a seed record of length ``duration`` [s].

    The ranges are chosen to resemble the parameters Rezaeian and Der
    Kiureghian (2010) fitted to recorded strong motions (envelope peak in the
    first third of the record, f_mid of a few Hz, f' zero or negative, zeta_f
    of a few tenths), scaled to the requested duration; vertical seeds have
    stiffer content (f_mid about twice as high). They shape the seed only:
    the matching sets the spectrum.

    Parameters
    ----------
    rng : numpy.random.Generator
        Source of the draws (consumed in a fixed order).
    duration : float
        Record length [s].
    direction : {"horizontal", "vertical"}
    """
    alpha2 = rng.uniform(2.5, 4.0)
    peak_time = duration * rng.uniform(0.18, 0.3)
    alpha3 = (alpha2 - 1.0) / peak_time
    mid_time = duration * rng.uniform(0.3, 0.45)
    if direction == "vertical":
        mid_frequency = rng.uniform(6.0, 14.0)
    else:
        mid_frequency = rng.uniform(3.0, 8.0)
    slope = -rng.uniform(0.0, 0.25) * mid_frequency / duration * 2.0
    zeta = rng.uniform(0.15, 0.45)
    return SeedParameters(alpha2, alpha3, mid_frequency, slope, zeta, mid_time)


@numba.njit(cache=True)
def _evolutionary_filter(noise, omegas, zeta, dt, lengths):
    """sum_i h(t_k - tau_i; omega(tau_i)) w_i and its normalisation, at every sample.

    Each pulse's impulse response is a damped sinusoid, advanced from sample
    to sample by one complex multiplication (exact), for ``lengths[i]``
    samples (until e^{-zeta omega t} falls below the cut-off).
    """
    n = noise.size
    out = np.zeros(n)
    variance = np.zeros(n)
    root = math.sqrt(1.0 - zeta * zeta)
    for i in range(n):
        omega = omegas[i]
        omega_d = omega * root
        amplitude = omega / root
        decay = math.exp(-zeta * omega * dt)
        c = math.cos(omega_d * dt) * decay
        s = math.sin(omega_d * dt) * decay
        # z = amplitude e^{(-zeta omega + i omega_d) t}; h = Im z
        re = amplitude
        im = 0.0
        w = noise[i]
        stop = min(n, i + lengths[i])
        for k in range(i, stop):
            out[k] += im * w
            variance[k] += im * im
            re, im = re * c - im * s, re * s + im * c
    return out, variance


def seed_acceleration(
    parameters: SeedParameters, n_samples: int, dt: float, rng: np.random.Generator
) -> np.ndarray:
    """One seed record [-] (unit-scale) by the model of Rezaeian and Der Kiureghian (2010).

    Parameters
    ----------
    parameters : SeedParameters
        Envelope and filter parameters.
    n_samples : int
        Number of samples [-].
    dt : float
        Time step [s].
    rng : numpy.random.Generator
        Source of the white noise (``n_samples`` standard normal draws).

    Returns
    -------
    numpy.ndarray
        x(t_i) with standard deviation q(t_i) (peak of q is 1), high-passed.
    """
    from scipy.signal import butter, sosfiltfilt

    t = np.arange(n_samples) * dt
    noise = rng.standard_normal(n_samples)
    omegas = 2.0 * np.pi * parameters.filter_frequency(t, 0.5 / dt)
    zeta = parameters.filter_damping
    lengths = np.ceil(-math.log(_IMPULSE_CUTOFF) / (zeta * omegas * dt)).astype(np.int64) + 1
    filtered, variance = _evolutionary_filter(noise, omegas, zeta, dt, lengths)
    sigma = np.sqrt(np.maximum(variance, 1e-300))
    x = np.where(variance > 0, filtered / sigma, 0.0) * parameters.envelope(t)
    sos = butter(4, parameters.highpass_frequency, btype="highpass", fs=1.0 / dt, output="sos")
    return sosfiltfilt(sos, x)
