"""Reading the options of a fragility campaign: intensity measure, levels, outcomes.

Syntax::

    --im pga | pgv | sa:2.5[,5%] | sa:2.5Hz,0.02 | pga-alpha[:BLOCK]
         two horizontal components (x and y): pga-gm | pga-rotd50 | pga-rotd100
         | pgv-gm | pgv-rotd50 | pgv-rotd100 | sa-gm:F[,DAMPING] | sa-rotd50:F[,DAMPING]
         | sa-rotd100:F[,DAMPING]
    --levels 0.5:10:20           20 levels from 0.5 to 10 (IM unit, or with units:
                                 0.05g:1g:20), or a list 1,2,4,8
    --outcome overturn:cart | rotation:cart>0.5alpha | rotation:cart>0.1rad
              | slide:cart>0.05m | slide:cart>5cm | uplift:bridge | flight:cart
              | twist:cask>5 (3-D bodies; deg, or with a unit: 0.1rad)
    --angle 30 | --angles 8      3-D: a fixed incidence angle [deg], or N angles every
                                 360/N deg (default: drawn uniformly per simulation)

Every problem raises :class:`freestand.errors.FreestandError` naming the
option, the value and the fix.
"""

from __future__ import annotations

import math
import re

import numpy as np

from freestand.core.body import BodyConfiguration
from freestand.core.model import Stack
from freestand.core.sweeps.fragility.intensity import KINDS, IntensityMeasure
from freestand.core.sweeps.fragility.outcomes import BODY_ONLY_KINDS, Outcome
from freestand.core.sweeps.fragility.outcomes import KINDS as OUTCOME_KINDS
from freestand.errors import FreestandError
from freestand.io.table_keys import TableKey
from freestand.io.units import to_si

_QUANTITY = {"m/s^2": "acceleration", "-": "dimensionless"}


#: The keys of a model file's ``[fragility]`` table (the options of ``freestand fragility``).
FRAGILITY_KEYS = {
    "suite": TableKey("the record suite file, relative to the model file", required=True),
    "configuration": TableKey("the configuration", shown_default="the first"),
    "im": TableKey(
        "the intensity measure, as --im", shown_default='"pga" (planar), "pga-rotd50" (3-D)'
    ),
    "levels": TableKey(
        'the levels, as --levels, e.g. "1:8:15" (IM unit); or cloud = true',
        shown_default="required without cloud",
    ),
    "cloud": TableKey("run the records unscaled (cloud analysis)", default=False),
    "outcomes": TableKey(
        "the outcomes, as --outcome", default=(), shown_default="per configuration"
    ),
    "vary": TableKey("uncertain inputs, as --vary", default=(), shown_default="none"),
    "samples": TableKey("samples per record and level", "-", shown_default="1; 10 with vary"),
    "both_polarities": TableKey("also run every record negated", default=False),
    "seed": TableKey("seed of the inputs and of the bootstrap", "-", default=0),
    "bootstrap": TableKey("bootstrap replicates", "-", default=1000),
    "free_time": TableKey("cap on the time simulated after a record", "s", default=10.0),
    "angle": TableKey(
        "3-D: a fixed incidence angle of the records' x axis, as --angle",
        "deg",
        shown_default="drawn uniformly over 0-360 deg per simulation",
    ),
    "angles": TableKey("3-D: every record at N incidence angles, as --angles", "-"),
}

#: Most samples per record and level: with 1000 levels and a suite of 30 records, 3e8
#: simulations already; beyond, a typo (--samples 100000000) would not finish.
MAX_SAMPLES = 10_000

#: Most incidence angles of a sweep (--angles): every degree.
MAX_ANGLES = 360

#: The default IM of a planar configuration and of a 3-D one.
DEFAULT_IM = "pga"
DEFAULT_BODY_IM = "pga-rotd50"


