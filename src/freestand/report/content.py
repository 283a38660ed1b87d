"""What the screening report says: every number, verdict and sentence, before any markup.

:func:`collect_report` runs the same core functions as the ``screen``,
``overturn`` and ``frequency`` commands on a loaded model file and returns a
:class:`ReportContent`: frozen result objects of the core plus the summary
sentences built from them. Rendering (:mod:`freestand.report.html`) only
formats this object; it computes nothing.

Which blocks get an overturning assessment (paper section 5): every block
that rocks (``rock`` or ``slide-rock``) in some screened case, once per
configuration and pivot. The single-block rocking check (Housner 1963;
Makris and Roussos 2000) is meaningful for a block with nothing on top that
rocks on a body at rest (the paper's cart on the steady bridge); a rocking
block that carries another block, or whose supporting block moves in that
case, is listed as not assessed, with the reason, rather than given numbers
that do not apply to it.
"""

from __future__ import annotations

import datetime as _dt
import math
import os
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from freestand import __version__
from freestand.core.contact.screening import BlockState, InitialMotion, Motion, screen
from freestand.core.model import Block, Stack
from freestand.core.motion.spectra import Spectrum, SpectrumCheck
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
from freestand.core.structure.beam import FrequencySweep, JumpCheck, frequency_sweep, jump_check
from freestand.errors import FreestandError
from freestand.io.model_file import ModelFile
from freestand.report.bodies import body_sentences, collect_body_cases

#: Callback told about each step: (description, steps done, steps in all).
Progress = Callable[[str, int, int], None]

_ROCKING = (Motion.ROCK, Motion.SLIDE_ROCK)


@dataclass(frozen=True)
class RockingAssessment:
    """Overturning assessment of one rocking block (paper section 5, Figs. 6-8).

    Parameters
    ----------
    configuration : str
        Configuration name.
    block : str
        Block name.
    pivot : str
        ``"left"`` or ``"right"``: the contact it rocks about.
    pivot_name : str
        The contact's name (the paper's A/B...).
    cases : tuple of str
        The screened cases in which it rocks (``"elastic, sense +"``).
    rocking : RockingBlock
        The block as a rocking body about ``pivot``.
    operating_amplitude : float
        The model's largest horizontal excitation [m/s^2].
    rectangular : RectangularPulseLimits
        Shortest overturning rectangular pulse at the model's excitation
        levels (Housner and exact) [s].
    rectangular_curve : RectangularPulseLimits
        The same over an amplitude grid, for the Fig. 6 analogue.
    half_sine_table : OverturningLimits
        Half-sine limits (Housner, Makris-Roussos, exact) at
        :data:`~freestand.core.rocking.overturning.TABLE_FREQUENCIES` [m/s^2].
    half_sine : OverturningLimits
        The same over :data:`~freestand.core.rocking.overturning.CURVE_FREQUENCIES`,
        with the frequency up to which ``operating_amplitude`` overturns.
    spectrum : Spectrum or None
        The model's horizontal spectrum, if it has one.
    checks : dict of str to SpectrumCheck
        Spectrum against each limit (empty without a spectrum).
    vertical : float
        The largest downward vertical support acceleration a_v [m/s^2] of the
        cases it rocks in (0 if none). Every limit above uses the weight m g;
        the two below use m (g - a_v).
    half_sine_vertical : OverturningLimits or None
        ``half_sine`` with the weight m (g - a_v) (None when a_v = 0).
    rectangular_vertical : RectangularPulseLimits or None
        ``rectangular`` with the weight m (g - a_v) (None when a_v = 0).
    """

    configuration: str
    block: str
    pivot: str
    pivot_name: str
    cases: tuple[str, ...]
    rocking: RockingBlock
    operating_amplitude: float
    rectangular: RectangularPulseLimits
    rectangular_curve: RectangularPulseLimits
    half_sine_table: OverturningLimits
    half_sine: OverturningLimits
    spectrum: Spectrum | None
    checks: dict[str, SpectrumCheck]
    vertical: float = 0.0
    half_sine_vertical: OverturningLimits | None = None
    rectangular_vertical: RectangularPulseLimits | None = None

    @property
    def governing_check(self) -> SpectrumCheck | None:
        """The spectrum check with the smallest margin (None without a spectrum)."""
        finite = [c for c in self.checks.values() if math.isfinite(c.min_ratio)]
        return min(finite, key=lambda c: c.min_ratio) if finite else None

    @property
    def verdict(self) -> str:
        """``"no overturning"``, ``"overturning possible"`` or ``"no spectrum"``/``"undetermined"``.

        Overturning is possible as soon as one limit says so (the linearised
        Housner limit never governs: it is the highest).
        """
        if self.spectrum is None:
            return "no spectrum"
        if not self.checks or all(c.verdict == "undetermined" for c in self.checks.values()):
            return "undetermined"
        if any(c.verdict == "overturning possible" for c in self.checks.values()):
            return "overturning possible"
        return "no overturning"


