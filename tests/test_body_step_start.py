"""The 3-D engine's step start: one solve for the references and the event functions (#18).

A sliding patch's references (its slip direction) need the held mode solved
at the step's start, and so do its event functions. ``start_functions``
solves once where that solve read no stored slip direction at any friction
centre (the stored one is what the reference replaces), and must give what
the two solves gave: the same event functions and the same accelerations,
to round-off; so must a step's end left unprojected, whose solve the next
start reuses. A sliding flat base is not projected while its held rows
have drifted by round-off only, a rocking or rolling one while they drift
by less than a thousandth of the contact tolerances (``drifted``); a
sticking or rolling step's end left unprojected is its next start.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from freestand.core.body import Body, Box, Cylinder
from freestand.core.contact import body_kernel as bk
from freestand.core.dynamics import body_projection
from freestand.core.dynamics import body_step as step
from freestand.core.dynamics.body_history import initial_state
from freestand.core.dynamics.results import ContactTolerances
from freestand.core.model import Friction

G = 9.81
STOP = ContactTolerances().velocity  # a slip slower counts as zero (the engine's stop speed) [m/s]
TOL = ContactTolerances()
BODIES = (
    Body("box", Box((1.0, 0.6, 2.0)), 400.0, Friction(0.4, 0.3), centre=(0.05, -0.02, 0.9)),
    Body("cylinder", Cylinder(0.8, 2.5), 5000.0, Friction(0.4, 0.3)),
)


def _sliding(body, speed, angle, twist, tilt=0.0):
    """A body flat on the support (optionally tilted about x by ``tilt`` [rad]), sliding."""
    y = initial_state(body)
    if tilt:
        y[3], y[4] = math.cos(0.5 * tilt), math.sin(0.5 * tilt)
    y[7], y[8], y[12] = speed * math.cos(angle), speed * math.sin(angle), twist
    return y


def _functions(body, y, record, start, solved=False):
    """(event functions, accelerations, stored slip) of a FACE slip at (0, y); ``solved``: as
    at a step's end left unprojected, the scratch holds the solve of its event functions."""
    par = bk.body_parameters(body, G)
    mode = np.array([bk.FACE, 0, 1], dtype=np.int64)
    data = np.zeros(bk.DATA_SIZE)
    data[bk.D_SLIP] = 1.0  # a stored direction the slip's own one replaces
    sc = bk.new_scratch()
    ref, values, kinds = _function_arrays()
    if solved:  # the step's end: the event functions with the step's stored direction
        step.event_functions(par, record, 1.0, 0.0, y, mode, data, sc, ref, values, kinds)
    if start:
        count = step.start_functions(par, record, 1.0, 0.0, y, mode, data, sc, ref, STOP, values,
                                       kinds, solved)  # fmt: skip
    else:  # the two solves the step's start made before
        step.references(par, record, 1.0, 0.0, y, mode, data, sc, ref, STOP)
        count = step.event_functions(par, record, 1.0, 0.0, y, mode, data, sc, ref, values,
                                       kinds)  # fmt: skip
    return values[:count].copy(), sc[bk.SC_ACC].copy(), data[bk.D_SLIP : bk.D_SLIP + 3].copy()


@settings(max_examples=100, deadline=None)
@given(
    st.sampled_from(BODIES), st.floats(1e-3, 1.0), st.floats(-1.5, 1.5),
    st.floats(-3.0, 3.0), st.floats(-4.0, 4.0), st.floats(-4.0, 4.0), st.floats(-3.0, 3.0),
)  # fmt: skip
def test_one_solve_at_the_step_start_gives_what_two_gave(body, speed, angle, twist, ax, ay, av):
    # the slip within 86 deg of the stored direction (+x), twisting: where the friction centre
    # is moved, the slip there may turn past 90 deg, and the first solve read the stored one
    record = np.array([[ax, ax], [ay, ay], [av, av]])
    y = _sliding(body, speed, angle, twist)
    once, acc_once, stored_once = _functions(body, y, record, start=True)
    twice, acc_twice, stored_twice = _functions(body, y, record, start=False)
    none, acc_none, stored_none = _functions(body, y, record, start=True, solved=True)
    scale = body.mass * G
    # tolerance: the friction centre settles to 1e-12 of the half-width in both solves
    for values, acc, stored in ((once, acc_once, stored_once), (none, acc_none, stored_none)):
        np.testing.assert_allclose(values, twice, rtol=1e-9, atol=1e-9 * scale)
        np.testing.assert_allclose(acc, acc_twice, rtol=1e-9, atol=1e-9)
        np.testing.assert_allclose(stored, stored_twice, rtol=1e-9, atol=1e-12)


