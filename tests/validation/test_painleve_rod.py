"""Painleve's rod: a slender block sliding on one corner on a rough floor jams.

Sources:
- P. Painleve (1895), "Sur les lois du frottement de glissement", C. R. Acad.
  Sci. Paris 121, 112-115.
- F. Genot and B. Brogliato (1999), "New results on Painleve paradoxes", Eur.
  J. Mech. A/Solids 18, 653-677: while the contact slides with Coulomb
  friction, the gap acceleration is ``a_n = (W_nn - mu s W_nt) N + ...`` with
  ``W_nn = 1/m + r_x^2/I``, ``W_nt = -r_x r_z / I`` (r from the centre to the
  contact, s the sign of the slip); when ``W_nn - mu s W_nt < 0`` no sliding
  mode is consistent, and the rod jams: a tangential impact at velocity level
  (the contact sticks; the impulse dissipates kinetic energy), after which it
  rotates about the stuck corner.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from freestand.core.dynamics.timehistory import simulate
from freestand.core.model import Block, Friction, Sliding, Stack

HALF_WIDTH, HALF_HEIGHT, MASS = 0.02, 1.0, 10.0
INERTIA = MASS * ((2 * HALF_WIDTH) ** 2 + (2 * HALF_HEIGHT) ** 2) / 12.0
TILT = 0.7  # [rad] from the vertical, leaning towards +x on its right corner
SLIP = -2.0  # [m/s] the corner slides towards -x, under the leaning rod


def _lever():
    """(r_x, r_z) [m] from the centre to the right corner, tilted."""
    x, z = HALF_WIDTH, -HALF_HEIGHT
    c, s = math.cos(-TILT), math.sin(-TILT)
    return c * x - s * z, s * x + c * z


def critical_friction():
    """mu above which sliding towards -x is inconsistent: W_nn + mu W_nt = 0 (s = -1)."""
    r_x, r_z = _lever()
    w_nn = 1.0 / MASS + r_x**2 / INERTIA
    w_nt = -r_x * r_z / INERTIA
    return w_nn / -w_nt


def rod(mu):
    block = Block(
        "rod", MASS, INERTIA, (0.0, HALF_HEIGHT), -HALF_WIDTH, HALF_WIDTH, 0.0,
        Friction(mu, mu), Sliding.FREE,
    )  # fmt: skip
    r_x, r_z = _lever()
    # the centre sits above the right corner, which stays where it was, (HALF_WIDTH, 0)
    position = np.array([[HALF_WIDTH - r_x, -r_z - HALF_HEIGHT, -TILT]])
    velocity = np.array([[SLIP, 0.0, 0.0]])
    return simulate(
        Stack("rod", (block,)), lambda t: (0.0, 0.0), 0.2, method="general",
        initial_position=position, initial_velocity=velocity,
    )  # fmt: skip


def kinetic_energy(velocity):
    return 0.5 * MASS * (velocity[0] ** 2 + velocity[1] ** 2) + 0.5 * INERTIA * velocity[2] ** 2


def test_critical_friction_of_the_set_up():
    # the uniform thin rod's value (1 + 3 cos^2 th) / (3 sin th cos th), th from the floor,
    # moved a little by the block's width: within 5 %
    theta = 0.5 * math.pi - TILT
    thin = (1 + 3 * math.cos(theta) ** 2) / (3 * math.sin(theta) * math.cos(theta))
    assert critical_friction() == pytest.approx(thin, rel=0.05)


def test_above_the_critical_friction_the_rod_jams_and_sticks():
    result = rod(1.3 * critical_friction())
    assert result.status == "completed"
    jam = [event for event in result.events if event.kind == "tangential-impact"]
    assert jam and jam[0].time == 0.0
    before = kinetic_energy(jam[0].velocity_before[0])
    after = kinetic_energy(jam[0].velocity_after[0])
    assert after < before  # the impulse dissipates (measured 20 J -> about 9 J)
    assert jam[0].motions == ("rock",)  # it turns about the stuck corner


def test_below_the_critical_friction_the_rod_slides_on():
    result = rod(0.7 * critical_friction())
    assert result.status == "completed"
    assert not [event for event in result.events if event.kind == "tangential-impact"]
