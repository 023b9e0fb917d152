"""rclpy's process-wide state (the default context, the global executor, ``sys.argv``), one set per script.

rclpy keeps one default context and one global executor per process: a
program calls ``rclpy.init()`` once and ``rclpy.shutdown()`` ends everything.
``actors run --with PARTNER.py SCRIPT.py`` runs several programs in one
process, as ROS runs them in several: each runs in its own
:class:`ScriptState`, so one program's ``rclpy.shutdown()`` or second
``rclpy.init()`` never touches another's, and ``sys.argv`` (a
:class:`ScriptArgv` while partners run) shows each its own command line.

The state follows the script through a context variable: the script's
thread, the threads of its executors (which run each callback in a copy of the
spinning thread's context) and its asyncio tasks see it.  A thread the script
starts itself begins with an empty context and sees the process's state: the
main script's.
"""

from __future__ import annotations

import sys
from collections.abc import MutableSequence
from contextvars import ContextVar
from typing import Any, overload

__all__ = ["ScriptState", "ScriptArgv", "script_state", "enter"]


class ScriptState:
    """One script's rclpy globals: its default context(s), its global executor, its ``sys.argv``."""

    __slots__ = ("name", "_argv", "contexts", "executors")

    def __init__(self, name: str, argv: list[str] | None = None) -> None:
        self.name = name
        self._argv = argv
        self.contexts: list[Any] = []  # the default context, made on first use
        self.executors: list[Any] = []  # the global executor, made on first use

    @property
    def argv(self) -> MutableSequence[str]:
        """The script's command line (``rclpy.init()`` reads its ROS arguments); the process's by default."""
        return sys.argv if self._argv is None else self._argv


_process = ScriptState("the process")
_current: ContextVar[ScriptState] = ContextVar("actors_compat_script_state", default=_process)


def script_state() -> ScriptState:
    """The state of the script the calling code runs for."""
    return _current.get()


def enter(state: ScriptState) -> None:
    """Make ``state`` the calling context's from now on (at the start of a partner script's thread)."""
    _current.set(state)


class ScriptArgv(MutableSequence[str]):
    """``sys.argv`` while partner scripts run: each script's code sees its own command line.

    The main script's is ``main``; a partner's is its :class:`ScriptState`'s.
    Not a ``list`` (C code would read a list's own items, not this one's).
    """

    def __init__(self, main: list[str]) -> None:
        self._main = main

    def _items(self) -> list[str]:
        own = _current.get()._argv
        return self._main if own is None else own

    @overload
    def __getitem__(self, index: int) -> str: ...

    @overload
    def __getitem__(self, index: slice) -> list[str]: ...

    def __getitem__(self, index: int | slice) -> str | list[str]:
        return self._items()[index]

    def __setitem__(self, index: Any, value: Any) -> None:
        self._items()[index] = value

    def __delitem__(self, index: int | slice) -> None:
        del self._items()[index]

    def __len__(self) -> int:
        return len(self._items())

    def insert(self, index: int, value: str) -> None:
        """Insert ``value`` into the calling script's command line."""
        self._items().insert(index, value)

    def __eq__(self, other: object) -> bool:
        return self._items() == (list(other) if isinstance(other, ScriptArgv) else other)

    def __repr__(self) -> str:
        return repr(self._items())
