"""Writing the report: whole or not at all, and printing it to PDF with Chromium.

The report is built in memory first; :func:`write_atomic` then writes it to
a temporary file in the target folder and renames it over the target, so a
reader never sees half a report and a failure leaves no file behind.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
from pathlib import Path

from freestand.errors import FreestandError

#: Executables tried, in order, for ``--pdf``.
CHROMIUM_NAMES = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")


def write_atomic(path: str | Path, data: str | bytes) -> Path:
    """Write ``data`` to ``path`` through a temporary file and a rename.

    Parameters
    ----------
    path : str or pathlib.Path
        Target file; its folder is created if missing.
    data : str or bytes
        Text (written as UTF-8) or bytes.

    Returns
    -------
    pathlib.Path
        The path written.
    """
    target = Path(path)
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise FreestandError(
            f"cannot create the folder {target.parent} ({error.strerror}); choose another "
            "output path",
            source=str(target),
        ) from None
    payload = data.encode("utf-8") if isinstance(data, str) else data
    handle, temporary = tempfile.mkstemp(
        prefix=f".{target.name}.", suffix=".tmp", dir=target.parent
    )
    try:
        with os.fdopen(handle, "wb") as stream:
            stream.write(payload)
        os.chmod(temporary, 0o644)
        os.replace(temporary, target)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise
    return target


def find_chromium() -> str | None:
    """The path of a Chromium (or Chrome) executable on PATH, if any."""
    for name in CHROMIUM_NAMES:
        found = shutil.which(name)
        if found:
            return found
    return None


def require_chromium() -> str:
    """The Chromium executable, or a FreestandError saying how to install it."""
    found = find_chromium()
    if found is None:
        raise FreestandError(
            "printing to PDF needs Chromium, and none was found on PATH (tried "
            f"{', '.join(CHROMIUM_NAMES)}); install it (Debian: apt-get install chromium) "
            "or open the HTML report in a browser and print it to PDF from there",
            source="--pdf",
        )
    return found


def print_pdf(html_path: str | Path, pdf_path: str | Path, *, timeout: float = 120.0) -> Path:
    """Print the HTML file ``html_path`` to ``pdf_path`` with headless Chromium.

    The page's print styles apply (A4, tables not split mid-row, figures with
    their captions); Chromium's own header and footer are left out.

    Parameters
    ----------
    html_path : str or pathlib.Path
        The report.
    pdf_path : str or pathlib.Path
        The PDF to write (atomically).
    timeout : float, optional
        Seconds to wait for Chromium [s].
    """
    chromium = require_chromium()
    source = Path(html_path).resolve()
    target = Path(pdf_path)
    target.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(dir=target.parent, prefix=".freestand-pdf-") as folder:
        temporary = Path(folder) / "report.pdf"
        command = [
            chromium,
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            f"--user-data-dir={Path(folder) / 'profile'}",
            "--no-pdf-header-footer",
            f"--print-to-pdf={temporary}",
            source.as_uri(),
        ]
        try:
            result = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            raise FreestandError(
                f"Chromium did not finish printing within {timeout:g} s", source="--pdf"
            ) from None
        if result.returncode != 0 or not temporary.is_file() or temporary.stat().st_size == 0:
            detail = (result.stderr or "").strip().splitlines()[-1:] or ["no output"]
            raise FreestandError(
                f"Chromium could not print the report to PDF (exit {result.returncode}: "
                f"{detail[0]}); open the HTML report in a browser and print it from there",
                source="--pdf",
            )
        os.replace(temporary, target)
    return target
