"""The worked cask example (docs/cask.md): the model, the comparison's JSON and the doc's
table, and a reduced campaign through fs, the comparison script and the command line."""

from __future__ import annotations

import importlib.util
import json
import math
import shutil
from pathlib import Path

import pytest

import freestand as fs
from tests.conftest import run_freestand

ROOT = Path(__file__).resolve().parents[1]
CASK = ROOT / "examples" / "cask.toml"
PACKAGED = ROOT / "src" / "freestand" / "examples" / "cask.toml"
COMPARISON = ROOT / "examples" / "cask-comparison.json"
DOC = ROOT / "docs" / "cask.md"
OUTCOMES = ["slide:cask>0.1m", "rotation:cask>0.5alpha", "overturn:cask"]
FRICTION = "cask.friction.static=uniform(0.2,0.8)"


def test_the_cask_model_loads_and_screens():
    model = fs.load_model(CASK)
    body = model.body_configuration("cask").body
    assert (body.shape.radius, body.shape.height, body.mass) == (1.683, 6.083, 163000.0)
    assert body.centre[2] == 3.0 and body.friction.static == 0.6
    planar = next(c for c in model.configurations if c.name == "cask-planar").blocks[0]
    # the planar section: the same mass, centre of gravity, base and inertia about a diameter
    assert planar.mass == body.mass and planar.centre[1] == body.centre[2]
    assert planar.base_right == -planar.base_left == body.shape.radius
    assert planar.inertia == pytest.approx(body.inertia[0, 0])
    assert body.inertia[0, 0] == pytest.approx(163000 * (3 * 1.683**2 + 6.083**2) / 12, abs=1)
    cases = {case.excitation: case for case in fs.screen(model, directions=8).body_cases}
    assert {d.motion for d in cases["0.3 g"].directions} == {"rest"}
    assert {d.motion for d in cases["0.6 g"].directions} == {"slide"}


def test_the_cask_is_a_packaged_example():
    assert PACKAGED.read_text() == CASK.read_text()
    result = run_freestand("example", "cask")
    assert result.returncode == 0 and result.stdout == CASK.read_text()


def _doc_rows() -> dict:
    text = DOC.read_text()
    table = text[text.index("| method | outcome |") :].split("\n\n")[0].splitlines()[2:]
    rows = {}
    for line in table:
        cells = [c.strip() for c in line.strip("|").split("|")]
        rows[cells[0], cells[1]] = cells[2:]
    return rows


def test_the_doc_table_agrees_with_the_json():
    document = json.loads(COMPARISON.read_text())
    names = {"slide": "slide > 0.1 m", "tilt": "tilt > 0.5 alpha", "overturn": "overturn"}
    rows = _doc_rows()
    expected = {
        **document["fragility"],
        **{
            f"{method}, mu_0 > R/h": fits
            for method, fits in document["friction_above_tan_alpha"]["fragility"].items()
        },
    }
    assert len(rows) == sum(len(fits) for fits in expected.values()) == 18
    for method, fits in expected.items():
        for key, fit in fits.items():
            median, interval, beta, hclpf = rows[method, names[key]]
            if fit["fitted"]:
                assert median.startswith(f"{fit['median']:.2f} ({fit['median'] / 9.81:.2f} g)")
                low, high = fit["median_interval"]
                assert interval == f"{low:.2f} to {high:.2f}"
                assert beta == f"{fit['beta']:.2f}"
                assert hclpf == f"{fit['hclpf']:.2f} ({fit['hclpf'] / 9.81:.2f} g)"
            else:
                assert median == f"not fitted: {sum(fit['counts'])} of {sum(fit['totals'])}"
    # the counts the text quotes
    text = " ".join(DOC.read_text().split())
    simulations = document["simulations"]
    assert f"{simulations['3-D']['capped']} of the 1,200 3-D simulations were capped" in text
    assert all(s["failed"] == 0 for s in simulations.values())
    paired = document["paired"]
    assert (
        f"slide {paired['slide']['both']} both, {paired['slide']['3-D only']} in 3-D only, "
        f"{paired['slide']['planar only']} planar only" in text
    )
    overturned = paired["overturn"]["both"] + paired["overturn"]["3-D only"]
    assert f"overturned in {overturned} of its 1,200 simulations" in text
    assert f"In {document['three_d_peaks']['twist_above_90deg']} of the 1,200" in text
    peaks = document["three_d_peaks"]
    assert f"free flight in {peaks['flight']} of 1,200" in text
    assert f"{peaks['flight_overturned']} of the {peaks['flight']} overturned" in text
    assert peaks["flight_with_friction_below_tan_alpha"] == 0  # "all with ... above R/h"


