"""The tf tools' listening half: ``/tf`` and ``/tf_static`` into a BufferCore, with tf2's QoS."""

from __future__ import annotations

from actors import DurabilityPolicy, Node, QoSProfile
from actors.ros.tf_buffer import LISTENER_AUTHORITY, BufferCore
from interfaces.tf2_msgs.msg import TFMessage

__all__ = ["feed"]


def feed(node: Node) -> BufferCore:
    """A new buffer that ``node`` fills from ``/tf`` and ``/tf_static`` (latched, as tf2's listener asks)."""
    buffer = BufferCore()

    def dynamic(message: TFMessage) -> None:
        for transform in message.transforms:
            buffer.set_transform(transform, LISTENER_AUTHORITY)

    def static(message: TFMessage) -> None:
        for transform in message.transforms:
            buffer.set_transform_static(transform, LISTENER_AUTHORITY)

    node.create_subscription(TFMessage, "/tf", dynamic, QoSProfile(depth=100))
    latched = QoSProfile(depth=100, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    node.create_subscription(TFMessage, "/tf_static", static, latched)
    return buffer
