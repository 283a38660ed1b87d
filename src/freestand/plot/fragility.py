"""Figure of a fragility campaign: one panel per outcome that occurred, a note for the rest.

Each outcome that occurred in at least one simulation gets its own panel:
the fraction of simulations in which it occurred at each level with its
Wilson interval, and where it could be fitted the lognormal curve
P(x) = Phi(ln(x / theta) / beta) with its bootstrap band; the panel's title
gives theta, beta and the HCLPF, or why no curve was fitted. The outcomes
that never occurred are not drawn (their fractions would all lie on the zero
line, on top of each other): a note under the panels names them, with the
simulations and levels that support that, and the simulations left out.
"""

from __future__ import annotations

import math
import textwrap
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from freestand.core.sweeps.fragility.analysis import FragilityResult, OutcomeFragility

#: Panel size [in] and most panels in a row.
PANEL_WIDTH, PANEL_HEIGHT, MOST_COLUMNS = 4.2, 3.3, 3
#: Labels of the three kinds of artist in every panel (the figure's legend).
LEGEND = (
    "fraction of simulations (95 % Wilson interval)",
    "lognormal fit",
    "bootstrap band of the fit",
)


def occurred(result: FragilityResult) -> list[OutcomeFragility]:
    """The outcomes that occurred in at least one counted simulation."""
    return [item for item in result.outcomes if int(np.sum(item.fragility.counts)) > 0]


def never_occurred(result: FragilityResult) -> list[OutcomeFragility]:
    """The outcomes that occurred in no counted simulation."""
    return [item for item in result.outcomes if int(np.sum(item.fragility.counts)) == 0]


def _number(value: float, unit: str) -> str:
    return f"{value:.3g}" + ("" if unit in ("", "-") else f" {unit}")


def fit_summary(item: OutcomeFragility, unit: str) -> str:
    """The fit in words: median, beta, HCLPF, or why there is no curve."""
    f = item.fragility
    if not f.fitted:
        return f"not fitted: {f.reason}"
    text = f"median {_number(f.median, unit)}, beta {f.beta:.2f}"
    top = float(np.max(f.levels)) if f.levels.size else math.nan
    if f.median > top:
        text += " (above the highest level)"
    if math.isfinite(f.hclpf):
        text += f", HCLPF {_number(f.hclpf, unit)}"
    return text


def fragility_note(result: FragilityResult, im_label: str) -> str:
    """The note under the figure: outcomes that never occurred, simulations left out."""
    sentences = []
    never = never_occurred(result)
    counted = result.simulations - result.failed
    levels = [item.fragility.levels for item in result.outcomes if item.fragility.levels.size]
    if never:
        names = ", ".join(item.outcome.name for item in never)
        span = ""
        if levels:
            low = min(float(np.min(x)) for x in levels)
            high = max(float(np.max(x)) for x in levels)
            span = f", {im_label.split(' [')[0]} {_number(low, result.unit)} to " + _number(
                high, result.unit
            )
        sentences.append(
            f"Never occurred in the {counted} simulations counted{span} (not drawn): {names}."
        )
    if result.failed:
        kinds = ", ".join(
            f"{count} {status}"
            for status, count in sorted(result.statuses.items())
            if status in ("failed", "invalid")
        )
        sentences.append(f"Left out of the counts: {kinds} simulation(s).")
    return " ".join(sentences)


def _grid(count: int) -> tuple[int, int]:
    columns = min(max(count, 1), MOST_COLUMNS)
    return math.ceil(max(count, 1) / columns), columns


def _levels_axis(result: FragilityResult) -> np.ndarray:
    top = 0.0
    for item in result.outcomes:
        if item.fragility.levels.size:
            top = max(top, float(np.max(item.fragility.levels)))
    top = top if top > 0 else 1.0
    return np.linspace(top / 400.0, top * 1.05, 300)


def _draw_outcome(
    ax, item: OutcomeFragility, x: np.ndarray, colour: str, cloud: bool, dodge: float = 0.0
) -> list:
    """Fractions (or simulations), fitted curve and band of one outcome; the artists drawn.

    ``dodge`` [IM unit] shifts the markers sideways (outcomes sharing one axes).
    """
    f = item.fragility
    name = item.outcome.name
    used = f.totals > 0
    if cloud:
        (markers,) = ax.plot(f.levels[used], f.fraction[used], "o", ms=3, alpha=0.4,
                             color=colour, label=f"{name}: fractions")  # fmt: skip
    else:
        fraction = f.fraction[used]
        err = np.vstack([fraction - f.fraction_low[used], f.fraction_high[used] - fraction])
        markers = ax.errorbar(f.levels[used] + dodge, fraction, yerr=err, fmt="o", ms=4,
                              capsize=2, color=colour, label=f"{name}: fractions")  # fmt: skip
    artists = [markers]
    if f.fitted:
        (curve,) = ax.plot(x, f.probability(x), "-", color=colour,
                           label=f"{name}: {fit_summary(item, '')}")  # fmt: skip
        low, high = f.band(x)
        band = ax.fill_between(x, low, high, color=colour, alpha=0.18, linewidth=0,
                               label=f"{name}: {100 * f.confidence:.0f} % band")  # fmt: skip
        artists += [curve, band]
    return artists


def _style(ax, x: np.ndarray) -> None:
    ax.grid(True, alpha=0.3)
    ax.set_ylim(-0.02, 1.02)
    ax.set_xlim(0.0, x[-1])