def test_a_slip_turned_against_the_stored_direction_is_solved_again():
    # the slip runs along -x, the stored direction is +x: the first solve read the stored one
    body = BODIES[1]
    record = np.zeros((3, 2))
    y = _sliding(body, 0.2, math.pi, 0.0)
    once, acc_once, _ = _functions(body, y, record, start=True)
    twice, acc_twice, _ = _functions(body, y, record, start=False)
    np.testing.assert_allclose(acc_once, acc_twice, rtol=1e-12, atol=1e-12)
    assert acc_once[0] > 0.0  # the kinetic friction opposes the slip along -x
    np.testing.assert_allclose(once, twice, rtol=1e-12, atol=1e-9)


@pytest.mark.parametrize("body", BODIES, ids=lambda b: b.name)
@pytest.mark.parametrize("speed", [0.3, 2.0 * STOP, 0.5 * STOP])
@pytest.mark.parametrize("turning", [True, False], ids=["turning", "straight"])
def test_a_flat_slip_faster_than_the_tolerance_also_stops_at_that_speed(body, speed, turning):
    # body_step.references arms REF_STOP where a flat slip starts faster than the velocity
    # tolerance and turns; the slip-stop function is then min(s . r, |s| - v_tol), else
    # s . r + STOP_TURN |s| (a slip stopped where it turned more than 120 deg from r).
    # The slip runs at 0.4 rad; a support acceleration along y turns it, none leaves it on
    # its line (Newmark's block: it stops where it reverses, at zero speed).
    record = np.zeros((3, 2))
    if turning:
        record[1, :] = 2.0  # a_y [m/s^2]
    armed = speed > STOP and turning
    par = bk.body_parameters(body, G)
    mode = np.array([bk.FACE, 0, 1], dtype=np.int64)
    data = np.zeros(bk.DATA_SIZE)
    data[bk.D_SLIP] = 1.0
    sc = bk.new_scratch()
    ref, values, kinds = _function_arrays()
    y = _sliding(body, speed, 0.4, 0.0)
    count = step.start_functions(par, record, 1.0, 0.0, y, mode, data, sc, ref, STOP, values,
                                 kinds)  # fmt: skip
    stop = values[:count][kinds[:count] == step.FN_SLIP_STOP]
    assert step.slip_turns(sc, 3) == turning
    assert ref[step.REF_STOP] == (STOP if armed else 0.0)
    # the start's reference is the slip's own direction (or, slower than SLIP_FLOOR, the
    # stored +x): s . r there, and |s| - v_tol where armed
    along = y[7] * ref[0] + y[8] * ref[1]
    expected = min(along, speed - STOP) if armed else along + step.STOP_TURN * speed
    assert stop == pytest.approx([expected], rel=1e-12, abs=1e-15)
    # later in the step: a slip slowed to half the tolerance, nearly across r (s . r > 0),
    # fires where the speed is armed only
    y[7] = (-0.5 * ref[1] + 1e-3 * ref[0]) * STOP
    y[8] = (0.5 * ref[0] + 1e-3 * ref[1]) * STOP
    count = step.event_functions(par, record, 1.0, 0.0, y, mode, data, sc, ref, values, kinds)
    stop = values[:count][kinds[:count] == step.FN_SLIP_STOP]
    assert (stop[0] < 0.0) == armed


def test_a_rocking_edge_s_slip_stops_where_it_reverses_only():
    body = BODIES[0]
    y, mode, data = _pivoting(body, 0.05, (0.3, 0.0, 0.0), edge=True)
    mode[bk.M_SLIP] = 1
    y[7] = 0.3  # sliding along x on its edge
    data[bk.D_SLIP] = 1.0
    par = bk.body_parameters(body, G)
    ref, values, kinds = _function_arrays()
    step.start_functions(par, np.zeros((3, 2)), 1.0, 0.0, y, mode, data, bk.new_scratch(), ref,
                         STOP, values, kinds)  # fmt: skip
    assert ref[step.REF_STOP] == 0.0


