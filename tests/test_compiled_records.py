"""No compiled function keeps a record of a structured array it allocated itself.

numba frees a local array after its last use. A record taken from it
(``work = np.zeros(1, dtype=SOME_DTYPE)[0]``, or in two statements) is a
bare pointer into the array's memory and keeps nothing alive: the record's
fields then live in freed memory, which the next allocations reuse. The 3-D
engine's loop did this with its impulses' work record; its writes into the
freed block damaged the heap, and about one test run in four under pytest-xdist
aborted inside malloc, far from the cause. Such records are owned by the
caller (an argument: the caller holds it for the whole call).
"""

from __future__ import annotations

import ast
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[1] / "src" / "freestand"
COMPILED = {"kernel", "njit", "jit"}  # decorators of compiled functions (also as nb.njit ...)
ALLOCATORS = {"zeros", "empty", "ones", "full"}


def _decorator_name(node: ast.expr) -> str:
    if isinstance(node, ast.Call):
        node = node.func
    if isinstance(node, ast.Attribute):
        return node.attr
    return node.id if isinstance(node, ast.Name) else ""


def _structured_allocation(node: ast.expr) -> bool:
    """``np.zeros(..., dtype=X_DTYPE)`` and the like: an array of a structured dtype."""
    if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)):
        return False
    if node.func.attr not in ALLOCATORS:
        return False
    dtypes = [k.value for k in node.keywords if k.arg == "dtype"] + node.args[1:2]
    return any(ast.unparse(d).endswith("DTYPE") for d in dtypes)


def dangling_records(source: str) -> list[str]:
    """Where a compiled function in ``source`` binds a record of an array it allocated."""
    found = []
    for function in ast.walk(ast.parse(source)):
        if not isinstance(function, ast.FunctionDef):
            continue
        if not any(_decorator_name(d) in COMPILED for d in function.decorator_list):
            continue
        allocated = set()
        for node in ast.walk(function):
            if not isinstance(node, ast.Assign):
                continue
            value = node.value
            if _structured_allocation(value):
                allocated |= {t.id for t in node.targets if isinstance(t, ast.Name)}
            elif isinstance(value, ast.Subscript) and (
                _structured_allocation(value.value)
                or (isinstance(value.value, ast.Name) and value.value.id in allocated)
            ):
                found.append(f"{function.name}, line {node.lineno}: {ast.unparse(node)}")
    return found


def test_the_check_finds_a_record_of_a_local_array():
    source = (
        "@kernel(cache=True)\n"
        "def f(x):\n"
        "    held = np.zeros(1, dtype=WORK_DTYPE)\n"
        "    work = held[0]\n"
        "    other = np.empty(1, WORK_DTYPE)[0]\n"
        "    fine = x[0]\n"
        "    k = np.zeros(3)[0]\n"
        "    return work\n"
    )
    assert [f.split(":")[0] for f in dangling_records(source)] == ["f, line 4", "f, line 5"]


def test_no_compiled_function_keeps_a_record_of_its_own_array():
    found = [
        f"{path.relative_to(SOURCE)}: {where}"
        for path in sorted(SOURCE.rglob("*.py"))
        for where in dangling_records(path.read_text())
    ]
    assert not found, "records of arrays the function frees:\n" + "\n".join(found)
