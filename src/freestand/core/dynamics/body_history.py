"""Time history of one rigid body (box or cylinder) under three-component support motion.

The Python front end of the compiled loop :func:`freestand.core.dynamics.body_engine.run`:
it builds the arrays, grows the output buffers when they fill, and reduces
the histories to the peaks a screening reads (largest tilt, slide and twist,
uplift, free flight, overturning).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field, replace

import numba as nb
import numpy as np

from freestand.core.body import Body, Box
from freestand.core.contact.body_kernel import (
    DATA_SIZE,
    FACE,
    FREE,
    P_CENTRE,
    P_HALF_X,
    P_SHAPE,
    PIVOT_LEAN,
    SHAPE_BOX,
    STATE_SIZE,
    body_parameters,
    box_corner,
    quaternion_rotation,
)
from freestand.core.contact.vectors import norm2
from freestand.core.dynamics import body_engine as engine
from freestand.core.dynamics import body_state
from freestand.core.dynamics.body_projection import FLAT_ROUND_OFF
from freestand.core.dynamics.body_work import engine_work
from freestand.core.dynamics.results import ContactTolerances, interval_peak
from freestand.core.dynamics.single_block import UPLIFT_GAP_FRACTION
from freestand.core.dynamics.timehistory import record_row_breaks
from freestand.errors import FreestandError

GRAVITY = 9.81

MOTION_NAMES = {0: "free-flight", 1: "rock-corner", 2: "rock-edge", 3: "rest"}
EVENT_ROWS = 200_000  # events kept (the engine counts the others)
#: A tilt below this [rad] is a flat base's round-off, reported as zero: the engine leaves a
#: sliding flat base's quaternion within FLAT_ROUND_OFF of flat (tilt 2 sqrt(2) times that).
FLAT_TILT = 4.0 * FLAT_ROUND_OFF

#: After the record, the body is at rest when it sits flat, sticks and no velocity
#: component exceeds this [m/s, rad/s] (the planar engine's rest test).
REST_VELOCITY = 1e-9

#: The contact tolerances of :func:`simulate_body` where none are given.
DEFAULT_TOLERANCES = ContactTolerances()

#: A base point deeper below the support than this many times the depth the engine's
#: tolerances allow (:func:`lost_contact_depth`) means the contact was lost [-].
LOST_CONTACT_MARGIN = 10.0


@dataclass(frozen=True)
class SupportMotion3:
    """Three components of support acceleration, sampled at a constant step, linear between.

    Parameters
    ----------
    time_step : float
        Sampling interval dt [s], positive.
    x, y : numpy.ndarray
        Horizontal support accelerations along x and y [m/s^2] at ``k dt``.
    vertical : numpy.ndarray or None
        Downward support acceleration a_v [m/s^2] (the weight is ``m (g - a_v)``);
        None for none. Zero before the first and after the last sample.

    The three are kept as the rows of one (3, n) array (:meth:`array`), copies
    of the arrays given.

    Examples
    --------
    >>> import numpy as np
    >>> import freestand as fs
    >>> motion = fs.SupportMotion3(0.01, np.array([0.0, 1.0, 0.0]), np.array([0.0, 2.0, 0.0]))
    >>> motion.duration, motion.vertical.tolist()  # [s], [m/s^2]
    (0.02, [0.0, 0.0, 0.0])
    >>> motion.at([0.005]).ravel().tolist()  # x, y, vertical at 5 ms [m/s^2]
    [0.5, 1.0, 0.0]
    """

    time_step: float
    x: np.ndarray
    y: np.ndarray | None = None
    vertical: np.ndarray | None = None

    def __post_init__(self) -> None:
        if not (self.time_step > 0.0 and math.isfinite(self.time_step)):
            raise FreestandError(f"time_step must be positive, not {self.time_step!r} s")
        x = np.asarray(self.x, dtype=float)
        if x.ndim != 1 or x.size < 2:
            raise FreestandError("x must be a 1-D array of at least 2 samples [m/s^2]")
        rows = np.zeros((3, x.size))  # x, y, vertical: the engine's record (array())
        rows[0] = x
        for row, name in ((1, "y"), (2, "vertical")):
            value = getattr(self, name)
            if value is not None:
                value = np.asarray(value, dtype=float)
                if value.shape != x.shape:
                    raise FreestandError(
                        f"{name} must have the {x.size} samples of x, not {value.shape}"
                    )
                rows[row] = value
        for row, name in enumerate(("x", "y", "vertical")):
            object.__setattr__(self, name, rows[row])
        object.__setattr__(self, "_rows", rows)

    @property
    def duration(self) -> float:
        """Time of the last sample [s]."""
        return (self.x.size - 1) * self.time_step

    def rotated(self, angle: float) -> SupportMotion3:
        """The motion with its horizontal pair turned by ``angle`` [rad] about the vertical."""
        c, s = math.cos(angle), math.sin(angle)
        return SupportMotion3(self.time_step, c * self.x - s * self.y, s * self.x + c * self.y,
                              self.vertical)  # fmt: skip

    def array(self) -> np.ndarray:
        """(3, n), C-contiguous: x, y, vertical, the rows ``x``, ``y`` and ``vertical`` view.

        Kept from the motion's making, as its three components' one array (the
        engine's record): stacking them again took 5 us of each run, 11 us where
        another program's run had left numpy out of the caches.
        """
        return self._rows

    def at(self, time) -> np.ndarray:
        """(3, K): x, y, vertical [m/s^2] at the times ``time`` [s] (linear, zero outside)."""
        samples = np.arange(self.x.size) * self.time_step
        return np.array([np.interp(time, samples, row, left=0.0, right=0.0)
                         for row in self.array()])  # fmt: skip


@dataclass(frozen=True)
class BodyTimeHistory:
    """Outcome of :func:`simulate_body`.

    Attributes
    ----------
    body : str
        The body's name.
    status : str
        ``"completed"``, ``"overturned"`` or ``"failed"`` (``message``).
    time : numpy.ndarray
        (K,) [s].
    state : numpy.ndarray
        (K, 13): centre of gravity r [m], orientation quaternion (w, x, y, z)
        [-], velocity v [m/s], angular velocity omega [rad/s] (support frame).
    patch : numpy.ndarray
        (K,) contact patch (0 free, 1 point, 2 edge, 3 face).
    sliding : numpy.ndarray
        (K,) True where the patch slides.
    normal_force : numpy.ndarray
        (K,) total normal force N [N].
    friction_force : numpy.ndarray
        (K,) friction on the limit surface's scale, ``|(F_x, F_y, T_z / rho)|``
        [N] (F the friction force, T_z a FACE's or EDGE's twist torque, rho
        its twist radius; a POINT has no T_z): at most mu_0 N while it holds,
        mu N while it slides.
    tilt : numpy.ndarray
        (K,) angle of the body's z axis from the vertical [rad].
    slide : numpy.ndarray
        (K, 2) horizontal displacement of the base centre from its start [m].
    twist : numpy.ndarray
        (K,) rotation about the vertical (swing-twist decomposition, unwrapped) [rad].
    events : tuple of (float, str, str, str)
        (time [s], kind, patch before, patch after); named from
        ``event_codes`` where first read.
    max_rotation, max_slide, max_twist : float
        Largest tilt [rad], horizontal slide magnitude [m], |twist| [rad].
    uplift, free_flight, overturned : bool
        A base point lifted by more than ``UPLIFT_GAP_FRACTION`` of the base
        width; the body left the support; it overturned.
    overturn_time : float or None
        [s].
    diagnostics : dict
        steps, events, impacts, remedies (where no contact mode was
        admissible: a velocity-level impact or time stepping),
        stretch_steps (the time-stepping steps) and event_trials (the
        RK4 trials of the events' searches).
    message : str
        Why the simulation failed (status ``"failed"``: the state stopped
        being finite, or a base point went deeper below the support than
        :func:`lost_contact_depth`; the histories, events and peaks stop
        before it), else empty.
    event_codes : tuple of numpy.ndarray
        The engine's events as codes: times [s], kinds, patches before and
        after (:data:`EVENT_KIND_NAMES`, :data:`PATCH_NAMES`), from which
        ``events`` is named. Naming the 293 events of the 3-D benchmark's
        cabinet as tuples took 34 us of its run warm and 86 us where another
        program's run had left Python's objects out of the caches, as the
        benchmark alternates them (3 % of the run): a run whose events are
        not read does not pay for them.
    """

    body: str
    status: str
    time: np.ndarray
    state: np.ndarray
    patch: np.ndarray
    sliding: np.ndarray
    normal_force: np.ndarray
    friction_force: np.ndarray
    tilt: np.ndarray
    slide: np.ndarray
    twist: np.ndarray
    event_codes: tuple
    max_rotation: float
    max_slide: float
    max_twist: float
    uplift: bool
    free_flight: bool
    overturned: bool
    overturn_time: float | None
    diagnostics: dict = field(default_factory=dict)
    message: str = ""

    @functools.cached_property
    def events(self) -> tuple:
        """(time [s], kind, patch before, patch after) of each event, named from
        ``event_codes`` (:func:`_event_tuples`) where first read."""
        return _event_tuples(self.event_codes)


def default_body_step(body: Body, gravity: float = GRAVITY) -> float:
    """Default largest step [s]: ``0.05 / p``, p the largest rocking frequency parameter.

    ``p = sqrt(m g rho / I_O)`` about each base edge (box) or rim tangent
    (cylinder) in x and y (Housner 1963), at most 20 ms; as the planar
    engine's :func:`freestand.core.dynamics.timehistory.default_step`.
    """
    shape, mass, inertia = body.shape, body.mass, np.asarray(body.inertia).tolist()
    centre_x, centre_y, height = body.centre
    if isinstance(shape, Box):
        half_x, half_y = 0.5 * shape.size[0], 0.5 * shape.size[1]
    else:
        half_x = half_y = shape.radius
    largest = 0.0
    # rocking in the x-z plane (about y) and in the y-z plane (about x)
    for moment, half, offset in ((inertia[1][1], half_x, centre_x),
                                 (inertia[0][0], half_y, centre_y)):  # fmt: skip
        for lever in (half - offset, half + offset):
            rho = math.hypot(lever, height)
            i_o = moment + mass * rho**2
            largest = max(largest, math.sqrt(mass * gravity * rho / i_o))
    return min(0.05 / largest, 0.02)


def initial_state(body: Body, initial_tilt: tuple[float, float] = (0.0, 0.0)) -> np.ndarray:
    """The state at rest on the support, optionally tilted (rotation vector (x, y) [rad]) about
    the base point that stays on the support: the base edge / rim point on the tilt's side."""
    y = np.zeros(STATE_SIZE)
    y[3] = 1.0
    y[2] = body.centre[2]
    angle = math.hypot(*initial_tilt)
    if angle > 0.0:
        axis = np.array([initial_tilt[0], initial_tilt[1], 0.0]) / angle
        y[3] = math.cos(0.5 * angle)
        y[4:7] = math.sin(0.5 * angle) * axis
        rot = rotation_matrices(y[3:7][None, :])[0]
        points = _base_points(body)
        y[2] = -np.min((rot @ (points - np.asarray(body.centre)).T)[2])
    return y


def _base_points(body: Body) -> np.ndarray:
    if isinstance(body.shape, Box):
        return body.shape.base_corners()
    angles = np.linspace(0.0, 2.0 * math.pi, 3601)
    radius = body.shape.radius
    return np.column_stack([radius * np.cos(angles), radius * np.sin(angles), 0.0 * angles])


def simulate_body(
    body: Body,
    motion: SupportMotion3,
    duration: float | None = None,
    *,
    max_step: float | None = None,
    gravity: float = GRAVITY,
    tolerances: ContactTolerances | None = None,
    initial: np.ndarray | None = None,
    restitution: float = 1.0,
) -> BodyTimeHistory:
    """Event-driven time history of a box or cylinder on the support under three components.

    Parameters
    ----------
    body : Body
        The body (:mod:`freestand.core.body`).
    motion : SupportMotion3
        Support accelerations x, y, vertical [m/s^2].
    duration : float, optional
        End time [s]; default the motion's duration (free motion continues
        after the record until then).
    max_step : float, optional
        Largest RK4 step [s]; default :func:`default_body_step`.
    gravity : float
        g [m/s^2].
    tolerances : ContactTolerances, optional
        Gap [m] and velocity [m/s] within which a point touches.
    initial : numpy.ndarray, optional
        (13,) initial state; default at rest, flat on the support.
    restitution : float, optional
        Factor e in [0, 1] on the body's velocity after each impact [-] (1:
        the plastic law; in a plane the angular-velocity ratio becomes ``e``
        times Housner's, as the planar engine's factor). A box's turn about
        the line through its pivot corner and a single corner landing beside
        it is kept whole
        (:func:`~freestand.core.contact.body_impulse.restitution_velocity`).

    Returns
    -------
    BodyTimeHistory

    Notes
    -----
    Exact rigid unilateral contact with Coulomb friction on the circular
    cone, events located to 1e-11 s, impacts plastic at the impacting points
    (Housner's law in a plane), then scaled by ``restitution``; see
    ``docs/three-d.md``.
    """
    tolerances = tolerances or DEFAULT_TOLERANCES
    end = motion.duration if duration is None else float(duration)
    if not (end > 0.0 and math.isfinite(end)):
        raise FreestandError(f"duration must be positive, not {duration!r} s")
    step = default_body_step(body, gravity) if max_step is None else float(max_step)
    if not (step > 0.0 and math.isfinite(step)):
        raise FreestandError(f"max_step must be positive, not {max_step!r} s")
    if not 0.0 <= restitution <= 1.0:
        raise FreestandError(
            f"restitution must lie in [0, 1] (1: the plastic impact law), not {restitution!r}",
            source="restitution",
        )
    par = body_parameters(body, gravity, float(restitution))
    y = initial_state(body) if initial is None else np.array(initial, dtype=float)
    scratch, impulse_work = engine_work()  # the kernel's scratch, the impulses' work arrays
    width = _base_width(body)
    istate, time, state, events, rows = _run_history(
        par, motion.array(), float(motion.time_step), step, end, motion.duration,
        tolerances.gap, tolerances.velocity, y, scratch, impulse_work,
        lost_contact_depth(width, tolerances.gap), 0,
    )  # fmt: skip
    return _result(body, width, istate, time, state, events, rows)


def _base_width(body: Body) -> float:
    """The base's smaller side (box) or its diameter (cylinder) [m]."""
    return min(body.shape.size[:2]) if isinstance(body.shape, Box) else 2.0 * body.shape.radius


@nb.njit(cache=True, error_model="numpy")
def _run_history(par, record, dt, h_max, t_end, record_end, gap_tol, velocity_tol, y, scratch,
                 impulse_work, depth, rows):  # fmt: skip
    """The engine's run from time 0 and the result's rows, in one compiled call.

    The record's breaks (:func:`~freestand.core.dynamics.timehistory.record_row_breaks`),
    the output buffers (``rows`` rows at first; 0: :func:`_capacity`'s), the loop
    (:func:`freestand.core.dynamics.body_engine.run`), called again where its
    buffers fill on buffers twice as long that keep the rows so far, and
    :func:`_history_rows` below ``depth`` [m]. One call from Python where there
    were three and the buffers' nine allocations: some 20-70 us less of the
    benchmark's runs alternated with MuJoCo's, which find Python's and numba's
    dispatch out of the caches. ``y`` (13,) the initial state, advanced to the end; ``scratch``
    and ``impulse_work`` the engine's records
    (:func:`~freestand.core.dynamics.body_work.engine_work`).

    Returns
    -------
    tuple
        (istate, time (K,) [s], state (K, 13), the events' (time [s], kind,
        patch before, after) arrays, :func:`_history_rows`'s tuple).
    """
    mode = np.zeros(3, dtype=np.int64)
    data = np.zeros(DATA_SIZE)
    istate = np.zeros(body_state.I_SIZE, dtype=np.int64)
    breaks = record_row_breaks(dt, record)
    if rows <= 0:
        rows = _capacity(t_end, h_max, breaks)
    out_t, out_y = np.empty(rows), np.empty((rows, STATE_SIZE))
    out_mode, out_force = np.empty((rows, 3), dtype=np.int64), np.empty((rows, 2))
    events = _event_size(rows, 0)
    ev_time, ev_kind = np.empty(events), np.empty(events, dtype=np.int64)
    ev_before, ev_after = np.empty(events, dtype=np.int64), np.empty(events, dtype=np.int64)
    t = 0.0
    while True:
        t = engine.run(par, record, dt, breaks, h_max, t_end, record_end, gap_tol, velocity_tol,
                       t, y, mode, data, scratch, impulse_work, istate, out_t, out_y, out_mode,
                       out_force, ev_time, ev_kind, ev_before, ev_after)  # fmt: skip
        if istate[body_state.I_STATUS] != body_state.STATUS_BUFFER_FULL:
            break
        # the rows so far kept, the loop goes on writing after them
        rows *= 2
        out_t, out_y = _grown(out_t, rows), _grown(out_y, rows)
        out_mode, out_force = _grown(out_mode, rows), _grown(out_force, rows)
        events = _event_size(rows, istate[body_state.I_EVENTS])
        if events > ev_time.shape[0]:
            ev_time, ev_kind = _grown(ev_time, events), _grown(ev_kind, events)
            ev_before, ev_after = _grown(ev_before, events), _grown(ev_after, events)
    count = istate[body_state.I_RECORDS]
    kept = min(istate[body_state.I_EVENTS], ev_time.shape[0])
    time, state = out_t[:count], out_y[:count]
    result = _history_rows(par, time, state, out_mode[:count], out_force[:count], ev_time[:kept],
                           depth)  # fmt: skip
    return (istate, time, state, (ev_time[:kept], ev_kind[:kept], ev_before[:kept],
                                  ev_after[:kept]), result)  # fmt: skip


@nb.njit(cache=True, error_model="numpy")
def _grown(values, size):
    """``values`` (rows first) in a new array of ``size`` rows, the rest not set."""
    grown = np.empty((size,) + values.shape[1:], dtype=values.dtype)
    grown[: values.shape[0]] = values
    return grown


@nb.njit(cache=True, error_model="numpy")
def _event_size(rows, count):
    """Events the engine's event arrays hold for a call of ``rows`` output rows after
    ``count`` events: a call writes at most an event per row, with one more at the start
    and one at an overturn; at most ``EVENT_ROWS`` (the engine counts the others)."""
    return min(EVENT_ROWS, count + rows + 2)


@nb.njit(cache=True, error_model="numpy")
def _capacity(end, step, breaks):
    """Rows of the output buffers of the engine's first call (twice as many at each further).

    A step ends at ``step`` [s], at every break of the record (``breaks`` [s],
    ascending) and at every event, up to ``end`` [s].
    """
    return int(end / step * 1.1) + 2 * np.searchsorted(breaks, end) + 64


@dataclass(frozen=True)
class BodyMotion:
    """The motion of a body read from its states (:func:`body_motion`).

    Attributes
    ----------
    tilt : numpy.ndarray
        (K,) angle of the body's z axis from the vertical [rad].
    slide : numpy.ndarray
        (K, 2) horizontal displacement of the base centre from the first state [m].
    twist : numpy.ndarray
        (K,) rotation about the vertical from the first state (swing-twist
        decomposition of the orientation, unwrapped) [rad].
    lowest, highest : numpy.ndarray
        (K,) height of the lowest and of the highest point of the base's
        outline above the support [m] (a box's corners, a cylinder's rim).
    """

    tilt: np.ndarray
    slide: np.ndarray
    twist: np.ndarray
    lowest: np.ndarray
    highest: np.ndarray


def body_motion(body: Body, state: np.ndarray) -> BodyMotion:
    """Tilt, slide, twist and base heights of ``body`` from its states.

    Parameters
    ----------
    body : Body
    state : numpy.ndarray
        (K, >= 7): the centre of gravity r [m] and the orientation quaternion
        (w, x, y, z) [-] of the body frame (origin at the base centre, z
        along the body's axis) in the support frame, as
        :attr:`BodyTimeHistory.state`.

    Returns
    -------
    BodyMotion

    Notes
    -----
    With the quaternion q = (w, x, y, z): ``cos(tilt) = 1 - 2 (x^2 + y^2)``
    (the z component of the body's axis), ``twist = 2 atan2(z, w)`` (the
    rotation about the vertical when the orientation is split into a twist
    about the vertical followed by a swing of the axis), the base centre
    ``r - R c`` with c the centre of gravity in the body frame.
    """
    return _read_motion(body, state, False)[0]


def _read_motion(body: Body, state: np.ndarray, with_rates: bool):
    """(:func:`body_motion`, and with ``with_rates`` the (3, K) rates of its tilt, slide
    size and twist [rad/s, m/s, rad/s] from the states' velocities, else None)."""
    state = np.ascontiguousarray(state, dtype=float)
    if isinstance(body.shape, Box):
        outline, radius = np.ascontiguousarray(body.shape.base_corners(), dtype=float), 0.0
    else:
        outline, radius = np.zeros((0, 3)), float(body.shape.radius)
    count = state.shape[0]
    tilt, twist, lowest, highest = (np.empty(count) for _ in range(4))
    slide = np.empty((count, 2))
    rates = np.empty((3, count if with_rates else 0))
    _motion_rows(state, np.asarray(body.centre, dtype=float), outline, radius, tilt, slide, twist,
                 lowest, highest, rates)  # fmt: skip
    return BodyMotion(tilt, slide, twist, lowest, highest), (rates if with_rates else None)


@nb.njit(cache=True, error_model="numpy")
def _tilt_columns(columns, lean, upright, tilt):
    """The tilt [rad] of each state in ``columns`` (13, K), but those past the series.

    ``lean`` and ``upright`` (K,): the sine and cosine of the tilt from the
    rotation's third row (``sqrt(R_31^2 + R_32^2)``, ``R_33``); ``tilt`` their
    ``atan2`` by :func:`_atan_small` below ``SMALL_ANGLE_TANGENT``, zero below
    ``FLAT_TILT`` (``acos(R_33)`` loses its digits near flat: below 1e-8 rad it
    is zero, and a rocking excursion of 1e-6 rad peaked 4e-5 off). Where the
    tangent is larger, :func:`_motion_rows` takes ``atan2`` after this pass,
    which has no branch and is vectorised.
    """
    for i in range(columns.shape[1]):
        _, _, _, _, _, _, r20, r21, r22 = quaternion_rotation(
            columns[3, i], columns[4, i], columns[5, i], columns[6, i])  # fmt: skip
        size = math.sqrt(r20 * r20 + r21 * r21)
        lean[i] = size
        upright[i] = r22
        # atan2(size, r22) < size / r22 below FLAT_TILT: a flat base, no series
        tilt[i] = 0.0 if size <= FLAT_TILT * r22 else _atan_small(size / r22)


#: Below this tangent an angle is :func:`_atan_small`'s series, not ``atan2`` [-].
SMALL_ANGLE_TANGENT = 0.1


@nb.njit(cache=True, error_model="numpy", inline="always")
def _atan_small(x):
    """atan(x) [rad] for ``|x| <= SMALL_ANGLE_TANGENT``: its Taylor series to x^17.

    ``x (1 - x^2/3 + x^4/5 - ... + x^16/17)``; the first term left out,
    ``x^19 / 19``, is below 1e-19 of x: ``atan2``'s value to round-off at a
    quarter of its cost (a rolling body's history takes a tilt and a twist at
    every row).
    """
    t = x * x
    series = 1.0 / 15.0 - t / 17.0
    for odd in (13.0, 11.0, 9.0, 7.0, 5.0, 3.0, 1.0):
        series = 1.0 / odd - t * series
    return x * series


@nb.njit(cache=True, error_model="numpy", inline="always")
def _small_turn(across, along):
    """Whether a turn of half-angle atan2(``across``, ``along``) is taken by :func:`_atan_small`
    (a positive ``along`` and a tangent within ``SMALL_ANGLE_TANGENT``)."""
    return along > 0.0 and abs(across) <= SMALL_ANGLE_TANGENT * along


@nb.njit(cache=True, error_model="numpy", inline="always")
def _twist_jump(w, z, w0, z0):
    """The twist's change [rad] from a state with quaternion components (w0, z0) to (w, z).

    ``2 atan2(z, w) - 2 atan2(z0, w0)`` taken in [-pi, pi) (a jump above pi
    is taken the other way round, as ``numpy.unwrap``): where the turn is
    small, ``2 atan(s / c)`` of the half-angles' difference (``s = z w0 - w
    z0``, ``c = w w0 + z z0``) by :func:`_atan_small`.
    """
    across = z * w0 - w * z0
    along = w * w0 + z * z0
    if _small_turn(across, along):
        return 2.0 * _atan_small(across / along)
    angle, previous = 2.0 * math.atan2(z, w), 2.0 * math.atan2(z0, w0)
    jump = angle - previous
    if abs(jump) >= math.pi:
        jump = (jump + math.pi) % (2.0 * math.pi) - math.pi
        if jump == -math.pi and angle > previous:
            jump = math.pi
    return jump


@nb.njit(cache=True, error_model="numpy")
def _motion_rows(state, centre, outline, radius, tilt, slide, twist, lowest, highest, rates):
    """:func:`body_motion`'s arrays from the states (its Notes).

    ``outline``: a box's base corners in the body frame (K, 3), or none and
    the rim's ``radius`` [m]. The twist is unwrapped as ``numpy.unwrap``
    (a jump above pi between two states is taken the other way round).
    ``rates`` (3, K): the rates of the tilt, the slide's size and the twist
    (:func:`_rate_columns`), or (3, 0) for none.

    The states are copied into columns first, and each quantity is a pass
    over them without a branch (:func:`_tilt_columns`,
    :func:`_twist_columns`, :func:`_base_columns`, :func:`_rate_columns`),
    which the compiler vectorises; then one pass takes the branches (a tilt
    past the small angles' series, the twist's unwrapping). The arithmetic of
    a loop over the states, to the last bit (but a zero rate's sign where a
    state repeats the one before with a velocity of -0.0, which the loop
    copied), at about half its cost: the benchmark's three bodies' rows
    (2,300 to 2,600 of a 10 s record) in 35 to 45 us where they took 50 to
    93 us.
    """
    count = state.shape[0]
    if count == 0:
        return
    columns = np.empty((STATE_SIZE, count))
    for i in range(count):
        for j in range(STATE_SIZE):
            columns[j, i] = state[i, j]
    lean, upright, jump = np.empty(count), np.empty(count), np.empty(count)
    _tilt_columns(columns, lean, upright, tilt)
    _twist_columns(columns, jump)
    base = np.empty((6, count))  # R c, the base centre's height, its slide (x, y) [m]
    _base_columns(columns, centre, base)
    for i in range(count):
        slide[i, 0], slide[i, 1] = base[4, i], base[5, i]
    _base_heights(columns, outline, radius, lean, base[3], lowest, highest)
    if rates.shape[1] > 0:
        _rate_columns(columns, base, rates)
    turned = 0.0
    for i in range(count):
        size, cosine = lean[i], upright[i]
        if not (size <= FLAT_TILT * cosine or size <= SMALL_ANGLE_TANGENT * cosine):
            tilt[i] = math.atan2(size, cosine)  # past the series
        if not tilt[i] > FLAT_TILT:
            tilt[i] = 0.0  # the integration's round-off of a flat base
        if i > 0:
            w, z, w0, z0 = columns[3, i], columns[6, i], columns[3, i - 1], columns[6, i - 1]
            if _small_turn(z * w0 - w * z0, w * w0 + z * z0):
                turned += jump[i]  # the series, as _twist_jump takes it
            else:
                turned += _twist_jump(w, z, w0, z0)
        twist[i] = turned


@nb.njit(cache=True, error_model="numpy")
def _twist_columns(columns, jump):
    """The twist's change from each state in ``columns`` to the next, by the series.

    ``jump[i]`` (K,) = ``2 atan(s / c)`` by :func:`_atan_small`, of the
    half-angles' difference from state i - 1 (:func:`_twist_jump`), the
    value it takes where the turn is small; the others are taken after this
    pass. ``jump[0]`` is not set.
    """
    for i in range(1, columns.shape[1]):
        w, z, w0, z0 = columns[3, i], columns[6, i], columns[3, i - 1], columns[6, i - 1]
        jump[i] = 2.0 * _atan_small((z * w0 - w * z0) / (w * w0 + z * z0))


@nb.njit(cache=True, error_model="numpy")
def _base_columns(columns, centre, base):
    """``base`` (6, K): R c (rows 0-2), the base centre's height ``r_z - (R c)_z`` (row 3) and
    its slide, the base centre ``r - R c`` from the first state's, horizontal (rows 4-5) [m].

    ``centre`` c: the centre of gravity in the body frame [m].
    """
    c0, c1, c2 = centre[0], centre[1], centre[2]
    r00, r01, r02, r10, r11, r12, _, _, _ = quaternion_rotation(
        columns[3, 0], columns[4, 0], columns[5, 0], columns[6, 0])  # fmt: skip
    first_x = columns[0, 0] - (r00 * c0 + r01 * c1 + r02 * c2)
    first_y = columns[1, 0] - (r10 * c0 + r11 * c1 + r12 * c2)
    for i in range(columns.shape[1]):
        r00, r01, r02, r10, r11, r12, r20, r21, r22 = quaternion_rotation(
            columns[3, i], columns[4, i], columns[5, i], columns[6, i])  # fmt: skip
        cx = r00 * c0 + r01 * c1 + r02 * c2
        cy = r10 * c0 + r11 * c1 + r12 * c2
        cz = r20 * c0 + r21 * c1 + r22 * c2
        base[0, i], base[1, i], base[2, i] = cx, cy, cz
        base[3, i] = columns[2, i] - cz
        base[4, i] = columns[0, i] - cx - first_x
        base[5, i] = columns[1, i] - cy - first_y


@nb.njit(cache=True, error_model="numpy")
def _base_heights(columns, outline, radius, lean, height, lowest, highest):
    """The heights [m] of the lowest and highest points of the base's outline.

    A box's corners (``outline`` (4, 3), body frame) at ``R_3 . s + h_b``, a
    cylinder's rim (no outline, ``radius`` [m]) at ``h_b -+ R sin(tilt)``
    (``lean``); ``height`` h_b the base centre's [m].
    """
    count = columns.shape[1]
    if outline.shape[0] == 0:
        for i in range(count):
            reach = radius * lean[i]
            lowest[i], highest[i] = height[i] - reach, height[i] + reach
        return
    for i in range(count):
        lowest[i], highest[i] = math.inf, -math.inf
    for k in range(outline.shape[0]):  # corner by corner, each a pass over the states
        sx, sy, sz = outline[k, 0], outline[k, 1], outline[k, 2]
        for i in range(count):
            _, _, _, _, _, _, r20, r21, r22 = quaternion_rotation(
                columns[3, i], columns[4, i], columns[5, i], columns[6, i])  # fmt: skip
            corner = r20 * sx + r21 * sy + r22 * sz + height[i]
            lowest[i], highest[i] = min(lowest[i], corner), max(highest[i], corner)


def lost_contact_depth(width: float, gap: float) -> float:
    """Depth [m] of a base point below the support past which the contact was lost.

    ``LOST_CONTACT_MARGIN (gap + PIVOT_LEAN width)``: the engine lets a
    point within the gap tolerance ``gap`` [m] touch, and turns a cylinder
    within ``PIVOT_LEAN`` of flat about its stored rim point, whose lowest
    rim point may then lie up to ``2 R sin(tilt) <= PIVOT_LEAN width`` below
    it; ``width`` [m] is the base's smaller side or diameter.
    """
    return LOST_CONTACT_MARGIN * (gap + PIVOT_LEAN * width)


def _kept_rows(time, state, lowest, first: int) -> tuple[int, str]:
    """Rows before ``first``, the first state that is not finite or lies below the support; why.

    ``first`` (:func:`_first_invalid`; -1 where every row is valid) is kept where it is
    the first row; ``lowest`` (K,) the heights of the base's lowest point [m].
    """
    if first < 0:
        return time.size, ""
    rows = max(first, 1)
    if not np.all(np.isfinite(state[first])):
        why = f"the state stopped being finite at t = {time[first]:.6g} s"
    else:
        why = (f"a base point went {-lowest[first]:.3g} m below the support at "
               f"t = {time[first]:.6g} s: the contact was lost")  # fmt: skip
    return rows, (f"{why} (a defect of the 3-D engine); the histories and peaks stop at "
                  f"t = {time[rows - 1]:.6g} s")  # fmt: skip


@nb.njit(cache=True, error_model="numpy")
def _first_invalid(state, lowest, depth):
    """The first row whose state is not finite or whose ``lowest`` is below ``-depth``; -1.

    A row's sum is finite where its entries are (a NaN or infinity carries
    into it); only where it is not are they read one by one (a sum may
    overflow).
    """
    for i in range(state.shape[0]):
        if not lowest[i] >= -depth:  # below, or NaN
            return i
        total = 0.0
        for j in range(state.shape[1]):
            total += state[i, j]
        if not math.isfinite(total):
            for j in range(state.shape[1]):
                if not math.isfinite(state[i, j]):
                    return i
    return -1


#: The events' kinds by code (:data:`~freestand.core.dynamics.body_state.EVENT_KINDS`).
EVENT_KIND_NAMES = body_state.EVENT_KINDS
#: The patches' names by code (FREE, POINT, EDGE, FACE); the code -1 (no patch before a start
#: event) takes the last, "".
PATCH_NAMES = ("free", "point", "edge", "face", "")


def _result(body, width, istate, time, state, events, rows) -> BodyTimeHistory:
    """The history of :func:`simulate_body` from :func:`_run_history`'s arrays; ``width`` [m]
    the base's (:func:`_base_width`)."""
    counts = istate.tolist()
    (first, shown, lowest, tilt, slide, twist, patch, sliding, normal_force, friction_force,
     peaks) = rows  # fmt: skip
    kept, message = _kept_rows(time, state, lowest, first)
    time, state = time[:kept], state[:kept]
    overturned = not message and counts[body_state.I_STATUS] == body_state.STATUS_OVERTURNED
    return BodyTimeHistory(
        body=body.name,
        status="failed" if message else "overturned" if overturned else "completed",
        time=time,
        state=state,
        patch=patch,
        sliding=sliding,
        normal_force=normal_force,
        friction_force=friction_force,
        tilt=tilt,
        slide=slide,
        twist=twist,
        event_codes=tuple(codes[:shown] for codes in events),
        max_rotation=peaks[0],
        max_slide=peaks[1],
        max_twist=peaks[2],
        uplift=bool(peaks[3] > UPLIFT_GAP_FRACTION * width),
        free_flight=bool(peaks[4]),
        overturned=bool(overturned),
        overturn_time=float(time[-1]) if overturned else None,
        diagnostics={
            "steps": counts[body_state.I_STEPS],
            "events": counts[body_state.I_EVENTS],
            "impacts": counts[body_state.I_IMPACTS],
            "remedies": counts[body_state.I_REMEDIES],
            "stretch_steps": counts[body_state.I_STRETCH_STEPS],
            "event_trials": counts[body_state.I_TRIALS],
        },
        message=message,
    )


def _event_tuples(codes: tuple) -> tuple:
    """The engine's events as (time [s], kind, patch before, after), from their ``codes``
    (:attr:`BodyTimeHistory.event_codes`).

    Named from lists of the codes (indexing arrays of names took 8 us warm, 26 us where
    another program's run had left numpy out of the caches).
    """
    columns = (column.tolist() for column in codes)
    return tuple(
        (time, EVENT_KIND_NAMES[kind], PATCH_NAMES[was], PATCH_NAMES[now])
        for time, kind, was, now in zip(*columns, strict=True)
    )


@nb.njit(cache=True, error_model="numpy")
def _history_rows(par, time, state, modes, forces, event_times, depth):
    """The result's rows and peaks from the engine's, in one call.

    :func:`_motion_rows` (with the rates) of the body of parameters ``par``
    (:func:`~freestand.core.contact.body_kernel.body_parameters`), the rows
    kept (:func:`_first_invalid` below ``depth`` [m], :func:`_kept_rows`),
    the events up to the last of them (``event_times`` [s] ascending, as the
    engine writes them) and :func:`_peaks`.

    Returns
    -------
    tuple
        (first invalid row or -1, events shown, lowest (K,) [m];
        of the rows kept: tilt [rad], slide [m], twist [rad], patch, sliding,
        normal force [N], friction force [N]; the peaks of :func:`_peaks`).
    """
    count = state.shape[0]
    outline, radius = _base_outline(par)
    tilt, twist = np.empty(count), np.empty(count)
    lowest, highest = np.empty(count), np.empty(count)
    slide = np.empty((count, 2))
    rates = np.empty((3, count))
    _motion_rows(state, par[P_CENTRE : P_CENTRE + 3], outline, radius, tilt, slide, twist,
                 lowest, highest, rates)  # fmt: skip
    first = _first_invalid(state, lowest, depth)
    rows = count if first < 0 else max(first, 1)
    last = time[rows - 1]
    shown = 0
    while shown < event_times.shape[0] and event_times[shown] <= last:
        shown += 1
    peaks = _peaks(time[:rows], tilt[:rows], slide[:rows], twist[:rows], rates[:, :rows],
                   highest[:rows], modes[:rows], event_times[:shown])  # fmt: skip
    return (first, shown, lowest, tilt[:rows], slide[:rows], twist[:rows],
            modes[:rows, 0].copy(), modes[:rows, 2] == 1, forces[:rows, 0].copy(),
            forces[:rows, 1].copy(), peaks)  # fmt: skip


@nb.njit(cache=True, error_model="numpy", inline="always")
def _base_outline(par):
    """(a box's base corners (4, 3) in the body frame [m], the engine's
    (:func:`~freestand.core.contact.body_kernel.box_corner`, the order of
    :meth:`Box.base_corners`), 0.0), or (none, the rim's radius [m]) of the body of
    parameters ``par``."""
    if par[P_SHAPE] != SHAPE_BOX:
        return np.zeros((0, 3)), par[P_HALF_X]
    outline = np.zeros((4, 3))
    for k in range(4):
        outline[k, 0], outline[k, 1] = box_corner(par, k)
    return outline, 0.0


@nb.njit(cache=True, error_model="numpy")
def _peaks(time, tilt, slide, twist, rates, highest, modes, event_times):
    """(largest tilt [rad], slide [m], |twist| [rad], highest base point [m], 1.0 if a row
    is FREE else 0.0): the result's peaks, in one pass over the rows.

    The tilt's, the slide's and the twist's are refined between rows on the
    cubic Hermite interpolant of each and its rate (``rates`` (3, K),
    :func:`_rate_columns`;
    :func:`~freestand.core.dynamics.results.interval_peak`, as the planar
    engine's peaks): a random box's rocking excursion of 38 ms, stepped at
    the record's 5 ms, peaked 3.8 % above its largest row. A row at an event
    (``event_times`` [s], ascending, as ``time``) holds the state after it (an
    impact's velocities): it keeps its value, and no step ending there is
    refined on its rates.
    """
    top_tilt, top_slide, top_twist, top_high, free = 0.0, 0.0, 0.0, -math.inf, 0.0
    event = 0  # the first event at or after the row's time
    size_before, skipped_before = 0.0, True
    for i in range(tilt.shape[0]):
        size = norm2(slide[i, 0], slide[i, 1])
        top_tilt = max(top_tilt, tilt[i])
        top_slide = max(top_slide, size)
        top_twist = max(top_twist, abs(twist[i]))
        top_high = max(top_high, highest[i])
        if modes[i, 0] == FREE:
            free = 1.0
        while event < event_times.shape[0] and event_times[event] < time[i]:
            event += 1
        skipped = event < event_times.shape[0] and event_times[event] == time[i]
        if i > 0 and not skipped and not skipped_before:
            h = time[i] - time[i - 1]
            top_tilt = max(top_tilt, interval_peak(h, tilt[i - 1], tilt[i], rates[0, i - 1],
                                                   rates[0, i]))  # fmt: skip
            top_slide = max(top_slide, interval_peak(h, size_before, size, rates[1, i - 1],
                                                     rates[1, i]))  # fmt: skip
            top_twist = max(top_twist, interval_peak(h, twist[i - 1], twist[i], rates[2, i - 1],
                                                     rates[2, i]))  # fmt: skip
        size_before, skipped_before = size, skipped
    return top_tilt, top_slide, top_twist, top_high, free


@nb.njit(cache=True, error_model="numpy")
def _rate_columns(columns, base, rates):
    """``rates`` (3, K): the rates of the tilt, the slide's size and the twist of each state.

    The states (r, q, v, omega) in ``columns`` (13, K); ``base`` R c and the
    slide [m] (:func:`_base_columns`). With omega in the
    support frame and e = R e_z the body's axis, ``tilt' = -(omega x e)_z /
    sin(tilt)``; the base centre ``r - R c`` moves at ``v - omega x (R
    c)``, ``|s|' = s . v_b / |s|``; with q = (w, x, y, z), ``twist = 2
    atan2(z, w)``, ``twist' = 2 (w z' - z w') / (w^2 + z^2)``, ``q' = (0,
    omega) q / 2``. Zero where the quotient's denominator is (no slide,
    upside down), and the tilt's where the body is flat (``sin(tilt)``
    within ``FLAT_TILT``).
    """
    for i in range(columns.shape[1]):
        w, x, y, z = columns[3, i], columns[4, i], columns[5, i], columns[6, i]
        _, _, r02, _, _, r12, _, _, _ = quaternion_rotation(w, x, y, z)
        cx, cy, cz = base[0, i], base[1, i], base[2, i]
        vx, vy = columns[7, i], columns[8, i]
        wx, wy, wz = columns[10, i], columns[11, i], columns[12, i]
        lean = norm2(r02, r12)
        turn = wx * r12 - wy * r02  # (omega x e)_z
        rates[0, i] = -turn / lean if lean > FLAT_TILT else 0.0
        # the base centre's horizontal velocity v - omega x (R c)
        bx = vx - (wy * cz - wz * cy)
        by = vy - (wz * cx - wx * cz)
        slide_x, slide_y = base[4, i], base[5, i]
        size = norm2(slide_x, slide_y)
        rates[1, i] = (slide_x * bx + slide_y * by) / size if size > 0.0 else 0.0
        w_rate = -0.5 * (wx * x + wy * y + wz * z)
        z_rate = 0.5 * (w * wz + wx * y - wy * x)
        norm = w * w + z * z
        rates[2, i] = 2.0 * (w * z_rate - z * w_rate) / norm if norm > 0.0 else 0.0


def rotation_matrices(quaternions: np.ndarray) -> np.ndarray:
    """(K, 3, 3) rotation matrices, body to support frame, of (K, 4) quaternions (w, x, y, z)."""
    w, x, y, z = quaternions.T
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
    ], axis=1)  # fmt: skip


