"""Reading a 3-D body's motion from its states (issue #18): tilt, slide, twist, base heights;
and the history's rows gathered from the engine's calls."""

import math
from functools import reduce

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from freestand.core.body import Body, Box, Cylinder
from freestand.core.contact.body_kernel import EDGE, FACE, FREE, POINT, body_parameters
from freestand.core.dynamics import body_history, body_state
from freestand.core.dynamics.body_history import (
    SupportMotion3,
    _first_invalid,
    _kept_rows,
    body_motion,
    initial_state,
    lost_contact_depth,
)
from freestand.core.dynamics.results import peak_between_samples
from freestand.core.model import Friction

BOX = Body("box", Box((1.0, 0.6, 2.0)), 400.0, Friction(0.5, 0.5))
CASK = Body("cask", Cylinder(0.5, 2.0), 1000.0, Friction(0.5, 0.5))


def _yawed(state, angle):
    """The state turned by ``angle`` about the vertical through the origin."""
    turned = state.copy()
    c, s = math.cos(0.5 * angle), math.sin(0.5 * angle)
    w, x, y, z = state[3:7]
    turned[3:7] = (c * w - s * z, c * x - s * y, c * y + s * x, c * z + s * w)
    r = state[0:3]
    turned[0:3] = (math.cos(angle) * r[0] - math.sin(angle) * r[1],
                   math.sin(angle) * r[0] + math.cos(angle) * r[1], r[2])  # fmt: skip
    return turned


@pytest.mark.parametrize("body", [BOX, CASK], ids=["box", "cylinder"])
def test_a_body_tilted_on_its_base_edge_has_that_tilt_and_lifts_its_far_side(body):
    angle = 0.2
    states = np.array([initial_state(body), initial_state(body, (angle, 0.0))])
    motion = body_motion(body, states)
    np.testing.assert_allclose(motion.tilt, [0.0, angle], atol=1e-12)
    # turned about x with G kept over the same point, standing on its edge (or rim point)
    # at y = -w/2: the far side rises by w sin(angle), the base centre moves by h sin(angle)
    width = body.shape.size[1] if isinstance(body.shape, Box) else 2.0 * body.shape.radius
    np.testing.assert_allclose(motion.lowest, [0.0, 0.0], atol=1e-12)
    np.testing.assert_allclose(motion.highest, [0.0, width * math.sin(angle)], atol=1e-12)
    expected = [0.0, body.centre_height * math.sin(angle)]
    np.testing.assert_allclose(motion.slide[1], expected, atol=1e-12)
    np.testing.assert_allclose(motion.twist, 0.0, atol=1e-12)


def test_a_yaw_is_a_twist_and_turns_the_slide_with_it():
    tilted = initial_state(BOX, (0.1, 0.05))
    tilted[0:2] += (0.3, -0.2)
    states = np.array([initial_state(BOX), tilted, _yawed(tilted, 2.5), _yawed(tilted, 4.0)])
    motion = body_motion(BOX, states)
    # a tilt is a swing: it leaves the twist alone; turning about the vertical adds to it,
    # unwrapped past pi
    np.testing.assert_allclose(motion.twist, [0.0, 0.0, 2.5, 4.0], atol=1e-12)
    np.testing.assert_allclose(motion.tilt[1:], math.hypot(0.1, 0.05), atol=1e-12)
    slide = motion.slide[1]
    for k, angle in ((2, 2.5), (3, 4.0)):
        turned = (math.cos(angle) * slide[0] - math.sin(angle) * slide[1],
                  math.sin(angle) * slide[0] + math.cos(angle) * slide[1])  # fmt: skip
        np.testing.assert_allclose(motion.slide[k], turned, atol=1e-12)


def _valid_rows(time, state, lowest, depth):
    return _kept_rows(time, state, lowest, _first_invalid(state, lowest, depth))


def test_a_history_is_cut_before_a_state_below_the_support_or_not_finite():
    time = np.arange(5.0)
    state = np.tile(initial_state(BOX), (5, 1))
    lowest = np.array([0.0, -1e-7, -0.01, 0.0, 0.0])  # within the gap tolerance, then lost
    depth = lost_contact_depth(0.6, 1e-7)
    rows, message = _valid_rows(time, state, lowest, depth)
    assert rows == 2
    assert "0.01 m below the support at t = 2 s: the contact was lost" in message
    state[1, 4] = math.nan
    rows, message = _valid_rows(time, state, np.zeros(5), depth)
    assert rows == 1
    assert "stopped being finite at t = 1 s" in message
    assert _valid_rows(time, np.tile(initial_state(BOX), (5, 1)), np.zeros(5), depth) == (5, "")


