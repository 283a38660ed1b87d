"""Benchmark: freestand's 3-D body engine against MuJoCo, and its speed (issue #18 (f)).

Records: a suite of spectrum-compatible three-component records
(:func:`freestand.core.motion.spectrum_matching.generate_suite`, US NRC RG 1.60
at 0.3 g and 5 %: x and y on the horizontal spectrum, the vertical on the
vertical one; 20 s at 200 samples/s, seed 2024), as ``freestand records
generate`` makes them.

(a) Accuracy. Three bodies on the rigid support, each under one record of the
suite times a scale (``CASES``):

- a cabinet, box 1.0 x 0.6 x 2.0 m, 400 kg, mu = 0.5 (rocks about its long
  edges and slides), and the same with mu = 2 (rocks, its base held);
- a cask, cylinder R 1.7 m, H 6.0 m, 1.8e5 kg, mu = 0.3: mu < R / h_G, so it
  slides and cannot rock (both thresholds scale with g - a_v); its exact slide
  is that of a point mass on the circular Coulomb cone, computed here
  independently (:func:`slide_reference`);
- a slender cylinder, R 0.4 m, H 3.0 m, 2 t, mu = 0.5 (rocks, rolls on its
  rim, slides and twists).

freestand: :func:`freestand.core.dynamics.body_history.simulate_body` at its
default step and at 0.5 ms. MuJoCo: a free body (mass, centre and inertia of
the freestand body) whose base is a set of 1 mm contact spheres on the plane
(:func:`base_points`: laid out to load the base about uniformly when it is
flat, with a box's corners and a cylinder's rim, 48 points, among them), elliptic
friction cones with the one Coulomb coefficient, critically damped contacts
(``solref = "T 1"``, ``solimp = "0.99 0.999 0.0001"``). Two fine runs:
step 0.1 ms with T = 1 ms and step 0.05 ms with T = 0.5 ms (stiffer and
finer together: the soft contacts converge to the rigid ones; for the
cabinet with mu = 2, 0.025 ms with T = 0.25 ms, see ``CASES``). MuJoCo's
cylinder primitive is not used for accuracy: flat on a plane it touches at 3
rim points (a triangle, half the lever arm towards its sides) and at one as
soon as it tilts, and its slide scattered by +-5 % around the exact one here;
the box primitive touches at its 4 corners only (a twist lever of the whole
half-diagonal instead of the mean distance of a uniformly loaded base). The
support acceleration enters as the d'Alembert force ``m (-a_x, -a_y, +a_v)``
at the centre of gravity (the support's frame, exact for a translating
frame), held over each step at its value at the step's midpoint, through
``mujoco.rollout`` (the loop in C).

Peaks: the largest tilt (angle of the body's axis from the vertical), slide
(horizontal displacement of the base centre) and twist (rotation about the
vertical), overturning, and the lowest point the base reached (0 for a rigid
contact; MuJoCo's contacts are soft). Both engines' states are read by
:func:`freestand.core.dynamics.body_history.body_motion`. The tolerances
(``TOLERANCES``) are stated with the reasons in docs/benchmarks.md.

(b) Speed, against MuJoCo at its 2 ms step in the same run (the box and
cylinder primitives with the stiff contacts of benchmarks/mujoco_rocking.py,
the cheapest MuJoCo model; and the contact-point model above): one body
under the first 10 s of its record (best of several runs after compilation,
alternated with MuJoCo's primitive so that a slow spell of the machine falls
on both); 1,000 simulations of 20 s under the 20 records (cabinet and cask, 25 levels
of the suite's scale 0.1-2.5 each) on a pool of ``WORKERS`` processes.
``records``: each of the three bodies under every record of the suite at
its case's scale, against MuJoCo on the same motion: the median and worst
ratio (:func:`record_runs`; a rocking body's run time depends on its
history, so one record's ratio is one draw).

(c) Profile: steps, events and impacts per simulated second of each case, its
remedies and time-stepping steps (no admissible mode), the RK4 trials of its
event searches per event, the time per step, and the share of the compiled
loop (the rest is the Python front end: arrays in, histories and peaks out).

(d) Ensemble: the slender cylinder's response is chaotic (one run's peaks move
with a 1e-3 change of the record), so it is also compared over all 20 records
of the suite at its scale: the runs that stay near flat, that overturn, and
the median peaks of the others, freestand at both steps against MuJoCo's
first fine run (:func:`ensemble`).

(e) Edges: the cabinet around mu = b_x / h = 0.5, with MuJoCo's base edges
loaded at their corners and uniformly (:func:`edges`).

(f) Example: the example cabinet of ``examples/bodies.toml`` under the
synthetic record on x and y at two incidence angles (:func:`example`).

(g) Robustness: ``ROBUST_RUNS`` random bodies (boxes and cylinders, hollow,
off-centre, with non-principal inertia, of random size, mass, friction and
restitution; :func:`robust_case`) under random records of the suite, scaled
0.2-5: no simulation may end ``failed``, nor take more than ``ROBUST_SLOW``
(:func:`robustness`; MuJoCo is not needed).
``strong``: ``STRONG_RUNS`` of them under records 3-10 times stronger, the
vertical 0-12 times (:func:`strong_case`), simulated ``STRONG_AFTER`` past
their end: a third overturn, many fly, and none may end ``failed``.

    python benchmarks/mujoco_body.py [accuracy] [speed] [profile]
    python benchmarks/mujoco_body.py single | campaign     # one half of (b)
    python benchmarks/mujoco_body.py records               # (b) under each record of the suite
    python benchmarks/mujoco_body.py ensemble              # (d), not in the default run
    python benchmarks/mujoco_body.py edges                 # (e), the cabinet around mu 0.5
    python benchmarks/mujoco_body.py example               # (f), the example cabinet
    python benchmarks/mujoco_body.py robust                # (g), random bodies, 0 failed
    python benchmarks/mujoco_body.py strong                # (g) under strong records

Each check prints PASS or FAIL; the command exits 1 if any failed.

Needs the optional dependency ``mujoco`` (``pip install -e ".[bench]"``),
except for (g); without it the script says so and exits.
"""

from __future__ import annotations

import cProfile
import math
import os
import pstats
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass
from pathlib import Path

import numba as nb
import numpy as np

try:
    import mujoco
    from mujoco import rollout
except ImportError:  # optional benchmark dependency
    mujoco = None

from engine import (  # benchmarks/engine.py: the shortest of several wall times
    best_time,
    best_times_alternated,
)
from freestand.core.body import Body, Box, Cylinder
from freestand.core.dynamics import body_engine
from freestand.core.dynamics.body_history import SupportMotion3, body_motion, simulate_body
from freestand.core.model import Friction
from freestand.core.motion.design_spectra import rg160_spectrum
from freestand.core.motion.spectrum_matching import generate_suite

