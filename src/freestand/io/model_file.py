"""Model files: TOML descriptions of stacks, excitations and checks.

The format is documented in the README ("Model file"). Bare numbers are SI;
strings with units are converted with pint (:mod:`freestand.io.units`).
Every problem is reported as one :class:`~freestand.errors.FreestandError`
naming the file, the field, the value and the fix.

A two-block configuration can also be given in the paper's own notation
(Table 1: ``p1, p3, g, h, p2, c, d, r, q`` in the y-z plane, or
``p1, p3, e, f, p2, a, b, s, t`` in the x-z plane); it is converted to
coordinates by :func:`paper_notation_blocks`.

A block with a ``shape`` is a 3-D body (:mod:`freestand.io.body_spec`): its
configuration loads as a :class:`~freestand.core.body.BodyConfiguration`
into :attr:`ModelFile.body_configurations`, beside the planar stacks of
:attr:`ModelFile.configurations`. An excitation's ``y`` is the second
horizontal component of the 3-D configurations.
"""

from __future__ import annotations

import difflib
import hashlib
import tomllib
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Annotated, Any

from pydantic import (
    ConfigDict,
    Discriminator,
    Tag,
    ValidationError,
    field_validator,
    model_validator,
)

from freestand.core.body import BodyConfiguration
from freestand.core.model import VERTICAL_SENSES, Block, Excitation, Friction, Sliding, Stack
from freestand.core.motion.spectra import Spectrum
from freestand.errors import FreestandError
from freestand.io.beam_section import BeamSection, parse_beam_section
from freestand.io.body_spec import BodySpec, block_kind
from freestand.io.schema import (
    Quantity,
    _FrictionSpec,
    _inertia_value,
    _mass_value,
    _name_value,
    _positive,
    _quantity,
    _Strict,
)
from freestand.io.spectrum_input import parse_spectrum_sections
from freestand.io.units import to_si


