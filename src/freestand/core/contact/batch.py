"""Batch solver: the initial motion of many stacks at once.

The same contact problem as :func:`freestand.core.contact.screening.initial_motion`
(paper section 3), solved by the same compiled contact kernel
(:mod:`freestand.core.contact.engine`), for thousands to millions of cases that share
one stack *structure* (number of blocks and sliding restrictions) but may
differ in every number: masses, inertias, centres, contact positions,
friction coefficients and the excitation.

Method
------
At rest the velocity terms vanish and the mass matrix ``M`` is diagonal
(``m, m, Theta_S`` per block), so the accelerations can be eliminated. With
``J`` the rows of the left/right gap accelerations and of the slip
acceleration of every interface, and ``Lambda`` the contact forces
``(N_L, N_R, T)`` of every interface::

    qdd = M^-1 (f + J^T Lambda)
    a   = J qdd = W Lambda + h,    W = J M^-1 J^T  (Delassus matrix),  h = J M^-1 f

In a contact mode the unknowns are the normal forces of the closed contacts
and the tangential forces of the sticking interfaces (a sliding interface
has ``T = -d mu (N_L + N_R)``); the mode's equations are the zero gap
acceleration of each closed contact and the zero slip acceleration of each
sticking interface, a system of at most 3 unknowns per interface. This is the
Schur complement of the full system ``[M -J^T; J 0]``; the two are singular
together.

Everything after the linear solve is the kernel's
(:func:`freestand.core.contact.engine.solve_contact_states`): the admissibility inequalities with
``RELATIVE_TOLERANCE`` scaled by the force and acceleration scales of
:func:`freestand.core.contact.screening.contact_problem_at_rest`, the static-friction
break-away test for interfaces that start sliding, the relaxation when no
mode passes it, the choice rule (most sticking interfaces, then fewest open
contacts, then enumeration order) and the deduplication of identical
solutions. Ambiguous and inconsistent cases are flagged as there.

Excitation plane
----------------
For a fixed stack the applied forces are linear in the inertial acceleration
``s a_hor`` and the effective gravity ``g - a_ver`` while the mode matrices do
not depend on them, so every mode's solution is
``Lambda = (s a_hor) Lambda_1 + (g - a_ver) Lambda_2``: the mode boundaries in
the excitation plane are straight lines through the origin.
:func:`solve_excitation_plane` solves each mode twice for the whole plane
and only combines the two solutions per point.

Compiled loops use numba (``cache=True``; ``parallel=True`` over cases).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, replace

import numpy as np
from numba import njit, prange

from freestand.core.contact.engine import (
    INFO_RELAXED,
    INFO_SIZE,
    RELATIVE_TOLERANCE,
    accelerations,
    accelerations_admissible,
    choose,
    delassus,
    forces_admissible,
    slides_with_static,
    solve_contact_states,
    solve_mode,
)
from freestand.core.contact.problem import Interface, Tangential
from freestand.core.contact.screening import GRAVITY, Motion
from freestand.core.model import Sliding, Stack

#: Status names, indexed by :attr:`BatchResult.status` codes.
STATUS_NAMES: tuple[str, ...] = ("unique", "ambiguous", "inconsistent", "free-flight", "invalid")
UNIQUE, AMBIGUOUS, INCONSISTENT, FREE_FLIGHT, INVALID = range(5)

#: Motion names, indexed by :attr:`BatchResult.motion` codes (-1: no state).
MOTIONS: tuple[Motion, ...] = (
    Motion.REST,
    Motion.SLIDE,
    Motion.ROCK,
    Motion.SLIDE_ROCK,
    Motion.FREE_FLIGHT,
)

#: Most alternative states recorded per case (the rest are only counted).
MAX_ALTERNATIVES = 8

_SLIDING_CODES = {Sliding.FREE: 0, Sliding.NONE: 1, Sliding.NO_RIGHT: 2, Sliding.NO_LEFT: 3}
_TANGENTIAL_CODES = {
    Tangential.FREE: 0,
    Tangential.STICK: 1,
    Tangential.SLIDE_POSITIVE: 2,
    Tangential.SLIDE_NEGATIVE: 3,
}

# --- parameters ---------------------------------------------------------------------------------

#: Block fields that can be varied: name -> (array attribute, quantity kind).
BLOCK_FIELDS: dict[str, tuple[str, str]] = {
    "mass": ("mass", "mass"),
    "inertia": ("inertia", "inertia"),
    "centre.x": ("centre_x", "length"),
    "centre.z": ("centre_z", "length"),
    "base.left": ("base_left", "length"),
    "base.right": ("base_right", "length"),
    "base.level": ("base_level", "length"),
    "friction.static": ("static_friction", "dimensionless"),
    "friction.kinetic": ("kinetic_friction", "dimensionless"),
}
#: Excitation fields: ``horizontal`` is a_hor [m/s^2] (the inertial force is
#: ``s m a_hor``), ``vertical`` the downward support acceleration a_ver [m/s^2].
EXCITATION_FIELDS: tuple[str, ...] = ("horizontal", "vertical")
#: How a value acts on the model's own (nominal) value.
OPERATIONS: tuple[str, ...] = ("set", "add", "scale")


def kinetic_below_static(static, kinetic, nominal, static_varied: bool, kinetic_varied: bool):
    """The kinetic friction coefficients [-] of varied inputs, never above the static ones.

    Where the kinetic coefficient is varied it is clipped to ``min(mu, mu_0)``;
    where only the static one is, the kinetic one follows it in the model's
    proportion ``mu = mu_0 (mu_model / mu_0,model)``; else it is unchanged.

    Parameters
    ----------
    static, kinetic : numpy.ndarray
        mu_0 and mu of the cases [-].
    nominal : Friction
        The model's friction.
    static_varied, kinetic_varied : bool
        Which coefficients were varied.
    """
    if kinetic_varied:
        return np.minimum(kinetic, static)
    if static_varied:
        ratio = nominal.kinetic / nominal.static if nominal.static > 0 else 1.0
        return static * ratio
    return kinetic


@dataclass(frozen=True)
class Parameter:
    """An input that a map or a sweep varies.

    Parameters
    ----------
    field : str
        One of :data:`EXCITATION_FIELDS` or :data:`BLOCK_FIELDS`.
    block : str or None
        Block name for a block field; None means every block of the stack
        (e.g. ``friction.static`` of every interface). Always None for the
        excitation fields.
    operation : str
        ``"set"`` (the value replaces the model's), ``"add"`` (it is added to
        the model's value) or ``"scale"`` (the model's value is multiplied by
        it).
    """

    field: str
    block: str | None = None
    operation: str = "set"

    def __post_init__(self):
        if self.field not in EXCITATION_FIELDS and self.field not in BLOCK_FIELDS:
            raise ValueError(f"unknown parameter field {self.field!r}")
        if self.field in EXCITATION_FIELDS and self.block is not None:
            raise ValueError(f"{self.field!r} belongs to the excitation, not to a block")
        if self.operation not in OPERATIONS:
            raise ValueError(f"unknown operation {self.operation!r}")

    @property
    def name(self) -> str:
        """Dotted name, e.g. ``"cart.centre.x"`` or ``"friction.static"``."""
        return self.field if self.block is None else f"{self.block}.{self.field}"

    @property
    def label(self) -> str:
        """Name with the operation, e.g. ``"cart.mass (x factor)"``."""
        suffix = {"set": "", "add": " (+ offset)", "scale": " (x factor)"}[self.operation]
        return self.name + suffix

    @property
    def quantity(self) -> str:
        """Kind of quantity of the values (``"length"``, ``"acceleration"``...)."""
        if self.operation == "scale":
            return "dimensionless"
        if self.field in EXCITATION_FIELDS:
            return "acceleration"
        return BLOCK_FIELDS[self.field][1]

    @property
    def unit(self) -> str:
        """SI unit of the values, for labels."""
        return {
            "acceleration": "m/s^2",
            "length": "m",
            "mass": "kg",
            "inertia": "kg m^2",
            "dimensionless": "-",
        }[self.quantity]

    def nominal(self, stack: Stack, horizontal: float, vertical: float) -> float:
        """The model's own value (first matching block for a stack-wide field).

        Parameters
        ----------
        stack : Stack
        horizontal, vertical : float
            The model's excitation [m/s^2].
        """
        if self.field == "horizontal":
            return horizontal
        if self.field == "vertical":
            return vertical
        blocks = (
            stack.blocks if self.block is None else (stack.blocks[stack.block_index(self.block)],)
        )
        block = blocks[0]
        values = {
            "mass": block.mass,
            "inertia": block.inertia,
            "centre.x": block.centre[0],
            "centre.z": block.centre[1],
            "base.left": block.base_left,
            "base.right": block.base_right,
            "base.level": block.base_level,
            "friction.static": block.friction.static,
            "friction.kinetic": block.friction.kinetic,
        }
        return float(values[self.field])

    def applied(self, nominal: float | np.ndarray, value: np.ndarray) -> np.ndarray:
        """The value in force after the operation on ``nominal``."""
        if self.operation == "set":
            return np.asarray(value, dtype=float)
        if self.operation == "add":
            return nominal + np.asarray(value, dtype=float)
        return nominal * np.asarray(value, dtype=float)


@dataclass(frozen=True)
class BatchStack:
    """Many variants of one stack: every number per case and block.

    Arrays have shape (N, B) for N cases of B blocks (bottom to top).

    Attributes
    ----------
    names : tuple of str
        Block names.
    sliding : tuple of Sliding
        Sliding restriction of each interface (shared by all cases).
    mass, inertia : numpy.ndarray
        m [kg] and Theta_S [kg m^2].
    centre_x, centre_z : numpy.ndarray
        Centre of gravity [m].
    base_left, base_right, base_level : numpy.ndarray
        Lower contacts: x of left and right, and their z [m].
    static_friction, kinetic_friction : numpy.ndarray
        mu_0 and mu [-] of the interface below each block.
    """

    names: tuple[str, ...]
    sliding: tuple[Sliding, ...]
    mass: np.ndarray
    inertia: np.ndarray
    centre_x: np.ndarray
    centre_z: np.ndarray
    base_left: np.ndarray
    base_right: np.ndarray
    base_level: np.ndarray
    static_friction: np.ndarray
    kinetic_friction: np.ndarray

    ARRAYS = (
        "mass",
        "inertia",
        "centre_x",
        "centre_z",
        "base_left",
        "base_right",
        "base_level",
        "static_friction",
        "kinetic_friction",
    )

    @classmethod
    def from_stack(cls, stack: Stack, count: int = 1) -> BatchStack:
        """``count`` copies of ``stack``."""
        blocks = stack.blocks

        def column(values):
            return np.tile(np.asarray(values, dtype=float), (count, 1))

        return cls(
            names=tuple(b.name for b in blocks),
            sliding=tuple(b.sliding for b in blocks),
            mass=column([b.mass for b in blocks]),
            inertia=column([b.inertia for b in blocks]),
            centre_x=column([b.centre[0] for b in blocks]),
            centre_z=column([b.centre[1] for b in blocks]),
            base_left=column([b.base_left for b in blocks]),
            base_right=column([b.base_right for b in blocks]),
            base_level=column([b.base_level for b in blocks]),
            static_friction=column([b.friction.static for b in blocks]),
            kinetic_friction=column([b.friction.kinetic for b in blocks]),
        )

    @property
    def count(self) -> int:
        """Number of cases N."""
        return int(self.mass.shape[0])

    def valid(self) -> np.ndarray:
        """Cases whose numbers make a model: shape (N,) bool.

        Positive masses and inertias, friction coefficients >= 0, left
        contact left of the right one, centre above its contacts, all finite
        (the checks of the model file).
        """
        arrays = [getattr(self, name) for name in self.ARRAYS]
        ok = np.all(np.isfinite(np.stack(arrays)), axis=(0, 2))
        ok &= np.all(self.mass > 0, axis=1) & np.all(self.inertia > 0, axis=1)
        ok &= np.all(self.static_friction >= 0, axis=1)
        ok &= np.all(self.kinetic_friction >= 0, axis=1)
        ok &= np.all(self.base_left < self.base_right, axis=1)
        ok &= np.all(self.centre_z > self.base_level, axis=1)
        return ok

    def take(self, index: np.ndarray) -> BatchStack:
        """The cases selected by ``index`` (integer or boolean array)."""
        return replace(self, **{name: getattr(self, name)[index] for name in self.ARRAYS})


@dataclass(frozen=True)
class CaseInputs:
    """Inputs of N cases of one stack structure.

    Attributes
    ----------
    stack : BatchStack
    horizontal : numpy.ndarray
        a_hor [m/s^2], shape (N,).
    vertical : numpy.ndarray
        Downward support acceleration a_ver [m/s^2], shape (N,).
    sense : int
        +1 or -1: sense of the horizontal inertial force.
    """

    stack: BatchStack
    horizontal: np.ndarray
    vertical: np.ndarray
    sense: int

    @property
    def inertial(self) -> np.ndarray:
        """Signed inertial acceleration ``s a_hor`` [m/s^2]."""
        return self.sense * self.horizontal


def case_inputs(
    stack: Stack,
    horizontal: float,
    vertical: float,
    sense: int,
    values: Mapping[Parameter, np.ndarray] | Sequence[tuple[Parameter, np.ndarray]],
    count: int,
) -> CaseInputs:
    """Apply varied parameters to a stack and an excitation.

    Parameters
    ----------
    stack : Stack
        The model's stack (nominal values).
    horizontal, vertical : float
        The model's excitation a_hor and a_ver [m/s^2].
    sense : int
        +1 or -1.
    values : mapping or sequence of (Parameter, numpy.ndarray)
        Value of each varied parameter per case, shape (N,) (or scalars), in
        SI units (a factor for ``scale``). Applied in order.
    count : int
        N.

    Returns
    -------
    CaseInputs

    Notes
    -----
    Kinetic friction never exceeds static friction: where only the static
    coefficient of an interface is varied, the kinetic one follows it in
    the model's proportion ``mu = mu_0 (mu_model / mu_0,model)``; where the
    kinetic coefficient is varied, it is clipped to ``min(mu, mu_0)``.

    Raises
    ------
    KeyError
        If a parameter names a block the stack does not have.
    """
    batch = BatchStack.from_stack(stack, count)
    arrays = {name: getattr(batch, name).copy() for name in BatchStack.ARRAYS}
    h = np.full(count, float(horizontal))
    v = np.full(count, float(vertical))
    static_set = np.zeros(len(stack.blocks), dtype=bool)
    kinetic_set = np.zeros(len(stack.blocks), dtype=bool)
    items = values.items() if isinstance(values, Mapping) else values
    for parameter, value in items:
        value = np.broadcast_to(np.asarray(value, dtype=float), (count,))
        if parameter.field == "horizontal":
            h = parameter.applied(h, value)
            continue
        if parameter.field == "vertical":
            v = parameter.applied(v, value)
            continue
        attribute = BLOCK_FIELDS[parameter.field][0]
        columns = (
            range(len(stack.blocks))
            if parameter.block is None
            else [stack.block_index(parameter.block)]
        )
        for column in columns:
            arrays[attribute][:, column] = parameter.applied(arrays[attribute][:, column], value)
            if parameter.field == "friction.static":
                static_set[column] = True
            elif parameter.field == "friction.kinetic":
                kinetic_set[column] = True
    for column, block in enumerate(stack.blocks):
        arrays["kinetic_friction"][:, column] = kinetic_below_static(
            arrays["static_friction"][:, column], arrays["kinetic_friction"][:, column],
            block.friction, static_set[column], kinetic_set[column],
        )  # fmt: skip
    return CaseInputs(stack=replace(batch, **arrays), horizontal=h, vertical=v, sense=int(sense))


# --- mode table ---------------------------------------------------------------------------------


@dataclass(frozen=True)
class ModeTable:
    """The contact modes of a stack structure, in the enumeration order of
    :func:`freestand.core.contact.engine.solve_contact_states` at rest.

    Attributes
    ----------
    modes : numpy.ndarray
        Shape (K, B, 3) int64: left closed, right closed, tangential code
        (0 free, 1 stick, 2 slide right, 3 slide left) of each interface.
    priority : numpy.ndarray
        Shape (K,): mode indices sorted by the choice rule (most sticking
        interfaces, then fewest open contacts, then enumeration order).
    sliding : numpy.ndarray
        Shape (B,) int64 sliding codes (0 free, 1 none, 2 no-right, 3 no-left).
    unknown_count : numpy.ndarray
        Shape (K,): number of unknown contact forces of each mode.
    unknown_index : numpy.ndarray
        Shape (K, 3B): row of each unknown in ``(N_L, N_R, T)`` per
        interface (closed contacts' normal forces, sticking interfaces'
        tangential forces).
    unknown_direction : numpy.ndarray
        Shape (K, 3B): slide direction (+1, -1) of a normal force's sliding
        interface, else 0.
    has_slide : numpy.ndarray
        Shape (K,) bool: some interface starts sliding.
    """

    modes: np.ndarray
    priority: np.ndarray
    sliding: np.ndarray
    unknown_count: np.ndarray
    unknown_index: np.ndarray
    unknown_direction: np.ndarray
    has_slide: np.ndarray

    @classmethod
    def for_sliding(cls, sliding: Sequence[Sliding]) -> ModeTable:
        """The mode table of an at-rest stack with these sliding restrictions."""
        import itertools

        per_interface = [
            Interface(
                normal_jacobian=np.zeros((2, 1)),
                normal_bias=np.zeros(2),
                tangential_jacobian=np.zeros((2, 1)),
                tangential_bias=np.zeros(2),
                static_friction=0.0,
                kinetic_friction=0.0,
                sliding=Sliding(s),
            ).modes()
            for s in sliding
        ]
        combinations = list(itertools.product(*per_interface))
        modes = np.array(
            [
                [
                    [int(m.left_closed), int(m.right_closed), _TANGENTIAL_CODES[m.tangential]]
                    for m in combination
                ]
                for combination in combinations
            ],
            dtype=np.int64,
        ).reshape(len(combinations), len(sliding), 3)
        sticking = np.sum(modes[:, :, 2] == 1, axis=1)
        open_count = np.sum(2 - modes[:, :, 0] - modes[:, :, 1], axis=1)
        priority = np.lexsort((np.arange(len(modes)), open_count, -sticking))
        size = 3 * len(sliding)
        unknown_count = np.zeros(len(modes), dtype=np.int64)
        unknown_index = np.zeros((len(modes), size), dtype=np.int64)
        unknown_direction = np.zeros((len(modes), size))
        for k, mode in enumerate(modes):
            j = 0
            for i, (left, right, tangential) in enumerate(mode):
                direction = {2: 1.0, 3: -1.0}.get(int(tangential), 0.0)
                for side, closed in enumerate((left, right)):
                    if closed:
                        unknown_index[k, j] = 3 * i + side
                        unknown_direction[k, j] = direction
                        j += 1
                if tangential == 1:
                    unknown_index[k, j] = 3 * i + 2
                    j += 1
            unknown_count[k] = j
        return cls(
            modes=modes,
            priority=priority.astype(np.int64),
            sliding=np.array([_SLIDING_CODES[Sliding(s)] for s in sliding], dtype=np.int64),
            unknown_count=unknown_count,
            unknown_index=unknown_index,
            unknown_direction=unknown_direction,
            has_slide=np.any(modes[:, :, 2] >= 2, axis=1),
        )

    def block_states(self, mode: int) -> tuple[tuple[Motion, str | None, int], ...]:
        """(motion, pivot, slide direction) of each block in mode ``mode``."""
        states = []
        for left, right, tangential in self.modes[mode]:
            slide = {2: 1, 3: -1}.get(int(tangential), 0)
            closed = int(left) + int(right)
            if closed == 2:
                motion = Motion.SLIDE if slide else Motion.REST
            elif closed == 1:
                motion = Motion.SLIDE_ROCK if slide else Motion.ROCK
            else:
                motion = Motion.FREE_FLIGHT
            pivot = ("left" if left else "right") if closed == 1 else None
            states.append((motion, pivot, slide))
        return tuple(states)


# --- compiled kernels ---------------------------------------------------------------------------


@njit(cache=True)
def _jacobian(cx, cz, bl, br, lvl, jac):
    """Rows (gap left, gap right, slip) per interface of the at-rest stack.

    Same rows as :func:`freestand.core.contact.screening._contact_rows`; both slip
    rows of an interface are equal (its contacts lie on one level).
    """
    count = cx.shape[0]
    jac[:, :] = 0.0
    for i in range(count):
        for side in range(2):
            px = bl[i] if side == 0 else br[i]
            row = 3 * i + side
            jac[row, 3 * i + 1] = 1.0
            jac[row, 3 * i + 2] = px - cx[i]
            if i > 0:
                jac[row, 3 * i - 2] = -1.0
                jac[row, 3 * i - 1] = -(px - cx[i - 1])
        row = 3 * i + 2
        jac[row, 3 * i] = 1.0
        jac[row, 3 * i + 2] = -(lvl[i] - cz[i])
        if i > 0:
            jac[row, 3 * i - 3] = -1.0
            jac[row, 3 * i - 1] = lvl[i] - cz[i - 1]


@njit(cache=True)
def _split(jac, jn, jt):
    """The at-rest rows in the kernel's layout: gap rows ``jn`` and (equal) slip rows ``jt``."""
    for i in range(jn.shape[0]):
        for c in range(jac.shape[1]):
            jn[i, 0, c] = jac[3 * i, c]
            jn[i, 1, c] = jac[3 * i + 1, c]
            jt[i, 0, c] = jac[3 * i + 2, c]
            jt[i, 1, c] = jac[3 * i + 2, c]