GRAVITY = 9.81  # [m/s^2]
SUITE_PGA = 0.3 * GRAVITY  # RG 1.60 anchor [m/s^2]
SUITE_COUNT = 20
SUITE_DURATION = 20.0  # [s]
SUITE_SEED = 2024
FINE_STEP = 5e-4  # freestand's fine run [s]
#: MuJoCo's fine runs: (step [s], contact time constant [s])
MUJOCO_FINE = ((1e-4, 1e-3), (5e-5, 5e-4))
MUJOCO_STEP = 0.002  # MuJoCo's default step [s]
MUJOCO_STIFF = 0.004  # contact time constant at the 2 ms step [s] (benchmarks/mujoco_rocking.py)
SPHERE = 1e-3  # contact sphere radius [m]
RIM_POINTS = 48  # a cylinder's rim points in MuJoCo's timing runs
CELL = 0.08  # [m] grid of a box's base
OVERTURNED_TILT = 1.4  # [rad] a MuJoCo body tilted this far lies on its side
SPEED_SECONDS = 10.0  # record length of the single-run timing [s]
CAMPAIGN_LEVELS = np.linspace(0.1, 2.5, 25)  # scale factors of the suite
WORKERS = 2

#: Tolerances of the comparison, per quantity: (relative, absolute).
#: Reasons in docs/benchmarks.md ("3-D bodies").
TOLERANCES = {
    "exact slide": (0.01, 1e-5),  # freestand against the exact slide of the cask
    "exact slide, MuJoCo": (0.03, 1e-5),  # MuJoCo's soft friction scatters by 1-2 %
    "tilt": (0.15, 2e-3),  # [rad] rocking under a record: the impact laws differ slightly
    "slide": (0.20, 2e-3),  # [m]
    "twist": (0.35, 0.05),  # [rad] a rolling cylinder's twist is the most sensitive
}


@dataclass(frozen=True)
class Case:
    """A body under one record of the suite (numbered from 1) times a scale.

    ``rim`` is the number of a cylinder's rim points in MuJoCo's two fine runs:
    a cylinder that rolls on its rim needs a fine one (on a polygon of 24, 48,
    96 points the slender cylinder below peaked at 0.12, 0.09 and 0.19 rad:
    each vertex is a small impact that damps the rolling). ``fine`` are
    MuJoCo's two fine runs, (step [s], contact time constant [s]) each.
    """

    body: Body
    record: int
    scale: float
    rim: tuple[int, int] = (48, 48)
    fine: tuple[tuple[float, float], tuple[float, float]] = MUJOCO_FINE


#: Records and scales where MuJoCo's two fine runs agree (a converged reference):
#: rocking under a record is sensitive, and at other records or scales they part
#: (e.g. the cabinet under record 1 x 1.2: peak tilt 0.046 and 0.148 rad).
CASES = (
    Case(Body("cabinet", Box((1.0, 0.6, 2.0)), 400.0, Friction(0.5, 0.5)), 2, 1.2),
    Case(Body("cask", Cylinder(1.7, 6.0), 1.8e5, Friction(0.3, 0.3)), 1, 1.5),
    Case(
        Body("slender cylinder", Cylinder(0.4, 3.0), 2000.0, Friction(0.5, 0.5)), 6, 0.7, (144, 192)
    ),
    # the cabinet with its base held by friction: it rocks under the three components
    # without sliding, which separates the rocking and impacts from the slide-rock. Its
    # response has two branches, and MuJoCo's soft contact picks one by its settings:
    # peak tilt 0.031 rad at 0.1 ms / T 1 ms, 0.16-0.17 rad at 0.05 ms / T 0.5 or 1 ms and
    # at 0.025 ms / T 0.5 ms, 0.031 again at 0.025 ms / T 0.25 ms and 0.0125 ms / T 0.125 ms
    # (the stiff limit). Its fine runs here: 0.1 ms / T 1 ms and 0.025 ms / T 0.25 ms.
    Case(
        Body("cabinet, mu 2", Box((1.0, 0.6, 2.0)), 400.0, Friction(2.0, 2.0)),
        2,
        1.2,
        fine=((1e-4, 1e-3), (2.5e-5, 2.5e-4)),
    ),
)
#: The cases timed in (b) and profiled in (c): the three bodies.
TIMED = CASES[:3]


# ------------------------------------------------------------------------------ records
def suite_records() -> tuple[list[SupportMotion3], float]:
    """The suite's three-component records, and the seconds it took to generate them."""
    start = time.perf_counter()
    horizontal = rg160_spectrum(SUITE_PGA, 0.05)
    vertical = rg160_spectrum(SUITE_PGA, 0.05, direction="vertical")
    suite = generate_suite(
        horizontal, count=SUITE_COUNT, duration=SUITE_DURATION, seed=SUITE_SEED,
        vertical_target=vertical, horizontal_y_target=horizontal,
    )  # fmt: skip
    records = [
        SupportMotion3(suite.dt, x.acceleration, y.acceleration, v.acceleration)
        for x, y, v in zip(
            suite.horizontal.records, suite.horizontal_y.records, suite.vertical.records,
            strict=True,
        )
    ]  # fmt: skip
    return records, time.perf_counter() - start


def scaled(motion: SupportMotion3, factor: float, seconds: float | None = None) -> SupportMotion3:
    """The motion times ``factor``, optionally cut to its first ``seconds``."""
    count = motion.x.size if seconds is None else int(round(seconds / motion.time_step)) + 1
    return SupportMotion3(
        motion.time_step, factor * motion.x[:count], factor * motion.y[:count],
        factor * motion.vertical[:count],
    )  # fmt: skip


# ------------------------------------------------------------------------------ reference
@nb.njit(cache=False)
def _slide_peak(ax, ay, av, dt, mu, gravity, h, duration):
    """Peak slide of a point mass on the circular Coulomb cone, implicit time stepping.

    Per step: the trial velocity ``w = v - h a_s`` (the support acceleration at
    the step's midpoint), then the friction impulse projected on the cone
    ``|p| <= h mu (g - a_v)``: ``v = 0`` if ``|w|`` is within it, else
    ``w (1 - h mu (g - a_v) / |w|)`` (Moreau's catching-up scheme: first order,
    converges for any record).
    """
    n = ax.size
    vx = vy = x = y = 0.0
    peak = 0.0
    for k in range(int(round(duration / h))):
        s = (k + 0.5) * h / dt
        i = int(s)
        a0 = a1 = a2 = 0.0
        if i < n - 1:
            f = s - i
            a0 = ax[i] + f * (ax[i + 1] - ax[i])
            a1 = ay[i] + f * (ay[i + 1] - ay[i])
            a2 = av[i] + f * (av[i + 1] - av[i])
        wx = vx - h * a0
        wy = vy - h * a1
        limit = h * mu * (gravity - a2)
        size = math.sqrt(wx * wx + wy * wy)
        if size <= limit:
            vx = vy = 0.0
        else:
            vx = wx * (1.0 - limit / size)
            vy = wy * (1.0 - limit / size)
        x += h * vx
        y += h * vy
        peak = max(peak, math.sqrt(x * x + y * y))
    return peak


def slide_reference(motion: SupportMotion3, mu: float, duration: float) -> tuple[float, float]:
    """Exact peak slide [m] of a flat body on the circular cone (two steps: 2 and 1 us)."""
    args = (motion.x, motion.y, motion.vertical, motion.time_step, mu, GRAVITY)
    return tuple(_slide_peak(*args, h, duration) for h in (2e-6, 1e-6))