@dataclass(frozen=True)
class ModelFile:
    """A loaded model file, validated and in SI units.

    Attributes
    ----------
    name : str
        Model name.
    gravity : float
        g [m/s^2].
    excitations : tuple of Excitation
    configurations : tuple of Stack
        The planar configurations, in the file's order.
    source : str
        File name the model was read from (``"<string>"`` for text).
    sha256 : str
        Hash of the file's bytes.
    spectra : dict of str to Spectrum
        The ``[[spectrum]]`` tables, by name.
    beam : BeamSection or None
        The ``[beam]`` table: the bridge as a simply supported beam and the
        cart's parking range (paper section 6).
    fragility : dict or None
        The ``[fragility]`` table as written (a fragility campaign for the
        report; read by :func:`freestand.io.fragility_options.fragility_table`).
    body_configurations : tuple of BodyConfiguration
        The 3-D configurations (a block with ``shape``), in the file's order
        (:class:`freestand.core.body.BodyConfiguration`). The analyses of
        planar stacks see ``configurations`` only; :meth:`configuration`
        refuses a 3-D configuration's name with a message saying so.
    """

    name: str
    gravity: float
    excitations: tuple[Excitation, ...]
    configurations: tuple[Stack, ...]
    source: str = "<string>"
    sha256: str = ""
    base_dir: Path = field(default_factory=Path.cwd)
    spectra: dict = field(default_factory=dict)
    beam: BeamSection | None = None
    fragility: dict | None = None
    body_configurations: tuple[BodyConfiguration, ...] = ()

    def spectrum(self, direction: str) -> Spectrum | None:
        """The model's first spectrum for ``direction`` ("horizontal"/"vertical"), if any."""
        return next((s for s in self.spectra.values() if s.direction == direction), None)

    def warnings(self) -> tuple[str, ...]:
        """What the model allows but an engineer must know: blocks that cannot stand.

        A block whose centre of gravity (together with the blocks it carries)
        lies outside its base tips over even without excitation
        (:meth:`freestand.core.model.Stack.unsupported`).
        """
        messages = []
        for stack in self.configurations:
            for name, x_centre, left, right in stack.unsupported():
                carried = stack.blocks[stack.block_index(name) + 1 :]
                what = f"{name!r} with the blocks on it" if carried else f"{name!r}"
                messages.append(
                    f"{self.source}: configuration {stack.name!r}: the centre of gravity of "
                    f"{what} lies at x = {x_centre:.3f} m, outside its base "
                    f"({left:g} .. {right:g} m), so it cannot stand even without excitation; "
                    "check its centre and base"
                )
        return tuple(messages)

    def configuration(self, name: str) -> Stack:
        """The planar configuration called ``name``, or a FreestandError listing the names.

        A 3-D configuration's name gives an error saying that this analysis
        takes planar configurations (:meth:`body_configuration` gives it).
        """
        for stack in self.configurations:
            if stack.name == name:
                return stack
        if any(body.name == name for body in self.body_configurations):
            raise FreestandError(
                f"configuration {name!r} is 3-D (a block with shape); this analysis takes "
                f"planar configurations only{self._planar_choice()}. 3-D configurations are "
                "screened by `freestand screen` (fs.screen), simulated by `freestand simulate` "
                "(fs.simulate) and reported by `freestand report`",
                source=self.source,
            )
        raise FreestandError(
            f"no configuration named {name!r}; choose one of {self._known()}", source=self.source
        )

    def body_configuration(self, name: str) -> BodyConfiguration:
        """The 3-D configuration called ``name``, or a FreestandError listing the names."""
        for body in self.body_configurations:
            if body.name == name:
                return body
        raise FreestandError(
            f"no configuration named {name!r}; choose one of {self._known()}", source=self.source
        )

    def first_configuration(self) -> Stack:
        """The first planar configuration, or a FreestandError when the model has none."""
        if not self.configurations:
            raise FreestandError(
                "has only 3-D configurations "
                f"({', '.join(repr(b.name) for b in self.body_configurations)}); this analysis "
                "takes planar configurations only. 3-D configurations are screened by "
                "`freestand screen` (fs.screen), simulated by `freestand simulate` (fs.simulate) "
                "and reported by `freestand report`",
                source=self.source,
            )
        return self.configurations[0]

    def _known(self) -> str:
        names = [repr(stack.name) for stack in self.configurations]
        names += [f"{body.name!r} (3-D)" for body in self.body_configurations]
        return ", ".join(names)

    def _planar_choice(self) -> str:
        if not self.configurations:
            return " and the model has none"
        return ": " + ", ".join(repr(stack.name) for stack in self.configurations)


# --- schema -------------------------------------------------------------------------------------

_SLIDING_WORDS = ", ".join(repr(s.value) for s in Sliding)


class _BaseSpec(_Strict):
    left: Quantity
    right: Quantity
    level: Quantity = 0.0
    names: tuple[str, str] = ("left", "right")

    @field_validator("left", "right", "level", mode="before")
    @classmethod
    def _length(cls, value, info):
        return _quantity(value, "length", info)

    @model_validator(mode="after")
    def _order(self):
        if not self.left < self.right:
            raise ValueError(
                f"left = {self.left} m is not left of right = {self.right} m; "
                "give the x of the left contact first (left < right)"
            )
        return self


def _sliding_word(value: Any) -> str:
    try:
        return Sliding(value).value
    except ValueError:
        raise ValueError(f"{value!r} is not a sliding word; use one of {_SLIDING_WORDS}") from None


