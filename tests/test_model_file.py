"""Model files: the documented form, units, the paper's notation and bad input."""

from __future__ import annotations

import pytest

from freestand.core.contact.screening import screen
from freestand.errors import FreestandError
from freestand.io.model_file import load_model, load_model_text
from tests.conftest import CRANE

ISSUE_FORM = """
name = "Bridge crane"
gravity = 9.81                  # optional, m/s^2

[[excitation]]                  # one or more levels; both horizontal senses are analysed
name = "rigid"
horizontal = "2.70 m/s^2"       # magnitude of the horizontal support acceleration
vertical = "2.35 m/s^2"         # downward support acceleration: weight becomes m*(g - vertical)

[[configuration]]               # one planar model (a plane, a parking position, ...)
name = "y-z"

[[configuration.block]]         # listed bottom to top; each rests on the one before
name = "bridge"
mass = 16600                    # kg
inertia = 49400                 # kg m^2, about the centre of gravity
centre = [0.0, 0.98]            # (x, z) of the centre of gravity, m
base = { left = -1.74, right = 2.46, level = 0.0 }   # x of its two lower contacts and their z
friction = { static = 0.25, kinetic = 0.20 }
sliding = "free"                # free | none | no-right | no-left
"""

PAPER_FORM = """
name = "crane, paper notation"
[[excitation]]
name = "elastic"
horizontal = "10.31 m/s^2"
vertical = "2.35 m/s^2"

[[configuration]]
name = "x-z cart right"
[configuration.paper]
plane = "x-z"
lower = { name = "bridge", mass = 16600, inertia = 256650, sliding = "none" }
upper = { name = "cart", mass = 25600, inertia = 124100, friction = { static = 0.25, kinetic = 0.20 }, sliding = "no-right" }
p1 = 0.98
p3 = 0.22
e = 5.9
f = 3.9
p2 = 2.83
a = 1.33
b = 1.33
s = 5.14
t = 2.0
"""


def test_the_issue_form_is_accepted_as_written():
    model = load_model_text(ISSUE_FORM)
    bridge = model.configurations[0].blocks[0]
    assert bridge.mass == 16600 and bridge.base_left == -1.74
    assert model.excitations[0].horizontal == pytest.approx(2.70)


def test_units_are_converted():
    text = (
        ISSUE_FORM.replace("mass = 16600", 'mass = "16.6 t"')
        .replace('"2.70 m/s^2"', '"0.275 g"')
        .replace("centre = [0.0, 0.98]", 'centre = [0.0, "98 cm"]')
    )
    model = load_model_text(text)
    assert model.configurations[0].blocks[0].mass == pytest.approx(16600)
    assert model.configurations[0].blocks[0].centre[1] == pytest.approx(0.98)
    # "g" in an acceleration means the model's gravity, not the gram.
    assert model.excitations[0].horizontal == pytest.approx(0.275 * 9.81)


def test_paper_notation_gives_the_same_results_as_coordinates():
    paper = load_model_text(PAPER_FORM).configurations[0]
    crane = load_model(CRANE)
    coordinates = crane.configuration("x-z cart right")
    assert paper.blocks[1].base_left == pytest.approx(coordinates.blocks[1].base_left)
    assert paper.blocks[1].centre == pytest.approx(coordinates.blocks[1].centre)
    assert paper.blocks[1].contact_names == ("A", "B")
    elastic = [e for e in crane.excitations if e.name == "elastic"]
    for a, b in zip(screen(paper, elastic), screen(coordinates, elastic), strict=True):
        assert [s.motion for s in a.blocks] == [s.motion for s in b.blocks]
        assert a.blocks[1].base_normal_right == pytest.approx(b.blocks[1].base_normal_right)


def test_the_shipped_crane_loads(crane_model):
    names = [stack.name for stack in crane_model.configurations]
    assert names == ["y-z", "x-z cart right", "x-z cart left"]
    assert [e.name for e in crane_model.excitations] == ["rigid", "elastic"]
    assert len(crane_model.sha256) == 64


BASE = CRANE.read_text()
BAD = [
    (
        "missing field",
        BASE.replace("mass = 16600                    # kg\n", "", 1),
        ["block[0] ('bridge').mass", "is missing"],
    ),
    (
        "wrong unit",
        BASE.replace('"2.70 m/s^2"', '"2.7 kg"'),
        ["excitation[0] ('rigid').horizontal", "'2.7 kg'", "not acceleration"],
    ),
    (
        "negative mass",
        BASE.replace("mass = 16600                    # kg", "mass = -16600", 1),
        ["mass", "-16600", "must be > 0"],
    ),
    (
        "zero inertia",
        BASE.replace("inertia = 49400 ", "inertia = 0 ", 1),
        ["inertia", "0.0 is not positive"],
    ),
    (
        "kinetic above static",
        BASE.replace(
            "friction = { static = 0.25, kinetic = 0.20 }",
            "friction = { static = 0.20, kinetic = 0.25 }",
            1,
        ),
        ["friction", "kinetic = 0.25 is above static = 0.2"],
    ),
    (
        "left not left of right",
        BASE.replace("left = -1.74, right = 2.46", "left = 2.46, right = -1.74"),
        ["base", "not left of right"],
    ),
    (
        "unknown sliding word",
        BASE.replace('sliding = "free"', 'sliding = "sometimes"'),
        ["sliding", "'sometimes'", "'no-right'"],
    ),
    (
        "malformed TOML",
        BASE.replace("[[excitation]]", "[[excitation]", 1),
        ["not valid TOML", "line"],
    ),
    (
        "misspelt field",
        BASE.replace("inertia = 49400 ", "intertia = 49400 ", 1),
        ["intertia", "did you mean 'inertia'"],
    ),
    (
        "no blocks",
        'name = "x"\n[[excitation]]\nname = "a"\nhorizontal = 1\n[[configuration]]\nname = "c"\n',
        ["configuration[0]", "either"],
    ),
    (
        "negative horizontal",
        BASE.replace('horizontal = "2.70 m/s^2"', 'horizontal = "-2.70 m/s^2"', 1),
        ["horizontal", "negative", "magnitude"],
    ),
    (
        "vertical senses",
        BASE.replace(
            'vertical = "2.35 m/s^2"', 'vertical = "2.35 m/s^2"\nvertical_senses = "up"', 1
        ),
        ["vertical_senses", "'up'", "'both'"],
    ),
]


def test_negative_vertical_is_an_upward_support_acceleration():
    model = load_model_text(
        BASE.replace('vertical = "2.35 m/s^2"', 'vertical = "-2.35 m/s^2"', 1), source="m.toml"
    )
    assert model.excitations[0].vertical == -2.35
    assert model.excitations[0].verticals() == (-2.35,)


@pytest.mark.parametrize(("label", "text", "fragments"), BAD, ids=[b[0] for b in BAD])
def test_bad_input_names_file_field_and_fix(label, text, fragments):
    with pytest.raises(FreestandError) as info:
        load_model_text(text, source="crane.toml")
    message = str(info.value)
    assert message.startswith("crane.toml")
    for fragment in fragments:
        assert fragment in message, message
