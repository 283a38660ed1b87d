"""The 3-D block of a model file: a ``[[configuration.block]]`` with a ``shape``.

::

    [[configuration.block]]
    name = "cabinet"
    shape = "box"                     # or "cylinder" with radius, height, inner_radius
    size = [0.8, 0.6, 2.0]            # lx, ly, lz [m]
    mass = 400                        # kg
    centre = [0.0, 0.0, 1.0]          # optional, m: x, y, z of G (default: the geometric centre)
    inertia = [150, 155, 35]          # optional, kg m^2 about G: principal values or a 3x3 matrix
    friction = { static = 0.5, kinetic = 0.4 }

A block with ``shape`` (or any key only a 3-D block has: ``size``, ``radius``,
``height``, ``inner_radius``) is read by :class:`BodySpec`, any other by the
planar block's schema (:mod:`freestand.io.model_file`): :func:`block_kind`
tells them apart. The values go to :class:`freestand.core.body.Body`, whose
own checks (the centre over the base, the inner radius below the radius)
are reported with the block's field path like the schema's.

The inertia about G must be symmetric positive definite and its principal
values I_1, I_2, I_3 must satisfy the triangle inequalities
``I_i <= I_j + I_k``, which every mass distribution does (the principal
moments are sums of second moments of the mass, e.g. Meriam and Kraige,
*Engineering Mechanics: Dynamics*, Appendix B).
"""

from __future__ import annotations

from typing import Any, ClassVar

import numpy as np
from pydantic import field_validator, model_validator

from freestand.core.body import Body, Box, Cylinder
from freestand.core.model import Friction
from freestand.errors import FreestandError
from freestand.io.schema import (
    Quantity,
    _FrictionSpec,
    _mass_value,
    _name_value,
    _quantity,
    _Strict,
)

#: The shapes a 3-D block can have.
SHAPES = ("box", "cylinder")

#: Keys only a 3-D block has: a block with any of them is read as 3-D.
BODY_ONLY_KEYS = ("shape", "size", "radius", "height", "inner_radius")

#: Keys only a planar block has.
PLANAR_ONLY_KEYS = ("base", "sliding")

_SIZE_EXAMPLE = "size = [0.8, 0.6, 2.0]"
_INERTIA_EXAMPLE = "inertia = [150, 155, 35]"


def block_kind(value: Any) -> str:
    """``"3-D"`` for a block with a 3-D key (:data:`BODY_ONLY_KEYS`), else ``"planar"``."""
    if isinstance(value, dict):
        return "3-D" if set(BODY_ONLY_KEYS) & set(value) else "planar"
    return "3-D" if isinstance(value, BodySpec) else "planar"


def _length_list(value: Any, count: int, info, what: str, example: str) -> tuple[float, ...]:
    if not isinstance(value, list | tuple) or len(value) != count:
        raise ValueError(f"{value!r} is not {what}; give {count} lengths in m, e.g. {example}")
    return tuple(_quantity(item, "length", info) for item in value)


def _positive_length(value: float, what: str, example: str) -> float:
    if not value > 0:
        raise ValueError(f"{value!r} m is not positive; the {what} must be > 0 m, e.g. {example}")
    return value


def _inertia_entries(value: Any, info) -> tuple:
    """Three principal values or a 3x3 matrix of inertias [kg m^2], as tuples of floats."""
    fix = (
        "give 3 principal values about the centre of gravity in kg m^2, e.g. "
        f"{_INERTIA_EXAMPLE}, or a symmetric 3x3 matrix [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], "
        "[Ixz, Iyz, Izz]], or leave it out for the homogeneous body"
    )
    if isinstance(value, list | tuple) and len(value) == 3:
        if all(isinstance(row, list | tuple) and len(row) == 3 for row in value):
            return tuple(tuple(_quantity(v, "inertia", info) for v in row) for row in value)
        if not any(isinstance(row, list | tuple) for row in value):
            return tuple(_quantity(v, "inertia", info) for v in value)
    raise ValueError(f"{value!r} is not a 3-D inertia; {fix}")


def check_inertia(entries: tuple) -> np.ndarray:
    """The inertia matrix [kg m^2] of principal values or a matrix, checked (module docstring).

    Raises
    ------
    ValueError
        Not symmetric, not positive definite, or principal values that break
        the triangle inequality; the message gives the value and the fix.
    """
    matrix = np.asarray(entries, dtype=float)
    if matrix.ndim == 1:
        matrix = np.diag(matrix)
    shown = np.asarray(entries).tolist()
    scale = np.abs(matrix).max()
    if not np.allclose(matrix, matrix.T, rtol=0.0, atol=1e-9 * scale):
        raise ValueError(
            f"{shown} kg m^2 is not symmetric (Ixy, Ixz, Iyz must equal Iyx, Izx, Izy); "
            "give a symmetric 3x3 matrix or 3 principal values, e.g. " + _INERTIA_EXAMPLE
        )
    principal = np.linalg.eigvalsh(matrix)
    if principal.min() <= 0.0:
        raise ValueError(
            f"{shown} kg m^2 is not positive definite (principal values "
            f"{', '.join(f'{p:.4g}' for p in principal)} kg m^2); every principal value must be "
            f"> 0: check the signs and the units, e.g. {_INERTIA_EXAMPLE}"
        )
    if principal[2] > (principal[0] + principal[1]) * (1.0 + 1e-9):
        raise ValueError(
            f"{shown} kg m^2 has principal values {', '.join(f'{p:.4g}' for p in principal)} "
            f"kg m^2: the largest exceeds the sum of the other two, which no mass distribution "
            f"gives; check the values (about the centre of gravity), e.g. {_INERTIA_EXAMPLE}"
        )
    return matrix


