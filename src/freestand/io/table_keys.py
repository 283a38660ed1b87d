"""The keys of model-file tables that are validated by their readers, not by the schema.

The ``[[spectrum]]`` and ``[fragility]`` tables are read key by key
(:mod:`freestand.io.spectrum_input`, :mod:`freestand.report.fragility`);
each reader takes its keys, units and defaults from a table of
:class:`TableKey`, and the model-file reference
(:mod:`freestand.io.model_reference`) is written from the same tables, so
that the two cannot drift apart.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class TableKey:
    """One key of a table: what it is, its unit and its default.

    Attributes
    ----------
    what : str
        What the key is, in words.
    unit : str
        SI unit of a number (``"m/s^2"``; ``"-"`` dimensionless; ``""`` text).
    default : object
        The value the reader takes when the key is left out (None: none).
    required : bool
        Whether the key must be given.
    shown_default : str
        The default in words, where the value alone does not say it
        (``"the first configuration"``).
    """

    what: str
    unit: str = ""
    default: object = None
    required: bool = False
    shown_default: str = ""

    def default_text(self) -> str:
        """The default as the reference shows it: ``required``, a value, or in words."""
        if self.required:
            return "required"
        if self.shown_default:
            return self.shown_default
        if self.default is None:
            return "none"
        if isinstance(self.default, str):
            return f'"{self.default}"'
        if isinstance(self.default, bool):
            return str(self.default).lower()
        return f"{self.default:g}" if isinstance(self.default, float) else str(self.default)
