"""Response spectra: one tabulated type that every check consumes.

A :class:`Spectrum` holds spectral (pseudo-)acceleration against frequency.
Design spectra (RG 1.60, EN 1998-1), spectra read from files and spectra
computed from records are all turned into this one type, so the overturning
check (paper section 5, Fig. 8) and the jump check (paper section 6) need to
know only :meth:`Spectrum.acceleration`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


@dataclass(frozen=True)
class Spectrum:
    """A response spectrum tabulated against frequency.

    Between tabulated points the spectrum is interpolated linearly on
    log-log axes (straight lines on tripartite paper). Outside the table it is
    held constant at the end values.

    Parameters
    ----------
    frequency : numpy.ndarray
        Strictly increasing frequencies [Hz], all positive.
    acceleration : numpy.ndarray
        Spectral acceleration at each frequency [m/s^2], non-negative.
    damping : float
        Fraction of critical damping the spectrum is for [-] (0.05 for 5 %).
    direction : str
        ``"horizontal"`` or ``"vertical"``.
    label : str
        A human-readable name (source, anchoring, damping).
    """

    frequency: np.ndarray
    acceleration: np.ndarray
    damping: float = 0.05
    direction: str = "horizontal"
    label: str = ""
    metadata: dict = field(default_factory=dict, compare=False)

    def __post_init__(self) -> None:
        f = np.asarray(self.frequency, dtype=float)
        a = np.asarray(self.acceleration, dtype=float)
        if f.ndim != 1 or f.shape != a.shape or f.size < 2:
            raise ValueError("frequency and acceleration must be 1-D arrays of equal length >= 2")
        if np.any(f <= 0) or np.any(np.diff(f) <= 0):
            raise ValueError("frequencies must be positive and strictly increasing")
        if np.any(a < 0) or not np.all(np.isfinite(a)):
            raise ValueError("spectral accelerations must be finite and non-negative")
        object.__setattr__(self, "frequency", f)
        object.__setattr__(self, "acceleration", a)

    def acceleration_at(self, frequency: np.ndarray | float) -> np.ndarray | float:
        """Spectral acceleration [m/s^2] at ``frequency`` [Hz] (log-log interpolation)."""
        f = np.asarray(frequency, dtype=float)
        logf = np.log(np.clip(f, self.frequency[0], self.frequency[-1]))
        floor = np.finfo(float).tiny
        loga = np.interp(logf, np.log(self.frequency), np.log(np.maximum(self.acceleration, floor)))
        out = np.exp(loga)
        out = np.where(np.interp(logf, np.log(self.frequency), self.acceleration) == 0, 0.0, out)
        return float(out) if np.ndim(frequency) == 0 else out

    def scaled(self, factor: float) -> Spectrum:
        """The same spectrum with every acceleration multiplied by ``factor`` [-]."""
        return Spectrum(
            self.frequency,
            self.acceleration * factor,
            self.damping,
            self.direction,
            self.label,
            dict(self.metadata),
        )


# --------------------------------------------------------------------------------------
# Comparison of a spectrum with an overturning limit (paper section 5, Fig. 8)
# --------------------------------------------------------------------------------------
@dataclass(frozen=True)
class SpectrumCheck:
    """A response spectrum compared with an overturning limit.

    Parameters
    ----------
    limit_name : str
        Which limit (``"housner"``, ``"makris-roussos"``, ``"exact"``...).
    verdict : str
        ``"no overturning"`` if the spectrum stays below the limit at every
        compared frequency (min_ratio > 1), ``"overturning possible"``
        otherwise, ``"undetermined"`` if no frequency could be compared.
    min_ratio : float
        Smallest ratio limit / spectral acceleration [-] (the margin).
    frequency_at_min : float
        Frequency of the smallest ratio [Hz].
    limit_at_min, spectrum_at_min : float
        The two accelerations there [m/s^2].
    frequency : numpy.ndarray
        Frequencies compared [Hz] (the limit's frequencies where it is finite).
    ratio : numpy.ndarray
        Ratio limit / spectrum at each of them [-].
    spectrum_label : str
        Label of the spectrum.
    """

    limit_name: str
    verdict: str
    min_ratio: float
    frequency_at_min: float
    limit_at_min: float
    spectrum_at_min: float
    frequency: np.ndarray
    ratio: np.ndarray
    spectrum_label: str


def spectrum_check(
    limit_frequency: np.ndarray,
    limit_amplitude: np.ndarray,
    spectrum: Spectrum,
    *,
    limit_name: str = "limit",
) -> SpectrumCheck:
    """Compare a spectrum with an overturning limit (paper section 5, Fig. 8).

    The paper reads the spectral acceleration at frequency f as the peak of a
    sinusoidal pulse of that frequency and compares it with the minimum
    overturning amplitude at f. The ratio limit / spectrum is evaluated at the
    limit's frequencies and at the spectrum's tabulated frequencies inside the
    limit's range (the limit interpolated log-log there); frequencies where
    the limit is infinite (no overturning found) are skipped.

    Parameters
    ----------
    limit_frequency : array_like
        Frequencies of the limit [Hz], increasing.
    limit_amplitude : array_like
        Minimum overturning amplitude at each frequency [m/s^2] (``inf`` where
        none).
    spectrum : Spectrum
        Response spectrum (horizontal).
    limit_name : str, optional
        Name of the limit, carried into the result.

    Returns
    -------
    SpectrumCheck
    """
    f = np.asarray(limit_frequency, dtype=float)
    a = np.asarray(limit_amplitude, dtype=float)
    if f.ndim != 1 or f.shape != a.shape or f.size < 1:
        raise ValueError("limit_frequency and limit_amplitude must be 1-D arrays of equal length")
    if np.any(f <= 0) or np.any(np.diff(f) <= 0):
        raise ValueError("limit frequencies must be positive and strictly increasing")
    finite = np.isfinite(a) & (a > 0)
    ff, aa = f[finite], a[finite]
    if ff.size == 0:
        return SpectrumCheck(
            limit_name, "undetermined", np.nan, np.nan, np.nan, np.nan,
            np.empty(0), np.empty(0), spectrum.label,
        )  # fmt: skip
    extra = spectrum.frequency[(spectrum.frequency > ff[0]) & (spectrum.frequency < ff[-1])]
    if ff.size >= 2:
        grid = np.unique(np.concatenate([ff, extra]))
        limit = np.exp(np.interp(np.log(grid), np.log(ff), np.log(aa)))
    else:
        grid, limit = ff, aa
    spec = np.asarray(spectrum.acceleration_at(grid), dtype=float)
    with np.errstate(divide="ignore"):
        ratio = np.where(spec > 0, limit / np.where(spec > 0, spec, 1.0), np.inf)
    i = int(np.argmin(ratio))
    verdict = "no overturning" if ratio[i] > 1 else "overturning possible"
    return SpectrumCheck(
        limit_name,
        verdict,
        float(ratio[i]),
        float(grid[i]),
        float(limit[i]),
        float(spec[i]),
        grid,
        ratio,
        spectrum.label,
    )
