"""``rclpy.validate_namespace``: whether a node namespace follows ROS's rules."""

from __future__ import annotations

from actors.errors import InvalidNamespaceException
from actors.ros.names import normalize_namespace

__all__ = ["validate_namespace"]


def validate_namespace(namespace: str) -> bool:
    """True if ``namespace`` is valid; InvalidNamespaceException naming the rule it breaks."""
    if not namespace:
        raise InvalidNamespaceException("invalid namespace '': a namespace must not be empty")
    if not namespace.startswith("/"):
        raise InvalidNamespaceException(f"invalid namespace {namespace!r}: a namespace must be absolute")
    if namespace != "/" and namespace.endswith("/"):
        raise InvalidNamespaceException(f"invalid namespace {namespace!r}: a namespace must not end with '/'")
    normalize_namespace(namespace)
    return True
