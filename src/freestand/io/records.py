"""Reading ground-motion records: PEER NGA ``.AT2``, COSMOS ``.V2``, CSV, single column.

Formats (details in ``docs/records.md``):

- **PEER ``.AT2``** (PEER NGA strong-motion database): four header lines --
  title (``PEER NGA STRONG MOTION DATABASE RECORD``, older files
  ``PEER STRONG MOTION DATABASE RECORD``), event/date/station/component, units
  (``ACCELERATION TIME SERIES IN UNITS OF G``), and the sample count and step
  (``NPTS=  16396, DT=   0.005 SEC``) -- then the accelerations, several per
  line. NPTS and DT are found by their keywords, in either order and with any
  spacing; the older form ``  4000   0.0050   NPTS, DT`` is read too. Values
  are in g unless the units line names another acceleration unit.
- **COSMOS / CSMIP ``.V2``** (processed records from CESMD): the acceleration
  block found by its data line (``8000 POINTS OF ACCEL DATA EQUALLY SPACED AT
  .005 SEC, IN CM/SEC/SEC`` or ``8000 acceleration pts, ... units=cm/sec2``);
  see :func:`read_v2_component`.
- **CSV**: a header row naming each column with its unit in brackets, then one
  row per sample: ``time [s], acceleration [g]`` (or ``horizontal [m/s^2]``),
  optionally a third column ``vertical [g]``. Time must be uniform; lines
  starting with ``#`` are comments.
- **single column**: one acceleration per line, no time; the step and the unit
  are given by the caller. Lines starting with ``#`` are comments.

Units: ``g`` (the model's gravitational acceleration), ``m/s^2``, ``cm/s^2``,
``gal`` (= cm/s^2), ``mm/s^2``; for CSV time ``s`` or ``ms``.

Vertical components are recorded positive upward; freestand's ``vertical`` is
the downward support acceleration (weight m (g - a_v)), so the readers change
the sign unless told ``vertical_positive="down"``.

Every problem raises :class:`freestand.errors.FreestandError` naming the file,
what is wrong and how to fix it.
"""

from __future__ import annotations

import csv
import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from freestand.core.motion.ground_motion import GroundMotion, combine_components
from freestand.errors import FreestandError
from freestand.io.units import to_si

ACCELERATION_UNITS_HELP = "g, m/s^2, cm/s^2, gal or mm/s^2"

#: Largest relative deviation of a CSV time step from the mean step.
TIME_STEP_TOLERANCE = 1e-3

_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][-+]?\d+)?"
_NPTS_KEY = re.compile(r"\bNPTS\s*[=:]\s*(" + _NUMBER + r")", re.IGNORECASE)
_DT_KEY = re.compile(r"\bDT\s*[=:]\s*(" + _NUMBER + r")\s*([A-Za-z]*)", re.IGNORECASE)
_OLD_NPTS_DT = re.compile(
    r"^\s*(" + _NUMBER + r")[\s,]+(" + _NUMBER + r")[\s,]+NPTS\s*,?\s*DT", re.IGNORECASE
)
_NUMBER_DIGITS = re.compile(r"\d")


@dataclass(frozen=True)
class RecordComponent:
    """One acceleration component read from a file.

    Parameters
    ----------
    acceleration : numpy.ndarray
        Accelerations [m/s^2] at t_i = i dt, as signed in the file.
    dt : float
        Time step [s].
    source : str
        File it was read from.
    header : tuple of str
        Header lines (AT2) or column names (CSV).
    unit : str
        Unit found in the file or given.
    start_time : float
        Time of the first sample in the file [s] (CSV); the record starts at 0.
    """

    acceleration: np.ndarray
    dt: float
    source: str
    header: tuple[str, ...] = ()
    unit: str = ""
    start_time: float = 0.0


# ------------------------------------------------------------------ helpers


def _read_lines(path: Path) -> list[str]:
    try:
        text = path.read_text(encoding="utf-8", errors="replace")
    except FileNotFoundError:
        raise FreestandError(
            "file not found; check the path of the record", source=str(path)
        ) from None
    except IsADirectoryError:
        raise FreestandError("is a directory, not a record file", source=str(path)) from None
    lines = text.splitlines()
    if not any(line.strip() for line in lines):
        raise FreestandError(
            "the record file is empty; give a file with a header and acceleration values",
            source=str(path),
        )
    return lines


def _parse_float(token: str, source: str, where: str) -> float:
    try:
        return float(token.replace("D", "E").replace("d", "e"))
    except ValueError:
        raise FreestandError(
            f"{where}: cannot read {token!r} as a number; the record must hold numbers only "
            "after its header",
            source=source,
        ) from None


