"""Public time history of a 3-D configuration: :func:`support_motion3` and its result.

:func:`freestand.api.simulation.simulate` dispatches here when the
configuration is 3-D (a box or a cylinder,
:class:`~freestand.core.body.BodyConfiguration`); the engine is
:func:`freestand.core.dynamics.body_history.simulate_body`. The result,
:class:`BodySimulationResult`, has the public surface of the planar
:class:`~freestand.api.simulation.SimulationResult` (status, message, peaks
per block, events, ``to_dict()`` = ``freestand simulate --json``,
``to_frame()``, ``plot()``, ``animate()``), with the 3-D peaks: the largest
tilt, slide and twist.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import NamedTuple

import numpy as np

from freestand.api.base import HistoryResult, finite, frame
from freestand.core.body import BodyConfiguration, Box
from freestand.core.contact.body_kernel import EDGE, FACE, FREE, POINT
from freestand.core.dynamics.body_history import BodyTimeHistory, SupportMotion3, simulate_body
from freestand.core.dynamics.results import SupportMotion
from freestand.core.motion.ground_motion import GroundMotion
from freestand.errors import FreestandError

#: Events listed in :meth:`BodySimulationResult.to_dict` (``first_events``), as for planar.
LISTED_EVENTS = 50

#: After the record, the body is at rest when it sits flat, sticks and no velocity
#: component exceeds this [m/s, rad/s] (the planar engine's rest test).
REST_VELOCITY = 1e-9

#: Patch names by the engine's code.
PATCH_NAMES = {FREE: "free", POINT: "point", EDGE: "edge", FACE: "face"}

#: Event kinds of the engine as the public results name them (the planar vocabulary).
EVENT_NAMES = {"stick": "slip-stop"}


def support_motion3(motion, *, angle: float = 0.0) -> SupportMotion3:
    """The three-component support motion of a 3-D body, its horizontal pair turned by ``angle``.

    Parameters
    ----------
    motion : GroundMotion, SupportMotion3 or SupportMotion
        A record read by :func:`freestand.load_record` (x from the file, y
        from ``horizontal_y=``, the downward vertical from ``vertical=``;
        a missing component is zero), scaled as wished with the record's own
        methods (``scaled``, ``scaled_to_peak``, ``scaled_to_spectral``: one
        factor, taken from the x component, for every component), or a
        support motion already.
    angle : float, optional
        Angle [deg] by which the horizontal motion is turned about the
        vertical, counter-clockwise seen from above (from +x towards +y): the
        record's x axis then points at ``angle`` in the model's frame, so a
        record along x with ``angle=90`` shakes the body along +y.

    Returns
    -------
    SupportMotion3
        ``a_x' = a_x cos(angle) - a_y sin(angle)``,
        ``a_y' = a_x sin(angle) + a_y cos(angle)`` and the downward vertical,
        at the record's step [s] [m/s^2].

    Examples
    --------
    >>> import freestand as fs
    >>> record = fs.load_record("examples/records/synthetic_H.AT2",
    ...                         horizontal_y="examples/records/synthetic_H.AT2",
    ...                         vertical="examples/records/synthetic_UP.AT2")
    >>> support = fs.support_motion3(record.scaled_to_peak(3.0), angle=-45.0)
    >>> round(float(abs(support.x).max()), 6), round(float(abs(support.y).max()), 6)  # [m/s^2]
    (4.242641, 0.0)
    """
    if not (isinstance(angle, int | float) and math.isfinite(angle)):
        raise FreestandError(
            f"{angle!r} is not an angle; give the direction of the record's x axis in degrees, "
            "e.g. --angle 30",
            source="--angle",
        )
    if isinstance(motion, GroundMotion):
        support = SupportMotion3(motion.dt, motion.horizontal, motion.horizontal_y, motion.vertical)
    elif isinstance(motion, SupportMotion3):
        support = motion
    elif isinstance(motion, SupportMotion):
        support = SupportMotion3(motion.time_step, motion.horizontal, None, motion.vertical)
    else:
        raise TypeError(
            "expected a GroundMotion (fs.load_record), a SupportMotion3 or a SupportMotion, "
            f"not {type(motion).__name__}"
        )
    return support.rotated(math.radians(angle)) if angle else support


class BodyEvent(NamedTuple):
    """One event of a 3-D time history.

    Attributes
    ----------
    time : float
        [s].
    kind : str
        ``"start"``, ``"lift-off"``, ``"impact"``, ``"slip"``, ``"slip-stop"``,
        ``"overturn"``, ``"pass-over"`` (a cylinder's axis swept past the
        vertical without its base landing) or ``"remedy"`` (no contact mode
        was admissible: the body went on in free flight).
    before, after : str
        The contact patch before and after: ``"face"`` (the base flat),
        ``"edge"``, ``"point"`` (a corner, or the rim point) or ``"free"``
        (``before`` is empty for the start).
    motion : str
        The body's motion after the event (:func:`motion_name`).
    """

    time: float
    kind: str
    before: str
    after: str
    motion: str


def motion_name(patch: int, sliding: bool, cylinder: bool) -> str:
    """The motion a contact patch means: ``rest``, ``slide``, ``rock-edge``, ``rock-corner``,
    ``roll`` (a cylinder rocking and rolling on its rim), ``slide-rock`` or ``free-flight``."""
    if patch == FREE:
        return "free-flight"
    if patch == FACE:
        return "slide" if sliding else "rest"
    if sliding:
        return "slide-rock"
    if patch == EDGE:
        return "rock-edge"
    return "roll" if cylinder else "rock-corner"


@dataclass(frozen=True)
class BodySimulationResult(HistoryResult):
    """The time history of one 3-D configuration (a box or a cylinder) under a support motion.

    The peaks and the verdict are attributes, per block (one body today) as
    for a planar :class:`~freestand.api.simulation.SimulationResult`:
    ``max_rotation`` (the largest tilt, the angle of the body's axis from
    the vertical) [rad], ``max_slide`` (the largest horizontal displacement
    of the base centre) [m], ``max_twist`` (the largest rotation about the
    vertical) [rad], ``uplift``, ``free_flight``, ``overturned`` and
    ``overturn_time`` [s]; the whole history is ``core`` (a
    :class:`~freestand.core.dynamics.body_history.BodyTimeHistory`).

    Attributes
    ----------
    model : str
        Model name.
    body_configuration : BodyConfiguration
        The configuration simulated.
    motion : GroundMotion or None
        The record, as given (None when a support motion was given).
    support : SupportMotion3
        The support accelerations simulated, turned by ``angle`` [m/s^2].
    angle : float
        The angle [deg] the record's horizontal pair was turned by.
    core : BodyTimeHistory
        Histories, events, peaks and the engine's counters.
    status : str
        ``"completed"`` (to the end time, until rest, or overturned),
        ``"capped"`` (``until_rest``: still moving at the cap) or ``"failed"``
        (the contact was lost: ``message`` says when; the histories, events
        and peaks stop there).
    message : str
        What happened, in words.

    Examples
    --------
    >>> import freestand as fs
    >>> model = fs.load_model("examples/bodies.toml")
    >>> record = fs.load_record("examples/records/synthetic_H.AT2").scaled_to_peak(6.0)
    >>> result = fs.simulate(model, record, configuration="cabinet", angle=90.0)
    >>> result.status, result.block_names, bool(result.uplift[0])
    ('completed', ('cabinet',), True)
    >>> result.to_frame().columns[:4].tolist()
    ['time [s]', 'support_x [m/s^2]', 'support_y [m/s^2]', 'support_vertical [m/s^2]']
    >>> len(result.plot().axes)  # support, motion, tilt, slide, twist, forces
    6
    """

    model: str
    body_configuration: BodyConfiguration
    motion: GroundMotion | None
    support: SupportMotion3
    angle: float
    core: BodyTimeHistory
    status: str
    message: str

    # --- the verdict ---------------------------------------------------------------------
    @property
    def configuration(self) -> str:
        """Configuration name."""
        return self.body_configuration.name

    @property
    def block_names(self) -> tuple[str, ...]:
        """The body's name (a tuple, bottom to top, as for a planar stack)."""
        return (self.core.body,)

    @property
    def cylinder(self) -> bool:
        """Whether the body is a cylinder (else a box)."""
        return not isinstance(self.body_configuration.body.shape, Box)

    @property
    def max_rotation(self) -> np.ndarray:
        """Largest tilt of each block: angle of its axis from the vertical [rad]."""
        return np.array([self.core.max_rotation])

    @property
    def max_slide(self) -> np.ndarray:
        """Largest horizontal displacement of each block's base centre [m]."""
        return np.array([self.core.max_slide])

    @property
    def max_twist(self) -> np.ndarray:
        """Largest rotation of each block about the vertical [rad]."""
        return np.array([self.core.max_twist])

    @property
    def uplift(self) -> np.ndarray:
        """Whether a base point of each block lifted (bool per block)."""
        return np.array([self.core.uplift])

    @property
    def free_flight(self) -> np.ndarray:
        """Whether each block left the support (bool per block)."""
        return np.array([self.core.free_flight])

    @property
    def overturned(self) -> np.ndarray:
        """Whether each block overturned (bool per block)."""
        return np.array([self.core.overturned])

    @property
    def overturn_time(self) -> np.ndarray:
        """Time of each block's overturning [s], NaN for none."""
        value = self.core.overturn_time
        return np.array([math.nan if value is None else value])

    @property
    def diagnostics(self) -> dict:
        """The engine's counters: ``steps``, ``events``, ``impacts``, ``remedies``."""
        return dict(self.core.diagnostics)

    @property
    def motions(self) -> np.ndarray:
        """The motion at every recorded instant (:func:`motion_name`), (K,) str."""
        cylinder = self.cylinder
        names = {
            (patch, sliding): motion_name(patch, sliding, cylinder)
            for patch in PATCH_NAMES
            for sliding in (False, True)
        }
        return np.array(
            [
                names[(int(p), bool(s))]
                for p, s in zip(self.core.patch, self.core.sliding, strict=True)
            ]
        )

    @property
    def events(self) -> tuple[BodyEvent, ...]:
        """Every event, in time order (:class:`BodyEvent`)."""
        time = self.core.time
        motions = self.motions
        events = []
        for instant, kind, before, after in self.core.events:
            row = min(int(np.searchsorted(time, instant, side="left")), time.size - 1)
            events.append(
                BodyEvent(instant, EVENT_NAMES.get(kind, kind), before, after, str(motions[row]))
            )
        return tuple(events)

    @property
    def tilt_vector(self) -> np.ndarray:
        """(K, 2): the tilt towards x and y [rad], the tilt angle along the horizontal
        projection of the body's axis (the wobbling rosette in plan)."""
        return tilt_vector(self.core.state[:, 3:7], self.core.tilt)

    @property
    def peak_horizontal(self) -> float:
        """Peak of the horizontal support acceleration's magnitude, max ``|(a_x, a_y)|`` [m/s^2]."""
        return float(np.max(np.hypot(self.support.x, self.support.y)))

    def blocks(self) -> list[dict]:
        """The peaks of every block, JSON-ready (one body today)."""
        core = self.core
        return [
            {
                "name": core.body,
                "max_rotation": finite(core.max_rotation),
                "max_slide": finite(core.max_slide),
                "max_twist": finite(core.max_twist),
                "uplift": bool(core.uplift),
                "free_flight": bool(core.free_flight),
                "overturned": bool(core.overturned),
                "overturn_time": None if core.overturn_time is None else finite(core.overturn_time),
            }
        ]

    def to_dict(self) -> dict:
        """The ``freestand simulate --json`` document of a 3-D configuration.

        Keys: ``model``, ``configuration``, ``shape`` (``box`` or
        ``cylinder``), ``record``, ``dt`` [s], ``angle`` [deg],
        ``peak_horizontal`` (max ``|(a_x, a_y)|``), ``peak_x``, ``peak_y``,
        ``peak_vertical`` [m/s^2] (as simulated, after ``angle``),
        ``scale_factor`` [-], ``status``, ``message``, ``method``
        (``"3-D"``), ``blocks`` (per block ``max_rotation`` = the largest
        tilt [rad], ``max_slide`` [m], ``max_twist`` [rad], ``uplift``,
        ``free_flight``, ``overturned``, ``overturn_time`` [s]), ``events``
        (count per kind), ``diagnostics`` (``steps``, ``events``,
        ``impacts``, ``remedies``), ``figures`` (files the command wrote) and
        ``first_events`` (the first 50: ``time`` [s], ``kind``, ``before``,
        ``after`` (contact patches), ``motion``).

        Returns
        -------
        dict
            JSON-ready: str, int, float, bool, None, lists and dicts
            (non-finite floats as None).
        """
        metadata = self.motion.metadata if self.motion is not None else {}
        support = self.support
        return {
            "model": self.model,
            "configuration": self.configuration,
            "shape": "cylinder" if self.cylinder else "box",
            "record": self.record,
            "dt": support.time_step,
            "angle": float(self.angle),
            "peak_horizontal": self.peak_horizontal,
            "peak_x": float(np.max(np.abs(support.x))),
            "peak_y": float(np.max(np.abs(support.y))),
            "peak_vertical": float(np.max(np.abs(support.vertical))),
            "scale_factor": metadata.get("scale_factor", 1.0),
            "status": self.status,
            "message": self.message,
            "method": "3-D",
            "blocks": self.blocks(),
            "events": self.event_counts(),
            "diagnostics": self.diagnostics,
            "figures": [],
            "first_events": [event._asdict() for event in self.events[:LISTED_EVENTS]],
        }

    def to_frame(self, table: str = "history"):
        """The histories, the peaks or the events as a DataFrame.

        Parameters
        ----------
        table : {"history", "peaks", "events"}
            ``"history"`` (default): one row per recorded instant, columns
            ``time [s]``, ``support_x [m/s^2]``, ``support_y [m/s^2]``,
            ``support_vertical [m/s^2]`` (downward), then for the body B
            ``B.tilt [rad]`` (its axis from the vertical), ``B.tilt_x [rad]``,
            ``B.tilt_y [rad]`` (the tilt along the axis's horizontal
            projection), ``B.slide_x [m]``, ``B.slide_y [m]``, ``B.slide [m]``
            (the base centre's horizontal displacement and its magnitude),
            ``B.twist [rad]`` (about the vertical), ``B.normal [N]``,
            ``B.friction [N]`` (``|(F_x, F_y, T_z/rho)|``, see
            :class:`~freestand.core.dynamics.body_history.BodyTimeHistory`),
            ``B.patch`` and ``B.motion``.
            ``"peaks"``: one row per block, columns ``block``,
            ``max_rotation [rad]``, ``max_slide [m]``, ``max_twist [rad]``,
            ``uplift``, ``free_flight``, ``overturned``, ``overturn_time [s]``.
            ``"events"``: one row per event, columns ``time [s]``, ``kind``,
            ``block``, ``before``, ``after``, ``motion``.

        ``attrs``: ``model``, ``configuration``, ``record``, ``status``,
        ``method``, ``angle [deg]``.

        Returns
        -------
        pandas.DataFrame
            The table described above: units in the column names, metadata in
            ``attrs``.
        """
        attrs = {
            "model": self.model,
            "configuration": self.configuration,
            "record": self.record,
            "status": self.status,
            "method": "3-D",
            "angle [deg]": float(self.angle),
        }
        name = self.core.body
        if table == "peaks":
            columns = ("block", "max_rotation [rad]", "max_slide [m]", "max_twist [rad]",
                       "uplift", "free_flight", "overturned", "overturn_time [s]")  # fmt: skip
            rows = [dict(zip(columns, block.values(), strict=True)) for block in self.blocks()]
            return frame(rows, columns, attrs)
        if table == "events":
            columns = ("time [s]", "kind", "block", "before", "after", "motion")
            rows = [
                dict(zip(columns, (e.time, e.kind, name, e.before, e.after, e.motion), strict=True))
                for e in self.events
            ]
            return frame(rows, columns, attrs)
        if table != "history":
            raise ValueError(f"{table!r} is not a table; use 'history', 'peaks' or 'events'")
        core = self.core
        time = core.time
        support = self.support.at(time)
        tilt = self.tilt_vector
        columns = {
            "time [s]": time,
            "support_x [m/s^2]": support[0],
            "support_y [m/s^2]": support[1],
            "support_vertical [m/s^2]": support[2],
            f"{name}.tilt [rad]": core.tilt,
            f"{name}.tilt_x [rad]": tilt[:, 0],
            f"{name}.tilt_y [rad]": tilt[:, 1],
            f"{name}.slide_x [m]": core.slide[:, 0],
            f"{name}.slide_y [m]": core.slide[:, 1],
            f"{name}.slide [m]": np.hypot(core.slide[:, 0], core.slide[:, 1]),
            f"{name}.twist [rad]": core.twist,
            f"{name}.normal [N]": core.normal_force,
            f"{name}.friction [N]": core.friction_force,
            f"{name}.patch": [PATCH_NAMES[int(p)] for p in core.patch],
            f"{name}.motion": self.motions,
        }
        import pandas as pd

        history = pd.DataFrame(columns)
        history.attrs.update(attrs)
        return history

    def plot(self, ax=None, view: str = "history"):
        """A figure ``freestand simulate --plot`` writes.

        Parameters
        ----------
        ax : None
            The figures have several panels: ``ax`` must be None.
        view : {"history", "plan"}
            ``"history"`` (``time-history.png``): panels sharing the time
            axis: the support accelerations, the motion (rest, slide, rock,
            roll, free flight) as a coloured band, the tilt, the slide (its
            magnitude and components), the twist and the contact forces, with
            lift-offs, impacts, slips and overturning marked and the verdict
            under the title. ``"plan"`` (``plan-view.png``): seen from above,
            the path of the base centre and the tilt vector (the rosette of a
            wobbling body), coloured by time.

        Returns
        -------
        matplotlib.figure.Figure
        """
        if ax is not None:
            raise ValueError("the 3-D time-history figures have several panels; call plot() "
                             "without ax")  # fmt: skip
        from freestand.plot.body_history import plan_view_figure, time_history_figure

        if view == "history":
            return time_history_figure(self)
        if view == "plan":
            return plan_view_figure(self)
        raise ValueError(f"{view!r} is not a view; use 'history' or 'plan'")

    def animate(self, path, exaggeration: float = 1.0):
        """Write an animated GIF of the body moving on the support, in a projected 3-D view.

        Parameters
        ----------
        path : str or pathlib.Path
            The GIF to write.
        exaggeration : float, optional
            The tilt drawn this many times larger [-] (labelled on every frame).

        Returns
        -------
        pathlib.Path
            The file written.
        """
        from freestand.plot.body_history import animate_body

        return animate_body(self, path, exaggeration=exaggeration)


