"""``rclpy.lifecycle``: managed nodes (LifecycleNode), their publishers and states, under rclpy's names.

``Node``, ``State`` and ``Publisher`` are short aliases of LifecycleNode,
LifecycleState and LifecyclePublisher, as rclpy gives them.
"""

from __future__ import annotations

from actors.compat.rclpy.lifecycle.managed_entity import ManagedEntity, SimpleManagedEntity
from actors.compat.rclpy.lifecycle.node import (
    LifecycleNode,
    LifecycleNodeMixin,
    LifecycleState,
    TransitionCallbackReturn,
)
from actors.compat.rclpy.lifecycle.publisher import LifecyclePublisher

__all__ = [
    "LifecycleNodeMixin",
    "LifecycleNode",
    "LifecycleState",
    "LifecyclePublisher",
    "ManagedEntity",
    "SimpleManagedEntity",
    "TransitionCallbackReturn",
    "Node",
    "NodeMixin",
    "State",
    "Publisher",
]

Node = LifecycleNode
NodeMixin = LifecycleNodeMixin
State = LifecycleState
Publisher = LifecyclePublisher
