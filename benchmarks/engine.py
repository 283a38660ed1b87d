"""Benchmark: freestand's stack time history against a general physics engine (MuJoCo).

Stacks and records (10 s each):

(a) two homogeneous rocking blocks: lower 0.6 x 2.0 m, 1.2 t; upper 0.4 x
    1.2 m, 0.4 t, centred on it; friction 0.8 / 0.7 (no sliding); a 1 Hz
    half-sine (0.5 s) at 1.2 times the lower block's uplift acceleration
    g tan(alpha), sampled at 5 ms, then rest;
(b) the crane's configuration "x-z cart right" (examples/crane.toml: bridge
    with sliding "none", cart with an end stop) under
    examples/records/synthetic_H.AT2 with its vertical synthetic_UP.AT2,
    scaled to a horizontal peak of 8 m/s^2;
(c) a three-block stack (the two blocks of (a) under a 0.3 x 0.6 m, 0.1 t
    block) under the record of (b): freestand only (target: under 50 ms);
(d) the crane under a 2-million-sample record (the record of (b) resampled
    at 5 microseconds): freestand only, through the command line's
    progress callback.

MuJoCo: every block a free planar body (slide x, slide z, hinge y through its
centre of gravity, mass and inertia as in the model), its lower contacts
small spheres (1 mm) touching the support plane or a thin box on the body
below (explicit contact pairs, elliptic cones, stiff contacts as in
benchmarks/mujoco_rocking.py), the crane's end stop a frictionless wall on
the bridge against the cart's right wheel, "sliding none" a friction
coefficient of 5. The support acceleration enters as d'Alembert forces in the
support's frame: ``-m a_h`` on x and ``+m a_v`` on z (a_v downward), through
``rollout`` (the whole loop in C). One Coulomb coefficient per contact: the
kinetic one (0.2 for the cart); for the accuracy figures of (b) freestand
also runs a variant with the static coefficient equal to the kinetic one.

Timings: the shortest of several runs after compilation (the machine may be
shared), in wall time and in the process's CPU time (less disturbed by other
jobs on a shared machine), freestand at its default step (0.05 / p, steps
ending where the record's slope changes), MuJoCo at its 2 ms step. Accuracy: peak relative
rotation and slide of every block and the first uplift (relative rotation
reaching 1e-5 rad, between samples on freestand's recorded rates, linearly
between MuJoCo's steps), for freestand and MuJoCo at 2 ms against MuJoCo at a 0.1 ms
step.

    python benchmarks/engine.py

Needs the optional dependency ``mujoco`` (``pip install -e ".[bench]"``).
"""

from __future__ import annotations

import math
import sys
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

try:
    import mujoco
    from mujoco import rollout
except ImportError:  # optional benchmark dependency
    mujoco = None

from freestand.core.dynamics.timehistory import SupportMotion, simulate, stack_kinematics
from freestand.core.model import Block, Friction, Stack
from freestand.io.model_file import load_model
from freestand.io.records import load_record

ROOT = Path(__file__).resolve().parents[1]
CRANE = ROOT / "examples" / "crane.toml"
RECORD = ROOT / "examples" / "records" / "synthetic_H.AT2"
VERTICAL = ROOT / "examples" / "records" / "synthetic_UP.AT2"
GRAVITY = 9.81
DURATION = 10.0  # [s]
STEP = 0.002  # MuJoCo's default step [s]
FINE_STEP = 1e-4  # MuJoCo reference step [s]
SPHERE = 1e-3  # contact sphere radius [m]
REPEATS = 9
OPTION = 'cone="elliptic" noslip_iterations="20"'
CONTACT = 'solref="0.004 1" solimp="0.99 0.999 0.0001"'


def rectangle(name, width, height, mass, level, friction=(0.8, 0.7)) -> Block:
    """A homogeneous rectangle centred on x = 0, standing at ``level`` [m]."""
    return Block.rectangle(name, width, height, mass, Friction(*friction), level=level)


