"""The documentation site (``make docs``) opened offline in headless Chromium.

Every page of the site's skeleton, the API reference of an analysis, the
model-file reference and every gallery example loads from the files alone
(no request leaves ``file://``), with no console error, its text and its
images rendered (each figure decoded, with a size). A screenshot of a
gallery page is saved in the test's temporary folder.

The site is the one in ``$FREESTAND_DOCS`` (set by ``make docs-test``, which
builds it first: then it must exist) or ``build/docs``; when neither is
built the tests are skipped. As for the report's browser test, they are
skipped without Chromium or playwright unless ``FREESTAND_REQUIRE_BROWSER=1``.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from tests.test_report_browser import CHROMIUM, FLAGS, _need

GIVEN = os.environ.get("FREESTAND_DOCS")
SITE = Path(GIVEN) if GIVEN else Path(__file__).resolve().parents[1] / "build" / "docs"
GALLERY = sorted(p.stem for p in (Path(__file__).resolve().parents[1] / "examples" / "gallery").glob("plot_*.py"))  # fmt: skip

#: Page -> (words its title starts with, least number of figures).
PAGES = {
    "index.html": ("freestand", 0),
    "getting-started.html": ("Getting started", 0),
    "guide.html": ("User guide", 0),
    "fragility.html": ("Fragility campaigns", 0),
    "model-file.html": ("Model file reference", 0),
    "api.html": ("API reference", 0),
    "generated/freestand.fragility.html": ("freestand.fragility", 0),
    "generated/freestand.FragilityResult.html": ("freestand.FragilityResult", 0),
    "gallery/index.html": ("Gallery", len(GALLERY)),  # a thumbnail per example
    **{f"gallery/{name}.html": ("", 2) for name in GALLERY},
}


@pytest.fixture(scope="module")
def browser():
    if GIVEN and not (SITE / "index.html").exists():
        pytest.fail(f"FREESTAND_DOCS={GIVEN} holds no built site (make docs)")
    if not (SITE / "index.html").exists():
        pytest.skip("the documentation site is not built (make docs, or make docs-test)")
    _need(CHROMIUM is not None, "Chromium is not installed (Debian: apt-get install chromium)")
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        _need(False, "playwright is not installed (pip install -e '.[dev]')")
    with sync_playwright() as playwright:
        launched = playwright.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
        try:
            yield launched
        finally:
            launched.close()


def _open(browser, page_path: str):
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    errors: list[str] = []
    outside: list[str] = []
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.on("request", lambda r: outside.append(r.url) if not r.url.startswith("file:") else None)
    page.goto((SITE / page_path).as_uri(), wait_until="load")
    return page, errors, outside


@pytest.mark.parametrize("page_path", list(PAGES))
def test_page_renders_offline(browser, page_path):
    title, figures = PAGES[page_path]
    assert (SITE / page_path).exists(), f"{page_path} was not built"
    page, errors, outside = _open(browser, page_path)
    try:
        assert errors == [] and outside == []
        assert page.title().startswith(title)
        heading = page.locator("article h1").first.inner_text()
        assert heading.strip(), "no heading"
        assert len(page.locator("article").inner_text()) > 200
        images = page.evaluate(
            """() => Array.from(document.querySelectorAll('article img')).map(
                   i => [i.getAttribute('src'), i.complete && i.naturalWidth > 0,
                         i.getBoundingClientRect().width])"""
        )
        assert all(loaded for _, loaded, _ in images), images
        shown = [src for src, _, width in images if width > 100]
        assert len(shown) >= figures, (page_path, images)
    finally:
        page.close()


def test_gallery_example_shows_its_output_and_figures(browser, tmp_path_factory):
    page, errors, _ = _open(browser, "gallery/plot_01_crane.html")
    try:
        text = page.locator("article").inner_text()
        # the screening table and the jump check, as computed when the site was built
        assert "3.1.2.3: bridge slides, cart rests on it" in text
        assert "jump possible" in text
        assert (
            page.locator("article img.sphx-glr-single-img, article img.sphx-glr-multi-img").count()
            == 4
        )
        target = tmp_path_factory.mktemp("docs") / "crane-gallery.png"
        page.screenshot(path=str(target), full_page=True)
        assert target.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        assert errors == []
    finally:
        page.close()