# ------------------------------------------------------------------------------ MuJoCo
def base_points(body: Body, rim: int = RIM_POINTS) -> np.ndarray:
    """Contact points of the base in the body frame (x, y) [m] that load it about uniformly.

    Flat on the support, soft contacts of equal depth carry equal forces, so
    the points are laid out as the nodes of a quadrature rule of the base's
    area. Box: the centres of a grid of cells of at most ``CELL`` (the
    midpoint rule), and the four corners (the pivots of rocking). Cylinder: the rim
    (``rim`` points, the pivot of rocking and rolling) and three rings inside
    it at R/4, R/2, 3R/4 with twice the rim's density, and the centre (the
    trapezoidal rule in r, in which the rim counts half).
    """
    if isinstance(body.shape, Box):
        lx, ly = body.shape.size[:2]
        nx, ny = math.ceil(lx / CELL), math.ceil(ly / CELL)
        xs = lx * ((np.arange(nx) + 0.5) / nx - 0.5)
        ys = ly * ((np.arange(ny) + 0.5) / ny - 0.5)
        corners = [(sx * 0.5 * lx, sy * 0.5 * ly) for sx in (-1, 1) for sy in (-1, 1)]
        return np.array([(x, y) for x in xs for y in ys] + corners)
    radius = body.shape.radius
    points = [(0.0, 0.0)]
    for ring in (1, 2, 3, 4):
        count = rim if ring == 4 else 2 * rim * ring // 4
        angles = 2.0 * math.pi * np.arange(count) / count
        points += [(radius * ring / 4 * math.cos(a), radius * ring / 4 * math.sin(a))
                   for a in angles]  # fmt: skip
    return np.array(points)


def boundary_points(body: Body, rim: int = RIM_POINTS) -> np.ndarray:
    """Contact points of a box's base on a grid that includes its boundary [m].

    Nodes every ``CELL`` at most, from edge to edge: a rocking edge rests on a
    row of equally loaded points (about freestand's uniform line pressure,
    lever L/4 for the twist) instead of its two corners. A cylinder's points
    are those of :func:`base_points`.
    """
    if not isinstance(body.shape, Box):
        return base_points(body, rim)
    lx, ly = body.shape.size[:2]
    xs = np.linspace(-lx / 2, lx / 2, math.ceil(lx / CELL) + 1)
    ys = np.linspace(-ly / 2, ly / 2, math.ceil(ly / CELL) + 1)
    return np.array([(x, y) for x in xs for y in ys])


def mujoco_xml(
    body: Body, step: float, timeconst: float, contact: str, rim: int = RIM_POINTS
) -> str:
    """MJCF of the body on the plane.

    ``contact``: "points" (:func:`base_points`), "boundary" (:func:`boundary_points`)
    or "primitive" (MuJoCo's box or cylinder).
    """
    c = np.asarray(body.centre)
    inertia = np.asarray(body.inertia)
    mu = body.friction.kinetic
    soft = f'solref="{timeconst} 1" solimp="0.99 0.999 0.0001" friction="{mu} 0.005 0.0001"'
    if contact in ("points", "boundary"):
        points = base_points(body, rim) if contact == "points" else boundary_points(body, rim)
        geoms = [
            f'<geom type="sphere" size="{SPHERE}" pos="{x - c[0]} {y - c[1]} {SPHERE - c[2]}" '
            f'mass="0" {soft}/>'
            for x, y in points
        ]
    elif isinstance(body.shape, Box):
        lx, ly, lz = body.shape.size
        geoms = [
            f'<geom type="box" size="{lx / 2} {ly / 2} {lz / 2}" '
            f'pos="{-c[0]} {-c[1]} {lz / 2 - c[2]}" mass="0" {soft}/>'
        ]
    else:
        height = body.shape.height
        geoms = [
            f'<geom type="cylinder" size="{body.shape.radius} {height / 2}" '
            f'pos="{-c[0]} {-c[1]} {height / 2 - c[2]}" mass="0" {soft}/>'
        ]
    full = (f"{inertia[0, 0]} {inertia[1, 1]} {inertia[2, 2]} "
            f"{inertia[0, 1]} {inertia[0, 2]} {inertia[1, 2]}")  # fmt: skip
    geom_text = "\n      ".join(geoms)
    return f"""<mujoco model="{body.name}">
  <option timestep="{step}" gravity="0 0 {-GRAVITY}" cone="elliptic"/>
  <worldbody>
    <geom name="support" type="plane" size="100 100 0.1" {soft}/>
    <body name="body" pos="{c[0]} {c[1]} {c[2]}">
      <freejoint/>
      <inertial pos="0 0 0" mass="{body.mass}" fullinertia="{full}"/>
      {geom_text}
    </body>
  </worldbody>
</mujoco>"""


class MujocoBody:
    """The body in MuJoCo, driven through rollouts; states as freestand's (r, q)."""

    CHUNK = 20_000  # steps per rollout call

    def __init__(
        self, body: Body, step: float, timeconst: float, contact: str, rim: int = RIM_POINTS
    ) -> None:
        self.body = body
        self.step = step
        self.model = mujoco.MjModel.from_xml_string(mujoco_xml(body, step, timeconst, contact, rim))
        self.data = mujoco.MjData(self.model)
        mujoco.mj_resetData(self.model, self.data)
        mujoco.mj_forward(self.model, self.data)
        spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
        self.initial = np.empty(mujoco.mj_stateSize(self.model, spec))
        mujoco.mj_getState(self.model, self.data, self.initial, spec)

    def forcing(self, motion: SupportMotion3, duration: float) -> np.ndarray:
        """d'Alembert forces m (-a_x, -a_y, +a_v) at each step's midpoint [N], (1, steps, nv)."""
        steps = int(round(duration / self.step))
        t = (np.arange(steps) + 0.5) * self.step
        grid = np.arange(motion.x.size) * motion.time_step
        force = np.zeros((1, steps, self.model.nv))
        for column, values, sign in ((0, motion.x, -1.0), (1, motion.y, -1.0),
                                     (2, motion.vertical, 1.0)):  # fmt: skip
            force[0, :, column] = sign * self.body.mass * np.interp(t, grid, values, right=0.0)
        return force

    def states(self, force: np.ndarray) -> np.ndarray:
        """(steps + 1, 7): position of G and orientation quaternion after each step."""
        state = self.initial[None, :]
        out = [self.initial[1:8][None, :]]
        for start in range(0, force.shape[1], self.CHUNK):
            chunk, _ = rollout.rollout(
                self.model, self.data, state, force[:, start : start + self.CHUNK],
                control_spec=mujoco.mjtState.mjSTATE_QFRC_APPLIED,
            )  # fmt: skip
            out.append(chunk[0, :, 1:8])
            state = chunk[:, -1, :]
        return np.concatenate(out)

    def peaks(self, motion: SupportMotion3, duration: float) -> Peaks:
        states = self.states(self.forcing(motion, duration))
        time_ = np.arange(states.shape[0]) * self.step
        moved = body_motion(self.body, states)
        return Peaks.of(time_, moved, bool(np.max(moved.tilt) >= OVERTURNED_TILT))


# ------------------------------------------------------------------------------ peaks
@dataclass(frozen=True)
class Peaks:
    """What the comparison reads from one run."""

    tilt: float  # [rad]
    slide: float  # [m]
    twist: float  # [rad]
    overturned: bool
    tilt_1rad: float  # time the tilt first reached 1 rad [s], nan if never
    lowest: float  # lowest height a base point reached [m]

    @staticmethod
    def of(time_: np.ndarray, moved, overturned: bool) -> Peaks:
        above = np.flatnonzero(moved.tilt >= 1.0)
        return Peaks(
            float(np.max(moved.tilt)),
            float(np.max(np.hypot(moved.slide[:, 0], moved.slide[:, 1]))),
            float(np.max(np.abs(moved.twist))),
            overturned,
            float(time_[above[0]]) if above.size else math.nan,
            float(np.min(moved.lowest)),
        )


