"""Markup shared by the report's sections: escaped text, numeric cells, numbered tables and figures.

Every number a reader may want to check carries its full-precision value
(``data-value``) and what it is (``data-quantity``); tables and figures are
numbered in the order they are made (:class:`Document`).
"""

from __future__ import annotations

import math
from html import escape
from itertools import count


def esc(text: object) -> str:
    """``text`` escaped for HTML text and attribute values."""
    return escape(str(text), quote=True)


def data_attrs(**data: object) -> str:
    """`` data-a="x" data-b="y"`` from keyword arguments (``_`` becomes ``-``)."""
    return "".join(f' data-{key.replace("_", "-")}="{esc(value)}"' for key, value in data.items())


def number_text(value: float, digits: int, *, grouped: bool = False) -> str:
    """``value`` with ``digits`` decimals (thousands grouped), true minus signs, infinities."""
    if not math.isfinite(value):
        return "&#8734;" if value > 0 else "&#8722;&#8734;" if value < 0 else "n/a"
    if value == 0:
        return "0"
    text = f"{value:,.{digits}f}" if grouped else f"{value:.{digits}f}"
    if text.startswith("-") and not text.strip("-0.,"):
        text = text[1:]  # a round-off below the digits shown: no sign
    return text.replace("-", "&#8722;")


def number_cell(
    value: float,
    digits: int,
    quantity: str,
    *,
    grouped: bool = False,
    text: str | None = None,
    tag: str = "td",
) -> str:
    """A numeric cell with its full-precision value in ``data-value``."""
    value = float(value)
    shown = text if text is not None else number_text(value, digits, grouped=grouped)
    return (
        f'<{tag} class="num" data-quantity="{esc(quantity)}" data-value="{value!r}" '
        f'data-digits="{digits}">{shown}</{tag}>'
    )


def table_head(*headers: str) -> str:
    """A ``<thead>``; headers with a unit in brackets are right-aligned (numbers)."""
    cells = "".join(
        f'<th class="num">{h}</th>' if "[" in h or h.endswith("[-]") else f"<th>{h}</th>"
        for h in headers
    )
    return f"<thead><tr>{cells}</tr></thead>"


class Document:
    """Numbering of tables and figures, and the figures drawn so far."""

    def __init__(self) -> None:
        self.tables = count(1)
        self.figures = count(1)
        self.figure_ids = count(1)

    def table(self, caption: str, head: str, rows: list[str], *, cls: str = "", **data) -> str:
        number = next(self.tables)
        klass = f' class="{cls}"' if cls else ""
        return (
            f'<table id="table-{number}"{klass}{data_attrs(**data)}>'
            f"<caption>Table {number}. {caption}</caption>{head}"
            f"<tbody>{''.join(rows)}</tbody></table>"
        )

    def figure(self, drawing, caption: str, **data) -> str:
        from freestand.plot.svg import figure_svg

        number = next(self.figures)
        svg = figure_svg(drawing, f"f{number}")
        return (
            f'<figure id="figure-{number}"{data_attrs(**data)}>{svg}'
            f"<figcaption><b>Figure {number}.</b> {caption}</figcaption></figure>"
        )
