"""Types shared by every time-history path: support motion, tolerances, events, results.

:mod:`freestand.core.dynamics.timehistory` (the general event-driven path and
the front end) and :mod:`freestand.core.dynamics.single_block` (the exact
single-block fast path) both return a :class:`TimeHistoryResult` built from
these; they live here so that neither path imports the other's module.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numba as nb
import numpy as np

#: Events on forces fire below ``-EVENT_TOLERANCE * force scale`` (larger than
#: the contact solver's tolerance, so that the state found by bisection is
#: unambiguous for the solver).
EVENT_TOLERANCE = 1e-7


#: A contact has lifted off (``uplift``) when its gap exceeds this fraction of
#: the base width of its interface [-]: 1 micrometre per metre of base. Smaller
#: openings (a contact mode that opens for an instant at round-off level) are
#: not a physical lift-off.
UPLIFT_GAP_FRACTION = 1e-6


@dataclass(frozen=True)
class SupportMotion:
    """Support accelerations sampled at a constant time step, piecewise linear in time.

    Parameters
    ----------
    time_step : float
        Sampling interval dt [s], positive.
    horizontal : numpy.ndarray
        Horizontal support acceleration a_h [m/s^2] at ``k dt``, +x positive.
    vertical : numpy.ndarray or None
        Downward support acceleration a_v [m/s^2] at ``k dt`` (the weight is
        ``m (g - a_v)``); None for none. Same length as ``horizontal``.

    Notes
    -----
    Before the first and after the last sample the accelerations are zero.

    Examples
    --------
    >>> import numpy as np
    >>> import freestand as fs
    >>> motion = fs.SupportMotion(0.01, np.array([0.0, 1.0, 0.0]), np.array([0.0, 0.5, 0.0]))
    >>> motion.time_step, motion.horizontal.tolist()
    (0.01, [0.0, 1.0, 0.0])
    """

    time_step: float
    horizontal: np.ndarray
    vertical: np.ndarray | None = None

    def __post_init__(self) -> None:
        if not (self.time_step > 0.0 and math.isfinite(self.time_step)):
            raise ValueError(f"time_step must be positive, not {self.time_step!r}")
        horizontal = np.asarray(self.horizontal, dtype=float)
        if horizontal.ndim != 1 or horizontal.size < 2:
            raise ValueError("horizontal must be a 1-D array of at least 2 samples")
        object.__setattr__(self, "horizontal", horizontal)
        if self.vertical is not None:
            vertical = np.asarray(self.vertical, dtype=float)
            if vertical.shape != horizontal.shape:
                raise ValueError(
                    f"vertical has {vertical.size} samples, horizontal {horizontal.size}; "
                    "give both at the same instants"
                )
            object.__setattr__(self, "vertical", vertical)

    @property
    def duration(self) -> float:
        """Time of the last sample [s]."""
        return (self.horizontal.size - 1) * self.time_step

    def __call__(self, time: float) -> tuple[float, float]:
        """(a_h, a_v) [m/s^2] at ``time`` [s] by linear interpolation."""
        position = time / self.time_step
        if position < 0.0 or position > self.horizontal.size - 1:
            return 0.0, 0.0
        index = min(int(position), self.horizontal.size - 2)
        fraction = position - index
        a_h = (1.0 - fraction) * self.horizontal[index] + fraction * self.horizontal[index + 1]
        if self.vertical is None:
            return float(a_h), 0.0
        a_v = (1.0 - fraction) * self.vertical[index] + fraction * self.vertical[index + 1]
        return float(a_h), float(a_v)


@dataclass(frozen=True)
class ContactTolerances:
    """Tolerances that decide the contact state from the kinematics.

    Parameters
    ----------
    gap : float
        A contact with ``gap <= gap`` [m] touches.
    velocity : float
        A touching contact is active when its gap velocity is ``<= velocity``
        [m/s]; a slip velocity within ``velocity`` counts as zero (the
        interface may stick).
    slide : float
        An end stop is engaged when the slide is within ``slide`` [m] of the
        parking position.
    """

    gap: float = 1e-7
    velocity: float = 1e-4
    slide: float = 1e-7


@dataclass(frozen=True)
class TimeHistoryEvent:
    """One event of a simulation.

    Attributes
    ----------
    time : float
        Time [s].
    kind : str
        ``"start"``, ``"impact"`` (a gap closed), ``"tangential-impact"`` (no
        consistent sliding state: a velocity jump in which sliding contacts
        may stick resolves it, Painleve's paradox), ``"lift-off"`` (a normal
        force reached zero), ``"slip"`` (static friction could no longer
        hold), ``"slip-stop"`` (a slip velocity reached zero), ``"stop-impact"``
        (a block slid back onto its end stop), ``"overturn"``,
        ``"time-stepping"`` (no consistent event-driven mode, or events
        accumulating: a stretch of velocity-impulse time stepping begins,
        see :mod:`freestand.core.dynamics.time_stepping`) and ``"resume"``
        (events take over again).
    interface : int
        Interface (= upper block index) concerned, -1 for none.
    contact : int
        0 left, 1 right, -1 for the whole interface.
    motions : tuple of str
        Motion of every block relative to the body below after the event
        (``rest``, ``slide``, ``rock``, ``slide-rock``, ``free-flight``,
        ``overturned``).
    velocity_before, velocity_after : numpy.ndarray
        Shape (B, 3): generalised velocities [m/s, rad/s] across the event
        (they differ at impacts).
    status : str
        Status of the contact solve after the event (``unique``,
        ``ambiguous``).
    """

    time: float
    kind: str
    interface: int
    contact: int
    motions: tuple[str, ...]
    velocity_before: np.ndarray = field(repr=False)
    velocity_after: np.ndarray = field(repr=False)
    status: str = "unique"

    @classmethod
    def _from_engine(
        cls,
        time: float,
        kind: str,
        interface: int,
        contact: int,
        motions: tuple[str, ...],
        velocity_before: np.ndarray,
        velocity_after: np.ndarray,
        status: str,
    ) -> TimeHistoryEvent:
        """The event with these fields, as the constructor makes it, at a third of its cost.

        A simulation builds one per event (hundreds of thousands in a campaign);
        the frozen dataclass's ``__init__`` sets each field through
        ``object.__setattr__``, this fills the instance's dictionary at once
        (the class has no ``__post_init__`` to run).
        """
        event = object.__new__(cls)
        event.__dict__.update(
            time=time,
            kind=kind,
            interface=interface,
            contact=contact,
            motions=motions,
            velocity_before=velocity_before,
            velocity_after=velocity_after,
            status=status,
        )
        return event


@dataclass(frozen=True)
class TimeHistoryDiagnostics:
    """How a simulation went.

    Attributes
    ----------
    time_step : float
        Integration step [s].
    steps : int
        Accepted steps.
    contact_solves : int
        Complete contact problems solved (start, events).
    impact_solves : int
        Impact problems solved.
    ambiguous_solves : int
        Contact or impact solves with several admissible states (the
        documented rule chose).
    max_penetration : float
        Largest penetration [m] found at an accepted step (before the
        projection back onto the contact).
    max_projection : float
        Largest position correction [m, rad] of the projection onto the closed
        contacts.
    method : str
        The path that produced the result: ``"general"`` (event-driven stack
        path), ``"single-block rocking"``, ``"single-block sliding"`` or
        ``"single-block rest"`` (the exact single-block equations, see
        :mod:`freestand.core.dynamics.single_block`).
    checks : tuple of str
        The assumptions of a single-block path, as verified, in words.
    fallback : str
        Why the single-block path was not used (its failed assumption), if
        it was tried; empty otherwise.
    stepped_time : float
        Time [s] integrated by velocity-impulse time stepping, the remedy
        where no event-driven contact mode is consistent (Painleve) or events
        accumulate (Zeno); see :mod:`freestand.core.dynamics.time_stepping`.
    stretches : tuple of (str, int)
        The stretches of time stepping begun, counted per cause (the
        situation each replaced: ``"contact problem inconsistent"``,
        ``"events repeat without progress"``, ``"events accumulate in a
        burst"`` (more than 200 events, each within 2 ms of the last), ...).
    energy_ratio : float
        Largest ratio of kinetic energies after and before the contact
        impulses of a time step, ``T(v+) / T(v_f)`` [-]: at most 1 (the
        impulses never create energy); 0 when no step was taken.
    dissipative_impacts : int
        Impacts whose enumerated velocity-level state would have raised the
        kinetic energy (kinetic friction acting against the slip before the
        impact, which the impact reversed), solved again by the dissipative
        velocity-level solver of the time stepping.
    zeno_landings : int
        Zeno sequences of impacts summed: once the support no longer
        accelerates, an impact after which the contact that opens could not
        rise beyond the gap tolerance before falling back ends its sequence
        there, the interface landing on both contacts (the remaining impacts,
        each lower than the last, would accumulate within about
        ``flight / (1 - ratio)`` [s]). While the support moves, an interface
        lands likewise after more than 100 such impacts in a row.
    """

    time_step: float
    steps: int
    contact_solves: int
    impact_solves: int
    ambiguous_solves: int
    max_penetration: float
    max_projection: float
    method: str = "general"
    checks: tuple[str, ...] = ()
    fallback: str = ""
    stepped_time: float = 0.0
    stretches: tuple[tuple[str, int], ...] = ()
    energy_ratio: float = 0.0
    dissipative_impacts: int = 0
    zeno_landings: int = 0


@dataclass(frozen=True)
class TimeHistoryResult:
    """Outcome of :func:`simulate`.

    Attributes
    ----------
    configuration : str
        Stack name.
    block_names : tuple of str
        Bottom to top.
    status : str
        ``"completed"`` (to the requested duration, until rest, or until
        every block overturned; stretches of time stepping where events could
        not continue are said in ``message`` and ``diagnostics``),
        ``"capped"`` (still moving at the cap of ``until_rest``) or
        ``"failed"`` (more than ``max_events`` events; see ``message``; the
        arrays hold the motion up to there).
    message : str
        What happened, in words.
    time : numpy.ndarray
        Shape (K,), non-decreasing [s]; an event appears as two rows at the
        same time (before and after).
    position, velocity : numpy.ndarray
        Shape (K, B, 3): ``(u_x, u_z, phi)`` [m, m, rad] of every block (its
        centre's displacement from rest relative to the support, its rotation)
        and their rates; NaN after the block overturned.
    normal_force : numpy.ndarray
        Shape (K, B, 2): normal force [N] on each block at its left and right
        lower contact.
    tangential_force : numpy.ndarray
        Shape (K, B): tangential force [N] on each block from the body below,
        along that body's surface.
    relative_rotation : numpy.ndarray
        Shape (K, B): rotation [rad] of each block relative to the body below.
    slide : numpy.ndarray
        Shape (K, B): slide [m] of each block along the body below from its
        starting position.
    events : tuple of TimeHistoryEvent
    max_rotation : numpy.ndarray
        Shape (B,): largest ``|relative rotation|`` [rad], refined between
        the steps by cubic Hermite interpolation.
    max_slide : numpy.ndarray
        Shape (B,): largest ``|slide|`` [m] per interface.
    uplift : numpy.ndarray
        Shape (B,), bool: a contact of the interface lifted off by more than
        :data:`UPLIFT_GAP_FRACTION` of the interface's base width (a
        momentary lift-off at round-off level does not count).
    free_flight : numpy.ndarray
        Shape (B,), bool: the block left the body below, both contacts open
        by more than that gap.
    overturned : numpy.ndarray
        Shape (B,), bool.
    overturn_time : numpy.ndarray
        Shape (B,): time of overturning [s], NaN if none.
    diagnostics : TimeHistoryDiagnostics
    max_lift : numpy.ndarray
        Shape (B,): largest gap [m] opened at a contact of each interface
        (the larger of the two contacts' gaps; 0 for none).

    Examples
    --------
    A homogeneous 0.4 x 2 m block under a 1 Hz half-sine of 2 m/s^2 (its
    uplift acceleration is g b / h = 1.96 m/s^2):

    >>> import numpy as np
    >>> import freestand as fs
    >>> block = fs.Block("cabinet", mass=400.0, inertia=400.0 * (0.4**2 + 2.0**2) / 12,
    ...                  centre=(0.0, 1.0), base_left=-0.2, base_right=0.2, base_level=0.0,
    ...                  friction=fs.Friction(0.8, 0.7))
    >>> t = np.arange(0.0, 0.5 + 1e-9, 0.005)
    >>> motion = fs.SupportMotion(0.005, 2.0 * np.sin(2 * np.pi * t))
    >>> result = fs.simulate(fs.Stack("cabinet", (block,)), motion, 3.0).core
    >>> result.status, bool(result.uplift[0]), bool(result.overturned[0])
    ('completed', True, False)
    >>> result.position.shape[1:]
    (1, 3)
    """

    configuration: str
    block_names: tuple[str, ...]
    status: str
    message: str
    time: np.ndarray = field(repr=False)
    position: np.ndarray = field(repr=False)
    velocity: np.ndarray = field(repr=False)
    normal_force: np.ndarray = field(repr=False)
    tangential_force: np.ndarray = field(repr=False)
    relative_rotation: np.ndarray = field(repr=False)
    slide: np.ndarray = field(repr=False)
    events: tuple[TimeHistoryEvent, ...] = field(repr=False)
    max_rotation: np.ndarray
    max_slide: np.ndarray
    uplift: np.ndarray
    free_flight: np.ndarray
    overturned: np.ndarray
    overturn_time: np.ndarray
    diagnostics: TimeHistoryDiagnostics = field(repr=False)
    max_lift: np.ndarray | None = None

    def block_index(self, name: str) -> int:
        """Index of the block called ``name``."""
        return self.block_names.index(name)

    def events_of(self, kind: str) -> tuple[TimeHistoryEvent, ...]:
        """The events of one kind, in time order."""
        return tuple(event for event in self.events if event.kind == kind)


def _peak_magnitude(time: np.ndarray, value: np.ndarray, rate: np.ndarray) -> float:
    """Largest ``|value|`` of a sampled motion, refined between samples.

    Where the rate changes sign inside a step the cubic Hermite interpolant
    of (value, rate) at the step ends gives the turning point, so the peak is
    found to the integration accuracy rather than to the sampling.
    """
    return float(
        peak_between_samples(
            np.ascontiguousarray(time, dtype=float),
            np.ascontiguousarray(value, dtype=float),
            np.ascontiguousarray(rate, dtype=float),
        )
    )


def history_peaks(
    time: np.ndarray, rotation: np.ndarray, rate: np.ndarray, slide: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Peak ``|rotation|`` and ``|slide|`` of every block of a sampled history.

    ``rotation``, ``rate`` [rad, rad/s] and ``slide`` [m] have shape (rows,
    B). The rotation's peak is refined between samples as in
    :func:`_peak_magnitude`; the slide's is the largest finite ``|slide|``
    (0 for none; NaN samples, of overturned blocks, skipped). One compiled
    pass over the columns, the values of :func:`_peak_magnitude` and of
    ``nan_to_num(nanmax(abs(slide), axis=0, initial=0))``.
    """
    return _history_peaks_kernel(np.ascontiguousarray(time, dtype=float), rotation, rate, slide)


@nb.njit(cache=True, error_model="numpy")
def _history_peaks_kernel(time, rotation, rate, slide):
    """:func:`history_peaks` compiled."""
    count = rotation.shape[1]
    max_rotation = np.empty(count)
    max_slide = np.empty(count)
    for i in range(count):
        max_rotation[i] = peak_between_samples(time, rotation[:, i], rate[:, i])
        peak = 0.0
        for k in range(slide.shape[0]):
            value = abs(slide[k, i])
            if value > peak:
                peak = value
        max_slide[i] = np.finfo(np.float64).max if math.isinf(peak) else peak
    return max_rotation, max_slide


@nb.njit(cache=True, error_model="numpy")
def peak_between_samples(time, value, rate):
    """:func:`_peak_magnitude` on float arrays, compiled; samples whose value or rate is not
    finite are skipped, and so are the steps next to them.

    ``time`` [s], ``value`` and its ``rate`` (per second) at the samples. Where the
    rate changes sign inside a step, the cubic Hermite interpolant of (value, rate)
    at its ends gives the turning point (the 3-D engine's peaks too,
    :mod:`freestand.core.dynamics.body_history`).
    """
    peak = 0.0
    count = value.shape[0]
    for k in range(count):
        if math.isfinite(value[k]) and math.isfinite(rate[k]):
            peak = max(peak, abs(value[k]))
    for k in range(count - 1):
        step = time[k + 1] - time[k]
        peak = max(peak, interval_peak(step, value[k], value[k + 1], rate[k], rate[k + 1]))
    return peak


@nb.njit(cache=True, error_model="numpy", inline="always")
def interval_peak(h, y0, y1, r0, r1):
    """|value| at a turning point inside a step of ``h`` [s]; 0.0 where it has none.

    The cubic Hermite interpolant of the values ``y0``, ``y1`` and their
    rates ``r0``, ``r1`` (per second) at the step's ends: where the rate
    changes sign, the root of its derivative inside the step, in the stable
    form of the quadratic's roots. 0.0 where a value or rate is not finite,
    the rate keeps its sign, or h is not positive.
    """
    peak = 0.0
    if not (math.isfinite(y0) and math.isfinite(y1) and math.isfinite(r0)
            and math.isfinite(r1)):  # fmt: skip
        return peak
    if not r0 * r1 < 0.0:
        return peak
    if not h > 0.0:
        return peak
    m0 = r0 * h
    m1 = r1 * h
    # p(s) = y0 + m0 s + (3 (y1 - y0) - 2 m0 - m1) s^2 + (2 (y0 - y1) + m0 + m1) s^3
    c2 = 3.0 * (y1 - y0) - 2.0 * m0 - m1
    c3 = 2.0 * (y0 - y1) + m0 + m1
    # roots of p'(s) = 3 c3 s^2 + 2 c2 s + m0 in the stable form q = -(b + sgn(b) sqrt(d)) / 2
    a = 3.0 * c3
    b = 2.0 * c2
    discriminant = b * b - 4.0 * a * m0
    root = math.sqrt(discriminant) if discriminant >= 0.0 else math.nan
    q = -0.5 * (b + (root if b >= 0.0 else -root))
    for s in (q / a, m0 / q):
        if math.isfinite(s) and s > 0.0 and s < 1.0:
            candidate = y0 + (m0 + (c2 + c3 * s) * s) * s
            peak = max(peak, abs(candidate))
    return peak


#: Solvers of :func:`simulate`.
METHODS = ("auto", "general", "single-block")
