"""``freestand overturn``: overturning of a rocking block (paper section 5, Figs. 6-8)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import typer
from rich.markup import escape
from rich.table import Table

from freestand.cli.common import (
    check_folder,
    console,
    load,
    parse_numbers,
    resolve_spectrum,
    staging,
)
from freestand.core.contact.screening import Motion, initial_motion
from freestand.core.rocking.overturning import (
    CURVE_FREQUENCIES,
    TABLE_FREQUENCIES,
    check_spectrum,
    overturning_limits,
    rectangular_amplitude_grid,
    rectangular_pulse_limits,
)
from freestand.core.rocking.properties import RockingBlock
from freestand.errors import FreestandError

#: Highest pulse frequency accepted [Hz]: beyond, the pulse is far shorter than any rocking
#: period and the overturning amplitude is beyond any support acceleration.
MAX_FREQUENCY = 100.0
#: Lowest pulse frequency accepted [Hz]: a pulse of 50 s, longer than any record.
MIN_FREQUENCY = 0.01

CONCLUSION = (
    "Housner's half-sine criterion, as the paper applies it, is unconservative (Makris and "
    "Roussos 2000): a block can overturn in free rocking after the pulse. The corrected "
    "linearised limit and the exact nonlinear limit are lower, so a pulse of the operating "
    "amplitude overturns the block up to a higher frequency than the paper's boundary."
)


def _rocking_block(
    model,
    configuration: str,
    block_name: str,
    pivot: str | None,
    vertical: bool,
    restitution: float | None = None,
):
    stack = model.configuration(configuration)
    try:
        index = stack.block_index(block_name)
    except KeyError:
        names = ", ".join(repr(b.name) for b in stack.blocks)
        raise FreestandError(
            f"no block named {block_name!r} in configuration {configuration!r}; "
            f"choose one of {names}",
            source="--block",
        ) from None
    if index != len(stack.blocks) - 1:
        above = stack.blocks[index + 1].name
        raise FreestandError(
            f"block {block_name!r} carries {above!r}; the overturning check is for a block with "
            "nothing on top, resting on a steady body (the paper's cart on the steady bridge)",
            source="--block",
        )
    if pivot is not None and pivot not in ("left", "right"):
        raise FreestandError(f"{pivot!r} is not a pivot; use 'left' or 'right'", source="--pivot")
    block = stack.blocks[index]
    if not block.base_left < block.centre[0] < block.base_right:
        raise FreestandError(
            f"the centre of gravity of {block_name!r} (x = {block.centre[0]:g} m) does not lie "
            f"between its contacts ({block.base_left:g} .. {block.base_right:g} m): it cannot "
            "stand, let alone rock about one contact; check its centre and base in "
            f"{model.source}",
            source="--block",
        )
    vertical_acceleration = vertical_for_overturning(model) if vertical else 0.0
    if pivot is None:
        pivot = _default_pivot(model, stack, block)
    if restitution is not None and not 0 <= restitution <= 1:
        raise FreestandError(
            f"{restitution} is not an angular-velocity ratio; give a value in [0, 1] "
            "(Housner's energy ratio r is its square)",
            source="--restitution",
        )
    rocking = RockingBlock.from_block(
        block,
        pivot,
        gravity=model.gravity,
        vertical_acceleration=vertical_acceleration,
        restitution_override=restitution,
    )
    return stack, block, pivot, rocking


def vertical_for_overturning(model) -> float:
    """The largest downward vertical support acceleration of the model [m/s^2], 0 if none.

    The weight m (g - a_v) is smallest, and overturning easiest, under it.
    """
    return max([0.0] + [max(e.verticals()) for e in model.excitations])


def _default_pivot(model, stack, block) -> str:
    """The pivot the block rocks about under the model's excitations, else the easier one."""
    for excitation in sorted(model.excitations, key=lambda e: -e.horizontal):
        for sense in (1, -1):
            case = initial_motion(
                stack, excitation.horizontal, excitation.vertical, sense, model.gravity
            )
            if case.blocks:
                state = case.block(block.name)
                if state.motion in (Motion.ROCK, Motion.SLIDE_ROCK):
                    return state.pivot
    thresholds = {
        side: RockingBlock.from_block(block, side, gravity=model.gravity).uplift_threshold
        for side in ("left", "right")
    }
    return min(thresholds, key=thresholds.get)


