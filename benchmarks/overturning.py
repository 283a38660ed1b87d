"""Benchmark: exact half-sine overturning curve of the crane cart at 100 frequencies.

Prints the time of the first call (including numba compilation, or loading it
from the cache) and of a second call, and a few points of the curve. Not a
test: run it with ``.venv/bin/python benchmarks/overturning.py``.
"""

from __future__ import annotations

import time

import numba
import numpy as np

from freestand.core.rocking.integrator import exact_minimum_overturning_amplitude
from freestand.core.rocking.properties import RockingBlock

CART = RockingBlock(25600.0, 124100.0, (-1.33, -2.83), (1.33, -2.83))


def main() -> None:
    frequency = np.geomspace(0.05, 20.0, 100)
    start = time.perf_counter()
    exact_minimum_overturning_amplitude(CART, "half-sine", frequency[:2])
    warm = time.perf_counter() - start
    start = time.perf_counter()
    result = exact_minimum_overturning_amplitude(CART, "half-sine", frequency)
    elapsed = time.perf_counter() - start
    print(f"threads: {numba.get_num_threads()}")
    print(f"compile or cache load + 2 frequencies: {warm:.2f} s")
    print(f"exact half-sine curve, 100 frequencies: {elapsed:.2f} s")
    print(f"all found: {bool(result.found.all())}")
    for f, a in zip(frequency[::11], result.amplitude[::11], strict=True):
        print(f"  f = {f:7.3f} Hz   a_min = {a:9.4f} m/s^2")


if __name__ == "__main__":
    main()
