"""ROS packages as ``ros2 run``, ``ros2 pkg`` and ament_index see them, without colcon or a ROS install.

Three places hold packages; where a name is in several, the first wins, as a
colcon overlay wins over its underlay:

1. the workspaces (:func:`actors.messages.discovery.workspace_starts`: the
   working directory's, ``--workspace``'s, ``ACTORS_WORKSPACE``'s): every
   ``src/**/package.xml``;
2. the shipped packages: the folders of ``actors.packages`` (``packages/`` in
   the repository), each laid out as a workspace's ament_python package
   (``package.xml``, ``setup.cfg`` with its console scripts, ``launch/``...);
3. the prefixes of ``AMENT_PREFIX_PATH`` (a ROS install or a colcon
   ``install/``), through ament's resource index as ament_index_python reads it.

A package in a source folder (1 and 2) is not built: its executables are the
``console_scripts`` of its setup files (:mod:`actors.launch.setup_files`), and
its prefix is a folder in the cache where its ``data_files`` are symbolic
links to the sources, at the places colcon would install them (as ``colcon
build --symlink-install`` does): ``share/<pkg>/launch/x.launch.py`` is the
package's ``launch/x.launch.py`` when ``data_files`` says so, and an edited
file is seen at once.  The links are made again in each process, the first
time the package's prefix is asked for.
"""

from __future__ import annotations

import functools
import hashlib
import importlib.resources
import os
import threading
import xml.etree.ElementTree as ElementTree
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path, PurePosixPath

from actors.core.explain import did_you_mean
from actors.errors import PackageError
from actors.launch.setup_files import SetupInfo, read_setup
from actors.messages.discovery import cache_dir, workspace_packages, workspace_starts

__all__ = [
    "Package",
    "Executable",
    "packages",
    "find_package",
    "find_executable",
    "shipped_packages",
    "search_paths",
    "INDEX",
]

INDEX = PurePosixPath("share/ament_index/resource_index")
"""Where a prefix keeps ament's resource index (``packages/<name>`` marks a package)."""


@dataclass(frozen=True)
class Executable:
    """One executable of a package: a console script (``target`` is ``module:attr``) or an installed file."""

    package: str
    name: str
    target: str | None = None  # "module.path:function" of a package in a source folder
    path: Path | None = None  # the file under lib/<pkg>/ of an installed package


@dataclass(frozen=True)
class Package:
    """One package: its name, where it comes from, and its folders."""

    name: str
    origin: str  # "workspace", "shipped" or "installed"
    manifest: Path  # its package.xml
    source: Path | None  # its source folder (workspace and shipped packages)
    installed_prefix: Path | None = None  # its prefix, for an installed package

    @property
    def build_type(self) -> str:
        """``<export><build_type>`` of its package.xml (ament_cmake when it says none, as ament does)."""
        try:
            found = ElementTree.parse(self.manifest).findtext("export/build_type")
        except (ElementTree.ParseError, OSError):
            found = None
        return (found or "ament_cmake").strip()

    def setup(self) -> SetupInfo:
        """What its setup files declare (nothing for an installed package)."""
        if self.source is None:
            return SetupInfo()
        return _setup(self.source, *_stamps(self.source))

    @property
    def prefix(self) -> Path:
        """Its install prefix: the installed one, or the mapped one in the cache (made if needed)."""
        if self.installed_prefix is not None:
            return self.installed_prefix
        assert self.source is not None
        return _mapped_prefix(self.name, self.source, *_stamps(self.source))

    @property
    def share(self) -> Path:
        """``<prefix>/share/<name>``, where its data files are."""
        return self.prefix / "share" / self.name

    def executables(self) -> dict[str, Executable]:
        """Its executables by name, sorted: console scripts, or the files of an install's ``lib/<pkg>``."""
        if self.source is not None:
            scripts = self.setup().console_scripts
            return {name: Executable(self.name, name, target=scripts[name]) for name in sorted(scripts)}
        assert self.installed_prefix is not None
        folder = self.installed_prefix / "lib" / self.name
        if not folder.is_dir():
            return {}
        return {
            p.name: Executable(self.name, p.name, path=p)
            for p in sorted(folder.iterdir())
            if p.is_file() and os.access(p, os.X_OK)
        }


def shipped_packages() -> Path:
    """The folder of the packages shipped with actors (``packages/`` in the repository)."""
    return Path(str(importlib.resources.files("actors.packages")))


def packages() -> dict[str, Package]:
    """Every package found, by name, sorted; a workspace's hides a shipped one, which hides an installed one."""
    env = os.environ.get("AMENT_PREFIX_PATH", "")
    return _packages(workspace_starts(), env)


def find_package(name: str) -> Package:
    """The package ``name``; PackageError (with a did-you-mean) when there is none."""
    found = packages()
    if name in found:
        return found[name]
    raise PackageError(f"package {name!r} not found{did_you_mean(name, list(found))}{_where()}")


