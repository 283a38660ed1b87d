"""A cylinder landing flat while it slides turns about the rim point its impact law finds (#18).

The instant comes from a random sample of the rotation-invariance check (a
hollow cylinder R 0.84 m, inner 0.38 m, H 5.5 m, 16.6 t, mu 0.32 / 0.24,
under two horizontal components and the vertical at about 0.5 g): the base
lands flat while the body slides at 2.4 cm/s and rocks by micro-radians.
Neither the base (its impulse's centre of pressure would lie off the base)
nor a rim point sticking is admissible; the body turns, slipping, about the
rim point whose normal velocity after the impact is lowest. The impact
law's pivot search was made for a stick impact only, and within 0.8 rad of
the point opposite the one it landed from: it found no candidate, and such
landings (274 in the 10 s run) went to the remedy's velocity-level impact
at eight rim points, which splits the impulse between the two points either
side of the true pivot.

The velocity after is checked against the laws on the continuous rim
(Moreau 1988; Glocker 2001): one impulse at the pivot, pushing, on the
circular cone's edge and opposite the pivot's slip after; no rim point
approaching the support after; no kinetic energy gained.
"""

from __future__ import annotations

import math

import numpy as np

from freestand.core.body import Body, Cylinder
from freestand.core.contact.body_impulse import kinetic_energy
from freestand.core.contact.body_kernel import (
    D_PSI,
    DATA_SIZE,
    FREE,
    M_KIND,
    M_SLIP,
    P_MASS,
    POINT,
    SC_INV,
    SC_ROT,
    arm,
    body_parameters,
    new_scratch,
    point_velocity,
    prepare,
)
from freestand.core.contact.body_modes import NONE_ADMISSIBLE, impact
from freestand.core.model import Friction

BODY = Body(
    "hollow cylinder",
    Cylinder(0.8433320403469565, 5.539191634657821, 0.384093396691132),
    16641.291271478614,
    Friction(0.3230732444636384, 0.23801952832983958),
)
# flat on the support (a pure yaw), G at its height; v [m/s], omega [rad/s] in the support frame
STATE = np.array([-0.1020145842284186, -0.042190956263099495, 2.7695958173289106,
                  0.9999816738918658, 0.0, 0.0, -0.006054079651138458,
                  0.02364882307850583, -0.0008184195583027247, -0.0004664154116550195,
                  -0.0006171357124588135, -0.00042570574883902244,
                  -0.0008404908522253935])  # fmt: skip
PSI_BEFORE = -0.21368025082243253  # [rad] the rim point it rocked on before landing
GAP_TOLERANCE = 1e-7  # [m] the engine's default


def _landing():
    par = body_parameters(BODY, 9.81)
    sc = new_scratch()
    # the instant's rotation and inverse inertia (the record plays no part at the velocity level)
    prepare(par, np.zeros((3, 2)), 1.0, 0.0, STATE, FREE, 0, 0.0, sc)
    mode = np.zeros(3, dtype=np.int64)
    data = np.zeros(DATA_SIZE)
    after = np.zeros(6)
    chosen = impact(par, STATE, sc, GAP_TOLERANCE, PSI_BEFORE, mode, data, after)
    return par, sc, chosen, mode, data, after


def _rim_arm(par, rot, angle):
    d = np.empty(3)
    radius = BODY.shape.radius
    arm(par, rot, radius * math.cos(angle), radius * math.sin(angle), 0.0, d)
    return d


def test_a_sliding_flat_landing_turns_about_its_lowest_moving_rim_point():
    par, sc, chosen, mode, data, after = _landing()
    assert chosen != NONE_ADMISSIBLE  # the remedy's eight points before
    assert (mode[M_KIND], mode[M_SLIP]) == (POINT, 1)  # on a rim point, slipping
    rot = np.array(sc[SC_ROT])
    moved = STATE.copy()
    moved[7:13] = after
    speed = np.linalg.norm(STATE[7:10]) + BODY.shape.radius * np.linalg.norm(STATE[10:13])
    tolerance = 1e-9 * speed  # the impact law's, RELATIVE_TOLERANCE of the speed [m/s]
    # the rim's normal velocity after: zero at the pivot, its minimum, nowhere approaching
    pivot = data[D_PSI]
    angles = pivot + np.linspace(-math.pi, math.pi, 3601)
    normal = np.array([point_velocity(moved, _rim_arm(par, rot, a), 0.0, 0.0, 1.0) for a in angles])
    assert abs(point_velocity(moved, _rim_arm(par, rot, pivot), 0.0, 0.0, 1.0)) <= tolerance
    assert np.min(normal) >= -tolerance
    assert abs(angles[np.argmin(normal)] - pivot) <= 2e-3  # [rad] the sampling's spacing
    assert np.ptp(normal) > 1e3 * tolerance  # the body does turn about it


def test_the_impulse_acts_at_the_pivot_pushing_and_opposite_its_slip():
    par, sc, chosen, mode, data, after = _landing()
    rot = np.array(sc[SC_ROT])
    mass = par[P_MASS]
    impulse = mass * (after[:3] - STATE[7:10])  # [N s]
    d = _rim_arm(par, rot, data[D_PSI])
    # the angular momentum about G changes by the moment of that one impulse at the pivot
    inertia = np.linalg.inv(np.array(sc[SC_INV]))
    change = inertia @ (after[3:] - STATE[10:13])
    assert np.allclose(change, np.cross(d, impulse), rtol=0.0, atol=1e-9 * np.linalg.norm(change))
    assert impulse[2] > 0.0
    moved = STATE.copy()
    moved[7:13] = after
    slip = np.array([point_velocity(moved, d, 1.0, 0.0, 0.0),
                     point_velocity(moved, d, 0.0, 1.0, 0.0)])  # fmt: skip
    assert np.linalg.norm(slip) > 1e-3  # [m/s] it slides on
    mu = BODY.friction.kinetic
    opposite = -mu * impulse[2] * slip / np.linalg.norm(slip)  # Coulomb: the cone's edge
    assert np.allclose(impulse[:2], opposite, rtol=0.0, atol=1e-7 * impulse[2])
    inv = np.array(sc[SC_INV])
    assert kinetic_energy(par, inv, after) <= kinetic_energy(par, inv, STATE[7:13])
