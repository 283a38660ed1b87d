"""Figures and animation of a 3-D body's time history (:mod:`freestand.api.body_simulation`).

- :func:`time_history_figure`: panels sharing the time axis (support
  accelerations, the motion as a coloured band, tilt, slide, twist, contact
  forces) with the events marked and the verdict under the title;
- :func:`plan_view_figure`: seen from above, the path of the base centre and
  the tilt vector (the rosette of a wobbling body), coloured by time;
- :func:`animate_body`: an animated GIF of the body in a projected 3-D view
  (the machinery of the planar animation,
  :func:`freestand.plot.timehistory.write_gif`).

Each takes a :class:`~freestand.api.body_simulation.BodySimulationResult`
and draws on new figures (Agg-safe: no window is opened).
"""

from __future__ import annotations

import math
import textwrap
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from freestand.core.body import Box, tipping_tilt
from freestand.core.dynamics.body_history import rotation_matrices
from freestand.plot.body_screening import MOTION_COLOURS as SCREENING_COLOURS
from freestand.plot.body_screening import shape_text
from freestand.plot.timehistory import (
    ROCKING_EVENTS,
    SLIDING_EVENTS,
    _legend,
    _scale,
    animation_target,
    frame_indices,
    write_gif,
)

#: Colour of each motion of a 3-D body (those of the screening's polar figure, rocking in reds).
MOTION_COLOURS = {
    "rest": SCREENING_COLOURS["rest"],
    "slide": SCREENING_COLOURS["slide"],
    "rock-edge": SCREENING_COLOURS["rock"],
    "rock-corner": "#f46d43",
    "roll": "#f46d43",
    "slide-rock": SCREENING_COLOURS["slide-rock"],
    "free-flight": SCREENING_COLOURS["free-flight"],
}

#: Events marked on the tilt panel beside lift-offs and impacts: marker, label.
REMEDY_EVENTS = {"remedy": ("x", "no lasting contact mode\n(continued by time stepping)")}

#: Colours of the x, y and magnitude curves.
X_COLOUR, Y_COLOUR, SIZE_COLOUR = "#1b9e77", "#d95f02", "k"


def verdict(result) -> str:
    """The verdict in words: the largest tilt, slide and twist; uplift, free flight, overturning;
    the status when not completed."""
    core = result.core
    overturned = f"at {core.overturn_time:.3f} s" if core.overturned else "no"
    lines = [
        f"largest tilt {core.max_rotation:.3g} rad, slide {1000.0 * core.max_slide:.1f} mm, "
        f"twist {1000.0 * core.max_twist:.1f} mrad",
        f"uplift: {_yes(core.uplift)}; free flight: {_yes(core.free_flight)}; "
        f"overturned: {overturned}",
    ]
    if result.status != "completed":
        lines += textwrap.wrap(f"simulation {result.status}: {result.message}", 90)
    return "\n".join(lines)


def _yes(flag: bool) -> str:
    return "yes" if flag else "no"


def _at_least(ax, values: np.ndarray, floor: float) -> None:
    """A y range of at least +-``floor`` (1 mm or 1 mrad: round-off must not look like
    motion)."""
    if float(np.max(np.abs(values), initial=0.0)) < floor:
        ax.set_ylim(-floor, floor)


def _mark(ax, result, values: np.ndarray, kinds: dict, factor: float) -> None:
    """Events of ``kinds`` as markers on the curve ``values`` (one entry each in the legend)."""
    time = result.core.time
    for kind, (marker, label) in kinds.items():
        times = [event.time for event in result.events if event.kind == kind]
        if not times:
            continue
        rows = np.clip(np.searchsorted(time, times, side="left"), 0, time.size - 1)
        ax.plot(
            times, factor * values[rows], linestyle="none", marker=marker, markersize=5,
            color="0.25", markerfacecolor="none" if marker == "o" else "0.25", label=label,
            gid=f"event:{kind}",
        )  # fmt: skip


def _motion_band(ax, result) -> None:
    """The motion over time as coloured spans, one legend entry per motion met."""
    time = result.core.time
    motions = result.motions
    changes = np.flatnonzero(motions[1:] != motions[:-1]) + 1
    starts = np.concatenate([[0], changes])
    ends = np.concatenate([changes, [time.size - 1]])
    for start, end in zip(starts, ends, strict=True):
        motion = str(motions[start])
        ax.axvspan(time[start], time[end], color=MOTION_COLOURS[motion], linewidth=0,
                   gid=f"motion:{motion}")  # fmt: skip
    for motion, colour in MOTION_COLOURS.items():  # the legend in a fixed order
        if motion in motions:
            ax.fill_between([], [], color=colour, label=motion)
    ax.set_yticks([])
    ax.set_ylabel("motion")
    _legend(ax)


