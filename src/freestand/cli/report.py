"""``freestand report``: the engineer's screening report as one self-contained HTML file."""

from __future__ import annotations

from pathlib import Path

import typer
from rich.markup import escape
from rich.progress import BarColumn, Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

from freestand.cli.common import check_file, console, load


def report(
    model_file: Path = typer.Argument(..., help="Model file (TOML)."),
    output: Path = typer.Option(
        None,
        "--output",
        "-o",
        help="Report to write: FILE.html, or FILE.pdf (printed with headless Chromium). "
        "Default: <model name>-report.html beside the model file.",
    ),
    pdf: bool = typer.Option(
        False, "--pdf", help="Also print the HTML report to <output>.pdf with headless Chromium."
    ),
    date: str = typer.Option(
        None,
        "--date",
        help="Date on the report, YYYY-MM-DD (default: SOURCE_DATE_EPOCH if set, else today).",
    ),
    as_json: bool = typer.Option(
        False, "--json", help="Write the files written and the conclusions as JSON to stdout."
    ),
) -> None:
    """Write the screening report: inputs, Tables 2-5, Figures 6-9 analogues, conclusions."""
    from freestand.api.report import SUFFIXES, default_path, write_report
    from freestand.report.content import report_date

    day = report_date(date)
    target = output if output is not None else default_path(model_file)
    check_file(target, "--output", SUFFIXES)
    model = load(model_file)
    out = console()
    columns = (
        SpinnerColumn(),
        TextColumn("{task.description}"),
        BarColumn(),
        TextColumn("{task.completed}/{task.total}"),
        TimeElapsedColumn(),
    )
    with Progress(*columns, console=out, transient=False, disable=as_json) as progress:
        task = progress.add_task("screening", total=None)

        def step(description: str, done: int, total: int) -> None:
            progress.update(task, description=description, completed=done, total=total)

        result = write_report(model, target, pdf=pdf, date=day, progress=step)
    if as_json:
        typer.echo(result.to_json())
        return
    for path in result.files:
        out.print(escape(f"wrote {path}"), highlight=False)


def register(app: typer.Typer) -> None:
    """Add the command of this module to ``app``."""
    app.command("report")(report)
