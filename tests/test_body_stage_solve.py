"""An RK4 stage of a sticking or sliding mode: the accelerations of the full solve.

``body_solve.rate`` solves a sticking patch with ``solve_at_centre`` (its
rows at the patch's geometric centre) instead of ``solve_at``, which after
the same solve expresses the friction about the centre of pressure
(``centre_stick_friction``): its accelerations must be those of
``solve_at`` to the last bit. A sticking POINT or EDGE (a box's corners
and edges, a cylinder's rim point) is solved in a stage by its closed
form on the applied wrench alone (``body_solve.sticking_stage``, no
inverse inertia): its accelerations must be ``solve_at``'s to round-off.
A sliding FACE's stage skips the check of its slip's direction at its
centre of pressure where a bound proves that it holds
(``body_solve._kept_by_bound``): its accelerations and forces must be
``solve_at``'s to the last bit. A stage reads the accelerations only. In
any state.
"""

from __future__ import annotations

import numpy as np
import pytest

from freestand.core.body import Body, Box, Cylinder
from freestand.core.contact import body_kernel, body_solve
from freestand.core.model import Friction

BOX = Body("cabinet", Box((1.0, 0.6, 2.0)), 400.0, Friction(0.5, 0.5))
CYLINDER = Body("cask", Cylinder(1.7, 6.0), 1.8e5, Friction(0.3, 0.3))
RECORD = np.array([[1.5, -2.0], [0.8, 2.5], [1.0, -0.5]])  # a_x, a_y, a_v at t = 0, 1 s
PATCHES = [(BOX, body_kernel.FACE, 0)] + [(BOX, body_kernel.EDGE, k) for k in range(4)]
PATCHES += [(BOX, body_kernel.POINT, k) for k in range(4)]
PATCHES += [(CYLINDER, body_kernel.FACE, 0), (CYLINDER, body_kernel.POINT, 0)]


def _random_state(rng):
    """A random state near the support (any orientation near upright, any velocity) and its
    mode data with a random stored rim angle."""
    y = np.zeros(body_kernel.STATE_SIZE)
    y[0:3] = rng.normal(0.0, 0.3, 3) + (0.0, 0.0, 1.0)
    q = np.array([1.0, 0.0, 0.0, 0.0]) + rng.normal(0.0, 0.2, 4)
    y[3:7] = q / np.linalg.norm(q)
    y[7:13] = rng.normal(0.0, 0.5, 6)
    data = np.zeros(body_kernel.DATA_SIZE)
    data[body_kernel.D_PSI] = rng.uniform(-np.pi, np.pi)
    return y, data


@pytest.mark.parametrize(("body", "kind", "index"), PATCHES)
def test_a_sticking_stage_has_the_full_solves_accelerations(body, kind, index):
    par = body_kernel.body_parameters(body, 9.81, 1.0)
    rng = np.random.default_rng(7 + 10 * kind + index)
    for _ in range(20):
        y, data = _random_state(rng)
        mode = np.array([kind, index, 0], dtype=np.int64)
        full, centre = body_kernel.new_scratch(), body_kernel.new_scratch()
        ok_full, *_ = body_solve.solve_at(par, RECORD, 1.0, 0.4, y, mode, data, full)
        ok_centre, *_ = body_solve.solve_at_centre(par, RECORD, 1.0, 0.4, y, mode, data, centre)
        assert ok_full == ok_centre
        acc_full, acc_centre = full[body_kernel.SC_ACC], centre[body_kernel.SC_ACC]
        assert np.array_equal(acc_full, acc_centre)  # to the last bit
        ydot = np.zeros(body_kernel.STATE_SIZE)
        stage = body_kernel.new_scratch()
        assert body_solve.rate(par, RECORD, 1.0, 0.4, y, mode, data, stage, ydot) == ok_full
        if kind == body_kernel.FACE:
            assert np.array_equal(ydot[7:13], acc_full)  # the same solve
        else:
            # tolerance: round-off of the closed form about the point or hinge against the
            # Delassus or hinge solve on M^-1 f_0, relative to the largest term
            scale = np.max(np.abs(acc_full)) + 9.81
            np.testing.assert_allclose(ydot[7:13], acc_full, rtol=0.0, atol=1e-12 * scale)