@njit(cache=True)
def _finite(values):
    for value in values:
        if not np.isfinite(value):
            return False
    return True


@njit(cache=True)
def _tolerances(total_mass, inertial, effective_gravity):
    scale = max(np.hypot(inertial, effective_gravity), 1e-12)
    tiny = np.finfo(np.float64).tiny
    force_tol = RELATIVE_TOLERANCE * max(total_mass * scale, tiny)
    accel_tol = RELATIVE_TOLERANCE * max(scale, tiny)
    return force_tol, accel_tol


@njit(cache=True)
def _write_free_flight(case, blocks, inertial, vertical, gravity, status, acceleration, count):
    status[case] = 3
    count[case] = 1
    for i in range(blocks):
        acceleration[case, i, 0] = inertial
        acceleration[case, i, 1] = vertical - gravity
        acceleration[case, i, 2] = 0.0


@njit(cache=True)
def _solve_range(
    start,
    stop,
    sliding,
    mass,
    inertia,
    cx,
    cz,
    bl,
    br,
    lvl,
    mu_s,
    mu_k,
    inertial,
    vertical,
    gravity,
    status,
    chosen,
    alternatives,
    count,
    relaxed,
    acceleration,
    forces,
):
    """Solve cases ``start:stop``, each with the contact kernel
    :func:`freestand.core.contact.engine.solve_contact_states` (at rest: every contact
    touching, no slip, so its enumeration index is the :class:`ModeTable` index)."""
    blocks = mass.shape[1]
    n = 3 * blocks
    jac = np.zeros((n, n))
    jn = np.zeros((blocks, 2, n))
    jt = np.zeros((blocks, 2, n))
    bn = np.zeros((blocks, 2))
    bt = np.zeros((blocks, 2))
    touching = np.ones((blocks, 2), dtype=np.bool_)
    slip = np.zeros(blocks)
    minv = np.empty(n)
    free_acc = np.empty(n)
    kept = alternatives.shape[1]
    out_modes = np.empty((kept, blocks, 3), dtype=np.int64)
    out_qdd = np.empty((kept, n))
    out_lam = np.empty((kept, blocks, 3))
    out_acc = np.empty((kept, blocks, 3))
    out_index = np.empty(kept, dtype=np.int64)
    info = np.zeros(INFO_SIZE, dtype=np.int64)
    for case in range(start, stop):
        if vertical[case] >= gravity:
            _write_free_flight(
                case, blocks, inertial[case], vertical[case], gravity, status, acceleration, count
            )
            continue
        effective_gravity = gravity - vertical[case]
        total_mass = 0.0
        for i in range(blocks):
            total_mass += mass[case, i]
            minv[3 * i] = 1.0 / mass[case, i]
            minv[3 * i + 1] = 1.0 / mass[case, i]
            minv[3 * i + 2] = 1.0 / inertia[case, i]
            free_acc[3 * i] = inertial[case]
            free_acc[3 * i + 1] = -effective_gravity
            free_acc[3 * i + 2] = 0.0
        force_tol, accel_tol = _tolerances(total_mass, inertial[case], effective_gravity)
        _jacobian(cx[case], cz[case], bl[case], br[case], lvl[case], jac)
        _split(jac, jn, jt)
        distinct = solve_contact_states(
            blocks, minv, free_acc, jn, bn, jt, bt, touching, slip, sliding, mu_s[case],
            mu_k[case], force_tol, accel_tol, out_modes, out_qdd, out_lam, out_acc, out_index,
            info,
        )  # fmt: skip
        _write_case(
            case,
            distinct,
            info[INFO_RELAXED] == 1,
            out_index,
            out_lam,
            out_qdd,
            status,
            chosen,
            alternatives,
            count,
            relaxed,
            acceleration,
            forces,
        )


