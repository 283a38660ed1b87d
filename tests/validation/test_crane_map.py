"""Mode maps of the crane: the paper's excitation points lie in the right regions.

Source: the reference paper, section 4 and Tables 2-5, as read in the crane
specification (``crane-model.md``, "What the paper's tables say"): in the
y-z plane the bridge slides with the cart for both excitations and senses;
in the x-z plane the cart stays at rest (rigid, 2.70 m/s^2) or rocks about
its outer wheel (elastic, 10.31 m/s^2) when the inertial force points to the
near end stop, and slides on the bridge when it points away from it.
a_ver = 2.35 m/s^2 downward, g = 9.81 m/s^2.
"""

from __future__ import annotations

import numpy as np
import pytest

from freestand.core.contact.batch import Parameter
from freestand.core.contact.screening import initial_motion
from freestand.core.sweeps.mode_map import Axis, mode_map, model_points
from freestand.io.model_file import load_model
from freestand.plot.maps import plot_mode_maps

MODEL = load_model(__file__.rsplit("/tests/", 1)[0] + "/examples/crane.toml")
HORIZONTAL = Axis(Parameter("horizontal"), 0.0, 12.0)
VERTICAL = Axis(Parameter("vertical"), -3.0, 10.0)

# (configuration, sense) -> region of the rigid and the elastic point (paper Tables 2 and 4).
PAPER = {
    ("y-z", 1): ("bridge slides, cart rests", "bridge slides, cart rests"),
    ("y-z", -1): ("bridge slides, cart rests", "bridge slides, cart rests"),
    ("x-z cart right", 1): ("bridge rests, cart rests", "bridge rests, cart rocks"),
    ("x-z cart right", -1): ("bridge rests, cart slides", "bridge rests, cart slides"),
    ("x-z cart left", 1): ("bridge rests, cart slides", "bridge rests, cart slides"),
    ("x-z cart left", -1): ("bridge rests, cart rests", "bridge rests, cart rocks"),
}


@pytest.mark.parametrize(("configuration", "sense"), list(PAPER))
def test_paper_points_lie_in_the_paper_regions(configuration, sense):
    stack = MODEL.configuration(configuration)
    crane_map = mode_map(stack, HORIZONTAL, VERTICAL, MODEL.excitations[0], sense, 400)
    points = model_points(crane_map, stack, MODEL.excitations)
    assert [name for name, _, _ in points] == ["rigid", "elastic"]
    for (name, x, y), expected in zip(points, PAPER[(configuration, sense)], strict=True):
        # The grid node nearest to the point (spacing 0.03 m/s^2) is in the
        # paper's region, and so is the point itself.
        assert crane_map.label_at(x, y) == expected, name
        motion = initial_motion(stack, x, y, sense, MODEL.gravity)
        words = ", ".join(
            f"{s.name} {'rests' if s.motion.value == 'rest' else s.motion.value + 's'}"
            for s in motion.blocks
        )
        assert words == expected


def test_boundaries_in_the_excitation_plane_are_straight_lines():
    """Each mode's solution is linear in (s a_hor, g - a_ver): along any ray from
    (0, g) the region does not change (excitation-plane superposition)."""
    stack = MODEL.configuration("x-z cart right")
    crane_map = mode_map(stack, HORIZONTAL, VERTICAL, MODEL.excitations[0], 1, 200)
    rng = np.random.default_rng(5)
    for _ in range(50):
        row, column = rng.integers(0, 200, 2)
        h, v = crane_map.x_values[column], crane_map.y_values[row]
        if v >= MODEL.gravity or h == 0:
            continue
        for factor in (0.5, 0.8, 1.25):
            hs, vs = factor * h, MODEL.gravity - factor * (MODEL.gravity - v)
            a = initial_motion(stack, h, v, 1, MODEL.gravity).blocks
            b = initial_motion(stack, hs, vs, 1, MODEL.gravity).blocks
            assert [s.motion for s in a] == [s.motion for s in b]


def test_map_figure_is_written(tmp_path):
    stack = MODEL.configuration("x-z cart right")
    maps = [mode_map(stack, HORIZONTAL, VERTICAL, MODEL.excitations[0], s, 60) for s in (1, -1)]
    points = [model_points(m, stack, MODEL.excitations) for m in maps]
    path = plot_mode_maps(maps, tmp_path / "map.png", points, title="crane")
    assert path.stat().st_size > 10_000
