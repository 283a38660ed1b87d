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
