"""What a person reads: units in help texts and table headers, flags as flags, map labels."""

from __future__ import annotations

import json
import re

import pytest

from tests.conftest import CRANE, ROOT, run_freestand

RECORD = ROOT / "examples" / "records" / "synthetic_H.AT2"
COMMANDS = ("screen", "example", "frequency", "map", "sample", "overturn", "simulate", "report")


def _flat(text: str) -> str:
    return re.sub(r"\s+", " ", text)


@pytest.mark.parametrize("command", COMMANDS)
def test_help_keeps_units_and_shows_flags_as_flags(command):
    result = run_freestand(command, "--help")
    assert result.returncode == 0, result.stderr
    text = result.stdout
    assert "<bool>" not in text
    assert re.search(r"--help\s+Show this message", text)
    if "--json" in text:
        assert re.search(r"--json\s+Write", text)  # a flag takes no value


@pytest.mark.parametrize(
    ("command", "expected"),
    [
        (
            "simulate",
            ("e.g. 0.005 [s] or '5 ms'", "factor [-]", "e.g. 10 [s] or '10 s'"),
        ),
        ("frequency", ("Model file (TOML) with a [beam] section",)),
        ("map", ("Grid nodes per axis",)),
    ],
)
def test_help_texts_keep_their_brackets(command, expected):
    text = _flat(run_freestand(command, "--help").stdout)
    for phrase in expected:
        assert phrase in text, phrase


def test_root_help_and_version():
    result = run_freestand("--help")
    assert result.returncode == 0
    assert "--version" in result.stdout and "simulate" in result.stdout


@pytest.mark.parametrize(
    ("args", "headers"),
    [
        (
            ("screen", str(CRANE), "-c", "y-z"),
            ("[1/s^2]", "[m/s^2]", "vertical, left [N]", "relative to the support"),
        ),
        (
            ("overturn", str(CRANE), "-c", "x-z cart right", "-b", "cart", "--frequencies", "1"),
            ("R [m]", "alpha [rad]", "p [rad/s]", "Housner [s]", "exact [m/s^2]", "weight m g"),
        ),
        (("frequency", str(CRANE), "--positions", "4.9"), ("position [m]", "Dunkerley [Hz]")),
        (
            ("simulate", str(CRANE), "-c", "y-z", "--record", str(RECORD), "--duration", "1"),
            ("max rotation [rad]", "max slide [m]"),
        ),
    ],
)
def test_table_headers_carry_units(args, headers):
    result = run_freestand(*args)
    assert result.returncode == 0, result.stderr
    text = _flat(result.stdout.replace("│", " ").replace("┃", " "))
    for header in headers:
        # a header may wrap inside its column: compare word by word
        assert all(word in text for word in header.split()), header


def test_screen_lists_blocks_bottom_to_top():
    result = run_freestand("screen", str(CRANE), "-c", "y-z", "--json")
    document = json.loads(result.stdout)
    assert [b["name"] for b in document["cases"][0]["blocks"]] == ["bridge", "cart"]
    table = run_freestand("screen", str(CRANE), "-c", "y-z").stdout
    rows = [line for line in table.splitlines() if "y-z" in line and "rigid" in line]
    assert "bridge" in rows[0] and "cart" in rows[1]


def test_map_points_are_the_cases_screen_computes():
    """A point shown on a map is the case screen computes for it, or it is not shown."""
    args = ("map", str(CRANE), "-c", "x-z cart right", "--x", "cart.mass=10000:40000")
    args += ("--y", "vertical=0:5", "--n", "20", "--json")
    shown = json.loads(run_freestand(*args).stdout)
    # the map takes the horizontal from 'rigid': the 'elastic' point would be mislabelled
    assert shown["points_not_shown"] == ["elastic"]
    assert all(p["excitation"] == "rigid" for m in shown["maps"] for p in m["points"])
    screened = json.loads(
        run_freestand("screen", str(CRANE), "-c", "x-z cart right", "--json").stdout
    )
    verbs = {"rest": "rests", "slide": "slides", "rock": "rocks", "slide-rock": "slide-rocks"}
    for excitation in ("rigid", "elastic"):
        mapped = json.loads(run_freestand(*args, "-e", excitation).stdout)
        for m in mapped["maps"]:
            (point,) = m["points"]
            case = next(
                c
                for c in screened["cases"]
                if c["excitation"] == excitation and c["sense"] == m["sense"]
            )
            for block in case["blocks"]:
                assert f"{block['name']} {verbs[block['motion']]}" in point["region"], (
                    excitation,
                    m["sense"],
                    point,
                )


def test_frequency_outside_the_parking_range_is_a_note_not_an_error():
    result = run_freestand("frequency", str(CRANE), "--positions", "0")
    assert result.returncode == 0, result.stderr
    assert "21.5" in result.stdout  # Dunkerley at the support (paper section 6)
    assert "outside the parking range" in _flat(result.stdout)
