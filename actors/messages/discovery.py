"""Interface packages found where ROS keeps them, typed on first import: no generate step.

A package of ``.msg``/``.srv``/``.action`` files is importable as
``interfaces.<pkg>.msg`` (``.srv``, ``.action``) wherever it is found:

- in the shipped ``interfaces`` folder (its committed modules, found first by
  Python's own import system);
- in a ROS workspace: ``<ws>/src/**/package.xml`` with ``msg/``, ``srv/`` or
  ``action/`` beside it, the workspace found by walking up from the working
  directory, from each folder given to :func:`add_workspace` (``actors run``
  gives the script's, ``actors.run`` the graph's, ``--workspace`` its own),
  and from each folder of ``ACTORS_WORKSPACE`` (``os.pathsep``-separated);
  the package is named by ``<name>`` in its ``package.xml``, as ament names it;
- in a ROS install: ``share/<pkg>/msg|srv|action`` under each prefix of
  ``AMENT_PREFIX_PATH``.

- in a bag: :func:`add_definitions` keeps the message types a bag's
  ``ros2msg`` schemas define and nothing here knows, as ``.msg`` files in
  the cache folder's ``bags/share``, read like a ROS install by every
  process after (so a foreign bag plays, and its topics echo).

A workspace's package wins over an installed one of the same name, as a
colcon overlay does, and an installed one over a bag's; a shipped package
wins over all.  The rclpy overlay
makes ``<pkg>.msg`` an alias of ``interfaces.<pkg>.msg``, so a type is one
class whatever the route.  The generated source is kept in a cache folder
(``ACTORS_INTERFACE_CACHE``, else ``$XDG_CACHE_HOME/actors/interfaces``, else
``~/.cache/actors/interfaces``) under a digest of the package's sources and of
the generator, so a later import only reads the sources to check the digest
and loads Python's compiled copy.  A malformed source is an ImportError
whose message names the file and line (:class:`InterfaceImportError`).
"""

from __future__ import annotations

import functools
import hashlib
import importlib.abc
import importlib.machinery
import importlib.util
import os
import threading
import xml.etree.ElementTree as ElementTree
from collections.abc import Iterator, Sequence
from pathlib import Path
from types import ModuleType

from actors.errors import InterfaceError
from actors.messages import generate, idl
from actors.messages.idl import IdlError, shipped_root

__all__ = [
    "KINDS",
    "InterfaceImportError",
    "add_workspace",
    "cache_dir",
    "add_definitions",
    "discovered",
    "find_spec",
    "package_sources",
    "workspace_starts",
    "workspace_packages",
]

KINDS = ("msg", "srv", "action")
_TOP = "interfaces"
_SKIPPED = frozenset({"build", "install", "log", "node_modules", "__pycache__"})
_DEPTH = 4  # how deep under src/ a package.xml is looked for


class InterfaceImportError(ImportError):
    """A discovered interface package whose sources cannot be typed: the message names file and line."""


_lock = threading.RLock()
_starts: list[Path] = []  # folders given by add_workspace, newest first
_found: dict[tuple[object, ...], dict[str, Path]] = {}  # discovered() by what it depends on


def add_workspace(folder: str | Path) -> None:
    """Look for interface packages in the workspace around ``folder`` too (newest first wins).

    Raises InterfaceError when ``folder`` is not a folder.
    """
    path = Path(folder).resolve()
    if not path.is_dir():
        raise InterfaceError(f"{folder}: no such workspace folder")
    with _lock:
        if path in _starts:
            _starts.remove(path)
        _starts.insert(0, path)
        _found.clear()  # looked for again, so a package added since is seen


def discovered() -> dict[str, Path]:
    """Every interface package found outside the shipped folder: name to the folder holding its kinds.

    Found again when the folders to look in change (the working directory, the
    environment), after :func:`add_workspace` (even of a folder named before:
    a package added since is seen then) and after a bag taught a new type.
    """
    env = (os.environ.get("ACTORS_WORKSPACE", ""), os.environ.get("AMENT_PREFIX_PATH", ""))
    starts = workspace_starts()
    bags = _bag_prefix()
    key = (starts, env, bags)
    with _lock:
        found = _found.get(key)
        if found is None:
            found = dict(_installed(bags))
            for prefix in reversed([p for p in env[1].split(os.pathsep) if p]):
                found.update(_installed(Path(prefix)))
            for start in reversed(starts):  # the first start wins: it is updated last
                found.update(_workspace(start))
            shipped = _shipped()
            found = {name: folder for name, folder in found.items() if name not in shipped}
            _found.clear()
            _found[key] = found
        return found


