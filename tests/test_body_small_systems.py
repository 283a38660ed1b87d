"""The 3-D kernel's small linear systems: Cramer's rule up to 3 x 3, elimination beyond (#18).

``solve_small`` must give what Gaussian elimination with partial pivoting
gives, to round-off, on any system it may meet, fall back to the
elimination where the rows are nearly dependent, and say so where the
system is singular. ``_solve_held`` solves a sticking patch's symmetric
system by ``L D L^T`` and must agree too.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from freestand.core.contact import body_kernel as bk


def _solved(matrix, rhs, eliminated=None):
    """(ok, x) of ``solve_small`` on copies of the leading block; ``eliminated``: assert
    whether the elimination ran (it overwrites the matrix, Cramer's rule does not)."""
    k = rhs.size
    m = np.zeros((6, 6))
    m[:k, :k] = matrix
    b = np.zeros(6)
    b[:k] = rhs
    ok = bk.solve_small(m, b, k)
    if eliminated is not None:
        assert (not np.array_equal(m[:k, :k], matrix)) is eliminated
    return ok, b[:k]


@settings(max_examples=300, deadline=None)
@given(st.integers(1, 6), st.integers(0, 2**32 - 1), st.floats(-6.0, 6.0))
def test_small_systems_are_solved_as_by_elimination(k, seed, scale_exponent):
    rng = np.random.default_rng(seed)
    matrix = rng.normal(size=(k, k)) * 10.0**scale_exponent + np.eye(k) * 10.0**scale_exponent
    rhs = rng.normal(size=k)
    ok, x = _solved(matrix, rhs)
    assert ok
    # tolerance: the residual of a backward-stable solve, eps times the condition number
    condition = np.linalg.cond(matrix)
    expected = np.linalg.solve(matrix, rhs)
    np.testing.assert_allclose(x, expected, rtol=1e-13 * condition, atol=1e-13 * condition
                               * np.max(np.abs(expected)))  # fmt: skip


@pytest.mark.parametrize("k", [2, 3])
def test_nearly_dependent_rows_fall_back_to_elimination(k):
    # rows dependent to 1e-12 (below the 1e-8 of Hadamard's bound): pivoting, not Cramer
    matrix = np.ones((k, k)) + np.diag(np.full(k, 1e-12))
    matrix[0, 0] += 1e-12
    rhs = np.arange(1.0, k + 1.0)
    ok, x = _solved(matrix, rhs, eliminated=True)
    assert ok
    # tolerance: pivoting's residual, eps |A| |x| with |x| ~ 1e12
    np.testing.assert_allclose(matrix @ x, rhs, rtol=0.0, atol=1e-3)
    # well-conditioned, the closed form
    _solved(np.eye(k) + 0.1, rhs, eliminated=False)


@pytest.mark.parametrize("k", [1, 2, 3, 5])
def test_singular_systems_are_refused(k):
    ok, _ = _solved(np.zeros((k, k)), np.ones(k))
    assert not ok


@settings(max_examples=100, deadline=None)
@given(st.integers(1, 6), st.integers(0, 2**32 - 1), st.booleans())
def test_held_rows_are_solved_alike_whether_symmetric_or_not(held, seed, symmetric):
    # the kernel's layout: rows in work[0:held], M^-1 times them in work[7 + j]
    rng = np.random.default_rng(seed)
    rows = rng.normal(size=(held, 6))
    weights = np.diag(rng.uniform(0.1, 2.0, size=6))
    work = np.zeros((14, 6))
    work[:held] = rows
    work[7 : 7 + held] = rows @ weights  # M^-1 diagonal: W = rows M^-1 rows^T, symmetric
    rhs = rng.normal(size=6)
    matrix = np.zeros((6, 6))
    b = rhs.copy()
    assert bk._solve_held(work, matrix, b, held, symmetric)
    delassus = rows @ weights @ rows.T
    # a backward-stable solve leaves a residual of some eps |W| |b|: random rows can make W
    # ill-conditioned (seed 1545, six rows: cond 1.4e8, |b| 4e6, residual 7e-9 = 1.4e-16 |W| |b|),
    # so the tolerance carries that term at 70 eps besides the 1e-9 of a well-conditioned W
    backward = 1e-14 * held * np.abs(delassus).max() * np.abs(b[:held]).max()
    np.testing.assert_allclose(delassus @ b[:held], rhs[:held], rtol=1e-9, atol=1e-9 + backward)


@settings(max_examples=200, deadline=None)
@given(st.integers(0, 2**32 - 1), st.floats(-6.0, 6.0), st.floats(0.0, 12.0))
def test_an_inertia_about_a_point_is_solved_by_its_adjugate(seed, scale_exponent, spread):
    """``_solve_inertia`` (a sticking point's I_P alpha = rhs): a symmetric positive
    definite 3 x 3 system solved as by elimination, to round-off, while its determinant
    is at least ADJUGATE_CONDITION of its diagonal's product; below, it declines and
    leaves the right-hand side for the caller's factorisation."""
    rng = np.random.default_rng(seed)
    # eigenvalues spread over up to 12 decades: from a well-conditioned inertia to a nearly
    # singular one
    rotation, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    values = 10.0 ** (scale_exponent - spread * rng.uniform(size=3))
    matrix = (rotation * values) @ rotation.T
    matrix = 0.5 * (matrix + matrix.T)
    rhs = rng.normal(size=3)
    m, b = np.zeros((6, 6)), np.zeros(6)
    m[:3, :3], b[:3] = matrix, rhs
    ok = bk._solve_inertia(m, b)
    ratio = np.linalg.det(matrix) / np.prod(np.diag(matrix))
    if not ok:
        assert ratio < 1.01 * bk.ADJUGATE_CONDITION  # declined only where ill-conditioned
        np.testing.assert_array_equal(b[:3], rhs)
        return
    assert ratio > 0.99 * bk.ADJUGATE_CONDITION
    expected = np.linalg.solve(matrix, rhs)
    # tolerance: the adjugate's error, some 10 u / ratio (135 u at the threshold, measured
    # on 20,000 such systems), plus elimination's u cond(A), relative to the solution
    condition = np.linalg.cond(matrix)
    unit = np.finfo(float).eps
    np.testing.assert_allclose(b[:3], expected, rtol=0.0,
                               atol=(500.0 + condition) * unit * np.max(np.abs(expected)))  # fmt: skip
