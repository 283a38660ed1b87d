"""The 3-D engine's event search starts on the step's cubic interpolant (#18).

``locate`` brackets an event on true RK4 states from the step's start. Its
first trials are seeded: the crossing is found on the step's cubic Hermite
interpolant (a solve per trial, or none for a gap), tried on RK4 states, and
Newton steps from there are tried half a tolerance to each side (a gap's,
a landing's or the tilt's second just past the crossing, where the state a
``BACK_STEP`` before it may close the bracket). These tests check the
interpolant (exact for a cubic), its crossing (exact for a free fall, whose
gaps are quadratic in time), the seeds, the back step's state, that a
spinning fall's landing (no cubic: the seeds only near it) is still the
crossing on RK4 states, and that a rocking box's impacts are located in
about one RK4 trial each where the regula falsi alone took nine. A box
corner's crossing on the interpolant is found by Newton's method there, and
a seeded trial within ``EXTRAPOLATION_TIME`` of the last is that trial's
state moved by its rate: both are checked against the searches they stand
for (bisection on the interpolant, the RK4 state).
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from freestand.core.body import Body, Box
from freestand.core.contact import body_kernel as bk
from freestand.core.contact import body_solve
from freestand.core.dynamics import body_events as events
from freestand.core.dynamics import body_step as step
from freestand.core.dynamics.body_history import SupportMotion3, initial_state, simulate_body
from freestand.core.model import Friction

G = 9.81
BOX = Body("box", Box((1.0, 0.6, 2.0)), 400.0, Friction(0.5, 0.5))


@settings(max_examples=50, deadline=None)
@given(
    st.lists(st.floats(-2.0, 2.0), min_size=4, max_size=4),
    st.floats(1e-4, 1e-2), st.floats(0.0, 1.0),
)  # fmt: skip
def test_the_interpolant_is_exact_for_a_cubic_and_meets_the_ends(coefficients, h, s):
    # each translational component of the state a cubic in time, r = a + b t + c t^2 + d t^3,
    # its velocity r' (the state's rate), and the velocity's rate r''; the quaternion at rest
    a, b, c, d = coefficients

    def state(t):
        y = np.zeros(bk.STATE_SIZE)
        y[3] = 1.0
        y[0:3] = a + b * t + c * t**2 + d * t**3
        y[7:10] = b + 2 * c * t + 3 * d * t**2
        return y

    def rate(t):
        ydot = np.zeros(bk.STATE_SIZE)
        ydot[0:3] = b + 2 * c * t + 3 * d * t**2
        ydot[7:10] = 2 * c + 6 * d * t
        return ydot

    out = np.zeros(bk.STATE_SIZE)
    events._hermite_state(h, s * h, state(0.0), rate(0.0), state(h), rate(h), out)
    # tolerance: round-off of the cubic's terms
    np.testing.assert_allclose(out, state(s * h), rtol=1e-12, atol=1e-12)


def _spinning_fall(tilt, azimuth, speed, spin):
    """The box tilted, its lowest corner 1 mm up, falling at ``speed`` and spinning at
    ``spin`` (3,) [rad/s]; the kernel's work arrays, the start's rate in ``k[0]``."""
    par = bk.body_parameters(BOX, G)
    y = initial_state(BOX, (tilt * math.cos(azimuth), tilt * math.sin(azimuth)))
    y[2] += 1e-3
    y[9] = -speed
    y[10:13] = spin
    fall = SimpleNamespace(
        par=par, y=y, record=np.zeros((3, 2)), mode=np.array([bk.FREE, 0, 0], dtype=np.int64),
        data=np.zeros(bk.DATA_SIZE), sc=bk.new_scratch(), ref=np.zeros(step.REF_SIZE),
        values=np.zeros(step.MAX_EVENT_FUNCTIONS),
        kinds=np.zeros(step.MAX_EVENT_FUNCTIONS, dtype=np.int64), k=np.zeros((5, bk.STATE_SIZE)),
    )  # fmt: skip
    fall.count = step.event_functions(par, fall.record, 1.0, 0.0, y, fall.mode, fall.data,
                                      fall.sc, fall.ref, fall.values, fall.kinds)  # fmt: skip
    body_solve.state_rate(y, fall.sc[bk.SC_ACC], fall.k[0])
    return fall


def _falling(tilt, speed):
    """:func:`_spinning_fall` tilted about x, not spinning, with the landing's time [s]."""
    fall = _spinning_fall(tilt, 0.0, speed, (0.0, 0.0, 0.0))
    fall.landing = (-speed + math.sqrt(speed**2 + 2.0 * G * 1e-3)) / G  # 1 mm = v t + g t^2 / 2
    return fall


