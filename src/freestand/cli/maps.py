"""``freestand map`` and ``freestand sample``."""

from __future__ import annotations

import contextlib
import csv
import json
from pathlib import Path

import numpy as np
import typer
from rich.console import Console
from rich.markup import escape
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn
from rich.table import Table

from freestand.api.maps import parse_sense
from freestand.cli.common import check_file, check_folder, load, staging, warn
from freestand.core.contact.batch import MOTIONS, STATUS_NAMES
from freestand.core.sweeps.mode_map import ModeMap
from freestand.errors import FreestandError


@contextlib.contextmanager
def _progress(total: int, description: str, quiet: bool):
    """A rich progress bar on stderr; yields the callback that advances it."""
    if quiet:
        yield None
        return
    console = Console(emoji=False, stderr=True)
    if not console.is_terminal and total >= 1_000_000:
        console.print(f"{description}: {total:,} cases ...", highlight=False)
    with Progress(
        TextColumn("{task.description}"),
        BarColumn(),
        MofNCompleteColumn(),
        TimeElapsedColumn(),
        console=console,
        transient=True,
        disable=not console.is_terminal,
    ) as bar:
        task = bar.add_task(description, total=total)
        yield lambda done: bar.advance(task, done)


def _sense_word(sense: int) -> str:
    return "+" if sense > 0 else "-"


def _map_csv(maps: list[ModeMap], path: Path) -> None:
    names = maps[0].result.names
    with path.open("w", newline="") as handle:
        writer = csv.writer(handle)
        header = ["sense", maps[0].x.parameter.label, maps[0].y.parameter.label, "status"]
        header += ["region", "admissible_states"]
        for name in names:
            header += [f"{name}.motion", f"{name}.pivot", f"{name}.slide_direction"]
        writer.writerow(header)
        for m in maps:
            result = m.result
            grid_x, grid_y = np.meshgrid(m.x_values, m.y_values)
            codes = m.codes.ravel()
            for k in range(result.count):
                row = [
                    _sense_word(m.sense),
                    f"{grid_x.flat[k]:.6g}",
                    f"{grid_y.flat[k]:.6g}",
                    STATUS_NAMES[result.status[k]],
                    m.labels[int(codes[k])],
                    int(result.admissible_count[k]),
                ]
                for b in range(len(names)):
                    motion = int(result.motion[k, b])
                    row += [
                        MOTIONS[motion].value if motion >= 0 else "",
                        {-1: "left", 1: "right"}.get(int(result.pivot[k, b]), ""),
                        int(result.slide_direction[k, b]),
                    ]
                writer.writerow(row)


