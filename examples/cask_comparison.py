"""The storage cask of ``examples/cask.toml``: fragility in 3-D against two planar problems.

    python examples/cask_comparison.py [--records N] [--levels A:B:N] [--samples K]
        [--workers W] [--output FILE] [--suite FOLDER]

1. The suite: 20 generated three-component records matched to RG 1.60 (x and y at
   0.3 g, the vertical at 0.2 g), 20 s each, seed 20; written to
   ``examples/cask-records`` the first time (the suite ``cask.toml``'s ``[fragility]``
   table names), read from there afterwards. The same seed gives the same files.
2. The 3-D campaign (``fs.fragility``): stripes of PGA RotD50 from 0.1 to 1.5 g, the
   static friction drawn uniformly from 0.2 to 0.8 (the kinetic one follows in the
   model's proportion), the incidence angle drawn over 0-360 deg per simulation,
   free motion after each record until the cask rests (at most 10 s); outcomes a slide
   beyond 0.1 m, a tilt beyond half of alpha and overturning.
3. The planar method: the cask's vertical section as a planar block (configuration
   ``cask-planar``: the same mass, inertia about a diameter, base and centre of
   gravity), simulated (``fs.simulate``) under each horizontal component on its own
   with the vertical, with the same scale factor and friction as each 3-D simulation;
   an outcome occurs when it occurs under x or under y (the worse of the two).
4. Lognormal fits with bootstrap intervals and HCLPF for every outcome and method,
   written to ``examples/cask-comparison.json`` (``docs/cask.md`` reads its table
   from there).

About 2 to 4 minutes on two cores once compiled (the first run compiles the engines
for a minute or two and generates the suite in about 30 s).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor
from dataclasses import replace
from pathlib import Path

import numpy as np
import pandas as pd

import freestand as fs
from freestand.core.sweeps.fragility.fit import fit_fragility
from freestand.io.store import CampaignStore

HERE = Path(__file__).resolve().parent
MODEL = HERE / "cask.toml"
SUITE = HERE / "cask-records"
OUTPUT = HERE / "cask-comparison.json"
G = 9.81
RADIUS, CENTRE_HEIGHT = 1.683, 3.0  # m, as in cask.toml

TARGET = "rg1.60:pga=0.3g,damping=5%"
VERTICAL = "rg1.60:pga=0.2g,damping=5%,direction=vertical"
SUITE_SEED = 20
LEVELS = "0.1g:1.5g:15"
FRICTION = "cask.friction.static=uniform(0.2,0.8)"
SLIDE = 0.1  # m
TILT = 0.5  # of alpha
OUTCOMES = (f"slide:cask>{SLIDE:g}m", f"rotation:cask>{TILT:g}alpha", "overturn:cask")
KEYS = ("slide", "tilt", "overturn")
SEED = 20
BOOTSTRAP = 1000


def generate_suite(folder: Path) -> Path:
    """The suite file, generated into ``folder`` unless it is there already."""
    suite = folder / "suite.toml"
    if not suite.exists():
        generated = fs.generate_suite(
            TARGET, count=20, duration=20.0, seed=SUITE_SEED, horizontal_y=True,
            vertical=VERTICAL, name="RG 1.60, three components, 20 x 20 s", output=folder,
        )  # fmt: skip
        print(f"generated {suite}: {generated.status}")
    return suite


def _planar_record(motion, component: str):
    """One horizontal component of a three-component record with its vertical, planar."""
    return fs.GroundMotion(
        dt=motion.dt, horizontal=getattr(motion, component), vertical=motion.vertical,
        name=f"{motion.name} {component}",
    )  # fmt: skip


def _planar_task(args) -> list[dict]:
    """The planar simulations of one record: each 3-D row under x and under y."""
    stack, motion, rows, free_time = args
    block = stack.blocks[0]
    ratio = block.friction.kinetic / block.friction.static
    alpha = math.atan(block.base_right / (block.centre[1] - block.base_level))
    out = []
    for row in rows:
        mu = row["input:cask.friction.static"]
        sample = replace(stack, blocks=(replace(block, friction=fs.Friction(mu, ratio * mu)),))
        result = {"task": row["task"]}
        for component, name in (("horizontal", "x"), ("horizontal_y", "y")):
            record = _planar_record(motion, component).scaled(row["scale_factor"])
            try:
                run = fs.simulate(sample, record, until_rest=True, free_time=free_time, gravity=G)
            except fs.FreestandError as error:  # counted, as a campaign counts a failed run
                result[f"{name}.status"] = f"failed: {error}"
                continue
            peaks = run.to_dict()["blocks"][0]
            overturned = bool(peaks["overturned"])
            result[f"{name}.status"] = run.to_dict()["status"]
            result[f"{name}.slide"] = abs(peaks["max_slide"]) > SLIDE
            result[f"{name}.tilt"] = overturned or abs(peaks["max_rotation"]) > TILT * alpha
            result[f"{name}.overturn"] = overturned
        out.append(result)
    return out


def planar_runs(model, suite, rows: pd.DataFrame, workers: int, free_time: float):
    """The planar block under x and under y for every 3-D simulation (same factor, friction)."""
    stack = next(c for c in model.configurations if c.name == "cask-planar")
    tasks = [
        (stack, suite.motions[r], group.to_dict("records"), free_time)
        for r, group in rows.groupby("record")
    ]
    if workers == 1:
        results = [_planar_task(task) for task in tasks]
    else:
        with ProcessPoolExecutor(workers) as pool:
            results = list(pool.map(_planar_task, tasks))
    return pd.DataFrame([row for part in results for row in part]).sort_values(
        "task", ignore_index=True
    )


def _status(text: str) -> str:
    return "failed" if text.startswith("failed") else text


def fit(levels, level_index, occurred, counted, seed: int, bootstrap: int) -> dict:
    """Counts per level and the lognormal fit (bootstrap intervals, HCLPF) of one outcome."""
    totals = np.bincount(level_index[counted], minlength=levels.size)
    counts = np.bincount(level_index[counted & occurred], minlength=levels.size)
    f = fit_fragility(levels, counts, totals, bootstrap=bootstrap, seed=seed, unit="m/s^2")
    number = (lambda x: round(float(x), 4)) if f.fitted else (lambda x: None)
    return {
        "fitted": bool(f.fitted),
        "reason": f.reason or None,
        "median": number(f.median),
        "median_interval": [number(x) for x in f.median_interval],
        "beta": number(f.beta),
        "beta_interval": [number(x) for x in f.beta_interval],
        "hclpf": number(f.hclpf),
        "counts": counts.tolist(),
        "totals": totals.tolist(),
    }


def _range(values) -> dict:
    return {key: round(float(f(values)), 3) for key, f in (("min", np.min), ("mean", np.mean),
                                                        ("max", np.max))}  # fmt: skip


def statuses(values) -> dict:
    """Completed, capped and failed counts (invalid counts as failed)."""
    values = [_status(str(v)) for v in values]
    return {
        "completed": values.count("completed"),
        "capped": values.count("capped"),
        "failed": len(values) - values.count("completed") - values.count("capped"),
    }


def run(
    records: int | None = None,
    levels: str = LEVELS,
    samples: int = 4,
    workers: int | None = None,
    suite_folder: Path = SUITE,
    bootstrap: int = BOOTSTRAP,
    free_time: float = 10.0,
) -> dict:
    """The comparison as a JSON-ready document (see the module's docstring)."""
    workers = workers or os.cpu_count() or 1
    model = fs.load_model(MODEL)
    suite = fs.load_suite(generate_suite(Path(suite_folder)))
    if records is not None:
        suite = replace(suite, motions=suite.motions[:records])
    start = time.perf_counter()
    with tempfile.TemporaryDirectory() as folder:
        three_d = fs.fragility(
            model, suite, "pga-rotd50", levels, list(OUTCOMES), configuration="cask",
            vary=[FRICTION], samples=samples, seed=SEED, bootstrap=bootstrap,
            workers=workers, store=Path(folder) / "store", free_time=free_time,
        )  # fmt: skip
        # every simulation of the campaign, in task order
        rows = pd.DataFrame(CampaignStore(Path(folder) / "store").read())
    seconds_3d = time.perf_counter() - start
    start = time.perf_counter()
    planar = planar_runs(model, suite, rows, workers, free_time)
    seconds_planar = time.perf_counter() - start

    document = three_d.to_dict()
    level_values = np.asarray(document["levels"], dtype=float)
    index = rows["level"].to_numpy(np.int64)
    counted_3d = rows["status"].isin(("completed", "capped")).to_numpy()
    status_x = planar["x.status"].map(_status)
    status_y = planar["y.status"].map(_status)
    counted_x = status_x.isin(("completed", "capped")).to_numpy()
    counted_y = status_y.isin(("completed", "capped")).to_numpy()
    methods = {"3-D": {}, "planar x": {}, "planar y": {}, "planar, worse of x and y": {}}
    # the cask can lift only where static friction holds it against the inertial force of
    # its uplift threshold: mu_0 > R / h (tan alpha); below, it slides flat (docs/cask.md)
    tan_alpha = RADIUS / CENTRE_HEIGHT
    lifting = rows["input:cask.friction.static"].to_numpy(float) > tan_alpha
    above = {"3-D": {}, "planar, worse of x and y": {}}
    paired = {}
    for number, (key, outcome) in enumerate(zip(KEYS, OUTCOMES, strict=True)):
        in_3d = rows[f"outcome:{outcome}"].to_numpy(bool)
        in_x = planar[f"x.{key}"].fillna(False).to_numpy(bool)
        in_y = planar[f"y.{key}"].fillna(False).to_numpy(bool)
        seed = SEED + number
        methods["3-D"][key] = fit(level_values, index, in_3d, counted_3d, seed, bootstrap)
        methods["planar x"][key] = fit(level_values, index, in_x, counted_x, seed, bootstrap)
        methods["planar y"][key] = fit(level_values, index, in_y, counted_y, seed, bootstrap)
        both = counted_x & counted_y
        worse = in_x | in_y
        methods["planar, worse of x and y"][key] = fit(
            level_values, index, worse, both, seed, bootstrap
        )
        above["3-D"][key] = fit(level_values, index, in_3d, counted_3d & lifting, seed, bootstrap)
        above["planar, worse of x and y"][key] = fit(
            level_values, index, worse, both & lifting, seed, bootstrap
        )
        pair = counted_3d & both
        paired[key] = {
            "both": int((in_3d & worse & pair).sum()),
            "3-D only": int((in_3d & ~worse & pair).sum()),
            "planar only": int((~in_3d & worse & pair).sum()),
            "neither": int((~in_3d & ~worse & pair).sum()),
        }
    twist = rows["cask.max_twist"].to_numpy(float)
    flight = rows["cask.flight"].to_numpy(bool)
    overturned = rows["cask.overturned"].to_numpy(bool)
    # the pair against its components: RotD50 and the peak of the resultant |(x, y)|
    rotd50 = np.array([fs.intensity_measure(m, "pga-rotd50") for m in suite.motions])
    larger = np.array([max(m.peak_horizontal, m.peak_horizontal_y) for m in suite.motions])
    resultant = np.array([np.hypot(m.horizontal, m.horizontal_y).max() for m in suite.motions])
    return {
        "title": "Storage cask of the HI-STORM 100 class: 3-D fragility against two planar "
        "problems (examples/cask_comparison.py)",
        "model": "examples/cask.toml",
        "suite": {
            "name": suite.name,
            "records": len(suite.motions),
            "target": TARGET,
            "vertical": VERTICAL,
            "seed": SUITE_SEED,
            "duration": float(suite.motions[0].duration),
            "rotd50_over_larger_pga": _range(rotd50 / larger),
            "resultant_over_larger_pga": _range(resultant / larger),
        },
        "im": "pga-rotd50",
        "unit": "m/s^2",
        "levels": [round(float(x), 4) for x in level_values],
        "samples": samples,
        "friction": FRICTION,
        "outcomes": dict(zip(KEYS, OUTCOMES, strict=True)),
        "seed": SEED,
        "bootstrap": bootstrap,
        "free_time": free_time,
        "simulations": {
            "3-D": statuses(rows["status"]),
            "planar x": statuses(status_x),
            "planar y": statuses(status_y),
        },
        "fragility": methods,
        "friction_above_tan_alpha": {
            "tan_alpha": round(tan_alpha, 4),
            "simulations": int(lifting.sum()),
            "fragility": above,
        },
        "paired": paired,
        "three_d_peaks": {
            "twist_above_5deg": int((twist > math.radians(5.0)).sum()),
            "twist_above_90deg": int((twist > math.radians(90.0)).sum()),
            "flight": int(flight.sum()),
            "flight_overturned": int((flight & overturned).sum()),
            "flight_with_friction_below_tan_alpha": int((flight & ~lifting).sum()),
            "overturned_with_friction_below_tan_alpha": int((overturned & ~lifting).sum()),
        },
        "runtime": {
            "workers": workers,
            "three_d_seconds": round(seconds_3d, 1),
            "planar_seconds": round(seconds_planar, 1),
        },
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--records", type=int, default=None, help="the first N records only")
    parser.add_argument("--levels", default=LEVELS, help="as --levels (default %(default)s)")
    parser.add_argument("--samples", type=int, default=4, help="friction samples per stripe")
    parser.add_argument("--workers", type=int, default=None, help="processes (default: all)")
    parser.add_argument("--bootstrap", type=int, default=BOOTSTRAP)
    parser.add_argument("--suite", type=Path, default=SUITE, help="suite folder")
    parser.add_argument("--output", type=Path, default=OUTPUT, help="the JSON document")
    arguments = parser.parse_args()
    document = run(
        arguments.records, arguments.levels, arguments.samples, arguments.workers,
        arguments.suite, arguments.bootstrap,
    )  # fmt: skip
    arguments.output.write_text(json.dumps(document, indent=1) + "\n", encoding="utf-8")
    for method, fits in document["fragility"].items():
        for key, item in fits.items():
            if item["fitted"]:
                print(f"{method:26s} {key:9s} median {item['median']:.2f} m/s^2 "
                      f"({item['median_interval'][0]:.2f}-{item['median_interval'][1]:.2f}), "
                      f"beta {item['beta']:.2f}, HCLPF {item['hclpf']:.2f}")  # fmt: skip
            else:
                print(f"{method:26s} {key:9s} not fitted: {item['reason']}")
    print(f"simulations: {document['simulations']}; wrote {arguments.output}")


if __name__ == "__main__":
    main()
