"""The Zenoh transport: ``Runtime(attach=[ZenohTransport()])`` speaks rmw_zenoh's protocol.

While it runs, the graph's nodes and endpoints are visible to every other
Zenoh peer of its domain (actors graphs, the ``actors`` command line, ROS 2
nodes with ``RMW_IMPLEMENTATION=rmw_zenoh_cpp``), topics and services flow
both ways, and the graph view (``rt.graph``, the command line, doctor) shows
theirs.  The wire format is rmw_zenoh's (:mod:`.keys`, :mod:`.attachment`,
CDR from :mod:`actors.codec`); how topics and services cross is described
in :mod:`.topics` and :mod:`.services`, the session's settings in
:mod:`.config`.

Threads.  Zenoh calls back on its own threads; every callback goes through
one :class:`~.handoff.Handoff` to the loop, in batches, and all the
transport's state lives on the loop.  Opening and closing the session, and
the first look at the graph, run in a worker thread.

Time.  A graph on virtual time cannot have a transport: other processes run
on the wall clock and could not follow its jumps, so the transport refuses
to start (TransportError) rather than stamp and time out on two clocks.

Start and stop.  The transport starts after the runtime's own endpoints and
before any node: it opens the session, subscribes to every liveliness token
of its domain and asks for those already there (so that, once started,
``remote_nodes()`` holds the graph as it was found), then joins the tables.
When the runtime stops, the nodes leave first (their tokens go with them),
then the transport closes the session.
"""

from __future__ import annotations

import functools
from typing import TYPE_CHECKING, Any

import anyio
import anyio.abc

from actors.errors import TransportError
from actors.launch.graph_file import TransportSection
from actors.ros.topics import Publisher, Subscription, Topic
from actors.services import Client, Service
from actors.transport.seam import Hub, RemoteNode, is_proxy
from actors.transport.zenoh.config import domain_id, load_zenoh, session_config
from actors.transport.zenoh.discovery import Discovery
from actors.transport.zenoh.handoff import Handoff
from actors.transport.zenoh.keys import Token, graph_key
from actors.transport.zenoh.link import Link, shown
from actors.transport.zenoh.peer_warnings import PeerWarnings
from actors.transport.zenoh.services import ServiceBridge
from actors.transport.zenoh.topics import TopicBridge

if TYPE_CHECKING:
    from actors.runtime import Runtime

__all__ = ["ZenohTransport"]

_FIRST_LOOK = 3.0  # seconds the first liveliness query may take