def map_command(
    model_file: Path = typer.Argument(..., help="Model file (TOML).", show_default=False),
    configuration: list[str] = typer.Option(
        None,
        "--configuration",
        "-c",
        help="Configuration to map (repeatable; default: the first).",
    ),
    x: str = typer.Option(
        "horizontal=0:12", "--x", help="x axis NAME=START:STOP, e.g. horizontal=0:12."
    ),
    y: str = typer.Option(
        "vertical=-3:10",
        "--y",
        help="y axis NAME=START:STOP, e.g. friction.static=0.1:0.5 (vertical: positive "
        "downward, negative upward).",
    ),
    nodes: int = typer.Option(
        400, "--nodes", "--n", help="Grid nodes per axis, 2 to 5000 (--n is the older name)."
    ),
    excitation: str = typer.Option(
        None,
        "--excitation",
        "-e",
        help="Excitation for the components not on an axis (default: the first).",
    ),
    sense: str = typer.Option("both", "--sense", help="Sense of the inertial force: +, - or both."),
    plot: Path = typer.Option(
        None,
        "--plot",
        help="Folder to write the map figure into (map.png, map.svg); created if missing.",
    ),
    csv_path: Path = typer.Option(None, "--csv", help="Write every grid node to a CSV file."),
    as_json: bool = typer.Option(False, "--json", help="Write a JSON summary to stdout."),
) -> None:
    """Mode map: the initial motion of every block over a grid of two parameters."""
    from freestand.api.maps import mode_map as map_model

    model = load(model_file)
    check_folder(plot, "--plot")
    check_file(csv_path, "--csv", (".csv",))
    senses = parse_sense(sense)
    count = len(set(configuration)) if configuration else 1
    with _progress(nodes * nodes * len(senses) * count, "mapping", as_json) as advance:
        result = map_model(
            model, x, y, configurations=configuration or None, excitation=excitation,
            sense=sense, nodes=nodes, progress=advance,
        )  # fmt: skip
    maps, points, n = list(result.maps), result.points, nodes
    stacks, nominal, x_axis, y_axis = (result.configurations, result.excitation, result.x, result.y)
    for k, m in enumerate(maps):
        invalid = result.invalid_share(k)
        if invalid:
            warn(
                f"{m.configuration}, sense {_sense_word(m.sense)}: {100 * invalid:.1f} % of the "
                "nodes make no model (a mass or inertia <= 0, a negative friction coefficient, "
                "contacts out of order or a centre below its contacts) and are shown as "
                "'invalid input'; narrow the axis ranges"
            )
    written: list[Path] = []
    if plot or csv_path:
        with staging() as stage:
            if plot:
                folder = stage.folder(plot)
                figure = result.plot()
                for suffix in (".png", ".svg"):
                    figure.savefig(folder / f"map{suffix}", dpi=120)
            if csv_path:
                _map_csv(maps, stage.file(csv_path))
            written = stage.commit()
    left_out = result.points_not_shown
    if as_json:
        document = result.to_dict()
        document["files"] = [str(path) for path in written]
        typer.echo(json.dumps(document, indent=2))
        return
    console = Console(emoji=False)
    console.print(
        f"[bold]{escape(model.name)}[/] / "
        + escape(
            f"{', '.join(stack.name for stack in stacks)}: {n} x {n} nodes, "
            f"{x_axis.title} {x_axis.start:g}..{x_axis.stop:g}, "
            f"{y_axis.title} {y_axis.start:g}..{y_axis.stop:g} "
            f"(other inputs from excitation {nominal.name!r})"
        )
    )
    for m, pts in zip(maps, points, strict=True):
        table = Table(
            title=escape(f"{m.configuration}, sense {_sense_word(m.sense)}: share of the map")
        )
        table.add_column("region")
        table.add_column(escape("share [%]"), justify="right")
        for label, share in m.fractions().items():
            table.add_row(escape(label), f"{100 * share:.1f}")
        console.print(table)
        if m.ambiguous.any():
            console.print(
                f"[yellow]{int(m.ambiguous.sum())} node(s) ambiguous[/] (several admissible "
                "states; the rule's choice is shown)"
            )
        for name, px, py, label in pts:
            console.print(escape(f"  {name} ({px:g}, {py:g}): {label}"), highlight=False)
    if left_out:
        console.print(
            escape(
                f"not shown: {', '.join(left_out)} (its components off the axes differ from "
                f"{nominal.name!r}'s, or it lies outside the map; choose it with -e to map it)"
            ),
            highlight=False,
        )
    for path in written:
        console.print(escape(f"wrote {path}"), highlight=False)


