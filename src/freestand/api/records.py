"""Public record analyses: response spectra, spectrum-compatible suites, floor motions.

:func:`response_spectrum`, :func:`generate_suite` and :func:`floor_motion` are
what ``freestand records spectrum``, ``generate`` and ``floor`` compute; each
returns a result with ``to_dict()`` (the command's ``--json`` document),
``to_frame()`` (a tidy :class:`pandas.DataFrame`, units in the column names)
and ``plot(ax=None)`` (the command's figure).

Example
-------
>>> import freestand as fs
>>> spectra = fs.response_spectrum("examples/records/synthetic_H.AT2", damping=0.05)
>>> frame = spectra.to_frame()
>>> list(frame.columns)
['record', 'component', 'frequency [Hz]', 'psa [m/s^2]', 'target [m/s^2]', 'ratio [-]']
>>> round(float(spectra.rows[0]["peak_acceleration"]), 3)
2.453
"""

from __future__ import annotations

import math
import os
import shutil
import tempfile
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from freestand.core.motion.ground_motion import GroundMotion
from freestand.core.motion.spectra import Spectrum
from freestand.errors import FreestandError
from freestand.io.outputs import check_file, check_writable

#: Frequencies of ``freestand records spectrum`` [Hz]: 0.1 to 100 Hz, 100 per decade.
SPECTRUM_FREQUENCIES = np.geomspace(0.1, 100.0, 301)

#: Components of a record in their order, with the words used in tables.
COMPONENT_WORDS = {"horizontal": "x", "horizontal_y": "y", "vertical": "vertical"}

GRAVITY = 9.81

#: Most samples per generated record (duration / dt): 600 s at 0.0006 s; beyond, a typo
#: such as dt=1e-9 would run for hours.
MAX_SAMPLES = 1_000_000


# ------------------------------------------------------------------------------- helpers


