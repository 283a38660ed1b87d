"""Helpers shared by the sub-commands: option parsing and consoles."""

from __future__ import annotations

from rich.console import Console

from freestand.core.spectra import Spectrum
from freestand.errors import FreestandError
from freestand.io.model_file import ModelFile
from freestand.io.spectrum_input import parse_spectrum_option


def console() -> Console:
    """A console that is wide enough for the tables when writing to a pipe or file."""
    terminal = Console()
    return terminal if terminal.is_terminal else Console(width=120)


def parse_numbers(text: str | None, option: str, unit: str) -> list[float] | None:
    """``"1.5,2,4.9"`` -> [1.5, 2.0, 4.9]; a FreestandError naming the option otherwise."""
    if text is None:
        return None
    values = []
    for item in filter(None, (part.strip() for part in text.split(","))):
        try:
            values.append(float(item))
        except ValueError:
            raise FreestandError(
                f"{item!r} is not a number; give a comma-separated list in {unit}, e.g. 1.5,4.9",
                source=option,
            ) from None
    if not values:
        raise FreestandError(f"no values given; e.g. {option} 1.5,4.9", source=option)
    return values


def resolve_spectrum(option: str | None, model: ModelFile, direction: str) -> Spectrum | None:
    """The spectrum named by ``--spectrum``, else the model's first one for ``direction``."""
    if option is None:
        return model.spectrum(direction)
    return parse_spectrum_option(
        option, model_spectra=model.spectra, base_dir=model.base_dir, gravity=model.gravity
    )
