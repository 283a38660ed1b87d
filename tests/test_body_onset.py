"""A box's first slip under two components: the edge that takes over from the face (#18).

The benchmark's cabinet (1.0 x 0.6 x 2.0 m, 400 kg, mu 0.5) under record 2 of
its suite x 1.2 (``benchmarks/mujoco_body.py``) leaves its flat base at
t = 4.5116 s: the face's centre of pressure reaches its long side under a
horizontal acceleration of 3.2 m/s^2 at about 130 deg from x, above the
uplift threshold in that direction and below the slide threshold. The state
just before the instant is stored in ``tests/data/cabinet_onset.npz`` (state,
time, a 0.15 s slice of the record).

With a FACE's and an EDGE's friction about their geometric centres (the
engine before 2026-11-27) no contact mode was admissible there: the long
edge needed a twist torque about its midpoint and stuck 0.2 % short of mu_0
(5.7 N of 3.2 kN), its slip drove the opposite corners into the support, and
the engine passed the instant by time stepping; from there the cabinet rocked
on an edge by micrometres, slid and twisted far more than MuJoCo's. About the
centre of pressure, which lies on the load's line of action, the edge needs
no twist torque and sticks: the cabinet starts to rock about its long edge.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from freestand.core.body import Body, Box
from freestand.core.contact import body_kernel, body_modes
from freestand.core.model import Friction

DATA = Path(__file__).parent / "data" / "cabinet_onset.npz"
CABINET = Body("cabinet", Box((1.0, 0.6, 2.0)), 400.0, Friction(0.5, 0.5))
GAP, VELOCITY = 1e-7, 1e-4  # the engine's default tolerances [m], [m/s]


def select(excluded_kind: int, scratch) -> np.ndarray:
    """The mode chosen at the stored instant with ``excluded_kind`` excluded (as the event does)."""
    data = np.load(DATA)
    par = body_kernel.body_parameters(CABINET, 9.81, 1.0)
    mode = np.zeros(3, dtype=np.int64)
    excluded = np.array([excluded_kind, 0, 2], dtype=np.int64)
    chosen = body_modes.select_mode(
        par, np.ascontiguousarray(data["record"]), float(data["dt"]), float(data["t"]),
        np.array(data["y"]), scratch, GAP, VELOCITY, mode, np.zeros(body_kernel.DATA_SIZE), excluded,
    )  # fmt: skip
    assert chosen != body_modes.NONE_ADMISSIBLE
    return mode


def test_the_stored_state_is_the_flat_base_at_its_limit():
    data = np.load(DATA)
    y = data["y"]
    assert abs(y[2] - 1.0) < 1e-6  # G at its height: the base flat on the support
    assert np.abs(y[7:13]).max() < 1e-3  # nearly at rest relative to the support


def test_the_long_edge_takes_over_from_the_face_and_sticks():
    scratch = body_kernel.new_scratch()
    mode = select(body_modes.FACE, scratch)
    assert tuple(mode) == (body_kernel.EDGE, 2, 0)  # edge 2: the long side at y = -b_y
    lam, centre = scratch[body_kernel.SC_LAM], scratch[body_kernel.SC_CENTRE]
    normal = lam[0] + lam[1]
    assert normal == pytest.approx(3216.0, rel=1e-3)  # m (g - a_v) [N]
    # the centre of pressure: on the long side, where the load's line of action meets it
    assert centre[1] == pytest.approx(-0.3, abs=1e-12)
    assert centre[0] == pytest.approx(0.2575, abs=1e-3)
    # its twist torque [N m] is round-off against the 250 N m about the edge's midpoint
    assert abs(lam[4] * centre[2]) < 1e-2
    # and the friction holds with a fifth to spare: |F| / (mu_0 N)
    assert math.hypot(lam[2], lam[3]) / (0.5 * normal) == pytest.approx(0.79, abs=0.01)
