"""Fragility validation (a): a rocking block under half-sine pulses of random frequency.

With IM = the pulse amplitude (its PGA) and one simulation per pulse and
level, the fraction of pulses that overturn the block at a level must equal
the fraction of pulses whose exact lowest overturning amplitude (Zhang and
Makris 2001, from :func:`exact_minimum_overturning_amplitude`) lies below
that level: the campaign (scaling, simulation after the pulse, overturning
judgement, counting) adds nothing and loses nothing.
"""

from __future__ import annotations

import numpy as np

from freestand.core.model import Block, Friction, Sliding, Stack
from freestand.core.motion.ground_motion import half_sine_pulse
from freestand.core.rocking.integrator import exact_minimum_overturning_amplitude
from freestand.core.rocking.properties import RockingBlock
from freestand.core.sweeps.fragility.analysis import analyse
from freestand.core.sweeps.fragility.campaign import Campaign, run_tasks
from freestand.core.sweeps.fragility.intensity import IntensityMeasure
from freestand.core.sweeps.fragility.outcomes import Outcome

# a block 0.8 m wide, 2.4 m high (alpha = 0.32 rad), on a base it cannot slide on
BLOCK = Block(
    "block", 500.0, 500.0 * (0.4**2 + 1.2**2) / 3.0, (0.0, 1.2), -0.4, 0.4, 0.0,
    Friction(2.0, 2.0), Sliding.NONE,
)  # fmt: skip
STACK = Stack("block", (BLOCK,))


def test_overturning_fraction_equals_the_exact_threshold_fraction():
    rng = np.random.default_rng(14)
    frequencies = rng.uniform(1.0, 5.0, 16)
    # 400 samples per pulse: the sampled (piecewise-linear) sine is within
    # 1e-5 of the sine the exact threshold is computed for
    motions = tuple(
        half_sine_pulse(1.0, frequency=f, dt=1.0 / (800.0 * f), name=f"pulse {f:.3f} Hz")
        for f in frequencies
    )
    levels = np.linspace(4.0, 16.0, 7)
    campaign = Campaign(
        STACK, motions, IntensityMeasure("pga"), levels, outcomes=(Outcome("overturn", "block"),)
    )
    rows = run_tasks(campaign, 0, campaign.size)
    assert set(rows["status"]) <= {"completed", "capped"}
    result = analyse(rows, campaign.outcomes, levels, bootstrap=0)
    counts = result.outcomes[0].fragility.counts

    rocking = RockingBlock.from_block(BLOCK, "left")
    exact = exact_minimum_overturning_amplitude(rocking, "half-sine", frequencies)
    assert exact.found.all()
    threshold = exact.amplitude
    # a pulse whose threshold lies within 0.2 % of a level is too close to call
    # with a sampled pulse; none does for this seed (checked, not assumed)
    closest = np.min(np.abs(threshold[:, None] / levels[None, :] - 1.0))
    assert closest > 2e-3
    expected = (threshold[:, None] <= levels[None, :]).sum(axis=0)
    assert counts.tolist() == expected.tolist()
    # the stripes straddle the thresholds: some levels partly overturn
    assert ((expected > 0) & (expected < frequencies.size)).any()
