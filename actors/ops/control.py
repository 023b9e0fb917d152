"""The control endpoint: the Unix socket through which the command line reads and drives a graph.

A :class:`~actors.runtime.Runtime` serves one while it runs when it is given
the :class:`ControlEndpoint` attachment (``python -m actors.run`` gives one).

Where.  ``<dir>/<graph name>.sock``.  ``<dir>`` is ``$XDG_RUNTIME_DIR/actors``
when that variable names a directory owned by this user, else
``/tmp/actors-<uid>``; it is made with mode 0700 and refused when it belongs to
someone else or is open to group or others.  The socket is 0600: only the same
user can connect.  A name taken by a live graph moves on to ``<name>-2``,
``<name>-3``...; a socket whose server is gone (a killed process) is replaced.
Names are claimed under a lock file, so two graphs starting at once cannot
steal each other's socket.

Frames.  A 4-byte big-endian length, then a msgpack body (msgspec, never
pickle).  A request body over :data:`MAX_FRAME` bytes, or not msgpack, is
answered with an error and closes that connection and nothing else; replies
are not capped (a large message may be streamed to a subscriber).  A body is
one request, tagged by its ``op`` field (the Structs below); the reply is a
:class:`Reply` whose ``result`` has the type each request names.  A request
that fails gets ``ok=False`` and the reason; it never stops the graph.  A
malformed request (a bad frame, an unknown operation, a value that does not
fit its type) is logged once per connection, as one line.

Limits.  Connections are bounded in number, in time and in what they may
make the graph hold (:mod:`actors.ops._connections`): one more than
:attr:`ConnectionLimits.connections` is refused with an error reply; idle
ones and half-sent frames time out; a slow subscriber loses samples, counted,
instead of growing the graph; running out of file descriptors refuses
connections without harming the graph.  ``doctor`` reports what was hit.

Sessions.  One connection is one session.  The publishers, subscriptions and
clients its requests create belong to a hidden owner ``/_actors_cli_<n>``
(hidden as ROS hides names starting with ``_``: ``node list`` and ``doctor``
leave them out, ``topic info`` shows them) and are removed when the connection
closes.  ``n`` is the lowest number no open session has: with a transport, the
names a graph announces come back rather than being new each time, and Zenoh
keeps state for every name it ever heard of (in this process and in its peers).
After a :class:`Subscribe` reply the server streams :class:`Sample` frames
until the client disconnects.  Samples are encoded as they arrive and wait in
the connection's bounded outbox, so a slow reader never holds up the graph nor
makes it hold more than the outbox.

The server runs in the runtime's task group; sockets are non-blocking, so it
never blocks the loop.  With it, on a wall-clock runtime, runs doctor's
:class:`~actors.ops.doctor.LagMonitor`.
"""

from __future__ import annotations

import itertools
import os
import socket
import stat
import struct
from collections.abc import Iterable, Iterator, Sequence
from contextlib import contextmanager, suppress
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any, cast

import anyio
import anyio.abc
import msgspec

from actors import codec
from actors.core._actor import Actor, CallbackFailed, Owner
from actors.core.explain import did_you_mean, explain
from actors.core.tomlfile import MAX_SECONDS
from actors.errors import ActorsError, ControlError, InterfaceError
from actors.ops._connections import Connection, ConnectionLimits, ConnectionPool, ConnectionStats
from actors.ros.names import expand
from actors.ros.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy, profile_from_short_keys
from actors.ros.topics import Publisher, Subscription, type_name
from actors.services import Client
from actors.system.introspection import NodeInfo, ServiceInfo, TopicInfo
from interfaces.rcl_interfaces.msg import Log, ParameterEvent

if TYPE_CHECKING:
    from actors.ops.doctor import LagMonitor, Report
    from actors.runtime import Runtime

