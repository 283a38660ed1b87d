"""``freestand screen`` and ``freestand example``."""

from __future__ import annotations

import json
from importlib import resources
from pathlib import Path

import typer
from rich.console import Console
from rich.table import Table

from freestand.core.screening import screen as screen_stack
from freestand.errors import FreestandError
from freestand.io.model_file import load_model
from freestand.io.results import screening_document
from freestand.report.tables import (
    FORCE_HEADERS,
    MOTION_HEADERS,
    PAPER_CASE_HEADERS,
    force_rows,
    motion_rows,
    paper_case_rows,
)

EXAMPLES = {"crane": "crane.toml"}


def _number(value: float, digits: int) -> str:
    return f"{value:,.{digits}f}" if value != 0 else "0"


def screen(
    model_file: Path = typer.Argument(..., help="Model file (TOML).", show_default=False),
    as_json: bool = typer.Option(False, "--json", help="Write one JSON document to stdout."),
    configuration: list[str] = typer.Option(
        None, "--configuration", "-c", help="Screen only this configuration (repeatable)."
    ),
) -> None:
    """Initial motion and contact forces of every configuration, excitation and sense."""
    model = load_model(model_file)
    stacks = (
        [model.configuration(name) for name in configuration]
        if configuration
        else list(model.configurations)
    )
    cases = [
        case for stack in stacks for case in screen_stack(stack, model.excitations, model.gravity)
    ]
    if as_json:
        typer.echo(json.dumps(screening_document(model.name, cases, model.gravity), indent=2))
        return
    console = Console()
    if not console.is_terminal:
        console = Console(width=120)
    console.print(f"[bold]{model.name}[/]  ({model.source}, g = {model.gravity} m/s^2)")
    console.print(
        "sense: of the horizontal inertial force along x; accelerations relative to the "
        "support; angular counter-clockwise positive"
    )
    table = Table(title="Initial types of motion and accelerations (paper Tables 2 and 4)")
    for header in MOTION_HEADERS:
        table.add_column(header, justify="right" if "acc." in header else "left")
    for row in motion_rows(cases):
        cells = list(row.cells)
        for k in (5, 6, 7):
            if isinstance(cells[k], float):
                cells[k] = _number(cells[k], 3)
        style = "yellow" if row.flag else None
        table.add_row(*[str(c) for c in cells], style=style)
    console.print(table)
    forces = Table(title="Contact forces on each body from the body below (paper Tables 3 and 5)")
    for header in FORCE_HEADERS:
        forces.add_column(header, justify="right" if "[N]" in header else "left")
    for row in force_rows(cases, stacks):
        cells = list(row.cells)
        cells[4] = f"{cells[4][0]}: {_number(cells[4][1], 0)}"
        cells[5] = f"{cells[5][0]}: {_number(cells[5][1], 0)}"
        cells[6] = _number(cells[6], 0)
        forces.add_row(*[str(c) for c in cells], style="yellow" if row.flag else None)
    console.print(forces)
    cases_table = Table(title="Cases of the paper's section 3")
    for header in PAPER_CASE_HEADERS:
        cases_table.add_column(header)
    for row in paper_case_rows(cases):
        cases_table.add_row(*[str(c) for c in row.cells], style="yellow" if row.flag else None)
    console.print(cases_table)
    flagged = [case for case in cases if case.status in ("ambiguous", "inconsistent")]
    for case in flagged:
        console.print(
            f"[yellow]{case.configuration} / {case.excitation} / sense "
            f"{'+' if case.sense > 0 else '-'}: {case.status}[/] "
            f"({len(case.alternatives)} admissible state(s); the table shows the one chosen by "
            "the rule 'static friction holds where it can, then fewest separations'; "
            "--json lists them all)"
        )


def example(
    name: str = typer.Argument("crane", help=f"Example name: {', '.join(EXAMPLES)}."),
) -> None:
    """Print a built-in example model file."""
    if name not in EXAMPLES:
        raise FreestandError(
            f"{name!r} is not a built-in example; choose one of {', '.join(EXAMPLES)}",
            source="freestand example",
        )
    text = resources.files("freestand.examples").joinpath(EXAMPLES[name]).read_text()
    typer.echo(text, nl=False)


def register(app: typer.Typer) -> None:
    """Add the commands of this module to ``app``."""
    app.command("screen")(screen)
    app.command("example")(example)
