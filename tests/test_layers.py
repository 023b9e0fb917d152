"""The import graph of ``actors``: no cycles, and every import points down the layers.

Every import counts, including those inside functions and under
``TYPE_CHECKING``: a lazy import still ties the two modules together.
"""

from __future__ import annotations

import ast
from pathlib import Path

import actors

ROOT = Path(actors.__file__).resolve().parent

# Lowest first.  A module may import its own layer and those below it, never above.  A layer is
# one package (``transport`` is two: its seam sits with the entities, its Zenoh implementation
# above the runtime) plus the root modules that belong to it.
LAYERS: list[tuple[str, set[str]]] = [
    ("core", {"core", "errors"}),
    ("messages", {"messages", "codec"}),
    ("ros", {"ros", "services", "transport"}),
    ("system", {"system", "runtime"}),
    ("launch", {"launch"}),
    ("ops", {"ops", "recording", "transport.zenoh"}),
    ("front", {"cli", "compat", "run", "testing", "__main__", "__init__"}),
]

# The modules that stay at the package's root: its entry points (``__init__``, ``__main__``,
# ``run`` for ``python -m actors.run``), the three the design fixes there (``runtime``, ``codec``,
# ``services``), the exception tree every layer raises from, and the pytest plugin, which
# pytest finds by the name ``actors.testing``.
ROOT_MODULES = {"__init__", "__main__", "run", "runtime", "codec", "services", "errors", "testing"}


def module_names() -> dict[str, Path]:
    names = {}
    for path in ROOT.rglob("*.py"):
        parts = path.relative_to(ROOT).with_suffix("").parts
        if parts[-1] == "__init__" and len(parts) > 1:
            parts = parts[:-1]
        names[".".join(parts)] = path
    return names


def imports_of(path: Path, package: str, known: set[str]) -> set[str]:
    """The modules of ``actors`` that ``path`` imports, by their names relative to the package."""
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            targets = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join(["actors", *[p for p in anchor if p], *([base] if base else [])])
            targets = [base, *(f"{base}.{alias.name}" for alias in node.names)]
        else:
            continue
        for target in targets:
            if not target.startswith("actors."):
                continue
            name = target.removeprefix("actors.")
            while name and name not in known:
                name = name.rpartition(".")[0]
            if name:
                found.add(name)
    return found


def graph() -> dict[str, set[str]]:
    names = module_names()
    result = {}
    for name, path in names.items():
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        result[name] = imports_of(path, package, set(names)) - {name}
    return result


def unit_of(name: str) -> str:
    """The listed package (or root module) that holds module ``name``: the longest listed prefix."""
    parts = name.split(".")
    for end in range(len(parts), 0, -1):
        prefix = ".".join(parts[:end])
        if any(prefix in members for _, members in LAYERS):
            return prefix
    raise AssertionError(f"actors.{name} belongs to no layer: add its package to LAYERS in {__file__}")


def layer_of(name: str) -> int:
    unit = unit_of(name)
    return next(i for i, (_, members) in enumerate(LAYERS) if unit in members)


def test_every_module_has_a_layer():
    for name in graph():
        layer_of(name)


def test_imports_point_down_the_layers():
    upward = [
        f"actors.{name} (layer {layer_of(name)}) imports actors.{target} (layer {layer_of(target)})"
        for name, targets in graph().items()
        for target in targets
        if layer_of(target) > layer_of(name)
    ]
    assert upward == []


def test_the_root_holds_only_entry_points_and_the_fixed_modules():
    root = {name for name, path in module_names().items() if "." not in name and path.name != "__init__.py"}
    root |= {"__init__"}
    assert root - ROOT_MODULES == set(), "a module at actors/ root that belongs in a package"


def find_cycles(edges: dict[str, set[str]]) -> list[str]:
    cycles = []
    state: dict[str, int] = {}  # 1 while on the current path, 2 when done
    path: list[str] = []

    def visit(name: str) -> None:
        state[name] = 1
        path.append(name)
        for target in sorted(edges[name]):
            if state.get(target) == 1:
                cycles.append(" -> ".join([*path[path.index(target) :], target]))
            elif target not in state:
                visit(target)
        path.pop()
        state[name] = 2

    for name in sorted(edges):
        if name not in state:
            visit(name)
    return cycles


def test_the_import_graph_has_no_cycle():
    assert find_cycles(graph()) == []


def test_no_cycle_across_layers_or_packages():
    # A root module counts as part of its layer's package (services.py is the entities'); the
    # front's root modules (run, testing, __main__) are units of their own beside cli and compat.
    def home(name: str) -> str:
        unit = unit_of(name)
        package = LAYERS[layer_of(name)][0]
        return package if unit in ROOT_MODULES and package in LAYERS[layer_of(name)][1] else unit

    packages: dict[str, set[str]] = {}
    for name, targets in graph().items():
        packages.setdefault(home(name), set()).update(home(t) for t in targets)
    assert find_cycles({p: targets - {p} for p, targets in packages.items()}) == []