def write_atomic(path: str | Path, writer) -> Path:
    """Call ``writer(temporary_path)``, then rename the temporary file to ``path``.

    The folder is created when missing; a failure leaves no file behind.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
    os.close(handle)
    try:
        writer(Path(temporary))
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise
    return path


def _as_spectrum(value, name: str, gravity: float) -> Spectrum | None:
    """A target given as a Spectrum or as the text ``--spectrum`` takes."""
    if value is None or isinstance(value, Spectrum):
        return value
    from freestand.io.spectrum_input import parse_spectrum_option

    try:
        return parse_spectrum_option(
            str(value), model_spectra={}, base_dir=Path.cwd(), gravity=gravity
        )
    except FreestandError as error:
        if "--spectrum" not in str(error):
            raise
        raise FreestandError(
            error.detail.replace("--spectrum", name),
            source=name if error.source == "--spectrum" else error.source,
            field=error.field,
        ) from None


def _fraction(value, name: str) -> float:
    """A damping ratio given as a number (0.05) or a text (``"5%"``) [-]."""
    from freestand.io.units import damping_fraction

    if isinstance(value, int | float) and not isinstance(value, bool):
        if not 0.0 <= value < 1.0:
            raise FreestandError(f"{value!r} is not a damping ratio in [0, 1)", source=name)
        return float(value)
    return damping_fraction(str(value).strip(), field="damping", source=name)


def _frequency(value, name: str) -> float:
    """A frequency given as a number [Hz] or a text (``"2.5Hz"``)."""
    from freestand.io.units import to_si

    if isinstance(value, int | float) and not isinstance(value, bool):
        frequency = float(value)
    else:
        frequency = to_si(str(value).strip(), "frequency", field="frequency", source=name)
    if not (frequency > 0 and math.isfinite(frequency)):
        raise FreestandError(f"{value!r} is not a positive frequency; e.g. 2.5Hz", source=name)
    return frequency


def _finite(value):
    """JSON-ready: non-finite floats as None, arrays as lists."""
    if isinstance(value, np.ndarray):
        return [_finite(v) for v in value.tolist()]
    if isinstance(value, float | np.floating):
        value = float(value)
        return value if math.isfinite(value) else None
    return value


# --------------------------------------------------------------------- response spectra


@dataclass(frozen=True)
class RecordSpectra:
    """Pseudo-acceleration spectra of records, against targets (``records spectrum``).

    Attributes
    ----------
    frequency : numpy.ndarray
        Oscillator frequencies [Hz].
    damping : float
        Damping ratio zeta [-].
    target : Spectrum or None
        The target of the figure (the horizontal one, else the vertical).
    targets : dict
        Target Spectrum of each direction given (``"horizontal"``, which also
        serves y, and ``"vertical"``).
    rows : tuple of dict
        One per record and component: ``record``, ``component``
        (``"horizontal"``, ``"horizontal_y"``, ``"vertical"``), ``dt`` [s],
        ``duration`` [s], ``peak_acceleration`` [m/s^2], ``peak_psa``
        [m/s^2], ``peak_psa_frequency`` [Hz], ``psa`` (array [m/s^2]), and
        with a target ``min_ratio``, ``max_ratio`` [-] over 0.2-50 Hz and
        their frequencies [Hz].
    motions : tuple of GroundMotion
        The records.
    pairings : tuple of StationPairing
        How files were put together into records (see
        :func:`freestand.io.pairing.pair_components`).
    files : tuple of str
        Files written from this result (``with_files``).

    Examples
    --------
    >>> import freestand as fs
    >>> spectra = fs.response_spectrum("examples/records/synthetic_H.AT2",
    ...                                target="rg1.60:pga=0.3g,damping=5%")
    >>> spectra.to_frame().columns.tolist()
    ['record', 'component', 'frequency [Hz]', 'psa [m/s^2]', 'target [m/s^2]', 'ratio [-]']
    >>> fig = spectra.plot()
    """

    frequency: np.ndarray
    damping: float
    target: Spectrum | None
    targets: dict
    rows: tuple
    motions: tuple
    pairings: tuple = ()
    files: tuple = ()

    @property
    def curves(self) -> list[tuple[str, np.ndarray]]:
        """(label, PSA [m/s^2]) of every record component, as drawn."""
        return [(f"{row['record']} ({row['component']})", row["psa"]) for row in self.rows]

    @property
    def spectra(self) -> list[Spectrum]:
        """Each row's spectrum as a :class:`Spectrum` (usable wherever a spectrum is taken)."""
        return [
            Spectrum(
                self.frequency,
                row["psa"],
                self.damping,
                "vertical" if row["component"] == "vertical" else "horizontal",
                f"{row['record']} PSA {100 * self.damping:g} % damping ({row['component']})",
                {"source": "record", "record": row["record"], "component": row["component"]},
            )
            for row in self.rows
        ]

    def with_files(self, *paths) -> RecordSpectra:
        """The same result listing ``paths`` among the files written from it."""
        return replace(self, files=self.files + tuple(str(p) for p in paths))

    def to_dict(self) -> dict:
        """The ``freestand records spectrum --json`` document.

        Keys: ``damping``, ``frequency`` [Hz], ``target`` (label, direction,
        damping, acceleration [m/s^2] at ``frequency``, or None), ``records``
        (the rows), ``pairing`` (the files paired into records, or refused,
        with how and why) and ``files``.

        Returns
        -------
        dict
            JSON-ready: str, int, float, bool, None, lists and dicts
            (non-finite floats as None).
        """
        target = self.target
        return {
            "damping": self.damping,
            "frequency": self.frequency.tolist(),
            "target": None
            if target is None
            else {
                "label": target.label,
                "direction": target.direction,
                "damping": target.damping,
                "acceleration": np.asarray(target.acceleration_at(self.frequency)).tolist(),
            },
            "records": [{key: _finite(value) for key, value in row.items()} for row in self.rows],
            "pairing": [p.to_dict() for p in self.pairings if p.paired or p.reason],
            "files": list(self.files),
        }

    def to_frame(self):
        """Tidy table: one row per record, component and frequency.

        Columns: ``record``, ``component``, ``frequency [Hz]``,
        ``psa [m/s^2]``, ``target [m/s^2]`` (NaN without a target for the
        component), ``ratio [-]`` (psa / target). ``attrs``: damping, targets,
        units.

        Returns
        -------
        pandas.DataFrame
            The table described above: units in the column names, metadata in
            ``attrs``.
        """
        import pandas as pd

        parts = []
        for row in self.rows:
            goal = self._goal(row["component"])
            parts.append(
                pd.DataFrame(
                    {
                        "record": row["record"],
                        "component": row["component"],
                        "frequency [Hz]": self.frequency,
                        "psa [m/s^2]": row["psa"],
                        "target [m/s^2]": goal,
                        "ratio [-]": row["psa"] / goal,
                    }
                )
            )
        frame = pd.concat(parts, ignore_index=True)
        frame.attrs.update(
            damping=self.damping,
            targets={d: s.label for d, s in self.targets.items()},
            units={"frequency": "Hz", "psa": "m/s^2", "target": "m/s^2"},
            source="freestand records spectrum",
        )
        return frame

    def _goal(self, component: str) -> np.ndarray:
        spectrum = self.targets.get("vertical" if component == "vertical" else "horizontal")
        if spectrum is None:
            return np.full(self.frequency.size, np.nan)
        return np.asarray(spectrum.acceleration_at(self.frequency), dtype=float)

    def plot(self, ax=None):
        """The spectra, the targets, 0.9 and 1.3 times the target, and the ratios.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Draw the spectra into these axes (without the ratio panel).

        Returns
        -------
        matplotlib.figure.Figure
            Upper axes: one line per record component (labelled ``record
            (component)``), the horizontal target (black) with the band
            (dashed) and the vertical target (dash-dotted); lower axes (with a
            target): each record / its own target.
        """
        from freestand.plot.records import plot_record_spectra

        return plot_record_spectra(
            self.frequency,
            [(label, psa, row["component"])
             for (label, psa), row in zip(self.curves, self.rows, strict=True)],
            target=self.targets.get("horizontal"),
            vertical_target=self.targets.get("vertical"),
            damping=self.damping,
            title=f"Pseudo-acceleration spectra, {100 * self.damping:g} % damping",
            axes=ax,
        )  # fmt: skip


def _load_records(records, *, dt, unit, gravity, pair):
    """Motions (and pairings) from records, paths of record files and suite files."""
    from freestand.io.pairing import load_pairing, pair_components
    from freestand.io.records import load_record
    from freestand.io.suites import load_suite

    if isinstance(records, GroundMotion | str | Path) or (
        isinstance(records, np.ndarray) and records.ndim == 1
    ):
        records = [records]
    motions, pairings, files = [], [], []

    def flush():
        if not files:
            return
        if pair:
            for pairing in pair_components(files, gravity=gravity):
                motions.append(load_pairing(pairing, dt=dt, unit=unit, gravity=gravity))
                pairings.append(pairing)
        else:
            motions.extend(load_record(p, dt=dt, unit=unit, gravity=gravity) for p in files)
        files.clear()

    for item in records:
        if isinstance(item, GroundMotion):
            flush()
            motions.append(item)
        elif isinstance(item, np.ndarray):
            if dt is None:
                raise FreestandError("an array of accelerations needs its time step dt [s]")
            flush()
            motions.append(GroundMotion(dt, item))
        elif Path(item).suffix.lower() == ".toml":
            flush()
            suite = load_suite(item, gravity=gravity)
            motions.extend(suite.motions)
            pairings.extend(pairing for pairing in suite.pairings if pairing is not None)
        else:
            if not Path(item).is_file():
                load_record(item, dt=dt, unit=unit, gravity=gravity)  # says what is wrong
            files.append(Path(item))
    flush()
    if not motions:
        raise FreestandError("no record given; give record files, suite files or GroundMotions")
    return motions, pairings