class ZenohTransport:
    """The attachment that carries a runtime's topics and services over Zenoh.

    ``section`` holds the ``[transport]`` settings (defaults: see
    :mod:`actors.transport.zenoh.config`).  Starting raises TransportError
    when zenoh is not installed, a setting is wrong, the session cannot open,
    or the runtime is on virtual time.  ``zid`` is the session's id once
    started; ``warnings`` holds the bounded warnings about what other
    processes sent (see :mod:`.peer_warnings`), ``ignored_tokens`` counts
    the liveliness tokens left out at the discovery's limit; ``hub`` owns its
    endpoints once started.
    """

    def __init__(self, section: TransportSection | None = None) -> None:
        self.section = section or TransportSection()
        self.zid = ""
        self._delete: Any = None  # zenoh.SampleKind.DELETE, once zenoh is imported
        self._discovery: Discovery | None = None
        self._topics: TopicBridge | None = None
        self._services: ServiceBridge | None = None
        self.warnings: PeerWarnings | None = None
        self.hub: Hub | None = None

    async def __call__(
        self, runtime: Runtime, *, task_status: anyio.abc.TaskStatus[Any] = anyio.TASK_STATUS_IGNORED
    ) -> None:
        if runtime.clock.virtual:
            raise TransportError(
                "a graph on virtual time cannot use a transport: other processes run on the wall clock "
                "(run it with --clock wall, or without [transport])"
            )
        zenoh = load_zenoh()
        self._delete = zenoh.SampleKind.DELETE
        config = session_config(self.section)
        domain = domain_id(self.section)
        try:
            session = await anyio.to_thread.run_sync(zenoh.open, config)
        except Exception as exc:
            raise TransportError(f"cannot open the zenoh session: {exc}") from None
        logger = runtime.make_logger("zenoh")
        hub = self.hub = Hub(f"/_zenoh_{runtime.name}".replace("-", "_"), runtime.loop, logger)
        handoff = Handoff(
            runtime.loop, runtime.scheduler, lambda exc: logger.error(f"zenoh transport: {exc!r}", exc_info=exc)
        )
        link = Link(zenoh, session, domain, hub, handoff, runtime.clock.now_ns, logger)
        self.zid = link.zid
        self.warnings = link.warnings
        discovery = self._discovery = Discovery(link.zid, self._remote_changed, functools.partial(_ignored, link))
        self._topics = TopicBridge(link, runtime.topics)
        self._services = ServiceBridge(link, runtime.services, discovery)
        try:
            liveliness = session.liveliness()
            watch = liveliness.declare_subscriber(
                graph_key(domain),
                zenoh.handlers.Callback(lambda sample: handoff.put(self._token_sample, sample), indirect=False),
                history=True,
            )
            try:
                for key in await anyio.to_thread.run_sync(_tokens_now, liveliness, graph_key(domain)):
                    discovery.put(key)
                self._join(runtime)
                task_status.started()
                await anyio.sleep_forever()  # the hub's endpoints run where they are woken, not here
            finally:
                self._leave(runtime)
                handoff.close()
                link.undeclare(watch)
                link.warnings.summarise()
        finally:
            with anyio.CancelScope(shield=True):
                await anyio.to_thread.run_sync(session.close)

    def remote_nodes(self) -> list[RemoteNode]:
        """The nodes of other processes on this domain, as their tokens say (the GraphSource seam)."""
        return [] if self._discovery is None else self._discovery.remote_nodes()

    @property
    def ignored_tokens(self) -> int:
        """Liveliness tokens of other processes ignored for want of room, since the start."""
        return 0 if self._discovery is None else self._discovery.ignored

    def limits(self) -> tuple[list[str], list[str]]:
        """What doctor says of the transport's bounds: (limits reached, warnings) (the LimitSource seam)."""
        reached = []
        if self._discovery is not None and self._discovery.ignored:
            reached.append(
                f"{self._discovery.ignored} liveliness token(s) of other processes ignored: more than "
                f"{self._discovery.limit} at once (their nodes and endpoints are missing from the graph)"
            )
        warnings = []
        if self.warnings is not None and self.warnings.left_out:
            warnings.append(
                f"{self.warnings.left_out} of {self.warnings.seen} warning(s) about what other processes sent "
                "left out of the log (rate-limited; the log has a summary)"
            )
        return reached, warnings

    # -- joining the tables -------------------------------------------------------------

    def _join(self, runtime: Runtime) -> None:
        runtime.topics.listeners.append(self)
        runtime.services.add_listener(self)
        for topic in list(runtime.topics.topics.values()):
            endpoints: list[Publisher | Subscription] = [*topic.publishers, *topic.subscriptions]
            for endpoint in endpoints:
                self.endpoint_added(topic, endpoint)
        for service in list(runtime.services.servers.values()):
            self.service_added(service)
        for core in list(runtime.nodes.values()):
            for client in core.clients:
                self.client_added(client)

    def _leave(self, runtime: Runtime) -> None:
        for listeners in (runtime.topics.listeners, runtime.services.listeners):
            if self in listeners:
                listeners.remove(self)
        if self._topics is not None:
            self._topics.close()
        if self._services is not None:
            self._services.close()

    # -- the listener seam: the runtime's own endpoints ----------------------------------

    def endpoint_added(self, topic: Topic, endpoint: Publisher | Subscription) -> None:
        """A local publisher or subscription goes on the wire."""
        assert self._topics is not None
        if is_proxy(endpoint):
            return
        if isinstance(endpoint, Publisher):
            self._topics.add_publisher(endpoint)
        else:
            self._topics.add_subscription(topic, endpoint)

    def endpoint_removed(self, topic: Topic, endpoint: Publisher | Subscription) -> None:
        """A local publisher or subscription leaves the wire."""
        assert self._topics is not None
        if is_proxy(endpoint):
            return
        if isinstance(endpoint, Publisher):
            self._topics.remove_publisher(endpoint)
        else:
            self._topics.remove_subscription(topic, endpoint)

    def service_added(self, service: Service) -> None:
        """A local server is served to other processes too."""
        assert self._services is not None
        if not is_proxy(service):
            self._services.add_service(service)

    def service_removed(self, service: Service) -> None:
        """A local server stops serving other processes."""
        assert self._services is not None
        if not is_proxy(service):
            self._services.remove_service(service)

    def client_added(self, client: Client) -> None:
        """A local client is announced."""
        assert self._services is not None
        self._services.add_client(client)

    def client_removed(self, client: Client) -> None:
        """A local client is withdrawn."""
        assert self._services is not None
        self._services.remove_client(client)

    # -- other processes -------------------------------------------------------------------

    def _token_sample(self, sample: Any) -> None:
        assert self._discovery is not None
        key = str(sample.key_expr)
        if sample.kind == self._delete:
            self._discovery.delete(key)
        else:
            self._discovery.put(key)

    def _remote_changed(self, token: Token, appeared: bool) -> None:
        if self._services is not None:
            self._services.remote_changed(token)


def _ignored(link: Link, reason: str, why: str) -> None:
    link.warnings.warn(f"liveliness ({reason})", "", f"ignored a liveliness token ({reason}): {shown(why)}")


def _tokens_now(liveliness: Any, key: str) -> list[str]:
    """The keys of the tokens alive now (blocking: run in a worker thread)."""
    return [str(reply.ok.key_expr) for reply in liveliness.get(key, timeout=_FIRST_LOOK) if reply.ok is not None]
