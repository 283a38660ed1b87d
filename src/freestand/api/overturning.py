"""Public overturning check of a rocking block (paper section 5, Figs. 6-8): :func:`overturning`."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass

import numpy as np

from freestand.api.base import Result, finite, frame, resolve_spectrum, subject, weight_text
from freestand.api.body_overturning import BodyOverturningResult, body_overturning
from freestand.api.simulation import body_configuration
from freestand.core.contact.screening import Motion, initial_motion
from freestand.core.model import Block, Excitation, Stack
from freestand.core.motion.spectra import Spectrum, SpectrumCheck
from freestand.core.rocking.body_overturning import largest_horizontal
from freestand.core.rocking.overturning import (
    CURVE_FREQUENCIES,
    TABLE_FREQUENCIES,
    OverturningLimits,
    RectangularPulseLimits,
    check_spectrum,
    overturning_limits,
    rectangular_amplitude_grid,
    rectangular_pulse_limits,
)
from freestand.core.rocking.properties import RockingBlock
from freestand.errors import FreestandError

#: Highest pulse frequency accepted [Hz]: beyond, the pulse is far shorter than any rocking
#: period and the overturning amplitude is beyond any support acceleration.
MAX_FREQUENCY = 100.0
#: Lowest pulse frequency accepted [Hz]: a pulse of 50 s, longer than any record.
MIN_FREQUENCY = 0.01

CONCLUSION = (
    "Housner's half-sine criterion, as the paper applies it, is unconservative (Makris and "
    "Roussos 2000): a block can overturn in free rocking after the pulse. The corrected "
    "linearised limit and the exact nonlinear limit are lower, so a pulse of the operating "
    "amplitude overturns the block up to a higher frequency than the paper's boundary."
)

#: Columns of :meth:`OverturningResult.to_frame` (``table="pulses"``).
PULSE_COLUMNS = (
    "frequency [Hz]",
    "half_sine_duration [s]",
    "half_sine_housner [m/s^2]",
    "half_sine_makris_roussos [m/s^2]",
    "half_sine_exact [m/s^2]",
    "one_sine_exact [m/s^2]",
    "one_cosine_exact [m/s^2]",
)
#: Columns of :meth:`OverturningResult.to_frame` (``table="rectangular"``).
RECTANGULAR_COLUMNS = ("amplitude [m/s^2]", "housner [s]", "exact [s]")
#: Figures of :meth:`OverturningResult.plot` (``figure=``), with the CLI's file names.
FIGURES = {
    "rectangular": "fig6_rectangular_pulse",
    "half-sine": "fig7_half_sine_pulse",
    "spectrum": "fig8_spectrum_check",
}


def vertical_for_overturning(excitations: Iterable[Excitation]) -> float:
    """The largest downward vertical support acceleration of the excitations [m/s^2], 0 if none.

    The weight m (g - a_v) is smallest, and overturning easiest, under it.
    """
    return max([0.0] + [max(e.verticals()) for e in excitations])


@dataclass(frozen=True)
class OverturningResult(Result):
    """Rocking properties, pulse overturning limits and the spectrum check of one block.

    Attributes
    ----------
    model : str
        Model name.
    configuration : str
        Configuration name.
    block : str
        The rocking block.
    pivot : str
        ``"left"`` or ``"right"``: the contact it rocks about.
    rocking : RockingBlock
        The block as a rocking body (R [m], alpha [rad], p [rad/s], ...).
    operating_amplitude : float
        The amplitude of interest [m/s^2] (the model's largest horizontal excitation).
    rectangular : RectangularPulseLimits
        Shortest overturning rectangular pulse [s] at the amplitudes asked (Fig. 6).
    half_sine, one_sine, one_cosine : OverturningLimits
        Minimum overturning amplitude [m/s^2] at the frequencies asked (Fig. 7).
    curves : OverturningLimits
        The half-sine limits on 48 frequencies from 0.1 to 20 Hz (Figs. 7, 8).
    spectrum : Spectrum or None
        The horizontal spectrum compared with the limits.
    checks : dict of str to SpectrumCheck
        The spectrum check of every limit (Fig. 8).
    include_vertical : bool
        Whether the weight is m (g - a_v) with ``vertical_acceleration``.
    vertical_acceleration : float
        a_v [m/s^2] in the weight (0 for m g).

    Examples
    --------
    >>> import freestand as fs
    >>> model = fs.load_model("examples/crane.toml")
    >>> result = fs.overturning(model, configuration="x-z cart right", block="cart")
    >>> result.checks["exact"].verdict
    'no overturning'
    >>> round(result.to_dict()["spectrum_check"]["exact"]["min_ratio"], 2)
    2.78
    >>> fig = result.plot(figure="spectrum")  # paper Fig. 8
    """

    model: str
    configuration: str
    block: str
    pivot: str
    rocking: RockingBlock
    operating_amplitude: float
    rectangular: RectangularPulseLimits
    half_sine: OverturningLimits
    one_sine: OverturningLimits
    one_cosine: OverturningLimits
    curves: OverturningLimits
    spectrum: Spectrum | None
    checks: dict[str, SpectrumCheck]
    include_vertical: bool
    vertical_acceleration: float

    @property
    def weight(self) -> str:
        """The weight the limits use, in words."""
        return weight_text(self.include_vertical, self.vertical_acceleration)

    def to_dict(self) -> dict:
        """The ``freestand overturn --json`` document (one configuration).

        Keys: ``block``, ``configuration``, ``pivot``, ``R`` [m], ``alpha``
        [rad], ``p`` [rad/s], ``inertia_about_pivot`` [kg m^2],
        ``uplift_threshold`` [m/s^2], ``restitution`` [-], ``other_pivot``,
        ``rectangular`` (``amplitude`` [m/s^2], ``housner``/``exact`` [s]),
        ``half_sine`` (``frequency`` [Hz], ``housner``/``linear``/``exact``
        [m/s^2]), ``one_sine``, ``one_cosine``, ``operating_amplitude``
        [m/s^2], ``overturns_below_frequency`` [Hz] by limit,
        ``spectrum_check``, ``weight``, ``vertical_acceleration`` [m/s^2],
        ``conclusion`` and ``figures`` (files the command wrote).

        Returns
        -------
        dict
            JSON-ready: str, int, float, bool, None, lists and dicts
            (non-finite floats as None).
        """
        first, other = self.rocking.about("pivot"), self.rocking.about("other")
        rectangular, half_sine = self.rectangular, self.half_sine
        return {
            "block": self.block,
            "configuration": self.configuration,
            "pivot": self.pivot,
            "R": first.R,
            "alpha": first.alpha,
            "p": first.p,
            "inertia_about_pivot": first.inertia_about_pivot,
            "uplift_threshold": first.uplift_threshold,
            "restitution": self.rocking.restitution,
            "other_pivot": {
                "R": other.R,
                "alpha": other.alpha,
                "p": other.p,
                "uplift_threshold": other.uplift_threshold,
            },
            "rectangular": [
                {"amplitude": float(a), "housner": finite(h), "exact": finite(e)}
                for a, h, e in zip(
                    rectangular.amplitude, rectangular.housner, rectangular.exact, strict=True
                )
            ],
            "half_sine": [
                {
                    "frequency": float(f),
                    "housner": finite(half_sine.limits["housner"][k]),
                    "linear": finite(half_sine.limits["makris-roussos"][k]),
                    "exact": finite(half_sine.limits["exact"][k]),
                }
                for k, f in enumerate(half_sine.frequency)
            ],
            "one_sine": [
                {"frequency": float(f), "exact": finite(self.one_sine.limits["exact"][k])}
                for k, f in enumerate(self.one_sine.frequency)
            ],
            "one_cosine": [
                {"frequency": float(f), "exact": finite(self.one_cosine.limits["exact"][k])}
                for k, f in enumerate(self.one_cosine.frequency)
            ],
            "operating_amplitude": self.operating_amplitude,
            "overturns_below_frequency": {
                k: finite(v) for k, v in self.curves.operating_frequency.items()
            },
            "spectrum_check": {
                name: {
                    "verdict": check.verdict,
                    "min_ratio": finite(check.min_ratio),
                    "frequency": finite(check.frequency_at_min),
                    "spectrum": check.spectrum_label,
                }
                for name, check in self.checks.items()
            },
            "weight": "m (g - a_v)" if self.include_vertical else "m g",
            "vertical_acceleration": self.vertical_acceleration,
            "conclusion": CONCLUSION,
            "figures": [],
        }

    def to_frame(self, table: str = "pulses"):
        """The pulse limits as a DataFrame.

        Parameters
        ----------
        table : {"pulses", "rectangular"}
            ``"pulses"`` (default): one row per pulse frequency asked, columns
            ``frequency [Hz]``, ``half_sine_duration [s]`` (1 / (2 f)), the
            minimum overturning amplitudes ``half_sine_housner [m/s^2]``
            (Housner 1963, eq. 12), ``half_sine_makris_roussos [m/s^2]``
            (Makris and Roussos 2000, eq. 27), ``half_sine_exact [m/s^2]``,
            ``one_sine_exact [m/s^2]``, ``one_cosine_exact [m/s^2]`` (Zhang
            and Makris 2001; NaN where none was found). ``"rectangular"``: one
            row per pulse amplitude, columns ``amplitude [m/s^2]``,
            ``housner [s]``, ``exact [s]`` (shortest overturning duration, inf
            where it never overturns).

        ``attrs``: ``model``, ``configuration``, ``block``, ``pivot``,
        ``weight``, ``operating_amplitude [m/s^2]``.

        Returns
        -------
        pandas.DataFrame
            The table described above: units in the column names, metadata in
            ``attrs``.
        """
        attrs = {
            "model": self.model,
            "configuration": self.configuration,
            "block": self.block,
            "pivot": self.pivot,
            "weight": "m (g - a_v)" if self.include_vertical else "m g",
            "operating_amplitude [m/s^2]": self.operating_amplitude,
        }
        if table == "rectangular":
            r = self.rectangular
            rows = [
                dict(zip(RECTANGULAR_COLUMNS, values, strict=True))
                for values in zip(r.amplitude, r.housner, r.exact, strict=True)
            ]
            return frame(rows, RECTANGULAR_COLUMNS, attrs)
        if table != "pulses":
            raise ValueError(f"{table!r} is not a table; use 'pulses' or 'rectangular'")
        h = self.half_sine
        values = zip(
            h.frequency, 0.5 / h.frequency, h.limits["housner"], h.limits["makris-roussos"],
            h.limits["exact"], self.one_sine.limits["exact"], self.one_cosine.limits["exact"],
            strict=True,
        )  # fmt: skip
        rows = [dict(zip(PULSE_COLUMNS, row, strict=True)) for row in values]
        return frame(rows, PULSE_COLUMNS, attrs)

    def plot(self, ax=None, figure: str = "half-sine"):
        """A figure of the check, as ``freestand overturn --plot`` writes it.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Draw into these axes (default: a new figure).
        figure : {"half-sine", "rectangular", "spectrum"}
            ``"half-sine"``: the minimum overturning amplitude of a half-sine
            pulse against its frequency by the three limits (paper Fig. 7);
            ``"rectangular"``: the shortest overturning rectangular pulse
            against its amplitude (Fig. 6); ``"spectrum"``: the horizontal
            spectrum against the limits (Fig. 8; needs a spectrum).

        Returns
        -------
        matplotlib.figure.Figure
        """
        from freestand.plot.overturning import (
            plot_pulse_limits,
            plot_rectangular_pulse,
            plot_spectrum_check,
        )

        if figure == "rectangular":
            amplitudes = rectangular_amplitude_grid(self.rocking, self.operating_amplitude)
            curve = rectangular_pulse_limits(
                self.rocking, amplitudes, operating_amplitude=self.operating_amplitude
            )
            return plot_rectangular_pulse(curve, ax=ax)
        if figure == "half-sine":
            return plot_pulse_limits(self.curves, ax=ax)
        if figure == "spectrum":
            if self.spectrum is None:
                raise FreestandError(
                    "no horizontal spectrum to compare with; give spectrum=... (a Spectrum "
                    "or 'rg1.60:pga=0.3g')",
                    source="spectrum",
                )
            return plot_spectrum_check(self.curves, self.spectrum, self.checks, ax=ax)
        raise ValueError(f"{figure!r} is not a figure; use one of {', '.join(FIGURES)}")


def overturning(
    model,
    *,
    configuration: str | None = None,
    block: str | None = None,
    pivot: str | None = None,
    spectrum: Spectrum | str | None = None,
    amplitudes: Sequence[float] | None = None,
    frequencies: Sequence[float] | None = None,
    restitution: float | None = None,
    include_vertical: bool = False,
    excitations: Excitation | Iterable[Excitation] | None = None,
    gravity: float | None = None,
    direction: float | None = None,
    progress: Callable[[], None] | None = None,
) -> OverturningResult | BodyOverturningResult:
    """Overturning of a rocking block with nothing on top, on a steady body (paper section 5).

    The block's rocking properties about both pivots (Housner 1963: R,
    alpha, p = sqrt(m g R / I_O), the uplift threshold g tan(alpha) and the
    angular-velocity ratio at impact 1 - 2 m R^2 sin^2(alpha) / I_O), the
    shortest overturning rectangular pulse (Housner's t1 = ln[A / (A - 1)] / p
    and the exact value), the minimum overturning amplitude of half-sine
    pulses by Housner's criterion a / (g alpha) = sqrt(1 + (omega / p)^2),
    the corrected linearised limit (Makris and Roussos 2000, eq. 27) and the
    exact nonlinear rocking equation with impacts (Zhang and Makris 2001),
    one-sine and one-cosine pulses, and a horizontal spectrum against each
    limit (paper Fig. 8).

    A 3-D configuration (a box or a cylinder): the minimum overturning
    amplitude of half-sine, one-sine and one-cosine pulses along
    ``direction`` at the frequencies asked, by the 3-D engine (it may slide,
    rock about an edge or a corner, roll on its rim) with the planar search
    (:mod:`freestand.core.rocking.body_overturning`), beside the planar limits
    of the block in the pulse's vertical plane; the result is a
    :class:`~freestand.api.body_overturning.BodyOverturningResult`. ``block``
    may only name the body; ``pivot``, ``spectrum``, ``amplitudes`` and
    ``restitution`` are for planar blocks. Each frequency costs some tens to
    hundreds of 3-D simulations (seconds).

    Parameters
    ----------
    model : ModelFile, Stack, Block or BodyConfiguration
        A loaded model file, a stack (its top block is checked unless
        ``block`` names it) or a single block on a steady base.
    configuration : str, optional
        Configuration of the model (default: the first).
    block : str, optional
        The rocking block: the top of its stack (default: the top block).
    pivot : {"left", "right"}, optional
        The pivot (default: the one it rocks about in screening under the
        excitations, else the one with the lower uplift threshold).
    spectrum : Spectrum or str, optional
        The horizontal spectrum (default: the model's), or a ``--spectrum``
        text (``"rg1.60:pga=0.3g"``, a model spectrum's name, a CSV file).
    amplitudes : sequence of float, optional
        Rectangular pulse amplitudes [m/s^2] (default: the excitations').
    frequencies : sequence of float, optional
        Pulse frequencies [Hz] (default 0.25, 0.5, 1, 2, 5).
    restitution : float, optional
        Angular-velocity ratio at impact [-] in place of Housner's.
    include_vertical : bool, optional
        Weight m (g - a_v) with the largest downward a_v of the excitations
        (default m g).
    excitations : Excitation or sequence of Excitation, optional
        In place of the model's (for a stack or block: give them, or ``amplitudes``).
    gravity : float, optional
        g [m/s^2] (default: the model's, 9.81 otherwise).
    direction : float, optional
        3-D configurations: phi [deg] of the pulses' positive acceleration,
        from +x towards +y (default: the direction of the lowest uplift
        threshold, every 15 deg). A planar block refuses it.
    progress : callable, optional
        3-D configurations: called once per pulse kind and frequency done.

    Returns
    -------
    OverturningResult or BodyOverturningResult
        ``to_dict()`` (the ``freestand overturn --json`` document),
        ``to_frame()`` (limits per frequency) and ``plot()`` (Figs. 6-8).

    Examples
    --------
    >>> import freestand as fs
    >>> model = fs.load_model("examples/crane.toml")
    >>> result = fs.overturning(model, configuration="x-z cart right", block="cart")
    >>> result.pivot, round(result.rocking.about("pivot").alpha, 3)
    ('right', 0.439)
    >>> result.to_frame().columns[:3].tolist()
    ['frequency [Hz]', 'half_sine_duration [s]', 'half_sine_housner [m/s^2]']

    A 3-D cabinet under pulses along y:

    >>> bodies = fs.load_model("examples/bodies.toml")
    >>> cabinet = fs.overturning(bodies, configuration="cabinet", direction=90, frequencies=[0.5])
    >>> cabinet.half_sine.pivot, round(float(cabinet.half_sine.amplitude[0]), 2)  # [m/s^2]
    ('edge -y', 3.32)
    """
    if isinstance(model, Block):
        model = Stack(model.name, (model,))
    what = subject(model, excitations, gravity)
    body = body_configuration(what, configuration)
    if body is not None:
        check_body_options(body, block, pivot, spectrum, amplitudes, restitution)
        return body_overturning(
            what.name, body, _frequencies(frequencies), direction=direction,
            operating_amplitude=largest_horizontal(what.excitations),
            vertical_acceleration=(
                vertical_for_overturning(what.excitations) if include_vertical else 0.0
            ),
            include_vertical=include_vertical, gravity=what.gravity, progress=progress,
        )  # fmt: skip
    stack = what.configuration(configuration)
    check_planar_direction(stack.name, direction)
    block_name = stack.blocks[-1].name if block is None else block
    vertical = vertical_for_overturning(what.excitations) if include_vertical else 0.0
    pivot, rocking = _rocking_block(what, stack, block_name, pivot, vertical, restitution)
    amplitude_values = _amplitudes(amplitudes, what.excitations)
    frequency_values = _frequencies(frequencies)
    horizontal = resolve_spectrum(spectrum, what, "horizontal")
    operating = (
        max(e.horizontal for e in what.excitations) if what.excitations else max(amplitude_values)
    )
    requested = np.array(sorted(set(frequency_values)))
    curves = overturning_limits(
        rocking, CURVE_FREQUENCIES, kind="half-sine", operating_amplitude=operating
    )
    return OverturningResult(
        model=what.name,
        configuration=stack.name,
        block=block_name,
        pivot=pivot,
        rocking=rocking,
        operating_amplitude=operating,
        rectangular=rectangular_pulse_limits(
            rocking, np.array(amplitude_values), operating_amplitude=operating
        ),
        half_sine=overturning_limits(rocking, requested, kind="half-sine"),
        one_sine=overturning_limits(rocking, requested, kind="one-sine"),
        one_cosine=overturning_limits(rocking, requested, kind="one-cosine"),
        curves=curves,
        spectrum=horizontal,
        checks=check_spectrum(curves, horizontal) if horizontal is not None else {},
        include_vertical=include_vertical,
        vertical_acceleration=vertical,
    )


def check_planar_direction(name: str, direction: float | None) -> None:
    """FreestandError for a pulse direction given for the planar configuration ``name``."""
    if direction is not None:
        raise FreestandError(
            f"--direction {direction:g} is the direction of the pulses on a 3-D configuration "
            f"(a box or a cylinder), and {name!r} is planar (its pulses act in its plane); "
            "leave --direction out, or choose a 3-D configuration",
            source="--direction",
        )


def check_body_options(configuration, block, pivot, spectrum, amplitudes, restitution) -> None:
    """FreestandError for an option of a planar block given for a 3-D configuration."""
    name = configuration.body.name
    if block is not None and block != name:
        raise FreestandError(
            f"no block named {block!r} in the 3-D configuration {configuration.name!r}: its "
            f"body is {name!r}; leave --block out or give {name!r}",
            source="--block",
        )
    planar_only = {
        "--pivot": (pivot, "the body tips about the edge, corner or rim point the pulse drives"),
        "--spectrum": (spectrum, "the 3-D limits are computed at a few frequencies only"),
        "--amplitudes": (amplitudes, "rectangular pulses are planar"),
        "--restitution": (restitution, "the 3-D impacts are plastic"),
    }
    for option, (value, why) in planar_only.items():
        if value is not None:
            raise FreestandError(
                f"{option} is for planar blocks, and {configuration.name!r} is 3-D ({why}); "
                f"leave {option} out, or choose a planar configuration",
                source=option,
            )


def check_block(what, stack: Stack, block_name: str, pivot: str | None) -> Block:
    """The block to check: it exists, carries nothing and can stand; a FreestandError else."""
    try:
        index = stack.block_index(block_name)
    except KeyError:
        names = ", ".join(repr(b.name) for b in stack.blocks)
        raise FreestandError(
            f"no block named {block_name!r} in configuration {stack.name!r}; choose one of {names}",
            source="--block",
        ) from None
    if index != len(stack.blocks) - 1:
        above = stack.blocks[index + 1].name
        raise FreestandError(
            f"block {block_name!r} carries {above!r}; the overturning check is for a block with "
            "nothing on top, resting on a steady body (the paper's cart on the steady bridge)",
            source="--block",
        )
    if pivot is not None and pivot not in ("left", "right"):
        raise FreestandError(f"{pivot!r} is not a pivot; use 'left' or 'right'", source="--pivot")
    block = stack.blocks[index]
    if not block.base_left < block.centre[0] < block.base_right:
        where = what.model.source if what.model is not None else "the model"
        raise FreestandError(
            f"the centre of gravity of {block_name!r} (x = {block.centre[0]:g} m) does not lie "
            f"between its contacts ({block.base_left:g} .. {block.base_right:g} m): it cannot "
            f"stand, let alone rock about one contact; check its centre and base in {where}",
            source="--block",
        )
    return block


def _rocking_block(what, stack, block_name, pivot, vertical, restitution):
    """(pivot, RockingBlock) of the block to check, after the checks of :func:`check_block`."""
    block = check_block(what, stack, block_name, pivot)
    if pivot is None:
        pivot = _default_pivot(what, stack, block)
    if restitution is not None and not 0 <= restitution <= 1:
        raise FreestandError(
            f"{restitution} is not an angular-velocity ratio; give a value in [0, 1] "
            "(Housner's energy ratio r is its square)",
            source="--restitution",
        )
    rocking = RockingBlock.from_block(
        block,
        pivot,
        gravity=what.gravity,
        vertical_acceleration=vertical,
        restitution_override=restitution,
    )
    return pivot, rocking


def _default_pivot(what, stack: Stack, block: Block) -> str:
    """The pivot the block rocks about under the excitations, else the easier one."""
    for excitation in sorted(what.excitations, key=lambda e: -e.horizontal):
        for sense in (1, -1):
            case = initial_motion(
                stack, excitation.horizontal, excitation.vertical, sense, what.gravity
            )
            if case.blocks:
                state = case.block(block.name)
                if state.motion in (Motion.ROCK, Motion.SLIDE_ROCK):
                    return state.pivot
    thresholds = {
        side: RockingBlock.from_block(block, side, gravity=what.gravity).uplift_threshold
        for side in ("left", "right")
    }
    return min(thresholds, key=thresholds.get)


def _amplitudes(amplitudes, excitations) -> list[float]:
    if amplitudes is None:
        if not excitations:
            raise FreestandError(
                "no amplitude to check; give amplitudes=[...] [m/s^2] or excitations",
                source="--amplitudes",
            )
        return sorted({e.horizontal for e in excitations})
    values = [float(value) for value in amplitudes]
    for value in values:
        if not value > 0:
            raise FreestandError(
                f"{value:g} m/s^2 is not a positive amplitude; e.g. --amplitudes 0.5g,1g",
                source="--amplitudes",
            )
    return values


def _frequencies(frequencies) -> list[float]:
    if frequencies is None:
        return list(TABLE_FREQUENCIES)
    values = [float(value) for value in frequencies]
    for value in values:
        if not MIN_FREQUENCY <= value <= MAX_FREQUENCY:
            raise FreestandError(
                f"{value:g} Hz is not a pulse frequency; give frequencies between "
                f"{MIN_FREQUENCY:g} and {MAX_FREQUENCY:g} Hz, e.g. --frequencies 0.5,1,2",
                source="--frequencies",
            )
    return values
