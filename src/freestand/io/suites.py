"""Record suites: a TOML file that lists ground-motion records.

A suite is one input for campaigns over many ground motions (fragility, record
spectra). It lists records by file, with paths relative to the suite file::

    name = "RG 1.60, 0.3 g, 30 records"

    [[record]]
    horizontal = "rec01_H.AT2"   # the x component (also written x = ...)
    vertical = "rec01_UP.AT2"    # optional
    scale = 1.0                  # optional, applied to every component
    name = "rec01"               # optional, default: the horizontal file's name
    dt = "0.005 s"               # single-column files only
    unit = "g"                   # single-column files only

    [[record]]                   # a record with two horizontal components
    x = "rec02_X.AT2"
    y = "rec02_Y.AT2"            # along y: x turned 90 deg counter-clockwise from above
    vertical = "rec02_UP.AT2"

    [[record]]                   # a station's files, paired from their names or headers
    files = ["RSN1063_NORTHR_RRS228.AT2", "RSN1063_NORTHR_RRS318.AT2",
             "RSN1063_NORTHR_RRS-UP.AT2"]

Every record is read by :func:`freestand.io.records.load_record` (AT2, V2,
CSV, single column); ``files`` are paired by
:func:`freestand.io.pairing.pair_components` (a ``.V2`` file with several
channels may be given alone). Every problem raises
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

_RECORD_KEYS = {"horizontal", "x", "y", "vertical", "files", "scale", "name", "dt", "unit"}
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
    files : tuple of dict
        The files of each record, as resolved: ``{"horizontal": ...,
        "horizontal_y": ..., "vertical": ...}`` (the components it has).
    pairings : tuple of StationPairing or None
        For a record given by ``files``, how they were paired (its ``note``;
        :func:`freestand.io.pairing.pair_components`); None otherwise.
    """

    name: str
    motions: tuple[GroundMotion, ...]
    source: str
    scales: tuple[float, ...]
    files: tuple[dict, ...]
    pairings: tuple = ()

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

    Examples
    --------
    >>> import pathlib, tempfile, freestand as fs
    >>> record = pathlib.Path("examples/records/synthetic_H.AT2").resolve()
    >>> suite_file = pathlib.Path(tempfile.mkdtemp()) / "suite.toml"
    >>> _ = suite_file.write_text(f'''name = "two records"
    ... [[record]]
    ... horizontal = "{record}"
    ... [[record]]
    ... horizontal = "{record}"
    ... scale = 2.0
    ... ''')
    >>> suite = fs.load_suite(suite_file)
    >>> suite.name, suite.scales, round(suite.motions[1].peak_horizontal, 3)
    ('two records', (1.0, 2.0), 4.905)
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
    motions, scales, files, pairings = [], [], [], []
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
        scale = _scale(entry.get("scale", 1.0), source, f"{field}.scale")
        dt = entry.get("dt")
        if dt is not None:
            dt = to_si(dt, "time", source=source, field=f"{field}.dt")
        unit = entry.get("unit")
        if "files" in entry:
            motion, paths, pairing = _paired_record(entry, folder, dt, unit, gravity, source, field)
        else:
            motion, paths = _listed_record(entry, folder, dt, unit, gravity, source, field)
            pairing = None
        if scale != 1.0:
            motion = motion.scaled(scale)
        motions.append(motion)
        scales.append(scale)
        files.append(paths)
        pairings.append(pairing)
    name = data.get("name") or path.stem
    return RecordSuite(
        str(name), tuple(motions), source, tuple(scales), tuple(files), tuple(pairings)
    )


def _file_entry(entry: dict, key: str, example: str, source: str, field: str) -> str | None:
    value = entry.get(key)
    if value is not None and (not isinstance(value, str) or not value):
        raise FreestandError(
            f'{key} must be a file name, e.g. {key} = "{example}"',
            source=source,
            field=f"{field}.{key}",
        )
    return value


def _existing(file_path: Path, source: str, field: str) -> Path:
    if not file_path.is_file():
        raise FreestandError(
            f"record file {str(file_path)!r} does not exist; paths are relative to "
            "the suite file's folder",
            source=source,
            field=field,
        )
    return file_path


