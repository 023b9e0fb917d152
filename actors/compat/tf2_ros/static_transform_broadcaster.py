"""``tf2_ros.static_transform_broadcaster``: latches transforms that never change on ``/tf_static``."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from actors.ros.qos import DurabilityPolicy, HistoryPolicy, QoSProfile
from interfaces.geometry_msgs.msg import TransformStamped
from interfaces.tf2_msgs.msg import TFMessage

__all__ = ["StaticTransformBroadcaster"]


class StaticTransformBroadcaster:
    """Publishes on ``/tf_static`` (transient-local, depth 1) every static transform sent so far, one per child.

    Each ``sendTransform`` republishes the whole set, so the one message a late
    subscriber gets holds every frame, as with tf2_ros.
    """

    def __init__(self, node: Any, qos: QoSProfile | int | None = None) -> None:
        if qos is None:
            qos = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, history=HistoryPolicy.KEEP_LAST)
        self.pub_tf = node.create_publisher(TFMessage, "/tf_static", qos)
        self._by_child: dict[str, TransformStamped] = {}

    def sendTransform(self, transform: TransformStamped | Iterable[TransformStamped]) -> None:
        """Add (or replace, by child frame) one or several transforms and publish them all."""
        transforms = [transform] if isinstance(transform, TransformStamped) else list(transform)
        for t in transforms:
            self._by_child[t.child_frame_id] = t
        self.pub_tf.publish(TFMessage(transforms=list(self._by_child.values())))
