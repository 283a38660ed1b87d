"""Sliding block under a rectangular pulse: Newmark's closed form.

Source: N. M. Newmark (1965), "Effects of earthquakes on dams and
embankments", Geotechnique 15(2), 139-160, the rigid block on a horizontal
plane under a single rectangular acceleration pulse (his Fig. 4 and the
equation beside it): a block at rest, support acceleration ``a`` for ``t1``,
resistance ``mu m g``. Relative to the support the block slides with the
acceleration ``a - mu g`` during the pulse and decelerates
at ``mu g`` afterwards until it stops, at ``t_stop = t1 a / (mu g)``. The
permanent slide is

    d = a (a - mu g) t1^2 / (2 mu g)     (= V^2 / (2 g N) (1 - N / A), V = a t1)

It starts only if ``a > mu_0 g`` (static coefficient, paper section
3.1.2.1); once sliding the kinetic coefficient ``mu`` acts.

The pulse jumps inside one integration step; RK4 is then first order in the
step for that step, so the slide converges linearly with the step (tested).
"""

from __future__ import annotations

import pytest

from freestand.core.dynamics.timehistory import simulate
from freestand.core.model import Block, Friction, Stack

G = 9.81


def wide_block(static: float, kinetic: float) -> Stack:
    """b/h = 2: rocking needs a > 2 g, so it only slides."""
    block = Block(
        name="block",
        mass=200.0,
        inertia=200.0 * (2.0**2 + 1.0**2) / 12.0,
        centre=(0.0, 0.5),
        base_left=-1.0,
        base_right=1.0,
        base_level=0.0,
        friction=Friction(static, kinetic),
    )
    return Stack("wide", (block,))


def newmark_slide(a: float, t1: float, mu: float) -> float:
    return a * (a - mu * G) * t1**2 / (2.0 * mu * G)


@pytest.mark.parametrize(
    "a_g, t1, static, kinetic",
    [(0.5, 0.2, 0.3, 0.3), (0.5, 0.2, 0.4, 0.3), (0.8, 0.15, 0.25, 0.2), (0.35, 0.4, 0.3, 0.3)],
)
def test_slide_under_rectangular_pulse(a_g, t1, static, kinetic):
    a = a_g * G
    stack = wide_block(static, kinetic)
    result = simulate(stack, lambda t: (a if t < t1 else 0.0, 0.0), 1.0, max_step=2.5e-4)
    assert result.status == "completed"
    expected = newmark_slide(a, t1, kinetic)
    # O(h) from the jump of the pulse inside one step: 0.1 % at h = 0.25 ms
    assert result.max_slide[0] == pytest.approx(expected, rel=1e-3)
    # the support moves +x, the block lags: it slides to -x relative to the support
    assert result.slide[-1, 0] == pytest.approx(-expected, rel=1e-3)
    stop = [e for e in result.events if e.kind == "slip-stop"]
    assert stop[0].time == pytest.approx(t1 * a / (kinetic * G), rel=1e-3)
    assert stop[0].motions == ("rest",)
    assert result.max_rotation[0] < 1e-12 and not result.uplift[0]


def test_no_slide_below_static_friction():
    """a = 0.35 g: above mu = 0.3 but below mu_0 = 0.4: static friction holds."""
    result = simulate(wide_block(0.4, 0.3), lambda t: (0.35 * G if t < 0.3 else 0.0, 0.0), 0.6)
    assert result.max_slide[0] < 1e-12
    assert [event.kind for event in result.events] == ["start"]


def test_slide_converges_linearly_with_the_step():
    a, t1, mu = 0.5 * G, 0.2, 0.3
    expected = newmark_slide(a, t1, mu)
    errors = []
    for step in (2e-3, 1e-3, 5e-4):
        result = simulate(
            wide_block(mu, mu), lambda t: (a if t < t1 else 0.0, 0.0), 0.6, max_step=step
        )
        errors.append(abs(result.max_slide[0] - expected))
    # first order: halving the step halves the error (ratio 2 +- 10 %)
    assert errors[0] / errors[1] == pytest.approx(2.0, rel=0.1)
    assert errors[1] / errors[2] == pytest.approx(2.0, rel=0.1)