def sample_command(
    model_file: Path = typer.Argument(..., help="Model file (TOML).", show_default=False),
    vary: list[str] = typer.Option(
        None,
        "--vary",
        help='Uncertain input NAME=DISTRIBUTION, e.g. "friction.static=uniform(0.15,0.35)" '
        "(repeatable; += adds to, *= scales the model's value).",
    ),
    n: int = typer.Option(100000, "--n", help="Samples per case."),
    seed: int = typer.Option(0, "--seed", help="Random seed."),
    configuration: list[str] = typer.Option(
        None, "--configuration", "-c", help="Only this configuration (repeatable)."
    ),
    excitation: list[str] = typer.Option(
        None, "--excitation", "-e", help="Only this excitation (repeatable)."
    ),
    sense: str = typer.Option("both", "--sense", help="Sense of the inertial force: +, - or both."),
    confidence: float = typer.Option(0.95, "--confidence", help="Confidence level."),
    interval: str = typer.Option(
        "wilson", "--interval", help="Confidence interval: wilson or clopper-pearson."
    ),
    samples_path: Path = typer.Option(
        None, "--samples", help="Write every sample and its motions (.csv, or .parquet)."
    ),
    as_json: bool = typer.Option(False, "--json", help="Write one JSON document to stdout."),
) -> None:
    """Monte Carlo over uncertain inputs: probability of each initial motion."""
    from freestand.api.maps import sample as sample_model

    model = load(model_file)
    check_file(samples_path, "option --samples", (".csv", ".parquet"))
    if samples_path is not None and samples_path.suffix.lower() == ".parquet":
        try:
            import pyarrow  # noqa: F401
        except ImportError:
            raise FreestandError(
                "writing Parquet needs pyarrow, which is not installed; install it or "
                f"write a .csv file instead, e.g. --samples {samples_path.with_suffix('.csv')}",
                source="option --samples",
            ) from None
    configurations = len(set(configuration)) if configuration else len(model.configurations)
    chosen = [e for e in model.excitations if not excitation or e.name in excitation]
    cases = configurations * sum(len(e.verticals()) for e in chosen) * len(parse_sense(sense))
    with _progress(n * cases, "sampling", as_json) as advance:
        result = sample_model(
            model, vary or [], n, seed, configurations=configuration or None,
            excitations=excitation or None, sense=sense, confidence=confidence,
            interval=interval, progress=advance,
        )  # fmt: skip
    sweep, variations = result.sweep, result.sweep.variations
    written: list[Path] = []
    if samples_path:
        with staging() as stage:
            _write_samples(result.sample_columns(), stage.file(samples_path))
            written = stage.commit()
    if as_json:
        typer.echo(result.to_json())
        return
    console = Console(emoji=False)
    if not console.is_terminal:
        console = Console(emoji=False, width=120)
    console.print(
        f"[bold]{escape(model.name)}[/]: {n} samples per case, seed {seed}, "
        f"{100 * confidence:g} % {interval} intervals",
        highlight=False,
    )
    for variation in variations:
        console.print(f"  {escape(variation.describe())}", highlight=False)
    table = Table(title="Probability of each initial motion (blocks bottom to top)")
    for header in ("configuration", "excitation", "sense", "block", "motion"):
        table.add_column(header)
    table.add_column(escape("probability [-]"), justify="right")
    table.add_column(escape("interval [-]"), justify="right")
    for case in sweep.cases:
        for item in case.motions:
            table.add_row(
                escape(case.configuration),
                escape(case.excitation),
                _sense_word(case.sense),
                escape(item.block),
                escape(item.outcome),
                f"{item.probability:.4f}",
                f"{item.low:.4f} - {item.high:.4f}",
            )
    console.print(table)
    for case in sweep.cases:
        flags = [f"{s.outcome} {s.probability:.4f}" for s in case.statuses if s.outcome != "unique"]
        if case.invalid:
            flags.append(f"{case.invalid} invalid sample(s) left out")
        if flags:
            console.print(
                "[yellow]"
                + escape(f"{case.configuration} / {case.excitation} / {_sense_word(case.sense)}:")
                + "[/] "
                + escape(", ".join(flags))
            )
    for path in written:
        console.print(escape(f"wrote {path}"), highlight=False)


def _write_samples(columns: dict[str, np.ndarray], path: Path) -> None:
    if path.suffix.lower() == ".parquet":
        try:
            import pyarrow as pa
            import pyarrow.parquet as pq
        except ImportError:
            raise FreestandError(
                "writing Parquet needs pyarrow, which is not installed; install it or "
                "write a .csv file instead",
                source="option --samples",
            ) from None
        pq.write_table(pa.table({k: list(v) for k, v in columns.items()}), path)
        return
    keys = list(columns)
    with path.open("w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(keys)
        writer.writerows(zip(*(columns[k] for k in keys), strict=True))


def register(app: typer.Typer) -> None:
    """Add the commands of this module to ``app``."""
    app.command("map")(map_command)
    app.command("sample")(sample_command)
