"""The live view: a graph's topics and services served to Foxglove over its WebSocket protocol (``--foxglove``).

``Runtime(attach=[FoxgloveView(port=8765)])`` (``python -m actors.run GRAPH
--foxglove``) runs foxglove-sdk's WebSocket server on 127.0.0.1 (the
``foxglove`` extra).  Every topic is a channel as rosbag2 writes it into a bag
(``ros2msg`` schema with the full definition, ``cdr`` payloads, the type hash
in its metadata), tapped through a :class:`~actors.recording.tap.TapSet`; a
message is encoded only while a client is subscribed to its channel, and the
server's queues drop for a slow client, so a view nobody watches costs the
graph nothing and none holds up a publisher.  A client that subscribes to a
latched topic (``/tf_static``) gets its transient-local history then, as a
late ROS subscriber would (sent again to the topic's other viewers too: the
SDK logs to all of a channel's subscribers).  Log times, and the time the
server broadcasts ten times per second of graph time, are the runtime clock's
(virtual time included).  Every service is callable from Foxglove (CDR
requests and responses).

Beside the topics, the view serves 3D scenes drawn by whoever knows them: a
node that finds a :class:`SceneHost` among its runtime's attachments offers
it ``add_scene(topic, draw)`` (the TurtleBot world draws its arena, robots
and scans on ``/scene``), and the view asks ``draw(now_ns)`` for a
``foxglove.SceneUpdate`` at each time broadcast while a client subscribes.
"""

from __future__ import annotations

import asyncio
import concurrent.futures
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, Protocol, cast, runtime_checkable

import anyio
import anyio.abc

from actors import codec
from actors.core._actor import Owner
from actors.errors import ActorsError
from actors.recording._subprotocols import MAX_VIEWERS, SubprotocolFront
from actors.recording.tap import Tap, TapOwner, TapSet, latched
from actors.ros.names import is_hidden_name
from actors.ros.topics import type_name
from actors.services import Client, Service

if TYPE_CHECKING:
    from actors.runtime import Runtime

__all__ = [
    "FoxgloveView",
    "SceneHost",
    "Draw",
    "VIEW_NODE",
    "DEFAULT_PORT",
    "CALL_TIMEOUT",
    "TIME_PERIOD",
    "MAX_VIEWERS",
    "BACKLOG",
]

VIEW_NODE = "/_actors_foxglove"
"""The hidden owner of the view's subscriptions, as ``topic info`` names it."""

DEFAULT_PORT = 8765
"""Foxglove's usual WebSocket port."""

CALL_TIMEOUT = 10.0
"""Seconds (wall clock) a service call from Foxglove waits for its response."""

TIME_PERIOD = 0.1
"""Seconds of graph time between two time broadcasts (and two updates of each watched scene)."""

BACKLOG = 256
"""Messages the SDK queues for one viewer (its default is 1,024): one that stops reading loses the oldest.

A viewer that keeps up never has more than a few queued; one that never reads holds at most this
many (issue 34 measured ~3.6 MB per such viewer at the default), times :data:`MAX_VIEWERS`.
"""

Draw = Callable[[int], Any]
"""A scene's painter: given the runtime clock's time (ns), the ``foxglove.messages.SceneUpdate`` to show."""


@runtime_checkable
class SceneHost(Protocol):
    """What shows 3D scenes beside a graph (:class:`FoxgloveView` does): nodes that can draw offer it theirs.

    A node finds hosts among its runtime's ``attachments``; the host calls
    ``draw`` in the graph's loop, so it may read the node's state freely.
    """

    def add_scene(self, topic: str, draw: Draw) -> None:
        """Show what ``draw`` paints on ``topic`` (replacing a scene already there)."""

    def remove_scene(self, topic: str) -> None:
        """Stop showing the scene on ``topic`` (nothing if there is none)."""


def _foxglove() -> Any:
    try:
        import foxglove
        import foxglove.channels
        import foxglove.websocket
    except ImportError as exc:
        raise ImportError("--foxglove needs foxglove-sdk: pip install 'actors[foxglove]'") from exc
    return foxglove


