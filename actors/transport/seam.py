"""The transport seam: how a runtime's topic and service tables reach other processes.

A transport is an attachment (``Runtime(attach=[...])``) that carries topics
and services to other processes.  It learns of the graph's own endpoints
through the tables' listeners (:class:`~actors.ros.topics.TopicListener`,
:class:`~actors.services.ServiceListener`), and joins the tables through
three kinds of endpoints of its own, all owned by one hidden :class:`Hub`:

- an :class:`Outlet` is subscription-like: the transport hangs one on a local
  publisher while a process elsewhere subscribes to its topic.
  ``publish()`` hands it the snapshot as it does every subscription (no new
  branch on the hot path), and the outlet passes it to the transport there
  and then, inside ``publish()`` (its actor is :data:`~actors.core._actor.AT_ONCE`):
  the transport serialises it once for all remote subscribers and sends it,
  as rmw_zenoh's publish does, with no loop round in between.  A
  publisher nobody elsewhere listens to has no outlet and costs nothing;
- an :class:`Inlet` is publisher-like: messages from other processes enter a
  topic through it and reach the local subscriptions as a local publisher's
  would.  They are decoded fresh, so they skip the snapshot;
- a :class:`RemoteService` stands in the service table for a server in
  another process: a local call to it goes to the transport.  A local server
  of the same name takes its place (and gives it back when it goes).

What a transport knows of other processes, it shows through
:class:`GraphSource` (:class:`RemoteNode` and :class:`RemoteEndpoint`
records), which the graph view merges with the local graph so that the
command line and ``doctor`` see one graph.  A transport that bounds what
other processes make it keep says so through :class:`LimitSource`, which
``doctor`` reports.
"""

from __future__ import annotations

import asyncio
from collections import deque
from collections.abc import Callable
from typing import Any, Protocol, runtime_checkable

import msgspec

from actors.core._actor import AT_ONCE, Actor
from actors.errors import ServiceError
from actors.ros.log import NodeLogger
from actors.ros.qos import DurabilityPolicy, QoSSnapshot, ReliabilityPolicy
from actors.ros.topics import Publisher, Subscription, TopicListener, type_name
from actors.services import Service, ServiceListener

__all__ = [
    "Hub",
    "Outlet",
    "Inlet",
    "RemoteService",
    "RemoteEndpoint",
    "RemoteNode",
    "GraphSource",
    "LimitSource",
    "Transport",
    "is_proxy",
    "submit",
]


class Hub:
    """The hidden owner of a transport's endpoints: a name, an actor, a logger.

    It quacks like the node core its endpoints expect (``fqn``, ``actor``,
    ``loop``, ``logger``) without being a node of the graph.  Nothing runs
    its actor: each of its endpoints runs where it is woken (an outlet inside
    ``publish()``, an inlet publishes, a remote service forwards in ``_push``),
    so an entity queued there would wait for ever; ``actor.pending`` stays 0.
    """

    def __init__(self, fqn: str, loop: asyncio.AbstractEventLoop, logger: NodeLogger) -> None:
        self.fqn = fqn
        self.loop = loop
        self.actor = Actor(loop)
        self._logger = logger

    @property
    def logger(self) -> NodeLogger:
        """The transport's logger."""
        return self._logger

    # The transport removes its endpoints itself; these only satisfy actors.core._actor.Owner.
    def destroy_publisher(self, publisher: Any) -> None: ...

    def destroy_subscription(self, subscription: Any) -> None: ...

    def destroy_timer(self, timer: Any) -> None: ...

    def destroy_service(self, service: Any) -> None: ...

    def destroy_client(self, client: Any) -> None: ...


# Matches every publisher: an outlet takes whatever its publisher offers.
_TAKES_ALL = ReliabilityPolicy.BEST_EFFORT
# Feeds every subscription: what arrives from elsewhere is delivered to all (zenoh, like
# rmw_zenoh, has no incompatible QoS pairs).
_OFFERS_ALL = QoSSnapshot(depth=1, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)


class Outlet(Subscription):
    """Carries one local publisher's messages to other processes: ``send(publisher, msg)`` each, in ``publish()``.

    ``send`` runs where the message is published, in publish order, and must
    not raise: what the wire cannot take is the transport's to drop or to
    wait for (Zenoh's congestion control), as in rmw_zenoh.
    """

    __slots__ = ("publisher",)

    def __init__(self, hub: Hub, publisher: Publisher, send: Callable[[Publisher, Any], None]) -> None:
        qos = publisher.qos
        super().__init__(
            hub,
            publisher.topic_name,
            publisher.msg_type,
            lambda msg: send(publisher, msg),
            QoSSnapshot(depth=max(qos.depth, 1), history=qos.history, reliability=_TAKES_ALL),
        )
        self.publisher = publisher
        self._queue = deque()  # fed by attach() below, not through the topic table's matching
        # Sent at once: a round of the hub's actor cost each message a loop round (and the
        # latency across processes a share of its hops).
        self._actor = AT_ONCE

    def attach(self) -> None:
        """Start receiving what the publisher publishes (only its messages, not its topic's)."""
        self.publisher._connect(self)

    def detach(self) -> None:
        """Stop receiving; what is queued is still sent."""
        self.publisher._disconnect(self)


