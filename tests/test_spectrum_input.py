"""Spectrum input: CSV files, model sections and the --spectrum option."""

from __future__ import annotations

from pathlib import Path

import pytest

from freestand.errors import FreestandError
from freestand.io.spectrum_input import (
    parse_spectrum_option,
    parse_spectrum_sections,
    read_spectrum_csv,
)


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "spectrum.csv"
    path.write_text(text)
    return path


def test_csv_with_units(tmp_path):
    path = write(tmp_path, "# site spectrum\nfrequency [Hz], acceleration [g]\n1, 0.5\n10, 1.0\n")
    spectrum = read_spectrum_csv(path, gravity=9.81)
    assert spectrum.acceleration_at(10.0) == pytest.approx(9.81)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("frequency [Hz], acceleration [m/s^2]\n2, 1\n1, 2\n", "increase strictly"),
        ("frequency [Hz], acceleration [m/s^2]\n1, 1\n2, -2\n", "negative"),
        ("frequency, acceleration\n1, 1\n2, 2\n", "units in brackets"),
        ("frequency [Hz], acceleration [kg]\n1, 1\n2, 2\n", "not acceleration"),
        ("frequency [Hz], acceleration [m/s^2]\n1, x\n2, 2\n", "not two numbers"),
        ("", "no data"),
    ],
)
def test_bad_csv_files(tmp_path, text, message):
    with pytest.raises(FreestandError, match=message):
        read_spectrum_csv(write(tmp_path, text))


def test_sections_and_options(tmp_path):
    sections = [
        {"name": "rg", "kind": "rg1.60", "pga": "0.3 g", "damping": "5 %"},
        {
            "name": "ec",
            "kind": "en1998",
            "ag": 2.5,
            "ground": "B",
            "type": 1,
            "direction": "vertical",
        },
    ]
    spectra = parse_spectrum_sections(sections, source="m.toml", base_dir=tmp_path, gravity=9.81)
    assert spectra["rg"].acceleration_at(2.5) == pytest.approx(3.13 * 0.3 * 9.81)
    assert spectra["ec"].direction == "vertical"
    option = parse_spectrum_option(
        "rg1.60:pga=0.3g,damping=5%", model_spectra=spectra, base_dir=tmp_path, gravity=9.81
    )
    assert option.acceleration_at(9.0) == pytest.approx(2.61 * 0.3 * 9.81)
    assert (
        parse_spectrum_option("ec", model_spectra=spectra, base_dir=tmp_path, gravity=9.81)
        is spectra["ec"]
    )


@pytest.mark.parametrize(
    ("section", "message"),
    [
        ({"name": "x", "kind": "rg1.60", "pga": 3.0, "damping": 0.03}, "tabulates damping"),
        ({"name": "x", "kind": "fancy"}, "not a kind of spectrum"),
        ({"name": "x", "kind": "rg1.60"}, "is missing"),
        ({"name": "x", "kind": "en1998", "ag": 2.0, "ground": "Z"}, "ground type"),
    ],
)
def test_bad_sections(tmp_path, section, message):
    with pytest.raises(FreestandError, match=message):
        parse_spectrum_sections([section], source="m.toml", base_dir=tmp_path, gravity=9.81)


def test_unknown_option(tmp_path):
    with pytest.raises(FreestandError, match="neither a spectrum of the model"):
        parse_spectrum_option("nonsense", model_spectra={}, base_dir=tmp_path, gravity=9.81)


RECORDS = Path(__file__).resolve().parents[1] / "examples" / "records"


def test_record_spectrum_is_the_records_response_spectrum(tmp_path):
    """kind = "record": the Nigam-Jennings spectrum of the scaled record, any direction."""
    import numpy as np

    from freestand.core.motion.response_spectrum import response_spectrum
    from freestand.io.records import load_record

    motion = load_record(RECORDS / "synthetic_H.AT2").scaled_to_peak(0.3 * 9.81)
    expected = response_spectrum(motion, damping=0.02)
    option = parse_spectrum_option(
        f"record:{RECORDS / 'synthetic_H.AT2'},damping=2%,peak=0.3g",
        model_spectra={},
        base_dir=tmp_path,
        gravity=9.81,
    )
    np.testing.assert_allclose(option.frequency, expected.frequency, rtol=0)
    np.testing.assert_allclose(option.acceleration, expected.acceleration, rtol=1e-12)
    assert option.damping == 0.02 and option.direction == "horizontal"
    # rigid limit of a pseudo-acceleration spectrum: the record's peak (1 % at 100 Hz)
    assert option.acceleration_at(100.0) == pytest.approx(0.3 * 9.81, rel=0.01)

    (tmp_path / "motions").mkdir()
    (tmp_path / "motions" / "up.AT2").write_bytes((RECORDS / "synthetic_UP.AT2").read_bytes())
    section = {
        "name": "site vertical",
        "kind": "record",
        "file": "motions/up.AT2",
        "scale": 2.0,
        "direction": "vertical",
    }
    spectra = parse_spectrum_sections([section], source="m.toml", base_dir=tmp_path, gravity=9.81)
    vertical = load_record(RECORDS / "synthetic_UP.AT2").scaled(2.0)
    expected = response_spectrum(vertical, damping=0.05)
    assert spectra["site vertical"].direction == "vertical"
    np.testing.assert_allclose(
        spectra["site vertical"].acceleration, expected.acceleration, rtol=1e-12
    )


@pytest.mark.parametrize(
    ("option", "message"),
    [
        ("record:", "needs a file"),
        ("record:missing.AT2", "missing.AT2"),
        (f"record:{RECORDS / 'synthetic_H.AT2'},scale=2,peak=0.3g", "either scale or peak"),
        (f"record:{RECORDS / 'synthetic_H.AT2'},peak=-1", "not a positive peak"),
        (f"record:{RECORDS / 'synthetic_H.AT2'},speed=3", "speed not known"),
        (f"record:{RECORDS / 'synthetic_H.AT2'},damping", "not key=value"),
    ],
)
def test_bad_record_spectrum(tmp_path, option, message):
    with pytest.raises(FreestandError, match=message):
        parse_spectrum_option(option, model_spectra={}, base_dir=tmp_path, gravity=9.81)
