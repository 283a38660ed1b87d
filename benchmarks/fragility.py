"""Fragility campaigns: simulations per second per core, and scaling from one to two workers.

Anchor (measured in the same run): one bare ``simulate`` call of the single
block under one 10 s record (the single-block fast path), best of 50.

A0. The same block and records up to 1.3 g tan(alpha) (rest and gentle
   rocking, nearly every simulation on the fast path): the cost of the campaign
   itself against the anchor, 1 and 2 workers.
A1. 1,000 tasks of A0 in this process, timed one by one: the time per
   solver path, the campaign's own overhead per simulation, and the 100,000
   projected from the fast-path simulations alone.
A. Single block (0.6 m x 2.0 m, tan(alpha) = 0.3, mu = 1) under 50
   synthetic 10 s records (``synthetic_ground_motion``, seeds 1000...), IM
   PGA / (g tan alpha) from 0.5 to 1.5 (the fast path's range: rocking
   without flight), mass x uniform(0.9, 1.1), both polarities. By default a
   slice of 4,000 simulations on 1 worker and on 2 workers, and the time
   projected for 100,000; ``--full`` runs the 100,000 on every core.
B. The same block from 0.5 to 2.5: strong rocking, where the fast path hands
   some simulations to the general path (free flight of the block); the
   share that does and the rate.
C. The crane's x-z cart right (two blocks) under 20 s records, PGA 1 to
   8 m/s^2: 40 records x 15 levels x both polarities (1,200 simulations),
   on 1 and on 2 workers.

Every simulation is one ``simulate(..., until_rest=True)`` run: it goes on
after the record until the stack rests, overturns, or 10 s after it.

    python benchmarks/fragility.py [--full]
"""

from __future__ import annotations

import math
import sys
import time
from collections import Counter
from pathlib import Path

import numpy as np

from freestand.core.dynamics.timehistory import SupportMotion, simulate
from freestand.core.model import Block, Friction, Sliding, Stack
from freestand.core.motion.ground_motion import synthetic_ground_motion
from freestand.core.sweeps.fragility.campaign import (
    Campaign,
    run_tasks,
    sample_stacks,
    simulate_task,
)
from freestand.core.sweeps.fragility.intensity import IntensityMeasure
from freestand.core.sweeps.fragility.outcomes import Outcome, default_outcomes
from freestand.io.campaign_runner import run_campaign
from freestand.io.model_file import load_model
from freestand.io.parameters import parse_variation

ROOT = Path(__file__).resolve().parents[1]
BLOCK = Block(
    "block", 1000.0, 1000.0 * (0.3**2 + 1.0**2) / 3.0, (0.0, 1.0), -0.3, 0.3, 0.0,
    Friction(1.0, 1.0), Sliding.FREE,
)  # fmt: skip
STACK = Stack("block", (BLOCK,))


def records(count: int, duration: float, vertical: bool = False):
    return tuple(
        synthetic_ground_motion(
            seed=1000 + i, duration=duration, vertical_peak=1.635 if vertical else None
        )
        for i in range(count)
    )


def block_campaign(levels, samples: int, motions) -> Campaign:
    return Campaign(
        STACK,
        motions,
        IntensityMeasure("pga-alpha", block="block"),
        levels,
        variations=(parse_variation("block.mass*=uniform(0.9,1.1)"),),
        samples=samples,
        polarities=(1, -1),
        seed=1,
        outcomes=(
            Outcome("overturn", "block"),
            Outcome("rotation", "block", 0.5, "alpha"),
            Outcome("uplift", "block"),
        ),
    )


def timed(campaign: Campaign, workers: int) -> tuple[float, dict]:
    """Wall time [s] and rows of the whole campaign (1 worker: in this process)."""
    start = time.perf_counter()
    rows = run_campaign(campaign, workers=workers)
    return time.perf_counter() - start, rows


