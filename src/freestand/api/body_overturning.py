"""Public overturning check of a 3-D body under pulses in one direction (issue #18).

:func:`freestand.api.overturning.overturning` dispatches here for a 3-D
configuration (``fs.overturning(model, configuration="cask", direction=30)``).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from freestand.api.base import Result, finite, frame, weight_text
from freestand.core.body import BodyConfiguration, Box
from freestand.core.rocking.body_overturning import (
    BodyOverturningCurve,
    body_overturning_limits,
    easiest_direction,
    excitation_plane_block,
)
from freestand.core.rocking.overturning import (
    CURVE_FREQUENCIES,
    OverturningLimits,
    overturning_limits,
)
from freestand.core.rocking.properties import RockingBlock
from freestand.errors import FreestandError

#: Columns of :meth:`BodyOverturningResult.to_frame`.
BODY_PULSE_COLUMNS = (
    "frequency [Hz]",
    "half_sine_duration [s]",
    "half_sine_exact_3d [m/s^2]",
    "one_sine_exact_3d [m/s^2]",
    "one_cosine_exact_3d [m/s^2]",
    "half_sine_planar_housner [m/s^2]",
    "half_sine_planar_makris_roussos [m/s^2]",
    "half_sine_planar_exact [m/s^2]",
)
#: The figure of :meth:`BodyOverturningResult.plot`, with the CLI's file name.
BODY_FIGURE = "half_sine_pulse_3d"
#: Counters of the search summed per pulse kind in ``to_dict()["diagnostics"]``.
COUNTERS = ("simulations", "failed", "undecided", "remedies", "stretch_steps")


@dataclass(frozen=True)
class BodyOverturningResult(Result):
    """Minimum overturning amplitude of pulses along one direction for a 3-D body.

    Attributes
    ----------
    model, configuration : str
        Names.
    shape : str
        ``"box"`` or ``"cylinder"``.
    direction : float
        phi [deg] of the pulses' positive acceleration, from +x towards +y.
    direction_given : bool
        False when ``direction`` is the default: the lowest uplift threshold
        of 24 directions (:func:`~freestand.core.rocking.body_overturning.easiest_direction`).
    half_sine, one_sine, one_cosine : BodyOverturningCurve
        The 3-D limits [m/s^2] at the frequencies asked, with the search's
        counts (:mod:`freestand.core.rocking.body_overturning`).
    plane : RockingBlock
        The planar block of the pulse's vertical plane (the body's own
        inertia; equal to the 3-D body for a cylinder or a box along an axis).
    planar : OverturningLimits
        Its half-sine limits (Housner, Makris-Roussos, exact) at the
        frequencies asked.
    curves : OverturningLimits
        The same on 48 frequencies from 0.1 to 20 Hz (the figure).
    operating_amplitude : float or None
        The amplitude of interest [m/s^2] (the largest horizontal excitation,
        ``|(x, y)|``), None without excitations.
    include_vertical : bool
        Whether the weight is m (g - a_v).
    vertical_acceleration : float
        a_v [m/s^2] in the weight.

    Examples
    --------
    >>> import freestand as fs
    >>> bodies = fs.load_model("examples/bodies.toml")
    >>> result = fs.overturning(bodies, configuration="cabinet", frequencies=[1.0])
    >>> result.direction, result.half_sine.pivot
    (90.0, 'edge -y')
    >>> round(float(result.half_sine.amplitude[0]), 2)  # [m/s^2]
    4.71
    """

    model: str
    configuration: str
    shape: str
    direction: float
    direction_given: bool
    half_sine: BodyOverturningCurve
    one_sine: BodyOverturningCurve
    one_cosine: BodyOverturningCurve
    plane: RockingBlock
    planar: OverturningLimits
    curves: OverturningLimits
    operating_amplitude: float | None
    include_vertical: bool
    vertical_acceleration: float

    @property
    def kinds(self) -> dict[str, BodyOverturningCurve]:
        """The curves by pulse kind."""
        return {"half-sine": self.half_sine, "one-sine": self.one_sine,
                "one-cosine": self.one_cosine}  # fmt: skip

    @property
    def weight(self) -> str:
        """The weight the limits use, in words."""
        return weight_text(self.include_vertical, self.vertical_acceleration)

    def to_dict(self) -> dict:
        """The ``freestand overturn --json`` document of a 3-D configuration.

        Keys: ``configuration``, ``block``, ``shape``, ``method`` (``"3-D"``),
        ``direction`` [deg], ``direction_given``, ``pivot``,
        ``uplift_threshold`` [m/s^2], ``tipping_distance`` [m],
        ``slides_flat`` (friction keeps the base flat: nothing overturns),
        ``plane`` (the planar block of the pulse's plane: ``R`` [m],
        ``alpha`` [rad], ``p`` [rad/s], ``inertia_about_pivot`` [kg m^2]),
        ``half_sine`` (``frequency`` [Hz], ``exact_3d``, and the plane's
        ``housner``, ``linear``, ``planar_exact`` [m/s^2]), ``one_sine`` and
        ``one_cosine`` (``frequency``, ``exact_3d``), ``operating_amplitude``
        [m/s^2], ``overturns_below_frequency`` [Hz] by limit (``exact-3d``
        interpolated between the frequencies asked), ``search``
        (``scan_ratio``, ``rel_tol``, ``samples_per_pulse``), ``diagnostics``
        (per pulse kind: ``simulations``, ``failed``, ``undecided``,
        ``remedies``, ``stretch_steps``), ``weight``,
        ``vertical_acceleration`` [m/s^2] and ``figures``. None where no
        overturning amplitude was found.

        Returns
        -------
        dict
            JSON-ready: str, int, float, bool, None, lists and dicts
            (non-finite floats as None).
        """
        curve, plane = self.half_sine, self.plane.about("pivot")
        operating = dict(self.curves.operating_frequency)
        operating.update(curve.limits.operating_frequency)
        return {
            "configuration": self.configuration,
            "block": curve.body,
            "shape": self.shape,
            "method": "3-D",
            "direction": self.direction,
            "direction_given": self.direction_given,
            "pivot": curve.pivot,
            "uplift_threshold": curve.uplift_threshold,
            "tipping_distance": curve.tipping_distance,
            "slides_flat": curve.slides_flat,
            "plane": {
                "R": plane.R,
                "alpha": plane.alpha,
                "p": plane.p,
                "inertia_about_pivot": plane.inertia_about_pivot,
            },  # fmt: skip
            "half_sine": [
                {
                    "frequency": float(f),
                    "exact_3d": finite(curve.amplitude[k]),
                    "housner": finite(self.planar.limits["housner"][k]),
                    "linear": finite(self.planar.limits["makris-roussos"][k]),
                    "planar_exact": finite(self.planar.limits["exact"][k]),
                }
                for k, f in enumerate(curve.frequency)
            ],
            "one_sine": _rows(self.one_sine),
            "one_cosine": _rows(self.one_cosine),
            "operating_amplitude": finite(self.operating_amplitude),
            "overturns_below_frequency": {k: finite(v) for k, v in operating.items()},
            "search": {
                "scan_ratio": curve.scan_ratio,
                "rel_tol": curve.rel_tol,
                "samples_per_pulse": curve.samples_per_pulse,
            },  # fmt: skip
            "diagnostics": {
                kind.replace("-", "_"): {name: int(np.sum(getattr(c, name))) for name in COUNTERS}
                for kind, c in self.kinds.items()
            },
            "weight": "m (g - a_v)" if self.include_vertical else "m g",
            "vertical_acceleration": self.vertical_acceleration,
            "figures": [],
        }

    def to_frame(self):
        """The limits as a DataFrame, one row per frequency asked.

        Columns: ``frequency [Hz]``, ``half_sine_duration [s]`` (1 / (2 f)),
        the 3-D limits ``half_sine_exact_3d``, ``one_sine_exact_3d``,
        ``one_cosine_exact_3d`` and the planar half-sine limits of the pulse's
        plane ``half_sine_planar_housner``, ``half_sine_planar_makris_roussos``,
        ``half_sine_planar_exact`` [m/s^2] (inf where none was found).
        ``attrs``: ``model``, ``configuration``, ``block``, ``direction [deg]``,
        ``pivot``, ``weight``, ``operating_amplitude [m/s^2]``.

        Returns
        -------
        pandas.DataFrame
            The table described above: units in the column names, metadata in
            ``attrs``.
        """
        f = self.half_sine.frequency
        values = zip(
            f, 0.5 / f, self.half_sine.amplitude, self.one_sine.amplitude,
            self.one_cosine.amplitude, self.planar.limits["housner"],
            self.planar.limits["makris-roussos"], self.planar.limits["exact"], strict=True,
        )  # fmt: skip
        rows = [dict(zip(BODY_PULSE_COLUMNS, row, strict=True)) for row in values]
        attrs = {
            "model": self.model,
            "configuration": self.configuration,
            "block": self.half_sine.body,
            "direction [deg]": self.direction,
            "pivot": self.half_sine.pivot,
            "weight": "m (g - a_v)" if self.include_vertical else "m g",
            "operating_amplitude [m/s^2]": self.operating_amplitude,
        }
        return frame(rows, BODY_PULSE_COLUMNS, attrs)

    def plot(self, ax=None):
        """The half-sine limits against frequency, as ``freestand overturn --plot`` writes it.

        The 3-D limit at the frequencies asked (points joined by a line) over
        the planar limits of the pulse's vertical plane (Housner, Makris and
        Roussos, exact; 48 frequencies), log-log.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Draw into these axes (default: a new figure).

        Returns
        -------
        matplotlib.figure.Figure
        """
        from freestand.plot.overturning import plot_body_pulse_limits

        title = (
            f"{self.configuration}: half-sine pulse along {self.direction:g} deg, "
            "overturning above the curves"
        )
        return plot_body_pulse_limits(self.half_sine, self.curves, title=title, ax=ax)


def _rows(curve: BodyOverturningCurve) -> list[dict]:
    return [{"frequency": float(f), "exact_3d": finite(curve.amplitude[k])}
            for k, f in enumerate(curve.frequency)]  # fmt: skip


def check_direction(direction: float | None) -> None:
    """FreestandError for a direction that is not a finite number of degrees."""
    if direction is not None and not math.isfinite(direction):
        raise FreestandError(
            f"{direction} is not a direction; give the pulse's direction in degrees from +x "
            "towards +y, e.g. --direction 45",
            source="--direction",
        )


def body_overturning(
    name: str,
    configuration: BodyConfiguration,
    frequencies,
    *,
    direction: float | None = None,
    operating_amplitude: float | None = None,
    vertical_acceleration: float = 0.0,
    include_vertical: bool = False,
    gravity: float,
    progress: Callable[[], None] | None = None,
    **search,
) -> BodyOverturningResult:
    """The 3-D check of :func:`freestand.api.overturning.overturning` (its parameters).

    ``progress`` is called once per pulse kind and frequency done (3 per
    frequency); ``search`` goes to
    :func:`~freestand.core.rocking.body_overturning.body_overturning_limits`
    (``scan_ratio``, ``rel_tol``, ...).
    """
    check_direction(direction)
    body = configuration.body
    given = direction is not None
    phi = float(direction) if given else easiest_direction(body, vertical_acceleration, gravity)
    f = np.array(sorted(set(frequencies)), dtype=float)
    curves = {
        kind: body_overturning_limits(
            body,
            f,
            phi,
            kind=kind,
            vertical_acceleration=vertical_acceleration,
            gravity=gravity,
            operating_amplitude=operating_amplitude,
            progress=progress,
            **search,
        )  # fmt: skip
        for kind in ("half-sine", "one-sine", "one-cosine")
    }
    plane = excitation_plane_block(body, math.radians(phi), gravity, vertical_acceleration)
    return BodyOverturningResult(
        model=name,
        configuration=configuration.name,
        shape="box" if isinstance(body.shape, Box) else "cylinder",
        direction=phi,
        direction_given=given,
        half_sine=curves["half-sine"],
        one_sine=curves["one-sine"],
        one_cosine=curves["one-cosine"],
        plane=plane,
        planar=overturning_limits(plane, f, kind="half-sine"),
        curves=overturning_limits(
            plane, CURVE_FREQUENCIES, kind="half-sine", operating_amplitude=operating_amplitude
        ),  # fmt: skip
        operating_amplitude=operating_amplitude,
        include_vertical=include_vertical,
        vertical_acceleration=vertical_acceleration,
    )
