"""Screening 3-D configurations from rest by direction (#18): fs.screen, --json, --directions, figure.

The closed forms (Housner 1963 in 3-D, ``docs/three-d.md``) and the planar
reduction are validated on the core in ``tests/validation/test_body_uplift_from_rest.py``;
here they are checked through the model file, the public API and the real
command.
"""

from __future__ import annotations

import json
import math

import pytest

import freestand as fs
from freestand.api.screening import DIRECTION_COLUMNS, SCREENING_COLUMNS
from tests.conftest import CRANE, ROOT, run_freestand

BODIES = ROOT / "examples" / "bodies.toml"

#: The same block twice: a 3-D box excited along x, and the planar block of its x-z plane
#: (centre (0, h/2), base +-l_x/2, inertia about y m (l_x^2 + l_z^2)/12).
REDUCTION = """
name = "box and its plane"
[[excitation]]
name = "low"
horizontal = 1.0
vertical = 2.0
[[excitation]]
name = "rocking"
horizontal = 2.8
vertical = 2.0
[[excitation]]
name = "upward"
horizontal = 4.5
vertical = -2.0
[[excitation]]
name = "sliding"
horizontal = 9.0
vertical = 3.0

[[configuration]]
name = "box"
[[configuration.block]]
name = "cabinet"
shape = "box"
size = [0.6, 0.7, 2.0]
mass = 500
friction = { static = 0.4, kinetic = 0.25 }

[[configuration]]
name = "plane x-z"
[[configuration.block]]
name = "cabinet"
mass = 500
inertia = 181.66666666666666
centre = [0.0, 1.0]
base = { left = -0.3, right = 0.3 }
friction = { static = 0.4, kinetic = 0.25 }
"""


@pytest.fixture(scope="module")
def bodies_model():
    return fs.load_model(BODIES)


def test_a_box_excited_along_x_screens_as_the_planar_block_of_its_plane(tmp_path):
    path = tmp_path / "reduction.toml"
    path.write_text(REDUCTION)
    result = fs.screen(fs.load_model(path), directions=4)
    planar = {(case.excitation, case.sense): case.blocks[0] for case in result.cases}
    motions = set()
    for case in result.body_cases:
        # the support acceleration along +x (0 deg) is the inertial force along -x: sense -
        for state, sense in ((case.directions[0], -1), (case.directions[2], 1)):
            reference = planar[(case.excitation, sense)]
            assert state.motion == reference.motion, (case.excitation, sense)
            motions.add(state.motion.value)
            if state.motion.value in ("rest", "slide", "rock"):
                normal = reference.base_normal_left + reference.base_normal_right
                # the same equations solved two ways: 1e-9 relative
                assert state.normal_force == pytest.approx(normal, rel=1e-9)
                assert state.tangential_force[0] == pytest.approx(
                    reference.base_tangential, rel=1e-9, abs=1e-9
                )
                assert state.angular_acceleration == pytest.approx(
                    abs(reference.angular_acceleration), rel=1e-9, abs=1e-12
                )
    assert motions >= {"rest", "slide", "rock"}


def test_thresholds_pivots_and_the_excitations_own_direction(bodies_model):
    result = fs.screen(bodies_model, configurations="cabinet")
    assert result.cases == () and len(result.body_cases) == 2  # SL-1, SL-2
    case = result.body_cases[1]
    g, a_v = 9.81, 0.27 * 9.81
    assert case.horizontal == pytest.approx(0.5 * 9.81)  # sqrt(0.4^2 + 0.3^2) g
    assert math.degrees(case.excitation_direction) == pytest.approx(36.8699, abs=1e-4)
    bx, by, h = 0.4, 0.25, 1.05
    for state in case.directions:
        c, s = abs(math.cos(state.direction)), abs(math.sin(state.direction))
        reach = min(bx / c if c > 1e-12 else math.inf, by / s if s > 1e-12 else math.inf)
        assert state.uplift_threshold == pytest.approx((g - a_v) * reach / h, rel=1e-12)
    assert [round(math.degrees(s.direction), 9) for s in case.directions] == [
        15.0 * k for k in range(24)
    ]
    assert case.directions[0].pivot == "edge -x" and case.directions[6].pivot == "edge -y"
    assert case.at_excitation.direction == case.excitation_direction


def test_directions_and_bad_counts(bodies_model):
    assert len(fs.screen(bodies_model, directions=7).body_cases[0].directions) == 7
    for bad in (0, -3, 2.5, 10**6):
        with pytest.raises(fs.FreestandError, match="--directions"):
            fs.screen(bodies_model, directions=bad)


def test_the_directions_table_has_the_documented_columns(bodies_model):
    result = fs.screen(bodies_model, directions=8)
    table = result.to_frame()  # no planar configuration: the directions
    assert tuple(table.columns) == DIRECTION_COLUMNS
    assert len(table) == 2 * 2 * 8  # configurations x excitations x directions
    assert set(table["motion"]) <= {"rest", "slide", "rock", "slide-rock", "free-flight"}
    assert table.attrs["model"] == "Cask and cabinet"
    assert tuple(result.to_frame("cases").columns) == SCREENING_COLUMNS
    with pytest.raises(fs.FreestandError, match="directions"):
        result.to_frame("bodies")


