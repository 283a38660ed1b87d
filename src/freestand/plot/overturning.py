"""Figures of the overturning assessment (analogues of the paper's Figs. 6-8).

Each function takes result objects of :mod:`freestand.core.rocking.overturning`, draws
on a new figure (Agg-safe: no window is opened) and returns the
:class:`matplotlib.figure.Figure`. :func:`save_figure` (defined in
:mod:`freestand.plot.figures`, importable from here) writes PNG and SVG.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from freestand.core.motion.spectra import Spectrum
from freestand.core.rocking.overturning import OverturningLimits, RectangularPulseLimits
from freestand.plot.figures import save_figure

__all__ = [
    "plot_body_pulse_limits",
    "plot_pulse_limits",
    "plot_rectangular_pulse",
    "plot_spectrum_check",
    "save_figure",
]

_STYLE = {
    "housner": {"color": "tab:blue", "linestyle": "--", "label": "Housner (1963), linearised"},
    "makris-roussos": {
        "color": "tab:green",
        "linestyle": "-.",
        "label": "Makris & Roussos (2000) eq. 27, linearised",
    },
    "exact": {"color": "tab:red", "linestyle": "-", "label": "exact nonlinear, with impacts"},
}


#: Short names of the limits in legends.
_SHORT = {"housner": "Housner", "makris-roussos": "Makris & Roussos", "exact": "exact"}


def _short(name: str) -> str:
    return _SHORT.get(name, name)


def _new_figure(ax=None, size: tuple[float, float] = (7.0, 4.8)) -> tuple[Figure, object]:
    """A new figure with one grid-lined axes, or ``ax`` and its figure when given."""
    if ax is None:
        fig = Figure(figsize=size, layout="constrained")
        ax = fig.add_subplot()
    else:
        fig = ax.figure
    ax.grid(True, which="both", alpha=0.3)
    return fig, ax


def plot_rectangular_pulse(
    limits: RectangularPulseLimits, *, title: str | None = None, ax=None
) -> Figure:
    """Shortest overturning duration against amplitude of a rectangular pulse (paper Fig. 6).

    Parameters
    ----------
    limits : RectangularPulseLimits
        Housner's and the exact limits.
    title : str, optional
        Figure title.
    ax : matplotlib.axes.Axes, optional
        Draw into these axes (default: a new figure).
    """
    fig, ax = _new_figure(ax)
    a = limits.amplitude
    for name, values in (("housner", limits.housner), ("exact", limits.exact)):
        finite = np.isfinite(values)
        ax.plot(a[finite], values[finite], **_STYLE[name])
    if limits.operating_amplitude is not None:
        a0 = limits.operating_amplitude
        for name, t in (("housner", limits.operating_housner), ("exact", limits.operating_exact)):
            if np.isfinite(t):
                ax.plot(
                    [a0], [t], "o", color=_STYLE[name]["color"],
                    label=f"{a0:.2f} m/s^2: {t:.2f} s ({_short(name)})",
                )  # fmt: skip
        ax.axvline(a0, color="0.4", linewidth=0.8, linestyle=":")
    ax.set_xlabel("pulse acceleration a [m/s^2]")
    ax.set_ylabel("shortest overturning pulse duration t1 [s]")
    ax.set_title(title or "Rectangular pulse: overturning above the curve")
    ax.legend(loc="upper right", fontsize="small")
    return fig


def plot_pulse_limits(limits: OverturningLimits, *, title: str | None = None, ax=None) -> Figure:
    """Minimum overturning amplitude against pulse frequency (paper Fig. 7).

    Parameters
    ----------
    limits : OverturningLimits
        The limits to draw (all on one figure, log-log axes).
    title : str, optional
        Figure title.
    ax : matplotlib.axes.Axes, optional
        Draw into these axes (default: a new figure).
    """
    fig, ax = _new_figure(ax)
    _draw_limits(ax, limits)
    ax.set_title(title or f"{limits.kind.capitalize()} pulse: overturning above the curves")
    ax.legend(loc="upper left", fontsize="small")
    return fig


def plot_body_pulse_limits(
    curve, reference: OverturningLimits, *, title: str | None = None, ax=None
) -> Figure:
    """The 3-D body's minimum overturning amplitude over the planar limits of its pulse's plane.

    Parameters
    ----------
    curve : freestand.core.rocking.body_overturning.BodyOverturningCurve
        The 3-D limit (points at its frequencies, joined by a line; a cross
        on the lower axis where none was found up to the search limit).
    reference : OverturningLimits
        The planar limits of the block in the pulse's vertical plane (thin
        lines, "planar" in the legend).
    title : str, optional
        Figure title.
    ax : matplotlib.axes.Axes, optional
        Draw into these axes (default: a new figure).
    """
    fig, ax = _new_figure(ax)
    _draw_limits(ax, reference, prefix="planar, pulse's plane: ", operating=False, linewidth=1.0)
    f, a = curve.frequency, curve.amplitude
    found = np.isfinite(a)
    label = f"3-D exact, along {curve.direction:g} deg (tips about {curve.pivot})"
    ax.loglog(f[found], a[found], "o-", color="k", linewidth=2.0, markersize=6, label=label)
    if not found.all():
        low = ax.get_ylim()[0]
        ax.plot(f[~found], np.full(int((~found).sum()), low), "x", color="k", markersize=9,
                clip_on=False, label="3-D: none found up to the search limit")  # fmt: skip
    a0 = curve.limits.operating_amplitude
    if a0 is not None:
        ax.axhline(a0, color="0.4", linewidth=0.8, linestyle=":")
        f0 = curve.limits.operating_frequency["exact-3d"]
        if np.isfinite(f0):
            ax.plot([f0], [a0], "s", color="k", markerfacecolor="none", markersize=9,
                    label=f"{a0:.2f} m/s^2 overturns up to {f0:.2f} Hz (3-D)")  # fmt: skip
    ax.set_title(title or "Half-sine pulse: overturning above the curves")
    ax.legend(loc="upper left", fontsize="small")
    return fig


def _draw_limits(
    ax, limits: OverturningLimits, prefix: str = "", operating: bool = True, **line
) -> None:
    f = limits.frequency
    for name, values in limits.limits.items():
        style = dict(_STYLE.get(name, {"label": name}), **line)
        style["label"] = prefix + style["label"]
        finite = np.isfinite(values)
        ax.loglog(f[finite], values[finite], **style)
    if operating and limits.operating_amplitude is not None:
        a0 = limits.operating_amplitude
        ax.axhline(a0, color="0.4", linewidth=0.8, linestyle=":")
        for name, f0 in limits.operating_frequency.items():
            if np.isfinite(f0):
                ax.plot(
                    [f0], [a0], "o", color=_STYLE.get(name, {}).get("color", "k"),
                    label=f"{a0:.2f} m/s^2 overturns up to {f0:.2f} Hz ({_short(name)})",
                )  # fmt: skip
    ax.set_xlabel("pulse frequency f [Hz]")
    ax.set_ylabel("peak acceleration of the pulse [m/s^2]")


def plot_spectrum_check(
    limits: OverturningLimits,
    spectrum: Spectrum,
    checks: dict | None = None,
    *,
    title: str | None = None,
    ax=None,
) -> Figure:
    """A response spectrum against the overturning limits (paper Fig. 8).

    Parameters
    ----------
    limits : OverturningLimits
        The limits.
    spectrum : Spectrum
        The horizontal response spectrum.
    checks : dict of str to SpectrumCheck, optional
        Results of :func:`freestand.core.rocking.overturning.check_spectrum`; the point
        of smallest margin of each is marked.
    title : str, optional
        Figure title.
    ax : matplotlib.axes.Axes, optional
        Draw into these axes (default: a new figure); the legend goes below
        the axes either way.
    """
    fig, ax = _new_figure(ax, size=(7.0, 7.2))
    _draw_limits(ax, limits)
    f = np.geomspace(limits.frequency[0], limits.frequency[-1], 300)
    ax.loglog(f, spectrum.acceleration_at(f), color="k", linewidth=2.0, label=spectrum.label)
    for name, check in (checks or {}).items():
        if np.isfinite(check.min_ratio):
            # nested open markers of different shapes and sizes: two limits whose smallest
            # margin falls at the same frequency stay both visible
            marker, size = _MARGIN_MARKERS.get(name, ("s", 8))
            ax.plot(
                [check.frequency_at_min], [check.spectrum_at_min], marker,
                color=_STYLE.get(name, {}).get("color", "k"), markerfacecolor="none",
                markersize=size, markeredgewidth=1.4, linestyle="none",
                label=f"smallest limit / spectrum {check.min_ratio:.2f} at "
                f"{check.frequency_at_min:.2f} Hz ({_short(name)}): {check.verdict}",
            )  # fmt: skip
    ax.set_ylabel("peak pulse / spectral acceleration [m/s^2]")
    ax.set_title(title or "Response spectrum against the overturning limits")
    # below the axes, so that no entry hides a curve
    fig.legend(loc="outside lower center", ncols=1, fontsize="x-small", frameon=False)
    return fig


#: Marker and size of the point of smallest margin of each limit on the Fig. 8 analogue.
_MARGIN_MARKERS = {"housner": ("s", 13), "makris-roussos": ("D", 9), "exact": ("o", 5)}
