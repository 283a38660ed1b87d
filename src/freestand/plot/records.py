"""Figures of record spectra and generated suites against a target spectrum."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from freestand.core.motion.spectra import Spectrum


def plot_record_spectra(
    frequency: np.ndarray,
    spectra: Sequence[tuple[str, np.ndarray]],
    *,
    target: Spectrum | None = None,
    bounds: tuple[float, float] | None = (0.9, 1.3),
    mean: np.ndarray | None = None,
    title: str | None = None,
    damping: float | None = None,
):
    """Pseudo-acceleration spectra of records, a target, and their ratio.

    Parameters
    ----------
    frequency : numpy.ndarray
        Frequencies [Hz] of every spectrum.
    spectra : sequence of (label, numpy.ndarray)
        Pseudo-acceleration [m/s^2] of each record component at ``frequency``.
        With more than ten, they are drawn thin and grey without a legend entry
        each (a suite), and their mean is drawn.
    target : Spectrum, optional
        Target spectrum [m/s^2]: drawn black, with ``bounds`` times it dashed,
        and a lower panel with record / target.
    bounds : tuple of float, optional
        Acceptance band [-] (default 0.9 and 1.3 times the target).
    mean : numpy.ndarray, optional
        A mean spectrum [m/s^2] to draw bold (default: the mean of a suite).
    title : str, optional
        Title of the figure.
    damping : float, optional
        Damping ratio [-] for the axis label.

    Returns
    -------
    matplotlib.figure.Figure
        A new figure (not shown, not saved): the upper axes hold the spectra
        (log frequency), the lower axes, with a target, the ratios.
    """
    from matplotlib.figure import Figure

    frequency = np.asarray(frequency, dtype=float)
    many = len(spectra) > 10
    if many and mean is None:
        mean = np.mean([values for _, values in spectra], axis=0)
    figure = Figure(figsize=(7.5, 6.5 if target is not None else 4.5), layout="constrained")
    if target is not None:
        axes, ratio_axes = figure.subplots(2, 1, sharex=True, height_ratios=(2.2, 1.0))
    else:
        axes, ratio_axes = figure.add_subplot(), None
    target_values = None
    if target is not None:
        target_values = np.asarray(target.acceleration_at(frequency), dtype=float)
    for index, (label, values) in enumerate(spectra):
        if many:
            axes.plot(frequency, values, color="0.7", lw=0.6,
                      label="records" if index == 0 else None)  # fmt: skip
        else:
            axes.plot(frequency, values, lw=1.4, label=label)
        if ratio_axes is not None:
            ratio_axes.plot(
                frequency,
                values / np.maximum(target_values, 1e-300),
                color="0.7" if many else f"C{index % 10}",
                lw=0.6 if many else 1.2,
            )
    if mean is not None:
        axes.plot(frequency, mean, color="C0", lw=2.2, label=f"mean of {len(spectra)}")
        if ratio_axes is not None:
            ratio_axes.plot(frequency, mean / np.maximum(target_values, 1e-300), color="C0", lw=2.2)
    if target is not None:
        axes.plot(frequency, target_values, color="k", lw=2.0, label=target.label or "target")
        if bounds is not None:
            for bound in bounds:
                axes.plot(frequency, bound * target_values, color="k", lw=1.0, ls="--",
                          label=f"{bounds[0]:g} and {bounds[1]:g} x target"
                          if bound == bounds[0] else None)  # fmt: skip
                ratio_axes.axhline(bound, color="k", lw=1.0, ls="--")
        ratio_axes.axhline(1.0, color="k", lw=1.0)
        ratio_axes.set_ylabel("record / target [-]")
        ratio_axes.set_xlabel("frequency [Hz]")
        ratio_axes.grid(True, which="both", alpha=0.3)
    else:
        axes.set_xlabel("frequency [Hz]")
    axes.set_xscale("log")
    zeta = "" if damping is None else f", {100 * damping:g} % damping"
    axes.set_ylabel(f"pseudo-acceleration [m/s$^2$]{zeta}")
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize=8, loc="best")
    if title:
        axes.set_title(title)
    return figure


def plot_floor_motion(time: np.ndarray, ground: np.ndarray, floor: np.ndarray, *, title=None):
    """Ground and floor (in-structure) acceleration histories [m/s^2] against time [s].

    Returns
    -------
    matplotlib.figure.Figure
        One axes with both histories (not shown, not saved).
    """
    from matplotlib.figure import Figure

    figure = Figure(figsize=(7.5, 3.5), layout="constrained")
    axes = figure.add_subplot()
    axes.plot(time, floor, color="C3", lw=0.8, label="floor (oscillator absolute acceleration)")
    axes.plot(time, ground, color="C0", lw=0.8, label="ground")
    axes.set_xlabel("time [s]")
    axes.set_ylabel("acceleration [m/s$^2$]")
    axes.grid(True, alpha=0.3)
    axes.legend(fontsize=8)
    if title:
        axes.set_title(title)
    return figure