class _BlockSpec(_Strict):
    name: str
    _name = field_validator("name", mode="before")(_name_value)
    mass: Quantity
    inertia: Quantity
    centre: tuple[Quantity, Quantity]
    base: _BaseSpec
    friction: _FrictionSpec | None = None
    sliding: str = "free"

    _mass = field_validator("mass", mode="before")(_mass_value)
    _inertia = field_validator("inertia", mode="before")(_inertia_value)
    _sliding = field_validator("sliding", mode="before")(_sliding_word)

    @field_validator("centre", mode="before")
    @classmethod
    def _centre(cls, value, info):
        if not isinstance(value, list | tuple) or len(value) != 2:
            raise ValueError(f"{value!r} is not a pair; give [x, z] in m, e.g. [0.0, 0.98]")
        return tuple(_quantity(v, "length", info) for v in value)

    @model_validator(mode="after")
    def _checks(self):
        if self.friction is None and self.sliding != Sliding.NONE.value:
            raise ValueError(
                "friction is missing; add friction = { static = 0.25, kinetic = 0.20 } "
                '(it may be left out only with sliding = "none")'
            )
        if not self.centre[1] > self.base.level:
            raise ValueError(
                f"the centre z = {self.centre[1]} m is not above the base level "
                f"{self.base.level} m; z is measured up from the support surface"
            )
        return self

    def to_block(self) -> Block:
        friction = self.friction or _FrictionSpec(static=0.0, kinetic=0.0)
        return Block(
            name=self.name,
            mass=float(self.mass),
            inertia=float(self.inertia),
            centre=(float(self.centre[0]), float(self.centre[1])),
            base_left=float(self.base.left),
            base_right=float(self.base.right),
            base_level=float(self.base.level),
            friction=Friction(friction.static, friction.kinetic),
            sliding=Sliding(self.sliding),
            contact_names=tuple(self.base.names),
        )


class _PaperBody(_Strict):
    name: str
    _name = field_validator("name", mode="before")(_name_value)
    mass: Quantity
    inertia: Quantity
    friction: _FrictionSpec | None = None
    sliding: str = "free"

    _mass = field_validator("mass", mode="before")(_mass_value)
    _inertia = field_validator("inertia", mode="before")(_inertia_value)
    _sliding = field_validator("sliding", mode="before")(_sliding_word)


_PAPER_LENGTHS = {
    "y-z": ("p1", "p3", "g", "h", "p2", "c", "d", "r", "q"),
    "x-z": ("p1", "p3", "e", "f", "p2", "a", "b", "s", "t"),
}


class _PaperSpec(_Strict):
    """The paper's Table 1 notation for a two-block configuration."""

    model_config = ConfigDict(extra="allow", frozen=True)
    plane: str
    lower: _PaperBody
    upper: _PaperBody

    @field_validator("plane")
    @classmethod
    def _plane(cls, value):
        if value not in _PAPER_LENGTHS:
            raise ValueError(f'{value!r} is not a plane of the paper; use "y-z" or "x-z"')
        return value

    @model_validator(mode="after")
    def _lengths(self, info):
        names = _PAPER_LENGTHS[self.plane]
        extra = dict(self.model_extra or {})
        unknown = sorted(set(extra) - set(names))
        if unknown:
            raise ValueError(
                f"unknown length(s) {', '.join(unknown)} for plane {self.plane}; "
                f"the paper's notation uses {', '.join(names)}"
            )
        missing = [name for name in names if name not in extra]
        if missing:
            raise ValueError(
                f"missing length(s) {', '.join(missing)}; plane {self.plane} needs "
                f"{', '.join(names)} (paper Table 1)"
            )
        lengths = {}
        for name in names:
            try:
                lengths[name] = _quantity(extra[name], "length", info)
            except FreestandError as error:
                raise ValueError(f"{name}: {error.detail}") from None
            if lengths[name] < 0:
                raise ValueError(f"{name} = {lengths[name]} m is negative; paper lengths are >= 0")
        object.__setattr__(self, "__pydantic_extra__", lengths)
        return self


#: A ``[[configuration.block]]``: planar, or 3-D when it has a shape (:func:`block_kind`).
_AnyBlock = Annotated[
    Annotated[_BlockSpec, Tag("planar")] | Annotated[BodySpec, Tag("3-D")],
    Discriminator(block_kind),
]


