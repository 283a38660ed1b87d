"""``freestand records``: spectrum, generate, floor (the real command line)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from freestand.io.records import load_record, read_at2_component
from freestand.io.suites import load_suite
from tests.conftest import run_freestand

RG = "rg1.60:pga=0.3g,damping=5%"


@pytest.fixture(scope="module")
def generated(tmp_path_factory):
    """A small suite generated twice with the same seed, once with another seed."""
    base = tmp_path_factory.mktemp("suites")
    runs = {}
    for label, seed in (("a", "7"), ("b", "7"), ("c", "8")):
        folder = base / label
        result = run_freestand(
            "records", "generate", "--target", RG, "--count", "2", "--duration", "8",
            "--seed", seed, "--output", str(folder), "--quiet",
            *(["--vertical", "rg1.60:pga=0.3g,damping=5%,direction=vertical"]
              if label != "c" else []),
            *(["--plot", str(base / "suite.png")] if label == "a" else []),
        )  # fmt: skip
        runs[label] = (folder, result)
    return base, runs


def test_generate_writes_records_and_a_suite_file(generated):
    base, runs = generated
    folder, result = runs["a"]
    assert result.returncode == 0, result.stdout + result.stderr
    assert "suite accepted" in result.stdout
    names = sorted(p.name for p in folder.iterdir())
    assert names == [
        "acceptance.json", "rec01_H.AT2", "rec01_UP.AT2", "rec02_H.AT2", "rec02_UP.AT2",
        "suite.toml",
    ]  # fmt: skip
    suite = load_suite(folder / "suite.toml")
    assert len(suite) == 2 and all(m.vertical is not None for m in suite.motions)
    assert suite.motions[0].dt == pytest.approx(0.005)
    checks = json.loads((folder / "acceptance.json").read_text())
    assert checks["status"] == "accepted"
    assert checks["horizontal"]["mean_ratio_min"] >= 1.0
    for record in checks["horizontal"]["records"] + checks["vertical"]["records"]:
        assert 0.9 <= record["min_ratio"] and record["max_ratio"] <= 1.3
        assert abs(record["peak_ratio"] - 1) <= 0.05
        assert record["duration_5_75"] > 0
    # x and vertical: the independence of each record's two components (SRP 3.7.1)
    assert [set(r["pairs"]) for r in checks["independence"]["records"]] == [
        {"horizontal-vertical"}, {"horizontal-vertical"}
    ]  # fmt: skip
    assert checks["independence"]["passed"] and "|r| x-vertical [-]" in result.stdout
    assert (base / "suite.png").stat().st_size > 10_000
    # the PGA in the file (in g, 7 digits) is the target's 0.3 g within 5 %
    assert suite.motions[0].peak_horizontal == pytest.approx(0.3 * 9.81, rel=0.05)


def test_generate_is_byte_identical_for_the_same_seed(generated):
    _, runs = generated
    a, b, c = (runs[k][0] for k in "abc")
    for path in sorted(a.iterdir()):
        assert path.read_bytes() == (b / path.name).read_bytes(), path.name
    assert (a / "rec01_H.AT2").read_bytes() != (c / "rec01_H.AT2").read_bytes()


def test_a_planar_suite_is_generated_as_before_the_second_horizontal_component(generated):
    # values of the files written for this seed before records could have a y component
    # (its seed stream comes after the vertical's): a suite without y draws as it did
    folder = generated[1]["a"][0]
    expected = {
        "rec01_H.AT2": ([0.2999606, 0.07408783], 24.922023492424547),
        "rec02_UP.AT2": ([1.6517953e-01, -2.9940099e-01], 17.58316728955045),
    }
    for name, (values, sum_of_squares) in expected.items():
        component = read_at2_component(folder / name)
        g = component.acceleration / 9.81
        # the files hold 8 significant digits
        np.testing.assert_allclose(g[[200, 700]], values, rtol=1e-6)
        assert np.sum(g * g) == pytest.approx(sum_of_squares, rel=1e-6)


def test_spectrum_of_a_suite_against_its_target(generated, tmp_path):
    folder = generated[1]["a"][0]
    csv_file = tmp_path / "spectra.csv"
    plot = tmp_path / "spectra.svg"
    result = run_freestand(
        "records", "spectrum", str(folder / "suite.toml"), "--target", RG,
        "--csv", str(csv_file), "--plot", str(plot),
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    assert "min PSA/target" in result.stdout and "rec01" in result.stdout
    assert "vertical" in result.stdout
    header = csv_file.read_text().splitlines()[0]
    assert header.startswith("frequency [Hz], target [m/s^2], rec01 (horizontal) PSA [m/s^2]")
    assert plot.read_text().startswith("<?xml")
    document = json.loads(
        run_freestand(
            "records", "spectrum", str(folder / "rec01_H.AT2"), "--target", RG, "--json"
        ).stdout
    )
    (record,) = document["records"]
    assert document["damping"] == 0.05
    # ratios over 0.2-50 Hz on this command's own grid: within the acceptance band
    assert 0.9 <= record["min_ratio"] and record["max_ratio"] <= 1.3
    assert record["peak_acceleration"] == pytest.approx(0.3 * 9.81, rel=0.05)


def test_floor_command(generated, tmp_path):
    record = generated[1]["a"][0] / "rec01_H.AT2"
    output = tmp_path / "floor.csv"
    result = run_freestand(
        "records", "floor", str(record), "--frequency", "2.5Hz", "--damping", "5%",
        "--output", str(output), "--json",
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    summary = json.loads(result.stdout)
    assert summary["floor_peak"] == pytest.approx(
        summary["spectral_absolute_acceleration"], rel=2e-3
    )
    floor = load_record(output)
    assert floor.peak_horizontal == pytest.approx(summary["floor_peak"], rel=1e-6)
    ground = load_record(record)
    assert floor.duration > ground.duration  # the structure's free vibration is kept
    text = run_freestand("records", "floor", str(record), "--frequency", "2.5").stdout
    assert "amplification" in text and "m/s^2" in text


def test_input_errors_exit_2_before_computing(generated, tmp_path):
    folder = generated[1]["a"][0]
    result = run_freestand(
        "records", "generate", "--target", RG, "--count", "1", "--output", str(folder)
    )
    assert result.returncode == 2 and "not empty" in result.stderr
    result = run_freestand(
        "records", "generate", "--target", RG, "--output", str(tmp_path / "x"), "--format", "v2"
    )
    assert result.returncode == 2 and "--format" in result.stderr
    assert not (tmp_path / "x").exists()
    result = run_freestand(
        "records", "floor", str(folder / "rec01_H.AT2"), "--frequency", "2.5Hz",
        "--output", str(tmp_path / "floor.txt"),
    )  # fmt: skip
    assert result.returncode == 2 and ".at2 or .csv" in result.stderr
    result = run_freestand("records", "spectrum", str(tmp_path / "missing.AT2"))
    assert result.returncode == 2 and "not found" in result.stderr
    assert "Traceback" not in result.stderr


def test_generate_three_components_with_their_own_targets(tmp_path):
    # the second horizontal component matched to a target of its own (EN 1998-1 here, RG
    # 1.60 for x), every component checked and each record's components independent
    folder = tmp_path / "three"
    y_target = "en1998:ag=2.0,ground=B,type=1"
    result = run_freestand(
        "records", "generate", "--target", RG, "--horizontal-y", y_target,
        "--vertical", "rg1.60:pga=0.3g,damping=5%,direction=vertical", "--count", "2",
        "--duration", "8", "--seed", "5", "--output", str(folder), "--quiet",
    )  # fmt: skip
    assert result.returncode == 0, result.stdout + result.stderr
    text = " ".join(result.stdout.split())
    assert "suite accepted" in text
    for title in ("horizontal: RG 1.60", "horizontal_y: EN 1998-1", "vertical: RG 1.60"):
        assert title in text, title
    assert "independence of each record's components (SRP 3.7.1)" in text
    for column in ("|r| x-y [-]", "|r| x-vertical [-]", "|r| y-vertical [-]", "largest [-]"):
        assert column in text, column
    checks = json.loads((folder / "acceptance.json").read_text())
    assert checks["status"] == "accepted" and checks["failures"] == []
    independence = checks["independence"]
    assert independence["passed"] and independence["max"] < 0.3
    assert (
        f"largest correlation coefficient of two components of a record: "
        f"{independence['max']:.3f}" in text
    )
    assert all(record["passed"] for record in independence["records"])
    for key in ("horizontal", "horizontal_y", "vertical"):
        assert checks[key]["mean_ratio_min"] >= 1.0, key
        assert all(r["min_ratio"] >= 0.9 and r["max_ratio"] <= 1.3
                   for r in checks[key]["records"]), key  # fmt: skip
    suite = load_suite(folder / "suite.toml")
    assert [m.components for m in suite.motions] == [("horizontal", "horizontal_y", "vertical")] * 2
    # each horizontal at its own target's zero-period acceleration (0.3 g; 2.0 m/s^2 x S = 1.2)
    assert suite.motions[0].peak_horizontal == pytest.approx(0.3 * 9.81, rel=0.05)
    assert suite.motions[0].peak_horizontal_y == pytest.approx(2.0 * 1.2, rel=0.05)


def test_failed_acceptance_exits_1_and_says_why(tmp_path):
    # a 2 s record cannot hold a 0.2 Hz oscillator's response: the command reports it
    result = run_freestand(
        "records", "generate", "--target", RG, "--count", "1", "--duration", "2",
        "--output", str(tmp_path / "short"), "--quiet",
    )  # fmt: skip
    assert result.returncode == 1, result.stdout
    assert "failed:" in result.stdout and "record 1 horizontal" in result.stdout
    checks = json.loads((tmp_path / "short" / "acceptance.json").read_text())
    assert checks["status"] == "failed" and checks["failures"]


def test_csv_format(tmp_path):
    folder = tmp_path / "csv"
    result = run_freestand(
        "records", "generate", "--target", "en1998:ag=2.5,ground=B,type=1", "--count", "2",
        "--duration", "10", "--seed", "2", "--output", str(folder), "--format", "csv", "--json",
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    assert document["status"] == "accepted"
    motion = load_suite(folder / "suite.toml").motions[0]
    assert np.max(np.abs(motion.horizontal)) == pytest.approx(
        document["horizontal"]["records"][0]["peak_acceleration"], rel=1e-6
    )


def test_floor_command_with_a_vertical_mode(generated, tmp_path):
    folder = generated[1]["a"][0]
    output = tmp_path / "floor.AT2"
    result = run_freestand(
        "records", "floor", str(folder / "rec01_H.AT2"), "--vertical", str(folder / "rec01_UP.AT2"),
        "--frequency", "2.5Hz", "--vertical-frequency", "8 Hz", "--output", str(output), "--json",
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    summary = json.loads(result.stdout)
    assert summary["vertical_frequency"] == 8.0
    assert summary["floor_peak_vertical"] > summary["ground_peak_vertical"]
    floor = load_record(output, vertical=tmp_path / "floor_UP.AT2")
    assert floor.peak_vertical == pytest.approx(summary["floor_peak_vertical"], rel=1e-6)
    text = run_freestand(
        "records", "floor", str(folder / "rec01_H.AT2"), "--frequency", "2.5Hz",
        "--vertical-frequency", "8Hz",
    )  # fmt: skip
    assert text.returncode == 2 and "--vertical FILE" in text.stderr