def response_spectrum(
    records,
    *,
    damping=None,
    target=None,
    vertical_target=None,
    frequencies=None,
    dt: float | None = None,
    unit: str | None = None,
    gravity: float = GRAVITY,
    pair: bool = True,
) -> RecordSpectra:
    """Pseudo-acceleration spectra of records, every component, against targets.

    Parameters
    ----------
    records : GroundMotion, str, Path, or a sequence of them
        Records (:class:`GroundMotion`), record files (``.AT2``, ``.V2``,
        CSV, single column) or suite files (``.toml``). Files of one
        station's components are paired into one record (see ``pair``).
    damping : float or str, optional
        Damping ratio zeta [-] (0.05 or ``"5%"``; default the target's, else
        0.05).
    target, vertical_target : Spectrum or str, optional
        Target spectra [m/s^2] of the horizontal (x and y) and vertical
        components, as Spectrum objects or as ``--spectrum`` takes them
        (``"rg1.60:pga=0.3g,damping=5%"``, ``"en1998:ag=2.5,ground=B"``, a
        CSV file, ``"record:FILE"``).
    frequencies : array_like, optional
        Oscillator frequencies [Hz], increasing (default 0.1 to 100 Hz, 100
        per decade). The ratios to a target are taken over those between
        0.2 and 50 Hz (the acceptance band), or over all when none is.
    dt, unit : optional
        Time step [s] and acceleration unit of single-column files.
    gravity : float, optional
        g [m/s^2] (default 9.81).
    pair : bool, optional
        Pair the components of a station given as several files (x, y,
        vertical), from their names or headers
        (:func:`freestand.io.pairing.pair_components`; default True).

    Returns
    -------
    RecordSpectra
        One row per record and component: peaks, the spectrum, and with a
        target the smallest and largest ratio record / target between 0.2
        and 50 Hz and where they occur.

    Notes
    -----
    PSA = omega^2 max|u| of u'' + 2 zeta omega u' + omega^2 u = -a_g(t), by
    the exact piecewise-linear recursion of Nigam and Jennings (1969, BSSA
    59(2), 909-922), followed for one period of free vibration after the
    record (:mod:`freestand.core.motion.response_spectrum`).

    Examples
    --------
    >>> import freestand as fs
    >>> result = fs.response_spectrum(
    ...     ["examples/records/synthetic_H.AT2", "examples/records/synthetic_UP.AT2"],
    ...     target="rg1.60:pga=0.25g,damping=5%")
    >>> [(row["record"], row["component"]) for row in result.rows]
    [('synthetic', 'horizontal'), ('synthetic', 'vertical')]
    >>> result.to_dict()["pairing"][0]["method"]
    'file names'
    """
    from freestand.core.motion.response_spectrum import SpectrumPlan
    from freestand.core.motion.spectrum_matching import AcceptanceCriteria

    target_spectrum = _as_spectrum(target, "target", gravity)
    targets = {}
    if target_spectrum is not None:
        targets[target_spectrum.direction] = target_spectrum
    if vertical_target is not None:
        targets["vertical"] = _as_spectrum(vertical_target, "vertical_target", gravity)
        if target_spectrum is None:
            target_spectrum = targets["vertical"]
    if damping is not None:
        zeta = _fraction(damping, "damping")
    else:
        zeta = target_spectrum.damping if target_spectrum is not None else 0.05
    frequency = SPECTRUM_FREQUENCIES.copy() if frequencies is None else np.asarray(frequencies)
    if frequency.ndim != 1 or frequency.size < 2 or not np.all(np.isfinite(frequency) & (
            frequency > 0)) or np.any(np.diff(frequency) <= 0):  # fmt: skip
        raise FreestandError(
            "give at least two positive, increasing frequencies [Hz], e.g. "
            "numpy.geomspace(0.1, 100, 301)",
            source="frequencies",
        )
    motions, pairings = _load_records(records, dt=dt, unit=unit, gravity=gravity, pair=pair)
    check_band = AcceptanceCriteria()
    in_band = (frequency >= check_band.lowest_frequency * (1 - 1e-9)) & (
        frequency <= check_band.highest_frequency * (1 + 1e-9)
    )
    if not in_band.any():  # ratios over the frequencies given when none is in 0.2-50 Hz
        in_band[:] = True
    plans: dict[float, SpectrumPlan] = {}
    rows = []
    for motion in motions:
        plan = plans.get(motion.dt)
        if plan is None:
            plan = plans[motion.dt] = SpectrumPlan.build(frequency, motion.dt, zeta)
        for component in motion.components:
            acceleration = motion.component(component)
            psa = plan.pseudo_acceleration(acceleration)
            k = int(np.argmax(psa))
            row = {
                "record": motion.name,
                "component": component,
                "dt": motion.dt,
                "duration": motion.duration,
                "peak_acceleration": float(np.max(np.abs(acceleration))),
                "peak_psa": float(psa[k]),
                "peak_psa_frequency": float(frequency[k]),
                "psa": psa,
            }
            goal_spectrum = targets.get("vertical" if component == "vertical" else "horizontal")
            if goal_spectrum is not None:
                goal = np.asarray(goal_spectrum.acceleration_at(frequency))
                ratio = psa / np.maximum(goal, 1e-300)
                low = int(np.argmin(np.where(in_band, ratio, np.inf)))
                high = int(np.argmax(np.where(in_band, ratio, -np.inf)))
                row.update(
                    min_ratio=float(ratio[low]),
                    min_ratio_frequency=float(frequency[low]),
                    max_ratio=float(ratio[high]),
                    max_ratio_frequency=float(frequency[high]),
                )
            rows.append(row)
    return RecordSpectra(
        frequency, zeta, target_spectrum, targets, tuple(rows), tuple(motions), tuple(pairings)
    )


# ------------------------------------------------------------------ generated suites