def test_a_run_whose_buffers_fill_gives_the_run_in_one_call():
    """The engine returns where its output buffers are full and is called again on longer
    ones; the rows, the events (whose arrays grow with the calls) and the peaks must be
    those of one call."""
    body = Body("box", Box((1.0, 0.6, 2.0)), 400.0, Friction(0.5, 0.5))
    t = np.arange(0.0, 2.0001, 0.005)
    a = 4.0 * np.sin(2.0 * np.pi * 2.0 * t) * (t < 1.5)
    motion = SupportMotion3(0.005, 0.3 * a, a, 0.2 * a)
    par = body_parameters(body, 9.81)
    step = body_history.default_body_step(body)
    depth = lost_contact_depth(0.6, 1e-7)

    def run(rows):
        scratch, work = body_history.engine_work()
        return body_history._run_history(par, motion.array(), 0.005, step, 2.0, 2.0, 1e-7,
                                         1e-4, initial_state(body), scratch, work, depth, rows)  # fmt: skip

    whole, chunked = run(0), run(40)  # the record's capacity; 40 rows, doubled as they fill
    assert whole[1].size > 200 and whole[0][body_state.I_EVENTS] > 5  # chunked: several calls
    np.testing.assert_array_equal(chunked[0], whole[0])  # the counters
    for one, other in zip((chunked[1], chunked[2], *chunked[3], *chunked[4][2:-1]),
                          (whole[1], whole[2], *whole[3], *whole[4][2:-1]), strict=True):  # fmt: skip
        assert one.tobytes() == other.tobytes()
    assert chunked[4][:2] == whole[4][:2] and chunked[4][-1] == whole[4][-1]


def _moved(state, tau):
    """The state after ``tau`` [s] of its rigid motion at constant v and omega (support frame)."""
    moved = state.copy()
    moved[0:3] += tau * state[7:10]
    omega = state[10:13]
    angle = np.linalg.norm(omega) * tau
    axis = omega / np.linalg.norm(omega)
    c, s = math.cos(0.5 * angle), math.sin(0.5 * angle)
    a = np.array([c, *(s * axis)])
    w, x, y, z = state[3:7]
    moved[3:7] = (a[0] * w - a[1] * x - a[2] * y - a[3] * z,
                  a[0] * x + a[1] * w + a[2] * z - a[3] * y,
                  a[0] * y - a[1] * z + a[2] * w + a[3] * x,
                  a[0] * z + a[1] * y - a[2] * x + a[3] * w)  # fmt: skip
    return moved


@pytest.mark.parametrize("seed", range(6))
def test_the_rates_of_tilt_slide_and_twist_are_their_derivatives(seed):
    # body_history._row_rates (the peaks' Hermite refinement) against central
    # differences of body_motion along the state's rigid motion; tolerance 1e-6 of the
    # rate's scale (the difference's truncation at 1e-5 s is about 1e-9, round-off 1e-10)
    rng = np.random.default_rng(seed)
    body = (BOX, CASK)[seed % 2]
    state = initial_state(body, tuple(rng.uniform(-0.4, 0.4, 2)))
    state[3:7] = _yawed(state, rng.uniform(-3.0, 3.0))[3:7]
    state[7:13] = rng.normal(size=6)
    tau = 1e-5
    # the slide counts from the first row, 0.3 s of the rigid motion before (a curved path)
    states = np.array([state] + [_moved(state, 0.3 + k * tau) for k in (-1, 0, 1)])
    motion, rates = body_history._read_motion(body, states, True)
    sizes = np.hypot(motion.slide[:, 0], motion.slide[:, 1])
    assert sizes[2] > 0.01
    for values, rate in ((motion.tilt, rates[0]), (sizes, rates[1]), (motion.twist, rates[2])):
        difference = (values[3] - values[1]) / (2.0 * tau)
        assert rate[2] == pytest.approx(difference, abs=1e-6 * max(1.0, abs(difference)))


