"""Vertical natural frequency of a bridge carrying a parked cart (paper section 6).

The bridge is a simply supported (pin-pin) Euler-Bernoulli beam of span ``l``,
bending stiffness ``E I`` and uniformly distributed mass ``m``; the cart is a
rigid body of mass ``M`` (and, optionally, rotary inertia ``J``) fixed to the
beam at a distance ``d`` from the left support. Three estimates of the lowest
vertical natural frequency are given here, all in hertz:

* :func:`dunkerley_frequency` -- Dunkerley's estimate exactly as the paper
  builds it (paper section 6, eqs. 1-4): the bare continuous beam and the cart
  on a massless beam combined as ``1/f^2 = 1/f_1^2 + 1/f_2^2``. It is a lower
  bound of the exact frequency.
* :func:`exact_frequency` -- the exact fundamental frequency of the continuous
  beam carrying the cart, from the analytic frequency equation.
* :func:`finite_element_frequency` -- Hermite (cubic) beam elements with
  consistent mass, which converge to the exact value as the mesh is refined.

:func:`frequency_sweep` evaluates the three over cart positions and
:func:`jump_check` compares the vertical spectral acceleration at the lowest
frequency with gravity: where it reaches ``g``, the cart may lose contact with
its rails (paper section 6.1).

Units of the paper's equations
------------------------------
The paper writes its frequencies as ``alpha`` and reports them in Hz, but its
eq. 2, ``alpha_i = i^2 pi^2 sqrt(I E / (m_1 l^3))``, and its eq. 4,
``alpha_2 = 1 / sqrt(m_2 k)``, give *angular* frequencies [rad/s]: for the crane
eq. 2 gives 135.4 rad/s, which is the reported 21.6 Hz only after division by
``2 pi``. Likewise its ``k = d^2 (l - d)^2 / (3 I E l)`` (eq. 3) is the static
*flexibility* [m/N] at the cart, not a spring constant. This module reproduces
the paper's numbers (21.6 Hz at a support, 10.6 Hz at mid-span) by dividing
eqs. 2 and 4 by ``2 pi``; Dunkerley's sum (eq. 1) is the same in either unit.

References
----------
Paper section 6, eqs. 1-4 and Fig. 9. Dunkerley's bound follows from the
subadditivity of the largest eigenvalue of a sum of positive semi-definite
operators; the exact solution uses the receptance of the simply supported beam
(modal expansion with the static flexibility in closed form, e.g. R. D.
Blevins, *Formulas for Natural Frequency and Mode Shape*, 1979, ch. 8).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.linalg import eigh
from scipy.optimize import brentq

from freestand.core.motion.spectra import Spectrum
from freestand.errors import FreestandError

TWO_PI = 2.0 * math.pi

#: Number of beam modes in the dynamic remainder of the receptance. The
#: remainder terms fall off as ``n^-8`` (deflection) and ``n^-6`` (slope), so
#: the truncation error is below 1e-12 relative.
RECEPTANCE_MODES = 256

#: A spectral acceleration within this relative distance of ``g`` counts as
#: reaching ``g`` (plateaus are often tabulated as exactly 1.0 g).
REACH_TOLERANCE = 1e-9

#: The finite-element mesh has a node at the load unless the load is closer to a
#: support than this fraction of the span: a shorter end element makes the
#: stiffness matrix ill-conditioned. Closer loads are interpolated within the
#: end element; the error this makes is of the order of this fraction.
NODE_AT_LOAD_FROM_SUPPORT = 1e-6


@dataclass(frozen=True)
class SimplySupportedBeam:
    """A simply supported uniform beam carrying a rigid load at one point.

    Parameters
    ----------
    span : float
        Distance between the supports, the paper's ``l`` [m]. Positive.
    youngs_modulus : float
        Modulus of elasticity ``E`` [Pa]. Positive.
    second_moment : float
        Second moment of area of the cross-section about the bending axis,
        the paper's ``I_y`` [m^4]. Positive.
    mass : float
        The beam's own mass ``m_1``, uniformly distributed [kg]. Non-negative.
    load_mass : float
        The load's (cart's) mass ``m_2``, a point mass [kg]. Non-negative;
        ``mass`` and ``load_mass`` must not both be zero.
    load_rotary_inertia : float, optional
        The load's mass moment of inertia about its own centre, about the axis
        of bending [kg m^2]. Non-negative; 0 (the paper's assumption) by default.
    load_height : float, optional
        Height of the load's centre above the beam's axis [m]. With the load
        rigidly fixed to the cross-section, a rotation ``theta`` of the section
        moves the centre horizontally by ``load_height * theta``, so the
        rotary inertia about the axis is ``J + M h^2`` (parallel axes). 0 by
        default.

    Notes
    -----
    The load is assumed to move with the beam's cross-section (no sliding,
    rocking or lift-off): the model is the linear one of paper section 6.
    """

    span: float
    youngs_modulus: float
    second_moment: float
    mass: float
    load_mass: float
    load_rotary_inertia: float = 0.0
    load_height: float = 0.0

    def __post_init__(self) -> None:
        checks = (
            ("span", self.span, "positive", "give the distance between the supports in m"),
            ("youngs_modulus", self.youngs_modulus, "positive", "give E in Pa, e.g. 2.1e11"),
            ("second_moment", self.second_moment, "positive", "give I in m^4, e.g. 0.014"),
            ("mass", self.mass, "non-negative", "give the beam's own mass in kg"),
            ("load_mass", self.load_mass, "non-negative", "give the cart's mass in kg"),
            (
                "load_rotary_inertia",
                self.load_rotary_inertia,
                "non-negative",
                "give the cart's rotary inertia in kg m^2, or 0 to neglect it",
            ),
            ("load_height", self.load_height, "finite", "give the height in m, or 0"),
        )
        for name, value, rule, fix in checks:
            try:
                number = float(value)
            except (TypeError, ValueError):
                raise FreestandError(f"{value!r} is not a number; {fix}", field=name) from None
            if not math.isfinite(number):
                raise FreestandError(f"{value!r} is not finite; {fix}", field=name)
            if rule == "positive" and number <= 0:
                raise FreestandError(f"{value!r} must be positive; {fix}", field=name)
            if rule == "non-negative" and number < 0:
                raise FreestandError(f"{value!r} must not be negative; {fix}", field=name)
            object.__setattr__(self, name, number)
        if self.mass == 0 and self.load_mass == 0 and self.effective_rotary_inertia == 0:
            raise FreestandError(
                "the beam and its load are both massless, so there is no vibration; "
                "give the beam's mass or the load's mass",
                field="mass",
            )

    @property
    def bending_stiffness(self) -> float:
        """``E I`` [N m^2]."""
        return self.youngs_modulus * self.second_moment

    @property
    def mass_per_length(self) -> float:
        """Distributed mass ``m / l`` [kg/m]."""
        return self.mass / self.span

    @property
    def effective_rotary_inertia(self) -> float:
        """Rotary inertia of the load about the beam's axis, ``J + M h^2`` [kg m^2]."""
        return self.load_rotary_inertia + self.load_mass * self.load_height**2

    def without_load(self) -> SimplySupportedBeam:
        """The same beam with a massless load."""
        return SimplySupportedBeam(
            self.span, self.youngs_modulus, self.second_moment, self.mass, 0.0, 0.0, 0.0
        )