class _ConfigurationSpec(_Strict):
    name: str
    _name = field_validator("name", mode="before")(_name_value)
    block: list[_AnyBlock] | None = None
    paper: _PaperSpec | None = None

    @model_validator(mode="after")
    def _one_form(self):
        if (self.block is None) == (self.paper is None):
            raise ValueError(
                "give either [[configuration.block]] entries (coordinates) or one "
                "[configuration.paper] table (the paper's notation), not both or neither"
            )
        if self.block is not None:
            if not self.block:
                raise ValueError("no blocks; add at least one [[configuration.block]]")
            if self.bodies:
                _one_body(self.block, self.bodies)
                return self
            names = [b.name for b in self.block]
            if len(set(names)) != len(names):
                raise ValueError(f"block names {names} repeat; give each block its own name")
            bottom = self.block[0]
            if bottom.base.level != 0:
                raise ValueError(
                    f"the bottom block {bottom.name!r} has its base at level = "
                    f"{bottom.base.level} m, not 0; z is measured up from the support surface, "
                    "so the bottom block stands at level = 0 (subtract "
                    f"{bottom.base.level} m from every z of this configuration)"
                )
            for lower, upper in zip(self.block, self.block[1:], strict=False):
                if not upper.base.level > lower.base.level:
                    raise ValueError(
                        f"block {upper.name!r} has its base at z = {upper.base.level} m, not above "
                        f"the base of {lower.name!r} below it ({lower.base.level} m); list blocks "
                        "bottom to top, each resting on the one before"
                    )
        return self

    @property
    def bodies(self) -> list[BodySpec]:
        """The 3-D blocks (those with a shape)."""
        return [block for block in self.block or () if isinstance(block, BodySpec)]


def _one_body(blocks: list, bodies: list[BodySpec]) -> None:
    """A 3-D configuration holds one 3-D block and nothing else (ValueError otherwise)."""
    planar = [block.name for block in blocks if not isinstance(block, BodySpec)]
    names = ", ".join(body.name for body in bodies)
    if planar:
        raise FreestandError(
            f"mixes planar blocks ({', '.join(planar)}) and 3-D blocks ({names}, with shape); "
            "a configuration is planar (blocks with base and centre = [x, z]) or 3-D (one "
            "block with shape): put them in separate [[configuration]] tables",
            field="block",
        )
    if len(bodies) > 1:
        raise FreestandError(
            f"has {len(bodies)} blocks with shape ({names}); stacks of 3-D bodies are not "
            "supported yet: give each body a [[configuration]] of its own",
            field="block",
        )


class _FloorSpec(_Strict):
    """``floor = { frequency = "2.5 Hz", damping = "5 %" }``: a mode that filters the record."""

    frequency: float
    damping: float = 0.05

    @field_validator("frequency", mode="before")
    @classmethod
    def _frequency(cls, value, info):
        return _positive(_quantity(value, "frequency", info), "floor frequency", '"2.5 Hz"')

    @field_validator("damping", mode="before")
    @classmethod
    def _damping(cls, value, info):
        from freestand.io.units import damping_fraction

        return damping_fraction(value, field="floor.damping", source="")


