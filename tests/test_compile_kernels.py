"""The test set-up's removal of stale compiled kernels (``tests/compile_kernels.py``)."""

from __future__ import annotations

import os

from tests.compile_kernels import drop_stale_kernels


def _touch(path, mtime):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("")
    os.utime(path, (mtime, mtime))


def test_kernels_older_than_the_newest_core_source_are_removed_and_newer_ones_kept(tmp_path):
    package = tmp_path / "freestand"
    _touch(package / "core" / "contact" / "kernel.py", 1000.0)
    _touch(package / "core" / "dynamics" / "engine.py", 2000.0)  # edited last
    cache = package / "core" / "dynamics" / "__pycache__"
    stale = [cache / "engine.run-10.py311.nbi", cache / "engine.run-10.py311.1.nbc"]
    fresh = [cache / "engine.step-20.py311.nbi", cache / "engine.step-20.py311.1.nbc"]
    for path in stale:
        _touch(path, 1500.0)  # compiled before the edit: it may hold the old callee
    for path in fresh:
        _touch(path, 2500.0)
    other = cache / "engine.cpython-311.pyc"
    _touch(other, 1500.0)  # not numba's

    assert drop_stale_kernels(package) == 2
    assert not any(path.exists() for path in stale)
    assert all(path.exists() for path in fresh) and other.exists()
    assert drop_stale_kernels(package) == 0
