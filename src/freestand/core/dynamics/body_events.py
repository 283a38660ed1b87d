"""The 3-D engine's ``locate`` phase: the earliest event within a step, to ``EVENT_TIME``.

The event functions at the step's end against its start
(:mod:`freestand.core.dynamics.body_step`); where one changed sign, its
crossing by Anderson and Bjorck's variant of regula falsi on RK4 states from
the step's start (:func:`locate`), its first trials seeded by the crossing on
the step's cubic Hermite interpolant (:func:`interpolated_crossing`; a box
corner's gap by Newton's method there, :func:`_corner_crossing`) and by
Newton steps just past it (:func:`_seeded_trial`), any trial within
``EXTRAPOLATION_TIME`` of the last one that trial's state moved by its rate
(:func:`_extrapolated`), a bracket closed from a trial just past a
gap's crossing by the state just before it (:func:`_clear_before`). The
loop that calls it is :func:`freestand.core.dynamics.body_engine.run`.
"""

from __future__ import annotations

import math

from freestand.core.contact.body_kernel import (
    FREE,
    M_KIND,
    P_GRAVITY,
    P_MASS,
    P_SHAPE,
    SC_ACC,
    SC_PROBE,
    SC_ROT,
    SHAPE_BOX,
    STATE_SIZE,
    corner_gap,
    rotation_matrix,
    row_counts,
)
from freestand.core.contact.body_modes import RELATIVE_TOLERANCE
from freestand.core.contact.body_solve import state_rate
from freestand.core.contact.compiled import kernel
from freestand.core.contact.regula_falsi import narrowed
from freestand.core.dynamics.body_step import (
    FN_FRICTION,
    FN_GAP,
    FN_LANDING,
    FN_NORMAL,
    FN_SLIP_STOP,
    FN_TILT,
    _normalise,
    _rk4,
    corner_held,
    event_functions,
    event_values,
)

EVENT_TIME = 1e-11  # [s] width of the bracket of a located event
GAP_SLACK = 1e-12  # [m] a released point may sit this far below the support
LANDING_SLACK = 1e-12  # [-] a landed cylinder's lean may sit this far past its pivot's side
INTERPOLANT_TRIALS = 40  # most trials of an event's search on the step's cubic interpolant
INTERPOLANT_TIME = 1e-10  # [s] width of its bracket that ends that search
SEED_TRIALS = 4  # most seeded trials of an event's search on RK4 states (locate)
SEED_OFFSET = 0.45  # a seeded trial lies this part of EVENT_TIME beyond its estimated crossing
#: [s] a trial this close to the last one and to the last RK4 trial is the last trial's
#: state moved by its rate (:func:`_extrapolated`), not an RK4 step from the step's start
EXTRAPOLATION_TIME = 1e-8
#: [s] the state this far before a trial past a gap's, a landing's or the tilt's crossing
#: closes the bracket where no function has fired there (:func:`_clear_before`)
BACK_STEP = 0.9 * EVENT_TIME
MARGIN_SLACK = RELATIVE_TOLERANCE  # a force margin fires this part of m g below zero (as modes)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _levels(par, n, start_values, kinds, levels):
    """Level below which each event function fires; NaN for a function that cannot fire.

    A force margin fires when it falls below ``-slack`` having started above
    it, the slack being the admissibility tolerance (a mode is chosen within
    it); the tilt function likewise with no slack. A gap that starts the
    step more than ``GAP_SLACK`` above the support fires at zero: the impact
    is located where the point touches, as the planar engine's single-block
    integrator locates it (1e-12 m below it delayed an impact by 1e-12 m
    over the approach speed, 1e-9 s for a box rocking at 1e-3 rad/s, and a
    sequence of such impacts multiplied that by hundreds). Otherwise it fires
    ``GAP_SLACK`` below the lower of zero and its start: a point released at
    an event may sit the held rows' drift (some 1e-11 m) below the support,
    and it must still be caught when it comes back down. The landing
    function likewise, with ``LANDING_SLACK``: a cylinder that has just
    landed leans by round-off, to either side of its new pivot, and may rock
    back within the step (a decaying sequence of landings), or within
    ``PIVOT_LEAN`` of flat tilt away from the pivot it keeps there.
    """
    for i in range(n):
        if kinds[i] == FN_GAP:
            levels[i] = _touch_level(start_values[i], GAP_SLACK)
            continue
        if kinds[i] == FN_LANDING:
            levels[i] = _touch_level(start_values[i], LANDING_SLACK)
            continue
        slack = 0.0
        if kinds[i] == FN_NORMAL or kinds[i] == FN_FRICTION:
            slack = MARGIN_SLACK * par[P_MASS] * par[P_GRAVITY]
        levels[i] = -slack if start_values[i] >= -slack else math.nan
    return n


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _touch_level(start, slack):
    """A gap's or landing's level: zero where it starts above ``slack``, else that below the
    lower of zero and its start (:func:`_levels`)."""
    return 0.0 if start > slack else min(start, 0.0) - slack