@pytest.mark.parametrize("turn", [0.0, 60.0, 100.0, 115.0, 125.0, 180.0])
def test_an_edge_s_slip_that_turns_across_its_reference_is_not_a_stop(turn):
    # A slip from rest at a friction limit grazed (its onset's acceleration zero) grows in a
    # direction of its own, across the onset's: the rocking cabinet of the 3-D benchmark on
    # its record slid away at 100 deg from it (2.9e-7 m/s after 0.1 ms). s . r alone fired
    # a stop at once, three times, and the remedy then held the edge for 90 ms on its
    # corners' cones. The stop fires where the slip turned more than 120 deg from r
    # (s . r + STOP_TURN |s| < 0); a slip on its line still stops exactly where it reverses.
    body = BODIES[0]
    y, mode, data = _pivoting(body, 0.05, (0.3, 0.0, 0.0), edge=True)
    mode[bk.M_SLIP] = 1
    data[bk.D_SLIP] = 1.0
    still = y[7:9].copy()  # the edge's points are still at these velocities of G [m/s]
    speed = 1e-3  # [m/s]
    y[7] = still[0] + speed
    par = bk.body_parameters(body, G)
    sc = bk.new_scratch()
    ref, values, kinds = _function_arrays()
    record = np.zeros((3, 2))
    step.start_functions(par, record, 1.0, 0.0, y, mode, data, sc, ref, STOP, values, kinds)
    np.testing.assert_allclose(ref[:3], [1.0, 0.0, 0.0], atol=1e-9)  # r: the slip's, along x
    angle = math.radians(turn)
    y[7] = still[0] + speed * math.cos(angle)
    y[8] = still[1] + speed * math.sin(angle)
    count = step.event_functions(par, record, 1.0, 0.0, y, mode, data, sc, ref, values, kinds)
    stop = values[:count][kinds[:count] == step.FN_SLIP_STOP][0]
    assert stop == pytest.approx(speed * (math.cos(angle) + step.STOP_TURN), abs=1e-12)
    assert (stop < 0.0) == (turn > 120.0)


@pytest.mark.parametrize("body", BODIES, ids=lambda b: b.name)
def test_a_sliding_flat_base_is_projected_only_past_round_off(body):
    sliding = np.array([bk.FACE, 0, 1], dtype=np.int64)
    flat = _sliding(body, 0.3, 0.4, 0.1)
    data = np.zeros(bk.DATA_SIZE)
    data[bk.D_SLIP] = 1.0
    par, sc = _solve_end(body, flat, sliding, data, np.zeros((3, 2)))  # as at a step's end
    gates = (TOL.gap, TOL.velocity)
    assert not body_projection.drifted(par, flat, sliding, sc, *gates)
    assert body_projection.drifted(
        par, _sliding(body, 0.3, 0.4, 0.1, tilt=1e-9), sliding, sc, *gates
    )
    rising = flat.copy()
    rising[9] = 1e-9  # [m/s]
    assert body_projection.drifted(par, rising, sliding, sc, *gates)
    sunk = flat.copy()
    sunk[2] -= 1e-9  # [m]
    assert body_projection.drifted(par, sunk, sliding, sc, *gates)
    # a sticking flat base that moves is always projected
    assert body_projection.drifted(par, flat, np.array([bk.FACE, 0, 0], dtype=np.int64), sc, *gates)


def _function_arrays():
    """A step's references and its event functions' values and kinds, as the engine holds
    them: (ref, values, kinds)."""
    return (np.zeros(step.REF_SIZE), np.zeros(step.MAX_EVENT_FUNCTIONS),
            np.zeros(step.MAX_EVENT_FUNCTIONS, dtype=np.int64))  # fmt: skip


def _pivoting(body, tilt, omega, edge):
    """A body on its base edge 0 (box, ``edge``) or lowest rim point (cylinder), the
    material point(s) there still: (state, mode, data). ``omega`` [rad/s]: about the edge
    (box), or any (cylinder)."""
    if edge:  # tilted about the x axis, the corners 0 and 1 (+b_y) lift: on the edge 2 to 3
        y = initial_state(body, (tilt, 0.0))
        omega = (omega[0], 0.0, 0.0)
        mode = np.array([bk.EDGE, 2, 0], dtype=np.int64)
    else:
        y = initial_state(body, (tilt * math.cos(omega[2]), tilt * math.sin(omega[2])))
        mode = np.array([bk.POINT, 0, 0], dtype=np.int64)
    par = bk.body_parameters(body, G)
    rot = np.empty((3, 3))
    bk.rotation_matrix(y, rot)
    data = np.zeros(bk.DATA_SIZE)
    d = np.empty(3)
    if edge:
        bk.corner_gap(par, y, rot, 2, d)
    else:
        data[bk.D_PSI] = bk.lowest_rim_angle(rot, 0.0)
        radius = body.shape.radius
        bk.arm(par, rot, radius * math.cos(data[bk.D_PSI]), radius * math.sin(data[bk.D_PSI]),
               0.0, d)  # fmt: skip
    y[2] = -d[2]  # on the support (initial_state finds the lowest rim point to 1e-10 m)
    y[10:13] = omega
    y[7:10] = -np.cross(omega, d)  # the pivot's material point is still
    return y, mode, data