def _listed_record(entry, folder, dt, unit, gravity, source, field):
    """A record whose components are named: horizontal (or x), y, vertical."""
    if "horizontal" in entry and "x" in entry:
        raise FreestandError(
            "give the x component once: horizontal and x are the same key",
            source=source,
            field=field,
        )
    key = "x" if "x" in entry else "horizontal"
    horizontal = entry.get(key)
    if not isinstance(horizontal, str) or not horizontal:
        raise FreestandError(
            'give the horizontal record file, e.g. horizontal = "rec01_H.AT2" (or x = ..., '
            "y = ... for two horizontal components, or files = [...] for a station's files)",
            source=source,
            field=f"{field}.{key}",
        )
    y = _file_entry(entry, "y", "rec01_Y.AT2", source, field)
    vertical = _file_entry(entry, "vertical", "rec01_UP.AT2", source, field)
    paths = {"horizontal": _existing(folder / horizontal, source, f"{field}.{key}")}
    if y:
        paths["horizontal_y"] = _existing(folder / y, source, f"{field}.y")
    if vertical:
        paths["vertical"] = _existing(folder / vertical, source, f"{field}.vertical")
    name = entry.get("name") or Path(horizontal).name
    motion = load_record(
        paths["horizontal"],
        dt=dt,
        unit=unit,
        gravity=gravity,
        vertical=paths.get("vertical"),
        name=str(name),
        horizontal_y=paths.get("horizontal_y"),
    )
    return motion, {role: str(p) for role, p in paths.items()}


def _paired_record(entry, folder, dt, unit, gravity, source, field):
    """A record given by a station's files, paired from their names or headers."""
    from freestand.io.pairing import load_pairing, pair_components

    named = sorted({"horizontal", "x", "y", "vertical"} & set(entry))
    if named:
        raise FreestandError(
            f"files and {', '.join(named)} exclude each other: give the station's files "
            "(paired by name or header) or name each component",
            source=source,
            field=field,
        )
    listed = entry["files"]
    if isinstance(listed, str):
        listed = [listed]
    if (
        not isinstance(listed, list)
        or not listed
        or not all(isinstance(item, str) and item for item in listed)
    ):
        raise FreestandError(
            'files must list the station\'s record files, e.g. files = ["RSN1_STA_000.AT2", '
            '"RSN1_STA_090.AT2", "RSN1_STA-UP.AT2"]',
            source=source,
            field=f"{field}.files",
        )
    paths = [_existing(folder / item, source, f"{field}.files") for item in listed]
    pairings = pair_components(paths, gravity=gravity)
    if len(pairings) != 1:
        raise FreestandError(
            "these files are not the components of one station: "
            + " | ".join(p.note for p in pairings)
            + "; name each component instead (x = ..., y = ..., vertical = ...)",
            source=source,
            field=f"{field}.files",
        )
    pairing = pairings[0]
    motion = load_pairing(pairing, dt=dt, unit=unit, gravity=gravity, name=entry.get("name"))
    files = {
        role: c.path if c.channel is None else f"{c.path} (channel {c.channel})"
        for role, c in pairing.components.items()
    }
    return motion, files, pairing


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
        One dict per record with ``horizontal`` (or ``x``) and optionally
        ``y``, ``vertical``, ``scale``, ``name``, ``dt`` [s] and ``unit``, or
        ``files`` (a list); file names relative to the suite file.
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
        for key in ("name", "horizontal", "x", "y", "vertical", "files", "scale", "dt", "unit"):
            value = record.get(key)
            if value is None:
                continue
            if isinstance(value, str):
                lines.append(f"{key} = {_toml_string(value)}")
            elif isinstance(value, list | tuple):
                items = ", ".join(_toml_string(str(item)) for item in value)
                lines.append(f"{key} = [{items}]")
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
        The records; each gives ``recNN_H`` (listed as ``horizontal``) and,
        with a vertical component, ``recNN_UP`` (positive up, as recorded); a
        record with two horizontal components gives ``recNN_X`` and
        ``recNN_Y`` (listed as ``x`` and ``y``) instead of ``recNN_H``.
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
        if motion.horizontal_y is None:
            entry = {"name": stem, "horizontal": f"{stem}_H{extension}"}
            components = [("horizontal", entry["horizontal"])]
        else:
            entry = {"name": stem, "x": f"{stem}_X{extension}", "y": f"{stem}_Y{extension}"}
            components = [("horizontal", entry["x"]), ("horizontal_y", entry["y"])]
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
