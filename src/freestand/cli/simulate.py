"""``freestand simulate``: time history of a stack or a 3-D body under a recorded ground motion."""

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

from freestand.api.body_simulation import BodySimulationResult, check_body_options
from freestand.api.simulation import check_options, check_steps, support_motion
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
from freestand.cli.record_options import (
    ANGLE,
    DT,
    PEAK,
    RECORD_Y,
    SCALE,
    SPECTRAL,
    UNIT,
    VERTICAL,
    check_angle,
    read_record,
)
from freestand.core.model import Stack
from freestand.errors import FreestandError


def simulate(
    model_file: Path = typer.Argument(..., help="Model file (TOML)."),
    configuration: list[str] = typer.Option(
        ...,
        "--configuration",
        "-c",
        help="Configuration name (repeatable: one simulation each; not with --plot/--animate).",
    ),
    record: Path = typer.Option(
        ..., "--record", help="Horizontal record, along x (.AT2, CSV with units, or one column)."
    ),
    record_y: Path = RECORD_Y,
    vertical: Path = VERTICAL,
    angle: float = ANGLE,
    dt: str = DT,
    unit: str = UNIT,
    scale: float = SCALE,
    peak: str = PEAK,
    spectral: str = SPECTRAL,
    duration: str = typer.Option(
        None, "--duration", help="Simulated time, e.g. 10 [s] or '10 s' (default: the record)."
    ),
    step: str = typer.Option(
        None,
        "--step",
        help="Largest integration step, e.g. 0.001 [s] or '1 ms' (default 1 ms; single block "
        "0.02/p; 3-D body 0.05/p).",
    ),
    method: str = typer.Option(
        "auto", "--method", help="Solver of planar stacks: auto, general or single-block."
    ),
    plot: Path = typer.Option(
        None,
        "--plot",
        help="Folder to write the figures into (time-history.png, .svg; a 3-D configuration "
        "also plan-view.png, .svg); created if missing.",
    ),
    animate: Path = typer.Option(
        None, "--animate", help="Write an animated GIF of the blocks or the body moving (FILE.gif)."
    ),
    exaggerate: float = typer.Option(
        1.0,
        "--exaggerate",
        help="Draw rotations (a 3-D body's tilt) this many times larger in the GIF [-].",
    ),
    as_json: bool = typer.Option(False, "--json", help="Write one JSON document to stdout."),
) -> None:
    """Sliding, rocking, impacts and overturning of every block (or a 3-D body) under a record.

    A 3-D configuration (a box or a cylinder) takes the three components:
    --record (x), --record-y and --vertical, the horizontal pair turned by
    --angle. With several ``-c``, each configuration is simulated under the
    same record in turn (a table each; with ``--json`` a list of documents,
    one per configuration); the command exits with 1 if any simulation failed.
    """
    model = load(model_file)
    names = list(dict.fromkeys(configuration))
    configurations = [_configuration(model, name) for name in names]
    for option, value in (("--plot", plot), ("--animate", animate)):
        if value is not None and len(configurations) > 1:
            raise FreestandError(
                f"{option} draws one simulation, and {len(configurations)} configurations are "
                f"given ({', '.join(repr(name) for name in names)}); give one -c with {option}",
                source=option,
            )
    planar = [item.name for item in configurations if isinstance(item, Stack)]
    for option, value in (("--record-y", record_y), ("--angle", angle)):
        if value is not None and planar:
            raise FreestandError(
                f"{option} is for 3-D configurations (a box or a cylinder under two horizontal "
                f"components), and {', '.join(repr(name) for name in planar)} "
                f"{'is' if len(planar) == 1 else 'are'} planar (the x component in its plane "
                f"alone); leave {option} out, or choose a 3-D configuration"
                + _choice(model.body_configurations),
                source=option,
            )
    check_angle(angle)
    duration = number(duration, "--duration", "time")
    step = number(step, "--step", "time")
    check_drawing_options(plot, animate, exaggerate)
    motion = read_record(
        model, record, record_y=record_y, vertical=vertical, dt=dt, unit=unit, scale=scale,
        peak=peak, spectral=spectral,
    )  # fmt: skip
    for item in configurations:
        if isinstance(item, Stack):
            check_options(item, support_motion(motion), duration, method, step)
        else:
            check_body_options(item, method, None)
            check_steps(motion.duration, duration, step)
    documents = []
    results = []
    for item in configurations:
        result, document = _simulate_one(
            model, item.name, motion, duration, method, step, angle or 0.0, plot, animate,
            exaggerate, as_json,
        )  # fmt: skip
        results.append(result)
        documents.append(document)
    if as_json:
        typer.echo(json.dumps(documents[0] if len(documents) == 1 else documents, indent=2))
    _exit_if_failed(results)