def parse_intensity(text: str, stack: Stack | None, option: str = "--im") -> IntensityMeasure:
    """Read ``pga``, ``pgv``, ``sa:F[,DAMPING]``, ``pga-alpha[:BLOCK]`` or a two-component IM.

    Two-component IMs (records with x and y): ``pga-gm``, ``pga-rotd50``,
    ``pga-rotd100``, the same for ``pgv``, and ``sa-gm:F[,DAMPING]``,
    ``sa-rotd50:F[,DAMPING]``, ``sa-rotd100:F[,DAMPING]``. ``stack`` (the
    configuration) is needed by ``pga-alpha`` alone; whether the
    configuration can take a two-component IM is :func:`check_planar_intensity`.
    """
    kind, _, rest = text.strip().partition(":")
    kind = kind.strip().lower()
    if kind not in KINDS:
        raise FreestandError(
            f"{text!r} is not an intensity measure; use pga, pgv, sa:FREQUENCY[,DAMPING] "
            "(e.g. sa:2.5Hz,5%) or pga-alpha[:BLOCK], or for two horizontal components "
            "pga-gm, pga-rotd50, pga-rotd100, pgv-rotd50, sa-rotd50:FREQUENCY[,DAMPING], ...",
            source=option,
        )
    if kind == "sa" or kind.startswith("sa-"):
        if not rest.strip():
            raise FreestandError(
                f"{text!r} needs a frequency; e.g. {kind}:2.5Hz or {kind}:2.5,5%", source=option
            )
        from freestand.io.records import parse_spectral_target

        target = parse_spectral_target(f"1@{rest}", source=option)
        return IntensityMeasure(kind, frequency=target.frequency, damping=target.damping)
    if kind == "pga-alpha":
        if stack is None:
            raise FreestandError(
                f"{text!r} is a multiple of a block's rocking threshold; give the configuration "
                "(a planar stack) it is of",
                source=option,
            )
        block = rest.strip() or stack.blocks[-1].name
        names = [b.name for b in stack.blocks]
        if block not in names:
            raise FreestandError(
                f"configuration {stack.name!r} has no block {block!r}; its blocks are "
                f"{', '.join(names)}",
                source=option,
            )
        return IntensityMeasure("pga-alpha", block=block)
    if rest.strip():
        raise FreestandError(f"{kind} takes no argument, not {rest!r}", source=option)
    return IntensityMeasure(kind)


def _level(text: str, unit: str, option: str, gravity: float) -> float:
    text = text.strip()
    try:
        return float(text)
    except ValueError:
        pass
    if unit == "-":
        raise FreestandError(f"{text!r} is not a number (the IM is dimensionless)", source=option)
    if unit == "m/s":
        return _pint(text, "m/s", option)
    return to_si(text, _QUANTITY[unit], field="level", source=option, gravity=gravity)


def _pint(text: str, unit: str, option: str) -> float:
    """``text`` with a unit (e.g. ``"30 cm/s"``, ``"5 deg"``) in ``unit``."""
    import pint

    try:
        return float(pint.UnitRegistry().Quantity(text).to(unit).magnitude)
    except (pint.errors.PintError, ValueError, TypeError, AttributeError):
        raise FreestandError(
            f"{text!r} is not a value in {unit} (or with a unit such as cm/s, deg)", source=option
        ) from None


def parse_levels(
    text: str, measure: IntensityMeasure, gravity: float = 9.81, option: str = "--levels"
) -> np.ndarray:
    """Read ``A:B:N`` (N levels evenly from A to B) or a list ``x1,x2,...`` [IM unit, SI]."""
    parts = text.split(":")
    if len(parts) == 3:
        try:
            count = int(parts[2])
        except ValueError:
            raise FreestandError(
                f"{parts[2]!r} is not a number of levels; write A:B:N, e.g. 0.5:10:20",
                source=option,
            ) from None
        start = _level(parts[0], measure.unit, option, gravity)
        stop = _level(parts[1], measure.unit, option, gravity)
        if count < 2 or count > 1000:
            raise FreestandError(f"{count} levels: give 2 to 1000", source=option)
        levels = np.linspace(start, stop, count)
    elif len(parts) == 1:
        levels = np.array(
            [_level(p, measure.unit, option, gravity) for p in text.split(",") if p.strip()]
        )
    else:
        raise FreestandError(
            f"{text!r} is not A:B:N or a list; e.g. 0.5:10:20 or 1,2,4", source=option
        )
    return check_levels(levels, option, text)


def check_levels(levels, option: str = "--levels", text: str | None = None) -> np.ndarray:
    """The levels [IM unit] as an array; a FreestandError unless positive and increasing."""
    levels = np.atleast_1d(np.asarray(levels, dtype=float))
    if levels.size == 0 or np.any(~(levels > 0)) or np.any(np.diff(levels) <= 0):
        given = text if text is not None else ", ".join(f"{x:g}" for x in levels)
        raise FreestandError(
            f"{given!r}: the levels must be positive and increasing; e.g. 0.5:10:20",
            source=option,
        )
    return levels


