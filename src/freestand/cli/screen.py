"""``freestand screen`` and ``freestand example``."""

from __future__ import annotations

from dataclasses import replace
from importlib import resources
from pathlib import Path

import typer
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from freestand.cli.common import load
from freestand.errors import FreestandError
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


def _table(title: str, caption: str | None = None) -> Table:
    return Table(title=escape(title), caption=escape(caption) if caption else None)


def screen(
    model_file: Path = typer.Argument(..., help="Model file (TOML).", show_default=False),
    as_json: bool = typer.Option(False, "--json", help="Write one JSON document to stdout."),
    configuration: list[str] = typer.Option(
        None, "--configuration", "-c", help="Screen only this configuration (repeatable)."
    ),
    vertical_senses: str = typer.Option(
        None,
        "--vertical-senses",
        help="'both': analyse every excitation with its vertical acceleration downward and "
        "upward (envelope of the contact forces); 'given': as given. Default: each "
        "excitation's vertical_senses (model file).",
    ),
) -> None:
    """Initial motion and contact forces of every configuration, excitation and sense."""
    from freestand.api.screening import screen as screen_model

    model = load(model_file)
    result = screen_model(
        model, configurations=configuration or None, vertical_senses=vertical_senses
    )
    cases, envelope, stacks = result.cases, result.envelope, result.configurations
    if as_json:
        typer.echo(result.to_json())
        return
    console = Console(emoji=False)
    if not console.is_terminal:
        console = Console(emoji=False, width=120)
    console.print(
        f"[bold]{escape(model.name)}[/]  ({escape(model.source)}, g = {model.gravity} m/s^2)",
        highlight=False,
    )
    console.print(
        "sense: of the horizontal inertial force along x; a_v: vertical support acceleration, "
        "positive downward (weight m (g - a_v)); accelerations relative to the support; "
        "angular counter-clockwise positive; blocks bottom to top",
        highlight=False,
    )
    for excitation in model.excitations:
        verticals = (
            excitation.verticals()
            if vertical_senses is None
            else replace(excitation, vertical_senses=vertical_senses).verticals()
        )
        console.print(
            escape(
                f"  {excitation.name}: a_h = {excitation.horizontal:.3g} m/s^2, a_v = "
                + " and ".join(f"{v:.3g} m/s^2" for v in verticals)
            ),
            highlight=False,
        )
    table = _table(
        "Initial types of motion and accelerations (paper Tables 2 and 4)",
        "Accelerations are relative to the support: a block that rests on a body that moves "
        "has that body's acceleration.",
    )
    for header in MOTION_HEADERS:
        table.add_column(escape(header), justify="right" if "acc." in header else "left")
    for row in motion_rows(cases):
        cells = list(row.cells)
        for k in (5, 6, 7):
            if isinstance(cells[k], float):
                cells[k] = _number(cells[k], 3)
        style = "yellow" if row.flag else None
        table.add_row(*[escape(str(c)) for c in cells], style=style)
    console.print(table)
    forces = _table("Contact forces on each body from the body below (paper Tables 3 and 5)")
    for header in FORCE_HEADERS:
        forces.add_column(escape(header), justify="right" if "[N]" in header else "left")
    for row in force_rows(cases, stacks):
        cells = list(row.cells)
        cells[4] = f"{cells[4][0]}: {_number(cells[4][1], 0)}"
        cells[5] = f"{cells[5][0]}: {_number(cells[5][1], 0)}"
        cells[6] = _number(cells[6], 0)
        forces.add_row(*[escape(str(c)) for c in cells], style="yellow" if row.flag else None)
    console.print(forces)
    by_name = {stack.name: stack for stack in stacks}
    largest = _table(
        "Envelope of the contact forces: largest over the excitations and senses above",
        "Normal forces compression positive; the case giving each value in brackets.",
    )
    for header in ENVELOPE_HEADERS:
        largest.add_column(escape(header), justify="right" if "[N]" in header else "left")
    for item in envelope:
        stack = by_name[item.configuration]
        left, right = stack.blocks[stack.block_index(item.block)].contact_names
        largest.add_row(
            *(
                escape(text)
                for text in (
                    item.configuration,
                    item.block,
                    f"{left}: {_number(item.normal_left, 0)} ({item.cases[0]})",
                    f"{right}: {_number(item.normal_right, 0)} ({item.cases[1]})",
                    f"{_number(item.tangential, 0)} ({item.cases[2]})",
                )
            )
        )
    console.print(largest)
    cases_table = _table("Cases of the paper's section 3")
    for header in PAPER_CASE_HEADERS:
        cases_table.add_column(escape(header))
    for row in paper_case_rows(cases):
        cases_table.add_row(
            *[escape(str(c)) for c in row.cells], style="yellow" if row.flag else None
        )
    console.print(cases_table)
    flagged = result.flagged
    for case in flagged:
        console.print(
            "[yellow]"
            + escape(
                f"{case.configuration} / {case.excitation} / sense "
                f"{'+' if case.sense > 0 else '-'}: {case.status}"
            )
            + "[/] "
            + escape(
                f"({len(case.alternatives)} admissible state(s); the table shows the one chosen "
                "by the rule 'static friction holds where it can, then fewest separations'; "
                "--json lists them all)"
            )
        )


ENVELOPE_HEADERS = (
    "configuration",
    "body",
    "largest vertical, left [N]",
    "largest vertical, right [N]",
    "largest |horizontal (sum)| [N]",
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
