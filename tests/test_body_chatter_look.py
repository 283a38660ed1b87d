"""A chatter's look for a mode (#18): ``body_modes.chatter_look`` against ``select_mode``.

A chatter's stretch of the remedy goes on while its patch could only slip
from rest (``body_remedy.stretch_step``). Its look for a mode does not seek
that slip's onset: where the selection would choose an onset, the look says
``SLIPS_FROM_REST``; where it would choose a stick, a slip under way or the
flight, the look chooses the same. The states: the benchmark's cabinet
(1.0 x 0.6 x 2.0 m, 400 kg, mu 0.5) at rest on its long edge, leaning 0.05
rad, under a constant support acceleration.
"""

from __future__ import annotations

import numpy as np
import pytest

from freestand.core.body import Body, Box
from freestand.core.contact import body_kernel, body_modes
from freestand.core.dynamics.body_history import initial_state
from freestand.core.model import Friction

CABINET = Body("cabinet", Box((1.0, 0.6, 2.0)), 400.0, Friction(0.5, 0.5))
GAP, VELOCITY = 1e-7, 1e-4  # the engine's default tolerances [m], [m/s]


def _choose(look: bool, acceleration: tuple[float, float, float], speed: float = 0.0):
    """(chosen, mode, onset flag) of the selection or the look at the leaning cabinet.

    ``acceleration`` (a_x, a_y, a_v) [m/s^2] of the support, constant;
    ``speed`` [m/s] a slip of the body along x.
    """
    par = body_kernel.body_parameters(CABINET, 9.81, 1.0)
    record = np.tile(np.array(acceleration, dtype=float)[:, None], (1, 2))
    y = initial_state(CABINET, (0.05, 0.0))
    y[7] = speed
    scratch = body_kernel.new_scratch()
    mode = np.zeros(3, dtype=np.int64)
    data = np.zeros(body_kernel.DATA_SIZE)
    if look:
        chosen = body_modes.chatter_look(par, record, 1.0, 0.0, y, scratch, GAP, VELOCITY, mode,
                                         data)  # fmt: skip
    else:
        none = np.array([-1, 0, 0], dtype=np.int64)
        chosen = body_modes.select_mode(par, record, 1.0, 0.0, y, scratch, GAP, VELOCITY, mode,
                                        data, none)  # fmt: skip
    return chosen, tuple(int(v) for v in mode), data[body_kernel.D_ONSET]


def test_an_edge_that_could_only_slip_from_rest_is_not_searched():
    # 5.7 m/s^2 at 45 deg, above mu g = 4.9: the edge cannot stick, and slips from rest
    chosen, mode, onset = _choose(False, (4.0, 4.0, 0.0))
    assert chosen >= 0 and mode == (body_kernel.EDGE, 2, 1) and onset == 1.0
    chosen, _, _ = _choose(True, (4.0, 4.0, 0.0))
    assert chosen == body_modes.SLIPS_FROM_REST
    # pushed along the edge, a slip along it would lift its rear corner (mu h = b_x); it
    # slips turned towards the lean (-y, 23 deg), where its friction spares the corner: an
    # onset again, which the look does not seek. (The engine until 2026-12-07 found no mode
    # here: the onset's Newton search converged linearly and gave up; test_body_onset_newton)
    chosen, mode, onset = _choose(False, (6.0, 0.0, 0.0))
    assert chosen >= 0 and mode == (body_kernel.EDGE, 2, 1) and onset == 1.0
    assert _choose(True, (6.0, 0.0, 0.0))[0] == body_modes.SLIPS_FROM_REST


@pytest.mark.parametrize(
    ("acceleration", "speed"),
    [
        ((2.0, 0.0, 0.0), 0.0),  # the edge sticks: friction within mu N
        ((4.0, 4.0, 0.0), 0.05),  # the edge slips under way, faster than the tolerance
        ((0.0, 0.0, 12.0), 0.0),  # the support falls faster than gravity: the flight
    ],
)
def test_a_stick_a_slip_under_way_and_the_flight_are_the_selection_s(acceleration, speed):
    expected = _choose(False, acceleration, speed)
    assert expected[0] >= 0 and expected[2] == 0.0  # not an onset
    assert _choose(True, acceleration, speed) == expected
