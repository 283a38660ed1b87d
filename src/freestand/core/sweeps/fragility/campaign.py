"""The simulations of a fragility campaign: records x levels x samples x polarities.

Every task is one time-history simulation (:func:`freestand.core.dynamics.timehistory.simulate`)
of the stack, with its uncertain inputs drawn for that task, under one record
scaled to one intensity level (or unscaled, for a cloud analysis), in one
polarity (the sign of a horizontal record is arbitrary).

Determinism: the inputs of sample k at record r and level l are drawn by
:func:`freestand.core.sweeps.sampling.draw_samples` with a seed derived from
``numpy.random.SeedSequence(seed, spawn_key=(r, l))``; both polarities use
the same inputs (common random numbers). Every task is thus a pure function
of the campaign and its index, and the results do not depend on how the
tasks are spread over workers or machines.

After the record: a block can overturn in free rocking after the shaking has
stopped, so every simulation goes on until the stack is back at rest or
every block has overturned, in one run
(:func:`~freestand.core.dynamics.timehistory.simulate` with
``until_rest=True``): the rest state is checked at every step after the
record (every interface sticking with both contacts closed, nothing moving),
and the run stops there. It is capped at ``record end + free_time`` (10 s by
default); status ``"capped"`` when still moving there.

Statuses: ``"completed"``, ``"capped"`` (moving at the cap; its peaks are
those reached by then), ``"failed"`` (the solver failed; the message says
why) and ``"invalid"`` (the sampled inputs make no model, e.g. a negative
mass). Failed and invalid simulations are recorded and counted, and left out
of the fits.

A 3-D configuration (a box or a cylinder,
:class:`~freestand.core.body.BodyConfiguration`) runs each task through
:func:`~freestand.core.dynamics.body_history.run_body_history` (the run of
:func:`freestand.simulate`, until the body rests after the record) under
the record's three components (x, y, vertical; a missing y is zero), its
horizontal pair turned by an incidence angle: drawn uniformly over
[0, 360) deg per simulation from ``SeedSequence(seed, spawn_key=(r, l, k,
1))`` (both polarities share it), or one of the campaign's fixed angles,
every sample running at each of them. A polarity of -1 negates both
horizontal components (the pair turned by 180 deg).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from freestand.core.body import BodyConfiguration
from freestand.core.contact.batch import case_inputs
from freestand.core.contact.screening import GRAVITY
from freestand.core.model import Friction, Stack
from freestand.core.motion.ground_motion import GroundMotion
from freestand.core.sweeps.fragility.intensity import IntensityMeasure, intensity, scale_factor
from freestand.core.sweeps.fragility.outcomes import (
    BLOCK_VALUES,
    BODY_VALUES,
    Outcome,
    block_values,
    body_values,
)
from freestand.core.sweeps.sampling import Variation, draw_samples

#: Default time simulated after the end of a record, at most [s].
FREE_TIME = 10.0

STATUSES = ("completed", "capped", "failed", "invalid")

#: The last word of the seed of a 3-D task's incidence angle (the samples' seeds have none).
ANGLE_STREAM = 1


@dataclass(frozen=True)
class Campaign:
    """Everything that defines the simulations of a fragility campaign.

    Parameters
    ----------
    stack : Stack or BodyConfiguration
        The configuration with its nominal inputs: a planar stack, or a 3-D
        configuration (a box or a cylinder).
    motions : tuple of GroundMotion
        The records (a 3-D configuration takes x, y and vertical; a missing
        y is zero).
    measure : IntensityMeasure
    levels : numpy.ndarray
        IM levels of the stripes [IM unit], increasing; empty for a cloud.
    variations : tuple of Variation
        Uncertain inputs (block fields only).
    samples : int
        K samples per record and level (1 without variations).
    polarities : tuple of int
        (+1,) or (+1, -1).
    seed : int
        Seed of the input samples.
    outcomes : tuple of Outcome
    gravity : float
        g [m/s^2].
    free_time : float
        Cap on the time simulated after the end of a record [s].
    method : str
        Solver choice of :func:`~freestand.core.dynamics.timehistory.simulate`.
    record_intensity : numpy.ndarray
        IM of each record as given [IM unit] (computed when omitted).
    angles : tuple of float
        3-D configurations: the incidence angles [deg] by which every
        record's horizontal pair is turned, each sample running at every one
        of them (one fixed angle, or a sweep); empty: one angle per
        simulation drawn uniformly over [0, 360) (see the module notes).
        Planar stacks: empty.
    """

    stack: Stack | BodyConfiguration
    motions: tuple[GroundMotion, ...] = field(repr=False)
    measure: IntensityMeasure
    levels: np.ndarray
    variations: tuple[Variation, ...] = ()
    samples: int = 1
    polarities: tuple[int, ...] = (1,)
    seed: int = 0
    outcomes: tuple[Outcome, ...] = ()
    gravity: float = GRAVITY
    free_time: float = FREE_TIME
    method: str = "auto"
    record_intensity: np.ndarray | None = None
    angles: tuple[float, ...] = ()

    def __post_init__(self) -> None:
        object.__setattr__(self, "angles", tuple(float(a) for a in self.angles))
        if self.angles and not self.three_d:
            raise ValueError("incidence angles apply to 3-D configurations only")
        if not all(math.isfinite(a) for a in self.angles):
            raise ValueError(f"the angles must be finite, not {self.angles}")
        levels = np.asarray(self.levels, dtype=float).ravel()
        object.__setattr__(self, "levels", levels)
        if not self.motions:
            raise ValueError("a campaign needs at least one record")
        if levels.size and (np.any(~(levels > 0)) or np.any(np.diff(levels) <= 0)):
            raise ValueError("levels must be positive and increasing")
        if self.samples < 1:
            raise ValueError(f"samples must be >= 1, not {self.samples}")
        if not self.polarities or any(p not in (1, -1) for p in self.polarities):
            raise ValueError("polarities must be +1 and/or -1")
        if not (self.free_time >= 0 and math.isfinite(self.free_time)):
            raise ValueError(f"free_time must be >= 0, not {self.free_time!r}")
        for variation in self.variations:
            if variation.parameter.block is None and variation.parameter.field in (
                "horizontal",
                "vertical",
            ):
                raise ValueError(
                    f"{variation.parameter.name} cannot be varied: the records and the "
                    "levels set the excitation"
                )
        if self.record_intensity is None:
            stack = None if self.three_d else self.stack
            values = [
                intensity(self.measured(m), self.measure, stack, self.gravity) for m in self.motions
            ]
            object.__setattr__(self, "record_intensity", np.array(values, dtype=float))
        else:
            object.__setattr__(
                self, "record_intensity", np.asarray(self.record_intensity, dtype=float)
            )

    @property
    def three_d(self) -> bool:
        """Whether the configuration is a 3-D body (else a planar stack)."""
        return isinstance(self.stack, BodyConfiguration)

    @property
    def block_names(self) -> tuple[str, ...]:
        """The blocks of the stack, or the 3-D configuration's body."""
        if self.three_d:
            return tuple(body.name for body in self.stack.bodies)
        return tuple(block.name for block in self.stack.blocks)

    @property
    def angle_count(self) -> int:
        """Incidence angles per sample (1 when drawn, and for planar stacks)."""
        return max(1, len(self.angles))

    def measured(self, motion: GroundMotion) -> GroundMotion:
        """The record whose IM is taken: as given, with y = 0 where a 3-D campaign lacks it."""
        if self.three_d and motion.horizontal_y is None:
            return replace(motion, horizontal_y=np.zeros_like(np.asarray(motion.horizontal)))
        return motion

    @property
    def cloud(self) -> bool:
        """Whether the records run unscaled (cloud analysis)."""
        return self.levels.size == 0

    @property
    def level_count(self) -> int:
        """Stripes (1 for a cloud)."""
        return 1 if self.cloud else int(self.levels.size)

    @property
    def size(self) -> int:
        """Number of simulations."""
        return (
            len(self.motions) * self.level_count * self.samples * self.angle_count
            * len(self.polarities)
        )  # fmt: skip

    def task(self, index: int) -> tuple[int, int, int, int]:
        """(record, level, sample, polarity) of task ``index``."""
        rest, p = divmod(int(index), len(self.polarities))
        rest = rest // self.angle_count
        rest, k = divmod(rest, self.samples)
        r, level = divmod(rest, self.level_count)
        return r, level, k, self.polarities[p]

    def angle(self, index: int) -> float:
        """Incidence angle [deg] of task ``index`` (3-D; NaN for a planar stack).

        One of :attr:`angles`, or drawn uniformly over [0, 360) from
        ``SeedSequence(seed, spawn_key=(record, level, sample, 1))``.
        """
        if not self.three_d:
            return math.nan
        slot = (int(index) // len(self.polarities)) % self.angle_count
        if self.angles:
            return self.angles[slot]
        r, level, k, _ = self.task(index)
        stream = np.random.SeedSequence(self.seed, spawn_key=(r, level, k, ANGLE_STREAM))
        return float(360.0 * np.random.default_rng(stream).random())

    def factor(self, record: int, level: int) -> float:
        """Scale factor [-] of a record at a level (1 for a cloud)."""
        if self.cloud:
            return 1.0
        return scale_factor(float(self.record_intensity[record]), float(self.levels[level]))

    def level_value(self, record: int, level: int) -> float:
        """IM of the scaled record [IM unit]."""
        if self.cloud:
            return float(self.record_intensity[record])
        return float(self.levels[level])

    def sample_seed(self, record: int, level: int) -> int:
        """Seed of the input samples of one record and level."""
        words = np.random.SeedSequence(self.seed, spawn_key=(record, level)).generate_state(2)
        return int(words[0]) | (int(words[1]) << 32)

    def input_values(self, record: int, level: int) -> tuple[np.ndarray, ...]:
        """The K drawn values of every variation at one record and level."""
        return draw_samples(self.variations, self.samples, self.sample_seed(record, level))


def sample_stacks(stack: Stack, variations, values) -> list[Stack | None]:
    """The stack with the varied inputs of each sample applied (None where they make no model).

    Parameters
    ----------
    stack : Stack
        Nominal model.
    variations : sequence of Variation
    values : sequence of numpy.ndarray
        The K drawn values of each variation.

    Notes
    -----
    The values act as :func:`freestand.core.contact.batch.case_inputs` applies them
    (set, add or scale; kinetic friction stays at or below static friction).
    """
    if not variations:
        return [stack] * (len(values[0]) if values else 1)
    count = len(values[0])
    inputs = case_inputs(
        stack, 0.0, 0.0, 1, [(v.parameter, x) for v, x in zip(variations, values, strict=True)],
        count,
    )  # fmt: skip
    batch = inputs.stack
    valid = batch.valid()
    stacks: list[Stack | None] = []
    for k in range(count):
        if not valid[k]:
            stacks.append(None)
            continue
        blocks = []
        for b, block in enumerate(stack.blocks):
            blocks.append(
                replace(
                    block,
                    mass=float(batch.mass[k, b]),
                    inertia=float(batch.inertia[k, b]),
                    centre=(float(batch.centre_x[k, b]), float(batch.centre_z[k, b])),
                    base_left=float(batch.base_left[k, b]),
                    base_right=float(batch.base_right[k, b]),
                    base_level=float(batch.base_level[k, b]),
                    friction=Friction(
                        float(batch.static_friction[k, b]), float(batch.kinetic_friction[k, b])
                    ),
                )
            )
        stacks.append(replace(stack, blocks=tuple(blocks)))
    return stacks


#: The inputs of a 3-D body a campaign can vary (``--vary``).
BODY_FIELDS = ("friction.static", "friction.kinetic", "mass")


def sample_bodies(
    configuration: BodyConfiguration, variations, values
) -> list[BodyConfiguration | None]:
    """The 3-D configuration with the varied inputs of each sample applied (None: no model).

    Parameters
    ----------
    configuration : BodyConfiguration
        Nominal configuration.
    variations : sequence of Variation
        Of :data:`BODY_FIELDS` (set, add or scale).
    values : sequence of numpy.ndarray
        The K drawn values of each variation.

    Notes
    -----
    The kinetic friction stays at or below the static one as for planar
    stacks (:func:`freestand.core.contact.batch.kinetic_below_static`); a
    varied mass scales the inertia with it (the same shape, denser or
    lighter).
    """
    from freestand.core.contact.batch import kinetic_below_static

    if not variations:
        return [configuration] * (len(values[0]) if values else 1)
    body = configuration.body
    count = len(values[0])
    inputs = {
        "friction.static": np.full(count, body.friction.static),
        "friction.kinetic": np.full(count, body.friction.kinetic),
        "mass": np.full(count, body.mass),
    }
    for variation, drawn in zip(variations, values, strict=True):
        field_name = variation.parameter.field
        if field_name not in BODY_FIELDS:
            raise ValueError(f"{field_name} of a 3-D body cannot be varied; vary {BODY_FIELDS}")
        inputs[field_name] = variation.parameter.applied(inputs[field_name], np.asarray(drawn))
    varied = {v.parameter.field for v in variations}
    static = inputs["friction.static"]
    kinetic = kinetic_below_static(
        static, inputs["friction.kinetic"], body.friction, "friction.static" in varied,
        "friction.kinetic" in varied,
    )  # fmt: skip
    out: list[BodyConfiguration | None] = []
    for k in range(count):
        mass = float(inputs["mass"][k])
        if not (static[k] >= 0.0 and kinetic[k] >= 0.0):  # no friction below zero (or NaN)
            out.append(None)
            continue
        try:
            sampled = replace(
                body, mass=mass, friction=Friction(float(static[k]), float(kinetic[k])),
                inertia=np.asarray(body.inertia) * (mass / body.mass),
            )  # fmt: skip
        except ValueError:  # a FreestandError: a mass or friction that makes no body
            out.append(None)
            continue
        out.append(replace(configuration, bodies=(sampled,)))
    return out


def simulate_task(
    stack: Stack, motion: GroundMotion, factor: float, polarity: int, campaign: Campaign
):
    """Simulate one task; (result or None, status, message, simulated time [s]).

    The record (times ``factor``, its horizontal component times
    ``polarity``) is simulated in one run that goes on after the record until
    the stack is at rest, every block has overturned, or ``free_time`` after
    the record (``simulate(..., until_rest=True)``; see the module notes).
    """
    from freestand.core.dynamics.timehistory import SupportMotion, simulate

    horizontal = np.asarray(motion.horizontal) * (factor * polarity)
    vertical = None if motion.vertical is None else np.asarray(motion.vertical) * factor
    support = SupportMotion(motion.dt, horizontal, vertical)
    try:
        result = simulate(
            stack,
            support,
            None,
            method=campaign.method,
            gravity=campaign.gravity,
            until_rest=True,
            free_time=campaign.free_time,
        )
    except Exception as error:  # noqa: BLE001 - any solver error is one failed simulation
        return None, "failed", f"{type(error).__name__}: {error}", math.nan
    simulated = float(result.time[-1])
    if result.status == "completed":
        return result, "completed", "", simulated
    if result.status == "capped":
        return result, "capped", _capped_message(campaign.free_time), simulated
    return result, "failed", result.message, simulated


def simulate_body_task(
    configuration: BodyConfiguration,
    motion: GroundMotion,
    factor: float,
    polarity: int,
    angle: float,
    campaign: Campaign,
):
    """Simulate one task of a 3-D configuration; (history or None, status, message, time [s]).

    The record's three components times ``factor`` (the horizontal pair
    also times ``polarity``), the pair turned by ``angle`` [deg]
    counter-clockwise seen from above (as :func:`freestand.support_motion3`),
    in one run of :func:`~freestand.core.dynamics.body_history.run_body_history`
    that goes on after the record until the body rests or overturns, at most
    ``free_time`` after it.
    """
    from freestand.core.dynamics.body_history import SupportMotion3, run_body_history

    scale = factor * polarity
    y = None if motion.horizontal_y is None else np.asarray(motion.horizontal_y) * scale
    vertical = None if motion.vertical is None else np.asarray(motion.vertical) * factor
    support = SupportMotion3(motion.dt, np.asarray(motion.horizontal) * scale, y, vertical)
    try:
        history, status, message = run_body_history(
            configuration.body, support.rotated(math.radians(angle)), until_rest=True,
            free_time=campaign.free_time, gravity=campaign.gravity,
        )  # fmt: skip
    except Exception as error:  # noqa: BLE001 - any solver error is one failed simulation
        return None, "failed", f"{type(error).__name__}: {error}", math.nan
    simulated = float(history.time[-1])
    if status == "capped":
        return history, "capped", _capped_message(campaign.free_time), simulated
    return history, status, "" if status == "completed" else message, simulated


def _capped_message(free_time: float) -> str:
    if free_time <= 0:
        return "moving at the end of the record"
    return f"still moving {free_time:g} s after the record"


def columns(campaign: Campaign) -> list[str]:
    """Column names of the rows of :func:`run_tasks`, in order.

    A 3-D campaign has ``angle`` [deg] after ``polarity`` and the body's
    :data:`~freestand.core.sweeps.fragility.outcomes.BODY_VALUES`.
    """
    names = ["task", "record", "record_name", "level", "im", "sample", "polarity"]
    names += ["angle"] if campaign.three_d else []
    names += ["scale_factor"]
    names += [f"input:{v.parameter.label}" for v in campaign.variations]
    names += ["status", "message", "solver", "simulated_time"]
    for name in campaign.block_names:
        names += [f"{name}.{q}" for q in _value_names(campaign)]
    names += [f"outcome:{o.key}" for o in campaign.outcomes]
    return names


def _value_names(campaign: Campaign) -> tuple[str, ...]:
    return BODY_VALUES if campaign.three_d else BLOCK_VALUES


def run_tasks(campaign: Campaign, start: int, stop: int) -> dict[str, np.ndarray]:
    """Run tasks ``start`` to ``stop - 1``; one row per simulation.

    Returns
    -------
    dict of str to numpy.ndarray
        The columns of :func:`columns`: the task's indices, the record's name,
        the IM of the scaled record, the drawn inputs (in SI, a factor for
        ``*=``), the status and message, the solver path
        (``diagnostics.method``), the simulated time [s], the per-block
        values of :data:`freestand.core.sweeps.fragility.outcomes.BLOCK_VALUES` (NaN
        for failed and invalid simulations) and whether each outcome occurred.
    """
    names = columns(campaign)
    rows: dict[str, list] = {name: [] for name in names}
    cache: dict[tuple[int, int], tuple] = {}
    blocks = campaign.block_names
    for index in range(start, min(stop, campaign.size)):
        r, level, k, polarity = campaign.task(index)
        if (r, level) not in cache:
            cache.clear()
            drawn_values = campaign.input_values(r, level)
            sample = sample_bodies if campaign.three_d else sample_stacks
            stacks = sample(campaign.stack, campaign.variations, drawn_values)
            cache[(r, level)] = (drawn_values, stacks)
        drawn_values, stacks = cache[(r, level)]
        drawn = [float(values[k]) for values in drawn_values]
        factor = campaign.factor(r, level)
        rows["task"].append(index)
        rows["record"].append(r)
        rows["record_name"].append(campaign.motions[r].name or f"record {r + 1}")
        rows["level"].append(level)
        rows["im"].append(campaign.level_value(r, level))
        rows["sample"].append(k)
        rows["polarity"].append(polarity)
        angle = campaign.angle(index)
        if campaign.three_d:
            rows["angle"].append(angle)
        rows["scale_factor"].append(factor)
        for variation, value in zip(campaign.variations, drawn, strict=True):
            rows[f"input:{variation.parameter.label}"].append(value)
        stack = stacks[k]
        values: dict[str, float] = {}
        solver = ""
        if stack is None:
            status, simulated = "invalid", math.nan
            message = "the sampled inputs make no model (check masses, inertias, geometry)"
        elif campaign.three_d:
            result, status, message, simulated = simulate_body_task(
                stack, campaign.motions[r], factor, polarity, angle, campaign
            )
            solver = "3-D"
            if status != "failed":
                values = body_values(result, stack)
        else:
            result, status, message, simulated = simulate_task(
                stack, campaign.motions[r], factor, polarity, campaign
            )
            if result is not None:
                solver = result.diagnostics.method
            if status != "failed":
                values = block_values(result, stack)
        rows["status"].append(status)
        rows["message"].append(message)
        rows["solver"].append(solver)
        rows["simulated_time"].append(simulated)
        for name in blocks:
            for quantity in _value_names(campaign):
                rows[f"{name}.{quantity}"].append(values.get(f"{name}.{quantity}", math.nan))
        for outcome in campaign.outcomes:
            occurred = bool(outcome.occurred(values)[()]) if values else False
            rows[f"outcome:{outcome.key}"].append(occurred)
    out = {}
    for name in names:
        if name in ("record_name", "status", "message", "solver"):
            out[name] = np.array(rows[name], dtype=object)
        elif name.startswith("outcome:"):
            out[name] = np.array(rows[name], dtype=bool)
        elif name in ("task", "record", "level", "sample", "polarity"):
            out[name] = np.array(rows[name], dtype=np.int64)
        else:
            out[name] = np.array(rows[name], dtype=float)
    return out
