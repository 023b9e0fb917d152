"""``rclpy.publisher``: a script node's publisher; ``publish`` runs on the runtime's thread."""

from __future__ import annotations

from typing import Any

from actors.codec import decode_cdr
from actors.compat.dispatch import NativeProxy, ScriptNode
from actors.compat.rclpy._destroyable import Destroyable
from actors.compat.rclpy.exceptions import InvalidHandle

__all__ = ["Publisher"]


class Publisher(Destroyable, NativeProxy):
    """Publishes on one topic (``Node.create_publisher``); other attributes are the native publisher's."""

    catcher = None  # nothing of the runtime calls into a publisher (its event callbacks are native)

    def __init__(self, node: ScriptNode, native: Any) -> None:
        self._node = node
        self._native = native
        self._session = node._rclpy.session

    def publish(self, msg: Any) -> None:
        """Deliver ``msg`` (a message or its CDR bytes); TypeError (or a validation error) if it does
        not fit the topic's type, InvalidHandle once the publisher or its node is destroyed
        (``rclpy.shutdown()`` does it).

        Every subscription in the runtime has it when this returns (a script's
        once its executor looks for work), so the script may reuse or change
        ``msg`` afterwards.
        """
        if self._destroyed or self._node._rclpy.destroyed:
            raise InvalidHandle("cannot use Destroyable because destruction was requested")
        if isinstance(msg, (bytes, bytearray, memoryview)):  # already serialized, as rclpy accepts
            msg = decode_cdr(msg, self._native.msg_type)
        self._session.call(self._native.publish, msg)

    @property
    def topic_name(self) -> str:
        """The full topic name."""
        return str(self._native.topic_name)

    @property
    def msg_type(self) -> type[Any]:
        """The message type."""
        return self._native.msg_type

    @property
    def qos_profile(self) -> Any:
        """The QoS the publisher offers (rclpy's QoSProfile)."""
        return self._native.qos_profile

    def get_subscription_count(self) -> int:
        """How many subscriptions it feeds."""
        return int(self._session.call(self._native.get_subscription_count))

    def wait_for_all_acked(self, timeout: Any = None) -> bool:
        """Always True: delivery in one process is acknowledged when publish returns."""
        return True

    def assert_liveliness(self) -> None:
        """Nothing to assert: a publisher of a running node is alive."""

    def destroy(self) -> None:
        """Stop publishing."""
        self._node.destroy_publisher(self)
