"""``rclpy.type_support``: checks that a class is a ROS message or service type before rclpy uses it.

rclpy's generated classes carry C type support that must be imported; actors'
classes are encoded from their own definitions, so a generated class is always
supported and only its kind (message, service) is checked.  A class that is
not generated is judged as rclpy judges it, by its ``_TYPE_SUPPORT``.
"""

from __future__ import annotations

from typing import Any

from actors.compat.rclpy.exceptions import NoTypeSupportImportedException

__all__ = ["check_for_type_support", "check_is_valid_msg_type", "check_is_valid_srv_type"]


def _kind(cls: Any) -> str | None:
    # "msg", "srv" or "action" for a generated class, from its ROS name; None for any other.
    ros_type = getattr(cls, "__ros_type__", None)
    return ros_type.split("/")[1] if isinstance(ros_type, str) and ros_type.count("/") == 2 else None


def check_for_type_support(msg_or_srv_type: Any) -> None:
    """Nothing for a usable type; AttributeError for a class that is no ROS type, NoTypeSupportImportedException
    for one whose type support cannot be imported."""
    if _kind(msg_or_srv_type) is not None:
        return
    if msg_or_srv_type._TYPE_SUPPORT is None:
        msg_or_srv_type.__import_type_support__()
    if msg_or_srv_type._TYPE_SUPPORT is None:
        raise NoTypeSupportImportedException()


def check_is_valid_msg_type(msg_type: Any) -> None:
    """Nothing for a message type (a service's Request and Response are messages); RuntimeError otherwise."""
    check_for_type_support(msg_type)
    kind = _kind(msg_type)
    if kind == "msg" or (kind is not None and "_" in msg_type.__ros_type__.rsplit("/", 1)[1]):
        return
    raise RuntimeError(f"The message type provided is not valid ({msg_type}), this might be a service or action")


def check_is_valid_srv_type(srv_type: Any) -> None:
    """Nothing for a service type; RuntimeError otherwise."""
    check_for_type_support(srv_type)
    if _kind(srv_type) == "srv" and hasattr(srv_type, "Request") and hasattr(srv_type, "Response"):
        return
    raise RuntimeError(f"The service type provided is not valid ({srv_type}), this might be a message or action")
