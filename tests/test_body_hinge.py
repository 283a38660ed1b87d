"""A box's sticking EDGE stepped in its one coordinate (``body_hinge.hinge_rk4``).

The turn about the held edge, RK4 on (chi, chi'), against RK4 on the 13
states with the sticking EDGE's closed form at each stage (what the engine
did before): the same step to RK4's truncation; both converge to the same
state; the edge's corners stay where they were; without excitation the
energy is kept; and the engine's ``_rk4`` takes this step for a sticking
EDGE.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from freestand.core.body import Body, Box, Friction
from freestand.core.contact.body_kernel import (
    DATA_SIZE,
    EDGE,
    SC_ACC,
    STATE_SIZE,
    body_parameters,
    box_corner,
    corner_gap,
    kinetic_energy,
    rotation_matrix,
)
from freestand.core.contact.body_solve import rate, solve_at, state_rate
from freestand.core.dynamics.body_hinge import hinge_rk4
from freestand.core.dynamics.body_step import _rk4
from freestand.core.dynamics.body_work import engine_work

GRAVITY = 9.81
DT = 0.005  # the record's sample interval [s]


def _body() -> Body:
    """A box off its centre, with an inertia that is not principal."""
    size = (0.6, 0.4, 1.5)
    base = Body("hinge", Box(size), 300.0, Friction(0.8, 0.8), (0.03, -0.02, 0.8))
    turn = _axis_rotation(np.array([0.3, -0.5, 0.8]), 0.4)
    inertia = turn @ (np.array(base.inertia) * 1.3) @ turn.T
    return Body("hinge", Box(size), 300.0, Friction(0.8, 0.8), (0.03, -0.02, 0.8), inertia)


def _axis_rotation(axis: np.ndarray, angle: float) -> np.ndarray:
    axis = axis / np.linalg.norm(axis)
    cross = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + math.sin(angle) * cross + (1 - math.cos(angle)) * cross @ cross


def _quaternion(axis: np.ndarray, angle: float) -> np.ndarray:
    axis = axis / np.linalg.norm(axis)
    return np.concatenate(([math.cos(angle / 2)], math.sin(angle / 2) * axis))


def _product(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return np.concatenate(([a[0] * b[0] - a[1:] @ b[1:]], a[0] * b[1:] + b[0] * a[1:]
                           + np.cross(a[1:], b[1:])))  # fmt: skip


def _on_edge(par: np.ndarray, body: Body, index: int, tilt: float, yaw: float, spin: float):
    """The state of the box on its base edge ``index``, turned up by ``tilt`` [rad] about it,
    yawed by ``yaw`` [rad], turning at ``spin`` [rad/s] about the edge."""
    centre = np.array(body.centre)
    turn_z = _axis_rotation(np.array([0.0, 0.0, 1.0]), yaw)
    first = np.array([*box_corner(par, index), 0.0])
    second = np.array([*box_corner(par, (index + 1) % 4), 0.0])
    axis = turn_z @ (second - first)
    axis /= np.linalg.norm(axis)
    pivot = turn_z @ first
    # the sign of the turn that lifts the base's other corners
    opposite = turn_z @ np.array([*box_corner(par, (index + 2) % 4), 0.0])
    sign = 1.0 if (_axis_rotation(axis, tilt) @ (opposite - pivot))[2] > 0.0 else -1.0
    lift = _axis_rotation(axis, sign * tilt)
    g = pivot + lift @ (turn_z @ centre - pivot)
    q = _product(_quaternion(axis, sign * tilt), _quaternion(np.array([0.0, 0.0, 1.0]), yaw))
    omega = spin * axis
    y = np.zeros(STATE_SIZE)
    y[0:3], y[3:7], y[7:10], y[10:13] = g, q, np.cross(omega, g - pivot), omega
    return y


def _record(seed: int, samples: int = 40) -> np.ndarray:
    """x, y and vertical support accelerations [m/s^2], (3, samples)."""
    rng = np.random.default_rng(seed)
    return rng.normal(scale=(3.0, 3.0, 1.5), size=(samples, 3)).T.copy()


def _generic_rk4(par, record, t, h, y, mode):
    """RK4 on the 13 states, the sticking EDGE's closed form at each stage."""
    scratch, _ = engine_work()
    sc = scratch[0]
    data = np.zeros(DATA_SIZE)
    k = np.zeros((4, STATE_SIZE))
    assert solve_at(par, record, DT, t, y, mode, data, sc)
    state_rate(y, sc[SC_ACC], k[0])
    for last, nxt, part in ((0, 1, 0.5), (1, 2, 0.5), (2, 3, 1.0)):
        assert rate(par, record, DT, t + part * h, y + part * h * k[last], mode, data, sc, k[nxt])
    out = y + h / 6.0 * (k[0] + 2.0 * k[1] + 2.0 * k[2] + k[3])
    out[3:7] /= np.linalg.norm(out[3:7])
    return out


