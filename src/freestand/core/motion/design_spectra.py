"""Design response spectra: US NRC RG 1.60, EN 1998-1, and the crane's stand-in.

Each function returns a :class:`freestand.core.motion.spectra.Spectrum` (spectral
acceleration [m/s^2] against frequency [Hz]).
"""

from __future__ import annotations

import math

import numpy as np

from freestand.core.motion.spectra import Spectrum

#: 36 inches per 1 g of peak ground acceleration [m] (RG 1.60, control point D).
RG160_DISPLACEMENT_PER_G = 36 * 0.0254

#: RG 1.60 amplification factors at the control points A (33 Hz), B (9 Hz),
#: C (2.5 Hz horizontal, 3.5 Hz vertical) and D (0.25 Hz), by damping [%].
#: A, B and C multiply the PGA; D multiplies the 36 in displacement.
RG160_FACTORS = {
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

RG160_FREQUENCIES = {"horizontal": (33.0, 9.0, 2.5, 0.25), "vertical": (33.0, 9.0, 3.5, 0.25)}

#: EN 1998-1 Table 3.2/3.3: S, T_B, T_C, T_D [s] by spectrum type and ground type.
EN1998_HORIZONTAL = {
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
#: EN 1998-1 Table 3.4: a_vg / a_g, T_B, T_C, T_D [s] by spectrum type.
EN1998_VERTICAL = {1: (0.90, 0.05, 0.15, 1.0), 2: (0.45, 0.05, 0.15, 1.0)}


def rg160_spectrum(
    peak_ground_acceleration: float,
    damping: float = 0.05,
    direction: str = "horizontal",
    gravity: float = 9.81,
    lowest_frequency: float = 0.05,
    highest_frequency: float = 100.0,
) -> Spectrum:
    """US NRC Regulatory Guide 1.60 design response spectrum (Rev. 1, 1973).

    Straight lines on log-log axes between the control points A (33 Hz),
    B (9 Hz), C (2.5 Hz horizontal, 3.5 Hz vertical) and D (0.25 Hz); equal to
    the PGA above 33 Hz; below D the spectral displacement is constant at
    ``f_D * 36 in * PGA / g`` (so ``S_a = (2 pi f)^2 S_d``). Linear in the PGA.
    The vertical spectrum is anchored to the *horizontal* PGA.

    Parameters
    ----------
    peak_ground_acceleration : float
        Horizontal PGA [m/s^2] the spectrum is anchored to.
    damping : float, optional
        Fraction of critical damping [-]; only the tabulated 0.005, 0.02,
        0.05, 0.07 and 0.10 are allowed.
    direction : {"horizontal", "vertical"}
    gravity : float, optional
        g [m/s^2], to turn the 36 in per g into a displacement.
    lowest_frequency, highest_frequency : float, optional
        Range tabulated [Hz].

    Returns
    -------
    Spectrum

    Raises
    ------
    ValueError
        For a damping value that RG 1.60 does not tabulate, an unknown
        direction or a negative PGA.
    """
    if direction not in RG160_FACTORS:
        raise ValueError(f"direction must be 'horizontal' or 'vertical', not {direction!r}")
    if peak_ground_acceleration < 0:
        raise ValueError(f"the PGA must be >= 0, not {peak_ground_acceleration}")
    percent = round(damping * 100, 6)
    table = RG160_FACTORS[direction]
    if percent not in table:
        allowed = ", ".join(f"{p:g} %" for p in table)
        raise ValueError(f"RG 1.60 tabulates damping of {allowed} only, not {percent:g} %")
    factor_a, factor_b, factor_c, factor_d = table[percent]
    f_a, f_b, f_c, f_d = RG160_FREQUENCIES[direction]
    displacement_d = factor_d * RG160_DISPLACEMENT_PER_G * peak_ground_acceleration / gravity
    acceleration_d = (2 * math.pi * f_d) ** 2 * displacement_d
    frequency = [lowest_frequency, f_d, f_c, f_b, f_a, highest_frequency]
    acceleration = [
        (2 * math.pi * lowest_frequency) ** 2 * displacement_d,
        acceleration_d,
        factor_c * peak_ground_acceleration,
        factor_b * peak_ground_acceleration,
        factor_a * peak_ground_acceleration,
        peak_ground_acceleration,
    ]
    return Spectrum(
        np.array(frequency),
        np.array(acceleration),
        damping=damping,
        direction=direction,
        label=(
            f"RG 1.60 {direction}, PGA {peak_ground_acceleration / gravity:.3g} g, "
            f"{percent:g} % damping"
        ),
        metadata={
            "source": "US NRC Regulatory Guide 1.60",
            "pga": peak_ground_acceleration,
            "zero_period_acceleration": factor_a * peak_ground_acceleration,
        },
    )


def en1998_damping_correction(damping: float) -> float:
    """EN 1998-1 eq. 3.6: eta = sqrt(10 / (5 + xi)) >= 0.55, xi in percent."""
    return max(math.sqrt(10.0 / (5.0 + 100.0 * damping)), 0.55)


def en1998_spectral_acceleration(
    period: np.ndarray,
    design_acceleration: float,
    soil_factor: float,
    periods: tuple[float, float, float],
    plateau: float,
    eta: float,
) -> np.ndarray:
    """EN 1998-1 eqs. 3.2-3.5 (horizontal) and 3.8-3.11 (vertical, plateau 3.0).

    ``S_e(T) = a S [1 + T/T_B (plateau eta - 1)]`` for T <= T_B,
    ``a S plateau eta`` up to T_C, ``... T_C / T`` up to T_D,
    ``... T_C T_D / T^2`` beyond [m/s^2].
    """
    t_b, t_c, t_d = periods
    t = np.asarray(period, dtype=float)
    top = design_acceleration * soil_factor * plateau * eta
    return np.where(
        t <= t_b,
        design_acceleration * soil_factor * (1 + t / t_b * (plateau * eta - 1)),
        np.where(
            t <= t_c,
            top,
            np.where(
                t <= t_d,
                top * t_c / np.maximum(t, 1e-300),
                top * t_c * t_d / np.maximum(t, 1e-300) ** 2,
            ),
        ),
    )


def en1998_spectrum(
    design_ground_acceleration: float,
    ground: str = "A",
    spectrum_type: int = 1,
    damping: float = 0.05,
    direction: str = "horizontal",
    importance_factor: float = 1.0,
    lowest_frequency: float = 0.05,
    highest_frequency: float = 100.0,
    points: int = 400,
) -> Spectrum:
    """EN 1998-1:2004 elastic response spectrum (section 3.2.2).

    Parameters
    ----------
    design_ground_acceleration : float
        Reference peak ground acceleration on type A ground, a_gR [m/s^2];
        the design value is ``a_g = importance_factor * a_gR``.
    ground : {"A", "B", "C", "D", "E"}
        Ground type (Table 3.1); not used for the vertical spectrum.
    spectrum_type : {1, 2}
        Type 1 (large earthquakes) or Type 2 (M_s <= 5.5).
    damping : float, optional
        Fraction of critical damping [-], any value: eta = sqrt(10/(5 + xi)) >= 0.55.
    direction : {"horizontal", "vertical"}
        Horizontal (eqs. 3.2-3.5) or vertical (eqs. 3.8-3.11, a_vg/a_g 0.90
        for Type 1, 0.45 for Type 2, T_B/T_C/T_D = 0.05/0.15/1.0 s, plateau 3.0).
    importance_factor : float, optional
        gamma_I [-].
    lowest_frequency, highest_frequency : float, optional
        Range tabulated [Hz].
    points : int, optional
        Number of log-spaced frequencies (the corner periods are added).

    Returns
    -------
    Spectrum
    """
    if spectrum_type not in (1, 2):
        raise ValueError(f"spectrum type must be 1 or 2, not {spectrum_type!r}")
    if direction not in ("horizontal", "vertical"):
        raise ValueError(f"direction must be 'horizontal' or 'vertical', not {direction!r}")
    if design_ground_acceleration < 0 or damping < 0:
        raise ValueError("the ground acceleration and the damping must be >= 0")
    a_g = importance_factor * design_ground_acceleration
    if direction == "horizontal":
        if ground not in EN1998_HORIZONTAL[spectrum_type]:
            raise ValueError(f"ground type must be one of A, B, C, D, E, not {ground!r}")
        soil, t_b, t_c, t_d = EN1998_HORIZONTAL[spectrum_type][ground]
        acceleration, plateau = a_g, 2.5
    else:
        ratio, t_b, t_c, t_d = EN1998_VERTICAL[spectrum_type]
        soil, acceleration, plateau = 1.0, ratio * a_g, 3.0
    eta = en1998_damping_correction(damping)
    frequency = np.geomspace(lowest_frequency, highest_frequency, points)
    corners = np.array([1 / t_d, 1 / t_c, 1 / t_b])
    frequency = np.unique(
        np.concatenate(
            [frequency, corners[(corners > lowest_frequency) & (corners < highest_frequency)]]
        )
    )
    values = en1998_spectral_acceleration(
        1 / frequency, acceleration, soil, (t_b, t_c, t_d), plateau, eta
    )
    label = (
        f"EN 1998-1 Type {spectrum_type} {direction}"
        + (f", ground {ground}" if direction == "horizontal" else "")
        + f", a_g = {a_g:.3g} m/s^2, {100 * damping:g} % damping"
    )
    return Spectrum(
        frequency,
        values,
        damping=damping,
        direction=direction,
        label=label,
        metadata={
            "source": "EN 1998-1:2004 section 3.2.2",
            "ag": a_g,
            "zero_period_acceleration": acceleration * soil,
        },
    )


def crane_stand_in_spectra() -> tuple[Spectrum, Spectrum]:
    """Stand-in for the paper's Figs. 4 and 5 (horizontal and vertical, 5 % damping).

    The paper's spectra are not legible in our copy; these are spectra of
    standard shape anchored to the values it quotes:

    - horizontal: RG 1.60 shape, rigid asymptote (above 33 Hz) 2.70 m/s^2,
      amplified region scaled so that 2.5 Hz gives 10.31 m/s^2 (paper
      section 4);
    - vertical: rigid asymptote 2.35 m/s^2, about g between 8 and 12 Hz
      (paper section 6.1), falling towards low frequencies.

    They are a stand-in, not the paper's data: results that depend on their
    detailed shape are illustrations.
    """
    rg = rg160_spectrum(2.70, 0.05, "horizontal")
    # Scale the amplified part so that 2.5 Hz gives 10.31 m/s^2; keep the 2.70 asymptote.
    scale = 10.31 / float(rg.acceleration_at(2.5))
    amplified = rg.acceleration.copy()
    amplified[:4] *= scale  # below 33 Hz: D, C, B and the lowest tabulated point
    horizontal = Spectrum(
        rg.frequency,
        amplified,
        damping=0.05,
        direction="horizontal",
        label=(
            "crane stand-in for the paper's Fig. 4/5 (horizontal, 5 %): "
            "2.70 m/s^2 rigid, 10.31 m/s^2 at 2.5 Hz"
        ),
        metadata={"stand_in": True},
    )
    g = 9.81
    vertical = Spectrum(
        np.array([0.05, 0.25, 3.5, 8.0, 12.0, 33.0, 100.0]),
        np.array([0.004 * g, 0.10 * g, 0.75 * g, 1.0 * g, 1.0 * g, 2.35, 2.35]),
        damping=0.05,
        direction="vertical",
        label=(
            "crane stand-in for the paper's Fig. 4/5 (vertical, 5 %): "
            "2.35 m/s^2 rigid, about g at 8-12 Hz"
        ),
        metadata={"stand_in": True},
    )
    return horizontal, vertical
