"""Every public name's docstring is numpydoc with an Examples section that runs as written.

The Examples are run from the repository's root (they read ``examples/``); the
result classes' methods that turn a result into a dict, a table or a figure
say what they return.
"""

from __future__ import annotations

import doctest
import inspect
from pathlib import Path

import matplotlib
import pytest

import freestand as fs

matplotlib.use("Agg")

ROOT = Path(__file__).resolve().parents[1]
NAMES = sorted(name for name in fs.__all__ if name != "__version__")
RESULTS = sorted(name for name in NAMES if inspect.isclass(getattr(fs, name)) and hasattr(getattr(fs, name), "to_frame"))  # fmt: skip


@pytest.mark.parametrize("name", NAMES)
def test_examples_section_runs(name, monkeypatch):
    obj = getattr(fs, name)
    assert "\nExamples\n--------\n" in inspect.cleandoc(obj.__doc__ or ""), f"fs.{name}"
    monkeypatch.chdir(ROOT)
    finder = doctest.DocTestFinder()  # the object and its methods
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE | doctest.ELLIPSIS)
    tests = [t for t in finder.find(obj, f"fs.{name}", globs={}) if t.examples]
    assert tests, f"fs.{name} has no example to run"
    for test in tests:
        runner.run(test)
    assert runner.summarize(verbose=False).failed == 0, f"fs.{name}"


@pytest.mark.parametrize("name", RESULTS)
def test_result_methods_say_what_they_return(name):
    cls = getattr(fs, name)
    for method in ("to_dict", "to_frame", "plot"):
        if hasattr(cls, method):
            doc = inspect.cleandoc(getattr(cls, method).__doc__ or "")
            assert "\nReturns\n-------\n" in doc, f"{name}.{method}"