def _solve_end(body, y, mode, data, record):
    """(parameters, scratch): the held mode solved at (0, y), as at a step's end."""
    par = bk.body_parameters(body, G)
    sc = bk.new_scratch()
    step.event_functions(par, record, 1.0, 0.0, y, mode, data, sc, *_function_arrays())
    return par, sc


@pytest.mark.parametrize("edge", [True, False], ids=["box on an edge", "cylinder on its rim"])
def test_a_rocking_or_rolling_body_is_projected_only_past_its_drift_gate(edge):
    body = BODIES[0] if edge else BODIES[1]
    y, mode, data = _pivoting(body, 0.05, (0.4, -0.3, 0.7), edge)
    record = np.zeros((3, 2))
    par, sc = _solve_end(body, y, mode, data, record)
    gates = (TOL.gap, TOL.velocity)
    assert not body_projection.drifted(par, y, mode, sc, *gates)
    # a gap or a held row's velocity past a thousandth of its tolerance is projected
    for index, size in ((2, TOL.gap), (9, TOL.velocity), (7, TOL.velocity), (8, TOL.velocity)):
        for fraction, projected in ((0.5e-3, False), (2e-3, True)):
            moved = y.copy()
            moved[index] += fraction * size
            assert body_projection.drifted(par, moved, mode, sc, *gates) is projected, (
                index,
                fraction,
            )
    # sliding, the tangential rows are not held: their velocity is the slip
    sliding = mode.copy()
    sliding[bk.M_SLIP] = 1
    moved = y.copy()
    moved[7] += 0.1
    assert not body_projection.drifted(par, moved, sliding, sc, *gates)
    # a FREE body holds no row
    free = np.array([bk.FREE, 0, 0], dtype=np.int64)
    assert not body_projection.drifted(par, moved, free, sc, *gates)


@settings(max_examples=60, deadline=None)
@given(
    st.booleans(), st.floats(0.01, 0.5), st.floats(-2.0, 2.0), st.floats(-2.0, 2.0),
    st.floats(-math.pi, math.pi), st.floats(-4.0, 4.0), st.floats(-4.0, 4.0), st.booleans(),
)  # fmt: skip
def test_a_sticking_step_end_left_unprojected_is_its_next_start(edge, tilt, w0, w1, w2, ax, ay,
                                                                 flipped):  # fmt: skip
    # the start at a step's end whose solve the scratch holds gives what a fresh start gives;
    # ``flipped``: a rolling cylinder's stored rim angle on the other side (its pivot past a
    # landing is the highest rim point): the start's pivot is the lowest, solved again
    body = BODIES[0] if edge else BODIES[1]
    y, mode, data = _pivoting(body, tilt, (w0, w1, w2), edge)
    if flipped and not edge:
        data[bk.D_PSI] += math.pi
    record = np.array([[ax, ax], [ay, ay], [0.0, 0.0]])
    results = []
    for solved in (False, True):
        work = data.copy()
        par, sc = _solve_end(body, y, mode, work, record) if solved else (
            bk.body_parameters(body, G), bk.new_scratch())  # fmt: skip
        ref, values, kinds = _function_arrays()
        count = step.start_functions(par, record, 1.0, 0.0, y, mode, work, sc, ref, STOP, values,
                                     kinds, solved)  # fmt: skip
        results.append((values[:count].copy(), sc[bk.SC_ACC].copy(), ref.copy(), work.copy()))
    (v0, a0, r0, d0), (v1, a1, r1, d1) = results
    # the same solve at the same state: equal to round-off
    np.testing.assert_allclose(v1, v0, rtol=1e-12, atol=1e-9 * body.mass * G)
    np.testing.assert_allclose(a1, a0, rtol=1e-12, atol=1e-12)
    np.testing.assert_array_equal(r1, r0)
    np.testing.assert_array_equal(d1, d0)
