"""Units at the input boundary.

Bare numbers are SI. A string with a unit (``"2.70 m/s^2"``, ``"0.275 g"``,
``"16.6 t"``, ``"9.8 m"``) is converted with pint to the SI unit of the field.
For accelerations the unit ``g`` means the model's gravitational acceleration
(9.81 m/s^2 unless the model file says otherwise), not the gram.
"""

from __future__ import annotations

import functools
import math
import re

from freestand.errors import FreestandError

#: SI unit and a human example for each kind of quantity a model file holds.
QUANTITIES: dict[str, tuple[str, str]] = {
    "length": ("m", '9.8 or "980 cm"'),
    "mass": ("kg", '16600 or "16.6 t"'),
    "inertia": ("kg*m^2", '49400 or "49.4 t*m^2"'),
    "acceleration": ("m/s^2", '2.70 or "2.70 m/s^2" or "0.275 g"'),
    "frequency": ("Hz", '2.5 or "2.5 Hz"'),
    "time": ("s", '0.005 or "5 ms"'),
    "pressure": ("Pa", '2.1e11 or "210 GPa"'),
    "second_moment": ("m^4", '0.014 or "1.4e6 cm^4"'),
    "dimensionless": ("", "0.25"),
}

#: Largest plausible magnitude of each kind of quantity [SI]. Beyond it a value is a typo or
#: a wrong unit (a mass of 1e300 kg, a record of 1e150 g) and the arithmetic would overflow.
LIMITS: dict[str, float] = {
    "length": 1e4,  # 10 km
    "mass": 1e9,  # a million tonnes
    "inertia": 1e15,  # kg m^2: a million tonnes at 30 m
    "acceleration": 1e4,  # about 1000 g
    "frequency": 1e4,  # Hz
    "time": 1e6,  # s, about 11 days
    "pressure": 1e13,  # Pa, 50 times the modulus of steel
    "second_moment": 1e4,  # m^4
    "dimensionless": 1e6,
}

_G_TOKEN = re.compile(r"(?<![A-Za-z_])g(?![A-Za-z_0-9])")


@functools.lru_cache(maxsize=1)
def _registry():
    import pint

    return pint.UnitRegistry()


def _is_plain_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def to_si(
    value: object,
    quantity: str,
    *,
    field: str,
    source: str | None = None,
    gravity: float = 9.81,
) -> float:
    """Convert a model-file value to a float in SI units.

    Parameters
    ----------
    value : float or int or str
        A bare number (already SI) or a string ``"<number> <unit>"``.
    quantity : str
        One of :data:`QUANTITIES` (``"length"``, ``"mass"``, ``"acceleration"``...).
    field : str
        Dotted field path, used in error messages.
    source : str, optional
        File name, used in error messages.
    gravity : float, optional
        Gravitational acceleration [m/s^2] that the unit ``g`` stands for in
        accelerations.

    Returns
    -------
    float
        The value in the SI unit of ``quantity``.

    Raises
    ------
    FreestandError
        If the value is not a number, has the wrong dimension, is not finite
        or is beyond the plausible magnitude of :data:`LIMITS`.
    """
    unit, example = QUANTITIES[quantity]
    fix = (
        f"give {quantity} as a bare SI number ({unit or 'no unit'}) or a string with a unit, "
        f"e.g. {example}"
    )
    if isinstance(value, bool):
        raise FreestandError(f"{value!r} is not a number; {fix}", source=source, field=field)
    if isinstance(value, int | float):
        result = float(value)
    elif isinstance(value, str) and _is_plain_number(value):
        # a bare number written as text (command-line options): already SI
        result = float(value)
    elif isinstance(value, str) and not any(c.isdigit() for c in value):
        raise FreestandError(
            f"cannot read {value!r} as a quantity: it is not a number; {fix}",
            source=source,
            field=field,
        )
    elif isinstance(value, str):
        text = value.strip()
        if quantity == "acceleration":
            text = _G_TOKEN.sub(
                lambda match: (
                    ("* " if text[: match.start()].rstrip()[-1:].isdigit() else "")
                    + f"({gravity!r} m/s^2)"
                ),
                text,
            )
        ureg = _registry()
        try:
            parsed = ureg.parse_expression(text)
        except Exception as exc:  # pint raises several unrelated classes
            raise FreestandError(
                f"cannot read {value!r} as a quantity ({exc.__class__.__name__}); {fix}",
                source=source,
                field=field,
            ) from None
        if not hasattr(parsed, "to"):
            result = float(parsed)
        else:
            try:
                result = float(parsed.to(unit or "dimensionless").magnitude)
            except Exception:
                raise FreestandError(
                    f"{value!r} has units of {parsed.dimensionality}, not {quantity}; {fix}",
                    source=source,
                    field=field,
                ) from None
    else:
        raise FreestandError(f"{value!r} is not a number; {fix}", source=source, field=field)
    if not math.isfinite(result):
        raise FreestandError(f"{value!r} is not finite; {fix}", source=source, field=field)
    limit = LIMITS[quantity]
    if abs(result) > limit:
        suffix = f" {unit}" if unit else ""
        raise FreestandError(
            f"{value!r} is {result:.3g}{suffix}, beyond the plausible {limit:g}{suffix}; "
            f"check the value and its unit ({fix})",
            source=source,
            field=field,
        )
    return result


def damping_fraction(value, *, field: str, source: str) -> float:
    """Damping as a fraction: 0.05, "5 %" or "5%"."""
    if isinstance(value, str) and value.strip().endswith("%"):
        try:
            result = float(value.strip()[:-1]) / 100.0
        except ValueError:
            raise FreestandError(
                f'{value!r} is not a percentage; write e.g. "5 %"', source=source, field=field
            ) from None
    else:
        result = to_si(value, "dimensionless", field=field, source=source)
    if not 0 <= result < 1:
        raise FreestandError(
            f'{value!r} is not a fraction of critical damping; give e.g. 0.05 or "5 %"',
            source=source,
            field=field,
        )
    return result
