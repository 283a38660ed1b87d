"""A digest of many 3-D time histories, to tell whether a change of the engine moved any run.

    python benchmarks/body_sweep.py record OUT.pkl     # the digests of this engine's runs
    python benchmarks/body_sweep.py compare A.pkl B.pkl

The runs (294): the benchmark's four cases over 20 s, the campaign's two
bodies under every other record of the suite at four scales, 150 random
bodies (``mujoco_body.robust_case``) and 60 under strong records
(``mujoco_body.strong_case``). A run's digest is a hash of its time, state,
patch, slip flags, forces and events, with its status and peaks; ``compare``
counts the runs identical to the last bit, those whose peaks moved by more
than 1e-6 (relative), and those whose status changed, and names the latter
two. A change meant to leave the arithmetic alone must show every run
identical; one that changes round-off moves chaotic runs' peaks, and should
change no status but near a threshold.

numba caches a compiled function by its own file: after editing a kernel,
delete the package's ``__pycache__/*.nbi`` and ``*.nbc`` before recording,
or the engine's loop may still hold the old code.
"""

from __future__ import annotations

import hashlib
import pickle
import sys
import time

import numpy as np

import mujoco_body as mb
from freestand.core.dynamics.body_history import simulate_body

ROBUST = 150  # random bodies
STRONG = 60  # random bodies under strong records
PEAK_MOVE = 1e-6  # a peak that moves by more than this (relative) is named


def digest(result) -> tuple:
    """(hash of the histories and events, (status, tilt, slide, twist, overturned))."""
    hashed = hashlib.sha1()
    for array in (result.time, result.state, result.patch, result.sliding,
                  result.normal_force, result.friction_force):  # fmt: skip
        hashed.update(np.ascontiguousarray(array).tobytes())
    hashed.update(repr(result.events).encode())
    peaks = (result.status, result.max_rotation, result.max_slide, result.max_twist,
             result.overturned)  # fmt: skip
    return hashed.hexdigest(), peaks


def record(path: str) -> None:
    records, _ = mb.suite_records()
    mb._WORKER["records"] = records  # strong_case reads the suite there
    runs = {}
    start = time.perf_counter()
    for i, case in enumerate(mb.CASES):
        motion = mb.case_motion(case, records, mb.SUITE_DURATION)
        runs[("case", i)] = digest(simulate_body(case.body, motion, mb.SUITE_DURATION))
    for b in (0, 1):
        for index in range(0, len(records), 2):
            for level in (0.7, 1.3, 1.9, 2.5):
                motion = mb.scaled(records[index], level)
                result = simulate_body(mb.CASES[b].body, motion, mb.SUITE_DURATION)
                runs[("campaign", b, index, level)] = digest(result)
    for seed in range(ROBUST):
        body, index, scale, restitution = mb.robust_case(seed)
        motion = mb.scaled(records[index], scale, mb.ROBUST_DURATION)
        result = simulate_body(body, motion, mb.ROBUST_DURATION, restitution=restitution)
        runs[("robust", seed)] = digest(result)
    for seed in range(STRONG):
        body, motion, restitution = mb.strong_case(seed)
        end = motion.duration + mb.STRONG_AFTER
        runs[("strong", seed)] = digest(simulate_body(body, motion, end, restitution=restitution))
    with open(path, "wb") as file:
        pickle.dump(runs, file)
    print(f"{len(runs)} runs in {time.perf_counter() - start:.1f} s: {path}")


def compare(before_path: str, after_path: str) -> None:
    with open(before_path, "rb") as file:
        before = pickle.load(file)
    with open(after_path, "rb") as file:
        after = pickle.load(file)
    identical = moved = changed = 0
    for key, (hashed, peaks) in before.items():
        other_hash, other = after[key]
        if hashed == other_hash:
            identical += 1
            continue
        if peaks[0] != other[0] or peaks[4] != other[4]:
            changed += 1
            print(f"  status {key}: {peaks} -> {other}")
            continue
        pairs = zip(peaks[1:4], other[1:4], strict=True)
        change = max(abs(a - b) / max(abs(a), 1e-12) for a, b in pairs)
        if change > PEAK_MOVE:
            moved += 1
            print(f"  moved {key}: peaks by {change:.2e} (relative)")
    print(
        f"{len(before)} runs: {identical} identical to the last bit, {moved} moved a peak by"
        f" more than {PEAK_MOVE:g}, {changed} changed status"
    )


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "record":
        record(sys.argv[2])
    elif len(sys.argv) == 4 and sys.argv[1] == "compare":
        compare(sys.argv[2], sys.argv[3])
    else:
        print(__doc__)
        sys.exit(2)
