"""The real ``freestand frequency`` command on the crane (paper section 6, Fig. 9)."""

from __future__ import annotations

import json

import pytest

from tests.conftest import CRANE, run_freestand


def test_frequency_json_reproduces_the_paper():
    result = run_freestand("frequency", str(CRANE), "--positions", "0,1.33,4.9", "--json")
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    support, outmost, middle = document["positions"]
    assert support["dunkerley"] == pytest.approx(21.6, abs=0.06)  # paper: 21.6 Hz at a support
    assert middle["dunkerley"] == pytest.approx(10.6, abs=0.05)  # paper: 10.6 Hz at mid-span
    assert outmost["dunkerley"] == pytest.approx(16.6, abs=0.05)
    assert all(row["exact"] >= row["dunkerley"] for row in document["positions"])
    # Paper section 6.1: the cart may jump when parked near mid-span, not at its outmost positions.
    assert middle["verdict"] == "jump possible" and outmost["verdict"] == "contact kept"
    assert document["jump_check"]["status"] == "jump possible"


def test_frequency_table_and_figure(tmp_path):
    result = run_freestand("frequency", str(CRANE), "--plot", str(tmp_path))
    assert result.returncode == 0, result.stderr
    assert "Verdict: jump possible" in result.stdout
    assert (tmp_path / "fig9_frequency.png").stat().st_size > 10_000
    assert "<svg" in (tmp_path / "fig9_frequency.svg").read_text()[:500]


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("--positions", "12"), "outside the span"),
        (("--positions", "a,b"), "not a number"),
        (("--spectrum", "rg1.60:pga=0.3g,damping=3%,direction=vertical"), "tabulates damping"),
    ],
)
def test_frequency_bad_options(args, message):
    result = run_freestand("frequency", str(CRANE), *args)
    assert result.returncode == 2
    assert message in result.stderr and "Traceback" not in result.stderr


def test_model_without_beam(tmp_path):
    text = CRANE.read_text().split("# --- bridge as a simply supported beam")[0]
    model = tmp_path / "nobeam.toml"
    model.write_text(text)
    result = run_freestand("frequency", str(model))
    assert result.returncode == 2 and "no [beam] section" in result.stderr
