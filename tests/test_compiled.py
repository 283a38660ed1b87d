"""The 3-D engine's compiled functions: run-time choices compiled once per type."""

from __future__ import annotations

import numba as nb

from freestand.core.contact import body_modes
from freestand.core.contact.compiled import RUNTIME_ARGUMENTS, RuntimeArgumentDispatcher, kernel


@kernel(cache=False)
def _scaled(x, level):
    return 2.0 * x if level == 1 else x


@nb.njit
def _both_levels(x):
    return _scaled(x, 1) + _scaled(x, 0)  # constants: numba would compile twice


@kernel(cache=False)
def _shifted(x, offset):
    return x + offset


@nb.njit
def _two_offsets(x):
    return _shifted(x, 1) + _shifted(x, 2)


def test_a_run_time_choice_passed_as_a_constant_is_compiled_once_for_its_type():
    assert "level" in RUNTIME_ARGUMENTS
    assert _both_levels(1.0) == 3.0
    assert len(_scaled.signatures) == 1
    assert "Literal" not in str(_scaled.signatures[0])


def test_other_constants_keep_numba_s_specialisation_per_value():
    assert _two_offsets(1.0) == 5.0
    assert type(_shifted) is not RuntimeArgumentDispatcher  # no run-time argument
    assert len(_shifted.signatures) == 2


def test_the_3d_kernel_uses_it():
    assert type(body_modes._solve) is RuntimeArgumentDispatcher