_OUTCOME = re.compile(
    r"^\s*(?P<kind>[a-z]+)\s*:\s*(?P<block>[^>]+?)\s*(?:>\s*(?P<threshold>.+?))?\s*$"
)


def parse_outcome(
    text: str, blocks, option: str = "--outcome", *, three_d: bool = False
) -> Outcome:
    """Read an outcome such as ``overturn:cart``, ``slide:cart>0.05m`` or ``twist:cask>5``.

    Parameters
    ----------
    text : str
    blocks : sequence of str
        The block names of the configuration.
    option : str, optional
        Option name for messages.
    three_d : bool, optional
        Whether the configuration is a 3-D body (``twist`` is refused for
        planar stacks).
    """
    match = _OUTCOME.match(text)
    if not match or match["kind"] not in OUTCOME_KINDS:
        raise FreestandError(
            f"{text!r} is not an outcome; use overturn:BLOCK, rotation:BLOCK>0.5alpha, "
            "slide:BLOCK>0.05m, uplift:BLOCK or flight:BLOCK, or for a 3-D body "
            "twist:BODY>DEGREES",
            source=option,
        )
    kind, block, threshold = match["kind"], match["block"], match["threshold"]
    if kind in BODY_ONLY_KINDS and not three_d:
        raise FreestandError(
            f"{text!r}: {kind} (the rotation about the vertical) is an outcome of 3-D bodies; "
            "this configuration is planar: use overturn, rotation, slide, uplift or flight",
            source=option,
        )
    if block not in blocks:
        raise FreestandError(
            f"{text!r}: no block {block!r}; the blocks are {', '.join(blocks)}", source=option
        )
    if kind in ("overturn", "uplift", "flight"):
        if threshold is not None:
            raise FreestandError(f"{text!r}: {kind} takes no threshold", source=option)
        return Outcome(kind, block)
    if threshold is None:
        example = {"rotation": "0.5alpha", "slide": "0.05m", "twist": "5deg"}[kind]
        raise FreestandError(
            f"{text!r}: give a threshold, e.g. {kind}:{block}>{example}", source=option
        )
    threshold = threshold.replace(" ", "")
    if kind == "twist":
        value = float(threshold) if _is_float(threshold) else _pint(threshold, "deg", option)
        return _outcome(text, kind, block, value, "deg", option)
    if kind == "rotation":
        if threshold.endswith("alpha"):
            number, unit = threshold[: -len("alpha")] or "1", "alpha"
            try:
                value = float(number)
            except ValueError:
                raise FreestandError(
                    f"{text!r}: {number!r} is not a number; e.g. rotation:{block}>0.5alpha",
                    source=option,
                ) from None
        else:
            value = float(threshold) if _is_float(threshold) else _pint(threshold, "rad", option)
            unit = "rad"
    else:
        value = (
            float(threshold)
            if _is_float(threshold)
            else to_si(threshold, "length", field="threshold", source=option)
        )
        unit = "m"
    return _outcome(text, kind, block, value, unit, option)


def _outcome(text: str, kind: str, block: str, value: float, unit: str, option: str) -> Outcome:
    try:
        return Outcome(kind, block, value, unit)
    except ValueError as error:
        raise FreestandError(f"{text!r}: {error}", source=option) from None