def _sliding_flat(rng, body, spin):
    """A state of ``body`` flat on the support, turned by a random yaw, sliding at a random
    velocity [m/s] and twisting at ``spin`` [rad/s]; its mode data (a sliding FACE, the
    stored direction the slip's at the base centre, as a step's start stores it)."""
    yaw = rng.uniform(-np.pi, np.pi)
    y = np.zeros(body_kernel.STATE_SIZE)
    y[2] = body.centre[2]
    y[3:7] = np.cos(yaw / 2), 0.0, 0.0, np.sin(yaw / 2)
    y[7:9] = rng.normal(0.0, 0.3, 2)
    y[12] = spin
    data = np.zeros(body_kernel.DATA_SIZE)
    slip = np.array(
        [y[7], y[8], body_kernel.body_parameters(body, 9.81)[body_kernel.P_RHO_FACE] * spin]
    )
    data[body_kernel.D_SLIP : body_kernel.D_SLIP + 3] = slip / np.linalg.norm(slip)
    return y, data


@pytest.mark.parametrize("body", [BOX, CYLINDER])
@pytest.mark.parametrize("spin", [0.0, 1e-14, 1e-9, 0.3])
def test_a_sliding_face_s_stage_has_the_full_solves_accelerations(body, spin):
    # a stage skips the check of the slip's direction at the centre of pressure where a
    # bound proves that it holds (body_solve._kept_by_bound): its accelerations and forces
    # must be the full solve's to the last bit, whether it skips (no twist, round-off's) or
    # not (a twist that turns the slip across the base)
    par = body_kernel.body_parameters(body, 9.81, 1.0)
    rng = np.random.default_rng(11)
    mode = np.array([body_kernel.FACE, 0, 1], dtype=np.int64)
    skipped = 0
    for _ in range(40):
        y, data = _sliding_flat(rng, body, spin * rng.choice((-1.0, 1.0)))
        record = rng.normal(0.0, 4.0, (3, 2))
        full, stage = body_kernel.new_scratch(), body_kernel.new_scratch()
        ok_full, *_ = body_solve.solve_at(par, record, 1.0, 0.4, y, mode, data, full)
        ok_stage, *_ = body_solve._solve_held_mode(par, record, 1.0, 0.4, y, mode, data, stage,
                                                   True)  # fmt: skip
        assert ok_full == ok_stage
        for field in (body_kernel.SC_ACC, body_kernel.SC_LAM):
            assert np.array_equal(full[field], stage[field])  # to the last bit
        # the skip leaves the tangential rows at the centre of the solve, not of pressure
        skipped += not np.array_equal(full[body_kernel.SC_TANGENT], stage[body_kernel.SC_TANGENT])
    if spin < 1e-12:
        assert skipped > 20  # no twist: the check is skipped in most states
    if spin > 0.1:
        assert skipped == 0  # a twist turns the slip: the check is made


@pytest.mark.parametrize(("body", "index"), [(BOX, k) for k in range(4)] + [(CYLINDER, 0)])
def test_a_sticking_point_s_stage_is_its_closed_form_without_its_rows(body, index):
    # an RK4 stage of a sticking POINT (body_solve.rate: sticking_stage without its rows)
    # computes the point's arm and its rows' biases alone: its accelerations and forces must
    # be those of the closed form on the rows (sticking_stage) to the last bit, and the
    # scratch's rows are left as they were
    par = body_kernel.body_parameters(body, 9.81, 1.0)
    rng = np.random.default_rng(23 + index)
    mode = np.array([body_kernel.POINT, index, 0], dtype=np.int64)
    for _ in range(40):
        y, data = _random_state(rng)
        rows, stage = body_kernel.new_scratch(), body_kernel.new_scratch()
        stage[body_kernel.SC_NORMAL][:] = rng.normal(size=stage[body_kernel.SC_NORMAL].shape)
        kept = stage[body_kernel.SC_NORMAL].copy(), stage[body_kernel.SC_TANGENT].copy()
        ok = body_solve.sticking_stage(par, RECORD, 1.0, 0.4, y, mode, data, rows)
        ydot = np.zeros(body_kernel.STATE_SIZE)
        assert body_solve.rate(par, RECORD, 1.0, 0.4, y, mode, data, stage, ydot) == ok
        for field in (body_kernel.SC_ACC, body_kernel.SC_LAM):
            assert np.array_equal(rows[field], stage[field])  # to the last bit
        assert np.array_equal(stage[body_kernel.SC_NORMAL], kept[0])
        assert np.array_equal(stage[body_kernel.SC_TANGENT], kept[1])
