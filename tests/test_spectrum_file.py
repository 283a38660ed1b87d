"""Spectrum files, [[spectrum]] sections and the --spectrum option."""

from importlib import resources
from pathlib import Path

import numpy as np
import pytest

from freestand.core.spectra import crane_stand_in_spectrum
from freestand.errors import FreestandError
from freestand.io.spectrum_file import (
    parse_spectrum_option,
    parse_spectrum_sections,
    read_spectrum_csv,
)

G = 9.81


def _write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "s.csv"
    path.write_text(text)
    return path


def test_csv_with_units_and_metadata(tmp_path):
    path = _write(
        tmp_path,
        "# site spectrum\n# damping: 2 %\n# direction: vertical\n"
        "frequency [Hz], acceleration [g]\n0.5, 0.1\n2.5, 0.9\n33, 0.3\n",
    )
    s = read_spectrum_csv(path, gravity=G)
    np.testing.assert_allclose(s.acceleration, [0.1 * G, 0.9 * G, 0.3 * G])
    assert s.damping == 0.02 and s.direction == "vertical"
    path = _write(tmp_path, "frequency [Hz], acceleration [cm/s^2]\n1 100\n2 200\n")
    np.testing.assert_allclose(read_spectrum_csv(path).acceleration, [1.0, 2.0])


@pytest.mark.parametrize(
    ("text", "match"),
    [
        (
            "frequency [Hz], acceleration [m/s^2]\n1, 1\n1, 2\n",
            "line 3: frequency 1 Hz does not increase",
        ),
        ("frequency [Hz], acceleration [m/s^2]\n2, 1\n1, 2\n", "does not increase"),
        (
            "frequency [Hz], acceleration [m/s^2]\n1, 1\n2, -2\n",
            "line 3: spectral acceleration -2.0 must be non-negative",
        ),
        ("frequency, acceleration\n1, 1\n2, 2\n", "lacks units"),
        ("frequency [Hz], acceleration [furlong]\n1, 1\n2, 2\n", "unknown acceleration unit"),
        ("frequency [Hz], acceleration [m/s^2]\n1, x\n2, 2\n", "line 2: '1, x' is not two numbers"),
        ("# only comments\n", "no header"),
        ("frequency [Hz], acceleration [m/s^2]\n1, 1\n", "at least two"),
    ],
)
def test_bad_csv_files_are_rejected(tmp_path, text, match):
    with pytest.raises(FreestandError, match=match) as err:
        read_spectrum_csv(_write(tmp_path, text))
    assert str(tmp_path) in str(err.value)


def test_missing_file():
    with pytest.raises(FreestandError, match="cannot read"):
        read_spectrum_csv("/nonexistent/spectrum.csv")


def test_sections_of_every_kind(tmp_path):
    _write(tmp_path, "frequency [Hz], acceleration [m/s^2]\n1, 1\n10, 2\n")
    spectra = parse_spectrum_sections(
        [
            {"name": "file", "kind": "csv", "path": "s.csv", "damping": "5 %"},
            {"name": "rg", "kind": "rg1.60", "pga": "0.2 g", "damping": 0.07},
            {
                "name": "ec8",
                "kind": "en1998",
                "ag": 2.0,
                "ground": "C",
                "type": 2,
                "damping": "3 %",
            },
            {
                "name": "tab",
                "kind": "table",
                "frequency": [1, "10 Hz"],
                "acceleration": ["0.1 g", 3.0],
            },
            {"name": "crane", "kind": "crane-stand-in", "direction": "vertical"},
        ],
        source="model.toml",
        base_dir=tmp_path,
        gravity=G,
    )
    assert set(spectra) == {"file", "rg", "ec8", "tab", "crane"}
    assert spectra["rg"].acceleration_at(2.5) == pytest.approx(2.72 * 0.2 * G)
    np.testing.assert_allclose(spectra["tab"].acceleration, [0.1 * G, 3.0])
    assert spectra["crane"].direction == "vertical"
    assert parse_spectrum_option("rg", model_spectra=spectra) is spectra["rg"]


@pytest.mark.parametrize(
    ("section", "field", "match"),
    [
        ({"kind": "rg1.60", "pga": 1.0}, "spectrum[0].name", "missing name"),
        ({"name": "a", "kind": "nrc"}, "spectrum[0].kind", "unknown spectrum kind"),
        ({"name": "a", "kind": "rg1.60", "pga": 1.0, "zpa": 1.0}, "spectrum[0]", "unknown key"),
        (
            {"name": "a", "kind": "rg1.60", "pga": 1.0, "damping": 5},
            "spectrum[0].damping",
            "not a fraction",
        ),
        (
            {"name": "a", "kind": "table", "frequency": [2, 1], "acceleration": [1, 1]},
            "spectrum[0].frequency[1]",
            "does not increase",
        ),
        (
            {"name": "a", "kind": "table", "frequency": [1, 2], "acceleration": [1, -1]},
            "spectrum[0].acceleration[1]",
            "non-negative",
        ),
        ({"name": "a", "kind": "rg1.60", "pga": "3 kg"}, "spectrum[0].pga", "not acceleration"),
    ],
)
def test_bad_sections(section, field, match):
    with pytest.raises(FreestandError, match=match) as err:
        parse_spectrum_sections([section], source="model.toml", base_dir=Path("."), gravity=G)
    assert err.value.field == field and err.value.source == "model.toml"


def test_duplicate_names():
    with pytest.raises(FreestandError, match="duplicate"):
        parse_spectrum_sections(
            [{"name": "a", "kind": "crane-stand-in"}] * 2, source="m", base_dir=Path("."), gravity=G
        )


def test_option_forms(tmp_path):
    path = _write(tmp_path, "frequency [Hz], acceleration [m/s^2]\n1, 1\n10, 2\n")
    assert parse_spectrum_option(str(path)).acceleration_at(10.0) == 2.0
    assert parse_spectrum_option("s.csv", base_dir=tmp_path).acceleration_at(1.0) == 1.0
    crane = parse_spectrum_option("crane-stand-in:direction=vertical")
    assert crane.direction == "vertical"
    with pytest.raises(FreestandError, match="unknown spectrum 'nope'") as err:
        parse_spectrum_option("nope")
    assert err.value.field == "--spectrum"
    with pytest.raises(FreestandError, match="not key=value"):
        parse_spectrum_option("rg1.60:pga")
    with pytest.raises(FreestandError, match="not found"):
        parse_spectrum_option("missing.csv")


def test_shipped_stand_in_files_match_the_builder():
    for direction in ("horizontal", "vertical"):
        ref = resources.files("freestand") / "examples" / f"crane-spectrum-{direction}.csv"
        text = ref.read_text()
        assert text.splitlines()[0].startswith("# STAND-IN for the paper's Fig.")
        with resources.as_file(ref) as path:
            s = read_spectrum_csv(path)
        built = crane_stand_in_spectrum(direction)
        np.testing.assert_allclose(s.frequency, built.frequency, rtol=1e-9)
        np.testing.assert_allclose(s.acceleration, built.acceleration, rtol=1e-9)
        assert s.direction == direction and s.damping == 0.05


def test_stand_in_anchors():
    h = crane_stand_in_spectrum("horizontal")
    v = crane_stand_in_spectrum("vertical")
    # the paper's quoted values (section 4)
    assert h.acceleration_at(2.5) == pytest.approx(10.31)
    assert h.acceleration_at(50.0) == pytest.approx(2.70)
    assert v.acceleration_at(50.0) == pytest.approx(2.35)
    assert v.acceleration_at(np.array([8.0, 10.0, 12.0])) == pytest.approx(9.81)
