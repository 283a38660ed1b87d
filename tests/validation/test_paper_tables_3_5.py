"""Paper Tables 3 and 5: contact forces of the crane, rigid and elastic structure.

Source: "Response of rigid block assemblies to earthquake excitation",
section 4, Tables 3 (a_hor = 2.70 m/s^2) and 5 (a_hor = 10.31 m/s^2), with
a_ver = 2.35 m/s^2 downward; our reading in shared/spec/crane-model.md.

Forces are compared by physical contact (left = smaller x in the global frame
for both senses), not by the paper's columns: the paper lists its -y / -x rows
for a mirrored structure. Tangential forces are compared in magnitude (the
paper gives sums without sign).

Tolerance: 0.5 % of the total reduced weight (m1 + m2)(g - a_ver) = 314 812 N,
i.e. 1600 N, for every force. The paper's sums show it computed with
m1 close to 16575 kg and a_hor = 0.275 g, a_ver = 0.24 g; with Table 1's
rounded data the forces differ from its tables by up to about 0.3 %.
"""

from __future__ import annotations

import pytest

from freestand.core.contact.screening import initial_motion

FORCE_TOLERANCE = 1600.0  # N, 0.5 % of the total reduced weight (see module docstring)

# (table, configuration, sense, {body: (left, right, |horizontal|)}) by physical contact.
ROWS = [
    # ---- Table 3, rigid structure (2.70 m/s^2) ----
    ("rigid", "y-z", +1, {"cart": (61661, 129203, 38173), "bridge": (125342, 189091, 62886)}),
    # -y: the paper prints the cart's forces as "D_z = 129203, C_z = 61661" but the
    # cart's centre is midway between C and D, so the contact on the side the
    # inertial force points to (C, the left one, for -y) carries the larger force:
    # its labels are swapped; its bridge row "H_z = 104158, G_z = 210274" is by label.
    ("rigid", "y-z", -1, {"cart": (129203, 61661, 38173), "bridge": (210274, 104158, 62886)}),
    (
        "rigid",
        "x-z cart right",
        +1,
        {"cart": (21652, 169211, 69062), "bridge": (81161, 233271, 113775)},
    ),
    (
        "rigid",
        "x-z cart left",
        +1,
        {"cart": (54652, 136212, 38173), "bridge": (194027, 120405, 82885)},
    ),
    (
        "rigid",
        "x-z cart right",
        -1,
        {"cart": (136212, 54652, 38173), "bridge": (134294, 180138, 82885)},
    ),
    (
        "rigid",
        "x-z cart left",
        -1,
        {"cart": (169211, 21652, 69062), "bridge": (247161, 67272, 113775)},
    ),
    # ---- Table 5, horizontally elastic structure (10.31 m/s^2) ----
    ("elastic", "y-z", +1, {"cart": (61661, 129203, 38173), "bridge": (125342, 189091, 62886)}),
    ("elastic", "y-z", -1, {"cart": (129203, 61661, 38173), "bridge": (210274, 104158, 62886)}),
    (
        "elastic",
        "x-z cart right",
        +1,
        {"cart": (0, 235670, 168210), "bridge": (59640, 299599, 339094)},
    ),
    (
        "elastic",
        "x-z cart left",
        +1,
        {"cart": (54652, 136212, 38173), "bridge": (181372, 133061, 209056)},
    ),
    # Misprint: the paper prints E_z = 149950 N, which breaks vertical equilibrium
    # (the row sums to 317 432 N against a reduced weight of 314 600 N); every
    # consistent solution gives about 146 900 N, which is tested here.
    (
        "elastic",
        "x-z cart right",
        -1,
        {"cart": (136212, 54652, 38173), "bridge": (146900, 167482, 209056)},
    ),
    (
        "elastic",
        "x-z cart left",
        -1,
        {"cart": (235668, 0, 168210), "bridge": (322669, 36570, 339094)},
    ),
]


def _case(model, excitation_name, configuration, sense):
    excitation = next(e for e in model.excitations if e.name == excitation_name)
    stack = model.configuration(configuration)
    return initial_motion(
        stack, excitation.horizontal, excitation.vertical, sense, model.gravity, excitation.name
    )


@pytest.mark.parametrize(("excitation", "configuration", "sense", "expected"), ROWS)
def test_contact_forces_match_paper(crane_model, excitation, configuration, sense, expected):
    case = _case(crane_model, excitation, configuration, sense)
    assert case.status == "unique"
    for body, (left, right, horizontal) in expected.items():
        state = case.block(body)
        assert state.base_normal_left == pytest.approx(left, abs=FORCE_TOLERANCE)
        assert state.base_normal_right == pytest.approx(right, abs=FORCE_TOLERANCE)
        assert abs(state.base_tangential) == pytest.approx(horizontal, abs=FORCE_TOLERANCE)


def test_misprinted_row_is_not_in_equilibrium():
    """The paper's E_z = 149950 N cannot balance the reduced weight (documents the misprint).

    With both blocks steady, the bridge's support forces sum to the reduced
    weight; the paper's own rows with a steady cart give that sum as
    181372 + 133061 = 314433 N (Table 5, "x-z, +x, left").
    """
    paper_reduced_weight = 181372 + 133061  # N
    misprinted_sum = 149950 + 167482  # N, Table 5 row "x-z, -x, cart right"
    assert misprinted_sum - paper_reduced_weight > FORCE_TOLERANCE
    assert abs(146900 + 167482 - paper_reduced_weight) < FORCE_TOLERANCE
