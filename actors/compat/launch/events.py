"""``launch.events``: what happens during a launch that handlers can act on."""

from __future__ import annotations

from typing import Any

from actors.compat.launch.entities import Event

__all__ = ["Shutdown", "ProcessStarted", "ProcessExited", "process"]


class Shutdown(Event):
    """Ask the launch to end: every node and process is stopped."""

    name = "launch.events.Shutdown"

    def __init__(self, *, reason: str = "reason not given", due_to_sigint: bool = False) -> None:
        self.reason = reason
        self.due_to_sigint = due_to_sigint


class ProcessStarted(Event):
    """A node or process started."""

    name = "launch.events.process.ProcessStarted"

    def __init__(self, *, action: Any, name: str, pid: int) -> None:
        self.action = action
        self.process_name = name
        self.pid = pid


class ProcessExited(ProcessStarted):
    """A node or process ended, with ``returncode``."""

    name = "launch.events.process.ProcessExited"

    def __init__(self, *, action: Any, name: str, pid: int, returncode: int) -> None:
        super().__init__(action=action, name=name, pid=pid)
        self.returncode = returncode


class _ProcessEvents:
    """``launch.events.process``: the process events by their module's names."""

    ProcessStarted = ProcessStarted
    ProcessExited = ProcessExited


process = _ProcessEvents()
