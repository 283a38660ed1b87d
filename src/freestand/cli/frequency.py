"""``freestand frequency``: vertical frequency of the bridge, jump check (paper section 6)."""

from __future__ import annotations

import json
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
from freestand.core.structure.beam import frequency_sweep, jump_check
from freestand.errors import FreestandError


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
    model = load(model_file)
    check_folder(plot, "--plot")
    if model.beam is None:
        raise FreestandError(
            "has no [beam] section; add span, youngs_modulus, second_moment, mass, load_mass "
            "and parking (see the README)",
            source=model.source,
        )
    beam, parking = model.beam.beam, model.beam.parking
    values = parse_numbers(positions, "--positions", "m", "length")
    if values is not None:
        for value in values:
            if not 0 <= value <= beam.span:
                raise FreestandError(
                    f"position {value:g} m is outside the span 0 .. {beam.span:g} m; give "
                    "positions measured from the left support",
                    source="--positions",
                )
    full_sweep = frequency_sweep(beam, parking=parking)
    sweep = full_sweep if values is None else frequency_sweep(beam, np.array(values))
    vertical = resolve_spectrum(spectrum, model, "vertical")
    tolerance = 1e-9 * beam.span
    parked = [parking[0] - tolerance <= p <= parking[1] + tolerance for p in sweep.position]
    outside_note = None
    if not all(parked):
        outside = ", ".join(
            f"{p:g}" for p, inside in zip(sweep.position, parked, strict=True) if not inside
        )
        outside_note = (
            f"position(s) {outside} m lie outside the parking range {parking[0]:g}-"
            f"{parking[1]:g} m: the cart does not park there"
            + ("; their jump verdict is given as if it did" if vertical else "")
        )
    check = None
    if vertical:
        # the jump check counts parked positions only; for positions asked outside the
        # parking range alone, it is made as if the cart parked there (and says so)
        check = jump_check(sweep, vertical, model.gravity, parking=parking if any(parked) else None)

    written: list[Path] = []
    if plot is not None:
        from freestand.plot.frequency import plot_frequency_sweep, save_frequency_figure

        full_check = check
        if vertical is not None and sweep is not full_sweep:
            full_check = jump_check(full_sweep, vertical, model.gravity, parking=parking)
        figure = plot_frequency_sweep(
            full_sweep, parking=parking, jump=full_check, vertical_spectrum=vertical
        )
        with staging() as stage:
            save_frequency_figure(figure, stage.folder(plot) / "fig9_frequency")
            written = stage.commit()

    if as_json:
        rows = []
        for k, position in enumerate(sweep.position):
            row = {
                "position": float(position),
                "dunkerley": float(sweep.dunkerley[k]),
                "exact": float(sweep.exact[k]),
            }
            if check is not None:
                row.update(
                    spectral_acceleration=float(check.spectral_acceleration[k]),
                    ratio_to_g=float(check.ratio[k]),
                    verdict=str(check.verdict[k]),
                )
            rows.append(row)
        document = {"model": model.name, "parking": list(parking), "positions": rows}
        if outside_note:
            document["note"] = outside_note
        if check is not None:
            document["jump_check"] = {
                "spectrum": check.spectrum_label,
                "basis": check.basis,
                "status": check.status,
                "positions_at_risk": [float(p) for p in check.positions_at_risk],
                "risk_intervals": [list(run) for run in check.risk_intervals],
                "minimum_margin": check.minimum_margin,
                "minimum_margin_position": check.minimum_margin_position,
                "notes": list(check.notes),
            }
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
