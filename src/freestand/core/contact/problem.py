"""The instantaneous contact problem of a planar rigid-block stack: its data.

The problem (equations, unilateral conditions, Coulomb friction with static
break-away, choice rule) is described in :mod:`freestand.core.contact.engine`,
which solves it; this module holds the plain types that describe a problem and
its solutions, shared by the compiled solver and by its numpy reference
implementation :mod:`freestand.core.contact.modes` (kept for tests).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import IntEnum

import numpy as np

from freestand.core.model import Sliding

#: Relative tolerance for the admissibility inequalities and for telling
#: solutions apart (scaled by the problem's force and acceleration scales).
RELATIVE_TOLERANCE = 1e-9


class Tangential(IntEnum):
    """Tangential state of an interface in a contact mode."""

    #: No contact closed: no tangential force.
    FREE = 0
    #: The interface holds: no relative tangential acceleration.
    STICK = 1
    #: Starts sliding to the right (+x along the lower surface).
    SLIDE_POSITIVE = 2
    #: Starts sliding to the left.
    SLIDE_NEGATIVE = 3
    #: Already sliding (non-zero slip velocity): kinetic friction against it.
    KINETIC = 4


@dataclass(frozen=True)
class InterfaceMode:
    """Contact mode of one interface.

    Parameters
    ----------
    left_closed, right_closed : bool
        Whether the left/right contact carries force (gap acceleration zero).
    tangential : Tangential
        Tangential state.
    """

    left_closed: bool
    right_closed: bool
    tangential: Tangential

    @property
    def closed_count(self) -> int:
        """Number of closed contacts (0, 1 or 2)."""
        return int(self.left_closed) + int(self.right_closed)

    @property
    def slide_direction(self) -> int:
        """+1 or -1 for a starting slide, 0 otherwise."""
        if self.tangential is Tangential.SLIDE_POSITIVE:
            return 1
        if self.tangential is Tangential.SLIDE_NEGATIVE:
            return -1
        return 0


@dataclass(frozen=True)
class Interface:
    """Kinematics and friction of one interface at the current instant.

    The interface joins an upper block to the body below (a block or the
    support) through a left and a right contact.

    Parameters
    ----------
    normal_jacobian : numpy.ndarray
        Shape (2, n): rows mapping ``qdd`` [m/s^2, rad/s^2] to the gap
        accelerations [m/s^2] of the left and right contacts.
    normal_bias : numpy.ndarray
        Shape (2,): velocity-dependent part of the gap accelerations [m/s^2]
        (zero at rest).
    tangential_jacobian : numpy.ndarray
        Shape (2, n): rows mapping ``qdd`` to the slip acceleration [m/s^2] of
        the upper block relative to the lower one at the left and right
        contact, along the lower surface.
    tangential_bias : numpy.ndarray
        Shape (2,): velocity-dependent part of the slip accelerations [m/s^2].
    static_friction, kinetic_friction : float
        Coulomb coefficients mu_0 and mu [-].
    sliding : Sliding
        Sliding restriction (free, none, end stop).
    active : tuple of bool
        Whether each contact is touching and not separating (may carry
        force). Inactive contacts are open.
    slip_velocity : float
        Current slip velocity [m/s]; non-zero means the interface slides with
        kinetic friction against it.
    stop_engaged : bool
        For an end stop (``no-right``/``no-left``): whether the block is at
        the stop, so that the stop can push it back.
    """

    normal_jacobian: np.ndarray
    normal_bias: np.ndarray
    tangential_jacobian: np.ndarray
    tangential_bias: np.ndarray
    static_friction: float
    kinetic_friction: float
    sliding: Sliding = Sliding.FREE
    active: tuple[bool, bool] = (True, True)
    slip_velocity: float = 0.0
    stop_engaged: bool = True

    def effective_sliding(self) -> Sliding:
        """The sliding restriction in force now (a stop acts only when engaged)."""
        if self.sliding in (Sliding.NO_LEFT, Sliding.NO_RIGHT) and not self.stop_engaged:
            return Sliding.FREE
        return self.sliding

    def modes(self) -> list[InterfaceMode]:
        """All contact modes this interface can be in, in enumeration order.

        Order: both contacts closed, left only, right only, none; for each,
        stick before slide right before slide left.
        """
        left_active, right_active = self.active
        normal_states = [
            (left, right)
            for left, right in ((True, True), (True, False), (False, True), (False, False))
            if (left <= left_active) and (right <= right_active)
        ]
        sliding = self.effective_sliding()
        result = []
        for left, right in normal_states:
            if not (left or right):
                result.append(InterfaceMode(False, False, Tangential.FREE))
                continue
            if self.slip_velocity != 0.0 and sliding is not Sliding.NONE:
                result.append(InterfaceMode(left, right, Tangential.KINETIC))
                continue
            result.append(InterfaceMode(left, right, Tangential.STICK))
            if sliding.allows(+1):
                result.append(InterfaceMode(left, right, Tangential.SLIDE_POSITIVE))
            if sliding.allows(-1):
                result.append(InterfaceMode(left, right, Tangential.SLIDE_NEGATIVE))
        return result


@dataclass(frozen=True)
class ContactProblem:
    """The instantaneous contact problem of a stack.

    Parameters
    ----------
    mass_matrix : numpy.ndarray
        Shape (n, n), generalised mass matrix [kg, kg m^2].
    applied_force : numpy.ndarray
        Shape (n,), generalised applied forces [N, N m] (weights, inertial
        forces of the support motion, velocity terms).
    interfaces : tuple of Interface
        One per interface, bottom to top.
    force_scale : float
        A typical force [N] (e.g. the total weight) for tolerances.
    acceleration_scale : float
        A typical acceleration [m/s^2] (e.g. g) for tolerances.
    """

    mass_matrix: np.ndarray
    applied_force: np.ndarray
    interfaces: tuple[Interface, ...]
    force_scale: float = 1.0
    acceleration_scale: float = 1.0

    @property
    def size(self) -> int:
        """Number of generalised coordinates n."""
        return int(self.applied_force.shape[0])


@dataclass(frozen=True)
class ContactSolution:
    """One consistent state of the contact problem.

    Attributes
    ----------
    modes : tuple of InterfaceMode
        Mode of each interface.
    acceleration : numpy.ndarray
        Generalised accelerations qdd, shape (n,).
    normal_force : numpy.ndarray
        Shape (I, 2): normal force [N] at the left and right contact of each
        interface, on the upper body.
    tangential_force : numpy.ndarray
        Shape (I,): total tangential force [N] on the upper body along the
        lower surface (+x at rest); friction and end-stop reaction together.
    gap_acceleration : numpy.ndarray
        Shape (I, 2): gap accelerations [m/s^2] (zero where closed).
    slip_acceleration : numpy.ndarray
        Shape (I,): slip acceleration [m/s^2] of each interface at its closed
        contact (the left one when both are closed or both open).
    residual : float
        Largest equation residual of the linear solve, relative to the
        force scale [-].
    """

    modes: tuple[InterfaceMode, ...]
    acceleration: np.ndarray
    normal_force: np.ndarray
    tangential_force: np.ndarray
    gap_acceleration: np.ndarray
    slip_acceleration: np.ndarray
    residual: float

    @property
    def sticking_count(self) -> int:
        """Number of interfaces that hold by friction."""
        return sum(mode.tangential is Tangential.STICK for mode in self.modes)

    @property
    def open_count(self) -> int:
        """Number of open contacts."""
        return sum(2 - mode.closed_count for mode in self.modes)


@dataclass(frozen=True)
class ContactDiagnostics:
    """How a contact problem was solved.

    Attributes
    ----------
    modes_tried : int
        Number of contact modes enumerated.
    singular_modes : int
        Modes whose linear system was singular (skipped).
    kinetic_only_modes : int
        Modes consistent with kinetic friction that static friction could have
        held (not physical from rest; not admissible).
    relaxed : bool
        True when no mode passed the static-friction test and the
        kinetic-only modes were accepted instead.
    rule : str
        The rule used to choose among admissible states.
    """

    modes_tried: int
    singular_modes: int
    kinetic_only_modes: int
    relaxed: bool
    rule: str = "static friction holds where it can, then fewest separations"


@dataclass(frozen=True)
class ContactResult:
    """Outcome of a contact solve (:func:`freestand.core.contact.engine.solve`).

    Attributes
    ----------
    status : str
        ``"unique"`` (one admissible state), ``"ambiguous"`` (several distinct
        admissible states; ``chosen`` by the documented rule) or
        ``"inconsistent"`` (none; ``chosen`` is None).
    chosen : ContactSolution or None
        The state picked by the rule.
    admissible : tuple of ContactSolution
        All distinct admissible states, the chosen one first.
    diagnostics : ContactDiagnostics
    """

    status: str
    chosen: ContactSolution | None
    admissible: tuple[ContactSolution, ...]
    diagnostics: ContactDiagnostics = field(repr=False)

    @property
    def ambiguous(self) -> bool:
        """Whether more than one distinct state is admissible."""
        return self.status == "ambiguous"
