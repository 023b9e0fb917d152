"""``launch.event_handlers``: entities to visit when a given node or process starts or exits."""

from __future__ import annotations

from typing import Any

from actors.compat.launch.entities import Event, EventHandler
from actors.compat.launch.events import ProcessExited, ProcessStarted, Shutdown

__all__ = ["OnProcessStart", "OnProcessExit", "OnShutdown"]


def _for(kind: type[Event], target: Any) -> Any:
    def matches(event: Event) -> bool:
        if type(event) is not kind:
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


class OnShutdown(EventHandler):
    """``on_shutdown`` when the launch is asked to end."""

    def __init__(self, *, on_shutdown: Any) -> None:
        super().__init__(matcher=lambda event: isinstance(event, Shutdown), entities=on_shutdown)
