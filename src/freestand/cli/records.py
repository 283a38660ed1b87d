"""``freestand records``: record spectra, spectrum-compatible suites, floor motions.

Each command is a shell over :mod:`freestand.api.records`: it parses the
options, calls the public function, writes the figure or table asked for and
prints from the result (``--json`` prints ``result.to_dict()``).
"""

from __future__ import annotations

import json
from pathlib import Path

import typer
from rich.console import Console
from rich.markup import escape
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn
from rich.table import Table

from freestand.cli.common import check_file, console
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


def _as_option(error: FreestandError, options: dict[str, str]) -> FreestandError:
    """The same error naming the command-line option instead of the parameter."""
    source = options.get(error.source, error.source)
    return FreestandError(error.detail, source=source, field=error.field)


def _call(function, options: dict[str, str], *args, **kwargs):
    """``function(*args, **kwargs)``, its input errors naming the options."""
    try:
        return function(*args, **kwargs)
    except FreestandError as error:
        raise _as_option(error, options) from None


def _save_figure(figure, path: Path) -> None:
    from freestand.api.records import write_atomic

    fmt = path.suffix.lower().lstrip(".")
    write_atomic(path, lambda tmp: figure.savefig(tmp, format=fmt, dpi=150))


def _progress(quiet: bool):
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


def _print_json(document: dict) -> None:
    typer.echo(json.dumps(document, indent=2))


# -------------------------------------------------------------------------- spectrum


@records_app.command("spectrum")
def spectrum(
    records: list[Path] = typer.Argument(
        ...,
        help="Records (.AT2, .V2, CSV with units, one column) or suite files (.toml); the "
        "files of one station's components are paired (x, y, vertical) from their names or "
        "headers.",
    ),
    damping: str = typer.Option(
        None, "--damping", help="Damping ratio, e.g. 5% or 0.05 (default: the target's, else 5%)."
    ),
    target: str = typer.Option(
        None,
        "--target",
        help="Target spectrum of the horizontal components, as --spectrum takes it: CSV file, "
        "'rg1.60:pga=0.3g,damping=5%', 'en1998:ag=2.5,ground=B,type=1', 'record:FILE'.",
    ),
    vertical_target: str = typer.Option(
        None, "--vertical-target", help="Target spectrum of the vertical components."
    ),
    dt: float = typer.Option(None, "--dt", help="Time step [s] of single-column records."),
    unit: str = typer.Option(None, "--unit", help="Unit of single-column records, e.g. g."),
    no_pair: bool = typer.Option(
        False, "--no-pair", help="Read every file as a record of its own (no pairing)."
    ),
    plot: Path = typer.Option(None, "--plot", help="Figure file (.png, .svg or .pdf)."),
    csv_file: Path = typer.Option(None, "--csv", help="Write the spectra to this CSV file."),
    as_json: bool = typer.Option(False, "--json", help="Write one JSON document to stdout."),
) -> None:
    """Pseudo-acceleration spectra of records (every component), against a target."""
    from freestand.api.records import response_spectrum, write_atomic
    from freestand.core.motion.spectrum_matching import AcceptanceCriteria

    check_file(plot, "--plot", _FIGURE_SUFFIXES)
    check_file(csv_file, "--csv", (".csv",))
    options = {"damping": "--damping", "target": "--target", "vertical_target": "--vertical-target"}
    result = _call(
        response_spectrum, options, records, damping=damping, target=target,
        vertical_target=vertical_target, dt=dt, unit=unit, gravity=GRAVITY, pair=not no_pair,
    )  # fmt: skip
    if csv_file is not None:
        write_atomic(csv_file, lambda tmp: tmp.write_text(_spectra_csv(result), encoding="utf-8"))
        result = result.with_files(csv_file)
    if plot is not None:
        _save_figure(result.plot(), plot)
        result = result.with_files(plot)
    if as_json:
        _print_json(result.to_dict())
        return
    out = console()
    zeta = result.damping
    title = f"Pseudo-acceleration spectra, {100 * zeta:g} % damping, 0.1-100 Hz"
    table = Table(title=escape(title))
    columns = ["record", "component", "PGA [m/s^2]", "peak PSA [m/s^2]", "at [Hz]"]
    if result.target is not None:
        columns += ["min PSA/target [-]", "at [Hz]", "max PSA/target [-]", "at [Hz]"]
    for column in columns:
        table.add_column(escape(column))
    for row in result.rows:
        cells = [
            escape(row["record"]),
            row["component"],
            f"{row['peak_acceleration']:.4g}",
            f"{row['peak_psa']:.4g}",
            f"{row['peak_psa_frequency']:.3g}",
        ]
        if result.target is not None:
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
    check_band = AcceptanceCriteria()
    for direction, spectrum_d in result.targets.items():
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
    for pairing in result.pairings:
        if pairing.paired or pairing.reason:
            out.print(escape(f"paired: {pairing.note}" if pairing.paired else pairing.note))
    for path in result.files:
        out.print(f"wrote {escape(path)}")


