"""Time history of a 3-D configuration through the public API and the real command (#18).

The engine is validated on the core (``tests/validation/test_body_planar_reduction.py``,
``tests/test_body_engine.py``); here: ``freestand simulate --json`` is
``fs.simulate(...).to_dict()``, the tables have their documented columns, the
figures and the animation draw what they say, ``--angle`` turns the pair,
``until_rest`` stops at rest, and bad input is refused through the command.
"""

from __future__ import annotations

import json
import math

import matplotlib
import numpy as np
import pytest

import freestand as fs
from tests.conftest import CRANE, ROOT, run_freestand

matplotlib.use("Agg")

BODIES = ROOT / "examples" / "bodies.toml"
RECORDS = ROOT / "examples" / "records"
X, UP = RECORDS / "synthetic_H.AT2", RECORDS / "synthetic_UP.AT2"

#: The cabinet rocks about an edge (with impacts) under the synthetic record on x and y,
#: turned by 30 deg, with the vertical, for 6 s; at its friction limit the edge slips by
#: micrometres (twist below 1e-6 rad).
CABINET_ARGS = ("--record", str(X), "--record-y", str(X), "--vertical", str(UP), "--peak", "5",
                "--angle", "30", "--duration", "6")  # fmt: skip


@pytest.fixture(scope="module")
def model():
    return fs.load_model(BODIES)


@pytest.fixture(scope="module")
def record():
    return fs.load_record(X, horizontal_y=X, vertical=UP).scaled_to_peak(5.0)


@pytest.fixture(scope="module")
def cabinet(model, record):
    return fs.simulate(model, record, 6.0, configuration="cabinet", angle=30.0)


def test_json_of_the_command_is_the_api_document(model, record, cabinet, tmp_path):
    result = run_freestand("simulate", str(BODIES), "-c", "cabinet", *CABINET_ARGS, "--json")
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    assert document == json.loads(json.dumps(cabinet.to_dict()))
    assert document["shape"] == "box" and document["angle"] == 30.0
    block = document["blocks"][0]
    assert set(block) == {"name", "max_rotation", "max_slide", "max_twist", "uplift",
                          "free_flight", "overturned", "overturn_time"}  # fmt: skip
    # the cabinet rocks about an edge: it lifts, impacts, does not overturn, never flies; its
    # edge slips at its friction limit and stops, event-driven (two stretches of the remedy's
    # time stepping there before the edge's slow slip was floored)
    assert document["status"] == "completed" and block["uplift"] and not block["overturned"]
    assert not block["free_flight"] and "remedy" not in document["events"]
    assert document["events"]["slip"] >= 1 and document["events"]["slip-stop"] >= 1
    assert document["events"]["impact"] > 0
    assert 0.0 < block["max_rotation"] < 0.1
    # the pair as simulated: the record on x and y, turned by 30 deg
    assert document["peak_horizontal"] == pytest.approx(math.sqrt(2.0) * 5.0, rel=1e-12)