def _positions(beam: SimplySupportedBeam, position) -> np.ndarray:
    """Positions as a float array, checked to lie on the span."""
    d = np.asarray(position, dtype=float)
    if not np.all(np.isfinite(d)):
        raise FreestandError(
            f"{position!r} holds a value that is not finite; give positions in m "
            f"between 0 and the span {beam.span:g} m",
            field="position",
        )
    slack = 1e-12 * beam.span
    outside = (d < -slack) | (d > beam.span + slack)
    if np.any(outside):
        bad = float(d[outside].flat[0]) if d.ndim else float(d)
        raise FreestandError(
            f"{bad:g} m is outside the span; the cart's centre must lie between "
            f"0 and {beam.span:g} m from the left support",
            field="position",
        )
    return np.clip(d, 0.0, beam.span)


def _shape_out(values: np.ndarray, position) -> np.ndarray | float:
    return float(values) if np.ndim(position) == 0 else values


def bare_beam_frequency(beam: SimplySupportedBeam, mode: int = 1) -> float:
    """Natural frequency of the bare simply supported beam [Hz] (paper eq. 2).

    .. math:: f_i = \\frac{1}{2\\pi}\\, i^2 \\pi^2 \\sqrt{\\frac{E I}{m l^3}}

    Paper eq. 2 is the angular frequency; divided by ``2 pi`` it gives the
    paper's 21.6 Hz for the crane bridge.

    Parameters
    ----------
    beam : SimplySupportedBeam
        The beam; only its span, stiffness and own mass are used.
    mode : int, optional
        Mode number ``i`` [-], 1 for the fundamental.

    Returns
    -------
    float
        ``f_i`` [Hz]; ``inf`` for a massless beam.
    """
    if mode < 1:
        raise ValueError("mode must be a positive integer")
    if beam.mass == 0:
        return math.inf
    omega = mode**2 * math.pi**2 * math.sqrt(beam.bending_stiffness / (beam.mass * beam.span**3))
    return omega / TWO_PI


