"""``tf2_ros.buffer_interface``: transforming stamped messages, and the registries of how to.

``Buffer.transform(msg, "frame")`` looks up the transform from the message's
``header.frame_id`` at its stamp and applies the function registered for its
type; :mod:`tf2_geometry_msgs` registers points, vectors and poses.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Callable
from typing import Any, ClassVar

from actors.ros.time import Duration

__all__ = [
    "BufferInterface",
    "TransformRegistration",
    "ConvertRegistration",
    "convert",
    "TypeException",
    "NotImplementedException",
]


class TypeException(Exception):
    """No function is registered for this type."""


class NotImplementedException(Exception):
    """tf2_ros's name for a BufferInterface method a subclass does not provide (kept for code that catches it)."""

    def __init__(self) -> None:
        super().__init__("function not implemented by this BufferInterface")


class TransformRegistration:
    """Which function transforms each stamped type: ``do_transform(msg, transform_stamped)``, shared by all."""

    _functions: ClassVar[dict[type, Callable[[Any, Any], Any]]] = {}

    def add(self, key: type, callback: Callable[[Any, Any], Any]) -> None:
        TransformRegistration._functions[key] = callback

    def get(self, key: type) -> Callable[[Any, Any], Any]:
        found = TransformRegistration._functions.get(key)
        if found is None:
            raise TypeException(f"Type {key} is not loaded or supported")
        return found


class ConvertRegistration:
    """Conversions between message types and others (tf2_ros keeps three tables; so does this)."""

    _to_msg: ClassVar[dict[type, Callable[[Any], Any]]] = {}
    _from_msg: ClassVar[dict[type, Callable[[Any], Any]]] = {}
    _convert: ClassVar[dict[tuple[type, type], Callable[[Any], Any]]] = {}

    def add_to_msg(self, key: type, callback: Callable[[Any], Any]) -> None:
        ConvertRegistration._to_msg[key] = callback

    def add_from_msg(self, key: type, callback: Callable[[Any], Any]) -> None:
        ConvertRegistration._from_msg[key] = callback

    def add_convert(self, key: tuple[type, type], callback: Callable[[Any], Any]) -> None:
        ConvertRegistration._convert[key] = callback

    def get_to_msg(self, key: type) -> Callable[[Any], Any]:
        return _found(ConvertRegistration._to_msg, key)

    def get_from_msg(self, key: type) -> Callable[[Any], Any]:
        return _found(ConvertRegistration._from_msg, key)

    def get_convert(self, key: tuple[type, type]) -> Callable[[Any], Any]:
        return _found(ConvertRegistration._convert, key)


def _found(table: dict[Any, Callable[[Any], Any]], key: Any) -> Callable[[Any], Any]:
    if key not in table:
        raise TypeException(f"Type {key} is not loaded or supported")
    return table[key]


def convert(a: Any, b_type: type) -> Any:
    """``a`` as a ``b_type``: a registered conversion, else through a message."""
    registry = ConvertRegistration()
    try:
        return registry.get_convert((type(a), b_type))(a)
    except TypeException:
        return registry.get_from_msg(b_type)(registry.get_to_msg(type(a))(a))


class BufferInterface(ABC):
    """What every tf2 buffer offers: lookups (by its subclass) and ``transform`` built on them."""

    def __init__(self) -> None:
        self.registration = TransformRegistration()

    def transform(
        self, object_stamped: Any, target_frame: str, timeout: Duration | None = None, new_type: type | None = None
    ) -> Any:
        """``object_stamped`` (a registered stamped type) expressed in ``target_frame``, at its own stamp."""
        do_transform = self.registration.get(type(object_stamped))
        header = object_stamped.header
        result = do_transform(
            object_stamped, self.lookup_transform(target_frame, header.frame_id, header.stamp, timeout)
        )
        return result if new_type is None else convert(result, new_type)

    def transform_full(
        self,
        object_stamped: Any,
        target_frame: str,
        target_time: Any,
        fixed_frame: str,
        timeout: Duration | None = None,
        new_type: type | None = None,
    ) -> Any:
        """As :meth:`transform`, into ``target_frame`` at ``target_time`` through ``fixed_frame`` (time travel)."""
        do_transform = self.registration.get(type(object_stamped))
        header = object_stamped.header
        found = self.lookup_transform_full(
            target_frame, target_time, header.frame_id, header.stamp, fixed_frame, timeout
        )
        result = do_transform(object_stamped, found)
        return result if new_type is None else convert(result, new_type)

    @abstractmethod
    def lookup_transform(self, target_frame: str, source_frame: str, time: Any, timeout: Duration | None = None) -> Any:
        """Implemented by the buffer."""

    @abstractmethod
    def lookup_transform_full(
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
        timeout: Duration | None = None,
    ) -> Any:
        """Implemented by the buffer."""

    @abstractmethod
    def can_transform(self, target_frame: str, source_frame: str, time: Any, timeout: Duration | None = None) -> bool:
        """Implemented by the buffer."""

    @abstractmethod
    def can_transform_full(
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
        timeout: Duration | None = None,
    ) -> bool:
        """Implemented by the buffer."""