def _component_document(component) -> dict:
    """JSON form of one direction of a generated suite (every check of every record)."""
    return {
        "direction": component.direction,
        "target": component.target.label,
        "damping": component.target.damping,
        "mean_ratio_min": component.mean_ratio_min,
        "records": [
            {
                "index": k + 1,
                "min_ratio": r.check.min_ratio,
                "min_ratio_frequency": r.check.min_ratio_frequency,
                "max_ratio": r.check.max_ratio,
                "max_ratio_frequency": r.check.max_ratio_frequency,
                "peak_acceleration": r.check.peak_acceleration,
                "zero_period_acceleration": r.check.zero_period_acceleration,
                "peak_ratio": r.check.peak_ratio,
                "duration_5_75": r.check.duration_5_75,
                "final_velocity": r.check.final_velocity,
                "final_displacement": r.check.final_displacement,
                "iterations": r.check.iterations,
                "attempts": r.check.attempts,
                "passed": r.check.passed,
                "reasons": list(r.check.reasons),
            }
            for k, r in enumerate(component.records)
        ],
    }


@dataclass(frozen=True)
class GeneratedSuite:
    """A suite of spectrum-compatible records and its acceptance checks (``records generate``).

    Attributes
    ----------
    core : SuiteResult
        The generation's result (:mod:`freestand.core.motion.spectrum_matching`):
        records, spectra, checks.
    name : str
        Suite name.
    duration : float
        Record length [s].
    motions : tuple of GroundMotion
        The records as written: ``horizontal`` (x), ``horizontal_y`` (y, when
        asked for) and ``vertical`` (downward, freestand's convention) [m/s^2].
    output : str or None
        The folder the suite was written to (None before :meth:`write`).
    suite_file : str or None
        Its suite file.
    files : tuple of str
        Files written: the suite file, ``acceptance.json`` and any added by
        :meth:`with_files` (a figure).

    Examples
    --------
    >>> import freestand as fs
    >>> suite = fs.generate_suite("rg1.60:pga=0.3g,damping=5%", count=2, duration=8.0, seed=7)
    >>> suite.status, suite.failures
    ('accepted', ())
    >>> suite.to_frame()[["record", "component", "passed"]].values.tolist()
    [[1, 'horizontal', True], [2, 'horizontal', True]]
    >>> fig = suite.plot()
    """

    core: object
    name: str
    duration: float
    motions: tuple
    output: str | None = None
    suite_file: str | None = None
    files: tuple = ()
    comments: tuple = field(default=(), repr=False)

    @property
    def status(self) -> str:
        """``"accepted"`` or ``"failed"``."""
        return self.core.status

    @property
    def failures(self) -> tuple[str, ...]:
        """Every failed check, naming the record and why."""
        return self.core.failures

    def independence(self) -> dict:
        """The independence of each record's components (US NRC SRP 3.7.1).

        Returns
        -------
        dict
            ``limit`` [-], ``max`` (the largest absolute correlation coefficient
            between two components of one record, over the suite),
            ``passed``, and ``records``: per record its ``index``, the
            coefficient of each pair (``pairs``), ``max`` and ``passed``
            (``max`` below ``limit``).
        """
        correlations = self.core.component_correlations()
        values = [c["max"] for c in correlations if c["max"] is not None]
        limit = self.core.criteria.max_correlation
        largest = max(values) if values else None
        return {
            "limit": limit,
            "max": largest,
            "passed": largest is None or largest < limit,
            "records": [
                {"index": k + 1, **c, "passed": c["max"] is None or c["max"] < limit}
                for k, c in enumerate(correlations)
            ],
        }

    def to_dict(self) -> dict:
        """The ``freestand records generate --json`` document.

        Keys: ``status``, ``failures``, ``seed``, ``count``, ``dt`` [s],
        ``criteria``, ``max_correlation`` (any two time histories) and its
        ``max_correlation_pair``, ``horizontal`` (x), ``horizontal_y`` (y,
        only in a suite with two horizontal components), ``vertical`` (each:
        target, damping, the lowest suite-mean / target ratio, every check of
        every record), ``independence`` (records of two or three
        components: the correlation coefficient of every pair of a record's
        components, the largest per record and for the suite, and whether
        each is below the limit, US NRC SRP 3.7.1), ``output``,
        ``suite_file`` and ``files``. ``acceptance.json``
        holds the same without the last three.

        Returns
        -------
        dict
            JSON-ready: str, int, float, bool, None, lists and dicts
            (non-finite floats as None).
        """
        result = self.core
        criteria = result.criteria
        document = {
            "status": result.status,
            "failures": list(result.failures),
            "seed": result.seed,
            "count": result.count,
            "dt": result.dt,
            "criteria": {
                "frequencies": f"{criteria.lowest_frequency:g}-{criteria.highest_frequency:g} "
                f"Hz, {criteria.per_decade} per decade",
                "ratio_bounds": [criteria.lower_ratio, criteria.upper_ratio],
                "peak_tolerance": criteria.peak_tolerance,
                "max_correlation": criteria.max_correlation,
            },
            "max_correlation": result.max_correlation,
            "max_correlation_pair": list(result.max_correlation_pair),
            "horizontal": _component_document(result.horizontal),
        }
        if result.horizontal_y is not None:
            document["horizontal_y"] = _component_document(result.horizontal_y)
        document["vertical"] = (
            None if result.vertical is None else _component_document(result.vertical)
        )
        if len(result.components) > 1:
            document["independence"] = self.independence()
        document.update(output=self.output, suite_file=self.suite_file, files=list(self.files))
        return document

    def acceptance(self) -> dict:
        """The ``acceptance.json`` document: :meth:`to_dict` without where it was written.

        Returns
        -------
        dict
            JSON-ready, as written to ``acceptance.json``.
        """
        document = self.to_dict()
        for key in ("output", "suite_file", "files"):
            document.pop(key)
        return document

    def to_frame(self):
        """Tidy table of the checks: one row per record and component.

        Columns: ``record``, ``component`` (``horizontal``, ``horizontal_y``,
        ``vertical``), ``min_ratio [-]``, ``min_ratio_frequency [Hz]``,
        ``max_ratio [-]``, ``max_ratio_frequency [Hz]``,
        ``peak_acceleration [m/s^2]``, ``zero_period_acceleration [m/s^2]``,
        ``peak_ratio [-]``, ``duration_5_75 [s]``, ``final_velocity [m/s]``,
        ``final_displacement [m]``, ``iterations``, ``attempts``, ``passed``,
        ``component_correlation [-]`` (the largest absolute correlation coefficient
        between the record's components; NaN for one component). ``attrs``:
        status, seed, dt, targets, suite-mean ratios, failures.

        Returns
        -------
        pandas.DataFrame
            The table described above: units in the column names, metadata in
            ``attrs``.
        """
        import pandas as pd

        correlations = self.core.component_correlations()
        rows = []
        for component in self.core.components:
            for k, record in enumerate(component.records):
                c = record.check
                largest = correlations[k]["max"]
                rows.append(
                    {
                        "record": k + 1,
                        "component": component.direction,
                        "min_ratio [-]": c.min_ratio,
                        "min_ratio_frequency [Hz]": c.min_ratio_frequency,
                        "max_ratio [-]": c.max_ratio,
                        "max_ratio_frequency [Hz]": c.max_ratio_frequency,
                        "peak_acceleration [m/s^2]": c.peak_acceleration,
                        "zero_period_acceleration [m/s^2]": c.zero_period_acceleration,
                        "peak_ratio [-]": c.peak_ratio,
                        "duration_5_75 [s]": c.duration_5_75,
                        "final_velocity [m/s]": c.final_velocity,
                        "final_displacement [m]": c.final_displacement,
                        "iterations": c.iterations,
                        "attempts": c.attempts,
                        "passed": c.passed,
                        "component_correlation [-]": np.nan if largest is None else largest,
                    }
                )
        frame = pd.DataFrame(rows)
        frame.attrs.update(
            status=self.status,
            seed=self.core.seed,
            dt=self.core.dt,
            name=self.name,
            targets={c.direction: c.target.label for c in self.core.components},
            mean_ratio_min={c.direction: c.mean_ratio_min for c in self.core.components},
            failures=list(self.failures),
            source="freestand records generate",
        )
        return frame

    def plot(self, ax=None):
        """Each component's spectra against its target, with the band and the ratios.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Draw the x components' spectra into these axes (no other panel).

        Returns
        -------
        matplotlib.figure.Figure
            One column per component (x, y, vertical): the records (grey),
            their mean (red), the target (black) and 0.9 and 1.3 times it
            (dashed), and below, record / target.
        """
        from freestand.plot.records import plot_suite_spectra

        result = self.core
        components = [
            (c.direction, c.target, [r.spectrum for r in c.records], c.mean_spectrum)
            for c in result.components
        ]
        return plot_suite_spectra(
            result.horizontal.frequencies,
            components,
            bounds=(result.criteria.lower_ratio, result.criteria.upper_ratio),
            title=f"{result.count} records matched to their targets (seed {result.seed})",
            axes=ax,
        )

    def with_files(self, *paths) -> GeneratedSuite:
        """The same result listing ``paths`` among the files written from it."""
        return replace(self, files=self.files + tuple(str(p) for p in paths))

    def write(self, output: str | Path, *, file_format: str = "at2") -> GeneratedSuite:
        """Write the records, ``suite.toml`` and ``acceptance.json`` into a new folder.

        Parameters
        ----------
        output : str or Path
            A new or empty folder (its parent must exist).
        file_format : {"at2", "csv"}
            PEER ``.AT2`` (values in g, ``%15.7E``) or CSV; the same records
            give the same bytes.

        Returns
        -------
        GeneratedSuite
            This result with ``output``, ``suite_file`` and ``files`` set. The
            files go to a temporary folder renamed at the end, so a failure
            leaves nothing half-written.
        """
        output = Path(output)
        _check_suite_folder(output)
        _check_format(file_format)
        return self._write(output, file_format)

    def _write(self, output: Path, file_format: str) -> GeneratedSuite:
        import json

        from freestand.io.suites import write_suite

        staging = Path(tempfile.mkdtemp(prefix=f".{output.name}.", dir=output.resolve().parent))
        try:
            suite_path = write_suite(
                staging, list(self.motions), name=self.name, file_format=file_format,
                comments=self.comments, gravity=GRAVITY,
            )  # fmt: skip
            (staging / "acceptance.json").write_text(
                json.dumps(self.acceptance(), indent=2) + "\n", encoding="utf-8"
            )
            if output.is_dir():
                output.rmdir()
            os.replace(staging, output)
        except BaseException:
            shutil.rmtree(staging, ignore_errors=True)
            raise
        suite_file = output / suite_path.name
        return replace(
            self,
            output=str(output),
            suite_file=str(suite_file),
            files=(str(suite_file), str(output / "acceptance.json")),
        )