def _finite(value: float) -> float | None:
    return float(value) if math.isfinite(value) else None


def overturn(
    model_file: Path = typer.Argument(..., help="Model file (TOML)."),
    configuration: list[str] = typer.Option(
        ...,
        "--configuration",
        "-c",
        help="Configuration name (repeatable: one check per configuration, the same block).",
    ),
    block: str = typer.Option(..., "--block", "-b", help="The rocking block (top of its stack)."),
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
    plot: Path = typer.Option(
        None,
        "--plot",
        help="Folder to write the Figs. 6-8 analogues into (PNG, SVG); created if missing.",
    ),
    as_json: bool = typer.Option(False, "--json", help="Write one JSON document to stdout."),
) -> None:
    """Rocking properties, overturning limits of pulses, and the response-spectrum check.

    With several ``-c``, every configuration is checked in turn (a set of tables
    each; with ``--json`` a list of documents, one per configuration; with
    ``--plot`` the figures of each go into a sub-folder named after it).
    """
    model = load(model_file)
    check_folder(plot, "--plot")
    names = list(dict.fromkeys(configuration))
    blocks = {
        name: _rocking_block(model, name, block, pivot, include_vertical, restitution)
        for name in names
    }
    amplitude_values = parse_numbers(
        amplitudes, "--amplitudes", "m/s^2", "acceleration", model.gravity
    ) or sorted({e.horizontal for e in model.excitations})
    frequency_values = parse_numbers(frequencies, "--frequencies", "Hz", "frequency") or list(
        TABLE_FREQUENCIES
    )
    for value in amplitude_values:
        if not value > 0:
            raise FreestandError(
                f"{value:g} m/s^2 is not a positive amplitude; e.g. --amplitudes 0.5g,1g",
                source="--amplitudes",
            )
    for value in frequency_values:
        if not MIN_FREQUENCY <= value <= MAX_FREQUENCY:
            raise FreestandError(
                f"{value:g} Hz is not a pulse frequency; give frequencies between "
                f"{MIN_FREQUENCY:g} and {MAX_FREQUENCY:g} Hz, e.g. --frequencies 0.5,1,2",
                source="--frequencies",
            )
    horizontal = resolve_spectrum(spectrum, model, "horizontal")
    documents = []
    with staging() as stage:
        for name in names:
            folder = None
            if plot is not None:
                folder = stage.folder(plot if len(names) == 1 else plot / _folder_name(name))
            documents.append(
                _check_one(
                    model,
                    name,
                    block,
                    blocks[name],
                    amplitude_values,
                    frequency_values,
                    horizontal,
                    include_vertical,
                    folder,
                    as_json,
                )  # fmt: skip
            )
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