@dataclass(frozen=True)
class SkippedBlock:
    """A block that rocks in screening but whose single-block overturning check does not apply."""

    configuration: str
    block: str
    reason: str


@dataclass(frozen=True)
class FrequencyAssessment:
    """Vertical frequency of the bridge and the jump check (paper section 6, Fig. 9).

    Parameters
    ----------
    sweep : FrequencySweep
        Dunkerley's and the exact frequency over the cart's positions [Hz].
    parking : tuple of float
        The cart's parking range [m].
    dunkerley_range, exact_range : tuple of float
        Lowest and highest frequency over the parking range [Hz].
    spectrum : Spectrum or None
        The model's vertical spectrum.
    jump : JumpCheck or None
        The jump check over the sweep (None without a vertical spectrum).
    """

    sweep: FrequencySweep
    parking: tuple[float, float]
    dunkerley_range: tuple[float, float]
    exact_range: tuple[float, float]
    spectrum: Spectrum | None
    jump: JumpCheck | None


@dataclass(frozen=True)
class ReportContent:
    """Everything the screening report shows.

    Parameters
    ----------
    model : ModelFile
        The validated model (inputs echoed from it).
    model_file : str
        The model file's name.
    sha256 : str
        Hash of the model file's bytes.
    version : str
        freestand's version.
    date : datetime.date
        Date of the report.
    cases : tuple of InitialMotion
        Screening of every configuration, excitation and sense (paper Tables 2-5).
    overturning : tuple of RockingAssessment
        One per configuration, rocking block and pivot.
    skipped : tuple of SkippedBlock
        Rocking blocks the single-block check does not apply to.
    frequency : FrequencyAssessment or None
        When the model has a ``[beam]`` section.
    summary : tuple of str
        Conclusions in the engineer's terms, one sentence (or short paragraph) each.
    fragility : FragilitySection or None
        When the model file has a ``[fragility]`` table
        (:mod:`freestand.report.fragility`).
    body_cases : tuple of BodyScreeningCase
        The screening of the 3-D configurations by direction
        (:mod:`freestand.report.bodies`).
    body_histories : tuple of BodySimulationResult
        The time history of every 3-D configuration under the report's record
        (:func:`freestand.simulate`), when one was given.
    """

    model: ModelFile
    model_file: str
    sha256: str
    version: str
    date: _dt.date
    cases: tuple[InitialMotion, ...]
    overturning: tuple[RockingAssessment, ...]
    skipped: tuple[SkippedBlock, ...]
    frequency: FrequencyAssessment | None
    summary: tuple[str, ...]
    fragility: object | None = None
    body_cases: tuple = ()
    body_histories: tuple = ()

    @property
    def flagged(self) -> tuple[InitialMotion, ...]:
        """Cases whose state is ambiguous or inconsistent."""
        return tuple(c for c in self.cases if c.status in ("ambiguous", "inconsistent"))


