"""Signed vertical support acceleration: upward grows the weight and the contact forces.

The screening of stacks at rest under an upward vertical acceleration is checked
against an independent hand solution (statics of rigid bodies on two supports),
through the real command with a model file; and the paper's observation (an
upward acceleration cannot start a motion that the same downward one does not,
section 2) is checked over a grid.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from freestand.core.contact.screening import Motion, force_envelope, initial_motion, screen
from freestand.core.model import Excitation
from freestand.io.model_file import load_model
from tests.conftest import CRANE, run_freestand

G = 9.81

#: Two blocks at rest: a cabinet (bottom) carrying a box, off-centre.
STACK_TOML = """
name = "cabinet and box"
gravity = 9.81

[[excitation]]
name = "floor"
horizontal = "2.0 m/s^2"
vertical = "-3.0 m/s^2"          # upward support acceleration
vertical_senses = "both"

[[configuration]]
name = "plane"

[[configuration.block]]
name = "cabinet"
mass = 1000
inertia = 300
centre = [0.0, 1.0]
base = { left = -0.5, right = 0.5, level = 0.0 }
friction = { static = 0.6, kinetic = 0.5 }

[[configuration.block]]
name = "box"
mass = 200
inertia = 20
centre = [0.1, 2.3]
base = { left = -0.2, right = 0.4, level = 2.0 }
friction = { static = 0.6, kinetic = 0.5 }
"""


def hand_forces(blocks, left, right, a_h, a_v, sense):
    """Normal forces at the two supports of the blocks resting on them, and the friction.

    All blocks at rest relative to the support: the inertial force s m a_h (along x)
    and the weight m (g - a_v) (down) of each block act at its centre; moments about
    the left support (counter-clockwise positive) give
    N_R (x_R - x_L) = sum W_i (x_i - x_L) + sum s m_i a_h z_i - (relative heights: z
    from the support level), N_L = sum W_i - N_R, T = -sum s m_i a_h.
    """
    level = blocks[0][3]
    weight = sum(m * (G - a_v) for m, _, _, _ in blocks)
    moment = sum(
        m * (G - a_v) * (x - left) + sense * m * a_h * (z - level) for m, x, z, _ in blocks
    )
    normal_right = moment / (right - left)
    return weight - normal_right, normal_right, -sense * sum(m for m, *_ in blocks) * a_h


@pytest.mark.parametrize("a_v", [-3.0, 3.0])
@pytest.mark.parametrize("sense", [1, -1])
def test_forces_at_rest_match_the_hand_solution(a_v, sense):
    model = load_model_text_helper()
    stack = model.configurations[0]
    case = initial_motion(stack, 2.0, a_v, sense, G)
    assert all(state.motion is Motion.REST for state in case.blocks)
    cabinet, box = case.blocks
    # the box on the cabinet's top (level 2.0)
    left, right, t = hand_forces([(200, 0.1, 2.3, 2.0)], -0.2, 0.4, 2.0, a_v, sense)
    assert box.base_normal_left == pytest.approx(left, rel=1e-9)
    assert box.base_normal_right == pytest.approx(right, rel=1e-9)
    assert box.base_tangential == pytest.approx(t, rel=1e-9)
    # the cabinet on the floor carries both
    both = [(1000, 0.0, 1.0, 0.0), (200, 0.1, 2.3, 0.0)]
    left, right, t = hand_forces(both, -0.5, 0.5, 2.0, a_v, sense)
    assert cabinet.base_normal_left == pytest.approx(left, rel=1e-9)
    assert cabinet.base_normal_right == pytest.approx(right, rel=1e-9)
    assert cabinet.base_tangential == pytest.approx(t, rel=1e-9)


def load_model_text_helper():
    from freestand.io.model_file import load_model_text

    return load_model_text(STACK_TOML, source="stack.toml")


def test_screen_command_gives_the_envelope_from_the_upward_case(tmp_path):
    model = tmp_path / "stack.toml"
    model.write_text(STACK_TOML)
    result = run_freestand("screen", str(model), "--json")
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    cases = document["cases"]
    assert [(c["excitation"], c["sense"], c["vertical"]) for c in cases] == [
        ("floor (a_v down)", "+", 3.0),
        ("floor (a_v down)", "-", 3.0),
        ("floor (a_v up)", "+", -3.0),
        ("floor (a_v up)", "-", -3.0),
    ]
    envelope = {item["block"]: item for item in document["force_envelope"]}
    both = [(1000, 0.0, 1.0, 0.0), (200, 0.1, 2.3, 0.0)]
    hand = {
        (a_v, sense): hand_forces(both, -0.5, 0.5, 2.0, a_v, sense)
        for a_v in (3.0, -3.0)
        for sense in (1, -1)
    }
    largest_left = max(forces[0] for forces in hand.values())
    largest_right = max(forces[1] for forces in hand.values())
    cabinet = envelope["cabinet"]
    assert cabinet["left"]["normal"] == pytest.approx(largest_left, rel=1e-9)
    assert cabinet["right"]["normal"] == pytest.approx(largest_right, rel=1e-9)
    assert cabinet["left"]["case"] == "floor (a_v up), sense -"
    assert cabinet["right"]["case"] == "floor (a_v up), sense +"
    assert cabinet["tangential"]["magnitude"] == pytest.approx(1200 * 2.0, rel=1e-9)
    # the total normal force is the weight grown by the upward acceleration
    up = cases[2]["blocks"][0]["base"]
    assert up["left"] + up["right"] == pytest.approx(1200 * (G + 3.0), rel=1e-9)


def test_table_output_names_the_vertical_sense_and_the_envelope(tmp_path):
    model = tmp_path / "stack.toml"
    model.write_text(STACK_TOML.replace('vertical_senses = "both"\n', ""))
    result = run_freestand("screen", str(model), "--vertical-senses", "both")
    assert result.returncode == 0, result.stderr
    assert "floor (a_v up)" in result.stdout and "floor (a_v down)" in result.stdout
    assert "Envelope of the contact forces" in result.stdout


def test_upward_acceleration_starts_no_motion_the_downward_one_does_not():
    """Paper section 2: an upward support acceleration only adds stability.

    Every admissible state depends on the excitation through a_h / (g - a_v), which an
    upward a_v makes smaller: a block that rests under a_v downward rests under it upward.
    """
    model = load_model(CRANE)
    for stack in model.configurations:
        for a_h in np.linspace(0.5, 12.0, 7):
            for a_v in np.linspace(0.5, 9.0, 5):
                for sense in (1, -1):
                    down = initial_motion(stack, a_h, a_v, sense, G)
                    up = initial_motion(stack, a_h, -a_v, sense, G)
                    for below, above in zip(down.blocks, up.blocks, strict=True):
                        if below.motion is Motion.REST:
                            assert above.motion is Motion.REST, (stack.name, a_h, a_v, sense)
                    if all(s.motion is Motion.REST for s in down.blocks):
                        assert up.status == "unique" or up.status == down.status


def test_both_senses_in_the_core_and_the_envelope():
    model = load_model(CRANE)
    stack = model.configuration("y-z")
    cases = screen(stack, [Excitation("rigid", 2.7, 2.35, "both")], G)
    assert [c.vertical for c in cases] == [2.35, 2.35, -2.35, -2.35]
    envelope = {item.block: item for item in force_envelope(cases)}
    bridge = envelope["bridge"]
    # rigid blocks at rest under upward a_v: the rails carry (m1 + m2)(g + a_v) in total
    up = [c for c in cases if c.vertical < 0]
    total = sum(up[0].blocks[0].base_normal_left + up[0].blocks[0].base_normal_right for _ in [0])
    assert total == pytest.approx(42200 * (G + 2.35), rel=1e-9)
    assert bridge.normal_left >= max(c.blocks[0].base_normal_left for c in cases) - 1e-6
    assert "a_v up" in bridge.cases[0]
