"""The ``[beam]`` section of a model file: the bridge under the parked cart.

Example (paper section 6)::

    [beam]
    span = 9.8                # m
    youngs_modulus = 2.1e11   # Pa
    second_moment = 0.014     # m^4
    mass = 16600              # kg, the beam's own mass, uniformly distributed
    load_mass = 25600         # kg, the cart, a point mass
    parking = [1.33, 8.47]    # m, range of the cart's centre from the left support
    # optional:
    load_rotary_inertia = 124100   # kg m^2, the cart about its centre
    load_height = 2.83             # m, the cart's centre above the beam's axis

Bare numbers are SI; strings with units are converted by
:func:`freestand.io.units.to_si` (``"210 GPa"``, ``"16.6 t"``, ``"980 cm"``).
"""

from __future__ import annotations

from dataclasses import dataclass

from freestand.core.structure.beam import SimplySupportedBeam
from freestand.errors import FreestandError
from freestand.io.units import to_si

#: field name -> (quantity for to_si, required, rule, what it is)
BEAM_FIELDS: dict[str, tuple[str, bool, str, str]] = {
    "span": ("length", True, "positive", "the distance between the supports"),
    "youngs_modulus": ("pressure", True, "positive", "the modulus of elasticity E"),
    "second_moment": ("second_moment", True, "positive", "the second moment of area I"),
    "mass": ("mass", True, "non-negative", "the beam's own mass, uniformly distributed"),
    "load_mass": ("mass", True, "non-negative", "the cart's mass, a point mass"),
    "load_rotary_inertia": (
        "inertia",
        False,
        "non-negative",
        "the cart's rotary inertia about its centre",
    ),
    "load_height": ("length", False, "any", "the height of the cart's centre above the axis"),
}


@dataclass(frozen=True)
class BeamSection:
    """A validated ``[beam]`` section.

    Parameters
    ----------
    beam : SimplySupportedBeam
        The bridge and its cart.
    parking : tuple of float
        The range ``(first, last)`` of the cart's centre, measured from the
        left support [m]; ``0 <= first <= last <= span``.
    """

    beam: SimplySupportedBeam
    parking: tuple[float, float]


def parse_beam_section(data: dict, *, source: str, gravity: float = 9.81) -> BeamSection:
    """Validate the ``[beam]`` table of a model file and convert it to SI.

    Parameters
    ----------
    data : dict
        The ``[beam]`` table as read from TOML.
    source : str
        The file the table came from, for error messages.
    gravity : float, optional
        The model's gravitational acceleration [m/s^2] (for ``g`` in units).

    Returns
    -------
    BeamSection
        The beam and the parking range.

    Raises
    ------
    FreestandError
        Naming the field (``beam.span``...), the value and the fix, when a
        field is missing, unknown, of the wrong unit, out of range, or the
        parking range does not fit on the span.
    """
    if not isinstance(data, dict):
        raise FreestandError(
            f"{data!r} is not a table; write a [beam] section with span, youngs_modulus, "
            "second_moment, mass, load_mass and parking",
            source=source,
            field="beam",
        )
    known = set(BEAM_FIELDS) | {"parking"}
    for key in data:
        if key not in known:
            raise FreestandError(
                f"unknown key {key!r}; remove it or give one of {', '.join(sorted(known))}",
                source=source,
                field=f"beam.{key}",
            )
    values: dict[str, float] = {}
    for name, (quantity, required, rule, meaning) in BEAM_FIELDS.items():
        field_name = f"beam.{name}"
        if name not in data:
            if required:
                raise FreestandError(
                    f"missing; give {meaning} (e.g. {name} = ...)",
                    source=source,
                    field=field_name,
                )
            continue
        value = to_si(data[name], quantity, field=field_name, source=source, gravity=gravity)
        if rule == "positive" and value <= 0:
            raise FreestandError(
                f"{data[name]!r} must be positive; give {meaning} as a number above 0",
                source=source,
                field=field_name,
            )
        if rule == "non-negative" and value < 0:
            raise FreestandError(
                f"{data[name]!r} must not be negative; give {meaning} as 0 or more",
                source=source,
                field=field_name,
            )
        values[name] = value
    if values["mass"] == 0 and values["load_mass"] == 0:
        raise FreestandError(
            "the beam's mass and the load's mass are both 0, so nothing vibrates; "
            "give the beam's own mass in kg",
            source=source,
            field="beam.mass",
        )
    parking = _parse_parking(data, values["span"], source=source, gravity=gravity)
    try:
        beam = SimplySupportedBeam(**values)
    except FreestandError as error:  # any remaining check, re-labelled for the file
        raise FreestandError(error.detail, source=source, field=f"beam.{error.field}") from None
    return BeamSection(beam=beam, parking=parking)


def _parse_parking(
    data: dict, span: float, *, source: str | None, gravity: float
) -> tuple[float, float]:
    field_name = "beam.parking"
    fix = (
        f"give the first and last position of the cart's centre from the left support, "
        f"within the span, e.g. parking = [1.33, {span - 1.33:.2f}]"
        if span > 2.66
        else f"give [first, last] within the span 0..{span:g} m"
    )
    if "parking" not in data:
        raise FreestandError(f"missing; {fix}", source=source, field=field_name)
    raw = data["parking"]
    if isinstance(raw, str) or not isinstance(raw, list | tuple) or len(raw) != 2:
        raise FreestandError(
            f"{raw!r} is not a pair of lengths; {fix}", source=source, field=field_name
        )
    first, last = (
        to_si(item, "length", field=f"{field_name}[{i}]", source=source, gravity=gravity)
        for i, item in enumerate(raw)
    )
    tolerance = 1e-9 * span
    if first > last:
        raise FreestandError(
            f"{raw!r} runs backwards ({first:g} m > {last:g} m); give the smaller position first",
            source=source,
            field=field_name,
        )
    if first < -tolerance or last > span + tolerance:
        raise FreestandError(
            f"{raw!r} does not fit on the span of {span:g} m (beam.span); {fix}",
            source=source,
            field=field_name,
        )
    first = min(max(first, 0.0), span)
    last = min(max(last, 0.0), span)
    return (first, last)
