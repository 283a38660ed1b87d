"""A rigid body in 3-D on the flat support: box or cylinder (issue #18).

Frames and signs (``docs/nomenclature.md``): x, y horizontal, z up; the body
frame has its origin at the centre of the base, z along the body's axis, and
coincides with the support frame at rest. Lengths [m], mass [kg], inertia
[kg m^2] about the centre of gravity in the body frame.

Homogeneous inertia about the centre of a box of sides l_x, l_y, l_z::

    I_xx = m (l_y^2 + l_z^2) / 12,  I_yy = m (l_x^2 + l_z^2) / 12,  I_zz = m (l_x^2 + l_y^2) / 12

and of a cylinder of radius R, height H (hollow: inner radius r, R^2 -> R^2 + r^2)::

    I_zz = m R^2 / 2,  I_xx = I_yy = m (3 R^2 + H^2) / 12

(e.g. Meriam and Kraige, *Engineering Mechanics: Dynamics*, Appendix D).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from freestand.core.model import Friction
from freestand.errors import FreestandError


def _positive(value: float, name: str) -> float:
    value = float(value)
    if not (math.isfinite(value) and value > 0.0):
        raise FreestandError(f"{name} must be a positive length or mass, not {value!r}")
    return value


@dataclass(frozen=True)
class Box:
    """A box of sides ``size = (l_x, l_y, l_z)`` [m]; its base is |x| <= l_x/2, |y| <= l_y/2."""

    size: tuple[float, float, float]

    def __post_init__(self) -> None:
        if len(self.size) != 3:
            raise FreestandError(f"size must be [lx, ly, lz] in m, not {self.size!r}")
        sides = tuple(_positive(s, f"size[{k}]") for k, s in enumerate(self.size))
        object.__setattr__(self, "size", sides)

    @property
    def height(self) -> float:
        """Height l_z [m]."""
        return self.size[2]

    def unit_inertia(self) -> np.ndarray:
        """Principal inertia per unit mass about the centre [m^2], (3,)."""
        lx, ly, lz = self.size
        return np.array([ly**2 + lz**2, lx**2 + lz**2, lx**2 + ly**2]) / 12.0

    def base_corners(self) -> np.ndarray:
        """The four base corners in the body frame [m], (4, 3), counter-clockwise from (+, +)."""
        bx, by = 0.5 * self.size[0], 0.5 * self.size[1]
        return np.array([[bx, by, 0.0], [-bx, by, 0.0], [-bx, -by, 0.0], [bx, -by, 0.0]])


@dataclass(frozen=True)
class Cylinder:
    """A cylinder of ``radius`` R and ``height`` H [m], solid or hollow (``inner_radius`` r < R)."""

    radius: float
    height: float
    inner_radius: float = 0.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "radius", _positive(self.radius, "radius"))
        object.__setattr__(self, "height", _positive(self.height, "height"))
        inner = float(self.inner_radius)
        if not (math.isfinite(inner) and 0.0 <= inner < self.radius):
            raise FreestandError(
                f"inner_radius must be at least 0 and below the radius {self.radius:g} m, "
                f"not {inner!r}"
            )
        object.__setattr__(self, "inner_radius", inner)

    def unit_inertia(self) -> np.ndarray:
        """Principal inertia per unit mass about the centre [m^2], (3,)."""
        radii = self.radius**2 + self.inner_radius**2
        transverse = (3.0 * radii + self.height**2) / 12.0
        return np.array([transverse, transverse, 0.5 * radii])


Shape = Box | Cylinder


def _inertia_matrix(value, mass: float, shape: Shape) -> np.ndarray:
    """The body-frame inertia [kg m^2], checked, as a read-only copy (a body is immutable)."""
    if value is None:
        matrix = np.diag(mass * shape.unit_inertia())
        matrix.flags.writeable = False
        return matrix
    matrix = np.array(value, dtype=float)
    if matrix.shape == (3,):
        matrix = np.diag(matrix)
    if matrix.shape != (3, 3) or not np.isfinite(matrix).all():
        raise FreestandError(
            "inertia must be 3 principal values or a 3x3 matrix in kg m^2, "
            f"not {np.asarray(value).tolist()!r}"
        )
    if not np.allclose(matrix, matrix.T, rtol=1e-9, atol=0.0):
        raise FreestandError(f"inertia must be symmetric, not {matrix.tolist()!r}")
    if np.linalg.eigvalsh(matrix).min() <= 0.0:
        raise FreestandError(f"inertia must be positive definite, not {matrix.tolist()!r}")
    matrix.flags.writeable = False
    return matrix


@dataclass(frozen=True)
class Body:
    """A rigid body standing on the support.

    Parameters
    ----------
    name : str
        Name.
    shape : Box or Cylinder
        Geometry; the base is the shape's lower face at z = 0.
    mass : float
        m [kg].
    friction : Friction
        Coulomb friction on the support (static mu_0, kinetic mu).
    centre : tuple of float, optional
        Centre of gravity in the body frame [m]; default the geometric centre
        (0, 0, H/2). It must lie over the base (inside its outline) and above it.
    inertia : array_like, optional
        About the centre of gravity, body frame [kg m^2]: three principal
        values or a symmetric positive definite 3x3 matrix; default the
        homogeneous body's. Kept as a read-only 3x3 copy: a body does not
        change (the 3-D kernel's parameters are kept on it,
        :func:`~freestand.core.contact.body_kernel.body_parameters`).
    """

    name: str
    shape: Shape
    mass: float
    friction: Friction
    centre: tuple[float, float, float] | None = None
    inertia: np.ndarray | None = field(default=None, compare=False)

    def __post_init__(self) -> None:
        mass = _positive(self.mass, "mass")
        object.__setattr__(self, "mass", mass)
        height = self.shape.height
        centre = (0.0, 0.0, 0.5 * height) if self.centre is None else tuple(map(float, self.centre))
        if len(centre) != 3 or not all(math.isfinite(c) for c in centre):
            raise FreestandError(f"centre must be [x, y, z] in m, not {self.centre!r}")
        if not 0.0 < centre[2]:
            raise FreestandError(f"centre z must be above the base (z > 0), not {centre[2]!r} m")
        if base_ray_distance(self.shape, centre[:2], (1.0, 0.0)) <= 0.0:
            raise FreestandError(f"centre {list(centre)} m must lie over the base")
        object.__setattr__(self, "centre", centre)
        object.__setattr__(self, "inertia", _inertia_matrix(self.inertia, mass, self.shape))

    @property
    def centre_height(self) -> float:
        """Height h of the centre of gravity above the base [m]."""
        return self.centre[2]


@dataclass(frozen=True)
class BodyConfiguration:
    """A 3-D configuration: rigid bodies on the support (a model file's 3-D configuration).

    A model-file ``[[configuration]]`` whose block has a ``shape`` loads as
    one of these (:func:`freestand.io.model_file.load_model`); the planar
    configurations load as :class:`freestand.core.model.Stack`. The bodies
    are a tuple so that stacks of bodies can follow; today a configuration
    holds exactly one body, standing on the support.

    Parameters
    ----------
    name : str
        Configuration name.
    bodies : tuple of Body
        Bottom to top; one body for now.

    Raises
    ------
    FreestandError
        Not exactly one body.
    """

    name: str
    bodies: tuple[Body, ...]

    def __post_init__(self) -> None:
        bodies = tuple(self.bodies)
        if len(bodies) != 1:
            raise FreestandError(
                f"configuration {self.name!r} has {len(bodies)} 3-D bodies; stacks of 3-D "
                "bodies are not supported yet: give one body per configuration"
            )
        object.__setattr__(self, "bodies", bodies)

    @property
    def body(self) -> Body:
        """The body standing on the support."""
        return self.bodies[0]


def base_ray_distance(shape: Shape, origin, direction) -> float:
    """Distance [m] from ``origin`` (x, y) along the unit ``direction`` to the base's outline.

    Negative or zero when the origin is not inside the base. Box: the ray leaves
    |x| <= b_x, |y| <= b_y at ``min((b_x - s_x o_x)/|w_x|, (b_y - s_y o_y)/|w_y|)``
    (s the signs of w); disc of radius R: ``-o.w + sqrt((o.w)^2 - |o|^2 + R^2)``.
    """
    ox, oy = float(origin[0]), float(origin[1])
    wx, wy = float(direction[0]), float(direction[1])
    if isinstance(shape, Box):
        bx, by = 0.5 * shape.size[0], 0.5 * shape.size[1]
        if abs(ox) >= bx or abs(oy) >= by:
            return 0.0
        distances = []
        if abs(wx) > 0.0:
            distances.append((bx - math.copysign(1.0, wx) * ox) / abs(wx))
        if abs(wy) > 0.0:
            distances.append((by - math.copysign(1.0, wy) * oy) / abs(wy))
        return min(distances)
    radius = shape.radius
    reach = ox * wx + oy * wy
    inside = reach**2 - (ox**2 + oy**2) + radius**2
    if ox**2 + oy**2 >= radius**2:
        return 0.0
    return -reach + math.sqrt(inside)


def tipping_tilt(body: Body, directions) -> np.ndarray:
    """Tilt [rad] at which the centre of gravity stands over the pivot, per tilt direction.

    A body tilted by theta towards the horizontal unit vector u (its axis's
    horizontal projection; no twist) pivots on the base points farthest along
    u, at the support function ``s(u) = max_c c . u`` (box ``b_x |u_x| +
    b_y |u_y|``, disc R). Its centre of gravity G = (g, h) is over them when
    ``(s(u) - g . u) cos theta = h sin theta``:

        theta*(u) = atan((s(u) - g . u) / h),

    beyond which the weight turns it over (Housner 1963's slenderness alpha
    in a plane, a corner's ``atan(sqrt(b_x^2 + b_y^2)/h)`` on the diagonal).

    Parameters
    ----------
    body : Body
        The body.
    directions : array_like
        Angles psi [rad] of the tilt directions u = (cos psi, sin psi).

    Returns
    -------
    numpy.ndarray
        theta* [rad] per direction.
    """
    psi = np.asarray(directions, dtype=float)
    ux, uy = np.cos(psi), np.sin(psi)
    if isinstance(body.shape, Box):
        reach = 0.5 * (body.shape.size[0] * np.abs(ux) + body.shape.size[1] * np.abs(uy))
    else:
        reach = np.full_like(psi, body.shape.radius)
    offset = body.centre[0] * ux + body.centre[1] * uy
    return np.arctan((reach - offset) / body.centre[2])