def _is_float(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def check_planar_intensity(measure: IntensityMeasure, stack: Stack, option: str = "--im") -> None:
    """Refuse an IM of two horizontal components for a planar configuration.

    A planar model moves under the x component alone, so its fragility is
    read against a one-component IM (``pga``, ``pgv``, ``sa``, ``pga-alpha``);
    a two-component IM (geometric mean, RotD50, RotD100) measures a y
    component the model never feels and is for 3-D configurations.
    """
    if measure.two_components:
        raise FreestandError(
            f"{measure.kind} ({measure.describe()}) measures two horizontal components (x and "
            f"y), for 3-D configurations; configuration {stack.name!r} is planar and moves "
            "under x alone: use pga, pgv, sa:FREQUENCY[,DAMPING] or pga-alpha[:BLOCK]",
            source=option,
        )


def chosen_configuration(model, name: str | None) -> Stack | BodyConfiguration:
    """The configuration called ``name`` (planar or 3-D); None: the first planar one, or the
    first 3-D one in a model that has no planar configuration."""
    bodies = model.body_configurations
    if name is None:
        if bodies and not model.configurations:
            return bodies[0]
        return model.first_configuration()
    return next((body for body in bodies if body.name == name), None) or model.configuration(name)


def check_body_intensity(kind: str, body: BodyConfiguration, source: str = "") -> None:
    """FreestandError for an IM kind (``--im`` before its ``:``) a 3-D campaign cannot take."""
    if kind == "pga-alpha":
        raise FreestandError(
            f"pga-alpha is a multiple of a planar block's rocking threshold; {body.name!r} is "
            "3-D, its threshold depends on the direction: use pga-rotd50 (the default), "
            "pga-rotd100, pga-gm, sa-rotd50:F, or pga, pgv, sa:F of the record's x component",
            source=source + "--im",
        )


def check_body_variations(variations, texts, body: BodyConfiguration, option: str) -> None:
    """FreestandError for an uncertain input a 3-D body does not have or that repeats."""
    from freestand.core.sweeps.fragility.campaign import BODY_FIELDS

    seen = set()
    for variation, text in zip(variations, texts, strict=True):
        parameter = variation.parameter
        if parameter.field in ("horizontal", "vertical"):
            continue  # refused below with the planar message
        if parameter.field not in BODY_FIELDS:
            raise FreestandError(
                f"{text!r}: a 3-D body's {parameter.field} cannot be varied yet; vary "
                f"{', '.join(f'{body.name}.{f}' for f in BODY_FIELDS)}",
                source=option,
            )
        if parameter.block not in (None, body.name):
            raise FreestandError(
                f"{text!r}: configuration {body.name!r} has no block {parameter.block!r}; its "
                f"body is {body.name}",
                source=option,
            )
        if parameter.field in seen:
            raise FreestandError(
                f"{text!r}: {parameter.field} is varied twice; give it once", source=option
            )
        seen.add(parameter.field)


def check_planar_angles(stack: Stack, angle, angles, source: str = "") -> None:
    """FreestandError for an incidence angle given for a planar configuration."""
    for option, value in (("--angle", angle), ("--angles", angles)):
        if value is not None:
            raise FreestandError(
                f"{option} {value:g} turns the horizontal pair of a 3-D configuration; "
                f"configuration {stack.name!r} is planar and moves under x alone: leave "
                f"{option} out, or choose a 3-D configuration",
                source=source + option,
            )


def incidence_angles(angle, angles, source: str = "") -> tuple[float, ...]:
    """The fixed incidence angles [deg] of ``--angle A`` or ``--angles N`` (every 360/N deg);
    empty for neither (one drawn per simulation)."""
    if angle is not None and angles is not None:
        raise FreestandError(
            "give --angle (one fixed angle) or --angles N (a sweep), not both",
            source=source + "--angles",
        )
    if angle is not None:
        if not math.isfinite(angle):
            raise FreestandError(
                f"{angle!r} is not an angle; give degrees, e.g. --angle 30",
                source=source + "--angle",
            )
        return (float(angle),)
    if angles is not None:
        if not 1 <= angles <= MAX_ANGLES:
            raise FreestandError(
                f"{angles} angles: give 1 to {MAX_ANGLES} (every 360/N deg), e.g. --angles 8",
                source=source + "--angles",
            )
        return tuple(360.0 * k / angles for k in range(angles))
    return ()


def build_campaign(
    model, configuration, suite, im, levels, vary, samples, outcome, both_polarities, seed,
    free_time, *, source: str = "", angle: float | None = None, angles: int | None = None,
):  # fmt: skip
    """The campaign of the command-line options (or of a model's ``[fragility]`` table).

    Parameters
    ----------
    model : ModelFile
    configuration : str or None
        Configuration name (None: the first).
    suite : str, Path or RecordSuite
        Record suite file (or the suite, loaded).
    im : str, IntensityMeasure or None
        ``--im`` (None: ``pga`` for a planar configuration, ``pga-rotd50``
        for a 3-D one).
    levels : str, sequence of float or None
        ``--levels`` (``"A:B:N"`` or a list) or the levels [IM unit]; None for
        a cloud analysis.
    vary : list of str or Variation, or None
        ``--vary`` options.
    samples : int or None
        Samples per record and level (None: 1, or 10 with variations).
    outcome : list of str or Outcome, or None
        ``--outcome`` options (None: the configuration's defaults).
    both_polarities : bool
    seed : int
    free_time : float
        Cap on the time simulated after a record [s].
    source : str, optional
        Prefix of option names in messages (e.g. the model file's table).
    angle : float, optional
        3-D: a fixed incidence angle [deg] (``--angle``).
    angles : int, optional
        3-D: N incidence angles every 360/N deg (``--angles``); with neither,
        one angle per simulation drawn uniformly over [0, 360).

    Returns
    -------
    tuple
        (Campaign, RecordSuite).
    """
    from freestand.core.sweeps.fragility.campaign import Campaign
    from freestand.core.sweeps.fragility.outcomes import default_body_outcomes, default_outcomes
    from freestand.core.sweeps.sampling import Variation
    from freestand.io.parameters import check_parameters, parse_variation
    from freestand.io.suites import RecordSuite, load_suite

    cloud = levels is None
    stack = chosen_configuration(model, configuration)
    three_d = isinstance(stack, BodyConfiguration)
    if im is None:
        im = DEFAULT_BODY_IM if three_d else DEFAULT_IM
    if three_d:
        kind = im.kind if isinstance(im, IntensityMeasure) else im.partition(":")[0]
        check_body_intensity(kind.strip().lower(), stack, source)
    measure = (
        im
        if isinstance(im, IntensityMeasure)
        else parse_intensity(im, None if three_d else stack, source + "--im")
    )
    if not three_d:
        check_planar_intensity(measure, stack, source + "--im")
        check_planar_angles(stack, angle, angles, source)
    incidence = incidence_angles(angle, angles, source) if three_d else ()
    level_values = (
        []
        if cloud
        else parse_levels(levels, measure, model.gravity, source + "--levels")
        if isinstance(levels, str)
        else check_levels(levels, source + "--levels")
    )
    variations = [
        text if isinstance(text, Variation) else parse_variation(text, "--vary", model.gravity)
        for text in vary or []
    ]
    if three_d:
        check_body_variations(variations, vary or [], stack, source + "--vary")
    elif variations:
        check_parameters(
            [(v.parameter, str(t)) for v, t in zip(variations, vary or [], strict=True)],
            [stack],
            "--vary",
        )
    for variation, text in zip(variations, vary or [], strict=True):
        if variation.parameter.field in ("horizontal", "vertical"):
            raise FreestandError(
                f"{text!r}: the excitation is set by the records and --levels; vary block "
                "inputs only (mass, inertia, centre, base, friction)",
                source=source + "--vary",
            )
    count = samples if samples is not None else (10 if variations else 1)
    if not 1 <= count <= MAX_SAMPLES:
        raise FreestandError(
            f"{count} samples: give 1 to {MAX_SAMPLES} per record and level, e.g. --samples 10",
            source=source + "--samples",
        )
    names = [b.name for b in (stack.bodies if three_d else stack.blocks)]
    if count > 1 and not variations:
        hint = (
            "leave --samples out (the incidence angles are drawn per simulation; --angles N "
            "runs each at N angles)"
            if three_d
            else f"vary an input (e.g. --vary {names[-1]}.friction.static=uniform(0.4,0.6)) or "
            "leave --samples out"
        )
        raise FreestandError(
            f"{count} samples without --vary would be {count} identical simulations; {hint}",
            source=source + "--samples",
        )
    outcomes = (
        tuple(
            text
            if isinstance(text, Outcome)
            else parse_outcome(text, names, source + "--outcome", three_d=three_d)
            for text in outcome
        )
        if outcome
        else default_body_outcomes(stack)
        if three_d
        else default_outcomes(stack)
    )
    keys = [o.key for o in outcomes]
    if len(set(keys)) != len(keys):
        raise FreestandError(
            f"an outcome repeats in {keys}; give each once", source=source + "--outcome"
        )
    records = suite if isinstance(suite, RecordSuite) else load_suite(suite, gravity=model.gravity)
    try:
        campaign = Campaign(
            stack=stack,
            motions=records.motions,
            measure=measure,
            levels=level_values,
            variations=tuple(variations),
            samples=count,
            polarities=(1, -1) if both_polarities else (1,),
            seed=seed,
            outcomes=outcomes,
            gravity=model.gravity,
            free_time=free_time,
            angles=incidence,
        )
    except ValueError as error:
        raise FreestandError(f"{error}", source=records.source) from None
    if campaign.cloud and (campaign.record_intensity <= 0).any():
        raise FreestandError("a record has zero intensity; remove it", source=records.source)
    return campaign, records
