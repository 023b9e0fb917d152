"""``rclpy.client``: a script node's service client.

``call_async`` sends the request through the native client and returns an
rclpy :class:`~actors.compat.rclpy.task.Future`.  The response is handed to the
node's executor like any other work (in the client's callback group), which
completes the Future on its own thread, as rclpy does: a client's future is
done only once its node has been spun.
"""

from __future__ import annotations

import asyncio
from collections import deque
from typing import Any

from actors.compat.dispatch import Handler, NativeProxy, ScriptNode, WorkSource
from actors.compat.rclpy._destroyable import Destroyable
from actors.compat.rclpy.service_introspection import REQUEST_SENT, RESPONSE_RECEIVED, Introspection
from actors.compat.rclpy.task import Future

__all__ = ["Client"]


class Client(Destroyable, WorkSource, NativeProxy):
    """Calls one service (``Node.create_client``)."""

    def __init__(self, node: ScriptNode, native: Any, callback_group: Any) -> None:
        self._node = node
        self._session = node._rclpy.session
        self._native = native
        self.srv_type = native.srv_type
        self.callback_group = callback_group
        self._responses: deque[tuple[Future[Any], asyncio.Future[Any]]] = deque()
        self._pending: dict[Future[Any], asyncio.Future[Any]] = {}
        self._introspection = Introspection(node, self.srv_type, self.service_name)
        self._sequences: dict[Future[Any], int] = {}  # each call's sequence number, for its events

    @property
    def service_name(self) -> str:
        """The full service name."""
        return str(self._native.service_name)

    def call_async(self, request: Any) -> Future[Any]:
        """Send ``request``; a Future of the response, done once the node is spun after it arrives.

        Raises TypeError for a request of the wrong type.
        """
        future: Future[Any] = Future()
        self._pending[future] = self._session.call(self._send, request, future)
        sequence = self._sequences[future] = self._introspection.next_sequence()
        self._introspection.emit(REQUEST_SENT, sequence, self._introspection.gid, request=request)
        return future

    def configure_introspection(self, clock: Any, service_event_qos_profile: Any, introspection_state: Any) -> None:
        """Publish this client's service events (see :mod:`~actors.compat.rclpy.service_introspection`)."""
        self._introspection.configure(clock, service_event_qos_profile, introspection_state)

    def _send(self, request: Any, future: Future[Any]) -> asyncio.Future[Any]:
        sent: asyncio.Future[Any] = self._native.call_async(request)
        sent.add_done_callback(lambda done: self._arrived(future, done))
        return sent

    def _arrived(self, future: Future[Any], done: asyncio.Future[Any]) -> None:
        with self._session.lock:
            self._responses.append((future, done))
            self._node._rclpy.notify()

    def _ready(self) -> bool:
        return bool(self._responses)

    def _take(self) -> Handler | None:
        if not self._responses:
            return None
        future, done = self._responses.popleft()
        self._pending.pop(future, None)
        executor = self._node.executor
        sequence = self._sequences.pop(future, 0)
        if not done.cancelled() and done.exception() is None:
            introspection = self._introspection
            introspection.emit(RESPONSE_RECEIVED, sequence, introspection.gid, response=done.result())

        async def run() -> None:
            future._set_executor(executor)
            if done.cancelled():
                future.cancel()
            elif (error := done.exception()) is not None:
                future.set_exception(error)
            else:
                future.set_result(done.result())

        return run

    def call(self, request: Any, timeout_sec: float | None = None) -> Any:
        """Send ``request`` and wait for the response (another thread must spin the node).

        Raises TimeoutError after ``timeout_sec`` seconds of runtime clock, and
        what the call raised.  Do not call it from a callback of a
        single-threaded executor: it would wait forever, as in rclpy.
        """
        waiter = self._session.waiter()
        future = self.call_async(request)
        future._add_resumer(waiter.wake)
        timeout = timeout_sec if timeout_sec is not None and timeout_sec >= 0 else None
        if not self._session.wait_until(lambda: not future._pending(), timeout, waiter):
            self.remove_pending_request(future)
            raise TimeoutError()
        return future.result()

    def remove_pending_request(self, future: Future[Any]) -> None:
        """Give up waiting for the response ``future`` stands for."""
        sent = self._pending.pop(future, None)
        self._sequences.pop(future, None)
        if sent is not None:
            self._session.call(sent.cancel)

    def service_is_ready(self) -> bool:
        """Whether a server for this service exists now."""
        return bool(self._session.call(self._native.service_is_ready))

    def wait_for_service(self, timeout_sec: float | None = None) -> bool:
        """Wait until the service exists (``timeout_sec`` of runtime clock at most); whether it does."""
        if timeout_sec is not None and timeout_sec < 0:
            timeout_sec = None
        return bool(self._session.block(self._native.wait_for_service, timeout_sec))

    def destroy(self) -> None:
        """Forget this client."""
        self._node.destroy_client(self)
