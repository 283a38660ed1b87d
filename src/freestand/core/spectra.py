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
# Design spectra
# --------------------------------------------------------------------------------------
#: US NRC Regulatory Guide 1.60 (Rev. 2, 2014), Tables 1 and 2: amplification
#: factors at the control points A (33 Hz), B (9 Hz), C (2.5 Hz horizontal,
#: 3.5 Hz vertical) for acceleration, and D (0.25 Hz) for displacement
#: (times 36 in per 1 g of PGA). Keys: damping in percent.
RG160_FACTORS: dict[str, dict[float, tuple[float, float, float, float]]] = {
    "horizontal": {
        0.5: (1.0, 4.96, 5.95, 3.20),
        2.0: (1.0, 3.54, 4.25, 2.50),
        5.0: (1.0, 2.61, 3.13, 2.05),
        7.0: (1.0, 2.27, 2.72, 1.88),
        10.0: (1.0, 1.90, 2.28, 1.70),
    },
    "vertical": {
        0.5: (1.0, 4.96, 5.67, 2.13),
        2.0: (1.0, 3.54, 4.05, 1.67),
        5.0: (1.0, 2.61, 2.98, 1.37),
        7.0: (1.0, 2.27, 2.59, 1.25),
        10.0: (1.0, 1.90, 2.17, 1.13),
    },
}

#: RG 1.60 control frequencies [Hz]: A, B, C (horizontal, vertical), D.
RG160_CONTROL_FREQUENCIES = {
    "horizontal": (33.0, 9.0, 2.5, 0.25),
    "vertical": (33.0, 9.0, 3.5, 0.25),
}

_INCH = 0.0254
_DIRECTIONS = ("horizontal", "vertical")


def _check_direction(direction: str) -> None:
    if direction not in _DIRECTIONS:
        raise ValueError(f"direction must be 'horizontal' or 'vertical', got {direction!r}")


def rg160_spectrum(
    pga: float,
    damping: float = 0.05,
    direction: str = "horizontal",
    *,
    gravity: float = 9.81,
    frequency_range: tuple[float, float] = (0.1, 100.0),
) -> Spectrum:
    """Design response spectrum of US NRC Regulatory Guide 1.60.

    Parameters
    ----------
    pga : float
        Horizontal peak ground acceleration the spectrum is anchored to
        [m/s^2] (the vertical spectrum is anchored to the same value).
    damping : float
        Fraction of critical damping [-]; only the tabulated values 0.005,
        0.02, 0.05, 0.07, 0.10 are defined.
    direction : str
        ``"horizontal"`` or ``"vertical"``.
    gravity : float, optional
        g [m/s^2] used to convert the 36 in / g displacement anchor.
    frequency_range : tuple of float, optional
        Lowest and highest tabulated frequency [Hz].

    Returns
    -------
    Spectrum
        Straight lines on log-log axes between the control points: equal to
        the PGA from 33 Hz up; factor x PGA at B (9 Hz) and C (2.5 Hz
        horizontal, 3.5 Hz vertical); constant spectral displacement
        D x 36 in x PGA / g at and below D (0.25 Hz), i.e.
        Sa = (2 pi f)^2 x D x 0.9144 m x PGA / g (RG 1.60, Figs. 1-2,
        Tables 1-2).

    Raises
    ------
    ValueError
        For a damping value the guide does not tabulate (the message lists
        them) or an unknown direction.
    """
    _check_direction(direction)
    if not (pga > 0 and np.isfinite(pga)):
        raise ValueError(f"pga must be positive and finite, got {pga!r}")
    percent = round(damping * 100.0, 6)
    table = RG160_FACTORS[direction]
    if percent not in table:
        raise ValueError(
            f"RG 1.60 tabulates damping {', '.join(f'{d:g} %' for d in table)} only, "
            f"not {percent:g} %"
        )
    fa, fb, fc, fd = RG160_CONTROL_FREQUENCIES[direction]
    a_fac, b_fac, c_fac, d_fac = table[percent]
    disp_d = d_fac * 36.0 * _INCH * pga / gravity
    lo, hi = frequency_range
    points = {
        fd: (2 * np.pi * fd) ** 2 * disp_d,
        fc: c_fac * pga,
        fb: b_fac * pga,
        fa: a_fac * pga,
    }
    freq = sorted(set([lo, hi, *points]))
    freq = [f for f in freq if lo <= f <= hi]
    acc = []
    for f in freq:
        if f in points:
            acc.append(points[f])
        elif f < fd:
            acc.append((2 * np.pi * f) ** 2 * disp_d)
        else:
            acc.append(pga)
    return Spectrum(
        np.array(freq),
        np.array(acc),
        damping,
        direction,
        f"RG 1.60 {direction}, PGA {pga / gravity:.3g} g, {percent:g} % damping",
        {"source": "rg1.60", "pga": pga, "control_points": points},
    )


