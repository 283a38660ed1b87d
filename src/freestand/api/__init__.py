"""The stable public entry points of freestand, for scripts and notebooks.

``import freestand as fs`` gives these names (see the README, "Python API").
They are thin: each calls the one implementation in :mod:`freestand.core` or
:mod:`freestand.io`; whatever moves inside the package, these names stay. One
module per analysis; the command line (:mod:`freestand.cli`) is a shell over
them.
"""

from __future__ import annotations

from freestand.api.records import floor_motion, generate_suite, response_spectrum
from freestand.api.screening import screen
from freestand.api.simulation import simulate, support_motion

__all__ = [
    "floor_motion",
    "generate_suite",
    "response_spectrum",
    "screen",
    "simulate",
    "support_motion",
]
