"""The crane report rendered in headless Chromium (Debian's ``chromium``).

Loads without console errors, every figure has a size, the page and its
print layout render; a screenshot is saved in the test's temporary folder.
The test installs nothing: with no Chromium or no playwright it is skipped,
unless ``FREESTAND_REQUIRE_BROWSER=1`` (set by .ci/run), where it fails.
"""

from __future__ import annotations

import os
import shutil

import pytest

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
REQUIRED = os.environ.get("FREESTAND_REQUIRE_BROWSER") == "1"
FLAGS = [
    "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
]  # fmt: skip


def _need(condition: bool, reason: str) -> None:
    if not condition:
        if REQUIRED:
            pytest.fail(f"{reason} (FREESTAND_REQUIRE_BROWSER=1)")
        pytest.skip(reason)


@pytest.fixture(scope="module")
def browser_page(crane_report, tmp_path_factory):
    _need(CHROMIUM is not None, "Chromium is not installed (Debian: apt-get install chromium)")
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        _need(False, "playwright is not installed (pip install -e '.[dev]')")
    folder = tmp_path_factory.mktemp("browser")
    path = folder / "crane-report.html"
    path.write_text(crane_report[1], encoding="utf-8")
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
        try:
            page = browser.new_page(viewport={"width": 1100, "height": 900})
            errors: list[str] = []
            requests: list[str] = []
            page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
            page.on("pageerror", lambda e: errors.append(str(e)))
            page.on("request", lambda r: requests.append(r.url))
            page.goto(path.as_uri(), wait_until="load")
            yield page, errors, requests, folder, path
        finally:
            browser.close()


def test_page_loads_without_console_errors_or_requests(browser_page):
    page, errors, requests, _, path = browser_page
    assert errors == []
    assert requests == [path.as_uri()]  # nothing fetched but the file itself
    assert page.title().startswith("Seismic screening report")


def test_every_figure_has_a_size(browser_page):
    page, *_ = browser_page
    figures = page.locator("figure svg")
    assert figures.count() == 7
    for k in range(figures.count()):
        box = figures.nth(k).bounding_box()
        assert box is not None and box["width"] > 200 and box["height"] > 100, (k, box)


def test_screenshot_of_the_whole_page(browser_page):
    page, _, _, folder, _ = browser_page
    target = folder / "crane-report.png"
    page.screenshot(path=str(target), full_page=True)
    data = target.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")
    assert width >= 1000 and height > 5000  # the whole report, not the first screen
    assert len(data) > 100_000


def test_print_layout_keeps_rows_and_figures_whole(browser_page):
    page, errors, _, folder, _ = browser_page
    page.emulate_media(media="print")
    rules = page.evaluate(
        """() => ({
            tr: getComputedStyle(document.querySelector('tbody tr')).breakInside,
            figure: getComputedStyle(document.querySelector('figure')).breakInside,
            thead: getComputedStyle(document.querySelector('thead')).display,
            nav: getComputedStyle(document.querySelector('nav')).display,
        })"""
    )
    assert rules == {"tr": "avoid", "figure": "avoid", "thead": "table-header-group", "nav": "none"}
    pdf = page.pdf(path=str(folder / "crane-report.pdf"), format="A4")
    assert pdf[:5] == b"%PDF-" and pdf.count(b"/Type /Page") >= 5
    page.emulate_media(media="screen")
    assert errors == []
