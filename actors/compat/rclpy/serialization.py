"""``rclpy.serialization``: messages to and from the bytes ROS 2 sends (CDR), as :mod:`actors.codec` makes them."""

from __future__ import annotations

from typing import Any, TypeVar

from actors.codec import decode_cdr, encode_cdr

__all__ = ["serialize_message", "deserialize_message"]

T = TypeVar("T")


def serialize_message(message: Any) -> bytes:
    """``message`` as CDR bytes; TypeError for an object that is not a message."""
    return encode_cdr(message)


def deserialize_message(serialized_message: bytes, message_type: type[T]) -> T:
    """A ``message_type`` message from CDR bytes; CdrError naming the field for malformed bytes."""
    return decode_cdr(serialized_message, message_type)