def static_flexibility(beam: SimplySupportedBeam, position) -> np.ndarray:
    """Static flexibility matrix of the beam at ``position`` [m/N, 1/N, 1/(N m)].

    Deflection ``w`` and slope ``theta`` at the point ``a`` due to a unit force
    ``F`` and a unit couple ``C`` there (``b = l - a``):

    .. math::
        f_{wF} = \\frac{a^2 b^2}{3 E I l},\\quad
        f_{wC} = f_{\\theta F} = \\frac{a b (b - a)}{3 E I l},\\quad
        f_{\\theta C} = \\frac{a^3 + b^3}{3 E I l^2}

    ``f_wF`` is the paper's ``k`` (eq. 3).

    Parameters
    ----------
    beam : SimplySupportedBeam
        The beam.
    position : float or array_like
        Distance ``a`` from the left support [m].

    Returns
    -------
    numpy.ndarray
        Shape ``(..., 2, 2)``: ``[[f_wF, f_wC], [f_thetaF, f_thetaC]]``.
    """
    a = _positions(beam, position)
    span = beam.span
    b = span - a
    denominator = 3.0 * beam.bending_stiffness * span
    f_ww = a**2 * b**2 / denominator
    f_wt = a * b * (b - a) / denominator
    f_tt = (a**3 + b**3) / (denominator * span)
    return np.stack([np.stack([f_ww, f_wt], -1), np.stack([f_wt, f_tt], -1)], -2)


def load_flexibility(beam: SimplySupportedBeam, position) -> np.ndarray | float:
    """The paper's ``k``: static deflection at the cart per unit force [m/N] (eq. 3).

    .. math:: k = \\frac{d^2 (l - d)^2}{3 I E l}

    The paper calls it a spring constant, but it is a flexibility.

    Parameters
    ----------
    beam : SimplySupportedBeam
        The beam.
    position : float or array_like
        The cart's distance ``d`` from the left support [m].

    Returns
    -------
    float or numpy.ndarray
        ``k`` [m/N].
    """
    return _shape_out(static_flexibility(beam, position)[..., 0, 0], position)


def spring_mass_frequency(beam: SimplySupportedBeam, position) -> np.ndarray | float:
    """Frequency of the cart on the beam taken as massless [Hz] (paper eq. 4).

    .. math:: f_2 = \\frac{1}{2\\pi} \\frac{1}{\\sqrt{m_2 k}}

    (paper eq. 4 divided by ``2 pi``). ``inf`` at the supports and for a
    massless cart.

    Parameters
    ----------
    beam : SimplySupportedBeam
        The beam and cart.
    position : float or array_like
        The cart's distance ``d`` from the left support [m].

    Returns
    -------
    float or numpy.ndarray
        ``f_2`` [Hz].
    """
    compliance = beam.load_mass * np.asarray(load_flexibility(beam, position), dtype=float)
    with np.errstate(divide="ignore"):
        frequency = np.where(compliance > 0, 1.0 / (TWO_PI * np.sqrt(compliance)), np.inf)
    return _shape_out(frequency, position)


def dunkerley_frequency(beam: SimplySupportedBeam, position) -> np.ndarray | float:
    """Dunkerley's estimate of the lowest vertical frequency [Hz] (paper eqs. 1-4).

    .. math::
        \\frac{1}{f^2} = \\frac{1}{f_1^2} + \\frac{1}{f_2^2} + \\frac{1}{f_3^2}

    with ``f_1`` the bare beam (eq. 2), ``f_2`` the cart's mass on the massless
    beam (eqs. 3, 4) and ``f_3 = 1 / (2 pi sqrt(J_eff f_thetaC))`` its rotary
    inertia on the massless beam (zero term when ``J_eff = 0``, the paper's
    case). Each term is the largest eigenvalue of one positive semi-definite
    part of the flexibility-times-mass operator, and the largest eigenvalue
    of a sum is at most the sum of the largest eigenvalues, so ``f`` never
    exceeds the exact frequency.

    Parameters
    ----------
    beam : SimplySupportedBeam
        The beam and cart.
    position : float or array_like
        The cart's distance ``d`` from the left support [m].

    Returns
    -------
    float or numpy.ndarray
        ``f`` [Hz], shaped like ``position``.
    """
    flexibility = static_flexibility(beam, position)
    f_bare = bare_beam_frequency(beam)
    inverse_square = (
        (1.0 / f_bare**2 if math.isfinite(f_bare) else 0.0)
        + TWO_PI**2 * beam.load_mass * flexibility[..., 0, 0]
        + TWO_PI**2 * beam.effective_rotary_inertia * flexibility[..., 1, 1]
    )
    with np.errstate(divide="ignore"):
        frequency = np.where(inverse_square > 0, 1.0 / np.sqrt(inverse_square), np.inf)
    return _shape_out(frequency, position)


