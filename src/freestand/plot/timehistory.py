"""Figures and animation of a time-history simulation (:mod:`freestand.core.dynamics.timehistory`).

:func:`plot_time_history` draws stacked panels sharing the time axis (support
acceleration, slides, rocking angles, contact forces) with the events marked;
:func:`animate_time_history` writes an animated GIF of the blocks moving.
Both take a :class:`~freestand.core.dynamics.timehistory.TimeHistoryResult` and draw on
new figures (Agg-safe: no window is opened).
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from freestand.core.dynamics.timehistory import SupportMotion, TimeHistoryResult
from freestand.core.geometry import block_outlines, place, stack_poses
from freestand.core.model import Stack

#: Event kinds marked on the rotation panel (rocking) and on the slide panel
#: (sliding): marker, label. Overturning is a vertical line on every panel.
ROCKING_EVENTS = {
    "lift-off": ("^", "lift-off"),
    "impact": ("v", "impact (contact closes)"),
}
SLIDING_EVENTS = {
    "slip": (">", "slip starts"),
    "slip-stop": ("o", "slip stops"),
    "stop-impact": ("X", "hits end stop"),
    "tangential-impact": ("D", "tangential impact"),
}

#: How long the last frame of an animation stays [ms] before it loops.
HOLD_LAST_FRAME = 1500


def _colour(index: int) -> str:
    return f"C{index % 10}"


def _scale(values: np.ndarray, small: float, units: tuple[str, str]) -> tuple[float, str]:
    """(factor, unit): the small unit (factor 1000) when every |value| is below ``small``."""
    finite = np.abs(values[np.isfinite(values)])
    peak = float(finite.max()) if finite.size else 0.0
    return (1000.0, units[0]) if peak < small else (1.0, units[1])


def support_samples(
    support_motion: SupportMotion, end_time: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """Samples of the support motion up to ``end_time`` [s] (and one past it).

    Returns
    -------
    tuple
        time [s], horizontal a_h [m/s^2], downward vertical a_v [m/s^2] or None.
    """
    count = support_motion.horizontal.size
    last = min(count, int(np.ceil(end_time / support_motion.time_step)) + 2)
    time = np.arange(last) * support_motion.time_step
    vertical = None if support_motion.vertical is None else support_motion.vertical[:last]
    return time, support_motion.horizontal[:last], vertical


def _value_at(time: np.ndarray, values: np.ndarray, instant: float) -> float:
    """The recorded value just before ``instant`` (events are two rows at one time)."""
    index = int(np.clip(np.searchsorted(time, instant, side="left"), 0, time.size - 1))
    return float(values[index])


def _mark_events(ax, result: TimeHistoryResult, trace: np.ndarray, kinds: dict, factor: float):
    for kind, (marker, label) in kinds.items():
        events = result.events_of(kind)
        if not events:
            continue
        for block in range(len(result.block_names)):
            times = [e.time for e in events if e.interface == block]
            if not times:
                continue
            values = [factor * _value_at(result.time, trace[:, block], t) for t in times]
            ax.plot(
                times, values, linestyle="none", marker=marker, markersize=5,
                markerfacecolor="none" if marker == "o" else _colour(block),
                markeredgecolor=_colour(block), gid=f"event:{kind}:{block}",
            )  # fmt: skip
        # one legend entry per kind, in neutral colour
        ax.plot(
            [], [], linestyle="none", marker=marker, markersize=5, color="0.3",
            markerfacecolor="none" if marker == "o" else "0.3", label=label,
        )  # fmt: skip


def _legend(ax) -> None:
    """Legend outside the panel, on its right, so that no curve is hidden."""
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize="small", borderaxespad=0.0)


def verdict_lines(result: TimeHistoryResult) -> list[str]:
    """The verdict in words: overturning, largest slide, uplift, free flight, status."""
    names = result.block_names
    overturned = [
        f"{names[i]} at {result.overturn_time[i]:.3f} s"
        for i in range(len(names))
        if result.overturned[i]
    ]
    lines = ["overturned: " + (", ".join(overturned) if overturned else "none")]
    slides = np.where(np.isfinite(result.max_slide), result.max_slide, 0.0)
    if slides.size and slides.max() > 0.0:
        block = int(np.argmax(slides))
        lines[0] += f"; largest slide {1000.0 * slides[block]:.1f} mm ({names[block]})"
    lifted = [names[i] for i in range(len(names)) if result.uplift[i]]
    flying = [names[i] for i in range(len(names)) if result.free_flight[i]]
    lines.append(
        "uplift: "
        + (", ".join(lifted) or "none")
        + "; left its support (free flight): "
        + (", ".join(flying) or "none")
    )
    if result.status != "completed":
        lines.append(f"simulation {result.status}: {result.message}")
    return lines


def _block_panel(ax, result, values, large, units, events, label, gid) -> None:
    """One curve per block of ``values`` (slide or rotation), its events and legend."""
    factor, unit = _scale(values, large, units)
    for block, name in enumerate(result.block_names):
        ax.plot(
            result.time, factor * values[:, block], color=_colour(block),
            linewidth=1.0, label=name, gid=f"{gid}:{block}",
        )  # fmt: skip
    _mark_events(ax, result, values, events, factor)
    ax.set_ylabel(f"{label}\n[{unit}]" if "\n" not in label else f"{label} [{unit}]")
    _legend(ax)


def plot_time_history(
    result: TimeHistoryResult,
    support_motion: SupportMotion | None = None,
    *,
    stack: Stack | None = None,
    title: str | None = None,
) -> Figure:
    """Stacked time histories of a simulation, sharing the time axis.

    Panels from the top: the support acceleration (when ``support_motion`` is
    given: ``a_h`` and, if any, the downward ``a_v`` [m/s^2]); the slide of
    every block along the body below (``TimeHistoryResult.slide``) [mm, or m
    from 1 m]; the rotation of every block relative to the body below
    (``relative_rotation``) [mrad, or rad from 0.1 rad]; then one panel per
    interface with the normal forces at its left and right contacts and the
    tangential force (``normal_force``, ``tangential_force``) [kN].

    Events are marked on the block's curve: lift-off and impacts on the
    rotation panel, slip, slip-stop, end-stop impacts and tangential impacts
    on the slide panel. A block's overturning is a red vertical line on every
    panel. The verdict is written under the title.

    Parameters
    ----------
    result : TimeHistoryResult
        The simulation.
    support_motion : SupportMotion, optional
        The excitation, drawn in the top panel.
    stack : Stack, optional
        The simulated stack, for the names of the contacts (the model's, e.g.
        A/B); "left"/"right" without it.
    title : str, optional
        Figure title (default: the configuration's name).

    Returns
    -------
    matplotlib.figure.Figure
        A new figure (not shown, not saved).
    """
    names = result.block_names
    count = len(names)
    panels = (1 if support_motion is not None else 0) + 2 + count
    figure = Figure(figsize=(9.0, 1.9 * panels + 1.0), layout="constrained")
    axes = figure.subplots(panels, 1, sharex=True, squeeze=False)[:, 0]
    for ax in axes:
        ax.grid(True, alpha=0.3)
    time = result.time
    row = 0
    if support_motion is not None:
        ax = axes[row]
        t, a_h, a_v = support_samples(support_motion, float(time[-1]))
        ax.plot(t, a_h, color="k", linewidth=0.8, label="a_h (+x)", gid="support:horizontal")
        if a_v is not None:
            ax.plot(
                t, a_v, color="0.5", linewidth=0.8, label="a_v (downward)", gid="support:vertical"
            )
        ax.set_ylabel("support accel.\n[m/s^2]")
        _legend(ax)
        row += 1

    _block_panel(
        axes[row], result, result.slide, 1.0, ("mm", "m"), SLIDING_EVENTS,
        "slide on body below", "slide",
    )  # fmt: skip
    row += 1
    _block_panel(
        axes[row], result, result.relative_rotation, 0.1, ("mrad", "rad"), ROCKING_EVENTS,
        "rotation rel. to\nbody below", "rotation",
    )  # fmt: skip
    row += 1

    for block, name in enumerate(names):
        ax = axes[row]
        contact_names = stack.blocks[block].contact_names if stack else ("left", "right")
        colour = _colour(block)
        for side, style in ((0, "-"), (1, "--")):
            ax.plot(
                time, result.normal_force[:, block, side] / 1000.0, color=colour, linestyle=style,
                linewidth=1.0, label=f"N {contact_names[side]}", gid=f"normal:{block}:{side}",
            )  # fmt: skip
        ax.plot(
            time, result.tangential_force[:, block] / 1000.0, color="0.35", linestyle=":",
            linewidth=1.0, label="T (friction)", gid=f"tangential:{block}",
        )  # fmt: skip
        below = names[block - 1] if block else "support"
        ax.set_ylabel(f"forces {name}\non {below} [kN]")
        _legend(ax)
        row += 1

    for block, name in enumerate(names):
        if result.overturned[block]:
            instant = float(result.overturn_time[block])
            for index, ax in enumerate(axes):
                ax.axvline(
                    instant, color="red", linewidth=1.5, linestyle="-.",
                    label=f"{name} overturns, {instant:.3f} s" if index == 0 else None,
                    gid=f"overturn:{block}",
                )  # fmt: skip
            _legend(axes[0])
    axes[-1].set_xlabel("time t [s]")
    axes[-1].set_xlim(float(time[0]), float(time[-1]))
    heading = title or f"Time history: {result.configuration}"
    figure.suptitle(heading + "\n" + "\n".join(verdict_lines(result)), fontsize="medium")
    return figure


def frame_indices(time: np.ndarray, fps: float, max_frames: int) -> tuple[np.ndarray, np.ndarray]:
    """Evenly spaced frame times and the recorded rows shown at them.

    Parameters
    ----------
    time : numpy.ndarray
        Recorded times [s], non-decreasing.
    fps : float
        Frames per second of simulated time [1/s]: real-time playback at
        that frame rate, unless capped by ``max_frames``.
    max_frames : int
        Largest number of frames (at least 2); a long simulation then plays
        faster than real time.

    Returns
    -------
    tuple of numpy.ndarray
        Frame times [s] and, for each, the index of the last recorded row at
        or before it (a recorded state, not an interpolation).
    """
    duration = float(time[-1] - time[0])
    count = int(min(max_frames, max(2, round(duration * fps) + 1)))
    instants = np.linspace(float(time[0]), float(time[-1]), count)
    rows = np.clip(np.searchsorted(time, instants, side="right") - 1, 0, time.size - 1)
    return instants, rows


def animate_time_history(
    result: TimeHistoryResult,
    stack: Stack,
    path: str | Path,
    *,
    support_motion: SupportMotion | None = None,
    fps: float = 20.0,
    max_frames: int = 300,
    exaggeration: float = 1.0,
    dpi: int = 80,
    title: str | None = None,
) -> Path:
    """Write an animated GIF of the blocks moving.

    Drawn in the support's frame (as the simulation's coordinates): the
    support is the fixed line z = 0 (hatched below) and the blocks move on it;
    the support's own motion is shown by the text ``a_h`` and by an arrow on
    the support (length proportional to ``a_h``, its peak a quarter of the
    picture). Each block is the schematic rectangle of
    :func:`freestand.core.geometry.block_outlines` at its recorded pose, with
    its centre of gravity (cross) and lower contacts (dots); its motion
    relative to the body below after the last event (rest, slide, rock,
    slide-rock, free-flight) is written on the frame. An overturned block
    stays drawn red at its last pose, with the time it overturned. Axis limits
    are fixed over the animation and the aspect is equal.

    Parameters
    ----------
    result : TimeHistoryResult
        The simulation.
    stack : Stack
        The simulated stack (geometry of the blocks).
    path : str or pathlib.Path
        The GIF to write (missing folders are created).
    support_motion : SupportMotion, optional
        The excitation, for the acceleration text and arrow.
    fps : float, optional
        Frames per second [1/s] of the GIF and of simulated time.
    max_frames : int, optional
        Largest number of frames (see :func:`frame_indices`).
    exaggeration : float, optional
        Factor [-] on the rotations relative to the body below, drawn about
        the lower contact (:func:`freestand.core.geometry.stack_poses`);
        written on every frame when not 1. Slides are never exaggerated.
    dpi : int, optional
        Resolution [dots per inch] of the 6.4 x 4.8 inch frames.
    title : str, optional
        Title on every frame (default: the configuration's name).

    Returns
    -------
    pathlib.Path
        The file written.
    """
    from matplotlib.patches import Polygon, Rectangle

    target = animation_target(path, fps, max_frames, exaggeration)
    names = result.block_names
    count = len(names)
    outlines = block_outlines(stack)
    contacts = [np.array(block.contacts, dtype=float) for block in stack.blocks]
    centres = [np.array(block.centre, dtype=float) for block in stack.blocks]
    instants, rows = frame_indices(result.time, fps, max_frames)

    # drawn poses; an overturned block keeps its last finite pose
    poses = np.array([stack_poses(stack, result.position[row], exaggeration) for row in rows])
    gone = ~np.isfinite(poses[:, :, 0])
    for block in range(count):
        finite = np.flatnonzero(~gone[:, block])
        if finite.size:
            last = finite[-1]
            poses[last + 1 :, block] = poses[last, block]

    corners = np.concatenate(
        [place(poses[k, b], outlines[b]) for k in range(len(rows)) for b in range(count)]
    )
    low, high = corners.min(axis=0), corners.max(axis=0)
    span = high - low
    pad = 0.08 * max(span)
    x_limits = (low[0] - pad, high[0] + pad)
    ground = 0.06 * max(span)
    bottom, top = min(low[1], 0.0) - ground - pad, high[1] + pad
    text_share = 0.09 + 0.055 * count  # of the height, above the blocks, for the text
    z_limits = (bottom, top + text_share * (top - bottom) / (1.0 - text_share))

    figure = Figure(figsize=(6.4, 4.8), layout="constrained")
    ax = figure.add_subplot()
    ax.set_aspect("equal")
    ax.set_xlim(*x_limits)
    ax.set_ylim(*z_limits)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("z [m]")
    ax.set_title(title or result.configuration, fontsize="medium")
    ax.add_patch(
        Rectangle(
            (x_limits[0], -ground), x_limits[1] - x_limits[0], ground,
            facecolor="0.85", edgecolor="0.3", hatch="///", linewidth=0.8,
        )
    )  # fmt: skip
    ax.axhline(0.0, color="k", linewidth=1.2)

    patches, centre_marks, contact_marks = [], [], []
    for block in range(count):
        patch = Polygon(
            outlines[block], closed=True, facecolor=_colour(block), alpha=0.55,
            edgecolor="k", linewidth=1.0,
        )  # fmt: skip
        ax.add_patch(patch)
        patches.append(patch)
        (centre_mark,) = ax.plot([], [], marker="+", markersize=9, color="k", linestyle="none")
        (contact_mark,) = ax.plot([], [], marker="o", markersize=4, color="k", linestyle="none")
        centre_marks.append(centre_mark)
        contact_marks.append(contact_mark)

    arrow_x = x_limits[0] + 0.5 * (x_limits[1] - x_limits[0])
    arrow_z = -0.5 * ground
    (arrow,) = ax.plot([], [], color="darkred", linewidth=3.0, solid_capstyle="butt")
    (arrow_head,) = ax.plot([], [], color="darkred", marker=">", markersize=7, linestyle="none")
    peak = 0.0
    if support_motion is not None:
        _, a_h, _ = support_samples(support_motion, float(result.time[-1]))
        peak = float(np.max(np.abs(a_h))) if a_h.size else 0.0
    arrow_length = 0.25 * (x_limits[1] - x_limits[0])

    clock = ax.text(0.02, 0.97, "", transform=ax.transAxes, va="top", family="monospace")
    states = [
        ax.text(
            0.02,
            0.90 - 0.055 * (count - 1 - block),
            "",
            transform=ax.transAxes,
            va="top",
            fontsize="small",
            family="monospace",
            color=_colour(block),
            fontweight="bold",
        )  # fmt: skip
        for block in range(count)
    ]  # the top block first, as stacked
    if exaggeration != 1.0:
        ax.text(
            0.98, 0.03, f"rotations drawn x{exaggeration:g}", transform=ax.transAxes,
            ha="right", va="bottom", color="darkred", fontweight="bold",
            bbox={"facecolor": "white", "edgecolor": "darkred"},
        )  # fmt: skip

    event_times = np.array([event.time for event in result.events])
    moving = [*patches, *centre_marks, *contact_marks, arrow, arrow_head, clock, *states]

    def draw_frame(frame: int) -> None:
        instant = instants[frame]
        for block in range(count):
            pose = poses[frame, block]
            patches[block].set_xy(place(pose, outlines[block]))
            centre_marks[block].set_data(*place(pose, centres[block][None, :]).T)
            contact_marks[block].set_data(*place(pose, contacts[block]).T)
            over = bool(result.overturned[block]) and instant >= result.overturn_time[block]
            patches[block].set_edgecolor("red" if over else "k")
            patches[block].set_linewidth(2.0 if over else 1.0)
            patches[block].set_hatch("xx" if over else None)
        text = f"t = {instant:7.3f} s"
        if support_motion is not None:
            a_h, a_v = support_motion(float(instant))
            text += f"   a_h = {a_h:+6.2f} m/s^2"
            if support_motion.vertical is not None:
                text += f"   a_v = {a_v:+6.2f} m/s^2"
            if abs(a_h) > 1e-3 * peak:
                tip = arrow_x + arrow_length * a_h / peak
                arrow.set_data([arrow_x, tip], [arrow_z, arrow_z])
                arrow_head.set_data([tip], [arrow_z])
                arrow_head.set_marker(">" if a_h >= 0 else "<")
            else:
                arrow.set_data([], [])
                arrow_head.set_data([], [])
        clock.set_text(text)
        latest = int(np.searchsorted(event_times, instant, side="right")) - 1
        for block, name in enumerate(names):
            if result.overturned[block] and instant >= result.overturn_time[block]:
                motion = f"overturned at {result.overturn_time[block]:.3f} s"
            elif latest >= 0:
                motion = result.events[latest].motions[block]
            else:
                motion = "rest"
            states[block].set_text(f"{name}: {motion}")

    return write_gif(figure, moving, len(instants), draw_frame, target, fps=fps, dpi=dpi)


def animation_target(path: str | Path, fps: float, max_frames: int, exaggeration: float) -> Path:
    """The GIF's path, its folder made; ValueError for a frame rate, frame count or factor
    an animation cannot take."""
    if not fps > 0:
        raise ValueError(f"fps must be positive, not {fps!r}")
    if max_frames < 2:
        raise ValueError(f"max_frames must be at least 2, not {max_frames!r}")
    if not exaggeration > 0:
        raise ValueError(f"exaggeration must be positive, not {exaggeration!r}")
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    return target


def write_gif(figure: Figure, moving, count: int, draw_frame, path: Path, *, fps: float,
              dpi: int) -> Path:  # fmt: skip
    """Write ``count`` frames of ``figure`` as one looping GIF at ``path``.

    The figure is laid out and what does not move is drawn once; each frame
    ``draw_frame(k)`` updates the ``moving`` artists, which alone are drawn
    over that background (blitting), and Pillow writes the frames as one GIF
    (as :class:`matplotlib.animation.PillowWriter`), the last held for
    :data:`HOLD_LAST_FRAME`.
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from PIL import Image

    for artist in moving:
        artist.set_animated(True)
    figure.set_dpi(dpi)
    canvas = FigureCanvasAgg(figure)
    canvas.draw()
    figure.set_layout_engine("none")
    background = canvas.copy_from_bbox(figure.bbox)
    frames = []
    for frame in range(count):
        draw_frame(frame)
        canvas.restore_region(background)
        for artist in moving:
            figure.draw_artist(artist)
        frames.append(
            Image.frombuffer("RGBA", canvas.get_width_height(), canvas.buffer_rgba()).convert("RGB")
        )
    durations = [round(1000.0 / fps)] * len(frames)
    durations[-1] = max(durations[-1], HOLD_LAST_FRAME)
    frames[0].save(path, save_all=True, append_images=frames[1:], duration=durations, loop=0)
    return path


def time_history_figures(
    result: TimeHistoryResult,
    folder: str | Path,
    *,
    support_motion: SupportMotion | None = None,
    stack: Stack | None = None,
    title: str | None = None,
    formats: Sequence[str] = ("png", "svg"),
) -> list[Path]:
    """Write the time-history figure into ``folder`` as ``time-history.png`` and ``.svg``.

    Returns
    -------
    list of pathlib.Path
        The files written.
    """
    from freestand.plot.figures import save_figure

    figure = plot_time_history(result, support_motion, stack=stack, title=title)
    return save_figure(figure, Path(folder) / "time-history", formats=tuple(formats))
