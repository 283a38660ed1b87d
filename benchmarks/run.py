"""Run every benchmark script in this folder and print its figures.

Usage: ``make bench`` (or ``python benchmarks/run.py [NAME ...]``).
Benchmarks are kept apart from the tests: they print timings, they never
assert them.
"""

from __future__ import annotations

import importlib.util
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent

#: Benchmarks that need an optional dependency (``pip install -e ".[bench]"``).
OPTIONAL = {"mujoco_rocking": "mujoco", "engine": "mujoco", "mujoco_body": "mujoco"}
#: Tools kept beside the benchmarks, run by hand with arguments (their docstrings say how).
TOOLS = {"body_sweep"}


def main(names: list[str]) -> int:
    scripts = sorted(p for p in HERE.glob("*.py") if p.name != "run.py" and p.stem not in TOOLS)
    if names:
        scripts = [p for p in scripts if p.stem in names]
    status = 0
    for script in scripts:
        print(f"=== {script.stem}", flush=True)
        module = OPTIONAL.get(script.stem)
        if module and importlib.util.find_spec(module) is None:
            print(f"skipped: needs {module} (pip install -e '.[bench]')", flush=True)
            continue
        result = subprocess.run([sys.executable, str(script)], check=False)
        status = status or result.returncode
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
