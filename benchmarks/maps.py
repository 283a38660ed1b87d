"""Cases per second of the batch solver against the case-by-case solver.

For the crane's two-block configurations (examples/crane.toml):

- a 400 x 400 mode map of the excitation plane (horizontal 0-12 m/s^2,
  vertical -3-10 m/s^2), batch (excitation-plane superposition) against
  ``initial_motion`` on a sample of the nodes;
- a Monte Carlo sweep of 200 000 samples varying friction and geometry
  (static friction uniform(0.15, 0.35), cart centre x offset normal(0, 0.05) m,
  cart mass factor uniform(0.9, 1.1)), batch (compiled per-case solver)
  against ``initial_motion`` on a sample of the cases.

Run: ``.venv/bin/python benchmarks/maps.py``. The first run compiles the
numba kernels (cached afterwards); every timing below is after a warm-up.
"""

from __future__ import annotations

import time
from pathlib import Path

import numba
import numpy as np

from freestand.core.contact.batch import Parameter, case_inputs, solve_batch
from freestand.core.contact.screening import initial_motion
from freestand.core.model import Block, Friction, Stack
from freestand.core.sweeps.mode_map import Axis, mode_map
from freestand.io.model_file import load_model

MODEL = load_model(Path(__file__).resolve().parents[1] / "examples" / "crane.toml")
REFERENCE_CASES = 300


def reference_rate(stack, horizontal, vertical, sense, count=REFERENCE_CASES) -> float:
    start = time.perf_counter()
    for h, v in zip(horizontal[:count], vertical[:count], strict=True):
        initial_motion(stack, float(h), float(v), sense, MODEL.gravity)
    return count / (time.perf_counter() - start)


def main() -> None:
    print(f"numba threads: {numba.get_num_threads()}")
    horizontal = Axis(Parameter("horizontal"), 0.0, 12.0)
    vertical = Axis(Parameter("vertical"), -3.0, 10.0)
    rng = np.random.default_rng(0)
    for name in ("y-z", "x-z cart right", "x-z cart left"):
        stack = MODEL.configuration(name)
        excitation = MODEL.excitations[0]
        mode_map(stack, horizontal, vertical, excitation, 1, 20)  # warm-up
        start = time.perf_counter()
        crane_map = mode_map(stack, horizontal, vertical, excitation, 1, 400)
        seconds = time.perf_counter() - start
        nodes = crane_map.codes.size
        grid_h = rng.uniform(0, 12, REFERENCE_CASES)
        grid_v = rng.uniform(-3, 9.8, REFERENCE_CASES)
        ref = reference_rate(stack, grid_h, grid_v, 1)
        print(
            f"{name:15s} map 400 x 400: {seconds:.3f} s, {nodes / seconds:,.0f} cases/s "
            f"(case by case {ref:,.0f} cases/s, x{nodes / seconds / ref:,.0f})"
        )

        count = 200_000
        values = [
            (Parameter("friction.static"), rng.uniform(0.15, 0.35, count)),
            (Parameter("centre.x", "cart", "add"), rng.normal(0.0, 0.05, count)),
            (Parameter("mass", "cart", "scale"), rng.uniform(0.9, 1.1, count)),
        ]
        elastic = MODEL.excitations[1]
        inputs = case_inputs(stack, elastic.horizontal, elastic.vertical, 1, values, count)
        solve_batch(case_inputs(stack, 1.0, 0.0, 1, [], 10), MODEL.gravity)  # warm-up
        start = time.perf_counter()
        solve_batch(inputs, MODEL.gravity)
        seconds = time.perf_counter() - start
        start = time.perf_counter()
        sample = inputs.stack.take(np.arange(REFERENCE_CASES))
        for case in range(REFERENCE_CASES):
            blocks = tuple(
                Block(
                    name=b.name,
                    mass=float(sample.mass[case, i]),
                    inertia=b.inertia,
                    centre=(float(sample.centre_x[case, i]), b.centre[1]),
                    base_left=b.base_left,
                    base_right=b.base_right,
                    base_level=b.base_level,
                    friction=Friction(
                        float(sample.static_friction[case, i]),
                        float(sample.kinetic_friction[case, i]),
                    ),
                    sliding=b.sliding,
                )
                for i, b in enumerate(stack.blocks)
            )
            initial_motion(
                Stack(name, blocks), elastic.horizontal, elastic.vertical, 1, MODEL.gravity
            )
        ref = REFERENCE_CASES / (time.perf_counter() - start)
        print(
            f"{name:15s} Monte Carlo (friction, centre, mass) {count:,}: {seconds:.3f} s, "
            f"{count / seconds:,.0f} cases/s (case by case {ref:,.0f} cases/s, "
            f"x{count / seconds / ref:,.0f})"
        )


if __name__ == "__main__":
    main()