def main(full: bool) -> None:
    motions = records(50, 10.0)
    # anchor: one bare simulation, the fast path
    support = SupportMotion(motions[0].dt, np.asarray(motions[0].horizontal) * 3.0)
    simulate(STACK, support)
    best = math.inf
    for _ in range(50):
        start = time.perf_counter()
        anchor = simulate(STACK, support)
        best = min(best, time.perf_counter() - start)
    print(f"anchor: one simulate() of the block, 10 s record: {1e3 * best:.2f} ms "
          f"({anchor.diagnostics.method})")  # fmt: skip

    # A0: gentle shaking (nearly every simulation on the fast path): the campaign's own cost
    gentle = block_campaign(np.linspace(0.5, 1.3, 10), 2, motions)  # 2,000
    one, rows = timed(gentle, 1)
    two, _ = timed(gentle, 2)
    rate1, rate2 = gentle.size / one, gentle.size / two
    print(f"A0: {gentle.size} simulations up to 1.3 g tan(alpha): 1 worker {one:.1f} s "
          f"({rate1:.0f} sims/s/core, {1e3 / rate1:.2f} ms per simulation = "
          f"{1e3 / rate1 / (1e3 * best):.2f} x the anchor), 2 workers {two:.1f} s "
          f"({rate2:.0f} sims/s, scaling x{rate2 / rate1:.2f}); projected 100,000: "
          f"{1e5 / rate2:.0f} s; solvers {dict(Counter(rows['solver']))}")  # fmt: skip

    # A1: where the time goes, per solver path (in this process, 1,000 tasks of A0): each
    # task timed alone through run_tasks (sampling, simulation, row) and its simulation alone
    spent: dict[str, list[float]] = {}
    overheads = []
    stacks: dict[tuple[int, int], list] = {}
    for index in range(1000):
        r, level, k, polarity = gentle.task(index)
        if (r, level) not in stacks:
            values = gentle.input_values(r, level)
            stacks[(r, level)] = sample_stacks(gentle.stack, gentle.variations, values)
        start_one = time.perf_counter()
        result, _, _, _ = simulate_task(
            stacks[(r, level)][k], gentle.motions[r], gentle.factor(r, level), polarity, gentle
        )
        alone = time.perf_counter() - start_one
        spent.setdefault(result.diagnostics.method, []).append(alone)
        if result.diagnostics.method != "general":
            start_one = time.perf_counter()
            run_tasks(gentle, index, index + 1)
            overheads.append(time.perf_counter() - start_one - alone)
    fast = [t for m, v in spent.items() if m != "general" for t in v]
    overhead = float(np.median(overheads))
    print("A1: per solver path: " + ", ".join(
        f"{m} {len(v)} x {1e3 * np.mean(v):.2f} ms" for m, v in sorted(spent.items())))  # fmt: skip
    print(f"    campaign overhead per simulation (sampling, rest check, row; median over the "
          f"fast-path tasks) {1e3 * overhead:.2f} ms; fast-path simulations alone "
          f"{1e3 * np.mean(fast):.2f} ms each -> 100,000 on 2 free workers "
          f"~{1e5 * (np.mean(fast) + overhead) / 2:.0f} s")  # fmt: skip

    # A: fast-path range
    levels = np.linspace(0.5, 1.5, 20)
    campaign = block_campaign(levels, 50, motions)  # 50 x 20 x 50 x 2 = 100,000
    if full:
        start = time.perf_counter()
        rows = run_campaign(campaign)
        elapsed = time.perf_counter() - start
        statuses = dict(Counter(rows["status"]))
        print(f"A full: {campaign.size} simulations in {elapsed:.1f} s "
              f"({campaign.size / elapsed:.0f} sims/s), statuses {statuses}")  # fmt: skip
    else:
        small = block_campaign(levels, 2, motions)  # 50 x 20 x 2 x 2 = 4,000
        one, rows = timed(small, 1)
        two, _ = timed(small, 2)
        rate1, rate2 = small.size / one, small.size / two
        print(
            f"A: {small.size} simulations, 1 worker {one:.1f} s ({rate1:.0f} sims/s/core, "
            f"{1e3 / rate1:.2f} ms per simulation = {1e3 / rate1 / (1e3 * best):.2f} x the "
            f"anchor); 2 workers {two:.1f} s ({rate2:.0f} sims/s, scaling x{rate2 / rate1:.2f})"
        )
        print(f"   projected 100,000 simulations on 2 workers: {1e5 / rate2:.0f} s; "
              f"solvers {dict(Counter(rows['solver']))}")  # fmt: skip

    # B: strong rocking
    strong = block_campaign(np.linspace(0.5, 2.5, 10), 2, motions[:10])  # 400
    elapsed, rows = timed(strong, 2)
    solvers = Counter(rows["solver"])
    print(f"B: {strong.size} simulations up to 2.5 g tan(alpha) on 2 workers: {elapsed:.1f} s "
          f"({strong.size / elapsed:.1f} sims/s); solvers {dict(solvers)}; "
          f"statuses {dict(Counter(rows['status']))}")  # fmt: skip

    # C: the crane
    model = load_model(ROOT / "examples" / "crane.toml")
    crane = model.configuration("x-z cart right")
    crane_motions = records(40, 20.0, vertical=True)
    crane_campaign = Campaign(
        crane, crane_motions, IntensityMeasure("pga"), np.linspace(1.0, 8.0, 15),
        polarities=(1, -1), outcomes=default_outcomes(crane), gravity=model.gravity,
    )  # fmt: skip
    one, rows = timed(crane_campaign, 1)
    two, _ = timed(crane_campaign, 2)
    rate1, rate2 = crane_campaign.size / one, crane_campaign.size / two
    print(f"C: crane x-z cart right, {crane_campaign.size} simulations of 20 s records: "
          f"1 worker {one:.1f} s ({rate1:.0f} sims/s/core, {1e3 / rate1:.1f} ms each), "
          f"2 workers {two:.1f} s ({rate2:.0f} sims/s, scaling x{rate2 / rate1:.2f}); "
          f"statuses {dict(Counter(rows['status']))}, mean simulated "
          f"{np.nanmean(rows['simulated_time']):.1f} s")  # fmt: skip


if __name__ == "__main__":
    main("--full" in sys.argv[1:])
