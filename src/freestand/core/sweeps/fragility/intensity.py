"""Intensity measures (IM) of a ground motion, and scaling records to an IM level.

Kinds of one horizontal component (x, ``GroundMotion.horizontal``), for
planar models:

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

Kinds of two horizontal components (x and y), independent of the record's
orientation (:mod:`freestand.core.motion.rotd`, Boore 2010), for 3-D
configurations (a planar model moves under x alone, and
:func:`freestand.io.fragility_options.check_planar_intensity` refuses them
for it):

``pga-gm``, ``pgv-gm``, ``sa-gm``
    Geometric mean sqrt(IM_x IM_y) of the two components' PGA [m/s^2], PGV
    [m/s] or Sa(f, zeta) [m/s^2].
``pga-rotd50``, ``pga-rotd100``, ``pgv-rotd50``, ``pgv-rotd100``, ``sa-rotd50``, ``sa-rotd100``
    RotD50 (median) and RotD100 (largest) over the rotation angles
    0-179 deg (1 deg steps) of the peak of the rotated series
    a_x cos theta + a_y sin theta: its PGA, its PGV, or its oscillator's
    pseudo-acceleration (the two responses computed once and combined per
    angle).

A two-component IM of a record with one horizontal component is an error.
All kinds are proportional to the scale factor of a record (the oscillator,
the integration and the rotation are linear), so a record is scaled to a
level x by the single factor ``x / IM(record)`` (multiple-stripe analysis:
every record scaled to every level). Every component is scaled by the same
factor.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from freestand.core.contact.screening import GRAVITY
from freestand.core.model import Stack
from freestand.core.motion.ground_motion import GroundMotion
from freestand.core.rocking.properties import RockingBlock

#: IM kinds of two horizontal components: (base measure, how the two combine).
TWO_COMPONENT_KINDS = {
    f"{base}-{combination}": (base, combination)
    for base in ("pga", "pgv", "sa")
    for combination in ("gm", "rotd50", "rotd100")
}

#: IM kinds and their SI units.
KINDS = {
    "pga": "m/s^2",
    "pgv": "m/s",
    "sa": "m/s^2",
    "pga-alpha": "-",
    **{
        kind: ("m/s" if base == "pgv" else "m/s^2")
        for kind, (base, _) in TWO_COMPONENT_KINDS.items()
    },
}

#: Words for how two components combine, in descriptions.
_COMBINATIONS = {"gm": "geometric mean", "rotd50": "RotD50", "rotd100": "RotD100"}


@dataclass(frozen=True)
class IntensityMeasure:
    """An intensity measure.

    Parameters
    ----------
    kind : str
        One of :data:`KINDS`: ``"pga"``, ``"pgv"``, ``"sa"``, ``"pga-alpha"``,
        or a two-component kind such as ``"pga-rotd50"`` or ``"sa-gm"``.
    frequency : float, optional
        Oscillator frequency f [Hz] (``"sa"`` kinds only).
    damping : float, optional
        Damping ratio zeta [-] (``"sa"`` kinds; default 0.05).
    block : str, optional
        Block name (``"pga-alpha"``; default the stack's top block).

    Examples
    --------
    >>> import freestand as fs
    >>> measure = fs.IntensityMeasure("sa-rotd50", frequency=2.5)
    >>> measure.describe(), measure.unit, measure.two_components
    ('Sa(2.5 Hz, 5 %) RotD50', 'm/s^2', True)
    >>> fs.IntensityMeasure("pga").two_components
    False
    """

    kind: str
    frequency: float | None = None
    damping: float = 0.05
    block: str | None = None

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"unknown intensity measure {self.kind!r}; use one of {list(KINDS)}")
        if self.base == "sa" and not (self.frequency is not None and self.frequency > 0):
            raise ValueError(f"{self.kind} needs a positive frequency [Hz]")
        if not 0.0 <= self.damping < 1.0:
            raise ValueError(f"damping must lie in [0, 1), not {self.damping!r}")

    @property
    def unit(self) -> str:
        """SI unit of the IM."""
        return KINDS[self.kind]

    @property
    def base(self) -> str:
        """The one-component measure: ``"pga"``, ``"pgv"``, ``"sa"`` or ``"pga-alpha"``."""
        return TWO_COMPONENT_KINDS.get(self.kind, (self.kind, None))[0]

    @property
    def two_components(self) -> bool:
        """Whether the IM needs both horizontal components (x and y)."""
        return self.kind in TWO_COMPONENT_KINDS

    def describe(self) -> str:
        """Text such as ``"Sa(2.5 Hz, 5 %)"``, ``"PGA RotD50"``, ``"PGA / (g tan alpha) of B"``."""
        if self.base == "pga-alpha":
            return f"PGA / (g tan alpha) of {self.block or 'the top block'}"
        text = {"pga": "PGA", "pgv": "PGV"}.get(self.base)
        if text is None:
            text = f"Sa({self.frequency:g} Hz, {100 * self.damping:g} %)"
        if self.two_components:
            text = f"{text} {_COMBINATIONS[TWO_COMPONENT_KINDS[self.kind][1]]}"
        return text

    def to_dict(self) -> dict:
        """JSON form: kind, unit and the parameters that apply."""
        data: dict = {"kind": self.kind, "unit": self.unit}
        if self.base == "sa":
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
        PGA [m/s^2], PGV [m/s], Sa [m/s^2] or PGA / (g tan alpha) [-], of the
        x component, or of the horizontal pair for a two-component kind.

    Raises
    ------
    ValueError
        A two-component IM of a record without a y component.
    """
    if measure.two_components:
        return _two_component_intensity(motion, measure)
    if measure.kind == "pga":
        return motion.peak_horizontal
    if measure.kind == "pgv":
        return motion.peak_horizontal_velocity
    if measure.kind == "sa":
        from freestand.core.motion.response_spectrum import spectral_response

        response = spectral_response(motion, None, [measure.frequency], measure.damping)
        return float(response.pseudo_acceleration[0])
    return motion.peak_horizontal / rocking_threshold(stack, measure.block, gravity)


def _two_component_intensity(motion: GroundMotion, measure: IntensityMeasure) -> float:
    """Geometric mean, RotD50 or RotD100 of the horizontal pair (Boore 2010)."""
    from freestand.core.motion import rotd

    if motion.horizontal_y is None:
        raise ValueError(
            f"record {motion.name!r} has one horizontal component; {measure.kind} "
            f"({measure.describe()}) needs two (x and y): give a suite with x and y, or a "
            "one-component IM (pga, pgv, sa)"
        )
    base, combination = TWO_COMPONENT_KINDS[measure.kind]
    if combination == "gm":
        one = IntensityMeasure(base, frequency=measure.frequency, damping=measure.damping)
        along_y = GroundMotion(motion.dt, motion.horizontal_y, name=motion.name)
        return rotd.geometric_mean(intensity(motion, one, None), intensity(along_y, one, None))
    if base == "pga":
        peaks = rotd.peaks_over_angles(motion.horizontal, motion.horizontal_y)
    elif base == "pgv":
        peaks = rotd.peaks_over_angles(
            motion.velocity("horizontal"), motion.velocity("horizontal_y")
        )
    else:
        peaks = rotd.spectral_peaks_over_angles(
            motion.horizontal, motion.horizontal_y, motion.dt, measure.frequency, measure.damping
        )
    return rotd.percentile_over_angles(peaks, 50.0 if combination == "rotd50" else 100.0)


def scale_factor(record_intensity: float, level: float) -> float:
    """Factor [-] that scales a record of IM ``record_intensity`` to ``level``."""
    if not (record_intensity > 0 and math.isfinite(record_intensity)):
        raise ValueError(f"the record's intensity is {record_intensity!r}; it cannot be scaled")
    return level / record_intensity
