"""Compile freestand's engines into numba's on-disk cache before the test workers start.

Run by ``tests/conftest.py`` when pytest runs on several workers (``make test``): the
3-D body engine and the planar engines are compiled once, in two processes side by
side, instead of once in every worker. A fresh clone has no cache: each worker then
spent minutes compiling the same functions (the 3-D engine alone takes about three).
The calls below are the public API's, on the built-in examples, with short records:
they reach the compiled entry points the tests reach; anything they miss is compiled
by the first test that needs it, as before.

Usage: ``python tests/compile_engines.py body`` or ``... planar``.
"""

from __future__ import annotations

import sys

import numpy as np

import freestand as fs

SAMPLE_INTERVAL = 0.01  # [s]
DURATION = 2.0  # [s]


def _motion3(peak: float) -> fs.SupportMotion3:
    """A short three-component sine record [m/s^2]."""
    time = np.arange(0.0, DURATION, SAMPLE_INTERVAL)
    wave = peak * np.sin(2.0 * np.pi * 2.0 * time)
    return fs.SupportMotion3(SAMPLE_INTERVAL, wave, 0.7 * wave, 0.3 * wave)


def body() -> None:
    """The 3-D engine: screening, time histories of a cylinder and a box, overturning."""
    model = fs.load_model(fs.example_path("bodies"))
    fs.screen(model, directions=4)
    for stack in model.body_configurations:
        fs.simulate(model, _motion3(6.0), configuration=stack.name)
    for stack in model.body_configurations:
        fs.overturning(model, configuration=stack.name, frequencies=[2.0])


def planar() -> None:
    """The planar engines: screening, a time history, overturning, a mode map."""
    model = fs.load_model(fs.example_path("crane"))
    fs.screen(model)
    time = np.arange(0.0, DURATION, SAMPLE_INTERVAL)
    motion = fs.SupportMotion(SAMPLE_INTERVAL, 6.0 * np.sin(2.0 * np.pi * 2.0 * time),
                              2.0 * np.sin(2.0 * np.pi * 3.0 * time))  # fmt: skip
    stack = model.configurations[1].name
    fs.simulate(model, motion, configuration=stack, until_rest=True)
    fs.overturning(model, configuration=stack, frequencies=[2.0], amplitudes=[3.0])
    fs.mode_map(model, nodes=16)


if __name__ == "__main__":
    {"body": body, "planar": planar}[sys.argv[1]]()
