"""Partner scripts: more rclpy programs in the same runtime as the main one (``actors run --with``).

ROS runs an action server and its client as two programs, in two terminals.
``actors run --with server.py client.py`` runs both in one process and one
runtime (so they share the virtual clock): the partner starts first, on a
thread of its own, with rclpy's process-wide state of its own
(:mod:`~actors.compat.script_state`), and ``__name__ == "__main__"``.  The run
lasts as long as the main script.  When it ends by itself, each partner goes
on while it has work in hand (a callback running or queued, a goal executing, a
timer due: at most :data:`LINGER` seconds of runtime clock), as a server in the
other terminal would go on until Ctrl-C; then it is stopped as Ctrl-C stops an
rclpy program: its context shuts down, so its spin returns or raises
ExternalShutdownException.  Ctrl-C, and the end of ``--duration``, stop
partners at once.
"""

from __future__ import annotations

import shlex
import sys
import threading
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

from actors.compat.programs import Program, program_for
from actors.compat.rclpy.executors import ExternalShutdownException
from actors.compat.script_state import ScriptState, enter

if TYPE_CHECKING:
    from actors.compat.session import Session

__all__ = ["Partner", "LINGER", "parse_partner"]

LINGER = 10.0
"""Seconds of runtime clock a partner may go on with its callbacks after the main script ended."""

_POLL = 0.05  # seconds of runtime clock between looks at partners that are finishing


def parse_partner(spec: str) -> tuple[Program, list[str]]:
    """``"server.py --ros-args -r __node:=srv"`` or ``"PKG EXE ARGS"`` -> (program, arguments).

    ValueError for an empty or unquotable one; FileNotFoundError or PackageError
    (from :func:`~actors.compat.programs.program_for`) for one that is not there.
    """
    words = shlex.split(spec)
    if not words:
        raise ValueError("--with needs a script")
    return program_for(words)


class Partner:
    """One partner script: its thread, its rclpy state, and how it ended."""

    def __init__(
        self,
        session: Session,
        program: Program,
        argv: Sequence[str],
        report: Callable[[BaseException, Program], None],
        on_exit: Callable[[int], None] | None = None,
    ) -> None:
        self.program = program
        self.returncode: int | None = None
        self._on_exit = on_exit
        self.state = ScriptState(program.name, [program.argv0, *argv])
        self.failed = False
        self._session = session
        self._report = report
        self._stopping = False
        self._thread: threading.Thread | None = None

    def start(self) -> None:
        """Run the script on a thread of its own; it holds virtual time still until it first waits."""
        sys.path[:0] = [str(folder) for folder in self.program.paths]
        self._thread = self._session.start_thread(self._main, f"actors partner {self.program.name}")

    def _main(self) -> None:
        enter(self.state)  # a new thread starts with an empty context: this state is the script's alone
        code = 0
        try:
            self.program.run(main=False)
        except SystemExit as exc:
            self.failed = exc.code not in (None, 0)
            code = exc.code if isinstance(exc.code, int) else int(self.failed)
        except (KeyboardInterrupt, ExternalShutdownException):
            self.failed = not self._stopping
            code = int(self.failed)
        except BaseException as exc:
            self.failed = True
            code = 1
            self._report(exc, self.program)
        self.returncode = code
        if self._on_exit is not None:
            self._on_exit(code)

    @property
    def running(self) -> bool:
        """Whether the script has not ended yet."""
        return self._thread is not None and self._thread.is_alive()

    def busy(self, horizon: float) -> bool:
        """Whether it has work in hand: a callback of one of its nodes running or waiting to run, or a
        timer of theirs due within ``horizon`` seconds (a deferred goal starts on a timer)."""
        with self._session.lock:
            nodes = [node for context in self.state.contexts for ref in context._nodes if (node := ref()) is not None]
            if any(_has_work(node) for node in nodes):
                return True
            timers = [timer._native for node in nodes for timer in node._rclpy.timers]
        soonest = self._session.call(_soonest, timers) if timers and self._session.running else None
        return soonest is not None and soonest <= horizon * 1e9

    def finish(self, linger: float = LINGER, *, wait: bool = True) -> None:
        """Let it finish the work in hand (``linger`` seconds of runtime clock at most), then stop it as
        Ctrl-C would and (with ``wait``) give its script :data:`LINGER` seconds to end; then shut its
        contexts down."""
        self._wait_while(self.busy, linger)
        self._stopping = True
        for context in list(self.state.contexts):
            context.interrupt()
        self._wait_while(lambda _left: True, LINGER if wait else 0.0)
        for context in list(self.state.contexts):
            context.finish()

    def _wait_while(self, condition: Callable[[float], bool], limit: float) -> None:
        waited = 0.0
        while self.running and waited < limit and self._session.running and condition(limit - waited):
            self._session.sleep(_POLL)
            waited += _POLL


def _has_work(node: Any) -> bool:
    # With the session's lock held: a task of the node's executor not done (a callback running, a goal
    # executing), or work of the node's that no executor has taken yet.
    executor = node.executor
    if executor is None:
        return False
    return any(task._pending() for task, _, _ in executor._tasks) or any(
        source._ready() for source in node._rclpy.work_sources()
    )


def _soonest(timers: list[Any]) -> int | None:
    # On the runtime's thread: nanoseconds until the first of ``timers`` ticks, None if all are canceled.
    due = [ns for timer in timers if (ns := timer.time_until_next_call()) is not None]
    return min(due, default=None)
