"""Response spectra at the input boundary: CSV files, model sections, options.

Sources, all turned into :class:`freestand.core.motion.spectra.Spectrum`:

- a CSV file: ``#`` comment lines, then a header row naming the two columns
  with their units in brackets, ``frequency [Hz], acceleration [m/s^2]``
  (``[g]`` means the model's gravity), then one row per frequency, strictly
  increasing;
- ``rg1.60``: the US NRC RG 1.60 design spectrum (``pga``, ``damping`` of
  0.5, 2, 5, 7 or 10 %, ``direction``);
- ``en1998``: the EN 1998-1 elastic spectrum (``ag``, ``ground`` A-E,
  ``type`` 1 or 2, ``damping``, ``direction``, ``importance``);
- ``table``: inline ``frequency`` and ``acceleration`` arrays (``unit``);
- ``record``: the response spectrum of a ground-motion record (``file``:
  PEER ``.AT2``, CSV with units or one column with ``dt`` and ``unit``;
  optional ``scale`` [-] or ``peak`` acceleration), computed by the exact
  Nigam-Jennings recursion of :mod:`freestand.core.motion.response_spectrum` at the
  given ``damping``;
- in a model file, ``[[spectrum]]`` tables with a ``name`` and a ``kind``
  among ``csv`` (``file``, relative to the model file), ``rg1.60``,
  ``en1998``, ``table`` and ``record`` (``file`` relative to the model file).

On the command line ``--spectrum`` takes the name of a model spectrum, a CSV
path, or ``KIND:key=value,key=value`` (e.g. ``rg1.60:pga=0.3g,damping=5%``,
``en1998:ag=2.5,ground=B,type=1,direction=vertical``), or
``record:FILE[,key=value...]`` (e.g. ``record:el-centro.AT2,damping=2%,peak=0.3g``).
"""

from __future__ import annotations

import csv
import re
from pathlib import Path

import numpy as np

from freestand.core.motion.design_spectra import (
    crane_stand_in_spectra,
    en1998_spectrum,
    rg160_spectrum,
)
from freestand.core.motion.spectra import Spectrum
from freestand.errors import FreestandError
from freestand.io.table_keys import TableKey
from freestand.io.units import damping_fraction, to_si

KINDS = ("csv", "rg1.60", "en1998", "table", "record")
_HEADER = re.compile(r"^\s*([A-Za-z _]+?)\s*\[(.+)\]\s*$")


def _direction(value, *, field: str, source: str) -> str:
    if value not in ("horizontal", "vertical"):
        raise FreestandError(
            f'{value!r} is not a direction; use "horizontal" or "vertical"',
            source=source,
            field=field,
        )
    return value


def _checked(frequency, acceleration, *, source: str, field: str, **kwargs) -> Spectrum:
    frequency = np.asarray(frequency, dtype=float)
    acceleration = np.asarray(acceleration, dtype=float)
    if frequency.size < 2 or frequency.shape != acceleration.shape:
        raise FreestandError(
            "needs at least two frequencies, each with one acceleration", source=source, field=field
        )
    if not np.all(np.isfinite(frequency)) or not np.all(np.isfinite(acceleration)):
        raise FreestandError("has a value that is not a finite number", source=source, field=field)
    if np.any(frequency <= 0):
        raise FreestandError(
            f"has a frequency {frequency[frequency <= 0][0]:g} Hz that is not positive",
            source=source,
            field=field,
        )
    steps = np.flatnonzero(np.diff(frequency) <= 0)
    if steps.size:
        k = int(steps[0])
        raise FreestandError(
            f"frequencies must increase strictly: {frequency[k]:g} Hz is followed by "
            f"{frequency[k + 1]:g} Hz (row {k + 2}); sort the rows and remove duplicates",
            source=source,
            field=field,
        )
    if np.any(acceleration < 0):
        k = int(np.flatnonzero(acceleration < 0)[0])
        raise FreestandError(
            f"spectral acceleration {acceleration[k]:g} at {frequency[k]:g} Hz is negative; "
            "spectral accelerations are magnitudes >= 0",
            source=source,
            field=field,
        )
    return Spectrum(frequency, acceleration, **kwargs)


