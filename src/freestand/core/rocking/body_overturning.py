"""Minimum overturning amplitude of pulses for a 3-D body excited in a direction (issue #18).

A box or cylinder (:class:`freestand.core.body.Body`) on the support is
shaken by one acceleration pulse along the horizontal direction phi, the
support acceleration ``a s(t) (cos phi, sin phi, 0)`` with s(t) the unit
half-sine ``sin(omega t)``, ``0 <= t <= pi / omega`` (Housner 1963), or the
one-sine / one-cosine pulse (Zhang and Makris 2001, types A and B, over one
period). The lowest amplitude a that overturns it, against the frequency
``f = omega / (2 pi)``, is the 3-D counterpart of the planar exact limit of
:func:`freestand.core.rocking.integrator.exact_minimum_overturning_amplitude`
(the paper's Fig. 7):

- the motion is the 3-D engine's
  (:func:`freestand.core.dynamics.body_engine.run`: exact rigid contact,
  Coulomb friction on the circular cone, plastic impacts), so the body may
  slide, twist, rock about an edge or a corner, or roll on its rim;
- the pulse is sampled with ``SAMPLES_PER_PULSE`` samples and linear between
  them (the engine takes a sampled record): the impulse of the half-sine is
  then short by a relative ``(pi / N)^2 / 12`` (5e-6 for N = 400), and the
  overturning amplitude is exact to about that;
- the search is the planar one
  (:func:`freestand.core.rocking.amplitude_search.lowest_overturning_amplitude`):
  overturning is not monotone in the amplitude (a block can overturn after
  an impact at amplitudes below those at which it overturns without one,
  Zhang and Makris 2001; Makris and Roussos 2000), so the amplitude is
  scanned up from the uplift threshold, local maxima of the margin are
  refined, and the first overturning amplitude is bisected;
- after the pulse the motion is simulated on, free, until the body has
  overturned (the engine: tilt pi/2, or pivoting past its top after the
  excitation) or its energy ``E = 1/2 m v^2 + 1/2 omega . I omega + m g' z_G``
  is below the barrier ``m g' d`` with d the smallest distance from the
  centre of gravity to the base's outline: without excitation the energy
  cannot grow, and to tip over the body must lift its centre of gravity over
  a point of that outline, so it cannot overturn any more. As the planar
  decision from energy, but simulated, since in 3-D the free motion has no
  closed form. The free motion is cut after ``FREE_PERIODS`` periods
  ``2 pi / p`` of the slowest rocking (p of the excitation's plane, see
  :func:`excitation_plane_block`); a cut motion counts as not overturned and
  is counted in the diagnostics (``undecided``).

A body that friction keeps flat (``mu_0 h < r``, r the distance from G's
projection to the base's outline: :func:`slides_flat`) slides and never
lifts: it is not searched, and nothing overturns it.

The margin that the search refines is the energy at the end of the pulse
over that barrier, ``(E - m g' h) / (m g' (d - h))`` (h the height of the
centre of gravity at rest): the planar margin for a cylinder or a square box
along an axis.

A constant downward vertical support acceleration a_v (the planar
``--include-vertical``) reduces the weight to ``m g'``, ``g' = g - a_v``,
throughout, as the planar limits do.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numba as nb
import numpy as np

from freestand.core.body import Body, Box, base_ray_distance
from freestand.core.contact.body_impulse import IMPULSE_WORK_DTYPE
from freestand.core.contact.body_kernel import (
    DATA_SIZE,
    P_MASS,
    SCRATCH_DTYPE,
    STATE_SIZE,
    body_parameters,
    energy,
    support_acceleration,
)
from freestand.core.contact.body_screening import pivot_label, uplift_threshold
from freestand.core.dynamics import body_engine as engine
from freestand.core.dynamics import body_state
from freestand.core.dynamics.body_history import GRAVITY, default_body_step, initial_state
from freestand.core.dynamics.results import ContactTolerances
from freestand.core.motion.ground_motion import half_sine_pulse, one_cosine_pulse, one_sine_pulse
from freestand.core.rocking.amplitude_search import lowest_overturning_amplitude
from freestand.core.rocking.overturning import OverturningLimits, limits_with_operating
from freestand.core.rocking.properties import RockingBlock
from freestand.errors import FreestandError

#: The unit pulses by kind: s(t) sampled at a step [s] for a frequency [Hz].
PULSES = {"half-sine": half_sine_pulse, "one-sine": one_sine_pulse, "one-cosine": one_cosine_pulse}

#: Name of the 3-D limit in :attr:`BodyOverturningCurve.limits`.
EXACT_3D = "exact-3d"

#: Samples of a pulse (linear between them) [-]; the planar search takes 400 steps per pulse.
SAMPLES_PER_PULSE = 400

#: Free motion after the pulse is simulated for at most this many periods 2 pi / p [-].
FREE_PERIODS = 10.0

#: Default ratio between successive amplitudes of the scan [-]: coarser than the planar
#: 1.002 (each amplitude is a 3-D simulation); bands narrower than it can be missed unless
#: the margin refinement catches them.
SCAN_RATIO = 1.01

#: Default relative width of the final bisection bracket [-] (the pulse's sampling is
#: good to about 5e-6).
REL_TOL = 1e-5

#: Default search limit, as a multiple of Housner's half-sine amplitude of the excitation's
#: plane (the planar search's 10 and 40) [-].
MAX_FACTOR = {"half-sine": 10.0, "one-sine": 40.0, "one-cosine": 40.0}

# counters of the compiled search, per frequency
_SIMULATIONS = 0
_UNDECIDED = 1
_FAILED = 2
_REMEDIES = 3
_STRETCH_STEPS = 4
_COUNTERS = 5

_BUFFER = 64  # rows of the engine's output buffer (the history is not kept)
_CHECK_STEPS = 20  # the free motion's energy is checked every so many largest steps

#: A simulation fails when its energy exceeds the rest energy plus the excitation's work by
#: more than this fraction of the barrier m g' (d - h) [-] (the work's trapezoidal rule
#: between steps is good to far less).
ENERGY_SLACK = 1e-2


def tipping_distance(body: Body) -> float:
    """Smallest distance d [m] from the centre of gravity to the outline of the base.

    To tip over, the body must bring its centre of gravity over a point of
    that outline, at a height of at least d: ``m g' d`` is the lowest energy
    barrier to overturning (box: the four base edges as segments; cylinder:
    the rim, ``sqrt((R - |c_xy|)^2 + h^2)`` for the centre c).
    """
    centre = np.asarray(body.centre, dtype=float)
    if isinstance(body.shape, Box):
        corners = body.shape.base_corners()
        distances = []
        for k in range(4):
            a, b = corners[k], corners[(k + 1) % 4]
            along = np.clip((centre - a) @ (b - a) / ((b - a) @ (b - a)), 0.0, 1.0)
            distances.append(float(np.linalg.norm(centre - (a + along * (b - a)))))
        return min(distances)
    offset = math.hypot(centre[0], centre[1])
    return math.hypot(body.shape.radius - offset, centre[2])


def base_inradius(body: Body) -> float:
    """Horizontal distance [m] from the centre of gravity's projection to the base's outline.

    Box: ``min(b_x - |c_x|, b_y - |c_y|)``; cylinder: ``R - |c_xy|``.
    """
    cx, cy = float(body.centre[0]), float(body.centre[1])
    if isinstance(body.shape, Box):
        return min(0.5 * body.shape.size[0] - abs(cx), 0.5 * body.shape.size[1] - abs(cy))
    return body.shape.radius - math.hypot(cx, cy)


def slides_flat(body: Body) -> bool:
    """Whether friction keeps the body flat under any horizontal excitation: ``mu_0 h < r``.

    r from :func:`base_inradius`, h the height of G. Flat on the support, the
    horizontal contact force is at most ``mu_0 N`` (static, and the kinetic
    coefficient is not larger), so the centre of pressure stays within
    ``mu_0 h`` of G's projection, inside the base: the base never lifts,
    whatever the horizontal pulse and a constant vertical acceleration (as
    the screening's flat slide, ``docs/three-d.md``). Such a body slides and
    never overturns.
    """
    return body.friction.static * body.centre_height < base_inradius(body)


def largest_horizontal(excitations) -> float | None:
    """The largest horizontal magnitude ``|(x, y)|`` of the excitations [m/s^2], None if none."""
    if not excitations:
        return None
    return max(math.hypot(e.horizontal, e.horizontal_y) for e in excitations)


def easiest_direction(body: Body, vertical: float = 0.0, gravity: float = GRAVITY,
                      count: int = 24) -> float:  # fmt: skip
    """phi [deg] of the lowest uplift threshold among ``count`` directions evenly over 0-360
    (the first of equal ones; a cylinder with G on its axis: 0)."""
    directions = 360.0 * np.arange(count) / count
    thresholds = [uplift_threshold(body, math.radians(d), vertical, gravity) for d in directions]
    lowest = min(thresholds)
    return float(directions[next(k for k, a in enumerate(thresholds) if a <= lowest * (1 + 1e-12))])


def excitation_plane_block(
    body: Body, direction: float, gravity: float = GRAVITY, vertical: float = 0.0
) -> RockingBlock:
    """The planar rocking block of the body in the vertical plane of the excitation.

    Rocking about the horizontal line perpendicular to ``u = (cos phi, sin phi)``
    through the point where the line of action leaves the base towards -u
    (the pivot of :func:`freestand.core.contact.body_screening.initial_motion`),
    and back about the point of the outline towards +u: half-widths the
    distances from the centre of gravity's projection to the outline along
    -u and +u (:func:`freestand.core.body.base_ray_distance`), height h, and
    the inertia about the centre for rotation in that plane ``e . I e``,
    ``e = (-sin phi, cos phi, 0)``.

    For a cylinder with its centre on the axis (any direction) and a box with
    its centre over the base centre excited along a principal axis, the
    plane is one of symmetry and the 3-D motion is this block's (Housner
    1963): a cylinder's ``I_O = I_xx + m (R^2 + h^2)`` about its rim point.
    Otherwise it is a reference only (sets the search's scale).

    Parameters
    ----------
    body : Body
        The body.
    direction : float
        phi [rad].
    gravity : float, optional
        g [m/s^2].
    vertical : float, optional
        Constant downward support acceleration a_v [m/s^2].
    """
    u = (math.cos(direction), math.sin(direction))
    origin = body.centre[:2]
    towards = base_ray_distance(body.shape, origin, (-u[0], -u[1]))
    away = base_ray_distance(body.shape, origin, u)
    e = np.array([-u[1], u[0], 0.0])
    inertia = float(e @ np.asarray(body.inertia) @ e)
    height = body.centre_height
    return RockingBlock(body.mass, inertia, (towards, -height), (-away, -height),
                        gravity=gravity, vertical_acceleration=vertical)  # fmt: skip


@dataclass(frozen=True)
class BodyOverturningCurve:
    """Minimum overturning amplitude of one pulse kind against frequency, 3-D body, one direction.

    Attributes
    ----------
    body : str
        The body's name.
    direction : float
        phi [deg] of the pulse, from +x towards +y.
    limits : OverturningLimits
        ``limits.limits["exact-3d"]``: the lowest overturning amplitude
        [m/s^2] at each ``limits.frequency`` [Hz] (inf where none was found up
        to ``search_limit``); ``found``; with an operating amplitude, the
        frequency up to which it overturns the body
        (``operating_frequency["exact-3d"]``).
    uplift_threshold : float
        a* [m/s^2] in the direction (rocking starts above it; the scan starts
        there; for the one-sine and one-cosine pulses, the lower of both senses).
    pivot : str
        What the body tips about first (``"edge +x"``, ``"corner -x-y"``,
        ``"rim at 180 deg"``).
    tipping_distance : float
        d [m] (:func:`tipping_distance`).
    vertical_acceleration : float
        Constant downward a_v [m/s^2] in the weight m (g - a_v).
    gravity : float
        g [m/s^2].
    search_limit : numpy.ndarray
        Largest amplitude tried at each frequency [m/s^2].
    scan_ratio, rel_tol : float
        Ratio between the scan's amplitudes and the bisection's relative bracket [-].
    samples_per_pulse : int
        Samples of the pulse [-].
    slides_flat : bool
        Friction keeps the base flat (:func:`slides_flat`): no search was
        run, nothing overturns (``found`` all False).
    simulations, failed, undecided, remedies, stretch_steps : numpy.ndarray
        Per frequency: the 3-D simulations the search ran; those whose
        energy rose above the excitation's work (counted as not overturned:
        where there are any, the limit is not to be trusted); the free
        motions cut after ``FREE_PERIODS`` periods (counted as not
        overturned); the engine's remedies over all simulations and the steps
        of its time-stepping stretches.
    """

    body: str
    direction: float
    limits: OverturningLimits
    uplift_threshold: float
    pivot: str
    tipping_distance: float
    vertical_acceleration: float
    gravity: float
    search_limit: np.ndarray
    scan_ratio: float
    rel_tol: float
    samples_per_pulse: int
    slides_flat: bool
    simulations: np.ndarray
    failed: np.ndarray
    undecided: np.ndarray
    remedies: np.ndarray
    stretch_steps: np.ndarray

    @property
    def kind(self) -> str:
        """The pulse kind."""
        return self.limits.kind

    @property
    def frequency(self) -> np.ndarray:
        """Pulse frequencies f [Hz]."""
        return self.limits.frequency

    @property
    def amplitude(self) -> np.ndarray:
        """Lowest overturning amplitude [m/s^2] (inf where none was found)."""
        return self.limits.limits[EXACT_3D]

    @property
    def found(self) -> np.ndarray:
        """Whether an overturning amplitude was found (bool)."""
        return self.limits.found


# ------------------------------------------------------------------------------------
# compiled: one simulation per amplitude, the shared search per frequency
# ------------------------------------------------------------------------------------
@nb.njit(cache=True)
def _inertial_work(par, record, dt, out_t, out_y, count):
    """Work [J] of the support's inertial force on the body over the first ``count`` rows.

    The force ``m (-a_x, -a_y, a_v)`` at G (a_v downward), its power on the
    velocity of G integrated by the trapezoidal rule between the rows.
    """
    mass = par[P_MASS]
    work = 0.0
    for i in range(count - 1):
        power = 0.0
        for j in (i, i + 1):
            a_x, a_y, a_v = support_acceleration(record, dt, out_t[j])
            power += mass * (-a_x * out_y[j, 7] - a_y * out_y[j, 8] + a_v * out_y[j, 9])
        work += 0.5 * power * (out_t[i + 1] - out_t[i])
    return work


@nb.njit(cache=True)
def _run_to(par, record, dt, breaks, h_max, t_end, record_end, gap_tol, velocity_tol, t, y,
            mode, data, scratch, impulse_work, istate, buffers, events, work):  # fmt: skip
    """The engine from t to ``t_end`` (or overturning); adds the inertial work to ``work[0]``.

    The output buffer is reused: after each call of the engine its rows are
    integrated and the last one is moved to the top (the history is not kept).
    """
    out_t, out_y, out_mode, out_force = buffers
    ev_time, ev_kind, ev_before, ev_after = events
    while True:
        t = engine.run(par, record, dt, breaks, h_max, t_end, record_end, gap_tol, velocity_tol,
                       t, y, mode, data, scratch, impulse_work, istate, out_t, out_y, out_mode,
                       out_force, ev_time, ev_kind, ev_before, ev_after)  # fmt: skip
        last = istate[body_state.I_RECORDS] - 1
        work[0] += _inertial_work(par, record, dt, out_t, out_y, last + 1)
        out_t[0] = out_t[last]
        out_y[0] = out_y[last]
        out_mode[0] = out_mode[last]
        out_force[0] = out_force[last]
        istate[body_state.I_RECORDS] = 1
        if istate[body_state.I_STATUS] != body_state.STATUS_BUFFER_FULL:
            return t


@nb.njit(cache=True)
def _pulse_record(unit, along, amplitude):
    """The (3, n) record x, y, vertical of the pulse ``amplitude * unit`` along ``along``."""
    n = unit.shape[0]
    record = np.zeros((3, n))
    for i in range(n):
        record[0, i] = amplitude * along[0] * unit[i]
        record[1, i] = amplitude * along[1] * unit[i]
    return record


@nb.njit(cache=True)
def _sound(e, e_rest, work, slack):
    """False when the energy balance is broken.

    Apart from the support's inertial force only impacts, friction and the
    engine's remedies (energy-checked velocity-level steps) act, and they
    dissipate: ``E - E_rest - W <= 0``, W the inertial force's work
    (:func:`_inertial_work`).
    """
    return e - e_rest - work[0] <= slack


@nb.njit(cache=True)
def _pulse_outcome(context, amplitude):
    """(overturned, margin) of the body under the pulse of ``amplitude`` [m/s^2].

    The pulse, then the free motion until the body overturns or its energy is
    below the barrier (module docstring). ``context`` = (par, unit pulse (n,),
    dt [s], along (2,) unit direction, h_max [s], rest state (13,), gap [m]
    and velocity [m/s] tolerances, rest and barrier energies [J], free time
    [s], counters (3,) of this frequency); the simulator of
    :func:`freestand.core.rocking.amplitude_search.lowest_overturning_amplitude`.

    A simulation whose energy rose above what the excitation put in (by more
    than ``ENERGY_SLACK`` of the barrier) counts as failed and as not
    overturned, with margin 0. The engine's remedies (a velocity-level impact
    or a stretch of time stepping where the contact problem has no
    consistent mode; they never add energy) are legitimate steps, counted.
    """
    (par, unit, dt, along, h_max, rest, gap_tol, velocity_tol, e_rest, e_barrier, free_time,
     counters) = context  # fmt: skip
    length = (unit.shape[0] - 1) * dt
    record = _pulse_record(unit, along, amplitude)
    breaks = np.arange(1, unit.shape[0]) * dt
    y = rest.copy()
    mode = np.zeros(3, dtype=np.int64)
    data = np.zeros(DATA_SIZE)
    istate = np.zeros(body_state.I_SIZE, dtype=np.int64)
    scratch = np.zeros(1, dtype=SCRATCH_DTYPE)  # the engine's scratch, alive for both runs
    impulse_work = np.zeros(1, dtype=IMPULSE_WORK_DTYPE)  # the engine's impulse work arrays
    buffers = (np.zeros(_BUFFER), np.zeros((_BUFFER, STATE_SIZE)),
               np.zeros((_BUFFER, 3), dtype=np.int64), np.zeros((_BUFFER, 2)))  # fmt: skip
    events = (np.zeros(0), np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64),
              np.zeros(0, dtype=np.int64))  # fmt: skip
    work = np.zeros(1)
    slack = ENERGY_SLACK * (e_barrier - e_rest)
    counters[_SIMULATIONS] += 1
    t = _run_to(par, record, dt, breaks, h_max, length, length, gap_tol, velocity_tol, 0.0, y,
                mode, data, scratch, impulse_work, istate, buffers, events, work)  # fmt: skip
    e = energy(par, y)
    margin = (e - e_rest) / (e_barrier - e_rest)
    end = length + free_time
    while (istate[body_state.I_STATUS] != body_state.STATUS_OVERTURNED and e >= e_barrier
           and t < end and _sound(e, e_rest, work, slack)):  # fmt: skip
        t_next = min(t + _CHECK_STEPS * h_max, end)
        t = _run_to(par, record, dt, breaks, h_max, t_next, length, gap_tol, velocity_tol, t, y,
                    mode, data, scratch, impulse_work, istate, buffers, events, work)  # fmt: skip
        e = energy(par, y)
    counters[_REMEDIES] += istate[body_state.I_REMEDIES]
    counters[_STRETCH_STEPS] += istate[body_state.I_STRETCH_STEPS]
    if not _sound(e, e_rest, work, slack):
        counters[_FAILED] += 1
        return False, 0.0
    if istate[body_state.I_STATUS] == body_state.STATUS_OVERTURNED:
        return True, 2.0 if t <= length else max(margin, 1.0)
    if e >= e_barrier:
        counters[_UNDECIDED] += 1
    return False, margin


@nb.njit(cache=True, parallel=True)
def _lowest_amplitudes(par, units, dts, along, h_max, rest, gap_tol, velocity_tol, e_rest,
                       e_barrier, free_time, a_lo, a_his, ratio, rel_tol, result, status,
                       counters):  # fmt: skip
    """The shared search for each frequency (one unit pulse per row of ``units``), in parallel."""
    for i in nb.prange(units.shape[0]):
        context = (par, units[i], dts[i], along, h_max, rest, gap_tol, velocity_tol, e_rest,
                   e_barrier, free_time, counters[i])  # fmt: skip
        a, s = lowest_overturning_amplitude(_pulse_outcome, context, a_lo, a_his[i], ratio,
                                            rel_tol)  # fmt: skip
        result[i] = a
        status[i] = s


# ------------------------------------------------------------------------------------
# Python API
# ------------------------------------------------------------------------------------
def unit_pulse(kind: str, frequency: float, samples: int = SAMPLES_PER_PULSE):
    """(step [s], samples of s(t) [-]) of the unit pulse of ``kind`` at ``frequency`` [Hz]."""
    length = (0.5 if kind == "half-sine" else 1.0) / frequency
    dt = length / samples
    values = PULSES[kind](1.0, frequency=frequency, dt=dt).horizontal
    return dt, np.ascontiguousarray(values[: samples + 1])


def body_overturning_limits(
    body: Body,
    frequency,
    direction: float,
    *,
    kind: str = "half-sine",
    vertical_acceleration: float = 0.0,
    gravity: float = GRAVITY,
    operating_amplitude: float | None = None,
    scan_ratio: float = SCAN_RATIO,
    rel_tol: float = REL_TOL,
    max_factor: float | None = None,
    samples_per_pulse: int = SAMPLES_PER_PULSE,
    tolerances: ContactTolerances | None = None,
    progress: Callable[[], None] | None = None,
) -> BodyOverturningCurve:
    """Lowest amplitude of a pulse along ``direction`` that overturns a 3-D body, per frequency.

    Parameters
    ----------
    body : Body
        The box or cylinder, at rest on the support.
    frequency : array_like
        Increasing pulse frequencies f [Hz].
    direction : float
        phi [deg] of the pulse's positive acceleration, from +x towards +y.
    kind : {"half-sine", "one-sine", "one-cosine"}, optional
        The pulse (module docstring).
    vertical_acceleration : float, optional
        Constant downward support acceleration a_v [m/s^2]: weight m (g - a_v).
    gravity : float, optional
        g [m/s^2].
    operating_amplitude : float, optional
        Amplitude of interest [m/s^2]: the result says up to which frequency it
        overturns the body.
    scan_ratio : float, optional
        Ratio between successive amplitudes of the scan (> 1) [-].
    rel_tol : float, optional
        Relative width of the final bisection bracket [-].
    max_factor : float, optional
        The scan stops at this multiple of Housner's half-sine amplitude of the
        excitation's plane (:func:`excitation_plane_block`; default 10 for the
        half-sine, 40 for the others, at least 20 times the uplift threshold).
    samples_per_pulse : int, optional
        Samples of the pulse (linear between them) [-].
    tolerances : ContactTolerances, optional
        The engine's contact tolerances.
    progress : callable, optional
        Called once per frequency done.

    Returns
    -------
    BodyOverturningCurve

    Notes
    -----
    For a cylinder this equals the planar exact limit
    (:func:`freestand.core.rocking.integrator.exact_minimum_overturning_amplitude`)
    of the block of its own inertia (:func:`excitation_plane_block`), in every
    direction, as long as friction holds the rim (``tests/validation``).
    """
    if kind not in PULSES:
        raise FreestandError(
            f"unknown pulse kind {kind!r} for a 3-D body; use one of {', '.join(PULSES)}",
            field="pulse",
        )
    f = np.atleast_1d(np.asarray(frequency, dtype=float)).ravel()
    if f.size == 0 or np.any(~(f > 0)) or not np.all(np.isfinite(f)) or np.any(np.diff(f) <= 0):
        raise ValueError("frequency must be increasing, positive and finite values [Hz]")
    if not scan_ratio > 1:
        raise ValueError(f"scan_ratio must exceed 1, got {scan_ratio!r}")
    if not 0 < rel_tol < 1:
        raise ValueError(f"rel_tol must be in (0, 1), got {rel_tol!r}")
    weight = gravity - vertical_acceleration
    if not weight > 0:
        raise FreestandError(
            f"the weight m (g - a_v) must be positive (g = {gravity:g}, a_v = "
            f"{vertical_acceleration:g} m/s^2): a downward support acceleration of g or more "
            "lifts the body off the support",
            field="vertical",
        )
    tolerances = tolerances or ContactTolerances()
    phi = math.radians(direction)
    plane = excitation_plane_block(body, phi, gravity, vertical_acceleration)
    a_lo = uplift_threshold(body, phi, vertical_acceleration, gravity)
    if kind != "half-sine":
        a_lo = min(a_lo, uplift_threshold(body, phi + math.pi, vertical_acceleration, gravity))
    factor = MAX_FACTOR[kind] if max_factor is None else float(max_factor)
    a_hi = np.maximum(factor * np.asarray(plane.housner_half_sine_amplitude(f)), 20.0 * a_lo)
    par = body_parameters(body, weight)
    rest = initial_state(body)
    distance = tipping_distance(body)
    e_rest = body.mass * weight * rest[2]
    e_barrier = body.mass * weight * distance
    p_slowest = min(plane.about("pivot").p, plane.about("other").p)
    free_time = FREE_PERIODS * 2.0 * math.pi / p_slowest
    h_max = default_body_step(body, weight)
    along = np.array([math.cos(phi), math.sin(phi)])
    pulses = [unit_pulse(kind, value, samples_per_pulse) for value in f]
    units = np.array([values for _dt, values in pulses])
    dts = np.array([dt for dt, _values in pulses])
    result = np.empty(f.size)
    status = np.empty(f.size, dtype=np.int64)
    counters = np.zeros((f.size, _COUNTERS), dtype=np.int64)
    flat = slides_flat(body)
    if flat:
        result[:] = math.inf
        status[:] = 1
    batch = max(1, nb.get_num_threads())
    for start in range(0, 0 if flat else f.size, batch):
        part = slice(start, min(start + batch, f.size))
        _lowest_amplitudes(par, units[part], dts[part], along, h_max, rest, tolerances.gap,
                           tolerances.velocity, e_rest, e_barrier, free_time, a_lo, a_hi[part],
                           float(scan_ratio), float(rel_tol), result[part], status[part],
                           counters[part])  # fmt: skip
        if progress is not None:
            for _ in range(part.stop - part.start):
                progress()
    if flat and progress is not None:
        for _ in range(f.size):
            progress()
    limits = limits_with_operating(kind, f, {EXACT_3D: result}, status == 0, operating_amplitude)
    return BodyOverturningCurve(
        body=body.name,
        direction=float(direction),
        limits=limits,
        uplift_threshold=float(a_lo),
        pivot=pivot_label(body, phi),
        tipping_distance=distance,
        vertical_acceleration=float(vertical_acceleration),
        gravity=float(gravity),
        search_limit=a_hi,
        scan_ratio=float(scan_ratio),
        rel_tol=float(rel_tol),
        samples_per_pulse=int(samples_per_pulse),
        slides_flat=flat,
        simulations=counters[:, _SIMULATIONS].copy(),
        failed=counters[:, _FAILED].copy(),
        undecided=counters[:, _UNDECIDED].copy(),
        remedies=counters[:, _REMEDIES].copy(),
        stretch_steps=counters[:, _STRETCH_STEPS].copy(),
    )