def _exact_angular_frequency_squared(beam: SimplySupportedBeam, a: float, modes: int) -> float:
    """Lowest ``omega^2`` [rad^2/s^2] of the beam with the load at ``a`` [m].

    The load's inertia ``D = diag(M, J)`` acts on the beam's deflection and
    slope at ``a``. With the receptance matrix ``G(Omega)`` of the bare beam at
    ``a`` (``Omega = omega^2``), the natural frequencies are where
    ``B(Omega) = I - Omega D^1/2 G(Omega) D^1/2`` is singular. Below the bare
    beam's first frequency ``G`` is positive definite and grows with
    ``Omega``, so the smallest eigenvalue of ``B`` falls monotonically from 1:
    its single zero there is the fundamental, found by Brent's method. ``G`` is
    the static flexibility in closed form plus the dynamic remainder of the
    modal expansion,
    ``sum_n phi_n phi_n^T / omega_n^2 * Omega / (omega_n^2 - Omega)``,
    whose terms fall off as ``n^-6`` or faster.
    """
    span = beam.span
    stiffness = beam.bending_stiffness
    load_mass = beam.load_mass
    rotary = beam.effective_rotary_inertia
    omega1_sq = math.pi**4 * stiffness / (beam.mass * span**3) if beam.mass > 0 else math.inf
    if load_mass == 0 and rotary == 0:
        return omega1_sq
    n = np.arange(1, modes + 1, dtype=float)
    wavenumber = n * math.pi / span
    sine = np.sin(wavenumber * a)
    cosine = np.cos(wavenumber * a)
    # phi_n phi_n^T / omega_n^2 with phi_n = sqrt(2/m) sin(n pi x / l): independent of m.
    modal = 2.0 * span**3 / (stiffness * (n * math.pi) ** 4)
    s_ww = modal * sine * sine
    s_wt = modal * sine * cosine * wavenumber
    s_tt = modal * cosine * cosine * wavenumber**2
    n4 = n**4
    g_static = static_flexibility(beam, a)
    root_mass = math.sqrt(load_mass)
    root_rotary = math.sqrt(rotary)

    def receptance(omega_sq: float) -> tuple[float, float, float]:
        ratio = omega_sq / omega1_sq  # 0 for a massless beam
        weight = ratio / (n4 - ratio)
        return (
            g_static[0, 0] + float(s_ww @ weight),
            g_static[0, 1] + float(s_wt @ weight),
            g_static[1, 1] + float(s_tt @ weight),
        )

    def smallest_eigenvalue(omega_sq: float) -> float:
        g_ww, g_wt, g_tt = receptance(omega_sq)
        b_ww = 1.0 - omega_sq * load_mass * g_ww
        b_wt = -omega_sq * root_mass * root_rotary * g_wt
        b_tt = 1.0 - omega_sq * rotary * g_tt
        return 0.5 * (b_ww + b_tt) - math.hypot(0.5 * (b_ww - b_tt), b_wt)

    # Upper bound: the load on the massless beam (Rayleigh: adding mass lowers).
    d_g = np.array(
        [
            [load_mass * g_static[0, 0], root_mass * root_rotary * g_static[0, 1]],
            [root_mass * root_rotary * g_static[0, 1], rotary * g_static[1, 1]],
        ]
    )
    largest = float(np.linalg.eigvalsh(d_g)[-1])
    massless_sq = 1.0 / largest if largest > 0 else math.inf
    near_pole = omega1_sq * (1.0 - 1e-13)
    upper = min(near_pole, massless_sq)
    if not math.isfinite(upper):  # massless beam with the load on a support, J = 0
        return math.inf
    if smallest_eigenvalue(upper) >= 0.0:
        # The root lies in [upper, min(omega1^2, massless^2)], an interval of
        # relative width below 1e-13: the load hardly engages the first mode.
        return omega1_sq if upper == near_pole else massless_sq
    return brentq(smallest_eigenvalue, 0.0, upper, xtol=1e-300, rtol=4.0 * np.finfo(float).eps)


