"""``freestand simulate``: time history of a stack under a recorded ground motion."""

from __future__ import annotations

import contextlib
import json
import math
from pathlib import Path

import numpy as np
import typer
from rich.console import Console
from rich.progress import BarColumn, Progress, TaskProgressColumn, TextColumn, TimeElapsedColumn
from rich.table import Table

from freestand.cli.common import console
from freestand.core.timehistory import METHODS, SupportMotion
from freestand.core.timehistory import simulate as simulate_stack
from freestand.errors import FreestandError
from freestand.io.model_file import load_model
from freestand.io.records import load_record, parse_spectral_target


def _number(value: float) -> float | None:
    return float(value) if math.isfinite(value) else None


def simulate(
    model_file: Path = typer.Argument(..., help="Model file (TOML)."),
    configuration: str = typer.Option(..., "--configuration", "-c", help="Configuration name."),
    record: Path = typer.Option(
        ..., "--record", help="Horizontal record (.AT2, CSV with units, or one column)."
    ),
    vertical: Path = typer.Option(
        None, "--vertical", help="Vertical record (positive up, as recorded)."
    ),
    dt: float = typer.Option(None, "--dt", help="Time step [s] of single-column records."),
    unit: str = typer.Option(
        None, "--unit", help="Unit of single-column records, e.g. g or m/s^2."
    ),
    scale: float = typer.Option(None, "--scale", help="Multiply the record(s) by this factor [-]."),
    peak: float = typer.Option(
        None,
        "--peak",
        help="Scale the horizontal record to this peak [m/s^2] (instead of --scale).",
    ),
    spectral: str = typer.Option(
        None,
        "--spectral",
        help="Scale the records so that the horizontal pseudo-acceleration at one "
        "frequency is A: 'A@F[,DAMPING]', e.g. '1.05g@2.5Hz,5%' (instead of --scale).",
    ),
    duration: float = typer.Option(
        None, "--duration", help="Simulated time [s] (default: the record)."
    ),
    step: float = typer.Option(
        None, "--step", help="Largest integration step [s] (default 1 ms; single block 0.02/p)."
    ),
    method: str = typer.Option(
        "auto", "--method", help="Solver: auto, general or single-block (one block only)."
    ),
    plot: Path = typer.Option(
        None, "--plot", help="Folder for the time-history figure (time-history.png, .svg)."
    ),
    animate: Path = typer.Option(
        None, "--animate", help="Write an animated GIF of the blocks moving (FILE.gif)."
    ),
    exaggerate: float = typer.Option(
        1.0, "--exaggerate", help="Draw rotations this many times larger in the GIF [-]."
    ),
    as_json: bool = typer.Option(False, "--json", help="Write one JSON document to stdout."),
) -> None:
    """Sliding, rocking, impacts and overturning of every block under a record."""
    model = load_model(model_file)
    stack = model.configuration(configuration)
    if sum(option is not None for option in (scale, peak, spectral)) > 1:
        raise FreestandError(
            "give one of --scale, --peak and --spectral, not several", source="--scale"
        )
    target = None if spectral is None else parse_spectral_target(spectral, gravity=model.gravity)
    if step is not None and not step > 0:
        raise FreestandError(f"{step} is not a positive step; e.g. --step 0.001", source="--step")
    if method not in METHODS or (method == "single-block" and len(stack.blocks) != 1):
        raise FreestandError(
            f"--method {method} does not apply to {configuration!r} ({len(stack.blocks)} blocks);"
            " use auto, general, or single-block for a one-block configuration",
            source="--method",
        )
    check_drawing_options(plot, animate, exaggerate)
    motion = load_record(record, dt=dt, unit=unit, gravity=model.gravity, vertical=vertical)
    if scale is not None:
        motion = motion.scaled(scale)
    if peak is not None:
        if not peak > 0:
            raise FreestandError(f"{peak} is not a positive peak", source="--peak")
        motion = motion.scaled_to_peak(peak)
    if target is not None:
        motion = motion.scaled_to_spectral(target.acceleration, target.frequency, target.damping)
    support = SupportMotion(
        motion.dt,
        np.asarray(motion.horizontal),
        None if motion.vertical is None else np.asarray(motion.vertical),
    )
    with _progress_bar(as_json) as progress:
        result = simulate_stack(
            stack, support, duration, method=method, max_step=step, gravity=model.gravity,
            progress=progress,
        )  # fmt: skip
    title = (
        f"{model.name} / {configuration}: {motion.name}, peak {motion.peak_horizontal:.2f} m/s^2"
    )
    written = draw(result, stack, support, plot, animate, exaggerate, title)
    kinds = sorted({event.kind for event in result.events})
    counts = {kind: sum(event.kind == kind for event in result.events) for kind in kinds}
    blocks = []
    for index, name in enumerate(result.block_names):
        blocks.append(
            {
                "name": name,
                "max_rotation": _number(result.max_rotation[index]),
                "max_slide": _number(result.max_slide[index]),
                "uplift": bool(result.uplift[index]),
                "free_flight": bool(result.free_flight[index]),
                "overturned": bool(result.overturned[index]),
                "overturn_time": _number(result.overturn_time[index]),
            }
        )
    if as_json:
        document = {
            "model": model.name,
            "configuration": configuration,
            "record": motion.name,
            "dt": motion.dt,
            "peak_horizontal": motion.peak_horizontal,
            "scale_factor": motion.metadata.get("scale_factor", 1.0),
            "status": result.status,
            "message": result.message,
            "method": result.diagnostics.method,
            "fallback": result.diagnostics.fallback,
            "blocks": blocks,
            "events": counts,
            "figures": [str(path) for path in written],
            "first_events": [
                {"time": event.time, "kind": event.kind, "interface": event.interface}
                for event in result.events[:50]
            ],
        }
        typer.echo(json.dumps(document, indent=2))
        return
    out = console()
    out.print(
        f"[bold]{model.name}[/] / {configuration}: {motion.name}, {motion.duration:.2f} s, "
        f"peak {motion.peak_horizontal:.2f} m/s^2; status {result.status}"
        + (f" ({result.message})" if result.message else "")
    )
    table = Table(title="Peak response")
    for header in (
        "block",
        "max rotation [rad]",
        "max slide [m]",
        "uplift",
        "free flight",
        "overturned",
    ):
        table.add_column(header)
    for block in blocks:
        overturned = f"at {block['overturn_time']:.3f} s" if block["overturned"] else "no"
        table.add_row(
            block["name"],
            f"{block['max_rotation']:.4g}" if block["max_rotation"] is not None else "-",
            f"{block['max_slide']:.4g}" if block["max_slide"] is not None else "-",
            "yes" if block["uplift"] else "no",
            "yes" if block["free_flight"] else "no",
            overturned,
        )
    out.print(table)
    out.print(
        f"Solver: {result.diagnostics.method}"
        + (f" (single-block path not used: {result.diagnostics.fallback})"
           if result.diagnostics.fallback else "")
    )  # fmt: skip
    out.print(
        "Events: " + (", ".join(f"{kind} x{count}" for kind, count in counts.items()) or "none")
    )
    for path in written:
        out.print(f"wrote {path}")


