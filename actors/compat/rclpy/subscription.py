"""``rclpy.subscription``: a script node's subscription, its queue, and ``MessageInfo``.

The native subscription's callback is the overlay's catcher: on the runtime's
thread it moves each message into this queue, bounded as the QoS says (a full
KEEP_LAST queue drops its oldest message, counted as the native drop count),
and wakes the node's executor, which takes one message at a time.
"""

from __future__ import annotations

import inspect
import sys
from collections import deque
from collections.abc import Callable
from enum import Enum
from typing import Any, TypedDict

from actors.compat.dispatch import Handler, NativeProxy, ScriptNode, WorkSource
from actors.compat.rclpy._destroyable import Destroyable
from actors.compat.rclpy.task import await_or_execute
from actors.messages import cdr
from actors.ros.qos import HistoryPolicy

__all__ = ["Subscription", "MessageInfo", "serialized"]


class MessageInfo(TypedDict):
    """What a two-argument subscription callback receives beside the message."""

    source_timestamp: int
    received_timestamp: int
    publication_sequence_number: int | None
    reception_sequence_number: int


class CallbackType(Enum):
    """What a subscription callback takes: the message, or the message and its MessageInfo."""

    MessageOnly = 0
    WithMessageInfo = 1


def _callback_type(callback: Callable[..., Any]) -> CallbackType:
    # As rclpy reads it off the signature; RuntimeError for one that takes neither form.
    try:
        signature = inspect.signature(callback)
    except ValueError:  # no signature (a builtin): give it the message only
        return CallbackType.MessageOnly
    for kind, arguments in ((CallbackType.MessageOnly, 1), (CallbackType.WithMessageInfo, 2)):
        try:
            signature.bind(*[object()] * arguments)
        except TypeError:
            continue
        return kind
    raise RuntimeError(f"Subscription callback {callback!r} must take one argument (the message) or two (and info)")


class Subscription(Destroyable, WorkSource, NativeProxy):
    """Receives one topic (``Node.create_subscription``); other attributes are the native one's."""

    CallbackType = CallbackType

    def __init__(
        self,
        node: ScriptNode,
        msg_type: type[Any],
        callback: Callable[..., Any],
        callback_group: Any,
        raw: bool = False,
    ) -> None:
        self._node = node
        self._session = node._rclpy.session
        self.msg_type = msg_type
        self.callback = callback
        self.callback_group = callback_group
        self.raw = raw
        self._native: Any = None
        self._queue: deque[tuple[Any, int]] = deque()
        self._limit = sys.maxsize
        self._received = 0
        self._callback_type = _callback_type(callback)
        self._with_info = self._callback_type is CallbackType.WithMessageInfo
        self._notify = node._rclpy.notify
        self.catcher = self._catch

    def _attach(self, native: Any) -> None:
        self._native = native
        qos = native.qos
        self._limit = qos.depth if qos.history == HistoryPolicy.KEEP_LAST else sys.maxsize

    def _catch(self, msg: Any) -> None:
        # On the runtime's thread, for each message the native subscription delivers.
        with self._session.lock:
            if len(self._queue) >= self._limit:
                self._queue.popleft()
                self._native.dropped += 1
            self._queue.append((msg, self._node._rclpy.clock.now_ns()))
            self._notify()

    def _ready(self) -> bool:
        return bool(self._queue)

    def _take(self) -> Handler | None:
        if not self._queue:
            return None
        msg, stamp = self._queue.popleft()
        self._received += 1
        if self.raw:
            msg = serialized(msg)
        args: tuple[Any, ...] = (msg,)
        if self._with_info:
            info: MessageInfo = {
                "source_timestamp": stamp,
                "received_timestamp": stamp,
                "publication_sequence_number": None,
                "reception_sequence_number": self._received,
            }
            args = (msg, info)
        callback = self.callback

        async def run() -> None:
            await await_or_execute(callback, *args)

        return run

    @property
    def topic_name(self) -> str:
        """The full topic name."""
        return str(self._native.topic_name)

    @property
    def qos_profile(self) -> Any:
        """The QoS the subscription requests (rclpy's QoSProfile)."""
        return self._native.qos_profile

    def destroy(self) -> None:
        """Stop receiving."""
        self._node.destroy_subscription(self)


def serialized(msg: Any) -> bytes:
    """``msg`` as a ``raw=True`` subscription receives it from rmw_fastrtps: CDR, padded to 4 bytes."""
    data = cdr.encode(msg)
    return data + bytes(-len(data) % 4)