def exact_frequency(
    beam: SimplySupportedBeam, position, *, modes: int = RECEPTANCE_MODES
) -> np.ndarray | float:
    """Exact lowest vertical frequency of the beam carrying the cart [Hz].

    Solves the frequency equation of the continuous Euler-Bernoulli beam with
    the point mass ``M`` and rotary inertia ``J_eff`` at ``position``:

    .. math:: \\det\\left(I - \\omega^2 D^{1/2} G(\\omega) D^{1/2}\\right) = 0,
        \\qquad D = \\mathrm{diag}(M, J_{\\mathrm{eff}})

    where ``G`` is the beam's 2x2 receptance (deflection and slope per force
    and couple) at the cart. With ``J = 0`` it is the classical
    ``M omega^2 G_ww(omega) = 1``, equivalent to the closed form
    ``(M beta / 2 mu) [sin(beta a) sin(beta b) / sin(beta l) -
    sinh(beta a) sinh(beta b) / sinh(beta l)] = 1``. The smallest root is
    bracketed in ``(0, min(f_bare, f_massless)]`` where it is unique, and
    refined by Brent's method to machine precision. Limits: a massless cart or
    a cart at a support give the bare beam's frequency; a massless beam gives
    the cart on the massless beam.

    Parameters
    ----------
    beam : SimplySupportedBeam
        The beam and cart.
    position : float or array_like
        The cart's distance from the left support [m], within ``[0, span]``.
    modes : int, optional
        Modes in the dynamic remainder of the receptance [-].

    Returns
    -------
    float or numpy.ndarray
        The lowest natural frequency [Hz], shaped like ``position``.
    """
    a = _positions(beam, position)
    omega_sq = np.array(
        [_exact_angular_frequency_squared(beam, float(x), modes) for x in a.ravel()]
    ).reshape(a.shape)
    return _shape_out(np.sqrt(omega_sq) / TWO_PI, position)


def _hermite_matrices(length: float, bending_stiffness: float, mass_per_length: float):
    h = length
    stiffness = (bending_stiffness / h**3) * np.array(
        [
            [12.0, 6 * h, -12.0, 6 * h],
            [6 * h, 4 * h * h, -6 * h, 2 * h * h],
            [-12.0, -6 * h, 12.0, -6 * h],
            [6 * h, 2 * h * h, -6 * h, 4 * h * h],
        ]
    )
    mass = (mass_per_length * h / 420.0) * np.array(
        [
            [156.0, 22 * h, 54.0, -13 * h],
            [22 * h, 4 * h * h, 13 * h, -3 * h * h],
            [54.0, 13 * h, 156.0, -22 * h],
            [-13 * h, -3 * h * h, -22 * h, 4 * h * h],
        ]
    )
    return stiffness, mass


def _finite_element_single(beam: SimplySupportedBeam, a: float, elements: int) -> float:
    span = beam.span
    left = min(max(int(round(elements * a / span)), 1), elements - 1)
    if NODE_AT_LOAD_FROM_SUPPORT * span <= a <= (1.0 - NODE_AT_LOAD_FROM_SUPPORT) * span:
        nodes = np.concatenate(
            [np.linspace(0.0, a, left + 1), np.linspace(a, span, elements - left + 1)[1:]]
        )
    else:  # load practically on a support: keep the mesh uniform, interpolate the load
        nodes = np.linspace(0.0, span, elements + 1)
    count = nodes.size
    stiffness = np.zeros((2 * count, 2 * count))
    mass = np.zeros_like(stiffness)
    for e in range(count - 1):
        k_e, m_e = _hermite_matrices(
            nodes[e + 1] - nodes[e], beam.bending_stiffness, beam.mass_per_length
        )
        block = slice(2 * e, 2 * e + 4)
        stiffness[block, block] += k_e
        mass[block, block] += m_e
    # The load enters through the element's shape functions at its position, which
    # is exact when ``a`` is a node (the usual case) and consistent otherwise.
    e = min(int(np.searchsorted(nodes, a, side="right")) - 1, count - 2)
    h = nodes[e + 1] - nodes[e]
    t = (a - nodes[e]) / h
    shape = np.array(
        [1 - 3 * t**2 + 2 * t**3, h * (t - 2 * t**2 + t**3), 3 * t**2 - 2 * t**3, h * (t**3 - t**2)]
    )
    slope = (
        np.array(
            [6 * t**2 - 6 * t, h * (1 - 4 * t + 3 * t**2), 6 * t - 6 * t**2, h * (3 * t**2 - 2 * t)]
        )
        / h
    )
    block = slice(2 * e, 2 * e + 4)
    mass[block, block] += beam.load_mass * np.outer(shape, shape)
    mass[block, block] += beam.effective_rotary_inertia * np.outer(slope, slope)
    free = np.array([i for i in range(2 * count) if i not in (0, 2 * count - 2)])
    stiffness = stiffness[np.ix_(free, free)]
    mass = mass[np.ix_(free, free)]
    # K phi = omega^2 M phi  <=>  M phi = (1/omega^2) K phi; K is positive definite
    # after the supports are fixed, M may be singular (massless beam).
    top = free.size - 1
    largest = float(eigh(mass, stiffness, eigvals_only=True, subset_by_index=[top, top])[0])
    return math.inf if largest <= 0 else 1.0 / (TWO_PI * math.sqrt(largest))