@njit(cache=True)
def _write_case(
    case,
    distinct,
    was_relaxed,
    kept,
    lam,
    qdd,
    status,
    chosen,
    alternatives,
    count,
    relaxed,
    acceleration,
    forces,
):
    """Record one case: ``kept`` the mode indices of the distinct states in the order of
    the choice rule, ``lam`` (., B, 3) and ``qdd`` (., 3 B) the chosen state's first."""
    count[case] = distinct
    relaxed[case] = was_relaxed
    for j in range(alternatives.shape[1]):
        alternatives[case, j] = kept[j] if j < distinct else -1
    if distinct == 0:
        status[case] = 2
        chosen[case] = -1
        return
    status[case] = 0 if distinct == 1 else 1
    chosen[case] = kept[0]
    blocks = acceleration.shape[1]
    for i in range(blocks):
        for c in range(3):
            acceleration[case, i, c] = qdd[0, 3 * i + c]
            forces[case, i, c] = lam[0, i, c]


@njit(cache=True, parallel=True)
def _solve_parallel(
    chunks,
    sliding,
    mass,
    inertia,
    cx,
    cz,
    bl,
    br,
    lvl,
    mu_s,
    mu_k,
    inertial,
    vertical,
    gravity,
    status,
    chosen,
    alternatives,
    count,
    relaxed,
    acceleration,
    forces,
):
    for c in prange(chunks.shape[0] - 1):
        _solve_range(
            chunks[c],
            chunks[c + 1],
            sliding,
            mass,
            inertia,
            cx,
            cz,
            bl,
            br,
            lvl,
            mu_s,
            mu_k,
            inertial,
            vertical,
            gravity,
            status,
            chosen,
            alternatives,
            count,
            relaxed,
            acceleration,
            forces,
        )


