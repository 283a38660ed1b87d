"""The model-file reference (every key, its unit and default), generated from the validation schema.

:func:`model_file_reference` walks the pydantic models of
:mod:`freestand.io.model_file` from the top (``_ModelSpec``): every field of
every table, nested tables and arrays of tables included, so that a key added
to the schema appears in the reference without an edit here. For each key:

- the TOML path (``[[configuration.block]]`` / ``base.left``);
- required, or its default (from the field);
- the unit, read from the field's own validator: ``"1 <unit>"`` is passed to
  it for the SI unit of every kind of quantity freestand converts
  (:data:`freestand.io.units.QUANTITIES`), and the unit it accepts as 1 is
  the key's (a plain number field is dimensionless, a text field has none);
- what it is: :data:`DESCRIPTIONS` where written (the bodies of a
  ``configuration.paper`` table take the block's, :data:`ALIASES`), else the
  hint the loader gives when the key is missing.

The tables validated outside the pydantic models follow from the tables
their readers take their keys, units and defaults from: ``[beam]`` from
:data:`freestand.io.beam_section.BEAM_FIELDS`, ``[[spectrum]]`` from
:data:`freestand.io.spectrum_input.COMMON_SPECTRUM_KEYS` and
:data:`~freestand.io.spectrum_input.SPECTRUM_KEYS`, ``[fragility]`` from
:data:`freestand.io.fragility_options.FRAGILITY_KEYS`.
"""

from __future__ import annotations

import types
import typing
from dataclasses import dataclass

from pydantic import BaseModel
from pydantic_core import PydanticUndefined

#: What each key is, by its dotted path (keys without an entry show the loader's hint).
DESCRIPTIONS = {
    "name": "the model's name, shown in every output",
    "gravity": "the gravitational acceleration g; the unit g in the file means this value",
    "excitation": "a level of support acceleration; both horizontal senses are analysed",
    "excitation.name": "the level's name (rigid, elastic...)",
    "excitation.horizontal": "magnitude of the horizontal support acceleration a_h: its x "
    "component (3-D configurations add y; planar configurations take it alone, in their plane)",
    "excitation.x": "the same key as horizontal (the x component); give one of them",
    "excitation.y": "the y component of the horizontal support acceleration, signed, for 3-D "
    "configurations (an error on a model without one)",
    "excitation.vertical": "signed vertical support acceleration a_v, positive downward "
    "(the weight becomes m (g - a_v))",
    "excitation.vertical_senses": '"given", or "both": also analysed with a_v upward',
    "excitation.record": "instead of horizontal: a ground record file (its peak), relative "
    "to the model file",
    "excitation.floor": "a structure's mode that filters the record (peak floor motion)",
    "excitation.floor.frequency": "the mode's frequency",
    "excitation.floor.damping": 'the mode\'s damping ratio (0.05 or "5 %")',
    "configuration": "one planar model (a plane, a parking position...), or one 3-D body",
    "configuration.name": "the configuration's name",
    "configuration.block": "a block, listed bottom to top; each rests on the one before",
    "configuration.block.name": "the block's name",
    "configuration.block.mass": "mass m",
    "configuration.block.inertia": "moment of inertia about the centre of gravity, in the plane",
    "configuration.block.centre": "(x, z) of the centre of gravity; z = 0 is the support",
    "configuration.block.base": "the two lower contacts",
    "configuration.block.base.left": "x of the left contact",
    "configuration.block.base.right": "x of the right contact (left < right)",
    "configuration.block.base.level": "z of the contacts: 0 for the bottom block, the top of "
    "the block below for the others",
    "configuration.block.base.names": "names of the two contacts in the tables",
    "configuration.block.friction": "friction of the interface below the block (may be left "
    'out with sliding = "none")',
    "configuration.block.friction.static": "static friction coefficient",
    "configuration.block.friction.kinetic": "kinetic friction coefficient (not above the static)",
    "configuration.block.sliding": '"free", "none" (never slides), "no-right" or "no-left" '
    "(an end stop)",
    "configuration.paper": "a two-block configuration in the paper's notation (its Table 1): "
    "plane, lower, upper and the lengths p1, p3, g, h, p2, c, d, r, q (y-z) or p1, p3, e, f, "
    "p2, a, b, s, t (x-z) in m",
    "configuration.paper.plane": '"y-z" or "x-z"',
    "configuration.paper.lower": "the lower body: name, mass, inertia, friction, sliding",
    "configuration.paper.upper": "the upper body: name, mass, inertia, friction, sliding",
    "spectrum": "a response spectrum (see below)",
    "beam": "the bridge as a simply supported beam carrying the cart (see below)",
    "fragility": "a fragility campaign for the report's appendix (see below)",
}