def report_date(option: str | None = None) -> _dt.date:
    """The report's date: ``option`` (YYYY-MM-DD), else ``SOURCE_DATE_EPOCH``, else today.

    ``SOURCE_DATE_EPOCH`` (seconds since 1970, UTC) makes reports reproducible.
    """
    if option is not None:
        try:
            return _dt.date.fromisoformat(option)
        except ValueError:
            raise FreestandError(
                f"{option!r} is not a date; give it as YYYY-MM-DD, e.g. 2024-05-31",
                source="--date",
            ) from None
    epoch = os.environ.get("SOURCE_DATE_EPOCH")
    if epoch:
        try:
            return _dt.datetime.fromtimestamp(int(epoch), tz=_dt.UTC).date()
        except (ValueError, OverflowError, OSError):
            raise FreestandError(
                f"{epoch!r} is not a number of seconds since 1970-01-01; unset it or give "
                "an integer",
                source="SOURCE_DATE_EPOCH",
            ) from None
    return _dt.date.today()


def sense_label(sense: int) -> str:
    """``"+"`` or ``"-"``."""
    return "+" if sense > 0 else "-"


def case_label(case: InitialMotion) -> str:
    """``"elastic, sense +"``."""
    return f"{case.excitation}, sense {sense_label(case.sense)}"


# --- sentences -----------------------------------------------------------------------------------


def _below_name(stack: Stack, index: int) -> str:
    return "support" if index == 0 else stack.blocks[index - 1].name


def block_phrase(stack: Stack, state: BlockState, *, sense: int | None = None) -> str:
    """What one block does, in words: ``"the cart rocks about its right contact B on the bridge"``.

    With ``sense`` (+1/-1, the sense of the inertial force) a slide is told relative to the
    inertial force instead of along x (for mirror-image senses told at once).
    """
    index = stack.block_index(state.name)
    block = stack.blocks[index]
    below = _below_name(stack, index)
    if sense is None:
        where = {1: ", to the right (+x)", -1: ", to the left (-x)"}.get(state.slide_direction, "")
    elif state.slide_direction:
        along = state.slide_direction == sense
        where = ", with the inertial force" if along else ", against the inertial force"
    else:
        where = ""
    contact = ""
    if state.pivot:
        name = block.contact_names[0 if state.pivot == "left" else 1]
        contact = f"its {state.pivot} contact {name}"
    subject = f"the {state.name}"
    if state.motion is Motion.REST:
        return f"{subject} rests on the {below}"
    if state.motion is Motion.SLIDE:
        return f"{subject} slides on the {below}{where}"
    if state.motion is Motion.ROCK:
        return f"{subject} lifts and rocks about {contact} on the {below}"
    if state.motion is Motion.SLIDE_ROCK:
        return f"{subject} lifts, rocks about {contact} and slides on the {below}{where}"
    return f"{subject} lifts off the {below} (free flight)"


def case_phrase(stack: Stack, case: InitialMotion, *, relative: bool = False) -> str:
    """What the stack does in one case, top block first, as one clause."""
    if case.status == "inconsistent" or not case.blocks:
        return "no consistent state of motion was found (see the flagged cases)"
    if all(state.motion is Motion.REST for state in case.blocks):
        return "nothing moves"
    moving = [s for s in reversed(case.blocks) if s.motion is not Motion.REST]
    resting = [s for s in reversed(case.blocks) if s.motion is Motion.REST]
    sense = case.sense if relative else None
    parts = [block_phrase(stack, s, sense=sense) for s in moving + resting]
    text = "; ".join(parts)
    if case.status == "ambiguous":
        text += " (ambiguous: other states are admissible too)"
    return text


