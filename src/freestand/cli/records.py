"""``freestand records``: record spectra, spectrum-compatible suites, floor motions."""

from __future__ import annotations

import json
import os
import shutil
import tempfile
from pathlib import Path

import numpy as np
import typer
from rich.console import Console
from rich.markup import escape
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn
from rich.table import Table

from freestand.cli.common import _check_parent, console
from freestand.core.motion.spectra import Spectrum
from freestand.errors import FreestandError

records_app = typer.Typer(
    name="records",
    help="Record spectra, spectrum-compatible record suites and in-structure (floor) motions.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)

GRAVITY = 9.81
_FIGURE_SUFFIXES = (".png", ".svg", ".pdf")


# --------------------------------------------------------------------------- helpers


def _damping(text: str, option: str) -> float:
    from freestand.io.units import damping_fraction

    return damping_fraction(text.strip(), field="damping", source=option)


def _frequency(text: str, option: str) -> float:
    from freestand.io.units import to_si

    value = to_si(text.strip(), "frequency", field="frequency", source=option)
    if not value > 0:
        raise FreestandError(f"{text!r} is not a positive frequency; e.g. 2.5Hz", source=option)
    return value


def _target(text: str, option: str) -> Spectrum:
    from freestand.io.spectrum_input import parse_spectrum_option

    try:
        return parse_spectrum_option(text, model_spectra={}, base_dir=Path.cwd(), gravity=GRAVITY)
    except FreestandError as error:
        if option == "--spectrum":
            raise
        raise FreestandError(str(error).replace("--spectrum", option)) from None


#: Most samples per generated record (duration / dt): 600 s at 0.0006 s; beyond, a typo such
#: as --dt 1e-9 would run for hours.
MAX_SAMPLES = 1_000_000


def _check_output_file(path: Path | None, option: str, suffixes: tuple[str, ...]) -> None:
    """Refuse, before computing, an output file of the wrong type or in a non-folder."""
    if path is None:
        return
    if path.suffix.lower() not in suffixes:
        raise FreestandError(
            f"{str(path)!r} has no {' or '.join(suffixes)} suffix; e.g. {option} "
            f"{path.with_suffix(suffixes[0]).name}",
            source=option,
        )
    if path.is_dir():
        raise FreestandError(f"{str(path)!r} is a folder; give a file name", source=option)
    _check_parent(path, option)


def _write_atomic(path: Path, writer) -> None:
    """Call ``writer(temporary_path)``, then rename the temporary file to ``path``."""
    path.parent.mkdir(parents=True, exist_ok=True)
    handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
    os.close(handle)
    try:
        writer(Path(temporary))
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise


def _save_figure(figure, path: Path) -> None:
    fmt = path.suffix.lower().lstrip(".")
    _write_atomic(path, lambda tmp: figure.savefig(tmp, format=fmt, dpi=150))


def _load_records(paths: list[Path], dt, unit):
    """Motions from record files and suite files (``.toml``)."""
    from freestand.io.records import load_record
    from freestand.io.suites import load_suite

    motions = []
    for path in paths:
        if path.suffix.lower() == ".toml":
            motions.extend(load_suite(path, gravity=GRAVITY).motions)
        else:
            motions.append(load_record(path, dt=dt, unit=unit, gravity=GRAVITY))
    return motions


def _progress(total: int, description: str, quiet: bool):
    if quiet:
        return None
    return Progress(
        TextColumn("{task.description}"),
        BarColumn(),
        MofNCompleteColumn(),
        TimeElapsedColumn(),
        console=Console(emoji=False, stderr=True),
        transient=True,
    )


# -------------------------------------------------------------------------- spectrum


@records_app.command("spectrum")
def spectrum(
    records: list[Path] = typer.Argument(
        ..., help="Records (.AT2, .V2, CSV with units, one column) or suite files (.toml)."
    ),
    damping: str = typer.Option(
        None, "--damping", help="Damping ratio, e.g. 5% or 0.05 (default: the target's, else 5%)."
    ),
    target: str = typer.Option(
        None,
        "--target",
        help="Target spectrum, as --spectrum takes it: CSV file, "
        "'rg1.60:pga=0.3g,damping=5%', 'en1998:ag=2.5,ground=B,type=1', 'record:FILE'.",
    ),
    vertical_target: str = typer.Option(
        None, "--vertical-target", help="Target spectrum of the vertical components."
    ),
    dt: float = typer.Option(None, "--dt", help="Time step [s] of single-column records."),
    unit: str = typer.Option(None, "--unit", help="Unit of single-column records, e.g. g."),
    plot: Path = typer.Option(None, "--plot", help="Figure file (.png, .svg or .pdf)."),
    csv_file: Path = typer.Option(None, "--csv", help="Write the spectra to this CSV file."),
    as_json: bool = typer.Option(False, "--json", help="Write one JSON document to stdout."),
) -> None:
    """Pseudo-acceleration spectra of records (horizontal and vertical), against a target."""
    from freestand.core.motion.response_spectrum import SpectrumPlan
    from freestand.core.motion.spectrum_matching import AcceptanceCriteria

    _check_output_file(plot, "--plot", _FIGURE_SUFFIXES)
    _check_output_file(csv_file, "--csv", (".csv",))
    target_spectrum = None if target is None else _target(target, "--target")
    targets = {}
    if target_spectrum is not None:
        targets[target_spectrum.direction] = target_spectrum
    if vertical_target is not None:
        spectrum_v = _target(vertical_target, "--vertical-target")
        targets["vertical"] = spectrum_v
        if target_spectrum is None:
            target_spectrum = spectrum_v
    if damping is not None:
        zeta = _damping(damping, "--damping")
    else:
        zeta = target_spectrum.damping if target_spectrum is not None else 0.05
    motions = _load_records(records, dt, unit)
    frequency = np.geomspace(0.1, 100.0, 301)
    check_band = AcceptanceCriteria()
    in_band = (frequency >= check_band.lowest_frequency * (1 - 1e-9)) & (
        frequency <= check_band.highest_frequency * (1 + 1e-9)
    )
    target_values = (
        None if target_spectrum is None else np.asarray(target_spectrum.acceleration_at(frequency))
    )
    plans: dict[float, SpectrumPlan] = {}
    rows = []
    curves = []
    for motion in motions:
        plan = plans.get(motion.dt)
        if plan is None:
            plan = plans[motion.dt] = SpectrumPlan.build(frequency, motion.dt, zeta)
        for component in ("horizontal", "vertical"):
            if component == "vertical" and motion.vertical is None:
                continue
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
            if component in targets:
                goal = np.asarray(targets[component].acceleration_at(frequency))
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
            curves.append((f"{motion.name} ({component})", psa))
    written = []
    if csv_file is not None:

        def write_csv(tmp: Path) -> None:
            header = ["frequency [Hz]"]
            if target_values is not None:
                header.append("target [m/s^2]")
            header += [f"{name} PSA [m/s^2]" for name, _ in curves]
            lines = [", ".join(header)]
            for i, f in enumerate(frequency):
                cells = [f"{f:.6g}"]
                if target_values is not None:
                    cells.append(f"{target_values[i]:.6e}")
                cells += [f"{values[i]:.6e}" for _, values in curves]
                lines.append(", ".join(cells))
            tmp.write_text("\n".join(lines) + "\n", encoding="utf-8")

        _write_atomic(csv_file, write_csv)
        written.append(csv_file)
    if plot is not None:
        from freestand.plot.records import plot_record_spectra

        figure = plot_record_spectra(
            frequency,
            curves,
            target=target_spectrum,
            damping=zeta,
            title=f"Pseudo-acceleration spectra, {100 * zeta:g} % damping",
        )
        _save_figure(figure, plot)
        written.append(plot)
    if as_json:
        document = {
            "damping": zeta,
            "frequency": frequency.tolist(),
            "target": None
            if target_spectrum is None
            else {
                "label": target_spectrum.label,
                "direction": target_spectrum.direction,
                "damping": target_spectrum.damping,
                "acceleration": target_values.tolist(),
            },
            "records": [
                {
                    key: (value.tolist() if isinstance(value, np.ndarray) else value)
                    for key, value in row.items()
                }
                for row in rows
            ],  # fmt: skip
            "files": [str(path) for path in written],
        }
        typer.echo(json.dumps(document, indent=2))
        return
    out = console()
    title = f"Pseudo-acceleration spectra, {100 * zeta:g} % damping, 0.1-100 Hz"
    table = Table(title=escape(title))
    columns = ["record", "component", "PGA [m/s^2]", "peak PSA [m/s^2]", "at [Hz]"]
    if target_spectrum is not None:
        columns += ["min PSA/target [-]", "at [Hz]", "max PSA/target [-]", "at [Hz]"]
    for column in columns:
        table.add_column(escape(column))
    for row in rows:
        cells = [
            escape(row["record"]),
            row["component"],
            f"{row['peak_acceleration']:.4g}",
            f"{row['peak_psa']:.4g}",
            f"{row['peak_psa_frequency']:.3g}",
        ]
        if target_spectrum is not None:
            if "min_ratio" in row:
                cells += [
                    f"{row['min_ratio']:.3f}",
                    f"{row['min_ratio_frequency']:.3g}",
                    f"{row['max_ratio']:.3f}",
                    f"{row['max_ratio_frequency']:.3g}",
                ]
            else:
                cells += ["-", "-", "-", "-"]
        table.add_row(*cells)
    out.print(table)
    for direction, spectrum_d in targets.items():
        out.print(
            escape(
                f"{direction} target: {spectrum_d.label}; ratios over "
                f"{check_band.lowest_frequency:g}-{check_band.highest_frequency:g} Hz"
            )
        )
        if abs(spectrum_d.damping - zeta) > 1e-12:
            out.print(
                f"[yellow]note:[/] the {direction} target is for {100 * spectrum_d.damping:g} % "
                f"damping, the spectra for {100 * zeta:g} %"
            )
    for path in written:
        out.print(f"wrote {escape(str(path))}")


# -------------------------------------------------------------------------- generate


def _prepare_output_folder(output: Path) -> None:
    if output.exists() and not output.is_dir():
        raise FreestandError(f"{str(output)!r} is a file; give a new folder", source="--output")
    if output.is_dir() and any(output.iterdir()):
        raise FreestandError(
            f"folder {str(output)!r} is not empty; give a new or empty folder so that no "
            "record of another suite is mixed in",
            source="--output",
        )
    parent = output.resolve().parent
    if parent.exists() and not parent.is_dir():
        raise FreestandError(
            f"{str(parent)!r} is a file, not a folder; give a new folder elsewhere",
            source="--output",
        )
    if not parent.is_dir():
        raise FreestandError(
            f"folder {str(parent)!r} does not exist; create it first", source="--output"
        )
    _check_parent(output, "--output")


def _suite_document(result, output: Path, suite_file: Path | None) -> dict:
    def component_doc(component):
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

    criteria = result.criteria
    return {
        "status": result.status,
        "failures": list(result.failures),
        "seed": result.seed,
        "count": result.count,
        "dt": result.dt,
        "criteria": {
            "frequencies": f"{criteria.lowest_frequency:g}-{criteria.highest_frequency:g} Hz, "
            f"{criteria.per_decade} per decade",
            "ratio_bounds": [criteria.lower_ratio, criteria.upper_ratio],
            "peak_tolerance": criteria.peak_tolerance,
            "max_correlation": criteria.max_correlation,
        },
        "max_correlation": result.max_correlation,
        "max_correlation_pair": list(result.max_correlation_pair),
        "horizontal": component_doc(result.horizontal),
        "vertical": None if result.vertical is None else component_doc(result.vertical),
        "output": str(output),
        "suite_file": None if suite_file is None else str(suite_file),
    }


@records_app.command("generate")
def generate(
    target: str = typer.Option(
        ..., "--target", help="Horizontal target spectrum, as --spectrum takes it."
    ),
    count: int = typer.Option(30, "--count", help="Number of records [-]."),
    duration: float = typer.Option(20.0, "--duration", help="Record length [s]."),
    seed: int = typer.Option(1, "--seed", help="Seed: the same seed gives the same files."),
    output: Path = typer.Option(..., "--output", help="New (or empty) folder for the suite."),
    vertical: str = typer.Option(
        None, "--vertical", help="Vertical target spectrum: adds vertical components."
    ),
    file_format: str = typer.Option("at2", "--format", help="Record files: at2 or csv."),
    dt: float = typer.Option(0.005, "--dt", help="Time step [s] (default 0.005 s)."),
    name: str = typer.Option(None, "--name", help="Suite name (default from the target)."),
    plot: Path = typer.Option(None, "--plot", help="Figure of the suite (.png, .svg or .pdf)."),
    as_json: bool = typer.Option(False, "--json", help="Write one JSON document to stdout."),
    quiet: bool = typer.Option(False, "--quiet", help="No progress bar."),
) -> None:
    """Generate a suite of spectrum-compatible records, with acceptance checks and a suite file."""
    from freestand.core.motion.ground_motion import GroundMotion
    from freestand.core.motion.spectrum_matching import generate_suite
    from freestand.io.suites import write_suite

    if file_format not in ("at2", "csv"):
        raise FreestandError(f"{file_format!r} is not a format; use at2 or csv", source="--format")
    if count < 1 or count > 1000:
        raise FreestandError(f"{count} records: give 1 to 1000", source="--count")
    if not (duration >= 2.0 and duration <= 600.0):
        raise FreestandError(
            f"{duration} s: give a record length of 2 to 600 s, e.g. --duration 20",
            source="--duration",
        )
    if not (0 < dt <= 0.01):
        raise FreestandError(
            f"{dt} s: the step must be positive and at most 0.01 s (50 Hz is checked), "
            "e.g. --dt 0.005",
            source="--dt",
        )
    if duration / dt > MAX_SAMPLES:
        raise FreestandError(
            f"{duration:g} s at dt = {dt:g} s is {duration / dt:.3g} samples per record, beyond "
            f"the {MAX_SAMPLES:.0e} freestand generates; give a larger --dt, e.g. --dt 0.005",
            source="--dt",
        )
    if seed < 0:
        raise FreestandError(f"{seed} is negative; give a seed >= 0", source="--seed")
    _prepare_output_folder(output)
    _check_output_file(plot, "--plot", _FIGURE_SUFFIXES)
    horizontal_target = _target(target, "--target")
    if horizontal_target.direction != "horizontal":
        raise FreestandError(
            "the target is a vertical spectrum; give it with --vertical and a horizontal "
            "one with --target",
            source="--target",
        )
    vertical_target = None if vertical is None else _target(vertical, "--vertical")
    if vertical_target is not None and vertical_target.direction != "vertical":
        # a spectrum given without a direction: use it for the vertical all the same
        vertical_target = Spectrum(
            vertical_target.frequency,
            vertical_target.acceleration,
            vertical_target.damping,
            "vertical",
            vertical_target.label,
            dict(vertical_target.metadata),
        )
    suite_name = name or f"{horizontal_target.label}, {count} records, seed {seed}"
    total = count * (2 if vertical_target is not None else 1)
    progress = _progress(total, "matching", quiet or as_json)
    try:
        if progress is not None:
            with progress:
                task = progress.add_task("matching records to the target", total=total)
                result = generate_suite(
                    horizontal_target, count=count, duration=duration, dt=dt, seed=seed,
                    vertical_target=vertical_target,
                    progress=lambda: progress.advance(task),
                )  # fmt: skip
        else:
            result = generate_suite(
                horizontal_target, count=count, duration=duration, dt=dt, seed=seed,
                vertical_target=vertical_target,
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
        motions.append(GroundMotion(dt, record.acceleration, vertical_values, name=f"rec{k + 1}"))
    comments = (
        "Spectrum-compatible records generated by freestand records generate",
        f"target: {horizontal_target.label}",
        *(() if vertical_target is None else (f"vertical target: {vertical_target.label}",)),
        f"seed {seed}, {count} records of {duration:g} s at dt = {dt:g} s",
        f"acceptance: {result.status}"
        + (f" ({len(result.failures)} failure(s), see acceptance.json)" if result.failures else ""),
        "seed motions: Rezaeian and Der Kiureghian (2010); matching: Montejo and Suarez (2013)",
    )
    document = None
    output_parent = output.resolve().parent
    staging = Path(tempfile.mkdtemp(prefix=f".{output.name}.", dir=output_parent))
    try:
        suite_path = write_suite(
            staging, motions, name=suite_name, file_format=file_format, comments=comments,
            gravity=GRAVITY,
        )  # fmt: skip
        document = _suite_document(result, output, output / suite_path.name)
        checks = dict(document)
        checks.pop("output")
        checks.pop("suite_file")
        (staging / "acceptance.json").write_text(
            json.dumps(checks, indent=2) + "\n", encoding="utf-8"
        )
        if output.is_dir():
            output.rmdir()
        os.replace(staging, output)
    except BaseException:
        shutil.rmtree(staging, ignore_errors=True)
        raise
    written = [output / suite_path.name, output / "acceptance.json"]
    if plot is not None:
        from freestand.plot.records import plot_record_spectra

        component = result.horizontal
        figure = plot_record_spectra(
            component.frequencies,
            [(f"rec{k + 1}", r.spectrum) for k, r in enumerate(component.records)],
            target=component.target,
            mean=component.mean_spectrum,
            damping=component.target.damping,
            bounds=(result.criteria.lower_ratio, result.criteria.upper_ratio),
            title=f"{count} records matched to the target (seed {seed})",
        )
        _save_figure(figure, plot)
        written.append(plot)
    if as_json:
        document["files"] = [str(path) for path in written]
        typer.echo(json.dumps(document, indent=2))
        if result.status != "accepted":
            raise SystemExit(1)  # a failed computation (main() returns the code)
        return
    out = console()
    for component in (result.horizontal, result.vertical):
        if component is None:
            continue
        table = Table(title=escape(f"{component.direction}: {component.target.label}"))
        for column in (
            "record",
            "min PSA/target [-]",
            "at [Hz]",
            "max PSA/target [-]",
            "at [Hz]",
            "PGA/ZPA [-]",
            "D5-75 [s]",
            "iterations",
            "seeds",
            "status",
        ):
            table.add_column(escape(column))
        for k, r in enumerate(component.records):
            c = r.check
            table.add_row(
                f"{k + 1}",
                f"{c.min_ratio:.3f}",
                f"{c.min_ratio_frequency:.3g}",
                f"{c.max_ratio:.3f}",
                f"{c.max_ratio_frequency:.3g}",
                f"{c.peak_ratio:.3f}",
                f"{c.duration_5_75:.2f}",
                f"{c.iterations}",
                f"{c.attempts}",
                "ok" if c.passed else "[red]failed[/]",
            )
        out.print(table)
        out.print(
            f"{component.direction} suite mean / target: lowest "
            f"{component.mean_ratio_min:.3f} (must be >= 1)"
        )
    criteria = result.criteria
    out.print(
        escape(
            f"checks: spectrum within {criteria.lower_ratio:g}-{criteria.upper_ratio:g} x target "
            f"at {criteria.per_decade} frequencies per decade, "
            f"{criteria.lowest_frequency:g}-{criteria.highest_frequency:g} Hz; PGA within "
            f"{100 * criteria.peak_tolerance:g} % of the zero-period value; largest correlation "
            f"coefficient {result.max_correlation:.3f} (records "
            f"{' and '.join(result.max_correlation_pair)}, must be < {criteria.max_correlation:g})"
        )
    )
    for path in written:
        out.print(f"wrote {escape(str(path))}")
    if result.status == "accepted":
        out.print(f"[green]suite accepted[/]: {count} records in {escape(str(output))}")
        return
    for failure in result.failures:
        out.print(f"[red]failed:[/] {escape(failure)}")
    raise SystemExit(1)  # a failed computation (main() returns the code)


# ----------------------------------------------------------------------------- floor


@records_app.command("floor")
def floor(
    record: Path = typer.Argument(..., help="Ground record (.AT2, .V2, CSV, one column)."),
    frequency: str = typer.Option(
        ..., "--frequency", help="Frequency of the structure's mode, e.g. 2.5Hz."
    ),
    damping: str = typer.Option("5%", "--damping", help="Damping ratio of the mode, e.g. 5%."),
    output: Path = typer.Option(
        None,
        "--output",
        help="Write the floor motion (.AT2 or .csv); a vertical goes to NAME_UP.AT2/.csv.",
    ),
    vertical: Path = typer.Option(
        None,
        "--vertical",
        help="Vertical ground record (positive up); passes unchanged unless "
        "--vertical-frequency is given.",
    ),
    vertical_frequency: str = typer.Option(
        None, "--vertical-frequency", help="Frequency of a vertical mode filtering the vertical."
    ),
    dt: float = typer.Option(None, "--dt", help="Time step [s] of single-column records."),
    unit: str = typer.Option(None, "--unit", help="Unit of single-column records, e.g. g."),
    plot: Path = typer.Option(None, "--plot", help="Figure of both histories (.png/.svg/.pdf)."),
    as_json: bool = typer.Option(False, "--json", help="Write one JSON document to stdout."),
) -> None:
    """In-structure motion: absolute acceleration of a linear oscillator under the record."""
    from freestand.core.motion.response_spectrum import floor_motion, spectral_response
    from freestand.io.records import load_record, write_at2, write_csv_record

    f = _frequency(frequency, "--frequency")
    zeta = _damping(damping, "--damping")
    f_v = None
    if vertical_frequency is not None:
        f_v = _frequency(vertical_frequency, "--vertical-frequency")
        if vertical is None:
            raise FreestandError(
                "a vertical mode filters a vertical record; give it with --vertical FILE",
                source="--vertical-frequency",
            )
    _check_output_file(output, "--output", (".at2", ".csv"))
    _check_output_file(plot, "--plot", _FIGURE_SUFFIXES)
    ground = load_record(record, dt=dt, unit=unit, gravity=GRAVITY, vertical=vertical)
    # follow the structure's free vibration after the record (5 periods of decay)
    extended = ground.with_trailing_zeros(ground.duration + 5.0 / min(f, f_v or f))
    result = floor_motion(extended, f, zeta, vertical_frequency=f_v)
    response = spectral_response(ground, None, [f], zeta)
    ground_peak = ground.peak_horizontal
    floor_peak = result.peak_horizontal
    summary = {
        "record": ground.name,
        "frequency": f,
        "damping": zeta,
        "ground_peak": ground_peak,
        "floor_peak": floor_peak,
        "amplification": floor_peak / ground_peak if ground_peak > 0 else None,
        "spectral_absolute_acceleration": float(response.absolute_acceleration[0]),
        "spectral_pseudo_acceleration": float(response.pseudo_acceleration[0]),
        "duration": result.duration,
        "vertical_frequency": f_v,
        "ground_peak_vertical": ground.peak_vertical,
        "floor_peak_vertical": result.peak_vertical,
        "output": None if output is None else str(output),
    }
    if output is not None:
        label = (
            f"{ground.name}: floor motion (absolute acceleration of a {f:g} Hz, "
            f"{100 * zeta:g} % oscillator)"
        )
        files = [("horizontal", output)]
        if result.vertical is not None:
            vertical_path = output.with_name(output.stem + "_UP" + output.suffix)
            files.append(("vertical", vertical_path))
            summary["output_vertical"] = str(vertical_path)
        for component, path in files:
            if path.suffix.lower() == ".at2":
                _write_atomic(
                    path,
                    lambda tmp, c=component: write_at2(
                        tmp, result, component=c, description=label, gravity=GRAVITY
                    ),
                )
            else:
                _write_atomic(
                    path,
                    lambda tmp, c=component: write_csv_record(
                        tmp, result, component=c, gravity=GRAVITY, comments=(label,)
                    ),
                )
    if plot is not None:
        from freestand.plot.records import plot_floor_motion

        figure = plot_floor_motion(
            result.time,
            extended.horizontal,
            result.horizontal,
            title=f"{ground.name}: floor motion, {f:g} Hz, {100 * zeta:g} %",
        )
        _save_figure(figure, plot)
    if as_json:
        typer.echo(json.dumps(summary, indent=2))
        return
    out = console()
    out.print(
        escape(
            f"{ground.name}: ground peak {ground_peak:.4g} m/s^2; floor ({f:g} Hz, "
            f"{100 * zeta:g} % damping) peak {floor_peak:.4g} m/s^2, amplification "
            f"{summary['amplification']:.3f}"
        )
    )
    out.print(
        escape(
            f"ground spectrum at {f:g} Hz: absolute acceleration "
            f"{summary['spectral_absolute_acceleration']:.4g} m/s^2, pseudo-acceleration "
            f"{summary['spectral_pseudo_acceleration']:.4g} m/s^2"
        )
    )
    if result.vertical is not None:
        how = "unchanged" if f_v is None else f"filtered by a {f_v:g} Hz, {100 * zeta:g} % mode"
        out.print(
            escape(
                f"vertical ({how}): ground peak {ground.peak_vertical:.4g} m/s^2, floor peak "
                f"{result.peak_vertical:.4g} m/s^2"
            )
        )
    if output is not None:
        out.print(f"wrote {escape(str(output))}")
        if "output_vertical" in summary:
            out.print(f"wrote {escape(summary['output_vertical'])}")
    if plot is not None:
        out.print(f"wrote {escape(str(plot))}")


def register(app: typer.Typer) -> None:
    """Add ``freestand records ...`` to the main command."""
    app.add_typer(records_app, name="records")