def finite_element_frequency(
    beam: SimplySupportedBeam, position, *, elements: int = 32
) -> np.ndarray | float:
    """Lowest vertical frequency from a finite-element model [Hz].

    The beam is meshed with ``elements`` Hermite cubic (Euler-Bernoulli)
    elements with consistent mass matrices and a node at the cart (unless the
    cart is closer to a support than :data:`NODE_AT_LOAD_FROM_SUPPORT` times
    the span, when it is interpolated within the end element); the cart adds
    ``M`` to the deflection and ``J_eff`` to the slope there. Pinned supports fix the
    deflection only. The generalized eigenproblem ``K phi = omega^2 M phi`` is
    solved for its lowest eigenvalue. As ``elements`` grows the result
    converges from above to :func:`exact_frequency` (error about
    ``elements^-4``).

    Parameters
    ----------
    beam : SimplySupportedBeam
        The beam and cart.
    position : float or array_like
        The cart's distance from the left support [m].
    elements : int, optional
        Number of beam elements [-], at least 2.

    Returns
    -------
    float or numpy.ndarray
        The lowest natural frequency [Hz], shaped like ``position``.
    """
    if elements < 2:
        raise ValueError("elements must be at least 2")
    a = _positions(beam, position)
    values = np.array([_finite_element_single(beam, float(x), elements) for x in a.ravel()])
    return _shape_out(values.reshape(a.shape), position)


@dataclass(frozen=True)
class FrequencySweep:
    """Lowest vertical frequency of the bridge against the cart's position (Fig. 9).

    Parameters
    ----------
    beam : SimplySupportedBeam
        The beam and cart the sweep is for.
    position : numpy.ndarray
        The cart's distance from the left support [m], increasing.
    dunkerley : numpy.ndarray
        Dunkerley's estimate at each position [Hz] (paper eqs. 1-4).
    exact : numpy.ndarray
        The exact fundamental frequency at each position [Hz].
    bare_beam : float
        The bare beam's first frequency [Hz] (paper eq. 2).
    spring_mass : numpy.ndarray
        The cart on the massless beam at each position [Hz] (paper eq. 4).
    """

    beam: SimplySupportedBeam
    position: np.ndarray
    dunkerley: np.ndarray
    exact: np.ndarray
    bare_beam: float
    spring_mass: np.ndarray

    @property
    def shortfall(self) -> np.ndarray:
        """How far Dunkerley's estimate is below the exact value, ``1 - f_D / f`` [-]."""
        return 1.0 - self.dunkerley / self.exact

    def within(self, parking: tuple[float, float]) -> np.ndarray:
        """Mask of the positions inside the closed range ``parking`` [m]."""
        low, high = parking
        tolerance = 1e-9 * self.beam.span
        return (self.position >= low - tolerance) & (self.position <= high + tolerance)

    def frequency_range(
        self, parking: tuple[float, float] | None = None, *, method: str = "dunkerley"
    ) -> tuple[float, float]:
        """Lowest and highest frequency [Hz] over ``parking`` [m] (all positions if None)."""
        values = {"dunkerley": self.dunkerley, "exact": self.exact}[method]
        mask = np.ones(self.position.shape, bool) if parking is None else self.within(parking)
        if not mask.any():
            raise ValueError("no position of the sweep lies in the parking range")
        return float(values[mask].min()), float(values[mask].max())