def _configuration_sentence(stack: Stack, cases: list[InitialMotion]) -> str:
    parts = []
    by_excitation: dict[str, list[InitialMotion]] = {}
    for case in cases:
        by_excitation.setdefault(case.excitation, []).append(case)
    for excitation, group in by_excitation.items():
        first = group[0]
        level = (
            f"{excitation} (a_h = {first.horizontal:.2f} m/s^2, a_v = {first.vertical:.2f} m/s^2)"
        )
        plain = {case_phrase(stack, c, relative=True) for c in group}
        if len(group) == 2 and len(plain) == 1 and all(c.status == "unique" for c in group):
            parts.append(f"Under {level}, in both senses: {next(iter(plain))}")
        else:
            senses = "; ".join(
                f"sense {sense_label(c.sense)}: {case_phrase(stack, c)}" for c in group
            )
            parts.append(f"Under {level}, {senses}")
    return f"Configuration {stack.name}. " + ". ".join(parts) + "."


def _overturning_sentence(item: RockingAssessment) -> str:
    op = item.operating_amplitude
    crossing = item.half_sine.operating_frequency
    exact_f = crossing.get("exact", float("nan"))
    mr_f = crossing.get("makris-roussos", float("nan"))
    housner_f = crossing.get("housner", float("nan"))

    def longer(f: float) -> str:
        return f"{0.5 / f:.2f} s" if math.isfinite(f) else "any duration up to 5 s"

    pulse = (
        f"A half-sine pulse of {op:.2f} m/s^2 overturns it only if it lasts longer than "
        f"{longer(exact_f)} (exact limit; {longer(mr_f)} by the corrected linearised limit of "
        f"Makris and Roussos, {longer(housner_f)} by Housner's criterion as the paper applies it)."
        if math.isfinite(exact_f)
        else f"No half-sine pulse of {op:.2f} m/s^2 between 0.1 and 20 Hz overturns it "
        "(exact limit)."
    )
    head = (
        f"In configuration {item.configuration} the {item.block} rocks about its {item.pivot} "
        f"contact {item.pivot_name} ({', '.join(item.cases)})."
    )
    governing = item.governing_check
    if item.verdict == "no spectrum":
        verdict = "The model has no horizontal spectrum, so no overturning verdict is given."
    elif governing is None:
        verdict = (
            f"Against the spectrum '{item.spectrum.label}' no overturning limit could be "
            "compared (undetermined)."
        )
    elif item.verdict == "no overturning":
        verdict = (
            f"It does not overturn under the spectrum '{governing.spectrum_label}': the "
            f"smallest margin (limit / spectrum) is {governing.min_ratio:.2f} at "
            f"{governing.frequency_at_min:.2f} Hz ({_limit_title(governing.limit_name)})."
        )
    else:
        verdict = (
            f"It may overturn under the spectrum '{governing.spectrum_label}': the spectrum "
            f"exceeds the {_limit_title(governing.limit_name)} limit (smallest margin "
            f"{governing.min_ratio:.2f} at {governing.frequency_at_min:.2f} Hz)."
        )
    weight = (
        "These limits use the weight m g, without the vertical support acceleration."
        if item.vertical > 0
        else "These limits use the weight m g (the cases it rocks in have no downward vertical "
        "acceleration)."
    )
    with_vertical = ""
    if item.half_sine_vertical is not None:
        exact_v = item.half_sine_vertical.operating_frequency.get("exact", float("nan"))
        rect = item.rectangular_vertical
        shortest = ""
        if rect is not None and len(rect.amplitude):
            k = int(np.argmax(rect.amplitude))
            before = item.rectangular.exact[k]
            after = rect.exact[k]
            if math.isfinite(before) or math.isfinite(after):
                shortest = (
                    f" A rectangular pulse of {rect.amplitude[k]:.2f} m/s^2 overturns it if it "
                    f"lasts {_seconds(after)} or longer with the weight m (g - a_v), "
                    f"{_seconds(before)} with m g (exact)."
                )
        with_vertical = (
            f" With the weight m (g - a_v), a_v = {item.vertical:.2f} m/s^2 downward as in the "
            "cases it rocks in, the limits are lower: a half-sine pulse of "
            f"{op:.2f} m/s^2 overturns it if it lasts longer than {longer(exact_v)} (exact)."
            + shortest
        )
    return f"{head} {verdict} {pulse} {weight}{with_vertical}"


