"""The real ``freestand simulate`` command (issue 7, in progress)."""

from __future__ import annotations

import json
from pathlib import Path

from tests.conftest import CRANE, run_freestand

RECORD = Path(__file__).resolve().parents[1] / "examples" / "records" / "synthetic_H.AT2"


def test_simulate_crane_under_the_synthetic_record():
    result = run_freestand(
        "simulate", str(CRANE), "-c", "x-z cart right", "--record", str(RECORD),
        "--peak", "8", "--duration", "2", "--json",
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    assert document["status"] == "completed"
    assert document["peak_horizontal"] == 8.0
    names = [block["name"] for block in document["blocks"]]
    assert names == ["bridge", "cart"]
    assert not any(block["overturned"] for block in document["blocks"])


def test_bad_record_gives_a_message(tmp_path):
    empty = tmp_path / "empty.AT2"
    empty.write_text("")
    result = run_freestand("simulate", str(CRANE), "-c", "y-z", "--record", str(empty))
    assert result.returncode == 2
    assert "empty.AT2" in result.stderr and "Traceback" not in result.stderr


def test_scale_and_peak_exclude_each_other():
    result = run_freestand(
        "simulate", str(CRANE), "-c", "y-z", "--record", str(RECORD), "--scale", "2", "--peak", "3"
    )
    assert result.returncode == 2 and "not both" in result.stderr