def two_blocks() -> Stack:
    lower = rectangle("lower", 0.6, 2.0, 1200.0, 0.0)
    upper = rectangle("upper", 0.4, 1.2, 400.0, 2.0)
    return Stack("two blocks", (lower, upper))


def three_blocks() -> Stack:
    lower, upper = two_blocks().blocks
    top = rectangle("top", 0.3, 0.6, 100.0, 3.2)
    return Stack("three blocks", (lower, upper, top))


def half_sine_motion(stack: Stack) -> SupportMotion:
    lower = stack.blocks[0]
    uplift = GRAVITY * (lower.base_right - lower.centre[0]) / (lower.centre[1])
    dt = 0.005
    t = np.arange(int(round(DURATION / dt)) + 1) * dt
    values = np.where(t < 0.5, 1.2 * uplift * np.sin(2.0 * math.pi * t), 0.0)
    return SupportMotion(dt, values)


def crane_motion() -> SupportMotion:
    motion = load_record(RECORD, gravity=GRAVITY, vertical=VERTICAL).scaled_to_peak(8.0)
    return SupportMotion(motion.dt, np.asarray(motion.horizontal), np.asarray(motion.vertical))


# ------------------------------------------------------------------------------ MuJoCo
def mujoco_xml(stack: Stack, step: float, friction_override=None) -> str:
    """MJCF of a planar stack: free planar bodies, contact spheres, explicit pairs."""
    bodies = []
    pairs = []
    for i, block in enumerate(stack.blocks):
        cx, cz = block.centre
        inertia = block.inertia
        geoms = []
        for side, x in (("L", block.base_left), ("R", block.base_right)):
            geoms.append(
                f'<geom name="c{i}{side}" type="sphere" size="{SPHERE}" contype="0" '
                f'conaffinity="0" mass="0" pos="{x - cx} 0 {block.base_level + SPHERE - cz}"/>'
            )
        if i + 1 < len(stack.blocks):
            above = stack.blocks[i + 1]
            top = above.base_level - cz
            half = 0.5 * (above.base_right - above.base_left) + 2.0
            middle = 0.5 * (above.base_right + above.base_left) - cx
            geoms.append(
                f'<geom name="top{i}" type="box" size="{half} 0.1 0.005" contype="0" '
                f'conaffinity="0" mass="0" pos="{middle} 0 {top - 0.005}"/>'
            )
            if above.sliding.value in ("no-right", "no-left"):
                sign = 1.0 if above.sliding.value == "no-right" else -1.0
                x = (above.base_right if sign > 0 else above.base_left) + sign * (SPHERE + 0.05)
                geoms.append(
                    f'<geom name="stop{i}" type="box" size="0.05 0.1 0.3" contype="0" '
                    f'conaffinity="0" mass="0" pos="{x - cx} 0 {top + 0.3}"/>'
                )
        bodies.append(
            f"""    <body name="b{i}" pos="{cx} 0 {cz}">
      <inertial pos="0 0 0" mass="{block.mass}" diaginertia="{inertia} {inertia} {inertia}"/>
      <joint name="x{i}" type="slide" axis="1 0 0"/>
      <joint name="z{i}" type="slide" axis="0 0 1"/>
      <joint name="r{i}" type="hinge" axis="0 1 0"/>
      {" ".join(geoms)}
    </body>"""
        )
        below = "support" if i == 0 else f"top{i - 1}"
        if block.sliding.value == "none":
            mu = 5.0
        else:
            mu = block.friction.kinetic if friction_override is None else friction_override
        for side in "LR":
            pairs.append(
                f'<pair geom1="{below}" geom2="c{i}{side}" condim="3" '
                f'friction="{mu} {mu} 0.005 0.0001 0.0001" {CONTACT}/>'
            )
        if i > 0 and block.sliding.value in ("no-right", "no-left"):
            side = "R" if block.sliding.value == "no-right" else "L"
            pairs.append(f'<pair geom1="stop{i - 1}" geom2="c{i}{side}" condim="1" {CONTACT}/>')
    body_text = "\n".join(bodies)
    pair_text = "\n    ".join(pairs)
    return f"""<mujoco model="{stack.name}">
  <option timestep="{step}" gravity="0 0 {-GRAVITY}" {OPTION}/>
  <worldbody>
    <geom name="support" type="plane" size="50 5 0.1" contype="0" conaffinity="0"/>
{body_text}
  </worldbody>
  <contact>
    {pair_text}
  </contact>
</mujoco>"""


