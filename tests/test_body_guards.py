"""The 3-D engine's guards: a mode that cannot go on, and impacts that accumulate (#18).

Each stored instant (``tests/data/*.npz``: the body, its restitution factor,
the state and a slice of the record from there) comes from a sweep of random
bodies under the benchmark suite's records, where the engine before these
guards failed or stalled:

- ``slender_box_edge_branch``: a box 0.20 x 0.52 x 5.6 m, 18 kg, its centre of
  gravity off the axis, mu 1.04 / 0.92, landed on an edge that slides. The
  selection found the slide admissible (corner forces +11 and +135 N), the
  step's solve at its start another friction centre with -3.9 kN; a margin
  that starts below its level cannot fire, and the box sank through the
  support 34 ms later ("the contact was lost").
- ``slender_box_pole``: a box 0.14 x 0.22 x 4.9 m, 44 t, a non-principal
  inertia, mu 1.17 / 0.63, sliding on a corner under a record at 1.3 g. Its
  normal force passed a pole (Painleve) within a step: the located lift-off
  came at 2,400 rad/s from 2 rad/s, and the state stopped being finite.
- ``slender_cylinder_zeno`` and ``hollow_cylinder_zeno_remedy``: a cylinder
  R 0.14 m, H 5.3 m, and a hollow one, R 1.23 m (inner 0.64 m), H 5.9 m,
  restitution factor 0, landing within the gap tolerance on a rim point
  again and again: 23,304 impacts in 0.1 s (500,000 in a second of record,
  24 s of computing), and 7,425 impacts and 8,438 velocity-level impacts
  in 0.05 s.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from freestand.core.body import Body, Box, Cylinder
from freestand.core.contact import body_kernel
from freestand.core.contact.body_modes import _restore_own_slip, select_mode
from freestand.core.dynamics import body_remedy
from freestand.core.dynamics.body_events import inconsistent_start
from freestand.core.dynamics.body_history import SupportMotion3, simulate_body
from freestand.core.dynamics.body_step import (
    FN_FRICTION,
    FN_GAP,
    FN_NORMAL,
    MAX_EVENT_FUNCTIONS,
    REF_SIZE,
    energy_jump,
    start_functions,
)
from freestand.core.dynamics.results import ContactTolerances
from freestand.core.model import Friction

DATA = Path(__file__).parent / "data"


def stored_case(name: str):
    """The stored instant ``name``: (its npz data, the body, the support motion from it)."""
    data = np.load(DATA / f"{name}.npz")
    if "size" in data:
        shape = Box(tuple(float(s) for s in data["size"]))
    else:
        shape = Cylinder(float(data["radius"]), float(data["height"]), float(data["inner_radius"]))
    body = Body(name, shape, float(data["mass"]),
                Friction(float(data["static"]), float(data["kinetic"])),
                tuple(float(c) for c in data["centre"]), data["inertia"])  # fmt: skip
    return data, body, SupportMotion3(float(data["dt"]), data["x"], data["ry"], data["v"])


def stored_run(name: str):
    """The engine from the stored instant ``name`` over its stored duration."""
    data, body, motion = stored_case(name)
    return simulate_body(body, motion, float(data["duration"]),
                         restitution=float(data["restitution"]), initial=data["y"])  # fmt: skip


@pytest.mark.parametrize("name", ["slender_box_edge_branch", "slender_box_pole"])
def test_a_mode_that_cannot_go_on_hands_over_to_the_remedy(name):
    result = stored_run(name)
    assert result.status == "completed", result.message
    assert result.diagnostics["remedies"] >= 1
    assert any(kind == "remedy" for _, kind, _, _ in result.events)
    # no blow-up: the body's speeds stay those of a body rocking under the record
    assert np.abs(result.state[:, 7:13]).max() < 50.0


@pytest.mark.parametrize(
    ("name", "before"),
    [("slender_cylinder_zeno", 23_305), ("hollow_cylinder_zeno_remedy", 15_864)],
)
def test_accumulating_impacts_hand_over_to_the_remedy(name, before):
    result = stored_run(name)
    assert result.status == "completed", result.message
    # the events the engine made before the guard over the same span, in the docstring
    assert result.diagnostics["events"] < 100 < before
    assert result.diagnostics["stretch_steps"] >= body_remedy.STRETCH_CHECK


def test_a_kinetic_slide_is_chosen_only_where_its_own_step_holds_it():
    """The slender box's edge at 13.4 ms of its stored case, sliding at some 1 mm/s.

    The selection solved the slide with its friction pulled towards the slip at
    the edge's middle, and found corner forces +11 and +135 N; the step's start
    stores the slip's own direction at the centre of pressure, and its solve had
    -3.9 kN (an inconsistent start, the remedy). The selection now solves again
    under the slip's own direction there; a mode it chooses starts consistent.
    (Here none is: under the slip's own direction the edge's friction centre
    finds no root short of its corner, and the remedy starts at the selection.)
    """
    data, body, motion = stored_case("slender_box_edge_branch")
    instant = np.load(DATA / "slender_box_edge_branch_instant.npz")
    t, y = float(instant["t"]), instant["y"].copy()
    par = body_kernel.body_parameters(body, 9.81, float(data["restitution"]))
    record = np.ascontiguousarray(motion.array())
    sc = np.zeros(1, dtype=body_kernel.SCRATCH_DTYPE)[0]
    mode = np.zeros(3, dtype=np.int64)
    mode_data = np.zeros(body_kernel.DATA_SIZE)
    tolerances = ContactTolerances()
    chosen = select_mode(par, record, motion.time_step, t, y, sc, tolerances.gap,
                         tolerances.velocity, mode, mode_data,
                         np.array([-1, 0, 0], dtype=np.int64))  # fmt: skip
    if chosen < 0:
        return  # no consistent mode: the remedy starts at the selection itself
    values = np.zeros(MAX_EVENT_FUNCTIONS)
    kinds = np.zeros(MAX_EVENT_FUNCTIONS, dtype=np.int64)
    count = start_functions(par, record, motion.time_step, t, y, mode, mode_data, sc,
                            np.zeros(REF_SIZE), tolerances.velocity, values, kinds)  # fmt: skip
    assert inconsistent_start(par, count, values, kinds) == -1, (mode, values[:count])


def test_a_pulled_slip_takes_its_own_direction_for_the_next_solve():
    sc = np.zeros(1, dtype=body_kernel.SCRATCH_DTYPE)[0]
    stored = np.zeros(body_kernel.DATA_SIZE)
    start = body_kernel.D_SLIP
    stored[start : start + 3] = (1.0, 0.0, 0.0)
    sc[body_kernel.SC_SVEL][:3] = (3e-3, 4e-3, 0.0)  # on r's side: u is its own, r kept
    assert not _restore_own_slip(sc, 3, stored)
    assert stored[start : start + 3].tolist() == [1.0, 0.0, 0.0]
    sc[body_kernel.SC_SVEL][:3] = (-3e-3, 4e-3, 0.0)  # turned against r: u was pulled
    assert _restore_own_slip(sc, 3, stored)
    np.testing.assert_allclose(stored[start : start + 3], (-0.6, 0.8, 0.0))
    sc[body_kernel.SC_SVEL][:3] = (1e-8, 0.0, 0.0)  # within the floor: no direction of its own
    assert not _restore_own_slip(sc, 3, stored)


def test_a_force_margin_below_its_level_at_the_start_is_found():
    par = body_kernel.body_parameters(Body("b", Box((1.0, 0.6, 2.0)), 400.0, Friction(0.5, 0.5)),
                                      9.81, 1.0)  # fmt: skip
    slack = 1e-9 * 400.0 * 9.81
    kinds = np.array([FN_NORMAL, FN_FRICTION, FN_GAP], dtype=np.int64)
    assert inconsistent_start(par, 3, np.array([1.0, 2.0, -5.0]), kinds) == -1  # a gap may
    assert inconsistent_start(par, 3, np.array([-0.5 * slack, 2.0, 1.0]), kinds) == -1
    assert inconsistent_start(par, 3, np.array([1.0, -2.0 * slack, 1.0]), kinds) == 1
    assert inconsistent_start(par, 3, np.array([-2.7, 2.0, 1.0]), kinds) == 0


def test_the_energy_bound_holds_a_free_fall_and_catches_a_jump():
    body = Body("b", Box((1.0, 0.6, 2.0)), 400.0, Friction(0.5, 0.5))
    par = body_kernel.body_parameters(body, 9.81, 1.0)
    record = np.zeros((3, 3))
    rot = np.zeros((3, 3))
    h = 0.005
    start = np.zeros(body_kernel.STATE_SIZE)
    start[2], start[3] = 1.0, 1.0
    start[10:13] = (0.3, -0.2, 0.1)
    fall = start.copy()
    fall[9] = -9.81 * h  # free fall: T grows at the bound's own rate
    memo = np.full(3, np.nan)
    assert not energy_jump(par, record, 0.005, 0.0, h, start, fall, rot, memo)
    # the step's end is kept for the next step, which starts there at t + h
    assert memo[0] == h and memo[2] == pytest.approx(9.81)
    assert memo[1] == pytest.approx(math.sqrt(0.5 * float(start[10:13] @ body.inertia @ start[10:13])
                                              + 0.5 * 400.0 * (9.81 * h) ** 2))  # fmt: skip
    farther = fall.copy()
    farther[9] = -9.81 * 2.0 * h
    assert not energy_jump(par, record, 0.005, h, h, fall, farther, rot, memo)
    assert memo[0] == 2.0 * h
    spun = start.copy()
    spun[10:13] *= 1000.0
    assert energy_jump(par, record, 0.005, 0.0, h, start, spun, rot, np.full(3, np.nan))
    # the bound is sqrt(T_end) <= sqrt(T_start) + 2 h A sqrt(m / 2): just above it fires
    t_start = 0.5 * float(start[10:13] @ body.inertia @ start[10:13])
    edge = math.sqrt(t_start) + 2.0 * h * 9.81 * math.sqrt(200.0)
    faster = start.copy()
    faster[9] = -edge / math.sqrt(200.0) * 1.01
    faster[10:13] = 0.0
    assert energy_jump(par, record, 0.005, 0.0, h, start, faster, rot, np.full(3, np.nan))
