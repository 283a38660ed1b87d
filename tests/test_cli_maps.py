"""``freestand map`` and ``freestand sample`` through the installed console script,
and the parsing of their parameter options."""

from __future__ import annotations

import csv
import json
import subprocess
import sys
from pathlib import Path

import pytest

from freestand.core.sweeps.sampling import Fixed, Normal, TruncatedNormal, Uniform
from freestand.errors import FreestandError
from freestand.io.model_file import load_model
from freestand.io.parameters import check_parameters, parse_axis, parse_variation

ROOT = Path(__file__).resolve().parents[1]
MODEL = ROOT / "examples" / "crane.toml"
SCRIPT = Path(sys.executable).with_name("freestand")


def run(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [str(SCRIPT), *args], capture_output=True, text=True, timeout=300, check=False
    )


def test_map_json_csv_and_plot(tmp_path):
    plot = tmp_path / "figures"
    table = tmp_path / "map.csv"
    done = run(
        "map",
        str(MODEL),
        "--configuration",
        "x-z cart right",
        "--x",
        "horizontal=0:12",
        "--y",
        "vertical=-3:10",
        "--n",
        "40",
        "--plot",
        str(plot),
        "--csv",
        str(table),
        "--json",
    )
    assert done.returncode == 0, done.stderr
    document = json.loads(done.stdout)
    senses = {m["sense"]: m for m in document["maps"]}
    assert set(senses) == {"+", "-"}
    regions = {p["excitation"]: p["region"] for p in senses["+"]["points"]}
    assert regions == {"rigid": "bridge rests, cart rests", "elastic": "bridge rests, cart rocks"}
    assert (plot / "map.png").stat().st_size > 10_000
    assert (plot / "map.svg").exists()
    assert document["files"][:2] == [str(plot / "map.png"), str(plot / "map.svg")]
    with table.open() as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) == 2 * 40 * 40
    assert rows[0]["cart.motion"] == "rest"


def test_map_of_friction_and_mass_prints_a_summary():
    done = run(
        "map",
        str(MODEL),
        "-c",
        "y-z",
        "--x",
        "friction.static=0.05:0.5",
        "--y",
        "cart.mass*=0.5:2",
        "--n",
        "30",
        "--excitation",
        "rigid",
        "--sense",
        "+",
    )
    assert done.returncode == 0, done.stderr
    assert "bridge slides, cart rests" in done.stdout
    assert "bridge rests, cart rests" in done.stdout


def test_sample_json_and_samples_file(tmp_path):
    samples = tmp_path / "samples.csv"
    done = run(
        "sample",
        str(MODEL),
        "--vary",
        "friction.static=uniform(0.15,0.35)",
        "--vary",
        "cart.centre.x+=normal(0,0.05)",
        "--n",
        "2000",
        "-c",
        "y-z",
        "--samples",
        str(samples),
        "--json",
    )
    assert done.returncode == 0, done.stderr
    document = json.loads(done.stdout)
    assert len(document["cases"]) == 4
    for case in document["cases"]:
        total = sum(m["probability"] for m in case["motions"] if m["block"] == "cart")
        assert total == pytest.approx(1.0)
    with samples.open() as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) == 4 * 2000
    assert 0.15 <= float(rows[0]["friction.static"]) <= 0.35


def test_sample_table_and_degenerate_distribution():
    done = run("sample", str(MODEL), "--vary", "friction.static=normal(0.25,0)", "--n", "100")
    assert done.returncode == 0, done.stderr
    assert "1.0000" in done.stdout


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (("sample", str(MODEL), "--vary", "cart.colour=1"), "is not a parameter"),
        (("sample", str(MODEL), "--vary", "friction.static=uniform(0.3,0.1)"), "low <= high"),
        (("sample", str(MODEL), "--vary", "crane.mass=1"), "has no block 'crane'"),
        (("sample", str(MODEL), "--vary", "horizontal=weibull(1,2)"), "not a distribution"),
        (("sample", str(MODEL), "--samples", "out.xlsx"), ".csv or .parquet"),
        (("map", str(MODEL), "--x", "horizontal=0-12"), "START:STOP"),
        (("map", str(MODEL), "--x", "horizontal=0:12 kg"), "acceleration"),
        (("map", str(MODEL), "--sense", "up"), "+, - or both"),
    ],
)
def test_errors_name_the_option_the_value_and_the_fix(args, words):
    done = run(*args)
    assert done.returncode == 2
    assert "Traceback" not in done.stderr
    assert words in done.stderr.replace("\n", "")


def test_parse_axis_and_units():
    axis = parse_axis("vertical=0 g:0.5 g", "--y", gravity=10.0)
    assert (axis.parameter.field, axis.start, axis.stop) == ("vertical", 0.0, 5.0)
    axis = parse_axis("cart.mass*=0.5:2", "--x")
    assert (axis.parameter.block, axis.parameter.operation) == ("cart", "scale")
    with pytest.raises(FreestandError, match="option --x"):
        parse_axis("horizontal", "--x")


def test_parse_variations():
    variation = parse_variation("cart.centre.x=normal(0.36,0.05)")
    assert variation.parameter.name == "cart.centre.x"
    assert variation.distribution == Normal(0.36, 0.05)
    assert parse_variation("friction.static=0.3").distribution == Fixed(0.3)
    assert parse_variation("friction.static=uniform(0.15, 0.35)").parameter.block is None
    assert parse_variation("bridge.mass=truncnormal(16.6 t, 1 t, 15 t, 18 t)").distribution == (
        TruncatedNormal(16600.0, 1000.0, 15000.0, 18000.0)
    )
    shift = parse_variation("horizontal+=uniform(-0.1 g,0.1 g)").distribution
    assert isinstance(shift, Uniform)
    assert (shift.low, shift.high) == pytest.approx((-0.981, 0.981), rel=1e-12)
    with pytest.raises(FreestandError, match="takes 2 argument"):
        parse_variation("friction.static=normal(0.3)")


def test_repeated_parameter_is_rejected():
    model = load_model(MODEL)
    variation = parse_variation("friction.static=0.3")
    with pytest.raises(FreestandError, match="already varied"):
        check_parameters(
            [(variation.parameter, "a"), (variation.parameter, "b")], model.configurations, "--vary"
        )
