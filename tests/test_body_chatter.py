"""An edge at its friction limit: the chatter of slip restarts and its remedy (#18).

The benchmark's cabinet (1.0 x 0.6 x 2.0 m, 400 kg, mu 0.5) under record 1 of
its suite x 2.4 (``benchmarks/mujoco_body.py``) rocks about its long edge,
slowly and 0.2 mm up, and reaches the edge's friction limit at t = 2.3029 s.
The state at t = 2.29 s is stored in ``tests/data/cabinet_chatter.npz``
(state, time, a 0.15 s slice of the record).

There the edge cannot stick and its slip from rest has no lasting direction:
the onset direction is unstable (the slip veers within microseconds and the
slip-stop function fires) or none exists. Without the remedy such a chatter
restarted the slip from rest every 30 to 100 microseconds (150 restarts in
0.1 s at the instant this file held before, 158 events). Three restarts
within a millisecond (``body_remedy.CHATTER_WINDOW``, ``CHATTER_COUNT``)
hand the edge to the velocity-level time stepping until the patch sticks,
slips at a speed, or another contact holds.

That earlier instant (the same run at t = 1.89 s, now
``tests/data/cabinet_edge_slip.npz``) no longer chatters: its edge's slip
onset exists, and the onset's Newton search, which converged only linearly
there, now finds it (``tests/test_body_onset_newton.py``).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from freestand.core.body import Body, Box
from freestand.core.contact import body_impulse, body_kernel
from freestand.core.dynamics import body_engine as engine
from freestand.core.dynamics import body_remedy, body_state
from freestand.core.dynamics.body_history import rotation_matrices
from freestand.core.model import Friction

DATA = Path(__file__).parent / "data" / "cabinet_chatter.npz"
EDGE_SLIP = Path(__file__).parent / "data" / "cabinet_edge_slip.npz"
CABINET = Body("cabinet", Box((1.0, 0.6, 2.0)), 400.0, Friction(0.5, 0.5))
GAP, VELOCITY = 1e-7, 1e-4  # the engine's default tolerances [m], [m/s]
SPAN = 0.1  # [s] simulated from the stored instant
ROWS = 20_000


def run_from_instant(max_step: float, instant: Path = DATA):
    """The engine from the stored state over ``SPAN``: istate, event kinds, times, states, modes
    and contact forces (N, |f_t|)."""
    data = np.load(instant)
    record = np.ascontiguousarray(data["record"])
    dt, t = float(data["dt"]), float(data["t"])
    breaks = np.arange(1, record.shape[1]) * dt
    par = body_kernel.body_parameters(CABINET, 9.81, 1.0)
    y = np.array(data["y"])
    mode, istate = np.zeros(3, dtype=np.int64), np.zeros(body_state.I_SIZE, dtype=np.int64)
    out = (np.empty(ROWS), np.empty((ROWS, body_kernel.STATE_SIZE)),
           np.empty((ROWS, 3), dtype=np.int64), np.empty((ROWS, 2)))  # fmt: skip
    events = (np.empty(ROWS),) + tuple(np.empty(ROWS, dtype=np.int64) for _ in range(3))
    engine.run(par, record, dt, breaks, max_step, t + SPAN, record.shape[1] * dt, GAP, VELOCITY,
               t, y, mode, np.zeros(body_kernel.DATA_SIZE), np.zeros(1, body_kernel.SCRATCH_DTYPE),
               np.zeros(1, body_impulse.IMPULSE_WORK_DTYPE), istate, *out, *events)  # fmt: skip
    count = min(int(istate[body_state.I_EVENTS]), ROWS)
    rows = int(istate[body_state.I_RECORDS])
    return istate, events[1][:count], out[0][:rows], out[1][:rows], out[2][:rows], out[3][:rows]


@pytest.fixture(scope="module")
def default_run():
    return run_from_instant(0.02)  # the cabinet's default step, 0.05 / omega_largest capped


def test_the_stored_instant_rocks_on_the_long_edge():
    y = np.load(DATA)["y"]
    # G 0.18 mm above its resting height: the box tilted about its long side, turning
    assert y[2] - 1.0 == pytest.approx(1.83e-4, abs=1e-6)
    assert abs(y[10]) > 0.01 > 1e-4 > abs(y[11])  # omega_x: rocking about the x-parallel edge


def test_the_chatter_is_handed_to_the_remedy(default_run):
    istate, kinds = default_run[:2]
    assert istate[body_state.I_STATUS] == body_state.STATUS_COMPLETED
    # without the remedy an edge's chatter restarted its slip 150 times in 0.1 s (158 events);
    # here 5 restarts ('stick' events) and two remedies, 10 events
    restarts = int(np.count_nonzero(kinds == body_state.EV_STICK))
    assert restarts < 30
    assert istate[body_state.I_REMEDIES] >= 1 and istate[body_state.I_STRETCH_STEPS] > 0
    assert len(kinds) < 100


def test_the_remedy_keeps_the_base_on_the_support(default_run):
    state = default_run[3]
    rot = rotation_matrices(state[:, 3:7])
    corners = np.array([[sx, sy, -1.0] for sx, sy in ((0.5, 0.3), (-0.5, 0.3), (-0.5, -0.3),
                                                      (0.5, -0.3))])  # fmt: skip
    heights = state[:, 2][:, None] + np.einsum("kj,cj->kc", rot[:, 2, :], corners)
    assert heights.min() > -1e-6  # [m] the velocity-level steps' penetration stays small
    speed = np.linalg.norm(state[:, 7:10], axis=1)
    assert np.all(np.isfinite(speed)) and speed.max() < 1.0  # [m/s] no blow-up


def test_the_remedy_records_the_edge_it_holds_and_its_force(default_run):
    istate, _, _, state, modes, forces = default_run
    # the stretch's rows: a long edge (corners 2 and 3, then 0 and 1 as it rocks back),
    # never free flight (its mode is FREE while it steps), carrying the weight on average
    # (m g = 3.9 kN; the vertical record and the rocking move it: 2.7-5.3 kN, median 4.4). The
    # two stretches take 144 steps of 0.1 ms
    assert istate[body_state.I_STRETCH_STEPS] >= 1
    assert not np.any(modes[:, 0] == body_kernel.FREE)
    assert np.count_nonzero(modes[:, 0] != body_kernel.EDGE) <= 3  # a corner as it lands
    held = modes[:, 0] == body_kernel.EDGE
    assert set(modes[held, 1].tolist()) == {0, 2}
    assert 2000.0 < np.median(forces[held, 0]) < 6000.0


def test_the_tilt_after_the_chatter_does_not_depend_on_the_step():
    # the remedy's time stepping has its own step; the event-driven parts follow max_step
    tilts = []
    for step in (0.02, 0.002):
        state = run_from_instant(step)[3]
        q = state[-1, 3:7]
        tilts.append(math.acos(1.0 - 2.0 * (q[1] ** 2 + q[2] ** 2)))
    assert tilts[1] == pytest.approx(tilts[0], rel=0.02)  # 0.0041 rad both; 0.7 % apart


def test_an_edge_whose_slip_onset_exists_slips_without_the_remedy():
    # the instant this file held before (t = 1.89 s): the edge's slip onset exists, and the
    # onset's Newton search, which converged linearly (by kappa / J an iteration) and ran out
    # of iterations there, finds it; the edge slips from rest, event-driven. The remedy's one
    # step had found the same slip: the tilt at the end was 0.0138766 rad (1e-5 apart)
    for step in (0.02, 0.002):
        istate, kinds, _, state = run_from_instant(step, EDGE_SLIP)[:4]
        assert istate[body_state.I_STATUS] == body_state.STATUS_COMPLETED
        assert istate[body_state.I_REMEDIES] == 0 and istate[body_state.I_STRETCH_STEPS] == 0
        assert np.count_nonzero(kinds == body_state.EV_SLIP) >= 1
        q = state[-1, 3:7]
        tilt = math.acos(1.0 - 2.0 * (q[1] ** 2 + q[2] ** 2))
        assert tilt == pytest.approx(0.01387, rel=2e-3)  # 0.013877 and 0.013859 rad


def _restarts(kind: int, times) -> list[int]:
    """The event kinds watch_chatter makes of slip restarts of a ``kind`` patch at ``times``."""
    istate = np.zeros(body_state.I_SIZE, dtype=np.int64)
    chatter = np.array([-math.inf, 0.0])
    kinds = []
    for t in times:
        mode = np.array([kind, 0, 1], dtype=np.int64)  # slipping again after the slip-stop
        kinds.append(body_remedy.watch_chatter(t, kind, body_state.EV_STICK, mode, istate, chatter))
    return kinds


@pytest.mark.parametrize(
    ("kind", "spacing", "chatters"),
    [
        (body_kernel.EDGE, 5e-4, True),  # an edge's restarts within a millisecond
        (body_kernel.EDGE, 2e-3, False),
        # a flat base's restarts 0.1 ms apart are real stick-slips (the support's acceleration
        # hovering at the friction limit); 5e-12 s apart (a cabinet once made 2,287 of them at
        # one instant) no slip from rest lasts
        (body_kernel.FACE, 1e-4, False),
        (body_kernel.FACE, 5e-12, True),
        (body_kernel.POINT, 5e-12, False),  # a point's slip is not watched
    ],
)
def test_slip_restarts_in_quick_succession_hand_the_patch_to_the_remedy(kind, spacing, chatters):
    kinds = _restarts(kind, 1.0 + spacing * np.arange(body_remedy.CHATTER_COUNT))
    assert kinds[:-1] == [body_state.EV_STICK] * (body_remedy.CHATTER_COUNT - 1)
    assert kinds[-1] == (body_state.EV_REMEDY if chatters else body_state.EV_STICK)