@settings(max_examples=30, deadline=None)
@given(st.floats(0.01, 0.3), st.floats(0.0, 0.5), st.floats(0.3, 1.0))
def test_a_free_fall_s_landing_is_found_on_the_interpolant(tilt, speed, fraction):
    """A body in free flight with no spin falls as a point: its corners' gaps are quadratic
    in time, the interpolant's gap is exact and so its crossing is the landing itself."""
    fall = _falling(tilt, speed)
    par, y, record, mode, data, sc = fall.par, fall.y, fall.record, fall.mode, fall.data, fall.sc
    ref, values, kinds, k, count = fall.ref, fall.values, fall.kinds, fall.k, fall.count
    landing = fall.landing
    h = landing / fraction  # the step ends at or past the landing
    start = values[:count].copy()
    end = np.zeros(bk.STATE_SIZE)
    step._rk4(par, record, 1.0, 0.0, h, y, mode, data, sc, k, end)
    step.event_functions(par, record, 1.0, h, end, mode, data, sc, ref, values, kinds)
    body_solve.state_rate(end, sc[bk.SC_ACC], k[1])
    target = int(np.argmin(values[:count]))  # a lowest corner
    assert kinds[target] == step.FN_GAP
    trial = np.zeros(bk.STATE_SIZE)
    crossing, fall = events.interpolated_crossing(
        par, record, 1.0, 0.0, h, y, end, mode, data, sc, k, ref, values, kinds,
        0.0, target, start[target], values[target], trial,
    )  # fmt: skip
    # tolerance: the search's bracket (1e-10 s); the gap starts 1 mm up, above GAP_SLACK, and
    # its level is zero (events._levels)
    assert abs(crossing - landing) <= events.INTERPOLANT_TIME
    # its rate of fall: the corner's speed at the landing; the secant of the last two trials
    # (within 2e-4 here, on a search's last steps), which a seed needs to 1e-2 or so
    assert fall == pytest.approx(speed + G * landing, rel=1e-3)


def test_a_seed_lies_just_past_the_newton_estimate_or_is_refused():
    # the function falls at 2 per second; at 1.0 it is 0.002 above its level: the crossing at
    # 1.001, tried 0.45 EVENT_TIME past it (from the last trial's side; to round-off)
    nan = math.nan
    x = events._seeded_trial(1.0, 0.002, nan, 0.0, 2.0, 0.0, 2.0, False)
    assert x == pytest.approx(1.001 + events.SEED_OFFSET * events.EVENT_TIME, abs=1e-15)
    # from the other side (the function below its level: fired), before the crossing
    x = events._seeded_trial(1.002, -0.002, nan, 0.0, 2.0, 0.0, 2.0, False)
    assert x == pytest.approx(1.001 - events.SEED_OFFSET * events.EVENT_TIME, abs=1e-15)
    # ... or past it, where the back step may close the bracket from there (past_first)
    x = events._seeded_trial(1.002, -0.002, nan, 0.0, 2.0, 0.0, 2.0, True)
    assert x == pytest.approx(1.001 + events.SEED_OFFSET * events.EVENT_TIME, abs=1e-15)
    # the secant of the last two trials replaces the interpolant's rate: 4 per second here
    x = events._seeded_trial(1.0, 0.004, 0.999, 0.008, 2.0, 0.0, 2.0, False)
    assert x == pytest.approx(1.001 + events.SEED_OFFSET * events.EVENT_TIME, abs=1e-15)
    # no rate, or a trial outside the bracket: no seed
    assert math.isnan(events._seeded_trial(1.0, 0.002, nan, 0.0, nan, 0.0, 2.0, False))
    assert math.isnan(events._seeded_trial(1.0, 0.002, nan, 0.0, 2.0, 0.0, 1.0005, False))