def read_spectrum_csv(
    path: str | Path, *, direction: str = "horizontal", damping: float = 0.05, gravity: float = 9.81
) -> Spectrum:
    """Read a spectrum from a CSV file (see the module docstring for the format).

    Parameters
    ----------
    path : str or pathlib.Path
    direction : {"horizontal", "vertical"}, optional
    damping : float, optional
        Fraction of critical damping the spectrum is for [-].
    gravity : float, optional
        g [m/s^2], for a column in ``[g]``.

    Returns
    -------
    Spectrum

    Raises
    ------
    FreestandError
        For an unreadable file, a missing or unit-less header, non-numeric
        values, non-increasing frequencies or negative accelerations.
    """
    path = Path(path)
    source = str(path)
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except OSError as error:
        raise FreestandError(
            f"cannot be read ({error.strerror}); check the path", source=source
        ) from None
    rows = [
        row
        for row in csv.reader(
            line for line in lines if line.strip() and not line.lstrip().startswith("#")
        )
    ]
    if not rows:
        raise FreestandError(
            "holds no data; expected a header row and frequency rows", source=source
        )
    header = rows[0]
    units = []
    for column, expected in zip(header[:2], ("frequency", "acceleration"), strict=False):
        match = _HEADER.match(column)
        if not match or not match.group(1).strip().lower().startswith(expected[:4]):
            raise FreestandError(
                f"header {','.join(header)!r} is not 'frequency [Hz], acceleration [m/s^2]'; "
                "name the columns with their units in brackets ([g] for multiples of g)",
                source=source,
            )
        units.append(match.group(2).strip())
    if len(header) < 2:
        raise FreestandError(
            "needs two columns: frequency [Hz], acceleration [m/s^2]", source=source
        )
    frequency_factor = to_si(f"1 {units[0]}", "frequency", field="header", source=source)
    acceleration_factor = to_si(
        f"1 {units[1]}", "acceleration", field="header", source=source, gravity=gravity
    )
    frequency, acceleration = [], []
    for number, row in enumerate(rows[1:], start=2):
        try:
            frequency.append(float(row[0]) * frequency_factor)
            acceleration.append(float(row[1]) * acceleration_factor)
        except (ValueError, IndexError):
            raise FreestandError(
                f"row {number} {','.join(row)!r} is not two numbers", source=source
            ) from None
    return _checked(
        frequency,
        acceleration,
        source=source,
        field="rows",
        damping=damping,
        direction=direction,
        label=f"{path.name} ({direction}, {100 * damping:g} %)",
    )


#: The keys every spectrum takes (a model file's ``[[spectrum]]`` table; ``--spectrum``
#: takes ``direction`` and ``damping``).
COMMON_SPECTRUM_KEYS = {
    "name": TableKey("the spectrum's name, by which checks and --spectrum take it", required=True),
    "kind": TableKey('"csv", "rg1.60", "en1998", "table" or "record"', required=True),
    "direction": TableKey('"horizontal" or "vertical"', default="horizontal"),
    "damping": TableKey('damping ratio (0.05 or "5 %")', "-", default=0.05),
}

#: The keys each kind of spectrum takes besides the common ones.
SPECTRUM_KEYS = {
    "csv": {
        "file": TableKey(
            "CSV file with a header frequency [Hz], acceleration [m/s^2] (or [g]), relative "
            "to the model file",
            required=True,
        ),
    },
    "rg1.60": {
        "pga": TableKey(
            "peak ground acceleration the US NRC RG 1.60 shape is anchored to",
            "m/s^2",
            required=True,
        ),
    },
    "en1998": {
        "ag": TableKey(
            "design ground acceleration on type A ground a_g (EN 1998-1)", "m/s^2", required=True
        ),
        "ground": TableKey("ground type, A to E", default="A"),
        "type": TableKey("spectrum type, 1 or 2", "-", default=1),
        "importance": TableKey("importance factor gamma_I", "-", default=1.0),
    },
    "table": {
        "frequency": TableKey("frequencies, increasing", "Hz", required=True),
        "acceleration": TableKey(
            "pseudo-accelerations at those frequencies (bare numbers in unit, or texts with units)",
            "m/s^2",
            required=True,
        ),
        "unit": TableKey("unit of the bare numbers of acceleration", default="m/s^2"),
        "label": TableKey("label in outputs", shown_default="the spectrum's name"),
    },
    "record": {
        "file": TableKey(
            "record file (.AT2, .V2, CSV, one column), relative to the model file", required=True
        ),
        "dt": TableKey("time step of a single-column file", "s"),
        "unit": TableKey("acceleration unit of a single-column file (g, m/s^2, cm/s^2)"),
        "scale": TableKey("factor on the record (instead of peak)", "-"),
        "peak": TableKey("scale the record to this peak acceleration (instead of scale)", "m/s^2"),
        "label": TableKey(
            "label in outputs", shown_default="the file's name, direction and damping"
        ),
    },
}