@settings(max_examples=300, deadline=None)
@given(st.floats(-1.0, 1.0), st.floats(-math.pi, math.pi), st.floats(-math.pi, math.pi),
       st.floats(0.01, 2.0), st.floats(0.01, 2.0))  # fmt: skip
def test_small_angles_and_twist_jumps_are_atan2s_to_round_off(tangent, half, turn, size, size0):
    # the history's series (|x| <= SMALL_ANGLE_TANGENT) against atan; the twist's change
    # between two states' (w, z) of any scale against atan2's difference, unwrapped (tolerances:
    # two ulps of the series' Horner sum; the difference's own round-off on angles up to 2 pi)
    x = tangent * body_history.SMALL_ANGLE_TANGENT
    assert body_history._atan_small(x) == pytest.approx(math.atan(x), rel=4e-16, abs=1e-300)
    w0, z0 = size0 * math.cos(half), size0 * math.sin(half)
    w, z = size * math.cos(half + turn / 2), size * math.sin(half + turn / 2)
    before, after = 2.0 * math.atan2(z0, w0), 2.0 * math.atan2(z, w)
    expected = np.unwrap([before, after])[1] - before
    assert body_history._twist_jump(w, z, w0, z0) == pytest.approx(expected, abs=4e-15)
    # the same rotation's other quaternion (-q) turns by no twist
    assert body_history._twist_jump(-w0, -z0, w0, z0) == pytest.approx(0.0, abs=4e-15)


def test_a_repeated_state_repeats_its_row():
    # a body at rest repeats its state: its row must equal the row computed alone (tilt,
    # slide, twist, base heights), before and after other states; equal to the last bit but
    # the twist (1e-12 rad: two histories' unwrapping)
    rng = np.random.default_rng(7)
    states = np.tile(initial_state(BOX), (6, 1))
    for i in (1, 4):
        quaternion = rng.normal(size=4)
        states[i, 3:7] = quaternion / np.linalg.norm(quaternion)
        states[i, :3] += rng.normal(size=3)
    states = states[[0, 1, 1, 1, 4, 4, 0]]  # runs of equal states
    together = body_motion(BOX, states)
    for i in range(states.shape[0]):
        alone = body_motion(BOX, states[[0, i]])  # the slide is from the first state
        assert together.tilt[i] == alone.tilt[1]
        np.testing.assert_array_equal(together.slide[i], alone.slide[1])
        assert together.lowest[i] == alone.lowest[1] and together.highest[i] == alone.highest[1]
        # the twist is unwrapped along the history: the same angle, to whole turns
        assert math.remainder(together.twist[i] - alone.twist[1], 2 * math.pi) == pytest.approx(
            0.0, abs=1e-12
        )


def _separate_rows(body, par, time, state, modes, forces, event_times, depth):
    """The result's rows and peaks as the front end computed them call by call before
    :func:`body_history._history_rows` did it in one, and its peaks in passes of
    :func:`peak_between_samples` before :func:`body_history._peaks` took them in one."""
    motion, rates = body_history._read_motion(body, state, True)
    first = _first_invalid(state, motion.lowest, depth)
    rows, _ = _kept_rows(time, state, motion.lowest, first)
    shown = int(np.count_nonzero(event_times <= time[rows - 1]))
    rates = np.ascontiguousarray(rates[:, :rows])
    # a row at an event holds the state after it: no step ending there is refined on its rates
    rates[:, np.isin(time[:rows], event_times[:shown])] = math.nan
    tilt, twist = motion.tilt[:rows], motion.twist[:rows]
    size = np.sqrt(motion.slide[:rows, 0] ** 2 + motion.slide[:rows, 1] ** 2)  # as norm2
    # the largest rows, and each quantity refined between its rows where its rate turns
    # (Python's max, as the compiled one's: a NaN after the first value is passed over)
    top = [reduce(max, values.tolist(), 0.0) for values in (tilt, size, np.abs(twist))]
    refined = [peak_between_samples(time[:rows], values, rate)
               for values, rate in zip((tilt, size, twist), rates, strict=True)]  # fmt: skip
    peaks = (*(max(a, b) for a, b in zip(top, refined, strict=True)),
             reduce(max, motion.highest[:rows].tolist(), -math.inf),
             float(np.any(modes[:rows, 0] == FREE)))  # fmt: skip
    return (first, shown, motion.lowest, motion.tilt[:rows], motion.slide[:rows],
            motion.twist[:rows], modes[:rows, 0].copy(), modes[:rows, 2] == 1,
            forces[:rows, 0].copy(), forces[:rows, 1].copy(), peaks)  # fmt: skip


