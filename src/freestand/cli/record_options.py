"""The record options shared by ``freestand simulate`` and ``freestand report``.

The files (``--record`` x, ``--record-y``, ``--vertical``), their sampling for
single-column files (``--dt``, ``--unit``), the scaling (``--scale``,
``--peak``, ``--spectral``: one factor, from the x component, for every
component) and the turn of the horizontal pair (``--angle``).
:func:`read_record` checks them all and reads the record.
"""

from __future__ import annotations

import math
from pathlib import Path

import typer

from freestand.cli.common import number
from freestand.errors import FreestandError
from freestand.io.records import check_record_values, load_record, parse_spectral_target

RECORD_Y = typer.Option(
    None,
    "--record-y",
    help="Second horizontal record, along y (3-D configurations only; any record format).",
)
VERTICAL = typer.Option(None, "--vertical", help="Vertical record (positive up, as recorded).")
ANGLE = typer.Option(
    None,
    "--angle",
    help="Turn the horizontal pair by this angle [deg], counter-clockwise from +x towards +y: "
    "the record's x axis then points at ANGLE (3-D configurations only).",
)
DT = typer.Option(
    None, "--dt", help="Time step of single-column records, e.g. 0.005 [s] or '5 ms'."
)
UNIT = typer.Option(None, "--unit", help="Unit of single-column records, e.g. g or m/s^2.")
SCALE = typer.Option(None, "--scale", help="Multiply the record(s) by this factor [-].")
PEAK = typer.Option(
    None,
    "--peak",
    help="Scale the records so that the x record's peak is this, e.g. 0.3g or '2.9 m/s^2' "
    "(bare numbers in m/s^2; one factor for every component; instead of --scale).",
)
SPECTRAL = typer.Option(
    None,
    "--spectral",
    help="Scale the records so that the x record's pseudo-acceleration at one frequency is A: "
    "'A@F[,DAMPING]', e.g. '1.05g@2.5Hz,5%' (one factor for every component; instead of "
    "--scale).",
)


def check_angle(angle: float | None) -> None:
    """FreestandError for an angle that is not a finite number of degrees."""
    if angle is not None and not math.isfinite(angle):
        raise FreestandError(
            f"{angle} is not an angle; give the direction of the record's x axis in degrees, "
            "e.g. --angle 30",
            source="--angle",
        )


def read_record(
    model,
    record: Path,
    *,
    record_y: Path | None = None,
    vertical: Path | None = None,
    dt: str | None = None,
    unit: str | None = None,
    scale: float | None = None,
    peak: str | None = None,
    spectral: str | None = None,
):
    """The record of the options, scaled, its values checked (a GroundMotion).

    Every option is checked before a file is read; the factor of ``--peak``
    and ``--spectral`` is taken from the x component and applied to every
    component (:meth:`~freestand.core.motion.ground_motion.GroundMotion.scaled`).
    """
    if sum(option is not None for option in (scale, peak, spectral)) > 1:
        raise FreestandError(
            "give one of --scale, --peak and --spectral, not several", source="--scale"
        )
    target = None if spectral is None else parse_spectral_target(spectral, gravity=model.gravity)
    peak_value = number(peak, "--peak", "acceleration", model.gravity)
    step = number(dt, "--dt", "time")
    if scale is not None and not (math.isfinite(scale) and scale != 0):
        raise FreestandError(
            f"{scale} is not a scale factor; give a finite, non-zero number, e.g. --scale 1.5",
            source="--scale",
        )
    if peak_value is not None and not peak_value > 0:
        raise FreestandError(
            f"{peak} is not a positive peak; e.g. --peak 0.3g or --peak 2.9", source="--peak"
        )
    if step is not None and not (math.isfinite(step) and step > 0):
        raise FreestandError(
            f"{step} is not a positive time step [s]; e.g. --dt 0.005", source="--dt"
        )
    motion = load_record(
        record, dt=step, unit=unit, gravity=model.gravity, vertical=vertical,
        horizontal_y=record_y,
    )  # fmt: skip
    try:
        if scale is not None:
            motion = motion.scaled(scale)
        if peak_value is not None:
            motion = motion.scaled_to_peak(peak_value)
        if target is not None:
            motion = motion.scaled_to_spectral(
                target.acceleration, target.frequency, target.damping
            )
    except ValueError as error:  # an all-zero record cannot be scaled
        raise FreestandError(str(error), source=str(record)) from None
    for values, what in ((motion.horizontal, "scaled horizontal"),
                         (motion.horizontal_y, "scaled y"),
                         (motion.vertical, "scaled vertical")):  # fmt: skip
        if values is not None:
            check_record_values(values, str(record), model.gravity, what)
    return motion
