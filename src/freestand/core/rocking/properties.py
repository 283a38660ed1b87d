"""Rocking properties of a rigid block and the closed-form overturning limits.

A free-standing block that uplifts rocks about one of its two lower contacts
(pivots). This module gives, for a block described by plain numbers, the
quantities of Housner's inverted-pendulum theory about each pivot and the
classical closed-form overturning limits that the paper uses in its section 5
(Figs. 6 and 7), together with the corrected linearised limit of Makris and
Roussos (2000). The exact limits from the nonlinear equation of motion are in
:mod:`freestand.core.rocking.integrator`.

Conventions
-----------
Pivot positions are given relative to the centre of gravity S, in the plane of
motion: ``(x, z)`` with ``z < 0`` (pivots below S). The block rocks first about
``pivot``; ``other_pivot`` is the contact it impacts on when it rocks back.
The rotation ``theta`` is positive when the block rocks about ``pivot``.
A *positive* support acceleration is one whose inertial force points from S
towards ``pivot`` (it tips the block over ``pivot``).

References
----------
.. [1] G. W. Housner, "The behavior of inverted pendulum structures during
   earthquakes", Bull. Seismol. Soc. Am. 53(2), 403-417, 1963.
.. [2] N. Makris and Y. Roussos, "Rocking response of rigid blocks under
   near-source ground motions", Geotechnique 50(3), 243-262, 2000.
.. [3] J. Zhang and N. Makris, "Rocking response of free-standing blocks under
   cycloidal pulses", J. Eng. Mech. 127(5), 473-483, 2001.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from freestand.errors import FreestandError

#: Names accepted wherever a pivot of a :class:`RockingBlock` is selected.
PIVOT_NAMES = ("pivot", "other")


@dataclass(frozen=True)
class PivotProperties:
    """Rocking properties of a block about one pivot (Housner 1963).

    Parameters
    ----------
    half_width : float
        Horizontal distance b from the pivot to the centre of gravity [m].
    height : float
        Height h of the centre of gravity above the pivot [m].
    R : float
        Distance from the pivot to the centre of gravity, sqrt(b^2 + h^2) [m].
    alpha : float
        Slenderness angle atan(b / h) [rad].
    inertia_about_pivot : float
        Moment of inertia about the pivot, I_S + m R^2 [kg m^2].
    p : float
        Frequency parameter sqrt(m g R / I_O) [rad/s], with g the effective
        gravity (g - a_v).
    uplift_threshold : float
        Support acceleration that starts rocking from rest, g tan(alpha)
        [m/s^2].
    """

    half_width: float
    height: float
    R: float
    alpha: float
    inertia_about_pivot: float
    p: float
    uplift_threshold: float


@dataclass(frozen=True)
class RockingBlock:
    """A rigid block that may rock about either of its two lower contacts.

    Parameters
    ----------
    mass : float
        Mass m [kg], positive.
    inertia : float
        Moment of inertia about the centre of gravity for rotation in the plane
        of motion, I_S [kg m^2], positive.
    pivot : tuple of float
        (x, z) of the pivot the block rocks about first, relative to the centre
        of gravity [m]; ``z < 0``.
    other_pivot : tuple of float
        (x, z) of the other lower contact relative to the centre of gravity
        [m]; on the other side of the centre of gravity (``x`` of opposite
        sign), ``z < 0``.
    gravity : float, optional
        Gravitational acceleration g [m/s^2] (9.81 as in the paper).
    vertical_acceleration : float, optional
        Downward support acceleration a_v [m/s^2], constant during the motion:
        the weight becomes m (g - a_v). 0 (the paper's section 5) by default.
    restitution_override : float, optional
        Angular-velocity ratio at impact [-] to use in place of the value from
        conservation of angular momentum (both impact directions).

    Notes
    -----
    About a pivot P with centre of gravity at r = S - P = (b, h) in the rest
    position: R = sqrt(b^2 + h^2), alpha = atan(b / h), I_O = I_S + m R^2 (parallel-axis
    rule), p = sqrt(m (g - a_v) R / I_O) (Housner 1963; Zhang and Makris 2001,
    eq. 3).

    Examples
    --------
    >>> import freestand as fs
    >>> cabinet = fs.Block.rectangle("cabinet", 0.6, 2.0, 1200.0, fs.Friction(0.8, 0.7))
    >>> rocking = fs.RockingBlock.from_block(cabinet, "right")
    >>> round(rocking.alpha, 4), round(rocking.p, 3)  # [rad], [rad/s]
    (0.2915, 2.655)
    >>> round(rocking.uplift_threshold, 3), round(rocking.restitution, 3)  # [m/s^2], [-]
    (2.943, 0.876)
    """

    mass: float
    inertia: float
    pivot: tuple[float, float]
    other_pivot: tuple[float, float]
    gravity: float = 9.81
    vertical_acceleration: float = 0.0
    restitution_override: float | None = None

    def __post_init__(self) -> None:
        if not (self.mass > 0 and math.isfinite(self.mass)):
            raise ValueError(f"mass must be positive and finite, got {self.mass!r}")
        if not (self.inertia > 0 and math.isfinite(self.inertia)):
            raise ValueError(f"inertia must be positive and finite, got {self.inertia!r}")
        if not self.gravity - self.vertical_acceleration > 0:
            raise ValueError(
                "the effective gravity g - a_v must be positive (a downward support "
                f"acceleration of at least g means free flight), got g = {self.gravity!r}, "
                f"a_v = {self.vertical_acceleration!r}"
            )
        px, pz = (float(v) for v in self.pivot)
        ox, oz = (float(v) for v in self.other_pivot)
        object.__setattr__(self, "pivot", (px, pz))
        object.__setattr__(self, "other_pivot", (ox, oz))
        if not (pz < 0 and oz < 0):
            raise ValueError("pivots must lie below the centre of gravity (z < 0)")
        if px == 0 or ox == 0 or px * ox > 0:
            raise ValueError(
                "the two pivots must lie on opposite sides of the centre of gravity "
                f"(x of opposite signs, neither zero), got x = {px!r} and {ox!r}"
            )
        if self.restitution_override is not None and not (0 <= self.restitution_override <= 1):
            raise ValueError(
                f"restitution_override must lie in [0, 1], got {self.restitution_override!r}"
            )

    # -- constructors -----------------------------------------------------------------
    @classmethod
    def rectangle(
        cls,
        mass: float,
        half_width: float,
        height: float,
        *,
        inertia: float | None = None,
        gravity: float = 9.81,
        vertical_acceleration: float = 0.0,
        restitution_override: float | None = None,
    ) -> RockingBlock:
        """A block with its centre of gravity above the middle of its base.

        Parameters
        ----------
        mass : float
            Mass m [kg].
        half_width : float
            Half the base width b [m].
        height : float
            Height h of the centre of gravity above the base [m].
        inertia : float, optional
            Moment of inertia about the centre of gravity [kg m^2]; by default
            that of a homogeneous rectangle 2b x 2h, m (b^2 + h^2) / 3.
        gravity, vertical_acceleration, restitution_override
            As for :class:`RockingBlock`.
        """
        if inertia is None:
            inertia = mass * (half_width**2 + height**2) / 3.0
        return cls(
            mass,
            inertia,
            (-half_width, -height),
            (half_width, -height),
            gravity,
            vertical_acceleration,
            restitution_override,
        )

    @classmethod
    def from_block(
        cls,
        block,
        pivot: str,
        *,
        gravity: float = 9.81,
        vertical_acceleration: float = 0.0,
        restitution_override: float | None = None,
    ) -> RockingBlock:
        """The rocking block of a :class:`freestand.core.model.Block` on a fixed support.

        Parameters
        ----------
        block : freestand.core.model.Block
            The block (its lower contacts are the pivots).
        pivot : str
            ``"left"`` or ``"right"``: the contact it rocks about first. Rocking
            about the left contact is driven by a support acceleration towards
            +x (inertial force towards -x).
        gravity, vertical_acceleration, restitution_override
            As for :class:`RockingBlock`.

        Raises
        ------
        FreestandError
            If ``pivot`` is neither ``"left"`` nor ``"right"``.
        """
        sx, sz = block.centre
        left = (block.base_left - sx, block.base_level - sz)
        right = (block.base_right - sx, block.base_level - sz)
        if pivot == "left":
            first, second = left, right
        elif pivot == "right":
            first, second = right, left
        else:
            raise FreestandError(f"unknown pivot {pivot!r}; use 'left' or 'right'", field="pivot")
        return cls(
            block.mass,
            block.inertia,
            first,
            second,
            gravity,
            vertical_acceleration,
            restitution_override,
        )

    # -- per-pivot properties ---------------------------------------------------------
    @property
    def effective_gravity(self) -> float:
        """g - a_v [m/s^2]: the weight per unit mass during the motion."""
        return self.gravity - self.vertical_acceleration

    def about(self, which: str = "pivot") -> PivotProperties:
        """Rocking properties about ``which`` pivot (``"pivot"`` or ``"other"``).

        Raises
        ------
        FreestandError
            If ``which`` is not one of :data:`PIVOT_NAMES`.
        """
        if which == "pivot":
            px, pz = self.pivot
        elif which == "other":
            px, pz = self.other_pivot
        else:
            raise FreestandError(
                f"unknown pivot {which!r}; use one of {', '.join(PIVOT_NAMES)}", field="pivot"
            )
        b, h = abs(px), -pz
        R = math.hypot(b, h)
        inertia_o = self.inertia + self.mass * R * R
        g = self.effective_gravity
        alpha = math.atan2(b, h)
        return PivotProperties(
            half_width=b,
            height=h,
            R=R,
            alpha=alpha,
            inertia_about_pivot=inertia_o,
            p=math.sqrt(self.mass * g * R / inertia_o),
            uplift_threshold=g * b / h,
        )

    @property
    def R(self) -> float:
        """Distance from ``pivot`` to the centre of gravity [m]."""
        return self.about("pivot").R

    @property
    def alpha(self) -> float:
        """Slenderness angle about ``pivot``, atan(b / h) [rad]."""
        return self.about("pivot").alpha

    @property
    def inertia_about_pivot(self) -> float:
        """Moment of inertia about ``pivot``, I_S + m R^2 [kg m^2]."""
        return self.about("pivot").inertia_about_pivot

    @property
    def p(self) -> float:
        """Frequency parameter about ``pivot``, sqrt(m (g - a_v) R / I_O) [rad/s]."""
        return self.about("pivot").p

    @property
    def uplift_threshold(self) -> float:
        """Support acceleration that uplifts the block about ``pivot``, (g - a_v) b / h [m/s^2]."""
        return self.about("pivot").uplift_threshold

    # -- impact -----------------------------------------------------------------------
    def computed_restitution(self, onto: str = "other") -> float:
        """Angular-velocity ratio at impact from conservation of angular momentum.

        Parameters
        ----------
        onto : str
            The pivot the block lands on: ``"other"`` (rocking about ``pivot``
            and landing on ``other_pivot``) or ``"pivot"``.

        Returns
        -------
        float
            omega_after / omega_before [-]. Conservation of angular momentum
            about the new pivot Q (Housner 1963, eq. 4, generalised):

            (I_S + m r_P . r_Q) omega_before = (I_S + m r_Q . r_Q) omega_after,

            with r_P, r_Q the vectors from the old and new pivot to the centre
            of gravity. For a homogeneous rectangle this is
            1 - 1.5 sin^2(alpha); Housner's r is its square (energy ratio).
            Negative values (squat blocks) mean the impact stops the rocking.
        """
        if onto not in PIVOT_NAMES:
            raise FreestandError(
                f"unknown pivot {onto!r}; use one of {', '.join(PIVOT_NAMES)}", field="pivot"
            )
        old, new = (
            (self.pivot, self.other_pivot) if onto == "other" else (self.other_pivot, self.pivot)
        )
        r_old = (-old[0], -old[1])
        r_new = (-new[0], -new[1])
        dot = r_old[0] * r_new[0] + r_old[1] * r_new[1]
        return (self.inertia + self.mass * dot) / (
            self.inertia + self.mass * (r_new[0] ** 2 + r_new[1] ** 2)
        )

    def restitution_onto(self, onto: str = "other") -> float:
        """Angular-velocity ratio used at an impact onto ``onto`` [-] (override or computed)."""
        if self.restitution_override is not None:
            if onto not in PIVOT_NAMES:
                raise FreestandError(
                    f"unknown pivot {onto!r}; use one of {', '.join(PIVOT_NAMES)}",
                    field="pivot",
                )
            return float(self.restitution_override)
        return self.computed_restitution(onto)

    @property
    def restitution(self) -> float:
        """Angular-velocity ratio at the impact from ``pivot`` onto ``other_pivot`` [-]."""
        return self.restitution_onto("other")

    # -- closed forms -----------------------------------------------------------------
    def housner_rectangular_duration(self, amplitude: np.ndarray | float) -> np.ndarray | float:
        """Shortest overturning rectangular pulse, Housner's linearised closed form.

        Parameters
        ----------
        amplitude : float or array_like
            Constant support acceleration a of the pulse [m/s^2].

        Returns
        -------
        float or numpy.ndarray
            t1 = ln[A / (A - 1)] / p with A = a / (g alpha) [s] (Housner 1963,
            eq. 9; paper section 5, Fig. 6). ``inf`` where A <= 1 (no pulse of
            that amplitude overturns the block in the linearised theory).
        """
        a = np.asarray(amplitude, dtype=float)
        big_a = a / (self.effective_gravity * self.alpha)
        with np.errstate(divide="ignore", invalid="ignore"):
            t1 = np.where(big_a > 1, np.log(big_a / (big_a - 1)) / self.p, np.inf)
        return float(t1) if np.ndim(amplitude) == 0 else t1

    def housner_half_sine_amplitude(self, frequency: np.ndarray | float) -> np.ndarray | float:
        """Minimum overturning amplitude of a half-sine pulse, Housner's criterion.

        Parameters
        ----------
        frequency : float or array_like
            Frequency f of the sine [Hz]; the pulse a sin(2 pi f t) lasts
            1 / (2 f).

        Returns
        -------
        float or numpy.ndarray
            a = g alpha sqrt(1 + (omega / p)^2) with omega = 2 pi f [m/s^2]
            (Housner 1963, eq. 12, as the paper applies it in section 5,
            Fig. 7). Makris and Roussos (2000) showed this is unconservative:
            it is the amplitude at which the block reaches the point of no
            return at the end of the pulse, but a block can still overturn
            with less.
        """
        w = 2 * np.pi * np.asarray(frequency, dtype=float)
        a = self.effective_gravity * self.alpha * np.sqrt(1 + (w / self.p) ** 2)
        return float(a) if np.ndim(frequency) == 0 else a

    def makris_roussos_half_sine_amplitude(
        self, frequency: np.ndarray | float
    ) -> np.ndarray | float:
        """Minimum overturning amplitude of a half-sine pulse, corrected linearised solution.

        Parameters
        ----------
        frequency : float or array_like
            Frequency f of the sine [Hz] (pulse duration 1 / (2 f)).

        Returns
        -------
        float or numpy.ndarray
            a = g alpha / sin(psi) [m/s^2], psi in (0, pi/2] the phase of the
            pulse at uplift, root of Makris and Roussos (2000), eq. 27:

            (omega / p) sin(psi) - cos(psi) = exp[-(p / omega)(pi - psi)].

            It is the exact solution of the linearised equation of motion
            (slender block); it lies below Housner's criterion.
        """
        f = np.atleast_1d(np.asarray(frequency, dtype=float))
        out = np.array([self._makris_roussos_one(2 * math.pi * fi) for fi in f])
        return float(out[0]) if np.ndim(frequency) == 0 else out.reshape(np.shape(frequency))

    def _makris_roussos_one(self, omega: float) -> float:
        if not (omega > 0 and math.isfinite(omega)):
            raise ValueError(f"frequency must be positive and finite, got omega = {omega!r}")
        return self.effective_gravity * self.alpha / math.sin(makris_roussos_psi(omega / self.p))


def makris_roussos_psi(frequency_ratio: float) -> float:
    """Uplift phase psi of the minimum overturning half-sine pulse (linearised theory).

    Parameters
    ----------
    frequency_ratio : float
        omega / p [-], omega the angular frequency of the sine.

    Returns
    -------
    float
        psi [rad] in (0, pi/2): the root of Makris and Roussos (2000), eq. 27,
        F(psi) = (omega/p) sin(psi) - cos(psi) - exp[-(p/omega)(pi - psi)] = 0.
        F < 0 at psi -> 0 and F > 0 at psi = pi/2; the root with the largest
        psi (the lowest amplitude) is bracketed on a fine grid and refined by
        Brent's method.
    """
    from scipy.optimize import brentq

    x = float(frequency_ratio)
    if not (x > 0 and math.isfinite(x)):
        raise ValueError(f"omega/p must be positive and finite, got {x!r}")

    def residual(psi: float) -> float:
        return x * math.sin(psi) - math.cos(psi) - math.exp(-(math.pi - psi) / x)

    grid = np.linspace(1e-12, math.pi / 2, 2001)
    values = np.array([residual(v) for v in grid])
    if values[-1] <= 0:
        raise ValueError(f"eq. 27 has no root in (0, pi/2] for omega/p = {x!r}")
    negative = np.nonzero(values < 0)[0]
    if negative.size == 0:
        raise ValueError(f"eq. 27 has no sign change in (0, pi/2] for omega/p = {x!r}")
    i = int(negative[-1])
    return brentq(residual, grid[i], grid[i + 1], xtol=1e-15, rtol=1e-15, maxiter=200)
