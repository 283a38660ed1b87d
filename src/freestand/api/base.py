"""What every public result shares: JSON-ready numbers, tables with units, the model given.

Every public result class has ``to_dict()`` (the document the command's
``--json`` prints: the command prints ``json.dumps(result.to_dict())``),
``to_json()`` and ``to_frame()`` (a tidy :class:`pandas.DataFrame`, units in
the column names as ``name [unit]``, metadata in ``frame.attrs``); those the
command draws a figure for also have ``plot(ax=None)``.

The analyses take a loaded model file (:class:`~freestand.io.model_file.ModelFile`,
from :func:`freestand.load_model`) or a bare :class:`~freestand.core.model.Stack`;
:func:`subject` turns either into the one form the analyses work on. A
configuration is a planar stack (``Subject.configurations``) or a 3-D body
(:class:`~freestand.core.body.BodyConfiguration`, ``Subject.bodies``); the
analyses of stacks take the first through :meth:`Subject.configuration` and
:meth:`Subject.select`, which refuse a 3-D configuration with a message
saying which analyses take it; :meth:`Subject.split` gives both kinds.
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

from freestand.core.body import Body, BodyConfiguration
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


class HistoryResult(Result):
    """Base of the time-history results (a planar stack's and a 3-D body's): what they
    share, from their ``motion`` (the record given, or None) and their ``events``."""

    @property
    def record(self) -> str:
        """The record's name (``"samples"`` for samples given directly)."""
        return self.motion.name if self.motion is not None and self.motion.name else "samples"

    @property
    def title(self) -> str:
        """The figure title: model, configuration (once when they share a name), record, peak."""
        same = self.model == self.configuration
        name = self.model if same else f"{self.model} / {self.configuration}"
        turned = f", turned {self.angle:g} deg" if getattr(self, "angle", 0.0) else ""
        return f"{name}: {self.record}{turned}, peak {self.peak_horizontal:.2f} m/s^2"

    def event_counts(self) -> dict[str, int]:
        """Number of events of each kind (sorted by kind)."""
        kinds = sorted({event.kind for event in self.events})
        return {kind: sum(event.kind == kind for event in self.events) for kind in kinds}


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
        Every planar configuration of the model (the stack itself for a stack).
    excitations : tuple of Excitation
        The model's excitations (those given with a bare stack).
    model : ModelFile or None
        The model file, when one was given.
    bodies : tuple of BodyConfiguration
        The 3-D configurations (the body itself for a body).
    """

    name: str
    gravity: float
    configurations: tuple[Stack, ...]
    excitations: tuple[Excitation, ...]
    model: Any = None
    bodies: tuple[BodyConfiguration, ...] = ()

    def configuration(self, name: str | None) -> Stack:
        """The planar configuration called ``name`` (the first for None)."""
        if self.model is not None:
            return (
                self.model.first_configuration() if name is None else self.model.configuration(name)
            )
        if name is None:
            if not self.configurations:
                raise FreestandError(
                    "a 3-D body is given; this analysis takes planar stacks only (3-D bodies: "
                    "fs.screen, fs.simulate)"
                )
            return self.configurations[0]
        for stack in self.configurations:
            if stack.name == name:
                return stack
        raise FreestandError(f"no configuration named {name!r}; choose one of {self._known()}")

    def select(self, names: str | Iterable[str] | None) -> list[Stack]:
        """The planar configurations called ``names`` (in that order, each once); all for None."""
        if names is None:
            if not self.configurations:
                self.configuration(None)  # the error saying there is none
            return list(self.configurations)
        if isinstance(names, str):
            names = [names]
        return [self.configuration(name) for name in dict.fromkeys(names)]

    def split(
        self, names: str | Iterable[str] | None
    ) -> tuple[list[Stack], list[BodyConfiguration]]:
        """The planar and the 3-D configurations called ``names`` (each once); all for None."""
        if names is None:
            return list(self.configurations), list(self.bodies)
        if isinstance(names, str):
            names = [names]
        stacks, bodies = [], []
        for name in dict.fromkeys(names):
            body = next((b for b in self.bodies if b.name == name), None)
            if body is not None:
                bodies.append(body)
            elif any(stack.name == name for stack in self.configurations):
                stacks.append(self.configuration(name))
            elif self.model is not None:
                self.model.configuration(name)  # the error listing the names
            else:
                raise FreestandError(
                    f"no configuration named {name!r}; choose one of {self._known()}"
                )
        return stacks, bodies

    def _known(self) -> str:
        names = [repr(stack.name) for stack in self.configurations]
        return ", ".join(names + [f"{body.name!r} (3-D)" for body in self.bodies])

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
    model : ModelFile, Stack, BodyConfiguration, Body or a sequence of them
        A loaded model file (its configurations, excitations, gravity and
        spectra), or stacks and 3-D bodies with ``excitations`` and
        ``gravity`` given here.
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
            tuple(model.body_configurations),
        )
    if isinstance(model, Body):
        model = BodyConfiguration(model.name, (model,))
    items = (model,) if isinstance(model, Stack | BodyConfiguration) else tuple(model)
    if not items or not all(isinstance(item, Stack | BodyConfiguration) for item in items):
        raise TypeError(
            "expected a model file (fs.load_model), a Stack, a 3-D BodyConfiguration or a list "
            f"of them, not {type(model).__name__}"
        )
    return Subject(
        items[0].name if len(items) == 1 else ", ".join(item.name for item in items),
        GRAVITY if gravity is None else float(gravity),
        tuple(item for item in items if isinstance(item, Stack)),
        _excitations(excitations),
        bodies=tuple(item for item in items if isinstance(item, BodyConfiguration)),
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
