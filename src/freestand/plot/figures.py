"""Writing figures to files, shared by the plot modules."""

from __future__ import annotations

from pathlib import Path

from matplotlib.figure import Figure


def save_figure(
    fig: Figure, path: str | Path, *, formats: tuple[str, ...] = ("png", "svg")
) -> list[Path]:
    """Write ``fig`` once per format next to ``path`` (its suffix is replaced).

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    path : str or pathlib.Path
        Target path; its suffix, if any, is replaced by each format's. Missing
        folders are created.
    formats : tuple of str, optional
        File formats (PNG at 150 dots per inch).

    Returns
    -------
    list of pathlib.Path
        The files written.
    """
    base = Path(path)
    written = []
    for fmt in formats:
        target = base.with_suffix(f".{fmt}")
        target.parent.mkdir(parents=True, exist_ok=True)
        fig.savefig(target, format=fmt, dpi=150)
        written.append(target)
    return written
