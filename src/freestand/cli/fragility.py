"""``freestand fragility``: probability of each outcome against ground-motion intensity."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import typer
from rich.markup import escape
from rich.progress import (
    BarColumn,
    MofNCompleteColumn,
    Progress,
    ProgressColumn,
    TextColumn,
    TimeElapsedColumn,
    TimeRemainingColumn,
)
from rich.table import Table
from rich.text import Text

from freestand.cli.common import check_writable, console
from freestand.errors import FreestandError
from freestand.io.fragility_results import im_label

_FIGURE_SUFFIXES = (".png", ".svg", ".pdf")


class _Rate(ProgressColumn):
    """Simulations per second."""

    def render(self, task) -> Text:
        speed = task.finished_speed or task.speed
        return Text(f"{speed:.1f} sims/s" if speed else "- sims/s")


def _progress(quiet: bool):
    from rich.console import Console

    err = Console(emoji=False, stderr=True)
    return Progress(
        TextColumn("{task.description}"),
        BarColumn(),
        MofNCompleteColumn(),
        _Rate(),
        TimeElapsedColumn(),
        TextColumn("left"),
        TimeRemainingColumn(),
        console=err,
        transient=True,
        disable=quiet or not err.is_terminal,
    )


def _check_outputs(plot: Path | None) -> None:
    if plot is None:
        return
    if plot.suffix.lower() not in _FIGURE_SUFFIXES:
        raise FreestandError(
            f"{str(plot)!r} has no .png, .svg or .pdf suffix; e.g. --plot fragility.png",
            source="--plot",
        )
    if not plot.parent.is_dir():
        raise FreestandError(
            f"the folder of {str(plot)!r} does not exist; create it first", source="--plot"
        )
    if plot.is_dir():
        raise FreestandError(
            f"{str(plot)!r} is a folder; give a file name, e.g. --plot {plot / 'fragility.png'}",
            source="--plot",
        )
    check_writable(plot, "--plot")


def fragility(
    model_file: Path = typer.Argument(None, help="Model file (TOML).", show_default=False),
    configuration: str = typer.Option(
        None, "--configuration", "-c", help="Configuration (default: the first)."
    ),
    suite: Path = typer.Option(None, "--suite", help="Record suite file (TOML)."),
    im: str = typer.Option(
        "pga",
        "--im",
        help="Intensity measure of planar models: pga, pgv, sa:F[,DAMPING], "
        "pga-alpha[:BLOCK]; of two horizontal components (records with x and y, for 3-D "
        "configurations): pga-gm, pga-rotd50, pga-rotd100, "
        "pgv-gm, pgv-rotd50, pgv-rotd100, sa-gm:F[,DAMPING], sa-rotd50:F[,DAMPING], "
        "sa-rotd100:F[,DAMPING].",
    ),
    levels: str = typer.Option(
        None,
        "--levels",
        help="IM levels LOW:HIGH:N (SI, or with units, e.g. 0.05g:1g:20) or a list.",
    ),
    vary: list[str] = typer.Option(
        None, "--vary", help="Uncertain input NAME=DISTRIBUTION (as for sample), repeatable."
    ),
    samples: int = typer.Option(
        None, "--samples", help="Samples per record and level (default 1; 10 with --vary)."
    ),
    outcome: list[str] = typer.Option(
        None,
        "--outcome",
        help="Outcome, repeatable: overturn:BLOCK, rotation:BLOCK>0.5alpha, "
        "slide:BLOCK>0.05m, uplift:BLOCK, flight:BLOCK (default: per configuration).",
    ),
    both_polarities: bool = typer.Option(
        False, "--both-polarities", help="Run every record with both signs."
    ),
    cloud: bool = typer.Option(False, "--cloud", help="Unscaled records (cloud analysis)."),
    workers: int = typer.Option(None, "--workers", help="Local worker processes (default: all)."),
    scheduler: str = typer.Option(
        None, "--scheduler", help="Dask scheduler address, e.g. tcp://HOST:8786."
    ),
    store: Path = typer.Option(
        None, "--store", help="Folder for every simulation (Parquet); resumes a stopped run."
    ),
    from_store: Path = typer.Option(
        None, "--from-store", help="Fit again from a store alone (no simulation)."
    ),
    seed: int = typer.Option(0, "--seed", help="Seed of the inputs and of the bootstrap."),
    free_time: float = typer.Option(
        10.0, "--free-time", help="Cap on the time simulated after a record [s]."
    ),
    bootstrap: int = typer.Option(1000, "--bootstrap", help="Bootstrap replicates."),
    confidence: float = typer.Option(0.95, "--confidence", help="Confidence level [-]."),
    chunk: int = typer.Option(None, "--chunk", help="Simulations per stored chunk."),
    plot: Path = typer.Option(None, "--plot", help="Write the figure (.png, .svg, .pdf)."),
    as_json: bool = typer.Option(False, "--json", help="Write one JSON document to stdout."),
) -> None:
    """Fragility curves: probability of overturning, sliding, uplift, flight against IM."""
    from freestand.api.fragility import check_fit_options, fragility_from_store

    _check_outputs(plot)
    check_fit_options(bootstrap, confidence, seed)
    if from_store is not None:
        result = fragility_from_store(
            from_store, outcome or None, bootstrap=bootstrap, confidence=confidence, seed=seed
        )
        stored, expected = result.core.simulations, result.definition["simulations"]
        if stored < expected:
            console().print(
                f"[yellow]the store holds {stored} of {expected} simulations; fitting those[/]"
            )
        if store is not None:
            result = replace(result, store=str(store))
    else:
        result = _run(
            model_file, configuration, suite, im, levels, vary, samples, outcome,
            both_polarities, cloud, workers, scheduler, store, seed, free_time, bootstrap,
            confidence, chunk, as_json,
        )  # fmt: skip
    document = result.to_dict()
    written = None
    if plot is not None:
        from freestand.plot.fragility import save_fragility_figure

        written = save_fragility_figure(result.plot(), plot)
    if as_json:
        typer.echo(json.dumps(document, indent=2))
    else:
        _print(document, written)
    if result.core.simulations and result.core.failed == result.core.simulations:
        from rich.console import Console

        Console(emoji=False, stderr=True).print(
            "[bold red]error:[/] every simulation failed or was invalid; nothing to fit"
        )
        raise typer.Exit(1)


def _run(model_file, configuration, suite, im, levels, vary, samples, outcome, both_polarities,
         cloud, workers, scheduler, store, seed, free_time, bootstrap, confidence, chunk,
         quiet):  # fmt: skip
    from freestand.api.fragility import fragility as run_fragility
    from freestand.io.model_file import load_model
    from freestand.io.store import CampaignStore

    if model_file is None:
        raise FreestandError("give the model file (or --from-store DIR)", source="MODEL_FILE")
    if suite is None:
        raise FreestandError("give the record suite, e.g. --suite records.toml", source="--suite")
    model = load_model(model_file)
    try:
        with _progress(quiet) as bar:
            task = bar.add_task("simulating", total=None)

            def advance(count: int, total: int) -> None:
                bar.update(task, total=total, advance=count)

            return run_fragility(
                model, suite, im, levels, outcome or None, configuration=configuration,
                vary=vary or None, samples=samples, both_polarities=both_polarities, cloud=cloud,
                seed=seed, free_time=free_time, bootstrap=bootstrap, confidence=confidence,
                workers=workers, scheduler=scheduler, store=store, chunk=chunk,
                progress=advance,
            )  # fmt: skip
    except KeyboardInterrupt:
        if store is not None and (store / "campaign.json").is_file():
            target = CampaignStore(store)
            size = target.definition()["chunk_size"]
            kept = (
                f"{len(target.chunks())} chunk(s) of {size} simulations are in {store}; run the "
                "same command again to resume"
            )
        else:
            kept = "nothing was kept (give --store DIR to keep finished simulations)"
        console().print(f"[yellow]interrupted:[/] {escape(kept)}")
        raise typer.Exit(130) from None


def _fmt(value, digits: int = 4) -> str:
    return "-" if value is None else f"{value:.{digits}g}"


def _print(document: dict, written) -> None:
    out = console()
    unit = document["im"]["unit"]
    u = escape(f"[{unit}]")
    out.print(
        f"[bold]{escape(document['model'])}[/] / {escape(document['configuration'])}: "
        f"{document['simulations']} simulations ({escape(document['suite']['name'])}, "
        f"{len(document['suite']['records'])} records), IM {escape(im_label(document['im']))}"
    )
    if document["failed"]:
        out.print(
            f"[yellow]{document['failed']} simulation(s) failed or invalid[/] (left out of the "
            f"fits): {document['statuses']}"
        )
    capped = document["statuses"].get("capped", 0)
    if capped:
        out.print(
            f"[yellow]{capped} simulation(s) still moving {document['free_time']:g} s after "
            "the record[/] (counted with the peaks reached by then)"
        )
    summary = Table(title="Lognormal fragility per outcome (maximum likelihood)")
    for header in (
        "outcome", f"median {u}", "median interval", "beta [-]", "beta interval",
        f"HCLPF {u}", "note",
    ):  # fmt: skip
        summary.add_column(header)
    for item in document["outcomes"]:
        if item["fitted"]:
            summary.add_row(
                item["name"], _fmt(item["median"]),
                f"{_fmt(item['median_interval'][0])} - {_fmt(item['median_interval'][1])}",
                _fmt(item["beta"], 3),
                f"{_fmt(item['beta_interval'][0], 3)} - {_fmt(item['beta_interval'][1], 3)}",
                _fmt(item["hclpf"]), "",
            )  # fmt: skip
        else:
            summary.add_row(item["name"], "-", "-", "-", "-", "-", "not fitted (below)")
    out.print(summary)
    for item in document["outcomes"]:
        if not item["fitted"]:
            out.print(f"  {escape(item['name'])}: not fitted, {escape(item['reason'] or '')}")
    conf = 100 * document["fit"]["confidence"]
    for item in document["outcomes"]:
        table = Table(title=f"{item['name']}: counts per level", title_justify="left")
        table.add_column(f"level {u}", justify="right")
        table.add_column("occurred / simulations", justify="right")
        table.add_column("fraction [-]", justify="right")
        table.add_column(f"{conf:.0f} % Wilson interval [-]", justify="right")
        rows = zip(item["levels"], item["counts"], item["totals"], item["fractions"],
                   item["fraction_intervals"], strict=True)  # fmt: skip
        for level, count, total, fraction, (low, high) in rows:
            table.add_row(
                f"{level:.4g}", f"{count} / {total}", _fmt(fraction, 3),
                f"{_fmt(low, 3)} - {_fmt(high, 3)}",
            )  # fmt: skip
        if len(item["levels"]) <= 60:
            out.print(table)
    out.print(f"HCLPF: {escape(document['fit']['hclpf'])}.")
    if written is not None:
        out.print(f"wrote {written}")
    if "store" in document:
        out.print(f"store: {document['store']}")


def register(app: typer.Typer) -> None:
    """Add the command of this module to ``app``."""
    app.command("fragility")(fragility)