__all__ = [
    "MAX_FRAME",
    "LISTEN_BACKLOG",
    "Request",
    "GetGraph",
    "GetNode",
    "Publish",
    "QoSChoice",
    "Subscribe",
    "Call",
    "Diagnose",
    "Play",
    "Reply",
    "Sample",
    "GraphSnapshot",
    "NodeDetail",
    "ControlServer",
    "ControlEndpoint",
    "ConnectionLimits",
    "endpoint_dir",
    "endpoint_paths",
    "endpoint_name",
    "GRAPH_VARIABLE",
    "is_alive",
    "frame",
    "decode_reply",
    "set_at",
]

MAX_FRAME = 1 << 20
"""The largest request body the server reads, in bytes."""

_HEADER = struct.Struct(">I")
_SUFFIX = ".sock"


# --------------------------------------------------------------------------- requests and replies


class Request(msgspec.Struct, tag_field="op", kw_only=True, forbid_unknown_fields=True):
    """Base of every request; the ``op`` field names the operation."""


class GetGraph(Request, tag="graph"):
    """The whole graph.  Result: :class:`GraphSnapshot`."""


class GetNode(Request, tag="node"):
    """One node (``/ns/name`` or plain name) and the types it uses.  Result: :class:`NodeDetail`."""

    name: str


class QoSChoice(msgspec.Struct, frozen=True, kw_only=True, forbid_unknown_fields=True):
    """``--qos-*`` of ``topic echo`` and ``topic pub``: a preset and the policies that override it,
    by rclpy's short keys (``sensor_data``, ``best_effort``)."""

    profile: str
    depth: Annotated[int, msgspec.Meta(ge=0, le=100_000)] | None = None
    history: str | None = None
    reliability: str | None = None
    durability: str | None = None
    liveliness: str | None = None
    lease_seconds: Annotated[float, msgspec.Meta(ge=0, le=1e9)] | None = None

    def overrides(self) -> bool:
        """Whether a policy is given besides the preset."""
        given = (self.depth, self.history, self.reliability, self.durability, self.liveliness, self.lease_seconds)
        return any(value is not None for value in given)

    def qos(self) -> QoSProfile:
        """The profile; ControlError naming an unknown key."""
        try:
            return profile_from_short_keys(
                self.profile,
                history=self.history,
                depth=self.depth,
                reliability=self.reliability,
                durability=self.durability,
                liveliness=self.liveliness,
                lease_seconds=self.lease_seconds,
            )
        except KeyError as exc:
            raise ControlError(f"qos: unknown short key {exc}") from None


class Publish(Request, tag="publish"):
    """Publish ``msg`` (field values) on ``topic`` as ``type``, from the session's publisher.

    The publisher is made on first use and kept until the connection closes.
    ``qos`` is the publisher's profile (default: rclpy's default, depth 10).
    ``stamps`` are the paths (field names, list indices) of ``builtin_interfaces/Time``
    fields set to the graph's clock as it publishes (``ros2 topic pub``'s ``auto``
    headers and ``now`` stamps); ``count_only`` makes the publisher and publishes
    nothing.  Result: ``{"subscribers": n}``, the subscriptions it reaches.  Fails
    when the topic carries another type.
    """

    topic: str
    type: str
    msg: dict[str, Any] = {}
    stamps: list[list[str | int]] = []
    count_only: bool = False
    qos: QoSChoice | None = None  # the publisher's, when this request makes it (default: depth 10)


class Subscribe(Request, tag="subscribe"):
    """Stream ``topic``: result ``{"type": ros_name}``, then :class:`Sample` frames until hang-up.

    ``content=False`` streams stamps only (what ``topic hz`` needs); ``ros_time``
    stamps samples in ROS time (what ``topic delay`` compares headers with).  With a
    ``type`` (``echo TOPIC TYPE``) the topic need not exist yet, as in ROS;
    without one, a topic that does not exist fails, and so does a topic of
    another type.  The subscription's QoS is chosen to match every publisher
    (see ``_subscribe``); a ``qos`` with policies of its own is taken as it is,
    one with a preset only gives its depth and history, as ``ros2 topic echo`` does.
    """

    topic: str
    content: bool = True
    depth: Annotated[int, msgspec.Meta(ge=1, le=10_000)] = 100
    ros_time: bool = False  # stamps in ROS time (the runtime clock's now), not loop time
    type: str = ""
    qos: QoSChoice | None = None


