"""Public records API: fs.response_spectrum, fs.generate_suite, fs.floor_motion.

Each result's ``to_dict()`` is the command's ``--json`` document (the real
command is run), ``to_frame()`` has the documented columns and ``plot()``
draws the documented content.
"""

from __future__ import annotations

import doctest
import json
import shutil
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest

import freestand as fs
from freestand.errors import FreestandError
from tests.conftest import ROOT, run_freestand

RG = "rg1.60:pga=0.3g,damping=5%"
RG_V = "rg1.60:pga=0.3g,damping=5%,direction=vertical"
H = ROOT / "examples" / "records" / "synthetic_H.AT2"
UP = ROOT / "examples" / "records" / "synthetic_UP.AT2"


def _normal(document: dict) -> dict:
    """JSON normalisation: what json.dumps / json.loads make of it."""
    return json.loads(json.dumps(document))


@pytest.fixture(scope="module")
def three(tmp_path_factory):
    """A three-component suite written by the command, and the same by the API."""
    base = tmp_path_factory.mktemp("three")
    folder = base / "suite"
    arguments = ("--target", RG, "--count", "2", "--duration", "8", "--seed", "11",
                 "--horizontal-y", "same", "--vertical", RG_V)  # fmt: skip
    result = run_freestand("records", "generate", *arguments, "--output", str(folder), "--json")
    assert result.returncode == 0, result.stdout + result.stderr
    command = base / "command"
    shutil.move(folder, command)
    suite = fs.generate_suite(RG, 2, 8.0, 11, horizontal_y="same", vertical=RG_V, output=folder)
    return base, folder, command, json.loads(result.stdout), suite


def test_generate_suite_to_dict_is_the_command_json(three):
    _, folder, command, document, suite = three
    # the same output folder (the command's was moved away): the same document
    assert _normal(suite.to_dict()) == document
    assert document["status"] == "accepted"
    assert [Path(f).name for f in document["files"]] == ["suite.toml", "acceptance.json"]
    # and the same bytes: records, suite file, acceptance checks
    names = sorted(p.name for p in folder.iterdir())
    assert names == sorted(p.name for p in command.iterdir())
    assert "rec01_X.AT2" in names and "rec01_Y.AT2" in names and "rec01_UP.AT2" in names
    for name in names:
        assert (folder / name).read_bytes() == (command / name).read_bytes(), name
    acceptance = json.loads((folder / "acceptance.json").read_text())
    assert acceptance == {k: v for k, v in document.items()
                          if k not in ("output", "suite_file", "files")}  # fmt: skip


def test_generate_suite_reports_independence_per_record_and_suite(three):
    _, _, _, document, suite = three
    independence = document["independence"]
    assert independence["limit"] == 0.3 and independence["passed"]
    assert len(independence["records"]) == 2
    for record, motion in zip(independence["records"], suite.motions, strict=True):
        assert set(record["pairs"]) == {
            "horizontal-horizontal_y", "horizontal-vertical", "horizontal_y-vertical"
        }  # fmt: skip
        r = np.corrcoef([motion.horizontal, motion.horizontal_y, -motion.vertical])
        assert record["pairs"]["horizontal-horizontal_y"] == pytest.approx(abs(r[0, 1]))
        assert record["pairs"]["horizontal_y-vertical"] == pytest.approx(abs(r[1, 2]))
        assert record["max"] < 0.3
    assert independence["max"] == max(r["max"] for r in independence["records"])
    # every component checked like the first
    for key in ("horizontal", "horizontal_y", "vertical"):
        assert document[key]["mean_ratio_min"] >= 1.0
        for record in document[key]["records"]:
            assert 0.9 <= record["min_ratio"] and record["max_ratio"] <= 1.3
            assert abs(record["peak_ratio"] - 1.0) <= 0.05 and record["duration_5_75"] > 0


