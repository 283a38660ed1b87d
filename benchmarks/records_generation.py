"""Speed of spectrum-compatible record generation (``freestand records generate``).

    python benchmarks/records_generation.py [COUNT]

Generates COUNT (default 30) records of 20 s at 200 samples per second matched
to the RG 1.60 spectrum (0.3 g, 5 %), with the acceptance checks of
docs/records.md, and prints the wall-clock time against an anchor measured in
the same run: one 5 %-damped spectrum of a 20 s record on the 241 check
frequencies (0.2-50 Hz, 100 per decade). Compiled code is loaded (and cached)
before timing. The goal is under 30 s for 30 records.
"""

from __future__ import annotations

import sys
import time

import numpy as np

from freestand.core.motion.design_spectra import rg160_spectrum
from freestand.core.motion.ground_motion import synthetic_ground_motion
from freestand.core.motion.response_spectrum import SpectrumPlan
from freestand.core.motion.spectrum_matching import AcceptanceCriteria, generate_suite


def main(count: int) -> None:
    target = rg160_spectrum(0.3 * 9.81, 0.05)
    generate_suite(target, count=1, duration=4.0, seed=0)  # compile / load the cache
    motion = synthetic_ground_motion(duration=20.0, dt=0.005)
    plan = SpectrumPlan.build(AcceptanceCriteria().frequencies(), 0.005, 0.05)
    plan.pseudo_acceleration(motion.horizontal)
    start = time.perf_counter()
    for _ in range(10):
        plan.pseudo_acceleration(motion.horizontal)
    anchor = (time.perf_counter() - start) / 10
    start = time.perf_counter()
    result = generate_suite(target, count=count, duration=20.0, dt=0.005, seed=2024)
    elapsed = time.perf_counter() - start
    iterations = [r.check.iterations for r in result.horizontal.records]
    attempts = [r.check.attempts for r in result.horizontal.records]
    print(f"anchor: one spectrum, 20 s record, 241 frequencies: {1e3 * anchor:.1f} ms")
    print(
        f"generate: {count} records of 20 s at 200 samples/s: {elapsed:.2f} s "
        f"({elapsed / anchor:.0f} anchors; goal < 30 s)"
    )
    print(
        f"  status {result.status}; iterations per record mean {np.mean(iterations):.1f}, "
        f"max {max(iterations)}; seeds {sum(attempts)}; suite mean / target >= "
        f"{result.horizontal.mean_ratio_min:.3f}; max correlation {result.max_correlation:.3f}"
    )
    for failure in result.failures:
        print(f"  failed: {failure}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 30)
