"""Where a graph's ``use = "module:Class"`` comes from: the graph's folder, the working directory, installed code.

The shipped tutorial nodes and world install inside actors, as ``actors.nodes``
and ``actors.world``, and the shipped graphs as ``actors.graphs``: nothing
named ``nodes`` or ``world`` is installed, so a user's own ``nodes/`` folder
or ``world.py`` never hides them, and they never hide the user's.  Graph
files keep saying ``use = "nodes.talker:MinimalPublisher"``; the top-level
name of a ``use`` (``nodes``) is looked for, in this order:

1. a shipped graph (one of ``actors.graphs``) uses the shipped code:
   ``nodes`` and ``world`` are ``actors.nodes`` and ``actors.world``;
2. the graph file's own folder, as running a script from there would;
3. the working directory;
4. installed packages (``sys.path``); ``nodes`` and ``world`` that are not
   found anywhere are the shipped ones.

The first place that has the name has every module under it: a ``nodes``
package (or namespace folder) found in the graph's folder is the only
``nodes`` of the run, and a module it lacks is an error, never filled in from
elsewhere.  When what it lacks is shipped, the error names both paths (yours
hides the shipped one), and so does a ``world.py`` that hides the shipped
``world`` package.
"""

from __future__ import annotations

import importlib
import importlib.machinery
import importlib.resources
import importlib.util
import os
import sys
import traceback
from pathlib import Path
from types import ModuleType

from actors.core._frames import is_users
from actors.core.explain import did_you_mean

__all__ = ["SHIPPED", "UseError", "shipped_graphs", "find_graph", "import_use"]

SHIPPED = {"nodes": "actors.nodes", "world": "actors.world"}
"""The shipped packages by the name graph files use for them."""


class UseError(ValueError):
    """A ``use`` that cannot be imported: the text says why, naming the paths involved."""


def shipped_graphs() -> Path:
    """The folder of the shipped graph files."""
    return Path(str(importlib.resources.files("actors.graphs")))


def find_graph(name: str | os.PathLike[str]) -> Path:
    """A graph file's path: ``name`` itself, or the shipped graph of that bare name (``turtlebot``).

    Raises FileNotFoundError naming the shipped graphs when a bare name is
    none of them.  A path is returned as it is, whether it exists or not.
    """
    path = Path(name)
    if path.suffix or path.parent != Path(".") or path.exists():
        return path
    known = sorted(p.stem for p in shipped_graphs().glob("*.toml"))
    if path.name in known:
        return shipped_graphs() / f"{path.name}.toml"
    raise FileNotFoundError(
        f"no graph file {path.name!r} here, nor a shipped graph of that name"
        f"{did_you_mean(path.name, known)}; the shipped graphs are {', '.join(known)}"
    )


def import_use(module_name: str, graph: Path | None = None) -> ModuleType:
    """Import ``module_name`` as the graph file ``graph`` names it (see the module docstring).

    Raises UseError when it cannot be imported.
    """
    top, _, rest = module_name.partition(".")
    if graph is not None and _is_shipped(graph) and top in SHIPPED:
        return _import(f"{SHIPPED[top]}.{rest}" if rest else SHIPPED[top])
    places = [graph.resolve().parent] if graph is not None else []
    places += [Path.cwd()]
    for place in dict.fromkeys(places):  # in order, once each
        spec = importlib.machinery.PathFinder.find_spec(top, [str(place)])
        if spec is not None:
            twin = _shipped_twin(module_name)
            if rest and not spec.submodule_search_locations and twin is not None:
                # A module, not a package: it holds no submodule (and is not run to find out).
                raise UseError(
                    f"{module_name}: your {os.path.basename(spec.origin or top)} ({_origin(spec)}) hides "
                    f"the shipped package {top} ({os.path.dirname(twin)}): rename yours, or write "
                    f"{SHIPPED[top]}.{rest}"
                )
            _adopt(top, spec, place)
            return _import(module_name, hidden=_shipped_twin(module_name))
    try:
        found = importlib.util.find_spec(top)
    except (ImportError, ValueError):
        found = None
    if found is None and top in SHIPPED:
        return _import(f"{SHIPPED[top]}.{rest}" if rest else SHIPPED[top])
    return _import(module_name, hidden=_shipped_twin(module_name))


def _is_shipped(graph: Path) -> bool:
    try:
        return graph.resolve().parent == shipped_graphs().resolve()
    except (OSError, ModuleNotFoundError):
        return False


def _adopt(top: str, spec: importlib.machinery.ModuleSpec, place: Path) -> None:
    """Make the ``top`` found in ``place`` the one of this process, importing it from there."""
    where = _origin(spec)
    loaded = sys.modules.get(top)
    if loaded is not None:
        if _module_origin(loaded) != where:
            raise UseError(
                f"{top} is already imported from {_module_origin(loaded)}; one process cannot also import {where}"
            )
        return
    if str(place) not in sys.path:
        sys.path.insert(0, str(place))  # its own imports of neighbours work, as a script's would
    module = importlib.util.module_from_spec(spec)
    sys.modules[top] = module
    try:
        if spec.loader is not None:
            spec.loader.exec_module(module)
    except Exception as exc:  # whatever the module raised while importing: one line, where it did
        del sys.modules[top]
        raise _cannot_import(top, exc) from None
    except BaseException:
        del sys.modules[top]
        raise


def _origin(spec: importlib.machinery.ModuleSpec) -> str:
    if spec.submodule_search_locations:
        return os.path.realpath(next(iter(spec.submodule_search_locations)))
    return os.path.realpath(spec.origin or "")


def _module_origin(module: ModuleType) -> str:
    paths = list(getattr(module, "__path__", []) or [])
    return os.path.realpath(paths[0] if paths else getattr(module, "__file__", "") or "")


def _shipped_twin(module_name: str) -> str | None:
    """The shipped module a ``nodes.x``/``world.x`` name would be, when one exists."""
    top, _, rest = module_name.partition(".")
    if top not in SHIPPED or not rest:
        return None
    twin = f"{SHIPPED[top]}.{rest}"
    try:
        spec = importlib.util.find_spec(twin)
    except (ImportError, ValueError):
        return None
    return spec.origin if spec is not None else None


def _import(module_name: str, hidden: str | None = None) -> ModuleType:
    """Import ``module_name``; a missing module says what hides the shipped one, if one does."""
    try:
        return importlib.import_module(module_name)
    except ModuleNotFoundError as exc:
        top = module_name.partition(".")[0]
        if hidden is not None and exc.name is not None and module_name.startswith(exc.name):
            mine = _module_origin(sys.modules[top]) if top in sys.modules else top
            raise UseError(
                f"{module_name} is not in your {top} ({mine}), which hides the shipped "
                f"{module_name} ({hidden}): write {SHIPPED[top]}.{module_name.partition('.')[2]} "
                f"to use the shipped one, or rename yours"
            ) from None
        raise _cannot_import(module_name, exc) from None
    except Exception as exc:  # whatever the module raised while importing
        raise _cannot_import(module_name, exc) from None


def _cannot_import(module_name: str, exc: Exception) -> UseError:
    """One line: what failed, and the user's line that raised it (the last of theirs in the traceback)."""
    theirs = [(frame, line) for frame, line in traceback.walk_tb(exc.__traceback__) if is_users(frame)]
    where = f" ({theirs[-1][0].f_code.co_filename}, line {theirs[-1][1]})" if theirs else ""
    return UseError(f"cannot import {module_name!r}: {exc}{where}")