def run_body_history(
    body: Body,
    motion: SupportMotion3,
    duration: float | None = None,
    *,
    until_rest: bool = False,
    free_time: float = 10.0,
    max_step: float | None = None,
    gravity: float = GRAVITY,
    **options,
) -> tuple[BodyTimeHistory, str, str]:
    """The time history of a body with its verdict: (history, status, message).

    The run of :func:`freestand.simulate` on a 3-D configuration and of a
    3-D fragility campaign's simulations: :func:`simulate_body` to
    ``duration`` (default the record; with ``until_rest``, the record plus
    ``free_time`` [s]), then :func:`body_verdict`.

    Parameters
    ----------
    body : Body
    motion : SupportMotion3
        Support accelerations [m/s^2], turned as wished.
    duration : float, optional
        End time [s].
    until_rest : bool, optional
        Go on after the record until the body rests, at most ``free_time`` [s].
    free_time : float, optional
        Cap on the time after the record [s] (``until_rest``).
    max_step, gravity, options
        As for :func:`simulate_body` (``tolerances``, ``initial``, ``restitution``).

    Returns
    -------
    tuple
        (BodyTimeHistory, status, message) of :func:`body_verdict`.
    """
    if until_rest and duration is None:
        if not (free_time >= 0.0 and math.isfinite(free_time)):
            raise FreestandError(f"free_time must be a finite time >= 0 [s], not {free_time!r}")
        end = motion.duration + free_time
    else:
        end = motion.duration if duration is None else float(duration)
    history = simulate_body(body, motion, end, max_step=max_step, gravity=gravity, **options)
    return body_verdict(history, motion.duration, until_rest)