class FoxgloveView:
    """The attachment that serves a graph live to Foxglove: ``Runtime(attach=[FoxgloveView()])``.

    ``port`` 0 lets the system choose one (:attr:`port` tells which, once
    started).  Hidden topics and services (a part starting with ``_``) only
    with ``include_hidden``.  At most ``max_viewers`` clients are connected at
    once; more are answered HTTP 503 (recording/_subprotocols.py).  :meth:`start` opens the server (the runtime calls
    it when it starts, if no one did before), raising ActorsError when the
    address cannot be had and ImportError without the ``foxglove`` extra.
    """

    def __init__(
        self,
        port: int = DEFAULT_PORT,
        *,
        host: str = "127.0.0.1",
        include_hidden: bool = False,
        max_viewers: int = MAX_VIEWERS,
    ) -> None:
        self.host = host
        self.port = port
        self.include_hidden = include_hidden
        self.max_viewers = max_viewers
        self._fox: Any = None
        self._context: Any = None
        self._server: Any = None
        self._front = SubprotocolFront(host, port, 0, warn=self._warn)  # replaced by the one started
        self._taps = TapSet(VIEW_NODE, self._wants, self._deliver, label="foxglove", tapped=self._advertise)
        self._now_ns: Any = None
        self._loop: asyncio.AbstractEventLoop | None = None
        self._runtime: Runtime | None = None
        self._owner: TapOwner | None = None
        self._services: dict[str, Client] = {}
        self._scenes: dict[str, list[Any]] = {}  # topic -> [draw, its channel once started]

    def start(self) -> int:
        """Open the WebSocket server; returns its port."""
        if self._server is None:
            fox = self._fox = _foxglove()
            self._context = fox.Context()
            capabilities = [fox.websocket.Capability.Time, fox.websocket.Capability.Services]
            # The SDK's server listens on a loopback port of its own, behind the front that
            # also lets foxglove.websocket.v1 clients in (recording/_subprotocols.py).
            try:
                self._server = fox.start_server(
                    name="actors",
                    host="127.0.0.1",
                    port=0,
                    capabilities=capabilities,
                    supported_encodings=["cdr"],
                    context=self._context,
                    server_listener=self,
                    message_backlog_size=BACKLOG,
                )
            except Exception as exc:  # the SDK raises RuntimeError when it cannot listen
                raise ActorsError(f"--foxglove: cannot serve on 127.0.0.1: {exc}") from None
            self._front = SubprotocolFront(
                self.host, self.port, self._server.port, max_viewers=self.max_viewers, warn=self._warn
            )
            try:
                self.port = self._front.start()
            except OSError as exc:
                self._server.stop()
                self._server = None
                where = f"{self.host}:{self.port}"
                raise ActorsError(f"--foxglove: cannot serve on {where}: {exc.strerror or exc}") from None
            for topic in self._scenes:
                self._open_scene(topic)
        return self.port

    @property
    def url(self) -> str:
        """The address Foxglove connects to (Open connection → Foxglove WebSocket)."""
        return f"ws://{self.host}:{self.port}"

    async def __call__(
        self, runtime: Runtime, *, task_status: anyio.abc.TaskStatus[Any] = anyio.TASK_STATUS_IGNORED
    ) -> None:
        self.start()
        self._now_ns = runtime.clock.now_ns
        self._loop = runtime.loop
        self._runtime = runtime
        self._owner = TapOwner(runtime, VIEW_NODE)
        try:
            self._taps.start(runtime)
            runtime.services.add_listener(self)
            for service in list(runtime.services.servers.values()):
                self.service_added(service)
            runtime.logger.info(f"foxglove: serving the graph on {self.url}")
            task_status.started()
            while True:
                now = runtime.clock.now_ns()
                self._server.broadcast_time(now)
                self._draw_scenes(now)
                await anyio.sleep(TIME_PERIOD)
        finally:
            self._taps.stop()
            if self in runtime.services.listeners:
                runtime.services.listeners.remove(self)
            self._front.stop()
            self._server.stop()

    def _warn(self, message: str) -> None:
        """Log ``message`` (told in the front's thread) in the graph's loop, once there is one."""
        loop, runtime = self._loop, self._runtime
        if loop is not None and runtime is not None:
            try:
                loop.call_soon_threadsafe(runtime.logger.warning, message)
            except RuntimeError:  # the loop has closed: the graph is gone
                pass

    # -- scenes (SceneHost) -----------------------------------------------------------------

    def add_scene(self, topic: str, draw: Draw) -> None:
        """Serve ``draw``'s ``foxglove.SceneUpdate`` on ``topic`` (protobuf, Foxglove's own schema).

        ``draw(now_ns)`` is called at each time broadcast (every
        :data:`TIME_PERIOD` of graph time) while a client subscribes, never
        otherwise.  A ``draw`` that raises is logged once and dropped.
        """
        self.remove_scene(topic)
        self._scenes[topic] = [draw, None]
        if self._server is not None:
            self._open_scene(topic)

    def remove_scene(self, topic: str) -> None:
        """Stop serving the scene on ``topic``; its channel goes away for clients."""
        scene = self._scenes.pop(topic, None)
        if scene is not None and scene[1] is not None:
            scene[1].close()

    def _open_scene(self, topic: str) -> None:
        self._scenes[topic][1] = self._fox.channels.SceneUpdateChannel(topic, context=self._context)

    def _draw_scenes(self, now: int) -> None:
        for topic, (draw, channel) in list(self._scenes.items()):
            if not channel.has_sinks():
                continue
            try:
                update = draw(now)
            except Exception as exc:  # a painter's bug must not take the view (or the graph) down
                self.remove_scene(topic)
                assert self._runtime is not None
                self._runtime.logger.warning(f"foxglove: scene {topic} left out: drawing it raised {exc!r}")
                continue
            channel.log(update, log_time=now)

    # -- topics ---------------------------------------------------------------------------

    def _wants(self, topic: str) -> bool:
        return self.include_hidden or not is_hidden_name(topic)

    def _advertise(self, tap: Tap) -> None:
        """A new tap: its channel, advertised to clients at once (a quiet topic too)."""
        if tap.channel is None:
            fox = self._fox
            schema = fox.Schema(name=tap.ros_type, encoding="ros2msg", data=tap.definition.encode())
            tap.channel = fox.Channel(
                tap.topic_name,
                schema=schema,
                message_encoding="cdr",
                context=self._context,
                metadata={"topic_type_hash": tap.type_hash},
            )

    def on_subscribe(self, client: Any, channel: Any) -> None:
        """A client subscribed (told in one of the SDK's threads): send the topic's latched messages, in the loop."""
        loop = self._loop
        if loop is not None:
            try:
                loop.call_soon_threadsafe(self._replay_latched, channel.topic)
            except RuntimeError:  # the loop has closed: the graph is gone
                pass

    def on_unsubscribe(self, client: Any, channel: Any) -> None:
        """Nothing to do: the channel's ``has_sinks`` already says whether anyone still looks."""

    def _replay_latched(self, topic_name: str) -> None:
        tap, runtime = self._taps.taps.get(topic_name), self._runtime
        topic = None if runtime is None else runtime.topics.topics.get(topic_name)
        if tap is not None and topic is not None and runtime is not None:
            for msg in latched(topic, runtime.loop.time()):
                self._deliver(tap, msg)

    def _deliver(self, tap: Tap, msg: Any) -> None:
        channel = tap.channel
        if not channel.has_sinks():  # nobody looks: nothing to encode
            return
        try:
            data = codec.encode_cdr(msg)
        except Exception as exc:  # a message its type cannot carry: never the publisher's problem
            tap.dropped += 1
            if not tap.failed:
                tap.failed = True
                tap.node.logger.warning(f"foxglove: a message on {tap.topic_name} cannot be sent: {exc}")
            return
        channel.log(data, log_time=self._now_ns())

    # -- services (ServiceListener) ----------------------------------------------------------

    def service_added(self, service: Service) -> None:
        """A new server: callable from Foxglove under its name."""
        name = service.service_name
        if name in self._services or (is_hidden_name(name) and not self.include_hidden):
            return
        fox, srv_type = self._fox, service.srv_type
        try:
            request, response = (
                fox.MessageSchema(
                    encoding="cdr",
                    schema=fox.Schema(name=type_name(t), encoding="ros2msg", data=codec.definition_text(t).encode()),
                )
                for t in (srv_type.Request, srv_type.Response)
            )
        except Exception as exc:  # a type with no ROS definition: say so once, serve the rest
            service.node.logger.warning(f"foxglove: leaving out service {name}: {exc}")
            return
        runtime, owner = self._runtime, self._owner
        assert runtime is not None and owner is not None  # servers are heard of only while attached
        # A partial owner: the view's clients are dropped, never destroyed through it.
        client = Client(cast(Owner, owner), name, srv_type, runtime.services)
        self._services[name] = client
        schema = fox.ServiceSchema(type_name(srv_type), request=request, response=response)
        self._server.add_services([fox.Service(name, schema=schema, handler=lambda req: self._call(client, req))])

    def service_removed(self, service: Service) -> None:
        """A server went away: no longer offered."""
        if self._services.pop(service.service_name, None) is not None:
            self._server.remove_services([service.service_name])

    def client_added(self, client: Client) -> None:
        """Clients are not shown."""

    def client_removed(self, client: Client) -> None:
        """Clients are not shown."""

    def _call(self, client: Client, request: Any) -> bytes:
        """Foxglove's call (in one of the SDK's threads): decoded, made in the graph's loop, answered.

        An exception becomes the call's error message in Foxglove.
        """
        assert self._loop is not None
        msg = codec.decode_cdr(request.payload, client.srv_type.Request)
        future = asyncio.run_coroutine_threadsafe(client.call(msg), self._loop)
        try:
            return codec.encode_cdr(future.result(timeout=CALL_TIMEOUT))
        except concurrent.futures.TimeoutError:
            future.cancel()
            raise TimeoutError(f"service {client.service_name} did not answer within {CALL_TIMEOUT:g} s") from None
