"""Shared fixtures: the crane example and the console script; hypothesis's settings."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import settings

# Tests never assert wall-clock times, and hypothesis's per-example deadline (200 ms by
# default) is one: on the 2-core machine running two test workers a fast property test
# (tests/test_sampling.py, under load) exceeded it. No deadline, for every property test.
settings.register_profile("freestand", deadline=None)
settings.load_profile("freestand")

ROOT = Path(__file__).resolve().parents[1]
CRANE = ROOT / "examples" / "crane.toml"


@pytest.fixture(scope="session")
def crane_path() -> Path:
    return CRANE


@pytest.fixture(scope="session")
def crane_model():
    from freestand.io.model_file import load_model

    return load_model(CRANE)


def freestand_command() -> list[str]:
    """The installed ``freestand`` console script (next to the running interpreter)."""
    script = Path(sys.executable).with_name("freestand")
    if script.exists():
        return [str(script)]
    found = shutil.which("freestand")
    if found:
        return [found]
    pytest.fail("the freestand console script is not installed; run `make install`")


def run_freestand(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess:
    """Run the real command line and capture its output."""
    env = dict(os.environ, COLUMNS="160", NO_COLOR="1")
    return subprocess.run(
        [*freestand_command(), *args],
        capture_output=True,
        text=True,
        cwd=cwd,
        env=env,
        timeout=600,
    )


@pytest.fixture(scope="session")
def crane_report(crane_model):
    """The crane's screening report, built once: (ReportContent, HTML text)."""
    import datetime

    from freestand.report.content import collect_report
    from freestand.report.html import render_html

    content = collect_report(crane_model, date=datetime.date(2024, 5, 31))
    return content, render_html(content)