class _ExcitationSpec(_Strict):
    name: str
    _name = field_validator("name", mode="before")(_name_value)
    horizontal: Quantity | None = None
    # the same key as horizontal (the x component), as in suite files
    x: Quantity | None = None
    # the y component, for 3-D configurations (signed)
    y: Quantity | None = None
    vertical: Quantity = 0.0
    vertical_senses: str = "given"
    # a ground record (relative to the model file) whose peak, after the optional floor
    # filter, is the horizontal acceleration (freestand.core.motion.response_spectrum.floor_motion)
    record: str | None = None
    floor: _FloorSpec | None = None

    @field_validator("horizontal", "x", mode="before")
    @classmethod
    def _horizontal(cls, value, info):
        result = _quantity(value, "acceleration", info)
        if result < 0:
            raise ValueError(
                f"{value!r} is negative; give the magnitude of the horizontal support "
                "acceleration (both senses are analysed"
                + (": the direction of (x, y) and its opposite)" if info.field_name == "x" else ")")
            )
        return result

    @field_validator("y", mode="before")
    @classmethod
    def _y(cls, value, info):
        # signed: with x >= 0 it gives every direction up to the sense, and both are analysed
        return _quantity(value, "acceleration", info)

    @field_validator("vertical", mode="before")
    @classmethod
    def _vertical(cls, value, info):
        # signed: positive downward (weight m (g - a_v) shrinks), negative upward (it grows)
        return _quantity(value, "acceleration", info)

    @field_validator("vertical_senses", mode="before")
    @classmethod
    def _senses(cls, value):
        if value not in VERTICAL_SENSES:
            raise ValueError(
                f"{value!r} is not a choice of vertical senses; use "
                + " or ".join(repr(v) for v in VERTICAL_SENSES)
                + " (both: the vertical acceleration downward and upward)"
            )
        return value

    @model_validator(mode="after")
    def _one_source(self):
        if self.horizontal is not None and self.x is not None:
            raise ValueError(
                f"horizontal = {self.horizontal} and x = {self.x} are both given; give the x "
                "component once: horizontal and x are the same key"
            )
        if (self.x_component is None) == (self.record is None):
            raise ValueError(
                "give either horizontal (a peak acceleration; also written x, with y for "
                "3-D configurations) or record (a ground record file, optionally with "
                'floor = { frequency = "2.5 Hz", damping = "5 %" })'
            )
        if self.floor is not None and self.record is None:
            raise ValueError('floor filters a record; give record = "FILE" with it')
        if self.y is not None and self.record is not None:
            raise ValueError(
                f"y = {self.y:g} m/s^2 goes with horizontal (or x) as accelerations, not with a "
                "record; give horizontal and y in m/s^2, or leave y out"
            )
        return self

    @property
    def x_component(self) -> float | None:
        """The x component [m/s^2]: ``horizontal`` or ``x``, whichever is given."""
        return self.horizontal if self.horizontal is not None else self.x

    def horizontal_peak(self, base_dir: Path, gravity: float) -> float:
        """Horizontal acceleration [m/s^2]: given, or the peak of the (floor-filtered) record."""
        if self.record is None:
            return float(self.x_component)
        from freestand.core.motion.response_spectrum import floor_motion
        from freestand.io.records import load_record

        path = Path(self.record)
        motion = load_record(path if path.is_absolute() else base_dir / path, gravity=gravity)
        if self.floor is None:
            return motion.peak_horizontal
        # the structure's free vibration after the record is kept (five periods)
        motion = motion.with_trailing_zeros(motion.duration + 5.0 / self.floor.frequency)
        return floor_motion(motion, self.floor.frequency, self.floor.damping).peak_horizontal


class _ModelSpec(_Strict):
    model_config = ConfigDict(extra="forbid", frozen=True)
    name: str
    _name = field_validator("name", mode="before")(_name_value)
    gravity: Quantity = 9.81
    excitation: list[_ExcitationSpec]
    configuration: list[_ConfigurationSpec]
    spectrum: list[dict] | None = None
    beam: dict | None = None
    fragility: dict | None = None

    @model_validator(mode="after")
    def _unique(self):
        for what, items in (("excitation", self.excitation), ("configuration", self.configuration)):
            if not items:
                raise ValueError(f"no {what}; add at least one [[{what}]] table")
            names = [item.name for item in items]
            if len(set(names)) != len(names):
                raise ValueError(f"{what} names {names} repeat; give each its own name")
        return self


# --- paper notation -----------------------------------------------------------------------------


