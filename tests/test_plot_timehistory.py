"""Time-history figure and animation: content, not only files."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from PIL import Image, ImageChops  # noqa: E402

from freestand.core.dynamics.timehistory import SupportMotion, simulate  # noqa: E402
from freestand.core.model import Block, Friction, Sliding, Stack  # noqa: E402
from freestand.plot.timehistory import (  # noqa: E402
    animate_time_history,
    frame_indices,
    plot_time_history,
    support_samples,
    time_history_figures,
)


def rectangle(name, half_width, height, level, mass, static, sliding=Sliding.FREE):
    return Block(
        name=name,
        mass=mass,
        inertia=mass * (4 * half_width**2 + height**2) / 12.0,
        centre=(0.0, level + 0.5 * height),
        base_left=-half_width,
        base_right=half_width,
        base_level=level,
        friction=Friction(static, 0.8 * static),
        sliding=sliding,
        contact_names=("L", "R"),
    )


def half_sine(amplitude, duration, total, dt=0.005):
    t = np.arange(0.0, total, dt)
    return SupportMotion(dt, np.where(t < duration, amplitude * np.sin(np.pi * t / duration), 0.0))


@pytest.fixture(scope="module")
def rocking_pair():
    """A slender cabinet on a plinth rocks under a half-sine, with impacts; nothing overturns."""
    stack = Stack(
        "plinth and cabinet",
        (
            rectangle("plinth", 0.8, 0.4, 0.0, 2000.0, 0.3, Sliding.NONE),
            rectangle("cabinet", 0.2, 1.6, 0.4, 500.0, 0.6),
        ),
    )
    motion = half_sine(4.0, 0.4, 1.0)
    return stack, motion, simulate(stack, motion, 0.8, max_step=2e-3)


@pytest.fixture(scope="module")
def overturning():
    """A slender block lifts, slips and overturns under a 6 m/s^2, 0.5 s half-sine."""
    stack = Stack("cabinet", (rectangle("cabinet", 0.2, 2.0, 0.0, 1000.0, 0.6),))
    motion = half_sine(6.0, 0.5, 3.0)
    result = simulate(stack, motion, 2.5, max_step=2e-3)
    assert result.overturned[0]
    return stack, motion, result


def _line(fig, gid):
    lines = [line for ax in fig.axes for line in ax.get_lines() if line.get_gid() == gid]
    assert len(lines) == 1, gid
    return lines[0]


def test_panels_hold_the_result_arrays(rocking_pair):
    stack, motion, result = rocking_pair
    assert result.max_rotation[1] > 0.01 and len(result.events_of("impact")) > 0
    fig = plot_time_history(result, motion, stack=stack)
    # support, slide, rotation, one force panel per interface
    assert len(fig.axes) == 1 + 2 + 2
    t, a_h, _ = support_samples(motion, result.time[-1])
    np.testing.assert_array_equal(_line(fig, "support:horizontal").get_ydata(), a_h)
    np.testing.assert_array_equal(_line(fig, "support:horizontal").get_xdata(), t)
    for block in range(2):
        slide = _line(fig, f"slide:{block}")
        np.testing.assert_array_equal(slide.get_xdata(), result.time)
        np.testing.assert_allclose(slide.get_ydata(), 1000.0 * result.slide[:, block])  # mm
        rotation = _line(fig, f"rotation:{block}")
        # peak 0.05 rad < 0.1 rad: drawn in mrad
        np.testing.assert_allclose(
            rotation.get_ydata(), 1000.0 * result.relative_rotation[:, block]
        )
        for side in range(2):
            normal = _line(fig, f"normal:{block}:{side}")
            np.testing.assert_allclose(
                normal.get_ydata(), result.normal_force[:, block, side] / 1000.0
            )
        tangential = _line(fig, f"tangential:{block}")
        np.testing.assert_allclose(tangential.get_ydata(), result.tangential_force[:, block] / 1e3)
    labels = [ax.get_ylabel() for ax in fig.axes]
    assert "[m/s^2]" in labels[0] and "[mm]" in labels[1] and "[mrad]" in labels[2]
    assert all("[kN]" in label for label in labels[3:])
    assert "on plinth" in labels[4] and "on support" in labels[3]
    assert fig.axes[-1].get_xlabel() == "time t [s]"
    legend = [text.get_text() for text in fig.axes[2].get_legend().get_texts()]
    assert "plinth" in legend and "cabinet" in legend and "impact (contact closes)" in legend
    forces_legend = [text.get_text() for text in fig.axes[4].get_legend().get_texts()]
    assert forces_legend == ["N L", "N R", "T (friction)"]  # the model's contact names


def test_events_are_marked_on_their_block(rocking_pair):
    stack, motion, result = rocking_pair
    fig = plot_time_history(result, motion, stack=stack)
    impacts = [e for e in result.events_of("impact") if e.interface == 1]
    markers = _line(fig, "event:impact:1")
    np.testing.assert_allclose(markers.get_xdata(), [e.time for e in impacts])
    lift = _line(fig, "event:lift-off:1")
    assert len(lift.get_xdata()) == sum(e.interface == 1 for e in result.events_of("lift-off"))
    # marked on the curve: the value of the rotation at the lift-off, in mrad (0 there)
    np.testing.assert_allclose(lift.get_ydata(), 0.0, atol=1e-6)
    title = fig.get_suptitle()
    assert "overturned: none" in title and "uplift: cabinet" in title


def test_overturning_is_marked_on_every_panel_and_in_the_title(overturning, tmp_path):
    stack, motion, result = overturning
    fig = plot_time_history(result)  # no support motion: no acceleration panel
    assert len(fig.axes) == 2 + 1
    instant = result.overturn_time[0]
    for ax in fig.axes:
        lines = [line for line in ax.get_lines() if line.get_gid() == "overturn:0"]
        assert len(lines) == 1 and lines[0].get_xdata()[0] == instant
    assert f"cabinet at {instant:.3f} s" in fig.get_suptitle()
    assert "[rad]" in fig.axes[1].get_ylabel()  # pi/2 at the end: radians
    assert len(_line(fig, "event:slip:0").get_xdata()) == len(result.events_of("slip"))
    written = time_history_figures(result, tmp_path / "out", support_motion=motion, stack=stack)
    assert [p.name for p in written] == ["time-history.png", "time-history.svg"]
    assert all(p.stat().st_size > 10_000 for p in written)


def test_frames_are_recorded_states_evenly_in_time():
    time = np.array([0.0, 0.1, 0.2, 0.2, 0.35, 1.0])
    instants, rows = frame_indices(time, fps=10.0, max_frames=300)
    assert instants.size == 11 and instants[-1] == 1.0
    assert all(time[r] <= t for r, t in zip(rows, instants, strict=True))
    assert rows[2] == 3  # at t = 0.2 the state after the event
    instants, _ = frame_indices(time, fps=1000.0, max_frames=50)
    assert instants.size == 50


def _frames(path):
    image = Image.open(path)
    frames = []
    for index in range(image.n_frames):
        image.seek(index)
        frames.append(image.convert("RGB"))
    return image, frames


def test_gif_is_animated_and_shows_the_motion(rocking_pair, tmp_path):
    stack, motion, result = rocking_pair
    path = animate_time_history(
        result, stack, tmp_path / "deep" / "pair.gif", support_motion=motion, fps=25
    )
    image, frames = _frames(path)
    assert image.format == "GIF" and path.stat().st_size > 0
    assert image.n_frames == frame_indices(result.time, 25, 300)[0].size > 1
    # rocking of 0.05 rad at the peak: frames differ, the first and last (at rest) less so
    peak = int(np.argmax(np.abs(result.relative_rotation[:, 1])))
    peak_frame = int(round(result.time[peak] * 25))
    assert ImageChops.difference(frames[0], frames[peak_frame]).getbbox() is not None
    assert image.info["loop"] == 0


def test_gif_marks_exaggeration_and_keeps_the_overturned_block(overturning, tmp_path):
    stack, motion, result = overturning
    true_path = animate_time_history(result, stack, tmp_path / "true.gif", max_frames=10)
    big_path = animate_time_history(
        result, stack, tmp_path / "big.gif", max_frames=10, exaggeration=3.0
    )
    _, true_frames = _frames(true_path)
    _, big_frames = _frames(big_path)
    assert len(true_frames) == 10
    # the last frame shows the overturned block (drawn red): reddish pixels appear
    last = np.asarray(true_frames[-1]).astype(int)
    first = np.asarray(true_frames[0]).astype(int)
    red = (last[..., 0] > 200) & (last[..., 1] < 80) & (last[..., 2] < 80)
    red0 = (first[..., 0] > 200) & (first[..., 1] < 80) & (first[..., 2] < 80)
    assert red.sum() > red0.sum() + 50
    # an exaggerated drawing differs (label and poses) from the true one
    assert ImageChops.difference(true_frames[3], big_frames[3]).getbbox() is not None
    with pytest.raises(ValueError, match="fps"):
        animate_time_history(result, stack, tmp_path / "x.gif", fps=0.0)