def _unit_factor(unit: str, quantity: str, *, source: str, field: str, gravity: float) -> float:
    """SI factor of an acceleration or time unit written in a record file."""
    text = unit.strip()
    normalised = text.lower().replace("sec", "s").replace(" ", "")
    normalised = re.sub(r"s\*\*2|s2$", "s^2", normalised)
    normalised = normalised.replace("/s/s", "/s^2")
    if quantity == "acceleration":
        if normalised in ("gal", "gals"):
            normalised = "cm/s^2"
        if normalised in ("g", "gs", "ofg"):
            normalised = "g"
        accepted = ACCELERATION_UNITS_HELP
    else:
        accepted = "s or ms"
    if not normalised:
        raise FreestandError(
            f"no unit given; write the unit in brackets, e.g. [{accepted.split(',')[0]}] "
            f"(accepted: {accepted})",
            source=source,
            field=field,
        )
    try:
        factor = to_si(f"1 {normalised}", quantity, field=field, source=source, gravity=gravity)
    except FreestandError:
        raise FreestandError(
            f"unit {unit!r} is not a unit of {quantity}; use one of: {accepted}",
            source=source,
            field=field,
        ) from None
    if not factor > 0:
        raise FreestandError(f"unit {unit!r} is not usable; use one of: {accepted}", source=source)
    return factor


def _check_finite(values: np.ndarray, line_numbers: list[int], source: str, what: str) -> None:
    bad = np.flatnonzero(~np.isfinite(values))
    if bad.size:
        first = int(bad[0])
        raise FreestandError(
            f"{what} value number {first + 1} (line {line_numbers[first]}) is {values[first]!r}; "
            f"{bad.size} value(s) are not finite numbers. Replace missing values (NaN) with "
            "valid accelerations or cut the record before them",
            source=source,
        )


# ---------------------------------------------------------------------- AT2


def _parse_npts_dt(line: str) -> tuple[str, str, str] | None:
    """(NPTS text, DT text, DT unit) found by keyword, or None."""
    npts_match = _NPTS_KEY.search(line)
    dt_match = _DT_KEY.search(line)
    if npts_match and dt_match:
        return npts_match.group(1), dt_match.group(1), dt_match.group(2)
    old = _OLD_NPTS_DT.search(line)
    if old:
        return old.group(1), old.group(2), "s"
    return None


def read_at2_component(path: str | Path, *, gravity: float = 9.81) -> RecordComponent:
    """Read the accelerations of a PEER ``.AT2`` file.

    Parameters
    ----------
    path : str or Path
        The ``.AT2`` file.
    gravity : float, optional
        g [m/s^2] used to convert values in g (default 9.81).

    Returns
    -------
    RecordComponent
        Accelerations [m/s^2] with the sign of the file, the step [s] and the
        header lines.

    Raises
    ------
    FreestandError
        Empty file, no NPTS/DT line, non-acceleration or unknown units,
        non-numeric or non-finite values, or a value count other than NPTS.
    """
    path = Path(path)
    source = str(path)
    lines = _read_lines(path)
    header_end = None
    parsed = None
    for index, line in enumerate(lines[:12]):
        if "NPTS" in line.upper():
            header_end = index
            parsed = _parse_npts_dt(line)
            break
    if header_end is None or parsed is None:
        raise FreestandError(
            "no 'NPTS=..., DT=...' line in the first lines of the header; a PEER .AT2 file "
            "has four header lines, the fourth like 'NPTS=  16396, DT=   0.005 SEC' "
            "(or give a CSV or single-column file instead)",
            source=source,
        )
    header = tuple(lines[: header_end + 1])
    npts_text, dt_text, dt_unit = parsed
    npts_value = _parse_float(npts_text, source, "NPTS")
    if not (npts_value == int(npts_value) and npts_value >= 2):
        raise FreestandError(
            f"NPTS={npts_text} is not a whole number of at least 2; fix the header line "
            f"{header_end + 1}",
            source=source,
        )
    npts = int(npts_value)
    dt = _parse_float(dt_text, source, "DT")
    dt_unit = dt_unit.strip().lower()
    if dt_unit in ("ms", "msec"):
        dt *= 1e-3
    elif dt_unit not in ("", "s", "sec", "secs", "second", "seconds"):
        raise FreestandError(
            f"DT unit {dt_unit!r} on header line {header_end + 1} is not a time unit; "
            "write 'DT= 0.005 SEC'",
            source=source,
        )
    if not (dt > 0 and math.isfinite(dt)):
        raise FreestandError(
            f"DT={dt_text} is not a positive time step; fix header line {header_end + 1}",
            source=source,
        )

    unit = "g"
    unit_note = "assumed (no units line)"
    for line in header[:-1]:
        upper = line.upper()
        if re.search(r"\b(VELOCITY|DISPLACEMENT)\b", upper) and "TIME SERIES" in upper:
            kind = "velocity" if "VELOCITY" in upper else "displacement"
            raise FreestandError(
                f"the header says this is a {kind} time series ({line.strip()!r}); "
                "give the acceleration record (.AT2), not the .VT2/.DT2 file",
                source=source,
            )
        match = re.search(r"UNITS?\s+OF\s+(.+?)\s*$", line, re.IGNORECASE)
        if match:
            unit = match.group(1).strip().rstrip(".")
            unit_note = "from header"
    factor = _unit_factor(unit, "acceleration", source=source, field="units", gravity=gravity)

    values: list[float] = []
    line_numbers: list[int] = []
    for number, line in enumerate(lines[header_end + 1 :], start=header_end + 2):
        for token in line.replace(",", " ").split():
            values.append(_parse_float(token, source, f"line {number}"))
            line_numbers.append(number)
    if not values:
        raise FreestandError(
            "the header is there but no acceleration values follow; the file is truncated",
            source=source,
        )
    acceleration = np.asarray(values, dtype=float)
    _check_finite(acceleration, line_numbers, source, "acceleration")
    if acceleration.size != npts:
        raise FreestandError(
            f"the header says NPTS={npts} but the file holds {acceleration.size} values; "
            "the file is truncated or the header is wrong -- fix NPTS or restore the values",
            source=source,
        )
    return RecordComponent(
        acceleration=acceleration * factor,
        dt=dt,
        source=source,
        header=header,
        unit=f"{unit} ({unit_note})",
    )