def _check_format(file_format: str) -> None:
    if file_format not in ("at2", "csv"):
        raise FreestandError(f"{file_format!r} is not a format; use at2 or csv", source="format")


def _check_suite_folder(output: Path) -> None:
    """Refuse, before computing, an output that is a file, a non-empty folder or nowhere."""
    if output.exists() and not output.is_dir():
        raise FreestandError(f"{str(output)!r} is a file; give a new folder", source="output")
    if output.is_dir() and any(output.iterdir()):
        raise FreestandError(
            f"folder {str(output)!r} is not empty; give a new or empty folder so that no "
            "record of another suite is mixed in",
            source="output",
        )
    parent = output.resolve().parent
    if parent.exists() and not parent.is_dir():
        raise FreestandError(
            f"{str(parent)!r} is a file, not a folder; give a new folder elsewhere",
            source="output",
        )
    if not parent.is_dir():
        raise FreestandError(f"folder {str(parent)!r} does not exist; create it first",
                             source="output")  # fmt: skip
    check_writable(output, "output")


def _check_generation(count, duration, dt, seed) -> None:
    if not isinstance(count, int) or count < 1 or count > 1000:
        raise FreestandError(f"{count} records: give 1 to 1000", source="count")
    if not (duration >= 2.0 and duration <= 600.0):
        raise FreestandError(
            f"{duration} s: give a record length of 2 to 600 s, e.g. 20", source="duration"
        )
    if not (0 < dt <= 0.01):
        raise FreestandError(
            f"{dt} s: the step must be positive and at most 0.01 s (50 Hz is checked), e.g. 0.005",
            source="dt",
        )
    if duration / dt > MAX_SAMPLES:
        raise FreestandError(
            f"{duration:g} s at dt = {dt:g} s is {duration / dt:.3g} samples per record, beyond "
            f"the {MAX_SAMPLES:.0e} freestand generates; give a larger step, e.g. 0.005",
            source="dt",
        )
    if not isinstance(seed, int) or seed < 0:
        raise FreestandError(f"{seed} is not a seed; give a whole number >= 0", source="seed")