def freestand_peaks(body: Body, motion: SupportMotion3, max_step=None):
    """Peaks of freestand's run (up to a failure, if it failed), and the run."""
    result = simulate_body(body, motion, SUITE_DURATION, max_step=max_step)
    moved = body_motion(body, result.state)
    return Peaks.of(result.time, moved, result.overturned), result


def within(value: float, reference: float, tolerance: tuple[float, float]) -> bool:
    relative, absolute = tolerance
    return abs(value - reference) <= max(relative * abs(reference), absolute)


# ------------------------------------------------------------------------------ (a)
def case_motion(case: Case, records: list[SupportMotion3], seconds=None) -> SupportMotion3:
    return scaled(records[case.record - 1], case.scale, seconds)


def _print_runs(runs: dict[str, Peaks], elapsed: dict[str, float]) -> None:
    print(
        f"  {'run':40s} {'tilt [rad]':>11s} {'slide [m]':>10s} {'twist [rad]':>11s}"
        f" {'overturned':>10s} {'t(1 rad) [s]':>12s} {'lowest [m]':>11s} {'time [s]':>8s}"
    )
    for name, p in runs.items():
        seconds = f"{elapsed[name]:8.2f}" if name in elapsed else ""
        print(
            f"  {name:40s} {p.tilt:11.5f} {p.slide:10.5f} {p.twist:11.5f}"
            f" {str(p.overturned):>10s} {p.tilt_1rad:12.3f} {p.lowest:11.2e} {seconds}"
        )


def _against_exact_slide(case: Case, motion, runs: dict[str, Peaks]) -> bool:
    """The cask slides flat: every run against the exact slide."""
    fine, finer = slide_reference(motion, case.body.friction.kinetic, SUITE_DURATION)
    print(
        f"  exact slide (point mass on the circular cone, implicit steps of 2 and 1 us):"
        f" {fine:.6f} / {finer:.6f} m"
    )
    agreed = True
    for name, p in runs.items():
        key = "exact slide, MuJoCo" if name.startswith("MuJoCo") else "exact slide"
        ok = within(p.slide, finer, TOLERANCES[key])
        agreed &= ok
        print(
            f"    {name:40s} slide {100 * (p.slide / finer - 1):+7.2f} %:"
            f" {'within' if ok else 'FAIL: outside'} {TOLERANCES[key][0]:.0%}"
        )
    return agreed


def _against_mujoco(fs: Peaks, fine: Peaks, mj: list[Peaks], status: str) -> bool:
    """Peaks of freestand at its default step against MuJoCo's finer run.

    Each engine's two runs (freestand at its default step and at
    ``FINE_STEP``, MuJoCo's two fine runs) must agree within the tolerance
    too: a reference that moves with its step has not converged.
    """
    agreed = True
    for key in ("tilt", "slide", "twist"):
        for engine, (a, b) in (("MuJoCo's fine runs", mj), ("freestand's two steps", (fine, fs))):
            spread = abs(getattr(a, key) - getattr(b, key))
            converged = within(getattr(a, key), getattr(b, key), TOLERANCES[key])
            agreed &= converged
            print(
                f"  {key:6s} {engine:22s} differ by {spread:.2e}"
                f" ({'within' if converged else 'FAIL: outside'} the tolerance)"
            )
    reference = mj[-1]
    if status == "failed":
        print("  FAIL: freestand failed, nothing to compare")
        return False
    if fs.overturned or reference.overturned:
        same = fs.overturned == reference.overturned
        print(
            f"  overturned: freestand {fs.overturned}, MuJoCo {reference.overturned}:"
            f" {'agree' if same else 'FAIL: disagree'}"
        )
        return agreed and same
    for key in ("tilt", "slide", "twist"):
        ours, theirs = getattr(fs, key), getattr(reference, key)
        ok = within(ours, theirs, TOLERANCES[key])
        agreed &= ok
        rel, ab = TOLERANCES[key]
        print(
            f"  {key:6s} freestand - MuJoCo {ours - theirs:+.3e}"
            f" ({100 * (ours / max(theirs, 1e-300) - 1):+.1f} %):"
            f" {'within' if ok else 'FAIL: outside'} max({rel:.0%}, {ab:g})"
        )
    return agreed


def accuracy(records: list[SupportMotion3]) -> bool:
    print(f"\n(a) accuracy, {SUITE_DURATION:g} s")
    agreed = True
    for case in CASES:
        body = case.body
        motion = case_motion(case, records)
        peak = np.max(np.hypot(motion.x, motion.y)) / GRAVITY
        vertical = np.max(np.abs(motion.vertical)) / GRAVITY
        runs, elapsed = {}, {}
        start = time.perf_counter()
        runs["freestand, default step"], result = freestand_peaks(body, motion)
        elapsed["freestand, default step"] = time.perf_counter() - start
        runs[f"freestand, {1e3 * FINE_STEP:g} ms"], fine = freestand_peaks(body, motion, FINE_STEP)
        for (step, timeconst), rim in zip(case.fine, case.rim, strict=True):
            name = f"MuJoCo {1e3 * step:g} ms, T {1e3 * timeconst:g} ms"
            if isinstance(body.shape, Cylinder):
                name += f", rim {rim}"
            start = time.perf_counter()
            engine = MujocoBody(body, step, timeconst, "points", rim)
            runs[name] = engine.peaks(motion, SUITE_DURATION)
            elapsed[name] = time.perf_counter() - start
        d = result.diagnostics
        print(
            f"\n{body.name}: {type(body.shape).__name__.lower()}, {body.mass:g} kg,"
            f" mu = {body.friction.kinetic:g}; record {case.record} x {case.scale:g}: horizontal"
            f" peak {peak:.2f} g, vertical {vertical:.2f} g;"
            f" MuJoCo's base: {' and '.join(str(len(base_points(body, r))) for r in case.rim)}"
            " contact points"
        )
        print(
            f"  freestand: {result.status}, {d['steps']} steps, {d['events']} events,"
            f" {d['impacts']} impacts, {d['remedies']} remedies"
        )
        for label, run in (("default step", result), (f"{1e3 * FINE_STEP:g} ms", fine)):
            if run.message:
                print(f"  freestand, {label}: {run.message}")
        _print_runs(runs, elapsed)
        if isinstance(body.shape, Cylinder) and (
            body.friction.kinetic * body.centre_height < body.shape.radius
        ):
            agreed &= _against_exact_slide(case, motion, runs)
        else:
            mujoco_runs = [p for name, p in runs.items() if name.startswith("MuJoCo")]
            agreed &= _against_mujoco(
                runs["freestand, default step"], runs[f"freestand, {1e3 * FINE_STEP:g} ms"],
                mujoco_runs, result.status,
            )  # fmt: skip
    print(f"\n(a) {'PASS: every peak within its tolerance' if agreed else 'FAIL: see above'}")
    return agreed


