"""What makes an rclpy entity a context manager, and the ``handle`` that rclpy code locks while using it."""

from __future__ import annotations

from collections.abc import Callable
from types import TracebackType
from typing import Any, Self

from actors.compat.rclpy.exceptions import InvalidHandle

__all__ = ["Destroyable", "Handle"]


class Handle:
    """Stands in for an entity's rcl handle: ``with entity.handle:`` works while the entity lives.

    Once it is destroyed, entering raises InvalidHandle, as rclpy's handles do.
    """

    def __init__(self, alive: Callable[[], bool]) -> None:
        self._alive = alive

    def __enter__(self) -> Handle:
        if not self._alive():
            raise InvalidHandle("cannot use Destroyable because destruction was requested")
        return self

    def __exit__(self, *exc: object) -> None:
        return None


class Destroyable:
    """``with entity:`` gives the entity and calls its ``destroy()`` on leaving, as rclpy 8's entities do."""

    destroy: Callable[[], None]  # each entity's own
    _node: Any  # the script node it belongs to
    _destroyed = False  # set when its node destroys it

    @property
    def handle(self) -> Handle:
        """Usable (``with entity.handle:``) until the entity or its node is destroyed."""
        return Handle(lambda: not self._destroyed and not self._node._rclpy.destroyed)

    def __enter__(self) -> Self:
        return self

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        self.destroy()
