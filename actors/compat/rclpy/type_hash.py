"""``rclpy.type_hash``: TypeHash, a message type's hash as rclpy hands it out (REP 2011's RIHS)."""

from __future__ import annotations

from typing import Any

__all__ = ["TypeHash"]

_PREFIX = "RIHS"


class TypeHash:
    """A hash ``version`` (1 for RIHS01) with its ``value`` bytes; version -1 and no bytes mean unset.

    ``str()`` gives the ``RIHS01_<hex>`` form ROS prints, ``INVALID`` for any
    other version.
    """

    __slots__ = ["_version", "_value"]

    def __init__(self, version: int = -1, value: bytes = b"") -> None:
        self.version = version
        self.value = value

    @classmethod
    def from_string(cls, text: str) -> TypeHash:
        """The TypeHash ``text`` (``RIHS01_<hex>``) names; the unset one for anything else ("" included)."""
        head, _, digits = text.partition("_")
        if not head.startswith(_PREFIX) or not head[len(_PREFIX) :].isdigit():
            return cls()
        try:
            return cls(int(head[len(_PREFIX) :]), bytes.fromhex(digits))
        except ValueError:
            return cls()

    @property
    def version(self) -> int:
        """The hash algorithm's version (1 for RIHS01)."""
        return self._version

    @version.setter
    def version(self, value: int) -> None:
        if not isinstance(value, int):
            raise TypeError(f"TypeHash.version must be an int, not {type(value).__name__}")
        self._version = value

    @property
    def value(self) -> bytes:
        """The hash's bytes."""
        return self._value

    @value.setter
    def value(self, value: bytes) -> None:
        if not isinstance(value, bytes):
            raise TypeError(f"TypeHash.value must be bytes, not {type(value).__name__}")
        self._value = value

    def __eq__(self, other: Any) -> bool:
        if not isinstance(other, TypeHash):
            return NotImplemented
        return (self._version, self._value) == (other._version, other._value)

    def __hash__(self) -> int:
        return hash((self._version, self._value))

    def __repr__(self) -> str:
        return f"TypeHash(version={self._version}, value={self._value!r})"

    def __str__(self) -> str:
        if self._version != 1:
            return "INVALID"
        return f"{_PREFIX}{self._version:02d}_{self._value.hex()}"