def test_generate_suite_frame_and_figure(three):
    *_, suite = three
    frame = suite.to_frame()
    assert list(frame.columns) == [
        "record", "component", "min_ratio [-]", "min_ratio_frequency [Hz]", "max_ratio [-]",
        "max_ratio_frequency [Hz]", "peak_acceleration [m/s^2]",
        "zero_period_acceleration [m/s^2]", "peak_ratio [-]", "duration_5_75 [s]",
        "final_velocity [m/s]", "final_displacement [m]", "iterations", "attempts", "passed",
        "component_correlation [-]",
    ]  # fmt: skip
    assert len(frame) == 6 and set(frame["component"]) == {"horizontal", "horizontal_y", "vertical"}
    assert frame.attrs["status"] == "accepted" and frame["passed"].all()
    figure = suite.plot()
    # one column per component: spectra above, ratios below
    assert len(figure.axes) == 6
    titles = [axes.get_title() for axes in figure.axes[:3]]
    assert titles[0].startswith("x (horizontal)") and titles[1].startswith("y (second")
    assert titles[2].startswith("vertical")
    spectra = figure.axes[0]
    labels = [line.get_label() for line in spectra.get_lines()]
    assert labels.count("records (2)") == 1 and "mean" in labels and "target" in labels
    assert "pseudo-acceleration [m/s$^2$]" in spectra.get_ylabel()
    assert figure.axes[3].get_ylabel() == "record / target [-]"
    assert figure.axes[3].get_xlabel() == "frequency [Hz]"


def test_response_spectrum_to_dict_is_the_command_json(three):
    _, folder, *_ = three
    files = [str(folder / name) for name in ("rec01_X.AT2", "rec01_Y.AT2", "rec01_UP.AT2")]
    result = run_freestand("records", "spectrum", *files, "--target", RG,
                           "--vertical-target", RG_V, "--json")  # fmt: skip
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    spectra = fs.response_spectrum(files, target=RG, vertical_target=RG_V)
    assert _normal(spectra.to_dict()) == document
    # the three files were paired into one record, and the document says how
    assert [(r["record"], r["component"]) for r in document["records"]] == [
        ("rec01", "horizontal"), ("rec01", "horizontal_y"), ("rec01", "vertical")
    ]  # fmt: skip
    (pairing,) = document["pairing"]
    assert pairing["method"] == "file names"
    assert pairing["components"]["horizontal_y"]["file"].endswith("rec01_Y.AT2")
    # each component against its own target: within the acceptance band
    for row in document["records"]:
        assert 0.9 <= row["min_ratio"] and row["max_ratio"] <= 1.3
    text = run_freestand("records", "spectrum", *files).stdout
    assert "paired: rec01: x = rec01_X.AT2" in text and "horizontal_y" in text


def test_response_spectrum_frame_and_figure():
    spectra = fs.response_spectrum([H, UP], target=RG, vertical_target=RG_V)
    frame = spectra.to_frame()
    assert list(frame.columns) == [
        "record", "component", "frequency [Hz]", "psa [m/s^2]", "target [m/s^2]", "ratio [-]"
    ]  # fmt: skip
    assert len(frame) == 2 * 301 and frame.attrs["damping"] == 0.05
    vertical = frame[frame["component"] == "vertical"]
    np.testing.assert_allclose(vertical["ratio [-]"], vertical["psa [m/s^2]"]
                               / vertical["target [m/s^2]"])  # fmt: skip
    figure = spectra.plot()
    upper, lower = figure.axes
    assert upper.get_xlabel() == "" and lower.get_xlabel() == "frequency [Hz]"
    labels = [line.get_label() for line in upper.get_lines()]
    assert "synthetic (horizontal)" in labels and "synthetic (vertical)" in labels
    assert spectra.targets["vertical"].label in labels
    assert len(lower.get_lines()) == 2 + 3  # two ratios, the band and 1
    # into given axes: the spectra only
    from matplotlib.figure import Figure

    axes = Figure().add_subplot()
    assert spectra.plot(ax=axes) is axes.figure and len(axes.figure.axes) == 1
    # a GroundMotion works as well, and a spectrum is reusable as a Spectrum
    motion = fs.load_record(H)
    one = fs.response_spectrum(motion, damping="2%")
    assert one.damping == 0.02 and one.spectra[0].direction == "horizontal"
    np.testing.assert_array_equal(one.spectra[0].acceleration, one.rows[0]["psa"])