#: EN 1998-1:2004, Tables 3.2 and 3.3: S, T_B, T_C, T_D [s] by spectrum type and ground type.
EN1998_HORIZONTAL: dict[int, dict[str, tuple[float, float, float, float]]] = {
    1: {
        "A": (1.0, 0.15, 0.4, 2.0),
        "B": (1.2, 0.15, 0.5, 2.0),
        "C": (1.15, 0.20, 0.6, 2.0),
        "D": (1.35, 0.20, 0.8, 2.0),
        "E": (1.4, 0.15, 0.5, 2.0),
    },
    2: {
        "A": (1.0, 0.05, 0.25, 1.2),
        "B": (1.35, 0.05, 0.25, 1.2),
        "C": (1.5, 0.10, 0.25, 1.2),
        "D": (1.8, 0.10, 0.30, 1.2),
        "E": (1.6, 0.05, 0.25, 1.2),
    },
}

#: EN 1998-1:2004, Table 3.4: a_vg / a_g, T_B, T_C, T_D [s] of the vertical spectrum.
EN1998_VERTICAL: dict[int, tuple[float, float, float, float]] = {
    1: (0.90, 0.05, 0.15, 1.0),
    2: (0.45, 0.05, 0.15, 1.0),
}


def en1998_damping_correction(damping: float) -> float:
    """eta = sqrt(10 / (5 + xi)) >= 0.55, xi in percent (EN 1998-1, eq. 3.6) [-]."""
    if not (damping >= 0 and np.isfinite(damping)):
        raise ValueError(f"damping must be a non-negative fraction, got {damping!r}")
    return max(float(np.sqrt(10.0 / (5.0 + 100.0 * damping))), 0.55)


