"""Pieces of the model-file schema shared by its tables: strict tables, names, quantities, friction.

Used by :mod:`freestand.io.model_file` (planar blocks, excitations) and
:mod:`freestand.io.body_spec` (3-D blocks). A validator raises ``ValueError``
with the value and the fix; the loader adds the file and the field path.
"""

from __future__ import annotations

import math
from typing import Any

from pydantic import BaseModel, ConfigDict, field_validator, model_validator

from freestand.io.units import to_si

Quantity = float | int | str


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


def _name_value(value: Any) -> Any:
    if isinstance(value, str) and not value.strip():
        raise ValueError(f'{value!r} is an empty name; give a name, e.g. name = "bridge"')
    return value


def _gravity(info) -> float:
    return (info.context or {}).get("gravity", 9.81)


def _quantity(value: Any, quantity: str, info) -> float:
    # The file and field path are added when the ValidationError is translated.
    return to_si(value, quantity, field="", gravity=_gravity(info))


def _positive(value: float, what: str, example: str) -> float:
    if not value > 0:
        raise ValueError(f"{value!r} is not positive; the {what} must be > 0, e.g. {example}")
    return value


#: Largest friction coefficient accepted [-]; a block that must never slip is given
#: ``sliding = "none"`` instead of a huge coefficient.
FRICTION_LIMIT = 100.0


class _FrictionSpec(_Strict):
    static: float
    kinetic: float

    @field_validator("static", "kinetic", mode="after")
    @classmethod
    def _finite(cls, value, info):
        if not math.isfinite(value) or abs(value) > FRICTION_LIMIT:
            raise ValueError(
                f"{info.field_name} = {value!r} is not a friction coefficient; give a finite "
                f"number between 0 and {FRICTION_LIMIT:g}, e.g. {info.field_name} = 0.25 "
                '(for an interface that never slips write sliding = "none")'
            )
        return value

    @model_validator(mode="after")
    def _order(self):
        if self.static < 0 or self.kinetic < 0:
            raise ValueError(
                f"friction coefficients must be >= 0 (static = {self.static}, "
                f"kinetic = {self.kinetic})"
            )
        if self.kinetic > self.static:
            raise ValueError(
                f"kinetic = {self.kinetic} is above static = {self.static}; the kinetic "
                "coefficient must not exceed the static one (swap them?)"
            )
        return self


#: Smallest mass [kg] and moment of inertia [kg m^2] accepted: below them the equations of
#: motion are ill-conditioned beside any real block (a mass of 1e-300 kg is a typo).
MASS_FLOOR = 1e-3
INERTIA_FLOOR = 1e-6


def _floor(value: float, floor: float, what: str, unit: str, example: str) -> float:
    if value < floor:
        raise ValueError(
            f"{value!r} {unit} is below the smallest plausible {what} ({floor:g} {unit}); "
            f"check the value and its unit, e.g. {example}"
        )
    return value


def _mass_value(value: Any, info) -> float:
    mass = _positive(_quantity(value, "mass", info), "mass", '16600 or "16.6 t"')
    return _floor(mass, MASS_FLOOR, "mass", "kg", '16600 or "16.6 t"')


def _inertia_value(value: Any, info) -> float:
    inertia = _positive(
        _quantity(value, "inertia", info), "moment of inertia about the centre", "49400"
    )
    return _floor(inertia, INERTIA_FLOOR, "moment of inertia", "kg m^2", "49400")