def time_history_figure(result) -> Figure:
    """Panels sharing the time axis (module docstring).

    From the top: the support accelerations ``a_x``, ``a_y`` and the downward
    ``a_v`` [m/s^2]; the motion (rest, slide, rock-edge, rock-corner, roll,
    slide-rock, free-flight) as a coloured band; the tilt (angle of the body's
    axis from the vertical) [mrad, or rad from 0.1 rad] with lift-offs and
    impacts; the slide of the base centre, its magnitude and x, y components
    [mm, or m from 1 m], with slips and slip-stops; the twist about the
    vertical [mrad or rad]; the normal force N and the friction (on the limit
    surface's scale) [kN]. An overturning is a red vertical line on every
    panel.

    Parameters
    ----------
    result : BodySimulationResult
        The simulation.

    Returns
    -------
    matplotlib.figure.Figure
    """
    core = result.core
    time = core.time
    figure = Figure(figsize=(9.0, 12.0), layout="constrained")
    axes = figure.subplots(6, 1, sharex=True, height_ratios=(1.0, 0.35, 1.0, 1.0, 1.0, 1.0))
    for ax in axes:
        ax.grid(True, alpha=0.3)
    support = result.support
    last = min(support.x.size, int(np.ceil(time[-1] / support.time_step)) + 2)
    samples = np.arange(last) * support.time_step
    ax = axes[0]
    for values, colour, label, gid in (
        (support.x, X_COLOUR, "a_x", "support:x"),
        (support.y, Y_COLOUR, "a_y", "support:y"),
        (support.vertical, "0.5", "a_v (downward)", "support:vertical"),
    ):
        ax.plot(samples, values[:last], color=colour, linewidth=0.8, label=label, gid=gid)
    ax.set_ylabel("support accel.\n[m/s^2]")
    _legend(ax)
    _motion_band(axes[1], result)

    factor, unit = _scale(core.tilt, 0.1, ("mrad", "rad"))
    axes[2].plot(time, factor * core.tilt, color=SIZE_COLOUR, linewidth=1.0, label="tilt",
                 gid="tilt")  # fmt: skip
    _mark(axes[2], result, core.tilt, ROCKING_EVENTS | REMEDY_EVENTS, factor)
    _at_least(axes[2], factor * core.tilt, 1e-3 * factor)
    axes[2].set_ylabel(f"tilt of the axis\n[{unit}]")
    _legend(axes[2])

    size = np.hypot(core.slide[:, 0], core.slide[:, 1])
    factor, unit = _scale(size, 1.0, ("mm", "m"))
    ax = axes[3]
    ax.plot(time, factor * size, color=SIZE_COLOUR, linewidth=1.0, label="|slide|", gid="slide")
    ax.plot(time, factor * core.slide[:, 0], color=X_COLOUR, linewidth=0.8, label="x",
            gid="slide:x")  # fmt: skip
    ax.plot(time, factor * core.slide[:, 1], color=Y_COLOUR, linewidth=0.8, label="y",
            gid="slide:y")  # fmt: skip
    _mark(ax, result, size, SLIDING_EVENTS, factor)
    _at_least(ax, factor * size, 1e-3 * factor)
    ax.set_ylabel(f"slide of the\nbase centre [{unit}]")
    _legend(ax)

    factor, unit = _scale(core.twist, 0.1, ("mrad", "rad"))
    axes[4].plot(time, factor * core.twist, color=SIZE_COLOUR, linewidth=1.0, label="twist",
                 gid="twist")  # fmt: skip
    _at_least(axes[4], factor * core.twist, 1e-3 * factor)
    axes[4].set_ylabel(f"twist about\nthe vertical [{unit}]")
    _legend(axes[4])

    ax = axes[5]
    ax.plot(time, core.normal_force / 1000.0, color=SIZE_COLOUR, linewidth=1.0, label="N",
            gid="normal")  # fmt: skip
    ax.plot(time, core.friction_force / 1000.0, color="0.45", linestyle=":", linewidth=1.0,
            label="friction", gid="friction")  # fmt: skip
    ax.set_ylabel("forces on the\nbody [kN]")
    _legend(ax)

    if core.overturned:
        instant = float(core.overturn_time)
        for index, ax in enumerate(axes):
            ax.axvline(
                instant, color="red", linewidth=1.5, linestyle="-.",
                label=f"overturns, {instant:.3f} s" if index == 0 else None, gid="overturn",
            )  # fmt: skip
        _legend(axes[0])
    axes[-1].set_xlabel("time t [s]")
    span = float(time[-1] - time[0])
    # an overturning ends the history: a margin shows its line
    axes[-1].set_xlim(float(time[0]), float(time[-1]) + (0.02 * span if core.overturned else 0.0))
    figure.suptitle(
        f"{result.title}\n{shape_text(result.body_configuration.body)}\n{verdict(result)}",
        fontsize="medium",
    )
    return figure