@settings(max_examples=30, deadline=None)
@given(st.floats(0.01, 0.3), st.floats(0.0, 0.5), st.floats(0.1, 0.8))
def test_the_back_step_brackets_a_landing_from_just_past_it(tilt, speed, fraction):
    """A free fall's landing (its time known): from an RK4 state a fraction of BACK_STEP past
    it the back step finds the state before it clear, and from one more than BACK_STEP past
    it not; the scratch's rotation and the functions' values are left as at the trial."""
    fall = _falling(tilt, speed)
    par, y, record, mode, data, sc = fall.par, fall.y, fall.record, fall.mode, fall.data, fall.sc
    ref, values, kinds, k, count = fall.ref, fall.values, fall.kinds, fall.k, fall.count
    landing = fall.landing
    levels = np.zeros(step.MAX_EVENT_FUNCTIONS)  # every gap starts 1 mm up: its level is zero
    out = np.zeros(bk.STATE_SIZE)
    results = []
    for past in (fraction * events.BACK_STEP, 1.2 * events.BACK_STEP):
        step._rk4(par, record, 1.0, 0.0, landing + past, y, mode, data, sc, k, out)
        step.event_functions(par, record, 1.0, landing + past, out, mode, data, sc, ref, values,
                             kinds)  # fmt: skip
        target = int(np.argmin(values[:count]))
        assume(values[target] < 0.0)  # fired at the trial (the RK4 state's own round-off)
        kept_values, kept_rot = values.copy(), sc[bk.SC_ROT].copy()
        results.append(events._clear_before(par, out, mode, sc, ref, count, values, kinds,
                                            levels, k[3], k[4]))  # fmt: skip
        np.testing.assert_array_equal(values, kept_values)
        np.testing.assert_array_equal(sc[bk.SC_ROT], kept_rot)
    # tolerance: the landing's time from the closed form, to round-off (some 1e-17 s) of the
    # 1e-11 s windows
    assert results == [True, False]


def test_a_rocking_box_s_impacts_take_about_one_rk4_trial_each():
    """Released from a tilt, the box rocks about its base edges, each half-cycle ending in
    an impact located on RK4 states: 12 impacts in 6 s. The seeded search with the back step
    takes 14 RK4 trials for them (the second trial of most extrapolated from the first), 22
    before the extrapolation, without the back step 36 and the regula falsi alone 52 (and
    8.97 per event of a rocking cabinet under a record, the seeded search 3.1, with the back
    step 2.3, with the corner's Newton seed 2.0 and with the extrapolation 1.4, slip-stops
    included, which are not seeded)."""
    motion = SupportMotion3(0.01, np.zeros(601), np.zeros(601), np.zeros(601))
    result = simulate_body(BOX, motion, 6.0, initial=initial_state(BOX, (0.25, 0.0)))
    assert result.status == "completed"
    impacts = [event for event in result.events if event[1] == "impact"]
    assert len(impacts) >= 10  # the rocking's impacts before it settles
    located = sum(1 for event in result.events if event[1] != "start")
    # tolerance: 1.5 RK4 trials per located event on average (the back step closes most
    # after 2 trials, the second extrapolated from the first)
    assert result.diagnostics["event_trials"] <= 1.5 * located


def test_a_sliding_plate_s_stops_take_about_one_rk4_trial_each():
    """A squat plate (1 x 1 x 0.4 m, mu 0.4) under 0.45 g at 1 Hz along x and 0.2 g at 1.3 Hz
    along y slips and sticks again eight times in 4 s. A slip-stop is not seeded (the
    friction's direction has kinks within its step): the regula falsi brackets it, and its
    last trials, which close the bracket to EVENT_TIME within 1e-9 s of each other, are
    extrapolated from the trial before (one solve each, no RK4 step): 12 RK4 trials for
    its 16 events, 26 before."""
    t = np.arange(0.0, 4.0 + 1e-9, 0.005)
    x = 0.45 * G * np.sin(2.0 * math.pi * t)
    y = 0.2 * G * np.sin(2.0 * math.pi * 1.3 * t + 0.5)
    plate = Body("plate", Box((1.0, 1.0, 0.4)), 500.0, Friction(0.4, 0.4))
    result = simulate_body(plate, SupportMotion3(0.005, x, y, np.zeros_like(t)), 4.0)
    assert result.status == "completed"
    kinds = [event[1] for event in result.events]
    assert kinds.count("stick") >= 6 and kinds.count("slip") >= 6
    located = sum(1 for kind in kinds if kind != "start")
    # tolerance: 1.2 RK4 trials per located event on average (the slips are seeded and take
    # one; the stops two or three, 1.75 per event before the extrapolation)
    assert result.diagnostics["event_trials"] <= 1.2 * located


def _lowest_gap(par, y):
    """The lowest base corner's gap [m] of the box at state y."""
    rot = np.zeros((3, 3))
    bk.rotation_matrix(y, rot)
    d = np.zeros(3)
    return min(bk.corner_gap(par, y, rot, c, d)[0] for c in range(4))


