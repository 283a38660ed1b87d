"""The steady rolling disc (issue #18 (d)).

Source: C. Le Saux, R. I. Leine and C. Glocker, Dynamics of a rolling disk in
the presence of dry friction, J. Nonlinear Sci. 15 (2005) 27-61, section 3
(steady motions of the rolling disc; here a thin cylinder of half-height h
rolling on the rim of its base).

Steady motion: the axis e3 keeps its tilt beta from the vertical and precesses
at Omega; omega = Omega e_z + s e3. The contact point P = G + r, r = -h e3 +
R u (u the downhill unit vector of the base plane), does not slip: v_G = r x
omega, horizontal, turning at Omega, so m a_G = F - m g e_z gives the contact
force. The angular momentum L = A omega + (C - A)(omega . e3) e3 about G turns
with the precession: Omega e_z x L = r x F. In the plane of e3 and e_z, with
r = (r_x, r_z), this is linear in the spin s:

    s = (-m g r_x + m Omega^2 r_x r_z - Omega^2 (C - A) sin(beta) cos(beta))
        / (Omega (C sin(beta) + m r_z^2 sin(beta) - m r_x r_z cos(beta)))

Started there, the exact motion keeps its tilt and its energy for ever: the
engine's rolling rim point (the contact point moving round the rim, its extra
acceleration terms) must too.
"""

from __future__ import annotations

import math

import numpy as np

from freestand.core.body import Body, Cylinder
from freestand.core.contact.body_kernel import body_parameters, energy
from freestand.core.dynamics.body_history import SupportMotion3, simulate_body
from freestand.core.model import Friction

RADIUS, HEIGHT, MASS, G = 0.5, 0.05, 10.0, 9.81
TILT, PRECESSION = 1.2, 3.0  # [rad] axis from the vertical, [rad/s]


def steady_rolling_state() -> np.ndarray:
    """The state (13,) of the steady rolling of the thin cylinder (module docstring)."""
    a = MASS * (3.0 * RADIUS**2 + HEIGHT**2) / 12.0
    c = MASS * RADIUS**2 / 2.0
    h = HEIGHT / 2.0
    sb, cb = math.sin(TILT), math.cos(TILT)
    rx, rz = -h * sb + RADIUS * cb, -h * cb - RADIUS * sb
    om = PRECESSION
    spin = (-MASS * G * rx + MASS * om**2 * rx * rz - om**2 * (c - a) * sb * cb) / (
        om * (c * sb + MASS * rz**2 * sb - MASS * rx * rz * cb)
    )
    speed = rz * spin * sb - rx * (om + spin * cb)
    state = np.zeros(13)
    state[2] = h * cb + RADIUS * sb  # the lowest rim point on the support
    state[3], state[5] = math.cos(TILT / 2.0), math.sin(TILT / 2.0)  # turned about y
    state[8] = speed
    state[10], state[12] = spin * sb, om + spin * cb
    return state


def test_the_steady_rolling_disc_keeps_its_tilt_and_energy_over_ten_turns():
    body = Body("disc", Cylinder(RADIUS, HEIGHT), MASS, Friction(2.0, 2.0))
    duration = 10.0 * 2.0 * math.pi / PRECESSION
    still = SupportMotion3(0.01, np.zeros(int(duration / 0.01) + 10))
    result = simulate_body(body, still, duration, initial=steady_rolling_state(), max_step=5e-3)
    assert result.status == "completed"
    # rolling on its rim throughout: no lift-off, impact, slip or remedy
    assert [event[1] for event in result.events] == ["start"]
    # tolerance 1e-6 rad: RK4 at 5 ms steps, measured 3.4e-7 (4.0e-8 at 2.5 ms,
    # 8.3e-10 at 1.25 ms: third to fifth order, so the steady motion is the engine's;
    # projected at every step, as before its drift gate, 1.6e-7, 1.0e-8, 6.4e-10)
    assert np.abs(result.tilt - TILT).max() <= 1e-6
    parameters = body_parameters(body, G)
    values = np.array([energy(parameters, state) for state in result.state])
    # energy: rolling without slip does no work; measured 4.9e-9 relative (1.9e-9 projected
    # at every step)
    assert np.abs(values / values[0] - 1.0).max() <= 1e-8
