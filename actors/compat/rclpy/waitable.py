"""``rclpy.waitable``: the base class of a user's own executor work, and NumberOfEntities.

rclpy's executor gathers each Waitable's entities into its rcl wait set and
asks it whether it is ready.  The overlay has no rcl wait set: each time a
node's executor looks for work it hands the waitable an empty
:class:`WaitSet` (``add_to_wait_set``), asks ``is_ready``, and for a ready
one calls ``take_data`` and then ``execute`` on the spinning thread, in its
callback group.  A waitable whose readiness depends on the entities it adds
to the wait set cannot work here; one that decides by its own state can.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from typing import Any

from actors.compat.dispatch import Handler, WorkSource
from actors.compat.rclpy.task import await_or_execute

__all__ = ["NumberOfEntities", "Waitable", "WaitSet"]

_KINDS = ("subscriptions", "guard_conditions", "timers", "clients", "services", "events")


class NumberOfEntities:
    """How many entities of each kind a waitable puts in a wait set; they add up."""

    __slots__ = tuple(f"num_{kind}" for kind in _KINDS)

    def __init__(
        self,
        num_subscriptions: int = 0,
        num_guard_conditions: int = 0,
        num_timers: int = 0,
        num_clients: int = 0,
        num_services: int = 0,
        num_events: int = 0,
    ) -> None:
        counts = (num_subscriptions, num_guard_conditions, num_timers, num_clients, num_services, num_events)
        for name, value in zip(self.__slots__, counts, strict=True):
            setattr(self, name, value)

    def _counts(self) -> tuple[int, ...]:
        return tuple(getattr(self, name) for name in self.__slots__)

    def __add__(self, other: NumberOfEntities) -> NumberOfEntities:
        return NumberOfEntities(*(a + b for a, b in zip(self._counts(), other._counts(), strict=True)))

    def __iadd__(self, other: NumberOfEntities) -> NumberOfEntities:
        for name, value in zip(self.__slots__, other._counts(), strict=True):
            setattr(self, name, getattr(self, name) + value)
        return self

    def __eq__(self, other: object) -> bool:
        return isinstance(other, NumberOfEntities) and self._counts() == other._counts()

    def __repr__(self) -> str:
        return f"<NumberOfEntities({', '.join(map(str, self._counts()))})>"


class WaitSet:
    """What ``add_to_wait_set`` and ``is_ready`` receive: there is no rcl wait set, so it holds nothing."""


class Waitable(WorkSource, ABC):
    """Work of a user's own making that a node's executor runs (``node.add_waitable``)."""

    def __init__(self, callback_group: Any) -> None:
        self.callback_group = callback_group
        self.callback_group.add_entity(self)
        self._wait_set = WaitSet()

    @abstractmethod
    def is_ready(self, wait_set: WaitSet) -> bool:
        """Whether there is work to take now."""

    @abstractmethod
    def take_data(self) -> Any:
        """Take what ``execute`` works on (called once the waitable is ready)."""

    @abstractmethod
    async def execute(self, taken_data: Any) -> None:
        """Do the work, on the spinning thread."""

    @abstractmethod
    def get_num_entities(self) -> NumberOfEntities:
        """How many entities of each kind it would put in a wait set."""

    @abstractmethod
    def add_to_wait_set(self, wait_set: WaitSet) -> None:
        """Put its entities in ``wait_set`` (here, a chance to look at its own state before ``is_ready``)."""

    def __enter__(self) -> Waitable:
        return self

    def __exit__(self, *exc: object) -> None:
        return None

    def _ready(self) -> bool:
        self.add_to_wait_set(self._wait_set)
        return bool(self.is_ready(self._wait_set))

    def _take(self) -> Handler | None:
        data = self.take_data()
        execute = self.execute

        async def run() -> None:
            await await_or_execute(execute, data)

        return run