def _seconds(value: float) -> str:
    return f"{value:.2f} s" if math.isfinite(value) else "no duration (no overturning)"


def _limit_title(name: str) -> str:
    return {
        "housner": "Housner, linearised",
        "makris-roussos": "Makris-Roussos, linearised",
        "exact": "exact nonlinear",
    }.get(name, name)


def limit_title(name: str) -> str:
    """Readable name of an overturning limit (``"exact"`` -> ``"exact nonlinear"``)."""
    return _limit_title(name)


def _frequency_sentences(item: FrequencyAssessment, model: ModelFile) -> list[str]:
    low, high = item.dunkerley_range
    exact_low, exact_high = item.exact_range
    sentences = [
        f"The bridge's lowest vertical natural frequency is {low:.1f}-{high:.1f} Hz by "
        f"Dunkerley's estimate (exact {exact_low:.1f}-{exact_high:.1f} Hz) with the cart "
        f"parked between {item.parking[0]:.2f} and "
        f"{item.parking[1]:.2f} m."
    ]
    jump = item.jump
    if jump is None:
        sentences.append("The model has no vertical spectrum, so the jump check is not made.")
    elif jump.jump_possible:
        runs = " and ".join(f"{a:.2f} and {b:.2f} m" for a, b in jump.risk_intervals)
        sentences.append(
            f"Under the vertical spectrum '{jump.spectrum_label}' the cart may jump (lose "
            f"contact with its rails) when parked between {runs}, where the spectral "
            "acceleration at the bridge's frequency reaches g."
        )
    else:
        sentences.append(
            f"Under the vertical spectrum '{jump.spectrum_label}' the cart keeps contact at "
            f"every parking position (smallest margin g - S_a = {jump.minimum_margin:.2f} "
            f"m/s^2 at {jump.minimum_margin_position:.2f} m)."
        )
    return sentences


# --- collection ----------------------------------------------------------------------------------


def _rocking_candidates(
    stacks: tuple[Stack, ...], cases: list[InitialMotion]
) -> tuple[dict, list[SkippedBlock]]:
    """(configuration, block, pivot) -> cases it rocks in; and the blocks not assessed."""
    found: dict[tuple[str, str, str], list[InitialMotion]] = {}
    skipped: dict[tuple[str, str], str] = {}
    by_name = {stack.name: stack for stack in stacks}
    for case in cases:
        stack = by_name[case.configuration]
        for index, state in enumerate(case.blocks):
            if state.motion not in _ROCKING:
                continue
            key = (case.configuration, state.name)
            block = stack.blocks[index]
            if not block.base_left < block.centre[0] < block.base_right:
                skipped.setdefault(
                    key,
                    "its centre of gravity does not lie between its contacts, so it cannot "
                    "stand, let alone rock about one contact; check its centre and base",
                )
                continue
            if index != len(stack.blocks) - 1:
                skipped.setdefault(
                    key,
                    f"it carries the {stack.blocks[index + 1].name}; the single-block rocking "
                    "check is for a block with nothing on top",
                )
                continue
            if index > 0 and case.blocks[index - 1].motion is not Motion.REST:
                skipped.setdefault(
                    key,
                    f"the {stack.blocks[index - 1].name} below it moves too "
                    f"({case_label(case)}); the single-block rocking check is for a block on a "
                    "body at rest",
                )
                continue
            found.setdefault((case.configuration, state.name, state.pivot), []).append(case)
    skipped_blocks = [
        SkippedBlock(configuration, block, reason)
        for (configuration, block), reason in skipped.items()
        if not any(k[0] == configuration and k[1] == block for k in found)
    ]
    return found, skipped_blocks