@njit(cache=True)
def _plane_basis(
    modes,
    unknown_count,
    unknown_index,
    unknown_direction,
    mass,
    inertia,
    cx,
    cz,
    bl,
    br,
    lvl,
    mu_s,
    mu_k,
):
    """Unit-load solutions of every mode of one stack (excitation plane).

    Each mode is solved by the contact kernel's mode solve
    (:func:`freestand.core.contact.engine.solve_mode`). Returns arrays of shape
    (K, 2, 3B): forces, contact accelerations and accelerations for the loads
    ``s a_hor = 1`` (index 0) and ``g_eff = 1`` (index 1), with kinetic friction;
    the contact accelerations with static friction; and flags (solvable kinetic,
    solvable static).
    """
    blocks = mass.shape[0]
    n = 3 * blocks
    modes_count = modes.shape[0]
    jac = np.zeros((n, n))
    jn = np.zeros((blocks, 2, n))
    jt = np.zeros((blocks, 2, n))
    bn = np.zeros((blocks, 2))
    bt = np.zeros((blocks, 2))
    minv = np.empty(n)
    free_acc = np.empty(n)
    w = np.empty((4 * blocks, 4 * blocks))
    h = np.empty(4 * blocks)
    matrix = np.empty((n, n))
    rhs = np.empty(n)
    index = np.empty(n, dtype=np.int64)
    coeff = np.empty(n)
    full = np.empty(4 * blocks)
    kinetic = np.zeros((blocks, 2))
    static = np.zeros((blocks, 2))
    for i in range(blocks):
        kinetic[i, 0] = mu_k[i]
        static[i, 0] = mu_s[i]
    lam = np.zeros((modes_count, 2, n))
    acc = np.zeros((modes_count, 2, n))
    qdd = np.zeros((modes_count, 2, n))
    acc_static = np.zeros((modes_count, 2, n))
    solvable = np.zeros((modes_count, 2), dtype=np.bool_)
    lam_mode = np.zeros((blocks, 3))
    acc_mode = np.zeros((blocks, 3))
    for i in range(blocks):
        minv[3 * i] = 1.0 / mass[i]
        minv[3 * i + 1] = 1.0 / mass[i]
        minv[3 * i + 2] = 1.0 / inertia[i]
    _jacobian(cx, cz, bl, br, lvl, jac)
    _split(jac, jn, jt)
    for load in range(2):
        for i in range(blocks):
            free_acc[3 * i] = 1.0 if load == 0 else 0.0
            free_acc[3 * i + 1] = 0.0 if load == 0 else -1.0
            free_acc[3 * i + 2] = 0.0
        delassus(blocks, minv, free_acc, jn, bn, jt, bt, w, h)
        for k in range(modes_count):
            mode = modes[k]
            ok = solve_mode(
                blocks, w, h, mode, kinetic, lam_mode, acc_mode, matrix, rhs, index, coeff, full
            )
            solvable[k, 0] = ok
            if ok:
                for i in range(blocks):
                    for c in range(3):
                        lam[k, load, 3 * i + c] = lam_mode[i, c]
                        acc[k, load, 3 * i + c] = acc_mode[i, c]
                accelerations(blocks, minv, free_acc, jn, jt, mode, lam_mode, qdd[k, load])
            ok_static = solve_mode(
                blocks, w, h, mode, static, lam_mode, acc_mode, matrix, rhs, index, coeff, full
            )
            solvable[k, 1] = ok_static
            if ok_static:
                for i in range(blocks):
                    for c in range(3):
                        acc_static[k, load, 3 * i + c] = acc_mode[i, c]
    return lam, acc, qdd, acc_static, solvable


