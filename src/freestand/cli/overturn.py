"""``freestand overturn``: overturning of a rocking block (paper section 5, Figs. 6-8), or of
a 3-D body under pulses in a direction."""

from __future__ import annotations

import contextlib
import json
import math
from pathlib import Path

import typer
from rich.console import Console
from rich.markup import escape
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn
from rich.table import Table

from freestand.api.base import subject
from freestand.api.body_overturning import BODY_FIGURE, BodyOverturningResult, check_direction
from freestand.api.overturning import (
    FIGURES,
    check_block,
    check_body_options,
    check_planar_direction,
    overturning,
)
from freestand.cli.common import (
    check_folder,
    console,
    load,
    parse_numbers,
    resolve_spectrum,
    staging,
)
from freestand.core.rocking.overturning import TABLE_FREQUENCIES


def overturn(
    model_file: Path = typer.Argument(..., help="Model file (TOML)."),
    configuration: list[str] = typer.Option(
        ...,
        "--configuration",
        "-c",
        help="Configuration name (repeatable: one check per configuration, the same block).",
    ),
    block: str = typer.Option(
        None, "--block", "-b", help="The rocking block (default: the top of its stack)."
    ),
    pivot: str = typer.Option(
        None, "--pivot", help="left | right (default: the pivot it rocks about in screening)."
    ),
    spectrum: str = typer.Option(
        None,
        "--spectrum",
        help="Horizontal spectrum: a model spectrum's name, a CSV file, 'rg1.60:pga=...' or "
        "'en1998:ag=...'. Default: the model's horizontal spectrum.",
    ),
    amplitudes: str = typer.Option(
        None,
        "--amplitudes",
        help="Rectangular pulse amplitudes, e.g. 0.5g,1g or 2.7,10.31 (bare numbers in m/s^2; "
        "default: the model's).",
    ),
    frequencies: str = typer.Option(
        None,
        "--frequencies",
        help="Half-sine pulse frequencies, e.g. 0.5,2 or '2.5 Hz' (bare numbers in Hz; default: "
        "0.25,0.5,1,2,5).",
    ),
    restitution: float = typer.Option(
        None,
        "--restitution",
        help="Angular-velocity ratio at impact [-] in place of the one from angular momentum.",
    ),
    include_vertical: bool = typer.Option(
        False,
        "--include-vertical",
        help="Weight m (g - a_v) with the model's largest downward a_v (default: m g).",
    ),
    direction: float = typer.Option(
        None,
        "--direction",
        help="3-D configurations: direction of the pulses [deg] from +x towards +y (default: "
        "that of the lowest uplift threshold).",
    ),
    plot: Path = typer.Option(
        None,
        "--plot",
        help="Folder to write the Figs. 6-8 analogues (3-D: the half-sine limits) into (PNG, "
        "SVG); created if missing.",
    ),
    as_json: bool = typer.Option(False, "--json", help="Write one JSON document to stdout."),
) -> None:
    """Rocking properties, overturning limits of pulses, and the response-spectrum check.

    A 3-D configuration (a box or a cylinder): the minimum overturning
    amplitude of half-sine, one-sine and one-cosine pulses along --direction,
    by the 3-D engine, at the frequencies asked (a progress bar: some seconds
    per frequency), beside the planar limits of the pulse's plane.

    With several ``-c``, every configuration is checked in turn (a set of tables
    each; with ``--json`` a list of documents, one per configuration; with
    ``--plot`` the figures of each go into a sub-folder named after it).
    """
    model = load(model_file)
    check_folder(plot, "--plot")
    check_direction(direction)
    names = list(dict.fromkeys(configuration))
    bodies = {body.name: body for body in model.body_configurations}
    for name in names:
        if name in bodies:
            check_body_options(bodies[name], block, pivot, spectrum, amplitudes, restitution)
        else:
            stack = model.configuration(name)
            check_planar_direction(name, direction)
            check_block(subject(model), stack, block or stack.blocks[-1].name, pivot)
    amplitude_values = parse_numbers(
        amplitudes, "--amplitudes", "m/s^2", "acceleration", model.gravity
    )
    frequency_values = parse_numbers(frequencies, "--frequencies", "Hz", "frequency")
    planar = [name for name in names if name not in bodies]
    horizontal = resolve_spectrum(spectrum, model, "horizontal") if planar else None
    three_d = len(names) - len(planar)
    steps = 3 * len(set(frequency_values or TABLE_FREQUENCIES)) * three_d
    with _progress_bar(steps, as_json) as progress:
        results = [
            overturning(
                model,
                configuration=name,
                block=block,
                pivot=pivot,
                spectrum=horizontal if name not in bodies else None,
                amplitudes=amplitude_values,
                frequencies=frequency_values,
                restitution=restitution,
                include_vertical=include_vertical,
                direction=direction,
                **({"progress": progress} if name in bodies else {}),
            )  # fmt: skip
            for name in names
        ]
    documents = []
    with staging() as stage:
        for result in results:
            if plot is not None:
                folder = stage.folder(
                    plot if len(names) == 1 else plot / _folder_name(result.configuration)
                )
                _save_figures(result, folder)
            if as_json:
                documents.append(result.to_dict())
            elif isinstance(result, BodyOverturningResult):
                _print_body(model, result)
            else:
                _print(model, result)
        written = stage.commit()
    if as_json:
        for document in documents:
            document["figures"] = [
                str(path) for path in written
                if len(names) == 1 or path.parent.name == _folder_name(document["configuration"])
            ]  # fmt: skip
        typer.echo(json.dumps(documents[0] if len(names) == 1 else documents, indent=2))
        return
    out = console()
    for path in written:
        out.print(escape(f"wrote {path}"), highlight=False)