def assess_rocking(
    model: ModelFile,
    block: Block,
    configuration: str,
    pivot: str,
    cases: tuple[str, ...],
    vertical: float = 0.0,
) -> RockingAssessment:
    """Overturning assessment of ``block`` about ``pivot``, as ``freestand overturn`` makes it.

    Parameters
    ----------
    model : ModelFile
        The model (excitations, gravity, horizontal spectrum).
    block : Block
        The rocking block (top of its stack).
    configuration : str
        Its configuration's name.
    pivot : str
        ``"left"`` or ``"right"``.
    cases : tuple of str
        Labels of the cases it rocks in.
    vertical : float, optional
        Downward vertical support acceleration a_v [m/s^2] of those cases:
        when positive, the limits are also given with the weight m (g - a_v)
        (``freestand overturn --include-vertical``).
    """
    rocking = RockingBlock.from_block(block, pivot, gravity=model.gravity)
    operating = max(e.horizontal for e in model.excitations)
    amplitudes = np.array(sorted({e.horizontal for e in model.excitations if e.horizontal > 0}))
    rectangular = rectangular_pulse_limits(rocking, amplitudes, operating_amplitude=operating)
    curve = rectangular_pulse_limits(
        rocking, rectangular_amplitude_grid(rocking, operating), operating_amplitude=operating
    )
    table = overturning_limits(rocking, np.array(TABLE_FREQUENCIES), kind="half-sine")
    limits = overturning_limits(
        rocking, CURVE_FREQUENCIES, kind="half-sine", operating_amplitude=operating
    )
    spectrum = model.spectrum("horizontal")
    checks = check_spectrum(limits, spectrum) if spectrum is not None else {}
    half_sine_vertical = rectangular_vertical = None
    if vertical > 0:
        lighter = RockingBlock.from_block(
            block, pivot, gravity=model.gravity, vertical_acceleration=vertical
        )
        half_sine_vertical = overturning_limits(
            lighter, CURVE_FREQUENCIES, kind="half-sine", operating_amplitude=operating
        )
        rectangular_vertical = rectangular_pulse_limits(
            lighter, amplitudes, operating_amplitude=operating
        )
    return RockingAssessment(
        vertical=max(vertical, 0.0),
        half_sine_vertical=half_sine_vertical,
        rectangular_vertical=rectangular_vertical,
        configuration=configuration,
        block=block.name,
        pivot=pivot,
        pivot_name=block.contact_names[0 if pivot == "left" else 1],
        cases=cases,
        rocking=rocking,
        operating_amplitude=operating,
        rectangular=rectangular,
        rectangular_curve=curve,
        half_sine_table=table,
        half_sine=limits,
        spectrum=spectrum,
        checks=checks,
    )


def assess_frequency(model: ModelFile) -> FrequencyAssessment | None:
    """Frequency sweep and jump check of the ``[beam]`` section, as ``freestand frequency``."""
    if model.beam is None:
        return None
    beam, parking = model.beam.beam, model.beam.parking
    sweep = frequency_sweep(beam, parking=parking)
    vertical = model.spectrum("vertical")
    jump = jump_check(sweep, vertical, model.gravity, parking=parking) if vertical else None
    return FrequencyAssessment(
        sweep=sweep,
        parking=parking,
        dunkerley_range=sweep.frequency_range(parking, method="dunkerley"),
        exact_range=sweep.frequency_range(parking, method="exact"),
        spectrum=vertical,
        jump=jump,
    )