class Call(Request, tag="call"):
    """Call ``service`` (of type ``type``) with ``request`` field values; wait ``timeout`` seconds.

    Result: the response message.  Fails for an unknown service, another type,
    a handler that raised, or no answer in time.
    """

    service: str
    type: str
    request: dict[str, Any] = {}
    timeout: Annotated[float, msgspec.Meta(gt=0, le=MAX_SECONDS)] = 10.0


class Diagnose(Request, tag="doctor"):
    """Run doctor's checks.  Result: :class:`~actors.ops.doctor.Report`."""


class Play(Request, tag="play"):
    """Play the bag at ``path`` into the graph on its own clock (``actors.recording.player.play``).

    Answered when the bag has played: result ``{"played": n}``.  The client
    sends nothing meanwhile; hanging up stops the playing (``loop`` plays
    until then).  Fails for a bag that cannot be read.
    """

    path: str
    topics: list[str] | None = None
    remap: dict[str, str] = {}
    rate: float = 1.0
    clock: float = 0.0
    loop: bool = False
    recover: bool = False


_Requests = GetGraph | GetNode | Publish | Subscribe | Call | Diagnose | Play


class Reply(msgspec.Struct, kw_only=True, omit_defaults=True):
    """The answer to one request: ``ok`` and ``result``, or the ``error`` text.

    ``busy`` marks the answer a refused connection gets (too many open, no
    descriptor left): the same request on a new connection may succeed soon.
    """

    ok: bool = True
    result: Any = None
    error: str = ""
    busy: bool = False


class Sample(msgspec.Struct, kw_only=True, omit_defaults=True):
    """One streamed message: when it was received (runtime clock, seconds), and its fields."""

    stamp: float
    msg: Any = None


class GraphSnapshot(msgspec.Struct, frozen=True, kw_only=True):
    """The graph as ``GraphView`` sees it, with its name and clock (``wall`` or ``virtual``)."""

    name: str
    clock: str
    nodes: tuple[NodeInfo, ...]
    topics: tuple[TopicInfo, ...]
    services: tuple[ServiceInfo, ...]


class NodeDetail(msgspec.Struct, frozen=True, kw_only=True):
    """A node's endpoints as ``(name, type)`` pairs, in the sections ``ros2 node info`` prints."""

    name: str
    subscribers: tuple[tuple[str, str], ...]
    publishers: tuple[tuple[str, str], ...]
    servers: tuple[tuple[str, str], ...]
    clients: tuple[tuple[str, str], ...]


def frame(obj: Any) -> bytes:
    """``obj`` encoded as one frame: length header and msgpack body."""
    body = codec.encode(obj)
    return _HEADER.pack(len(body)) + body


def decode_reply(body: bytes) -> Reply:
    """A :class:`Reply` from a frame body; msgspec.DecodeError when it is not one."""
    return _reply_decoder.decode(body)


_reply_decoder = msgspec.msgpack.Decoder(Reply)


# --------------------------------------------------------------------------- where endpoints live


def endpoint_dir(*, create: bool = False) -> Path:
    """The per-user directory of the endpoints (see the module docstring).

    With ``create``, it is made (mode 0700) when missing.  Raises ControlError
    when it exists but is not a real directory owned by this user and closed to
    group and others: someone else could read or plant sockets there.
    """
    uid = os.getuid()
    runtime_dir = os.environ.get("XDG_RUNTIME_DIR")
    directory = Path(f"/tmp/actors-{uid}")
    if runtime_dir:
        with suppress(OSError):
            if os.stat(runtime_dir).st_uid == uid:
                directory = Path(runtime_dir) / "actors"
    if create:
        with suppress(FileExistsError):
            os.mkdir(directory, 0o700)
    try:
        info = os.lstat(directory)
    except FileNotFoundError:
        return directory  # nothing runs yet
    if not stat.S_ISDIR(info.st_mode) or info.st_uid != uid or info.st_mode & 0o077:
        raise ControlError(
            f"refusing the control directory {directory}: it must be a directory owned by "
            f"uid {uid} with mode 0700 (it is {stat.filemode(info.st_mode)}, uid {info.st_uid})"
        )
    return directory