def body_verdict(history: BodyTimeHistory, record_end: float, until_rest: bool):
    """(history, status, message); with ``until_rest`` the history ends where the body rests.

    Status ``"completed"`` (to the end, at rest, or overturned), ``"capped"``
    (``until_rest`` and still moving at the end) or ``"failed"`` (the contact
    was lost). At rest: flat, sticking, no velocity component above
    :data:`REST_VELOCITY`, after the record.
    """
    if history.status == "failed":
        remedies = history.diagnostics.get("remedies", 0)
        cause = (
            f" (after {remedies} contact states without a lasting admissible mode, continued"
            " by velocity-level time stepping: a limitation of this version's 3-D engine)"
            if remedies
            else ""
        )
        return history, "failed", history.message + cause
    if history.overturned:
        return history, "completed", f"overturned at t = {history.overturn_time:.6g} s"
    end = float(history.time[-1])
    if not until_rest:
        return history, "completed", f"simulated to t = {end:.6g} s"
    moving = (
        (history.patch != FACE)
        | history.sliding
        | (np.max(np.abs(history.state[:, 7:13]), axis=1) > REST_VELOCITY)
        | (history.time < record_end)
    )
    if moving[-1]:
        return history, "capped", f"still moving at the cap, t = {end:.6g} s"
    rest = int(np.flatnonzero(moving)[-1]) + 1 if moving.any() else 0
    kept = slice(0, rest + 1)
    arrays = ("time", "state", "patch", "sliding", "normal_force", "friction_force", "tilt",
              "slide", "twist")  # fmt: skip
    history = replace(history, **{name: getattr(history, name)[kept] for name in arrays})
    return history, "completed", f"at rest at t = {float(history.time[-1]):.6g} s"


def tilt_vector(quaternions: np.ndarray, tilt: np.ndarray) -> np.ndarray:
    """(K, 2) [rad]: ``tilt (e_x, e_y) / |(e_x, e_y)|``, e the body axis R e_z (0 when upright)."""
    w, x, y, z = quaternions.T
    axis = np.column_stack([2.0 * (x * z + w * y), 2.0 * (y * z - w * x)])
    size = np.hypot(axis[:, 0], axis[:, 1])
    scale = np.divide(tilt, size, out=np.zeros_like(tilt), where=size > 0.0)
    return axis * scale[:, None]
