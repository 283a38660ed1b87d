"""sphinx-gallery: show the figures a gallery example makes with ``result.plot()``.

freestand's figures are :class:`matplotlib.figure.Figure` objects made without
pyplot (nothing opens a window), so sphinx-gallery's own scraper, which asks
pyplot for its figures, does not see them. This scraper looks for the
figures among the example's variables after each code block and writes each
new one once, in the order they appear.
"""

from __future__ import annotations

from matplotlib.figure import Figure
from sphinx_gallery.scrapers import figure_rst

_SHOWN: set[int] = set()


def _figures(namespace: dict) -> list[Figure]:
    found = []
    for value in namespace.values():
        candidates = value if isinstance(value, list | tuple) else (value,)
        for item in candidates:
            if isinstance(item, Figure) and id(item) not in _SHOWN and item not in found:
                found.append(item)
    return found


def figure_scraper(block, block_vars, gallery_conf, **kwargs):
    """Save the figures new since the last block; the reST that shows them."""
    paths = []
    names = block_vars["image_path_iterator"]
    for figure, path in zip(_figures(block_vars["example_globals"]), names, strict=False):
        figure.savefig(path, dpi=110)
        _SHOWN.add(id(figure))
        paths.append(path)
    return figure_rst(paths, gallery_conf["src_dir"])


def reset_figures(gallery_conf, fname):
    """Forget the figures of the previous example."""
    _SHOWN.clear()