def test_tables_have_the_documented_columns(cabinet):
    history = cabinet.to_frame()
    assert history.columns.tolist() == [
        "time [s]", "support_x [m/s^2]", "support_y [m/s^2]", "support_vertical [m/s^2]",
        "cabinet.tilt [rad]", "cabinet.tilt_x [rad]", "cabinet.tilt_y [rad]",
        "cabinet.slide_x [m]", "cabinet.slide_y [m]", "cabinet.slide [m]",
        "cabinet.twist [rad]", "cabinet.normal [N]", "cabinet.friction [N]",
        "cabinet.patch", "cabinet.motion",
    ]  # fmt: skip
    # the peak is refined between rows on the tilt's Hermite interpolant (as the planar
    # engine's): at or above the rows' largest, by less than the step's change (1e-3)
    rows_peak = history["cabinet.tilt [rad]"].max()
    assert rows_peak <= cabinet.max_rotation[0] <= rows_peak * (1.0 + 1e-3)
    tilt = np.hypot(history["cabinet.tilt_x [rad]"], history["cabinet.tilt_y [rad]"])
    np.testing.assert_allclose(tilt, history["cabinet.tilt [rad]"], atol=1e-12)
    # it rests, rocks about an edge, and where the edge's friction is at its limit slips by
    # micrometres (its chatter of slip restarts taken over by the remedy, which holds the edge)
    motions = history["cabinet.motion"].value_counts()
    assert {"rest", "rock-edge"} <= set(motions.index) <= {"rest", "rock-edge", "slide-rock",
                                                          "free-flight"}  # fmt: skip
    assert motions["rock-edge"] > 0.5 * len(history) and "free-flight" not in motions
    # the contact force [N] stays the weight's order (m g = 4.4 kN): the edge that lands
    # within the remedy's time stepping is an impact, its impulse kept out (it read 393 kN)
    assert history["cabinet.normal [N]"].max() < 3.0 * 450.0 * 9.81
    assert history.attrs["angle [deg]"] == 30.0 and history.attrs["method"] == "3-D"
    peaks = cabinet.to_frame("peaks")
    assert peaks.columns.tolist() == ["block", "max_rotation [rad]", "max_slide [m]",
                                      "max_twist [rad]", "uplift", "free_flight", "overturned",
                                      "overturn_time [s]"]  # fmt: skip
    events = cabinet.to_frame("events")
    assert events.columns.tolist() == ["time [s]", "kind", "block", "before", "after", "motion"]
    assert len(events) == sum(cabinet.event_counts().values())
    with pytest.raises(ValueError, match="not a table"):
        cabinet.to_frame("directions")


def test_the_history_figure_has_its_panels_curves_and_events(cabinet):
    figure = cabinet.plot()
    axes = figure.axes
    assert [ax.get_ylabel().replace("\n", " ") for ax in axes] == [
        "support accel. [m/s^2]", "motion", "tilt of the axis [mrad]",
        "slide of the base centre [mm]", "twist about the vertical [mrad]",
        "forces on the body [kN]",
    ]  # fmt: skip
    assert axes[-1].get_xlabel() == "time t [s]"
    assert [line.get_gid() for line in axes[0].lines] == ["support:x", "support:y",
                                                           "support:vertical"]  # fmt: skip
    tilt = next(line for line in axes[2].lines if line.get_gid() == "tilt")
    # the rows' tilt [mrad]; the peak is refined between them (above)
    assert max(tilt.get_ydata()) == pytest.approx(1000.0 * cabinet.max_rotation[0], rel=1e-3)
    assert max(tilt.get_ydata()) <= 1000.0 * cabinet.max_rotation[0]
    impacts = next(line for line in axes[2].lines if line.get_gid() == "event:impact")
    assert len(impacts.get_xdata()) == cabinet.event_counts()["impact"]
    motions = set(cabinet.to_frame()["cabinet.motion"])
    assert {patch.get_gid() for patch in axes[1].patches} == {f"motion:{m}" for m in motions}
    assert "largest tilt" in figure.get_suptitle() and "turned 30 deg" in figure.get_suptitle()
    # round-off twist (a box rocking about an edge) is drawn flat within +-1 mrad
    assert axes[4].get_ylim() == (-1.0, 1.0)
    with pytest.raises(ValueError, match="without ax"):
        cabinet.plot(ax=axes[0])


def test_the_plan_view_shows_the_path_and_the_tilt_vector(cabinet):
    figure = cabinet.plot(view="plan")
    slide, tilt = figure.axes[:2]
    assert slide.get_xlabel() == "x [mm]" and tilt.get_xlabel() == "tilt towards x [mrad]"
    assert [c.get_gid() for c in slide.collections] == ["slide"]
    assert [c.get_gid() for c in tilt.collections] == ["tilt"]
    # rocking about an edge along x: the tilt vector stays on the y axis, to the twist (3.8e-5
    # rad, the same at the default step and at 1 to 0.05 ms; round-off while the edge's slip
    # at its friction limit was time-stepped on its two corner points)
    segments = np.concatenate(tilt.collections[0].get_segments())
    assert np.max(np.abs(segments[:, 0])) < 1e-4 * np.max(np.abs(segments[:, 1]))
    assert cabinet.max_twist[0] < 1e-4
    # far below the tilt at which G stands over the long edge, atan(b_y / h): said, not drawn
    assert f"G over the pivot from {1000.0 * math.atan(0.25 / 1.05):.3g} mrad" in tilt.get_title()
    assert not any(line.get_gid() == "tipping" for line in tilt.lines)
    assert figure.axes[-1].get_ylabel() == "time t [s]"  # the colour bar


