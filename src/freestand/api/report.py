"""Public screening report: :func:`write_report` writes the engineer's report of a model file.

(Not ``fs.report``: that name is the package :mod:`freestand.report`.)
"""

from __future__ import annotations

import datetime as _dt
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from freestand.api.base import Result
from freestand.errors import FreestandError

#: Suffixes of the report's file: HTML, or PDF (printed with headless Chromium).
SUFFIXES = (".html", ".htm", ".pdf")


@dataclass(frozen=True)
class ReportResult(Result):
    """The report written and what it says.

    Attributes
    ----------
    files : tuple of pathlib.Path
        The files written (the HTML report, and the PDF when asked).
    content : ReportContent
        Everything the report shows: the screening cases (paper Tables
        2-5), the overturning assessments (Figs. 6-8), the frequency and
        jump check (Fig. 9), the fragility appendix and the summary of
        conclusions (:mod:`freestand.report.content`).

    Examples
    --------
    >>> import tempfile, freestand as fs
    >>> folder = tempfile.mkdtemp()
    >>> result = fs.write_report(fs.load_model("examples/crane.toml"), f"{folder}/crane.html",
    ...                          date="2024-01-01")
    >>> [path.endswith("crane.html") for path in result.to_dict()["files"]]
    [True]
    """

    files: tuple[Path, ...]
    content: object

    @property
    def summary(self) -> tuple[str, ...]:
        """The conclusions, one sentence (or short paragraph) each."""
        return self.content.summary

    def to_dict(self) -> dict:
        """The ``freestand report --json`` document.

        Keys: ``model``, ``model_file``, ``sha256`` (of the model file),
        ``version`` (freestand's), ``date`` (YYYY-MM-DD), ``summary`` (the
        conclusions), ``flagged_cases`` (ambiguous or inconsistent screening
        cases) and ``files`` (written).

        Returns
        -------
        dict
            JSON-ready: str, int, float, bool, None, lists and dicts
            (non-finite floats as None).
        """
        content = self.content
        return {
            "model": content.model.name,
            "model_file": content.model_file,
            "sha256": content.sha256,
            "version": content.version,
            "date": content.date.isoformat(),
            "summary": list(content.summary),
            "flagged_cases": len(content.flagged),
            "files": [str(path) for path in self.files],
        }

    def to_frame(self):
        """The report's screening table (paper Tables 2-5): one row per case and block.

        The columns of :meth:`freestand.api.screening.ScreeningResult.to_frame`;
        ``attrs`` add ``date`` and ``sha256``.

        Returns
        -------
        pandas.DataFrame
            The table described above: units in the column names, metadata in
            ``attrs``.
        """
        from freestand.api.screening import ScreeningResult

        content = self.content
        model = content.model
        cases = tuple(content.cases)
        screening = ScreeningResult(
            model.name, model.gravity, tuple(model.configurations), cases, ()
        )
        table = screening.to_frame()
        table.attrs.update({"date": content.date.isoformat(), "sha256": content.sha256})
        return table


def default_path(model_file: str | Path) -> Path:
    """``<model>-report.html`` beside the model file."""
    model_file = Path(model_file)
    return model_file.with_name(f"{model_file.stem}-report.html")


