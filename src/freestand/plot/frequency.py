"""Fig. 9 of the paper: the bridge's lowest vertical frequency against the cart's position."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from freestand.core.motion.spectra import Spectrum
from freestand.core.structure.beam import REACH_TOLERANCE, FrequencySweep, JumpCheck


def plot_frequency_sweep(
    sweep: FrequencySweep,
    *,
    parking: tuple[float, float] | None = None,
    jump: JumpCheck | None = None,
    vertical_spectrum: Spectrum | None = None,
    title: str | None = None,
    ax=None,
):
    """Draw the lowest vertical frequency against the cart's position (paper Fig. 9).

    Parameters
    ----------
    sweep : FrequencySweep
        Frequencies [Hz] against positions [m], from
        :func:`freestand.core.structure.beam.frequency_sweep`.
    parking : tuple of float, optional
        The parking range of the cart's centre [m], shaded. Taken from
        ``jump`` when not given.
    jump : JumpCheck, optional
        A jump check on the same positions: positions where the cart may jump
        are marked on the lower curve (a thick red stretch).
    vertical_spectrum : Spectrum, optional
        The vertical spectrum of the check: the frequencies at which it
        reaches ``g`` (``jump.gravity``, else 9.81 m/s^2) are shaded.
    title : str, optional
        The axes' title.
    ax : matplotlib.axes.Axes, optional
        Draw into these axes (default: a new figure).

    Returns
    -------
    matplotlib.figure.Figure
        A new figure (not shown, not saved), or the figure of ``ax``.
    """
    from matplotlib.figure import Figure

    if parking is None and jump is not None:
        parking = jump.parking
    if ax is None:
        figure = Figure(figsize=(7.0, 4.5), layout="constrained")
        axes = figure.add_subplot()
    else:
        figure, axes = ax.figure, ax
    axes.plot(sweep.position, sweep.exact, color="C0", lw=2.0, label="exact (continuous beam)")
    axes.plot(
        sweep.position,
        sweep.dunkerley,
        color="C1",
        lw=2.0,
        ls="--",
        label="Dunkerley (paper eqs. 1-4)",
    )
    if parking is not None:
        axes.axvspan(parking[0], parking[1], color="0.9", zorder=0, label="parking range")
    top = 1.1 * float(np.nanmax(np.where(np.isfinite(sweep.exact), sweep.exact, np.nan)))
    if vertical_spectrum is not None:
        gravity = jump.gravity if jump is not None else 9.81
        _shade_reaching_band(axes, vertical_spectrum, gravity, top)
    if jump is not None:
        _mark_jump(axes, sweep, jump)
    axes.set_xlim(0.0, sweep.beam.span)
    axes.set_ylim(0.0, top)
    axes.set_xlabel("cart position d from the left support [m]")
    axes.set_ylabel("lowest vertical natural frequency [Hz]")
    axes.set_title(title or "Lowest vertical frequency of the bridge against the cart position")
    axes.grid(True, color="0.9")
    axes.legend(loc="lower center", fontsize="small")
    return figure


def _mark_jump(axes, sweep: FrequencySweep, jump: JumpCheck) -> None:
    if jump.position.shape != sweep.position.shape or not np.allclose(
        jump.position, sweep.position
    ):
        raise ValueError("the jump check was made on other positions than the sweep")
    if jump.at_risk.any():
        lower = np.minimum(sweep.dunkerley, sweep.exact)
        axes.plot(
            jump.position,
            np.where(jump.at_risk, lower, np.nan),
            color="C3",
            lw=6.0,
            alpha=0.45,
            marker="o",
            markersize=3.0,
            solid_capstyle="round",
            label="cart may jump (S_a >= g)",
        )


def _shade_reaching_band(axes, spectrum: Spectrum, gravity: float, top: float) -> None:
    """Shade the frequencies up to ``top`` [Hz] where ``S_a >= g``."""
    frequency = np.geomspace(min(spectrum.frequency[0], 0.1), max(top, 1.0), 4000)
    reaching = spectrum.acceleration_at(frequency) >= gravity * (1.0 - REACH_TOLERANCE)
    edges = np.flatnonzero(np.diff(np.concatenate([[0], reaching.astype(int), [0]])))
    label = "spectrum reaches g"
    for start, stop in zip(edges[::2], edges[1::2], strict=True):
        axes.axhspan(
            frequency[start], frequency[stop - 1], color="C3", alpha=0.12, zorder=0, label=label
        )
        label = None


def save_frequency_figure(figure, path: str | Path, *, dpi: int = 150) -> list[Path]:
    """Write ``figure`` as PNG and SVG next to each other.

    Parameters
    ----------
    figure : matplotlib.figure.Figure
        The figure to write.
    path : str or pathlib.Path
        Target path; its suffix, if any, is replaced by ``.png`` and ``.svg``.
    dpi : int, optional
        Resolution of the PNG [dots per inch].

    Returns
    -------
    list of pathlib.Path
        The two files written.
    """
    base = Path(path)
    base.parent.mkdir(parents=True, exist_ok=True)
    written = []
    for suffix in (".png", ".svg"):
        target = base.with_suffix(suffix)
        figure.savefig(target, dpi=dpi)
        written.append(target)
    return written
