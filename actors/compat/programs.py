"""What ``actors run`` runs: an rclpy script file, or a package's executable as ``ros2 run`` finds it.

A package's executable is one of three things:

- a console script of a package in a source folder (``module:function`` in its
  setup files): its package folder goes first on ``sys.path`` (as an install's
  ``site-packages`` would hold its module) and ``sys.exit(function())`` runs, as
  the wrapper setuptools writes does;
- the same, naming an :class:`actors.Node` subclass instead of a function: a
  native node, spawned in the runtime with its ``--ros-args`` (name, namespace,
  remappings, parameters) and run until the run ends;
- a file of an installed package's ``lib/<pkg>/`` that is a Python program (a
  colcon-installed console script): run as a script, with its prefix's
  ``site-packages`` on ``sys.path``.  Any other file (a compiled program) is a
  PackageError: actors runs Python only.
"""

from __future__ import annotations

import builtins
import importlib
import runpy
import sys
from abc import ABC, abstractmethod
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from actors.compat.rclpy.context import current_session
from actors.compat.session import Session
from actors.errors import PackageError
from actors.launch.packages import Executable, find_executable, find_package
from actors.launch.rosargs import parse
from actors.ros.log import set_logger_level
from actors.ros.node import Node

__all__ = [
    "Program",
    "ScriptProgram",
    "EntryPointProgram",
    "program_for",
    "program_of",
    "load_target",
    "run_native",
    "spawn_native",
]


class Program(ABC):
    """A program to run on the main thread (or a partner's), under the overlay."""

    name: str  # the runtime's name, and what messages call the program
    argv0: str  # sys.argv[0] while it runs
    paths: Sequence[Path] = ()  # put first on sys.path while it runs

    @abstractmethod
    def run(self, *, main: bool = True) -> None:
        """Run it to its end; raises what it raises (SystemExit with its exit code).

        ``main``: on the main thread, the only program of the process that owns
        ``sys.modules["__main__"]``; a partner's script gets a ``__main__`` namespace of its own.
        """

    @abstractmethod
    def owns(self, filename: str) -> bool:
        """Whether a traceback frame of ``filename`` is the program's own (where a shown traceback starts)."""


class ScriptProgram(Program):
    """A Python file, run as ``python FILE`` runs it (``__name__ == "__main__"``)."""

    def __init__(self, path: Path, paths: Sequence[Path] = ()) -> None:
        self.path = path
        self.name = path.stem
        self.argv0 = str(path)
        self.paths = (path.resolve().parent, *paths)

    def run(self, *, main: bool = True) -> None:
        if main:
            runpy.run_path(str(self.path), run_name="__main__")
            return
        code = compile(self.path.read_bytes(), str(self.path), "exec")
        exec(code, {"__name__": "__main__", "__file__": str(self.path), "__builtins__": builtins})

    def owns(self, filename: str) -> bool:
        return Path(filename).resolve() == self.path.resolve()


class EntryPointProgram(Program):
    """A console script ``module:attr`` of a package in a source folder."""

    def __init__(self, executable: Executable, folder: Path) -> None:
        assert executable.target is not None
        self.executable = executable
        self.name = executable.name
        self.argv0 = str(folder / executable.name)
        self.paths = (folder,)
        self.folder = folder

    def run(self, *, main: bool = True) -> None:
        target = load_target(self.executable)
        if isinstance(target, type) and issubclass(target, Node):
            run_native(target, self.executable.name)
            return
        sys.exit(target())

    def owns(self, filename: str) -> bool:
        return Path(filename).resolve().is_relative_to(self.folder.resolve())


def load_target(executable: Executable) -> Any:
    """Import what a console script names; PackageError when it cannot be had."""
    assert executable.target is not None
    module_name, _, attr = executable.target.partition(":")
    where = f"executable {executable.name!r} of package {executable.package!r} ({executable.target})"
    try:
        target: Any = importlib.import_module(module_name)
    except ModuleNotFoundError as exc:
        if exc.name is not None and (module_name == exc.name or module_name.startswith(f"{exc.name}.")):
            raise PackageError(f"{where}: no module named {exc.name!r}") from None
        raise
    for part in attr.split("."):
        if not hasattr(target, part):
            raise PackageError(f"{where}: module {module_name!r} has no {attr!r}")
        target = getattr(target, part)
    if not callable(target):
        raise PackageError(f"{where}: {attr!r} is not a function")
    return target