GRAPH_VARIABLE = "ACTORS_GRAPH"
"""The environment variable naming the graph commands talk to when no ``--graph`` is given."""


def endpoint_name(path: Path) -> str:
    """The name the command line reaches the endpoint at ``path`` by (``--graph NAME``)."""
    return path.name[: -len(_SUFFIX)]


def endpoint_paths() -> dict[str, Path]:
    """The socket of every graph that may be running, by endpoint name (stale ones included)."""
    directory = endpoint_dir()
    if not directory.is_dir():
        return {}
    return {endpoint_name(path): path for path in sorted(directory.glob(f"*{_SUFFIX}"))}


LISTEN_BACKLOG = 1024
"""New connections the kernel queues for the graph to accept: a burst of clients waits there
(costing the graph no descriptor) instead of being turned away unanswered."""


def is_alive(path: Path) -> bool:
    """Whether a server listens on ``path``; never blocks."""
    probe = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    probe.setblocking(False)
    try:
        probe.connect(str(path))
    except BlockingIOError:
        return True  # its backlog is full: it is alive, just busy
    except OSError:
        return False
    finally:
        probe.close()
    return True


@contextmanager
def _claim_lock(directory: Path) -> Iterator[None]:
    import fcntl

    fd = os.open(directory / ".lock", os.O_CREAT | os.O_RDWR, 0o600)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)  # held for a few system calls only
        yield
    finally:
        os.close(fd)


def _endpoint_base(name: str) -> str:
    """The endpoint name a graph called ``name`` asks for first: its characters safe in a file name."""
    return "".join(c if c.isalnum() or c in "-_." else "_" for c in name) or "actors"


def _bind(name: str) -> tuple[socket.socket, Path]:
    """A listening socket on the first free ``<name>[-n].sock``; raises ControlError or OSError."""
    directory = endpoint_dir(create=True)
    base = _endpoint_base(name)
    with _claim_lock(directory):
        for n in range(1, 1000):
            path = directory / f"{base if n == 1 else f'{base}-{n}'}{_SUFFIX}"
            if len(os.fsencode(path)) >= 104:  # sun_path holds 104 bytes on macOS, 108 on Linux
                raise ControlError(f"control socket path too long: {path}")
            if path.exists() or path.is_symlink():
                if is_alive(path):
                    continue
                path.unlink()  # stale: its graph was killed
            sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
            try:
                sock.setblocking(False)
                sock.bind(str(path))
                os.chmod(path, 0o600)
                sock.listen(LISTEN_BACKLOG)
            except BaseException:
                sock.close()
                raise
            return sock, path
    raise ControlError(f"no free control socket name for graph {name!r} in {directory}")


# --------------------------------------------------------------------------- the server


class ControlServer:
    """A running endpoint: its socket ``path``, its loop-lag ``monitor`` (None on virtual time).

    ``pool`` holds its connections, within ``limits``; ``pool.stats()`` is
    what doctor reports.
    """

    def __init__(self, runtime: Runtime, path: Path, limits: ConnectionLimits | None = None) -> None:
        self.runtime = runtime
        self.path = path
        self.monitor: LagMonitor | None = None
        self.pool = ConnectionPool(limits or ConnectionLimits(), self.serve, _refusal, runtime.logger.warning)
        self._session_numbers: set[int] = set()  # of the open sessions (see the module docstring)

    def snapshot(self) -> GraphSnapshot:
        """The graph now."""
        rt = self.runtime
        graph = rt.graph
        return GraphSnapshot(
            name=rt.name,
            clock="virtual" if rt.clock.virtual else "wall",
            nodes=tuple(graph.nodes()),
            topics=tuple(graph.topics()),
            services=tuple(graph.services()),
        )

    def stats(self) -> ConnectionStats:
        """What the endpoint's connections did so far."""
        return self.pool.stats()

    def diagnose(self) -> Report:
        """Doctor's report on the graph now."""
        from actors.ops.doctor import diagnose

        return diagnose(self.runtime, self.monitor, self.stats())

    async def serve(self, connection: Connection) -> None:
        """Serve one connection until it closes or sends a bad frame."""
        number = next(n for n in itertools.count(1) if n not in self._session_numbers)
        self._session_numbers.add(number)
        session = _Session(self, connection, number)
        try:
            async with anyio.create_task_group() as tg:
                tg.start_soon(session.run_actor, tg.cancel_scope)
                tg.start_soon(session.write_samples, tg.cancel_scope)
                await session.serve()
                tg.cancel_scope.cancel()
        finally:
            session.close()
            self._session_numbers.discard(number)


