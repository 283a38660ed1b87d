"""The real ``freestand report`` command: a whole report, or a clear error and no file."""

from __future__ import annotations

import os
import shutil

import pytest

from tests.conftest import CRANE, run_freestand
from tests.report_html import parse_report


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    folder = tmp_path_factory.mktemp("report")
    target = folder / "out" / "crane.html"
    result = run_freestand("report", str(CRANE), "-o", str(target), "--date", "2024-05-31")
    return result, target


def test_report_command_writes_the_report_and_prints_its_path(written):
    result, target = written
    assert result.returncode == 0, result.stderr
    assert f"wrote {target}" in result.stdout
    report = parse_report(target.read_text(encoding="utf-8"))
    assert report.by_id["date"] == "2024-05-31"
    assert len(report.figures) == 7
    assert [p.name for p in target.parent.iterdir()] == ["crane.html"]  # no temporary left


def test_bad_field_gives_the_error_and_no_file(tmp_path):
    model = tmp_path / "bad.toml"
    model.write_text(CRANE.read_text().replace("mass = 25600", 'mass = "heavy"', 1))
    target = tmp_path / "bad-report.html"
    result = run_freestand("report", str(model), "-o", str(target))
    assert result.returncode == 2
    assert "bad.toml" in result.stderr and "mass" in result.stderr
    assert "Traceback" not in result.stderr + result.stdout
    assert not target.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.toml"]


def test_bad_date_gives_the_error_and_no_file(tmp_path):
    target = tmp_path / "r.html"
    result = run_freestand("report", str(CRANE), "-o", str(target), "--date", "tomorrow")
    assert result.returncode == 2
    assert "--date" in result.stderr and "YYYY-MM-DD" in result.stderr
    assert not target.exists()


def test_pdf_without_chromium_says_how_to_get_it(tmp_path):
    # A PATH with only the interpreter's folder: freestand runs, no Chromium is found.
    env_path = os.path.dirname(shutil.which("python3") or "/usr/bin/python3")
    if any(
        os.path.exists(os.path.join(env_path, name))
        for name in ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")
    ):
        pytest.skip("a Chromium executable sits next to the interpreter")
    import subprocess

    from tests.conftest import freestand_command

    target = tmp_path / "r.html"
    result = subprocess.run(
        [*freestand_command(), "report", str(CRANE), "-o", str(target), "--pdf"],
        capture_output=True,
        text=True,
        env=dict(os.environ, PATH=env_path),
        timeout=120,
    )
    assert result.returncode == 2
    assert "Chromium" in result.stderr and "apt-get install chromium" in result.stderr
    assert not target.exists()
