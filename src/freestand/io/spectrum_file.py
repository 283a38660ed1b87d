"""Response spectra from files, model-file sections and command-line options.

Every source yields a :class:`freestand.core.spectra.Spectrum`. Problems raise
:class:`freestand.errors.FreestandError` naming the file or field, the value and
the fix.

CSV spectrum files
------------------
::

    # any comment line; "# key: value" lines set metadata:
    # damping: 5 %
    # direction: horizontal
    # label: site spectrum, 5 % damping
    frequency [Hz], acceleration [m/s^2]
    0.1, 0.25
    0.25, 1.55
    ...

The header names the two columns with their units in brackets: the first is
``frequency [Hz]``, the second ``acceleration [<unit>]`` with ``m/s^2``,
``cm/s^2``, ``mm/s^2``, ``gal`` or ``g`` (g: the model's gravity). Values are
separated by commas (or whitespace); frequencies must increase strictly and
accelerations must be non-negative. Damping defaults to 5 %, direction to
horizontal.

``[[spectrum]]`` sections of a model file
-----------------------------------------
Each has a ``name`` and a ``kind``:

- ``kind = "csv"``: ``path`` (relative to the model file), optional
  ``damping``, ``direction`` (override the file's comment lines);
- ``kind = "rg1.60"``: ``pga``, ``damping`` (0.5, 2, 5, 7 or 10 %),
  ``direction``;
- ``kind = "en1998"``: ``ag``, ``ground`` (A-E), ``type`` (1 or 2),
  ``damping``, ``direction``, ``importance`` (gamma_I, default 1);
- ``kind = "table"``: ``frequency`` and ``acceleration`` arrays (numbers are
  SI, or strings with units), ``damping``, ``direction``;
- ``kind = "crane-stand-in"``: the stand-in for the paper's Figs. 4-5,
  ``direction``.

Accelerations accept units (``"0.3 g"``, ``"2.9 m/s^2"``); damping is a
fraction (``0.05``) or a percentage string (``"5 %"``).

Command-line option
-------------------
``--spectrum`` takes one of: ``rg1.60:pga=0.3g,damping=5%[,direction=vertical]``,
``en1998:type=1,ground=B,ag=0.25g,damping=5%``, ``crane-stand-in[:direction=vertical]``,
the path of a CSV file, or the name of a ``[[spectrum]]`` of the model.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np

from freestand.core.spectra import (
    RG160_FACTORS,
    Spectrum,
    crane_stand_in_spectrum,
    en1998_spectrum,
    rg160_spectrum,
)
from freestand.errors import FreestandError
from freestand.io.units import to_si

#: Spectrum kinds of a ``[[spectrum]]`` section.
SPECTRUM_KINDS = ("csv", "rg1.60", "en1998", "table", "crane-stand-in")

_ACCEL_UNITS = {
    "m/s^2": 1.0,
    "m/s2": 1.0,
    "m/s**2": 1.0,
    "cm/s^2": 0.01,
    "cm/s2": 0.01,
    "gal": 0.01,
    "mm/s^2": 0.001,
    "mm/s2": 0.001,
}
_HEADER = re.compile(r"^\s*([A-Za-z_ ]+?)\s*\[\s*([^\]]+?)\s*\]\s*$")
_CSV_EXAMPLE = "frequency [Hz], acceleration [m/s^2]"
_NUMBER_UNIT = re.compile(r"^([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([A-Za-z].*)$")


def _split(line: str) -> list[str]:
    parts = [p.strip() for p in re.split(r"[,;\t]|\s+", line.strip()) if p.strip()]
    return parts


def _split_header(line: str) -> list[str]:
    if "," in line or ";" in line or "\t" in line:
        return [p.strip() for p in re.split(r"[,;\t]", line) if p.strip()]
    return [m.group(0).strip() for m in re.finditer(r"[A-Za-z_ ]+\[[^\]]*\]", line)]


def parse_damping(value: object, *, field: str, source: str | None = None) -> float:
    """Damping as a fraction of critical [-] from ``0.05`` or ``"5 %"``.

    Raises
    ------
    FreestandError
        For a bare number above 1 (write a percentage as ``"5 %"``), a negative
        value or unreadable text.
    """
    fix = "give damping as a fraction (0.05) or a percentage string ('5 %')"
    if isinstance(value, bool):
        raise FreestandError(f"{value!r} is not a damping value; {fix}", source=source, field=field)
    if isinstance(value, int | float):
        d = float(value)
        if d > 1:
            raise FreestandError(
                f"damping {value!r} is not a fraction of critical; write {d / 100:g} or '{d:g} %'",
                source=source,
                field=field,
            )
    elif isinstance(value, str):
        text = value.strip()
        try:
            if text.endswith("%"):
                d = float(text[:-1].strip()) / 100.0
            else:
                d = float(text)
                if d > 1:
                    raise FreestandError(
                        f"damping {value!r} is not a fraction of critical; write '{d:g} %'",
                        source=source,
                        field=field,
                    )
        except ValueError as exc:
            if isinstance(exc, FreestandError):
                raise
            raise FreestandError(
                f"cannot read damping {value!r}; {fix}", source=source, field=field
            ) from None
    else:
        raise FreestandError(f"{value!r} is not a damping value; {fix}", source=source, field=field)
    if not (math.isfinite(d) and d >= 0):
        raise FreestandError(f"damping {value!r} must be >= 0; {fix}", source=source, field=field)
    return d


def _direction(value: object, *, field: str, source: str | None) -> str:
    text = str(value).strip().lower()
    if text in ("horizontal", "h"):
        return "horizontal"
    if text in ("vertical", "v"):
        return "vertical"
    raise FreestandError(
        f"unknown direction {value!r}; use 'horizontal' or 'vertical'", source=source, field=field
    )


def read_spectrum_csv(
    path: str | Path,
    *,
    gravity: float = 9.81,
    damping: float | None = None,
    direction: str | None = None,
    label: str | None = None,
) -> Spectrum:
    """Read a response spectrum from a CSV file with a units header.

    Parameters
    ----------
    path : str or pathlib.Path
        The file (format in the module docstring).
    gravity : float, optional
        g [m/s^2] for an acceleration column in ``[g]``.
    damping : float, optional
        Fraction of critical damping [-]; overrides the file's ``# damping:``.
    direction : str, optional
        Overrides the file's ``# direction:``.
    label : str, optional
        Overrides the file's ``# label:`` (default: the file name).

    Returns
    -------
    Spectrum

    Raises
    ------
    FreestandError
        If the file is missing, has no units header, a non-numeric value,
        non-increasing or non-positive frequencies, or negative accelerations.
    """
    path = Path(path)
    source = str(path)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise FreestandError(
            f"cannot read the spectrum file ({exc.strerror or exc}); check the path",
            source=source,
        ) from None
    meta: dict[str, str] = {}
    header: list[str] | None = None
    header_line = 0
    rows: list[tuple[int, float, float]] = []
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.strip()
        if not line:
            continue
        if line.startswith("#"):
            body = line.lstrip("#").strip()
            m = re.match(r"^([A-Za-z_ ]+?)\s*[:=]\s*(.+)$", body)
            if m and m.group(1).strip().lower() in ("damping", "direction", "label"):
                meta[m.group(1).strip().lower()] = m.group(2).strip()
            continue
        if header is None:
            header = _split_header(line)
            header_line = number
            continue
        parts = _split(line)
        if len(parts) != 2:
            raise FreestandError(
                f"line {number}: expected 2 values (frequency, acceleration), got {len(parts)}: "
                f"{raw!r}",
                source=source,
            )
        try:
            f, a = float(parts[0]), float(parts[1])
        except ValueError:
            raise FreestandError(
                f"line {number}: {raw!r} is not two numbers; write e.g. '2.5, 10.31'",
                source=source,
            ) from None
        rows.append((number, f, a))
    if header is None:
        raise FreestandError(
            f"no header row; the first non-comment line must name the columns with units, "
            f"e.g. '{_CSV_EXAMPLE}'",
            source=source,
        )
    scale = _parse_header(header, header_line, source, gravity)
    if len(rows) < 2:
        raise FreestandError(
            f"the spectrum has {len(rows)} data row(s); give at least two", source=source
        )
    for (n0, f0, _a0), (n1, f1, _a1) in zip(rows, rows[1:], strict=False):
        if not f1 > f0:
            raise FreestandError(
                f"line {n1}: frequency {f1:g} Hz does not increase (line {n0} has {f0:g} Hz); "
                "sort the rows by strictly increasing frequency and remove duplicates",
                source=source,
            )
    for n, f, a in rows:
        if not (f > 0 and math.isfinite(f)):
            raise FreestandError(
                f"line {n}: frequency {f!r} Hz must be positive and finite", source=source
            )
        if not (a >= 0 and math.isfinite(a)):
            raise FreestandError(
                f"line {n}: spectral acceleration {a!r} must be non-negative and finite",
                source=source,
            )
    if damping is None:
        damping = (
            parse_damping(meta["damping"], field="# damping", source=source)
            if "damping" in meta
            else 0.05
        )
    if direction is None:
        direction = (
            _direction(meta["direction"], field="# direction", source=source)
            if "direction" in meta
            else "horizontal"
        )
    freq = np.array([r[1] for r in rows])
    acc = np.array([r[2] for r in rows]) * scale
    return Spectrum(
        freq,
        acc,
        damping,
        direction,
        label or meta.get("label") or path.name,
        {"source": "csv", "path": str(path)},
    )


def _parse_header(header: list[str], line: int, source: str, gravity: float) -> float:
    fix = f"write the header as '{_CSV_EXAMPLE}' (acceleration unit m/s^2, cm/s^2, gal or g)"
    if len(header) != 2:
        raise FreestandError(
            f"line {line}: header {header!r} must name 2 columns; {fix}", source=source
        )
    m0 = _HEADER.match(header[0])
    m1 = _HEADER.match(header[1])
    if not m0 or not m1:
        raise FreestandError(
            f"line {line}: header {header!r} lacks units in brackets; {fix}", source=source
        )
    name0, unit0 = m0.group(1).strip().lower(), m0.group(2).strip()
    name1, unit1 = m1.group(1).strip().lower(), m1.group(2).strip()
    if not name0.startswith("freq") or unit0.lower() != "hz":
        raise FreestandError(
            f"line {line}: first column {header[0]!r} must be 'frequency [Hz]'; {fix}",
            source=source,
        )
    if not name1.startswith("acc"):
        raise FreestandError(
            f"line {line}: second column {header[1]!r} must be 'acceleration [...]'; {fix}",
            source=source,
        )
    key = unit1.lower().replace(" ", "")
    if key == "g":
        return gravity
    if key in _ACCEL_UNITS:
        return _ACCEL_UNITS[key]
    raise FreestandError(f"line {line}: unknown acceleration unit {unit1!r}; {fix}", source=source)


def write_spectrum_csv(path: str | Path, spectrum: Spectrum, *, comments: list[str] = ()) -> None:
    """Write ``spectrum`` as a CSV file readable by :func:`read_spectrum_csv`."""
    lines = [f"# {c}" for c in comments]
    lines += [
        f"# label: {spectrum.label}",
        f"# damping: {100 * spectrum.damping:g} %",
        f"# direction: {spectrum.direction}",
        _CSV_EXAMPLE,
    ]
    lines += [
        f"{f:.10g}, {a:.10g}"
        for f, a in zip(spectrum.frequency, spectrum.acceleration, strict=True)
    ]
    Path(path).write_text("\n".join(lines) + "\n", encoding="utf-8")


# --------------------------------------------------------------------------------------
# model-file sections
# --------------------------------------------------------------------------------------
_KIND_KEYS = {
    "csv": {"path", "damping", "direction", "label"},
    "rg1.60": {"pga", "damping", "direction"},
    "en1998": {"ag", "ground", "type", "damping", "direction", "importance"},
    "table": {"frequency", "acceleration", "damping", "direction", "label"},
    "crane-stand-in": {"direction"},
}


def _require(section: dict, key: str, field: str, source: str, example: str):
    if key not in section:
        raise FreestandError(f"missing; add e.g. {key} = {example}", source=source, field=field)
    return section[key]


def _rg160(pga, damping, direction, *, field: str, source: str, gravity: float) -> Spectrum:
    pga_si = to_si(pga, "acceleration", field=f"{field}.pga", source=source, gravity=gravity)
    if not pga_si > 0:
        raise FreestandError(f"pga {pga!r} must be positive", source=source, field=f"{field}.pga")
    percent = round(damping * 100, 6)
    table = RG160_FACTORS[direction]
    if percent not in table:
        raise FreestandError(
            f"RG 1.60 has no spectrum for {percent:g} % damping; it tabulates "
            f"{', '.join(f'{d:g} %' for d in table)} only (use one of these, or an EN 1998-1 "
            "spectrum for other damping values)",
            source=source,
            field=f"{field}.damping",
        )
    return rg160_spectrum(pga_si, damping, direction, gravity=gravity)


def _en1998(values: dict, *, field: str, source: str, gravity: float) -> Spectrum:
    ag = to_si(
        _require(values, "ag", f"{field}.ag", source, '"0.25 g"'),
        "acceleration",
        field=f"{field}.ag",
        source=source,
        gravity=gravity,
    )
    if not ag > 0:
        raise FreestandError(f"ag {ag!r} must be positive", source=source, field=f"{field}.ag")
    ground = str(values.get("ground", "A")).strip().upper()
    if ground not in ("A", "B", "C", "D", "E"):
        raise FreestandError(
            f"unknown ground type {values.get('ground')!r}; use A, B, C, D or E",
            source=source,
            field=f"{field}.ground",
        )
    try:
        spectrum_type = int(str(values.get("type", 1)).strip())
    except ValueError:
        spectrum_type = 0
    if spectrum_type not in (1, 2):
        raise FreestandError(
            f"unknown spectrum type {values.get('type')!r}; use 1 or 2",
            source=source,
            field=f"{field}.type",
        )
    damping = parse_damping(values.get("damping", 0.05), field=f"{field}.damping", source=source)
    direction = _direction(
        values.get("direction", "horizontal"), field=f"{field}.direction", source=source
    )
    importance = to_si(
        values.get("importance", 1.0), "dimensionless", field=f"{field}.importance", source=source
    )
    if not importance > 0:
        raise FreestandError(
            f"importance {importance!r} must be positive",
            source=source,
            field=f"{field}.importance",
        )
    return en1998_spectrum(
        ag, ground, spectrum_type, damping, direction, importance, gravity=gravity
    )


def spectrum_from_section(
    section: dict, *, field: str, source: str, base_dir: Path, gravity: float
) -> Spectrum:
    """Build the spectrum one ``[[spectrum]]`` section describes (see module docstring)."""
    if not isinstance(section, dict):
        raise FreestandError("must be a table with a name and a kind", source=source, field=field)
    kind = str(_require(section, "kind", f"{field}.kind", source, '"rg1.60"')).strip().lower()
    if kind not in SPECTRUM_KINDS:
        raise FreestandError(
            f"unknown spectrum kind {section['kind']!r}; use one of {', '.join(SPECTRUM_KINDS)}",
            source=source,
            field=f"{field}.kind",
        )
    unknown = set(section) - _KIND_KEYS[kind] - {"name", "kind"}
    if unknown:
        raise FreestandError(
            f"unknown key(s) {', '.join(sorted(unknown))} for kind '{kind}'; allowed: "
            f"{', '.join(sorted(_KIND_KEYS[kind] | {'name', 'kind'}))}",
            source=source,
            field=field,
        )
    direction = _direction(
        section.get("direction", "horizontal"), field=f"{field}.direction", source=source
    )
    if kind == "crane-stand-in":
        return crane_stand_in_spectrum(direction)
    if kind == "en1998":
        return _en1998(section, field=field, source=source, gravity=gravity)
    damping = (
        parse_damping(section["damping"], field=f"{field}.damping", source=source)
        if "damping" in section
        else None
    )
    if kind == "rg1.60":
        pga = _require(section, "pga", f"{field}.pga", source, '"0.3 g"')
        return _rg160(
            pga, 0.05 if damping is None else damping, direction,
            field=field, source=source, gravity=gravity,
        )  # fmt: skip
    if kind == "csv":
        rel = _require(section, "path", f"{field}.path", source, '"spectra/site.csv"')
        path = Path(rel)
        if not path.is_absolute():
            path = Path(base_dir) / path
        return read_spectrum_csv(
            path,
            gravity=gravity,
            damping=damping,
            direction=direction if "direction" in section else None,
            label=section.get("label"),
        )
    # table
    freq_raw = _require(section, "frequency", f"{field}.frequency", source, "[0.5, 2.5, 33]")
    acc_raw = _require(section, "acceleration", f"{field}.acceleration", source, "[1.0, 8.0, 2.7]")
    if not isinstance(freq_raw, list) or not isinstance(acc_raw, list):
        raise FreestandError(
            "frequency and acceleration must be arrays, e.g. frequency = [0.5, 2.5, 33]",
            source=source,
            field=field,
        )
    if len(freq_raw) != len(acc_raw) or len(freq_raw) < 2:
        raise FreestandError(
            f"frequency has {len(freq_raw)} values and acceleration {len(acc_raw)}; give "
            "the same number, at least two",
            source=source,
            field=field,
        )
    freq = np.array(
        [
            to_si(v, "frequency", field=f"{field}.frequency[{i}]", source=source)
            for i, v in enumerate(freq_raw)
        ]
    )
    acc = np.array(
        [
            to_si(
                v,
                "acceleration",
                field=f"{field}.acceleration[{i}]",
                source=source,
                gravity=gravity,
            )
            for i, v in enumerate(acc_raw)
        ]
    )
    for i in range(freq.size):
        if not freq[i] > 0:
            raise FreestandError(
                f"frequency {freq_raw[i]!r} must be positive",
                source=source,
                field=f"{field}.frequency[{i}]",
            )
        if i and not freq[i] > freq[i - 1]:
            raise FreestandError(
                f"frequency {freq_raw[i]!r} does not increase after {freq_raw[i - 1]!r}; list "
                "frequencies in strictly increasing order",
                source=source,
                field=f"{field}.frequency[{i}]",
            )
        if not acc[i] >= 0:
            raise FreestandError(
                f"spectral acceleration {acc_raw[i]!r} must be non-negative",
                source=source,
                field=f"{field}.acceleration[{i}]",
            )
    return Spectrum(
        freq,
        acc,
        0.05 if damping is None else damping,
        direction,
        str(section.get("label", section.get("name", "table"))),
        {"source": "table"},
    )


def parse_spectrum_sections(
    sections: list[dict], *, source: str, base_dir: Path, gravity: float
) -> dict[str, Spectrum]:
    """Spectra of the ``[[spectrum]]`` sections of a model file, by name.

    Parameters
    ----------
    sections : list of dict
        The parsed TOML array of tables.
    source : str
        Model file name, for error messages.
    base_dir : pathlib.Path
        Directory CSV paths are relative to (the model file's).
    gravity : float
        The model's g [m/s^2] (for values in g).

    Raises
    ------
    FreestandError
        For a missing or duplicate name, an unknown kind or key, or any invalid
        value (the field is named as ``spectrum[i].key``).
    """
    if not isinstance(sections, list):
        raise FreestandError(
            "must be an array of tables: write each as [[spectrum]]",
            source=source,
            field="spectrum",
        )
    spectra: dict[str, Spectrum] = {}
    for i, section in enumerate(sections):
        field = f"spectrum[{i}]"
        if not isinstance(section, dict):
            raise FreestandError("must be a table", source=source, field=field)
        name = section.get("name")
        if not isinstance(name, str) or not name.strip():
            raise FreestandError(
                'missing name; add e.g. name = "site-horizontal"',
                source=source,
                field=f"{field}.name",
            )
        if name in spectra:
            raise FreestandError(
                f"duplicate spectrum name {name!r}; give each [[spectrum]] its own name",
                source=source,
                field=f"{field}.name",
            )
        spectra[name] = spectrum_from_section(
            section, field=field, source=source, base_dir=Path(base_dir), gravity=gravity
        )
    return spectra


# --------------------------------------------------------------------------------------
# command-line option
# --------------------------------------------------------------------------------------
_OPTION_KINDS = {
    "rg1.60": "rg1.60",
    "rg160": "rg1.60",
    "rg-1.60": "rg1.60",
    "en1998": "en1998",
    "en1998-1": "en1998",
    "ec8": "en1998",
    "crane-stand-in": "crane-stand-in",
}


def parse_spectrum_option(
    text: str,
    *,
    model_spectra: dict[str, Spectrum] | None = None,
    base_dir: Path | None = None,
    gravity: float = 9.81,
) -> Spectrum:
    """The spectrum a ``--spectrum`` option names.

    Parameters
    ----------
    text : str
        ``"rg1.60:pga=0.3g,damping=5%"``, ``"en1998:type=1,ground=B,ag=0.25g,damping=5%"``,
        ``"crane-stand-in"`` (``":direction=vertical"`` optional), a CSV path, or
        the name of a model ``[[spectrum]]``.
    model_spectra : dict, optional
        Spectra of the model's ``[[spectrum]]`` sections.
    base_dir : pathlib.Path, optional
        Directory a relative CSV path is taken from (default: current).
    gravity : float, optional
        g [m/s^2] for values in g.

    Raises
    ------
    FreestandError
        With ``field='--spectrum'`` for anything it cannot read.
    """
    field = "--spectrum"
    model_spectra = model_spectra or {}
    raw = text.strip()
    if not raw:
        raise FreestandError(
            "empty; name a spectrum (e.g. 'rg1.60:pga=0.3g,damping=5%')", field=field
        )
    if raw in model_spectra:
        return model_spectra[raw]
    head, _, tail = raw.partition(":")
    kind = _OPTION_KINDS.get(head.strip().lower())
    if kind is not None:
        values: dict[str, str] = {}
        for item in filter(None, (p.strip() for p in tail.split(","))):
            key, eq, value = item.partition("=")
            if not eq:
                raise FreestandError(
                    f"{item!r} in {raw!r} is not key=value; "
                    f"write e.g. '{head}:pga=0.3g,damping=5%'",
                    field=field,
                )
            values[key.strip().lower()] = _NUMBER_UNIT.sub(r"\1 \2", value.strip())
        section = {"kind": kind, **values}
        return spectrum_from_section(
            section, field=field, source=None, base_dir=Path(base_dir or "."), gravity=gravity
        )
    path = Path(raw)
    if not path.is_absolute() and base_dir is not None and not path.exists():
        path = Path(base_dir) / path
    if path.suffix.lower() in (".csv", ".txt") or path.exists():
        if not path.exists():
            raise FreestandError(f"spectrum file {raw!r} not found; check the path", field=field)
        return read_spectrum_csv(path, gravity=gravity)
    names = ", ".join(sorted(model_spectra)) or "none"
    raise FreestandError(
        f"unknown spectrum {raw!r}; use 'rg1.60:pga=...,damping=...', "
        f"'en1998:type=...,ground=...,ag=...,damping=...', 'crane-stand-in', a CSV file, "
        f"or a model [[spectrum]] name (the model has: {names})",
        field=field,
    )