def test_floor_motion_to_dict_is_the_command_json(tmp_path):
    command = tmp_path / "command.csv"
    result = run_freestand("records", "floor", str(H), "--vertical", str(UP), "--frequency",
                           "2.5Hz", "--output", str(command), "--json")  # fmt: skip
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    floor = fs.floor_motion(H, "2.5Hz", "5%", vertical=UP, output=command)
    assert _normal(floor.to_dict()) == document
    assert document["output_vertical"].endswith("command_UP.csv")
    frame = floor.to_frame()
    assert list(frame.columns) == [
        "time [s]", "ground [m/s^2]", "floor [m/s^2]", "ground_vertical [m/s^2]",
        "floor_vertical [m/s^2]",
    ]  # fmt: skip
    assert frame["floor [m/s^2]"].abs().max() == pytest.approx(document["floor_peak"])
    assert frame["time [s]"].iloc[-1] == pytest.approx(document["duration"])
    figure = floor.plot()
    (axes,) = figure.axes
    assert {line.get_label() for line in axes.get_lines()} == {
        "ground", "floor (oscillator absolute acceleration)"
    }  # fmt: skip
    assert axes.get_xlabel() == "time [s]" and "2.5 Hz, 5 % damping" in axes.get_title()


def test_floor_motion_of_two_horizontal_components(three, tmp_path):
    *_, suite = three
    motion = suite.motions[0]
    floor = fs.floor_motion(motion, 2.5, 0.05, output=tmp_path / "floor.AT2")
    document = floor.to_dict()
    assert document["floor_peak_y"] == pytest.approx(floor.floor.peak_horizontal_y)
    assert Path(document["output_y"]).name == "floor_Y.AT2"
    written = fs.load_record(document["output_y"])
    assert written.peak_horizontal == pytest.approx(document["floor_peak_y"], rel=1e-6)


def test_input_errors_name_the_parameter(tmp_path):
    with pytest.raises(FreestandError, match="^count: 0 records"):
        fs.generate_suite(RG, 0, 8.0, 1)
    with pytest.raises(FreestandError, match="^horizontal_y: .*rg1.61"):
        fs.generate_suite(RG, 1, 8.0, 1, horizontal_y="rg1.61:pga=0.3g")
    with pytest.raises(FreestandError, match="^output: .*not empty"):
        (tmp_path / "full").mkdir()
        (tmp_path / "full" / "x").write_text("x")
        fs.generate_suite(RG, 1, 8.0, 1, output=tmp_path / "full")
    with pytest.raises(FreestandError, match="^frequency: "):
        fs.floor_motion(H, "fast")
    with pytest.raises(FreestandError, match="^output: .*.at2 or .csv"):
        fs.floor_motion(H, 2.5, output=tmp_path / "floor.txt")
    # on the command line the same errors name the options
    result = run_freestand("records", "generate", "--target", RG, "--count", "1",
                           "--horizontal-y", "rg1.61:pga=0.3g", "--output", str(tmp_path / "o"))  # fmt: skip
    assert result.returncode == 2 and "--horizontal-y" in result.stderr
    assert "Traceback" not in result.stderr and not (tmp_path / "o").exists()


def test_docstring_examples_run(monkeypatch):
    import freestand.api.records as module

    monkeypatch.chdir(ROOT)
    failures, attempted = doctest.testmod(module, optionflags=doctest.ELLIPSIS)
    assert attempted >= 10 and failures == 0


def test_a_planar_model_takes_one_component_ims_of_three_component_records(three, tmp_path):
    from tests.test_cli_fragility import MODEL

    _, folder, *_ = three
    (tmp_path / "block.toml").write_text(MODEL)
    arguments = ("fragility", "block.toml", "--suite", str(folder / "suite.toml"),
                 "--levels", "1:2:2", "--outcome", "uplift:block", "--workers", "1",
                 "--bootstrap", "20", "--json")  # fmt: skip
    result = run_freestand(*arguments, "--im", "pga", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    assert document["im"] == {"kind": "pga", "unit": "m/s^2"}
    assert document["simulations"] == 4
    # the planar block moves under x alone: an IM of x and y is refused, naming the option,
    # before any simulation (it is for 3-D configurations)
    result = run_freestand(*arguments, "--im", "pga-rotd50", cwd=tmp_path)
    assert result.returncode == 2, result.stdout
    assert "--im" in result.stderr and "two horizontal components" in result.stderr
    assert "'block' is planar" in result.stderr and "Traceback" not in result.stderr
    model = fs.load_model(tmp_path / "block.toml")
    for im in ("sa-rotd100:2.5", "pgv-gm", fs.IntensityMeasure("pga-rotd100")):
        with pytest.raises(FreestandError, match=r"--im.*two horizontal.*'block' is planar"):
            fs.fragility(model, folder / "suite.toml", im=im, levels="1:2:2",
                         outcomes=["uplift:block"], workers=1)  # fmt: skip
