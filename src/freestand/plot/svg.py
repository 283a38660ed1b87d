"""Figures as inline SVG for self-contained HTML documents.

Text is kept as text (``svg.fonttype = "none"``), so the figures stay crisp
in print and searchable; the ids matplotlib gives clip paths and markers are
prefixed per figure, so that several figures can share one HTML document
without clashing ids. Metadata (date, RDF namespaces) is left out: the SVG
refers to nothing outside itself, not even by a namespace URI (the HTML
parser puts an inline ``<svg>`` in the SVG namespace by itself).
"""

from __future__ import annotations

import io
import re

_ID = re.compile(r'\bid="([^"]+)"')


def figure_svg(figure, prefix: str) -> str:
    """The ``<svg>`` element of ``figure``, ready to be put inline in HTML.

    Parameters
    ----------
    figure : matplotlib.figure.Figure
        The figure to write.
    prefix : str
        Prefix for every id in the SVG (letters, digits, ``-``), unique in the
        document.

    Returns
    -------
    str
        The ``<svg ...>...</svg>`` text, without XML declaration or DOCTYPE.
    """
    import matplotlib

    if not re.fullmatch(r"[A-Za-z][A-Za-z0-9-]*", prefix):
        raise ValueError(f"{prefix!r} is not an id prefix (a letter, then letters, digits, -)")
    buffer = io.StringIO()
    with matplotlib.rc_context({"svg.fonttype": "none", "svg.hashsalt": prefix}):
        figure.savefig(buffer, format="svg", metadata={"Date": None})
    text = buffer.getvalue()
    text = text[text.index("<svg") :]
    text = re.sub(r"<metadata>.*?</metadata>\s*", "", text, flags=re.S)
    # Inline in HTML the parser puts <svg> in the SVG namespace and knows xlink:href.
    text = re.sub(r'\s+xmlns(?::\w+)?="[^"]*"', "", text)
    ids = set(_ID.findall(text))
    for old in sorted(ids, key=len, reverse=True):
        new = f"{prefix}-{old}"
        text = text.replace(f'id="{old}"', f'id="{new}"')
        text = text.replace(f"url(#{old})", f"url(#{new})")
        text = text.replace(f'href="#{old}"', f'href="#{new}"')
    return text.strip()
