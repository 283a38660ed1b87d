"""The stable public entry points of freestand, for scripts and notebooks.

``import freestand as fs`` gives these names (see the README, "Python API").
They are thin: each calls the one implementation in :mod:`freestand.core` or
:mod:`freestand.io`; whatever moves inside the package, these names stay.

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

from freestand.core.contact.screening import GRAVITY, InitialMotion
from freestand.core.contact.screening import screen as _screen_stack
from freestand.core.dynamics.timehistory import SupportMotion, TimeHistoryResult
from freestand.core.dynamics.timehistory import simulate as _simulate_stack
from freestand.core.model import Excitation, Stack
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


def screen(
    stack: Stack,
    excitations: Excitation | list[Excitation] | tuple[Excitation, ...],
    gravity: float = GRAVITY,
) -> list[InitialMotion]:
    """Initial motion and contact forces of a stack from rest (paper Tables 2-5).

    Parameters
    ----------
    stack : Stack
        The blocks, bottom first (``model.configuration(name)``).
    excitations : Excitation or sequence of Excitation
        Support acceleration levels: horizontal magnitude a_h [m/s^2] (both
        senses analysed) and downward vertical a_v [m/s^2] (weight m (g - a_v)).
    gravity : float, optional
        g [m/s^2] (9.81; use ``model.gravity`` for a model file's value).

    Returns
    -------
    list of InitialMotion
        For each excitation, sense ``+`` then ``-``: every block's motion,
        accelerations and contact forces, with the ambiguity report.
    """
    if isinstance(excitations, Excitation):
        excitations = (excitations,)
    return _screen_stack(stack, tuple(excitations), gravity)


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
