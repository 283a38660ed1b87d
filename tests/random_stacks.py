"""Seeded random planar stacks and records: the engine's robustness sweep (issue #19).

Stacks of 1-3 blocks of random proportions, masses and frictions, 15 % of the
interfaces with ``sliding = "none"`` and 20 % with an end stop; half the
records with a vertical component; peaks 1-12 m/s^2. Used by
``tests/test_no_failed_simulation.py`` and ``tests/test_timehistory.py``.
"""

from __future__ import annotations

import numpy as np

from freestand.core.dynamics.results import SupportMotion
from freestand.core.model import Block, Friction, Sliding, Stack


def random_record(rng: np.random.Generator, peak: float, duration: float, vertical: bool,
                  dt: float = 0.01) -> SupportMotion:  # fmt: skip
    """Band-limited noise [m/s^2] in a rise-hold-decay envelope, scaled to ``peak``."""
    count = int(round(duration / dt)) + 1
    time = np.arange(count) * dt
    envelope = np.minimum(1.0, time) * np.exp(
        -np.maximum(0.0, time - 0.5 * duration) / (0.2 * duration)
    )

    def component() -> np.ndarray:
        noise = np.convolve(rng.standard_normal(count), np.ones(5) / 5, mode="same") * envelope
        return noise / np.abs(noise).max()

    horizontal = peak * component()
    return SupportMotion(dt, horizontal, 0.6 * peak * component() if vertical else None)


def random_stack(rng: np.random.Generator) -> Stack:
    """A stack of 1-3 blocks, each on the one below (a block's base is the top of the one below)."""
    blocks = []
    level = 0.0
    for index in range(int(rng.integers(1, 4))):
        width = rng.uniform(0.2, 3.0)
        left = rng.uniform(-1.0, 1.0) if index else -0.5 * width
        height = rng.uniform(0.2, 3.0)
        mass = rng.uniform(50.0, 5e4)
        radius = rng.uniform(0.2, 1.0) * np.hypot(width, height) / 2
        static = rng.uniform(0.1, 1.0)
        draw = rng.uniform()
        if draw < 0.15:
            sliding = Sliding.NONE
        elif draw < 0.25:
            sliding = Sliding.NO_RIGHT
        elif draw < 0.35:
            sliding = Sliding.NO_LEFT
        else:
            sliding = Sliding.FREE
        blocks.append(
            Block(
                name=f"block{index}",
                mass=mass,
                inertia=mass * radius**2,
                centre=(
                    rng.uniform(left + 0.1 * width, left + 0.9 * width),
                    level + rng.uniform(0.2, 0.8) * height,
                ),
                base_left=left,
                base_right=left + width,
                base_level=level,
                friction=Friction(static, static * rng.uniform(0.6, 1.0)),
                sliding=sliding,
            )
        )
        level += height
    return Stack(name="random", blocks=tuple(blocks))


def random_cases(count: int, seed: int, duration: float = 10.0):
    """``count`` (stack, record) pairs drawn from ``seed``."""
    rng = np.random.default_rng(seed)
    for _ in range(count):
        stack = random_stack(rng)
        peak = rng.uniform(1.0, 12.0)
        yield stack, random_record(rng, peak, duration, vertical=bool(rng.uniform() < 0.5))