# ------------------------------------------------------------------------------ (d)
#: The case whose response is chaotic (the slender cylinder): compared over the suite.
ENSEMBLE_CASE = 2
NEAR_FLAT = 0.01  # [rad] a run whose peak tilt stays below this has not started to roll


def _band(count_a: int, count_b: int, n: int) -> bool:
    """Two counts of n agree within two standard deviations of their difference (+1)."""
    p = 0.5 * (count_a + count_b) / n
    return abs(count_a - count_b) <= 2.0 * math.sqrt(2.0 * n * p * (1.0 - p)) + 1.0


def ensemble(records: list[SupportMotion3]) -> bool:
    """(d) The slender cylinder under every record of the suite at its case's scale.

    Its single-run peaks are chaotic (the record times 1 +- 1e-3 moves freestand's
    peak tilt from 0.22 to 0.07 rad at one step, and MuJoCo's two fine runs differ
    by 11 %): what a campaign reads is the statistics. Per engine: the runs that
    stay near flat (peak tilt below ``NEAR_FLAT``), that overturn, and the median
    peak tilt and slide of the runs that rock and stay up. Counts agree within
    two standard deviations of a difference of binomial counts (:func:`_band`).
    """
    case = CASES[ENSEMBLE_CASE]
    body = case.body
    (step, timeconst), rim = case.fine[0], case.rim[0]
    engine = MujocoBody(body, step, timeconst, "points", rim)
    names = ("freestand, default step", f"freestand, {1e3 * FINE_STEP:g} ms",
             f"MuJoCo {1e3 * step:g} ms, T {1e3 * timeconst:g} ms, rim {rim}")  # fmt: skip
    runs: dict[str, list[Peaks]] = {name: [] for name in names}
    print(f"\n(d) {body.name} under the {len(records)} records of the suite x {case.scale:g}")
    for motion in records:
        motion = scaled(motion, case.scale)
        runs[names[0]].append(freestand_peaks(body, motion)[0])
        runs[names[1]].append(freestand_peaks(body, motion, FINE_STEP)[0])
        runs[names[2]].append(engine.peaks(motion, SUITE_DURATION))
    n = len(records)
    counts = {}
    header = ("run", "near flat", "overturned", "tilt [rad]", "slide [m]")
    print("  {:40s} {:>9s} {:>10s} {:>10s} {:>9s}".format(*header))
    for name, peaks in runs.items():
        flat = sum(p.tilt < NEAR_FLAT for p in peaks)
        over = sum(p.overturned for p in peaks)
        rocking = [p for p in peaks if p.tilt >= NEAR_FLAT and not p.overturned]
        tilt = np.median([p.tilt for p in rocking]) if rocking else math.nan
        slide = np.median([p.slide for p in rocking]) if rocking else math.nan
        counts[name] = (flat, over)
        print(f"  {name:40s} {flat:9d} {over:10d} {tilt:10.4f} {slide:9.4f}")
    agreed = True
    reference = counts[names[2]]
    for name in names[:2]:
        for k, label in enumerate(("near flat", "overturned")):
            ok = _band(counts[name][k], reference[k], n)
            agreed &= ok
            print(f"  {label:10s} {name} {counts[name][k]} against MuJoCo {reference[k]} of {n}:"
                  f" {'within' if ok else 'FAIL: outside'} two standard deviations")  # fmt: skip
    return agreed


# ------------------------------------------------------------------------------ (b)
_WORKER: dict = {}  # the suite's records in a worker process of the pool


def _worker_init(records: list[tuple]) -> None:
    _WORKER["records"] = [SupportMotion3(*r) for r in records]


def _worker_pool(records: list[SupportMotion3]) -> ProcessPoolExecutor:
    """``WORKERS`` processes, each holding the suite's records (``_WORKER``)."""
    arrays = [(m.time_step, m.x, m.y, m.vertical) for m in records]
    return ProcessPoolExecutor(WORKERS, initializer=_worker_init, initargs=(arrays,))


def _campaign_chunk(tasks: list[tuple[int, tuple[int, int, float]]]) -> list[tuple]:
    """Run (body, record, level) tasks: (task, status, tilt, slide, twist, seconds, cpu) each.

    seconds is the wall time, cpu the process's CPU time [s] (what the
    simulation costs on a busy machine, where other jobs take the cores).
    """
    rows = []
    for task, (b, r, level) in tasks:
        start, cpu = time.perf_counter(), time.process_time()
        motion = scaled(_WORKER["records"][r], level)
        result = simulate_body(CASES[b].body, motion, SUITE_DURATION)
        rows.append((task, result.status, result.max_rotation, result.max_slide,
                     result.max_twist, time.perf_counter() - start,
                     time.process_time() - cpu))  # fmt: skip
    return rows


# ------------------------------------------------------------------------------ (g)
ROBUST_RUNS = 2000
ROBUST_DURATION = 12.0  # [s] of each record
ROBUST_SLOW = 2.0  # [s] a run slower than this (on one core, once compiled) is reported as a FAIL
STRONG_RUNS = 1400  # random bodies under strong records (robust strong)
STRONG_AFTER = 2.0  # [s] simulated past a strong record's end


def _log_uniform(rng: np.random.Generator, low: float, high: float) -> float:
    return float(math.exp(rng.uniform(math.log(low), math.log(high))))


def robust_case(seed: int) -> tuple[Body, int, float, float]:
    """Random (body, record index, scale, restitution) of the seed.

    60 % boxes of sides 0.1-3 x 0.1-3 x 0.1-6 m, the others cylinders of R
    0.1-2 m and H 0.1-8 m (30 % of them hollow, inner radius 0.3-0.95 R), all
    log-uniform; mass 10 kg-300 t; 40 % with the centre of gravity off the
    axis (within 0.6 of the half-widths, at 0.2-0.9 of the height); 30 % with
    the homogeneous inertia times 0.5-2, turned by up to 0.5 rad about a
    random axis (not principal); static friction 0.05-1.5, kinetic 0.5-1
    times it; the record's scale 0.2-5; restitution 1, 0.8, 0.5 or 0.
    """
    rng = np.random.default_rng(10_000 + seed)
    if rng.random() < 0.6:
        shape = Box(
            (_log_uniform(rng, 0.1, 3), _log_uniform(rng, 0.1, 3), _log_uniform(rng, 0.1, 6))
        )
        half_x, half_y, height = shape.size[0] / 2, shape.size[1] / 2, shape.size[2]
    else:
        radius = _log_uniform(rng, 0.1, 2)
        inner = float(rng.uniform(0.3, 0.95)) * radius if rng.random() < 0.3 else 0.0
        shape = Cylinder(radius, _log_uniform(rng, 0.1, 8), inner)
        half_x = half_y = radius / math.sqrt(2.0)
        height = shape.height
    centre = None
    if rng.random() < 0.4:
        centre = (float(rng.uniform(-0.6, 0.6)) * half_x, float(rng.uniform(-0.6, 0.6)) * half_y,
                  float(rng.uniform(0.2, 0.9)) * height)  # fmt: skip
    mass = _log_uniform(rng, 10, 3e5)
    mu = _log_uniform(rng, 0.05, 1.5)
    homogeneous = Body("", shape, mass, Friction(mu, mu * float(rng.uniform(0.5, 1.0))), centre)
    inertia = None
    if rng.random() < 0.3:
        axis = rng.normal(size=3)
        axis /= np.linalg.norm(axis)
        angle = float(rng.uniform(0, 0.5))
        cross = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
        turn = np.eye(3) + math.sin(angle) * cross + (1 - math.cos(angle)) * cross @ cross
        inertia = turn @ (np.array(homogeneous.inertia) * float(rng.uniform(0.5, 2.0))) @ turn.T
    friction = Friction(mu, mu * float(rng.uniform(0.5, 1.0)))
    body = Body(f"random {seed}", shape, mass, friction, centre, inertia)
    record = int(rng.integers(SUITE_COUNT))
    return body, record, _log_uniform(rng, 0.2, 5.0), float(rng.choice([1.0, 0.8, 0.5, 0.0]))