@kernel(cache=True, error_model="numpy", _nrt=False)
def inconsistent_start(par, n, start_values, kinds):
    """Index of a force margin already below its level at the step's start, or -1.

    The held mode was chosen admissible (:func:`~freestand.core.contact.body_modes.select_mode`,
    within the same slack), so its margins start above their levels, and
    :func:`_levels` gives a margin that starts below none: it could not
    fire. Where the mode's solve at its own start differs from the one that
    chose it, a margin starts below (a slender box, 0.2 x 0.52 x 5.6 m, mu
    0.92, landed on its edge: N = +11 N at the selection, -3.9 kN at the
    step's start, and the body then sank through the support; there the
    selection's slip law had pulled the friction towards another stored
    direction than the step's, which ``body_modes._restore_own_slip`` now
    prevents). Such a mode must not be held (the engine's remedy takes over).
    """
    slack = MARGIN_SLACK * par[P_MASS] * par[P_GRAVITY]
    for i in range(n):
        if (kinds[i] == FN_NORMAL or kinds[i] == FN_FRICTION) and start_values[i] < -slack:
            return i
    return -1


@kernel(cache=True, error_model="numpy", _nrt=False)
def _fired(n, values, levels, prefer):
    """Index of an event function below its level (``prefer`` if it is one), or -1."""
    if prefer >= 0 and values[prefer] < levels[prefer]:
        return prefer
    for i in range(n):
        if values[i] < levels[i]:
            return i
    return -1


@kernel(cache=True, error_model="numpy", _nrt=False)
def _trial_time(low, high, g_low, g_high):
    """Next trial [s] of the search: the secant root, kept half a tolerance inside."""
    if g_low > 0.0 and g_high < 0.0:
        x = low + g_low * (high - low) / (g_low - g_high)
    else:
        x = 0.5 * (low + high)
    return min(max(x, low + 0.5 * EVENT_TIME), high - 0.5 * EVENT_TIME)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _hermite_state(h, tau, y, rate_start, end, rate_end, out):
    """The step's cubic Hermite interpolant at t + tau in ``out`` (its quaternion normalised).

    ``y(t + s h) = h00 y_0 + h10 h y'_0 + h01 y_1 + h11 h y'_1`` with
    ``h00 = 2 s^3 - 3 s^2 + 1``, ``h10 = s^3 - 2 s^2 + s``, ``h01 = 3 s^2 - 2 s^3``,
    ``h11 = s^3 - s^2`` (Hairer, Norsett and Wanner, Solving ODEs I, 1993,
    II.6: the dense output of order 3 of a one-step method from its ends).
    """
    s = tau / h
    s2 = s * s
    s3 = s2 * s
    a = 2.0 * s3 - 3.0 * s2 + 1.0
    b = (s3 - 2.0 * s2 + s) * h
    c = 3.0 * s2 - 2.0 * s3
    d = (s3 - s2) * h
    for i in range(STATE_SIZE):
        out[i] = a * y[i] + b * rate_start[i] + c * end[i] + d * rate_end[i]
    _normalise(out)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _function_value(par, record, dt, t, y, mode, data, sc, ref, values, kinds, target):
    """The event function ``target`` at (t, y).

    A gap, a landing or the tilt depends on the state alone: it is taken
    without a solve (the other entries of ``values`` are then the last
    solve's and are not read). A force margin or a slip is solved for.
    """
    kind = kinds[target]
    if kind == FN_GAP or kind == FN_LANDING or kind == FN_TILT:
        rotation_matrix(y, sc[SC_ROT])
        n_normal, n_tangent = row_counts(mode[M_KIND])
        event_values(par, y, mode, sc, ref, n_normal, n_tangent, values, kinds)
    else:
        event_functions(par, record, dt, t, y, mode, data, sc, ref, values, kinds)
    return values[target]