def _spectra_csv(result) -> str:
    """The spectra side by side: frequency, target, one column per record component."""
    curves = result.curves
    target_values = (
        None if result.target is None else result.target.acceleration_at(result.frequency)
    )
    header = ["frequency [Hz]"]
    if target_values is not None:
        header.append("target [m/s^2]")
    header += [f"{name} PSA [m/s^2]" for name, _ in curves]
    lines = [", ".join(header)]
    for i, f in enumerate(result.frequency):
        cells = [f"{f:.6g}"]
        if target_values is not None:
            cells.append(f"{target_values[i]:.6e}")
        cells += [f"{values[i]:.6e}" for _, values in curves]
        lines.append(", ".join(cells))
    return "\n".join(lines) + "\n"


# -------------------------------------------------------------------------- generate

_GENERATE_OPTIONS = {
    "target": "--target",
    "count": "--count",
    "duration": "--duration",
    "seed": "--seed",
    "output": "--output",
    "vertical": "--vertical",
    "horizontal_y": "--horizontal-y",
    "format": "--format",
    "dt": "--dt",
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
    horizontal_y: str = typer.Option(
        None,
        "--horizontal-y",
        help="Adds a second horizontal component (y) matched to this target; 'same' for the "
        "--target spectrum. With --vertical: three-component records (SRP 3.7.1).",
    ),
    file_format: str = typer.Option("at2", "--format", help="Record files: at2 or csv."),
    dt: float = typer.Option(0.005, "--dt", help="Time step [s] (default 0.005 s)."),
    name: str = typer.Option(None, "--name", help="Suite name (default from the target)."),
    plot: Path = typer.Option(None, "--plot", help="Figure of the suite (.png, .svg or .pdf)."),
    as_json: bool = typer.Option(False, "--json", help="Write one JSON document to stdout."),
    quiet: bool = typer.Option(False, "--quiet", help="No progress bar."),
) -> None:
    """Generate a suite of spectrum-compatible records, with acceptance checks and a suite file."""
    from freestand.api.records import generate_suite

    check_file(plot, "--plot", _FIGURE_SUFFIXES)
    total = count * (1 + (vertical is not None) + (horizontal_y is not None))
    progress = _progress(quiet or as_json)
    arguments = dict(
        vertical=vertical, horizontal_y=horizontal_y, dt=dt, name=name, output=output,
        file_format=file_format,
    )  # fmt: skip
    if progress is not None:
        with progress:
            task = progress.add_task("matching records to the target", total=total)
            result = _call(generate_suite, _GENERATE_OPTIONS, target, count, duration, seed,
                           progress=lambda: progress.advance(task), **arguments)  # fmt: skip
    else:
        result = _call(generate_suite, _GENERATE_OPTIONS, target, count, duration, seed,
                       **arguments)  # fmt: skip
    if plot is not None:
        _save_figure(result.plot(), plot)
        result = result.with_files(plot)
    if as_json:
        _print_json(result.to_dict())
        if result.status != "accepted":
            raise SystemExit(1)  # a failed computation (main() returns the code)
        return
    _print_suite(result, output)