def spectrum_from_settings(
    kind: str, settings: dict, *, source: str, field: str, base_dir: Path, gravity: float
) -> Spectrum:
    """Build a spectrum of ``kind`` from a dict of settings (model section or option)."""
    settings = dict(settings)
    common = COMMON_SPECTRUM_KEYS
    direction = _direction(
        settings.pop("direction", common["direction"].default),
        field=f"{field}.direction",
        source=source,
    )
    damping = damping_fraction(
        settings.pop("damping", common["damping"].default),
        field=f"{field}.damping",
        source=source,
    )
    allowed = SPECTRUM_KEYS
    if kind not in allowed:
        raise FreestandError(
            f"{kind!r} is not a kind of spectrum; use one of {', '.join(KINDS)}",
            source=source,
            field=f"{field}.kind",
        )
    unknown = sorted(set(settings) - set(allowed[kind]))
    if unknown:
        raise FreestandError(
            f"{', '.join(unknown)} not known for a {kind} spectrum; it takes "
            f"{', '.join(sorted(set(allowed[kind]) | {'direction', 'damping'}))}",
            source=source,
            field=field,
        )

    def need(key: str):
        if key not in settings:
            raise FreestandError(
                f"is missing for a {kind} spectrum", source=source, field=f"{field}.{key}"
            )
        return settings[key]

    try:
        if kind == "csv":
            path = Path(need("file"))
            return read_spectrum_csv(
                path if path.is_absolute() else base_dir / path,
                direction=direction,
                damping=damping,
                gravity=gravity,
            )
        if kind == "record":
            return _record_spectrum(
                settings,
                need("file"),
                direction=direction,
                damping=damping,
                source=source,
                field=field,
                base_dir=base_dir,
                gravity=gravity,
            )
        if kind == "rg1.60":
            pga = to_si(
                need("pga"), "acceleration", field=f"{field}.pga", source=source, gravity=gravity
            )
            return rg160_spectrum(pga, damping, direction, gravity)
        if kind == "en1998":
            ag = to_si(
                need("ag"), "acceleration", field=f"{field}.ag", source=source, gravity=gravity
            )
            keys = SPECTRUM_KEYS["en1998"]
            spectrum_type = int(settings.get("type", keys["type"].default))
            importance = to_si(
                settings.get("importance", keys["importance"].default),
                "dimensionless",
                field=f"{field}.importance",
                source=source,
            )
            return en1998_spectrum(
                ag,
                str(settings.get("ground", keys["ground"].default)).upper(),
                spectrum_type,
                damping,
                direction,
                importance,
            )
        unit = settings.get("unit", SPECTRUM_KEYS["table"]["unit"].default)
        factor = to_si(
            f"1 {unit}", "acceleration", field=f"{field}.unit", source=source, gravity=gravity
        )
        frequency = need("frequency")
        acceleration = need("acceleration")
        if not isinstance(frequency, list) or not isinstance(acceleration, list):
            raise FreestandError(
                "frequency and acceleration must be arrays of numbers", source=source, field=field
            )
        return _checked(
            [to_si(f, "frequency", field=f"{field}.frequency", source=source) for f in frequency],
            [
                to_si(
                    a, "acceleration", field=f"{field}.acceleration", source=source, gravity=gravity
                )
                if isinstance(a, str)
                else factor
                * to_si(a, "dimensionless", field=f"{field}.acceleration", source=source)
                for a in acceleration
            ],
            source=source,
            field=field,
            damping=damping,
            direction=direction,
            label=str(settings.get("label", f"{field} ({direction}, {100 * damping:g} %)")),
        )
    except ValueError as error:
        if isinstance(error, FreestandError):
            raise
        raise FreestandError(str(error), source=source, field=field) from None


