"""``tf2_ros.transform_broadcaster``: sends transforms on ``/tf``."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from actors.ros.qos import QoSProfile
from interfaces.geometry_msgs.msg import TransformStamped
from interfaces.tf2_msgs.msg import TFMessage

__all__ = ["TransformBroadcaster"]


class TransformBroadcaster:
    """Publishes TransformStamped messages on ``/tf`` from ``node`` (depth 100 unless ``qos`` says otherwise)."""

    def __init__(self, node: Any, qos: QoSProfile | int | None = None) -> None:
        self.pub_tf = node.create_publisher(TFMessage, "/tf", QoSProfile(depth=100) if qos is None else qos)

    def sendTransform(self, transform: TransformStamped | Iterable[TransformStamped]) -> None:
        """Publish one transform, or several in one TFMessage."""
        transforms = [transform] if isinstance(transform, TransformStamped) else list(transform)
        self.pub_tf.publish(TFMessage(transforms=transforms))
