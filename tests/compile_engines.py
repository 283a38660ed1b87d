"""Compile the engines into numba's cache once, before the test workers start.

Every test worker that runs a time history compiles the engine it uses, unless
numba's on-disk cache already holds it: on a fresh clone both workers compiled
the planar and the 3-D engine, each some two minutes. ``conftest.py`` runs the
two jobs below side by side (one process each) before the workers start; the
workers then load the engines from the cache. Nothing is asserted here: a job
that fails leaves the compilation to the tests, which report any error.

    python -m tests.compile_engines planar     # or three-d
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"


def planar() -> None:
    """The stack engine: screening, a time history and a pulse's overturning (the crane)."""
    import freestand as fs

    model = fs.load_model(EXAMPLES / "crane.toml")
    fs.screen(model)
    record = fs.load_record(
        EXAMPLES / "records" / "synthetic_H.AT2", vertical=EXAMPLES / "records" / "synthetic_UP.AT2"
    ).scaled_to_peak(8.0)
    fs.simulate(model, record, configuration="x-z cart right", duration=1.0)
    fs.overturning(model, configuration="x-z cart right", block="cart", frequencies=[2.0])


def three_d() -> None:
    """The 3-D engine: a body's screening, time history and overturning (examples/bodies.toml)."""
    import freestand as fs

    model = fs.load_model(EXAMPLES / "bodies.toml")
    fs.screen(model, directions=4)
    pair = fs.load_record(
        EXAMPLES / "records" / "synthetic_H.AT2",
        horizontal_y=EXAMPLES / "records" / "synthetic_UP.AT2",
        vertical=EXAMPLES / "records" / "synthetic_UP.AT2",
    ).scaled_to_peak(7.0)
    fs.simulate(model, pair, configuration="cask", duration=1.0)
    fs.overturning(model, configuration="cabinet", frequencies=[2.0])


JOBS = {"planar": planar, "three-d": three_d}


def compile_side_by_side() -> tuple[float, list[str]]:
    """Run every job in its own process, at once; (seconds taken, the jobs that failed)."""
    started = time.perf_counter()
    processes = {
        name: subprocess.Popen(
            [sys.executable, "-m", "tests.compile_engines", name],
            cwd=ROOT,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
            env=dict(os.environ, MPLBACKEND="Agg"),
        )
        for name in JOBS
    }
    failed = [name for name, process in processes.items() if process.wait() != 0]
    return time.perf_counter() - started, failed


if __name__ == "__main__":
    JOBS[sys.argv[1]]()
