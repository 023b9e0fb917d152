"""``rclpy.service_introspection``: service events, what a client or service publishes about each call.

``configure_introspection(clock, qos, state)`` on a Client or Service turns
them on.  With METADATA each step of a call (request sent, request received,
response sent, response received) is published on the hidden topic
``<service>/_service_event`` as the service type's ``Event`` message: its
``info`` (the step, the clock's time, the client's id, the call's sequence
number); with CONTENTS the event also carries the request or the response.
OFF stops it and removes the topic's publisher.

A client numbers its calls 1, 2, ... and names itself with a 16-byte id; a
service, which cannot see the caller's header in process, numbers the
requests it receives the same way and leaves the client id zero.
"""

from __future__ import annotations

import itertools
from enum import IntEnum
from typing import Any

from interfaces.service_msgs.msg import ServiceEventInfo

__all__ = ["ServiceIntrospectionState", "Introspection"]

_ids = itertools.count(1)  # what makes each client's id unique in the process


class ServiceIntrospectionState(IntEnum):
    """How much a service or client tells about its calls (rcl's values)."""

    OFF = 0
    METADATA = 1
    CONTENTS = 2


class Introspection:
    """One client's or service's introspection: its state, publisher and call counter."""

    def __init__(self, node: Any, srv_type: type[Any], service_name: str) -> None:
        self._node = node
        self._srv_type = srv_type
        self._topic = f"{service_name}/_service_event"
        self._state = ServiceIntrospectionState.OFF
        self._clock: Any = None
        self._publisher: Any = None
        self._calls = itertools.count(1)
        self.gid = list(next(_ids).to_bytes(8, "little")) + [0] * 8

    def next_sequence(self) -> int:
        """The sequence number of the next call (or request received)."""
        return next(self._calls)

    def configure(self, clock: Any, service_event_qos: Any, state: ServiceIntrospectionState) -> None:
        """Start (METADATA, CONTENTS) or stop (OFF) publishing events, stamped with ``clock``."""
        state = ServiceIntrospectionState(state)
        if state is ServiceIntrospectionState.OFF:
            if self._publisher is not None:
                self._node.destroy_publisher(self._publisher)
                self._publisher = None
        elif self._publisher is None:
            self._publisher = self._node.create_publisher(self._srv_type.Event, self._topic, service_event_qos)
        self._clock, self._state = clock, state

    def emit(self, event_type: int, sequence: int, gid: list[int], request: Any = None, response: Any = None) -> None:
        """Publish one step of a call, when on; ``request``/``response`` go in only with CONTENTS."""
        if self._state is ServiceIntrospectionState.OFF or self._publisher is None:
            return
        contents = self._state is ServiceIntrospectionState.CONTENTS
        info = ServiceEventInfo(
            event_type=event_type, stamp=self._clock.now().to_msg(), client_gid=gid, sequence_number=sequence
        )
        event = self._srv_type.Event(
            info=info,
            request=[request] if contents and request is not None else [],
            response=[response] if contents and response is not None else [],
        )
        self._publisher.publish(event)


REQUEST_SENT = ServiceEventInfo.REQUEST_SENT
REQUEST_RECEIVED = ServiceEventInfo.REQUEST_RECEIVED
RESPONSE_SENT = ServiceEventInfo.RESPONSE_SENT
RESPONSE_RECEIVED = ServiceEventInfo.RESPONSE_RECEIVED
