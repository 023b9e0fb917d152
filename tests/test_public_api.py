"""Every public module's ``__all__`` names what it defines; ``actors`` re-exports what it lists."""

from __future__ import annotations

import importlib
import pkgutil
import re
import types
from pathlib import Path

import pytest

import actors
import world

MODULES = sorted(
    name
    for package in (actors, world)
    for _, name, _ in pkgutil.walk_packages(package.__path__, f"{package.__name__}.")
    if not name.rsplit(".", 1)[-1].startswith("_") and name not in {"actors.__main__", "actors.run"}
)


@pytest.mark.parametrize("name", MODULES)
def test_all_is_declared_and_exists(name):
    module = importlib.import_module(name)
    exported = getattr(module, "__all__", None)
    assert exported is not None, f"{name} has no __all__"
    missing = [n for n in exported if not hasattr(module, n)]
    assert missing == [], f"{name}.__all__ lists names it does not define: {missing}"
    assert len(set(exported)) == len(exported), f"{name}.__all__ has duplicates"


def test_actors_reexports_its_public_names():
    # Submodules become attributes once imported; "@..." names are pytest's (it rewrites
    # the package of its actors.testing plugin).
    public = {
        name
        for name, value in vars(actors).items()
        if not name.startswith(("_", "@")) and not isinstance(value, types.ModuleType)
    } - {"annotations"}
    assert set(actors.__all__) == public


def test_shipped_user_code_reaches_only_public_modules():
    # The line between public and internal: a module or package whose name starts with "_" is
    # internal.  What users copy (the shipped nodes and worlds, the scripts, the README) must
    # not cross it, or the line means nothing.
    root = Path(__file__).resolve().parent.parent
    sources = [*root.glob("nodes/*.py"), *root.glob("world/*.py"), *root.glob("scripts/*.py"), root / "README.md"]
    private = re.compile(r"\bactors(?:\.\w+)*\._\w+")
    crossings = [
        f"{path.relative_to(root)}: {match.group(0)}"
        for path in sources
        for match in private.finditer(path.read_text(encoding="utf-8"))
    ]
    assert crossings == []