@kernel(cache=True, error_model="numpy", _nrt=False)
def interpolated_crossing(par, record, dt, t, h, y, end, mode, data, sc, k, ref, values, kinds,
                          level, target, g_start, g_end, trial):  # fmt: skip
    """The crossing of event function ``target`` on the step's cubic interpolant.

    The search of :func:`locate` (Anderson and Bjorck's regula falsi) on
    the function at :func:`_hermite_state`'s states (``k[0]`` and ``k[1]``
    the rates at the step's ends), to ``INTERPOLANT_TIME`` (a box corner's
    gap by Newton's method, :func:`_corner_crossing`): one solve per
    trial for a force margin, none for a gap, a landing or the tilt, where
    a trial on true RK4 states costs four. ``g_start`` and ``g_end`` are the
    function less its ``level`` at the step's ends (positive, negative).
    Returns the crossing's time from t [s] and the function's rate of fall
    there [units/s] (the secant of the last two trials; positive, or NaN
    where the search found none). The interpolant is of third order where
    RK4 is of fourth: its crossing starts the search on RK4 states, it is
    not the event.
    """
    corner = _gap_corner(par, mode, kinds, target)
    if corner >= 0:
        return _corner_crossing(par, h, y, end, sc, k, corner, level, g_start, g_end, trial)
    low = 0.0
    high = h
    g_low = g_start
    g_high = g_end
    last, g_last = h, g_end  # the last two trials, for the rate
    previous, g_previous = 0.0, g_start
    side = 0
    for _ in range(INTERPOLANT_TRIALS):
        if high - low <= INTERPOLANT_TIME:
            break
        middle = _trial_time(low, high, g_low, g_high)
        _hermite_state(h, middle, y, k[0], end, k[1], trial)
        g = _function_value(par, record, dt, t + middle, trial, mode, data, sc, ref, values,
                            kinds, target) - level  # fmt: skip
        if not math.isfinite(g):
            return 0.0, math.nan
        previous, g_previous = last, g_last
        last, g_last = middle, g
        low, high, g_low, g_high, side = narrowed(g < 0.0, middle, g, low, high, g_low, g_high,
                                                  side)  # fmt: skip
    rate_ = (g_previous - g_last) / (last - previous) if last != previous else math.nan
    return 0.5 * (low + high), rate_ if rate_ > 0.0 else math.nan


@kernel(cache=True, error_model="numpy", _nrt=False)
def _gap_corner(par, mode, kinds, target):
    """The box corner whose gap is event function ``target`` (:func:`event_values`' order), or
    -1 where the function is not a box corner's gap."""
    if par[P_SHAPE] != SHAPE_BOX or kinds[target] != FN_GAP:
        return -1
    count = 0 if mode[M_KIND] == FREE else 2  # a held patch's normal and friction (or slip)
    for c in range(4):
        if corner_held(mode, c):
            continue
        if count == target:
            return c
        count += 1
    return -1


@kernel(cache=True, error_model="numpy", _nrt=False)
def _corner_crossing(par, h, y, end, sc, k, corner, level, g_start, g_end, trial):
    """:func:`interpolated_crossing` for a box corner's gap: Newton's method on the interpolant.

    The gap g and its rate g' (the corner's vertical velocity) at
    :func:`_hermite_state`'s states, from the step's end (where g has
    fallen below its ``level``) backwards: ``tau - g / g'``, kept inside the
    bracket that the signs of g keep (else Anderson and Bjorck's regula
    falsi on it, as where g' does not fall), until a step is below half of
    ``INTERPOLANT_TIME``. The interpolant's velocities are the derivative
    of its positions to its own order, so the steps converge as Newton's; a
    landing corner's gap is concave (it falls ever faster), and from the
    step's end each step stays past the crossing. The benchmark's rocking
    cabinet under its record: 3.6 interpolant states per crossing (and the
    step's end) where the regula falsi on the values took 10.3, and better
    seeds for the RK4 trials, 2.0 per event where they took 2.4.
    ``level``, ``g_start`` and ``g_end`` as :func:`interpolated_crossing`'s;
    ``sc``'s rotation and probe are work space. Returns the crossing's time
    from t [s] and the gap's rate of fall there [m/s] (positive, or NaN
    where it does not fall).
    """
    rot, d = sc[SC_ROT], sc[SC_PROBE][0]
    low, high = 0.0, h
    g_low, g_high = g_start, g_end
    side = 0
    tau, g = h, g_end
    rotation_matrix(end, rot)
    _, rate_ = corner_gap(par, end, rot, corner, d)
    for _ in range(INTERPOLANT_TRIALS):
        step = -g / rate_ if rate_ < 0.0 else math.nan
        if abs(step) <= 0.5 * INTERPOLANT_TIME:
            return min(max(tau + step, low), high), -rate_
        following = tau + step
        if not low < following < high:
            following = _trial_time(low, high, g_low, g_high)  # Anderson and Bjorck's
        if high - low <= INTERPOLANT_TIME:
            break
        tau = following
        _hermite_state(h, tau, y, k[0], end, k[1], trial)
        rotation_matrix(trial, rot)
        g, rate_ = corner_gap(par, trial, rot, corner, d)
        g -= level
        if not math.isfinite(g):
            return 0.0, math.nan
        low, high, g_low, g_high, side = narrowed(g < 0.0, tau, g, low, high, g_low, g_high,
                                                  side)  # fmt: skip
    return 0.5 * (low + high), -rate_ if rate_ < 0.0 else math.nan


