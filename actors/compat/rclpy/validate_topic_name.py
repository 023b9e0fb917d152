"""``rclpy.validate_topic_name``: whether a topic or service name, before expansion, follows ROS's rules."""

from __future__ import annotations

import re

from actors.errors import InvalidNameError, InvalidServiceNameException, InvalidTopicNameException

__all__ = ["TOPIC_SEPARATOR_STRING", "validate_topic_name", "invalid_name"]

TOPIC_SEPARATOR_STRING = "/"

_ALLOWED = re.compile(r"[A-Za-z0-9_/~{}]*\Z")


def invalid_name(name: str, rule: str, *, is_service: bool) -> InvalidNameError:
    """The error for a topic (or service) ``name`` that breaks ``rule``, in rcl's words."""
    what = "service name" if is_service else "topic name"
    error = InvalidServiceNameException if is_service else InvalidTopicNameException
    return error(f"invalid {what} {name!r}: a {what} {rule}")


def validate_topic_name(name: str, *, is_service: bool = False) -> bool:
    """True if ``name`` (relative, absolute, ``~/private`` or with ``{node}``) is valid.

    Raises InvalidTopicNameException (InvalidServiceNameException with
    ``is_service``) naming the rule it breaks.
    """
    rule = None
    if not name:
        rule = "must not be empty"
    elif name.endswith("/"):
        rule = "must not end with a forward slash"
    elif not _ALLOWED.match(name):
        rule = "must not contain characters other than alphanumerics, '_', '~', '{', or '}'"
    elif "~" in name[1:] or (name.startswith("~") and name not in ("~",) and not name.startswith("~/")):
        rule = "may have '~' only as its first character, followed by '/'"
    elif not _balanced(name):
        rule = "must have balanced '{' and '}' around substitutions"
    elif any(token[:1].isdigit() for token in name.split("/")):
        rule = "must not start with a number in any token"
    elif "//" in name:
        rule = "must not contain repeated '/'"
    if rule is not None:
        raise invalid_name(name, rule, is_service=is_service)
    return True


def _balanced(name: str) -> bool:
    # Substitutions ({node}, {ns}) neither nest nor stay open.
    depth = 0
    for char in name:
        depth += {"{": 1, "}": -1}.get(char, 0)
        if depth not in (0, 1):
            return False
    return depth == 0
