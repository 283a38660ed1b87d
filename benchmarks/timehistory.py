"""Time-history simulation: wall time for a 20 s record at 200 samples per second.

Synthesises a deterministic record (seeded white noise through a Kanai-Tajimi
filter, 2.5 Hz, 60 % damping, under a 2 s rise / 8 s strong / 10 s decay
envelope), scales it to a peak ground acceleration, and simulates:

- a single rocking block (0.6 m x 2.0 m, tan(alpha) = 0.3) at PGA 4 m/s^2,
  by the single-block fast path (best of 20 runs after compilation) and by
  the general path;
- the crane's configurations of examples/crane.toml (two blocks each) at PGA
  5 m/s^2, with a vertical component of 40 % of the horizontal, by the
  general path.

Prints, for each, the wall time, the solver used, steps, events, peak
rotation and slide of every block and whether anything overturned.

    python benchmarks/timehistory.py
"""

from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np

from freestand.core.dynamics.timehistory import SupportMotion, simulate
from freestand.core.model import Block, Friction, Stack
from freestand.io.model_file import load_model

SAMPLING = 200.0  # samples per second
DURATION = 20.0  # s
ROOT = Path(__file__).resolve().parents[1]


def filtered_noise(seed: int, peak: float) -> np.ndarray:
    """Kanai-Tajimi-filtered white noise with an envelope, scaled to ``peak`` [m/s^2]."""
    rng = np.random.default_rng(seed)
    dt = 1.0 / SAMPLING
    count = int(round(DURATION * SAMPLING)) + 1
    t = np.arange(count) * dt
    noise = rng.standard_normal(count)
    omega, zeta = 2.0 * np.pi * 2.5, 0.6
    # ground filter x'' + 2 zeta omega x' + omega^2 x = -w; output 2 zeta omega x' + omega^2 x
    x = v = 0.0
    out = np.zeros(count)
    for k in range(count):
        a = -noise[k] - 2 * zeta * omega * v - omega**2 * x
        v += a * dt
        x += v * dt
        out[k] = 2 * zeta * omega * v + omega**2 * x
    envelope = np.clip(t / 2.0, 0.0, 1.0) * np.where(t < 10.0, 1.0, np.exp(-(t - 10.0) / 3.0))
    record = out * envelope
    return record * peak / np.max(np.abs(record))


def run(stack: Stack, motion: SupportMotion, method: str = "auto", repeat: int = 1) -> None:
    simulate(stack, motion, 0.5, method=method)  # compile
    elapsed = math.inf
    for _ in range(repeat):
        start = time.perf_counter()
        result = simulate(stack, motion, method=method)
        elapsed = min(elapsed, time.perf_counter() - start)
    kinds = {}
    for event in result.events:
        kinds[event.kind] = kinds.get(event.kind, 0) + 1
    print(
        f"{stack.name:18s} {elapsed * 1e3:9.1f} ms wall  {result.diagnostics.method}"
        f"  status {result.status}  {result.message}"
    )
    print(f"{'':18s} steps {result.diagnostics.steps}, events {dict(sorted(kinds.items()))}")
    for index, name in enumerate(result.block_names):
        print(
            f"{'':18s} {name:8s} max rotation {result.max_rotation[index]:.5f} rad,"
            f" max slide {result.max_slide[index]:.4f} m,"
            f" uplift {bool(result.uplift[index])}, overturned {bool(result.overturned[index])}"
        )


def main() -> None:
    horizontal = filtered_noise(seed=7, peak=4.0)
    block = Block(
        "block",
        500.0,
        500.0 * (0.6**2 + 2.0**2) / 12.0,
        (0.0, 1.0),
        -0.3,
        0.3,
        0.0,
        Friction(0.8, 0.7),
    )
    print(f"record: {DURATION:g} s at {SAMPLING:g} samples/s")
    single = Stack("single block", (block,))
    motion = SupportMotion(1.0 / SAMPLING, horizontal)
    print("single-block fast path (rocking integrator step 0.02/p, cut at every sample):")
    run(single, motion, "single-block", repeat=20)
    print("general path (default step):")
    run(single, motion, "general")
    model = load_model(ROOT / "examples" / "crane.toml")
    horizontal = filtered_noise(seed=11, peak=5.0)
    vertical = 0.4 * filtered_noise(seed=13, peak=5.0)
    motion = SupportMotion(1.0 / SAMPLING, horizontal, vertical)
    print("general path (default step):")
    for stack in model.configurations:
        run(stack, motion)


if __name__ == "__main__":
    main()