def _fresh(msg: Any) -> Any:
    return msg


class Inlet(Publisher):
    """Delivers messages decoded from other processes to a topic's local subscriptions.

    It feeds every local subscription (reliable and transient-local ones too),
    keeps no history for local late joiners (a remote publisher's history is
    the transport's to fetch), and skips the snapshot: a decoded message
    belongs to nobody else.
    """

    __slots__ = ()

    def __init__(self, hub: Hub, topic_name: str, msg_type: type[Any]) -> None:
        super().__init__(hub, topic_name, msg_type, _OFFERS_ALL)
        self._history = None
        self._use(_fresh, self._check)


class RemoteService(Service):
    """A server in another process, standing in the service table for local callers.

    ``forward(service, request, future)`` sends the request; the transport
    settles ``future`` with the response, or with ServiceError or
    TimeoutError.  A request of another type than the server's fails at once.
    """

    __slots__ = ("_forward", "provider")
    remote = True

    def __init__(
        self,
        hub: Hub,
        service_name: str,
        srv_type: type[Any],
        provider: str,
        forward: Callable[[RemoteService, Any, asyncio.Future[Any]], None],
    ) -> None:
        super().__init__(hub, service_name, srv_type, _unused_handler)
        self.provider = provider  # the remote node's full name
        self._forward = forward

    def _push(self, call: Any) -> None:
        request, future = call
        if type(request) is not self.srv_type.Request:
            future.set_exception(
                ServiceError(
                    f"service {self.service_name} (served by {self.provider} in another process) takes "
                    f"{type_name(self.srv_type.Request)}, not {type_name(type(request))}"
                )
            )
            return
        self._forward(self, request, future)


def _unused_handler(request: Any, response: Any) -> Any:  # a remote server's handler runs elsewhere
    raise AssertionError("a remote service is never run locally")


def submit(service: Service, request: Any, future: asyncio.Future[Any]) -> None:
    """Queue a request from another process for a local server, as a local client's call would.

    ``future`` gets the response, or ServiceError when the handler raises or
    the server is destroyed first.
    """
    service._push((request, future))


def is_proxy(endpoint: Any) -> bool:
    """Whether ``endpoint`` is a transport's own (an outlet, inlet or remote service)."""
    return isinstance(endpoint, (Outlet, Inlet, RemoteService))


class RemoteEndpoint(msgspec.Struct, frozen=True, kw_only=True):
    """A publisher, subscription, server or client in another process.

    ``type`` is the ROS type name (``std_msgs/msg/String``), ``type_hash`` its
    RIHS01 hash as announced, ``known`` whether this process can decode it
    (the type exists here with the same hash); ``why`` says why not. ``gid``
    is the endpoint's GID as its transport gives it (b"" if it gives none).
    """

    kind: str  # "publisher", "subscription", "server" or "client"
    name: str
    type: str
    type_hash: str
    qos: QoSSnapshot
    known: bool = True
    why: str = ""
    gid: bytes = b""


class RemoteNode(msgspec.Struct, frozen=True, kw_only=True):
    """A node in another process: full name, where it runs, and its endpoints."""

    name: str
    process: str  # the transport's id of the process (a Zenoh session id)
    endpoints: tuple[RemoteEndpoint, ...] = ()


@runtime_checkable
class GraphSource(Protocol):
    """Something that knows nodes in other processes (a transport)."""

    def remote_nodes(self) -> list[RemoteNode]:
        """Every node seen in other processes now, sorted by name."""
        ...


@runtime_checkable
class LimitSource(Protocol):
    """Something with bounds on what other processes make it keep or log (a transport)."""

    def limits(self) -> tuple[list[str], list[str]]:
        """``(limits reached, warnings)``: what was left out because a bound was hit, one line each."""
        ...


class Transport(TopicListener, ServiceListener, GraphSource, Protocol):
    """The seam itself: what a transport is to a runtime.

    An attachment (``async __call__(runtime, task_status=...)``) that, while it
    runs, listens to the runtime's topic and service tables, joins them with
    its :class:`Outlet`, :class:`Inlet` and :class:`RemoteService` endpoints,
    and shows what it knows of other processes as a :class:`GraphSource`.
    """
