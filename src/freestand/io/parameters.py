"""Command-line parameter specifications for maps and sweeps.

Syntax (values in SI, or strings with units as in model files; ``g`` in an
acceleration is the model's gravity)::

    horizontal=0:12                       map axis: a_hor from 0 to 12 m/s^2
    vertical=0 g:0.5 g                    map axis with units
    friction.static=uniform(0.15,0.35)    every interface's static coefficient
    cart.friction.static=0.3              one block's interface
    cart.centre.x=normal(0.36,0.05)       a block's centre x [m]
    cart.centre.x+=normal(0,0.05)         an offset added to the model's value
    cart.mass*=uniform(0.9,1.1)           a factor on the model's value

Parameters: ``horizontal``, ``vertical`` (the excitation) and, for one block
(``BLOCK.``) or every block (no prefix): ``mass``, ``inertia``, ``centre.x``,
``centre.z``, ``base.left``, ``base.right``, ``base.level``,
``friction.static``, ``friction.kinetic``.

Distributions: ``uniform(low,high)``, ``normal(mean,std)``,
``truncnormal(mean,std,low,high)``, ``triangular(low,mode,high)``,
``lognormal(median,log_std)``, ``fixed(value)`` or a bare value.

Every problem raises :class:`freestand.errors.FreestandError` naming the
option, the value and the fix.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from freestand.core.contact.batch import BLOCK_FIELDS, EXCITATION_FIELDS, Parameter
from freestand.core.model import Stack
from freestand.core.sweeps.mode_map import Axis
from freestand.core.sweeps.sampling import (
    Fixed,
    LogNormal,
    Normal,
    Triangular,
    TruncatedNormal,
    Uniform,
    Variation,
)
from freestand.errors import FreestandError
from freestand.io.units import to_si

_ASSIGNMENT = re.compile(r"^\s*(?P<name>[^=+*]+?)\s*(?P<operator>[+*]?=)\s*(?P<value>.*?)\s*$")
_CALL = re.compile(r"^(?P<function>[A-Za-z_]+)\s*\((?P<arguments>.*)\)$")
_OPERATIONS = {"=": "set", "+=": "add", "*=": "scale"}
_FIELDS = ", ".join((*EXCITATION_FIELDS, *BLOCK_FIELDS))

#: Distribution name -> (class, argument names, which arguments are log-scale factors).
DISTRIBUTIONS = {
    "uniform": (Uniform, ("low", "high")),
    "normal": (Normal, ("mean", "std")),
    "truncnormal": (TruncatedNormal, ("mean", "std", "low", "high")),
    "triangular": (Triangular, ("low", "mode", "high")),
    "lognormal": (LogNormal, ("median", "log_std")),
    "fixed": (Fixed, ("value",)),
}


def _error(option: str, text: str, message: str) -> FreestandError:
    return FreestandError(f"{text!r}: {message}", source=f"option {option}")


def parse_parameter(name: str, option: str, operation: str = "set", text: str = "") -> Parameter:
    """Read a parameter name such as ``"cart.centre.x"`` or ``"friction.static"``.

    Parameters
    ----------
    name : str
        ``FIELD`` or ``BLOCK.FIELD``.
    option : str
        The command-line option, for messages (``"--vary"``).
    operation : str, optional
        ``"set"``, ``"add"`` or ``"scale"``.
    text : str, optional
        The whole option value, for messages.

    Returns
    -------
    Parameter
    """
    text = text or name
    name = name.strip()
    if name in EXCITATION_FIELDS:
        return Parameter(name, None, operation)
    for field in sorted(BLOCK_FIELDS, key=len, reverse=True):
        if name == field:
            return Parameter(field, None, operation)
        if name.endswith("." + field):
            block = name[: -len(field) - 1].strip()
            if block:
                return Parameter(field, block, operation)
    raise _error(
        option,
        text,
        f"{name!r} is not a parameter; use one of {_FIELDS}, optionally after a block name "
        "(e.g. cart.centre.x, friction.static)",
    )


def _split(text: str, option: str) -> tuple[Parameter, str]:
    match = _ASSIGNMENT.match(text)
    if not match or not match["value"]:
        raise _error(
            option,
            text,
            "is not NAME=VALUE; write e.g. horizontal=0:12 or cart.centre.x=normal(0.36,0.05)",
        )
    operation = _OPERATIONS[match["operator"]]
    parameter = parse_parameter(match["name"], option, operation, text)
    return parameter, match["value"]


def _number(value: str, parameter: Parameter, option: str, text: str, gravity: float) -> float:
    try:
        return to_si(
            float(value) if _is_float(value) else value,
            parameter.quantity,
            field=parameter.name,
            gravity=gravity,
        )
    except FreestandError as error:
        raise _error(option, text, error.detail) from None


def _is_float(value: str) -> bool:
    try:
        float(value)
    except ValueError:
        return False
    return True


def parse_axis(text: str, option: str = "--x", gravity: float = 9.81) -> Axis:
    """Read a map axis ``NAME=START:STOP`` (also ``+=`` and ``*=``).

    Parameters
    ----------
    text : str
        The option value, e.g. ``"horizontal=0:12"``.
    option : str, optional
        Option name for messages.
    gravity : float, optional
        g [m/s^2] for accelerations given in ``g``.

    Returns
    -------
    Axis
    """
    parameter, value = _split(text, option)
    parts = value.split(":")
    if len(parts) != 2 or not all(part.strip() for part in parts):
        raise _error(option, text, f"{value!r} is not a range START:STOP; write e.g. 0:12")
    start, stop = (_number(part.strip(), parameter, option, text, gravity) for part in parts)
    if start == stop:
        raise _error(option, text, f"the range {value!r} is empty; give START and STOP apart")
    return Axis(parameter, start, stop)


def parse_distribution(
    value: str, parameter: Parameter, option: str = "--vary", text: str = "", gravity: float = 9.81
):
    """Read a distribution such as ``"normal(0.36, 0.05)"`` or a bare value.

    Arguments are in the parameter's SI unit (or strings with units); the
    ``log_std`` of ``lognormal`` is dimensionless.
    """
    text = text or value
    match = _CALL.match(value.strip())
    if not match:
        return Fixed(_number(value, parameter, option, text, gravity))
    function = match["function"].lower()
    if function not in DISTRIBUTIONS:
        raise _error(
            option,
            text,
            f"{function!r} is not a distribution; use one of {', '.join(DISTRIBUTIONS)}",
        )
    kind, names = DISTRIBUTIONS[function]
    arguments = [a.strip() for a in match["arguments"].split(",")] if match["arguments"] else []
    if len(arguments) != len(names):
        raise _error(
            option,
            text,
            f"{function} takes {len(names)} argument(s) ({', '.join(names)}), "
            f"not {len(arguments)}; e.g. {function}({', '.join('...' for _ in names)})",
        )
    numbers = []
    for argument_name, argument in zip(names, arguments, strict=True):
        if argument_name == "log_std":
            try:
                numbers.append(float(argument))
            except ValueError:
                raise _error(
                    option, text, f"log_std {argument!r} is not a number (e.g. 0.1)"
                ) from None
        else:
            numbers.append(_number(argument, parameter, option, text, gravity))
    try:
        return kind(*numbers)
    except ValueError as error:
        raise _error(option, text, f"{error}; fix the arguments") from None


def parse_variation(text: str, option: str = "--vary", gravity: float = 9.81) -> Variation:
    """Read an uncertain input ``NAME=DISTRIBUTION`` (also ``+=`` and ``*=``).

    Parameters
    ----------
    text : str
        The option value, e.g. ``"cart.centre.x=normal(0.36,0.05)"``.
    option : str, optional
        Option name for messages.
    gravity : float, optional
        g [m/s^2] for accelerations given in ``g``.

    Returns
    -------
    Variation
    """
    parameter, value = _split(text, option)
    return Variation(parameter, parse_distribution(value, parameter, option, text, gravity))


def check_parameters(
    parameters: Sequence[tuple[Parameter, str]], stacks: Sequence[Stack], option: str
) -> None:
    """Check that every named block exists in every stack and no parameter repeats.

    Parameters
    ----------
    parameters : sequence of (Parameter, str)
        Each parameter with the option text it came from.
    stacks : sequence of Stack
        The configurations it will be applied to.
    option : str
        Option name for messages.
    """
    seen = {}
    for parameter, text in parameters:
        if parameter.name in seen:
            raise _error(
                option,
                text,
                f"{parameter.name} is already varied by {seen[parameter.name]!r}; "
                "give each parameter once",
            )
        seen[parameter.name] = text
        if parameter.block is None:
            continue
        for stack in stacks:
            names = [block.name for block in stack.blocks]
            if parameter.block not in names:
                raise _error(
                    option,
                    text,
                    f"configuration {stack.name!r} has no block {parameter.block!r}; "
                    f"its blocks are {', '.join(names)} (choose configurations with "
                    "--configuration)",
                )