def strong_case(seed: int) -> tuple[Body, SupportMotion3, float]:
    """(g)'s random body of the seed under a strong record: (body, motion, restitution).

    The body, record and restitution of :func:`robust_case`; its scale times
    3-10 on the horizontal pair and 0-12 on the vertical component,
    ``ROBUST_DURATION`` of it.
    """
    body, record, scale, restitution = robust_case(seed)
    rng = np.random.default_rng(seed + 777)
    horizontal, vertical = float(rng.uniform(3, 10)), float(rng.uniform(0, 12))
    motion = scaled(_WORKER["records"][record], scale * horizontal, ROBUST_DURATION)
    motion = SupportMotion3(motion.time_step, motion.x, motion.y,
                            motion.vertical * (vertical / horizontal))  # fmt: skip
    return body, motion, restitution


def _robust_chunk(seeds: list[int], strong: bool = False) -> list[tuple]:
    """Run the random cases of the seeds: (seed, status, message, remedies, seconds) each.

    ``strong``: under :func:`strong_case`'s records, simulated
    ``STRONG_AFTER`` past their end.
    """
    rows = []
    if not _WORKER.get("warm"):
        # the process's first run loads the compiled engine: not one of the runs timed
        body, record, scale, restitution = robust_case(0)
        simulate_body(body, scaled(_WORKER["records"][record], scale, 1.0), 1.0)
        _WORKER["warm"] = True
    for seed in seeds:
        if strong:
            body, motion, restitution = strong_case(seed)
        else:
            body, record, scale, restitution = robust_case(seed)
            motion = scaled(_WORKER["records"][record], scale, ROBUST_DURATION)
        duration = ROBUST_DURATION + (STRONG_AFTER if strong else 0.0)
        start = time.perf_counter()
        result = simulate_body(body, motion, duration, restitution=restitution)
        seconds = time.perf_counter() - start
        rows.append((seed, result.status, result.message, result.diagnostics["remedies"], seconds))
    return rows


def _strong_chunk(seeds: list[int]) -> list[tuple]:
    return _robust_chunk(seeds, strong=True)


def robustness(records: list[SupportMotion3], strong: bool = False) -> bool:
    """(g): ``ROBUST_RUNS`` random bodies on the worker pool; none failed, none slow.

    ``strong``: ``STRONG_RUNS`` of them under the strong records of
    :func:`strong_case` instead.
    """
    runs = STRONG_RUNS if strong else ROBUST_RUNS
    chunks = [list(range(i, min(i + 25, runs))) for i in range(0, runs, 25)]
    start = time.perf_counter()
    with _worker_pool(records) as pool:
        work = _strong_chunk if strong else _robust_chunk
        rows = [row for chunk in pool.map(work, chunks) for row in chunk]
    statuses = [row[1] for row in rows]
    failed = [row for row in rows if row[1] == "failed"]
    slow = [row for row in rows if row[4] > ROBUST_SLOW]
    times = np.array([row[4] for row in rows])
    scales = (
        f"{ROBUST_DURATION:g} s of a suite record x 0.2-5 x 3-10 (the vertical x 0-12 of that), "
        f"simulated {STRONG_AFTER:g} s past its end"
        if strong
        else f"{ROBUST_DURATION:g} s of a suite record x 0.2-5"
    )
    print(
        f"\n(g{' strong' if strong else ''}) robustness: {len(rows)} random bodies (boxes and "
        f"cylinders, hollow, off-centre, non-principal inertia; robust_case), {scales}, "
        f"restitution 1 / 0.8 / 0.5 / 0, {time.perf_counter() - start:.1f} s on {WORKERS} workers"
    )
    print(
        f"  {'PASS' if not failed and not slow else 'FAIL'}: {statuses.count('completed')} "
        f"completed, {statuses.count('overturned')} overturned, {len(failed)} failed;"
        f" {sum(row[3] > 0 for row in rows)} needed a remedy; a run's time median "
        f"{1e3 * np.median(times):.1f} ms, 99th percentile {1e3 * np.percentile(times, 99):.0f} ms,"
        f" slowest {times.max():.2f} s (seed {rows[int(times.argmax())][0]}; goal under "
        f"{ROBUST_SLOW:g} s)"
    )
    for seed, _, message, _, _ in failed:
        print(f"  failed: seed {seed} ({robust_case(seed)[0].shape}): {message}")
    for seed, _, _, _, seconds in slow:
        print(f"  slow: seed {seed} ({robust_case(seed)[0].shape}): {seconds:.2f} s")
    return not failed and not slow


SPEED_RATIO_GOAL = 10.0  # freestand against MuJoCo's primitives at 2 ms, one 10 s record (#18)
CAMPAIGN_GOAL = 60.0  # [s] the 1,000 simulations on this 2-core machine (#18)


SINGLE_REPEATS = 15  # alternated runs of freestand and MuJoCo's primitive per case (best kept)


def single_runs(records: list[SupportMotion3]) -> tuple[dict[str, float], bool]:
    """Time of one run per case, freestand against MuJoCo at 2 ms.

    Returns MuJoCo's primitive time [s] per case and whether every ratio meets
    ``SPEED_RATIO_GOAL``.
    """
    print(
        f"one body, the first {SPEED_SECONDS:g} s of its record (best of {SINGLE_REPEATS} runs"
        " after compilation, alternated with MuJoCo's primitive; MuJoCo: the rollout alone,"
        " its states not read)"
    )
    print(
        f"  {'body':18s} {'freestand [ms]':>14s} {'MuJoCo primitive [ms]':>21s} {'x':>6s}"
        f" {'MuJoCo points [ms]':>18s} {'x':>6s}"
    )
    primitive, met = {}, True
    for case in TIMED:
        motion = case_motion(case, records, SPEED_SECONDS)
        simulate_body(case.body, motion, SPEED_SECONDS)
        cells = []
        for contact, width in (("primitive", 21), ("points", 18)):
            engine = MujocoBody(case.body, MUJOCO_STEP, MUJOCO_STIFF, contact)
            force = engine.forcing(motion, SPEED_SECONDS)
            if contact == "primitive":
                # alternated with freestand's runs: a slow spell of the machine falls on both
                ours, theirs = best_times_alternated(
                    [lambda b=case.body, m=motion: simulate_body(b, m, SPEED_SECONDS),
                     lambda e=engine, f=force: e.states(f)], SINGLE_REPEATS)  # fmt: skip
            else:
                theirs = best_time(lambda e=engine, f=force: e.states(f), 7)
            cells.append(f"{1e3 * theirs:>{width}.2f} {theirs / ours:5.1f}x")
            if contact == "primitive":
                primitive[case.body.name] = theirs
                met &= theirs / ours >= SPEED_RATIO_GOAL
        print(f"  {case.body.name:18s} {1e3 * ours:14.2f} " + " ".join(cells))
    print(
        f"  {'PASS' if met else 'FAIL'}: freestand at least {SPEED_RATIO_GOAL:g}x as fast as"
        " MuJoCo's primitives at 2 ms on every case"
    )
    return primitive, met


