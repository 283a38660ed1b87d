"""Record suites: a TOML file that lists ground-motion records.

A suite is one input for campaigns over many ground motions (fragility, record
spectra). It lists records by file, with paths relative to the suite file::

    name = "RG 1.60, 0.3 g, 30 records"

    [[record]]
    horizontal = "rec01_H.AT2"
    vertical = "rec01_UP.AT2"    # optional
    scale = 1.0                  # optional, applied to both components
    name = "rec01"               # optional, default: the horizontal file's name
    dt = "0.005 s"               # single-column files only
    unit = "g"                   # single-column files only

Every record is read by :func:`freestand.io.records.load_record` (AT2, CSV,
single column, and the other formats it knows). Every problem raises
:class:`freestand.errors.FreestandError` naming the suite file, the record and
the fix.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass
from pathlib import Path

from freestand.core.motion.ground_motion import GroundMotion
from freestand.errors import FreestandError
from freestand.io.records import load_record
from freestand.io.units import to_si

_RECORD_KEYS = {"horizontal", "vertical", "scale", "name", "dt", "unit"}
_SUITE_KEYS = {"name", "record", "description"}


@dataclass(frozen=True)
class RecordSuite:
    """Ground-motion records read from a suite file.

    Attributes
    ----------
    name : str
        Suite name (the file's ``name``, default the file name).
    motions : tuple of GroundMotion
        The records, scaled by their ``scale`` [m/s^2 samples], in file order.
    source : str
        The suite file.
    scales : tuple of float
        The ``scale`` factor [-] applied to each record.
    files : tuple of tuple of str
        The (horizontal, vertical or "") files of each record, as resolved.
    """

    name: str
    motions: tuple[GroundMotion, ...]
    source: str
    scales: tuple[float, ...]
    files: tuple[tuple[str, str], ...]

    def __len__(self) -> int:
        return len(self.motions)


def _scale(value, source: str, field: str) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise FreestandError(
            f"scale must be a number, not {value!r}; write for example scale = 1.5",
            source=source,
            field=field,
        )
    scale = float(value)
    if not (math.isfinite(scale) and scale > 0.0):
        raise FreestandError(
            f"scale must be positive and finite, not {value!r}; give a factor such as 1.0",
            source=source,
            field=field,
        )
    return scale


def load_suite(path: str | Path, *, gravity: float = 9.81) -> RecordSuite:
    """Read a record suite file (TOML).

    Parameters
    ----------
    path : str or Path
        The suite file; record paths in it are relative to its folder.
    gravity : float, optional
        g [m/s^2] that the unit g stands for in the records (default 9.81).

    Returns
    -------
    RecordSuite
        The records in file order, each scaled by its ``scale``.
    """
    path = Path(path)
    source = str(path)
    if not path.is_file():
        raise FreestandError(
            "no such suite file; give the path of a TOML file with [[record]] tables",
            source=source,
        )
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError) as error:
        raise FreestandError(f"cannot read the suite file ({error})", source=source) from None
    except tomllib.TOMLDecodeError as error:
        raise FreestandError(
            f"not valid TOML ({error}); fix the syntax at that line", source=source
        ) from None
    unknown = sorted(set(data) - _SUITE_KEYS)
    if unknown:
        raise FreestandError(
            f"unknown key(s) {', '.join(unknown)}; a suite has 'name' and [[record]] tables",
            source=source,
        )
    entries = data.get("record")
    if not isinstance(entries, list) or not entries:
        raise FreestandError(
            'the suite lists no record; add [[record]] tables with horizontal = "FILE"',
            source=source,
        )
    folder = path.parent
    motions, scales, files = [], [], []
    for index, entry in enumerate(entries):
        field = f"record[{index}]"
        if not isinstance(entry, dict):
            raise FreestandError("each record must be a [[record]] table", source=source)
        unknown = sorted(set(entry) - _RECORD_KEYS)
        if unknown:
            raise FreestandError(
                f"unknown key(s) {', '.join(unknown)}; a record takes "
                + ", ".join(sorted(_RECORD_KEYS)),
                source=source,
                field=field,
            )
        horizontal = entry.get("horizontal")
        if not isinstance(horizontal, str) or not horizontal:
            raise FreestandError(
                'give the horizontal record file, e.g. horizontal = "rec01_H.AT2"',
                source=source,
                field=f"{field}.horizontal",
            )
        vertical = entry.get("vertical")
        if vertical is not None and (not isinstance(vertical, str) or not vertical):
            raise FreestandError(
                'vertical must be a file name, e.g. vertical = "rec01_UP.AT2"',
                source=source,
                field=f"{field}.vertical",
            )
        scale = _scale(entry.get("scale", 1.0), source, f"{field}.scale")
        dt = entry.get("dt")
        if dt is not None:
            dt = to_si(dt, "time", source=source, field=f"{field}.dt")
        unit = entry.get("unit")
        horizontal_path = folder / horizontal
        vertical_path = folder / vertical if vertical else None
        for file_path, key in ((horizontal_path, "horizontal"), (vertical_path, "vertical")):
            if file_path is not None and not file_path.is_file():
                raise FreestandError(
                    f"record file {str(file_path)!r} does not exist; paths are relative to "
                    "the suite file's folder",
                    source=source,
                    field=f"{field}.{key}",
                )
        name = entry.get("name") or Path(horizontal).name
        motion = load_record(
            horizontal_path,
            dt=dt,
            unit=unit,
            gravity=gravity,
            vertical=vertical_path,
            name=str(name),
        )
        if scale != 1.0:
            motion = motion.scaled(scale)
        motions.append(motion)
        scales.append(scale)
        files.append((str(horizontal_path), str(vertical_path) if vertical_path else ""))
    name = data.get("name") or path.stem
    return RecordSuite(str(name), tuple(motions), source, tuple(scales), tuple(files))


def _toml_string(text: str) -> str:
    escaped = text.replace("\\", "\\\\").replace('"', '\\"')
    return f'"{escaped}"'


def suite_text(
    name: str, records: list[dict], *, description: str = "", comments: tuple[str, ...] = ()
) -> str:
    """The TOML text of a suite file.

    Parameters
    ----------
    name : str
        Suite name.
    records : list of dict
        One dict per record with ``horizontal`` and optionally ``vertical``,
        ``scale``, ``name``, ``dt`` [s] and ``unit``; file names relative to
        the suite file.
    description : str, optional
        The suite's ``description``.
    comments : tuple of str, optional
        Comment lines written at the top (each after ``# ``).
    """
    lines = [f"# {line}" if line else "#" for line in comments]
    lines.append(f"name = {_toml_string(name)}")
    if description:
        lines.append(f"description = {_toml_string(description)}")
    lines.append("")
    for record in records:
        lines.append("[[record]]")
        for key in ("name", "horizontal", "vertical", "scale", "dt", "unit"):
            value = record.get(key)
            if value is None:
                continue
            if isinstance(value, str):
                lines.append(f"{key} = {_toml_string(value)}")
            else:
                lines.append(f"{key} = {float(value)!r}")
        lines.append("")
    return "\n".join(lines)


def write_suite(
    folder: str | Path,
    motions: list[GroundMotion],
    *,
    name: str,
    file_format: str = "at2",
    suite_file: str = "suite.toml",
    description: str = "",
    comments: tuple[str, ...] = (),
    gravity: float = 9.81,
) -> Path:
    """Write records and the suite file that lists them into ``folder``.

    Parameters
    ----------
    folder : str or Path
        An existing folder.
    motions : list of GroundMotion
        The records; each gives ``recNN_H`` and, with a vertical component,
        ``recNN_UP`` (positive up, as recorded).
    name : str
        Suite name.
    file_format : {"at2", "csv"}
        PEER ``.AT2`` (values in g, ``%15.7E``) or CSV ``time [s], acceleration [g]``.
    suite_file : str, optional
        Name of the suite file (default ``suite.toml``).
    description, comments : optional
        Written into the suite file.
    gravity : float, optional
        g [m/s^2] for values in g.

    Returns
    -------
    Path
        The suite file. Fixed formatting: the same records give the same bytes.
    """
    from freestand.io.records import write_at2, write_csv_record

    if file_format not in ("at2", "csv"):
        raise FreestandError(
            f"format {file_format!r} is not known; use at2 or csv", field="--format"
        )
    folder = Path(folder)
    width = max(2, len(str(len(motions))))
    extension = ".AT2" if file_format == "at2" else ".csv"
    entries = []
    for index, motion in enumerate(motions, start=1):
        stem = f"rec{index:0{width}d}"
        entry = {"name": stem, "horizontal": f"{stem}_H{extension}"}
        components = [("horizontal", entry["horizontal"])]
        if motion.vertical is not None:
            entry["vertical"] = f"{stem}_UP{extension}"
            components.append(("vertical", entry["vertical"]))
        for component, file_name in components:
            label = f"{name}, {stem} {component}"
            if file_format == "at2":
                write_at2(
                    folder / file_name, motion, component=component, description=label,
                    gravity=gravity,
                )  # fmt: skip
            else:
                write_csv_record(
                    folder / file_name, motion, component=component, gravity=gravity,
                    comments=(label,),
                )  # fmt: skip
        entries.append(entry)
    path = folder / suite_file
    path.write_text(
        suite_text(name, entries, description=description, comments=comments), encoding="utf-8"
    )
    return path