@kernel(cache=True, error_model="numpy", _nrt=False)
def _extrapolated(state, acc, delta, rate_):
    """The trial ``state`` moved by ``delta`` [s] along its rate, in place (quaternion normalised).

    ``y + delta y'``, y' from the accelerations ``acc`` of the trial's solve
    (:func:`~freestand.core.contact.body_solve.state_rate`; ``rate_``
    (``STATE_SIZE``,) is work space). It differs from the RK4 state at that
    time by ``delta^2 y'' / 2`` and ``delta`` times RK4's truncation error
    rate: within ``EXTRAPOLATION_TIME`` (1e-8 s) some 1e-16 s^2 times y'',
    far below the ``EVENT_TIME y'`` (1e-11 s) within which the search
    locates the event's state anyway.
    """
    state_rate(state, acc, rate_)
    for i in range(STATE_SIZE):
        state[i] += delta * rate_[i]
    _normalise(state)


@kernel(cache=True, error_model="numpy", _nrt=False)
def _seeded_trial(last, g_last, previous, g_previous, rate_, low, high, past_first):
    """The next seeded trial of :func:`locate` [s from the step's start], or NaN.

    From the last trial on RK4 states (at ``last``, the followed function
    less its level ``g_last`` there) the crossing is estimated by a Newton
    step, ``r = last + g_last / rate``, the rate of fall being the secant of
    the last two trials (``previous``, NaN before the second) or else the
    interpolant's ``rate_``; the trial lies ``SEED_OFFSET`` of an
    ``EVENT_TIME`` beyond r, seen from the last trial, or past r
    (``past_first``: the second trial of a function that needs no solve,
    which :func:`_clear_before` may then close alone). Where the estimates
    are that close, each trial crosses over and the bracket closes in two
    or three. NaN where no rate is known or the trial falls outside the
    bracket (low, high).
    """
    if math.isfinite(previous) and previous != last:
        secant = (g_previous - g_last) / (last - previous)
        if secant > 0.0:
            rate_ = secant
    if not rate_ > 0.0:
        return math.nan
    direction = 1.0 if g_last >= 0.0 or past_first else -1.0
    x = last + g_last / rate_ + SEED_OFFSET * direction * EVENT_TIME
    return x if low < x < high else math.nan


@kernel(cache=True, inline="always", error_model="numpy", _nrt=False)
def _state_only(kind):
    """True for an event function of the state alone (a gap, a landing, the tilt): no solve."""
    return kind == FN_GAP or kind == FN_LANDING or kind == FN_TILT