def read_at2(path: str | Path, *, gravity: float = 9.81, name: str | None = None) -> GroundMotion:
    """Read a PEER NGA ``.AT2`` file as a horizontal record.

    Parameters
    ----------
    path : str or Path
        The ``.AT2`` file (values in g unless its units line says otherwise).
    gravity : float, optional
        g [m/s^2] for the conversion from g (default 9.81).
    name : str, optional
        Record name (default: the file name).

    Returns
    -------
    GroundMotion
        The file's accelerations [m/s^2] as the horizontal component.
    """
    component = read_at2_component(path, gravity=gravity)
    return _motion_from(component, name)


# ---------------------------------------------------------------- COSMOS V2

_V2_CSMIP = re.compile(
    r"^\s*(\d+)\s+POINTS\s+OF\s+(ACCEL|VELOC|DISPL)\w*\s+DATA\s+EQUALLY\s+SPACED\s+AT\s+("
    + _NUMBER
    + r")\s*(SEC|MSEC|S|MS)\w*\s*,?\s*(?:IN\s+([^.(]+?))?\s*\.?\s*(\(.*\))?\s*$",
    re.IGNORECASE,
)
_V2_COSMOS = re.compile(
    r"^\s*(\d+)\s+(acceleration|velocity|displacement)\s+pts\b(.*)$", re.IGNORECASE
)
_V2_UNITS = re.compile(r"units\s*=\s*([^(,]+)", re.IGNORECASE)
_V2_FORMAT = re.compile(r"\(\s*(\d+)\s*[FE]\s*(\d+)\s*\.\s*\d+\s*\)", re.IGNORECASE)
_V2_STEP = (
    re.compile(r"\bdt\s*[=:]\s*(" + _NUMBER + r")\s*(ms|msec|s|sec)?\b", re.IGNORECASE),
    re.compile(r"\bsampling\s+interval\s*[=:]?\s*(" + _NUMBER + r")\s*(ms|msec|s|sec)?\b",
               re.IGNORECASE),
)  # fmt: skip
_V2_RATE = re.compile(r"(" + _NUMBER + r")\s*(?:sps|samples?\s*/\s*s(?:ec)?)\b", re.IGNORECASE)


def _fixed_width_values(line: str, width: int | None) -> list[str]:
    """Tokens of a data line: fixed-width fields when a Fortran format gives them.

    Fixed-width fields may run together (``-123.456-234.567`` in F8.3); a line
    is cut by width when its length fits the format, by whitespace otherwise.
    """
    text = line.rstrip()
    if width and len(text) % width == 0 and len(text) >= width:
        fields = [text[i : i + width] for i in range(0, len(text), width)]
        if all(field.strip() for field in fields):
            return [field.strip() for field in fields]
    return text.replace(",", " ").split()


def _is_v2_acceleration_line(line: str) -> bool:
    csmip = _V2_CSMIP.match(line)
    if csmip:
        return csmip.group(2).upper().startswith("ACCEL")
    cosmos = _V2_COSMOS.match(line)
    return bool(cosmos) and cosmos.group(2).lower() == "acceleration"


