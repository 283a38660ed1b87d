"""Initial motion of a stack from rest under a support acceleration.

This is the paper's section 3 for any planar stack: at the first instant after
the support acceleration appears, find the type of motion of every block
(rest, slide, rock, slide-rock, free flight), its accelerations and all the
contact forces.

Frame: the support's (translating, non-inertial) frame. The support motion
acts on each block as inertial forces at its centre of gravity (paper
section 2): horizontal ``s m a_hor`` along x, where ``s = +1`` or ``-1`` is the
*sense of the inertial force*, and a reduced weight ``m (g - a_ver)``
downwards, ``a_ver`` being the downward support acceleration. Accelerations
are relative to the support; angles counter-clockwise positive.

The type of motion of a block is its motion relative to the body it stands
on (the block below, or the support):

=============  =========================================================
rest           both contacts closed, interface sticks
slide          both contacts closed, interface slides
rock           one contact closed (the pivot), no slip at it
slide-rock     one contact closed, slipping
free-flight    both contacts open
=============  =========================================================
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace
from enum import StrEnum

import numpy as np

from freestand.core.contact.engine import solve
from freestand.core.contact.paper_cases import paper_case
from freestand.core.contact.problem import (
    ContactDiagnostics,
    ContactProblem,
    ContactResult,
    ContactSolution,
    Interface,
    Tangential,
)
from freestand.core.model import Excitation, Stack

#: Standard value of the gravitational acceleration used by the paper [m/s^2].
GRAVITY = 9.81


class Motion(StrEnum):
    """Type of motion of a block relative to the body below it."""

    REST = "rest"
    SLIDE = "slide"
    ROCK = "rock"
    SLIDE_ROCK = "slide-rock"
    FREE_FLIGHT = "free-flight"


@dataclass(frozen=True)
class BlockState:
    """Initial state of motion of one block.

    Attributes
    ----------
    name : str
        Block name.
    motion : Motion
        Type of motion relative to the body below.
    pivot : str or None
        ``"left"`` or ``"right"``: the contact it rocks about (rock,
        slide-rock), else None.
    slide_direction : int
        +1 (right) or -1 (left) when sliding relative to the body below, else 0.
    acceleration_x, acceleration_z : float
        Acceleration of the centre of gravity relative to the support [m/s^2].
    angular_acceleration : float
        Angular acceleration [rad/s^2], counter-clockwise positive.
    base_normal_left, base_normal_right : float
        Normal force [N] on this block at its left and right lower contact,
        from the body below.
    base_tangential : float
        Total tangential force [N] on this block from the body below, +x
        positive (friction, and the end stop's reaction where there is one).
    """

    name: str
    motion: Motion
    pivot: str | None
    slide_direction: int
    acceleration_x: float
    acceleration_z: float
    angular_acceleration: float
    base_normal_left: float
    base_normal_right: float
    base_tangential: float

    def describe(self, below: str) -> str:
        """A short phrase such as ``"slides to the right on the bridge"``."""
        direction = {1: "to the right", -1: "to the left"}.get(self.slide_direction, "")
        if self.motion is Motion.REST:
            return f"rests on the {below}"
        if self.motion is Motion.SLIDE:
            return f"slides {direction} on the {below}"
        if self.motion is Motion.ROCK:
            return f"rocks about its {self.pivot} contact on the {below}"
        if self.motion is Motion.SLIDE_ROCK:
            return f"rocks about its {self.pivot} contact and slides {direction} on the {below}"
        return f"lifts off the {below} (free flight)"


@dataclass(frozen=True)
class InitialMotion:
    """Initial motion of a stack for one excitation and sense.

    Attributes
    ----------
    configuration : str
        Stack name.
    excitation : str
        Excitation name.
    sense : int
        +1 or -1: sense of the horizontal inertial force along x.
    horizontal : float
        Magnitude of the horizontal support acceleration [m/s^2].
    vertical : float
        Signed vertical support acceleration [m/s^2], positive downward
        (weight m (g - a_ver)), negative upward.
    gravity : float
        Gravitational acceleration [m/s^2].
    status : str
        ``"unique"``, ``"ambiguous"`` (several admissible states; ``blocks``
        is the one chosen by the rule), ``"inconsistent"`` (no admissible
        state; ``blocks`` is empty) or ``"free-flight"`` (a_ver >= g).
    blocks : tuple of BlockState
        Chosen state, bottom to top.
    alternatives : tuple of tuple of BlockState
        Every distinct admissible state, the chosen one first.
    paper_case : str or None
        The paper's section 3 case this state corresponds to, where one does.
    diagnostics : ContactDiagnostics or None
        How the contact problem was solved.
    """

    configuration: str
    excitation: str
    sense: int
    horizontal: float
    vertical: float
    gravity: float
    status: str
    blocks: tuple[BlockState, ...]
    alternatives: tuple[tuple[BlockState, ...], ...]
    paper_case: str | None
    diagnostics: ContactDiagnostics | None = None

    @property
    def ambiguous(self) -> bool:
        """Whether several distinct states are admissible."""
        return self.status == "ambiguous"

    def block(self, name: str) -> BlockState:
        """The state of the block called ``name``."""
        for state in self.blocks:
            if state.name == name:
                return state
        raise KeyError(name)


def _perp_dot(normal: tuple[float, float], arm: tuple[float, float]) -> float:
    """``normal . perp(arm)`` with ``perp(x, z) = (-z, x)`` (rotation by +90 deg)."""
    return -normal[0] * arm[1] + normal[1] * arm[0]


def _contact_rows(
    stack: Stack, upper: int, point: tuple[float, float], direction: tuple[float, float]
) -> np.ndarray:
    """Jacobian row of the relative acceleration of ``point`` along ``direction``.

    Relative acceleration of the material point of block ``upper`` at
    ``point`` with respect to the coincident point of the body below, at rest
    (no velocity terms): ``a_G + eps perp(P - G)`` for each body.
    """
    row = np.zeros(3 * len(stack.blocks))
    block = stack.blocks[upper]
    arm = (point[0] - block.centre[0], point[1] - block.centre[1])
    row[3 * upper : 3 * upper + 3] = (direction[0], direction[1], _perp_dot(direction, arm))
    if upper > 0:
        lower = stack.blocks[upper - 1]
        arm = (point[0] - lower.centre[0], point[1] - lower.centre[1])
        row[3 * upper - 3 : 3 * upper] = (
            -direction[0],
            -direction[1],
            -_perp_dot(direction, arm),
        )
    return row


def contact_problem_at_rest(
    stack: Stack, inertial_acceleration: float, vertical: float, gravity: float = GRAVITY
) -> ContactProblem:
    """Build the contact problem of a stack at rest (paper section 3).

    Parameters
    ----------
    stack : Stack
        Blocks bottom to top.
    inertial_acceleration : float
        Signed horizontal inertial acceleration [m/s^2]: the inertial force on
        each block is ``m * inertial_acceleration`` along x (the paper's
        ``F = m k_y g`` with its sense).
    vertical : float
        Downward support acceleration a_ver [m/s^2]; the weight is
        ``m (g - a_ver)`` (paper section 3.1, ``G = m g (1 - k_z)``).
    gravity : float, optional
        g [m/s^2].

    Returns
    -------
    ContactProblem
    """
    count = len(stack.blocks)
    size = 3 * count
    mass_matrix = np.zeros((size, size))
    applied = np.zeros(size)
    effective_gravity = gravity - vertical
    for index, block in enumerate(stack.blocks):
        mass_matrix[3 * index, 3 * index] = block.mass
        mass_matrix[3 * index + 1, 3 * index + 1] = block.mass
        mass_matrix[3 * index + 2, 3 * index + 2] = block.inertia
        applied[3 * index] = block.mass * inertial_acceleration
        applied[3 * index + 1] = -block.mass * effective_gravity
    interfaces = []
    for index, block in enumerate(stack.blocks):
        points = block.contacts
        normal = np.array([_contact_rows(stack, index, p, (0.0, 1.0)) for p in points])
        tangential = np.array([_contact_rows(stack, index, p, (1.0, 0.0)) for p in points])
        interfaces.append(
            Interface(
                normal_jacobian=normal,
                normal_bias=np.zeros(2),
                tangential_jacobian=tangential,
                tangential_bias=np.zeros(2),
                static_friction=block.friction.static,
                kinetic_friction=block.friction.kinetic,
                sliding=block.sliding,
            )
        )
    total_mass = sum(block.mass for block in stack.blocks)
    acceleration_scale = max(float(np.hypot(inertial_acceleration, effective_gravity)), 1e-12)
    return ContactProblem(
        mass_matrix=mass_matrix,
        applied_force=applied,
        interfaces=tuple(interfaces),
        force_scale=total_mass * acceleration_scale,
        acceleration_scale=acceleration_scale,
    )


def _block_states(stack: Stack, solution: ContactSolution) -> tuple[BlockState, ...]:
    states = []
    for index, (block, mode) in enumerate(zip(stack.blocks, solution.modes, strict=True)):
        closed = mode.closed_count
        slide = mode.slide_direction
        if mode.tangential is Tangential.KINETIC:  # not at rest; kept for completeness
            slide = int(np.sign(solution.slip_acceleration[index]))
        if closed == 2:
            motion = Motion.SLIDE if slide else Motion.REST
        elif closed == 1:
            motion = Motion.SLIDE_ROCK if slide else Motion.ROCK
        else:
            motion = Motion.FREE_FLIGHT
        pivot = None
        if closed == 1:
            pivot = "left" if mode.left_closed else "right"
        acceleration = solution.acceleration[3 * index : 3 * index + 3]
        states.append(
            BlockState(
                name=block.name,
                motion=motion,
                pivot=pivot,
                slide_direction=slide,
                acceleration_x=float(acceleration[0]),
                acceleration_z=float(acceleration[1]),
                angular_acceleration=float(acceleration[2]),
                base_normal_left=float(solution.normal_force[index, 0]),
                base_normal_right=float(solution.normal_force[index, 1]),
                base_tangential=float(solution.tangential_force[index]),
            )
        )
    return tuple(_clean(state) for state in states)


def _clean(state: BlockState) -> BlockState:
    """Round away the signed zeros and 1e-13 residues of the linear solves."""

    def tidy(value: float, scale: float) -> float:
        return 0.0 if abs(value) <= 1e-10 * max(scale, 1.0) else value

    force_scale = abs(state.base_normal_left) + abs(state.base_normal_right)
    return BlockState(
        name=state.name,
        motion=state.motion,
        pivot=state.pivot,
        slide_direction=state.slide_direction,
        acceleration_x=tidy(state.acceleration_x, 1.0),
        acceleration_z=tidy(state.acceleration_z, 1.0),
        angular_acceleration=tidy(state.angular_acceleration, 1.0),
        base_normal_left=tidy(state.base_normal_left, force_scale),
        base_normal_right=tidy(state.base_normal_right, force_scale),
        base_tangential=tidy(state.base_tangential, force_scale),
    )


def _free_flight_states(
    stack: Stack, inertial_acceleration: float, vertical: float, gravity: float
) -> tuple[BlockState, ...]:
    return tuple(
        BlockState(
            name=block.name,
            motion=Motion.FREE_FLIGHT,
            pivot=None,
            slide_direction=0,
            acceleration_x=inertial_acceleration,
            acceleration_z=vertical - gravity,
            angular_acceleration=0.0,
            base_normal_left=0.0,
            base_normal_right=0.0,
            base_tangential=0.0,
        )
        for block in stack.blocks
    )


def initial_motion(
    stack: Stack,
    horizontal: float,
    vertical: float = 0.0,
    sense: int = 1,
    gravity: float = GRAVITY,
    excitation_name: str = "",
) -> InitialMotion:
    """Initial type of motion, accelerations and contact forces of a stack.

    Solves the complementarity problem with the compiled kernel of
    :mod:`freestand.core.contact.engine` for
    the stack at rest under the inertial forces ``s m a_hor`` (horizontal)
    and the reduced weights ``m (g - a_ver)`` (paper section 3, eqs. of
    3.1.1-3.1.2.3 for two blocks, generalised to any stack).

    Parameters
    ----------
    stack : Stack
        Blocks bottom to top.
    horizontal : float
        Magnitude of the horizontal support acceleration a_hor [m/s^2], >= 0.
    vertical : float, optional
        Signed vertical support acceleration a_ver [m/s^2], positive
        downward; negative (upward) increases the weight m (g - a_ver). When
        it reaches g the blocks are weightless and every block is in free
        flight.
    sense : int, optional
        +1 or -1: sense of the horizontal inertial force along x.
    gravity : float, optional
        g [m/s^2].
    excitation_name : str, optional
        Label carried into the result.

    Returns
    -------
    InitialMotion
    """
    if sense not in (1, -1):
        raise ValueError(f"sense must be +1 or -1, not {sense!r}")
    inertial = sense * horizontal
    common = dict(
        configuration=stack.name,
        excitation=excitation_name,
        sense=sense,
        horizontal=horizontal,
        vertical=vertical,
        gravity=gravity,
    )
    if vertical >= gravity:
        states = _free_flight_states(stack, inertial, vertical, gravity)
        return InitialMotion(
            **common,
            status="free-flight",
            blocks=states,
            alternatives=(states,),
            paper_case=None,
        )
    # a batch of one for the compiled contact kernel
    result: ContactResult = solve(contact_problem_at_rest(stack, inertial, vertical, gravity))
    alternatives = tuple(_block_states(stack, solution) for solution in result.admissible)
    blocks = alternatives[0] if alternatives else ()
    return InitialMotion(
        **common,
        status=result.status,
        blocks=blocks,
        alternatives=alternatives,
        paper_case=paper_case(stack, blocks) if blocks else None,
        diagnostics=result.diagnostics,
    )


def vertical_label(name: str, vertical: float, both: bool) -> str:
    """The case name of an excitation: ``"<name> (a_v down)"``/``"(a_v up)"`` when ``both``."""
    if not both:
        return name
    return f"{name} (a_v {'up' if vertical < 0 else 'down'})"


def screen(
    stack: Stack,
    excitations: tuple[Excitation, ...] | list[Excitation],
    gravity: float = GRAVITY,
    vertical_senses: str | None = None,
) -> list[InitialMotion]:
    """Initial motion for every excitation level and both horizontal senses.

    Parameters
    ----------
    stack : Stack
    excitations : sequence of Excitation
    gravity : float, optional
        g [m/s^2].
    vertical_senses : str, optional
        ``"both"`` analyses every excitation with its vertical acceleration
        downward (+|a_ver|) and upward (-|a_ver|), ``"given"`` as given; None
        (default) follows each excitation's own ``vertical_senses``. The
        cases of an excitation analysed both ways are named
        ``"<name> (a_v down)"`` and ``"<name> (a_v up)"``.

    Returns
    -------
    list of InitialMotion
        In the order excitation, vertical sense (downward first), then sense
        ``+``, ``-``.
    """
    cases = []
    for excitation in excitations:
        if vertical_senses is not None:
            excitation = replace(excitation, vertical_senses=vertical_senses)
        verticals = excitation.verticals()
        for vertical in verticals:
            label = vertical_label(excitation.name, vertical, len(verticals) > 1)
            for sense in (1, -1):
                cases.append(
                    initial_motion(stack, excitation.horizontal, vertical, sense, gravity, label)
                )
    return cases


@dataclass(frozen=True)
class ForceEnvelope:
    """Extreme contact forces on one block over a set of screening cases.

    Attributes
    ----------
    configuration, block : str
        Names.
    normal_left, normal_right : float
        Largest normal force [N] on the block at its left and right lower
        contact, from the body below (compression positive).
    tangential : float
        Largest magnitude of the total tangential force [N] on the block
        from the body below.
    cases : tuple of str
        For ``normal_left``, ``normal_right`` and ``tangential`` in turn: the
        case ``"<excitation>, sense <+|->"`` that gives it.
    """

    configuration: str
    block: str
    normal_left: float
    normal_right: float
    tangential: float
    cases: tuple[str, str, str]


def force_envelope(cases: Sequence[InitialMotion]) -> list[ForceEnvelope]:
    """Envelope of the contact forces of every block over ``cases``.

    The largest normal force at each lower contact and the largest tangential
    force of each block, with the case that gives it; configurations and
    blocks in the order of ``cases`` (blocks bottom to top). Cases with no
    admissible state are left out (they are reported on their own).

    Parameters
    ----------
    cases : sequence of InitialMotion

    Returns
    -------
    list of ForceEnvelope
    """
    table: dict[tuple[str, str], list] = {}
    for case in cases:
        label = f"{case.excitation}, sense {'+' if case.sense > 0 else '-'}"
        for state in case.blocks:
            key = (case.configuration, state.name)
            values = (
                state.base_normal_left,
                state.base_normal_right,
                abs(state.base_tangential),
            )
            entry = table.setdefault(key, [[-np.inf, -np.inf, -np.inf], ["", "", ""]])
            for k, value in enumerate(values):
                if value > entry[0][k]:
                    entry[0][k] = value
                    entry[1][k] = label
    return [
        ForceEnvelope(configuration, block, *values, cases=tuple(labels))
        for (configuration, block), (values, labels) in table.items()
    ]
