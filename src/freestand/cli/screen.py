"""``freestand screen`` and ``freestand example``."""

from __future__ import annotations

import json
import math
from dataclasses import replace
from pathlib import Path

import typer
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from freestand.cli.common import check_folder, load, staging
from freestand.errors import FreestandError
from freestand.io.examples import EXAMPLES, example_path
from freestand.plot.body_screening import shape_text
from freestand.report.tables import (
    BODY_DIRECTION_HEADERS,
    FORCE_HEADERS,
    MOTION_HEADERS,
    PAPER_CASE_HEADERS,
    body_case_sentence,
    body_direction_rows,
    force_rows,
    motion_rows,
    paper_case_rows,
)


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
    directions: int = typer.Option(
        24,
        "--directions",
        help="3-D configurations: number of horizontal directions screened, evenly over "
        "0-360 deg (24: every 15 deg).",
    ),
    plot: Path = typer.Option(
        None,
        "--plot",
        help="3-D configurations: folder to write the polar figure of uplift thresholds and "
        "initial motions into (uplift_polar.png, .svg); created if missing.",
    ),
) -> None:
    """Initial motion and contact forces of every configuration, excitation and sense.

    A 3-D configuration (a block with shape) is screened in every horizontal
    direction of a sweep (--directions) under each excitation's horizontal
    magnitude sqrt(x^2 + y^2): its initial motion, pivot, contact forces and
    uplift threshold per direction, and the state in the excitation's own
    direction.
    """
    from freestand.api.screening import screen as screen_model

    model = load(model_file)
    check_folder(plot, "--plot")
    result = screen_model(
        model,
        configurations=configuration or None,
        vertical_senses=vertical_senses,
        directions=directions,
    )
    written = _write_figure(result, plot)
    if as_json:
        if plot is None:
            typer.echo(result.to_json())
        else:
            document = result.to_dict()
            document["figures"] = [str(path) for path in written]
            typer.echo(json.dumps(document, indent=2))
        return
    console = Console(emoji=False)
    if not console.is_terminal:
        console = Console(emoji=False, width=120)
    console.print(
        f"[bold]{escape(model.name)}[/]  ({escape(model.source)}, g = {model.gravity} m/s^2)",
        highlight=False,
    )
    planar = bool(result.cases) or not result.body_cases
    if planar:
        console.print(
            "sense: of the horizontal inertial force along x; a_v: vertical support acceleration, "
            "positive downward (weight m (g - a_v)); accelerations relative to the support; "
            "angular counter-clockwise positive; blocks bottom to top",
            highlight=False,
        )
    _print_excitations(console, model, vertical_senses)
    if planar:
        _print_planar(console, result)
    if result.body_cases:
        _print_bodies(console, result)
    for path in written:
        console.print(escape(f"wrote {path}"), highlight=False)


def _write_figure(result, folder: Path | None) -> list[Path]:
    """The polar figure of the 3-D screening into ``folder`` (refused without 3-D cases)."""
    if folder is None:
        return []
    if not result.body_cases:
        raise FreestandError(
            "draws the polar figure of 3-D configurations (blocks with shape), and none is "
            "screened; leave --plot out for planar configurations",
            source="--plot",
        )
    from freestand.plot.figures import save_figure

    with staging() as stage:
        save_figure(result.plot(), stage.folder(folder) / "uplift_polar")
        return stage.commit()


def _print_excitations(console: Console, model, vertical_senses: str | None) -> None:
    """One line per excitation: a_h, a_v (both senses when asked) and y with the direction."""
    for excitation in model.excitations:
        verticals = (
            excitation.verticals()
            if vertical_senses is None
            else replace(excitation, vertical_senses=vertical_senses).verticals()
        )
        console.print(
            escape(
                f"  {excitation.name}: {_horizontal_text(excitation)}, a_v = "
                + " and ".join(f"{v:.3g} m/s^2" for v in verticals)
            ),
            highlight=False,
        )


def _print_planar(console: Console, result) -> None:
    """The planar tables: paper Tables 2-5, the force envelope and the paper's cases."""
    cases, envelope, stacks = result.cases, result.envelope, result.configurations
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


def _horizontal_text(excitation) -> str:
    """``"a_h = 2.7 m/s^2"``, or with y ``"x = 2.94, y = 1.96 m/s^2 (3.54 m/s^2 at 33.7 deg)"``."""
    x, y = excitation.horizontal, excitation.horizontal_y
    if not y:
        return f"a_h = {x:.3g} m/s^2"
    angle = math.degrees(math.atan2(y, x)) % 360.0
    return f"x = {x:.3g}, y = {y:.3g} m/s^2 ({math.hypot(x, y):.3g} m/s^2 at {angle:.1f} deg)"


def _print_bodies(console: Console, result) -> None:
    """The 3-D configurations: one table of directions per configuration and excitation."""
    console.print(
        "3-D configurations: direction of the horizontal support acceleration from +x towards "
        "+y, under the excitation's magnitude sqrt(x^2 + y^2) in each; pivots: the base edge "
        "at +x, -y..., a corner, or the rim point at an angle; forces on the body from the "
        "support",
        highlight=False,
    )
    bodies = {configuration.name: configuration.body for configuration in result.bodies}
    for case in result.body_cases:
        body = bodies[case.configuration]
        table = _table(
            f"{case.configuration} ({shape_text(body)}), {case.excitation}: a = "
            f"{case.horizontal:.3g} m/s^2 in each direction, a_v = {case.vertical:.3g} m/s^2",
            "Last row (own): the excitation's own direction.",
        )
        for header in BODY_DIRECTION_HEADERS:
            motion = header == "type of motion"
            table.add_column(escape(header), justify="left" if motion else "right", no_wrap=motion)
        for row in body_direction_rows(case):
            direction, label, *numbers = row.cells
            table.add_row(
                f"{direction:.1f}" + (" (own)" if row.flag else ""),
                escape(label),
                *(
                    _value(value, digits)
                    for value, digits in zip(numbers, (3, 0, 0, 0, 3), strict=True)
                ),
                style="bold" if row.flag else None,
            )
        console.print(table)
        console.print(escape(body_case_sentence(case, body)), highlight=False)


def _value(value: float, digits: int) -> str:
    """A number for the tables: grouped, '-' where not computed (slide-rock forces)."""
    if not math.isfinite(value):
        return "-"
    return _number(value if abs(value) >= 0.5 * 10.0**-digits else 0.0, digits)


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
    typer.echo(example_path(name).read_text(), nl=False)


def register(app: typer.Typer) -> None:
    """Add the commands of this module to ``app``."""
    app.command("screen")(screen)
    app.command("example")(example)
