"""Table rows of screening results, shared by the terminal and the report.

The rows are plain strings and numbers (no markup), in the layout of the
paper's Tables 2/4 (types of motion and accelerations) and 3/5 (contact
forces); for a 3-D body, one row per direction of the sweep and a sentence
per excitation.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass

from freestand.core.body import Body
from freestand.core.contact.body_screening import (
    BodyInitialMotion,
    BodyScreeningCase,
    pivot_label,
)
from freestand.core.contact.screening import BlockState, InitialMotion, Motion
from freestand.core.model import Stack
from freestand.io.results import degrees

MOTION_HEADERS = (
    "configuration",
    "excitation",
    "sense",
    "body",
    "type of motion",
    "angular acc. [1/s^2]",
    "CoG horiz. acc. [m/s^2]",
    "CoG vert. acc. [m/s^2]",
)

FORCE_HEADERS = (
    "configuration",
    "excitation",
    "sense",
    "body",
    "vertical, left [N]",
    "vertical, right [N]",
    "horizontal (sum) [N]",
)


@dataclass(frozen=True)
class Row:
    """A table row; ``flag`` marks ambiguous or inconsistent cases."""

    cells: tuple
    flag: str = ""


def motion_label(state: BlockState) -> str:
    """``"rock (right)"``, ``"slide (+x)"``, ``"slide-rock (left, -x)"``..."""
    details = []
    if state.pivot:
        details.append(state.pivot)
    if state.slide_direction:
        details.append("+x" if state.slide_direction > 0 else "-x")
    if state.motion is Motion.REST or not details:
        return state.motion.value
    return f"{state.motion.value} ({', '.join(details)})"


def _flag(case: InitialMotion) -> str:
    if case.status == "ambiguous":
        return f"ambiguous: {len(case.alternatives)} admissible states, chosen by rule"
    if case.status == "inconsistent":
        return "no consistent state (see diagnostics)"
    return ""


def motion_rows(cases: Sequence[InitialMotion]) -> list[Row]:
    """Rows of the Tables 2/4 analogue, blocks bottom to top within a case."""
    rows = []
    for case in cases:
        sense = "+" if case.sense > 0 else "-"
        if not case.blocks:
            rows.append(
                Row(
                    (case.configuration, case.excitation, sense, "-", "none found", "", "", ""),
                    _flag(case),
                )
            )
        for state in case.blocks:
            rows.append(
                Row(
                    (
                        case.configuration,
                        case.excitation,
                        sense,
                        state.name,
                        motion_label(state),
                        state.angular_acceleration,
                        state.acceleration_x,
                        state.acceleration_z,
                    ),
                    _flag(case),
                )
            )
    return rows


def paper_case_rows(cases: Sequence[InitialMotion]) -> list[Row]:
    """One row per case: configuration, excitation, sense, status and the paper's case name."""
    return [
        Row(
            (
                case.configuration,
                case.excitation,
                "+" if case.sense > 0 else "-",
                case.status,
                case.paper_case or "(no case of the paper)",
            ),
            _flag(case),
        )
        for case in cases
    ]


PAPER_CASE_HEADERS = ("configuration", "excitation", "sense", "status", "paper section 3 case")


def force_rows(cases: Sequence[InitialMotion], stacks: Sequence[Stack]) -> list[Row]:
    """Rows of the Tables 3/5 analogue: forces on each body from the one below, by named contact."""
    by_name = {stack.name: stack for stack in stacks}
    rows = []
    for case in cases:
        stack = by_name[case.configuration]
        sense = "+" if case.sense > 0 else "-"
        for state in case.blocks:
            block = stack.blocks[stack.block_index(state.name)]
            left_name, right_name = block.contact_names
            rows.append(
                Row(
                    (
                        case.configuration,
                        case.excitation,
                        sense,
                        state.name,
                        (left_name, state.base_normal_left),
                        (right_name, state.base_normal_right),
                        state.base_tangential,
                    ),
                    _flag(case),
                )
            )
    return rows


# --- 3-D bodies ---------------------------------------------------------------------------------

BODY_DIRECTION_HEADERS = (
    "direction [deg]",
    "type of motion",
    "uplift threshold [m/s^2]",
    "normal force [N]",
    "friction x [N]",
    "friction y [N]",
    "angular acc. [1/s^2]",
)

#: The motions in the order the sentences name them.
_MOTION_ORDER = ("rest", "slide", "rock", "slide-rock", "free-flight")
_MOTION_VERBS = {
    "rest": "rests",
    "slide": "slides",
    "rock": "rocks",
    "slide-rock": "slides and rocks",
    "free-flight": "flies",
}


def body_motion_label(state: BodyInitialMotion) -> str:
    """``"rock (edge -x)"``, ``"slide (to 195 deg)"``, ``"slide-rock (edge +x, to 180 deg)"``."""
    details = [state.pivot] if state.pivot else []
    if state.slide_direction is not None:
        details.append(f"to {degrees(state.slide_direction):.0f} deg")
    if not details:
        return state.motion.value
    return f"{state.motion.value} ({', '.join(details)})"


def body_direction_rows(case: BodyScreeningCase) -> list[Row]:
    """One row per swept direction, then the excitation's own (flagged ``"excitation"``)."""
    rows = []
    for state, flag in [(s, "") for s in case.directions] + [(case.at_excitation, "excitation")]:
        rows.append(
            Row(
                (
                    degrees(state.direction),
                    body_motion_label(state),
                    state.uplift_threshold,
                    state.normal_force,
                    state.tangential_force[0],
                    state.tangential_force[1],
                    state.angular_acceleration,
                ),
                flag,
            )
        )
    return rows


def body_case_sentence(case: BodyScreeningCase, body: Body) -> str:
    """What the body does under one excitation over the directions, in words."""
    counts = Counter(state.motion.value for state in case.directions)
    total = len(case.directions)
    parts = [
        f"{_MOTION_VERBS[motion]} in {counts[motion]} of {total} directions"
        for motion in _MOTION_ORDER
        if counts[motion]
    ]
    if len(parts) == 1:
        parts = [f"{_MOTION_VERBS[next(iter(counts))]} in all {total} directions swept"]
    own = case.at_excitation
    thresholds = [state.uplift_threshold for state in case.directions]
    lowest = case.lowest_threshold
    if max(thresholds) - min(thresholds) <= 1e-9 * max(max(thresholds), 1.0):
        uplift = f"its uplift threshold is {lowest.uplift_threshold:.2f} m/s^2 in every direction"
    else:
        uplift = (
            f"its uplift threshold ranges from {min(thresholds):.2f} m/s^2 (at "
            f"{degrees(lowest.direction):.0f} deg, tipping about the "
            f"{pivot_label(body, lowest.direction)}) to {max(thresholds):.2f} m/s^2"
        )
    return (
        f"Under {case.excitation} (a = {case.horizontal:.2f} m/s^2 applied in each direction, "
        f"a_v = {case.vertical:.2f} m/s^2) the {case.body} "
        + ", ".join(parts)
        + f"; in the excitation's own direction ({degrees(case.excitation_direction):.0f} deg) "
        f"it {_MOTION_VERBS[own.motion.value]}; {uplift}."
    )