def _check_one(
    model, configuration, block, rocking_block, amplitude_values, frequency_values,
    horizontal, include_vertical, plot, as_json,
) -> dict | None:  # fmt: skip
    """Compute (and print, unless ``as_json``) the check of one configuration.

    ``plot`` is the (staged) folder to write the figures into, or None. Returns
    the JSON document (without its ``figures``) when ``as_json``.
    """
    _, _, pivot, rocking = rocking_block
    weight = (
        f"weight m (g - a_v) with a_v = {vertical_for_overturning(model):.2f} m/s^2 downward"
        if include_vertical
        else "weight m g (the vertical support acceleration not included; see --include-vertical)"
    )
    operating = max(e.horizontal for e in model.excitations)
    rectangular = rectangular_pulse_limits(
        rocking, np.array(amplitude_values), operating_amplitude=operating
    )
    requested = np.array(sorted(set(frequency_values)))
    half_sine = overturning_limits(rocking, requested, kind="half-sine")
    curves = overturning_limits(
        rocking, CURVE_FREQUENCIES, kind="half-sine", operating_amplitude=operating
    )
    one_sine = overturning_limits(rocking, requested, kind="one-sine")
    one_cosine = overturning_limits(rocking, requested, kind="one-cosine")
    checks = check_spectrum(curves, horizontal) if horizontal is not None else {}

    if plot is not None:
        from freestand.plot.overturning import (
            plot_pulse_limits,
            plot_rectangular_pulse,
            plot_spectrum_check,
            save_figure,
        )

        amplitude_grid = rectangular_amplitude_grid(rocking, operating)
        curve = rectangular_pulse_limits(rocking, amplitude_grid, operating_amplitude=operating)
        save_figure(plot_rectangular_pulse(curve), plot / "fig6_rectangular_pulse")
        save_figure(plot_pulse_limits(curves), plot / "fig7_half_sine_pulse")
        if horizontal is not None:
            figure = plot_spectrum_check(curves, horizontal, checks)
            save_figure(figure, plot / "fig8_spectrum_check")

    properties = {side: rocking.about(side) for side in ("pivot", "other")}
    if as_json:
        first = properties["pivot"]
        document = {
            "block": block,
            "configuration": configuration,
            "pivot": pivot,
            "R": first.R,
            "alpha": first.alpha,
            "p": first.p,
            "inertia_about_pivot": first.inertia_about_pivot,
            "uplift_threshold": first.uplift_threshold,
            "restitution": rocking.restitution,
            "other_pivot": {
                "R": properties["other"].R,
                "alpha": properties["other"].alpha,
                "p": properties["other"].p,
                "uplift_threshold": properties["other"].uplift_threshold,
            },
            "rectangular": [
                {"amplitude": float(a), "housner": _finite(h), "exact": _finite(e)}
                for a, h, e in zip(
                    rectangular.amplitude, rectangular.housner, rectangular.exact, strict=True
                )
            ],
            "half_sine": [
                {
                    "frequency": float(f),
                    "housner": _finite(half_sine.limits["housner"][k]),
                    "linear": _finite(half_sine.limits["makris-roussos"][k]),
                    "exact": _finite(half_sine.limits["exact"][k]),
                }
                for k, f in enumerate(half_sine.frequency)
            ],
            "one_sine": [
                {"frequency": float(f), "exact": _finite(one_sine.limits["exact"][k])}
                for k, f in enumerate(one_sine.frequency)
            ],
            "one_cosine": [
                {"frequency": float(f), "exact": _finite(one_cosine.limits["exact"][k])}
                for k, f in enumerate(one_cosine.frequency)
            ],
            "operating_amplitude": operating,
            "overturns_below_frequency": {
                k: _finite(v) for k, v in curves.operating_frequency.items()
            },
            "spectrum_check": {
                name: {
                    "verdict": check.verdict,
                    "min_ratio": _finite(check.min_ratio),
                    "frequency": _finite(check.frequency_at_min),
                    "spectrum": check.spectrum_label,
                }
                for name, check in checks.items()
            },
            "weight": "m (g - a_v)" if include_vertical else "m g",
            "vertical_acceleration": vertical_for_overturning(model) if include_vertical else 0.0,
            "conclusion": CONCLUSION,
        }
        return document

    out = console()
    out.print(
        f"[bold]{escape(model.name)}[/]: "
        + escape(f"overturning of {block!r} in {configuration!r} (paper section 5); {weight}")
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
        table = Table(title=escape(f"Spectrum check (paper Fig. 8): {horizontal.label}"))
        for header in ("limit", "verdict", "min. limit / spectrum [-]", "at [Hz]"):
            table.add_column(escape(header))
        for name, check in checks.items():
            table.add_row(
                name, check.verdict, f"{check.min_ratio:.2f}", f"{check.frequency_at_min:.2f}"
            )
        out.print(table)
    return None


def register(app: typer.Typer) -> None:
    """Add the command of this module to ``app``."""
    app.command("overturn")(overturn)