def _folder_name(configuration: str) -> str:
    """A folder for the figures of one configuration: ``x-z cart right`` -> ``x-z_cart_right``."""
    return (
        "".join(c if c.isalnum() or c in "-_." else "_" for c in configuration) or "configuration"
    )


@contextlib.contextmanager
def _progress_bar(total: int, quiet: bool):
    """A rich progress bar of the 3-D searches on stderr (a terminal only, not with --json)."""
    console = Console(emoji=False, stderr=True)
    if quiet or total == 0 or not console.is_terminal:
        yield None
        return
    with Progress(
        TextColumn("3-D pulse searches"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(),
        console=console, transient=True,
    ) as bar:  # fmt: skip
        task = bar.add_task("3-D pulse searches", total=total)
        yield lambda: bar.advance(task)


def _save_figures(result, folder: Path) -> None:
    """The Figs. 6-8 analogues of one configuration into ``folder`` (PNG and SVG)."""
    from freestand.plot.figures import save_figure

    if isinstance(result, BodyOverturningResult):
        save_figure(result.plot(), folder / BODY_FIGURE)
        return
    for figure, name in FIGURES.items():
        if figure != "spectrum" or result.spectrum is not None:
            save_figure(result.plot(figure=figure), folder / name)


def _print(model, result) -> None:
    """The tables of one configuration's check."""
    from freestand.api.overturning import CONCLUSION

    rocking, pivot = result.rocking, result.pivot
    properties = {side: rocking.about(side) for side in ("pivot", "other")}
    rectangular, half_sine = result.rectangular, result.half_sine
    one_sine, one_cosine = result.one_sine, result.one_cosine
    operating, curves, checks = result.operating_amplitude, result.curves, result.checks
    out = console()
    out.print(
        f"[bold]{escape(model.name)}[/]: "
        + escape(
            f"overturning of {result.block!r} in {result.configuration!r} (paper section 5); "
            f"{result.weight}"
        )
    )
    table = Table(title="Rocking properties (Housner 1963)")
    for header in (
        "pivot",
        "R [m]",
        "alpha [rad]",
        "I_pivot [kg m^2]",
        "p [rad/s]",
        "uplift [m/s^2]",
    ):
        table.add_column(escape(header), justify="left" if header == "pivot" else "right")
    for label, side in ((pivot, "pivot"), ("left" if pivot == "right" else "right", "other")):
        prop = properties[side]
        table.add_row(
            label + (" (rocks first)" if side == "pivot" else ""),
            f"{prop.R:.3f}",
            f"{prop.alpha:.4f}",
            f"{prop.inertia_about_pivot:,.0f}",
            f"{prop.p:.3f}",
            f"{prop.uplift_threshold:.2f}",
        )
    out.print(table)
    out.print(
        f"Angular-velocity ratio at impact (restitution): {rocking.restitution:.3f}; "
        f"Housner's energy ratio r = {rocking.restitution**2:.3f}."
    )
    table = Table(title="Rectangular pulse: shortest overturning duration (paper Fig. 6)")
    for header in ("amplitude [m/s^2]", "Housner [s]", "exact [s]"):
        table.add_column(escape(header), justify="right")
    for a, h, e in zip(rectangular.amplitude, rectangular.housner, rectangular.exact, strict=True):
        table.add_row(
            f"{a:.2f}",
            f"{h:.3f}" if math.isfinite(h) else "no overturning",
            f"{e:.3f}" if math.isfinite(e) else "no overturning",
        )
    out.print(table)
    table = Table(title=escape("Pulses: minimum overturning amplitude [m/s^2] (paper Fig. 7)"))
    for header in (
        "f [Hz]",
        "half-sine duration [s]",
        "Housner [m/s^2]",
        "Makris-Roussos [m/s^2]",
        "exact [m/s^2]",
        "one-sine exact [m/s^2]",
        "one-cosine exact [m/s^2]",
    ):
        table.add_column(escape(header), justify="right")

    def cell(value: float) -> str:
        return f"{value:.2f}" if math.isfinite(value) else "none found"

    for k, f in enumerate(half_sine.frequency):
        table.add_row(
            f"{f:g}",
            f"{0.5 / f:.3f}",
            cell(half_sine.limits["housner"][k]),
            cell(half_sine.limits["makris-roussos"][k]),
            cell(half_sine.limits["exact"][k]),
            cell(one_sine.limits["exact"][k]),
            cell(one_cosine.limits["exact"][k]),
        )
    out.print(table)
    out.print(f"A half-sine pulse of {operating:g} m/s^2 overturns the block up to:")
    for name, value in curves.operating_frequency.items():
        text = (
            f"{value:.2f} Hz (pulses longer than {0.5 / value:.2f} s)"
            if math.isfinite(value)
            else "never in 0.1-20 Hz"
        )
        out.print(f"  {name:15s} {text}")
    out.print(CONCLUSION)
    if checks:
        table = Table(title=escape(f"Spectrum check (paper Fig. 8): {result.spectrum.label}"))
        for header in ("limit", "verdict", "min. limit / spectrum [-]", "at [Hz]"):
            table.add_column(escape(header))
        for name, check in checks.items():
            table.add_row(
                name, check.verdict, f"{check.min_ratio:.2f}", f"{check.frequency_at_min:.2f}"
            )
        out.print(table)


def _print_body(model, result: BodyOverturningResult) -> None:
    """The tables of one 3-D configuration's check."""
    curve, plane = result.half_sine, result.plane.about("pivot")
    out = console()
    chosen = "" if result.direction_given else " (the lowest uplift threshold)"
    out.print(
        f"[bold]{escape(model.name)}[/]: "
        + escape(
            f"overturning of the {result.shape} {curve.body!r} in {result.configuration!r} "
            f"under pulses along {result.direction:g} deg{chosen}; {result.weight}"
        )
    )
    out.print(escape(
        f"It tips about {curve.pivot} above {curve.uplift_threshold:.2f} m/s^2; the centre of "
        f"gravity is {curve.tipping_distance:.3f} m from the nearest point of the base outline. "
        f"Planar block of the pulse's plane: R = {plane.R:.3f} m, alpha = {plane.alpha:.4f} rad, "
        f"p = {plane.p:.3f} rad/s."
    ))  # fmt: skip
    if curve.slides_flat:
        out.print(escape(
            "Friction keeps the base flat (mu_0 h is less than the distance from the centre "
            "of gravity to the base's edge): the body slides and no pulse overturns it."
        ))  # fmt: skip
    table = Table(title=escape("Pulses: minimum overturning amplitude [m/s^2], 3-D exact"))
    for header in ("f [Hz]", "half-sine duration [s]", "half-sine 3-D [m/s^2]",
                   "one-sine 3-D [m/s^2]", "one-cosine 3-D [m/s^2]",
                   "half-sine planar exact [m/s^2]", "Housner [m/s^2]"):  # fmt: skip
        table.add_column(escape(header), justify="right")

    def cell(value: float) -> str:
        return f"{value:.2f}" if math.isfinite(value) else "none found"

    for k, f in enumerate(curve.frequency):
        table.add_row(
            f"{f:g}", f"{0.5 / f:.3f}", cell(curve.amplitude[k]),
            cell(result.one_sine.amplitude[k]), cell(result.one_cosine.amplitude[k]),
            cell(result.planar.limits["exact"][k]), cell(result.planar.limits["housner"][k]),
        )  # fmt: skip
    out.print(table)
    document = result.to_dict()
    if result.operating_amplitude is not None:
        f0 = document["overturns_below_frequency"]["exact-3d"]
        text = (
            f"{f0:.2f} Hz (pulses longer than {0.5 / f0:.2f} s; interpolated between the "
            "frequencies asked)" if f0 is not None else "none of the frequencies asked"
        )  # fmt: skip
        out.print(escape(
            f"A half-sine pulse of {result.operating_amplitude:.2f} m/s^2 along "
            f"{result.direction:g} deg overturns the body up to: {text}"
        ))  # fmt: skip
    counts = {name: sum(d[name] for d in document["diagnostics"].values())
              for name in ("simulations", "failed", "undecided", "remedies")}  # fmt: skip
    out.print(escape(
        f"Engine: 3-D, exact rigid contact ({counts['simulations']} simulations, "
        f"{counts['failed']} failed the energy check, {counts['undecided']} free motions cut "
        f"undecided, {counts['remedies']} remedies)"
    ))  # fmt: skip


def register(app: typer.Typer) -> None:
    """Add the command of this module to ``app``."""
    app.command("overturn")(overturn)