def paper_notation_blocks(spec: _PaperSpec) -> tuple[Block, Block]:
    """Convert the paper's Table 1 notation of a two-block model to coordinates.

    y-z plane (paper Fig. 1): lower block centre S1 = (0, p1), lower contacts
    G = (-g, 0), H = (h, 0); top of the lower block at z = p1 + p3; upper
    contacts C = (-(g - r), p1 + p3), D = (h - q, p1 + p3); upper centre S2 at
    x = C + c (= D - d), z = p1 + p3 + p2.

    x-z plane (paper Fig. 2): E = (-e, 0), F = (f, 0); upper contacts
    A = (-e + s, p1 + p3), B = (f - t, p1 + p3); upper centre S2 at x = A + a
    (= B - b), z = p1 + p3 + p2.

    Raises
    ------
    ValueError
        If the two ways of locating S2 disagree by more than 2 cm, or the
        upper contacts are not in order.
    """
    d = spec.model_extra
    top = d["p1"] + d["p3"]
    if spec.plane == "y-z":
        names = (("G", "H"), ("C", "D"))
        lower_left, lower_right = -d["g"], d["h"]
        upper_left, upper_right = -(d["g"] - d["r"]), d["h"] - d["q"]
        centre_from_left, centre_from_right = upper_left + d["c"], upper_right - d["d"]
        letters = "c, d, r, q"
    else:
        names = (("E", "F"), ("A", "B"))
        lower_left, lower_right = -d["e"], d["f"]
        upper_left, upper_right = -d["e"] + d["s"], d["f"] - d["t"]
        centre_from_left, centre_from_right = upper_left + d["a"], upper_right - d["b"]
        letters = "a, b, s, t"
    if not upper_left < upper_right:
        raise ValueError(
            f"the upper contacts come out at x = {upper_left:.3f} and {upper_right:.3f} m, "
            f"not left before right; check {letters}"
        )
    if abs(centre_from_left - centre_from_right) > 0.02:
        raise ValueError(
            f"the upper centre is at x = {centre_from_left:.3f} m from its left contact but "
            f"{centre_from_right:.3f} m from its right one; check {letters}"
        )
    blocks = []
    for body, centre, left, right, level, contact_names in (
        (spec.lower, (0.0, d["p1"]), lower_left, lower_right, 0.0, names[0]),
        (spec.upper, (centre_from_left, top + d["p2"]), upper_left, upper_right, top, names[1]),
    ):
        friction = body.friction or _FrictionSpec(static=0.0, kinetic=0.0)
        blocks.append(
            Block(
                name=body.name,
                mass=float(body.mass),
                inertia=float(body.inertia),
                centre=(float(centre[0]), float(centre[1])),
                base_left=float(left),
                base_right=float(right),
                base_level=float(level),
                friction=Friction(friction.static, friction.kinetic),
                sliding=Sliding(body.sliding),
                contact_names=contact_names,
            )
        )
        if body.friction is None and body.sliding != Sliding.NONE.value:
            raise ValueError(
                f"{body.name}: friction is missing; add friction = {{ static = 0.25, "
                'kinetic = 0.20 }} (it may be left out only with sliding = "none")'
            )
    return blocks[0], blocks[1]


# --- loading ------------------------------------------------------------------------------------


#: The tags of :data:`_AnyBlock` that pydantic puts in an error's location.
_BLOCK_TAGS = ("planar", "3-D")


def _field_path(location: tuple, data: dict) -> str:
    """A readable dotted path such as ``configuration[0] 'y-z'.block[1] 'cart'.mass``."""
    parts = []
    node: Any = data
    previous = None
    for item in location:
        if item in _BLOCK_TAGS and isinstance(previous, int):
            previous = item  # which schema read the block (planar or 3-D): not a field
            continue
        previous = item
        if isinstance(item, int):
            parts[-1] = f"{parts[-1]}[{item}]" if parts else f"[{item}]"
            node = node[item] if isinstance(node, list) and item < len(node) else None
            if isinstance(node, dict) and isinstance(node.get("name"), str):
                parts[-1] += f" ({node['name']!r})"
        else:
            parts.append(str(item))
            node = node.get(item) if isinstance(node, dict) else None
    return ".".join(parts)


