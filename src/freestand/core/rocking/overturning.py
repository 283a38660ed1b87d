"""Overturning assessment of a rocking block (paper section 5, Figs. 6-8).

Collects the closed-form limits of :mod:`freestand.core.rocking.properties` and the exact
limits of :mod:`freestand.core.rocking.integrator` into result objects that a
command, a report or :mod:`freestand.plot.overturning` can consume, and checks
a response spectrum against them.

What the limits mean for the paper's conclusion (crane cart, b = 1.33 m,
h = 2.83 m, p = 1.449 rad/s, alpha = 0.4393 rad, a = 10.31 m/s^2):

- Housner's half-sine criterion (the paper's Fig. 7) gives overturning only
  for pulses longer than 0.99 s (f < 0.50 Hz).
- The corrected linearised limit (Makris and Roussos 2000, eq. 27) is lower
  at every frequency: 10.31 m/s^2 overturns the cart up to 0.74 Hz (pulses
  longer than 0.68 s).
- The exact nonlinear limit lies between the two (the uplift threshold of the
  cart, g tan(alpha), is 4.61 m/s^2 against the linearised g alpha =
  4.31 m/s^2): 10.31 m/s^2 overturns it up to 0.66 Hz (pulses longer than
  0.76 s).

So the paper's 0.5 Hz boundary is unconservative; its qualitative conclusion
(a spectrum whose low-frequency content is small does not overturn the cart)
holds only where the spectrum stays below the corrected limits, which
:func:`check_spectrum` tells.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from freestand.core.motion.spectra import Spectrum, SpectrumCheck, spectrum_check
from freestand.core.rocking.integrator import (
    exact_minimum_overturning_amplitude,
    exact_rectangular_duration,
)
from freestand.core.rocking.properties import RockingBlock

#: Names of the half-sine limits, in the order they are reported.
HALF_SINE_LIMITS = ("housner", "makris-roussos", "exact")

#: Frequencies of the half-sine limit curves drawn and compared with a spectrum [Hz]
#: (the range of the paper's Figs. 7-8; 48 points keep the exact limit to seconds).
CURVE_FREQUENCIES = np.geomspace(0.1, 20.0, 48)

#: Half-sine pulse frequencies tabulated by default [Hz].
TABLE_FREQUENCIES = (0.25, 0.5, 1.0, 2.0, 5.0)


def rectangular_amplitude_grid(
    block: RockingBlock, operating_amplitude: float, points: int = 40
) -> np.ndarray:
    """Pulse amplitudes [m/s^2] for drawing the rectangular-pulse limit (paper Fig. 6).

    From just above the uplift threshold ``g tan(alpha)`` (1.02 times it) to
    the larger of four times ``operating_amplitude`` and three times the
    threshold, geometrically spaced.

    Parameters
    ----------
    block : RockingBlock
        The block.
    operating_amplitude : float
        Amplitude of interest [m/s^2].
    points : int, optional
        Number of amplitudes [-].
    """
    threshold = block.uplift_threshold
    return np.geomspace(1.02 * threshold, max(4.0 * operating_amplitude, 3.0 * threshold), points)


@dataclass(frozen=True)
class RectangularPulseLimits:
    """Shortest overturning rectangular pulse against its amplitude (paper Fig. 6).

    Parameters
    ----------
    amplitude : numpy.ndarray
        Pulse accelerations a [m/s^2].
    housner : numpy.ndarray
        Housner's t1 = ln[A / (A - 1)] / p [s] (``inf`` if A <= 1).
    exact : numpy.ndarray
        Exact shortest overturning duration [s] (``inf`` below uplift).
    operating_amplitude : float or None
        The amplitude of interest (the paper's 10.31 m/s^2) [m/s^2].
    operating_housner, operating_exact : float
        The two durations at it [s] (NaN if none).
    """

    amplitude: np.ndarray
    housner: np.ndarray
    exact: np.ndarray
    operating_amplitude: float | None = None
    operating_housner: float = float("nan")
    operating_exact: float = float("nan")


@dataclass(frozen=True)
class OverturningLimits:
    """Minimum overturning amplitude of a pulse against its frequency (paper Figs. 7-8).

    Parameters
    ----------
    kind : str
        Pulse kind (``"half-sine"``, ``"one-sine"``, ``"one-cosine"``).
    frequency : numpy.ndarray
        Pulse frequencies f [Hz] (a sine of frequency f; a half-sine lasts
        1 / (2 f)).
    limits : dict of str to numpy.ndarray
        Minimum overturning amplitude [m/s^2] by limit name: ``"housner"``
        (Housner 1963, eq. 12) and ``"makris-roussos"`` (eq. 27; half-sine
        only), ``"exact"`` (nonlinear equation with impacts).
    found : numpy.ndarray
        Whether the exact search found an overturning amplitude (bool).
    operating_amplitude : float or None
        The amplitude of interest [m/s^2].
    operating_frequency : dict of str to float
        For each limit, the highest frequency of the grid range up to which
        ``operating_amplitude`` overturns the block [Hz] (linear
        interpolation of the limit in log-log; NaN if it never does).
    """

    kind: str
    frequency: np.ndarray
    limits: dict[str, np.ndarray]
    found: np.ndarray
    operating_amplitude: float | None = None
    operating_frequency: dict[str, float] = field(default_factory=dict)


def rectangular_pulse_limits(
    block: RockingBlock,
    amplitude: np.ndarray,
    *,
    operating_amplitude: float | None = None,
) -> RectangularPulseLimits:
    """Housner's and the exact shortest overturning rectangular pulse (paper Fig. 6).

    Parameters
    ----------
    block : RockingBlock
        The block.
    amplitude : array_like
        Pulse accelerations [m/s^2].
    operating_amplitude : float, optional
        Amplitude of interest [m/s^2] (the paper's 10.31 m/s^2 for the cart).
    """
    a = np.asarray(amplitude, dtype=float)
    housner = np.asarray(block.housner_rectangular_duration(a), dtype=float)
    exact = np.asarray(exact_rectangular_duration(block, a), dtype=float)
    op_h = op_e = float("nan")
    if operating_amplitude is not None:
        op_h = float(block.housner_rectangular_duration(operating_amplitude))
        op_e = float(exact_rectangular_duration(block, operating_amplitude))
    return RectangularPulseLimits(a, housner, exact, operating_amplitude, op_h, op_e)


def _crossing_frequency(frequency: np.ndarray, limit: np.ndarray, amplitude: float) -> float:
    """Highest f at which ``limit`` rises through ``amplitude`` (log-log interpolation)."""
    below = np.isfinite(limit) & (limit <= amplitude)
    if not below.any():
        return float("nan")
    i = int(np.nonzero(below)[0][-1])
    if i == frequency.size - 1:
        return float(frequency[-1])
    f0, f1 = np.log(frequency[i]), np.log(frequency[i + 1])
    a0, a1 = np.log(limit[i]), np.log(limit[i + 1]) if np.isfinite(limit[i + 1]) else np.inf
    if not np.isfinite(a1):
        return float(frequency[i])
    x = (np.log(amplitude) - a0) / (a1 - a0) if a1 != a0 else 0.0
    return float(np.exp(f0 + x * (f1 - f0)))


def overturning_limits(
    block: RockingBlock,
    frequency: np.ndarray,
    *,
    kind: str = "half-sine",
    operating_amplitude: float | None = None,
    exact: bool = True,
) -> OverturningLimits:
    """The overturning limits of a pulse kind against frequency (paper Fig. 7).

    Parameters
    ----------
    block : RockingBlock
        The block.
    frequency : array_like
        Increasing pulse frequencies [Hz].
    kind : str, optional
        ``"half-sine"`` (Housner, Makris-Roussos and exact limits) or
        ``"one-sine"`` / ``"one-cosine"`` (exact only).
    operating_amplitude : float, optional
        Amplitude of interest [m/s^2] (10.31 m/s^2 for the cart).
    exact : bool, optional
        Compute the exact limit (the expensive one).

    Returns
    -------
    OverturningLimits
        The minimum overturning amplitude [m/s^2] of each limit at each
        frequency (``limits``), and with ``operating_amplitude`` the frequency
        up to which that amplitude overturns the block by each limit.

    Examples
    --------
    >>> import numpy as np
    >>> import freestand as fs
    >>> cabinet = fs.Block.rectangle("cabinet", 0.6, 2.0, 1200.0, fs.Friction(0.8, 0.7))
    >>> limits = fs.overturning_limits(fs.RockingBlock.from_block(cabinet, "right"),
    ...                                np.array([0.5, 1.0, 2.0]))
    >>> for name, values in limits.limits.items():  # [m/s^2] at 0.5, 1 and 2 Hz
    ...     print(name, np.round(values, 2).tolist())
    housner [4.43, 7.35, 13.83]
    makris-roussos [4.02, 5.66, 9.02]
    exact [4.14, 5.84, 9.33]
    """
    f = np.asarray(frequency, dtype=float)
    if f.ndim != 1 or np.any(np.diff(f) <= 0):
        raise ValueError("frequency must be a 1-D array of increasing values")
    limits: dict[str, np.ndarray] = {}
    if kind == "half-sine":
        limits["housner"] = np.asarray(block.housner_half_sine_amplitude(f), dtype=float)
        limits["makris-roussos"] = np.asarray(
            block.makris_roussos_half_sine_amplitude(f), dtype=float
        )
    found = np.ones(f.size, dtype=bool)
    if exact:
        result = exact_minimum_overturning_amplitude(block, kind, f)
        limits["exact"] = np.asarray(result.amplitude, dtype=float)
        found = np.asarray(result.found, dtype=bool)
    return limits_with_operating(kind, f, limits, found, operating_amplitude)


def limits_with_operating(
    kind: str,
    frequency: np.ndarray,
    limits: dict[str, np.ndarray],
    found: np.ndarray,
    operating_amplitude: float | None = None,
) -> OverturningLimits:
    """:class:`OverturningLimits` of the given limits, with the frequency up to which
    ``operating_amplitude`` [m/s^2] overturns the block by each (when given)."""
    op: dict[str, float] = {}
    if operating_amplitude is not None:
        op = {
            name: _crossing_frequency(frequency, lim, operating_amplitude)
            for name, lim in limits.items()
        }
    return OverturningLimits(kind, frequency, limits, found, operating_amplitude, op)


def check_spectrum(limits: OverturningLimits, spectrum: Spectrum) -> dict[str, SpectrumCheck]:
    """Compare ``spectrum`` with each limit of ``limits`` (paper section 5, Fig. 8).

    Returns
    -------
    dict of str to SpectrumCheck
        By limit name: verdict, smallest ratio limit / spectrum and its
        frequency.
    """
    return {
        name: spectrum_check(limits.frequency, lim, spectrum, limit_name=name)
        for name, lim in limits.limits.items()
    }
