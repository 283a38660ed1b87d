"""Cross-check of the general solver with the paper's own equations of section 3.

Source: the paper's section 3.1 (equation systems 3.1.1.1, 3.1.1.2, 3.1.2.1
and 3.1.2.3), written here literally in its notation (Table 1 lengths
g, h, r, q, c, d, p1, p2, p3; in the x-z plane e, f, s, t, a, b take their
places) and solved with numpy. The paper writes each system for the inertial
force pointing towards its "right" (rear) edges; the opposite sense is the
same system for the mirrored structure (g <-> h, r <-> q, c <-> d), whose
left/right results are then swapped back to physical contacts.

The general solver knows nothing of these cases; agreement to round-off
(1e-6 relative) shows it solves the same mechanics.
"""

from __future__ import annotations

import numpy as np
import pytest

from freestand.core.contact.screening import Motion, initial_motion

RELATIVE_TOLERANCE = 1e-6  # both are exact linear solutions: only round-off differs
G = 9.81
MU = 0.20  # kinetic coefficient (Table 1 data, section 4)

YZ = dict(
    m1=16600,
    m2=25600,
    I1=49400,
    I2=151600,
    p1=0.98,
    p3=0.22,
    p2=2.83,
    g=1.74,
    h=2.46,
    r=0.5,
    q=0.5,
    c=1.6,
    d=1.6,
)
XZ_RIGHT = dict(
    m1=16600,
    m2=25600,
    I1=256650,
    I2=124100,
    p1=0.98,
    p3=0.22,
    p2=2.83,
    g=5.9,
    h=3.9,
    r=5.14,
    q=2.0,
    c=1.33,
    d=1.33,
)  # e, f, s, t, a, b
XZ_LEFT = dict(XZ_RIGHT, r=0.0, q=7.14)  # s = 0; t = 7.14 puts B at -3.24 m as in the example


def _mirror(p):
    return dict(p, g=p["h"], h=p["g"], r=p["q"], q=p["r"], c=p["d"], d=p["c"])


def both_at_rest(p, a_h, a_v):
    """3.1.1.1 (cart at rest) with 3.1.2.1 (bridge held): unknowns CD, Cz, Dz, GH, Gz, Hz."""
    W1, W2 = p["m1"] * (G - a_v), p["m2"] * (G - a_v)
    F1, F2 = p["m1"] * a_h, p["m2"] * a_h
    A = np.zeros((6, 6))
    b = np.zeros(6)
    CD, Cz, Dz, GH, Gz, Hz = range(6)
    A[0, CD] = -1
    b[0] = -F2  # 3.1.1.1 (1)
    A[1, Cz] = A[1, Dz] = 1
    b[1] = W2  # 3.1.1.1 (2)
    A[2, Cz] = p["c"]
    A[2, Dz] = -p["d"]
    A[2, CD] = p["p2"]  # 3.1.1.1 (3)
    A[3, CD] = 1
    A[3, GH] = -1
    b[3] = -F1  # 3.1.2.1 (1)
    A[4, Gz] = A[4, Hz] = 1
    A[4, Cz] = A[4, Dz] = -1
    b[4] = W1  # 3.1.2.1 (2)
    A[5, Gz] = p["g"]
    A[5, Hz] = -p["h"]
    A[5, GH] = p["p1"]
    A[5, CD] = p["p3"]
    A[5, Cz] = -(p["g"] - p["r"])
    A[5, Dz] = p["h"] - p["q"]  # 3.1.2.1 (3)
    x = np.linalg.solve(A, b)
    return dict(upper=(x[Cz], x[Dz], x[CD]), lower=(x[Gz], x[Hz], x[GH]), a_upper=0.0, a_lower=0.0)