_MISSING_HINTS = {
    "name": 'a name, e.g. name = "bridge"',
    "mass": "the mass in kg, e.g. mass = 16600",
    "inertia": "the moment of inertia about the centre in kg m^2, e.g. inertia = 49400",
    "centre": "the centre of gravity [x, z] in m, e.g. centre = [0.0, 0.98]",
    "base": "the lower contacts, e.g. base = { left = -1.74, right = 2.46, level = 0.0 }",
    "left": "the x of the left contact in m",
    "right": "the x of the right contact in m",
    "static": "the static friction coefficient, e.g. static = 0.25",
    "kinetic": "the kinetic friction coefficient, e.g. kinetic = 0.20",
    "horizontal": 'the horizontal support acceleration, e.g. horizontal = "2.70 m/s^2"',
    "shape": '"box" (with size) or "cylinder" (with radius and height) for a 3-D block, e.g. '
    'shape = "box"',
    "size": "the box's sides [lx, ly, lz] in m, e.g. size = [0.8, 0.6, 2.0]",
    "radius": "the cylinder's radius in m, e.g. radius = 0.9",
    "height": "the cylinder's height in m, e.g. height = 4.0",
    "friction": "the friction on the support, e.g. friction = { static = 0.5, kinetic = 0.4 }",
    "excitation": "at least one [[excitation]] table with name, horizontal and vertical",
    "configuration": "at least one [[configuration]] table with its blocks",
    "plane": 'the plane, "y-z" or "x-z"',
    "lower": 'the lower body, e.g. lower = { name = "bridge", mass = 16600, inertia = 49400, ... }',
    "upper": 'the upper body, e.g. upper = { name = "cart", mass = 25600, inertia = 151600, ... }',
}


def _translate(error: ValidationError, data: dict, source: str) -> FreestandError:
    errors = error.errors(include_url=False)
    # A misspelt field shows as an unknown one and a missing one: name the unknown one.
    first = next((e for e in errors if e["type"] == "extra_forbidden"), errors[0])
    location = tuple(first["loc"])
    kind = first["type"]
    path = _field_path(location, data)
    name = str(location[-1]) if location else ""
    if kind == "missing":
        hint = _MISSING_HINTS.get(name, "add it")
        return FreestandError(f"is missing; add {hint}", source=source, field=path)
    if kind == "extra_forbidden":
        missing = [str(e["loc"][-1]) for e in errors if e["type"] == "missing"]
        close = difflib.get_close_matches(name, missing + list(_MISSING_HINTS), n=1)
        suggestion = f"did you mean {close[0]!r}? " if close else ""
        return FreestandError(
            f"is not a known field (value {first.get('input')!r}); {suggestion}check its "
            "spelling against the README's model-file section",
            source=source,
            field=path,
        )
    if kind == "value_error":
        cause = first.get("ctx", {}).get("error")
        message = cause.detail if isinstance(cause, FreestandError) else str(cause)
        if isinstance(cause, FreestandError) and cause.field:
            # a table's check that names the key at fault below the table
            path = f"{path}.{cause.field}" if path else cause.field
        return FreestandError(message, source=source, field=path or None)
    value = first.get("input")
    return FreestandError(
        f"{value!r}: {first['msg'].lower()}; see the README's model-file section",
        source=source,
        field=path or None,
    )


