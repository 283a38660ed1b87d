"""``freestand simulate``: time history of a stack under a recorded ground motion."""

from __future__ import annotations

import contextlib
import json
import math
from pathlib import Path

import typer
from rich.console import Console
from rich.markup import escape
from rich.progress import BarColumn, Progress, TaskProgressColumn, TextColumn, TimeElapsedColumn
from rich.table import Table

from freestand.api.simulation import check_options, support_motion
from freestand.api.simulation import simulate as simulate_model
from freestand.cli.common import (
    Staging,
    check_file,
    check_folder,
    console,
    load,
    number,
    staging,
    warn,
)
from freestand.errors import FreestandError
from freestand.io.records import check_record_values, load_record, parse_spectral_target


def simulate(
    model_file: Path = typer.Argument(..., help="Model file (TOML)."),
    configuration: list[str] = typer.Option(
        ...,
        "--configuration",
        "-c",
        help="Configuration name (repeatable: one simulation each; not with --plot/--animate).",
    ),
    record: Path = typer.Option(
        ..., "--record", help="Horizontal record (.AT2, CSV with units, or one column)."
    ),
    vertical: Path = typer.Option(
        None, "--vertical", help="Vertical record (positive up, as recorded)."
    ),
    dt: str = typer.Option(
        None, "--dt", help="Time step of single-column records, e.g. 0.005 [s] or '5 ms'."
    ),
    unit: str = typer.Option(
        None, "--unit", help="Unit of single-column records, e.g. g or m/s^2."
    ),
    scale: float = typer.Option(None, "--scale", help="Multiply the record(s) by this factor [-]."),
    peak: str = typer.Option(
        None,
        "--peak",
        help="Scale the horizontal record to this peak, e.g. 0.3g or '2.9 m/s^2' (bare "
        "numbers in m/s^2; instead of --scale).",
    ),
    spectral: str = typer.Option(
        None,
        "--spectral",
        help="Scale the records so that the horizontal pseudo-acceleration at one "
        "frequency is A: 'A@F[,DAMPING]', e.g. '1.05g@2.5Hz,5%' (instead of --scale).",
    ),
    duration: str = typer.Option(
        None, "--duration", help="Simulated time, e.g. 10 [s] or '10 s' (default: the record)."
    ),
    step: str = typer.Option(
        None,
        "--step",
        help="Largest integration step, e.g. 0.001 [s] or '1 ms' (default 1 ms; single block "
        "0.02/p).",
    ),
    method: str = typer.Option(
        "auto", "--method", help="Solver: auto, general or single-block (one block only)."
    ),
    plot: Path = typer.Option(
        None,
        "--plot",
        help="Folder to write the time-history figure into (time-history.png, .svg); "
        "created if missing.",
    ),
    animate: Path = typer.Option(
        None, "--animate", help="Write an animated GIF of the blocks moving (FILE.gif)."
    ),
    exaggerate: float = typer.Option(
        1.0, "--exaggerate", help="Draw rotations this many times larger in the GIF [-]."
    ),
    as_json: bool = typer.Option(False, "--json", help="Write one JSON document to stdout."),
) -> None:
    """Sliding, rocking, impacts and overturning of every block under a record.

    With several ``-c``, each configuration is simulated under the same record
    in turn (a table each; with ``--json`` a list of documents, one per
    configuration); the command exits with 1 if any simulation failed.
    """
    model = load(model_file)
    names = list(dict.fromkeys(configuration))
    stacks = [model.configuration(name) for name in names]
    for option, value in (("--plot", plot), ("--animate", animate)):
        if value is not None and len(stacks) > 1:
            raise FreestandError(
                f"{option} draws one simulation, and {len(stacks)} configurations are given "
                f"({', '.join(repr(name) for name in names)}); give one -c with {option}",
                source=option,
            )
    if sum(option is not None for option in (scale, peak, spectral)) > 1:
        raise FreestandError(
            "give one of --scale, --peak and --spectral, not several", source="--scale"
        )
    target = None if spectral is None else parse_spectral_target(spectral, gravity=model.gravity)
    peak_value = number(peak, "--peak", "acceleration", model.gravity)
    dt = number(dt, "--dt", "time")
    duration = number(duration, "--duration", "time")
    step = number(step, "--step", "time")
    if scale is not None and not (math.isfinite(scale) and scale != 0):
        raise FreestandError(
            f"{scale} is not a scale factor; give a finite, non-zero number, e.g. --scale 1.5",
            source="--scale",
        )
    if peak_value is not None and not peak_value > 0:
        raise FreestandError(
            f"{peak} is not a positive peak; e.g. --peak 0.3g or --peak 2.9", source="--peak"
        )
    if dt is not None and not (math.isfinite(dt) and dt > 0):
        raise FreestandError(
            f"{dt} is not a positive time step [s]; e.g. --dt 0.005", source="--dt"
        )
    check_drawing_options(plot, animate, exaggerate)
    motion = load_record(record, dt=dt, unit=unit, gravity=model.gravity, vertical=vertical)
    try:
        if scale is not None:
            motion = motion.scaled(scale)
        if peak_value is not None:
            motion = motion.scaled_to_peak(peak_value)
        if target is not None:
            motion = motion.scaled_to_spectral(
                target.acceleration, target.frequency, target.damping
            )
    except ValueError as error:  # an all-zero record cannot be scaled
        raise FreestandError(str(error), source=str(record)) from None
    check_record_values(motion.horizontal, str(record), model.gravity, "scaled horizontal")
    if motion.vertical is not None:
        check_record_values(motion.vertical, str(record), model.gravity, "scaled vertical")
    support = support_motion(motion)
    for stack in stacks:
        check_options(stack, support, duration, method, step)
    documents = []
    results = []
    for stack in stacks:
        result, document = _simulate_one(
            model, stack, motion, duration, method, step, plot, animate, exaggerate, as_json
        )
        results.append(result)
        documents.append(document)
    if as_json:
        typer.echo(json.dumps(documents[0] if len(documents) == 1 else documents, indent=2))
    _exit_if_failed(results)


