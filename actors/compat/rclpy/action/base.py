"""What an action server and an action client of a script node share: their queue of work and
goal handles that are equal by goal id."""

from __future__ import annotations

from collections import deque
from typing import Any

from actors.compat.dispatch import Handler, ScriptNode, WorkSource

__all__ = ["ActionWork", "GoalHandle"]


class ActionWork(WorkSource):
    """A waitable of a script node: what the runtime's thread queues here runs when the node is spun,
    in ``callback_group`` (the node's default if None)."""

    def __init__(self, node: ScriptNode, callback_group: Any) -> None:
        if callback_group is None:
            callback_group = node.default_callback_group
        self.callback_group = callback_group
        self._node = node
        self._session = node._rclpy.session
        self._work: deque[Handler] = deque()

    def _queue(self, handler: Handler) -> None:
        # From the runtime's thread: the node's executor takes it on its next look.
        with self._session.lock:
            self._work.append(handler)
            self._node._rclpy.notify()

    def _ready(self) -> bool:
        return bool(self._work)

    def _take(self) -> Handler | None:
        return self._work.popleft() if self._work else None


class GoalHandle:
    """Equal by goal id to the handles of the same kind, and (as rclpy's) not hashable."""

    _native: Any

    @property
    def goal_id(self) -> Any:
        """The goal's UUID (unique_identifier_msgs/UUID)."""
        return self._native.goal_id

    def __eq__(self, other: object) -> bool:
        return type(other) is type(self) and self.goal_id == other.goal_id

    def __ne__(self, other: object) -> bool:
        return not self == other

    __hash__ = None  # type: ignore[assignment]  # unhashable, as rclpy's goal handles; object types it as hashable
