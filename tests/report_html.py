"""Reading the screening report's HTML back with the standard library's parser.

Every number the report wants checked carries ``data-quantity`` and
``data-value``; the rows and sections around it carry ``data-*`` attributes
saying what it belongs to. :func:`parse_report` collects each such number with
the merged ``data-*`` attributes of its ancestors, the figures, every
``src``/``href`` and the text of ``<style>`` elements.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from html.parser import HTMLParser

VOID = {"meta", "br", "img", "input", "link", "hr", "col", "source", "wbr", "area", "base"}


@dataclass
class Quantity:
    name: str
    value: float | None
    text: str
    digits: int | None
    context: dict
    attr_text: str | None = None

    def matches(self, **where) -> bool:
        return all(self.context.get(k.replace("_", "-")) == v for k, v in where.items())


@dataclass
class Figure:
    attrs: dict
    svg_elements: dict = field(default_factory=dict)
    images: list = field(default_factory=list)
    caption: str = ""


@dataclass
class Report:
    quantities: list = field(default_factory=list)
    figures: list = field(default_factory=list)
    references: list = field(default_factory=list)  # (tag, attribute, value)
    tags: dict = field(default_factory=dict)
    styles: list = field(default_factory=list)
    ids: list = field(default_factory=list)
    by_id: dict = field(default_factory=dict)
    text: str = ""

    def find(self, name: str, **where) -> list[Quantity]:
        return [q for q in self.quantities if q.name == name and q.matches(**where)]

    def one(self, name: str, **where) -> Quantity:
        found = self.find(name, **where)
        assert len(found) == 1, f"{len(found)} cells {name} {where}"
        return found[0]


class _Parser(HTMLParser):
    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.report = Report()
        self.stack: list[tuple[str, dict]] = []
        self.open_quantities: list[tuple[int, Quantity]] = []
        self.figure: Figure | None = None
        self.in_caption = False
        self.in_style = False
        self.id_capture: list[tuple[int, str]] = []
        self.chunks: list[str] = []

    def handle_starttag(self, tag, attrs):
        attributes = {k: (v if v is not None else "") for k, v in attrs}
        self.report.tags[tag] = self.report.tags.get(tag, 0) + 1
        for key in ("src", "href", "xlink:href", "action", "poster", "data"):
            if key in attributes:
                self.report.references.append((tag, key, attributes[key]))
        if "id" in attributes:
            self.report.ids.append(attributes["id"])
            self.id_capture.append((len(self.stack), attributes["id"]))
            self.report.by_id[attributes["id"]] = ""
        if tag == "figure":
            self.figure = Figure(attributes)
            self.report.figures.append(self.figure)
        elif self.figure is not None:
            if tag == "figcaption":
                self.in_caption = True
            elif tag == "img":
                self.figure.images.append(attributes)
            else:
                self.figure.svg_elements[tag] = self.figure.svg_elements.get(tag, 0) + 1
        if tag == "style":
            self.in_style = True
        if "data-quantity" in attributes:
            context = {}
            for _, outer in self.stack:
                context.update({k[5:]: v for k, v in outer.items() if k.startswith("data-")})
            raw = attributes.get("data-value")
            quantity = Quantity(
                attributes["data-quantity"],
                float(raw) if raw is not None else None,
                "",
                int(attributes["data-digits"]) if "data-digits" in attributes else None,
                context,
                attributes.get("data-text"),
            )
            self.report.quantities.append(quantity)
            self.open_quantities.append((len(self.stack), quantity))
        if tag not in VOID:
            self.stack.append((tag, attributes))

    def handle_startendtag(self, tag, attrs):
        self.handle_starttag(tag, attrs)
        if tag not in VOID:
            self.handle_endtag(tag)

    def handle_endtag(self, tag):
        if tag in VOID:
            return
        while self.stack:
            open_tag, _ = self.stack.pop()
            depth = len(self.stack)
            self.open_quantities = [(d, q) for d, q in self.open_quantities if d < depth]
            self.id_capture = [(d, i) for d, i in self.id_capture if d < depth]
            if open_tag == tag:
                break
        if tag == "figure":
            self.figure = None
        if tag == "figcaption":
            self.in_caption = False
        if tag == "style":
            self.in_style = False

    def handle_data(self, data):
        for _, quantity in self.open_quantities:
            quantity.text += data
        for _, key in self.id_capture:
            self.report.by_id[key] += data
        if self.in_caption and self.figure is not None:
            self.figure.caption += data
        if self.in_style:
            self.report.styles.append(data)
        self.chunks.append(data)


def parse_report(text: str) -> Report:
    parser = _Parser()
    parser.feed(text)
    parser.close()
    parser.report.text = " ".join(" ".join(parser.chunks).split())
    return parser.report


def shown_number(text: str) -> float:
    """The number a cell shows: ``"B: 235,803"`` -> 235803.0, ``"−1.317"`` -> -1.317."""
    token = text.split(":")[-1].strip().replace(",", "").replace("\u2212", "-")
    return float(token)
