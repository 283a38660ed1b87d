"""Intensity measures (IM) of a ground motion, and scaling records to an IM level.

Kinds:

``pga``
    Peak horizontal ground acceleration max |a_h| [m/s^2].
``pgv``
    Peak horizontal ground velocity [m/s] (the record integrated from rest,
    :meth:`freestand.core.motion.ground_motion.GroundMotion.velocity`).
``sa``
    Pseudo-spectral acceleration of the horizontal component at frequency f
    [Hz] and damping zeta [-], ``omega^2 max|u|`` [m/s^2]
    (:func:`freestand.core.motion.response_spectrum.spectral_response`).
``pga-alpha``
    PGA / (g tan alpha) [-] of a block: the peak acceleration as a multiple
    of the acceleration that starts the block rocking on a rigid base,
    ``g tan(alpha)`` (Housner 1963), alpha the smaller slenderness angle of
    its two lower contacts (:class:`freestand.core.rocking.properties.RockingBlock`).

All four are proportional to the scale factor of a record (the oscillator and
the integration are linear), so a record is scaled to a level x by the single
factor ``x / IM(record)`` (multiple-stripe analysis: every record scaled to
every level). The vertical component is scaled by the same factor.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from freestand.core.contact.screening import GRAVITY
from freestand.core.model import Stack
from freestand.core.motion.ground_motion import GroundMotion
from freestand.core.rocking.properties import RockingBlock

#: IM kinds and their SI units.
KINDS = {"pga": "m/s^2", "pgv": "m/s", "sa": "m/s^2", "pga-alpha": "-"}


@dataclass(frozen=True)
class IntensityMeasure:
    """An intensity measure.

    Parameters
    ----------
    kind : str
        ``"pga"``, ``"pgv"``, ``"sa"`` or ``"pga-alpha"``.
    frequency : float, optional
        Oscillator frequency f [Hz] (``"sa"`` only).
    damping : float, optional
        Damping ratio zeta [-] (``"sa"``; default 0.05).
    block : str, optional
        Block name (``"pga-alpha"``; default the stack's top block).
    """

    kind: str
    frequency: float | None = None
    damping: float = 0.05
    block: str | None = None

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"unknown intensity measure {self.kind!r}; use one of {list(KINDS)}")
        if self.kind == "sa" and not (self.frequency is not None and self.frequency > 0):
            raise ValueError("sa needs a positive frequency [Hz]")
        if not 0.0 <= self.damping < 1.0:
            raise ValueError(f"damping must lie in [0, 1), not {self.damping!r}")

    @property
    def unit(self) -> str:
        """SI unit of the IM."""
        return KINDS[self.kind]

    def describe(self) -> str:
        """Text such as ``"Sa(2.5 Hz, 5 %)"`` or ``"PGA / (g tan alpha) of cart"``."""
        if self.kind == "pga":
            return "PGA"
        if self.kind == "pgv":
            return "PGV"
        if self.kind == "sa":
            return f"Sa({self.frequency:g} Hz, {100 * self.damping:g} %)"
        return f"PGA / (g tan alpha) of {self.block or 'the top block'}"

    def to_dict(self) -> dict:
        """JSON form: kind, unit and the parameters that apply."""
        data: dict = {"kind": self.kind, "unit": self.unit}
        if self.kind == "sa":
            data.update(frequency=self.frequency, damping=self.damping)
        if self.kind == "pga-alpha":
            data["block"] = self.block
        return data


def rocking_threshold(stack: Stack, block: str | None, gravity: float = GRAVITY) -> float:
    """g tan(alpha) [m/s^2] of a block: the smaller uplift threshold of its two pivots.

    Parameters
    ----------
    stack : Stack
    block : str or None
        Block name; None for the top block.
    gravity : float, optional
        g [m/s^2].
    """
    index = len(stack.blocks) - 1 if block is None else stack.block_index(block)
    rocking = RockingBlock.from_block(stack.blocks[index], "left", gravity=gravity)
    return min(rocking.about("pivot").uplift_threshold, rocking.about("other").uplift_threshold)


def intensity(
    motion: GroundMotion, measure: IntensityMeasure, stack: Stack, gravity: float = GRAVITY
) -> float:
    """The IM of a record [IM unit].

    Parameters
    ----------
    motion : GroundMotion
        The record (as given; not scaled).
    measure : IntensityMeasure
    stack : Stack
        The nominal model (for ``pga-alpha``).
    gravity : float, optional
        g [m/s^2].

    Returns
    -------
    float
        PGA [m/s^2], PGV [m/s], Sa [m/s^2] or PGA / (g tan alpha) [-].
    """
    if measure.kind == "pga":
        return motion.peak_horizontal
    if measure.kind == "pgv":
        return motion.peak_horizontal_velocity
    if measure.kind == "sa":
        from freestand.core.motion.response_spectrum import spectral_response

        response = spectral_response(motion, None, [measure.frequency], measure.damping)
        return float(response.pseudo_acceleration[0])
    return motion.peak_horizontal / rocking_threshold(stack, measure.block, gravity)


def scale_factor(record_intensity: float, level: float) -> float:
    """Factor [-] that scales a record of IM ``record_intensity`` to ``level``."""
    if not (record_intensity > 0 and math.isfinite(record_intensity)):
        raise ValueError(f"the record's intensity is {record_intensity!r}; it cannot be scaled")
    return level / record_intensity
