"""The real ``freestand`` command: screen, example, bad input."""

from __future__ import annotations

import json

import pytest

from tests.conftest import CRANE, run_freestand


def test_screen_prints_the_paper_tables():
    result = run_freestand("screen", str(CRANE))
    assert result.returncode == 0, result.stderr
    out = result.stdout
    assert "paper Tables 2 and 4" in out and "paper Tables 3 and 5" in out
    assert "rock (right)" in out and "slide (+x)" in out
    assert "3.1.2.3: bridge slides, cart rests on it" in out
    assert "B: 235,803" in out  # cart rocking on its outer wheel, elastic structure


def test_screen_json_document():
    result = run_freestand("screen", str(CRANE), "--json")
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    assert document["model"] == "Bridge crane"
    assert len(document["cases"]) == 3 * 2 * 2  # configurations x excitations x senses
    first = document["cases"][0]
    assert (first["configuration"], first["excitation"], first["sense"]) == ("y-z", "rigid", "+")
    assert first["ambiguous"] is False
    bridge = first["blocks"][0]
    assert bridge["name"] == "bridge" and bridge["motion"] == "slide"
    assert bridge["acceleration"]["x"] == pytest.approx(1.208, abs=1e-3)
    assert set(bridge["base"]) == {"left", "right", "friction"}
    assert bridge["base"]["friction"] < 0  # the rails hold the bridge back against +x


def test_screen_one_configuration():
    result = run_freestand("screen", str(CRANE), "--json", "--configuration", "x-z cart left")
    document = json.loads(result.stdout)
    assert {case["configuration"] for case in document["cases"]} == {"x-z cart left"}


def test_example_prints_the_shipped_file():
    result = run_freestand("example", "crane")
    assert result.returncode == 0
    assert result.stdout == CRANE.read_text()


@pytest.mark.parametrize(
    ("args", "expected"),
    [
        (("screen", "does-not-exist.toml"), "cannot be read"),
        (("example", "tower"), "not a built-in example"),
        (("screen", str(CRANE), "--configuration", "z-z"), "no configuration named 'z-z'"),
    ],
)
def test_bad_arguments_give_a_message_not_a_traceback(args, expected):
    result = run_freestand(*args)
    assert result.returncode != 0
    assert expected in result.stderr
    assert "Traceback" not in result.stderr + result.stdout


def test_bad_model_file_through_the_command(tmp_path):
    model = tmp_path / "bad.toml"
    model.write_text(
        CRANE.read_text().replace("mass = 25600                    # kg", "mass = -25600  # kg")
    )
    result = run_freestand("screen", str(model))
    assert result.returncode == 2
    assert "bad.toml" in result.stderr and "mass" in result.stderr and "-25600" in result.stderr
    assert "Traceback" not in result.stderr