class BodySpec(_Strict):
    """A ``[[configuration.block]]`` with a ``shape``: one rigid body in 3-D."""

    #: Title of the model-file reference's table of these keys.
    reference_title: ClassVar[str] = "3-D blocks: `[[configuration.block]]` with `shape`"

    name: str
    _name = field_validator("name", mode="before")(_name_value)
    shape: str
    size: tuple[Quantity, Quantity, Quantity] | None = None
    radius: Quantity | None = None
    height: Quantity | None = None
    inner_radius: Quantity = 0.0
    mass: Quantity
    centre: tuple[Quantity, Quantity, Quantity] | None = None
    inertia: tuple[Quantity, Quantity, Quantity] | tuple[tuple, tuple, tuple] | None = None
    friction: _FrictionSpec

    _mass = field_validator("mass", mode="before")(_mass_value)

    @model_validator(mode="before")
    @classmethod
    def _planar_keys(cls, data):
        if isinstance(data, dict):
            planar = [key for key in PLANAR_ONLY_KEYS if key in data]
            if planar:
                raise ValueError(
                    f"{' and '.join(planar)} belong(s) to planar blocks; a block with shape is a "
                    "3-D body standing on its lower face: remove "
                    f"{' and '.join(planar)} (or remove shape, size, radius, height for a planar "
                    "block)"
                )
        return data

    @field_validator("shape", mode="before")
    @classmethod
    def _shape(cls, value):
        if value not in SHAPES:
            raise ValueError(
                f'{value!r} is not a shape; use "box" (with size = [lx, ly, lz]) or "cylinder" '
                "(with radius and height)"
            )
        return value

    @field_validator("size", mode="before")
    @classmethod
    def _size(cls, value, info):
        sides = _length_list(value, 3, info, "[lx, ly, lz]", _SIZE_EXAMPLE)
        for name, side in zip(("lx", "ly", "lz"), sides, strict=True):
            if not side > 0:
                raise ValueError(
                    f"{list(value)!r}: the side {name} = {side!r} m is not positive; give the "
                    f"box's sides [lx, ly, lz] > 0 in m, e.g. {_SIZE_EXAMPLE}"
                )
        return sides

    @field_validator("radius", "height", mode="before")
    @classmethod
    def _cylinder_length(cls, value, info):
        example = "radius = 0.9" if info.field_name == "radius" else "height = 4.0"
        length = _quantity(value, "length", info)
        return _positive_length(length, f"cylinder's {info.field_name}", example)

    @field_validator("inner_radius", mode="before")
    @classmethod
    def _inner_radius(cls, value, info):
        length = _quantity(value, "length", info)
        if length < 0:
            raise ValueError(
                f"{length!r} m is negative; the inner radius of a hollow cylinder is >= 0 m "
                "(0, the default, for a solid one), e.g. inner_radius = 0.6"
            )
        return length

    @field_validator("centre", mode="before")
    @classmethod
    def _centre(cls, value, info):
        return _length_list(
            value, 3, info, "[x, y, z] (a 3-D block's centre)", "centre = [0.0, 0.0, 1.0]"
        )

    @field_validator("inertia", mode="before")
    @classmethod
    def _inertia(cls, value, info):
        entries = _inertia_entries(value, info)
        check_inertia(entries)
        return entries

    @model_validator(mode="after")
    def _dimensions(self):
        given = {key for key in ("size", "radius", "height") if getattr(self, key) is not None}
        if self.inner_radius:
            given.add("inner_radius")
        if self.shape == "box":
            wrong, missing = given - {"size"}, [] if self.size is not None else ["size"]
            fix = f"a box takes size = [lx, ly, lz] in m, e.g. {_SIZE_EXAMPLE}"
        else:
            wrong = given & {"size"}
            missing = [key for key in ("radius", "height") if getattr(self, key) is None]
            fix = "a cylinder takes radius and height in m, e.g. radius = 0.9, height = 4.0"
        if missing:
            raise FreestandError(
                f"is missing for shape = {self.shape!r}; {fix}", field=" and ".join(missing)
            )
        if wrong:
            raise FreestandError(
                f"does not apply to shape = {self.shape!r}; {fix}", field=", ".join(sorted(wrong))
            )
        try:
            shape = self._shape_object()
        except FreestandError as error:
            raise FreestandError(
                f"{error.detail}; give a smaller inner radius, or 0 for a solid cylinder",
                field="inner_radius",
            ) from None
        try:
            self.to_body(shape)
        except FreestandError as error:
            raise FreestandError(
                f"{error.detail}; give x, y inside the base and z > 0 (from the base centre), "
                "or leave centre out for the geometric centre",
                field="centre",
            ) from None
        return self

    def _shape_object(self) -> Box | Cylinder:
        if self.shape == "box":
            return Box(tuple(float(side) for side in self.size))
        return Cylinder(float(self.radius), float(self.height), float(self.inner_radius))

    def to_body(self, shape: Box | Cylinder | None = None) -> Body:
        """The :class:`~freestand.core.body.Body` (SI floats)."""
        return Body(
            name=self.name,
            shape=shape or self._shape_object(),
            mass=float(self.mass),
            friction=Friction(self.friction.static, self.friction.kinetic),
            centre=None if self.centre is None else tuple(float(c) for c in self.centre),
            inertia=None if self.inertia is None else check_inertia(self.inertia),
        )