def _generation_targets(target, vertical, horizontal_y, gravity):
    """The x, y and vertical target spectra (y: None, or the x target for True / "same")."""
    x = _as_spectrum(target, "target", gravity)
    if x.direction != "horizontal":
        raise FreestandError(
            "the target is a vertical spectrum; give it as the vertical target and a "
            "horizontal one as the target",
            source="target",
        )
    if horizontal_y is True or (isinstance(horizontal_y, str) and horizontal_y == "same"):
        y = x
    elif horizontal_y is None or horizontal_y is False:
        y = None
    else:
        y = _as_spectrum(horizontal_y, "horizontal_y", gravity)
        if y.direction != "horizontal":
            raise FreestandError(
                "the second horizontal target is a vertical spectrum; give a horizontal one",
                source="horizontal_y",
            )
    v = _as_spectrum(vertical, "vertical", gravity)
    if v is not None and v.direction != "vertical":
        # a spectrum given without a direction: use it for the vertical all the same
        v = Spectrum(v.frequency, v.acceleration, v.damping, "vertical", v.label,
                     dict(v.metadata))  # fmt: skip
    return x, y, v


def generate_suite(
    target,
    count: int = 30,
    duration: float = 20.0,
    seed: int = 1,
    *,
    vertical=None,
    horizontal_y=None,
    dt: float = 0.005,
    name: str | None = None,
    output: str | Path | None = None,
    file_format: str = "at2",
    progress=None,
) -> GeneratedSuite:
    """Spectrum-compatible records (one, two or three components) with acceptance checks.

    Parameters
    ----------
    target : Spectrum or str
        Horizontal target pseudo-acceleration spectrum [m/s^2] at its damping
        (x components), or its text as ``--spectrum`` takes it, e.g.
        ``"rg1.60:pga=0.3g,damping=5%"`` or ``"en1998:ag=2.5,ground=B,type=1"``.
    count : int, optional
        Number of records [-], 1 to 1000 (default 30).
    duration : float, optional
        Record length [s], 2 to 600 (default 20).
    seed : int, optional
        Seed [-], >= 0 (default 1): the same seed gives the same records
        (and, written, the same bytes).
    vertical : Spectrum or str, optional
        Target of vertical components (none by default).
    horizontal_y : Spectrum, str or bool, optional
        A second horizontal component along y: True or ``"same"`` for the x
        target, or its own target; None (default) for records with one
        horizontal component (generated exactly as before y existed).
    dt : float, optional
        Time step [s], at most 0.01 (default 0.005).
    name : str, optional
        Suite name (default from the target, count and seed).
    output : str or Path, optional
        A new or empty folder: the records, ``suite.toml`` and
        ``acceptance.json`` are written there (see :meth:`GeneratedSuite.write`).
    file_format : {"at2", "csv"}
        Format of the written records (default ``"at2"``).
    progress : callable, optional
        Called with no argument after each matched component.

    Returns
    -------
    GeneratedSuite
        Records, every check of every record and of the suite, ``status``
        (``"accepted"`` or ``"failed"``) and the ``failures``.

    Notes
    -----
    Seeds from the stochastic model of Rezaeian and Der Kiureghian (2010,
    EESD 39(10)), matched by the continuous-wavelet method of Montejo and
    Suarez (2013, IJASE 5:26), baseline corrected; checked against US NRC SRP
    3.7.1: each spectrum within 0.9-1.3 times its target at 100 frequencies
    per decade from 0.2 to 50 Hz, the suite mean not below it, the PGA within
    5 % of the zero-period acceleration, the 5-75 % Arias duration reported,
    and every correlation coefficient of two time histories (so of two
    components of a record: statistical independence) below 0.3. See
    ``docs/records.md``.

    Examples
    --------
    >>> import freestand as fs
    >>> suite = fs.generate_suite("rg1.60:pga=0.3g,damping=5%", count=2, duration=8.0,
    ...                           seed=7, horizontal_y=True)
    >>> suite.status, len(suite.motions), suite.motions[0].components
    ('accepted', 2, ('horizontal', 'horizontal_y'))
    >>> suite.independence()["max"] < 0.3
    True
    """
    from freestand.core.motion.spectrum_matching import generate_suite as _generate

    _check_format(file_format)
    _check_generation(count, duration, dt, seed)
    if output is not None:
        _check_suite_folder(Path(output))
    x, y, v = _generation_targets(target, vertical, horizontal_y, GRAVITY)
    try:
        result = _generate(
            x, count=count, duration=duration, dt=dt, seed=seed, vertical_target=v,
            horizontal_y_target=y, progress=progress,
        )  # fmt: skip
    except ValueError as error:
        if isinstance(error, FreestandError):
            raise
        raise FreestandError(str(error), source="records generate") from None
    motions = []
    for k, record in enumerate(result.horizontal.records):
        vertical_values = None
        if result.vertical is not None:
            # generated as recorded (positive up); freestand stores downward acceleration
            vertical_values = -result.vertical.records[k].acceleration
        y_values = None if y is None else result.horizontal_y.records[k].acceleration
        motions.append(GroundMotion(dt, record.acceleration, vertical_values, name=f"rec{k + 1}",
                                    horizontal_y=y_values))  # fmt: skip
    comments = (
        "Spectrum-compatible records generated by freestand records generate",
        f"target: {x.label}",
        *(() if y is None else (f"second horizontal (y) target: {y.label}",)),
        *(() if v is None else (f"vertical target: {v.label}",)),
        f"seed {seed}, {count} records of {duration:g} s at dt = {dt:g} s",
        f"acceptance: {result.status}"
        + (f" ({len(result.failures)} failure(s), see acceptance.json)" if result.failures else ""),
        "seed motions: Rezaeian and Der Kiureghian (2010); matching: Montejo and Suarez (2013)",
    )
    suite = GeneratedSuite(
        result,
        name or f"{x.label}, {count} records, seed {seed}",
        float(duration),
        tuple(motions),
        comments=comments,
    )
    return suite if output is None else suite._write(Path(output), file_format)


