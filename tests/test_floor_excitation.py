"""A model-file excitation from a ground record filtered by a structure's mode."""

from __future__ import annotations

import pytest

from freestand.core.motion.ground_motion import synthetic_ground_motion
from freestand.core.motion.response_spectrum import floor_motion, spectral_response
from freestand.errors import FreestandError
from freestand.io.model_file import load_model
from freestand.io.records import write_at2
from tests.conftest import CRANE


def _model(tmp_path, excitation: str):
    ground = synthetic_ground_motion(duration=10.0, vertical_peak=None)
    write_at2(tmp_path / "ground.AT2", ground)
    text = CRANE.read_text().replace("[[excitation]]", excitation + "\n\n[[excitation]]", 1)
    path = tmp_path / "model.toml"
    path.write_text(text)
    return path, ground


def test_floor_excitation_is_the_peak_floor_acceleration(tmp_path):
    path, ground = _model(
        tmp_path,
        '[[excitation]]\nname = "floor"\nrecord = "ground.AT2"\n'
        'floor = { frequency = "2.5 Hz", damping = "5 %" }\nvertical = "2.35 m/s^2"',
    )
    model = load_model(path)
    excitation = next(e for e in model.excitations if e.name == "floor")
    # the record as written (7 digits) and read back
    from freestand.io.records import load_record

    motion = load_record(tmp_path / "ground.AT2")
    expected = floor_motion(motion.with_trailing_zeros(motion.duration + 2.0), 2.5, 0.05)
    assert excitation.horizontal == pytest.approx(expected.peak_horizontal, rel=1e-12)
    # which is the ground spectrum's absolute acceleration at 2.5 Hz, 5 % (the paper's
    # "elastic" level is that spectral value)
    spectral = spectral_response(motion, None, [2.5], 0.05).absolute_acceleration[0]
    assert excitation.horizontal == pytest.approx(spectral, rel=2e-3)
    assert excitation.horizontal > 2 * ground.peak_horizontal
    assert excitation.vertical == pytest.approx(2.35)


def test_record_excitation_without_floor_is_the_pga(tmp_path):
    path, ground = _model(tmp_path, '[[excitation]]\nname = "ground"\nrecord = "ground.AT2"')
    excitation = next(e for e in load_model(path).excitations if e.name == "ground")
    assert excitation.horizontal == pytest.approx(ground.peak_horizontal, rel=1e-6)


@pytest.mark.parametrize(
    ("excitation", "message"),
    [
        ('name = "x"\nhorizontal = 2.0\nrecord = "ground.AT2"', "either horizontal"),
        ('name = "x"\nhorizontal = 2.0\nfloor = { frequency = 2.5 }', "floor filters a record"),
        ('name = "x"\nrecord = "ground.AT2"\nfloor = { frequency = -1 }', "not positive"),
        ('name = "x"\nrecord = "missing.AT2"', "not found"),
    ],
)
def test_floor_excitation_errors(tmp_path, excitation, message):
    path, _ = _model(tmp_path, "[[excitation]]\n" + excitation)
    with pytest.raises(FreestandError, match=message):
        load_model(path)
