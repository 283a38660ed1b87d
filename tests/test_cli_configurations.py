"""Several ``-c/--configuration`` in ``overturn`` and ``simulate``; a failed simulation exits 1."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import pytest

from tests.conftest import CRANE, run_freestand

RECORD = Path(__file__).resolve().parents[1] / "examples" / "records" / "synthetic_H.AT2"
RIGHT, LEFT = "x-z cart right", "x-z cart left"


def test_overturn_checks_every_configuration_in_turn(tmp_path):
    result = run_freestand(
        "overturn", str(CRANE), "-c", RIGHT, "-c", LEFT, "-c", RIGHT, "-b", "cart",
        "--frequencies", "1", "--plot", str(tmp_path / "figures"), "--json",
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    documents = json.loads(result.stdout)
    # one document per configuration, in the order given, a repeated one once
    assert [d["configuration"] for d in documents] == [RIGHT, LEFT]
    # the cart leans the other way in the two parking positions
    assert [d["pivot"] for d in documents] == ["right", "left"]
    for document, folder in zip(documents, ("x-z_cart_right", "x-z_cart_left"), strict=True):
        names = {Path(path).name for path in document["figures"]}
        assert "fig7_half_sine_pulse.png" in names
        assert all(
            Path(path).parent == tmp_path / "figures" / folder for path in document["figures"]
        )
        assert all(Path(path).is_file() for path in document["figures"])
    # a single -c keeps the single document
    single = run_freestand(
        "overturn", str(CRANE), "-c", LEFT, "-b", "cart", "--frequencies", "1", "--json"
    )
    assert single.returncode == 0, single.stderr
    assert json.loads(single.stdout) == {**documents[1], "figures": []}


def test_overturn_several_configurations_print_a_set_of_tables_each():
    result = run_freestand(
        "overturn", str(CRANE), "-c", RIGHT, "-c", LEFT, "-b", "cart", "--frequencies", "1"
    )
    assert result.returncode == 0, result.stderr
    assert result.stdout.count("Rocking properties") == 2
    assert f"in '{RIGHT}'" in result.stdout and f"in '{LEFT}'" in result.stdout


def test_overturn_unknown_configuration_among_several_is_refused_before_computing(tmp_path):
    result = run_freestand(
        "overturn", str(CRANE), "-c", RIGHT, "-c", "x-z cart middle", "-b", "cart",
        "--plot", str(tmp_path / "figures"),
    )  # fmt: skip
    assert result.returncode == 2 and "Traceback" not in result.stderr
    assert "x-z cart middle" in result.stderr
    assert not (tmp_path / "figures").exists()


def test_simulate_runs_one_simulation_per_configuration():
    result = run_freestand(
        "simulate", str(CRANE), "-c", "y-z", "-c", RIGHT, "--record", str(RECORD),
        "--duration", "0.2", "--json",
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    documents = json.loads(result.stdout)
    assert [d["configuration"] for d in documents] == ["y-z", RIGHT]
    assert all(d["status"] == "completed" for d in documents)
    assert [b["name"] for b in documents[1]["blocks"]] == ["bridge", "cart"]
    text = run_freestand(
        "simulate", str(CRANE), "-c", "y-z", "-c", RIGHT, "--record", str(RECORD),
        "--duration", "0.2",
    )  # fmt: skip
    assert text.returncode == 0, text.stderr
    assert text.stdout.count("Peak response") == 2


@pytest.mark.parametrize("option", ["--plot", "--animate"])
def test_simulate_draws_one_configuration_only(option, tmp_path):
    target = tmp_path / ("figures" if option == "--plot" else "motion.gif")
    result = run_freestand(
        "simulate", str(CRANE), "-c", "y-z", "-c", RIGHT, "--record", str(RECORD),
        option, str(target),
    )  # fmt: skip
    assert result.returncode == 2 and "Traceback" not in result.stderr
    assert option in result.stderr and "give one -c" in result.stderr
    assert list(tmp_path.iterdir()) == []


def test_failed_simulation_exits_with_1(monkeypatch, capsys):
    """Injection: no model found makes the engine fail (a Painleve-type inconsistency is
    resolved by a tangential impact, see test_timehistory), so the real command line runs
    in-process (``freestand.cli.main``) with the engine's result marked failed."""
    import freestand.api.simulation as command
    from freestand.cli import main

    real = command._simulate_stack

    def failing(*args, **kwargs):
        result = real(*args, **kwargs)
        return dataclasses.replace(
            result, status="failed", message="at t = 0.1 s: no consistent contact mode"
        )

    monkeypatch.setattr(command, "_simulate_stack", failing)
    base = ["simulate", str(CRANE), "-c", "y-z", "--record", str(RECORD), "--duration", "0.1"]
    assert main([*base, "--json"]) == 1
    captured = capsys.readouterr()
    assert json.loads(captured.out)["status"] == "failed"  # the document is still written
    assert "Traceback" not in captured.out + captured.err
    assert "simulation of 'y-z' failed" in captured.err
    assert "no consistent contact mode" in captured.err
    assert main(base) == 1
    captured = capsys.readouterr()
    assert "status failed" in captured.out and "Peak response" in captured.out
    assert "simulation of 'y-z' failed" in captured.err and "Traceback" not in captured.err