# ------------------------------------------------------------------------ floor motion


@dataclass(frozen=True)
class FloorMotion:
    """In-structure (floor) motion of a record (``records floor``).

    Attributes
    ----------
    ground : GroundMotion
        The ground record as read [m/s^2].
    floor : GroundMotion
        The floor motion: the absolute acceleration of the oscillator [m/s^2]
        under the ground record followed by five periods of zeros (the
        structure's free vibration); y filtered like x; the vertical unchanged
        unless a vertical mode is given.
    frequency : float
        Frequency f of the structure's horizontal mode [Hz].
    damping : float
        Its damping ratio zeta [-].
    vertical_frequency : float or None
        Frequency of a vertical mode [Hz], if any.
    spectral_absolute_acceleration, spectral_pseudo_acceleration : float
        The ground's spectrum at f [m/s^2]: peak absolute acceleration and
        PSA.
    outputs : dict
        Files written per component (``"horizontal"``, ``"horizontal_y"``,
        ``"vertical"``).

    Examples
    --------
    >>> import freestand as fs
    >>> floor = fs.floor_motion("examples/records/synthetic_H.AT2", 2.5, 0.05)
    >>> round(floor.to_dict()["floor_peak"], 2)
    7.72
    >>> floor.to_frame().columns[:2].tolist()
    ['time [s]', 'ground [m/s^2]']
    >>> fig = floor.plot()
    """

    ground: GroundMotion
    floor: GroundMotion
    frequency: float
    damping: float
    vertical_frequency: float | None
    spectral_absolute_acceleration: float
    spectral_pseudo_acceleration: float
    outputs: dict = field(default_factory=dict)

    @property
    def extended_ground(self) -> GroundMotion:
        """The ground record followed by zeros to the floor motion's length [m/s^2]."""
        return self.ground.with_trailing_zeros(self.floor.duration)

    def to_dict(self) -> dict:
        """The ``freestand records floor --json`` document.

        Keys: ``record``, ``frequency`` [Hz], ``damping`` [-], ``ground_peak``
        and ``floor_peak`` [m/s^2] (x), ``amplification`` [-],
        ``spectral_absolute_acceleration`` and ``spectral_pseudo_acceleration``
        [m/s^2] (the ground's spectrum at the frequency), ``duration`` [s],
        ``vertical_frequency`` [Hz], ``ground_peak_vertical`` and
        ``floor_peak_vertical`` [m/s^2], ``output``; ``output_vertical`` when
        a vertical file was written; with a second horizontal component
        ``ground_peak_y``, ``floor_peak_y`` [m/s^2] (and ``output_y``).

        Returns
        -------
        dict
            JSON-ready: str, int, float, bool, None, lists and dicts
            (non-finite floats as None).
        """
        ground_peak = self.ground.peak_horizontal
        floor_peak = self.floor.peak_horizontal
        document = {
            "record": self.ground.name,
            "frequency": self.frequency,
            "damping": self.damping,
            "ground_peak": ground_peak,
            "floor_peak": floor_peak,
            "amplification": floor_peak / ground_peak if ground_peak > 0 else None,
            "spectral_absolute_acceleration": self.spectral_absolute_acceleration,
            "spectral_pseudo_acceleration": self.spectral_pseudo_acceleration,
            "duration": self.floor.duration,
            "vertical_frequency": self.vertical_frequency,
            "ground_peak_vertical": self.ground.peak_vertical,
            "floor_peak_vertical": self.floor.peak_vertical,
            "output": self.outputs.get("horizontal"),
        }
        if "vertical" in self.outputs:
            document["output_vertical"] = self.outputs["vertical"]
        if self.ground.horizontal_y is not None:
            document.update(
                ground_peak_y=self.ground.peak_horizontal_y,
                floor_peak_y=self.floor.peak_horizontal_y,
            )
            if "horizontal_y" in self.outputs:
                document["output_y"] = self.outputs["horizontal_y"]
        return document

    def to_frame(self):
        """Tidy table: one row per time step.

        Columns: ``time [s]``, ``ground [m/s^2]``, ``floor [m/s^2]`` (x), and
        where the record has them ``ground_y [m/s^2]``, ``floor_y [m/s^2]``,
        ``ground_vertical [m/s^2]``, ``floor_vertical [m/s^2]`` (downward
        positive). ``attrs``: record, frequency, damping, units.

        Returns
        -------
        pandas.DataFrame
            The table described above: units in the column names, metadata in
            ``attrs``.
        """
        import pandas as pd

        ground = self.extended_ground
        columns = {"time [s]": self.floor.time}
        for component, suffix in (("horizontal", ""), ("horizontal_y", "_y"),
                                  ("vertical", "_vertical")):  # fmt: skip
            if getattr(self.floor, component) is None:
                continue
            columns[f"ground{suffix} [m/s^2]"] = ground.component(component)
            columns[f"floor{suffix} [m/s^2]"] = self.floor.component(component)
        frame = pd.DataFrame(columns)
        frame.attrs.update(
            record=self.ground.name,
            frequency=self.frequency,
            damping=self.damping,
            vertical_frequency=self.vertical_frequency,
            units={"time": "s", "acceleration": "m/s^2 (vertical positive downward)"},
            source="freestand records floor",
        )
        return frame

    def plot(self, ax=None):
        """Ground and floor acceleration (x) against time, as the command draws.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Draw into these axes instead of a new figure.

        Returns
        -------
        matplotlib.figure.Figure
            One axes, two lines: ``ground`` and ``floor (oscillator absolute
            acceleration)``.
        """
        from freestand.plot.records import plot_floor_motion

        return plot_floor_motion(
            self.floor.time,
            self.extended_ground.horizontal,
            self.floor.horizontal,
            title=f"{self.ground.name}: floor motion, {self.frequency:g} Hz, "
            f"{100 * self.damping:g} % damping",
            axes=ax,
        )

    def write(self, output: str | Path) -> FloorMotion:
        """Write the floor motion: ``FILE.AT2`` or ``FILE.csv`` (x), ``FILE_Y`` (y), ``FILE_UP``.

        The vertical is written positive up, as recorded; each file is
        written to a temporary file renamed at the end.

        Returns
        -------
        FloorMotion
            This result with ``outputs`` set.
        """
        from freestand.io.records import write_at2, write_csv_record

        output = _check_floor_output(output)
        label = (
            f"{self.ground.name}: floor motion (absolute acceleration of a {self.frequency:g} "
            f"Hz, {100 * self.damping:g} % oscillator)"
        )
        files = {"horizontal": output}
        if self.floor.horizontal_y is not None:
            files["horizontal_y"] = output.with_name(output.stem + "_Y" + output.suffix)
        if self.floor.vertical is not None:
            files["vertical"] = output.with_name(output.stem + "_UP" + output.suffix)
        for component, path in files.items():
            if path.suffix.lower() == ".at2":
                write_atomic(path, lambda tmp, c=component: write_at2(
                    tmp, self.floor, component=c, description=label, gravity=GRAVITY))  # fmt: skip
            else:
                write_atomic(path, lambda tmp, c=component: write_csv_record(
                    tmp, self.floor, component=c, gravity=GRAVITY, comments=(label,)))  # fmt: skip
        return replace(self, outputs={c: str(p) for c, p in files.items()})


