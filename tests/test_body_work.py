"""The 3-D engine's work records, kept per thread (``body_work.engine_work``, #18).

A run takes the records its thread kept and zeroes them: whatever the run before it left
there, a run gives what a run on fresh records gives, to the last bit.
"""

import threading

import numpy as np

from freestand.core.body import Body, Box, Cylinder
from freestand.core.contact.body_impulse import IMPULSE_WORK_DTYPE
from freestand.core.contact.body_kernel import SCRATCH_DTYPE
from freestand.core.dynamics.body_history import SupportMotion3, simulate_body
from freestand.core.dynamics.body_work import engine_work
from freestand.core.model import Friction

DT = 0.01
TIME = np.arange(0.0, 1.5 + DT / 2, DT)
MOTION = SupportMotion3(DT, 9.0 * np.sin(2.0 * np.pi * TIME), 3.0 * np.sin(3.0 * np.pi * TIME),
                        1.0 * np.sin(5.0 * np.pi * TIME))  # fmt: skip
CABINET = Body("cabinet", Box((0.6, 0.4, 2.0)), 400.0, Friction(0.5, 0.45))
CASK = Body("cask", Cylinder(0.4, 1.6), 1000.0, Friction(0.3, 0.3))


def _arrays(result):
    return (result.time, result.state, result.patch, result.sliding, result.normal_force,
            result.friction_force)  # fmt: skip


def test_the_records_are_zeroed_and_kept_per_thread():
    scratch, work = engine_work()
    assert scratch.dtype == SCRATCH_DTYPE and work.dtype == IMPULSE_WORK_DTYPE
    assert scratch.shape == work.shape == (1,)
    scratch.view(np.uint8)[:] = 7
    work.view(np.uint8)[:] = 7
    again, work_again = engine_work()
    assert again is scratch and work_again is work  # kept: the same arrays
    assert not again.view(np.uint8).any() and not work_again.view(np.uint8).any()  # zeroed
    other = []
    thread = threading.Thread(target=lambda: other.extend(engine_work()))
    thread.start()
    thread.join()
    assert other[0] is not scratch and other[1] is not work  # another thread, its own


def test_a_run_after_another_body_s_run_equals_a_first_run():
    # the cabinet rocks and slides, the cask rolls: each leaves its own scratch behind
    first = simulate_body(CABINET, MOTION)
    assert first.diagnostics["events"] > 2  # it moved
    simulate_body(CASK, MOTION)
    again = simulate_body(CABINET, MOTION)
    for a, b in zip(_arrays(first), _arrays(again), strict=True):
        np.testing.assert_array_equal(a, b)
    assert first.events == again.events
