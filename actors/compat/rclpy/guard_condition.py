"""``rclpy.guard_condition``: a callback that runs, on the spinning thread, after ``trigger()``."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from actors.compat.dispatch import Handler, ScriptNode, WorkSource
from actors.compat.rclpy.task import await_or_execute

__all__ = ["GuardCondition"]


class GuardCondition(WorkSource):
    """Made by ``Node.create_guard_condition``; ``trigger()`` from any thread makes it ready."""

    def __init__(self, node: ScriptNode, callback: Callable[[], Any] | None, callback_group: Any) -> None:
        self._node = node
        self._session = node._rclpy.session
        self.callback = callback
        self.callback_group = callback_group
        self._triggered = False

    def trigger(self) -> None:
        """Make the callback run at the node's next spin."""
        with self._session.lock:
            self._triggered = True
            self._node._rclpy.notify()

    def _ready(self) -> bool:
        return self._triggered

    def _take(self) -> Handler | None:
        self._triggered = False
        callback = self.callback
        if callback is None:
            return None

        async def run() -> None:
            await await_or_execute(callback)

        return run

    def destroy(self) -> None:
        """Forget it."""
        self._node.destroy_guard_condition(self)
