"""Pairing a station's component files (x, y, vertical) by file name and by header."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from freestand.core.motion.ground_motion import GroundMotion
from freestand.errors import FreestandError
from freestand.io.pairing import load_station, orientation_of, pair_components
from freestand.io.records import load_record, write_at2
from freestand.io.suites import load_suite, suite_text, write_suite
from tests.test_records_v2 import _csmip_channel

RNG = np.random.default_rng(7)
X, Y, UP = (RNG.normal(size=40) for _ in range(3))


def _at2(folder: Path, stem: str, values, description: str = "EVENT, STATION") -> Path:
    path = folder / f"{stem}.AT2"
    write_at2(path, GroundMotion(0.01, values), description=description)
    return path


@pytest.mark.parametrize(
    ("x_name", "y_name", "vertical_name"),
    [
        ("RSN123_STATION_090", "RSN123_STATION_000", "RSN123_STATION-UP"),  # _000 / _090 / -UP
        ("RSN1063_NORTHR_RRS318", "RSN1063_NORTHR_RRS228", "RSN1063_NORTHR_RRS-UP"),  # NGA
        ("RSN6_IMPVALL.I_I-ELC270", "RSN6_IMPVALL.I_I-ELC180", "RSN6_IMPVALL.I_I-ELC-UP"),
        ("RSN1503_CHICHI_TCU065-E", "RSN1503_CHICHI_TCU065-N", "RSN1503_CHICHI_TCU065-V"),
        ("STA_HNE", "STA_HNN", "STA_HNZ"),  # SEED channel codes
        ("rec01_X", "rec01_Y", "rec01_UP"),  # freestand's own
    ],
)
def test_components_paired_by_file_name(tmp_path, x_name, y_name, vertical_name):
    paths = [_at2(tmp_path, y_name, Y), _at2(tmp_path, vertical_name, UP),
             _at2(tmp_path, x_name, X)]  # fmt: skip
    (pairing,) = pair_components(paths)
    assert pairing.method == "file names"
    assert Path(pairing.components["horizontal"].path).stem == x_name
    assert Path(pairing.components["horizontal_y"].path).stem == y_name
    assert Path(pairing.components["vertical"].path).stem == vertical_name
    # the note says which file is which and how
    assert f"x = {x_name}.AT2" in pairing.note and f"y = {y_name}.AT2" in pairing.note
    assert "paired by file names" in pairing.note
    motion = load_station(paths)
    np.testing.assert_allclose(motion.horizontal, X, atol=5e-7 * 9.81)
    np.testing.assert_allclose(motion.horizontal_y, Y, atol=5e-7 * 9.81)
    # written positive up, stored downward
    np.testing.assert_allclose(motion.vertical, -UP, atol=5e-7 * 9.81)
    assert motion.metadata["pairing"] == pairing.note


def test_azimuths_give_a_right_handed_pair():
    # seen from above y is x turned 90 deg counter-clockwise: azimuth(y) = azimuth(x) - 90
    assert orientation_of("090").azimuth == 90.0 and orientation_of("360").azimuth == 0.0
    assert orientation_of("-UP") is None and orientation_of("UP").vertical
    assert orientation_of("DWN").vertical_positive == "down"
    assert orientation_of("HN1").order == 1 and orientation_of("E").azimuth == 90.0
    assert orientation_of("rec") is None


def test_components_paired_by_at2_header(tmp_path):
    # names without a component tag: the second header line names station and component
    station = "Imperial Valley-06, 10/15/1979, El Centro Array #6"
    paths = [
        _at2(tmp_path, "a", X, f"{station}, 230"),
        _at2(tmp_path, "b", Y, f"{station}, 140"),
        _at2(tmp_path, "c", UP, f"{station}, UP"),
        _at2(tmp_path, "d", X, "Imperial Valley-06, 10/15/1979, Bonds Corner, 140"),
    ]
    first, second = pair_components(paths)
    assert first.method == "AT2 headers" and first.station == station
    assert first.components["horizontal"].path.endswith("a.AT2")  # 230 = 140 + 90: x
    assert first.components["horizontal_y"].path.endswith("b.AT2")
    assert first.components["vertical"].path.endswith("c.AT2")
    assert "paired by AT2 headers" in first.note
    assert second.method == "none" and second.components["horizontal"].path.endswith("d.AT2")


def test_channels_of_a_v2_file_paired_by_their_headers(tmp_path):
    path = tmp_path / "CE89486.V2"
    channels = [(X, "CHAN 1: 180 DEG"), (UP, "CHAN 2: UP"), (Y, "CHAN 3:  90 DEG")]
    path.write_text("".join(_csmip_channel(values * 100.0, label=label)
                            for values, label in channels))  # fmt: skip
    (pairing,) = pair_components([path])
    assert pairing.method == "V2 channel headers" and pairing.station == "station 24087"
    assert pairing.components["horizontal"].channel == 1  # 180 deg; 90 deg is 90 deg clockwise
    assert pairing.components["horizontal_y"].channel == 3
    assert pairing.components["vertical"].channel == 2
    assert "CE89486.V2 channel 3" in pairing.note
    motion = load_station(path)
    np.testing.assert_allclose(motion.horizontal, X, atol=1e-5)
    np.testing.assert_allclose(motion.horizontal_y, Y, atol=1e-5)
    np.testing.assert_allclose(motion.vertical, -UP, atol=1e-5)
    # single-channel files of one station pair by their station number
    for number, (values, label) in enumerate(channels):
        (tmp_path / f"chan{number}.v2").write_text(_csmip_channel(values * 100.0, label=label))
    (pairing,) = pair_components(sorted(tmp_path.glob("chan*.v2")))
    assert pairing.method == "V2 channel headers"
    assert pairing.components["horizontal"].path.endswith("chan0.v2")


def test_what_cannot_be_paired_is_read_on_its_own_and_says_why(tmp_path):
    paths = [_at2(tmp_path, "bad_000", X), _at2(tmp_path, "bad_045", Y),
             _at2(tmp_path, "alone", X, "no component here")]  # fmt: skip
    pairings = pair_components(paths)
    assert [p.method for p in pairings] == ["none", "none", "none"]
    assert "not orthogonal" in pairings[0].note and "not orthogonal" in pairings[1].note
    assert pairings[2].note == "alone.AT2: read on its own"
    with pytest.raises(FreestandError, match="not the components of one station"):
        load_station(paths[:2])


def test_suite_files_carry_x_y_and_vertical(tmp_path):
    motions = [
        GroundMotion(0.01, X, -UP, name="a", horizontal_y=Y),
        GroundMotion(0.01, Y, name="b"),
    ]
    suite_path = write_suite(tmp_path, motions, name="three components")
    text = suite_path.read_text()
    assert 'x = "rec01_X.AT2"' in text and 'y = "rec01_Y.AT2"' in text
    assert 'vertical = "rec01_UP.AT2"' in text and 'horizontal = "rec02_H.AT2"' in text
    suite = load_suite(suite_path)
    first, second = suite.motions
    for read, written in ((first.horizontal, X), (first.horizontal_y, Y), (first.vertical, -UP),
                          (second.horizontal, Y)):  # fmt: skip
        np.testing.assert_allclose(read, written, atol=5e-7 * 9.81)  # 8 digits in g
    assert second.horizontal_y is None and second.vertical is None
    assert set(suite.files[0]) == {"horizontal", "horizontal_y", "vertical"}
    # written again, the same bytes
    again = tmp_path / "again"
    again.mkdir()
    write_suite(again, list(suite.motions), name="three components")
    for path in tmp_path.glob("rec*"):
        assert (again / path.name).read_bytes() == path.read_bytes()


def test_suite_keys_horizontal_x_and_files(tmp_path):
    for stem, values in (("S_000", Y), ("S_090", X), ("S-UP", UP)):
        _at2(tmp_path, stem, values)
    (tmp_path / "suite.toml").write_text(
        suite_text("keys", [{"horizontal": "S_090.AT2", "y": "S_000.AT2"},
                            {"x": "S_090.AT2", "vertical": "S-UP.AT2"},
                            {"files": ["S_000.AT2", "S-UP.AT2", "S_090.AT2"], "scale": 2.0}])
    )  # fmt: skip
    suite = load_suite(tmp_path / "suite.toml")
    horizontal_y, with_vertical, paired = suite.motions
    np.testing.assert_array_equal(horizontal_y.horizontal, with_vertical.horizontal)
    assert horizontal_y.horizontal_y is not None and with_vertical.horizontal_y is None
    np.testing.assert_allclose(paired.horizontal, 2.0 * horizontal_y.horizontal)
    np.testing.assert_allclose(paired.horizontal_y, 2.0 * horizontal_y.horizontal_y)
    assert suite.pairings[:2] == (None, None) and "paired by file names" in suite.pairings[2].note
    reference = load_record(tmp_path / "S_090.AT2", horizontal_y=tmp_path / "S_000.AT2")
    np.testing.assert_array_equal(reference.horizontal_y, horizontal_y.horizontal_y)


@pytest.mark.parametrize(
    ("body", "expected"),
    [
        ('horizontal = "S_090.AT2"\nx = "S_090.AT2"\n', "horizontal and x are the same key"),
        ('files = ["S_090.AT2"]\nx = "S_090.AT2"\n', "exclude each other"),
        ("files = []\n", "files must list"),
        ('x = "S_090.AT2"\ny = "missing.AT2"\n', "does not exist"),
        ('files = ["S_090.AT2", "other.AT2"]\n', "not the components of one station"),
    ],
)
def test_bad_three_component_entries(tmp_path, body, expected):
    for stem, values in (("S_090", X), ("other", Y)):
        _at2(tmp_path, stem, values)
    (tmp_path / "suite.toml").write_text(f"[[record]]\n{body}")
    with pytest.raises(FreestandError, match=expected) as error:
        load_suite(tmp_path / "suite.toml")
    assert "suite.toml" in str(error.value)