def lower_slides_upper_rests(p, a_h, a_v):
    """3.1.2.3, eqs. (1)-(7): unknowns a12, CD, Cz, Dz, GH, Gz, Hz."""
    W1, W2 = p["m1"] * (G - a_v), p["m2"] * (G - a_v)
    a12, CD, Cz, Dz, GH, Gz, Hz = range(7)
    A = np.zeros((7, 7))
    b = np.zeros(7)
    A[0, CD] = -1
    A[0, a12] = -p["m2"]
    b[0] = -p["m2"] * a_h  # (1)
    A[1, Cz] = A[1, Dz] = 1
    b[1] = W2  # (2)
    A[2, Cz] = p["c"]
    A[2, Dz] = -p["d"]
    A[2, CD] = p["p2"]  # (3)
    A[3, CD] = 1
    A[3, GH] = -1
    A[3, a12] = -p["m1"]
    b[3] = -p["m1"] * a_h  # (4)
    A[4, Gz] = A[4, Hz] = 1
    A[4, Cz] = A[4, Dz] = -1
    b[4] = W1  # (5)
    A[5, Gz] = p["g"]
    A[5, Hz] = -p["h"]
    A[5, GH] = p["p1"]
    A[5, CD] = p["p3"]
    A[5, Dz] = p["h"] - p["q"]
    A[5, Cz] = -(p["g"] - p["r"])  # (6)
    A[6, GH] = 1
    A[6, Gz] = A[6, Hz] = -MU  # (7)
    x = np.linalg.solve(A, b)
    return dict(
        upper=(x[Cz], x[Dz], x[CD]), lower=(x[Gz], x[Hz], x[GH]), a_upper=x[a12], a_lower=x[a12]
    )


def upper_slides_on_steady_lower(p, a_h, a_v):
    """Section 3.2 (x-z): the cart slides on the steady bridge; 3.1.2.1 b for the cart, 3.1.2.1 for the bridge."""
    W1, W2 = p["m1"] * (G - a_v), p["m2"] * (G - a_v)
    a2, CD, Cz, Dz, GH, Gz, Hz = range(7)
    A = np.zeros((7, 7))
    b = np.zeros(7)
    A[0, CD] = -1
    A[0, a2] = -p["m2"]
    b[0] = -p["m2"] * a_h
    A[1, Cz] = A[1, Dz] = 1
    b[1] = W2
    A[2, Cz] = p["c"]
    A[2, Dz] = -p["d"]
    A[2, CD] = p["p2"]
    A[3, CD] = 1
    A[3, Cz] = A[3, Dz] = -MU
    A[4, CD] = 1
    A[4, GH] = -1
    b[4] = -p["m1"] * a_h
    A[5, Gz] = A[5, Hz] = 1
    A[5, Cz] = A[5, Dz] = -1
    b[5] = W1
    A[6, Gz] = p["g"]
    A[6, Hz] = -p["h"]
    A[6, GH] = p["p1"]
    A[6, CD] = p["p3"]
    A[6, Cz] = -(p["g"] - p["r"])
    A[6, Dz] = p["h"] - p["q"]
    x = np.linalg.solve(A, b)
    return dict(
        upper=(x[Cz], x[Dz], x[CD]), lower=(x[Gz], x[Hz], x[GH]), a_upper=x[a2], a_lower=0.0
    )


def upper_rocks_on_steady_lower(p, a_h, a_v):
    """3.1.1.2, eqs. (1)-(5), with 3.1.2.1 (C_z = 0) for the steady lower block."""
    W1, W2 = p["m1"] * (G - a_v), p["m2"] * (G - a_v)
    ay, az, eps, Dy, Dz, GH, Gz, Hz = range(8)
    A = np.zeros((8, 8))
    b = np.zeros(8)
    A[0, Dy] = -1
    A[0, ay] = -p["m2"]
    b[0] = -p["m2"] * a_h  # (1)
    A[1, Dz] = 1
    A[1, az] = -p["m2"]
    b[1] = W2  # (2)
    A[2, Dz] = -p["d"]
    A[2, Dy] = p["p2"]
    A[2, eps] = -p["I2"]  # (3)
    A[3, eps] = p["p2"]
    A[3, ay] = -1  # (4)
    A[4, eps] = p["d"]
    A[4, az] = -1  # (5)
    A[5, Dy] = 1
    A[5, GH] = -1
    b[5] = -p["m1"] * a_h
    A[6, Gz] = A[6, Hz] = 1
    A[6, Dz] = -1
    b[6] = W1
    A[7, Gz] = p["g"]
    A[7, Hz] = -p["h"]
    A[7, GH] = p["p1"]
    A[7, Dy] = p["p3"]
    A[7, Dz] = p["h"] - p["q"]
    x = np.linalg.solve(A, b)
    return dict(
        upper=(0.0, x[Dz], x[Dy]),
        lower=(x[Gz], x[Hz], x[GH]),
        a_upper=x[ay],
        a_upper_z=x[az],
        eps=x[eps],
        a_lower=0.0,
    )