def _refusal(why: str) -> bytes:
    return frame(Reply(ok=False, error=why, busy=True))


_GONE = (anyio.EndOfStream, anyio.BrokenResourceError, anyio.ClosedResourceError)


class _Session:
    """One connection's hidden owner of publishers, subscriptions and clients.

    It quacks like the NodeCore its entities expect (``fqn``, ``runtime``,
    ``loop``, ``actor``) without being a node of the graph: a partial
    :class:`~actors.core._actor.Owner` (cast to one where its entities are
    made), with no ``destroy_*``, as the session removes its entities itself.
    """

    def __init__(self, server: ControlServer, connection: Connection, number: int) -> None:
        rt = server.runtime
        self.server = server
        self.runtime = rt
        self.connection = connection
        self.fqn = f"/_actors_cli_{number}"
        self.loop = rt.loop
        self.actor = Actor(rt.loop)
        self._publishers: dict[str, Publisher] = {}
        self._subscriptions: list[Subscription] = []
        self._clients: dict[str, Client] = {}

    @property
    def logger(self) -> Any:
        """The runtime's logger (what an entity of the session would log through)."""
        return self.runtime.logger

    async def run_actor(self, scope: anyio.CancelScope) -> None:
        """Run the session's callbacks; a failed one ends the session."""
        try:
            await self.actor.run()
        except CallbackFailed:
            scope.cancel()

    async def write_samples(self, scope: anyio.CancelScope) -> None:
        """Send the streamed samples; the client gone ends the session."""
        try:
            await self.connection.write_outbox()
        except _GONE:
            scope.cancel()

    async def serve(self) -> None:
        """Answer requests until the client goes away or sends a bad frame."""
        connection = self.connection
        buffer = bytearray()
        try:
            while True:
                while len(buffer) >= _HEADER.size:
                    (size,) = _HEADER.unpack_from(buffer)
                    if size > MAX_FRAME:
                        await self._fail(f"a request of {size} bytes is over the limit of {MAX_FRAME}")
                        return
                    if len(buffer) < _HEADER.size + size:
                        break
                    body = bytes(buffer[_HEADER.size : _HEADER.size + size])
                    del buffer[: _HEADER.size + size]
                    try:
                        request: Any = msgspec.msgpack.decode(body)
                    except (msgspec.DecodeError, RecursionError) as exc:
                        await self._fail(f"a request must be a msgpack map ({exc})")
                        return
                    with connection.busy():
                        await connection.send(await self.answer(request))
                if buffer:
                    connection.frame_begun()
                else:
                    connection.frame_done()
                buffer += await connection.stream.receive(1 << 16)
        except _GONE:
            pass  # the client went away

    async def _fail(self, problem: str) -> None:
        """Answer a frame that cannot be read, then leave: the stream can no longer be trusted."""
        self.connection.report(problem)
        with suppress(*_GONE):
            await self.connection.send(frame(Reply(ok=False, error=problem)))

    async def answer(self, raw: Any) -> bytes:
        """The reply frame to one decoded request body; errors become ``ok=False`` replies."""
        try:
            request = msgspec.convert(raw, _Requests)
        except msgspec.ValidationError as exc:
            key, problem, _ = explain(exc, _Requests, raw)
            text = f"bad request: {key}: {problem}" if key else f"bad request: {problem}"
            self.connection.report(text)
            return frame(Reply(ok=False, error=text))
        try:
            return frame(Reply(result=await self._dispatch(request)))
        except InterfaceError as exc:  # a message or type that does not fit: malformed
            self.connection.report(str(exc))
            return frame(Reply(ok=False, error=str(exc)))
        except (ActorsError, TimeoutError) as exc:
            return frame(Reply(ok=False, error=str(exc)))
        except Exception as exc:
            self.connection.report(f"{type(request).__name__} failed: {type(exc).__name__}: {exc}")
            self.runtime.logger.debug(f"control request {request!r} failed", exc_info=exc)
            return frame(Reply(ok=False, error=f"internal error in the graph: {exc!r}"))

    async def _dispatch(self, request: Request) -> Any:
        if isinstance(request, GetGraph):
            return self.server.snapshot()
        if isinstance(request, GetNode):
            return self._node(request.name)
        if isinstance(request, Publish):
            return await self._publish(request)
        if isinstance(request, Subscribe):
            return self._subscribe(request)
        if isinstance(request, Call):
            return await self._call(request)
        if isinstance(request, Play):
            return await self._play(request)
        assert isinstance(request, Diagnose)
        return self.server.diagnose()

    # -- the operations ---------------------------------------------------------

    def _node(self, name: str) -> NodeDetail:
        try:
            core = self.runtime._find(name)
        except LookupError:
            return self._remote_node(name)
        return NodeDetail(
            name=core.fqn,
            subscribers=_pairs((s.topic_name, s.msg_type) for s in core.subscriptions),
            publishers=_pairs([*((p.topic_name, p.msg_type) for p in core.publishers), *_EVERY_NODE_PUBLISHES]),
            servers=_pairs(core.served()),
            clients=_pairs((c.service_name, c.srv_type) for c in core.clients),
        )

    def _remote_node(self, name: str) -> NodeDetail:
        """A node of another process (seen through a transport); ControlError if there is none."""
        full = name if name.startswith("/") else f"/{name}"
        node = next((n for n in self.runtime.graph.remote_nodes() if n.name == full), None)
        if node is None:
            known = [n.name for n in self.runtime.graph.nodes()]
            raise ControlError(f"unknown node {name}{did_you_mean(full, known)}")

        def pairs(kind: str) -> tuple[tuple[str, str], ...]:
            return tuple(sorted({(e.name, e.type) for e in node.endpoints if e.kind == kind}))

        return NodeDetail(
            name=node.name,
            subscribers=pairs("subscription"),
            publishers=pairs("publisher"),
            servers=pairs("server"),
            clients=pairs("client"),
        )

    def _topic(self, name: str, asked: str) -> tuple[Any, type[Any]]:
        """The topic ``name`` (None if it does not exist yet) and its type, ``asked`` or its own.

        A topic only other processes use (seen through a transport) has the type they give it.
        """
        topic = self.runtime.topics.topics.get(name)
        if topic is None and not asked:
            remote = self.runtime.graph.topic(name)
            asked = remote.type if remote is not None else ""
        msg_type = codec.get_type(asked) if asked else None
        if topic is None and msg_type is None:
            known = [t.name for t in self.runtime.graph.topics()]
            raise ControlError(f"unknown topic {name}{did_you_mean(name, known)}")
        if topic is not None and msg_type is not None and topic.msg_type is not msg_type:
            raise ControlError(f"topic {name} carries {type_name(topic.msg_type)}, not {asked}")
        if msg_type is None:
            assert topic is not None  # one of them is, as checked above
            msg_type = topic.msg_type
        return topic, msg_type

    async def _publish(self, request: Publish) -> dict[str, Any]:
        name = expand(request.topic, "/", "_")
        _, msg_type = self._topic(name, request.type)
        msg = codec.convert(request.msg, msg_type)  # before anything is made: a bad one leaves no trace
        pub = self._publishers.get(name)
        if pub is None:
            qos = request.qos.qos() if request.qos is not None else QoSProfile(depth=10)
            pub = Publisher(cast(Owner, self), name, msg_type, qos)  # see _Session
            self.runtime.topics.add_publisher(pub)
            self._publishers[name] = pub
            await self._reach_other_processes(pub)
        if request.count_only:
            return {"subscribers": pub.get_subscription_count()}
        now = self.runtime.clock.now().to_msg()
        for path in request.stamps:
            set_at(msg, path, now)
        pub.publish(msg)
        return {"subscribers": pub.get_subscription_count(), "stamp": codec.to_builtins(now)}

    async def _reach_other_processes(self, pub: Publisher) -> None:
        """Give a new publisher a moment to find the subscriptions of other processes.

        A transport connects it to them once discovery has matched them (a few
        milliseconds); publishing before would miss them.  At most 2 s.
        """
        info = self.runtime.graph.topic(pub.topic_name)
        if info is not None and any(s.process for s in info.subscriptions):
            with anyio.move_on_after(2.0):
                while not pub.get_subscription_count():
                    await anyio.sleep(0.01)

    def _subscribe(self, request: Subscribe) -> dict[str, str]:
        name = expand(request.topic, "/", "_")
        _, msg_type = self._topic(name, request.type)
        # Best effort and volatile match every publisher; transient local when all
        # publishers keep history, so that a latched topic's last message shows up.
        # Those of other processes count too (a transport's graph view has them).
        info = self.runtime.graph.topic(name)
        pubs = info.publishers if info is not None else ()
        # (Not for `hz`, content=False: a replayed history would look like a burst.)
        latched = (
            request.content and bool(pubs) and all(p.qos.durability == DurabilityPolicy.TRANSIENT_LOCAL for p in pubs)
        )
        choice = request.qos
        if choice is not None and choice.overrides():
            qos = choice.qos()
        else:
            qos = choice.qos() if choice is not None else QoSProfile(depth=max(1, request.depth))
            qos.reliability = ReliabilityPolicy.BEST_EFFORT
            qos.durability = DurabilityPolicy.TRANSIENT_LOCAL if latched else DurabilityPolicy.VOLATILE
        clock = self.runtime.clock
        content = request.content
        post = self.connection.post
        now = (lambda: clock.now_ns() / 1e9) if request.ros_time else clock.monotonic

        def forward(msg: Any) -> None:  # encoded at once: the outbox bounds what waits
            post(frame(Sample(stamp=now(), msg=msg if content else None)))

        sub = Subscription(cast(Owner, self), name, msg_type, forward, qos)  # see _Session
        self.runtime.topics.add_subscription(sub)
        self._subscriptions.append(sub)
        self.connection.streaming = True
        return {"type": type_name(msg_type)}

    async def _call(self, request: Call) -> Any:
        name = expand(request.service, "/", "_", what="service name")
        server = self.runtime.services.get(name)
        if server is None:
            known = [s.name for s in self.runtime.graph.services()]
            raise ControlError(f"unknown service {name}{did_you_mean(name, known)}")
        srv_type = codec.get_type(request.type)
        if srv_type is not server.srv_type:
            raise ControlError(f"service {name} has type {type_name(server.srv_type)}, not {request.type}")
        client = self._clients.get(name)
        if client is None:
            client = Client(cast(Owner, self), name, srv_type, self.runtime.services)  # see _Session
            self._clients[name] = client
        try:
            return await client.call(codec.convert(request.request, srv_type.Request), timeout=request.timeout)
        except TimeoutError:
            raise TimeoutError(f"service {name} did not answer within {request.timeout:g} s") from None

    async def _play(self, request: Play) -> dict[str, int]:
        from actors.recording.player import play
        from actors.recording.reader import Bag

        try:
            bag = Bag(request.path, recover=request.recover)
        except FileNotFoundError as exc:
            raise ControlError(str(exc)) from None
        if request.rate <= 0:
            raise ControlError(f"rate must be > 0, got {request.rate}")
        played = 0
        async with anyio.create_task_group() as tg:

            async def until_hang_up() -> None:
                with suppress(*_GONE):
                    await self.connection.stream.receive(1)  # the client sends nothing while a bag plays
                tg.cancel_scope.cancel()

            tg.start_soon(until_hang_up)
            played = await play(
                self.runtime,
                bag,
                topics=request.topics,
                remap=request.remap,
                rate=request.rate,
                clock_hz=request.clock,
                loop=request.loop,
            )
            tg.cancel_scope.cancel()
        return {"played": played}

    def close(self) -> None:
        """Remove everything this session created from the graph."""
        self.actor.stop()
        topics = self.runtime.topics
        for pub in self._publishers.values():
            topics.remove_publisher(pub)
        for sub in self._subscriptions:
            topics.remove_subscription(sub)
        self._publishers.clear()
        self._subscriptions.clear()
        self._clients.clear()


