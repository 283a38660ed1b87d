"""Reading records: PEER .AT2, CSV with units, single-column files, bad records."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from freestand.core.motion.ground_motion import synthetic_ground_motion
from freestand.errors import FreestandError
from freestand.io.records import (
    load_record,
    read_at2,
    read_csv_record,
    read_single_column,
    write_at2,
)

G = 9.81
EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "records"

NGA_HEADER = """PEER NGA STRONG MOTION DATABASE RECORD
Test event, 1/1/2000, Station X, 090
ACCELERATION TIME SERIES IN UNITS OF G
"""
VALUES = [0.01, -0.02, 0.03, 0.0, -0.015, 0.004, 0.002]


def _values_text(values, per_line=5):
    rows = [values[i : i + per_line] for i in range(0, len(values), per_line)]
    return "\n".join("".join(f"{v:15.7E}" for v in row) for row in rows) + "\n"


def _write(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text)
    return path


def test_read_nga_at2(tmp_path):
    path = _write(
        tmp_path, "rec.AT2", NGA_HEADER + "NPTS=      7, DT=   .0100 SEC\n" + _values_text(VALUES)
    )
    motion = read_at2(path, gravity=9.80665)
    assert motion.dt == 0.01
    assert motion.n_samples == 7
    np.testing.assert_allclose(motion.horizontal, np.array(VALUES) * 9.80665, rtol=1e-12)
    assert motion.vertical is None
    assert motion.name == "rec.AT2"
    assert motion.metadata["header"][0].startswith("PEER NGA")


def test_read_older_peer_header(tmp_path):
    text = (
        "PEER STRONG MOTION DATABASE RECORD. PROCESSING BY PACIFIC ENGINEERING.\n"
        "IMPERIAL VALLEY 10/15/79 2316, EL CENTRO ARRAY #6, 230\n"
        "ACCELERATION TIME HISTORY IN UNITS OF G\n"
        "    7    0.01000    NPTS, DT\n" + _values_text(VALUES)
    )
    motion = read_at2(_write(tmp_path, "old.at2", text))
    assert motion.dt == 0.01
    np.testing.assert_allclose(motion.horizontal, np.array(VALUES) * G, rtol=1e-12)


@pytest.mark.parametrize(
    "line",
    [
        "NPTS=      7, DT=   .0100 SEC",
        "NPTS=7,DT=0.01SEC",
        "NPTS = 7    DT = 1.0E-02 SEC",
        "DT= 0.0100 SEC, NPTS= 7",
        "dt=0.01 sec  npts=7",
        "   NPTS=   7,   DT=  0.01",
    ],
)
def test_npts_dt_parsed_by_keyword(tmp_path, line):
    motion = read_at2(_write(tmp_path, "k.AT2", NGA_HEADER + line + "\n" + _values_text(VALUES)))
    assert motion.dt == pytest.approx(0.01, rel=1e-15)
    assert motion.n_samples == 7


def test_fortran_exponents_and_commas(tmp_path):
    body = "0.1D-01, -0.2D-01 3.0e-2\n0 -.015 .004 2E-3\n"
    motion = read_at2(_write(tmp_path, "f.AT2", NGA_HEADER + "NPTS=7, DT=0.01\n" + body))
    np.testing.assert_allclose(motion.horizontal, np.array(VALUES) * G, rtol=1e-12)


def test_at2_units_in_cm_per_s2(tmp_path):
    header = NGA_HEADER.replace("UNITS OF G", "UNITS OF CM/SEC/SEC")
    motion = read_at2(
        _write(tmp_path, "c.AT2", header + "NPTS=7, DT=0.01\n" + _values_text(VALUES))
    )
    np.testing.assert_allclose(motion.horizontal, np.array(VALUES) * 0.01, rtol=1e-12)


# ------------------------------------------------------------- bad AT2 files


def _expect_error(path, *words, **kwargs):
    with pytest.raises(FreestandError) as info:
        load_record(path, **kwargs)
    message = str(info.value)
    assert str(path) in message
    for word in words:
        assert word.lower() in message.lower(), message
    return message


@pytest.mark.parametrize("count, word", [(6, "truncated"), (8, "NPTS=7")])
def test_at2_npts_mismatch(tmp_path, count, word):
    values = (VALUES + [0.001])[:count]
    path = _write(tmp_path, "m.AT2", NGA_HEADER + "NPTS=7, DT=0.01\n" + _values_text(values))
    _expect_error(path, word, f"holds {count} values")


def test_at2_nan(tmp_path):
    body = _values_text(VALUES[:5]) + "            NaN  2.0000000E-03\n"
    path = _write(tmp_path, "n.AT2", NGA_HEADER + "NPTS=7, DT=0.01\n" + body)
    _expect_error(path, "value number 6", "line 6", "not finite")


def test_at2_empty(tmp_path):
    _expect_error(_write(tmp_path, "e.AT2", "\n  \n"), "empty")


def test_at2_header_only(tmp_path):
    _expect_error(_write(tmp_path, "h.AT2", NGA_HEADER + "NPTS=7, DT=0.01\n"), "truncated")


def test_at2_without_npts(tmp_path):
    path = _write(tmp_path, "x.AT2", NGA_HEADER + "7 values at 0.01\n" + _values_text(VALUES))
    _expect_error(path, "NPTS", "DT")


def test_at2_velocity_file(tmp_path):
    header = NGA_HEADER.replace("ACCELERATION", "VELOCITY").replace("UNITS OF G", "UNITS OF CM/S")
    path = _write(tmp_path, "v.AT2", header + "NPTS=7, DT=0.01\n" + _values_text(VALUES))
    _expect_error(path, "velocity time series", "acceleration record")


def test_at2_unknown_unit(tmp_path):
    header = NGA_HEADER.replace("UNITS OF G", "UNITS OF FURLONGS")
    path = _write(tmp_path, "u.AT2", header + "NPTS=7, DT=0.01\n" + _values_text(VALUES))
    _expect_error(path, "FURLONGS", "not a unit of acceleration")


def test_at2_bad_dt(tmp_path):
    path = _write(tmp_path, "d.AT2", NGA_HEADER + "NPTS=7, DT=0\n" + _values_text(VALUES))
    _expect_error(path, "DT=0", "positive")


def test_at2_text_in_values(tmp_path):
    body = _values_text(VALUES) + "END OF DATA\n"
    path = _write(tmp_path, "t.AT2", NGA_HEADER + "NPTS=7, DT=0.01\n" + body)
    _expect_error(path, "line 7", "'END'")


def test_missing_file(tmp_path):
    _expect_error(tmp_path / "nothere.AT2", "not found")


def test_at2_rejects_dt_and_unit_arguments(tmp_path):
    path = _write(tmp_path, "r.AT2", NGA_HEADER + "NPTS=7, DT=0.01\n" + _values_text(VALUES))
    _expect_error(path, "header says DT", dt=0.02)
    _expect_error(path, "leave the unit out", unit="g")
    assert load_record(path, dt=0.01).dt == 0.01


# ------------------------------------------------------------------------ CSV


def _csv(tmp_path, header, rows, name="r.csv"):
    text = header + "\n" + "\n".join(",".join(str(x) for x in row) for row in rows) + "\n"
    return _write(tmp_path, name, text)


@pytest.mark.parametrize(
    "unit, factor",
    [
        ("g", G),
        ("m/s^2", 1.0),
        ("m/s2", 1.0),
        ("cm/s^2", 0.01),
        ("gal", 0.01),
        ("mm/s^2", 1e-3),
        ("cm/sec/sec", 0.01),
    ],
)
def test_csv_units(tmp_path, unit, factor):
    rows = [(0.005 * i, v) for i, v in enumerate(VALUES)]
    motion = read_csv_record(_csv(tmp_path, f"time [s], acceleration [{unit}]", rows))
    assert motion.dt == pytest.approx(0.005, rel=1e-12)
    np.testing.assert_allclose(motion.horizontal, np.array(VALUES) * factor, rtol=1e-12)


def test_csv_time_in_ms_with_offset_and_comments(tmp_path):
    rows = [(1000 + 5 * i, v) for i, v in enumerate(VALUES)]
    path = _csv(tmp_path, "# synthetic test\ntime [ms], horizontal [g]", rows)
    motion = load_record(path)
    assert motion.dt == pytest.approx(0.005, rel=1e-12)
    assert motion.metadata["start_time"] == pytest.approx(1.0, rel=1e-12)
    assert read_csv_record(path).metadata["start_time"] == pytest.approx(1.0, rel=1e-12)
    np.testing.assert_allclose(motion.horizontal, np.array(VALUES) * G, rtol=1e-12)


def test_csv_with_vertical_column(tmp_path):
    rows = [(0.01 * i, v, 0.5 * v) for i, v in enumerate(VALUES)]
    path = _csv(tmp_path, "time [s], horizontal [g], vertical [g]", rows)
    up = load_record(path)  # recorded positive up -> stored downward
    np.testing.assert_allclose(up.vertical, -0.5 * np.array(VALUES) * G, rtol=1e-12)
    down = load_record(path, vertical_positive="down")
    np.testing.assert_allclose(down.vertical, 0.5 * np.array(VALUES) * G, rtol=1e-12)


def test_csv_non_uniform_time(tmp_path):
    times = [0.0, 0.01, 0.02, 0.035, 0.04, 0.05, 0.06]
    path = _csv(tmp_path, "time [s], acceleration [g]", list(zip(times, VALUES, strict=True)))
    _expect_error(path, "not uniformly spaced", "line 5", "resample")


def test_csv_time_not_increasing(tmp_path):
    times = [0.0, 0.01, 0.02, 0.02, 0.04, 0.05, 0.06]
    path = _csv(tmp_path, "time [s], acceleration [g]", list(zip(times, VALUES, strict=True)))
    _expect_error(path, "does not increase", "sort")


def test_csv_wrong_unit(tmp_path):
    rows = [(0.01 * i, v) for i, v in enumerate(VALUES)]
    path = _csv(tmp_path, "time [s], acceleration [m/s]", rows)
    _expect_error(path, "'m/s'", "not a unit of acceleration", "m/s^2")


def test_csv_time_in_wrong_unit(tmp_path):
    rows = [(0.01 * i, v) for i, v in enumerate(VALUES)]
    path = _csv(tmp_path, "time [m], acceleration [g]", rows)
    _expect_error(path, "not a unit of time")


def test_csv_missing_unit(tmp_path):
    rows = [(0.01 * i, v) for i, v in enumerate(VALUES)]
    path = _csv(tmp_path, "time, acceleration", rows)
    _expect_error(path, "no unit in brackets", "time [s], acceleration [g]")


def test_csv_nan(tmp_path):
    rows = [(0.01 * i, v) for i, v in enumerate(VALUES)]
    rows[3] = (0.03, "nan")
    path = _csv(tmp_path, "time [s], acceleration [g]", rows)
    _expect_error(path, "line 5", "not finite")


def test_csv_empty_and_header_only(tmp_path):
    _expect_error(_write(tmp_path, "e.csv", ""), "empty")
    _expect_error(_write(tmp_path, "h.csv", "time [s], acceleration [g]\n"), "at least two")


def test_csv_ragged_row(tmp_path):
    path = _write(tmp_path, "r.csv", "time [s], acceleration [g]\n0, 0.1\n0.01\n")
    _expect_error(path, "line 3", "one value per column")


def test_csv_rejects_dt(tmp_path):
    rows = [(0.01 * i, v) for i, v in enumerate(VALUES)]
    _expect_error(_csv(tmp_path, "time [s], acceleration [g]", rows), "do not give", dt=0.01)


# -------------------------------------------------------------- single column


def test_single_column(tmp_path):
    path = _write(tmp_path, "a.txt", "# accelerations\n" + "\n".join(map(str, VALUES)) + "\n")
    motion = read_single_column(path, 0.02, "cm/s^2")
    assert motion.dt == 0.02
    np.testing.assert_allclose(motion.horizontal, np.array(VALUES) * 0.01, rtol=1e-12)
    same = load_record(path, dt=0.02, unit="cm/s^2")
    np.testing.assert_array_equal(same.horizontal, motion.horizontal)


def test_single_column_needs_dt_and_unit(tmp_path):
    path = _write(tmp_path, "a.dat", "\n".join(map(str, VALUES)))
    _expect_error(path, "give both", "dt")
    _expect_error(path, "give both", unit="g")
    _expect_error(path, "not a unit of acceleration", dt=0.01, unit="kg")


def test_single_column_with_two_columns(tmp_path):
    path = _write(tmp_path, "a.txt", "0.0 0.1\n0.01 0.2\n")
    _expect_error(path, "line 1 holds 2 values", "CSV", dt=0.01, unit="g")


def test_single_column_nan(tmp_path):
    path = _write(tmp_path, "a.txt", "0.1\nnan\n0.2\n")
    _expect_error(path, "line 2", "not finite", dt=0.01, unit="g")


# ------------------------------------------------------ horizontal + vertical


def test_vertical_file_same_step(tmp_path):
    h = _write(tmp_path, "h.AT2", NGA_HEADER + "NPTS=7, DT=0.01\n" + _values_text(VALUES))
    v = _write(
        tmp_path,
        "v.AT2",
        NGA_HEADER + "NPTS=7, DT=0.01\n" + _values_text([0.5 * x for x in VALUES]),
    )
    motion = load_record(h, vertical=v)
    # recorded positive up, stored as downward acceleration
    np.testing.assert_allclose(motion.vertical, -0.5 * np.array(VALUES) * G, rtol=1e-12)
    assert motion.metadata["combination"] == "same step and length"


def test_single_column_pair(tmp_path):
    """dt and unit apply to both single-column files."""
    h = _write(tmp_path, "h.txt", "\n".join(str(x) for x in VALUES))
    v = _write(tmp_path, "v.txt", "\n".join(str(0.5 * x) for x in VALUES))
    motion = load_record(h, vertical=v, dt=0.01, unit="g", vertical_positive="down")
    np.testing.assert_allclose(motion.vertical, 0.5 * np.array(VALUES) * G, rtol=1e-12)


def test_vertical_file_coarser_and_shorter(tmp_path):
    """Rule: finer step for both, linear interpolation, zeros after the shorter."""
    h = _write(tmp_path, "h.AT2", NGA_HEADER + "NPTS=7, DT=0.01\n" + _values_text(VALUES))
    v = _write(tmp_path, "v.AT2", NGA_HEADER + "NPTS=3, DT=0.02\n" + _values_text([0.1, 0.3, 0.1]))
    motion = load_record(h, vertical=v, vertical_positive="down")
    assert motion.dt == 0.01
    np.testing.assert_allclose(motion.vertical / G, [0.1, 0.2, 0.3, 0.2, 0.1, 0.0, 0.0], atol=1e-15)
    assert "resampled" in motion.metadata["combination"]
    assert "padded" in motion.metadata["combination"]


def test_vertical_given_twice(tmp_path):
    rows = [(0.01 * i, v, v) for i, v in enumerate(VALUES)]
    path = _csv(tmp_path, "time [s], horizontal [g], vertical [g]", rows)
    other = _csv(
        tmp_path,
        "time [s], acceleration [g]",
        [(0.01 * i, v) for i, v in enumerate(VALUES)],
        name="o.csv",
    )
    _expect_error(path, "only one", vertical=other)


def test_bad_vertical_positive(tmp_path):
    rows = [(0.01 * i, v) for i, v in enumerate(VALUES)]
    with pytest.raises(FreestandError, match="'up'"):
        load_record(_csv(tmp_path, "time [s], acceleration [g]", rows), vertical_positive="upward")


# ---------------------------------------------------------- shipped example


def test_example_records_are_small_labelled_and_reproducible(tmp_path):
    h_path = EXAMPLES / "synthetic_H.AT2"
    v_path = EXAMPLES / "synthetic_UP.AT2"
    for path in (h_path, v_path):
        assert path.stat().st_size < 200_000
        header = path.read_text().splitlines()[:2]
        assert "SYNTHETIC" in header[0] and "SYNTHETIC" in header[1]
    motion = load_record(h_path, vertical=v_path)
    regenerated = synthetic_ground_motion()
    # tolerance: the files hold 8 significant digits in g
    np.testing.assert_allclose(motion.horizontal, regenerated.horizontal, atol=1e-7 * G)
    np.testing.assert_allclose(motion.vertical, regenerated.vertical, atol=1e-7 * G)
    assert motion.peak_horizontal == pytest.approx(0.25 * G, rel=1e-6)


def test_write_read_roundtrip(tmp_path):
    motion = synthetic_ground_motion(duration=2.0)
    write_at2(tmp_path / "x.AT2", motion, component="vertical")
    back = read_at2(tmp_path / "x.AT2")
    # written positive up: the sign of the downward value is changed
    np.testing.assert_allclose(back.horizontal, -motion.vertical, atol=1e-7 * G)
    assert back.dt == motion.dt