CASES = [
    # configuration, paper geometry, excitation, sense, paper system, expected motions
    ("y-z", YZ, "rigid", +1, lower_slides_upper_rests, (Motion.SLIDE, Motion.REST)),
    ("y-z", YZ, "rigid", -1, lower_slides_upper_rests, (Motion.SLIDE, Motion.REST)),
    ("y-z", YZ, "elastic", +1, lower_slides_upper_rests, (Motion.SLIDE, Motion.REST)),
    ("y-z", YZ, "elastic", -1, lower_slides_upper_rests, (Motion.SLIDE, Motion.REST)),
    ("x-z cart right", XZ_RIGHT, "rigid", +1, both_at_rest, (Motion.REST, Motion.REST)),
    (
        "x-z cart right",
        XZ_RIGHT,
        "elastic",
        +1,
        upper_rocks_on_steady_lower,
        (Motion.REST, Motion.ROCK),
    ),
    (
        "x-z cart right",
        XZ_RIGHT,
        "rigid",
        -1,
        upper_slides_on_steady_lower,
        (Motion.REST, Motion.SLIDE),
    ),
    (
        "x-z cart right",
        XZ_RIGHT,
        "elastic",
        -1,
        upper_slides_on_steady_lower,
        (Motion.REST, Motion.SLIDE),
    ),
    (
        "x-z cart left",
        XZ_LEFT,
        "rigid",
        +1,
        upper_slides_on_steady_lower,
        (Motion.REST, Motion.SLIDE),
    ),
    (
        "x-z cart left",
        XZ_LEFT,
        "elastic",
        +1,
        upper_slides_on_steady_lower,
        (Motion.REST, Motion.SLIDE),
    ),
    ("x-z cart left", XZ_LEFT, "rigid", -1, both_at_rest, (Motion.REST, Motion.REST)),
    (
        "x-z cart left",
        XZ_LEFT,
        "elastic",
        -1,
        upper_rocks_on_steady_lower,
        (Motion.REST, Motion.ROCK),
    ),
]


@pytest.mark.parametrize(
    ("configuration", "geometry", "excitation", "sense", "system", "motions"), CASES
)
def test_general_solver_matches_paper_equations(
    crane_model, configuration, geometry, excitation, sense, system, motions
):
    level = next(e for e in crane_model.excitations if e.name == excitation)
    # The example file gives B of the left-parked cart at -3.24 m (A + a + b), so
    # the paper's t is taken as 7.14 m here (Table 1 prints 7.15).
    paper = system(geometry if sense > 0 else _mirror(geometry), level.horizontal, level.vertical)
    case = initial_motion(
        crane_model.configuration(configuration), level.horizontal, level.vertical, sense, G
    )
    assert tuple(state.motion for state in case.blocks) == motions
    lower, upper = case.blocks
    scale = (16600 + 25600) * G
    for state, (left, right, horizontal) in ((upper, paper["upper"]), (lower, paper["lower"])):
        if sense < 0:  # mirrored structure: its left contact is our right one
            left, right = right, left
        assert state.base_normal_left == pytest.approx(left, abs=RELATIVE_TOLERANCE * scale)
        assert state.base_normal_right == pytest.approx(right, abs=RELATIVE_TOLERANCE * scale)
        # The paper's horizontal sums act against the inertial force on the upper body.
        assert state.base_tangential == pytest.approx(
            -sense * horizontal, abs=RELATIVE_TOLERANCE * scale
        )
    assert upper.acceleration_x == pytest.approx(sense * paper["a_upper"], abs=1e-6)
    assert lower.acceleration_x == pytest.approx(sense * paper["a_lower"], abs=1e-6)
    if "eps" in paper:
        assert upper.acceleration_z == pytest.approx(paper["a_upper_z"], abs=1e-6)
        # The paper's epsilon lifts the front edge: clockwise for the + sense.
        assert upper.angular_acceleration == pytest.approx(-sense * paper["eps"], abs=1e-6)