def _hinge(par, record, t, h, y, index, pieces=1):
    out = y.copy()
    for piece in range(pieces):
        start = out.copy()
        hinge_rk4(par, record, DT, t + piece * h / pieces, h / pieces, start, index, out)
    return out


@pytest.mark.parametrize("index", [0, 1, 2, 3])
def test_hinge_step_matches_rk4_on_the_full_state(index: int) -> None:
    # one step over a sample interval of the record (the engine's steps end at its
    # samples), against 64 hinge steps: both RK4s within their truncation of it
    body = _body()
    par = body_parameters(body, GRAVITY)
    record = _record(index)
    y = _on_edge(par, body, index, 0.08, 0.7 + index, -0.4)
    mode = np.array([EDGE, index, 0], dtype=np.int64)
    t, h = 3 * DT, DT
    generic = _generic_rk4(par, record, t, h, y, mode)
    hinge = _hinge(par, record, t, h, y, index)
    reference = _hinge(par, record, t, h, y, index, pieces=64)  # to round-off
    error_hinge = np.max(np.abs(hinge - reference))
    error_generic = np.max(np.abs(generic - reference))
    error_half = np.max(np.abs(_hinge(par, record, t, h, y, index, pieces=2) - reference))
    assert np.max(np.abs(hinge - y)) > 1e-3  # the step moves the state
    # measured: hinge 7e-10 to 1.1e-8, the full state's RK4 8e-10 to 1.7e-7 (m, m/s, rad/s)
    assert error_hinge < 5e-8
    assert error_generic < 1e-6
    assert error_hinge <= error_generic  # the hinge keeps the corners: no drift to add
    assert error_hinge / error_half > 8.0  # fourth order: about 16


def test_edge_corners_stay_on_the_support() -> None:
    # the held corners keep their place and have no velocity (to round-off, 1e-13)
    body = _body()
    par = body_parameters(body, GRAVITY)
    record = _record(7)
    y = _on_edge(par, body, 2, 0.1, -1.1, 0.9)
    out = _hinge(par, record, 0.0, 0.02, y, 2, pieces=4)
    d0, d1 = np.zeros(3), np.zeros(3)
    for state in (y, out):
        rot = np.zeros((3, 3))
        rotation_matrix(state, rot)
        positions = []
        for corner in (2, 3):
            gap, speed = corner_gap(par, state, rot, corner, d0)
            d1[:] = state[0:3] + d0
            positions.append(d1.copy())
            assert abs(gap) < 1e-13 and abs(speed) < 1e-13
        if state is y:
            before = positions
    assert np.allclose(positions, before, atol=1e-13, rtol=0.0)


def test_hinge_keeps_energy_without_excitation() -> None:
    # gravity alone: kinetic plus potential energy kept to RK4's accuracy over 1 s in
    # 5 ms steps (1e-9 of the energy's swing)
    body = _body()
    par = body_parameters(body, GRAVITY)
    record = np.zeros((3, 400))
    y = _on_edge(par, body, 1, 0.05, 0.3, 0.2)
    mass = body.mass

    def energy(state):
        rot = np.zeros((3, 3))
        rotation_matrix(state, rot)
        return kinetic_energy(par, state, rot) + mass * GRAVITY * state[2]

    start = energy(y)
    state = y.copy()
    swing = 0.0
    for step in range(200):
        out = state.copy()
        hinge_rk4(par, record, DT, step * DT, DT, state, 1, out)
        state = out
        swing = max(swing, abs(mass * GRAVITY * (state[2] - y[2])))
    assert swing > 1.0  # the box falls back towards its base: energy changes form
    assert abs(energy(state) - start) < 1e-9 * swing


def test_engine_steps_a_sticking_edge_on_its_hinge() -> None:
    # _rk4, the engine's step and its event search's trials, takes the hinge's step
    body = _body()
    par = body_parameters(body, GRAVITY)
    record = _record(3)
    y = _on_edge(par, body, 3, 0.06, 2.0, 0.5)
    mode = np.array([EDGE, 3, 0], dtype=np.int64)
    scratch, _ = engine_work()
    k = np.zeros((5, STATE_SIZE))
    out = np.zeros(STATE_SIZE)
    assert _rk4(par, record, DT, 0.0, 0.004, y, mode, np.zeros(DATA_SIZE), scratch[0], k, out)
    assert np.array_equal(out, _hinge(par, record, 0.0, 0.004, y, 3))
