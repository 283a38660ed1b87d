"""``freestand overturn`` and ``fs.overturning`` on a 3-D configuration (issue #18, item 5).

One low frequency keeps the searches short (some tens of 3-D simulations per
pulse kind); the limits themselves are validated in
``tests/validation/test_body_overturning_pulses.py``.
"""

from __future__ import annotations

import json

import matplotlib
import pytest

import freestand as fs
from freestand.api.body_overturning import BODY_PULSE_COLUMNS
from tests.conftest import CRANE, ROOT, run_freestand

matplotlib.use("Agg")

BODIES = ROOT / "examples" / "bodies.toml"


@pytest.fixture(scope="module")
def cabinet():
    return fs.overturning(fs.load_model(BODIES), configuration="cabinet", direction=90.0,
                          frequencies=[0.25])  # fmt: skip


@pytest.fixture(scope="module")
def command(tmp_path_factory):
    folder = tmp_path_factory.mktemp("figures")
    result = run_freestand("overturn", str(BODIES), "-c", "cabinet", "--direction", "90",
                           "--frequencies", "0.25", "--json", "--plot", str(folder))  # fmt: skip
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout), folder


def test_the_json_is_the_results_dictionary(cabinet, command):
    document, folder = command
    assert document["figures"] == [str(folder / "half_sine_pulse_3d.png"),
                                   str(folder / "half_sine_pulse_3d.svg")]  # fmt: skip
    assert (folder / "half_sine_pulse_3d.png").stat().st_size > 0
    document["figures"] = []
    assert document == json.loads(json.dumps(cabinet.to_dict()))


def test_the_document_gives_the_direction_and_the_limits(command):
    document, _folder = command
    assert document["method"] == "3-D" and document["shape"] == "box"
    assert document["direction"] == 90.0 and document["direction_given"] is True
    assert document["pivot"] == "edge -y"
    (row,) = document["half_sine"]
    # along y the cabinet rocks in its y-z plane, as the planar block of that plane
    assert row["exact_3d"] == pytest.approx(row["planar_exact"], rel=2e-4)
    assert document["one_sine"][0]["exact_3d"] > document["uplift_threshold"]
    assert document["diagnostics"]["half_sine"]["simulations"] > 0
    assert document["diagnostics"]["half_sine"]["failed"] == 0


def test_the_table_has_the_documented_columns(cabinet):
    table = cabinet.to_frame()
    assert tuple(table.columns) == BODY_PULSE_COLUMNS
    assert len(table) == 1 and table.attrs["direction [deg]"] == 90.0


def test_the_figure_draws_the_3d_limit_over_the_planar_ones(cabinet):
    fig = cabinet.plot()
    (ax,) = fig.axes
    labels = [line.get_label() for line in ax.get_lines()]
    assert sum(label.startswith("planar, pulse's plane") for label in labels) == 3
    assert any(label.startswith("3-D exact, along 90 deg") for label in labels)
    assert "along 90 deg" in ax.get_title()
    assert ax.get_xlabel() == "pulse frequency f [Hz]"


def test_a_body_that_friction_keeps_flat_is_said_to_slide():
    result = run_freestand("overturn", str(BODIES), "-c", "cask", "--frequencies", "1")
    assert result.returncode == 0, result.stderr
    assert "under pulses along 0 deg (the lowest uplift threshold)" in result.stdout
    assert "Friction keeps the base flat" in result.stdout and "none found" in result.stdout


@pytest.mark.parametrize(
    ("model", "args", "message"),
    [
        (CRANE, ("-c", "x-z cart right", "-b", "cart", "--direction", "30"), "--direction 30"),
        (BODIES, ("-c", "cabinet", "--direction", "nan"), "not a direction"),
        (BODIES, ("-c", "cabinet", "--pivot", "left"), "--pivot is for planar blocks"),
    ],
)
def test_bad_input(model, args, message):
    result = run_freestand("overturn", str(model), *args)
    assert result.returncode == 2
    assert message in result.stderr and "Traceback" not in result.stderr


def test_the_api_refuses_a_direction_for_a_planar_block():
    with pytest.raises(fs.FreestandError, match="direction"):
        fs.overturning(fs.load_model(CRANE), configuration="x-z cart right", direction=10.0)


@pytest.mark.parametrize(
    ("options", "message"),
    [
        ({"amplitudes": [9.81]}, "--amplitudes is for planar blocks"),
        ({"restitution": 0.9}, "--restitution is for planar blocks"),
        ({"block": "door"}, "no block named 'door'"),
    ],
)
def test_the_api_refuses_planar_options_for_a_3d_body(options, message):
    with pytest.raises(fs.FreestandError, match=message):
        fs.overturning(fs.load_model(BODIES), configuration="cabinet", **options)