def read_v2_component(
    path: str | Path, *, gravity: float = 9.81, channel: int = 1
) -> RecordComponent:
    """Read the acceleration of a COSMOS / CSMIP ``.V2`` processed record (CESMD).

    Two layouts are read, both by keyword, never by line number:

    - CSMIP (as distributed by CESMD): a text header, then a line such as
      ``8000 POINTS OF ACCEL DATA EQUALLY SPACED AT  .005 SEC, IN CM/SEC/SEC.
      (8F10.3)`` followed by the accelerations; the velocity (``VELOC``) and
      displacement (``DISPL``) blocks that follow are skipped;
    - COSMOS v1.20: a line ``8000 acceleration pts, approx 40 secs,
      units=cm/sec2 (04), Format=(8F10.5)`` followed by the accelerations;
      the time step comes from a ``dt = 0.005 sec``, ``sampling interval`` or
      ``200 sps`` keyword in the header.

    Values in Fortran fixed-width fields that run together are split by the
    field width of the data line's format.

    Parameters
    ----------
    path : str or Path
        The ``.V2`` file; a file with several channels holds one acceleration
        block per channel, one after the other.
    gravity : float, optional
        g [m/s^2] for values in g (default 9.81).
    channel : int, optional
        Which acceleration block to read, 1 for the first (default).

    Returns
    -------
    RecordComponent
        Accelerations [m/s^2] with the sign of the file, the step [s], the
        header lines and the unit.

    Raises
    ------
    FreestandError
        No acceleration data line, no time step, a non-acceleration unit,
        too few or non-numeric values.
    """
    path = Path(path)
    source = str(path)
    lines = _read_lines(path)
    blocks = [index for index, line in enumerate(lines) if _is_v2_acceleration_line(line)]
    if blocks and not 1 <= channel <= len(blocks):
        raise FreestandError(
            f"channel {channel} asked for, but the file holds {len(blocks)} acceleration "
            f"block(s); give a channel from 1 to {len(blocks)}",
            source=source,
        )
    first = blocks[channel - 1] if blocks else 0
    start = None
    for index, line in enumerate(lines):
        if index < first:
            continue
        match = _V2_CSMIP.match(line)
        if match and match.group(2).upper().startswith("ACCEL"):
            npts = int(match.group(1))
            dt = _parse_float(match.group(3), source, f"line {index + 1}")
            if match.group(4).lower().startswith("m"):
                dt *= 1e-3
            unit = (match.group(5) or "cm/sec/sec").strip()
            fmt = match.group(6) or ""
            start = index
            break
        match = _V2_COSMOS.match(line)
        if match and match.group(2).lower() == "acceleration":
            npts = int(match.group(1))
            rest = match.group(3)
            unit_match = _V2_UNITS.search(rest)
            unit = unit_match.group(1).strip() if unit_match else ""
            fmt = rest
            dt = None
            for header_line in lines[:index]:
                for pattern in _V2_STEP:
                    step = pattern.search(header_line)
                    if step:
                        dt = _parse_float(step.group(1), source, "dt")
                        if (step.group(2) or "").lower().startswith("m"):
                            dt *= 1e-3
                        break
                if dt is None:
                    rate = _V2_RATE.search(header_line)
                    if rate:
                        dt = 1.0 / _parse_float(rate.group(1), source, "sps")
                if dt is not None:
                    break
            if dt is None:
                raise FreestandError(
                    f"the acceleration data line {index + 1} has no time step and the header "
                    "states none; a COSMOS .V2 header must give it as 'dt = 0.005 sec', "
                    "'sampling interval 0.005 sec' or '200 sps'",
                    source=source,
                )
            if not unit:
                raise FreestandError(
                    f"the acceleration data line {index + 1} states no units "
                    "('units=cm/sec2'); fix the file",
                    source=source,
                )
            start = index
            break
    if start is None:
        raise FreestandError(
            "no acceleration data line in this .V2 file: a CSMIP file has a line like "
            "'8000 POINTS OF ACCEL DATA EQUALLY SPACED AT .005 SEC, IN CM/SEC/SEC', a COSMOS "
            "file one like '8000 acceleration pts, approx 40 secs, units=cm/sec2'; give a "
            "processed (V2) record, or a .AT2 or CSV file",
            source=source,
        )
    if npts < 2:
        raise FreestandError(
            f"line {start + 1} announces {npts} acceleration points; a record needs at least 2",
            source=source,
        )
    if not (dt > 0 and math.isfinite(dt)):
        raise FreestandError(
            f"time step {dt!r} s on or before line {start + 1} is not positive", source=source
        )
    width_match = _V2_FORMAT.search(fmt)
    width = int(width_match.group(2)) if width_match else None
    factor = _unit_factor(unit, "acceleration", source=source, field="units", gravity=gravity)
    values: list[float] = []
    line_numbers: list[int] = []
    for number, line in enumerate(lines[start + 1 :], start=start + 2):
        if len(values) >= npts:
            break
        if _V2_CSMIP.match(line) or _V2_COSMOS.match(line) or line.lower().startswith("end-of"):
            break
        for token in _fixed_width_values(line, width):
            values.append(_parse_float(token, source, f"line {number}"))
            line_numbers.append(number)
    if len(values) < npts:
        raise FreestandError(
            f"line {start + 1} announces {npts} acceleration points but only {len(values)} "
            "follow; the file is truncated",
            source=source,
        )
    acceleration = np.asarray(values[:npts], dtype=float)
    _check_finite(acceleration, line_numbers, source, "acceleration")
    previous = 0  # the channel's header starts after the previous channel's end marker
    for index in range(start - 1, -1, -1):
        marker = lines[index].strip().lower()
        if marker.startswith("/&") or marker.startswith("end-of-data"):
            previous = index + 1
            break
    return RecordComponent(
        acceleration=acceleration * factor,
        dt=float(dt),
        source=source,
        header=tuple(lines[previous : start + 1]),
        unit=f"{unit} (channel {channel} of {len(blocks)})",
    )


def read_v2(path: str | Path, *, gravity: float = 9.81, name: str | None = None) -> GroundMotion:
    """Read a COSMOS / CSMIP ``.V2`` file as a horizontal record (see :func:`read_v2_component`)."""
    return _motion_from(read_v2_component(path, gravity=gravity), name)


# ---------------------------------------------------------------------- CSV

_HEADER_CELL = re.compile(r"^\s*([A-Za-z_ ]+?)\s*[\[(]\s*([^\])]*)\s*[\])]\s*$")


