"""The storage cask's fragility campaign: 1,200 3-D simulations on one and two workers.

The cask of ``examples/cask.toml`` (a solid cylinder, R 1.683 m, H 6.083 m, 163 t,
centre of gravity 3.0 m up) under the 20 three-component RG 1.60 records of
``examples/cask_comparison.py`` (20 s each, generated into ``examples/cask-records``
if missing, about 30 s, not timed): stripes of PGA RotD50 from 0.1 to 1.5 g (15
levels), 4 samples of the static friction uniform on 0.2-0.8 per record and level, the
incidence angle drawn per simulation: 20 x 15 x 4 = 1,200 simulations, each run
(``fs.fragility``, as ``freestand fragility``) until the cask rests after the record,
at most 10 s later. Printed: the wall time of the whole campaign on 1 and on 2 workers
(the worker processes' start included), the rate per core, the CPU time per
simulation (this process and its worker processes: other work on the machine inflates
it less than the wall time), the scaling from 1 to 2 workers, and the simulations
completed, capped (still moving 10 s after the record) and failed. A small campaign on
each worker count first warms the compiled code.

    python benchmarks/cask_campaign.py [--workers 1,2]
"""

from __future__ import annotations

import argparse
import os
import resource
import time
from pathlib import Path

import freestand as fs

ROOT = Path(__file__).resolve().parents[1]
MODEL = ROOT / "examples" / "cask.toml"
SUITE = ROOT / "examples" / "cask-records"
OUTCOMES = ["slide:cask>0.1m", "rotation:cask>0.5alpha", "overturn:cask"]
FRICTION = ["cask.friction.static=uniform(0.2,0.8)"]


def suite_file() -> Path:
    """The comparison's suite, generated as ``examples/cask_comparison.py`` does if missing."""
    path = SUITE / "suite.toml"
    if not path.exists():
        fs.generate_suite(
            "rg1.60:pga=0.3g,damping=5%", count=20, duration=20.0, seed=20,
            horizontal_y=True, vertical="rg1.60:pga=0.2g,damping=5%,direction=vertical",
            name="RG 1.60, three components, 20 x 20 s", output=SUITE,
        )  # fmt: skip
    return path


def _cpu() -> float:
    """CPU seconds of this process and of its finished children (the worker processes)."""
    own = resource.getrusage(resource.RUSAGE_SELF)
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def campaign(model, suite, workers: int, levels: str = "0.1g:1.5g:15", records=None):
    """One campaign; (wall seconds, CPU seconds, result)."""
    if records is not None:
        suite = suite.motions[:records]
    cpu = _cpu()
    start = time.perf_counter()
    result = fs.fragility(
        model, suite, "pga-rotd50", levels, OUTCOMES, configuration="cask", vary=FRICTION,
        samples=4, seed=20, bootstrap=0, workers=workers,
    )  # fmt: skip
    return time.perf_counter() - start, _cpu() - cpu, result


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--workers", default="1,2", help="worker counts (default 1,2)")
    counts = [int(w) for w in parser.parse_args().workers.split(",")]
    model = fs.load_model(MODEL)
    suite = fs.load_suite(suite_file())
    print(f"machine: {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f} at start")
    wall = {}
    for workers in counts:
        campaign(model, suite, workers, "0.5g:1.5g:2", records=2)  # warm the compiled code
        seconds, cpu, result = campaign(model, suite, workers)
        document = result.to_dict()
        statuses = document["statuses"]
        total = document["simulations"]
        wall[workers] = seconds
        print(
            f"{workers} worker(s): {total} simulations in {seconds:.1f} s wall, "
            f"{total / seconds:.1f} /s, {total / seconds / workers:.1f} /s per core; "
            f"{cpu:.1f} s of CPU ({1000 * cpu / total:.1f} ms per simulation, "
            f"{total / cpu:.1f} per CPU second); "
            f"completed {statuses.get('completed', 0)}, capped {statuses.get('capped', 0)}, "
            f"failed {statuses.get('failed', 0) + statuses.get('invalid', 0)} "
            f"(load average {os.getloadavg()[0]:.1f})"
        )
    if 1 in wall and 2 in wall:
        print(f"scaling 1 -> 2 workers: {wall[1] / wall[2]:.2f} x")


if __name__ == "__main__":
    main()
