"""Benchmark: freestand's exact rocking against a general physics engine (MuJoCo).

One homogeneous rectangular block, 0.4 m wide and 1.2 m tall (half-width
b = 0.2 m, half-height h = 0.6 m: the block of Makris and Roussos 2000;
alpha = atan(1/3) = 0.3218 rad, p = 3.411 rad/s), 100 kg, on a rigid
horizontal support, friction high enough that it does not slide.

- freestand: :func:`freestand.core.rocking.integrator.simulate` (exact
  nonlinear rocking equation, Housner impacts) and
  :func:`~freestand.core.rocking.integrator.exact_minimum_overturning_amplitude`.
- MuJoCo: a box geom (2b x 0.2 m x 2h) on a plane, in the x-z plane (slide x,
  slide z and a hinge about y through the centre of gravity), 2 ms step.
  The support acceleration a_g(t) is applied as the d'Alembert force
  -m a_g(t) at the centre of gravity (the hinge axis), i.e. the block is
  simulated in the frame of the support: for a translating frame this is
  exact, and it keeps the contact with a fixed plane (a kinematic mocap base
  would move by teleporting, without contact velocities). Two contact
  settings: MuJoCo's defaults (soft contacts, pyramidal cone), and stiff
  contacts (elliptic cone, no-slip iterations, solref/solimp below).
- scipy: ``solve_ivp`` (RK45) on the same rocking equation, restarted at
  each impact found by an event; an independent reference.

Cases: (a) 10 s of examples/records/synthetic_H.AT2 (200 samples/s) scaled
by 2 (PGA 0.5 g; the block rocks to about 0.09 rad and does not overturn):
time per run (median of several, numba compiled beforehand) and the rotation
history against freestand's with a 0.01 ms step; (b) the lowest half-sine
amplitude that overturns the block at omega/p = 2, 4, 8, against
freestand's exact one.

    python benchmarks/mujoco_rocking.py

Needs the optional dependency ``mujoco`` (``pip install -e ".[bench]"``);
without it the script says so and exits.
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import numpy as np

try:
    import mujoco
    from mujoco import rollout
except ImportError:  # optional benchmark dependency
    mujoco = None

from scipy.integrate import solve_ivp

from freestand.core.dynamics.timehistory import SupportMotion
from freestand.core.dynamics.timehistory import simulate as simulate_time_history
from freestand.core.model import Block, Friction, Stack
from freestand.core.rocking.integrator import (
    SampledAcceleration,
    exact_minimum_overturning_amplitude,
    simulate,
)
from freestand.core.rocking.properties import RockingBlock
from freestand.io.records import read_at2

ROOT = Path(__file__).resolve().parents[1]
RECORD = ROOT / "examples" / "records" / "synthetic_H.AT2"

HALF_WIDTH = 0.2  # b [m]
HALF_HEIGHT = 0.6  # h [m]
MASS = 100.0  # [kg]
DEPTH = 0.1  # half-depth of the MuJoCo box out of the plane of motion [m]
FRICTION = 3.0  # Coulomb friction coefficient in MuJoCo (no sliding)
GRAVITY = 9.81  # [m/s^2]
TIMESTEP = 0.002  # MuJoCo step [s] (its default)
RECORD_SECONDS = 10.0  # [s]
RECORD_SCALE = 2.0  # PGA 0.25 g -> 0.5 g
FREQUENCY_RATIOS = (2.0, 4.0, 8.0)  # omega / p of the half-sine pulses
REPEATS = 7  # timed runs; the median is reported

#: MuJoCo contact settings: (attributes of <option>, attributes of the geoms).
CONTACTS = {
    "default": ("", ""),
    "stiff": (
        'cone="elliptic" noslip_iterations="20"',
        'solref="0.004 1" solimp="0.99 0.999 0.0001"',
    ),
}


# ------------------------------------------------------------------------------ MuJoCo
def mujoco_model_xml(contact: str) -> str:
    """MJCF text of the block on a plane, planar joints, for a contact setting."""
    option, geom = CONTACTS[contact]
    friction = f'friction="{FRICTION} 0.005 0.0001"'
    return f"""<mujoco model="rocking block">
  <option timestep="{TIMESTEP}" gravity="0 0 {-GRAVITY}" {option}/>
  <worldbody>
    <geom name="support" type="plane" size="5 5 0.1" {friction} {geom}/>
    <body name="block" pos="0 0 {HALF_HEIGHT}">
      <joint name="x" type="slide" axis="1 0 0"/>
      <joint name="z" type="slide" axis="0 0 1"/>
      <joint name="rotation" type="hinge" axis="0 1 0"/>
      <geom name="block" type="box" size="{HALF_WIDTH} {DEPTH} {HALF_HEIGHT}" mass="{MASS}"
            {friction} {geom}/>
    </body>
  </worldbody>
