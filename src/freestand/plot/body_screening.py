"""The polar figure of a 3-D body's screening: uplift threshold and initial motion by direction.

One polar panel per 3-D configuration and vertical acceleration a_v (the
threshold depends on a_v, not on the horizontal magnitude). The angle is the
direction phi of the horizontal support acceleration, from +x towards +y; the
radius an acceleration [m/s^2]. In each panel:

- the uplift threshold a*(phi) as a closed curve (the body stays seated
  inside it), with the base plan view drawn faintly at the centre;
- the slide threshold mu_0 (g - a_v) as a dashed circle (the same in every
  direction: the friction cone is circular);
- each excitation as a circle of its magnitude sqrt(x^2 + y^2), with a
  marker per swept direction coloured by the initial motion there, and a
  star in the excitation's own direction.

The legend sits outside the axes, on the right.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from freestand.core.body import Body, Box
from freestand.core.contact.body_screening import BodyScreeningCase, threshold_curve

#: Marker colour of each initial motion.
MOTION_COLOURS = {
    "rest": "#bdbdbd",
    "slide": "#2c7bb6",
    "rock": "#d7191c",
    "slide-rock": "#7b3294",
    "free-flight": "#000000",
}


def shape_text(body: Body) -> str:
    """``"box 0.80 x 0.60 x 2.00 m"`` or ``"cylinder R 1.20 m, H 5.00 m"`` (``r`` when hollow)."""
    shape = body.shape
    if isinstance(shape, Box):
        return "box " + " x ".join(f"{side:.2f}" for side in shape.size) + " m"
    hollow = f", r {shape.inner_radius:.2f}" if shape.inner_radius else ""
    return f"cylinder R {shape.radius:.2f}{hollow} m, H {shape.height:.2f} m"


#: The legend's entry of the star.
OWN_LABEL = "excitation's own direction\n(coloured by its motion)"

#: Width and height of a panel [in].
PANEL_SIZE = 4.4

#: What the polar coordinates are.
LEGEND_TITLE = "angle: direction of the\nsupport acceleration;\nradius: acceleration [m/s²]"


def _legend_entries(axes) -> tuple[list, list[str]]:
    """The legend's handles and labels of all ``axes``, each once: curves, motions, the star."""
    found: dict[str, object] = {}
    for panel in axes:
        for handle, label in zip(*panel.get_legend_handles_labels(), strict=True):
            found.setdefault(label, handle)
    order = [label for label in found if label not in MOTION_COLOURS and label != OWN_LABEL]
    order += [motion for motion in MOTION_COLOURS if motion in found]
    stars = [label for label in found if label == OWN_LABEL]
    if stars:  # a white star: its colour in the panels is the motion there
        from matplotlib.lines import Line2D

        found[stars[0]] = Line2D([], [], ls="none", marker="*", markersize=12,
                                 markerfacecolor="white", markeredgecolor="black")  # fmt: skip
    return [found[label] for label in order + stars], order + stars


def _groups(cases: Sequence[BodyScreeningCase]) -> list[list[BodyScreeningCase]]:
    """Cases by configuration and vertical acceleration, in their order."""
    groups: dict[tuple[str, float], list[BodyScreeningCase]] = {}
    for case in cases:
        groups.setdefault((case.configuration, case.vertical), []).append(case)
    return list(groups.values())