def frequency_sweep(
    beam: SimplySupportedBeam,
    positions=None,
    *,
    points: int = 99,
    parking: tuple[float, float] | None = None,
) -> FrequencySweep:
    """Evaluate Dunkerley's and the exact frequency over cart positions.

    Parameters
    ----------
    beam : SimplySupportedBeam
        The beam and cart.
    positions : array_like, optional
        Cart positions [m]; default ``points`` equally spaced over the span.
        The ends of ``parking`` and mid-span are added when given, so that the
        extreme parking frequencies are in the sweep.
    points : int, optional
        Number of positions when ``positions`` is not given [-].
    parking : tuple of float, optional
        The range of the cart's centre [m], added to the positions.

    Returns
    -------
    FrequencySweep
        Frequencies at the sorted, de-duplicated positions.
    """
    if positions is None:
        if points < 2:
            raise ValueError("points must be at least 2")
        positions = np.linspace(0.0, beam.span, points)
    position = _positions(beam, np.atleast_1d(np.asarray(positions, dtype=float)))
    if parking is not None:
        low, high = _positions(beam, np.asarray(parking, dtype=float))
        position = np.concatenate([position, [low, high, 0.5 * (low + high)]])
    position = np.unique(position)
    return FrequencySweep(
        beam=beam,
        position=position,
        dunkerley=np.asarray(dunkerley_frequency(beam, position)),
        exact=np.asarray(exact_frequency(beam, position)),
        bare_beam=bare_beam_frequency(beam),
        spring_mass=np.asarray(spring_mass_frequency(beam, position)),
    )


@dataclass(frozen=True)
class JumpCheck:
    """Whether the parked cart may lose contact with its rails (paper section 6.1).

    At each position the vertical spectral acceleration ``S_a`` at the lowest
    vertical frequency is compared with ``g``; where ``S_a >= g`` the
    bridge's upward acceleration can exceed gravity and the cart may jump.

    Parameters
    ----------
    position : numpy.ndarray
        The cart's positions [m].
    frequency_low, frequency_high : numpy.ndarray
        The frequency band at which the spectrum was read [Hz]; both equal
        the chosen estimate unless ``basis == "band"``.
    spectral_acceleration : numpy.ndarray
        The governing vertical spectral acceleration ``S_a`` [m/s^2].
    ratio : numpy.ndarray
        ``S_a / g`` [-].
    considered : numpy.ndarray
        Positions inside the parking range (all if no range was given).
    at_risk : numpy.ndarray
        Considered positions where ``S_a`` reaches ``g`` (to within
        :data:`REACH_TOLERANCE`).
    gravity : float
        ``g`` [m/s^2].
    basis : str
        Which frequency was used: ``"dunkerley"``, ``"exact"`` or ``"band"``
        (the largest ``S_a`` between the two, the default).
    parking : tuple of float or None
        The parking range [m].
    spectrum_label : str
        The spectrum's label.
    notes : tuple of str
        Anything the reader should know (spectrum direction, extrapolation).
    """

    position: np.ndarray
    frequency_low: np.ndarray
    frequency_high: np.ndarray
    spectral_acceleration: np.ndarray
    ratio: np.ndarray
    considered: np.ndarray
    at_risk: np.ndarray
    gravity: float
    basis: str
    parking: tuple[float, float] | None
    spectrum_label: str = ""
    notes: tuple[str, ...] = field(default=())

    @property
    def margin(self) -> np.ndarray:
        """``g - S_a`` at each position [m/s^2]; negative where the cart may jump."""
        return self.gravity - self.spectral_acceleration

    @property
    def verdict(self) -> np.ndarray:
        """Per position: ``"jump possible"``, ``"contact kept"`` or ``"not parked"``."""
        out = np.where(self.at_risk, "jump possible", "contact kept")
        return np.where(self.considered, out, "not parked")

    @property
    def jump_possible(self) -> bool:
        """True if the cart may jump at some considered position."""
        return bool(self.at_risk.any())

    @property
    def status(self) -> str:
        """``"jump possible"`` or ``"no jump"`` over the considered positions."""
        return "jump possible" if self.jump_possible else "no jump"

    @property
    def positions_at_risk(self) -> np.ndarray:
        """The considered positions where the cart may jump [m]."""
        return self.position[self.at_risk]

    @property
    def minimum_margin(self) -> float:
        """Smallest ``g - S_a`` over the considered positions [m/s^2]."""
        return float(self.margin[self.considered].min())

    @property
    def minimum_margin_position(self) -> float:
        """Position of the smallest margin [m]."""
        index = np.flatnonzero(self.considered)[np.argmin(self.margin[self.considered])]
        return float(self.position[index])

    @property
    def risk_intervals(self) -> tuple[tuple[float, float], ...]:
        """Runs of consecutive at-risk positions as ``(first, last)`` [m]."""
        runs = []
        start = None
        for i, flag in enumerate(self.at_risk):
            if flag and start is None:
                start = i
            if start is not None and (not flag or i == self.at_risk.size - 1):
                end = i if flag else i - 1
                runs.append((float(self.position[start]), float(self.position[end])))
                start = None
        return tuple(runs)