def summary_sentences(
    model: ModelFile,
    cases: tuple[InitialMotion, ...],
    overturning: tuple[RockingAssessment, ...],
    skipped: tuple[SkippedBlock, ...],
    frequency: FrequencyAssessment | None,
    body_cases: tuple = (),
    body_histories: tuple = (),
) -> tuple[str, ...]:
    """The conclusions at the top of the report, like the paper's section 7."""
    sentences = [f"Warning: {message}." for message in model.warnings()]
    for stack in model.configurations:
        own = [c for c in cases if c.configuration == stack.name]
        sentences.append(_configuration_sentence(stack, own))
    sentences += body_sentences(model, body_cases, body_histories)
    flagged = [c for c in cases if c.status in ("ambiguous", "inconsistent")]
    if flagged:
        listed = "; ".join(f"{c.configuration}, {case_label(c)} ({c.status})" for c in flagged)
        sentences.append(
            f"{len(flagged)} case(s) need the engineer's judgement, as several states of "
            f"motion are admissible or none is: {listed}. The tables show the state chosen by "
            "the rule 'static friction holds where it can, then fewest separations'."
        )
    rocking_blocks = {(a.configuration, a.block) for a in overturning}
    if not overturning and not skipped and model.configurations:
        blocks = "block of the planar configurations" if model.body_configurations else "block"
        sentences.append(
            f"No {blocks} lifts in any screened case, so none can rock or overturn under these "
            "excitations."
        )
    sentences += [_overturning_sentence(item) for item in overturning]
    sentences += [
        f"In configuration {s.configuration} the {s.block} rocks, but its overturning is not "
        f"assessed: {s.reason}."
        for s in skipped
        if (s.configuration, s.block) not in rocking_blocks
    ]
    if frequency is not None:
        sentences += _frequency_sentences(frequency, model)
    return tuple(sentences)


def collect_report(
    model: ModelFile,
    *,
    date: _dt.date | None = None,
    progress: Progress | None = None,
    body_histories: tuple = (),
) -> ReportContent:
    """Run every check of the screening report on ``model`` and gather the results.

    Parameters
    ----------
    model : ModelFile
        A validated model (:func:`freestand.io.model_file.load_model`).
    date : datetime.date, optional
        Date printed on the report (default :func:`report_date`).
    progress : callable, optional
        Called as ``progress(description, done, total)`` before each step.
    body_histories : tuple of BodySimulationResult, optional
        The time histories of the 3-D configurations under a record
        (:func:`freestand.write_report` simulates them), shown in section 4.

    Returns
    -------
    ReportContent
    """
    tell = progress or (lambda *_: None)
    tell("screening the initial motion (paper Tables 2-5)", 0, 2)
    cases = tuple(
        case
        for stack in model.configurations
        for case in screen(stack, model.excitations, model.gravity)
    )
    candidates, skipped = _rocking_candidates(model.configurations, list(cases))
    total = 1 + len(candidates) + 1
    assessments = []
    for k, ((configuration, block_name, pivot), rocking_cases) in enumerate(candidates.items()):
        tell(f"overturning of the {block_name} in {configuration} (Figs. 6-8)", 1 + k, total)
        stack = model.configuration(configuration)
        block = stack.blocks[stack.block_index(block_name)]
        labels = tuple(case_label(case) for case in rocking_cases)
        vertical = max(max(case.vertical for case in rocking_cases), 0.0)
        assessments.append(assess_rocking(model, block, configuration, pivot, labels, vertical))
    tell("vertical frequency and jump check (Fig. 9)", total - 1, total)
    frequency = assess_frequency(model)
    overturning = tuple(assessments)
    body_cases = collect_body_cases(model)
    return ReportContent(
        model=model,
        model_file=os.path.basename(model.source),
        sha256=model.sha256,
        version=__version__,
        date=date or report_date(),
        cases=cases,
        overturning=overturning,
        skipped=tuple(skipped),
        frequency=frequency,
        summary=summary_sentences(
            model, cases, overturning, tuple(skipped), frequency, body_cases, body_histories
        ),
        fragility=_fragility(model, tell, total),
        body_cases=body_cases,
        body_histories=tuple(body_histories),
    )


def _fragility(model: ModelFile, tell, total: int):
    """The ``[fragility]`` campaign of the model, if it names one."""
    if not model.fragility:
        return None
    from freestand.report.fragility import assess_fragility

    tell("fragility campaign of the [fragility] table", total, total + 1)
    return assess_fragility(model)