def test_planar_models_keep_their_document_and_have_no_figure(crane_model):
    result = fs.screen(crane_model)
    assert "body_cases" not in result.to_dict()
    with pytest.raises(fs.FreestandError, match="no 3-D screening to draw"):
        result.plot()


def test_the_polar_figure_shows_thresholds_circles_motions_and_a_legend(bodies_model):
    figure = fs.screen(bodies_model).plot()
    panels = [ax for ax in figure.axes if ax.name == "polar"]
    assert len(panels) == 4  # (cask, cabinet) x (a_v of SL-1, a_v of SL-2)
    for ax in panels:
        # threshold curve, slide circle, the excitation's circle
        assert len(ax.get_lines()) == 3
        assert ax.get_lines()[0].get_label().startswith("uplift threshold")
        markers = sum(len(c.get_offsets()) for c in ax.collections if len(c.get_offsets()))
        assert markers == 24 + 1  # one per swept direction, the star
        assert "m/s²" in ax.get_title() and (
            "cylinder" in ax.get_title() or "box" in ax.get_title()
        )
    legend = figure.legends[0]
    labels = [text.get_text() for text in legend.get_texts()]
    assert labels[:2] == [
        "uplift threshold $a^*(\\varphi)$",
        "slide threshold $\\mu_0\\,(g - a_v)$",
    ]
    assert {"rest", "slide", "rock", "slide-rock"} <= set(labels)
    assert "radius: acceleration [m/s²]" in legend.get_title().get_text()
    # one panel into the caller's axes
    from matplotlib.figure import Figure

    ax = Figure().add_subplot(projection="polar")
    one = fs.screen(bodies_model).plot(ax, configuration="cask", excitation="SL-2")
    assert one is ax.figure and len(ax.get_lines()) == 3


def test_screen_json_is_the_api_document_and_lists_every_direction(tmp_path):
    model = tmp_path / "both.toml"
    model.write_text(REDUCTION)
    result = run_freestand("screen", str(model), "--json", "--directions", "8")
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    assert document == fs.screen(fs.load_model(model), directions=8).to_dict()
    assert len(document["cases"]) == 4 * 2  # the planar configuration, unchanged
    body_cases = document["body_cases"]
    assert [c["excitation"] for c in body_cases] == ["low", "rocking", "upward", "sliding"]
    first = body_cases[1]
    assert (first["configuration"], first["shape"], first["size"]) == (
        "box",
        "box",
        [0.6, 0.7, 2.0],
    )
    assert [d["direction"] for d in first["directions"]] == [45.0 * k for k in range(8)]
    entry = first["directions"][0]
    assert set(entry) == {"direction", "motion", "pivot", "slide_direction", "uplift_threshold",
                          "forces", "angular_acceleration"}  # fmt: skip
    assert entry["motion"] == "rock" and entry["pivot"] == "edge -x"
    assert entry["uplift_threshold"] == pytest.approx((9.81 - 2.0) * 0.3 / 1.0)
    assert set(entry["forces"]) == {"normal", "tangential"}
    assert first["at_excitation"]["direction"] == 0.0


def test_screen_prints_a_table_per_excitation_and_writes_the_polar_figure(tmp_path):
    folder = tmp_path / "figures"
    result = run_freestand("screen", str(BODIES), "-c", "cabinet", "--plot", str(folder))
    assert result.returncode == 0, result.stderr
    out = result.stdout
    assert "x = 1.96, y = 1.47 m/s^2 (2.45 m/s^2 at 36.9 deg)" in out
    assert out.count("(own)") == 2 + 2 and "345.0" in out  # rows and caption; every 15 deg
    assert "rock (edge -y)" in out and "cabinet (box 0.80 x 0.50 x 2.20 m)" in out
    words = " ".join(out.split())  # the sentence as printed, wrapped at 120 characters
    assert "the cabinet rests in 14 of 24 directions, rocks in 10 of 24 directions" in words
    assert "paper Tables 2 and 4" not in out  # no planar configuration
    assert sorted(p.name for p in folder.iterdir()) == ["uplift_polar.png", "uplift_polar.svg"]
    assert f"wrote {folder / 'uplift_polar.png'}" in out


def test_a_figure_of_a_planar_model_is_refused_before_anything_is_written(tmp_path):
    folder = tmp_path / "figures"
    result = run_freestand("screen", str(CRANE), "--plot", str(folder))
    assert result.returncode == 2
    assert "--plot" in result.stderr and "3-D configurations" in result.stderr
    assert "Traceback" not in result.stderr + result.stdout
    assert not folder.exists() or not any(folder.iterdir())
