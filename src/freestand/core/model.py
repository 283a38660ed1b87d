"""The planar model: blocks stacked on a support, and the excitation.

Conventions (see ``docs/nomenclature.md``): x horizontal to the right, z
vertical up, z = 0 on the support surface; angles and angular accelerations
positive counter-clockwise (from x towards z). All values SI.

A :class:`Stack` lists its blocks bottom to top; block ``i`` rests on block
``i - 1`` through its two lower contacts (the paper's edges or wheels), block 0
on the support. The interface *below* a block belongs to that block: its
friction and its sliding restriction are given with the block.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import StrEnum

from freestand.errors import FreestandError

#: Choices of :attr:`Excitation.vertical_senses`.
VERTICAL_SENSES = ("given", "both")


def _number(value) -> float:
    """``value`` as a finite float, NaN when it is not one."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        return math.nan
    return number if math.isfinite(number) else math.nan


class Sliding(StrEnum):
    """Which way the interface below a block may slide.

    ``free``: both ways; ``none``: never (wheel flanges, pins); ``no-right``: an
    end stop, the block cannot slide further to the right (+x) relative to the
    body below; ``no-left``: likewise to the left.

    Examples
    --------
    >>> import freestand as fs
    >>> fs.Sliding("no-right").allows(+1), fs.Sliding("no-right").allows(-1)
    (False, True)
    """

    FREE = "free"
    NONE = "none"
    NO_RIGHT = "no-right"
    NO_LEFT = "no-left"

    def allows(self, direction: int) -> bool:
        """Whether sliding in ``direction`` (+1 right, -1 left) is possible."""
        if self is Sliding.FREE:
            return True
        if self is Sliding.NONE:
            return False
        if self is Sliding.NO_RIGHT:
            return direction < 0
        return direction > 0


@dataclass(frozen=True)
class Friction:
    """Coulomb friction of an interface (paper section 3.1.2.1).

    Parameters
    ----------
    static : float
        Static coefficient mu_0 [-]: the interface holds while
        ``|T| <= static * N``.
    kinetic : float
        Kinetic coefficient mu [-]: while sliding, ``|T| = kinetic * N``
        against the sliding. Not above ``static``.

    Examples
    --------
    >>> import freestand as fs
    >>> fs.Friction(static=0.8, kinetic=0.7)
    Friction(static=0.8, kinetic=0.7)
    """

    static: float
    kinetic: float


@dataclass(frozen=True)
class Block:
    """One rigid block of a stack, with the interface below it.

    Parameters
    ----------
    name : str
        Name used in results (``"bridge"``, ``"cart"``).
    mass : float
        Mass m [kg], positive.
    inertia : float
        Mass moment of inertia about the centre of gravity for rotation in the
        plane, Theta_S [kg m^2], positive.
    centre : tuple of float
        (x, z) of the centre of gravity S [m].
    base_left, base_right : float
        x of the left and right lower contacts [m], ``base_left < base_right``.
    base_level : float
        z of the lower contacts [m]: 0 for the bottom block, the top of the
        block below for the others.
    friction : Friction
        Friction of the interface below this block.
    sliding : Sliding
        Sliding restriction of the interface below this block.
    contact_names : tuple of str
        Names of the left and right lower contacts, for tables (the paper's
        G/H, C/D, E/F, A/B); ``("left", "right")`` by default.

    Examples
    --------
    >>> import freestand as fs
    >>> cabinet = fs.Block.rectangle("cabinet", 0.6, 2.0, 1200.0, fs.Friction(0.8, 0.7))
    >>> cabinet.centre, cabinet.base_left, cabinet.base_right  # [m]
    ((0.0, 1.0), -0.3, 0.3)
    >>> cabinet.inertia  # m (b^2 + h^2) / 12 [kg m^2]
    436.0
    >>> frame = fs.Block("frame", mass=150.0, inertia=14.0, centre=(0.0, 0.15), base_left=-0.5,
    ...                  base_right=0.5, base_level=0.0, friction=fs.Friction(0.5, 0.4))
    """

    name: str
    mass: float
    inertia: float
    centre: tuple[float, float]
    base_left: float
    base_right: float
    base_level: float
    friction: Friction
    sliding: Sliding = Sliding.FREE
    contact_names: tuple[str, str] = ("left", "right")

    @property
    def contacts(self) -> tuple[tuple[float, float], tuple[float, float]]:
        """(x, z) of the left and right lower contacts [m]."""
        return (self.base_left, self.base_level), (self.base_right, self.base_level)

    def inertia_about(self, point: tuple[float, float]) -> float:
        """Moment of inertia about ``point`` [kg m^2] by the parallel-axis rule."""
        dx = self.centre[0] - point[0]
        dz = self.centre[1] - point[1]
        return self.inertia + self.mass * (dx * dx + dz * dz)

    @classmethod
    def rectangle(
        cls,
        name: str,
        width: float,
        height: float,
        mass: float,
        friction: Friction,
        level: float = 0.0,
        sliding: Sliding = Sliding.FREE,
    ) -> Block:
        """A homogeneous rectangular block centred on x = 0, standing at ``level``.

        Parameters
        ----------
        name : str
        width, height : float
            Base width b and height h [m]; the lower contacts are the base's
            corners, x = -b/2 and b/2.
        mass : float
            m [kg].
        friction : Friction
            Friction of the interface below it.
        level : float, optional
            z of its base [m] (0: on the support).
        sliding : Sliding, optional

        Returns
        -------
        Block
            Centre of gravity at (0, level + h/2), ``Theta_S = m (b^2 + h^2) / 12``
            (a homogeneous rectangle).

        Raises
        ------
        FreestandError
            A width, height or mass that is not a positive finite number, or a
            level that is not finite.
        """
        checks = (("width", width, "m"), ("height", height, "m"), ("mass", mass, "kg"))
        for field, value, unit in checks:
            if not _number(value) > 0.0:
                raise FreestandError(
                    f"{value!r} is not a positive finite number; give the {field} in {unit}",
                    source=f"Block.rectangle({name!r})",
                    field=field,
                )
        if math.isnan(_number(level)):
            raise FreestandError(
                f"{level!r} is not a finite number; give the base level in m",
                source=f"Block.rectangle({name!r})",
                field="level",
            )
        width, height, mass, level = (float(value) for value in (width, height, mass, level))
        return cls(
            name,
            mass,
            mass * (width**2 + height**2) / 12.0,
            (0.0, level + 0.5 * height),
            -0.5 * width,
            0.5 * width,
            level,
            friction,
            sliding,
        )


