"""``freestand report``: the engineer's screening report as one self-contained HTML file."""

from __future__ import annotations

from pathlib import Path

import typer
from rich.markup import escape
from rich.progress import BarColumn, Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

from freestand.cli.common import check_file, console, load, staging
from freestand.errors import FreestandError


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
) -> None:
    """Write the screening report: inputs, Tables 2-5, Figures 6-9 analogues, conclusions."""
    from freestand.report.content import collect_report, report_date
    from freestand.report.html import render_html
    from freestand.report.output import print_pdf, require_chromium

    day = report_date(date)
    target = (
        output if output is not None else model_file.with_name(f"{model_file.stem}-report.html")
    )
    check_file(target, "--output", (".html", ".htm", ".pdf"))
    as_pdf = target.suffix.lower() == ".pdf"
    if pdf and as_pdf:
        raise FreestandError(
            f"{str(target)!r} is already a PDF; give -o FILE.html --pdf for both, or "
            "-o FILE.pdf alone",
            source="--pdf",
        )
    if pdf or as_pdf:
        require_chromium()
    model = load(model_file)
    out = console()
    columns = (
        SpinnerColumn(),
        TextColumn("{task.description}"),
        BarColumn(),
        TextColumn("{task.completed}/{task.total}"),
        TimeElapsedColumn(),
    )
    with staging() as stage, Progress(*columns, console=out, transient=False) as progress:
        task = progress.add_task("screening", total=None)

        def step(description: str, done: int, total: int) -> None:
            progress.update(task, description=description, completed=done, total=total + 2)

        content = collect_report(model, date=day, progress=step)
        total = progress.tasks[0].total or 0
        progress.update(task, description="drawing the figures and the HTML", completed=total - 2)
        document = render_html(content)
        progress.update(task, description=f"writing {target}", completed=total - 1)
        if as_pdf:
            html = stage.file(target.with_suffix(".html"))
            html.write_text(document, encoding="utf-8")
            progress.update(task, description="printing to PDF with Chromium")
            print_pdf(html, stage.file(target))
            html.unlink()
            stage.forget(html)
        else:
            stage.file(target).write_text(document, encoding="utf-8")
            if pdf:
                progress.update(task, description="printing to PDF with Chromium")
                html = stage.file(target.with_suffix(".print.html"))
                html.write_text(document, encoding="utf-8")
                print_pdf(html, stage.file(target.with_suffix(".pdf")))
                html.unlink()
                stage.forget(html)
        written = stage.commit()
        progress.update(task, description="done", completed=total)
    for path in written:
        out.print(escape(f"wrote {path}"), highlight=False)


def register(app: typer.Typer) -> None:
    """Add the command of this module to ``app``."""
    app.command("report")(report)
