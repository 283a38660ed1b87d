"""``freestand frequency``: vertical frequency of the bridge, jump check (paper section 6)."""

from __future__ import annotations

import json
from pathlib import Path

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


def frequency(
    model_file: Path = typer.Argument(..., help="Model file (TOML) with a [beam] section."),
    positions: str = typer.Option(
        None,
        "--positions",
        help="Cart positions from the left support, e.g. 1.33,4.9 (bare numbers in m) or '133 cm'.",
    ),
    spectrum: str = typer.Option(
        None,
        "--spectrum",
        help="Vertical spectrum: a model spectrum's name, a CSV file, or "
        "'rg1.60:pga=0.3g,damping=5%,direction=vertical' / 'en1998:ag=...,direction=vertical'. "
        "Default: the model's vertical spectrum.",
    ),
    plot: Path = typer.Option(
        None,
        "--plot",
        help="Folder to write the Fig. 9 analogue into (PNG, SVG); created if missing.",
    ),
    as_json: bool = typer.Option(False, "--json", help="Write one JSON document to stdout."),
) -> None:
    """Lowest vertical frequency against the cart's position, and whether the cart may jump."""
    from freestand.api.frequency import frequency as frequency_of

    model = load(model_file)
    check_folder(plot, "--plot")
    values = parse_numbers(positions, "--positions", "m", "length")
    vertical = resolve_spectrum(spectrum, model, "vertical") if model.beam is not None else None
    result = frequency_of(model, values, spectrum=vertical)
    sweep, full_sweep, check, parking = (
        result.sweep,
        result.full_sweep,
        result.check,
        result.parking,
    )
    outside_note = result.note

    written: list[Path] = []
    if plot is not None:
        from freestand.plot.frequency import save_frequency_figure

        with staging() as stage:
            save_frequency_figure(result.plot(), stage.folder(plot) / "fig9_frequency")
            written = stage.commit()

    if as_json:
        document = result.to_dict()
        document["figures"] = [str(path) for path in written]
        typer.echo(json.dumps(document, indent=2))
        return

    out = console()
    out.print(
        f"[bold]{escape(model.name)}[/]: lowest vertical natural frequency of the bridge "
        "(paper section 6)"
    )
    table = Table(title="Frequency against the cart's position (paper Fig. 9)")
    for header in (
        "position [m]",
        "Dunkerley [Hz]",
        "exact [Hz]",
        "S_a,v [m/s^2]",
        "S_a,v / g [-]",
        "verdict",
    ):
        table.add_column(
            escape(header), justify="right" if "[" in header or "/" in header else "left"
        )
    step = max(1, len(sweep.position) // 25) if values is None else 1
    for k in range(0, len(sweep.position), step):
        cells = [f"{sweep.position[k]:.2f}", f"{sweep.dunkerley[k]:.2f}", f"{sweep.exact[k]:.2f}"]
        if check is not None:
            cells += [
                f"{check.spectral_acceleration[k]:.2f}",
                f"{check.ratio[k]:.2f}",
                str(check.verdict[k]),
            ]
        else:
            cells += ["", "", "no vertical spectrum"]
        table.add_row(*cells, style="red" if check is not None and check.at_risk[k] else None)
    out.print(table)
    low, high = full_sweep.frequency_range(parking, method="dunkerley")
    exact_low, exact_high = full_sweep.frequency_range(parking, method="exact")
    out.print(
        f"Parking range {parking[0]:g}-{parking[1]:g} m: Dunkerley {low:.1f}-{high:.1f} Hz, "
        f"exact {exact_low:.1f}-{exact_high:.1f} Hz (Dunkerley is a lower bound)."
    )
    if outside_note:
        out.print(f"[yellow]note:[/] {escape(outside_note)}")
    if check is not None:
        runs = ", ".join(f"{a:.2f}-{b:.2f} m" for a, b in check.risk_intervals) or "none"
        out.print(escape(f"Vertical spectrum: {check.spectrum_label}"))
        out.print(
            f"Verdict: [bold]{check.status}[/]; positions at risk: {runs}; smallest margin "
            f"g - S_a = {check.minimum_margin:.2f} m/s^2 at {check.minimum_margin_position:.2f} m."
        )
        for note in check.notes:
            out.print(f"[yellow]note:[/] {escape(note)}")
    for path in written:
        out.print(escape(f"wrote {path}"), highlight=False)


def register(app: typer.Typer) -> None:
    """Add the command of this module to ``app``."""
    app.command("frequency")(frequency)