# Every ROS node publishes its log and its parameter changes, so ros2's node info lists both for
# each; here the runtime's one publisher of each carries them for all its nodes.
_EVERY_NODE_PUBLISHES = (("/parameter_events", ParameterEvent), ("/rosout", Log))


def _pairs(items: Iterable[tuple[str, type]]) -> tuple[tuple[str, str], ...]:
    return tuple(sorted({(name, type_name(t)) for name, t in items}))


class ControlEndpoint:
    """The attachment that serves a runtime's control endpoint: ``Runtime(attach=[ControlEndpoint()])``.

    ``server`` is the running :class:`ControlServer` once the runtime has
    started, or None when no endpoint could be made: no Unix sockets on this
    platform, or an unsafe or unusable directory (a warning is logged; the
    graph runs either way).  When the runtime stops, the socket file is removed.
    ``limits`` bound its connections (:class:`ConnectionLimits`' defaults).
    """

    def __init__(self, limits: ConnectionLimits | None = None) -> None:
        self.server: ControlServer | None = None
        self.limits = limits

    async def __call__(
        self, runtime: Runtime, *, task_status: anyio.abc.TaskStatus[Any] = anyio.TASK_STATUS_IGNORED
    ) -> None:
        try:
            if not hasattr(socket, "AF_UNIX"):
                raise ControlError("this platform has no Unix sockets")
            sock, path = _bind(runtime.name)
        except (ControlError, OSError) as exc:
            runtime.logger.warning(f"no control endpoint, the command line cannot reach this graph: {exc}")
            task_status.started()
            return
        endpoint = endpoint_name(path)
        if endpoint != _endpoint_base(runtime.name):
            runtime.logger.warning(
                f"another graph named {runtime.name!r} is running: the command line reaches this one "
                f"as --graph {endpoint}, and --graph {runtime.name} reaches the other"
            )
        inode = -1  # the socket file is ours only once we know its inode
        try:
            inode = os.stat(path).st_ino
            self.server = server = ControlServer(runtime, path, self.limits)
            async with anyio.create_task_group() as tg:
                if not runtime.clock.virtual:
                    from actors.ops.doctor import LagMonitor

                    server.monitor = LagMonitor(runtime)
                    tg.start_soon(server.monitor.run)
                task_status.started()
                await server.pool.run(sock)
        finally:
            sock.close()
            _unlink_if_same(path, inode)


def _unlink_if_same(path: Path, inode: int) -> None:
    # Only our own socket: after a stale-name takeover the file may be another graph's.
    # Failing to remove it is harmless: the next graph of that name replaces a stale socket.
    with suppress(OSError):
        if os.stat(path).st_ino == inode:
            path.unlink()


def set_at(msg: Any, path: Sequence[str | int], value: Any) -> None:
    """Set the field of ``msg`` that ``path`` names (names and list indices) to ``value``."""
    target = msg
    try:
        for step in path[:-1]:
            target = target[step] if isinstance(step, int) else getattr(target, step)
        if not path or isinstance(path[-1], int) or type(getattr(target, path[-1])) is not type(value):
            raise TypeError
    except (AttributeError, IndexError, TypeError):
        raise ControlError(f"stamps: {'.'.join(map(str, path))} is no time field of {type_name(type(msg))}") from None
    setattr(target, path[-1], value)
