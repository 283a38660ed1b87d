"""The 3-D engine's compiled functions: numba's ``njit``, compiled once per argument type
where an argument is a run-time choice.

numba compiles a function called from another compiled function once for each
*literal* value a caller passes as a constant: ``_solve(..., ACCELERATION, 1, ...)``
and ``_solve(..., VELOCITY, 0, ...)`` are two compilations of the whole tree of
functions below ``_solve``, each of them a library that numba optimises and turns into
machine code again with everything it links. The 3-D kernel passes its levels
(acceleration or velocity), slip flags, row counts and kinds of contact as constants
from many places: its compilation for a time history took 200 s. The arguments named
in :data:`RUNTIME_ARGUMENTS` are compiled for their type instead (a branch on them at
run time): 126 s, the same runs to the last bit, 1-2 % slower (the cabinet's, the cask's
and the slender cylinder's 10 s records, alternated, best of 15). Compiling *every*
argument for its type took 145 s and made the runs 30-50 % slower: the other constants
are worth their specialisations.

No fast-math flags are set. ``contract`` alone (fused multiply-adds, rounded once) made
the 3-D benchmark's three bodies 4-5 % faster, but a run's last bits then depended on
whether its kernels were compiled in the process or loaded from numba's cache (LLVM fuses
after inlining, which differs between the two): a resumed campaign's rows no longer
equalled an uninterrupted one's (``tests/test_body_fragility.py``).
"""

from __future__ import annotations

import inspect

import numba as nb
from numba.core import types
from numba.core.registry import CPUDispatcher

RUNTIME_ARGUMENTS = frozenset(
    {
        "level",  # acceleration or velocity (an impact's) level of a mode's solve
        "use_bias",  # with the velocity-dependent terms or without (a velocity level)
        "kinetic",  # the slip direction from the slip velocity, or as given
        "iterations",  # an iteration limit
        "slip",  # a mode sticks or slides
        "which",  # which margin fired
        "solved",  # the scratch holds the solve already
        "count",  # a count of recorded rows or events
        "kind",  # FACE, EDGE, POINT or FREE
        "index",  # which edge or corner
        "n_tangent",  # a mode's tangential rows
        "n_normal",  # a mode's normal rows
        "reuse_terms",  # a sliding EDGE's solve on the terms the solve before it left
        "stage",  # an RK4 stage's solve, which reads the accelerations alone
        "chatter",  # a mode's selection in a chatter's stretch of the remedy, or any other
    }
)


class RuntimeArgumentDispatcher(CPUDispatcher):
    """numba's CPU dispatcher, typing the arguments in :data:`RUNTIME_ARGUMENTS` by type.

    It overrides ``get_call_template``, which numba's typing calls with the
    argument types of a call from compiled code (numba 0.68 here; not a
    public interface). Further arguments a later numba may pass are handed
    on untouched; were the method renamed, the override would go unused and
    each literal compiled on its own (slower to compile, the same results):
    ``tests/test_compiled.py`` checks that it is used.
    """

    def get_call_template(self, args, kws, *more, **options):
        positions = _runtime_positions(self.py_func)
        args = tuple(
            types.unliteral(value) if position in positions else value
            for position, value in enumerate(args)
        )
        return super().get_call_template(args, kws, *more, **options)


_POSITIONS: dict = {}


def _runtime_positions(function) -> frozenset:
    """The positions of ``function``'s parameters named in :data:`RUNTIME_ARGUMENTS`."""
    if function not in _POSITIONS:
        names = inspect.signature(function).parameters
        _POSITIONS[function] = frozenset(
            position for position, name in enumerate(names) if name in RUNTIME_ARGUMENTS
        )
    return _POSITIONS[function]


def kernel(**options):
    """``numba.njit(**options)``, compiling the :data:`RUNTIME_ARGUMENTS` once per type.

    Under ``NUMBA_DISABLE_JIT`` the plain Python function, as ``njit`` gives it.
    """

    def wrap(function):
        dispatcher = nb.njit(**options)(function)
        if type(dispatcher) is CPUDispatcher and _runtime_positions(function):
            dispatcher.__class__ = RuntimeArgumentDispatcher
        return dispatcher

    return wrap
