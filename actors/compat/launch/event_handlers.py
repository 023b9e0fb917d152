"""``launch.event_handlers``: entities to visit when a given node or process starts or exits."""

from __future__ import annotations

from typing import Any

from actors.compat.launch.entities import Event, EventHandler
from actors.compat.launch.events import ExecutionComplete, ProcessExited, ProcessIO, ProcessStarted, Shutdown

__all__ = ["OnProcessStart", "OnProcessExit", "OnProcessIO", "OnExecutionComplete", "OnShutdown"]


def _for(kind: type[Event], target: Any) -> Any:
    def matches(event: Event) -> bool:
        if not isinstance(event, kind):
            return False
        return target is None or getattr(event, "action", None) is target

    return matches


class OnProcessStart(EventHandler):
    """``on_start`` (entities, or ``f(event, context)`` returning them) when ``target_action`` starts."""

    def __init__(self, *, target_action: Any = None, on_start: Any) -> None:
        super().__init__(matcher=_for(ProcessStarted, target_action), entities=on_start)


class OnProcessExit(EventHandler):
    """``on_exit`` (entities, or ``f(event, context)`` returning them) when ``target_action`` exits."""

    def __init__(self, *, target_action: Any = None, on_exit: Any) -> None:
        super().__init__(matcher=_for(ProcessExited, target_action), entities=on_exit)


class OnProcessIO(EventHandler):
    """``on_stdout``/``on_stderr``/``on_stdin`` (each ``f(event)`` returning entities) for a line of
    ``target_action``'s output."""

    def __init__(
        self, *, target_action: Any = None, on_stdin: Any = None, on_stdout: Any = None, on_stderr: Any = None
    ) -> None:
        self.by_fd = {0: on_stdin, 1: on_stdout, 2: on_stderr}
        super().__init__(matcher=_for(ProcessIO, target_action), entities=self._for_line)

    def _for_line(self, event: ProcessIO, context: Any) -> Any:
        react = self.by_fd.get(event.fd)
        return None if react is None else react(event)


class OnExecutionComplete(EventHandler):
    """``on_completion`` (entities, or ``f(event, context)`` returning them) when ``target_action`` is done."""

    def __init__(self, *, target_action: Any = None, on_completion: Any) -> None:
        super().__init__(matcher=_for(ExecutionComplete, target_action), entities=on_completion)


class OnShutdown(EventHandler):
    """``on_shutdown`` when the launch is asked to end."""

    def __init__(self, *, on_shutdown: Any) -> None:
        super().__init__(matcher=lambda event: isinstance(event, Shutdown), entities=on_shutdown)