@dataclass(frozen=True)
class Stack:
    """A planar model: blocks listed bottom to top (one model-file configuration).

    Parameters
    ----------
    name : str
        Configuration name (``"y-z"``, ``"x-z cart right"``).
    blocks : tuple of Block
        Bottom to top; block 0 rests on the support.

    Examples
    --------
    >>> import freestand as fs
    >>> frame = fs.Block.rectangle("frame", 1.0, 0.3, 150.0, fs.Friction(0.5, 0.4))
    >>> cabinet = fs.Block.rectangle("cabinet", 0.8, 2.2, 600.0, fs.Friction(0.4, 0.35),
    ...                              level=0.3)
    >>> stack = fs.Stack("cabinet on frame", (frame, cabinet))  # bottom first
    >>> stack.block_index("cabinet"), stack.unsupported()
    (1, ())
    """

    name: str
    blocks: tuple[Block, ...]

    def block_index(self, name: str) -> int:
        """Index of the block called ``name``; ``KeyError`` if there is none."""
        for index, block in enumerate(self.blocks):
            if block.name == name:
                return index
        raise KeyError(name)

    def unsupported(self) -> tuple[tuple[str, float, float, float], ...]:
        """The blocks that cannot stand even without excitation.

        The blocks ``i`` to the top rest on the lower contacts of block ``i``;
        under gravity alone they can stand only if their joint centre of gravity
        lies over that base, ``base_left <= x_G <= base_right`` with
        ``x_G = sum(m_j x_j) / sum(m_j)`` over ``j >= i`` (static equilibrium of
        a rigid body on two supports).

        Returns
        -------
        tuple of (str, float, float, float)
            For each such block: its name, ``x_G`` [m] of the blocks it carries
            together with itself, and its base's left and right x [m].
        """
        found = []
        for index, block in enumerate(self.blocks):
            above = self.blocks[index:]
            mass = sum(b.mass for b in above)
            x_centre = sum(b.mass * b.centre[0] for b in above) / mass
            if not block.base_left <= x_centre <= block.base_right:
                found.append((block.name, x_centre, block.base_left, block.base_right))
        return tuple(found)


@dataclass(frozen=True)
class Excitation:
    """A level of support acceleration (paper section 2).

    Parameters
    ----------
    name : str
        Name of the level (``"rigid"``, ``"elastic"``).
    horizontal : float
        Magnitude of the horizontal support acceleration a_hor [m/s^2]; both
        senses are analysed.
    vertical : float
        Signed vertical support acceleration a_ver [m/s^2], positive
        downward: the weight becomes m (g - a_ver). A negative value is an
        upward support acceleration, which increases the weight and with it
        the contact forces (the largest rail and anchor loads); it cannot
        start a motion that the same downward acceleration does not start
        (paper section 2).
    vertical_senses : str
        ``"given"``: analyse ``vertical`` as given; ``"both"``: analyse
        ``+|a_ver|`` (downward) and ``-|a_ver|`` (upward), for the envelope of
        the contact forces.
    horizontal_y : float
        The horizontal support acceleration's y component [m/s^2] (model-file
        key ``y``), for 3-D configurations (:mod:`freestand.core.body`):
        ``horizontal`` is then its x component, the pair (x, y) gives the
        excitation's magnitude ``sqrt(x^2 + y^2)`` and direction. Planar
        configurations take ``horizontal`` alone (their plane's x).

    Examples
    --------
    >>> import freestand as fs
    >>> level = fs.Excitation("SL-2", horizontal=3.5, vertical=2.3, vertical_senses="both")
    >>> level.verticals()  # a_v downward, then upward [m/s^2]
    (2.3, -2.3)
    """

    name: str
    horizontal: float
    vertical: float = 0.0
    vertical_senses: str = "given"
    horizontal_y: float = 0.0

    def verticals(self) -> tuple[float, ...]:
        """The signed vertical accelerations to analyse [m/s^2], downward first."""
        if self.vertical_senses == "both" and self.vertical != 0:
            return (abs(self.vertical), -abs(self.vertical))
        return (self.vertical,)