def write_report(
    model,
    path: str | Path | None = None,
    *,
    pdf: bool = False,
    date: _dt.date | str | None = None,
    progress: Callable[[str, int, int], None] | None = None,
    record=None,
    angle: float = 0.0,
) -> ReportResult:
    """Write the engineer's screening report of a model file (HTML, and PDF on request).

    One self-contained HTML file (styles and SVG figures inline, no script):
    the summary of conclusions, the inputs with units and the model file's
    SHA-256, the analogues of the paper's Tables 2-5 for every
    configuration, excitation and sense, the overturning assessment of every
    rocking block (Figs. 6-8: Housner 1963, Makris and Roussos 2000, exact),
    the time history of every 3-D configuration under a ``record`` when one
    is given, the vertical frequency and jump check (Fig. 9), a fragility
    appendix for a ``[fragility]`` table, and the method, limits and references
    (``docs/report.md``). It is written to a temporary file and renamed into
    place, so a failure leaves nothing behind.

    Parameters
    ----------
    model : ModelFile, str or pathlib.Path
        A loaded model file, or the path of one.
    path : str or pathlib.Path, optional
        The report: ``FILE.html``, or ``FILE.pdf`` (printed with headless
        Chromium). Default: ``<model>-report.html`` beside the model file.
    pdf : bool, optional
        Also print the HTML report to ``<path>.pdf``.
    date : datetime.date or str, optional
        The date on the report (``YYYY-MM-DD``; default ``SOURCE_DATE_EPOCH``
        if set, else today): the same date gives the same bytes.
    progress : callable, optional
        Called with (what is being done, steps done, steps in all).
    record : GroundMotion, optional
        A ground record (``fs.load_record(x, horizontal_y=..., vertical=...)``,
        scaled as wished): every 3-D configuration is simulated under it, and
        after it until it rests (:func:`freestand.simulate` with
        ``until_rest``), and section 4 shows its peaks and figures. Planar
        configurations are not simulated (``freestand simulate`` is their
        time history).
    angle : float, optional
        The angle [deg] the record's horizontal pair is turned by, counter-clockwise
        from +x towards +y (:func:`freestand.support_motion3`).

    Returns
    -------
    ReportResult
        The files written, the content and ``to_dict()`` (the ``freestand
        report --json`` document).

    Examples
    --------
    >>> import freestand as fs, tempfile, pathlib
    >>> folder = pathlib.Path(tempfile.mkdtemp())
    >>> result = fs.write_report("examples/crane.toml", folder / "crane.html", date="2024-01-01")
    >>> [path.name for path in result.files]
    ['crane.html']
    """
    from freestand.io.model_file import ModelFile, load_model
    from freestand.io.outputs import check_file
    from freestand.report.content import collect_report, report_date
    from freestand.report.output import require_chromium

    day = date if isinstance(date, _dt.date) else report_date(date)
    if not isinstance(model, ModelFile):
        model = load_model(model)
    target = Path(path) if path is not None else default_path(model.source)
    check_file(target, "--output", SUFFIXES)
    as_pdf = target.suffix.lower() == ".pdf"
    if pdf and as_pdf:
        raise FreestandError(
            f"{str(target)!r} is already a PDF; give -o FILE.html --pdf for both, or "
            "-o FILE.pdf alone",
            source="--pdf",
        )
    if pdf or as_pdf:
        require_chromium()
    steps = [0]

    def step(description: str, done: int, total: int) -> None:
        steps[0] = total + 2
        if progress is not None:
            progress(description, done, total + 2)

    histories = _body_histories(model, record, angle, progress)
    content = collect_report(model, date=day, progress=step, body_histories=histories)
    files = _write(content, target, pdf, as_pdf, progress, steps[0])
    return ReportResult(tuple(files), content)


def _body_histories(model, record, angle: float, progress) -> tuple:
    """The time history of every 3-D configuration under ``record`` (none without one)."""
    from freestand.api.body_simulation import support_motion3
    from freestand.api.simulation import simulate

    if record is None:
        if angle:
            raise FreestandError(
                "--angle turns the record's horizontal pair; give the record (--record)",
                source="--angle",
            )
        return ()
    if not model.body_configurations:
        raise FreestandError(
            "the report simulates the 3-D configurations under the record, and this model has "
            "none; leave --record out (freestand simulate gives the time history of a planar "
            "configuration)",
            source="--record",
        )
    support_motion3(record, angle=angle)  # an angle that is not a number: before any work
    histories = []
    for configuration in model.body_configurations:
        if progress is not None:
            progress(f"time history of {configuration.name} under the record", 0, 1)
        histories.append(
            simulate(
                model, record, configuration=configuration.name, angle=angle, until_rest=True
            )  # fmt: skip
        )
    return tuple(histories)


def _write(content, target: Path, pdf: bool, as_pdf: bool, progress, total: int) -> list[Path]:
    """Render the HTML and write it (and the PDF) through temporary files."""
    from freestand.io.outputs import staging
    from freestand.report.html import render_html
    from freestand.report.output import print_pdf

    def say(description: str, done: int) -> None:
        if progress is not None:
            progress(description, done, total)

    say("drawing the figures and the HTML", total - 2)
    document = render_html(content)
    say(f"writing {target}", total - 1)
    with staging() as stage:
        if as_pdf:
            html = stage.file(target.with_suffix(".html"))
            html.write_text(document, encoding="utf-8")
            say("printing to PDF with Chromium", total - 1)
            print_pdf(html, stage.file(target))
            html.unlink()
            stage.forget(html)
        else:
            stage.file(target).write_text(document, encoding="utf-8")
            if pdf:
                say("printing to PDF with Chromium", total - 1)
                html = stage.file(target.with_suffix(".print.html"))
                html.write_text(document, encoding="utf-8")
                print_pdf(html, stage.file(target.with_suffix(".pdf")))
                html.unlink()
                stage.forget(html)
        written = stage.commit()
    say("done", total)
    return written
