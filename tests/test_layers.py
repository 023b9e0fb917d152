"""The import graph of ``actors``: no cycles, and every import points down the layers.

Every import counts, including those inside functions and under
``TYPE_CHECKING``: a lazy import still ties the two modules together.
"""

from __future__ import annotations

import ast
from pathlib import Path

import actors

ROOT = Path(actors.__file__).resolve().parent

# Lowest first.  A module may import its own layer and those below it, never above.
LAYERS: list[set[str]] = [
    {"errors", "log", "names", "clock", "actor", "config", "idl", "idl_gen", "codec", "rosargs", "layout", "cdr",
     "typehash", "snapshot", "qos", "explain", "parameter"},
    {"topics", "services", "timers", "params", "actions", "endpoint_info", "refusals", "qos_events", "transport",
     "param_services", "logger_services"},
    {"node", "node_params", "node_graph", "param_client"},
    {"supervisor", "runtime", "introspection", "graph", "use"},
    {"control", "connections", "doctor", "transport.zenoh", "recording"},
    {"run", "testing", "cli", "__main__", "__init__", "compat"},
]


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


def layer_of(name: str) -> int:
    # The longest listed prefix decides: "transport" holds the seam, "transport.zenoh" sits higher.
    parts = name.split(".")
    for end in range(len(parts), 0, -1):
        prefix = ".".join(parts[:end])
        for index, layer in enumerate(LAYERS):
            if prefix in layer:
                return index
    raise AssertionError(f"actors.{name} belongs to no layer: add it to LAYERS in {__file__}")


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


def test_the_import_graph_has_no_cycle():
    edges = graph()
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
    assert cycles == []