</mujoco>"""


class MujocoBlock:
    """The MuJoCo block driven by a support acceleration through rollouts (C loop)."""

    def __init__(self, contact: str) -> None:
        self.model = mujoco.MjModel.from_xml_string(mujoco_model_xml(contact))
        self.data = mujoco.MjData(self.model)
        spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
        mujoco.mj_resetData(self.model, self.data)
        mujoco.mj_forward(self.model, self.data)
        self.initial_state = np.empty(mujoco.mj_stateSize(self.model, spec))
        mujoco.mj_getState(self.model, self.data, self.initial_state, spec)
        # index of the hinge angle in the full-physics state: [time, qpos...]
        self.rotation_index = 1 + self.model.jnt_qposadr[2]

    def rotation(self, support_acceleration: np.ndarray) -> np.ndarray:
        """freestand's theta [rad] after each step under a_g at the step starts [m/s^2].

        The d'Alembert force -m a_g acts on the x slide at the centre of
        gravity. A positive a_g tips the block towards -x, a negative rotation
        about +y: theta = -(hinge angle).
        """
        force = np.zeros((1, support_acceleration.size, self.model.nv))
        force[0, :, 0] = -MASS * support_acceleration
        state, _ = rollout.rollout(
            self.model,
            self.data,
            self.initial_state[None, :],
            force,
            control_spec=mujoco.mjtState.mjSTATE_QFRC_APPLIED,
        )
        return -state[0, :, self.rotation_index]

    def impact_ratio(self, block: RockingBlock, theta0: float) -> float:
        """Angular-velocity ratio of the first impact in free rocking from rest at theta0.

        From the peaks before (theta0) and after the impact: the energy above
        the rest position is m g R (cos(alpha - |theta_peak|) - cos(alpha)) on
        either side, and the kinetic energy at theta = 0 equals it.
        """
        m, d = self.model, self.data
        mujoco.mj_resetData(m, d)
        # rotate about the corner (-b, -h): the hinge angle is -theta0
        c, s = math.cos(theta0), math.sin(theta0)
        d.qpos[0] = -HALF_WIDTH + HALF_WIDTH * c - HALF_HEIGHT * s
        d.qpos[1] = HALF_WIDTH * s + HALF_HEIGHT * c - HALF_HEIGHT
        d.qpos[2] = -theta0
        theta = self.rotation_python_loop(np.zeros(int(2.0 / TIMESTEP)), reset=False)
        crossing = int(np.argmax(theta < 0.0))
        after = theta[crossing:]
        peak = -float(np.min(after[: int(np.argmax(after > 0.0)) or None]))
        alpha = block.about("pivot").alpha
        return math.sqrt(
            (math.cos(alpha - peak) - math.cos(alpha))
            / (math.cos(alpha - theta0) - math.cos(alpha))
        )

    def rotation_python_loop(self, support_acceleration: np.ndarray, reset=True) -> np.ndarray:
        """The same as :meth:`rotation` stepping from Python (mj_step per step)."""
        m, d = self.model, self.data
        if reset:
            mujoco.mj_resetData(m, d)
        theta = np.empty(support_acceleration.size)
        for k, a in enumerate(support_acceleration):
            d.qfrc_applied[0] = -MASS * a
            mujoco.mj_step(m, d)
            theta[k] = -d.qpos[2]
        return theta


def half_sine(amplitude: float, omega: float, steps: int) -> np.ndarray:
    """Half-sine support acceleration at the start of each MuJoCo step [m/s^2]."""
    t = np.arange(steps) * TIMESTEP
    return np.where(omega * t < math.pi, amplitude * np.sin(omega * t), 0.0)


# ------------------------------------------------------------------------------ scipy
def solve_ivp_rocking(
    block: RockingBlock, values: np.ndarray, dt: float, t_end: float, rtol: float = 1e-6
):
    """Rocking under a record with scipy's RK45 and impact events (Housner impacts).

    Relative tolerance ``rtol``, absolute 1e-9 rad, steps of at most one
    sample. Returns (times [s], theta [rad]) at the solver's steps. Rest until |a_g|
    exceeds g tan(alpha); at theta = 0 the angular velocity is multiplied by
    the restitution; below 1e-6 of the overturning speed the block rests.
    """
    g = block.effective_gravity
    side_props = {1: block.about("pivot"), -1: block.about("other")}
    k = {s: block.mass * q.R / q.inertia_about_pivot for s, q in side_props.items()}
    alpha = {s: q.alpha for s, q in side_props.items()}
    threshold = {s: q.uplift_threshold for s, q in side_props.items()}
    restitution = {1: block.restitution_onto("other"), -1: block.restitution_onto("pivot")}
    rest_speed = 1e-6 * math.sqrt(2 * g * (1 - math.cos(alpha[1])) / k[1])
    n = values.size
    slope = np.append(np.diff(values), 0.0)

    def accel(t):
        i = min(int(t / dt), n - 1)
        return values[i] + (t / dt - i) * slope[i] if t <= (n - 1) * dt else 0.0

    def rhs(t, y, s):
        phi = alpha[s] - s * y[0]
        return (y[1], k[s] * (-s * g * math.sin(phi) + accel(t) * math.cos(phi)))

    def impact(t, y, s):
        return s * y[0]

    impact.terminal = True
    impact.direction = -1

    def overturn(t, y, s):
        return s * y[0] - 0.5 * math.pi

    overturn.terminal = True
    times, thetas = [0.0], [0.0]
    t, theta, omega, resting, side = 0.0, 0.0, 0.0, True, 1
    while t < t_end:
        if resting:
            start = int(math.ceil(t / dt))
            above = np.nonzero((values[start:] > threshold[1]) | (values[start:] < -threshold[-1]))
            if above[0].size == 0:
                break
            j = start + int(above[0][0])
            side = 1 if values[j] > 0 else -1
            level = side * threshold[side]
            t = max(t, (j - 1 + (level - values[j - 1]) / (values[j] - values[j - 1])) * dt)
            theta, omega, resting = 0.0, 0.0, False
        sol = solve_ivp(
            rhs, (t, t_end), (theta, omega), args=(side,), events=(impact, overturn),
            rtol=rtol, atol=1e-9, max_step=dt,
        )  # fmt: skip
        times.extend(sol.t[1:])
        thetas.extend(sol.y[0, 1:])
        t, theta, omega = sol.t[-1], 0.0, sol.y[1, -1]
        if sol.t_events[1].size:
            break
        if sol.t_events[0].size:
            omega = restitution[side] * omega
            side = -side
            if abs(omega) < rest_speed or sol.t_events[0][0] <= times[-2] + 1e-12:
                resting, omega = True, 0.0
    if times[-1] < t_end:
        times.append(t_end)
        thetas.append(0.0 if resting else thetas[-1])
    return np.asarray(times), np.asarray(thetas)


# ------------------------------------------------------------------------------ helpers
def median_time(function, repeats: int = REPEATS) -> float:
    """Median wall time of ``function()`` [s]."""
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return float(np.median(times))


def mujoco_threshold(engine: MujocoBlock, block: RockingBlock, omega: float, guess: float):
    """Lowest half-sine amplitude that overturns the MuJoCo block [m/s^2], and runs made.

    Scans up by 1 % from 0.7 ``guess`` to the first overturning amplitude,
    then bisects to 1e-4. Overturned: past (alpha + pi/2) / 2 during the run,
    or past alpha at its end (pulse plus 6 s of free rocking).
    """
    alpha = block.about("pivot").alpha
    steps = int((math.pi / omega + 6.0) / TIMESTEP)
    runs = 0

    def overturns(amplitude):
        nonlocal runs
        runs += 1
        theta = engine.rotation(half_sine(amplitude, omega, steps))
        return np.max(np.abs(theta)) > 0.5 * (alpha + 0.5 * math.pi) or abs(theta[-1]) > alpha

    low = 0.7 * guess
    while overturns(low):
        low *= 0.8
    high = low * 1.01
    while not overturns(high):
        low, high = high, high * 1.01
        if high > 5 * guess:
            return math.inf, runs
    while high - low > 1e-4 * high:
        mid = 0.5 * (low + high)
        if overturns(mid):
            high = mid
        else:
            low = mid
    return high, runs


def main() -> int:
    if mujoco is None:
        print("mujoco is not installed (pip install -e '.[bench]'): benchmark skipped")
        return 0
    block = RockingBlock.rectangle(MASS, HALF_WIDTH, HALF_HEIGHT, gravity=GRAVITY)
    pivot = block.about("pivot")
    motion = read_at2(RECORD, gravity=GRAVITY)
    count = int(round(RECORD_SECONDS / motion.dt)) + 1
    values = RECORD_SCALE * motion.horizontal[:count]
    record = SampledAcceleration(values, motion.dt)
    steps = int(round(RECORD_SECONDS / TIMESTEP))
    grid = np.arange(1, steps + 1) * TIMESTEP  # MuJoCo state times
    forcing = np.interp(grid - TIMESTEP, np.arange(count) * motion.dt, values)
    print(f"mujoco {mujoco.__version__}, numpy {np.__version__}")
    print(
        f"block 2b x 2h = {2 * HALF_WIDTH:g} x {2 * HALF_HEIGHT:g} m, {MASS:g} kg:"
        f" alpha = {pivot.alpha:.4f} rad, p = {pivot.p:.4f} rad/s,"
        f" uplift at {pivot.uplift_threshold:.3f} m/s^2"
    )
    print(
        f"record: {RECORD.name}, first {RECORD_SECONDS:g} s at {1 / motion.dt:g} samples/s,"
        f" x {RECORD_SCALE:g}: PGA {np.max(np.abs(values)):.3f} m/s^2"
    )

    # --- (a) record: accuracy ---------------------------------------------------
    reference = simulate(block, record, t_end=RECORD_SECONDS, history=True, max_step=1e-5)
    ref_theta = np.interp(grid, reference.time, reference.rotation)
    histories = {}
    timings = {}
    simulate(block, record, t_end=RECORD_SECONDS)  # numba compilation (or cache load)
    fs = simulate(block, record, t_end=RECORD_SECONDS, history=True)
    histories["freestand"] = (np.interp(grid, fs.time, fs.rotation), fs.max_abs_rotation)
    timings["freestand"] = median_time(lambda: simulate(block, record, t_end=RECORD_SECONDS))
    timings["freestand, with history"] = median_time(
        lambda: simulate(block, record, t_end=RECORD_SECONDS, history=True)
    )
    # The same block through the time-history front end: the single-block fast
    # path with its assumption checks (no slip, no free flight) and full history.
    stack = Stack(
        "block",
        (
            Block(
                "block", MASS, block.inertia, (0.0, HALF_HEIGHT), -HALF_WIDTH, HALF_WIDTH, 0.0,
                Friction(3.0, 3.0),
            ),
        ),
    )  # fmt: skip
    support = SupportMotion(motion.dt, values)
    front = simulate_time_history(stack, support, RECORD_SECONDS, gravity=GRAVITY)
    assert front.diagnostics.method == "single-block rocking", front.diagnostics
    timings["freestand simulate, fast path"] = median_time(
        lambda: simulate_time_history(stack, support, RECORD_SECONDS, gravity=GRAVITY)
    )
    engines = {name: MujocoBlock(name) for name in CONTACTS}
    for name, engine in engines.items():
        theta = engine.rotation(forcing)
        histories[f"MuJoCo {name}"] = (theta, float(np.max(np.abs(theta))))
        timings[f"MuJoCo {name}"] = median_time(lambda e=engine: e.rotation(forcing))
        timings[f"MuJoCo {name}, Python loop"] = median_time(
            lambda e=engine: e.rotation_python_loop(forcing), repeats=3
        )
    t_ivp, th_ivp = solve_ivp_rocking(block, values, motion.dt, RECORD_SECONDS)
    histories["scipy solve_ivp"] = (np.interp(grid, t_ivp, th_ivp), float(np.max(np.abs(th_ivp))))
    timings["scipy solve_ivp"] = median_time(
        lambda: solve_ivp_rocking(block, values, motion.dt, RECORD_SECONDS), repeats=3
    )
    print(
        f"\n(a) {RECORD_SECONDS:g} s record; reference: freestand with a 0.01 ms step,"
        f" peak |theta| {reference.max_abs_rotation:.5f} rad, {reference.impacts} impacts"
    )
    print(f"{'method':30s} {'peak |theta| [rad]':>18s} {'peak error':>10s} {'RMS diff [rad]':>15s}")
    for name, (theta, peak) in histories.items():
        rms = float(np.sqrt(np.mean((theta - ref_theta) ** 2)))
        error = 100 * (peak / reference.max_abs_rotation - 1)
        print(f"{name:30s} {peak:18.5f} {error:9.1f}% {rms:15.2e}")
    theta0 = 0.5 * pivot.alpha
    ratios = ", ".join(
        f"MuJoCo {name} {engine.impact_ratio(block, theta0):.3f}"
        for name, engine in engines.items()
    )
    print(
        f"angular-velocity ratio at impact, free rocking from {theta0:.3f} rad:"
        f" Housner (freestand) {block.restitution:.3f}, {ratios}"
    )

    # --- (b) half-sine thresholds ---------------------------------------------------
    omegas = [ratio * pivot.p for ratio in FREQUENCY_RATIOS]
    frequencies = np.array(omegas) / (2 * math.pi)
    exact_minimum_overturning_amplitude(block, "half-sine", frequencies[0])  # compile
    exact = exact_minimum_overturning_amplitude(block, "half-sine", frequencies).amplitude
    threshold_error = {}
    search_time = {
        "freestand": median_time(
            lambda: [
                exact_minimum_overturning_amplitude(block, "half-sine", f) for f in frequencies
            ],
            repeats=3,
        )
    }
    print("\n(b) lowest overturning half-sine amplitude [m/s^2]")
    print(f"{'omega/p':>8s} {'exact':>9s}" + "".join(f" {'MuJoCo ' + n:>22s}" for n in engines))
    rows = []
    for name, engine in engines.items():
        start = time.perf_counter()
        found = [mujoco_threshold(engine, block, w, a) for w, a in zip(omegas, exact, strict=True)]
        search_time[f"MuJoCo {name}"] = time.perf_counter() - start
        rows.append(found)
        threshold_error[f"MuJoCo {name}"] = [
            100 * (a / e - 1) for (a, _), e in zip(found, exact, strict=True)
        ]
    for i, ratio in enumerate(FREQUENCY_RATIOS):
        cells = "".join(
            f" {row[i][0]:9.4f} ({100 * (row[i][0] / exact[i] - 1):+6.2f} %)" for row in rows
        )
        print(f"{ratio:8g} {exact[i]:9.4f}{cells}")
    print(
        "search time for the three frequencies: "
        + ", ".join(f"{name} {t:.2f} s" for name, t in search_time.items())
        + f" (MuJoCo: {sum(r for row in rows for _, r in row)} runs;"
        " freestand: scan from the uplift threshold and bisection to 1e-7)"
    )

    # --- summary ----------------------------------------------------------------
    default, stiff = timings["MuJoCo default"], timings["MuJoCo stiff"]
    print(
        f"\nsummary: time per {RECORD_SECONDS:g} s record at {1 / motion.dt:g} samples/s,"
        " speed-up against MuJoCo (default / stiff contacts, rollout),"
        " half-sine threshold error"
    )
    header = f"{'method':30s} {'time/run [ms]':>13s} {'x default':>9s} {'x stiff':>8s}"
    header += "".join(f" {'err w/p=' + format(r, 'g'):>10s}" for r in FREQUENCY_RATIOS)
    print(header)
    for name, seconds in timings.items():
        errors = threshold_error.get(name)
        cells = "".join(f" {e:+9.2f}%" for e in errors) if errors else ""
        if name == "freestand":
            cells = f" {'exact: the reference':>32s}"
        print(
            f"{name:30s} {1e3 * seconds:13.2f} {default / seconds:8.1f}x"
            f" {stiff / seconds:7.1f}x{cells}"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
