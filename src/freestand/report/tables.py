"""Table rows of screening results, shared by the terminal and the report.

The rows are plain strings and numbers (no markup), in the layout of the
paper's Tables 2/4 (types of motion and accelerations) and 3/5 (contact
forces).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from freestand.core.contact.screening import BlockState, InitialMotion, Motion
from freestand.core.model import Stack

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
