"""The public API: ``import freestand as fs`` gives the documented entry points."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import freestand as fs

ROOT = Path(__file__).resolve().parents[1]
CRANE = ROOT / "examples" / "crane.toml"
RECORD = ROOT / "examples" / "records" / "synthetic_H.AT2"


def test_every_public_name_resolves():
    for name in fs.__all__:
        assert getattr(fs, name) is not None, name
    with pytest.raises(AttributeError):
        fs.no_such_name  # noqa: B018


def test_readme_example_screen_and_simulate():
    model = fs.load_model(CRANE)
    stack = model.configuration("x-z cart right")
    results = fs.screen(stack, model.excitations, model.gravity)
    assert len(results) == 2 * len(model.excitations)
    motion = fs.load_record(RECORD).scaled_to_peak(8.0)
    result = fs.simulate(stack, motion, duration=2.0, gravity=model.gravity)
    assert result.status == "completed"
    assert result.block_names == ("bridge", "cart")


def test_simulate_takes_a_ground_motion_or_a_support_motion_alike():
    model = fs.load_model(CRANE)
    stack = model.configuration("y-z")
    motion = fs.load_record(RECORD).scaled_to_peak(3.0)
    support = fs.SupportMotion(motion.dt, np.asarray(motion.horizontal))
    first = fs.simulate(stack, motion, duration=1.0)
    second = fs.simulate(stack, support, duration=1.0)
    np.testing.assert_array_equal(first.max_rotation, second.max_rotation)
    with pytest.raises(TypeError, match="GroundMotion"):
        fs.simulate(stack, [1.0, 2.0], duration=1.0)


def test_a_single_excitation_is_screened_in_both_senses():
    model = fs.load_model(CRANE)
    stack = model.configuration("y-z")
    results = fs.screen(stack, model.excitations[0], model.gravity)
    assert len(results) == 2


def test_the_readme_python_tour_runs(monkeypatch, capsys, tmp_path):
    """Every Python block of the README's "Python API", in order, as a reader would run them."""
    text = (ROOT / "README.md").read_text()
    section = text.split("## Python API", 1)[1].split("\n## ", 1)[0]
    blocks = [part.split("```", 1)[0] for part in section.split("```python")[1:]]
    assert len(blocks) == 3
    (tmp_path / "examples").symlink_to(ROOT / "examples")
    monkeypatch.chdir(tmp_path)
    namespace: dict = {}
    for block in blocks:
        exec(compile(block, "README.md", "exec"), namespace)
    printed = capsys.readouterr().out
    assert "['y-z', 'x-z cart right', 'x-z cart left']" in printed
    assert "bridge  slide" in printed and "cart uplifts" in printed
    assert namespace["run"].status == "completed"
    assert list(namespace["fits"].columns[:2]) == ["outcome", "kind"]
    assert (tmp_path / "crane-fragility.png").stat().st_size > 10_000
    assert "uplift_threshold [m/s^2]" in printed  # the 3-D bodies by direction
    assert (tmp_path / "bodies-polar.png").stat().st_size > 10_000
    assert namespace["cask"].status == "completed"  # the 3-D time history
    assert namespace["cask"].max_slide[0] > 0.0
    assert (tmp_path / "cask-plan.png").stat().st_size > 10_000
    assert "['rock', 'rock']" in printed  # the cabinet at SL-2, both senses
