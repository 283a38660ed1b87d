"""Single-block fast path: assumptions, fallback, front end, uplift flag (issue 7)."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from freestand.core.dynamics.single_block import simulate_single_block
from freestand.core.dynamics.timehistory import SupportMotion, simulate
from freestand.core.model import Block, Friction, Sliding, Stack
from freestand.core.rocking.integrator import SampledAcceleration
from freestand.core.rocking.integrator import simulate as simulate_rocking
from freestand.core.rocking.properties import RockingBlock
from freestand.io.model_file import load_model
from tests.conftest import CRANE, run_freestand

RECORD = Path(__file__).resolve().parents[1] / "examples" / "records" / "synthetic_H.AT2"

BLOCK = Block(
    "block", 500.0, 500.0 * (0.6**2 + 2.0**2) / 12.0, (0.0, 1.0), -0.3, 0.3, 0.0,
    Friction(0.8, 0.7),
)  # fmt: skip


def pulse(amplitude: float, vertical: float | None = None, length: float = 0.5) -> SupportMotion:
    time = np.linspace(0.0, length, 201)
    horizontal = amplitude * np.sin(np.pi * time / length)
    down = None if vertical is None else np.full(time.size, vertical)
    return SupportMotion(time[1] - time[0], horizontal, down)


def test_constant_vertical_record_equals_the_constant_effective_gravity():
    rng = np.random.default_rng(3)
    values = np.convolve(rng.standard_normal(801), np.ones(20) / 20, mode="same") * 6.0
    constant = RockingBlock.from_block(BLOCK, "left", vertical_acceleration=2.0)
    plain = RockingBlock.from_block(BLOCK, "left")
    a = simulate_rocking(constant, SampledAcceleration(values, 0.005), t_end=3.9, max_step=1e-3)
    b = simulate_rocking(
        plain,
        SampledAcceleration(values, 0.005, vertical=np.full(values.size, 2.0)),
        t_end=3.9,
        max_step=1e-3,
    )
    assert a.rocked and a.impacts > 0
    assert b.max_abs_rotation == pytest.approx(a.max_abs_rotation, rel=1e-12)
    # impacts match; only the settling threshold of a Zeno sequence (scaled by the
    # block's g, not g - a_v) may differ
    assert a.impact_log is None and abs(b.impacts - a.impacts) <= 2


def test_vertical_record_must_match_the_horizontal():
    with pytest.raises(ValueError, match="vertical"):
        SampledAcceleration(np.zeros(10), 0.01, vertical=np.zeros(9))


def test_auto_uses_the_fast_path_for_one_block_and_general_for_a_stack():
    rocking = simulate(Stack("one", (BLOCK,)), pulse(4.0), 2.0)
    assert rocking.diagnostics.method == "single-block rocking"
    assert rocking.diagnostics.fallback == ""
    assert rocking.uplift[0] and rocking.max_lift[0] > 0.0
    crane = load_model(CRANE).configurations[0]
    general = simulate(crane, pulse(1.0), 0.3)
    assert general.diagnostics.method == "general"


def test_front_end_rejects_unknown_or_inapplicable_methods():
    with pytest.raises(ValueError, match="unknown method"):
        simulate(Stack("one", (BLOCK,)), pulse(1.0), method="fast")
    crane = load_model(CRANE).configurations[0]
    with pytest.raises(ValueError, match="single-block path needs"):
        simulate(crane, pulse(1.0), method="single-block")
    with pytest.raises(ValueError, match="single-block path needs"):
        simulate(Stack("one", (BLOCK,)), lambda t: (0.0, 0.0), 1.0, method="single-block")


def test_slide_rock_falls_back_to_the_general_path():
    # tan(alpha) = 0.3 and mu_0 = 0.32: rocking needs more friction, sliding lifts it
    block = replace(BLOCK, friction=Friction(0.32, 0.3))
    result = simulate(Stack("one", (block,)), pulse(6.0), 1.0)
    assert result.diagnostics.method == "general"
    assert "slips" in result.diagnostics.fallback
    assert result.diagnostics.checks


def test_free_flight_falls_back_to_the_general_path():
    attempt = simulate_single_block(Stack("one", (BLOCK,)), pulse(1.0, vertical=11.0), 0.4)
    assert attempt.result is None
    assert "free flight" in attempt.failure


def test_sliding_with_an_end_stop_falls_back():
    squat = Block(
        "squat", 800.0, 800.0 * 5.0 / 12.0, (0.0, 0.5), -1.0, 1.0, 0.0, Friction(0.2, 0.15),
        Sliding.NO_RIGHT,
    )  # fmt: skip
    result = simulate(Stack("one", (squat,)), pulse(5.0), 1.5)
    assert result.diagnostics.method == "general"
    assert "end stop" in result.diagnostics.fallback
    free = simulate(Stack("one", (replace(squat, sliding=Sliding.FREE),)), pulse(5.0), 1.5)
    assert free.diagnostics.method == "single-block sliding"
    # the stop holds the block against +x slip; without it the block slides to -x here:
    # the pulse pushes the support to +x, the block lags to -x, both agree until it returns
    assert free.slide[:, 0].min() < -0.01


def test_crane_bridge_momentary_lift_off_is_not_uplift():
    # the known doubt of issue 7: a lift-off event at round-off level (5e-10 rad)
    result = run_freestand(
        "simulate", str(CRANE), "-c", "x-z cart right", "--record", str(RECORD),
        "--peak", "8", "--duration", "4", "--json",
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    assert document["method"] == "general"
    bridge, cart = document["blocks"]
    assert bridge["max_rotation"] < 1e-8
    assert not bridge["uplift"]
    assert cart["uplift"]  # the cart does rock


def test_uplift_needs_a_gap_of_a_micrometre_per_metre_of_base():
    # a pulse just above the uplift threshold lifts the corner by far less than 1e-6 of
    # the base: the motion is reported, the uplift flag is not set
    threshold = 9.81 * 0.3
    tiny = simulate(Stack("one", (BLOCK,)), pulse(threshold * 1.0000001), 1.0)
    assert tiny.diagnostics.method == "single-block rocking"
    assert 0.0 < tiny.max_lift[0] < 1e-6 * 0.6
    assert not tiny.uplift[0]
    general = simulate(Stack("one", (BLOCK,)), pulse(threshold * 1.0000001), 1.0, method="general")
    assert not general.uplift[0]