def workspace_starts() -> tuple[Path, ...]:
    """Where workspaces are looked for, first wins: :func:`add_workspace`'s folders (newest first),
    ``ACTORS_WORKSPACE``'s, then the working directory."""
    env = os.environ.get("ACTORS_WORKSPACE", "")
    with _lock:
        given = tuple(_starts)
    return (*given, *(Path(p) for p in env.split(os.pathsep) if p), Path.cwd())


def package_sources(folder: Path) -> dict[str, list[Path]]:
    """A package folder's interface files by kind, sorted."""
    return {kind: files for kind in KINDS if (files := sorted((folder / kind).glob(f"*.{kind}")))}


def cache_dir() -> Path:
    """Where generated sources of discovered packages are kept."""
    explicit = os.environ.get("ACTORS_INTERFACE_CACHE")
    if explicit:
        return Path(explicit)
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "actors" / "interfaces"


def _bag_prefix() -> Path:
    return cache_dir() / "bags"


def add_definitions(ros_type: str, schema: str) -> None:
    """Keep the message types of a bag's ``ros2msg`` schema (``ros_type``'s text, then
    ``MSG: pkg/Name`` sections) that nothing here defines.

    A type a shipped, workspace or installed package defines is left alone (the
    player then compares type hashes).  Raises InterfaceError for a schema that
    is not ``ros2msg`` text.
    """
    rule = "\n" + "=" * 80 + "\n"
    sections = schema.split(rule)
    named = [(ros_type, sections[0])]
    for section in sections[1:]:
        head, _, text = section.partition("\n")
        if not head.startswith("MSG: "):
            raise InterfaceError(f"{ros_type}: its bag schema has a section without 'MSG: <type>': {head[:60]!r}")
        named.append((head.removeprefix("MSG: ").strip(), text))
    known = {**discovered(), **{name: shipped_root() / name for name in _shipped()}}
    for name, text in named:
        parts = name.split("/")
        if len(parts) == 2:
            parts.insert(1, "msg")
        if len(parts) != 3 or parts[1] != "msg" or not idl.PACKAGE_NAME.fullmatch(parts[0]):
            continue  # services and actions are not topics' types; a malformed name defines nothing
        pkg, _, type_name = parts
        if not idl.TYPE_NAME.fullmatch(type_name):
            continue
        folder = known.get(pkg)
        bag_folder = _bag_prefix() / "share" / pkg
        if folder is not None and folder != bag_folder:
            continue  # its package is here already: a type it lacks is not added to it
        path = bag_folder / "msg" / f"{type_name}.msg"
        if not path.is_file() or path.read_text(encoding="utf-8") != text:
            path.parent.mkdir(parents=True, exist_ok=True)
            partial = path.with_suffix(f".{os.getpid()}.tmp")
            partial.write_text(text, encoding="utf-8")
            os.replace(partial, path)
            with _lock:
                _found.clear()  # a package may have appeared in the bags' folder


def _shipped() -> frozenset[str]:
    root = shipped_root()
    return frozenset(p.name for p in root.iterdir() if (p / "__init__.py").is_file())


def _installed(prefix: Path) -> Iterator[tuple[str, Path]]:
    share = prefix / "share"
    if share.is_dir():
        for folder in sorted(share.iterdir()):
            if idl.PACKAGE_NAME.fullmatch(folder.name) and any((folder / kind).is_dir() for kind in KINDS):
                yield folder.name, folder


def _workspace(start: Path) -> dict[str, Path]:
    """The interface packages of the workspace around ``start``."""
    found = workspace_packages(start)
    return {name: path for name, path in found.items() if any((path / kind).is_dir() for kind in KINDS)}


