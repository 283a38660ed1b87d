"""The 3-D engine's work records, one pair per thread, zeroed for each run.

The loop (:func:`freestand.core.dynamics.body_engine.run`) takes its scratch
(:data:`~freestand.core.contact.body_kernel.SCRATCH_DTYPE`) and the impulses'
work arrays (:data:`~freestand.core.contact.body_impulse.IMPULSE_WORK_DTYPE`)
from its caller, as one-element structured arrays. Creating such an array
walks its dtype's 30-odd fields: some 5 us when numpy's structures are in the
caches, 50-80 us where another program's run has just left them out (the 3-D
benchmark's runs, alternated with MuJoCo's). A thread keeps its pair here and
each run zeroes it through a byte view, a plain fill.
"""

from __future__ import annotations

import threading

import numpy as np

from freestand.core.contact.body_impulse import IMPULSE_WORK_DTYPE
from freestand.core.contact.body_kernel import SCRATCH_DTYPE

_KEPT = threading.local()


def engine_work() -> tuple[np.ndarray, np.ndarray]:
    """(scratch, impulse work): one-element arrays of ``SCRATCH_DTYPE`` and
    ``IMPULSE_WORK_DTYPE``, every byte zero.

    The same two arrays for every call on a thread, zeroed again by each
    call: the run given them must be over before the next call on its
    thread (a time history's runs are: nothing keeps them after it).
    """
    kept = getattr(_KEPT, "arrays", None)
    if kept is None:
        scratch = np.zeros(1, dtype=SCRATCH_DTYPE)
        impulse_work = np.zeros(1, dtype=IMPULSE_WORK_DTYPE)
        kept = _KEPT.arrays = (scratch, impulse_work, scratch.view(np.uint8),
                               impulse_work.view(np.uint8))  # fmt: skip
    kept[2].fill(0)
    kept[3].fill(0)
    return kept[0], kept[1]
