"""A point's slip rate in closed form against its solve (#18: the onset's scan without solves).

The slip from rest of one point (a box's corner, a cylinder's rim point) is
searched on the circle of friction directions u: f(theta) = u_perp . s'(u)
changes sign where the slip rate is parallel to u
(``body_modes._onset_on_circle``). ``body_modes.point_slip_terms`` writes
s'(u) = (c + K u) / D(u) from the point's Delassus matrix, which the scan
evaluates at no solve; here it must equal the rate the mode's solve gives
(``body_modes._onset_rate``, one held normal row with ``-mu N u``), at the
acceleration and the velocity level, for any state: an identity of the
solve's linear algebra, so to round-off (1e-9 of the rate's scale).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from freestand.core.body import Body, Box, Cylinder
from freestand.core.contact import body_kernel, body_modes
from freestand.core.model import Friction

BODIES = (
    Body("cabinet", Box((1.0, 0.6, 2.0)), 400.0, Friction(0.5, 0.5)),
    Body("slender cylinder", Cylinder(0.4, 3.0), 2000.0, Friction(0.7, 0.6)),
)
RECORD = np.array([[1.5, -2.0], [0.8, 2.5], [1.0, -0.5]])  # a_x, a_y, a_v at t = 0, 1 s


def _state(rng: np.random.Generator) -> np.ndarray:
    y = np.zeros(body_kernel.STATE_SIZE)
    y[0:3] = rng.normal(0.0, 0.3, 3) + (0.0, 0.0, 1.0)
    q = np.array([1.0, 0.0, 0.0, 0.0]) + rng.normal(0.0, 0.2, 4)
    y[3:7] = q / np.linalg.norm(q)
    y[7:13] = rng.normal(0.0, 0.5, 6)
    return y


def _prepared(seed: int, body: Body, level: int):
    rng = np.random.default_rng(seed)
    par = body_kernel.body_parameters(body, 9.81, 1.0)
    y = _state(rng)
    sc = body_kernel.new_scratch()
    index, psi = int(rng.integers(4)), float(rng.uniform(-math.pi, math.pi))
    body_kernel.prepare(par, RECORD, 1.0, 0.4, y, body_kernel.POINT, index, psi, sc)
    if level == body_modes.VELOCITY:
        sc[body_kernel.SC_BASE][:] = y[7:13]  # the velocity before, as body_modes.impact
    return par, y, sc, rng


@given(
    seed=st.integers(0, 2**32 - 1),
    shape=st.sampled_from((0, 1)),
    level=st.sampled_from((body_modes.ACCELERATION, body_modes.VELOCITY)),
)
def test_the_closed_form_is_the_solve(seed, shape, level):
    par, y, sc, rng = _prepared(seed, BODIES[shape], level)
    body_modes.point_slip_terms(par, sc, level)
    terms = sc[body_kernel.SC_ONSET].copy()
    mu = par[body_kernel.P_MU_KINETIC]
    direction = np.zeros(3)
    for theta in rng.uniform(-math.pi, math.pi, 6):
        direction[:2] = math.cos(theta), math.sin(theta)
        *_, size = body_modes._onset_rate(par, y, sc, level, 1, 2, direction, False)
        if size < 0.0:  # singular: D(u) = 0, a measure-zero event for random states
            continue
        rate = sc[body_kernel.SC_SACC]
        solved = direction[0] * rate[1] - direction[1] * rate[0]
        closed = body_modes.point_slip_sign(terms, mu, theta)
        # round-off of the 1 x 1 system and the rows' products, on the rate's own scale
        assert abs(closed - solved) <= 1e-9 * max(size, 1e-12)


@pytest.mark.parametrize("search", ["scan", "fixed point first"])
def test_an_onset_found_on_the_closed_form_is_consistent(search):
    """The onset found on the closed form is confirmed by the solve: s'(u) = kappa u, kappa >= 0.

    ``scan``: the circle's scan and roots alone; ``fixed point first``: the
    whole search of a point (``_slip_onset``: the fixed-point iteration, then
    the scan where it does not settle).
    """
    found = 0
    for seed in range(40):
        level = (body_modes.ACCELERATION, body_modes.VELOCITY)[seed % 2]
        par, y, sc, _ = _prepared(seed, BODIES[(seed // 2) % 2], level)
        start, direction = np.array([1.0, 0.0, 0.0]), np.zeros(3)
        if search == "scan":
            body_modes.point_slip_terms(par, sc, level)  # the scan reads them from the scratch
            ok = body_modes._onset_on_circle(par, y, sc, level, 1, start, direction, 1e-9)
        else:
            ok = body_modes._slip_onset(par, y, sc, level, 1, 2, start, direction, 1e-9)
        if not ok:
            continue
        found += 1
        kept = sc[body_kernel.SC_SACC][:2].copy()  # the search's own solve at its onset
        along, across, size = body_modes._onset_rate(par, y, sc, level, 1, 2, direction, False)
        assert np.array_equal(kept, sc[body_kernel.SC_SACC][:2])  # the scratch holds it
        assert along >= -1e-9 and across <= 1e-9 + 1e-10 * size
        assert abs(math.hypot(direction[0], direction[1]) - 1.0) < 1e-15
    assert found >= 10  # most random states have a consistent onset of a point