@contextlib.contextmanager
def _progress_bar(quiet: bool):
    """A rich progress bar of the simulated time on stderr (a terminal only, not with --json)."""
    console = Console(stderr=True)
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
    """FreestandError for a --plot that is a file, a non-GIF --animate, a factor <= 0."""
    if plot is not None and plot.exists() and not plot.is_dir():
        raise FreestandError(
            f"{str(plot)!r} is a file; give a folder for the figures, e.g. --plot figures",
            source="--plot",
        )
    if animate is not None and animate.suffix.lower() != ".gif":
        raise FreestandError(
            f"{str(animate)!r} is not a .gif file; the animation is written as an animated GIF, "
            f"e.g. --animate {animate.with_suffix('.gif')}",
            source="--animate",
        )
    if not (exaggerate > 0 and math.isfinite(exaggerate)):
        raise FreestandError(
            f"{exaggerate} is not a positive factor; e.g. --exaggerate 100 draws rotations "
            "100 times larger (1 draws them true)",
            source="--exaggerate",
        )


def draw(result, stack, support, plot, animate, exaggerate, title) -> list[Path]:
    """Write the figure into ``plot`` and the GIF to ``animate`` (each if given)."""
    written: list[Path] = []
    if plot is not None:
        from freestand.plot.timehistory import time_history_figures

        written += time_history_figures(
            result, plot, support_motion=support, stack=stack, title=title
        )
    if animate is not None:
        from freestand.plot.timehistory import animate_time_history

        written.append(
            animate_time_history(
                result, stack, animate, support_motion=support, exaggeration=exaggerate,
                title=title,
            )
        )  # fmt: skip
    return written


def register(app: typer.Typer) -> None:
    """Add the command of this module to ``app``."""
    app.command("simulate")(simulate)
