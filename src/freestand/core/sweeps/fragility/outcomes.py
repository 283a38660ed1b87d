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

A 3-D body (a box or a cylinder, :func:`body_values`) has the same kinds,
judged from its :class:`~freestand.core.dynamics.body_history.BodyTimeHistory`:
``rotation`` is its tilt (the angle of its axis from the vertical), and a
fraction of alpha is read against the tilt at which it would tip over in
the direction it tilts, ``theta*(u)`` (:func:`freestand.core.body.tipping_tilt`):
``rotation:B>0.5alpha`` occurs when ``max_t tilt(t) / theta*(u(t))`` exceeds
0.5; ``slide`` is the horizontal displacement magnitude of its base centre;
``uplift`` a base point lifted; ``flight`` the body left the support; and

``twist``
    (3-D bodies only) its peak |rotation about the vertical| exceeds an angle
    [deg].
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from freestand.core.body import BodyConfiguration, tipping_tilt
from freestand.core.model import Sliding, Stack

KINDS = ("overturn", "rotation", "slide", "uplift", "flight", "twist")

#: Kinds that only a 3-D body has.
BODY_ONLY_KINDS = ("twist",)

#: Units of the thresholds, per kind that has one.
THRESHOLD_UNITS = {"rotation": ("alpha", "rad"), "slide": ("m",), "twist": ("deg",)}

#: Per-block peak values kept for every simulation (the outcome inputs).
BLOCK_VALUES = ("overturned", "max_rotation", "max_slide", "uplift", "flight", "alpha")

#: Per-body peak values of a 3-D body: ``max_rotation`` the largest tilt [rad],
#: ``max_twist`` [rad], ``alpha`` the tipping tilt theta* [rad] where the tilt's ratio to
#: it peaks, ``tilt_ratio`` that peak ratio [-].
BODY_VALUES = ("overturned", "max_rotation", "max_slide", "max_twist", "uplift", "flight",
               "alpha", "tilt_ratio")  # fmt: skip


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
        the angle [rad] (``unit = "rad"``); for ``slide``: the distance [m];
        for ``twist``: the angle [deg].
    unit : str, optional
        ``"alpha"``, ``"rad"``, ``"m"`` or ``"deg"``.
    """

    kind: str
    block: str
    threshold: float = math.nan
    unit: str = ""

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"unknown outcome {self.kind!r}; use one of {', '.join(KINDS)}")
        if self.kind in THRESHOLD_UNITS:
            if not (self.threshold >= 0 and math.isfinite(self.threshold)):
                raise ValueError(f"{self.kind} needs a threshold >= 0, not {self.threshold!r}")
            allowed = THRESHOLD_UNITS[self.kind]
            if self.unit not in allowed:
                raise ValueError(f"{self.kind} thresholds are in {' or '.join(allowed)}")

    @property
    def key(self) -> str:
        """The option text, e.g. ``"rotation:cart>0.5alpha"`` (unique per outcome)."""
        if self.kind in THRESHOLD_UNITS:
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
        if self.kind == "twist":
            return f"{self.block} twists > {self.threshold:g} deg"
        return f"{self.block} in free flight"

    def to_dict(self) -> dict:
        """JSON form: name, kind, block and the threshold where there is one."""
        data: dict = {"name": self.name, "kind": self.kind, "block": self.block}
        if self.kind in THRESHOLD_UNITS:
            data.update(threshold=self.threshold, threshold_unit=self.unit)
        return data

    def occurred(self, values: dict[str, np.ndarray]) -> np.ndarray:
        """Whether the outcome occurred, from the per-block values of simulations.

        Parameters
        ----------
        values : dict of str to numpy.ndarray
            ``"BLOCK.QUANTITY"`` for QUANTITY in :data:`BLOCK_VALUES` (the
            columns of :func:`block_values`) or, for a 3-D body,
            :data:`BODY_VALUES` (:func:`body_values`), each shape (N,).

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
        if self.kind == "twist":
            twist = np.nan_to_num(get("max_twist").astype(float), nan=0.0)
            return np.degrees(twist) > self.threshold
        if self.unit == "alpha" and f"{self.block}.tilt_ratio" in values:
            # a 3-D body: its tilt against the tipping tilt in the direction it tilts
            ratio = np.nan_to_num(get("tilt_ratio").astype(float), nan=0.0)
            return overturned | (ratio > self.threshold)
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


def body_values(history, configuration: BodyConfiguration) -> dict[str, float]:
    """The outcome inputs of one 3-D time history (:data:`BODY_VALUES`).

    Parameters
    ----------
    history : BodyTimeHistory
        The simulated history (:func:`~freestand.core.dynamics.body_history.run_body_history`).
    configuration : BodyConfiguration
        The simulated configuration (for the tipping tilt).

    Returns
    -------
    dict of str to float
        ``"BODY.QUANTITY"``: overturned, uplift, flight as 0/1; the largest
        tilt [rad], horizontal slide [m] and twist [rad]; ``tilt_ratio``,
        the largest ``tilt(t) / theta*(u(t) - twist(t))`` [-] with u the
        direction of the body's tilt (its axis's horizontal projection) and
        theta* :func:`freestand.core.body.tipping_tilt` (the twist turns the
        base under the tilt: the direction in the body's frame is u less the
        twist); ``alpha``, theta* [rad] at that instant. For a cylinder with
        G on its axis theta* = atan(R/h) in every direction; for a box
        atan((b_x |u_x| + b_y |u_y|)/h): atan(b/h) towards an edge, up to
        atan(sqrt(b_x^2 + b_y^2)/h) towards a corner (Housner 1963's alpha
        in a plane).
    """
    from freestand.core.dynamics.body_history import tilt_vector

    body = configuration.body
    tilt = np.asarray(history.tilt, dtype=float)
    lean = tilt_vector(history.state[:, 3:7], tilt)
    direction = np.arctan2(lean[:, 1], lean[:, 0]) - np.asarray(history.twist, dtype=float)
    tipping = tipping_tilt(body, direction)
    ratio = tilt / tipping
    peak = int(np.argmax(ratio)) if ratio.size else 0
    name = body.name
    return {
        f"{name}.overturned": float(bool(history.overturned)),
        f"{name}.max_rotation": float(history.max_rotation),
        f"{name}.max_slide": float(history.max_slide),
        f"{name}.max_twist": float(history.max_twist),
        f"{name}.uplift": float(bool(history.uplift)),
        f"{name}.flight": float(bool(history.free_flight)),
        f"{name}.alpha": float(tipping[peak]) if ratio.size else math.nan,
        f"{name}.tilt_ratio": float(ratio[peak]) if ratio.size else math.nan,
    }


def default_body_outcomes(configuration: BodyConfiguration) -> tuple[Outcome, ...]:
    """Outcomes of a 3-D configuration: overturning, uplift and a slide of more than 1 cm."""
    name = configuration.body.name
    return (Outcome("overturn", name), Outcome("uplift", name), Outcome("slide", name, 0.01, "m"))
