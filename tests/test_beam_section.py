"""The [beam] section of a model file (paper section 6)."""

from __future__ import annotations

import pytest

from freestand.errors import FreestandError
from freestand.io.beam_section import BeamSection, parse_beam_section

GOOD = {
    "span": 9.8,
    "youngs_modulus": 2.1e11,
    "second_moment": 0.014,
    "mass": 16600,
    "load_mass": 25600,
    "parking": [1.33, 8.47],
}


def test_paper_section_reads_as_si():
    section = parse_beam_section(dict(GOOD), source="crane.toml")
    assert isinstance(section, BeamSection)
    assert section.beam.span == 9.8
    assert section.beam.mass == 16600.0
    assert section.beam.load_rotary_inertia == 0.0
    assert section.parking == (1.33, 8.47)


def test_units_are_converted():
    data = GOOD | {
        "span": "980 cm",
        "youngs_modulus": "210 GPa",
        "second_moment": "1.4e6 cm^4",
        "mass": "16.6 t",
        "load_mass": "25.6 t",
        "parking": ["1330 mm", "8.47 m"],
        "load_rotary_inertia": "124.1 t*m^2",
        "load_height": "283 cm",
    }
    beam = parse_beam_section(data, source="crane.toml").beam
    assert beam.span == pytest.approx(9.8)
    assert beam.youngs_modulus == pytest.approx(2.1e11)
    assert beam.second_moment == pytest.approx(0.014)
    assert beam.mass == pytest.approx(16600.0)
    assert beam.load_rotary_inertia == pytest.approx(124100.0)
    assert beam.load_height == pytest.approx(2.83)


def _error(data: dict) -> FreestandError:
    with pytest.raises(FreestandError) as info:
        parse_beam_section(data, source="crane.toml")
    return info.value


@pytest.mark.parametrize(
    ("changes", "field", "words"),
    [
        ({"span": 0}, "beam.span", "positive"),
        ({"span": -9.8}, "beam.span", "positive"),
        ({"span": "9.8 kg"}, "beam.span", "length"),
        ({"youngs_modulus": 0.0}, "beam.youngs_modulus", "positive"),
        ({"second_moment": -0.014}, "beam.second_moment", "positive"),
        ({"mass": -1}, "beam.mass", "negative"),
        ({"load_mass": -25600}, "beam.load_mass", "negative"),
        ({"load_rotary_inertia": -1.0}, "beam.load_rotary_inertia", "negative"),
        ({"mass": 0, "load_mass": 0}, "beam.mass", "both 0"),
        ({"parking": [1.33, 10.5]}, "beam.parking", "does not fit"),
        ({"parking": [-0.5, 8.47]}, "beam.parking", "does not fit"),
        ({"parking": [8.47, 1.33]}, "beam.parking", "backwards"),
        ({"parking": [1.33]}, "beam.parking", "pair"),
        ({"parking": "1.33..8.47"}, "beam.parking", "pair"),
        ({"parking": [1.33, "far"]}, "beam.parking[1]", "cannot read"),
        ({"spam": 1}, "beam.spam", "unknown key"),
        ({"load_mass": True}, "beam.load_mass", "not a number"),
    ],
)
def test_bad_input_names_field_value_and_fix(changes, field, words):
    error = _error(GOOD | changes)
    assert error.field == field
    assert error.source == "crane.toml"
    message = str(error)
    assert message.startswith("crane.toml: field '" + field + "'")
    assert words in message
    # The fix: every message tells what to give.
    assert "give" in message


@pytest.mark.parametrize(
    "missing", ["span", "youngs_modulus", "second_moment", "mass", "load_mass", "parking"]
)
def test_missing_field_is_named(missing):
    data = {k: v for k, v in GOOD.items() if k != missing}
    error = _error(data)
    assert error.field == f"beam.{missing}"
    assert "missing" in str(error)


def test_parking_may_touch_the_supports_and_a_single_point():
    assert parse_beam_section(GOOD | {"parking": [0, 9.8]}, source="m").parking == (0.0, 9.8)
    assert parse_beam_section(GOOD | {"parking": [4.9, 4.9]}, source="m").parking == (4.9, 4.9)


def test_section_must_be_a_table():
    error = _error([1, 2])
    assert error.field == "beam"
