"""3-D blocks in model files (#18): the keys, their units and defaults, and bad input."""

from __future__ import annotations

import numpy as np
import pytest

from freestand.core.body import Box, Cylinder
from freestand.errors import FreestandError
from freestand.io.model_file import load_model_text
from freestand.io.model_reference import body_keys, model_file_reference
from tests.conftest import CRANE, run_freestand

#: A cask and a cabinet, each a 3-D configuration, with units and the optional keys.
BODIES = """
name = "Cask and cabinet"

[[excitation]]
name = "SL-2"
horizontal = "0.3 g"
y = "-0.2 g"
vertical = "0.2 g"

[[configuration]]
name = "cask"
[[configuration.block]]
name = "cask"
shape = "cylinder"
radius = "120 cm"
height = 5
inner_radius = 0.8
mass = "120 t"
friction = { static = 0.6, kinetic = 0.5 }

[[configuration]]
name = "cabinet"
[[configuration.block]]
name = "cabinet"
shape = "box"
size = [0.8, "60 cm", 2.0]
mass = 400
centre = [0.05, 0.0, 0.9]
inertia = [[150, 2, 0], [2, 155, 0], [0, 0, 35]]
friction = { static = 0.5, kinetic = 0.4 }
"""

#: A planar block, for a model with both kinds.
PLANAR = """
[[configuration]]
name = "plane"
[[configuration.block]]
name = "frame"
mass = 150
inertia = 14
centre = [0.0, 0.15]
base = { left = -0.5, right = 0.5 }
friction = { static = 0.5, kinetic = 0.4 }
"""


def test_box_and_cylinder_load_in_si_units_with_their_defaults():
    model = load_model_text(BODIES, source="bodies.toml")
    assert model.configurations == ()  # no planar configuration
    cask, cabinet = (c.body for c in model.body_configurations)
    assert cask.shape == Cylinder(1.2, 5.0, 0.8)
    assert cask.mass == 120000.0 and cask.centre == (0.0, 0.0, 2.5)  # geometric centre
    # homogeneous hollow cylinder: I_zz = m (R^2 + r^2) / 2
    assert cask.inertia[2, 2] == pytest.approx(0.5 * 120000.0 * (1.2**2 + 0.8**2))
    assert cabinet.shape == Box((0.8, 0.6, 2.0))
    assert cabinet.centre == (0.05, 0.0, 0.9)
    assert np.allclose(cabinet.inertia, [[150, 2, 0], [2, 155, 0], [0, 0, 35]])
    assert (cabinet.friction.static, cabinet.friction.kinetic) == (0.5, 0.4)
    (excitation,) = model.excitations
    assert excitation.horizontal == pytest.approx(0.3 * 9.81)  # x
    assert excitation.horizontal_y == pytest.approx(-0.2 * 9.81)
    assert excitation.vertical == pytest.approx(0.2 * 9.81)


def test_principal_inertia_and_x_as_the_name_of_horizontal():
    text = BODIES.replace('horizontal = "0.3 g"', 'x = "0.3 g"').replace(
        "inertia = [[150, 2, 0], [2, 155, 0], [0, 0, 35]]", "inertia = [150, 155, 35]"
    )
    model = load_model_text(text)
    assert model.excitations[0].horizontal == pytest.approx(0.3 * 9.81)
    assert np.allclose(model.body_configuration("cabinet").body.inertia, np.diag([150, 155, 35]))


def test_a_model_holds_both_kinds_and_planar_analyses_name_the_3d_ones():
    model = load_model_text(BODIES + PLANAR, source="both.toml")
    assert [stack.name for stack in model.configurations] == ["plane"]
    assert [body.name for body in model.body_configurations] == ["cask", "cabinet"]
    assert model.first_configuration().name == "plane"
    with pytest.raises(
        FreestandError, match="'cask' is 3-D .* planar configurations only: 'plane'"
    ):
        model.configuration("cask")
    with pytest.raises(FreestandError, match=r"choose one of 'plane', 'cask' \(3-D\)"):
        model.configuration("tower")
    only_bodies = load_model_text(BODIES, source="bodies.toml")
    with pytest.raises(FreestandError, match="has only 3-D configurations"):
        only_bodies.first_configuration()


def test_planar_models_load_exactly_as_before(crane_model):
    assert crane_model.body_configurations == ()
    assert all(e.horizontal_y == 0.0 for e in crane_model.excitations)
    assert [s.name for s in crane_model.configurations] == [
        "y-z",
        "x-z cart right",
        "x-z cart left",
    ]


