"""The package's architecture, checked from its imports: layers and no import circles."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

SOURCE = Path(__file__).resolve().parents[1] / "src"
CORE = SOURCE / "freestand" / "core"

#: What each layer may not import (a layer only consumes the ones below it).
FORBIDDEN = {
    "freestand.core": (
        "freestand.io",
        "freestand.plot",
        "freestand.report",
        "freestand.cli",
        "freestand.api",
    ),
    "freestand.io": ("freestand.plot", "freestand.report", "freestand.cli", "freestand.api"),
    "freestand.plot": ("freestand.report", "freestand.cli", "freestand.api"),
    "freestand.report": ("freestand.cli", "freestand.api"),
}

#: The concern folders of the core: the architecture at a glance.
CORE_FOLDERS = {"motion", "contact", "rocking", "structure", "dynamics", "sweeps"}


def _modules() -> dict[str, Path]:
    modules = {}
    for path in SOURCE.rglob("*.py"):
        name = ".".join(path.relative_to(SOURCE).with_suffix("").parts)
        modules[name.removesuffix(".__init__")] = path
    return modules


def _imports(path: Path, modules: dict[str, Path]) -> set[str]:
    """Every freestand module that ``path`` imports, at top level or inside functions."""
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            names = [node.module] + [f"{node.module}.{alias.name}" for alias in node.names]
        else:
            continue
        found.update(name for name in names if name in modules)
    return found


def _graph() -> dict[str, set[str]]:
    modules = _modules()
    graph = {}
    for name, path in modules.items():
        # a package's own submodules (and its parents) are not edges of a circle
        graph[name] = {
            target
            for target in _imports(path, modules)
            if target != name
            and not name.startswith(target + ".")
            and not target.startswith(name + ".")
        }
    return graph


def test_no_import_circles():
    graph = _graph()
    circles = []
    state: dict[str, int] = {}

    def visit(node: str, trail: list[str]) -> None:
        state[node] = 1
        for target in sorted(graph[node]):
            if state.get(target) == 1:
                circles.append(trail[trail.index(target) :] + [target])
            elif target not in state:
                visit(target, [*trail, target])
        state[node] = 2

    for node in sorted(graph):
        if node not in state:
            visit(node, [node])
    assert not circles, "import circles: " + "; ".join(" -> ".join(c) for c in circles)


@pytest.mark.parametrize("layer", sorted(FORBIDDEN))
def test_layers_only_consume_the_layers_below(layer):
    graph = _graph()
    wrong = sorted(
        f"{name} imports {target}"
        for name, targets in graph.items()
        if name == layer or name.startswith(layer + ".")
        for target in targets
        if any(target == f or target.startswith(f + ".") for f in FORBIDDEN[layer])
    )
    assert not wrong, "\n".join(wrong)


def test_the_core_is_laid_out_by_concern():
    folders = {p.name for p in CORE.iterdir() if p.is_dir() and (p / "__init__.py").exists()}
    assert CORE_FOLDERS <= folders
    flat = sorted(p.stem for p in CORE.glob("*.py") if p.stem != "__init__")
    # the model types (planar blocks and stacks; 3-D bodies) and their geometry are shared
    # by every concern; everything else sits in a folder by concern
    assert flat == ["body", "geometry", "model"], f"modules left flat in core/: {flat}"