@settings(max_examples=200, deadline=None)
@given(st.integers(0, 2**32 - 1), st.sampled_from([BOX, CASK]), st.integers(1, 40),
       st.sampled_from(["valid", "below", "not finite"]))  # fmt: skip
def test_the_history_s_rows_in_one_call_are_the_separate_calls_to_the_bit(seed, body, count, bad):
    # _history_rows (the body from its parameter vector) against _read_motion, _first_invalid,
    # _kept_rows and peak_between_samples on random states: tilted, turned, repeated, some
    # below the support or not finite; events at some rows and between them
    rng = np.random.default_rng(seed)
    state = np.tile(initial_state(body), (count, 1))
    quaternion = rng.normal(size=(count, 4)) * rng.choice([0.0, 1e-9, 0.05, 1.0], size=(count, 1))
    quaternion[:, 0] += 1.0
    state[:, 3:7] = quaternion / np.linalg.norm(quaternion, axis=1)[:, None]
    state[:, 0:3] += rng.normal(size=(count, 3)) * rng.choice([0.0, 1e-3], size=(count, 1))
    state[:, 7:13] = rng.normal(size=(count, 6))
    repeated = rng.random(count) < 0.3
    repeated[0] = False
    for i in np.flatnonzero(repeated):
        state[i] = state[i - 1]
    row = int(rng.integers(count))
    if bad == "below":
        state[row:, 2] -= 0.5
    elif bad == "not finite":
        state[row, int(rng.integers(13))] = rng.choice([math.nan, math.inf, -math.inf])
    time = np.cumsum(rng.choice([0.0, 0.01], size=count))
    modes = rng.integers(0, 4, size=(count, 3))
    forces = rng.normal(size=(count, 2))
    event_times = np.sort(np.concatenate([rng.choice(time, 3), rng.uniform(0.0, 0.5, 2)]))
    depth = lost_contact_depth(0.6, 1e-7)
    par = body_parameters(body, 9.81)
    together = body_history._history_rows(par, time, state, modes, forces, event_times, depth)
    separate = _separate_rows(body, par, time, state, modes, forces, event_times, depth)
    assert together[:2] == separate[:2]
    for one, other in zip(together[2:-1], separate[2:-1], strict=True):
        assert one.dtype == other.dtype
        assert one.tobytes() == other.tobytes()
    assert np.array(together[-1]).tobytes() == np.array(separate[-1]).tobytes()


def test_the_events_are_named_by_their_codes():
    events = (np.array([0.0, 0.5, 1.0]), np.array([0, 1, 3]), np.array([-1, FACE, 1]),
              np.array([FACE, 0, 2]))  # fmt: skip
    assert body_history._event_tuples(tuple(codes[:2] for codes in events)) == (
        (0.0, "start", "", "face"),
        (0.5, "impact", "face", "free"),
    )
    names = [body_history.PATCH_NAMES[code] for code in (FREE, POINT, EDGE, FACE)]
    assert names == ["free", "point", "edge", "face"]


def test_a_history_names_its_events_from_their_codes_where_first_read():
    # the result keeps the engine's event codes and names them on the first read of
    # ``events`` (a run whose events are not read does not pay for them): the same
    # events each read, one per code, the start first
    body = Body("box", Box((1.0, 0.6, 2.0)), 400.0, Friction(0.5, 0.5))
    t = np.arange(0.0, 2.0001, 0.005)
    a = 4.0 * np.sin(2.0 * np.pi * 2.0 * t) * (t < 1.5)
    result = body_history.simulate_body(body, SupportMotion3(0.005, 0.3 * a, a, 0.2 * a), 2.0)
    assert "events" not in vars(result)
    times, kinds, was, now = result.event_codes
    events = result.events
    assert events is result.events and len(events) == times.size > 5
    assert events[0][1:] == ("start", "", "face")
    for (time, kind, before, after), codes in zip(events, zip(times, kinds, was, now,
                                                               strict=True), strict=True):  # fmt: skip
        assert time == codes[0]
        assert kind == body_history.EVENT_KIND_NAMES[codes[1]]
        assert (before, after) == (body_history.PATCH_NAMES[codes[2]],
                                   body_history.PATCH_NAMES[codes[3]])  # fmt: skip


