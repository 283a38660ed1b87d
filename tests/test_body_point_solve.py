"""A sticking POINT's closed-form solve against the general one on its rows (#18).

``solve_mode`` solves a sticking POINT (a cylinder's rim point rolling, a
box's corner held) from the point's Delassus matrix
(``body_kernel.solve_sticking_point``) rather than on its rows in general
(``solve_held_rows``). The two must agree to round-off for any body, state
and load, at the acceleration level and at the velocity level (an impact).
"""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from freestand.core.body import Body, Box, Cylinder
from freestand.core.contact import body_kernel as bk
from freestand.core.model import Friction

G = 9.81
BODIES = (
    Body("box", Box((1.0, 0.6, 2.0)), 400.0, Friction(0.5, 0.5)),
    Body("off-centre box", Box((0.4, 1.3, 0.8)), 25.0, Friction(0.9, 0.7), (0.05, -0.2, 0.3)),
    Body("cylinder", Cylinder(0.4, 3.0), 2000.0, Friction(0.5, 0.5)),
    Body("hollow cask", Cylinder(1.7, 6.0, 1.2), 1.8e5, Friction(0.3, 0.3)),
)


@settings(max_examples=200, deadline=None)
@given(
    st.integers(0, len(BODIES) - 1), st.integers(0, 3), st.integers(0, 2**32 - 1),
    st.booleans(),
)  # fmt: skip
def test_a_sticking_point_is_solved_as_on_its_rows(which, corner, seed, acceleration):
    body = BODIES[which]
    par = bk.body_parameters(body, G)
    rng = np.random.default_rng(seed)
    y = np.zeros(bk.STATE_SIZE)
    quaternion = rng.normal(size=4)
    y[3:7] = quaternion / np.linalg.norm(quaternion)
    y[7:10] = rng.normal(size=3)
    y[10:13] = rng.normal(size=3) * 3.0
    record = rng.normal(size=(3, 2)) * 5.0  # a support acceleration [m/s^2]
    psi = float(rng.uniform(-np.pi, np.pi))  # a cylinder's rim point
    sc = bk.new_scratch()
    bk.prepare(par, record, 1.0, 0.5, y, bk.POINT, corner, psi, sc)
    # the acceleration level from M^-1 f_0, the velocity level from the velocity before
    base = sc[bk.SC_BASE].copy() if acceleration else y[7:13].copy()
    results = []
    for closed in (True, False):
        acc, lam = np.zeros(6), np.zeros(6)
        if closed:
            ok = bk.solve_sticking_point(par, sc, base, acceleration, acc, lam)
        else:
            ok = bk.solve_held_rows(par, sc, base, acceleration, 0, np.zeros(3), 1, 2, acc, lam)
        assert ok
        results.append((acc, lam[:3]))
    (acc, lam), (acc_rows, lam_rows) = results
    # tolerance: round-off of the two orders of the same products, relative to the largest
    # term (the accelerations or velocities, the forces or impulses)
    scale = np.max(np.abs(acc_rows)) + np.max(np.abs(base)) + G
    np.testing.assert_allclose(acc, acc_rows, rtol=0.0, atol=1e-12 * scale)
    np.testing.assert_allclose(lam, lam_rows, rtol=0.0, atol=1e-12 * np.max(np.abs(lam_rows)))
    # the held rows: the point's acceleration (or velocity after) is zero along z, x and y
    rows = np.column_stack([sc[bk.SC_NORMAL][:, 0], sc[bk.SC_TANGENT][:, :2]])
    bias = np.array([sc[bk.SC_NBIAS][0], *sc[bk.SC_TBIAS][:2]]) if acceleration else 0.0
    np.testing.assert_allclose(rows.T @ acc + bias, 0.0, atol=1e-11 * scale)
