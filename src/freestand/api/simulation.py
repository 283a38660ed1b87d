"""Public time history: :func:`simulate` and :func:`support_motion`.

Example
-------
>>> import freestand as fs
>>> model = fs.load_model("examples/crane.toml")
>>> stack = model.configuration("x-z cart right")
>>> motion = fs.load_record("examples/records/synthetic_H.AT2").scaled_to_peak(8.0)
>>> result = fs.simulate(stack, motion, duration=12.0)
>>> result.status
'completed'
"""

from __future__ import annotations

import numpy as np

from freestand.core.dynamics.timehistory import SupportMotion, TimeHistoryResult
from freestand.core.dynamics.timehistory import simulate as _simulate_stack
from freestand.core.model import Stack
from freestand.core.motion.ground_motion import GroundMotion


def support_motion(motion: GroundMotion | SupportMotion) -> SupportMotion:
    """The sampled support motion of a record.

    Parameters
    ----------
    motion : GroundMotion or SupportMotion
        A record read by :func:`load_record` (horizontal and downward vertical
        accelerations [m/s^2] at a step dt [s]) or a support motion already.

    Returns
    -------
    SupportMotion
        The same samples, as the time history takes them.
    """
    if isinstance(motion, SupportMotion):
        return motion
    if isinstance(motion, GroundMotion):
        return SupportMotion(
            motion.dt,
            np.asarray(motion.horizontal),
            None if motion.vertical is None else np.asarray(motion.vertical),
        )
    raise TypeError(
        f"expected a GroundMotion (fs.load_record) or a SupportMotion, not {type(motion).__name__}"
    )


def simulate(
    stack: Stack,
    motion: GroundMotion | SupportMotion,
    duration: float | None = None,
    **options,
) -> TimeHistoryResult:
    """Time history of a stack under a support motion (exact rigid contact).

    Parameters
    ----------
    stack : Stack
        The blocks, bottom first.
    motion : GroundMotion or SupportMotion
        Horizontal and downward vertical support accelerations [m/s^2].
    duration : float, optional
        Simulated time [s]; by default the record and then free motion until
        the stack is at rest again or a block overturns.
    **options
        Passed to :func:`freestand.core.dynamics.timehistory.simulate` (``method``,
        ``max_step`` [s], ``gravity`` [m/s^2], ...).

    Returns
    -------
    TimeHistoryResult
        Status, histories, events, peaks and diagnostics.
    """
    return _simulate_stack(stack, support_motion(motion), duration, **options)