class MujocoStack:
    """A stack in MuJoCo driven through rollouts; states mapped to freestand's coordinates."""

    def __init__(self, stack: Stack, step: float) -> None:
        self.stack = stack
        self.step = step
        self.model = mujoco.MjModel.from_xml_string(mujoco_xml(stack, step))
        self.data = mujoco.MjData(self.model)
        spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
        mujoco.mj_resetData(self.model, self.data)
        # the contact spheres stand SPHERE above the surfaces: start at rest on them
        mujoco.mj_forward(self.model, self.data)
        self.initial = np.empty(mujoco.mj_stateSize(self.model, spec))
        mujoco.mj_getState(self.model, self.data, self.initial, spec)
        masses = np.repeat([b.mass for b in stack.blocks], 3).reshape(-1, 3)
        self.masses = masses

    def forcing(self, motion: SupportMotion, duration: float) -> np.ndarray:
        steps = int(round(duration / self.step))
        grid = np.arange(steps) * self.step
        a_h, a_v = np.vectorize(motion.__call__)(grid)
        force = np.zeros((1, steps, self.model.nv))
        for i, block in enumerate(self.stack.blocks):
            force[0, :, 3 * i] = -block.mass * a_h
            force[0, :, 3 * i + 1] = block.mass * a_v
        return force

    def run(self, force: np.ndarray) -> np.ndarray:
        state, _ = rollout.rollout(
            self.model,
            self.data,
            self.initial[None, :],
            force,
            control_spec=mujoco.mjtState.mjSTATE_QFRC_APPLIED,
        )
        return state[0]

    def response(self, state: np.ndarray) -> dict:
        """Peak relative rotations and slides and the first uplift from the states."""
        count = len(self.stack.blocks)
        qpos = state[:, 1 : 1 + 3 * count].reshape(-1, count, 3).copy()
        qpos[:, :, 2] *= -1.0  # MuJoCo's hinge about +y is clockwise in x-z
        rotation = np.empty((qpos.shape[0], count))
        slide = np.empty((qpos.shape[0], count))
        for k in range(qpos.shape[0]):
            kin = stack_kinematics(self.stack, qpos[k], np.zeros(3 * count))
            rotation[k] = kin.rotation
            slide[k] = kin.slide
        return summary(self.stack, np.arange(1, qpos.shape[0] + 1) * self.step, rotation, slide)


UPLIFT = 1e-5  # relative rotation taken as the first uplift [rad]


def first_crossing(time_: np.ndarray, value: np.ndarray, rate: np.ndarray | None) -> float:
    """First time |value| reaches UPLIFT: between the samples around it on the cubic
    Hermite interpolant of (value, rate), or linearly without rates; NaN if never."""
    above = np.abs(value) > UPLIFT
    if not above.any():
        return math.nan
    k = int(np.argmax(above))
    if k == 0:
        return float(time_[0])
    t0, t1 = float(time_[k - 1]), float(time_[k])
    y0, y1 = float(value[k - 1]), float(value[k])
    sign = 1.0 if y1 > 0.0 else -1.0
    if rate is None:
        return t0 + (t1 - t0) * (UPLIFT - sign * y0) / (sign * (y1 - y0))
    h = t1 - t0
    m0, m1 = float(rate[k - 1]) * h, float(rate[k]) * h

    def level(x: float) -> float:
        hermite = (
            (2 * x**3 - 3 * x**2 + 1) * y0
            + (x**3 - 2 * x**2 + x) * m0
            + (-2 * x**3 + 3 * x**2) * y1
            + (x**3 - x**2) * m1
        )
        return sign * hermite - UPLIFT

    low, high = 0.0, 1.0
    for _ in range(60):
        middle = 0.5 * (low + high)
        low, high = (middle, high) if level(middle) < 0.0 else (low, middle)
    return t0 + h * high