def _path(ax, x: np.ndarray, y: np.ndarray, time: np.ndarray, gid: str):
    """A line coloured by time, with its start (circle) and end (square)."""
    from matplotlib.collections import LineCollection

    points = np.column_stack([x, y])
    lines = LineCollection(
        np.stack([points[:-1], points[1:]], axis=1), cmap="viridis", linewidths=1.4, gid=gid
    )
    lines.set_array(0.5 * (time[:-1] + time[1:]))
    lines.set_clim(float(time[0]), float(time[-1]))
    ax.add_collection(lines)
    ax.plot([x[0]], [y[0]], "o", color="k", markerfacecolor="white", label="start",
            gid=f"{gid}:start")  # fmt: skip
    ax.plot([x[-1]], [y[-1]], "s", color="k", label="end", gid=f"{gid}:end")
    return lines


def _square_limits(ax, x: np.ndarray, y: np.ndarray, floor: float) -> None:
    """Equal, centred limits around the data, at least ``floor`` on each side."""
    half = max(float(np.max(np.abs(x))), float(np.max(np.abs(y))), floor) * 1.15
    ax.set_xlim(-half, half)
    ax.set_ylim(-half, half)
    ax.set_aspect("equal")
    ax.axhline(0.0, color="0.6", linewidth=0.6)
    ax.axvline(0.0, color="0.6", linewidth=0.6)


def plan_view_figure(result) -> Figure:
    """The body seen from above (module docstring): base-centre path and tilt rosette.

    Left: the horizontal displacement of the base centre [mm, or m from 1 m]
    from its start. Right: the tilt vector, the tilt angle along the
    horizontal projection of the body's axis [mrad, or rad from 0.1 rad]: a
    body rocking in a plane draws a line, a wobbling cylinder a rosette.
    Both are coloured by time (the colour bar), with the start and the end
    marked. The dashed curve on the right, where it fits, is the tilt at
    which the centre of gravity stands over the pivot
    (:func:`freestand.core.body.tipping_tilt`, the body untwisted).

    Parameters
    ----------
    result : BodySimulationResult
        The simulation.

    Returns
    -------
    matplotlib.figure.Figure
    """
    core = result.core
    time = core.time
    figure = Figure(figsize=(10.0, 5.4), layout="constrained")
    slide_ax, tilt_ax = figure.subplots(1, 2)
    size = np.hypot(core.slide[:, 0], core.slide[:, 1])
    factor, unit = _scale(size, 1.0, ("mm", "m"))
    lines = _path(slide_ax, factor * core.slide[:, 0], factor * core.slide[:, 1], time, "slide")
    _square_limits(slide_ax, factor * core.slide[:, 0], factor * core.slide[:, 1], 1e-3 * factor)
    slide_ax.set_xlabel(f"x [{unit}]")
    slide_ax.set_ylabel(f"y [{unit}]")
    slide_ax.set_title(f"path of the base centre\n(largest slide {factor * size.max():.3g} {unit})",
                       fontsize="medium")  # fmt: skip
    if size.max() == 0.0:
        slide_ax.text(0.5, 0.35, "no slide", transform=slide_ax.transAxes, ha="center")

    tilt = result.tilt_vector
    factor, unit = _scale(core.tilt, 0.1, ("mrad", "rad"))
    _path(tilt_ax, factor * tilt[:, 0], factor * tilt[:, 1], time, "tilt")
    _square_limits(tilt_ax, factor * tilt[:, 0], factor * tilt[:, 1], 1e-3 * factor)
    psi = np.linspace(0.0, 2.0 * math.pi, 721)
    tipping = factor * tipping_tilt(result.body_configuration.body, psi)
    if tipping.min() <= 1.5 * tilt_ax.get_xlim()[1]:
        tilt_ax.plot(tipping * np.cos(psi), tipping * np.sin(psi), color="red", linestyle="--",
                     linewidth=1.0, label="G over the pivot", gid="tipping")  # fmt: skip
        half = max(tilt_ax.get_xlim()[1], 1.1 * float(tipping.max()))
        tilt_ax.set_xlim(-half, half)
        tilt_ax.set_ylim(-half, half)
    tilt_ax.set_xlabel(f"tilt towards x [{unit}]")
    tilt_ax.set_ylabel(f"tilt towards y [{unit}]")
    tilt_ax.set_title(
        f"tilt vector (the axis's lean, seen from above)\n(largest tilt "
        f"{factor * core.tilt.max():.3g} {unit}; G over the pivot from "
        f"{tipping.min():.3g} {unit})",
        fontsize="medium",
    )
    if core.tilt.max() == 0.0:
        tilt_ax.text(0.5, 0.35, "no tilt: the base stayed flat", transform=tilt_ax.transAxes,
                     ha="center")  # fmt: skip
    handles, labels = tilt_ax.get_legend_handles_labels()
    figure.legend(handles, labels, loc="outside lower center", ncols=3, fontsize="small",
                  frameon=False)  # fmt: skip
    figure.colorbar(lines, ax=[slide_ax, tilt_ax], label="time t [s]", shrink=0.8)
    figure.suptitle(f"{result.title}: seen from above\n{verdict(result)}", fontsize="medium")
    return figure


