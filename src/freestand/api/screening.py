"""Public screening from rest: :func:`screen` (paper Tables 2-5)."""

from __future__ import annotations

from freestand.core.contact.screening import GRAVITY, InitialMotion
from freestand.core.contact.screening import screen as _screen_stack
from freestand.core.model import Excitation, Stack


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