#: What each key of a 3-D block is (:class:`freestand.io.body_spec.BodySpec`), by its path in
#: the block.
BODY_DESCRIPTIONS = {
    "name": "the body's name",
    "shape": '"box" or "cylinder": makes the configuration 3-D (one body on the support)',
    "size": "box: its sides [lx, ly, lz], x and y horizontal, z up",
    "radius": "cylinder: its radius R",
    "height": "cylinder: its height H",
    "inner_radius": "cylinder: the inner radius r of a hollow one (0: solid)",
    "mass": "mass m",
    "centre": "[x, y, z] of the centre of gravity from the base centre (default the "
    "geometric centre); it must lie over the base",
    "inertia": "about the centre of gravity: 3 principal values [Ixx, Iyy, Izz] or a "
    "symmetric positive definite 3x3 matrix (default: the homogeneous body's)",
    "friction": "Coulomb friction on the support (the circular cone)",
    "friction.static": "static friction coefficient",
    "friction.kinetic": "kinetic friction coefficient (not above the static)",
}

#: The type of a 3-D block's keys where the annotation does not say it in words.
BODY_KINDS = {"inertia": "array of 3, or 3x3 array", "centre": "array of 3"}

#: Units of the keys converted outside the schema's field validators (by the loader itself).
UNITS = {"gravity": "m/s^2"}


#: Paths whose keys are described as those of another (the paper notation's two bodies are
#: blocks).
ALIASES = {
    "configuration.paper.lower.": "configuration.block.",
    "configuration.paper.upper.": "configuration.block.",
}


def _description(path: str) -> str:
    """:data:`DESCRIPTIONS` of ``path`` or of the path it is an alias of ('' if none)."""
    if path in DESCRIPTIONS:
        return DESCRIPTIONS[path]
    for alias, original in ALIASES.items():
        if path.startswith(alias):
            return DESCRIPTIONS.get(original + path[len(alias) :], "")
    return ""


@dataclass(frozen=True)
class Key:
    """One key of the model file."""

    path: str
    kind: str
    required: bool
    default: str
    unit: str
    description: str


def _models_in(annotation) -> list[type[BaseModel]]:
    """The pydantic models inside an annotation (``X``, ``list[X]``, ``X | None``...)."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return [annotation]
    found = []
    for argument in typing.get_args(annotation):
        found += _models_in(argument)
    return found


def _is_list(annotation) -> bool:
    origin = typing.get_origin(annotation)
    if origin in (typing.Union, types.UnionType):
        return any(_is_list(a) for a in typing.get_args(annotation))
    return origin is list


def _kind(annotation) -> str:
    """A short name of a field's type: number, text, table, array of tables, pair..."""
    models = _models_in(annotation)
    if models:
        return "array of tables" if _is_list(annotation) else "table"
    origin = typing.get_origin(annotation)
    arguments = [a for a in typing.get_args(annotation) if a is not type(None)]
    if origin in (typing.Union, types.UnionType):
        if set(arguments) >= {float, str}:
            return "number or text with unit"
        return " or ".join(_kind(a) for a in arguments)
    if origin is tuple:
        return f"array of {len(arguments)}" if arguments else "array"
    if origin is list:
        return "array of tables" if dict in arguments else "array"
    if origin is dict or annotation is dict:
        return "table"
    return {float: "number", int: "integer", str: "text", bool: "boolean"}.get(
        annotation, getattr(annotation, "__name__", str(annotation))
    )


class _Info:
    """The stand-in for pydantic's ValidationInfo passed to a validator when probing."""

    def __init__(self, field_name: str):
        self.field_name = field_name
        self.context = {"gravity": 9.81}
        self.data = {}


def _probe_unit(model: type[BaseModel], field: str) -> str:
    """The SI unit a field's before-validator accepts ``"1 <unit>"`` in, '' if none."""
    from freestand.io.units import QUANTITIES

    for decorator in model.__pydantic_decorators__.field_validators.values():
        if field not in decorator.info.fields or decorator.info.mode != "before":
            continue
        function = decorator.func
        for unit, _ in QUANTITIES.values():
            if not unit:
                continue
            sample = f"1 {unit}"
            for value in (sample, [sample, sample], [sample, sample, sample]):
                try:
                    result = _call(function, value, field)
                except Exception:  # noqa: BLE001 - a unit the validator refuses
                    continue
                numbers = result if isinstance(result, tuple | list) else (result,)
                if all(isinstance(n, float | int) and abs(n - 1.0) < 1e-12 for n in numbers):
                    return unit.replace("*", " ")
    return ""


def _call(function, value, field: str):
    try:
        return function(value, _Info(field))
    except TypeError:
        return function(value)


def _default(info) -> str:
    if info.is_required():
        return ""
    value = info.get_default(call_default_factory=True)
    if value is None or value is PydanticUndefined:
        return "none"
    if isinstance(value, tuple):
        return "[" + ", ".join(f'"{v}"' if isinstance(v, str) else f"{v:g}" for v in value) + "]"
    if isinstance(value, str):
        return f'"{value}"'
    return f"{value:g}" if isinstance(value, float) else str(value)