def test_the_animation_draws_the_recorded_poses_with_the_tilt_exaggerated(cabinet, tmp_path):
    from PIL import Image

    from freestand.plot.body_history import _solid, animate_body, drawn_poses

    path = animate_body(cabinet, tmp_path / "cabinet.gif", exaggeration=3.0, max_frames=25)
    assert Image.open(path).n_frames == 25
    row = int(np.argmax(cabinet.core.tilt))
    vertices = _solid(cabinet.body_configuration.body)[0]
    true, true_base = drawn_poses(cabinet, np.array([row]), 1.0, vertices)
    drawn, drawn_base = drawn_poses(cabinet, np.array([row]), 3.0, vertices)
    # the axis tilts three times as far, about the base point that stays on the support
    assert math.acos(drawn[0][2, 2]) == pytest.approx(3.0 * cabinet.core.tilt[row], rel=1e-9)
    lowest = vertices[np.argmin((true[0] @ vertices[:4].T)[2])]
    np.testing.assert_allclose(drawn_base[0] + drawn[0] @ lowest,
                               true_base[0] + true[0] @ lowest, atol=1e-12)  # fmt: skip


def test_angle_turns_the_pair_counter_clockwise(model):
    """A record along x turned by 90 deg is the same record along y."""
    t = np.arange(0.0, 1.0 + 1e-9, 0.005)
    pulse = np.where(t < 0.5, 7.0 * np.sin(2.0 * np.pi * t), 0.0)
    along_x = fs.GroundMotion(0.005, pulse)
    along_y = fs.GroundMotion(0.005, 0.0 * pulse, horizontal_y=pulse)
    turned = fs.simulate(model, along_x, 2.0, configuration="cabinet", angle=90.0)
    direct = fs.simulate(model, along_y, 2.0, configuration="cabinet")
    assert turned.support.y == pytest.approx(pulse) and np.all(np.abs(turned.support.x) < 1e-15)
    assert turned.max_rotation[0] > 0.01
    np.testing.assert_allclose(turned.core.tilt, direct.core.tilt, atol=1e-12)
    assert turned.to_dict()["angle"] == 90.0


def test_until_rest_stops_where_the_body_rests(model):
    """The cask slides when the record is cut at 2.3 s; friction stops it soon after."""
    record = fs.load_record(X).scaled_to_peak(6.0)
    cut = fs.GroundMotion(record.dt, record.horizontal[:461], name="cut at 2.3 s")
    result = fs.simulate(model, cut, configuration="cask", until_rest=True)
    assert result.status == "completed" and result.message.startswith("at rest at t = ")
    assert 2.3 < result.core.time[-1] < 2.5 and result.max_slide[0] > 1e-4
    assert result.motions[-1] == "rest" and "slide" in result.motions
    capped = fs.simulate(model, cut, configuration="cask", until_rest=True, free_time=0.0)
    assert capped.status == "capped" and capped.core.time[-1] == pytest.approx(2.3)


def test_a_restitution_factor_scales_the_velocity_after_each_impact(model, record, cabinet):
    """fs.simulate passes the factor to the 3-D engine (validated against the planar one in
    tests/validation/test_body_planar_reduction.py): the rocking cabinet's impacts change."""
    damped = fs.simulate(model, record, 6.0, configuration="cabinet", angle=30.0,
                         restitution=0.5)  # fmt: skip
    assert damped.status == cabinet.status == "completed"
    impacts = [e[0] for e in cabinet.core.events if e[1] == "impact"]
    assert impacts, "the cabinet must rock for this test"
    assert [e[0] for e in damped.core.events if e[1] == "impact"][:2] != impacts[:2]
    assert damped.max_rotation[0] < cabinet.max_rotation[0]