@njit(cache=True)
def _plane_range(
    start,
    stop,
    modes,
    priority,
    sliding,
    has_slide,
    mu_s,
    total_mass,
    lam_basis,
    acc_basis,
    qdd_basis,
    acc_static_basis,
    solvable,
    inertial,
    vertical,
    gravity,
    status,
    chosen,
    alternatives,
    count,
    relaxed,
    acceleration,
    forces,
):
    """Solve points ``start:stop`` of the excitation plane: each mode's solution is the
    combination of its unit-load solutions, then the contact kernel's admissibility,
    break-away test and choice rule (:mod:`freestand.core.contact.engine`) decide."""
    modes_count = modes.shape[0]
    n = lam_basis.shape[2]
    blocks = n // 3
    lam_all = np.empty((modes_count, blocks, 3))
    qdd_all = np.empty((modes_count, n))
    a = np.empty((blocks, 3))
    a_static = np.empty((blocks, 3))
    touching = np.ones((blocks, 2), dtype=np.bool_)
    candidate = np.zeros(modes_count, dtype=np.bool_)
    physical = np.zeros(modes_count, dtype=np.bool_)
    kept = np.empty(modes_count, dtype=np.int64)
    chosen_lam = np.empty((1, blocks, 3))
    chosen_qdd = np.empty((1, n))
    for case in range(start, stop):
        if vertical[case] >= gravity:
            _write_free_flight(
                case, blocks, inertial[case], vertical[case], gravity, status, acceleration, count
            )
            continue
        x = inertial[case]
        y = gravity - vertical[case]
        force_tol, accel_tol = _tolerances(total_mass, x, y)
        for k in range(modes_count):
            candidate[k] = False
            physical[k] = False
            if not solvable[k, 0]:
                continue
            for i in range(blocks):
                for c in range(3):
                    r = 3 * i + c
                    lam_all[k, i, c] = x * lam_basis[k, 0, r] + y * lam_basis[k, 1, r]
                    qdd_all[k, r] = x * qdd_basis[k, 0, r] + y * qdd_basis[k, 1, r]
                    a[i, c] = x * acc_basis[k, 0, r] + y * acc_basis[k, 1, r]
            mode = modes[k]
            if not _finite(qdd_all[k]):
                continue
            if not forces_admissible(blocks, mode, sliding, mu_s, lam_all[k], force_tol):
                continue
            if not accelerations_admissible(blocks, mode, touching, a, accel_tol):
                continue
            candidate[k] = True
            if not has_slide[k]:
                physical[k] = True
                continue
            if solvable[k, 1]:
                for i in range(blocks):
                    for c in range(3):
                        r = 3 * i + c
                        a_static[i, c] = (
                            x * acc_static_basis[k, 0, r] + y * acc_static_basis[k, 1, r]
                        )
                physical[k] = slides_with_static(blocks, mode, a_static, accel_tol)
        distinct, was_relaxed = choose(
            priority, candidate, physical, lam_all, qdd_all, force_tol, accel_tol, kept
        )
        if distinct:
            chosen_lam[0] = lam_all[kept[0]]
            chosen_qdd[0] = qdd_all[kept[0]]
        _write_case(
            case,
            distinct,
            was_relaxed,
            kept,
            chosen_lam,
            chosen_qdd,
            status,
            chosen,
            alternatives,
            count,
            relaxed,
            acceleration,
            forces,
        )


