"""Outcomes (damage states) of a simulation, judged from its time-history result.

Kinds (one block each; slides and rotations are relative to the body below):

``overturn``
    The block overturned (:attr:`TimeHistoryResult.overturned`).
``rotation``
    Its peak |rotation| exceeds a threshold: a fraction of its slenderness
    angle alpha (the smaller of its two pivots, of the simulated sample) or an
    angle [rad]. An overturned block counts as exceeding it.
``slide``
    Its peak |slide| exceeds a distance [m] (e.g. a cart's travel to its end
    stop, an anchor's gap).
``uplift``
    A lower contact lifted off (:attr:`TimeHistoryResult.uplift`).
``flight``
    Both lower contacts lifted off at once: free flight, e.g. a cart jumping
    off its rails (:attr:`TimeHistoryResult.free_flight`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from freestand.core.model import Sliding, Stack

KINDS = ("overturn", "rotation", "slide", "uplift", "flight")

#: Per-block peak values kept for every simulation (the outcome inputs).
BLOCK_VALUES = ("overturned", "max_rotation", "max_slide", "uplift", "flight", "alpha")


@dataclass(frozen=True)
class Outcome:
    """A damage state of one block.

    Parameters
    ----------
    kind : str
        One of :data:`KINDS`.
    block : str
        Block name.
    threshold : float, optional
        For ``rotation``: the fraction of alpha [-] (``unit = "alpha"``) or
        the angle [rad] (``unit = "rad"``); for ``slide``: the distance [m].
    unit : str, optional
        ``"alpha"``, ``"rad"`` or ``"m"``.
    """

    kind: str
    block: str
    threshold: float = math.nan
    unit: str = ""

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"unknown outcome {self.kind!r}; use one of {', '.join(KINDS)}")
        if self.kind in ("rotation", "slide"):
            if not (self.threshold >= 0 and math.isfinite(self.threshold)):
                raise ValueError(f"{self.kind} needs a threshold >= 0, not {self.threshold!r}")
            allowed = ("alpha", "rad") if self.kind == "rotation" else ("m",)
            if self.unit not in allowed:
                raise ValueError(f"{self.kind} thresholds are in {' or '.join(allowed)}")

    @property
    def key(self) -> str:
        """The option text, e.g. ``"rotation:cart>0.5alpha"`` (unique per outcome)."""
        if self.kind in ("rotation", "slide"):
            return f"{self.kind}:{self.block}>{self.threshold:g}{self.unit}"
        return f"{self.kind}:{self.block}"

    @property
    def name(self) -> str:
        """Words, e.g. ``"cart overturns"``, ``"cart slides > 0.05 m"``."""
        if self.kind == "overturn":
            return f"{self.block} overturns"
        if self.kind == "rotation":
            amount = (
                f"{self.threshold:g} alpha" if self.unit == "alpha" else f"{self.threshold:g} rad"
            )
            return f"{self.block} rotates > {amount}"
        if self.kind == "slide":
            return f"{self.block} slides > {self.threshold:g} m"
        if self.kind == "uplift":
            return f"{self.block} uplifts"
        return f"{self.block} in free flight"

    def to_dict(self) -> dict:
        """JSON form: name, kind, block and the threshold where there is one."""
        data: dict = {"name": self.name, "kind": self.kind, "block": self.block}
        if self.kind in ("rotation", "slide"):
            data.update(threshold=self.threshold, threshold_unit=self.unit)
        return data

    def occurred(self, values: dict[str, np.ndarray]) -> np.ndarray:
        """Whether the outcome occurred, from the per-block values of simulations.

        Parameters
        ----------
        values : dict of str to numpy.ndarray
            ``"BLOCK.QUANTITY"`` for QUANTITY in :data:`BLOCK_VALUES` (the
            columns of :func:`block_values`), each shape (N,).

        Returns
        -------
        numpy.ndarray
            Shape (N,) bool.
        """

        def get(quantity: str) -> np.ndarray:
            return np.asarray(values[f"{self.block}.{quantity}"])

        overturned = get("overturned").astype(bool)
        if self.kind == "overturn":
            return overturned
        if self.kind == "uplift":
            return get("uplift").astype(bool)
        if self.kind == "flight":
            return get("flight").astype(bool)
        if self.kind == "slide":
            slide = np.nan_to_num(get("max_slide").astype(float), nan=0.0)
            return slide > self.threshold
        rotation = np.nan_to_num(get("max_rotation").astype(float), nan=0.0)
        limit = self.threshold * get("alpha") if self.unit == "alpha" else self.threshold
        return overturned | (rotation > limit)


def slenderness(stack: Stack) -> np.ndarray:
    """alpha [rad] of every block: the smaller angle of its two pivots, atan(b / h)."""
    out = []
    for block in stack.blocks:
        height = block.centre[1] - block.base_level
        b = min(block.centre[0] - block.base_left, block.base_right - block.centre[0])
        out.append(math.atan2(b, height) if height > 0 else math.nan)
    return np.array(out)


def block_values(result, stack: Stack) -> dict[str, float]:
    """The per-block outcome inputs of one time-history result.

    Parameters
    ----------
    result : TimeHistoryResult
    stack : Stack
        The simulated stack (for alpha).

    Returns
    -------
    dict of str to float
        ``"BLOCK.QUANTITY"`` for QUANTITY in :data:`BLOCK_VALUES`: overturned,
        uplift, flight as 0/1; peak rotation [rad] and slide [m]; alpha [rad].
    """
    alpha = slenderness(stack)
    data = {}
    for index, name in enumerate(result.block_names):
        data[f"{name}.overturned"] = float(bool(result.overturned[index]))
        data[f"{name}.max_rotation"] = float(result.max_rotation[index])
        data[f"{name}.max_slide"] = float(result.max_slide[index])
        data[f"{name}.uplift"] = float(bool(result.uplift[index]))
        data[f"{name}.flight"] = float(bool(result.free_flight[index]))
        data[f"{name}.alpha"] = float(alpha[index])
    return data


def default_outcomes(stack: Stack) -> tuple[Outcome, ...]:
    """Outcomes that make sense for a configuration.

    Every block: overturning and uplift; a block on another block: free
    flight (a cart leaving its rails); a block whose interface can slide:
    a slide of more than 1 cm.
    """
    outcomes = []
    for block in stack.blocks:
        outcomes.append(Outcome("overturn", block.name))
    for index, block in enumerate(stack.blocks):
        outcomes.append(Outcome("uplift", block.name))
        if index > 0:
            outcomes.append(Outcome("flight", block.name))
        if block.sliding is not Sliding.NONE:
            outcomes.append(Outcome("slide", block.name, 0.01, "m"))
    return tuple(outcomes)
