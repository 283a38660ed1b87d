"""``freestand map`` and ``freestand sample``."""

from __future__ import annotations

import contextlib
import csv
import json
from dataclasses import replace
from pathlib import Path

import numpy as np
import typer
from rich.console import Console
from rich.markup import escape
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn
from rich.table import Table

from freestand.cli.common import check_file, check_folder, load, staging, warn
from freestand.core.contact.batch import MOTIONS, STATUS_NAMES
from freestand.core.sweeps.mode_map import ModeMap, mode_map, model_points, point_label
from freestand.core.sweeps.sampling import INTERVALS, monte_carlo
from freestand.errors import FreestandError
from freestand.io.parameters import check_parameters, parse_axis, parse_variation

_SENSES = {"+": (1,), "-": (-1,), "both": (1, -1)}

#: Most samples per case of ``sample``, and most solutions (samples x cases) of one run:
#: beyond, a run lasts many minutes and its --samples file many gigabytes.
MAX_SAMPLES = 10_000_000
MAX_SOLVES = 20_000_000
#: Most grid nodes of one ``map`` run (nodes per axis squared, times senses and
#: configurations): about 1.5 GB of results and a minute of work.
MAX_MAP_NODES = 10_000_000


def _senses(value: str) -> tuple[int, ...]:
    if value not in _SENSES:
        raise FreestandError(f"{value!r} is not a sense; use +, - or both", source="option --sense")
    return _SENSES[value]


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
    model = load(model_file)
    n = nodes
    stacks = (
        [model.configuration(name) for name in dict.fromkeys(configuration)]
        if configuration
        else [model.configurations[0]]
    )
    if excitation:
        matches = [e for e in model.excitations if e.name == excitation]
        if not matches:
            known = ", ".join(repr(e.name) for e in model.excitations)
            raise FreestandError(
                f"no excitation named {excitation!r}; choose one of {known}",
                source="option --excitation",
            )
        nominal = matches[0]
    else:
        nominal = model.excitations[0]
    if not 2 <= n <= 5000:
        raise FreestandError(
            f"{n} nodes per axis is out of range; give 2 to 5000, e.g. --nodes 400",
            source="--nodes",
        )
    x_axis = parse_axis(x, "--x", model.gravity)
    y_axis = parse_axis(y, "--y", model.gravity)
    if x_axis.parameter.name == y_axis.parameter.name:
        raise FreestandError(
            f"both axes vary {x_axis.parameter.label!r}; choose two different parameters, "
            "e.g. --x horizontal=0:12 --y vertical=-3:10",
            source="--x/--y",
        )
    check_parameters([(x_axis.parameter, x), (y_axis.parameter, y)], stacks, "--x/--y")
    senses = _senses(sense)
    total = n * n * len(senses) * len(stacks)
    if total > MAX_MAP_NODES:
        largest = int((MAX_MAP_NODES / (len(senses) * len(stacks))) ** 0.5)
        raise FreestandError(
            f"{n} x {n} nodes x {len(senses) * len(stacks)} map(s) is {total:,} nodes, beyond "
            f"the {MAX_MAP_NODES:,} of one run (each takes about 150 bytes and a few "
            f"microseconds); give --nodes {largest} or fewer, or --sense + / -",
            source="--nodes",
        )
    check_folder(plot, "--plot")
    check_file(csv_path, "--csv", (".csv",))
    maps = []
    with _progress(n * n * len(senses) * len(stacks), "mapping", as_json) as advance:
        for stack in stacks:
            for s in senses:
                maps.append(mode_map(stack, x_axis, y_axis, nominal, s, n, model.gravity, advance))
    for m in maps:
        invalid = m.fractions().get("invalid input", 0.0)
        if invalid:
            warn(
                f"{m.configuration}, sense {_sense_word(m.sense)}: {100 * invalid:.1f} % of the "
                "nodes make no model (a mass or inertia <= 0, a negative friction coefficient, "
                "contacts out of order or a centre below its contacts) and are shown as "
                "'invalid input'; narrow the axis ranges"
            )
    by_name = {stack.name: stack for stack in stacks}
    points = []
    for m in maps:
        stack = by_name[m.configuration]
        points.append(
            [
                (name, px, py, point_label(m, stack, px, py, nominal, model.gravity))
                for name, px, py in model_points(m, stack, model.excitations, nominal)
            ]
        )
    written: list[Path] = []
    if plot or csv_path:
        with staging() as stage:
            if plot:
                from freestand.plot.maps import plot_mode_maps

                folder = stage.folder(plot)
                for suffix in (".png", ".svg"):
                    plot_mode_maps(
                        maps, folder / f"map{suffix}", points, title=f"{model.name}: initial motion"
                    )
            if csv_path:
                _map_csv(maps, stage.file(csv_path))
            written = stage.commit()
    left_out = sorted(
        {e.name for e in model.excitations}
        - {name.split(" (a_v")[0] for pts in points for name, *_ in pts}
    )
    if as_json:
        document = {
            "model": model.name,
            "configurations": [stack.name for stack in stacks],
            "configuration": stacks[0].name,
            "excitation": nominal.name,
            "x": {"parameter": x_axis.parameter.label, "start": x_axis.start, "stop": x_axis.stop},
            "y": {"parameter": y_axis.parameter.label, "start": y_axis.start, "stop": y_axis.stop},
            "nodes": n,
            "maps": [
                {
                    "configuration": m.configuration,
                    "sense": _sense_word(m.sense),
                    "regions": {label: float(f) for label, f in m.fractions().items()},
                    "ambiguous_nodes": int(m.ambiguous.sum()),
                    "points": [
                        {"excitation": name, "x": px, "y": py, "region": label}
                        for name, px, py, label in pts
                    ],
                }
                for m, pts in zip(maps, points, strict=True)
            ],
            "points_not_shown": left_out,
            "files": [str(path) for path in written],
        }
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
    model = load(model_file)
    stacks = (
        [model.configuration(name) for name in dict.fromkeys(configuration)]
        if configuration
        else list(model.configurations)
    )
    if excitation:
        known = {e.name: e for e in model.excitations}
        for name in excitation:
            if name not in known:
                raise FreestandError(
                    f"no excitation named {name!r}; choose one of "
                    + ", ".join(repr(e) for e in known),
                    source="option --excitation",
                )
        excitations = [known[name] for name in excitation]
    else:
        excitations = list(model.excitations)
    excitations = [
        replace(
            e,
            name=e.name if len(e.verticals()) == 1 else f"{e.name} (a_v {word})",
            vertical=vertical,
            vertical_senses="given",
        )
        for e in excitations
        for vertical, word in zip(e.verticals(), ("down", "up"), strict=False)
    ]
    if not 0 <= seed < 2**63:
        raise FreestandError(
            f"{seed} is not a seed; give a whole number >= 0, e.g. --seed 1",
            source="option --seed",
        )
    if not 1 <= n <= MAX_SAMPLES:
        raise FreestandError(
            f"{n} samples per case is out of range; give 1 to {MAX_SAMPLES:,}, e.g. --n 10000",
            source="option --n",
        )
    if not 0 < confidence < 1:
        raise FreestandError(
            f"{confidence} is not a confidence level; give a number between 0 and 1, e.g. 0.95",
            source="option --confidence",
        )
    if interval not in INTERVALS:
        raise FreestandError(
            f"{interval!r} is not an interval; use {' or '.join(INTERVALS)}",
            source="option --interval",
        )
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
    variations = [parse_variation(text, "--vary", model.gravity) for text in vary or []]
    check_parameters(
        [(v.parameter, text) for v, text in zip(variations, vary or [], strict=True)],
        stacks,
        "--vary",
    )
    senses = _senses(sense)
    total = n * len(stacks) * len(excitations) * len(senses)
    if total > MAX_SOLVES:
        raise FreestandError(
            f"{n:,} samples x {total // n} cases is {total:,} solutions, beyond the "
            f"{MAX_SOLVES:,} of one run; give a smaller --n, or fewer cases with -c, -e or "
            "--sense",
            source="option --n",
        )
    with _progress(total, "sampling", as_json) as advance:
        sweep = monte_carlo(
            stacks,
            excitations,
            variations,
            n,
            seed,
            model.gravity,
            senses,
            confidence,
            interval,
            advance,
        )
    written: list[Path] = []
    if samples_path:
        with staging() as stage:
            _write_samples(sweep, stage.file(samples_path))
            written = stage.commit()
    if as_json:
        typer.echo(json.dumps(_sweep_document(model.name, sweep), indent=2))
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