def summary(stack: Stack, time_: np.ndarray, rotation: np.ndarray, slide: np.ndarray) -> dict:
    """Peaks and the first uplift of sampled states (MuJoCo's, at every step)."""
    return {
        "rotation": np.nanmax(np.abs(rotation), axis=0),
        "slide": np.nanmax(np.abs(slide), axis=0),
        "first_uplift": [
            first_crossing(time_, rotation[:, i], None) for i in range(len(stack.blocks))
        ],
    }


def freestand_summary(stack: Stack, result) -> dict:
    """Peaks and the first uplift of a freestand result (on its recorded rates)."""
    rates = result.velocity[:, :, 2].copy()
    rates[:, 1:] -= result.velocity[:, :-1, 2]
    return {
        "rotation": result.max_rotation,
        "slide": result.max_slide,
        "first_uplift": [
            first_crossing(result.time, result.relative_rotation[:, i], rates[:, i])
            for i in range(len(stack.blocks))
        ],
    }


def best_time(function, repeats: int = REPEATS, clock=time.perf_counter) -> float:
    """Shortest time of ``function()`` over ``repeats`` runs [s] (the least disturbed).

    ``clock``: wall time by default; ``time.process_time`` gives the CPU time of
    the process, which a shared machine disturbs less (a long run is more often
    interrupted than a short one, so the shortest wall times favour the
    shorter run).
    """
    times = []
    for _ in range(repeats):
        start = clock()
        function()
        times.append(clock() - start)
    return float(np.min(times))


def best_times_alternated(
    functions, repeats: int = REPEATS, clock=time.perf_counter
) -> list[float]:
    """:func:`best_time` of each of ``functions`` [s], their runs alternated.

    Round r runs every function once, in turn: a shared machine's slow spell
    then falls on all of them alike, and their ratio is steadier than that
    of best times taken one function after the other.
    """
    best = [np.inf] * len(functions)
    for _ in range(repeats):
        for i, function in enumerate(functions):
            start = clock()
            function()
            best[i] = min(best[i], clock() - start)
    return [float(b) for b in best]


def compare(name: str, stack: Stack, motion: SupportMotion, accuracy_stack: Stack) -> float:
    """Time freestand and MuJoCo on one case; print timings, ratio and accuracy."""
    simulate(stack, motion, 0.5)  # compilation (or cache load)
    result = simulate(stack, motion, DURATION)
    fs_time = best_time(lambda: simulate(stack, motion, DURATION))
    fs_cpu = best_time(lambda: simulate(stack, motion, DURATION), clock=time.process_time)
    coarse = MujocoStack(stack, STEP)
    force = coarse.forcing(motion, DURATION)
    coarse.run(force)
    mj_time = best_time(lambda: coarse.run(force))
    mj_cpu = best_time(lambda: coarse.run(force), clock=time.process_time)
    print(f"\n({name}) {stack.name}, {DURATION:g} s")
    kinds = {}
    for event in result.events:
        kinds[event.kind] = kinds.get(event.kind, 0) + 1
    print(
        f"  freestand {1e3 * fs_time:8.2f} ms  ({result.diagnostics.method}, status"
        f" {result.status}, {result.diagnostics.steps} steps, events {kinds})"
    )
    print(f"  MuJoCo    {1e3 * mj_time:8.2f} ms  (2 ms step, rollout)")
    print(
        f"  speed-up  {mj_time / fs_time:8.1f} x  (CPU time: freestand {1e3 * fs_cpu:.2f} ms,"
        f" MuJoCo {1e3 * mj_cpu:.2f} ms, {mj_cpu / fs_cpu:.1f} x)"
    )
    # accuracy against MuJoCo at a fine step
    accurate = simulate(accuracy_stack, motion, DURATION)
    fine = MujocoStack(accuracy_stack, FINE_STEP)
    reference = fine.response(fine.run(fine.forcing(motion, DURATION)))
    coarse_acc = MujocoStack(accuracy_stack, STEP)
    engines = {
        "freestand": freestand_summary(accuracy_stack, accurate),
        "MuJoCo 2 ms": coarse_acc.response(coarse_acc.run(coarse_acc.forcing(motion, DURATION))),
        "MuJoCo 0.1 ms": reference,
    }
    if accuracy_stack is not stack:
        print(f"  accuracy on {accuracy_stack.name!r} (static friction = kinetic)")
    for i, block in enumerate(accuracy_stack.blocks):
        for label, key, unit in (
            ("peak rotation", "rotation", "rad"),
            ("peak slide", "slide", "m"),
            ("first uplift", "first_uplift", "s"),
        ):
            ref = reference[key][i]
            cells = []
            for engine, values in engines.items():
                value = values[key][i]
                if engine != "MuJoCo 0.1 ms" and ref and math.isfinite(ref) and abs(ref) > 1e-9:
                    cells.append(f"{engine} {value:.5g} ({100 * (value / ref - 1):+.2f} %)")
                else:
                    cells.append(f"{engine} {value:.5g}")
            print(f"  {block.name:6s} {label:13s} [{unit}]: " + ", ".join(cells))
    return mj_time / fs_time