# --- the animation ------------------------------------------------------------------------------

#: Direction of the view: azimuth and elevation [deg] of the eye, seen from the body.
VIEW_AZIMUTH, VIEW_ELEVATION = -60.0, 22.0

#: Sides of the polygon drawing a cylinder.
CYLINDER_SIDES = 36


def _view() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Unit vectors (right, up, towards the eye) of the orthographic view."""
    az, el = math.radians(VIEW_AZIMUTH), math.radians(VIEW_ELEVATION)
    eye = np.array([math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el)])
    right = np.array([-math.sin(az), math.cos(az), 0.0])
    return right, np.cross(eye, right), eye


def _solid(body) -> tuple[np.ndarray, list[np.ndarray], np.ndarray]:
    """The body's vertices (V, 3) in its frame, faces (vertex indices) and outward normals."""
    shape = body.shape
    if isinstance(shape, Box):
        bx, by, lz = 0.5 * shape.size[0], 0.5 * shape.size[1], shape.size[2]
        base = np.array([[bx, by], [-bx, by], [-bx, -by], [bx, -by]])
        sides = 4
    else:
        angles = np.linspace(0.0, 2.0 * math.pi, CYLINDER_SIDES, endpoint=False)
        base = shape.radius * np.column_stack([np.cos(angles), np.sin(angles)])
        lz, sides = shape.height, CYLINDER_SIDES
    vertices = np.vstack([np.column_stack([base, np.zeros(sides)]),
                          np.column_stack([base, np.full(sides, lz)])])  # fmt: skip
    faces = [np.arange(sides)[::-1], np.arange(sides, 2 * sides)]
    normals = [np.array([0.0, 0.0, -1.0]), np.array([0.0, 0.0, 1.0])]
    for k in range(sides):
        nxt = (k + 1) % sides
        faces.append(np.array([k, nxt, sides + nxt, sides + k]))
        middle = 0.5 * (base[k] + base[nxt])
        normals.append(np.array([*(middle / np.linalg.norm(middle)), 0.0]))
    return vertices, faces, np.array(normals)


def _turn(axis: np.ndarray, angle: float) -> np.ndarray:
    """Rotation matrix of ``angle`` [rad] about the unit ``axis`` (Rodrigues)."""
    k = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]], [-axis[1], axis[0], 0.0]])
    return np.eye(3) + math.sin(angle) * k + (1.0 - math.cos(angle)) * k @ k