def tilt_vector(quaternions: np.ndarray, tilt: np.ndarray) -> np.ndarray:
    """(K, 2) [rad]: ``tilt (e_x, e_y) / |(e_x, e_y)|``, e the body axis R e_z (0 when upright)."""
    w, x, y, z = quaternions.T
    axis = np.column_stack([2.0 * (x * z + w * y), 2.0 * (y * z - w * x)])
    size = np.hypot(axis[:, 0], axis[:, 1])
    scale = np.divide(tilt, size, out=np.zeros_like(tilt), where=size > 0.0)
    return axis * scale[:, None]


def check_body_options(configuration: BodyConfiguration, method: str, restitution) -> None:
    """FreestandError for an option of the planar engine given for a 3-D configuration."""
    if method != "auto":
        raise FreestandError(
            f"--method {method} chooses a solver of planar stacks; {configuration.name!r} is "
            "3-D and has one engine: leave --method out",
            source="--method",
        )
    if restitution is not None and not (
        np.ndim(restitution) == 0 and 0.0 <= float(restitution) <= 1.0
    ):
        raise FreestandError(
            f"restitution {restitution!r} for the 3-D body {configuration.name!r}: give one "
            "factor in [0, 1] (1: the plastic impact law)",
            source="restitution",
        )


def simulate_body_configuration(
    model_name: str,
    configuration: BodyConfiguration,
    motion,
    duration: float | None,
    *,
    angle: float = 0.0,
    max_step: float | None = None,
    gravity: float,
    until_rest: bool = False,
    free_time: float,
    progress: Callable[[float], None] | None = None,
    **options,
) -> BodySimulationResult:
    """The time history of a 3-D configuration (called by :func:`freestand.simulate`).

    ``options``: ``tolerances``, ``initial`` and ``restitution`` of
    :func:`~freestand.core.dynamics.body_history.simulate_body`.
    """
    unknown = sorted(set(options) - {"tolerances", "initial", "restitution"})
    if unknown:
        raise TypeError(f"simulate() got options a 3-D body does not take: {', '.join(unknown)}")
    support = support_motion3(motion, angle=angle)
    if until_rest and duration is None:
        if not (free_time >= 0.0 and math.isfinite(free_time)):
            raise FreestandError(f"free_time must be a finite time >= 0 [s], not {free_time!r}")
        end = support.duration + free_time
    else:
        end = support.duration if duration is None else float(duration)
    core = simulate_body(configuration.body, support, end, max_step=max_step, gravity=gravity,
                         **options)  # fmt: skip
    if progress is not None:
        progress(1.0)
    core, status, message = _verdict(core, support.duration, until_rest)
    record = motion if isinstance(motion, GroundMotion) else None
    return BodySimulationResult(
        model_name, configuration, record, support, float(angle), core, status, message
    )