def main() -> int:
    if mujoco is None:
        print("mujoco is not installed (pip install -e '.[bench]'): benchmark skipped")
        return 0
    print(f"mujoco {mujoco.__version__}, numpy {np.__version__}")
    two = two_blocks()
    ratio_a = compare("a", two, half_sine_motion(two), two)
    crane = load_model(CRANE).configuration("x-z cart right")
    record = crane_motion()
    bridge, cart = crane.blocks
    equal = replace(
        crane,
        name="x-z cart right, mu_0 = mu",
        blocks=(
            bridge,
            replace(cart, friction=Friction(cart.friction.kinetic, cart.friction.kinetic)),
        ),
    )
    ratio_b = compare("b", crane, record, equal)

    three = three_blocks()
    simulate(three, record, 0.5)
    result = simulate(three, record, DURATION)
    three_time = best_time(lambda: simulate(three, record, DURATION))
    print(
        f"\n(c) {three.name} under the record of (b), {DURATION:g} s: {1e3 * three_time:.1f} ms"
        f" (target < 50 ms); status {result.status}, {result.diagnostics.steps} steps,"
        f" {len(result.events)} events, peak rotations"
        f" {np.array2string(result.max_rotation, precision=4)} rad"
    )

    dense_dt = (record.horizontal.size - 1) * record.time_step / 2_000_000
    grid = np.arange(2_000_001) * dense_dt
    a_h, a_v = np.vectorize(record.__call__)(grid)
    dense = SupportMotion(dense_dt, a_h, a_v)
    ticks = []
    start = time.perf_counter()
    long_result = simulate(crane, dense, progress=ticks.append)
    long_time = time.perf_counter() - start
    print(
        f"\n(d) crane under a {grid.size:,}-sample record (dt {dense_dt * 1e6:.1f} us,"
        f" {grid[-1]:.1f} s): {long_time:.2f} s with {len(ticks)} progress reports;"
        f" status {long_result.status}; peak cart rotation {long_result.max_rotation[1]:.4g} rad"
        f" (record of (b): {simulate(crane, record).max_rotation[1]:.4g} rad)"
    )
    print(
        f"\nsummary: speed-up against MuJoCo at 2 ms: (a) {ratio_a:.1f} x, (b) {ratio_b:.1f} x"
        f" (goal 10 x, floor 6 x; CPU-time ratios above); (c) {1e3 * three_time:.1f} ms;"
        f" (d) {long_time:.2f} s"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