def _read_csv_columns(path: Path, gravity: float):
    source = str(path)
    lines = _read_lines(path)
    rows = [
        (number, line)
        for number, line in enumerate(lines, start=1)
        if line.strip() and not line.lstrip().startswith("#")
    ]
    if not rows:
        raise FreestandError("the record file holds only comments", source=source)
    header_number, header_line = rows[0]
    cells = next(csv.reader([header_line]))
    fix = (
        "the first row must name the columns with units, e.g. "
        "'time [s], acceleration [g]' or 'time [s], horizontal [m/s^2], vertical [m/s^2]'"
    )
    names = []
    units = []
    for cell in cells:
        match = _HEADER_CELL.match(cell)
        if not match:
            raise FreestandError(
                f"header cell {cell.strip()!r} (line {header_number}) has no unit in brackets; "
                + fix,
                source=source,
            )
        names.append(match.group(1).strip().lower())
        units.append(match.group(2).strip())
    if len(names) not in (2, 3) or names[0] != "time":
        raise FreestandError(f"columns {cells!r} are not understood; " + fix, source=source)
    if names[1] not in ("acceleration", "horizontal"):
        raise FreestandError(
            f"second column is {names[1]!r}; name it 'acceleration' or 'horizontal'; " + fix,
            source=source,
        )
    if len(names) == 3 and names[2] != "vertical":
        raise FreestandError(
            f"third column is {names[2]!r}; only a 'vertical' column may follow; " + fix,
            source=source,
        )
    time_factor = _unit_factor(units[0], "time", source=source, field=cells[0].strip(), gravity=1)
    acc_factors = [
        _unit_factor(u, "acceleration", source=source, field=c.strip(), gravity=gravity)
        for u, c in zip(units[1:], cells[1:], strict=True)
    ]
    data = []
    line_numbers = []
    for number, line in rows[1:]:
        row = next(csv.reader([line]))
        if len(row) != len(names):
            raise FreestandError(
                f"line {number} has {len(row)} values, the header {len(names)} columns; "
                "every row needs one value per column",
                source=source,
            )
        data.append([_parse_float(cell.strip(), source, f"line {number}") for cell in row])
        line_numbers.append(number)
    if len(data) < 2:
        raise FreestandError(
            f"the file holds {len(data)} data row(s); a record needs at least two samples",
            source=source,
        )
    table = np.asarray(data, dtype=float)
    for column in range(table.shape[1]):
        _check_finite(table[:, column], line_numbers, source, f"column {cells[column].strip()!r}")
    time = table[:, 0] * time_factor
    steps = np.diff(time)
    if np.any(steps <= 0):
        bad = int(np.flatnonzero(steps <= 0)[0])
        raise FreestandError(
            f"time does not increase at line {line_numbers[bad + 1]} "
            f"({table[bad, 0]!r} then {table[bad + 1, 0]!r}); sort the rows by time and "
            "remove duplicates",
            source=source,
        )
    dt = (time[-1] - time[0]) / (time.size - 1)
    deviation = np.abs(steps - dt)
    if np.max(deviation) > TIME_STEP_TOLERANCE * dt:
        bad = int(np.argmax(deviation))
        raise FreestandError(
            f"time is not uniformly spaced: the step at line {line_numbers[bad + 1]} is "
            f"{steps[bad]:.6g} s against a mean step of {dt:.6g} s; resample the record to a "
            "uniform time step (freestand integrates piecewise-linear records at a fixed step)",
            source=source,
        )
    columns = [table[:, i + 1] * f for i, f in enumerate(acc_factors)]
    return dt, time[0], columns, tuple(cells), units


def read_csv_record(
    path: str | Path,
    *,
    gravity: float = 9.81,
    name: str | None = None,
    vertical_positive: str = "up",
) -> GroundMotion:
    """Read a CSV record with a header row naming columns and units.

    Parameters
    ----------
    path : str or Path
        CSV file: ``time [s], acceleration [g]`` (or ``horizontal [unit]``),
        optionally ``vertical [unit]``; units g, m/s^2, cm/s^2, gal, mm/s^2;
        time in s or ms, uniformly spaced (within 0.1 % of the mean step).
    gravity : float, optional
        g [m/s^2] for values in g (default 9.81).
    name : str, optional
        Record name (default: the file name).
    vertical_positive : str, optional
        ``"up"`` (default, as instruments record) or ``"down"``: the sense of
        the vertical column; it is stored as downward acceleration.

    Returns
    -------
    GroundMotion
        The record; a time offset of the first row is kept in
        ``metadata["start_time"]`` and the record starts at t = 0.
    """
    path = Path(path)
    sign = _vertical_sign(vertical_positive)
    dt, start, columns, header, units = _read_csv_columns(path, gravity)
    vertical = columns[1] * sign if len(columns) > 1 else None
    return GroundMotion(
        dt,
        columns[0],
        vertical,
        name=name or path.name,
        metadata={
            "source": str(path),
            "format": "csv",
            "header": header,
            "units": tuple(units),
            "start_time": float(start),
        },
    )


# -------------------------------------------------------------- single column


