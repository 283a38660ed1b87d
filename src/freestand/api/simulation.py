"""Public time history: :func:`simulate`, its result, and :func:`support_motion`.

3-D configurations are simulated by :mod:`freestand.api.body_simulation`.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from freestand.api.base import HistoryResult, finite, frame, subject
from freestand.api.body_simulation import (
    BodySimulationResult,
    check_body_options,
    simulate_body_configuration,
    support_motion3,
)
from freestand.core.body import BodyConfiguration
from freestand.core.dynamics.body_history import SupportMotion3
from freestand.core.dynamics.timehistory import (
    FREE_TIME,
    METHODS,
    SupportMotion,
    TimeHistoryResult,
)
from freestand.core.dynamics.timehistory import simulate as _simulate_stack
from freestand.core.model import Stack
from freestand.core.motion.ground_motion import GroundMotion
from freestand.errors import FreestandError

#: Most integration steps a given ``max_step`` may ask for (duration / step): beyond, a run
#: lasts minutes; a typo such as 1e-7 s is refused instead of running for hours. Without
#: ``max_step`` the engine chooses its own steps and a record of any length is taken.
MAX_STEPS = 20_000_000

#: Events listed in :meth:`SimulationResult.to_dict` (``first_events``).
LISTED_EVENTS = 50


def support_motion(motion: GroundMotion | SupportMotion) -> SupportMotion:
    """The sampled support motion of a record.

    Parameters
    ----------
    motion : GroundMotion or SupportMotion
        A record read by :func:`load_record` (horizontal and downward vertical
        accelerations [m/s^2] at a step dt [s]) or a support motion already.

    Returns
    -------
    SupportMotion
        The same samples, as the time history takes them.

    Examples
    --------
    >>> import freestand as fs
    >>> support = fs.support_motion(fs.load_record("examples/records/synthetic_H.AT2"))
    >>> support.time_step, support.horizontal.shape, support.vertical  # [s]
    (0.005, (3001,), None)
    """
    if isinstance(motion, SupportMotion):
        return motion
    if isinstance(motion, GroundMotion):
        return SupportMotion(
            motion.dt,
            np.asarray(motion.horizontal),
            None if motion.vertical is None else np.asarray(motion.vertical),
        )
    raise TypeError(
        f"expected a GroundMotion (fs.load_record) or a SupportMotion, not {type(motion).__name__}"
    )


@dataclass(frozen=True)
class SimulationResult(HistoryResult):
    """The time history of one configuration under one support motion.

    The peaks and the verdict are attributes (``status``, ``max_rotation``,
    ``max_slide``, ``uplift``, ``free_flight``, ``overturned``,
    ``overturn_time``, ``events``, ``block_names``); the whole history is
    ``core`` (a :class:`~freestand.core.dynamics.results.TimeHistoryResult`).

    Attributes
    ----------
    model : str
        Model name.
    stack : Stack
        The configuration simulated.
    motion : GroundMotion or None
        The record, as given (None when samples were given).
    support : SupportMotion
        The support accelerations simulated [m/s^2].
    core : TimeHistoryResult
        Histories of every block, events, peaks and diagnostics.

    Examples
    --------
    >>> import freestand as fs
    >>> model = fs.load_model("examples/crane.toml")
    >>> record = fs.load_record("examples/records/synthetic_H.AT2").scaled_to_peak(8.0)
    >>> result = fs.simulate(model, record, duration=4.0, configuration="x-z cart right")
    >>> result.status, result.block_names
    ('completed', ('bridge', 'cart'))
    >>> result.to_frame().columns[:3].tolist()
    ['time [s]', 'support_horizontal [m/s^2]', 'support_vertical [m/s^2]']
    >>> len(result.plot().axes)  # support, slides, rotations, forces of each block
    5
    """

    model: str
    stack: Stack
    motion: GroundMotion | None
    support: SupportMotion
    core: TimeHistoryResult

    # --- the verdict, as the core result gives it ----------------------------------------
    @property
    def configuration(self) -> str:
        """Configuration (stack) name."""
        return self.core.configuration

    @property
    def block_names(self) -> tuple[str, ...]:
        """Block names, bottom to top."""
        return self.core.block_names

    @property
    def status(self) -> str:
        """``"completed"``, ``"capped"`` (still moving at the cap) or ``"failed"``."""
        return self.core.status

    @property
    def message(self) -> str:
        """What happened, in words."""
        return self.core.message

    @property
    def max_rotation(self) -> np.ndarray:
        """Largest absolute rotation of each block relative to the body below [rad]."""
        return self.core.max_rotation

    @property
    def max_slide(self) -> np.ndarray:
        """Largest absolute slide of each block along the body below [m]."""
        return self.core.max_slide

    @property
    def uplift(self) -> np.ndarray:
        """Whether a lower contact of each block lifted off (bool per block)."""
        return self.core.uplift

    @property
    def free_flight(self) -> np.ndarray:
        """Whether each block left the body below (bool per block)."""
        return self.core.free_flight

    @property
    def overturned(self) -> np.ndarray:
        """Whether each block overturned (bool per block)."""
        return self.core.overturned

    @property
    def overturn_time(self) -> np.ndarray:
        """Time of each block's overturning [s], NaN for none."""
        return self.core.overturn_time

    @property
    def events(self):
        """Every event (impacts, lift-offs, slips...), in time order."""
        return self.core.events

    @property
    def diagnostics(self):
        """How the simulation went (solver path, steps, solves)."""
        return self.core.diagnostics

    @property
    def peak_horizontal(self) -> float:
        """Peak horizontal support acceleration [m/s^2]."""
        return float(np.max(np.abs(self.support.horizontal)))

    def blocks(self) -> list[dict]:
        """The peaks of every block, bottom to top, JSON-ready."""
        core = self.core
        return [
            {
                "name": name,
                "max_rotation": finite(core.max_rotation[index]),
                "max_slide": finite(core.max_slide[index]),
                "uplift": bool(core.uplift[index]),
                "free_flight": bool(core.free_flight[index]),
                "overturned": bool(core.overturned[index]),
                "overturn_time": finite(core.overturn_time[index]),
            }
            for index, name in enumerate(core.block_names)
        ]

    def to_dict(self) -> dict:
        """The ``freestand simulate --json`` document (one configuration).

        Keys: ``model``, ``configuration``, ``record``, ``dt`` [s],
        ``peak_horizontal`` [m/s^2], ``scale_factor`` [-], ``status``,
        ``message``, ``method``, ``fallback``, ``blocks`` (per block
        ``max_rotation`` [rad], ``max_slide`` [m], ``uplift``,
        ``free_flight``, ``overturned``, ``overturn_time`` [s]), ``events``
        (count per kind), ``time_stepping`` (where events could not
        continue: ``time`` [s] stepped, ``stretches`` per cause,
        ``energy_ratio`` [-] at most 1, ``dissipative_impacts``), ``figures``
        (files the command wrote) and ``first_events`` (the first 50:
        ``time`` [s], ``kind``, ``interface``).

        Returns
        -------
        dict
            JSON-ready: str, int, float, bool, None, lists and dicts
            (non-finite floats as None).
        """
        metadata = self.motion.metadata if self.motion is not None else {}
        return {
            "model": self.model,
            "configuration": self.configuration,
            "record": self.record,
            "dt": self.support.time_step,
            "peak_horizontal": self.peak_horizontal,
            "scale_factor": metadata.get("scale_factor", 1.0),
            "status": self.status,
            "message": self.message,
            "method": self.diagnostics.method,
            "fallback": self.diagnostics.fallback,
            "blocks": self.blocks(),
            "events": self.event_counts(),
            "time_stepping": {
                "time": self.diagnostics.stepped_time,
                "stretches": dict(self.diagnostics.stretches),
                "energy_ratio": self.diagnostics.energy_ratio,
                "dissipative_impacts": self.diagnostics.dissipative_impacts,
            },
            "figures": [],
            "first_events": [
                {"time": event.time, "kind": event.kind, "interface": event.interface}
                for event in self.events[:LISTED_EVENTS]
            ],
        }

    def to_frame(self, table: str = "history"):
        """The histories, the peaks or the events as a DataFrame.

        Parameters
        ----------
        table : {"history", "peaks", "events"}
            ``"history"`` (default): one row per recorded instant (an event
            gives two rows at the same time, before and after), columns
            ``time [s]``, ``support_horizontal [m/s^2]``,
            ``support_vertical [m/s^2]`` (downward), then for every block B
            ``B.slide [m]`` (along the body below), ``B.rotation [rad]``
            (relative to the body below), ``B.u_x [m]``, ``B.u_z [m]`` (its
            centre's displacement), ``B.normal_left [N]``, ``B.normal_right
            [N]``, ``B.tangential [N]`` (forces from the body below).
            ``"peaks"``: one row per block, columns ``block``,
            ``max_rotation [rad]``, ``max_slide [m]``, ``uplift``,
            ``free_flight``, ``overturned``, ``overturn_time [s]``.
            ``"events"``: one row per event, columns ``time [s]``, ``kind``,
            ``block`` (the upper block of the interface, empty for none),
            ``contact`` (``left``/``right``/empty).

        ``attrs``: ``model``, ``configuration``, ``record``, ``status``,
        ``method``.

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
            "method": self.diagnostics.method,
        }
        if table == "peaks":
            columns = ("block", "max_rotation [rad]", "max_slide [m]", "uplift",
                       "free_flight", "overturned", "overturn_time [s]")  # fmt: skip
            rows = [dict(zip(columns, block.values(), strict=True)) for block in self.blocks()]
            return frame(rows, columns, attrs)
        if table == "events":
            names = self.block_names
            rows = [
                {
                    "time [s]": event.time,
                    "kind": event.kind,
                    "block": names[event.interface] if 0 <= event.interface < len(names) else "",
                    "contact": {0: "left", 1: "right"}.get(event.contact, ""),
                }
                for event in self.events
            ]
            return frame(rows, ("time [s]", "kind", "block", "contact"), attrs)
        if table != "history":
            raise ValueError(f"{table!r} is not a table; use 'history', 'peaks' or 'events'")
        core = self.core
        time = np.asarray(core.time)
        samples = np.arange(self.support.horizontal.size) * self.support.time_step
        columns = {
            "time [s]": time,
            "support_horizontal [m/s^2]": np.interp(
                time, samples, self.support.horizontal, left=0.0, right=0.0
            ),
            "support_vertical [m/s^2]": (
                np.zeros_like(time)
                if self.support.vertical is None
                else np.interp(time, samples, self.support.vertical, left=0.0, right=0.0)
            ),
        }
        for b, name in enumerate(core.block_names):
            columns[f"{name}.slide [m]"] = core.slide[:, b]
            columns[f"{name}.rotation [rad]"] = core.relative_rotation[:, b]
            columns[f"{name}.u_x [m]"] = core.position[:, b, 0]
            columns[f"{name}.u_z [m]"] = core.position[:, b, 1]
            columns[f"{name}.normal_left [N]"] = core.normal_force[:, b, 0]
            columns[f"{name}.normal_right [N]"] = core.normal_force[:, b, 1]
            columns[f"{name}.tangential [N]"] = core.tangential_force[:, b]
        import pandas as pd

        history = pd.DataFrame(columns)
        history.attrs.update(attrs)
        return history

    def plot(self, ax=None):
        """The time-history figure ``freestand simulate --plot`` writes.

        Panels sharing the time axis: the support acceleration, the slide and
        the rotation of every block, the contact forces of every interface,
        with lift-offs, impacts, slips and overturning marked and the verdict
        under the title. It has several panels, so ``ax`` must be None.

        Returns
        -------
        matplotlib.figure.Figure
        """
        if ax is not None:
            raise ValueError("the time-history figure has several panels; call plot() without ax")
        from freestand.plot.timehistory import plot_time_history

        return plot_time_history(self.core, self.support, stack=self.stack, title=self.title)

    def animate(self, path, exaggeration: float = 1.0):
        """Write an animated GIF of the blocks moving on the support (``--animate``).

        Parameters
        ----------
        path : str or pathlib.Path
            The GIF to write.
        exaggeration : float, optional
            Rotations drawn this many times larger [-] (labelled on every frame).
        """
        from freestand.plot.timehistory import animate_time_history

        animate_time_history(
            self.core, self.stack, path, support_motion=self.support,
            exaggeration=exaggeration, title=self.title,
        )  # fmt: skip


def simulate(
    model,
    motion,
    duration: float | None = None,
    *,
    configuration: str | None = None,
    method: str = "auto",
    max_step: float | None = None,
    gravity: float | None = None,
    restitution: float | None = None,
    until_rest: bool = False,
    free_time: float = FREE_TIME,
    progress: Callable[[float], None] | None = None,
    angle: float = 0.0,
    **options,
) -> SimulationResult | BodySimulationResult:
    """Time history of a configuration under a support motion (exact rigid contact).

    A planar stack: every block's rocking, sliding (static friction to hold,
    kinetic to slide), end stops, free flight, impacts (perfectly plastic;
    Housner 1963 for a single block) and overturning are followed: the
    screening's contact problem, extended by the velocity terms, is solved at
    every event and the equations of motion are integrated between events; a
    single block on the support takes the exact rocking or sliding equation
    (Zhang and Makris 2001, eqs. 10-12) where it applies
    (``diagnostics.method`` says which).

    A 3-D configuration (a box or a cylinder): the body under the three
    components x, y and vertical, with exact rigid contact on the circular
    friction cone: it rests, slides and twists, rocks about an edge or a
    corner, rocks and rolls on its rim, flies and overturns
    (:func:`freestand.core.dynamics.body_history.simulate_body`,
    ``docs/three-d.md``); the result is a :class:`BodySimulationResult`.

    Parameters
    ----------
    model : ModelFile, Stack, BodyConfiguration or Body
        A loaded model file (then ``configuration`` names the configuration),
        a stack or a 3-D body.
    motion : GroundMotion, SupportMotion or SupportMotion3
        Support accelerations [m/s^2] (``fs.load_record(...)``, scaled as
        wished): horizontal x and downward vertical; for a 3-D configuration
        also y (``fs.load_record(..., horizontal_y=...)``, or
        :func:`support_motion3`).
    duration : float, optional
        Simulated time [s]; by default the record (and, with ``until_rest``,
        free motion after it).
    configuration : str, optional
        Configuration of the model (default: the first planar one, or the
        first 3-D one in a model that has no planar configuration).
    method : {"auto", "general", "single-block"}
        Solver path of a planar stack; ``"auto"`` takes the single-block
        equations where they apply (a 3-D configuration has one engine:
        ``"auto"``).
    max_step : float, optional
        Largest integration step [s] (default 0.05 / p for a 3-D body, 0.02 /
        p for a planar one).
    gravity : float, optional
        g [m/s^2] (default: the model's, 9.81 for a stack).
    restitution : float, optional
        Factor [-] in [0, 1] on the post-impact relative velocities: one per
        block or one for all of a planar stack; one for a 3-D body (a box's
        turn about the line through its pivot corner and a corner landing
        beside it is kept whole, ``docs/three-d.md``).
    until_rest : bool, optional
        Go on after the record until the configuration is at rest or has
        overturned, at most ``free_time`` [s] after it (status ``"capped"``
        if still moving).
    free_time : float, optional
        Cap [s] on the time simulated after the record with ``until_rest``.
    progress : callable, optional
        Called with the fraction [-] simulated.
    angle : float, optional
        3-D configurations: the angle [deg] by which the horizontal pair of
        the record is turned, counter-clockwise from +x towards +y
        (:func:`support_motion3`).
    **options
        Passed to :func:`freestand.core.dynamics.timehistory.simulate`
        (``initial_position``, ``tolerances``, ...) or, for a 3-D body, to
        :func:`~freestand.core.dynamics.body_history.simulate_body`
        (``tolerances``, ``initial``).

    Returns
    -------
    SimulationResult or BodySimulationResult
        Status, peaks, events, the histories (``to_frame()``), the
        ``freestand simulate --json`` document (``to_dict()``) and the figure
        (``plot()``).

    Examples
    --------
    >>> import freestand as fs
    >>> model = fs.load_model("examples/crane.toml")
    >>> record = fs.load_record("examples/records/synthetic_H.AT2").scaled_to_peak(8.0)
    >>> result = fs.simulate(model, record, duration=4.0, configuration="x-z cart right")
    >>> result.status
    'completed'
    >>> result.to_frame("peaks")["block"].tolist()
    ['bridge', 'cart']

    A 3-D body under two horizontal components and the vertical, the pair
    turned by 30 deg:

    >>> bodies = fs.load_model("examples/bodies.toml")
    >>> record = fs.load_record("examples/records/synthetic_H.AT2",
    ...                         horizontal_y="examples/records/synthetic_H.AT2",
    ...                         vertical="examples/records/synthetic_UP.AT2")
    >>> cask = fs.simulate(bodies, record.scaled_to_peak(8.0), configuration="cask", angle=30.0)
    >>> cask.status, bool(cask.overturned[0]), round(float(cask.max_slide[0]), 3)  # [m]
    ('completed', False, 0.09)
    """
    what = subject(model, gravity=gravity)
    body = body_configuration(what, configuration)
    if body is not None:
        check_body_options(body, method, restitution)
        check_steps(support_motion3(motion).duration, duration, max_step)
        return simulate_body_configuration(
            what.name, body, motion, duration, angle=angle, max_step=max_step,
            gravity=what.gravity, until_rest=until_rest, free_time=free_time, progress=progress,
            **({} if restitution is None else {"restitution": float(restitution)}), **options,
        )  # fmt: skip
    stack = what.configuration(configuration)
    check_planar_motion(stack, motion, angle)
    support = support_motion(motion)
    check_options(stack, support, duration, method, max_step)
    core = _simulate_stack(
        stack, support, duration, method=method, max_step=max_step, gravity=what.gravity,
        restitution=restitution, until_rest=until_rest, free_time=free_time,
        progress=progress, **options,
    )  # fmt: skip
    return SimulationResult(
        what.name, stack, motion if isinstance(motion, GroundMotion) else None, support, core
    )


def body_configuration(what, name: str | None) -> BodyConfiguration | None:
    """The 3-D configuration called ``name`` (for None: the first, when there is no planar
    one), or None for a planar configuration."""
    if name is None:
        return what.bodies[0] if what.bodies and not what.configurations else None
    return next((body for body in what.bodies if body.name == name), None)


def check_planar_motion(stack, motion, angle: float) -> None:
    """FreestandError for a second horizontal component or an angle given to a planar stack."""
    planar = f"{stack.name!r} is planar: it takes the x component (in its plane) alone"
    if angle:
        raise FreestandError(
            f"--angle {angle:g} turns the horizontal pair of a 3-D configuration; {planar}. "
            "Leave --angle out, or choose a 3-D configuration",
            source="--angle",
        )
    y = getattr(motion, "horizontal_y", None)
    if y is not None or isinstance(motion, SupportMotion3):
        raise FreestandError(
            f"the record has a y component, which only a 3-D configuration takes; {planar}. "
            "Leave --record-y out, or choose a 3-D configuration",
            source="--record-y",
        )


def check_options(stack, support, duration, method, max_step) -> None:
    """FreestandError for a step, duration or solver that cannot be used on a planar stack."""
    check_steps(support.duration, duration, max_step)
    if method not in METHODS:
        raise FreestandError(
            f"{method!r} is not a solver; use " + ", ".join(METHODS), source="--method"
        )
    if method == "single-block" and len(stack.blocks) != 1:
        raise FreestandError(
            f"--method {method} does not apply to {stack.name!r} ({len(stack.blocks)} "
            "blocks); use auto, general, or single-block for a one-block configuration",
            source="--method",
        )


def check_steps(record_duration: float, duration: float | None, max_step: float | None) -> None:
    """FreestandError for a step or duration that cannot be used (any configuration)."""
    if max_step is not None and not (math.isfinite(max_step) and max_step > 0):
        raise FreestandError(
            f"{max_step} is not a positive step [s]; e.g. --step 0.001", source="--step"
        )
    if duration is not None and not (math.isfinite(duration) and duration > 0):
        raise FreestandError(
            f"{duration} is not a positive duration [s]; give the simulated time, e.g. "
            "--duration 10, or leave it out to simulate the whole record",
            source="--duration",
        )
    end = record_duration if duration is None else duration
    if max_step is not None and end / max_step > MAX_STEPS:
        raise FreestandError(
            f"{end:g} s in steps of {max_step:g} s is {end / max_step:.3g} integration steps, "
            f"beyond the {MAX_STEPS:.0e} freestand takes on in one run; give a larger --step "
            f"(e.g. --step {10 * end / MAX_STEPS:g}), a shorter --duration, or no --step at all",
            source="--step",
        )