def campaign(records: list[SupportMotion3], mujoco_10s: dict[str, float] | None = None) -> bool:
    """1,000 simulations of 20 s on the worker pool; whether they took under ``CAMPAIGN_GOAL``.

    ``mujoco_10s``: MuJoCo's primitive time per case for the first 10 s of a
    record [s] (:func:`single_runs`), for a projection of MuJoCo's campaign.
    """
    tasks = [(b, r, float(level)) for b in (0, 1) for r in range(len(records))
             for level in CAMPAIGN_LEVELS]  # fmt: skip
    numbered = list(enumerate(tasks))
    chunks = [numbered[i : i + 25] for i in range(0, len(numbered), 25)]
    start = time.perf_counter()
    with _worker_pool(records) as pool:
        list(pool.map(_campaign_chunk, [[]] * WORKERS))  # workers up, numba's cache loaded
        ready = time.perf_counter()
        rows = [row for chunk in pool.map(_campaign_chunk, chunks) for row in chunk]
    done = time.perf_counter()
    seconds = np.array([row[5] for row in rows])
    cpu = sum(row[6] for row in rows)
    statuses = [row[1] for row in rows]
    moved = [row for row in rows if row[1] == "completed"]
    names = " and ".join(CASES[b].body.name for b in (0, 1))
    print(
        f"\n{len(rows)} simulations of {SUITE_DURATION:g} s ({names} x {len(records)} records"
        f" x {len(CAMPAIGN_LEVELS)} levels, the suite x {CAMPAIGN_LEVELS[0]:g} to"
        f" {CAMPAIGN_LEVELS[-1]:g}) on {WORKERS} worker processes ({os.cpu_count()} cores):"
    )
    met = done - start < CAMPAIGN_GOAL
    print(
        f"  {'PASS' if met else 'FAIL'}: wall {done - start:.1f} s (goal < {CAMPAIGN_GOAL:g} s):"
        f" {ready - start:.1f} s starting the workers, then"
        f" {done - ready:.1f} s of simulations; per simulation mean"
        f" {1e3 * seconds.mean():.1f} ms, 95 % below {1e3 * np.quantile(seconds, 0.95):.1f} ms,"
        f" max {1e3 * seconds.max():.1f} ms"
    )
    print(
        f"  CPU time of the simulations {cpu:.1f} s: {cpu / WORKERS:.1f} s on {WORKERS} cores"
        " that nothing else uses (the wall time above includes other jobs' share)"
    )
    print(
        f"  outcomes: {statuses.count('completed')} completed"
        f" ({sum(row[2] > 1e-3 for row in moved)} rocked > 1 mrad,"
        f" {sum(row[3] > 1e-3 for row in moved)} slid > 1 mm),"
        f" {statuses.count('overturned')} overturned, {statuses.count('failed')} failed"
    )
    if mujoco_10s:
        projected = sum(
            mujoco_10s[CASES[b].body.name] * SUITE_DURATION / SPEED_SECONDS for b, _, _ in tasks
        ) / WORKERS  # fmt: skip
        print(
            f"  MuJoCo's primitives at 2 ms, projected from the single runs: {projected:.1f} s"
            f" on {WORKERS} workers ({projected / (done - ready):.1f}x freestand's simulations)"
        )
    return met


RECORD_REPEATS = 3  # runs of each body under each record in ``records`` (the best is kept)


def record_runs(records: list[SupportMotion3]) -> None:
    """(b) across the suite: each timed body under every record at its case's scale.

    The first ``SPEED_SECONDS`` of each record, freestand against MuJoCo's
    primitive at 2 ms on the same motion, best of ``RECORD_REPEATS``. A
    rocking body's run time depends on its history: where an edge sits at
    its friction limit, the remedy's time stepping takes over
    (``docs/three-d.md``, "Remedies") for as long as no consistent mode
    exists, and round-off in an earlier impact decides whether that
    happens; one record's ratio is then one draw. The median and the
    worst ratio over the 20 records say what a user's records see. For
    information: the goal's ratio is the single case's (``single_runs``).
    """
    print(
        f"\n(b) across the suite: each body under each of the {len(records)} records at its"
        f" case's scale, the first {SPEED_SECONDS:g} s (best of {RECORD_REPEATS}); ratio"
        " MuJoCo primitive / freestand"
    )
    print(
        f"  {'body':18s} {'freestand median [ms]':>21s} {'max [ms]':>9s}"
        f" {'MuJoCo median [ms]':>18s} {'ratio: median':>13s} {'worst':>6s} {'best':>6s}"
    )
    for case in TIMED:
        ours, theirs = [], []
        for record in records:
            motion = scaled(record, case.scale, SPEED_SECONDS)
            simulate_body(case.body, motion, SPEED_SECONDS)
            engine = MujocoBody(case.body, MUJOCO_STEP, MUJOCO_STIFF, "primitive")
            force = engine.forcing(motion, SPEED_SECONDS)
            times = best_times_alternated(
                [lambda b=case.body, m=motion: simulate_body(b, m, SPEED_SECONDS),
                 lambda e=engine, f=force: e.states(f)], RECORD_REPEATS)  # fmt: skip
            ours.append(times[0])
            theirs.append(times[1])
        ours_ms, theirs_ms = 1e3 * np.array(ours), 1e3 * np.array(theirs)
        ratio = theirs_ms / ours_ms
        print(
            f"  {case.body.name:18s} {np.median(ours_ms):21.2f} {ours_ms.max():9.2f}"
            f" {np.median(theirs_ms):18.2f} {np.median(ratio):12.1f}x {ratio.min():5.1f}x"
            f" {ratio.max():5.1f}x"
        )


def speed(records: list[SupportMotion3], parts: tuple[str, ...] = ("single", "campaign")) -> bool:
    """(b): the single runs against MuJoCo at 2 ms and/or the campaign; whether goals are met."""
    print(f"\n(b) speed against MuJoCo at its {1e3 * MUJOCO_STEP:g} ms step (same run)")
    primitive, met = single_runs(records) if "single" in parts else (None, True)
    if "campaign" in parts:
        met &= campaign(records, primitive)
    return met


# ------------------------------------------------------------------------------ (c)
REST_SCALE = 0.3  # each case's record x 0.3: every body stays at rest


