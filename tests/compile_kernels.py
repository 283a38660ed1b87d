"""Compile the package's numba kernels once, before the test workers start (``make test``).

The tests run on two workers (pytest-xdist, ``-n auto`` on two cores). Each
worker compiles every kernel it first meets and writes it to the on-disk cache
(``cache=True``), and on a fresh clone both meet nearly all of them: the same
compilation twice, side by side, some three minutes of each worker's time.
Here the 3-D engine and the planar engines compile once, in two processes side
by side (the 3-D engine alone takes about as long as all the planar ones), and
the workers load them from the cache. On a warm cache this takes seconds.

numba's cache checks each compiled function against its own source file only:
a kernel that calls one in another file keeps the callee's old code after that
file is edited (the callee is linked into the caller's cached object code), and
the tests would run it. So compiled kernels older than the newest source of the
numerical core are removed first (:func:`drop_stale_kernels`): after an edit of
``core/`` everything compiles again, as on a fresh clone.

Each process runs the public API (``import freestand as fs``) on the examples,
as the README's tour does, for two seconds of a record: the kernels compile for the
argument types the analyses pass them. Not a test: it asserts nothing, and any
error is the tests' to report as well (it exits non-zero).

    python tests/compile_kernels.py
"""

from __future__ import annotations

import sys
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
RECORDS = ROOT / "examples" / "records"


def _record(fs, peak: float = 6.0, pair: bool = False):
    """The example's synthetic record and its vertical (and a second horizontal), scaled."""
    horizontal, vertical = RECORDS / "synthetic_H.AT2", RECORDS / "synthetic_UP.AT2"
    extra = {"horizontal_y": vertical} if pair else {}
    return fs.load_record(horizontal, vertical=vertical, **extra).scaled_to_peak(peak)


def three_d() -> float:
    """The 3-D engine: screening, time histories of a cylinder and a box, overturning."""
    import freestand as fs

    start = time.perf_counter()
    model = fs.load_model(ROOT / "examples" / "bodies.toml")
    fs.screen(model, directions=8)
    pair = _record(fs, pair=True)
    for configuration in ("cask", "cabinet"):
        fs.simulate(model, pair, configuration=configuration, duration=2.0)
    fs.overturning(model, configuration="cask", frequencies=[2.0])
    return time.perf_counter() - start


def planar() -> float:
    """The planar engines: screening, a time history, overturning, a mode map."""
    import freestand as fs

    start = time.perf_counter()
    model = fs.load_model(ROOT / "examples" / "crane.toml")
    fs.screen(model)
    record = _record(fs)
    fs.simulate(model, record, configuration="x-z cart right", duration=2.0)
    fs.overturning(model, configuration="x-z cart right", frequencies=[2.0])
    fs.mode_map(model, nodes=16)
    return time.perf_counter() - start


def drop_stale_kernels(package: Path = ROOT / "src" / "freestand") -> int:
    """Remove numba's cache files (``.nbi``, ``.nbc``) older than the newest source of
    ``package/core``; returns how many were removed."""
    newest = max(path.stat().st_mtime for path in (package / "core").rglob("*.py"))
    stale = [
        path
        for pattern in ("*.nbi", "*.nbc")
        for path in package.rglob(pattern)
        if path.stat().st_mtime < newest
    ]
    for path in stale:
        path.unlink(missing_ok=True)
    return len(stale)


def main() -> int:
    start = time.perf_counter()
    dropped = drop_stale_kernels()
    if dropped:
        print(f"{dropped} compiled kernel files older than the core's sources removed")
    with ProcessPoolExecutor(2) as pool:
        jobs = {name: pool.submit(job) for name, job in (("3-D", three_d), ("planar", planar))}
        seconds = {name: job.result() for name, job in jobs.items()}
    parts = ", ".join(f"{name} {value:.0f} s" for name, value in seconds.items())
    print(f"kernels compiled or loaded in {time.perf_counter() - start:.0f} s ({parts})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
