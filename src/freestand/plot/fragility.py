"""Figure of a fragility campaign: fitted curves, their confidence bands, stripe fractions."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from freestand.core.sweeps.fragility.analysis import FragilityResult


def plot_fragility(result: FragilityResult, im_label: str, title: str = "", ax=None) -> Figure:
    """One panel: every outcome's fitted lognormal curve, its bootstrap band, the fractions.

    Parameters
    ----------
    result : FragilityResult
    im_label : str
        Axis label with the unit in brackets, e.g. ``"PGA [m/s^2]"``.
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure
        Lines labelled ``"<outcome>: median ..., beta ..."`` (fitted) and
        markers ``"<outcome>: fractions"`` with Wilson intervals as error bars
        (outcomes drawn slightly apart at each level so that none hides another);
        outcomes not fitted are named in the legend with the words "not fitted".
    """
    if ax is None:
        fig = Figure(figsize=(7.5, 5.0), layout="constrained")
        ax = fig.add_subplot()
    else:
        fig = ax.figure
    ax.grid(True, alpha=0.3)
    colours = [f"C{i}" for i in range(10)]
    top = 0.0
    for item in result.outcomes:
        top = max(top, float(np.max(item.fragility.levels)) if item.fragility.levels.size else 0)
    x = np.linspace(top / 400.0, top * 1.05 if top > 0 else 1.0, 300)
    for number, item in enumerate(result.outcomes):
        f = item.fragility
        colour = colours[number % len(colours)]
        name = item.outcome.name
        used = f.totals > 0
        if result.cloud:
            ax.plot(f.levels[used], f.fraction[used], "o", ms=3, alpha=0.4, color=colour,
                    label=f"{name}: simulations")  # fmt: skip
        else:
            fraction = f.fraction[used]
            err = np.vstack([fraction - f.fraction_low[used], f.fraction_high[used] - fraction])
            # outcomes side by side at each level (markers drawn 0.8 % of the axis apart)
            dodge = (number - 0.5 * (len(result.outcomes) - 1)) * 0.008 * x[-1]
            ax.errorbar(f.levels[used] + dodge, fraction, yerr=err, fmt="o", ms=4, capsize=2,
                        color=colour, label=f"{name}: fractions")  # fmt: skip
        if f.fitted:
            ax.plot(x, f.probability(x), "-", color=colour,
                    label=f"{name}: median {f.median:.3g}, beta {f.beta:.2f}")  # fmt: skip
            low, high = f.band(x)
            ax.fill_between(x, low, high, color=colour, alpha=0.15, linewidth=0,
                            label=f"{name}: {100 * f.confidence:.0f} % band")  # fmt: skip
        else:
            ax.plot([], [], " ", label=f"{name}: not fitted")
    ax.set_xlabel(im_label)
    ax.set_ylabel("probability [-]")
    ax.set_ylim(-0.02, 1.02)
    ax.set_xlim(0.0, x[-1])
    ax.legend(fontsize=7, loc="best")
    if title:
        ax.set_title(title, fontsize=10)
    return fig


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