@kernel(cache=True, error_model="numpy", _nrt=False)
def _clear_before(par, out, mode, sc, ref, n, values, kinds, levels, rate_, back):
    """True where ``BACK_STEP`` before the trial ``out``, past the crossing of a function of
    the state alone, no such function has fired, and no force margin had at the trial.

    The state there is ``y - BACK_STEP y'`` from the trial's RK4 state y and
    its rate (the scratch's solve at it): it differs from the RK4 state at
    that time by ``BACK_STEP^2 y'' / 2`` and ``BACK_STEP`` times RK4's
    truncation error, some 1e-22 of the state, below its round-off. Its gap,
    landing and tilt functions then bracket the crossing within
    ``EVENT_TIME`` with the trial, which stays the event's state: where a
    seeded trial falls just past the crossing, the bracket closes without
    the trial before it that the regula falsi needs (a rocking cabinet's
    events: 2.3 RK4 trials each, 3.1 without it, before the trials within
    ``EXTRAPOLATION_TIME`` were extrapolated). Other gaps fired with the
    target (an edge's two corners landing together, to round-off) lie in the
    same bracket, as a trial of the regula falsi before the crossing would
    find them. The force margins are not checked before the trial, as no
    trial checks them between trials. ``rate_`` and ``back``
    (``STATE_SIZE``,) are work space; the scratch's rotation and
    ``values`` are left as they were at the trial.
    """
    for i in range(n):
        if not _state_only(kinds[i]) and values[i] < levels[i]:
            return False
    state_rate(out, sc[SC_ACC], rate_)
    for i in range(STATE_SIZE):
        back[i] = out[i] - BACK_STEP * rate_[i]
    _normalise(back)
    n_normal, n_tangent = row_counts(mode[M_KIND])
    rotation_matrix(back, sc[SC_ROT])
    event_values(par, back, mode, sc, ref, n_normal, n_tangent, values, kinds)
    clear = True
    for i in range(n):
        if _state_only(kinds[i]) and values[i] < levels[i]:
            clear = False
    rotation_matrix(out, sc[SC_ROT])
    event_values(par, out, mode, sc, ref, n_normal, n_tangent, values, kinds)
    return clear


