"""The model-file reference of the documentation is generated from the loader: every key, unit, default."""

from __future__ import annotations

from freestand.io.fragility_options import FRAGILITY_KEYS
from freestand.io.model_file import _ModelSpec
from freestand.io.model_reference import model_file_reference, schema_keys
from freestand.io.spectrum_input import COMMON_SPECTRUM_KEYS, SPECTRUM_KEYS


def test_every_schema_key_is_listed_with_a_description_of_its_own():
    keys = {key.path: key for key in schema_keys()}
    assert set(_ModelSpec.model_fields) <= set(keys)
    assert {"excitation.horizontal", "configuration.block.base.left",
            "configuration.paper.upper.friction.static"} <= set(keys)  # fmt: skip
    for key in keys.values():
        assert key.description, key.path
    # the paper notation's bodies are blocks, not excitation levels
    assert keys["configuration.paper.lower.name"].description == "the block's name"
    text = model_file_reference()
    for path in keys:
        assert f"| `{path}` |" in text


def test_units_and_defaults_come_from_the_validators():
    keys = {key.path: key for key in schema_keys()}
    assert (keys["configuration.block.mass"].unit, keys["configuration.block.mass"].required) == (
        "kg",
        True,
    )
    assert keys["configuration.block.inertia"].unit == "kg m^2"
    assert (keys["excitation.vertical"].unit, keys["excitation.vertical"].default) == ("m/s^2", "0")
    assert keys["excitation.floor.frequency"].unit == "Hz"
    assert keys["configuration.block.sliding"].default == '"free"'


def test_the_tables_read_key_by_key_come_from_their_readers_key_tables():
    text = model_file_reference()
    for name in COMMON_SPECTRUM_KEYS:
        assert f"| `{name}` |" in text
    for kind, keys in SPECTRUM_KEYS.items():
        assert f'### `kind = "{kind}"`' in text
        for name, key in keys.items():
            assert f"| `{name}` | {key.default_text()} | {key.unit} | {key.what} |" in text
    for name, key in FRAGILITY_KEYS.items():
        assert f"| `fragility.{name}` | {key.default_text()} | {key.unit} |" in text
    assert "| `pga` | required | m/s^2 |" in text
    assert '| `fragility.im` | "pga" (planar), "pga-rotd50" (3-D) |' in text
    assert "| `fragility.free_time` | 10 | s |" in text
    assert "| `fragility.angle` | drawn uniformly over 0-360 deg per simulation | deg |" in text