def read_single_column_component(
    path: str | Path, dt: float, unit: str, *, gravity: float = 9.81
) -> RecordComponent:
    """Read a file of one acceleration per line (see :func:`read_single_column`)."""
    path = Path(path)
    source = str(path)
    if not path.is_file():
        _read_lines(path)  # a missing file or a folder: says so (before asking for dt, unit)
    if dt is None or unit is None:
        raise FreestandError(
            "a single-column record holds no time step or unit; give both, e.g. "
            "dt=0.01 and unit='g' (command line: --dt 0.01 --unit g)",
            source=source,
        )
    try:
        dt = float(dt)
    except (TypeError, ValueError):
        raise FreestandError(f"dt={dt!r} is not a number of seconds", source=source) from None
    if not (dt > 0 and math.isfinite(dt)):
        raise FreestandError(f"dt={dt!r} must be a positive time step [s]", source=source)
    factor = _unit_factor(str(unit), "acceleration", source=source, field="unit", gravity=gravity)
    lines = _read_lines(path)
    values = []
    line_numbers = []
    for number, line in enumerate(lines, start=1):
        text = line.strip().rstrip(",")
        if not text or text.startswith("#"):
            continue
        tokens = text.replace(",", " ").split()
        if len(tokens) != 1:
            raise FreestandError(
                f"line {number} holds {len(tokens)} values; a single-column record holds one "
                "acceleration per line (for time and acceleration use a CSV file with a header "
                "'time [s], acceleration [g]')",
                source=source,
            )
        values.append(_parse_float(tokens[0], source, f"line {number}"))
        line_numbers.append(number)
    if len(values) < 2:
        raise FreestandError(
            f"the file holds {len(values)} value(s); a record needs at least two samples",
            source=source,
        )
    acceleration = np.asarray(values, dtype=float)
    _check_finite(acceleration, line_numbers, source, "acceleration")
    return RecordComponent(acceleration * factor, dt, source, (), str(unit))


def read_single_column(
    path: str | Path,
    dt: float,
    unit: str,
    *,
    gravity: float = 9.81,
    name: str | None = None,
) -> GroundMotion:
    """Read a plain file of accelerations, one per line, as a horizontal record.

    Parameters
    ----------
    path : str or Path
        The file; blank lines and lines starting with ``#`` are skipped.
    dt : float
        Time step [s].
    unit : str
        Unit of the values: g, m/s^2, cm/s^2, gal or mm/s^2.
    gravity : float, optional
        g [m/s^2] for values in g (default 9.81).
    name : str, optional
        Record name (default: the file name).
    """
    return _motion_from(read_single_column_component(path, dt, unit, gravity=gravity), name)


# ------------------------------------------------------------------ dispatch


def _vertical_sign(vertical_positive: str) -> float:
    if vertical_positive == "up":
        return -1.0
    if vertical_positive == "down":
        return 1.0
    raise FreestandError(
        f"vertical_positive={vertical_positive!r}; give 'up' (as instruments record) or 'down'",
        field="vertical_positive",
    )


def _motion_from(component: RecordComponent, name: str | None) -> GroundMotion:
    return GroundMotion(
        component.dt,
        component.acceleration,
        name=name or Path(component.source).name,
        metadata={
            "source": component.source,
            "header": component.header,
            "unit": component.unit,
        },
    )


#: Largest plausible acceleration in a record, in g: beyond it the values are in another unit
#: than the file says, or corrupt (a record of 1e150 g would overflow the simulation).
RECORD_LIMIT_G = 100.0


def check_record_values(values: np.ndarray, source: str, gravity: float, what: str) -> None:
    """FreestandError for non-finite values or a peak beyond :data:`RECORD_LIMIT_G`."""
    values = np.asarray(values, dtype=float)
    if values.size and not np.all(np.isfinite(values)):
        index = int(np.flatnonzero(~np.isfinite(values))[0])
        raise FreestandError(
            f"the {what} acceleration has a value that is not a number ({values[index]!r}) at "
            f"sample {index + 1}; fix or remove that sample",
            source=source,
        )
    peak = float(np.max(np.abs(values))) if values.size else 0.0
    if peak > RECORD_LIMIT_G * gravity:
        raise FreestandError(
            f"the {what} acceleration reaches {peak:.3g} m/s^2 ({peak / gravity:.3g} g), beyond "
            f"the plausible {RECORD_LIMIT_G:g} g; check the file's unit (g, m/s^2, cm/s^2...) "
            "and its values",
            source=source,
        )


def _read_component(
    path: Path, dt, unit, gravity, what: str = "horizontal"
) -> tuple[RecordComponent, np.ndarray | None]:
    """One file by its extension; returns the (first) component and a CSV vertical column."""
    component, vertical = _read_component_file(path, dt, unit, gravity)
    check_record_values(component.acceleration, str(path), gravity, what)
    if vertical is not None:
        check_record_values(vertical, str(path), gravity, "vertical")
    return component, vertical


def _read_component_file(
    path: Path, dt, unit, gravity
) -> tuple[RecordComponent, np.ndarray | None]:
    suffix = path.suffix.lower()
    source = str(path)
    if suffix == ".at2":
        component = read_at2_component(path, gravity=gravity)
        if unit is not None:
            raise FreestandError(
                f"unit={unit!r} given, but an .AT2 file states its unit in its header; "
                "leave the unit out",
                source=source,
            )
        if dt is not None and not math.isclose(float(dt), component.dt, rel_tol=1e-9):
            raise FreestandError(
                f"dt={dt!r} given, but the header says DT={component.dt!r}; leave dt out",
                source=source,
            )
        return component, None
    if suffix == ".v2":
        component = read_v2_component(path, gravity=gravity)
        if unit is not None or dt is not None:
            raise FreestandError(
                "a .V2 file states its time step and unit in its header; do not give dt or unit",
                source=source,
            )
        return component, None
    if suffix == ".csv":
        if dt is not None or unit is not None:
            raise FreestandError(
                "a CSV record holds its time column and units in its header; do not give "
                "dt or unit",
                source=source,
            )
        step, start, columns, header, units = _read_csv_columns(path, gravity)
        component = RecordComponent(columns[0], step, source, header, units[1], float(start))
        return component, (columns[1] if len(columns) > 1 else None)
    return read_single_column_component(path, dt, unit, gravity=gravity), None


