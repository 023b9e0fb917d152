"""``rclpy.validate_full_topic_name``: whether an expanded (absolute) topic or service name is valid."""

from __future__ import annotations

from actors.compat.rclpy.validate_topic_name import invalid_name
from actors.errors import InvalidNameError
from actors.ros.names import normalize_namespace

__all__ = ["validate_full_topic_name"]


def validate_full_topic_name(name: str, *, is_service: bool = False) -> bool:
    """True if ``name`` is absolute and valid; InvalidTopicNameException (or Service...) naming the rule."""
    if not name.startswith("/"):
        raise invalid_name(name, "must be absolute (start with '/')", is_service=is_service)
    if name != "/" and name.endswith("/"):
        raise invalid_name(name, "must not end with a forward slash", is_service=is_service)
    try:
        normalize_namespace(name)
    except InvalidNameError as error:
        rule = str(error).split(": a namespace ", 1)[-1]
        raise invalid_name(name, rule, is_service=is_service) from None
    return True