def plot_fragility(result: FragilityResult, im_label: str, title: str = "", ax=None) -> Figure:
    """The fragility figure: a panel per outcome that occurred, a note for the others.

    Parameters
    ----------
    result : FragilityResult
        The campaign's counts and fits.
    im_label : str
        Axis label with the unit in brackets, e.g. ``"PGA [m/s^2]"``.
    title : str, optional
        The figure's title.
    ax : matplotlib.axes.Axes, optional
        Draw every outcome that occurred into these axes instead (legend
        outside them, on the right; the note under them).

    Returns
    -------
    matplotlib.figure.Figure
        Per outcome that occurred: markers ``"<outcome>: fractions"`` (with
        Wilson intervals as error bars; for a cloud, one point per
        simulation), and where fitted a line ``"<outcome>: median ...,
        beta ..."`` and a band ``"<outcome>: 95 % band"``; panels titled with
        the outcome and its fit or the reason it has none. Outcomes that
        never occurred have no artist: the text with gid ``"note"`` names
        them (and the simulations left out).
    """
    x = _levels_axis(result)
    shown = occurred(result)
    note = fragility_note(result, im_label)
    if ax is not None:
        return _into_axes(ax, result, shown, x, im_label, title, note)
    rows, columns = _grid(len(shown))
    width = max(7.5, PANEL_WIDTH * columns)
    wrap = int(width * 15)  # characters of the note per line at its font size
    note_height = 0.45 + 0.2 * (len(textwrap.wrap(note, wrap)) if note else 0)
    fig = Figure(figsize=(width, PANEL_HEIGHT * rows + note_height + 0.4), layout="constrained")
    grid = fig.add_gridspec(rows + 1, columns, height_ratios=[PANEL_HEIGHT] * rows + [note_height])
    kinds = _draw_panels(fig, grid, columns, shown, x, result, im_label)
    bottom = fig.add_subplot(grid[rows, :])
    bottom.axis("off")
    if kinds:
        handles, labels = _legend_keys(result.cloud)
        bottom.legend(handles[:kinds], labels[:kinds], loc="upper left", ncols=kinds,
                      frameon=False, fontsize=8, borderaxespad=0.0)  # fmt: skip
    if note:
        bottom.text(0.0, 0.0, textwrap.fill(note, wrap), fontsize=8, va="bottom", ha="left",
                    transform=bottom.transAxes, gid="note")  # fmt: skip
    if title:
        fig.suptitle(title, fontsize=10)
    return fig


def _draw_panels(fig, grid, columns: int, shown, x, result, im_label: str) -> int:
    """A panel per outcome shown (one saying so when none is); the most kinds of artist drawn."""
    kinds = 0
    items = shown or [None]
    for number, item in enumerate(items):
        panel = fig.add_subplot(grid[number // columns, number % columns])
        _style(panel, x)
        if item is None:
            panel.text(0.5, 0.5, "no outcome occurred", ha="center", va="center",
                       transform=panel.transAxes, color="0.4")  # fmt: skip
        else:
            kinds = max(kinds, len(_draw_outcome(panel, item, x, f"C{number % 10}", result.cloud)))
            summary = "\n".join(textwrap.wrap(fit_summary(item, result.unit), 52))
            panel.set_title(f"{item.outcome.name}\n{summary}", fontsize=9, loc="left")
        if number % columns == 0:
            panel.set_ylabel("probability [-]")
        if number + columns >= len(items):  # no panel below it
            panel.set_xlabel(im_label)
    return kinds


def _legend_keys(cloud: bool) -> tuple[list, tuple[str, ...]]:
    """Grey keys of the three kinds of artist (the panels' colours tell outcomes apart)."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    markers = Line2D([], [], color="0.35", marker="o", ms=4, linestyle="none")
    labels = LEGEND if not cloud else ("simulations (1: occurred, 0: not)", *LEGEND[1:])
    return [markers, Line2D([], [], color="0.35"), Patch(color="0.35", alpha=0.25)], labels


def _into_axes(ax, result, shown, x, im_label: str, title: str, note: str) -> Figure:
    """Every outcome that occurred in one axes: legend outside on the right, note below.

    One legend key per outcome (its markers and curve); the markers of the
    outcomes are drawn 0.8 % of the axis apart so that none hides another.
    """
    _style(ax, x)
    handles, labels = [], []
    for number, item in enumerate(shown):
        dodge = (number - 0.5 * (len(shown) - 1)) * 0.008 * x[-1]
        artists = _draw_outcome(ax, item, x, f"C{number % 10}", result.cloud, dodge)
        handles.append(tuple(artists[:2]))
        labels.append(f"{item.outcome.name}: {fit_summary(item, result.unit)}")
    ax.set_xlabel(im_label)
    ax.set_ylabel("probability [-]")
    if shown:
        ax.legend(handles, ["\n".join(textwrap.wrap(t, 48)) for t in labels], fontsize=7,
                  loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)  # fmt: skip
    keys = "Markers: " + LEGEND[0] + "; shading: " + LEGEND[2] + "."
    note = f"{keys} {note}".strip()
    if note:
        ax.annotate(textwrap.fill(note, 90), xy=(0.0, 0.0), xycoords="axes fraction",
                    xytext=(0.0, -38.0), textcoords="offset points", va="top", ha="left",
                    fontsize=8, gid="note")  # fmt: skip
    if title:
        ax.set_title(title, fontsize=10)
    return ax.figure


def save_fragility_figure(fig: Figure, path: str | Path) -> Path:
    """Write the figure to ``path`` (format from the suffix), through a temporary file."""
    import os
    import tempfile

    target = Path(path)
    handle, temporary = tempfile.mkstemp(dir=target.parent, suffix=target.suffix)
    os.close(handle)
    try:
        fig.savefig(temporary, format=target.suffix.lstrip(".").lower(), dpi=150)
        os.replace(temporary, target)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise
    return target