def load_record(
    path: str | Path,
    *,
    dt: float | None = None,
    unit: str | None = None,
    gravity: float = 9.81,
    vertical: str | Path | None = None,
    vertical_positive: str = "up",
    name: str | None = None,
    horizontal_y: str | Path | None = None,
) -> GroundMotion:
    """Read a record by its file type, with an optional vertical and second horizontal component.

    Parameters
    ----------
    path : str or Path
        Horizontal record (x): ``.AT2`` (PEER), ``.V2`` (COSMOS/CSMIP), ``.csv`` (header with
        units) or any other extension as a single-column file.
    dt : float, optional
        Time step [s]; needed for single-column files only.
    unit : str, optional
        Acceleration unit (g, m/s^2, cm/s^2, gal, mm/s^2); needed for
        single-column files only.
    gravity : float, optional
        g [m/s^2] that the unit g stands for (default 9.81).
    vertical : str or Path, optional
        A second file with the vertical component (any of the formats;
        ``dt`` and ``unit`` apply to it as well). Not allowed when the CSV
        already has a vertical column.
    vertical_positive : str, optional
        Sense of the vertical values in the files: ``"up"`` (default, as
        recorded) or ``"down"``. freestand stores downward acceleration.
    name : str, optional
        Record name (default: the file name).
    horizontal_y : str or Path, optional
        A file with the second horizontal component, along y (seen from
        above, x turned 90 degrees counter-clockwise); any of the formats.
        :func:`freestand.io.pairing.pair_components` finds which files of a
        station are x, y and vertical from their names or headers.

    Returns
    -------
    GroundMotion
        Horizontal [m/s^2] and, if given, second horizontal and downward
        vertical [m/s^2] acceleration. Components with different steps or
        lengths are combined by
        :func:`freestand.core.motion.ground_motion.combine_components` (finer
        step, linear interpolation, zeros after the shorter one).

    Examples
    --------
    >>> import freestand as fs
    >>> record = fs.load_record("examples/records/synthetic_H.AT2",
    ...                         vertical="examples/records/synthetic_UP.AT2")
    >>> record.dt, record.n_samples, record.components  # [s], [-]
    (0.005, 3001, ('horizontal', 'vertical'))
    >>> round(record.peak_horizontal, 3)  # [m/s^2]
    2.453
    >>> record.scaled_to_peak(8.0).peak_horizontal
    8.0
    """
    path = Path(path)
    sign = _vertical_sign(vertical_positive)
    component, csv_vertical = _read_component(path, dt, unit, gravity)
    metadata = {
        "source": str(path),
        "header": component.header,
        "unit": component.unit,
        "start_time": component.start_time,
        "vertical_positive_in_file": vertical_positive,
    }
    record_name = name or path.name
    if vertical is not None and csv_vertical is not None:
        raise FreestandError(
            "the CSV already has a vertical column and a vertical file was given too; "
            "give only one of them",
            source=str(path),
        )
    second = None
    if horizontal_y is not None:
        second = _read_single_component(Path(horizontal_y), dt, unit, gravity, "horizontal_y")
        metadata["horizontal_y_source"] = str(horizontal_y)
        metadata["horizontal_y_header"] = second.header
    if csv_vertical is not None and second is None:
        return GroundMotion(
            component.dt, component.acceleration, sign * csv_vertical, record_name, metadata
        )
    if vertical is None and csv_vertical is None and second is None:
        return GroundMotion(component.dt, component.acceleration, None, record_name, metadata)
    down, down_dt = None, None
    if csv_vertical is not None:
        down, down_dt = sign * csv_vertical, component.dt
    elif vertical is not None:
        vertical_component = _read_single_component(Path(vertical), dt, unit, gravity, "vertical")
        metadata["vertical_source"] = str(vertical)
        metadata["vertical_header"] = vertical_component.header
        down, down_dt = sign * vertical_component.acceleration, vertical_component.dt
    return combine_components(
        component.acceleration,
        component.dt,
        down,
        down_dt,
        horizontal_y=None if second is None else second.acceleration,
        horizontal_y_dt=None if second is None else second.dt,
        name=record_name,
        metadata=metadata,
    )


def _read_single_component(path: Path, dt, unit, gravity, what: str) -> RecordComponent:
    """The one component of a file given for ``what`` (a CSV with two columns is refused)."""
    component, extra = _read_component(path, dt, unit, gravity, what)
    if extra is not None:
        raise FreestandError(
            f"the {what} file has two acceleration columns; give a file with one component",
            source=str(path),
        )
    return component