def _check_floor_output(output) -> Path:
    return check_file(Path(output), "output", (".at2", ".csv"))


def floor_motion(
    record,
    frequency,
    damping=0.05,
    *,
    vertical=None,
    horizontal_y=None,
    vertical_frequency=None,
    output: str | Path | None = None,
    dt: float | None = None,
    unit: str | None = None,
    gravity: float = GRAVITY,
) -> FloorMotion:
    """In-structure motion: the absolute acceleration of a linear oscillator under a record.

    Parameters
    ----------
    record : GroundMotion, str or Path
        The ground record, or its file (``.AT2``, ``.V2``, CSV, one column).
    frequency : float or str
        Frequency f of the structure's horizontal mode [Hz] (``2.5`` or
        ``"2.5Hz"``).
    damping : float or str, optional
        Its damping ratio zeta [-] (0.05 or ``"5%"``; default 0.05).
    vertical, horizontal_y : str or Path, optional
        Files of the vertical (positive up) and second horizontal components,
        with a record file.
    vertical_frequency : float or str, optional
        Frequency of a vertical mode [Hz] that filters the vertical; without
        it the vertical passes unchanged.
    output : str or Path, optional
        Write the floor motion there (``.AT2`` or ``.csv``; see
        :meth:`FloorMotion.write`).
    dt, unit : optional
        Time step [s] and unit of single-column files.
    gravity : float, optional
        g [m/s^2].

    Returns
    -------
    FloorMotion
        Ground and floor motions, their peaks and the ground's spectrum at f.

    Notes
    -----
    Equipment on a structure that does not interact with it feels the
    structure's absolute acceleration; with one dominant mode (f, zeta)
    a_floor = u'' + a_g = -(2 zeta omega u' + omega^2 u) for
    u'' + 2 zeta omega u' + omega^2 u = -a_g (exact piecewise-linear
    recursion, Nigam and Jennings 1969). The record is followed by five
    periods of zeros so that the structure's free vibration is kept; the
    floor peak is the ground's absolute-acceleration spectrum at f.

    Examples
    --------
    >>> import freestand as fs
    >>> floor = fs.floor_motion("examples/records/synthetic_H.AT2", 2.5, 0.05)
    >>> round(floor.to_dict()["amplification"], 2)
    3.15
    """
    from freestand.core.motion.response_spectrum import floor_motion as _floor
    from freestand.core.motion.response_spectrum import spectral_response
    from freestand.io.records import load_record

    f = _frequency(frequency, "frequency")
    zeta = _fraction(damping, "damping")
    f_v = None if vertical_frequency is None else _frequency(vertical_frequency,
                                                            "vertical_frequency")  # fmt: skip
    if output is not None:
        _check_floor_output(output)
    if isinstance(record, GroundMotion):
        if vertical is not None or horizontal_y is not None:
            raise FreestandError(
                "vertical and horizontal_y are files that go with a record file; a "
                "GroundMotion carries its own components",
                source="vertical" if vertical is not None else "horizontal_y",
            )
        ground = record
    else:
        ground = load_record(record, dt=dt, unit=unit, gravity=gravity, vertical=vertical,
                             horizontal_y=horizontal_y)  # fmt: skip
    if f_v is not None and ground.vertical is None:
        raise FreestandError(
            "a vertical mode filters a vertical record; give the vertical component",
            source="vertical_frequency",
        )
    # follow the structure's free vibration after the record (5 periods of decay)
    extended = ground.with_trailing_zeros(ground.duration + 5.0 / min(f, f_v or f))
    response = spectral_response(ground, None, [f], zeta)
    result = FloorMotion(
        ground,
        _floor(extended, f, zeta, vertical_frequency=f_v),
        f,
        zeta,
        f_v,
        float(response.absolute_acceleration[0]),
        float(response.pseudo_acceleration[0]),
    )
    return result if output is None else result.write(output)