def profile(records: list[SupportMotion3]) -> None:
    print(
        f"\n(c) profile, {SUITE_DURATION:g} s: each case's record, and x {REST_SCALE:g} (at rest"
        " throughout); RK4 trials per located event; the compiled loop's share of the time"
        " from cProfile"
    )
    print(
        f"  {'body':18s} {'scale':>5s} {'steps/s':>8s} {'events/s':>8s} {'impacts/s':>9s}"
        f" {'remedies':>8s} {'stretch steps':>13s} {'trials/event':>12s}"
        f" {'ms per run':>10s} {'us per step':>11s} {'compiled loop':>13s}"
    )
    for case in TIMED:
        for scale in (case.scale, REST_SCALE):
            body = case.body
            motion = scaled(records[case.record - 1], scale)
            result = simulate_body(body, motion, SUITE_DURATION)
            seconds = best_time(lambda b=body, m=motion: simulate_body(b, m, SUITE_DURATION), 5)
            profiler = cProfile.Profile()
            profiler.enable()
            for _ in range(5):
                simulate_body(body, motion, SUITE_DURATION)
            profiler.disable()
            stats = pstats.Stats(profiler).stats
            total = sum(v[2] for v in stats.values())
            loop = sum(
                v[3] for k, v in stats.items() if k[2] == "run" and body_engine.__file__ in k[0]
            )
            d = result.diagnostics
            print(
                f"  {body.name:18s} {scale:5g} {d['steps'] / SUITE_DURATION:8.0f}"
                f" {d['events'] / SUITE_DURATION:8.1f} {d['impacts'] / SUITE_DURATION:9.1f}"
                f" {d['remedies']:8d} {d['stretch_steps']:13d}"
                f" {d['event_trials'] / max(d['events'] - 1, 1):12.1f}"
                f" {1e3 * seconds:10.2f} {1e6 * seconds / d['steps']:11.2f}"
                f" {100 * loop / total:12.0f}%"
            )


#: Friction coefficients of the cabinet in (e): around its b_x / h = 0.5
EDGE_FRICTIONS = (0.4, 0.49, 0.5, 0.51)


def edges(records: list[SupportMotion3]) -> None:
    """(e) The cabinet around mu = b_x / h = 0.5, with MuJoCo's edges loaded two ways.

    MuJoCo's fine runs with the base's edges loaded at their two corners
    (:func:`base_points`) and uniformly (:func:`boundary_points`), beside
    freestand, for friction coefficients around b_x / h = 0.5 (where sliding
    and rocking about the long edges start together): how the peaks depend
    on the edge's pressure and on the friction near the tie. Prints the
    peaks; no verdict (a diagnosis, not a check).
    """
    case = CASES[0]
    print(f"\n(e) {case.body.name} under record {case.record} x {case.scale:g}: peaks tilt [rad],"
          " slide [mm], twist [rad]")  # fmt: skip
    for mu in EDGE_FRICTIONS:
        body = Body(case.body.name, case.body.shape, case.body.mass, Friction(mu, mu))
        motion = case_motion(case, records)
        runs = {
            "freestand, default step": freestand_peaks(body, motion)[0],
            f"freestand, {1e3 * FINE_STEP:g} ms": freestand_peaks(body, motion, FINE_STEP)[0],
        }
        for contact, label in (("points", "corners"), ("boundary", "uniform edges")):
            for step, timeconst in case.fine:
                name = f"MuJoCo {1e3 * step:g} ms, T {1e3 * timeconst:g} ms, {label}"
                runs[name] = MujocoBody(body, step, timeconst, contact).peaks(
                    motion, SUITE_DURATION
                )
        print(f"  mu = {mu:g}")
        for name, peaks in runs.items():
            print(f"    {name:42s} {peaks.tilt:8.4f} {1e3 * peaks.slide:7.2f} {peaks.twist:9.2e}")


EXAMPLE_LEVEL = 4.0  # [m/s^2] PGA RotD50 of the example cabinet's record (fs.fragility's example)
EXAMPLE_ANGLES = (0.0, 90.0)  # [deg] incidence angles: the same motion by the box's symmetry


def example(_records: list[SupportMotion3]) -> None:
    """(f) The example cabinet (``examples/bodies.toml``) under the synthetic record on x and y.

    The record scaled to a PGA RotD50 of ``EXAMPLE_LEVEL`` (the level where the
    fragility example of ``fs.fragility`` counts its twist), at two incidence
    angles that the box's symmetry makes the same motion; freestand at its
    default step against MuJoCo's first fine run, with the one friction
    coefficient 0.5 (the example's kinetic one; MuJoCo has no static one).
    Prints the peaks; no verdict.
    """
    import freestand as fs
    from freestand.core.sweeps.fragility.intensity import IntensityMeasure, intensity

    root = Path(__file__).resolve().parents[1] / "examples"
    model = fs.load_model(root / "bodies.toml")
    source = next(c for c in model.body_configurations if c.name == "cabinet").bodies[0]
    body = Body(source.name, source.shape, source.mass, Friction(0.5, 0.5),
                centre=source.centre, inertia=source.inertia)  # fmt: skip
    path = root / "records" / "synthetic_H.AT2"
    record = fs.load_record(path, horizontal_y=path)
    record = record.scaled(EXAMPLE_LEVEL / intensity(record, IntensityMeasure("pga-rotd50"), None))
    motion = SupportMotion3(record.dt, record.horizontal, record.horizontal_y, None)
    step, timeconst = MUJOCO_FINE[0]
    print(f"\n(f) the example cabinet, mu 0.5, PGA RotD50 {EXAMPLE_LEVEL:g} m/s^2, "
          f"{SUITE_DURATION:g} s: peaks tilt [rad], slide [mm], twist [rad]")  # fmt: skip
    for angle in EXAMPLE_ANGLES:
        turned = motion.rotated(math.radians(angle))
        runs = {
            "freestand, default step": freestand_peaks(body, turned)[0],
            f"MuJoCo {1e3 * step:g} ms, T {1e3 * timeconst:g} ms": MujocoBody(
                body, step, timeconst, "points"
            ).peaks(turned, SUITE_DURATION),
        }
        for name, peaks in runs.items():
            print(f"  {angle:5.0f} deg  {name:30s} {peaks.tilt:8.4f} {1e3 * peaks.slide:7.2f}"
                  f" {peaks.twist:9.2e}")  # fmt: skip


def main(sections: list[str]) -> int:
    known = ("accuracy", "speed", "single", "records", "campaign", "profile", "ensemble", "edges",
             "example", "robust", "strong")  # fmt: skip
    unknown = [name for name in sections if name not in known]
    if unknown:
        print(f"unknown section {', '.join(unknown)}: give any of {', '.join(known)}")
        return 2
    sections = sections or ["accuracy", "speed", "profile"]
    if mujoco is None and not set(sections) <= {"robust", "strong"}:
        print("mujoco is not installed (pip install -e '.[bench]'): benchmark skipped")
        return 0
    version = mujoco.__version__ if mujoco is not None else "not installed"
    print(f"mujoco {version}, numpy {np.__version__}, {os.cpu_count()} cores")
    records, seconds = suite_records()
    print(
        f"suite: {len(records)} three-component records of {SUITE_DURATION:g} s (RG 1.60,"
        f" {SUITE_PGA / GRAVITY:g} g), generated in {seconds:.1f} s"
    )
    status = 0
    if "accuracy" in sections and not accuracy(records):
        status = 1
    parts = tuple(p for p in ("single", "campaign") if p in sections or "speed" in sections)
    if parts and not speed(records, parts):
        status = 1
    if "records" in sections:
        record_runs(records)
    if "profile" in sections:
        profile(records)
    if "ensemble" in sections and not ensemble(records):
        status = 1
    if "edges" in sections:
        edges(records)
    if "example" in sections:
        example(records)
    if "robust" in sections and not robustness(records):
        status = 1
    if "strong" in sections and not robustness(records, strong=True):
        status = 1
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
