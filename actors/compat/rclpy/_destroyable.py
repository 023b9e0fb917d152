"""What makes an rclpy entity a context manager: ``with node.create_timer(...) as timer:`` destroys it on leaving."""

from __future__ import annotations

from collections.abc import Callable
from types import TracebackType
from typing import Self

__all__ = ["Destroyable"]


class Destroyable:
    """``with entity:`` gives the entity and calls its ``destroy()`` on leaving, as rclpy 8's entities do."""

    destroy: Callable[[], None]  # each entity's own

    def __enter__(self) -> Self:
        return self

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        self.destroy()