def _configuration(model, name: str):
    """The planar stack or the 3-D configuration called ``name`` (an error lists the names)."""
    for body in model.body_configurations:
        if body.name == name:
            return body
    return model.configuration(name)


def _choice(bodies) -> str:
    if not bodies:
        return " (this model has none)"
    return " (" + ", ".join(repr(body.name) for body in bodies) + ")"


def _simulate_one(model, name, motion, duration, method, step, angle, plot, animate, exaggerate,
                  as_json):  # fmt: skip
    """Simulate one configuration; print its tables unless ``as_json``.

    Returns (result, JSON document or None).
    """
    with _progress_bar(as_json) as progress:
        result = simulate_model(
            model, motion, duration, configuration=name, method=method, max_step=step,
            progress=progress, angle=angle,
        )  # fmt: skip
    with staging() as stage:
        draw(result, plot, animate, exaggerate, stage)
        written = stage.commit()
    if as_json:
        document = result.to_dict()
        document["figures"] = [str(path) for path in written]
        return result, document
    three_d = isinstance(result, BodySimulationResult)
    out = console()
    turned = f", turned {angle:g} deg" if angle else ""
    out.print(
        f"[bold]{escape(model.name)}[/] / "
        + escape(
            f"{result.configuration}: {result.record}{turned}, {motion.duration:.2f} s, "
            f"peak {result.peak_horizontal:.2f} m/s^2; status {result.status}"
            + (f" ({result.message})" if result.message else "")
        )
    )
    out.print(_peak_table(result.blocks(), three_d))
    if three_d:
        counts = result.diagnostics
        out.print(escape(
            f"Engine: 3-D, exact rigid contact ({counts['steps']} steps, {counts['impacts']} "
            f"impacts, {counts['remedies']} stretches of time stepping where no contact mode"
            " lasts)"
        ))  # fmt: skip
    else:
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


def _peak_table(blocks: list[dict], three_d: bool) -> Table:
    """The peaks of every block (a 3-D body: its tilt, slide and twist)."""
    table = Table(title="Peak response" + ("" if three_d else " (blocks bottom to top)"))
    rotation = "max tilt [rad]" if three_d else "max rotation [rad]"
    headers = ["block", rotation, "max slide [m]"] + (["max twist [rad]"] if three_d else [])
    for header in (*headers, "uplift", "free flight", "overturned"):
        table.add_column(escape(header))
    keys = ("max_rotation", "max_slide") + (("max_twist",) if three_d else ())
    for block in blocks:
        overturned = f"at {block['overturn_time']:.3f} s" if block["overturned"] else "no"
        table.add_row(
            escape(block["name"]),
            *(f"{block[key]:.4g}" if block[key] is not None else "-" for key in keys),
            "yes" if block["uplift"] else "no",
            "yes" if block["free_flight"] else "no",
            overturned,
        )
    return table


def _exit_if_failed(results) -> None:
    """A simulation that failed ends the command with exit status 1 (and says why)."""
    failed = [result for result in results if result.status == "failed"]
    for result in failed:
        hint = "" if isinstance(result, BodySimulationResult) else " (try a smaller --step)"
        warn(
            f"the simulation of {result.configuration!r} failed"
            + (f": {result.message}" if result.message else "")
            + f"; the results above stop where it failed{hint}"
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

        folder = stage.folder(plot)
        save_figure(result.plot(), folder / "time-history")
        if isinstance(result, BodySimulationResult):
            save_figure(result.plot(view="plan"), folder / "plan-view")
    if animate is not None:
        result.animate(stage.file(animate), exaggeration=exaggerate)


def register(app: typer.Typer) -> None:
    """Add the command of this module to ``app``."""
    app.command("simulate")(simulate)