def test_planar_options_and_motions_are_refused_by_name(model, record):
    with pytest.raises(fs.FreestandError, match="--method general chooses a solver of planar"):
        fs.simulate(model, record, configuration="cask", method="general")
    for factor in (1.5, -0.1, [0.5, 0.5]):
        with pytest.raises(fs.FreestandError, match="restitution .* give one factor in"):
            fs.simulate(model, record, configuration="cask", restitution=factor)
    crane = fs.load_model(CRANE)
    with pytest.raises(fs.FreestandError, match="only a 3-D configuration takes"):
        fs.simulate(crane, record, configuration="y-z")
    with pytest.raises(fs.FreestandError, match="--angle 30 turns the horizontal pair"):
        fs.simulate(crane, fs.load_record(X), configuration="y-z", angle=30.0)


@pytest.mark.parametrize(
    ("model_file", "args", "option", "fix"),
    [
        (CRANE, ("-c", "y-z", "--record-y", str(X)), "--record-y", "leave --record-y out"),
        (CRANE, ("-c", "y-z", "--angle", "30"), "--angle", "choose a 3-D configuration"),
        (BODIES, ("-c", "cask", "--method", "single-block"), "--method", "leave --method out"),
        (BODIES, ("-c", "cask", "--angle", "nan"), "--angle", "e.g. --angle 30"),
        (BODIES, ("-c", "cask", "--animate", "cask.mp4"), "--animate", "cask.gif"),
    ],
)
def test_bad_input_through_the_command(model_file, args, option, fix, tmp_path):
    result = run_freestand("simulate", str(model_file), "--record", str(X), *args, cwd=tmp_path)
    assert result.returncode == 2, result.stdout
    assert option in result.stderr and fix in result.stderr
    assert "Traceback" not in result.stderr
    assert not any(tmp_path.iterdir())  # nothing written


def test_plot_and_animate_through_the_command(tmp_path):
    figures, gif = tmp_path / "figures", tmp_path / "cask.gif"
    result = run_freestand(
        "simulate", str(BODIES), "-c", "cask", "--record", str(X), "--record-y", str(UP),
        "--peak", "6", "--duration", "2.5", "--plot", str(figures), "--animate", str(gif),
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    written = [figures / f"{name}.{kind}" for name in ("plan-view", "time-history")
               for kind in ("png", "svg")] + [gif]  # fmt: skip
    for path in written:
        assert path.stat().st_size > 1000
        assert f"wrote {path}" in result.stdout.replace("\n", "")
    assert "max twist [rad]" in result.stdout and "slip-stop" in result.stdout


def test_a_base_point_through_the_support_ends_the_history_as_failed(model):
    """The front end's guard: the histories, events and peaks stop where the contact was lost."""
    from freestand.core.contact.body_kernel import body_parameters
    from freestand.core.dynamics import body_state
    from freestand.core.dynamics.body_history import (
        GRAVITY,
        _base_width,
        _history_rows,
        _result,
        initial_state,
        lost_contact_depth,
    )

    body = model.body_configuration("cabinet").body
    state = np.tile(initial_state(body), (5, 1))
    state[3:, 2] -= 1e-3  # the cabinet sinks 1 mm into the support at 0.3 s
    state[2, 0] += 0.01  # and slid 10 mm before
    modes = np.zeros((5, 3), dtype=np.int64)
    modes[:, 0] = 3
    events = (np.array([0.0, 0.35]), np.array([0, 1]), np.array([-1, 3]), np.array([3, 3]))
    istate = np.zeros(body_state.I_SIZE, dtype=np.int64)
    istate[body_state.I_EVENTS] = 2
    time, width = np.arange(5) * 0.1, _base_width(body)
    rows = _history_rows(body_parameters(body, GRAVITY), time, state, modes, np.zeros((5, 2)),
                         events[0], lost_contact_depth(width, 1e-7))  # fmt: skip
    history = _result(body, width, istate, time, state, events, rows)
    assert history.status == "failed" and not history.overturned
    assert history.message.startswith("a base point went 0.001 m below the support at t = 0.3 s")
    assert history.time.tolist() == [0.0, 0.1, 0.2] and len(history.events) == 1
    assert history.max_slide == pytest.approx(0.01)
