"""``rclpy.expand_topic_name``: a topic name made absolute for a node name and namespace."""

from __future__ import annotations

from actors.compat.rclpy.validate_namespace import validate_namespace
from actors.compat.rclpy.validate_topic_name import validate_topic_name
from actors.ros.names import expand, validate_node_name

__all__ = ["expand_topic_name"]


def expand_topic_name(topic_name: str, node_name: str, node_namespace: str) -> str:
    """``topic_name`` expanded: relative to ``node_namespace``, ``~`` to the node, ``{node}``/``{ns}`` substituted.

    Raises a ValueError (the InvalidNameError for what is wrong) naming the node
    name, the namespace or the topic name.
    """
    validate_node_name(node_name)
    validate_namespace(node_namespace)
    validate_topic_name(topic_name)
    substituted = (
        topic_name.replace("{node}", node_name)
        .replace("{ns}", node_namespace)
        .replace("{namespace}", node_namespace)
        .replace("//", "/")
    )
    return expand(substituted, node_namespace.rstrip("/") or "/", node_name)