@pytest.fixture(scope="module")
def small_suite(tmp_path_factory):
    """Two three-component RG 1.60 records of 6 s, as the example's suite is generated."""
    folder = tmp_path_factory.mktemp("cask") / "cask-records"
    fs.generate_suite(
        "rg1.60:pga=0.3g,damping=5%", count=2, duration=6.0, seed=20, horizontal_y=True,
        vertical="rg1.60:pga=0.2g,damping=5%,direction=vertical", output=folder,
    )  # fmt: skip
    return folder


def test_a_reduced_campaign_runs_through_fs_and_the_command_line(small_suite):
    model = fs.load_model(CASK)
    result = fs.fragility(
        model, small_suite / "suite.toml", "pga-rotd50", "0.5g:1.5g:2", OUTCOMES,
        configuration="cask", vary=[FRICTION], samples=2, seed=20, bootstrap=20, workers=1,
        free_time=3.0,
    )  # fmt: skip
    document = result.to_dict()
    assert document["simulations"] == 8 and document["failed"] == 0
    assert document["im"]["kind"] == "pga-rotd50" and document["angles"] == "uniform"
    folder = small_suite.parent
    shutil.copy(CASK, folder / "cask.toml")
    cli = run_freestand(
        "fragility", "cask.toml", "-c", "cask", "--suite", "cask-records/suite.toml",
        "--levels", "0.5g:1.5g:2", "--vary", FRICTION, "--samples", "2", "--seed", "20",
        "--bootstrap", "20", "--workers", "1", "--free-time", "3",
        *(a for outcome in OUTCOMES for a in ("--outcome", outcome)), "--json", cwd=folder,
    )  # fmt: skip
    assert cli.returncode == 0, cli.stderr
    from_cli = json.loads(cli.stdout)
    assert from_cli["failed"] == 0 and from_cli["statuses"] == document["statuses"]
    for a, b in zip(from_cli["outcomes"], document["outcomes"], strict=True):
        assert a["counts"] == b["counts"]


def test_the_comparison_script_runs_reduced(small_suite):
    spec = importlib.util.spec_from_file_location(
        "cask_comparison", ROOT / "examples" / "cask_comparison.py"
    )
    script = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(script)
    document = script.run(
        records=2, levels="0.5g:1.5g:2", samples=1, workers=1, suite_folder=small_suite,
        bootstrap=20, free_time=3.0,
    )  # fmt: skip
    for counts in document["simulations"].values():
        assert counts["failed"] == 0 and counts["completed"] + counts["capped"] == 4
    assert set(document["fragility"]) == {
        "3-D", "planar x", "planar y", "planar, worse of x and y"
    }  # fmt: skip
    for key in ("slide", "tilt", "overturn"):
        worse = document["fragility"]["planar, worse of x and y"][key]["counts"]
        x = document["fragility"]["planar x"][key]["counts"]
        y = document["fragility"]["planar y"][key]["counts"]
        assert all(w >= max(a, b) for w, a, b in zip(worse, x, y, strict=True))
        assert sum(document["paired"][key].values()) == 4
    assert document["suite"]["rotd50_over_larger_pga"]["min"] >= 1.0 - 1e-9
    assert not math.isnan(document["runtime"]["three_d_seconds"])
    assert document["suite"]["records"] == 2
