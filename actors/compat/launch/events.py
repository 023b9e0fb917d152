"""``launch.events``: what happens during a launch that handlers can act on."""

from __future__ import annotations

from typing import Any

from actors.compat.launch.entities import Event

__all__ = [
    "Shutdown",
    "ExecutionComplete",
    "RunningProcessEvent",
    "ProcessStarted",
    "ProcessExited",
    "ProcessIO",
    "ProcessStdout",
    "ProcessStderr",
    "process",
]


class Shutdown(Event):
    """Ask the launch to end: every node and process is stopped."""

    name = "launch.events.Shutdown"

    def __init__(self, *, reason: str = "reason not given", due_to_sigint: bool = False) -> None:
        self.reason = reason
        self.due_to_sigint = due_to_sigint


class ExecutionComplete(Event):
    """An action is done: at once for most, when its process ends for a process or a node."""

    name = "launch.events.ExecutionComplete"

    def __init__(self, *, action: Any) -> None:
        self.action = action


class RunningProcessEvent(Event):
    """Something about a started node or process: its action, name and pid."""

    def __init__(self, *, action: Any, name: str, pid: int) -> None:
        self.action = action
        self.process_name = name
        self.pid = pid


class ProcessStarted(RunningProcessEvent):
    """A node or process started."""

    name = "launch.events.process.ProcessStarted"


class ProcessExited(RunningProcessEvent):
    """A node or process ended, with ``returncode``."""

    name = "launch.events.process.ProcessExited"

    def __init__(self, *, action: Any, name: str, pid: int, returncode: int) -> None:
        super().__init__(action=action, name=name, pid=pid)
        self.returncode = returncode


class ProcessIO(RunningProcessEvent):
    """A line a process wrote: ``text`` (bytes, with its newline) on file descriptor ``fd``."""

    name = "launch.events.process.ProcessIO"

    def __init__(self, *, action: Any, name: str, pid: int, text: bytes, fd: int) -> None:
        super().__init__(action=action, name=name, pid=pid)
        self.text = text
        self.fd = fd

    @property
    def from_stdout(self) -> bool:
        """Whether it came on standard output."""
        return self.fd == 1

    @property
    def from_stderr(self) -> bool:
        """Whether it came on standard error."""
        return self.fd == 2


class ProcessStdout(ProcessIO):
    """A line on a process's standard output."""

    name = "launch.events.process.ProcessStdout"


class ProcessStderr(ProcessIO):
    """A line on a process's standard error."""

    name = "launch.events.process.ProcessStderr"


class _ProcessEvents:
    """``launch.events.process``: the process events by their module's names."""

    RunningProcessEvent = RunningProcessEvent
    ProcessStarted = ProcessStarted
    ProcessExited = ProcessExited
    ProcessIO = ProcessIO
    ProcessStdout = ProcessStdout
    ProcessStderr = ProcessStderr


process = _ProcessEvents()