@settings(max_examples=25, deadline=None)
@given(
    st.floats(0.02, 0.3), st.floats(-3.0, 3.0), st.floats(0.0, 0.5),
    st.lists(st.floats(-1.0, 1.0), min_size=3, max_size=3), st.floats(1.05, 2.0),
)  # fmt: skip
def test_a_spinning_fall_s_landing_is_the_crossing_on_rk4_states(
    tilt, azimuth, speed, spin, overshoot
):
    """A box falling and spinning in free flight: its corners' gaps are no cubic in time, the
    interpolant's crossing is only near the landing, and the seeds and the regula falsi must
    still end on the crossing on RK4 states from the step's start (found here by bisection
    on them) to the event's tolerance."""
    par = bk.body_parameters(BOX, G)
    y = initial_state(BOX, (tilt * math.cos(azimuth), tilt * math.sin(azimuth)))
    y[2] += 1e-3
    y[9] = -speed
    y[10:13] = spin
    record = np.zeros((3, 2))
    mode = np.array([bk.FREE, 0, 0], dtype=np.int64)
    data = np.zeros(bk.DATA_SIZE)
    sc = bk.new_scratch()
    k = np.zeros((5, bk.STATE_SIZE))
    state = np.zeros(bk.STATE_SIZE)

    def gap(tau):  # the lowest corner's gap on the RK4 state at tau (k[0]: the start's rate)
        step._rk4(par, record, 1.0, 0.0, tau, y, mode, data, sc, k, state)
        return _lowest_gap(par, state)  # fires at zero: it starts above GAP_SLACK

    ref, values = np.zeros(step.REF_SIZE), np.zeros(step.MAX_EVENT_FUNCTIONS)
    kinds = np.zeros(step.MAX_EVENT_FUNCTIONS, dtype=np.int64)
    count = step.event_functions(par, record, 1.0, 0.0, y, mode, data, sc, ref, values, kinds)
    start = values.copy()
    body_solve.state_rate(y, sc[bk.SC_ACC], k[0])
    # the first crossing: scanned, then bisected on RK4 states
    taus = np.linspace(0.0, 0.3, 2001)
    first = next(i for i, tau in enumerate(taus) if gap(tau) < 0.0)
    low, high = taus[first - 1], taus[first]
    for _ in range(80):
        middle = 0.5 * (low + high)
        low, high = (middle, high) if gap(middle) >= 0.0 else (low, middle)
    h = min(overshoot * high, taus[first])  # the step ends past the landing, before another
    assume(gap(h) < 0.0)
    out = np.zeros(bk.STATE_SIZE)
    step._rk4(par, record, 1.0, 0.0, h, y, mode, data, sc, k, out)
    located, kind, trials = events.locate(
        par, record, 1.0, 0.0, h, y, mode, data, sc, k, ref, start, count,
        np.zeros(bk.STATE_SIZE), np.zeros(step.MAX_EVENT_FUNCTIONS), kinds,
        np.zeros((3, step.MAX_EVENT_FUNCTIONS)), out,
    )  # fmt: skip
    assert kind == step.FN_GAP
    # a crossing on RK4 states to the event's tolerance: fired at it (or a trial exactly on
    # the level, zero, which ends the search), not a tolerance before, and within a tolerance
    # after the first crossing the scan found (bisected to 1e-15 s)
    assert gap(located) <= 0.0 <= gap(located - events.EVENT_TIME)
    assert located <= high + events.EVENT_TIME
    assert 1 <= trials <= 12  # the seeds close most in 3; the regula falsi needs about 8