def _verdict(core: BodyTimeHistory, record_end: float, until_rest: bool):
    """(history, status, message); with ``until_rest`` the history ends where the body rests."""
    if core.status == "failed":
        remedies = core.diagnostics.get("remedies", 0)
        cause = (
            f" (after {remedies} contact states without an admissible mode, continued in free "
            "flight: a limitation of this version's 3-D engine)"
            if remedies
            else ""
        )
        return core, "failed", core.message + cause
    if core.overturned:
        return core, "completed", f"overturned at t = {core.overturn_time:.6g} s"
    end = float(core.time[-1])
    if not until_rest:
        return core, "completed", f"simulated to t = {end:.6g} s"
    moving = (
        (core.patch != FACE)
        | core.sliding
        | (np.max(np.abs(core.state[:, 7:13]), axis=1) > REST_VELOCITY)
        | (core.time < record_end)
    )
    if moving[-1]:
        return core, "capped", f"still moving at the cap, t = {end:.6g} s"
    rest = int(np.flatnonzero(moving)[-1]) + 1 if moving.any() else 0
    kept = slice(0, rest + 1)
    arrays = ("time", "state", "patch", "sliding", "normal_force", "friction_force", "tilt",
              "slide", "twist")  # fmt: skip
    core = replace(core, **{name: getattr(core, name)[kept] for name in arrays})
    return core, "completed", f"at rest at t = {float(core.time[-1]):.6g} s"