@njit(cache=True, parallel=True)
def _plane_parallel(
    chunks,
    modes,
    priority,
    sliding,
    has_slide,
    mu_s,
    total_mass,
    lam_basis,
    acc_basis,
    qdd_basis,
    acc_static_basis,
    solvable,
    inertial,
    vertical,
    gravity,
    status,
    chosen,
    alternatives,
    count,
    relaxed,
    acceleration,
    forces,
):
    for c in prange(chunks.shape[0] - 1):
        _plane_range(
            chunks[c],
            chunks[c + 1],
            modes,
            priority,
            sliding,
            has_slide,
            mu_s,
            total_mass,
            lam_basis,
            acc_basis,
            qdd_basis,
            acc_static_basis,
            solvable,
            inertial,
            vertical,
            gravity,
            status,
            chosen,
            alternatives,
            count,
            relaxed,
            acceleration,
            forces,
        )


# --- results ------------------------------------------------------------------------------------


@dataclass(frozen=True)
class BatchResult:
    """Initial motion of N cases of one stack structure.

    Attributes
    ----------
    names : tuple of str
        Block names, bottom to top.
    table : ModeTable
        The contact modes (to decode ``chosen`` and ``alternatives``).
    status : numpy.ndarray
        Shape (N,) int8 codes into :data:`STATUS_NAMES`: unique, ambiguous
        (several distinct admissible states; the chosen one by the rule),
        inconsistent (none), free-flight (a_ver >= g), invalid (inputs that
        make no model; not solved).
    chosen : numpy.ndarray
        Shape (N,) int64: mode index of the chosen state (-1 for none or
        free flight).
    admissible_count : numpy.ndarray
        Shape (N,): number of distinct admissible states.
    alternatives : numpy.ndarray
        Shape (N, MAX_ALTERNATIVES): mode indices of the distinct admissible
        states, chosen first, -1 padded.
    relaxed : numpy.ndarray
        Shape (N,) bool: no state passed the static-friction break-away test
        and the kinetic-only states were accepted
        (:class:`freestand.core.contact.problem.ContactDiagnostics`).
    motion : numpy.ndarray
        Shape (N, B) int8 codes into :data:`MOTIONS` (-1: no state).
    pivot : numpy.ndarray
        Shape (N, B) int8: -1 left, +1 right, 0 none.
    slide_direction : numpy.ndarray
        Shape (N, B) int8: +1 right, -1 left, 0 not sliding.
    acceleration : numpy.ndarray
        Shape (N, B, 3): x, z [m/s^2] and angular [rad/s^2] accelerations of
        each centre relative to the support.
    base_force : numpy.ndarray
        Shape (N, B, 3): normal force at the left and right lower contact and
        total tangential force [N] on each block from the body below.
    """

    names: tuple[str, ...]
    table: ModeTable = field(repr=False)
    status: np.ndarray
    chosen: np.ndarray
    admissible_count: np.ndarray
    alternatives: np.ndarray
    relaxed: np.ndarray
    motion: np.ndarray
    pivot: np.ndarray
    slide_direction: np.ndarray
    acceleration: np.ndarray
    base_force: np.ndarray

    @property
    def count(self) -> int:
        """Number of cases N."""
        return int(self.status.shape[0])

    def status_name(self, case: int) -> str:
        """Status of case ``case`` as a word."""
        return STATUS_NAMES[int(self.status[case])]

    def alternative_states(self, case: int) -> list[tuple[tuple[Motion, str | None, int], ...]]:
        """(motion, pivot, slide direction) per block of each recorded admissible state."""
        return [self.table.block_states(int(k)) for k in self.alternatives[case] if k >= 0]

    def state_codes(self) -> np.ndarray:
        """One integer per case naming the joint motion of all blocks.

        ``sum_b (motion_b + 1) * 6**b`` for solved cases (motion codes of
        :data:`MOTIONS`), and negative codes ``-1 - status`` for
        inconsistent, free-flight and invalid cases.
        """
        codes = np.zeros(self.count, dtype=np.int64)
        for b in range(len(self.names)):
            codes += (self.motion[:, b].astype(np.int64) + 1) * 6**b
        solved = (self.status == UNIQUE) | (self.status == AMBIGUOUS)
        return np.where(solved, codes, -1 - self.status.astype(np.int64))

    def state_label(self, code: int) -> str:
        """The words for a :meth:`state_codes` code, e.g. ``"bridge slides, cart rests"``."""
        if code < 0:
            status = STATUS_NAMES[-1 - code]
            return {
                "inconsistent": "no consistent state",
                "free-flight": "free flight (a_ver >= g)",
                "invalid": "invalid input",
            }.get(status, status)
        motions = []
        for b in range(len(self.names)):
            motions.append(MOTIONS[(code // 6**b) % 6 - 1])
        return motion_label(self.names, motions)


_VERBS = {
    Motion.REST: "rests",
    Motion.SLIDE: "slides",
    Motion.ROCK: "rocks",
    Motion.SLIDE_ROCK: "slides and rocks",
    Motion.FREE_FLIGHT: "lifts off",
}


def motion_label(names: Sequence[str], motions: Sequence[Motion]) -> str:
    """Name a joint state, e.g. ``"bridge slides, cart rocks"`` (bottom block first)."""
    return ", ".join(f"{name} {_VERBS[Motion(m)]}" for name, m in zip(names, motions, strict=True))


def _empty_outputs(count: int, blocks: int) -> dict:
    return dict(
        status=np.full(count, INVALID, dtype=np.int8),
        chosen=np.full(count, -1, dtype=np.int64),
        alternatives=np.full((count, MAX_ALTERNATIVES), -1, dtype=np.int64),
        count=np.zeros(count, dtype=np.int64),
        relaxed=np.zeros(count, dtype=np.bool_),
        acceleration=np.zeros((count, blocks, 3)),
        forces=np.zeros((count, blocks, 3)),
    )


def _chunks(count: int, parts: int) -> np.ndarray:
    parts = max(1, min(parts, count))
    return np.linspace(0, count, parts + 1).astype(np.int64)


def _tidy(values: np.ndarray, scale: np.ndarray) -> np.ndarray:
    """Round away the 1e-13 residues as :func:`freestand.core.contact.screening._clean` does."""
    return np.where(np.abs(values) <= 1e-10 * np.maximum(scale, 1.0), 0.0, values)


def _finish(names, table: ModeTable, out: dict) -> BatchResult:
    count = out["status"].shape[0]
    blocks = len(names)
    motion = np.full((count, blocks), -1, dtype=np.int8)
    pivot = np.zeros((count, blocks), dtype=np.int8)
    slide = np.zeros((count, blocks), dtype=np.int8)
    solved = out["chosen"] >= 0
    modes = table.modes[out["chosen"][solved]]  # (M, B, 3)
    if modes.size:
        closed = modes[:, :, 0] + modes[:, :, 1]
        direction = np.where(modes[:, :, 2] == 2, 1, np.where(modes[:, :, 2] == 3, -1, 0))
        code = np.where(
            closed == 2,
            np.where(direction != 0, 1, 0),
            np.where(closed == 1, np.where(direction != 0, 3, 2), 4),
        )
        motion[solved] = code
        pivot[solved] = np.where(closed == 1, np.where(modes[:, :, 0] == 1, -1, 1), 0)
        slide[solved] = direction
    flight = out["status"] == FREE_FLIGHT
    motion[flight] = 4
    forces = out["forces"]
    acceleration = out["acceleration"]
    force_scale = np.abs(forces[:, :, 0]) + np.abs(forces[:, :, 1])
    forces = _tidy(forces, force_scale[:, :, None])
    acceleration = _tidy(acceleration, np.ones_like(acceleration))
    return BatchResult(
        names=tuple(names),
        table=table,
        status=out["status"],
        chosen=out["chosen"],
        admissible_count=out["count"],
        alternatives=out["alternatives"],
        relaxed=out["relaxed"],
        motion=motion,
        pivot=pivot,
        slide_direction=slide,
        acceleration=acceleration,
        base_force=forces,
    )


def _threads() -> int:
    import numba

    return int(numba.get_num_threads())


def solve_batch(
    inputs: CaseInputs,
    gravity: float = GRAVITY,
    progress: Callable[[int], None] | None = None,
    chunk: int = 65536,
) -> BatchResult:
    """Initial motion of every case (paper section 3; same answers as
    :func:`freestand.core.contact.screening.initial_motion`).

    Parameters
    ----------
    inputs : CaseInputs
        Stacks, excitations and sense of N cases.
    gravity : float, optional
        g [m/s^2].
    progress : callable, optional
        Called with the number of cases just finished, after each chunk.
    chunk : int, optional
        Cases per chunk between progress calls.

    Returns
    -------
    BatchResult
        Cases with invalid inputs (:meth:`BatchStack.valid`) get status
        ``invalid`` and are not solved.
    """
    stack = inputs.stack
    count = stack.count
    table = ModeTable.for_sliding(stack.sliding)
    out = _empty_outputs(count, len(stack.names))
    valid = stack.valid() & np.isfinite(inputs.horizontal) & np.isfinite(inputs.vertical)
    index = np.flatnonzero(valid)
    inertial = np.ascontiguousarray(inputs.inertial, dtype=float)
    vertical = np.ascontiguousarray(inputs.vertical, dtype=float)
    arrays = [np.ascontiguousarray(getattr(stack, name)) for name in BatchStack.ARRAYS]
    for start in range(0, max(len(index), 1), chunk):
        part = index[start : start + chunk]
        if not len(part):
            break
        sub = _empty_outputs(len(part), len(stack.names))
        _solve_parallel(
            _chunks(len(part), 4 * _threads()),
            table.sliding,
            *[np.ascontiguousarray(a[part]) for a in arrays],
            inertial[part],
            vertical[part],
            float(gravity),
            sub["status"],
            sub["chosen"],
            sub["alternatives"],
            sub["count"],
            sub["relaxed"],
            sub["acceleration"],
            sub["forces"],
        )
        for key, value in sub.items():
            out[key][part] = value
        if progress is not None:
            progress(len(part))
    if progress is not None and len(index) < count:
        progress(count - len(index))
    return _finish(stack.names, table, out)


def solve_excitation_plane(
    stack: Stack,
    inertial: np.ndarray,
    vertical: np.ndarray,
    gravity: float = GRAVITY,
    progress: Callable[[int], None] | None = None,
    chunk: int = 65536,
) -> BatchResult:
    """Initial motion of one stack at many excitations (the excitation plane).

    Every mode is solved for the two unit loads ``s a_hor = 1`` and
    ``g - a_ver = 1`` once; each point combines them linearly (paper section
    3: the equations of every case are linear in the inertial force
    ``m k_y g`` and the reduced weight ``m g (1 - k_z)``).

    Parameters
    ----------
    stack : Stack
    inertial : numpy.ndarray
        Signed horizontal inertial acceleration ``s a_hor`` [m/s^2], shape (N,).
    vertical : numpy.ndarray
        Downward support acceleration a_ver [m/s^2], shape (N,).
    gravity : float, optional
        g [m/s^2].
    progress : callable, optional
        Called with the number of cases just finished, after each chunk.
    chunk : int, optional
        Cases per chunk between progress calls.

    Returns
    -------
    BatchResult
    """
    batch = BatchStack.from_stack(stack, 1)
    table = ModeTable.for_sliding(batch.sliding)
    inertial = np.ascontiguousarray(np.broadcast_arrays(inertial, vertical)[0], dtype=float)
    vertical = np.ascontiguousarray(np.broadcast_arrays(inertial, vertical)[1], dtype=float)
    count = inertial.shape[0]
    basis = _plane_basis(
        table.modes,
        table.unknown_count,
        table.unknown_index,
        table.unknown_direction,
        *[np.ascontiguousarray(getattr(batch, name)[0]) for name in batch.ARRAYS],
    )
    out = _empty_outputs(count, len(batch.names))
    valid = np.isfinite(inertial) & np.isfinite(vertical)
    if not bool(batch.valid()[0]):
        valid[:] = False
    index = np.flatnonzero(valid)
    total_mass = float(np.sum(batch.mass[0]))
    for start in range(0, max(len(index), 1), chunk):
        part = index[start : start + chunk]
        if not len(part):
            break
        sub = _empty_outputs(len(part), len(batch.names))
        _plane_parallel(
            _chunks(len(part), 4 * _threads()),
            table.modes,
            table.priority,
            table.sliding,
            table.has_slide,
            np.ascontiguousarray(batch.static_friction[0]),
            total_mass,
            *basis,
            inertial[part],
            vertical[part],
            float(gravity),
            sub["status"],
            sub["chosen"],
            sub["alternatives"],
            sub["count"],
            sub["relaxed"],
            sub["acceleration"],
            sub["forces"],
        )
        for key, value in sub.items():
            out[key][part] = value
        if progress is not None:
            progress(len(part))
    if progress is not None and len(index) < count:
        progress(count - len(index))
    return _finish(batch.names, table, out)
