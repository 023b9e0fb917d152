"""``rclpy.lifecycle.publisher``: a publisher that delivers only while its lifecycle node is active."""

from __future__ import annotations

from typing import Any

from actors.compat.dispatch import ScriptNode
from actors.compat.rclpy.lifecycle.managed_entity import SimpleManagedEntity
from actors.compat.rclpy.publisher import Publisher

__all__ = ["LifecyclePublisher"]


class LifecyclePublisher(SimpleManagedEntity, Publisher):
    """``create_lifecycle_publisher``'s publisher: ``publish`` drops messages unless the node is active."""

    def __init__(self, node: ScriptNode, native: Any) -> None:
        SimpleManagedEntity.__init__(self)
        Publisher.__init__(self, node, native)

    @SimpleManagedEntity.when_enabled
    def publish(self, msg: Any) -> None:
        """Publish ``msg`` if the node is active (see Publisher.publish); otherwise do nothing."""
        Publisher.publish(self, msg)