def en1998_acceleration(
    period: np.ndarray | float,
    ag: float,
    ground: str = "A",
    spectrum_type: int = 1,
    damping: float = 0.05,
    direction: str = "horizontal",
    importance: float = 1.0,
) -> np.ndarray | float:
    """Elastic spectral acceleration of EN 1998-1 at ``period``.

    Parameters
    ----------
    period : float or array_like
        Oscillator period T [s], >= 0.
    ag : float
        Reference peak ground acceleration on ground type A, a_gR [m/s^2].
    ground : str
        Ground type ``"A"`` to ``"E"`` (horizontal only).
    spectrum_type : int
        1 or 2.
    damping : float
        Fraction of critical damping [-].
    direction : str
        ``"horizontal"`` (eqs. 3.2-3.5) or ``"vertical"`` (eqs. 3.8-3.11).
    importance : float
        Importance factor gamma_I [-]: a_g = gamma_I a_gR.

    Returns
    -------
    float or numpy.ndarray
        S_e(T) [m/s^2]: a S [1 + T/T_B (k eta - 1)] up to T_B, k a S eta up to
        T_C, k a S eta T_C / T up to T_D, k a S eta T_C T_D / T^2 beyond, with
        k = 2.5, a = a_g horizontally and k = 3.0, a = a_vg, S = 1 vertically.
    """
    _check_direction(direction)
    if spectrum_type not in (1, 2):
        raise ValueError(f"spectrum_type must be 1 or 2, got {spectrum_type!r}")
    a_g = importance * ag
    if direction == "horizontal":
        if ground not in EN1998_HORIZONTAL[spectrum_type]:
            raise ValueError(f"ground must be one of A, B, C, D, E, got {ground!r}")
        s, tb, tc, td = EN1998_HORIZONTAL[spectrum_type][ground]
        base, k = a_g * s, 2.5
    else:
        ratio, tb, tc, td = EN1998_VERTICAL[spectrum_type]
        base, k = ratio * a_g, 3.0
    eta = en1998_damping_correction(damping)
    t = np.asarray(period, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = np.select(
            [t <= tb, t <= tc, t <= td],
            [
                base * (1 + t / tb * (k * eta - 1)),
                k * base * eta * np.ones_like(t),
                k * base * eta * tc / t,
            ],
            k * base * eta * tc * td / t**2,
        )
    return float(out) if np.ndim(period) == 0 else out


def en1998_spectrum(
    ag: float,
    ground: str = "A",
    spectrum_type: int = 1,
    damping: float = 0.05,
    direction: str = "horizontal",
    importance: float = 1.0,
    *,
    gravity: float = 9.81,
    frequency_range: tuple[float, float] = (0.1, 100.0),
    points: int = 400,
) -> Spectrum:
    """EN 1998-1 elastic response spectrum tabulated against frequency.

    Parameters are those of :func:`en1998_acceleration`; ``points``
    log-spaced frequencies in ``frequency_range`` [Hz] plus the corner
    frequencies 1/T_B, 1/T_C, 1/T_D exactly. ``gravity`` [m/s^2] is used for
    the label only.
    """
    value = en1998_acceleration(1.0, ag, ground, spectrum_type, damping, direction, importance)
    del value  # validates the arguments
    if direction == "horizontal":
        _s, tb, tc, td = EN1998_HORIZONTAL[spectrum_type][ground]
    else:
        _r, tb, tc, td = EN1998_VERTICAL[spectrum_type]
    lo, hi = frequency_range
    freq = np.geomspace(lo, hi, points)
    corners = [1 / t for t in (tb, tc, td) if lo < 1 / t < hi]
    freq = np.unique(np.concatenate([freq, corners]))
    acc = en1998_acceleration(1 / freq, ag, ground, spectrum_type, damping, direction, importance)
    where = f"ground {ground}, " if direction == "horizontal" else ""
    return Spectrum(
        freq,
        acc,
        damping,
        direction,
        f"EN 1998-1 Type {spectrum_type} {direction}, {where}"
        f"a_g {importance * ag / gravity:.3g} g, {100 * damping:g} % damping",
        {
            "source": "en1998",
            "ag": ag,
            "ground": ground,
            "type": spectrum_type,
            "importance": importance,
            "corner_periods": (tb, tc, td),
        },
    )


#: Values the paper quotes from its Figs. 4 and 5 (section 4), the anchors of the stand-in.
CRANE_ANCHORS = {
    "horizontal": {"rigid": 2.70, "peak_frequency": 2.5, "peak": 10.31},
    "vertical": {"rigid": 2.35, "plateau": (8.0, 12.0), "peak": 9.81},
}

CRANE_STAND_IN_NOTE = (
    "stand-in for the paper's Figs. 4-5 (not the original spectra): standard shape anchored to "
    "the values the paper quotes"
)


def crane_stand_in_spectrum(
    direction: str = "horizontal",
    *,
    frequency_range: tuple[float, float] = (0.1, 100.0),
) -> Spectrum:
    """A stand-in for the paper's typical spectra (Figs. 4-5), 5 % damping.

    The paper's Figs. 4 and 5 are not reproduced in its text; it quotes only
    a few values. This spectrum has a standard shape anchored to them:

    - horizontal: the RG 1.60 shape (control points 33, 9, 2.5, 0.25 Hz, see
      :func:`rg160_spectrum`) with 2.70 m/s^2 from 33 Hz up (the rigid
      asymptote of paper section 4) and its amplification factors scaled so
      that it passes through 10.31 m/s^2 at 2.5 Hz (the paper's value for a
      2.5 Hz mode with 5 % damping);
    - vertical: 2.35 m/s^2 from 33 Hz up, rising on a log-log line to a
      plateau at g = 9.81 m/s^2 between 8 and 12 Hz, constant spectral
      velocity from 8 Hz down to 0.25 Hz and constant displacement below.

    Parameters
    ----------
    direction : str
        ``"horizontal"`` or ``"vertical"``.
    frequency_range : tuple of float, optional
        Lowest and highest tabulated frequency [Hz].

    Returns
    -------
    Spectrum
        Tabulated at the corner frequencies (straight lines on log-log axes
        between them) and at the ends of ``frequency_range``.
    """
    _check_direction(direction)
    lo, hi = frequency_range
    if direction == "horizontal":
        anchor = CRANE_ANCHORS["horizontal"]
        zpa = anchor["rigid"]
        a_fac, b_fac, c_fac, d_fac = RG160_FACTORS["horizontal"][5.0]
        scale = anchor["peak"] / (c_fac * zpa)
        rg = rg160_spectrum(zpa, 0.05, "horizontal", frequency_range=frequency_range)
        points = dict(zip(rg.frequency, rg.acceleration, strict=True))
        freq = np.array(sorted(points))
        acc = np.array(
            [points[f] * (scale if f < 33.0 else 1.0) for f in freq]
        )  # scale the amplified part only
        label = "crane stand-in horizontal (5 %): 2.70 m/s^2 rigid, 10.31 m/s^2 at 2.5 Hz"
    else:
        anchor = CRANE_ANCHORS["vertical"]
        zpa, peak = anchor["rigid"], anchor["peak"]
        f_lo, f_hi = anchor["plateau"]
        f_d = 0.25
        v = peak / (2 * np.pi * f_lo)  # constant spectral velocity below the plateau
        d = v / (2 * np.pi * f_d)  # constant displacement below 0.25 Hz
        corner = {f_d: v * 2 * np.pi * f_d, f_lo: peak, f_hi: peak, 33.0: zpa}
        freq = np.array(sorted(set([lo, hi, *corner])))
        freq = freq[(freq >= lo) & (freq <= hi)]
        acc = np.array(
            [
                corner[f] if f in corner else ((2 * np.pi * f) ** 2 * d if f < f_d else zpa)
                for f in freq
            ]
        )
        label = "crane stand-in vertical (5 %): 2.35 m/s^2 rigid, about g at 8-12 Hz"
    return Spectrum(
        freq,
        acc,
        0.05,
        direction,
        label,
        {"source": "crane-stand-in", "note": CRANE_STAND_IN_NOTE, "anchors": anchor},
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