def v2_channel_count(path: str | Path) -> int:
    """Number of acceleration blocks (channels) in a ``.V2`` file [-] (0 when none)."""
    return sum(1 for line in _read_lines(Path(path)) if _is_v2_acceleration_line(line))


# -------------------------------------------------------------------- writing


def write_at2(
    path: str | Path,
    motion: GroundMotion,
    *,
    component: str = "horizontal",
    title: str = "PEER NGA STRONG MOTION DATABASE RECORD",
    description: str = "",
    gravity: float = 9.81,
    values_per_line: int = 5,
) -> None:
    """Write one component of a record as a PEER ``.AT2`` file (values in g).

    Parameters
    ----------
    path : str or Path
        File to write.
    motion : GroundMotion
        The record.
    component : str, optional
        ``"horizontal"`` (x), ``"horizontal_y"`` or ``"vertical"``; the vertical is written positive
        upward, as recorded (the sign of freestand's downward value changed).
    title : str, optional
        Header line 1.
    description : str, optional
        Header line 2 (event, date, station, component).
    gravity : float, optional
        g [m/s^2] for the conversion to g.
    values_per_line : int, optional
        Values per data line (default 5).
    """
    values = motion.component(component) / gravity
    if component == "vertical":
        values = -values
    lines = [
        title,
        description or motion.name,
        "ACCELERATION TIME SERIES IN UNITS OF G",
        f"NPTS= {values.size:7d}, DT= {motion.dt:.10g} SEC",
    ]
    for start in range(0, values.size, values_per_line):
        lines.append("".join(f"{x:15.7E}" for x in values[start : start + values_per_line]))
    Path(path).write_text("\n".join(lines) + "\n", encoding="ascii")


@dataclass(frozen=True)
class SpectralTarget:
    """A record-scaling target: pseudo-acceleration at one oscillator frequency.

    Parameters
    ----------
    acceleration : float
        Wanted spectral pseudo-acceleration PSA(f, zeta) [m/s^2].
    frequency : float
        Oscillator natural frequency f [Hz].
    damping : float
        Damping ratio zeta [-].
    """

    acceleration: float
    frequency: float
    damping: float


def parse_spectral_target(
    text: str, *, gravity: float = 9.81, source: str = "--spectral"
) -> SpectralTarget:
    """Read ``"A@F[,DAMPING]"``, e.g. ``"10.31@2.5"`` or ``"1.05g@2.5Hz,2%"``.

    Parameters
    ----------
    text : str
        Spectral acceleration (bare numbers in m/s^2, or with a unit, ``g``
        being ``gravity``), ``@``, the frequency (bare numbers in Hz) and
        optionally the damping (fraction or percentage, default 5 %).
    gravity : float, optional
        g [m/s^2].
    source : str, optional
        Name of the option, for messages.

    Raises
    ------
    FreestandError
        For a text not of that form, a negative acceleration, a frequency that
        is not positive or a damping outside [0, 1).
    """
    from freestand.io.units import damping_fraction

    value, at, rest = text.partition("@")
    if not at or not value.strip() or not rest.strip():
        raise FreestandError(
            f"{text!r} is not ACCELERATION@FREQUENCY[,DAMPING]; e.g. 1.05g@2.5Hz,5%",
            source=source,
        )
    frequency_text, _, damping_text = rest.partition(",")
    acceleration = to_si(
        value.strip(), "acceleration", field="acceleration", source=source, gravity=gravity
    )
    if acceleration < 0:
        raise FreestandError(
            f"{value.strip()!r} is negative; give a spectral acceleration >= 0",
            source=source,
            field="acceleration",
        )
    frequency = to_si(frequency_text.strip(), "frequency", field="frequency", source=source)
    if not frequency > 0:
        raise FreestandError(
            f"{frequency_text.strip()!r} is not a positive frequency; e.g. 2.5Hz",
            source=source,
            field="frequency",
        )
    damping = (
        damping_fraction(damping_text.strip(), field="damping", source=source)
        if damping_text.strip()
        else 0.05
    )
    return SpectralTarget(acceleration, frequency, damping)


def write_csv_record(
    path: str | Path,
    motion: GroundMotion,
    *,
    component: str = "horizontal",
    gravity: float = 9.81,
    comments: tuple[str, ...] = (),
) -> None:
    """Write one component of a record as a CSV file ``time [s], acceleration [g]``.

    Parameters
    ----------
    path : str or Path
        File to write.
    motion : GroundMotion
        The record.
    component : str, optional
        ``"horizontal"`` (x), ``"horizontal_y"`` or ``"vertical"``; the vertical is written positive
        upward, as recorded (and as :func:`load_record` expects).
    gravity : float, optional
        g [m/s^2] for the conversion to g.
    comments : tuple of str, optional
        Lines written first, each after ``# ``.

    Notes
    -----
    Fixed formatting (time with 4 decimals, accelerations ``%.7e``), so the
    same record gives the same bytes.
    """
    values = motion.component(component) / gravity
    if component == "vertical":
        values = -values
    lines = [f"# {line}" for line in comments]
    lines.append("time [s], acceleration [g]")
    lines.extend(f"{i * motion.dt:.4f}, {value:.7e}" for i, value in enumerate(values.tolist()))
    Path(path).write_text("\n".join(lines) + "\n", encoding="ascii")