def workspace_packages(start: Path) -> dict[str, Path]:
    """Every package of the workspace around ``start``, name to folder: the package ``start`` is in,
    and those of the first ``src/`` found walking up (at most four folders deep under it).

    A package is a folder with a ``package.xml``, named by its ``<name>`` (else its folder's).
    """
    found: dict[str, Path] = {}
    for folder in (start, *start.parents):
        if (folder / "package.xml").is_file():
            found.setdefault(*_package(folder))
        src = folder / "src"
        if src.is_dir():
            for manifest in _manifests(src, _DEPTH):
                found.setdefault(*_package(manifest.parent))
            break
    return found


def _manifests(folder: Path, depth: int) -> Iterator[Path]:
    try:
        entries = sorted(folder.iterdir())
    except OSError:
        return
    if (folder / "package.xml").is_file():
        yield folder / "package.xml"
        return  # packages do not nest
    if depth:
        for entry in entries:
            if entry.is_dir() and not entry.name.startswith(".") and entry.name not in _SKIPPED:
                yield from _manifests(entry, depth - 1)


def _package(folder: Path) -> tuple[str, Path]:
    """A package's name (``<name>`` in its package.xml, else its folder's) and folder."""
    try:
        name = (ElementTree.parse(folder / "package.xml").findtext("name") or "").strip()
    except (ElementTree.ParseError, OSError):
        name = ""
    return (name if idl.PACKAGE_NAME.fullmatch(name) else folder.name), folder


def _modules(packages: dict[str, Path]) -> dict[str, str]:
    """Where every known message and service is defined (what a generated module imports)."""
    shipped = [(name, _TOP, package_sources(shipped_root() / name)) for name in sorted(_shipped())]
    found = [(name, _TOP, package_sources(folder)) for name, folder in packages.items()]
    return generate.module_map([*shipped, *found])


@functools.cache
def _generator_digest() -> bytes:
    here = Path(generate.__file__).parent
    return hashlib.sha256(b"".join((here / name).read_bytes() for name in ("generate.py", "idl.py"))).digest()


class _Finder(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Serves ``interfaces.<pkg>`` and ``interfaces.<pkg>.<kind>`` for discovered packages.

    It sits after Python's own finders, so shipped or generated files win.
    """

    def find_spec(
        self, fullname: str, path: Sequence[str] | None = None, target: ModuleType | None = None
    ) -> importlib.machinery.ModuleSpec | None:
        parts = fullname.split(".")
        if parts[0] != _TOP or not 2 <= len(parts) <= 3:
            return None
        packages = discovered()
        folder = packages.get(parts[1])
        if folder is None:
            return None
        if len(parts) == 2:
            spec = importlib.machinery.ModuleSpec(fullname, self, is_package=True)
            spec.submodule_search_locations = []
            return spec
        kind = parts[2]
        sources = package_sources(folder).get(kind)
        if sources is None:
            return None
        cached = self._cached(parts[1], kind, sources, packages)
        return importlib.util.spec_from_file_location(fullname, cached)

    def create_module(self, spec: importlib.machinery.ModuleSpec) -> ModuleType | None:
        return None  # the default module; exec_module gives it a docstring

    def exec_module(self, module: ModuleType) -> None:
        pkg = module.__name__.split(".")[1]
        module.__doc__ = f"The {pkg} interface package, found at {discovered()[pkg]}."

    def _cached(self, pkg: str, kind: str, sources: list[Path], packages: dict[str, Path]) -> Path:
        """The generated module's file, made when its sources or the generator changed."""
        digest = hashlib.sha256(_generator_digest())
        for source in sources:
            digest.update(source.name.encode() + b"\0" + source.read_bytes() + b"\0")
        path = cache_dir() / pkg / f"{kind}_{digest.hexdigest()[:20]}.py"
        if path.is_file():
            return path
        try:
            text = generate.render_kind(pkg, kind, sources, _modules(packages))
        except (IdlError, InterfaceError) as error:
            raise InterfaceImportError(str(error), name=f"{_TOP}.{pkg}.{kind}") from None
        path.parent.mkdir(parents=True, exist_ok=True)
        partial = path.with_suffix(f".{os.getpid()}.tmp")
        partial.write_text(text, encoding="utf-8")
        os.replace(partial, path)  # another process making the same file writes the same text
        return path


_finder = _Finder()
#: The finder's ``find_spec``: ``interfaces/__init__.py`` puts a finder after Python's own that
#: imports this module and asks it, on the first import the shipped folder cannot answer.
find_spec = _finder.find_spec
