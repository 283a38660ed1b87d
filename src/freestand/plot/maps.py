"""Mode-map figures: coloured regions of initial motion with a legend.

One panel per map (typically one per sense of the horizontal inertial
force); every region is coloured by the joint motion of the blocks, nodes
with several admissible states are hatched, and the model's own excitation
points are marked and named.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np

from freestand.core.sweeps.mode_map import ModeMap

#: Colours by the words of a region name (first match wins), else a cycle.
_PALETTE = (
    "#d9d9d9",
    "#8dd3c7",
    "#fdb462",
    "#80b1d3",
    "#fb8072",
    "#bebada",
    "#b3de69",
    "#fccde5",
    "#ffffb3",
    "#bc80bd",
    "#ccebc5",
    "#ffed6f",
)


def _colours(labels: Sequence[str]) -> dict[str, str]:
    ordered = sorted(labels, key=lambda label: (label.count("rests") == 0, label))
    colours = {}
    spare = iter(_PALETTE[1:] * 4)
    for label in ordered:
        if "free flight" in label:
            colours[label] = "#636363"
        elif "no consistent" in label:
            colours[label] = "#000000"
        elif "slides" not in label and "rocks" not in label and "lifts" not in label:
            colours[label] = _PALETTE[0]
        else:
            colours[label] = next(spare)
    return colours


def mode_map_figure(
    maps: Sequence[ModeMap],
    points: Sequence[Sequence[tuple[str, float, float]]] = (),
    title: str | None = None,
):
    """Mode maps side by side, one panel each, with a legend of the regions below.

    Parameters
    ----------
    maps : sequence of ModeMap
        One panel each (same axes), e.g. sense + and sense -.
    points : sequence of sequence of (str, float, float[, str])
        For each map, the model's points (name, x, y) to mark, with the
        region name solved at the point (else the nearest node's).
    title : str, optional
        Figure title.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.colors import ListedColormap
    from matplotlib.figure import Figure
    from matplotlib.patches import Patch

    labels = sorted({label for m in maps for label in m.labels.values()})
    colours = _colours(labels)
    index = {label: i for i, label in enumerate(labels)}
    cmap = ListedColormap([colours[label] for label in labels])
    figure = Figure(figsize=(5.2 * len(maps) + 0.5, 5.6))
    axes = figure.subplots(1, len(maps), squeeze=False, sharey=True)
    for panel, (ax, m) in enumerate(zip(axes[0], maps, strict=True)):
        lookup = np.vectorize(lambda code, m=m: index[m.labels[int(code)]])
        image = lookup(m.codes) if m.codes.size else m.codes
        dx = (m.x_values[-1] - m.x_values[0]) / max(len(m.x_values) - 1, 1)
        dy = (m.y_values[-1] - m.y_values[0]) / max(len(m.y_values) - 1, 1)
        ax.imshow(
            image,
            origin="lower",
            extent=(
                m.x_values[0] - dx / 2,
                m.x_values[-1] + dx / 2,
                m.y_values[0] - dy / 2,
                m.y_values[-1] + dy / 2,
            ),
            aspect="auto",
            cmap=cmap,
            vmin=-0.5,
            vmax=len(labels) - 0.5,
            interpolation="nearest",
        )
        if m.ambiguous.any():
            ax.contourf(
                m.x_values,
                m.y_values,
                m.ambiguous.astype(float),
                levels=[0.5, 1.5],
                colors="none",
                hatches=["////"],
            )
        for number, point in enumerate(points[panel] if panel < len(points) else ()):
            name, x, y = point[:3]
            label = point[3] if len(point) > 3 else m.label_at(x, y)
            ax.plot(x, y, marker="o", color="black", markersize=6, markerfacecolor="white")
            # labels stay in the panel (to the left of a point in its right half) and apart
            # (every other one below its point)
            right = x > 0.5 * (m.x_values[0] + m.x_values[-1])
            below = number % 2 == 1
            ax.annotate(
                f"{name}:\n{label}",
                (x, y),
                textcoords="offset points",
                xytext=(-6 if right else 6, -6 if below else 6),
                ha="right" if right else "left",
                va="top" if below else "bottom",
                fontsize=7,
                bbox={"boxstyle": "round,pad=0.15", "facecolor": "white", "alpha": 0.7,
                      "linewidth": 0},
            )  # fmt: skip
        sense = "+" if m.sense > 0 else "-"
        ax.set_title(f"{m.configuration}, {m.excitation}, sense {sense}", fontsize=10)
        ax.set_xlabel(m.x.title)
        if panel == 0:
            ax.set_ylabel(m.y.title)
    handles = [Patch(facecolor=colours[label], edgecolor="black", label=label) for label in labels]
    if any(m.ambiguous.any() for m in maps):
        handles.append(
            Patch(
                facecolor="white",
                edgecolor="black",
                hatch="////",
                label="ambiguous (rule's choice)",
            )
        )
    figure.legend(
        handles=handles, loc="lower center", ncol=min(3, len(handles)), fontsize=8, frameon=False
    )
    if title:
        figure.suptitle(title)
    rows = (len(handles) + 2) // 3
    figure.tight_layout(rect=(0, 0.05 + 0.035 * rows, 1, 1))
    return figure


def plot_mode_maps(
    maps: Sequence[ModeMap],
    path: str | Path,
    points: Sequence[Sequence[tuple[str, float, float]]] = (),
    title: str | None = None,
) -> Path:
    """Draw mode maps side by side (:func:`mode_map_figure`) and save the figure.

    Parameters
    ----------
    maps, points, title
        As for :func:`mode_map_figure`.
    path : str or pathlib.Path
        Output file (the format follows the suffix: .png, .pdf, .svg).

    Returns
    -------
    pathlib.Path
        The file written.
    """
    path = Path(path)
    mode_map_figure(maps, points, title).savefig(path, dpi=120)
    return path