@settings(max_examples=40, deadline=None)
@given(
    st.floats(0.02, 0.3), st.floats(-3.0, 3.0), st.floats(0.0, 0.5),
    st.lists(st.floats(-2.0, 2.0), min_size=3, max_size=3), st.floats(1e-3, 2e-2),
)  # fmt: skip
def test_a_corner_s_crossing_on_the_interpolant_is_found_by_newton_s_method(
    tilt, azimuth, speed, spin, h
):
    """A spinning fall's step (its gaps no cubic in time): for each corner whose gap falls
    below zero within the step, Newton's method on the interpolant (_corner_crossing) ends
    on the interpolant's crossing, found here by bisection, and gives the gap's rate of fall
    there."""
    fall = _spinning_fall(tilt, azimuth, speed, spin)
    par, y, record, mode, data, sc = fall.par, fall.y, fall.record, fall.mode, fall.data, fall.sc
    ref, values, kinds, k, count = fall.ref, fall.values, fall.kinds, fall.k, fall.count
    start = values[:count].copy()
    end = np.zeros(bk.STATE_SIZE)
    step._rk4(par, record, 1.0, 0.0, h, y, mode, data, sc, k, end)
    step.event_functions(par, record, 1.0, h, end, mode, data, sc, ref, values, kinds)
    body_solve.state_rate(end, sc[bk.SC_ACC], k[1])
    trial, state, rot, d = (np.zeros(bk.STATE_SIZE), np.zeros(bk.STATE_SIZE), np.zeros((3, 3)),
                            np.zeros(3))  # fmt: skip
    crossed = [i for i in range(count) if kinds[i] == step.FN_GAP and values[i] < 0.0]
    assume(crossed)
    for target in crossed:
        corner = events._gap_corner(par, mode, kinds, target)
        assert corner == target  # a free box's functions: its four corners' gaps first

        def gap(tau, corner=corner):  # on the interpolant
            events._hermite_state(h, tau, y, k[0], end, k[1], state)
            bk.rotation_matrix(state, rot)
            return bk.corner_gap(par, state, rot, corner, d)

        crossing, fall_rate = events._corner_crossing(par, h, y, end, sc, k, corner, 0.0,
                                                      start[target], values[target], trial)  # fmt: skip
        # the interpolant's gap may cross more than once: the crossing found is one of them,
        # bracketed here by bisection from a scan around it
        low, high = crossing - 1e-9, crossing + 1e-9
        assume(0.0 < low and high < h and gap(low)[0] > 0.0 > gap(high)[0])
        for _ in range(60):
            middle = 0.5 * (low + high)
            low, high = (middle, high) if gap(middle)[0] >= 0.0 else (low, middle)
        # tolerance: the search's (INTERPOLANT_TIME, 1e-10 s), and the bisection's (1e-27 s)
        assert abs(crossing - low) <= events.INTERPOLANT_TIME
        # the rate of fall: the corner's velocity on the interpolant at the last trial
        assert fall_rate == pytest.approx(-gap(crossing)[1], rel=1e-6)


@settings(max_examples=40, deadline=None)
@given(
    st.floats(0.02, 0.3), st.floats(-3.0, 3.0), st.floats(0.0, 0.5),
    st.lists(st.floats(-3.0, 3.0), min_size=3, max_size=3), st.floats(1e-4, 2e-2),
    st.floats(-1.0, 1.0),
)  # fmt: skip
def test_a_trial_extrapolated_within_its_window_is_the_rk4_state_there(
    tilt, azimuth, speed, spin, tau, share
):
    """A trial moved from the last one by its rate (_extrapolated) within
    EXTRAPOLATION_TIME: the RK4 state at that time from the step's start, but for a small
    part (5 delta / tau) of the RK4 step's own truncation error and delta^2 y'' / 2."""
    fall = _spinning_fall(tilt, azimuth, speed, spin)
    par, y, record, mode, data, sc = fall.par, fall.y, fall.record, fall.mode, fall.data, fall.sc
    ref, values, kinds, k = fall.ref, fall.values, fall.kinds, fall.k
    tau = min(tau, step.turn_step(y))  # the engine's steps turn the body by TURN_ANGLE at most
    delta = share * events.EXTRAPOLATION_TIME
    last, there = np.zeros(bk.STATE_SIZE), np.zeros(bk.STATE_SIZE)
    middle, halves, rates = np.zeros(bk.STATE_SIZE), np.zeros(bk.STATE_SIZE), k.copy()
    # the RK4 step's truncation error at tau, by step doubling (two steps of tau / 2)
    step._rk4(par, record, 1.0, 0.0, 0.5 * tau, y, mode, data, sc, rates, middle)
    step.event_functions(par, record, 1.0, 0.5 * tau, middle, mode, data, sc, ref, values, kinds)
    body_solve.state_rate(middle, sc[bk.SC_ACC], rates[0])
    step._rk4(par, record, 1.0, 0.5 * tau, 0.5 * tau, middle, mode, data, sc, rates, halves)
    step._rk4(par, record, 1.0, 0.0, tau, y, mode, data, sc, k, last)
    truncation = np.max(np.abs(last - halves))  # 15/16 of the step's error, to leading order
    step.event_functions(par, record, 1.0, tau, last, mode, data, sc, ref, values, kinds)
    events._extrapolated(last, sc[bk.SC_ACC], delta, k[2])
    step._rk4(par, record, 1.0, 0.0, tau + delta, y, mode, data, sc, k, there)
    # tolerance: the two differ by delta times the growth of RK4's truncation error with its
    # step, 5 (delta / tau) of it to leading order (twice that allowed), and by
    # delta^2 y'' / 2 with round-off (1e-14: y'' up to 100 here)
    limit = 10.0 * abs(delta) / tau * truncation + 1e-14
    np.testing.assert_allclose(last, there, rtol=0.0, atol=limit)
    # which, within the turn's bound, is a small part of the state's change within the
    # event's tolerance (1e-11 s)
    assert limit < 1e-3 * events.EVENT_TIME * np.max(np.abs(k[0])) + 1e-14