def find_executable(package: str, executable: str) -> Executable:
    """Executable ``executable`` of ``package``; PackageError naming the package's executables if none."""
    pkg = find_package(package)
    found = pkg.executables()
    if executable in found:
        return found[executable]
    known = list(found)
    listed = f"; its executables are {', '.join(known)}" if known else "; it has no executables"
    raise PackageError(
        f"no executable {executable!r} in package {package!r} ({pkg.manifest.parent}){did_you_mean(executable, known)}"
        f"{listed}"
    )


def search_paths() -> list[Path]:
    """Every prefix, first wins: each found package's (mapped ones made), then ``AMENT_PREFIX_PATH``'s."""
    env = [Path(p) for p in os.environ.get("AMENT_PREFIX_PATH", "").split(os.pathsep) if p]
    own = [pkg.prefix for pkg in packages().values() if pkg.installed_prefix is None]
    return [*own, *env]


def _where() -> str:
    starts = ", ".join(dict.fromkeys(str(start) for start in workspace_starts()))
    return f"; looked in the workspaces around {starts}, the shipped packages and AMENT_PREFIX_PATH"


def _packages(starts: tuple[Path, ...], env: str) -> dict[str, Package]:
    # Looked for again at each call (a package made a moment ago is there): a walk of a few folders.
    found: dict[str, Package] = {}
    for prefix in reversed([Path(p) for p in env.split(os.pathsep) if p]):
        for name, manifest in _indexed(prefix):
            found[name] = Package(name, "installed", manifest, None, prefix)
    for name, folder in _source_packages(shipped_packages()):
        found[name] = Package(name, "shipped", folder / "package.xml", folder)
    for start in reversed(starts):
        for name, folder in workspace_packages(start).items():
            found[name] = Package(name, "workspace", folder / "package.xml", folder)
    return dict(sorted(found.items()))


def _source_packages(root: Path) -> Iterator[tuple[str, Path]]:
    if root.is_dir():
        for folder in sorted(root.iterdir()):
            if (folder / "package.xml").is_file():
                try:
                    name = (ElementTree.parse(folder / "package.xml").findtext("name") or "").strip()
                except ElementTree.ParseError:
                    name = ""
                yield name or folder.name, folder


def _indexed(prefix: Path) -> Iterator[tuple[str, Path]]:
    index = prefix / INDEX / "packages"
    if index.is_dir():
        for marker in sorted(index.iterdir()):
            yield marker.name, prefix / "share" / marker.name / "package.xml"


def _stamps(folder: Path) -> tuple[tuple[int, int], ...]:
    # What tells an edited setup file: its modification time, and its size (two edits within the
    # file system's time resolution).
    def stamp(name: str) -> tuple[int, int]:
        try:
            found = (folder / name).stat()
        except OSError:
            return (0, 0)
        return found.st_mtime_ns, found.st_size

    return stamp("setup.py"), stamp("setup.cfg")


@functools.lru_cache(maxsize=256)
def _setup(folder: Path, *_stamps: tuple[int, int]) -> SetupInfo:
    return read_setup(folder)


@functools.lru_cache(maxsize=256)
def _mapped_prefix(name: str, folder: Path, *stamps: tuple[int, int]) -> Path:
    """Make (again) the prefix of the source package in ``folder``: its data files linked where colcon
    would install them, and its marker in the resource index."""
    setup = _setup(folder, *stamps)
    digest = hashlib.sha256(str(folder.resolve()).encode()).hexdigest()[:16]
    prefix = cache_dir() / "_prefixes" / digest / name
    wanted: dict[Path, Path] = {}
    where = folder / ("setup.py" if (folder / "setup.py").is_file() else "setup.cfg")
    for destination, sources in setup.data_files:
        if PurePosixPath(destination).is_absolute() or ".." in PurePosixPath(destination).parts:
            raise PackageError(f"{where}: data_files: {destination!r} is not a folder inside the install prefix")
        for source in sources:
            path = folder / source
            if not path.is_file():
                raise PackageError(f"{where}: data_files: no such file {source!r} (in {folder})")
            wanted[prefix / destination / path.name] = path.resolve()
    (prefix / "share" / name).mkdir(parents=True, exist_ok=True)
    marker = prefix / INDEX / "packages" / name
    if marker not in wanted and not marker.exists():
        marker.parent.mkdir(parents=True, exist_ok=True)
        marker.touch()
    for link, target in wanted.items():
        if link.is_symlink() and Path(os.readlink(link)) == target:
            continue
        link.parent.mkdir(parents=True, exist_ok=True)
        partial = link.with_name(f".{link.name}.{os.getpid()}.{threading.get_ident()}")
        partial.unlink(missing_ok=True)
        partial.symlink_to(target)
        os.replace(partial, link)
    for dirpath, _dirs, files in os.walk(prefix):
        for file in files:
            path = Path(dirpath) / file
            if path.is_symlink() and path not in wanted:
                path.unlink(missing_ok=True)  # a data file the setup files no longer list
    return prefix