def _band_maximum(spectrum: Spectrum, low: float, high: float) -> float:
    """Largest ``S_a`` [m/s^2] over ``[low, high]`` Hz (log-log segments are monotone)."""
    inside = spectrum.frequency[(spectrum.frequency > low) & (spectrum.frequency < high)]
    candidates = np.concatenate([[low, high], inside])
    return float(np.max(spectrum.acceleration_at(candidates)))


def jump_check(
    sweep: FrequencySweep,
    vertical_spectrum: Spectrum,
    gravity: float = 9.81,
    *,
    parking: tuple[float, float] | None = None,
    basis: str = "band",
) -> JumpCheck:
    """Check whether the parked cart may jump on the bridge (paper section 6.1).

    At each position the vertical spectral acceleration at the lowest
    vertical frequency is compared with gravity:

    .. math:: S_a(f(d)) \\ge g \\;\\Rightarrow\\; \\text{the cart may lose contact}

    Parameters
    ----------
    sweep : FrequencySweep
        Frequencies against position, from :func:`frequency_sweep`.
    vertical_spectrum : Spectrum
        Vertical response spectrum [m/s^2 against Hz], for the damping of the
        bridge (the paper uses 5 %).
    gravity : float, optional
        ``g`` [m/s^2].
    parking : tuple of float, optional
        The range of the cart's centre [m]; positions outside are reported as
        not parked and do not count. All positions count when None.
    basis : {"band", "dunkerley", "exact"}, optional
        The frequency at which to read the spectrum. ``"band"`` (default) takes
        the largest ``S_a`` between Dunkerley's lower bound and the exact
        value, so that the verdict holds wherever in between the real
        bridge's frequency lies; ``"dunkerley"`` is the paper's choice.

    Returns
    -------
    JumpCheck
        Per-position spectral acceleration, ratio to ``g`` and verdict.
    """
    if not (gravity > 0 and math.isfinite(gravity)):
        raise ValueError("gravity must be positive")
    if basis not in ("band", "dunkerley", "exact"):
        raise ValueError("basis must be 'band', 'dunkerley' or 'exact'")
    if basis == "dunkerley":
        low = high = sweep.dunkerley
    elif basis == "exact":
        low = high = sweep.exact
    else:
        low, high = (
            np.minimum(sweep.dunkerley, sweep.exact),
            np.maximum(sweep.dunkerley, sweep.exact),
        )
    acceleration = np.array(
        [_band_maximum(vertical_spectrum, lo, hi) for lo, hi in zip(low, high, strict=True)]
    )
    ratio = acceleration / gravity
    if parking is None:
        considered = np.ones(sweep.position.shape, bool)
    else:
        considered = sweep.within(parking)
        if not considered.any():
            raise ValueError("no position of the sweep lies in the parking range")
    at_risk = considered & (ratio >= 1.0 - REACH_TOLERANCE)
    notes = []
    if vertical_spectrum.direction != "vertical":
        notes.append(
            f"the spectrum is marked {vertical_spectrum.direction!r}, not 'vertical'; "
            "the jump check needs the vertical spectrum"
        )
    used = np.concatenate([low[considered], high[considered]])
    if used.max() > vertical_spectrum.frequency[-1] or used.min() < vertical_spectrum.frequency[0]:
        notes.append(
            "some frequencies lie outside the spectrum's table "
            f"({vertical_spectrum.frequency[0]:g}-{vertical_spectrum.frequency[-1]:g} Hz); "
            "the end values were held"
        )
    return JumpCheck(
        position=sweep.position,
        frequency_low=np.asarray(low, dtype=float),
        frequency_high=np.asarray(high, dtype=float),
        spectral_acceleration=acceleration,
        ratio=ratio,
        considered=considered,
        at_risk=at_risk,
        gravity=float(gravity),
        basis=basis,
        parking=None if parking is None else (float(parking[0]), float(parking[1])),
        spectrum_label=vertical_spectrum.label,
        notes=tuple(notes),
    )
