"""COSMOS / CSMIP ``.V2`` processed records (as distributed by CESMD)."""

from __future__ import annotations

import numpy as np
import pytest

from freestand.errors import FreestandError
from freestand.io.records import load_record, read_v2, read_v2_component

# The CSMIP processed-data layout: a text header (record, station, processing),
# integer and real header lines, then for each channel the acceleration, velocity
# and displacement blocks, each announced by a line stating the number of points,
# the step and the unit, values in Fortran fixed-width fields (8F10.3), and '/&'
# closing the channel.
HEADER = """CORRECTED ACCELEROGRAM DATA
 NORTHRIDGE EARTHQUAKE  JANUARY 17, 1994 04:31 PST
 STATION NO. 24087  34.236N, 118.439W   ARLETA - NORDHOFF FIRE STATION
 CHAN 1:  90 DEG
 INSTRUMENT PERIOD = .042 SEC  DAMPING = .56
 PEAK ACCELERATION =   12.345 CM/SEC/SEC  AT    0.030 SEC
 PEAK VELOCITY     =    1.234 CM/SEC      AT    0.050 SEC
 BANDPASS FILTER FROM  .10 TO 25.0 HZ
   24087      1     90      1  1994     17
    .005   .042   .560   .100  25.000
"""


def _fixed(values, width=10, per_line=8, decimals=3):
    rows = []
    for start in range(0, len(values), per_line):
        rows.append("".join(f"{v:{width}.{decimals}f}" for v in values[start : start + per_line]))
    return "\n".join(rows)


def _csmip_channel(acc, dt="  .005", unit="CM/SEC/SEC", label="CHAN 1:  90 DEG"):
    n = len(acc)
    velocity = np.cumsum(acc) * 0.005
    return (
        HEADER.replace("CHAN 1:  90 DEG", label)
        + f"  {n:5d} POINTS OF ACCEL DATA EQUALLY SPACED AT {dt} SEC, IN {unit}.  (8F10.3)\n"
        + _fixed(acc)
        + f"\n  {n:5d} POINTS OF VELOC DATA EQUALLY SPACED AT {dt} SEC, IN CM/SEC.  (8F10.3)\n"
        + _fixed(velocity)
        + f"\n  {n:5d} POINTS OF DISPL DATA EQUALLY SPACED AT {dt} SEC, IN CM.  (8F10.3)\n"
        + _fixed(np.zeros(n))
        + "\n/&\n"
    )


ACC = np.array([0.0, 1.5, -2.25, 12.345, -1234.5, 3.0, 0.125, -0.5, 7.0, -8.0, 1.0, 0.0])


def test_csmip_v2_reads_acceleration_by_keyword(tmp_path):
    path = tmp_path / "ARLETA.V2"
    path.write_text(_csmip_channel(ACC))
    motion = load_record(path)
    assert motion.dt == pytest.approx(0.005)
    # cm/s^2 to m/s^2; the velocity and displacement blocks are not read
    assert np.allclose(motion.horizontal, ACC / 100.0)
    assert motion.n_samples == ACC.size
    # "-1234.500" fills its 10-character field: fields that run together are cut by width
    assert "-1234.500" in path.read_text()


def test_csmip_v2_fields_running_together(tmp_path):
    values = np.array([-1234.567, -2345.678, 123.456, -9999.999, 1.0, 2.0, 3.0, 4.0])
    text = _csmip_channel(values).replace(_fixed(values), _fixed(values, width=9))
    text = text.replace("(8F10.3)", "(8F9.3)", 1)
    path = tmp_path / "tight.v2"
    path.write_text(text)
    assert "-1234.567-2345.678" in text
    assert np.allclose(read_v2(path).horizontal, values / 100.0)


def test_v2_second_channel_and_units_in_g(tmp_path):
    path = tmp_path / "two.V2"
    second = np.array([0.01, -0.02, 0.03, 0.0])
    path.write_text(
        _csmip_channel(ACC)
        + _csmip_channel(second, dt=".010", unit="G", label="CHAN 2: UP").replace(
            "(8F10.3)", "(8F10.3)"
        )
    )
    component = read_v2_component(path, channel=2)
    assert component.dt == pytest.approx(0.01)
    assert np.allclose(component.acceleration, second * 9.81, atol=5e-3)
    assert any("CHAN 2: UP" in line for line in component.header)
    assert "channel 2 of 2" in component.unit
    with pytest.raises(FreestandError, match="channel 3"):
        read_v2_component(path, channel=3)


def test_cosmos_v2_layout(tmp_path):
    lines = [
        "Corrected acceleration  (Format v01.20 with 13 text lines) Src: test.v2",
        "Test earthquake  Jan 17, 1994",
        "Processed: CSMIP, dt = 0.01 sec",
        "   6 acceleration pts, approx   0 secs, units=cm/sec2 (04), Format=(6F10.5)",
        "   1.00000  -2.00000   3.00000  -4.00000   5.00000  -6.00000",
        "End-of-data for Chan  1 acceleration",
    ]
    path = tmp_path / "cosmos.V2"
    path.write_text("\n".join(lines) + "\n")
    motion = load_record(path)
    assert motion.dt == pytest.approx(0.01)
    assert np.allclose(motion.horizontal, np.array([1, -2, 3, -4, 5, -6]) / 100.0)


def test_v2_errors_name_the_problem(tmp_path):
    path = tmp_path / "bad.V2"
    path.write_text("CORRECTED ACCELEROGRAM DATA\n 1.0 2.0 3.0\n")
    with pytest.raises(FreestandError, match="no acceleration data line"):
        load_record(path)
    path.write_text(_csmip_channel(ACC).replace("  12 POINTS OF ACCEL", "  40 POINTS OF ACCEL"))
    with pytest.raises(FreestandError, match="announces 40 acceleration points"):
        load_record(path)
    path.write_text(_csmip_channel(ACC).replace("IN CM/SEC/SEC", "IN CM/SEC"))
    with pytest.raises(FreestandError, match="not a unit of acceleration"):
        load_record(path)
    cosmos = "   6 acceleration pts, approx 0 secs, units=cm/sec2 (04), Format=(6F10.5)\n" + (
        "   1.0 2.0 3.0 4.0 5.0 6.0\n"
    )
    path.write_text(cosmos)
    with pytest.raises(FreestandError, match="no time step"):
        load_record(path)
    path.write_text(_csmip_channel(ACC))
    with pytest.raises(FreestandError, match="do not give dt or unit"):
        load_record(path, dt=0.01)


@pytest.mark.parametrize(
    "data_line",
    [
        "  12 POINTS OF ACCEL DATA EQUALLY SPACED AT  .005 SEC, IN CM/SEC2.  (FORMAT=(8F10.3))",
        "      12 points of accel data equally spaced at 0.005 sec, in cm/sec/sec. (8F10.3)",
        "  12 POINTS OF ACCELERATION DATA EQUALLY SPACED AT 5 MSEC, IN CM/SEC/SEC",
    ],
)
def test_csmip_data_line_variants(tmp_path, data_line):
    text = _csmip_channel(ACC)
    lines = text.splitlines()
    index = next(i for i, line in enumerate(lines) if "POINTS OF ACCEL" in line)
    lines[index] = data_line
    path = tmp_path / "variant.V2"
    path.write_text("\n".join(lines) + "\n")
    motion = load_record(path)
    assert motion.dt == pytest.approx(0.005)
    assert np.allclose(motion.horizontal, ACC / 100.0)