def _print_suite(result, output: Path) -> None:
    out = console()
    core = result.core
    for component in core.components:
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
    criteria = core.criteria
    if len(core.components) > 1:
        _print_independence(out, result.independence())
    out.print(
        escape(
            f"checks: spectrum within {criteria.lower_ratio:g}-{criteria.upper_ratio:g} x target "
            f"at {criteria.per_decade} frequencies per decade, "
            f"{criteria.lowest_frequency:g}-{criteria.highest_frequency:g} Hz; PGA within "
            f"{100 * criteria.peak_tolerance:g} % of the zero-period value; largest correlation "
            f"coefficient {core.max_correlation:.3f} (records "
            f"{' and '.join(core.max_correlation_pair)}, must be < {criteria.max_correlation:g})"
        )
    )
    for path in result.files:
        out.print(f"wrote {escape(path)}")
    if result.status == "accepted":
        out.print(f"[green]suite accepted[/]: {core.count} records in {escape(str(output))}")
        return
    for failure in result.failures:
        out.print(f"[red]failed:[/] {escape(failure)}")
    raise SystemExit(1)  # a failed computation (main() returns the code)


def _print_independence(out, independence: dict) -> None:
    """The SRP 3.7.1 table: each record's |correlation coefficient| of every pair of components."""
    from freestand.api.records import COMPONENT_WORDS

    def words(pair: str) -> str:
        return "-".join(COMPONENT_WORDS[c] for c in pair.split("-"))

    limit = independence["limit"]
    pairs = list(independence["records"][0]["pairs"])
    table = Table(title="independence of each record's components (SRP 3.7.1)")
    for column in ("record", *(f"|r| {words(p)} [-]" for p in pairs), "largest [-]", "status"):
        table.add_column(escape(column))
    for record in independence["records"]:
        table.add_row(
            f"{record['index']}",
            *(f"{record['pairs'][p]:.3f}" for p in pairs),
            f"{record['max']:.3f}",
            "ok" if record["max"] < limit else "[red]failed[/]",
        )
    out.print(table)
    worst = max(independence["records"], key=lambda r: r["max"])
    pair = words(max(worst["pairs"], key=worst["pairs"].get))
    out.print(
        f"largest correlation coefficient of two components of a record: "
        f"{independence['max']:.3f} (record {worst['index']}, {pair}; must be < {limit:g})"
    )


# ----------------------------------------------------------------------------- floor

_FLOOR_OPTIONS = {
    "frequency": "--frequency",
    "damping": "--damping",
    "vertical": "--vertical",
    "vertical_frequency": "--vertical-frequency",
    "output": "--output",
}


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
    from freestand.api.records import floor_motion

    if vertical_frequency is not None and vertical is None:
        raise FreestandError(
            "a vertical mode filters a vertical record; give it with --vertical FILE",
            source="--vertical-frequency",
        )
    check_file(plot, "--plot", _FIGURE_SUFFIXES)
    result = _call(
        floor_motion, _FLOOR_OPTIONS, record, frequency, damping, vertical=vertical,
        vertical_frequency=vertical_frequency, output=output, dt=dt, unit=unit, gravity=GRAVITY,
    )  # fmt: skip
    if plot is not None:
        _save_figure(result.plot(), plot)
    summary = result.to_dict()
    if as_json:
        _print_json(summary)
        return
    out = console()
    f, zeta = result.frequency, result.damping
    out.print(
        escape(
            f"{summary['record']}: ground peak {summary['ground_peak']:.4g} m/s^2; floor "
            f"({f:g} Hz, {100 * zeta:g} % damping) peak {summary['floor_peak']:.4g} m/s^2, "
            f"amplification {summary['amplification']:.3f}"
        )
    )
    out.print(
        escape(
            f"ground spectrum at {f:g} Hz: absolute acceleration "
            f"{summary['spectral_absolute_acceleration']:.4g} m/s^2, pseudo-acceleration "
            f"{summary['spectral_pseudo_acceleration']:.4g} m/s^2"
        )
    )
    if result.floor.vertical is not None:
        f_v = result.vertical_frequency
        how = "unchanged" if f_v is None else f"filtered by a {f_v:g} Hz, {100 * zeta:g} % mode"
        out.print(
            escape(
                f"vertical ({how}): ground peak {summary['ground_peak_vertical']:.4g} m/s^2, "
                f"floor peak {summary['floor_peak_vertical']:.4g} m/s^2"
            )
        )
    for path in result.outputs.values():
        out.print(f"wrote {escape(path)}")
    if plot is not None:
        out.print(f"wrote {escape(str(plot))}")


def register(app: typer.Typer) -> None:
    """Add ``freestand records ...`` to the main command."""
    app.add_typer(records_app, name="records")