@kernel(cache=True, error_model="numpy", _nrt=False)
def locate(par, record, dt, t, h, y, mode, data, sc, k, ref, start_values, count, trial,
           values, kinds, bracket, out):  # fmt: skip
    """Phase 2: the earliest crossing of an event function within the step.

    ``out`` holds the state at t + h; ``start_values`` the functions at t.
    Returns (step taken [s], kind of the function that fired or -1, RK4
    trials made; the extrapolated ones are not counted). On an event,
    ``out`` holds the state just after the crossing (within ``EVENT_TIME``).

    The crossing is bracketed on true RK4 states from the step's start by
    Anderson and Bjorck's variant of regula falsi on the function that fired
    (:mod:`~freestand.core.contact.regula_falsi`; superlinear, each end of the
    bracket moves; the Illinois variant of Dowell and Jarratt 1971 took 10.5
    trials per event of a rocking cabinet, this 9.4), each trial kept
    half a tolerance inside the bracket so that it closes to ``EVENT_TIME``
    once the root is found; a trial at which another function has fired
    becomes the bracket's end and that function the one followed. About eight
    trials instead of the bisection's thirty; with the seeds below, three or
    four for a gap (a rocking cabinet under a record: 4.6 per event, its
    slip-stops' eight included).

    The first trials are seeded: the crossing is found first on the step's
    cubic interpolant (:func:`interpolated_crossing`, at one solve or none
    per trial), tried on RK4 states, and then a Newton step from there is
    tried just past it, from each side in turn (:func:`_seeded_trial`);
    where the seeds do not close the bracket, the regula falsi goes on from
    it. A gap's, a landing's or the tilt's second trial is aimed just past
    the crossing, and a trial past it within ``BACK_STEP`` closes the
    bracket alone where the state that far before it has fired no such
    function (:func:`_clear_before`): a rocking cabinet under a record,
    2.3 RK4 trials per event where it took 3.1. A trial within
    ``EXTRAPOLATION_TIME`` of the last one and of the last RK4 trial is the
    last trial's state moved by its rate (:func:`_extrapolated`), at one
    solve and no RK4 step: most second seeded trials (the interpolant's
    crossing lies within 1e-10 s of the RK4 states' for half of a rocking
    cabinet's impacts, within 2e-9 s for nine in ten; its impacts then take
    1.4 RK4 trials each, its run about 8 % less time), and the last trials
    of the regula falsi, which close its bracket to ``EVENT_TIME`` (a
    slip-stop's, unseeded: the cabinet's took 6.2 RK4 trials each, now 4.0,
    the cask's 4.2, now 2.3). A slip-stop is not seeded:
    the friction's direction has kinks within such a step (where the slip
    crosses its floor and turns against the stored direction,
    :func:`~freestand.core.contact.body_solve.slip_direction`), and the
    cubic through the step's ends missed the cask's stops by up to 3e-5 s.
    ``bracket`` (3, ``MAX_EVENT_FUNCTIONS``) is work space: the functions'
    levels and their values at the bracket's ends.
    """
    n = event_functions(par, record, dt, t + h, out, mode, data, sc, ref, values, kinds)
    levels, low_values, high_values = bracket[0], bracket[1], bracket[2]
    _levels(par, n, start_values, kinds, levels)
    target = _fired(n, values, levels, -1)
    if target < 0:
        return h, -1, 0
    for i in range(n):
        low_values[i] = start_values[i]
        high_values[i] = values[i]
    low = 0.0
    high = h
    g_low = low_values[target] - levels[target]
    g_high = high_values[target] - levels[target]
    # the crossing on the step's cubic interpolant seeds the search on RK4 states
    first, rate_ = 0.0, math.nan
    if kinds[target] != FN_SLIP_STOP:
        # (not a slip-stop: the friction's direction has kinks within its step, see above)
        state_rate(out, sc[SC_ACC], k[1])  # y' at the step's end (k[1] is free until a trial)
        first, rate_ = interpolated_crossing(par, record, dt, t, h, y, out, mode, data, sc, k, ref,
                                             values, kinds, levels[target], target, g_low,
                                             g_high, trial)  # fmt: skip
    seeding = math.isfinite(rate_) and 0.0 < first < h
    seeded = 0
    last, g_last, previous, g_previous = first, 0.0, math.nan, 0.0
    side = 0
    trials = 0
    at_high = False  # the scratch and ``values`` hold the solve at the bracket's high end
    latest = math.nan  # the last trial's time: its state in ``trial``, its solve in the scratch
    anchor = math.nan  # the last RK4 trial's time
    for _ in range(200):
        if high - low <= EVENT_TIME:
            break
        middle = math.nan
        if seeding and seeded == 0:
            middle = min(max(first, 0.5 * EVENT_TIME), h - 0.5 * EVENT_TIME)
        elif seeding and seeded < SEED_TRIALS:
            middle = _seeded_trial(last, g_last, previous, g_previous, rate_, low, high,
                                   seeded == 1 and _state_only(kinds[target]))  # fmt: skip
        if seeding and math.isnan(middle):
            # the seeds are spent: the regula falsi from the bracket's ends, unscaled
            seeding = False
            side = 0
            g_low = low_values[target] - levels[target]
            g_high = high_values[target] - levels[target]
        if math.isnan(middle):
            middle = _trial_time(low, high, g_low, g_high)
        near_rk4 = abs(middle - anchor) <= EXTRAPOLATION_TIME  # (False before the first)
        if near_rk4 and abs(middle - latest) <= EXTRAPOLATION_TIME:
            _extrapolated(trial, sc[SC_ACC], middle - latest, k[2])  # from the last trial
        else:
            _rk4(par, record, dt, t, middle, y, mode, data, sc, k, trial)
            trials += 1
            anchor = middle
        event_functions(par, record, dt, t + middle, trial, mode, data, sc, ref, values, kinds)
        latest = middle
        fired = _fired(n, values, levels, target)
        if fired < 0 and values[target] == levels[target]:
            # a trial on the level itself (a gap at zero): the crossing, to round-off; the
            # regula falsi could not move its bracket's end from there and bisected
            for i in range(STATE_SIZE):
                out[i] = trial[i]
            high = middle
            at_high = True
            break
        if seeding:
            seeded += 1
            previous, g_previous = (last if seeded > 1 else math.nan), g_last
            last, g_last = middle, values[target] - levels[target]
            seeding = fired < 0 or fired == target  # another function fired: no more seeds
        at_high = fired >= 0
        if fired >= 0:
            for i in range(n):
                high_values[i] = values[i]
            for i in range(STATE_SIZE):
                out[i] = trial[i]
        else:
            for i in range(n):
                low_values[i] = values[i]
        if fired >= 0 and fired != target:
            # another function fired first: it is followed, from the bracket's low end
            target = fired
            side = 0
            high = middle
            g_low = low_values[target] - levels[target]
            g_high = high_values[target] - levels[target]
        else:
            g_trial = values[target] - levels[target]
            low, high, g_low, g_high, side = narrowed(fired >= 0, middle, g_trial, low, high,
                                                      g_low, g_high, side)  # fmt: skip
            if (fired == target and _state_only(kinds[target]) and middle - BACK_STEP > low
                    and high - low > EVENT_TIME
                    and _clear_before(par, out, mode, sc, ref, n, values, kinds, levels, k[3],
                                      k[4])):  # fmt: skip
                break  # the crossing lies within BACK_STEP before the trial, the event's state
    # the solve at the event's state (the caller's next phase reads the scratch), unless the
    # last trial made it
    if not at_high:
        event_functions(par, record, dt, t + high, out, mode, data, sc, ref, values, kinds)
    return high, kinds[target], trials