def test_the_reference_lists_the_3d_keys_with_units():
    keys = {key.path: key for key in body_keys()}
    expected_units = {
        "configuration.block.size": "m",
        "configuration.block.radius": "m",
        "configuration.block.height": "m",
        "configuration.block.inner_radius": "m",
        "configuration.block.centre": "m",
        "configuration.block.inertia": "kg m^2",
        "configuration.block.mass": "kg",
    }
    for path, unit in expected_units.items():
        assert keys[path].unit == unit, path
    assert keys["configuration.block.shape"].required
    text = model_file_reference()
    assert "## 3-D blocks: `[[configuration.block]]` with `shape`" in text
    for path, key in keys.items():
        assert f"| `{path}` | {key.kind} |" in text and key.description, path
    for name in ("excitation.x", "excitation.y"):
        assert f"| `{name}` | number or text with unit | none | m/s^2 |" in text


CABINET = 'shape = "box"\nsize = [0.8, "60 cm", 2.0]'
CASK = 'radius = "120 cm"\nheight = 5'

#: (label, old, new, fragments of the message): each edit of BODIES is an error.
BAD = [
    ("negative side", CABINET, 'shape = "box"\nsize = [0.8, -0.6, 2.0]',
     ["cabinet').size", "ly = -0.6 m is not positive", "size = [0.8, 0.6, 2.0]"]),
    ("missing size", CABINET, 'shape = "box"', ["cabinet').size", "is missing", "size = ["]),
    ("two sides", CABINET, 'shape = "box"\nsize = [0.8, 0.6]', ["size", "not [lx, ly, lz]"]),
    ("negative radius", CASK, "radius = -1.2\nheight = 5",
     ["cask').radius", "-1.2 m is not positive", "radius = 0.9"]),
    ("missing height", CASK, 'radius = "120 cm"', ["cask').height", "is missing", "height"]),
    ("zero height", CASK, 'radius = "120 cm"\nheight = 0', ["height", "0.0 m is not positive"]),
    ("inner radius too big", "inner_radius = 0.8", "inner_radius = 1.5",
     ["cask').inner_radius", "below the radius 1.2 m", "1.5"]),
    ("inertia not positive definite", "[[150, 2, 0], [2, 155, 0], [0, 0, 35]]",
     "[150, -155, 35]", ["inertia", "not positive definite", "-155", "inertia = [150, 155, 35]"]),
    ("inertia not symmetric", "[[150, 2, 0], [2, 155, 0], [0, 0, 35]]",
     "[[150, 2, 0], [0, 155, 0], [0, 0, 35]]", ["inertia", "not symmetric"]),
    ("inertia no body has", "[[150, 2, 0], [2, 155, 0], [0, 0, 35]]", "[10, 10, 35]",
     ["inertia", "exceeds the sum of the other two"]),
    ("scalar inertia", "[[150, 2, 0], [2, 155, 0], [0, 0, 35]]", "150",
     ["inertia", "not a 3-D inertia", "3 principal values"]),
    ("unknown shape", 'shape = "box"', 'shape = "sphere"', ["shape", "'sphere'", '"cylinder"']),
    ("size without shape", 'shape = "box"\n', "", ["cabinet').shape", "is missing"]),
    ("radius on a box", CABINET, CABINET + "\nradius = 1", ["radius", "does not apply", "box"]),
    ("planar key on a 3-D block", CABINET, CABINET + "\nsliding = \"none\"",
     ["sliding", "planar blocks", "remove"]),
    ("planar centre", "centre = [0.05, 0.0, 0.9]", "centre = [0.05, 0.9]",
     ["centre", "[x, y, z]"]),
    ("centre outside the base", "centre = [0.05, 0.0, 0.9]", "centre = [0.5, 0.0, 0.9]",
     ["cabinet').centre", "must lie over the base"]),
    ("two bodies in a configuration", '[[configuration]]\nname = "cabinet"\n', "",
     ["configuration[0] ('cask').block", "stacks of 3-D bodies are not supported yet"]),
    ("y with a record", 'horizontal = "0.3 g"', 'record = "ground.AT2"', ["y", "not with a record"]),
    ("x and horizontal", 'horizontal = "0.3 g"', 'horizontal = "0.3 g"\nx = 1',
     ["x = 1.0", "same key"]),
]  # fmt: skip