def drawn_poses(result, rows: np.ndarray, exaggeration: float, vertices: np.ndarray):
    """(rotations (F, 3, 3), base centres (F, 3)) drawn at the recorded ``rows``.

    With ``exaggeration`` k != 1 the tilt (the swing of the axis from the
    vertical) is drawn k times larger about the same horizontal axis, the
    twist true, and the body turned about its lowest base point, which stays
    where it is (a rocking body keeps its pivot on the support).
    """
    core = result.core
    body = result.body_configuration.body
    rotation = rotation_matrices(core.state[rows, 3:7])
    base = core.state[rows, 0:3] - rotation @ np.asarray(body.centre)
    if exaggeration == 1.0:
        return rotation, base
    floor = vertices[: len(vertices) // 2]
    for k in range(len(rows)):
        axis = rotation[k][:, 2]
        tilt = math.acos(min(1.0, max(-1.0, axis[2])))
        if tilt == 0.0:
            continue
        hinge = np.cross([0.0, 0.0, 1.0], axis)
        hinge /= np.linalg.norm(hinge)
        swing = _turn(hinge, (exaggeration - 1.0) * tilt)
        lowest = floor[np.argmin((rotation[k] @ floor.T)[2])]
        pivot = base[k] + rotation[k] @ lowest
        rotation[k] = swing @ rotation[k]
        base[k] = pivot - rotation[k] @ lowest
    return rotation, base


def animate_body(
    result,
    path: str | Path,
    *,
    fps: float = 20.0,
    max_frames: int = 300,
    exaggeration: float = 1.0,
    dpi: int = 80,
) -> Path:
    """Write an animated GIF of the body moving on the support, in a projected 3-D view.

    An orthographic view from azimuth :data:`VIEW_AZIMUTH` and elevation
    :data:`VIEW_ELEVATION` of the support's frame (the support is the fixed
    grey plate z = 0, with the axes x and y): the box or the
    cylinder (a prism of :data:`CYLINDER_SIDES` sides) at its recorded
    poses, its faces shaded by their orientation, the path of its base
    centre drawn on the support as it grows, the horizontal support
    acceleration as a red arrow on the plate (its peak a quarter of the
    plate), and in text the time, the support accelerations, the motion
    after the last event and the tilt, slide and twist. Axis limits are fixed
    over the animation; an overturned body is drawn red from then on.

    Parameters
    ----------
    result : BodySimulationResult
        The simulation.
    path : str or pathlib.Path
        The GIF to write (missing folders are created).
    fps : float, optional
        Frames per second [1/s] of the GIF and of simulated time.
    max_frames : int, optional
        Largest number of frames (:func:`freestand.plot.timehistory.frame_indices`).
    exaggeration : float, optional
        Factor [-] on the tilt, drawn about the lowest base point
        (:func:`drawn_poses`), written on every frame when not 1.
    dpi : int, optional
        Resolution [dots per inch] of the 6.4 x 5.6 inch frames.

    Returns
    -------
    pathlib.Path
        The file written.
    """
    from matplotlib.patches import Polygon

    target = animation_target(path, fps, max_frames, exaggeration)
    core = result.core
    body = result.body_configuration.body
    instants, rows = frame_indices(core.time, fps, max_frames)
    vertices, faces, normals = _solid(body)
    box = isinstance(body.shape, Box)
    rotation, base = drawn_poses(result, rows, exaggeration, vertices)
    right, up, eye = _view()
    screen = np.stack([right, up])

    world = base[:, None, :] + np.einsum("fij,vj->fvi", rotation, vertices)
    reach = max(float(np.max(np.abs(world[:, :, :2]))), 0.6 * float(np.max(vertices[:, 2])))
    plate = 1.15 * reach
    corners = np.array([[plate, plate, 0.0], [-plate, plate, 0.0], [-plate, -plate, 0.0],
                        [plate, -plate, 0.0]])  # fmt: skip
    seen = np.concatenate([world.reshape(-1, 3), corners]) @ screen.T
    low, high = seen.min(axis=0), seen.max(axis=0)
    pad = 0.05 * float(max(high - low))
    text_room = 0.22 * float(high[1] - low[1])

    figure = Figure(figsize=(6.4, 5.6), layout="constrained")
    ax = figure.add_subplot()
    ax.set_aspect("equal")
    ax.set_xlim(low[0] - pad, high[0] + pad)
    ax.set_ylim(low[1] - pad, high[1] + pad + text_room)
    ax.set_axis_off()
    ax.set_title(f"{result.title}\n{shape_text(body)}", fontsize="medium")
    ax.add_patch(Polygon(corners @ screen.T, closed=True, facecolor="0.88", edgecolor="0.5"))
    for k in np.linspace(-plate, plate, 9):
        for line in (np.array([[k, -plate, 0.0], [k, plate, 0.0]]),
                     np.array([[-plate, k, 0.0], [plate, k, 0.0]])):  # fmt: skip
            ax.plot(*(line @ screen.T).T, color="0.78", linewidth=0.5)
    for axis, label in ((np.array([1.0, 0.0, 0.0]), "x"), (np.array([0.0, 1.0, 0.0]), "y")):
        tip = (plate * axis) @ screen.T
        ax.plot(*np.array([[0.0, 0.0], tip]).T, color="0.35", linewidth=0.8)
        ax.text(*tip, f" {label}", color="0.25", fontsize="small")

    (trail,) = ax.plot([], [], color="#2c7bb6", linewidth=1.2)
    faces_drawn = [Polygon(np.zeros((len(face), 2)), closed=True, edgecolor="k", linewidth=0.4)
                   for face in faces]  # fmt: skip
    for patch in faces_drawn:
        ax.add_patch(patch)
    (arrow,) = ax.plot([], [], color="darkred", linewidth=3.0, solid_capstyle="butt")
    (arrow_head,) = ax.plot([], [], color="darkred", marker="o", markersize=5, linestyle="none")
    peak = result.peak_horizontal
    arrow_from = np.array([0.0, -plate, 0.0])
    clock = ax.text(0.01, 0.99, "", transform=ax.transAxes, va="top", family="monospace",
                    fontsize="small")  # fmt: skip
    state = ax.text(0.01, 0.92, "", transform=ax.transAxes, va="top", family="monospace",
                    fontsize="small", fontweight="bold")  # fmt: skip
    if exaggeration != 1.0:
        ax.text(0.99, 0.01, f"tilt drawn x{exaggeration:g}", transform=ax.transAxes, ha="right",
                va="bottom", color="darkred", fontweight="bold",
                bbox={"facecolor": "white", "edgecolor": "darkred"})  # fmt: skip
    light = np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8])
    events = result.events
    event_times = np.array([event.time for event in events])
    slide = core.slide
    support = result.support.at(instants).T
    moving = [trail, *faces_drawn, arrow, arrow_head, clock, state]

    def draw_frame(frame: int) -> None:
        instant = instants[frame]
        row = rows[frame]
        over = core.overturned and instant >= core.overturn_time
        outward = normals @ rotation[frame].T
        points = world[frame] @ screen.T
        # a convex body: the faces turned to the eye never hide one another
        for index, (patch, face, normal) in enumerate(zip(faces_drawn, faces, outward,
                                                          strict=True)):  # fmt: skip
            patch.set_visible(bool(normal @ eye > 1e-9))
            patch.set_xy(points[face])
            shade = 0.45 + 0.55 * max(0.0, float(normal @ light))
            colour = (0.85, 0.2, 0.2) if over else (0.35 * shade, 0.55 * shade, 0.85 * shade)
            patch.set_facecolor(colour)
            # a cylinder's sides without seams: only its caps and a box's faces are outlined
            patch.set_edgecolor("k" if index < 2 or box else colour)
        start = base[0, :2] - slide[0]
        path = np.column_stack([start + slide[: row + 1], np.zeros(row + 1)])
        trail.set_data(*(path @ screen.T).T)
        a_x, a_y, a_v = support[frame]
        if peak > 0.0 and math.hypot(a_x, a_y) > 1e-3 * peak:
            tip = arrow_from + 0.25 * 2.0 * plate * np.array([a_x, a_y, 0.0]) / peak
            line = np.array([arrow_from, tip]) @ screen.T
            arrow.set_data(*line.T)
            arrow_head.set_data([line[1, 0]], [line[1, 1]])
        else:
            arrow.set_data([], [])
            arrow_head.set_data([], [])
        clock.set_text(
            f"t = {instant:7.3f} s  a_x = {a_x:+6.2f}  a_y = {a_y:+6.2f}  a_v = {a_v:+6.2f} m/s^2"
        )
        latest = int(np.searchsorted(event_times, instant, side="right")) - 1
        if over:
            motion = f"overturned at {core.overturn_time:.3f} s"
        else:
            motion = events[latest].motion if latest >= 0 else "rest"
        state.set_text(
            f"{body.name}: {motion}\ntilt {1000.0 * core.tilt[row]:7.1f} mrad   slide "
            f"{1000.0 * math.hypot(*slide[row]):7.1f} mm   twist {1000.0 * core.twist[row]:+7.1f} "
            "mrad"
        )

    return write_gif(figure, moving, len(instants), draw_frame, target, fps=fps, dpi=dpi)
