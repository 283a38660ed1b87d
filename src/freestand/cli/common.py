"""Helpers shared by the sub-commands: option parsing, consoles, model loading, output paths.

Output paths are checked and written by :mod:`freestand.io.outputs` (re-exported here).
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
from pathlib import Path

from rich.console import Console
from rich.markup import escape

from freestand.core.motion.spectra import Spectrum
from freestand.errors import FreestandError
from freestand.io.model_file import ModelFile, load_model
from freestand.io.outputs import (  # noqa: F401 (the commands' output helpers, re-exported)
    Staging,
    check_file,
    check_folder,
    check_writable,
    staging,
)
from freestand.io.units import to_si


def console() -> Console:
    """A console that is wide enough for the tables when writing to a pipe or file."""
    terminal = Console(emoji=False)
    return terminal if terminal.is_terminal else Console(emoji=False, width=120)


def error_console() -> Console:
    """The console on stderr, for warnings and progress."""
    return Console(emoji=False, stderr=True, highlight=False, soft_wrap=True)


def warn(message: str) -> None:
    """Print a warning on stderr (never on stdout, which may hold a JSON document)."""
    error_console().print(f"[bold yellow]warning:[/] {escape(message)}")


COMPILE_NOTICE = (
    "compiling freestand's engines for this machine: the first run of an analysis takes "
    "minutes (the 3-D engine about two), later runs load them from numba's cache"
)


@contextlib.contextmanager
def compile_notice() -> Iterator[None]:
    """Say once on stderr when numba compiles an engine (its first run on this machine).

    The engines are compiled on first use and cached on disk: without a word the
    first 3-D run would sit at 0 % for some two minutes. numba's event API
    reports a compilation (``numba:compile``), not a load from its cache.
    """
    from numba.core import event

    class _Notice(event.Listener):
        said = False

        def on_start(self, _event) -> None:
            if not self.said:
                self.said = True
                error_console().print(escape(COMPILE_NOTICE) + " ...")

        def on_end(self, _event) -> None:
            pass

    with event.install_listener("numba:compile", _Notice()):
        yield


def load(path: Path) -> ModelFile:
    """Load a model file and warn on stderr about what it allows but should not."""
    model = load_model(path)
    for message in model.warnings():
        warn(message)
    return model


def number(text: str | None, option: str, quantity: str, gravity: float = 9.81) -> float | None:
    """A quantity option (``"0.3g"``, ``"2.9 m/s^2"``, ``"5 ms"``, ``"2.9"``) in SI, or None."""
    if text is None:
        return None
    return to_si(text, quantity, field="", source=option, gravity=gravity)


def parse_numbers(
    text: str | None, option: str, unit: str, quantity: str | None = None, gravity: float = 9.81
) -> list[float] | None:
    """``"1.5,2,4.9"`` -> [1.5, 2.0, 4.9]; a FreestandError naming the option otherwise.

    With ``quantity`` (``"acceleration"``, ``"frequency"``, ``"length"``) each
    item may carry a unit (``0.5g``, ``2.5 Hz``); bare numbers are in ``unit``
    (SI). Every value must be finite.
    """
    if text is None:
        return None
    values = []
    for item in filter(None, (part.strip() for part in text.split(","))):
        if quantity is not None and any(c.isdigit() for c in item):
            values.append(to_si(item, quantity, field="", source=option, gravity=gravity))
            continue
        try:
            value = float(item)
        except ValueError:
            value = None
        if value is None or value != value or abs(value) == float("inf"):
            raise FreestandError(
                f"{item!r} is not a number (or not finite); give a comma-separated list in {unit}, "
                "e.g. 1.5,4.9",
                source=option,
            )
        values.append(value)
    if not values:
        raise FreestandError(f"no values given; e.g. {option} 1.5,4.9", source=option)
    return values


def resolve_spectrum(option: str | None, model: ModelFile, direction: str) -> Spectrum | None:
    """The spectrum named by ``--spectrum``, else the model's first one for ``direction``.

    A spectrum of the other direction is refused (:func:`freestand.api.base.resolve_spectrum`).
    """
    from freestand.api.base import resolve_spectrum as resolve
    from freestand.api.base import subject

    with _busy(
        f"computing the response spectrum of {option.partition(':')[2].partition(',')[0]}"
        if option is not None and option.strip().startswith("record:")
        else None
    ):
        return resolve(option, subject(model), direction)


@contextlib.contextmanager
def _busy(description: str | None) -> Iterator[None]:
    """A spinner on stderr for work that may take a while (a line when not a terminal)."""
    if description is None:
        yield
        return
    err = error_console()
    if not err.is_terminal:
        err.print(f"{escape(description)} ...")
        yield
        return
    with err.status(escape(description)):
        yield