def run_native(cls: type[Node], executable: str, params: dict[str, Any] | None = None) -> None:
    """Spawn ``cls`` in the current run with the program's ``--ros-args``, and wait until the run ends.

    ``params`` come from the program's own arguments (a tool's command line);
    ``--ros-args -p`` overrides them.  Raises PackageError outside ``actors run``.
    """
    session = current_session()
    if session is None:
        raise PackageError(f"{executable}: a native node runs under actors run or actors launch")
    from actors.compat.rclpy.utilities import get_default_context

    spawn_native(session, cls, executable, sys.argv[1:], params)
    # Until the run ends (Ctrl-C, --duration, a failure) or the launcher stops this program as it
    # stops an rclpy one, by interrupting its context (a partner, once the main program has ended).
    context = get_default_context()
    waiter = session.waiter()
    context.add_waker(waiter)
    session.wait_until(lambda: context.interrupted, None, waiter)


def spawn_native(
    session: Session, cls: type[Node], executable: str, argv: Sequence[str], params: dict[str, Any] | None = None
) -> Node:
    """Spawn ``cls`` in the session's runtime with the name, namespace, remappings and parameters its
    ``--ros-args`` in ``argv`` give it (over ``params``); RosArgsError for malformed ones."""
    from actors.launch.graph_file import default_node_name

    ros_args, _ = parse(argv)
    setup = ros_args.for_node(default_node_name(cls) or executable, None)
    given = {**(params or {}), **setup.params}
    # Before the spawn: a constructor's own log lines (turtlesim's "Starting ...") obey the level.
    # The default level is this program's node's alone: its partners share the process, not its arguments.
    own_logger = f"{setup.namespace.strip('/')}/{setup.name}".strip("/").replace("/", ".")
    for logger, level in ros_args.log_levels.items():
        set_logger_level(logger or own_logger, level)
    return session.call(
        lambda: session.runtime.spawn(cls, name=setup.name, namespace=setup.namespace, params=given, remap=setup.remap)
    )


def program_of(executable: Executable, folder: Path | None, prefix: Path | None) -> Program:
    """The program that runs ``executable`` of the package in ``folder`` (sources) or at ``prefix`` (an install)."""
    if executable.target is not None:
        assert folder is not None
        return EntryPointProgram(executable, folder)
    assert executable.path is not None and prefix is not None
    return _installed_program(executable.path, prefix)


def program_for(words: Sequence[str]) -> tuple[Program, list[str]]:
    """The program ``actors run`` names and its arguments: ``SCRIPT.py ARGS`` or ``PKG EXE ARGS``.

    A first word that is a file, or ends in ``.py``, is a script; otherwise it
    names a package and the second word its executable.  Raises PackageError
    (no such package or executable, or one actors cannot run) or
    FileNotFoundError (no such script).
    """
    first, rest = words[0], list(words[1:])
    path = Path(first)
    if path.is_file() or path.suffix == ".py" or "/" in first:
        if not path.is_file():
            raise FileNotFoundError(f"{first}: no such script")
        return ScriptProgram(path), rest
    if not rest or rest[0].startswith("-"):
        package = find_package(first)  # a name that is no package says so first
        raise PackageError(f"actors run {first}: name one of package {package.name!r}'s executables after it")
    executable = find_executable(first, rest[0])
    package = find_package(first)
    return program_of(executable, package.source, package.installed_prefix), rest[1:]


def _installed_program(path: Path, prefix: Path) -> Program:
    head = path.read_bytes()[:256]
    first_line = head.split(b"\n", 1)[0]
    if not (first_line.startswith(b"#!") and b"python" in first_line):
        raise PackageError(f"{path}: not a Python program: actors runs Python executables only")
    site = sorted((prefix / "lib").glob("python3*/site-packages"))
    return ScriptProgram(path, site)
