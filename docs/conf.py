"""Sphinx configuration of the freestand documentation site (``make docs`` -> build/docs).

The user guide is the Markdown of this folder (MyST); the API reference is
generated from the numpydoc docstrings; the model-file reference is written
from the validation schema at every build (``_ext/model_reference.py``); the
gallery (``examples/gallery``) is executed at every build by sphinx-gallery.
"""

from __future__ import annotations

import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE / "_ext"))

import freestand  # noqa: E402

project = "freestand"
author = "freestand contributors"
copyright = "freestand contributors"  # noqa: A001
version = release = freestand.__version__

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "numpydoc",
    "sphinx_gallery.gen_gallery",
    "model_reference",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "gallery/*.ipynb", "gallery/*.py", "gallery/*.zip"]
templates_path = ["_templates"]

# --- MyST: the user guide's Markdown, links between pages as they are on GitHub
myst_heading_anchors = 3
myst_enable_extensions = ["colon_fence"]

# --- API reference from the docstrings
autosummary_generate = True
autodoc_typehints = "none"
numpydoc_show_class_members = False
numpydoc_xref_param_type = False
numpydoc_validation_checks: set[str] = set()

# --- the gallery, executed at every build (callables by name: the configuration stays cacheable)
sphinx_gallery_conf = {
    "examples_dirs": [str(HERE.parent / "examples" / "gallery")],
    "gallery_dirs": ["gallery"],
    "filename_pattern": r"/plot_",
    "image_scrapers": ("gallery_scraper.figure_scraper",),
    "reset_modules": ("gallery_scraper.reset_figures",),
    "download_all_examples": False,
    "remove_config_comments": True,
    "abort_on_example_error": True,
    "only_warn_on_example_error": False,
    "show_memory": False,
    "min_reported_time": 1,
    "within_subsection_order": "FileNameSortKey",
}

# --- the site: the pydata theme, no script or font from elsewhere (it opens offline)
html_theme = "pydata_sphinx_theme"
html_title = f"freestand {release}"
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "secondary_sidebar_items": ["page-toc"],
    "footer_start": ["copyright"],
    "footer_end": [],
}
# the reader's light or dark preference (the theme's script refuses an empty mode)
html_context = {"default_mode": "auto"}
html_show_sourcelink = False
html_copy_source = False
html_last_updated_fmt = None