def schema_keys(
    model: type[BaseModel] | None = None, prefix: str = "", *, top: str = ""
) -> list[Key]:
    """Every key of the model-file schema, depth first, in declaration order.

    A table read by a schema of its own (one with a ``reference_title``, the
    3-D block) is left out: :func:`body_keys` lists it. ``top`` is the path of
    ``model`` below which the key paths are given (for those tables).
    """
    from freestand.io.model_file import _MISSING_HINTS, _ModelSpec

    model = model or _ModelSpec
    keys = []
    for name, info in model.model_fields.items():
        path = f"{prefix}{name}"
        annotation = info.annotation
        relative = path[len(top) :]
        kind = BODY_KINDS.get(relative, "") if top else ""
        kind = kind or _kind(annotation)
        unit = UNITS.get(path) or _probe_unit(model, name)
        if unit and kind in ("number", "integer"):
            kind = "number or text with unit"
        if not unit and kind in ("number", "integer"):
            unit = "-"
        described = BODY_DESCRIPTIONS.get(relative, "") if top else _description(path)
        description = described or _MISSING_HINTS.get(name, "")
        keys.append(Key(path, kind, info.is_required(), _default(info), unit, description))
        for nested in _models_in(annotation):
            if not hasattr(nested, "reference_title"):
                keys += schema_keys(nested, path + ".", top=top)
    return keys


def body_keys() -> list[Key]:
    """Every key of a 3-D block (:class:`freestand.io.body_spec.BodySpec`)."""
    from freestand.io.body_spec import BodySpec

    return schema_keys(BodySpec, "configuration.block.", top="configuration.block.")


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def _table(rows: list[tuple[str, ...]], header: tuple[str, ...]) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(_cell(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def _table_key_rows(prefix: str, keys: dict) -> list[tuple[str, ...]]:
    """Rows of the reference for the :class:`~freestand.io.table_keys.TableKey` of a table."""
    return [
        (f"`{prefix}{name}`", key.default_text(), key.unit, key.what) for name, key in keys.items()
    ]


INTRODUCTION = (
    "Generated from the validation schema (`freestand.io.model_file`) and the readers' key "
    "tables when the site is built: every key the loader accepts, with its unit and default. "
    'Bare numbers are in the unit given; a text with a unit (`"2.70 m/s^2"`, '
    '`"0.275 g"`, `"16.6 t"`, `"98 cm"`) is converted at load time, `g` meaning the '
    "model's gravity. An unknown key is an error naming it. Keys are given by their TOML "
    "path: `configuration.block.base.left` is `left` in the `base` table of a "
    "`[[configuration.block]]`."
)


def model_file_reference() -> str:
    """The model-file reference as Markdown (MyST): every key, its unit and default."""
    from freestand.io.beam_section import BEAM_FIELDS
    from freestand.io.body_spec import BodySpec
    from freestand.io.fragility_options import FRAGILITY_KEYS
    from freestand.io.spectrum_input import COMMON_SPECTRUM_KEYS, SPECTRUM_KEYS
    from freestand.io.units import QUANTITIES

    rows, body_rows = (
        [
            (f"`{key.path}`", key.kind, "required" if key.required else key.default, key.unit,
             key.description)
            for key in keys
        ]
        for keys in (schema_keys(), body_keys())
    )  # fmt: skip
    beam = [
        (f"`beam.{name}`", "number or text with unit", "required" if required else "none",
         QUANTITIES[quantity][0].replace("*", " ") or "-", f"{what} ({rule})")
        for name, (quantity, required, rule, what) in BEAM_FIELDS.items()
    ]  # fmt: skip
    beam.append(
        ("`beam.parking`", "array of 2", "required", "m",
         "range of the cart's centre from the left support")
    )  # fmt: skip
    header = ("key", "type", "default", "unit", "what it is")
    short = ("key", "default", "unit", "what it is")
    parts = [
        "# Model file reference",
        INTRODUCTION,
        "## Model, excitations and configurations",
        _table(rows, header),
        f"## {BodySpec.reference_title}",
        "A block with `shape` (or any of `size`, `radius`, `height`, `inner_radius`) is a "
        "3-D body and its configuration is 3-D: one such block and no other (stacks of 3-D "
        "bodies are not supported yet). Its keys:",
        _table(body_rows, header),
        "## `[beam]`: the bridge under the parked cart (paper section 6)",
        _table(beam, header),
        "## `[[spectrum]]`: response spectra",
        "Every spectrum takes these keys (`--spectrum` takes `direction` and `damping`):",
        _table(_table_key_rows("", COMMON_SPECTRUM_KEYS), short),
    ]
    for kind, keys in SPECTRUM_KEYS.items():
        parts += [f'### `kind = "{kind}"`', _table(_table_key_rows("", keys), short)]
    parts += [
        "## `[fragility]`: a fragility campaign for the report",
        "The options of `freestand fragility` (see the fragility guide); paths relative to "
        "the model file.",
        _table(_table_key_rows("fragility.", FRAGILITY_KEYS), short),
    ]
    return "\n\n".join(parts) + "\n"
