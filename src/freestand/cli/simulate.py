"""``freestand simulate``: time history of a stack under a recorded ground motion."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import typer
from rich.table import Table

from freestand.cli.common import console
from freestand.core.timehistory import METHODS, SupportMotion
from freestand.core.timehistory import simulate as simulate_stack
from freestand.errors import FreestandError
from freestand.io.model_file import load_model
from freestand.io.records import load_record


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
    duration: float = typer.Option(
        None, "--duration", help="Simulated time [s] (default: the record)."
    ),
    step: float = typer.Option(
        None, "--step", help="Largest integration step [s] (default 1 ms; single block 0.02/p)."
    ),
    method: str = typer.Option(
        "auto", "--method", help="Solver: auto, general or single-block (one block only)."
    ),
    as_json: bool = typer.Option(False, "--json", help="Write one JSON document to stdout."),
) -> None:
    """Sliding, rocking, impacts and overturning of every block under a record."""
    model = load_model(model_file)
    stack = model.configuration(configuration)
    if scale is not None and peak is not None:
        raise FreestandError("give either --scale or --peak, not both", source="--scale")
    if step is not None and not step > 0:
        raise FreestandError(f"{step} is not a positive step; e.g. --step 0.001", source="--step")
    if method not in METHODS or (method == "single-block" and len(stack.blocks) != 1):
        raise FreestandError(
            f"--method {method} does not apply to {configuration!r} ({len(stack.blocks)} blocks);"
            " use auto, general, or single-block for a one-block configuration",
            source="--method",
        )
    motion = load_record(record, dt=dt, unit=unit, gravity=model.gravity, vertical=vertical)
    if scale is not None:
        motion = motion.scaled(scale)
    if peak is not None:
        if not peak > 0:
            raise FreestandError(f"{peak} is not a positive peak", source="--peak")
        motion = motion.scaled_to_peak(peak)
    support = SupportMotion(
        motion.dt,
        np.asarray(motion.horizontal),
        None if motion.vertical is None else np.asarray(motion.vertical),
    )
    result = simulate_stack(
        stack, support, duration, method=method, max_step=step, gravity=model.gravity
    )
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
            "status": result.status,
            "message": result.message,
            "method": result.diagnostics.method,
            "fallback": result.diagnostics.fallback,
            "blocks": blocks,
            "events": counts,
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


def register(app: typer.Typer) -> None:
    """Add the command of this module to ``app``."""
    app.command("simulate")(simulate)
