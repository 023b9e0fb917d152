"""``rclpy.callback_groups``: which callbacks an executor may run at the same time.

Every entity belongs to one group (the node's default group, mutually
exclusive, unless ``callback_group=`` says otherwise).  Executors ask the group
before they run a callback (``can_execute``, ``beginning_execution``) and tell
it afterwards (``ending_execution``); a subclass may decide differently, as
rclpy allows.
"""

from __future__ import annotations

import threading
from typing import Any

__all__ = ["CallbackGroup", "MutuallyExclusiveCallbackGroup", "ReentrantCallbackGroup"]


class CallbackGroup:
    """The base of callback groups: subclasses decide in the three methods below."""

    def __init__(self) -> None:
        super().__init__()
        self.entities: set[int] = set()

    def add_entity(self, entity: Any) -> None:
        """Put ``entity`` (a subscription, timer, client, service...) in this group."""
        self.entities.add(id(entity))

    def has_entity(self, entity: Any) -> bool:
        """Whether ``entity`` is in this group."""
        return id(entity) in self.entities

    def can_execute(self, entity: Any) -> bool:
        """Whether a callback of ``entity`` could start now."""
        raise NotImplementedError()

    def beginning_execution(self, entity: Any) -> bool:
        """Ask to start a callback of ``entity``; if True, :meth:`ending_execution` follows it."""
        raise NotImplementedError()

    def ending_execution(self, entity: Any) -> None:
        """A callback of ``entity`` has finished."""
        raise NotImplementedError()


class ReentrantCallbackGroup(CallbackGroup):
    """Callbacks run in parallel without restriction (with a multi-threaded executor)."""

    def can_execute(self, entity: Any) -> bool:
        return True

    def beginning_execution(self, entity: Any) -> bool:
        return True

    def ending_execution(self, entity: Any) -> None:
        pass


class MutuallyExclusiveCallbackGroup(CallbackGroup):
    """One callback of the group at a time."""

    def __init__(self) -> None:
        super().__init__()
        self._active_entity: Any = None
        self._lock = threading.Lock()

    def can_execute(self, entity: Any) -> bool:
        with self._lock:
            return self._active_entity is None

    def beginning_execution(self, entity: Any) -> bool:
        with self._lock:
            if self._active_entity is None:
                self._active_entity = entity
                return True
        return False

    def ending_execution(self, entity: Any) -> None:
        with self._lock:
            self._active_entity = None