def _sweep_document(model_name: str, sweep) -> dict:
    def probability(item):
        return {
            "outcome": item.outcome,
            "block": item.block,
            "count": item.count,
            "total": item.total,
            "probability": item.probability,
            "interval": [item.low, item.high],
        }

    return {
        "model": model_name,
        "seed": sweep.seed,
        "confidence": sweep.confidence,
        "interval": sweep.interval,
        "variations": [v.describe() for v in sweep.variations],
        "cases": [
            {
                "configuration": case.configuration,
                "excitation": case.excitation,
                "sense": _sense_word(case.sense),
                "samples": case.samples,
                "invalid": case.invalid,
                "motions": [probability(item) for item in case.motions],
                "states": [probability(item) for item in case.states],
                "statuses": [probability(item) for item in case.statuses],
            }
            for case in sweep.cases
        ],
    }


def _sample_columns(sweep) -> dict[str, np.ndarray]:
    columns: dict[str, list] = {}
    n = len(sweep.samples[0]) if sweep.samples else sweep.cases[0].samples
    for case in sweep.cases:
        result = case.result
        columns.setdefault("configuration", []).append(np.full(n, case.configuration, dtype=object))
        columns.setdefault("excitation", []).append(np.full(n, case.excitation, dtype=object))
        columns.setdefault("sense", []).append(np.full(n, _sense_word(case.sense), dtype=object))
        columns.setdefault("sample", []).append(np.arange(n))
        for variation, values in zip(sweep.variations, sweep.samples, strict=True):
            columns.setdefault(variation.parameter.label, []).append(values)
        columns.setdefault("status", []).append(np.array(STATUS_NAMES, dtype=object)[result.status])
        motion_names = np.array([m.value for m in MOTIONS] + [""], dtype=object)
        for b, name in enumerate(result.names):
            columns.setdefault(f"{name}.motion", []).append(motion_names[result.motion[:, b]])
            columns.setdefault(f"{name}.slide_direction", []).append(result.slide_direction[:, b])
    return {key: np.concatenate(parts) for key, parts in columns.items()}


def _write_samples(sweep, path: Path) -> None:
    columns = _sample_columns(sweep)
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
