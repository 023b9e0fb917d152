"""``rclpy.wait_for_message``: wait for one message on a topic without spinning."""

from __future__ import annotations

from typing import Any

from actors.compat.dispatch import ScriptNode
from actors.compat.rclpy.subscription import Subscription
from actors.ros.node import Node as NativeNode

__all__ = ["wait_for_message"]


def wait_for_message(
    msg_type: type[Any], node: ScriptNode, topic: str, *, qos_profile: Any = 1, time_to_wait: float = -1
) -> tuple[bool, Any]:
    """``(True, msg)`` with the next message on ``topic``; ``(False, None)`` after ``time_to_wait``
    seconds of runtime clock (negative: no limit) or when the context shuts down.

    A subscription of its own, outside any executor, lives for the wait only.
    """
    session = node._rclpy.session
    context = node.context
    waiter = session.waiter()
    subscription = Subscription(node, msg_type, lambda _msg: None, None)
    subscription._notify = waiter.wake
    node._create(subscription, NativeNode.create_subscription, msg_type, topic, subscription.catcher, qos_profile)
    context.add_waker(waiter)

    def arrived() -> Any:
        return subscription._queue.popleft() if subscription._queue else not context.ok()

    try:
        got = session.wait_until(arrived, time_to_wait if time_to_wait >= 0 else None, waiter)
    finally:
        if session.running:
            session.call(NativeNode.destroy_subscription, node, subscription._native)
    return (True, got[0]) if isinstance(got, tuple) else (False, None)
