"""Figures of record spectra and generated suites against a target spectrum."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from freestand.core.motion.spectra import Spectrum


def _frequency_axis(axes) -> None:
    """Log frequency axis labelled 0.1, 0.2, 0.5, 1, 2, 5, ... rather than powers of ten."""
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    axes.set_xscale("log")
    axes.xaxis.set_major_locator(LogLocator(base=10.0, subs=(1.0, 2.0, 5.0)))
    axes.xaxis.set_major_formatter(FuncFormatter(lambda value, _: f"{value:g}"))
    axes.xaxis.set_minor_formatter(NullFormatter())


def plot_record_spectra(
    frequency: np.ndarray,
    spectra: Sequence[tuple],
    *,
    target: Spectrum | None = None,
    bounds: tuple[float, float] | None = (0.9, 1.3),
    mean: np.ndarray | None = None,
    title: str | None = None,
    damping: float | None = None,
    axes=None,
    vertical_target: Spectrum | None = None,
):
    """Pseudo-acceleration spectra of records, their targets, and their ratios.

    Parameters
    ----------
    frequency : numpy.ndarray
        Frequencies [Hz] of every spectrum.
    spectra : sequence of (label, numpy.ndarray) or (label, numpy.ndarray, component)
        Pseudo-acceleration [m/s^2] of each record component at ``frequency``,
        and which component it is (``"horizontal"``, ``"horizontal_y"`` or
        ``"vertical"``; default horizontal). With more than ten, they are
        drawn thin and grey without a legend entry each (a suite), and their
        mean is drawn.
    target : Spectrum, optional
        Target spectrum [m/s^2] of the horizontal components (or of all when
        no ``vertical_target`` is given): drawn black, with ``bounds`` times
        it dashed, and a lower panel with record / target.
    bounds : tuple of float, optional
        Acceptance band [-] (default 0.9 and 1.3 times the target).
    mean : numpy.ndarray, optional
        A mean spectrum [m/s^2] to draw bold (default: the mean of a suite).
    title : str, optional
        Title of the figure.
    damping : float, optional
        Damping ratio [-] for the axis label.
    axes : matplotlib.axes.Axes, optional
        Draw the spectra into these axes (no ratio panel) instead of a new
        figure.
    vertical_target : Spectrum, optional
        Target of the vertical components: drawn black dash-dotted; their
        ratios are taken to it (without it, to ``target``).

    Returns
    -------
    matplotlib.figure.Figure
        A new figure (not shown, not saved), or the figure of ``axes``: the
        upper axes hold the spectra (log frequency), the lower axes, with a
        target, each record / its target.
    """
    from matplotlib.figure import Figure

    frequency = np.asarray(frequency, dtype=float)
    many = len(spectra) > 10
    if many and mean is None:
        mean = np.mean([item[1] for item in spectra], axis=0)
    main = target if target is not None else vertical_target
    if axes is not None:
        figure, ratio_axes = axes.figure, None
    elif main is not None:
        figure = Figure(figsize=(7.5, 6.5), layout="constrained")
        axes, ratio_axes = figure.subplots(2, 1, sharex=True, height_ratios=(2.2, 1.0))
    else:
        figure = Figure(figsize=(7.5, 4.5), layout="constrained")
        axes, ratio_axes = figure.add_subplot(), None

    def goal(spectrum):
        return None if spectrum is None else np.asarray(spectrum.acceleration_at(frequency))

    goals = {"horizontal": goal(target), "vertical": goal(vertical_target or target)}
    for index, item in enumerate(spectra):
        label, values = item[0], item[1]
        direction = "vertical" if len(item) > 2 and item[2] == "vertical" else "horizontal"
        if many:
            axes.plot(frequency, values, color="0.7", lw=0.6,
                      label="records" if index == 0 else None)  # fmt: skip
        else:
            axes.plot(frequency, values, lw=1.4, label=label, color=f"C{index % 10}")
        if ratio_axes is not None and goals[direction] is not None:
            ratio_axes.plot(
                frequency,
                values / np.maximum(goals[direction], 1e-300),
                color="0.7" if many else f"C{index % 10}",
                lw=0.6 if many else 1.2,
            )
    main_values = goal(main)
    if mean is not None:
        axes.plot(frequency, mean, color="C3" if not many else "C0", lw=2.2,
                  label=f"mean of {len(spectra)}")  # fmt: skip
        if ratio_axes is not None:
            ratio_axes.plot(frequency, mean / np.maximum(main_values, 1e-300),
                            color="C3" if not many else "C0", lw=2.2)  # fmt: skip
    if main is not None:
        axes.plot(frequency, main_values, color="k", lw=2.0, label=main.label or "target")
        if bounds is not None:
            for bound in bounds:
                axes.plot(frequency, bound * main_values, color="k", lw=1.0, ls="--",
                          label=f"{bounds[0]:g} and {bounds[1]:g} x target"
                          if bound == bounds[0] else None)  # fmt: skip
                if ratio_axes is not None:
                    ratio_axes.axhline(bound, color="k", lw=1.0, ls="--")
    if target is not None and vertical_target is not None:
        axes.plot(frequency, goal(vertical_target), color="k", lw=1.6, ls="-.",
                  label=vertical_target.label or "vertical target")  # fmt: skip
    if ratio_axes is not None:
        ratio_axes.axhline(1.0, color="k", lw=1.0)
        ratio_axes.set_ylabel("record / its target [-]")
        ratio_axes.set_xlabel("frequency [Hz]")
        ratio_axes.grid(True, which="both", alpha=0.3)
    else:
        axes.set_xlabel("frequency [Hz]")
    _frequency_axis(axes)
    zeta = "" if damping is None else f", {100 * damping:g} % damping"
    axes.set_ylabel(f"pseudo-acceleration [m/s$^2$]{zeta}")
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize=8, loc="best")
    if title:
        axes.set_title(title)
    return figure


#: Column titles of the components of a suite.
_COMPONENT_TITLES = {
    "horizontal": "x (horizontal)",
    "horizontal_y": "y (second horizontal)",
    "vertical": "vertical",
}


def plot_suite_spectra(
    frequency: np.ndarray,
    components: Sequence[tuple[str, Spectrum, Sequence[np.ndarray], np.ndarray]],
    *,
    bounds: tuple[float, float] = (0.9, 1.3),
    title: str | None = None,
    axes=None,
):
    """Spectra of a generated suite against its targets: one column per component.

    Parameters
    ----------
    frequency : numpy.ndarray
        Check frequencies [Hz].
    components : sequence of (direction, target, spectra, mean)
        Per component (``"horizontal"``, ``"horizontal_y"``, ``"vertical"``):
        its target Spectrum, the records' pseudo-accelerations [m/s^2] at
        ``frequency`` and their mean [m/s^2].
    bounds : tuple of float, optional
        Acceptance band [-] (0.9 and 1.3 times the target).
    title : str, optional
        Title of the figure.
    axes : matplotlib.axes.Axes, optional
        Draw the first component's spectra into these axes (no other panel).

    Returns
    -------
    matplotlib.figure.Figure
        Per component, a column: above, the records (thin grey), their mean
        (red), the target (black) and the band (dashed); below, record /
        target with the band. One legend, in the first column.
    """
    from matplotlib.figure import Figure

    frequency = np.asarray(frequency, dtype=float)
    if axes is not None:
        columns = [(axes, None)]
        figure = axes.figure
    else:
        figure = Figure(figsize=(1.0 + 5.0 * len(components), 6.0), layout="constrained")
        grid = figure.subplots(2, len(components), sharex=True, squeeze=False,
                               height_ratios=(2.2, 1.0))  # fmt: skip
        columns = [(grid[0, k], grid[1, k]) for k in range(len(components))]
    for (upper, lower), component in zip(columns, components, strict=False):
        direction, target, spectra, mean = component
        goal = np.asarray(target.acceleration_at(frequency), dtype=float)
        for index, values in enumerate(spectra):
            label = f"records ({len(spectra)})" if index == 0 else None
            upper.plot(frequency, values, color="0.65", lw=0.7, label=label)
            if lower is not None:
                lower.plot(frequency, values / goal, color="0.65", lw=0.7)
        upper.plot(frequency, mean, color="C3", lw=2.0, label="mean")
        upper.plot(frequency, goal, color="k", lw=2.0, label="target")
        for bound in bounds:
            upper.plot(frequency, bound * goal, color="k", lw=1.0, ls="--",
                       label=f"{bounds[0]:g} and {bounds[1]:g} x target"
                       if bound == bounds[0] else None)  # fmt: skip
        upper.set_title(f"{_COMPONENT_TITLES.get(direction, direction)}\n{target.label}",
                        fontsize=9)  # fmt: skip
        upper.set_ylabel(f"pseudo-acceleration [m/s$^2$], {100 * target.damping:g} % damping")
        upper.grid(True, which="both", alpha=0.3)
        _frequency_axis(upper)
        if lower is None:
            upper.set_xlabel("frequency [Hz]")
            continue
        lower.plot(frequency, mean / goal, color="C3", lw=2.0)
        lower.axhline(1.0, color="k", lw=1.0)
        for bound in bounds:
            lower.axhline(bound, color="k", lw=1.0, ls="--")
        lower.set_ylabel("record / target [-]")
        lower.set_xlabel("frequency [Hz]")
        lower.grid(True, which="both", alpha=0.3)
    columns[0][0].legend(fontsize=8, loc="lower center")
    if title:
        figure.suptitle(title)
    return figure


def plot_floor_motion(
    time: np.ndarray, ground: np.ndarray, floor: np.ndarray, *, title=None, axes=None
):
    """Ground and floor (in-structure) acceleration histories [m/s^2] against time [s].

    Parameters
    ----------
    time : numpy.ndarray
        Times [s].
    ground, floor : numpy.ndarray
        Ground and floor accelerations [m/s^2] at ``time``.
    title : str, optional
        Title of the axes.
    axes : matplotlib.axes.Axes, optional
        Draw into these axes instead of a new figure.

    Returns
    -------
    matplotlib.figure.Figure
        One axes with both histories (not shown, not saved).
    """
    from matplotlib.figure import Figure

    if axes is None:
        figure = Figure(figsize=(7.5, 3.5), layout="constrained")
        axes = figure.add_subplot()
    else:
        figure = axes.figure
    axes.plot(time, floor, color="C3", lw=0.8, label="floor (oscillator absolute acceleration)")
    axes.plot(time, ground, color="C0", lw=0.8, label="ground")
    axes.set_xlabel("time [s]")
    axes.set_ylabel("acceleration [m/s$^2$]")
    axes.grid(True, alpha=0.3)
    axes.legend(fontsize=8)
    if title:
        axes.set_title(title)
    return figure