def _panel(ax, group: list[BodyScreeningCase], body: Body, seen: set[str]) -> None:
    """Draw one configuration at one a_v into the polar axes ``ax``."""
    first = group[0]
    phi, threshold = threshold_curve(body, first.vertical, first.gravity)
    slide = first.directions[0].slide_threshold
    ax.fill(phi, threshold, color="#f0f0f0", zorder=0)
    ax.plot(phi, threshold, color="#252525", lw=1.8, zorder=2,
            label=r"uplift threshold $a^*(\varphi)$")  # fmt: skip
    circle = np.linspace(0.0, 2.0 * math.pi, 361)
    ax.plot(circle, np.full_like(circle, slide), color="#2c7bb6", lw=1.2, ls="--", zorder=2,
            label=r"slide threshold $\mu_0\,(g - a_v)$")  # fmt: skip
    radius = max(float(threshold.max()), slide)
    for case in group:
        radius = max(radius, case.horizontal)
        ax.plot(circle, np.full_like(circle, case.horizontal), color="#737373", lw=0.7, ls=":",
                zorder=3)  # fmt: skip
        for state in case.directions:
            motion = state.motion.value
            ax.scatter([state.direction], [case.horizontal], s=34, zorder=4,
                       color=MOTION_COLOURS[motion], edgecolors="black", linewidths=0.4,
                       label=motion if motion not in seen else None)  # fmt: skip
            seen.add(motion)
        own = case.at_excitation.motion.value
        if own not in seen:  # a motion met only in the excitation's own direction
            ax.scatter([], [], s=34, color=MOTION_COLOURS[own], edgecolors="black",
                       linewidths=0.4, label=own)  # fmt: skip
            seen.add(own)
        ax.scatter([case.excitation_direction], [case.horizontal], marker="*", s=190, zorder=5,
                   color=MOTION_COLOURS[own], edgecolors="black", linewidths=0.8,
                   label=None if "own" in seen else OWN_LABEL)  # fmt: skip
        seen.add("own")
        ax.annotate(
            f"{case.excitation}\n{case.horizontal:.2f} m/s²",
            (case.excitation_direction, case.horizontal), xytext=(9, 7),
            textcoords="offset points", fontsize=8.5, zorder=1,
            bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none", "alpha": 0.7},
        )  # fmt: skip
    ax.set_rlim(0.0, 1.12 * radius if radius > 0 else 1.0)
    ax.set_thetagrids(range(0, 360, 45), ["0° (+x)", "45°", "90° (+y)", "135°", "180° (-x)",
                                          "225°", "270° (-y)", "315°"], fontsize=8.5)  # fmt: skip
    ax.tick_params(axis="y", labelsize=8)
    ax.set_rlabel_position(100.0)
    ax.set_title(
        f"{first.configuration}: {shape_text(body)}\n$a_v$ = {first.vertical:.2f} m/s² "
        f"(downward), $\\mu_0$ = {body.friction.static:g}",
        fontsize=9.5,
        pad=12,
    )


def uplift_polar_figure(
    cases: Sequence[BodyScreeningCase], bodies: dict[str, Body], ax=None, title: str | None = None
):
    """The polar figure of the 3-D screening (module docstring).

    Parameters
    ----------
    cases : sequence of BodyScreeningCase
        The screening cases (any configurations and excitations).
    bodies : dict of str to Body
        The body of each configuration, by configuration name.
    ax : matplotlib polar Axes, optional
        Draw into these axes (one configuration and a_v only).
    title : str, optional
        Figure title (with several panels).

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.figure import Figure

    groups = _groups(cases)
    if not groups:
        raise ValueError("no 3-D screening case to draw")
    if ax is not None and len(groups) > 1:
        raise ValueError(
            f"{len(groups)} panels (configurations x vertical accelerations) to draw; pass "
            "ax=None, or select one configuration and excitation"
        )
    seen: set[str] = set()
    if ax is not None:
        _panel(ax, groups[0], bodies[groups[0][0].configuration], seen)
        handles, labels = _legend_entries([ax])
        ax.legend(handles, labels, loc="upper left", bbox_to_anchor=(1.12, 1.0), fontsize=8,
                  frameon=False, title=LEGEND_TITLE, title_fontsize=8)  # fmt: skip
        return ax.figure
    columns = min(len(groups), 2)
    rows = math.ceil(len(groups) / columns)
    height = PANEL_SIZE * rows + 1.2 + (0.3 if title else 0.0)
    figure = Figure(figsize=(PANEL_SIZE * columns + 0.6, height), layout="constrained")
    for k, group in enumerate(groups):
        panel = figure.add_subplot(rows, columns, k + 1, projection="polar")
        _panel(panel, group, bodies[group[0].configuration], seen)
    handles, labels = _legend_entries(figure.axes)
    figure.legend(handles, labels, loc="outside lower center", ncols=3, fontsize=9,
                  frameon=False, title=LEGEND_TITLE.replace("\n", " "),
                  title_fontsize=9)  # fmt: skip
    if title:
        figure.suptitle(title, fontsize=10)
    return figure