def test_a_motion_s_components_are_the_rows_of_its_record():
    x, y = np.array([0.0, 1.0, -2.0]), np.array([0.5, 0.0, 3.0])
    motion = SupportMotion3(0.01, x, y)
    record = motion.array()
    assert record is motion.array()  # kept, not stacked again for each run
    assert record.shape == (3, 3) and record.flags["C_CONTIGUOUS"]
    assert np.array_equal(record, [x, y, [0.0, 0.0, 0.0]])
    for row, component in enumerate((motion.x, motion.y, motion.vertical)):
        assert np.shares_memory(component, record) and np.array_equal(component, record[row])
    x[1] = 99.0  # the caller's array is copied: the motion does not change with it
    assert motion.x[1] == 1.0


def _motion_by_numpy(body, states):
    """body_motion's tilt, slide, twist and base heights, and its rates, state by state in
    numpy: rotation matrices, atan2 and numpy.unwrap (an independent reading)."""
    rot = body_history.rotation_matrices(states[:, 3:7])
    axis = rot[:, :, 2]  # R e_z
    tilt = np.arctan2(np.hypot(axis[:, 0], axis[:, 1]), axis[:, 2])
    arm = rot @ np.asarray(body.centre)  # R c
    base = states[:, 0:3] - arm
    slide = base[:, :2] - base[0, :2]
    twist = np.unwrap(2.0 * np.arctan2(states[:, 6], states[:, 3]))
    twist -= twist[0]
    if isinstance(body.shape, Box):
        corners = np.einsum("kij,pj->kpi", rot, body.shape.base_corners())[:, :, 2]
        heights = corners + base[:, 2:3]
        lowest, highest = heights.min(axis=1), heights.max(axis=1)
    else:
        reach = body.shape.radius * np.hypot(axis[:, 0], axis[:, 1])
        lowest, highest = base[:, 2] - reach, base[:, 2] + reach
    omega, velocity = states[:, 10:13], states[:, 7:10]
    tilt_rate = -np.cross(omega, axis)[:, 2] / np.hypot(axis[:, 0], axis[:, 1])
    base_velocity = velocity - np.cross(omega, arm)
    with np.errstate(invalid="ignore"):  # the first state has no slide: its rate is not compared
        slide_rate = np.einsum("ki,ki->k", slide, base_velocity[:, :2]) / np.hypot(*slide.T)
    w, x, y, z = states[:, 3:7].T
    w_rate = -0.5 * (omega[:, 0] * x + omega[:, 1] * y + omega[:, 2] * z)
    z_rate = 0.5 * (w * omega[:, 2] + omega[:, 0] * y - omega[:, 1] * x)
    twist_rate = 2.0 * (w * z_rate - z * w_rate) / (w * w + z * z)
    return (tilt, slide, twist, lowest, highest), np.array([tilt_rate, slide_rate, twist_rate])


@pytest.mark.parametrize("seed", range(8))
def test_the_motion_read_in_columns_is_the_motion_state_by_state(seed):
    # body_history._motion_rows reads the states in vectorised passes over their columns;
    # against numpy state by state (random tilts up to 1.2 rad, yaws, velocities, runs of
    # repeated states); tolerance 1e-12 (round-off of the two readings' arithmetic)
    rng = np.random.default_rng(seed)
    body = (BOX, CASK)[seed % 2]
    count = 40
    states = np.empty((count, 13))
    for i in range(count):
        state = initial_state(body, tuple(rng.uniform(-0.85, 0.85, 2)))
        state[3:7] = _yawed(state, rng.uniform(-3.0, 3.0) + 0.3 * i)[3:7]
        state[0:3] += rng.normal(size=3)
        state[7:13] = rng.normal(size=6)
        states[i] = state
    states[[5, 6, 20]] = states[[4, 4, 19]]  # repeated states
    motion, rates = body_history._read_motion(body, states, True)
    expected, expected_rates = _motion_by_numpy(body, states)
    got = (motion.tilt, motion.slide, motion.twist, motion.lowest, motion.highest)
    for value, reference in zip(got, expected, strict=True):
        np.testing.assert_allclose(value, reference, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(rates[:, 1:], expected_rates[:, 1:], rtol=1e-10, atol=1e-12)