def _simulate_one(model, stack, motion, duration, method, step, plot, animate, exaggerate,
                  as_json):  # fmt: skip
    """Simulate one configuration; print its tables unless ``as_json``.

    Returns (result, JSON document or None).
    """
    with _progress_bar(as_json) as progress:
        result = simulate_model(
            model, motion, duration, configuration=stack.name, method=method, max_step=step,
            progress=progress,
        )  # fmt: skip
    with staging() as stage:
        draw(result, plot, animate, exaggerate, stage)
        written = stage.commit()
    if as_json:
        document = result.to_dict()
        document["figures"] = [str(path) for path in written]
        return result, document
    blocks = result.blocks()
    out = console()
    out.print(
        f"[bold]{escape(model.name)}[/] / "
        + escape(
            f"{result.configuration}: {result.record}, {motion.duration:.2f} s, "
            f"peak {result.peak_horizontal:.2f} m/s^2; status {result.status}"
            + (f" ({result.message})" if result.message else "")
        )
    )
    table = Table(title="Peak response (blocks bottom to top)")
    for header in (
        "block",
        "max rotation [rad]",
        "max slide [m]",
        "uplift",
        "free flight",
        "overturned",
    ):
        table.add_column(escape(header))
    for block in blocks:
        overturned = f"at {block['overturn_time']:.3f} s" if block["overturned"] else "no"
        table.add_row(
            escape(block["name"]),
            f"{block['max_rotation']:.4g}" if block["max_rotation"] is not None else "-",
            f"{block['max_slide']:.4g}" if block["max_slide"] is not None else "-",
            "yes" if block["uplift"] else "no",
            "yes" if block["free_flight"] else "no",
            overturned,
        )
    out.print(table)
    out.print(escape(
        f"Solver: {result.diagnostics.method}"
        + (f" (single-block path not used: {result.diagnostics.fallback})"
           if result.diagnostics.fallback else "")
    ))  # fmt: skip
    counts = result.event_counts()
    out.print(
        "Events: " + (", ".join(f"{kind} x{count}" for kind, count in counts.items()) or "none")
    )
    for path in written:
        out.print(escape(f"wrote {path}"), highlight=False)
    return result, None


def _exit_if_failed(results) -> None:
    """A simulation that failed ends the command with exit status 1 (and says why)."""
    failed = [result for result in results if result.status == "failed"]
    for result in failed:
        warn(
            f"the simulation of {result.configuration!r} failed"
            + (f": {result.message}" if result.message else "")
            + "; the results above stop where it failed (try a smaller --step)"
        )
    if failed:
        raise typer.Exit(1)


@contextlib.contextmanager
def _progress_bar(quiet: bool):
    """A rich progress bar of the simulated time on stderr (a terminal only, not with --json)."""
    console = Console(emoji=False, stderr=True)
    if quiet or not console.is_terminal:
        yield None
        return
    with Progress(
        TextColumn("simulating"),
        BarColumn(),
        TaskProgressColumn(),
        TimeElapsedColumn(),
        console=console,
        transient=True,
    ) as bar:
        task = bar.add_task("simulating", total=1.0)
        yield lambda fraction: bar.update(task, completed=fraction)


def check_drawing_options(plot: Path | None, animate: Path | None, exaggerate: float) -> None:
    """FreestandError for an unusable --plot folder or --animate file, a factor <= 0."""
    check_folder(plot, "--plot")
    check_file(animate, "--animate", (".gif",))
    if not (exaggerate > 0 and math.isfinite(exaggerate)):
        raise FreestandError(
            f"{exaggerate} is not a positive factor; e.g. --exaggerate 100 draws rotations "
            "100 times larger (1 draws them true)",
            source="--exaggerate",
        )


def draw(result, plot, animate, exaggerate, stage: Staging) -> None:
    """Write the figure into ``plot`` and the GIF to ``animate`` (each if given), staged."""
    if plot is not None:
        from freestand.plot.figures import save_figure

        save_figure(result.plot(), stage.folder(plot) / "time-history")
    if animate is not None:
        result.animate(stage.file(animate), exaggeration=exaggerate)


def register(app: typer.Typer) -> None:
    """Add the command of this module to ``app``."""
    app.command("simulate")(simulate)