def _record_spectrum(
    settings: dict,
    file: str,
    *,
    direction: str,
    damping: float,
    source: str,
    field: str,
    base_dir: Path,
    gravity: float,
) -> Spectrum:
    """Pseudo-acceleration spectrum of a record file (kind ``record``)."""
    from freestand.core.motion.response_spectrum import response_spectrum
    from freestand.io.records import load_record

    path = Path(file)
    path = path if path.is_absolute() else base_dir / path
    dt = settings.get("dt")
    if dt is not None:
        dt = to_si(dt, "time", field=f"{field}.dt", source=source)
    motion = load_record(path, dt=dt, unit=settings.get("unit"), gravity=gravity)
    if "scale" in settings and "peak" in settings:
        raise FreestandError(
            "takes either scale or peak, not both", source=source, field=f"{field}.scale"
        )
    if "scale" in settings:
        factor = to_si(settings["scale"], "dimensionless", field=f"{field}.scale", source=source)
        if not factor > 0:
            raise FreestandError(
                f"{settings['scale']!r} is not a positive factor",
                source=source,
                field=f"{field}.scale",
            )
        motion = motion.scaled(factor)
    if "peak" in settings:
        target = to_si(
            settings["peak"], "acceleration", field=f"{field}.peak", source=source, gravity=gravity
        )
        if not target > 0:
            raise FreestandError(
                f'{settings["peak"]!r} is not a positive peak acceleration; e.g. peak = "0.3 g"',
                source=source,
                field=f"{field}.peak",
            )
        motion = motion.scaled_to_peak(target)
    label = settings.get("label", f"{path.name} ({direction}, {100 * damping:g} %)")
    # One file holds one component: its spectrum is that of the direction it is used for.
    spectrum = response_spectrum(motion.horizontal, motion.dt, damping=damping, label=str(label))
    return Spectrum(
        spectrum.frequency,
        spectrum.acceleration,
        damping=damping,
        direction=direction,
        label=str(label),
        metadata=dict(spectrum.metadata, record=str(path)),
    )


def parse_spectrum_sections(
    sections: list[dict], *, source: str, base_dir: Path, gravity: float
) -> dict[str, Spectrum]:
    """The ``[[spectrum]]`` tables of a model file, by name."""
    result: dict[str, Spectrum] = {}
    for index, section in enumerate(sections):
        field = f"spectrum[{index}]"
        if not isinstance(section, dict):
            raise FreestandError("must be a table", source=source, field=field)
        section = dict(section)
        name = section.pop("name", None)
        if not isinstance(name, str) or not name:
            raise FreestandError(
                'needs a name, e.g. name = "horizontal"', source=source, field=f"{field}.name"
            )
        field = f"{field} ({name!r})"
        if name in result:
            raise FreestandError(
                "repeats a spectrum name; give each its own", source=source, field=field
            )
        kind = section.pop("kind", None)
        if kind is None:
            raise FreestandError(
                f"needs a kind, one of {', '.join(KINDS)}", source=source, field=f"{field}.kind"
            )
        if kind == "table":
            section.setdefault("label", name)
        result[name] = spectrum_from_settings(
            kind, section, source=source, field=field, base_dir=base_dir, gravity=gravity
        )
    return result


def parse_spectrum_option(
    text: str, *, model_spectra: dict[str, Spectrum], base_dir: Path, gravity: float
) -> Spectrum:
    """Resolve a ``--spectrum`` option: a model spectrum's name, a CSV path or ``KIND:k=v,...``."""
    source = "--spectrum"
    text = text.strip()
    if text in model_spectra:
        return model_spectra[text]
    if text == "crane-stand-in":
        return crane_stand_in_spectra()[0]
    kind, _, rest = text.partition(":")
    if kind == "record":
        file, _, options = rest.partition(",")
        if not file.strip():
            raise FreestandError(
                "'record:' needs a file, e.g. record:motion.AT2,damping=5%", source=source
            )
        settings = {"file": file.strip()}
        for item in filter(None, (part.strip() for part in options.split(","))):
            key, sep, value = item.partition("=")
            if not sep:
                raise FreestandError(f"{item!r} is not key=value", source=source)
            settings[key.strip()] = value.strip()
        return spectrum_from_settings(
            "record", settings, source=source, field="record", base_dir=Path.cwd(), gravity=gravity
        )
    if kind in ("rg1.60", "en1998"):
        settings = {}
        for item in filter(None, (part.strip() for part in rest.split(","))):
            key, sep, value = item.partition("=")
            if not sep:
                raise FreestandError(f"{item!r} is not key=value", source=source)
            settings[key.strip()] = value.strip()
        return spectrum_from_settings(
            kind, settings, source=source, field=kind, base_dir=base_dir, gravity=gravity
        )
    end = text.lower().find(".csv")
    if end >= 0:
        path, options = Path(text[: end + 4]), text[end + 4 :].lstrip(":")
        settings = {"file": str(path)}
        for item in filter(None, (part.strip() for part in options.split(","))):
            key, _, value = item.partition("=")
            settings[key.strip()] = value.strip()
        return spectrum_from_settings(
            "csv", settings, source=source, field="csv", base_dir=Path.cwd(), gravity=gravity
        )
    known = ", ".join(repr(name) for name in model_spectra) or "none in the model"
    raise FreestandError(
        f"{text!r} is neither a spectrum of the model ({known}), a CSV file, nor "
        "'rg1.60:pga=...,damping=...' / 'en1998:ag=...,ground=...,type=...' / "
        "'record:FILE,damping=...'",
        source=source,
    )
