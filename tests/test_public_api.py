"""Every public module's ``__all__`` names what it defines; ``actors`` re-exports what it lists."""

from __future__ import annotations

import importlib
import pkgutil
import re
import subprocess
import sys
import types
from pathlib import Path

import pytest

import actors
import world
from actors.system import _exports

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
    # The names load on first use (see actors/__init__.py): dir() lists them before they have.
    # Submodules become attributes once imported; "@..." names are pytest's (it rewrites
    # the package of its actors.testing plugin).
    public = {
        name
        for name in dir(actors)
        if not name.startswith(("_", "@")) and not isinstance(getattr(actors, name), types.ModuleType)
    } - {"annotations", "TYPE_CHECKING", "Any"}
    assert set(actors.__all__) == public
    assert set(actors.__all__) == {name for name in vars(_exports) if not name.startswith(("_", "@"))}


def test_importing_actors_loads_none_of_the_runtime():
    # python -m actors.run and the actors command take signals before the runtime loads (#34).
    code = "import sys, actors; print(sorted(m for m in sys.modules if m.startswith(('actors.', 'anyio', 'asyncio'))))"
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert result.stdout.strip() == "[]"


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
