"""``rclpy.validate_node_name``: whether a node name follows ROS's rules."""

from __future__ import annotations

from actors.ros.names import validate_node_name as _validate

__all__ = ["validate_node_name"]


def validate_node_name(node_name: str) -> bool:
    """True if ``node_name`` is valid; InvalidNodeNameException naming the rule it breaks."""
    _validate(node_name)
    return True
