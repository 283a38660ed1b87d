"""Initiation of rest / slide / rock / slide-rock of one block from rest (Shenton 1996).

Source: Shenton, H. W. (1996), "Criteria for initiation of slide, rock, and
slide-rock rigid-body modes", J. Eng. Mech. 122(7), 690-693, as restated in
shared/spec/references.md (derived from Zhang and Makris 2001, eq. 7): with
x = a_h / g and beta = b / h for a homogeneous rectangle of half-width b and
centre height h, static = kinetic friction mu:

- rest if x <= min(mu, beta);
- slide if mu < beta and x > mu;
- rock if mu >= beta, x > beta and mu >= mu_R(x);
- slide-rock if beta < mu < mu_R(x) and x > beta;

mu_R(x) = [x (1 + 4 beta^2) + 3 beta] / [4 + beta^2 + 3 beta x].

The grid keeps 2 % away from every boundary (tolerance of the region test);
on it the general solver must give exactly the region's mode.
"""

from __future__ import annotations

import numpy as np
import pytest

from freestand.core.contact.screening import Motion, initial_motion
from freestand.core.model import Block, Friction, Sliding, Stack

G = 9.81
MARGIN = 0.02  # relative distance kept from region boundaries


def mu_rock(x: float, beta: float) -> float:
    return (x * (1 + 4 * beta**2) + 3 * beta) / (4 + beta**2 + 3 * beta * x)


def shenton_region(x: float, mu: float, beta: float) -> Motion | None:
    """The region of Shenton's criteria, or None within MARGIN of a boundary."""

    def near(a, b):
        return abs(a - b) <= MARGIN * max(abs(b), 1e-3)

    if near(x, mu) or near(x, beta) or near(mu, beta) or near(mu, mu_rock(x, beta)):
        return None
    if x <= min(mu, beta):
        return Motion.REST
    if mu < beta:
        return Motion.SLIDE
    if mu >= mu_rock(x, beta):
        return Motion.ROCK
    return Motion.SLIDE_ROCK


def block(b: float, h: float, mu: float) -> Stack:
    mass = 1000.0
    inertia = mass * (b**2 + h**2) / 3.0  # homogeneous rectangle 2b x 2h about its centre
    return Stack(
        "block",
        (Block("block", mass, inertia, (0.0, h), -b, b, 0.0, Friction(mu, mu), Sliding.FREE),),
    )


CASES = [
    (x, mu, beta)
    for beta in (0.2, 0.5, 1.0)
    for mu in np.linspace(0.05, 1.2, 12)
    for x in np.linspace(0.05, 2.0, 14)
    if shenton_region(x, mu, beta) is not None
]


@pytest.mark.parametrize(("x", "mu", "beta"), CASES)
def test_initial_mode_matches_shenton(x, mu, beta):
    h = 1.0
    case = initial_motion(block(beta * h, h, mu), x * G, 0.0, 1, G)
    assert case.status == "unique"
    assert case.blocks[0].motion is shenton_region(x, mu, beta)


def test_all_four_regions_are_exercised():
    regions = {shenton_region(x, mu, beta) for x, mu, beta in CASES}
    assert regions == {Motion.REST, Motion.SLIDE, Motion.ROCK, Motion.SLIDE_ROCK}


def test_free_flight_when_vertical_reaches_g():
    case = initial_motion(block(0.5, 1.0, 0.3), 3.0, G, 1, G)
    assert case.status == "free-flight"
    assert case.blocks[0].motion is Motion.FREE_FLIGHT
    assert case.blocks[0].base_normal_left == 0.0