@pytest.mark.parametrize(("label", "old", "new", "fragments"), BAD, ids=[b[0] for b in BAD])
def test_bad_3d_input_names_the_file_the_field_and_the_fix(label, old, new, fragments):
    assert old in BODIES
    with pytest.raises(FreestandError) as info:
        load_model_text(BODIES.replace(old, new, 1), source="bodies.toml")
    message = str(info.value)
    assert message.startswith("bodies.toml: field '"), message
    for fragment in fragments:
        assert fragment in message, message


def _mixed(text: str) -> str:
    """``text`` with the planar frame's block added to the cask's configuration."""
    frame = PLANAR[PLANAR.index("[[configuration.block]]") :]
    cabinet = '[[configuration]]\nname = "cabinet"'
    return text.replace(cabinet, frame + cabinet)


def test_mixed_planar_and_3d_blocks_in_one_configuration_are_refused():
    mixed = _mixed(BODIES)
    with pytest.raises(FreestandError) as info:
        load_model_text(mixed, source="mixed.toml")
    message = str(info.value)
    assert "mixed.toml: field 'configuration[0] ('cask').block'" in message
    assert "mixes planar blocks (frame) and 3-D blocks (cask" in message
    assert "separate [[configuration]] tables" in message


def test_y_on_a_planar_model_is_refused():
    text = CRANE.read_text().replace(
        'horizontal = "2.70 m/s^2"', 'horizontal = "2.70 m/s^2"\ny = 1'
    )
    with pytest.raises(FreestandError) as info:
        load_model_text(text, source="crane.toml")
    message = str(info.value)
    assert "crane.toml: field 'excitation[0] ('rigid').y'" in message
    assert "every configuration of this model is planar" in message and "Remove y" in message


#: Bad 3-D input through the real command: (edit of BODIES, fragments of stderr).
CLI_BAD = {
    "negative-size": (
        lambda text: text.replace(CABINET, 'shape = "box"\nsize = [0.8, 0.6, -2.0]'),
        ["field 'configuration[1] ('cabinet').block[0] ('cabinet').size'", "lz = -2.0 m",
         "e.g. size = [0.8, 0.6, 2.0]"],
    ),
    "missing-size": (
        lambda text: text.replace(CABINET, 'shape = "box"'),
        ["('cabinet').size'", "is missing for shape = 'box'", "size = [lx, ly, lz]"],
    ),
    "missing-radius": (
        lambda text: text.replace(CASK, "height = 5"),
        ["('cask').radius'", "is missing for shape = 'cylinder'", "radius = 0.9"],
    ),
    "inertia-not-positive-definite": (
        lambda text: text.replace("[[150, 2, 0], [2, 155, 0], [0, 0, 35]]", "[150, 155, -35]"),
        ["('cabinet').inertia'", "[150.0, 155.0, -35.0] kg m^2 is not positive definite",
         "inertia = [150, 155, 35]"],
    ),
    "y-on-a-planar-model": (
        lambda _: CRANE.read_text().replace('horizontal = "2.70 m/s^2"',
                                            'horizontal = "2.70 m/s^2"\ny = 1.5'),
        ["field 'excitation[0] ('rigid').y'", "y = 1.5 m/s^2", "Remove y"],
    ),
    "mixed-planar-and-3d": (
        _mixed,
        ["field 'configuration[0] ('cask').block'", "mixes planar blocks (frame)",
         "separate [[configuration]] tables"],
    ),
    "two-3d-blocks": (
        lambda text: text.replace('[[configuration]]\nname = "cabinet"\n', ""),
        ["field 'configuration[0] ('cask').block'", "2 blocks with shape (cask, cabinet)",
         "stacks of 3-D bodies are not supported yet"],
    ),
}  # fmt: skip


@pytest.mark.parametrize(("edit", "fragments"), CLI_BAD.values(), ids=list(CLI_BAD))
def test_bad_3d_input_through_the_command_is_a_message_not_a_traceback(tmp_path, edit, fragments):
    path = tmp_path / "model.toml"
    path.write_text(edit(BODIES))
    result = run_freestand("screen", str(path))
    assert result.returncode == 2
    assert "Traceback" not in result.stderr + result.stdout
    assert result.stdout == ""
    message = " ".join(result.stderr.split())
    assert f"{path}: field '" in message
    for fragment in fragments:
        assert fragment in message, message
