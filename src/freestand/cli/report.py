"""``freestand report``: the engineer's screening report as one self-contained HTML file."""

from __future__ import annotations

from pathlib import Path

import typer
from rich.progress import BarColumn, Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

from freestand.cli.common import console
from freestand.io.model_file import load_model


def report(
    model_file: Path = typer.Argument(..., help="Model file (TOML)."),
    output: Path = typer.Option(
        None,
        "--output",
        "-o",
        help="HTML file to write (default: <model name>-report.html beside the model file).",
    ),
    pdf: bool = typer.Option(
        False, "--pdf", help="Also print the report to <output>.pdf with headless Chromium."
    ),
    date: str = typer.Option(
        None,
        "--date",
        help="Date on the report, YYYY-MM-DD (default: SOURCE_DATE_EPOCH if set, else today).",
    ),
) -> None:
    """Write the screening report: inputs, Tables 2-5, Figs. 6-9 analogues and conclusions."""
    from freestand.report.content import collect_report, report_date
    from freestand.report.html import render_html
    from freestand.report.output import print_pdf, require_chromium, write_atomic

    day = report_date(date)
    if pdf:
        require_chromium()
    target = (
        output if output is not None else model_file.with_name(f"{model_file.stem}-report.html")
    )
    out = console()
    columns = (
        SpinnerColumn(),
        TextColumn("{task.description}"),
        BarColumn(),
        TextColumn("{task.completed}/{task.total}"),
        TimeElapsedColumn(),
    )
    with Progress(*columns, console=out, transient=False) as progress:
        task = progress.add_task("reading the model file", total=None)
        model = load_model(model_file)

        def step(description: str, done: int, total: int) -> None:
            progress.update(task, description=description, completed=done, total=total + 2)

        content = collect_report(model, date=day, progress=step)
        total = progress.tasks[0].total or 0
        progress.update(task, description="drawing the figures and the HTML", completed=total - 2)
        document = render_html(content)
        progress.update(task, description=f"writing {target}", completed=total - 1)
        written = write_atomic(target, document)
        if pdf:
            progress.update(task, description="printing to PDF with Chromium")
            pdf_path = print_pdf(written, written.with_suffix(".pdf"))
        progress.update(task, description="done", completed=total)
    out.print(f"wrote {written}")
    if pdf:
        out.print(f"wrote {pdf_path}")


def register(app: typer.Typer) -> None:
    """Add the command of this module to ``app``."""
    app.command("report")(report)
