"""The real ``freestand fragility`` command."""

from __future__ import annotations

import json

import pytest

from freestand.core.motion.ground_motion import half_sine_pulse
from freestand.io.records import write_at2
from freestand.io.suites import suite_text
from tests.conftest import CRANE, run_freestand

MODEL = """
name = "Block"
[[excitation]]
name = "none"
horizontal = 0.0
[[configuration]]
name = "block"
[[configuration.block]]
name = "block"
mass = 500
inertia = 266.6666666666667
centre = [0.0, 1.2]
base = { left = -0.4, right = 0.4, level = 0.0 }
friction = { static = 2.0, kinetic = 2.0 }
sliding = "none"
"""


@pytest.fixture()
def files(tmp_path):
    (tmp_path / "block.toml").write_text(MODEL)
    records = []
    for number, f in enumerate((1.5, 2.5, 3.5, 4.5)):
        motion = half_sine_pulse(1.0, frequency=f, dt=1.0 / (200.0 * f))
        write_at2(tmp_path / f"p{number}.AT2", motion, component="horizontal", title="pulse",
                  description=f"half-sine {f} Hz")  # fmt: skip
        records.append({"horizontal": f"p{number}.AT2", "name": f"p{number}"})
    (tmp_path / "suite.toml").write_text(suite_text("pulses", records))
    return tmp_path


def test_json_document(files):
    result = run_freestand(
        "fragility", "block.toml", "--suite", "suite.toml", "--levels", "0.3g:1.2g:4",
        "--outcome", "overturn:block", "--outcome", "rotation:block>0.5alpha",
        "--outcome", "uplift:block", "--workers", "1", "--bootstrap", "50", "--json",
        cwd=files,
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    assert document["model"] == "Block" and document["configuration"] == "block"
    assert document["im"] == {"kind": "pga", "unit": "m/s^2"}
    assert document["simulations"] == 16 and document["failed"] == 0
    names = [o["name"] for o in document["outcomes"]]
    assert names == ["block overturns", "block rotates > 0.5 alpha", "block uplifts"]
    first = document["outcomes"][0]
    assert first["kind"] == "overturn" and first["block"] == "block"
    # levels in SI: 0.3 g to 1.2 g
    assert first["levels"] == pytest.approx([0.3 * 9.81, 0.6 * 9.81, 0.9 * 9.81, 1.2 * 9.81])
    assert first["totals"] == [4, 4, 4, 4]
    for item in document["outcomes"]:
        if item["fitted"]:
            assert item["median"] > 0 and item["beta"] > 0 and item["reason"] is None
            assert item["median_interval"][0] <= item["median"] <= item["median_interval"][1]
        else:
            assert item["median"] is None and item["beta"] is None and item["reason"]
    # g tan(alpha) = g / 3: every pulse of 0.6 g and more lifts the block
    uplift = document["outcomes"][2]
    assert uplift["counts"][1:] == [4, 4, 4]


def test_table_plot_store_and_from_store(files):
    result = run_freestand(
        "fragility", "block.toml", "--suite", "suite.toml", "--levels", "3:12:4",
        "--both-polarities", "--workers", "2", "--store", "store", "--plot", "f.png",
        "--bootstrap", "50", cwd=files,
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    assert "block overturns" in result.stdout and "[m/s^2]" in result.stdout
    assert "HCLPF" in result.stdout and "counts per level" in result.stdout
    assert (files / "f.png").stat().st_size > 1000
    again = run_freestand(
        "fragility", "--from-store", "store", "--bootstrap", "50", "--json", cwd=files
    )
    assert again.returncode == 0, again.stderr
    document = json.loads(again.stdout)
    assert document["simulations"] == 32 and document["polarities"] == [1, -1]
    # a new outcome judged from the stored peak values
    other = run_freestand(
        "fragility", "--from-store", "store", "--outcome", "rotation:block>0.2rad", "--json",
        "--bootstrap", "0", cwd=files,
    )  # fmt: skip
    assert other.returncode == 0, other.stderr
    assert json.loads(other.stdout)["outcomes"][0]["name"] == "block rotates > 0.2 rad"


def test_store_of_another_campaign_is_refused(files):
    first = run_freestand("fragility", "block.toml", "--suite", "suite.toml", "--levels",
                          "3:12:3", "--workers", "1", "--store", "s", "--bootstrap", "0",
                          cwd=files)  # fmt: skip
    assert first.returncode == 0, first.stderr
    second = run_freestand("fragility", "block.toml", "--suite", "suite.toml", "--levels",
                           "3:12:4", "--workers", "1", "--store", "s", cwd=files)  # fmt: skip
    assert second.returncode == 2 and "another campaign" in second.stderr


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--levels", "3:12:4", "--outcome", "topple:block"], "not an outcome"),
        (["--levels", "3:12:4", "--outcome", "overturn:cart"], "no block 'cart'"),
        (["--levels", "3:12:4", "--outcome", "slide:block"], "give a threshold"),
        (["--levels", "12:3:4"], "positive and increasing"),
        (["--im", "sa", "--levels", "1:2:3"], "needs a frequency"),
        (["--im", "pgx", "--levels", "1:2:3"], "not an intensity measure"),
        ([], "--levels"),
        (["--levels", "1:2:3", "--vary", "horizontal=uniform(1,2)"], "block inputs only"),
        (["--levels", "1:2:3", "--plot", "f.txt"], ".png"),
    ],
)
def test_bad_options_give_messages(files, args, message, capsys, monkeypatch):
    """In-process (the same ``main`` as the console script) to keep the test fast."""
    from freestand.cli import main

    monkeypatch.chdir(files)
    monkeypatch.setenv("COLUMNS", "300")
    status = main(["fragility", "block.toml", "--suite", "suite.toml", *args])
    captured = capsys.readouterr()
    assert status == 2, captured.out
    assert message in captured.err and "Traceback" not in captured.err


def test_crane_defaults_name_every_block():
    from freestand.core.sweeps.fragility.outcomes import default_outcomes
    from freestand.io.model_file import load_model

    stack = load_model(CRANE).configuration("x-z cart right")
    keys = [o.key for o in default_outcomes(stack)]
    assert "overturn:bridge" in keys and "overturn:cart" in keys
    assert "flight:cart" in keys and "slide:cart>0.01m" in keys
    assert not any(k.startswith("slide:bridge") for k in keys)  # the bridge cannot slide


def test_every_simulation_invalid_exits_1(files, capsys, monkeypatch):
    """Sampled inputs that make no model are counted, and a campaign of nothing else fails."""
    from freestand.cli import main

    monkeypatch.chdir(files)
    status = main(["fragility", "block.toml", "--suite", "suite.toml", "--levels", "3:6:2",
                   "--vary", "block.mass=uniform(-2,-1)", "--samples", "2", "--workers", "1",
                   "--json"])  # fmt: skip
    captured = capsys.readouterr()
    assert status == 1
    document = json.loads(captured.out)
    assert document["failed"] == document["simulations"] == 16
    assert document["statuses"] == {"invalid": 16}
    assert "every simulation failed" in captured.err


def test_im_help_lists_the_two_component_measures():
    text = " ".join(run_freestand("fragility", "--help").stdout.split())
    for name in ("pga-gm", "pga-rotd50", "pga-rotd100", "pgv-gm", "pgv-rotd50", "pgv-rotd100",
                 "sa-gm:F[,DAMPING]", "sa-rotd50:F[,DAMPING]", "sa-rotd100:F[,DAMPING]"):  # fmt: skip
        assert name in text.replace("- ", "-"), name
