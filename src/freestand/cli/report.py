"""``freestand report``: the engineer's screening report as one self-contained HTML file."""

from __future__ import annotations

from pathlib import Path

import typer
from rich.markup import escape
from rich.progress import BarColumn, Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

from freestand.cli.common import check_file, console, load
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
    as_json: bool = typer.Option(
        False, "--json", help="Write the files written and the conclusions as JSON to stdout."
    ),
    record: Path = typer.Option(
        None,
        "--record",
        help="Ground record along x: each 3-D configuration is simulated under it (with "
        "--record-y and --vertical) and its time history reported.",
    ),
    record_y: Path = RECORD_Y,
    vertical: Path = VERTICAL,
    angle: float = ANGLE,
    dt: str = DT,
    unit: str = UNIT,
    scale: float = SCALE,
    peak: str = PEAK,
    spectral: str = SPECTRAL,
) -> None:
    """Write the screening report: inputs, Tables 2-5, Figures 6-9 analogues, conclusions.

    With --record, every 3-D configuration's time history under the record
    (peaks, figures) is reported as well.
    """
    from freestand.api.report import SUFFIXES, default_path, write_report
    from freestand.report.content import report_date

    day = report_date(date)
    target = output if output is not None else default_path(model_file)
    check_file(target, "--output", SUFFIXES)
    given = {"--record-y": record_y, "--vertical": vertical, "--angle": angle, "--dt": dt,
             "--unit": unit, "--scale": scale, "--peak": peak, "--spectral": spectral}  # fmt: skip
    if record is None:
        for option, value in given.items():
            if value is not None:
                raise FreestandError(
                    f"{option} goes with a ground record; give --record FILE (the x component) "
                    f"too, or leave {option} out",
                    source=option,
                )
    check_angle(angle)
    model = load(model_file)
    motion = None
    if record is not None:
        motion = read_record(
            model, record, record_y=record_y, vertical=vertical, dt=dt, unit=unit, scale=scale,
            peak=peak, spectral=spectral,
        )  # fmt: skip
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

        result = write_report(
            model, target, pdf=pdf, date=day, progress=step, record=motion, angle=angle or 0.0
        )
    if as_json:
        typer.echo(result.to_json())
        return
    for path in result.files:
        out.print(escape(f"wrote {path}"), highlight=False)


def register(app: typer.Typer) -> None:
    """Add the command of this module to ``app``."""
    app.command("report")(report)
