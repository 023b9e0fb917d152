"""``rclpy.service``: a script node's service server.

The native service's handler is the overlay's catcher: it queues the request
here, wakes the node's executor, and returns a future of the response, which
the script's callback settles on the executor's thread.
"""

from __future__ import annotations

import asyncio
from collections import deque
from collections.abc import Callable
from typing import Any

from actors.compat.dispatch import Handler, NativeProxy, ScriptNode, WorkSource
from actors.compat.rclpy._destroyable import Destroyable
from actors.compat.rclpy.service_introspection import REQUEST_RECEIVED, RESPONSE_SENT, Introspection
from actors.compat.rclpy.task import await_or_execute

__all__ = ["Service"]

_NO_CLIENT = [0] * 16  # a service does not see its caller's id in process


class Service(Destroyable, WorkSource, NativeProxy):
    """Answers requests while its node is spun (``Node.create_service``)."""

    def __init__(
        self, node: ScriptNode, srv_type: type[Any], callback: Callable[..., Any], callback_group: Any
    ) -> None:
        self._node = node
        self._session = node._rclpy.session
        self.srv_type = srv_type
        self.callback = callback
        self.callback_group = callback_group
        self._native: Any = None
        self._requests: deque[tuple[Any, Any, asyncio.Future[Any]]] = deque()
        self.catcher = self._catch
        self._introspection: Introspection | None = None  # made by configure_introspection

    def _catch(self, request: Any, response: Any) -> asyncio.Future[Any]:
        # The native service's handler, with the turn held (on a script thread when a script's
        # executor flushes what its call made due): the native service awaits the future.
        answer = self._session.loop.create_future()
        self._requests.append((request, response, answer))
        self._node._rclpy.notify()
        return answer

    def _ready(self) -> bool:
        return bool(self._requests)

    def _take(self) -> Handler | None:
        if not self._requests:
            return None
        request, response, answer = self._requests.popleft()
        callback, call = self.callback, self._session.call
        response_type = self.srv_type.Response
        introspection = self._introspection
        sequence = introspection.next_sequence() if introspection is not None else 0

        async def run() -> None:
            if introspection is not None:
                introspection.emit(REQUEST_RECEIVED, sequence, _NO_CLIENT, request=request)
            try:
                result = await await_or_execute(callback, request, response)
                if type(result) is not response_type:  # rclpy refuses it as it sends: the spin raises
                    raise TypeError(f"service callback returned {type(result).__name__}, not {response_type.__name__}")
            except Exception as exc:
                call(_settle, answer, None, exc)
                raise
            if introspection is not None:
                introspection.emit(RESPONSE_SENT, sequence, _NO_CLIENT, response=result)
            call(_settle, answer, result, None)

        return run

    @property
    def service_name(self) -> str:
        """The full service name."""
        return str(self._native.service_name)

    def configure_introspection(self, clock: Any, service_event_qos_profile: Any, introspection_state: Any) -> None:
        """Publish this service's events (see :mod:`~actors.compat.rclpy.service_introspection`)."""
        if self._introspection is None:
            self._introspection = Introspection(self._node, self.srv_type, self.service_name)
        self._introspection.configure(clock, service_event_qos_profile, introspection_state)

    def destroy(self) -> None:
        """Stop serving."""
        self._node.destroy_service(self)


def _settle(answer: asyncio.Future[Any], result: Any, error: BaseException | None) -> None:
    if answer.done():  # the node was destroyed meanwhile
        return
    if error is not None:
        answer.set_exception(error)
    else:
        answer.set_result(result)
