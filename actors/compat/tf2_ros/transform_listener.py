"""``tf2_ros.transform_listener``: fills a Buffer from ``/tf`` and ``/tf_static``, with tf2's QoS."""

from __future__ import annotations

import threading
from typing import Any

from actors.compat.rclpy.callback_groups import ReentrantCallbackGroup
from actors.compat.rclpy.executors import SingleThreadedExecutor
from actors.ros.qos import DurabilityPolicy, HistoryPolicy, QoSProfile
from actors.ros.tf_buffer import LISTENER_AUTHORITY
from interfaces.tf2_msgs.msg import TFMessage

__all__ = ["TransformListener", "DEFAULT_TF_TOPIC", "DEFAULT_STATIC_TF_TOPIC"]

DEFAULT_TF_TOPIC = "/tf"
DEFAULT_STATIC_TF_TOPIC = "/tf_static"


class TransformListener:
    """Subscribes ``node`` to the transform topics and puts every transform into ``buffer``.

    The subscriptions are in a reentrant callback group of their own and run
    when the node is spun; with ``spin_thread=True`` a thread of the
    listener's own spins the node (so a callback may wait on the buffer).
    ``/tf`` is volatile depth 100, ``/tf_static`` transient-local depth 100,
    as tf2_ros subscribes them.
    """

    def __init__(
        self,
        buffer: Any,
        node: Any,
        *,
        spin_thread: bool = False,
        qos: QoSProfile | int | None = None,
        static_qos: QoSProfile | int | None = None,
        tf_topic: str = DEFAULT_TF_TOPIC,
        tf_static_topic: str = DEFAULT_STATIC_TF_TOPIC,
    ) -> None:
        if qos is None:
            qos = QoSProfile(depth=100, durability=DurabilityPolicy.VOLATILE, history=HistoryPolicy.KEEP_LAST)
        if static_qos is None:
            static_qos = QoSProfile(
                depth=100, durability=DurabilityPolicy.TRANSIENT_LOCAL, history=HistoryPolicy.KEEP_LAST
            )
        self.buffer = buffer
        self.node = node
        self.group = ReentrantCallbackGroup()
        self.tf_sub = node.create_subscription(TFMessage, tf_topic, self.callback, qos, callback_group=self.group)
        self.tf_static_sub = node.create_subscription(
            TFMessage, tf_static_topic, self.static_callback, static_qos, callback_group=self.group
        )
        self.executor: SingleThreadedExecutor | None = None
        if spin_thread:
            self.executor = SingleThreadedExecutor()
            self.executor.add_node(node)
            self.dedicated_listener_thread = threading.Thread(target=self.executor.spin, daemon=True)
            self.dedicated_listener_thread.start()

    def unregister(self) -> None:
        """Remove the subscriptions (and stop the listener's own thread, if any)."""
        if self.executor is not None:
            self.executor.shutdown()
            self.executor = None
        self.node.destroy_subscription(self.tf_sub)
        self.node.destroy_subscription(self.tf_static_sub)

    def callback(self, data: TFMessage) -> None:
        for transform in data.transforms:
            self.buffer.set_transform(transform, LISTENER_AUTHORITY)

    def static_callback(self, data: TFMessage) -> None:
        for transform in data.transforms:
            self.buffer.set_transform_static(transform, LISTENER_AUTHORITY)
