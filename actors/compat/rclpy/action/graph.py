"""``rclpy.action.graph``: the actions of the graph, read as ``ros2 action list`` reads them."""

from __future__ import annotations

from typing import Any

from actors.ros.names import fully_qualified, normalize_namespace
from actors.system.introspection import ActionInfo

__all__ = [
    "get_action_client_names_and_types_by_node",
    "get_action_names_and_types",
    "get_action_server_names_and_types_by_node",
]


def _actions(node: Any) -> list[ActionInfo]:
    session = node._rclpy.session
    return session.call(lambda: session.runtime.graph.actions())


def get_action_names_and_types(node: Any) -> list[tuple[str, list[str]]]:
    """Every action of the graph, sorted by name, with its type: ``[(name, [type]), ...]``."""
    return [(info.name, [info.type]) for info in _actions(node)]


def get_action_server_names_and_types_by_node(
    node: Any, remote_node_name: str, remote_node_namespace: str
) -> list[tuple[str, list[str]]]:
    """The actions the node ``remote_node_namespace/remote_node_name`` serves."""
    fqn = fully_qualified(normalize_namespace(remote_node_namespace), remote_node_name)
    return [(info.name, [info.type]) for info in _actions(node) if fqn in info.servers]


def get_action_client_names_and_types_by_node(
    node: Any, remote_node_name: str, remote_node_namespace: str
) -> list[tuple[str, list[str]]]:
    """The actions the node ``remote_node_namespace/remote_node_name`` sends goals to."""
    fqn = fully_qualified(normalize_namespace(remote_node_namespace), remote_node_name)
    return [(info.name, [info.type]) for info in _actions(node) if fqn in info.clients]
