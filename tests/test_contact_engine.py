"""The one compiled contact kernel (freestand.core.contact.engine) against its numpy oracle."""

from __future__ import annotations

import ast
from pathlib import Path

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import freestand
from freestand.core.contact import engine
from freestand.core.contact.modes import solve_contact
from freestand.core.contact.screening import contact_problem_at_rest
from freestand.core.model import Block, Friction, Sliding, Stack
from tests.strategies import friction_clear_of_the_tolerance, stacks

G = 9.81
ORACLE = "freestand.core.contact.modes"


def _imports(path: Path) -> set[str]:
    """Modules a source file imports (``from a import b`` gives ``a`` and ``a.b``)."""
    names: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module:
            names.add(node.module)
            names.update(f"{node.module}.{alias.name}" for alias in node.names)
    return names


def test_no_production_module_imports_the_numpy_oracle():
    # the numpy solver is only the tests' independent reference: every production path
    # solves the contact problem with the compiled kernel
    package = Path(freestand.__file__).parent
    offenders = [
        str(path.relative_to(package))
        for path in sorted(package.rglob("*.py"))
        if path.name != "modes.py" and ORACLE in _imports(path)
    ]
    assert offenders == []


@settings(max_examples=60, deadline=None)
@given(
    stack=stacks(max_blocks=3),
    inertial=st.floats(-2.0 * G, 2.0 * G),
    vertical=st.floats(-0.5 * G, 0.9 * G),
)
def test_kernel_agrees_with_the_numpy_oracle_at_rest(stack, inertial, vertical):
    assume(friction_clear_of_the_tolerance(stack))  # an exact tie: see the helper
    problem = contact_problem_at_rest(stack, inertial, vertical, G)
    result = engine.solve(problem)
    oracle = solve_contact(problem)
    assert result.status == oracle.status
    assert result.diagnostics.modes_tried == oracle.diagnostics.modes_tried
    assert result.diagnostics.kinetic_only_modes == oracle.diagnostics.kinetic_only_modes
    assert result.diagnostics.relaxed == oracle.diagnostics.relaxed
    assert result.diagnostics.singular_modes == oracle.diagnostics.singular_modes
    assert len(result.admissible) == len(oracle.admissible)
    # tolerance: the kernel solves the Schur complement of the oracle's full system, so
    # the two agree to round-off relative to the problem's force/acceleration scales
    force_tol = 1e-8 * problem.force_scale
    accel_tol = 1e-8 * problem.acceleration_scale
    for ours, theirs in zip(result.admissible, oracle.admissible, strict=True):
        assert ours.modes == theirs.modes
        np.testing.assert_allclose(ours.normal_force, theirs.normal_force, atol=force_tol)
        np.testing.assert_allclose(ours.tangential_force, theirs.tangential_force, atol=force_tol)
        np.testing.assert_allclose(ours.acceleration, theirs.acceleration, atol=accel_tol)
        open_contacts = [
            (i, side)
            for i, mode in enumerate(ours.modes)
            for side, closed in enumerate((mode.left_closed, mode.right_closed))
            if not closed
        ]
        for i, side in open_contacts:
            assert abs(ours.gap_acceleration[i, side] - theirs.gap_acceleration[i, side]) <= (
                accel_tol
            )
        assert ours.residual <= 1e-9


def test_kernel_keeps_more_candidates_than_its_first_buffer():
    # in free fall (a_v = g, no horizontal load) every mode of every interface has zero
    # forces and accelerations: all 100 modes of two blocks are admissible (the kernel's
    # candidate buffers, 16 at first, grow) and they are one state, as in the oracle
    lower = Block.rectangle("lower", 0.6, 2.0, 1200.0, Friction(0.8, 0.7))
    upper = Block.rectangle("upper", 0.4, 1.2, 400.0, Friction(0.8, 0.7), level=2.0)
    pair = Stack("pair", (lower, upper))
    problem = contact_problem_at_rest(pair, 0.0, G, G)
    result = engine.solve(problem)
    oracle = solve_contact(problem)
    assert result.diagnostics.modes_tried == 100
    assert result.status == oracle.status == "unique"
    assert result.chosen.modes == oracle.chosen.modes
    np.testing.assert_allclose(result.chosen.acceleration, 0.0, atol=1e-12)


@pytest.mark.parametrize("static", [0.0, 0.999e-9, 1.001e-9, 1.999e-9, 2.001e-9, 1e-8])
def test_kernel_and_oracle_agree_next_to_the_tolerance(static):
    # the one input left out of the property test above is a coefficient equal to
    # RELATIVE_TOLERANCE (static 1e-9, or kinetic 1e-9 from static 2e-9): next to it the
    # two solvers agree on every mode
    block = Block(
        name="block0", mass=10.0, inertia=10.0, centre=(0.0, 1.0), base_left=0.0,
        base_right=1.0, base_level=0.0, friction=Friction(static, 0.5 * static),
        sliding=Sliding.FREE,
    )  # fmt: skip
    problem = contact_problem_at_rest(Stack(name="edge", blocks=(block,)), 0.0, 1.0, G)
    result = engine.solve(problem)
    oracle = solve_contact(problem)
    assert result.diagnostics.kinetic_only_modes == oracle.diagnostics.kinetic_only_modes
    assert [s.modes for s in result.admissible] == [s.modes for s in oracle.admissible]
