"""The stack engine's hot kernels are loaded from numba's cache before its loop.

numba's cached ``run`` carries copies of the functions it calls, which measure
slower than their own compiled code (docs/benchmarks.md); loading the hot ones
first links the loop to them. Loading must never compile, fail or change a result.
"""

from __future__ import annotations

import subprocess
import sys

import numba as nb
import numpy as np

from freestand.core.contact import engine as contact_engine
from freestand.core.dynamics import engine, timehistory
from freestand.core.dynamics.results import SupportMotion
from freestand.core.model import Block, Friction, Stack


def test_the_hot_kernels_are_compiled_functions_the_loop_calls():
    source = "".join(
        open(module.__file__, encoding="utf-8").read() for module in (engine, contact_engine)
    )
    for kernel in engine.HOT_KERNELS:
        assert hasattr(kernel, "overloads")  # a numba dispatcher
        assert kernel.__name__ + "(" in source


def test_a_kernel_without_a_cache_entry_loads_nothing_and_compiles_nothing():
    @nb.njit(cache=False)
    def never_cached(x):
        return x + 1.0

    plain = object()
    assert engine.load_cached_kernels((never_cached, plain)) == 0
    assert len(never_cached.overloads) == 0


def test_loading_twice_loads_nothing_more_and_the_engine_runs():
    timehistory._load_engine()
    assert engine.load_cached_kernels(engine.HOT_KERNELS) == 0  # already loaded
    block = Block.rectangle("block", 0.4, 2.0, 1000.0, Friction(0.8, 0.7))
    time = np.arange(0.0, 1.0, 0.01)
    motion = SupportMotion(0.01, 3.0 * np.sin(2.0 * np.pi * time))
    result = timehistory.simulate(Stack("one", (block,)), motion, method="general")
    assert result.status == "completed"


def test_a_new_process_loads_the_hot_kernels_from_the_cache():
    # the engine has run in this process, so numba's cache holds its kernels; a new
    # process must find them there (this breaks if numba's cache layout changes and
    # the loading silently finds nothing: docs/benchmarks.md, the cache's copies)
    block = Block.rectangle("block", 0.4, 2.0, 1000.0, Friction(0.8, 0.7))
    time = np.arange(0.0, 1.0, 0.01)
    motion = SupportMotion(0.01, 3.0 * np.sin(2.0 * np.pi * time))
    timehistory.simulate(Stack("one", (block,)), motion, method="general")
    code = "from freestand.core.dynamics import timehistory; print(timehistory._load_engine())"
    output = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True, timeout=600
    )
    assert int(output.stdout.split()[-1]) >= len(engine.HOT_KERNELS)