def load_model_text(
    text: str, *, source: str = "<string>", base_dir: Path | None = None
) -> ModelFile:
    """Read a model from TOML text.

    Parameters
    ----------
    text : str
        TOML document.
    source : str, optional
        Name used in error messages.
    base_dir : pathlib.Path, optional
        Folder that relative paths in the model (spectrum files) are relative to.

    Returns
    -------
    ModelFile

    Raises
    ------
    FreestandError
        For malformed TOML or any invalid field.
    """
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise FreestandError(
            f"is not valid TOML ({error}); fix the syntax at that line", source=source
        ) from None
    gravity_value = data.get("gravity", 9.81)
    gravity = to_si(gravity_value, "acceleration", field="gravity", source=source, gravity=9.81)
    if not 0 < gravity < 100:
        raise FreestandError(
            f"{gravity_value!r} is not a plausible gravitational acceleration; give it in "
            "m/s^2, e.g. 9.81",
            source=source,
            field="gravity",
        )
    try:
        spec = _ModelSpec.model_validate(data, context={"gravity": gravity})
    except ValidationError as error:
        raise _translate(error, data, source) from None

    configurations, bodies = [], []
    for index, configuration in enumerate(spec.configuration):
        if configuration.bodies:
            bodies.append(
                BodyConfiguration(configuration.name, (configuration.bodies[0].to_body(),))
            )
            continue
        if configuration.block is not None:
            blocks = tuple(block.to_block() for block in configuration.block)
        else:
            try:
                blocks = paper_notation_blocks(configuration.paper)
            except ValueError as error:
                raise FreestandError(
                    str(error),
                    source=source,
                    field=f"configuration[{index}] ({configuration.name!r}).paper",
                ) from None
        configurations.append(Stack(name=configuration.name, blocks=blocks))
    if not bodies:
        _check_planar_excitations(spec, source)
    base_dir = base_dir or Path.cwd()
    excitations = tuple(
        Excitation(
            name=e.name,
            horizontal=e.horizontal_peak(base_dir, gravity),
            vertical=float(e.vertical),
            vertical_senses=e.vertical_senses,
            horizontal_y=0.0 if e.y is None else float(e.y),
        )
        for e in spec.excitation
    )
    spectra = (
        parse_spectrum_sections(spec.spectrum, source=source, base_dir=base_dir, gravity=gravity)
        if spec.spectrum is not None
        else {}
    )
    beam = (
        parse_beam_section(spec.beam, source=source, gravity=gravity)
        if spec.beam is not None
        else None
    )
    return ModelFile(
        name=spec.name,
        gravity=gravity,
        excitations=excitations,
        configurations=tuple(configurations),
        source=source,
        sha256=hashlib.sha256(text.encode()).hexdigest(),
        base_dir=base_dir,
        spectra=spectra,
        beam=beam,
        fragility=spec.fragility,
        body_configurations=tuple(bodies),
    )


def _check_planar_excitations(spec: _ModelSpec, source: str) -> None:
    """On a model without 3-D configurations, an excitation's ``y`` is a mistake: refuse it."""
    for index, excitation in enumerate(spec.excitation):
        if excitation.y is not None:
            raise FreestandError(
                f"y = {excitation.y:g} m/s^2 is given, but every configuration of this model is "
                "planar; y is the second horizontal component of a 3-D configuration (a block "
                "with shape). Remove y (a planar configuration takes horizontal, its plane's x), "
                "or give a configuration a 3-D block",
                source=source,
                field=f"excitation[{index}] ({excitation.name!r}).y",
            )


def load_model(path: str | Path) -> ModelFile:
    """Read and validate a model file.

    Parameters
    ----------
    path : str or pathlib.Path
        The TOML model file.

    Returns
    -------
    ModelFile

    Raises
    ------
    FreestandError
        If the file cannot be read, is not TOML or has an invalid field.

    Examples
    --------
    >>> import freestand as fs
    >>> model = fs.load_model("examples/crane.toml")
    >>> model.name, [stack.name for stack in model.configurations]
    ('Bridge crane', ['y-z', 'x-z cart right', 'x-z cart left'])
    >>> [(level.name, level.horizontal, level.vertical) for level in model.excitations]
    [('rigid', 2.7, 2.35), ('elastic', 10.31, 2.35)]
    >>> model.configuration("y-z").blocks[1].mass  # [kg]
    25600.0
    """
    path = Path(path)
    try:
        raw = path.read_bytes()
    except OSError as error:
        raise FreestandError(
            f"cannot be read ({error.strerror}); check the path", source=str(path)
        ) from None
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError:
        raise FreestandError("is not UTF-8 text; save it as UTF-8 TOML", source=str(path)) from None
    model = load_model_text(text, source=str(path), base_dir=path.resolve().parent)
    return replace(model, sha256=hashlib.sha256(raw).hexdigest())
