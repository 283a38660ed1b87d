"""What every public result shares: JSON-ready numbers, tables with units, the model given.

Every public result class has ``to_dict()`` (the document the command's
``--json`` prints: the command prints ``json.dumps(result.to_dict())``),
``to_json()`` and ``to_frame()`` (a tidy :class:`pandas.DataFrame`, units in
the column names as ``name [unit]``, metadata in ``frame.attrs``); those the
command draws a figure for also have ``plot(ax=None)``.

The analyses take a loaded model file (:class:`~freestand.io.model_file.ModelFile`,
from :func:`freestand.load_model`) or a bare :class:`~freestand.core.model.Stack`;
:func:`subject` turns either into the one form the analyses work on. A stack
is the only kind of configuration today: a second kind would be told apart
in :func:`subject` and dispatched by each analysis.
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

from freestand.core.contact.screening import GRAVITY
from freestand.core.model import Excitation, Stack
from freestand.errors import FreestandError


def finite(value: Any) -> float | None:
    """A float for JSON: None for NaN and infinities."""
    value = float(value)
    return value if math.isfinite(value) else None


class Result:
    """Base of the public results: ``to_dict``, ``to_json``, ``to_frame``."""

    def to_dict(self) -> dict:
        """The result as a JSON-ready dict (the command's ``--json`` document).

        Returns
        -------
        dict
            JSON-ready: str, int, float, bool, None, lists and dicts
            (non-finite floats as None).
        """
        raise NotImplementedError

    def to_json(self, indent: int | None = 2) -> str:
        """:meth:`to_dict` as JSON text, exactly as the command prints it.

        Parameters
        ----------
        indent : int or None, optional
            Spaces per level (None: one line).

        Returns
        -------
        str
        """
        return json.dumps(self.to_dict(), indent=indent)

    def to_frame(self):
        """The result as a tidy :class:`pandas.DataFrame` (units in the column names).

        Returns
        -------
        pandas.DataFrame
            One row per case, level, stripe, time step or frequency as fits
            the result; units in the column names, metadata in ``attrs``.
        """
        raise NotImplementedError


def frame(rows: Sequence[dict], columns: Sequence[str], attrs: dict):
    """A DataFrame of ``rows`` with exactly ``columns`` (in that order) and ``attrs``."""
    import pandas as pd

    table = pd.DataFrame(list(rows), columns=list(columns))
    table.attrs.update(attrs)
    return table


@dataclass(frozen=True)
class Subject:
    """What an analysis is run on, whatever form it was given in.

    Attributes
    ----------
    name : str
        The model's name (a bare stack's own name).
    gravity : float
        g [m/s^2].
    configurations : tuple of Stack
        Every configuration of the model (the stack itself for a stack).
    excitations : tuple of Excitation
        The model's excitations (those given with a bare stack).
    model : ModelFile or None
        The model file, when one was given.
    """

    name: str
    gravity: float
    configurations: tuple[Stack, ...]
    excitations: tuple[Excitation, ...]
    model: Any = None

    def configuration(self, name: str | None) -> Stack:
        """The configuration called ``name`` (the first for None)."""
        if name is None:
            return self.configurations[0]
        if self.model is not None:
            return self.model.configuration(name)
        for stack in self.configurations:
            if stack.name == name:
                return stack
        known = ", ".join(repr(stack.name) for stack in self.configurations)
        raise FreestandError(f"no configuration named {name!r}; choose one of {known}")

    def select(self, names: str | Iterable[str] | None) -> list[Stack]:
        """The configurations called ``names`` (in that order, each once); all for None."""
        if names is None:
            return list(self.configurations)
        if isinstance(names, str):
            names = [names]
        return [self.configuration(name) for name in dict.fromkeys(names)]

    def spectrum(self, direction: str):
        """The model's first spectrum of ``direction``, None for a bare stack."""
        return None if self.model is None else self.model.spectrum(direction)


def _excitations(excitations) -> tuple[Excitation, ...]:
    if excitations is None:
        return ()
    if isinstance(excitations, Excitation):
        return (excitations,)
    return tuple(excitations)


def subject(model, excitations=None, gravity: float | None = None) -> Subject:
    """The :class:`Subject` of a model file, a stack or a list of stacks.

    Parameters
    ----------
    model : ModelFile, Stack or sequence of Stack
        A loaded model file (its configurations, excitations, gravity and
        spectra), or stacks with ``excitations`` and ``gravity`` given here.
    excitations : Excitation or sequence of Excitation, optional
        In place of the model's excitations (required for a stack by the
        analyses that need excitations).
    gravity : float, optional
        g [m/s^2] in place of the model's (9.81 for a stack).
    """
    from freestand.io.model_file import ModelFile

    if isinstance(model, ModelFile):
        return Subject(
            model.name,
            model.gravity if gravity is None else float(gravity),
            tuple(model.configurations),
            _excitations(excitations) or tuple(model.excitations),
            model,
        )
    stacks = (model,) if isinstance(model, Stack) else tuple(model)
    if not stacks or not all(isinstance(stack, Stack) for stack in stacks):
        raise TypeError(
            "expected a model file (fs.load_model), a Stack or a list of Stacks, "
            f"not {type(model).__name__}"
        )
    return Subject(
        stacks[0].name if len(stacks) == 1 else ", ".join(s.name for s in stacks),
        GRAVITY if gravity is None else float(gravity),
        stacks,
        _excitations(excitations),
    )


def resolve_spectrum(spectrum, what: Subject, direction: str):
    """The spectrum given (a Spectrum, or a ``--spectrum`` text), else the model's.

    A text is a model spectrum's name, a CSV file or ``KIND:k=v,...``
    (:func:`freestand.io.spectrum_input.parse_spectrum_option`). A spectrum
    of the other direction is refused: the horizontal overturning check
    needs a horizontal spectrum, the jump check a vertical one.
    """
    from pathlib import Path

    if spectrum is None:
        return what.spectrum(direction)
    spectra = what.model.spectra if what.model is not None else {}
    label = spectrum
    if isinstance(spectrum, str):
        from freestand.io.spectrum_input import parse_spectrum_option

        spectrum = parse_spectrum_option(
            spectrum,
            model_spectra=spectra,
            base_dir=what.model.base_dir if what.model is not None else Path.cwd(),
            gravity=what.gravity,
        )
    else:
        label = spectrum.label
    if spectrum.direction != direction:
        other = ", ".join(repr(name) for name, s in spectra.items() if s.direction == direction)
        raise FreestandError(
            f"{label!r} is a {spectrum.direction} spectrum; this check needs a {direction} one"
            + (f" (the model has {other})" if other else "")
            + f", e.g. 'rg1.60:pga=0.3g,direction={direction}'",
            source="--spectrum",
        )
    return spectrum
