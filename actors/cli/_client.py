"""The command line's side of the control endpoint: finding the running graph, requests, samples.

Every verb that talks to a graph goes through :func:`connect` (or
:func:`query` for one request).  Whatever goes wrong (no graph, an error
reply, a graph that stops answering) is raised as ControlError, which the
dispatcher prints as one line on stderr, exiting 2.

The client is plain blocking sockets: a command makes a request or two and
waits, so it needs no event loop.
"""

from __future__ import annotations

import argparse
import contextlib
import functools
import os
import socket
import time
from collections.abc import Callable, Iterable, Iterator, Sequence
from pathlib import Path
from typing import Any, TypeVar, overload

import msgspec

from actors.errors import ControlError
from actors.ops.control import (
    GRAPH_VARIABLE,
    Call,
    GetGraph,
    GraphSnapshot,
    Request,
    Sample,
    decode_reply,
    endpoint_paths,
    frame,
    is_alive,
)

__all__ = [
    "NO_GRAPH",
    "BUSY_RETRY",
    "Connection",
    "add_verb",
    "print_names",
    "print_matching",
    "type_of",
    "add_type_and_find",
    "connect",
    "query",
    "graph_snapshot",
    "call_service",
]

T = TypeVar("T")

NO_GRAPH = "no running actors graph found (start one with: python -m actors.run graph.toml)"
BUSY_RETRY = 2.0
"""Seconds the command line keeps asking a graph that refused it as too busy."""
_sample_decoder = msgspec.msgpack.Decoder(Sample)


def add_verb(
    verbs: Any, name: str, func: Callable[[argparse.Namespace], int | None], help: str, aliases: Sequence[str] = ()
) -> Any:
    """Add a verb that runs ``func(args)`` and takes ``--graph NAME`` and ``--transport``; return its parser."""
    parser = verbs.add_parser(name, help=help, aliases=list(aliases))
    parser.add_argument(
        "--graph",
        metavar="NAME",
        help="the graph to talk to when several run (its file's stem, e.g. graph)",
    )
    parser.add_argument(
        "--transport",
        choices=("zenoh", "none"),
        help="zenoh: see every process's nodes over Zenoh (actors graphs, ROS 2 with rmw_zenoh_cpp) "
        "instead of one graph; default: $ACTORS_TRANSPORT, else none",
    )
    parser.set_defaults(func=functools.partial(_through_transport, func), verb_parser=parser)
    return parser


def _through_transport(func: Callable[[argparse.Namespace], int | None], args: argparse.Namespace) -> int | None:
    """Run a verb against one graph, or against the whole Zenoh graph (``--transport zenoh``)."""
    from actors.cli import _transport

    if not _transport.chosen(args.transport):
        return func(args)
    with _transport.bridge() as path:
        args.graph = path  # every verb connects to it as it would to a graph
        return func(args)


class Connection:
    """A connection to one graph's endpoint: requests, then possibly a stream of samples.

    ``name`` is the endpoint's name.  Use as a context manager; closing the
    connection removes whatever its requests created in the graph.  A graph
    too busy to take the connection says so at once; then its first request
    is sent again on a new connection (to ``path``) for up to :data:`BUSY_RETRY` s.
    """

    def __init__(self, sock: socket.socket, name: str, path: Path | None = None) -> None:
        self.name = name
        self._sock = sock
        self._path = path
        self._answered = False
        self._busy_until: float | None = None
        self._buffer = bytearray()

    def __enter__(self) -> Connection:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def close(self) -> None:
        """Close the connection."""
        self._sock.close()

    def fileno(self) -> int:
        """The socket's descriptor, so that a selector can wait on several connections."""
        return self._sock.fileno()

    @overload
    def request(self, request: Request, result_type: type[T], *, timeout: float | None = 10.0) -> T: ...

    @overload
    def request(self, request: Request, result_type: Any = Any, *, timeout: float | None = 10.0) -> Any: ...

    def request(self, request: Request, result_type: Any = Any, *, timeout: float | None = 10.0) -> Any:
        """Send ``request``; return its result as ``result_type``.

        Raises ControlError with the graph's reason when the request failed,
        or when no reply came within ``timeout`` seconds (None: no limit).
        """
        try:
            self._sock.sendall(frame(request))
        except OSError as exc:  # not BrokenPipeError: that means our stdout was closed
            # A graph too busy to take us answers before we speak, and hangs up.
            body = None if self._answered else self._read(0.5, quiet=True)
            if body is None:
                raise ControlError(f"lost the connection to graph {self.name}: {exc.strerror or exc}") from None
        else:
            body = self._read(timeout)
        if body is None:
            raise ControlError(f"graph {self.name} did not answer within {timeout:g} s")
        with self._readable():
            reply = decode_reply(body)
            if reply.busy and not self._answered and self._reconnect():
                return self.request(request, result_type, timeout=timeout)
            self._answered = True
            if not reply.ok:
                raise ControlError(reply.error)
            if result_type is Any:
                return reply.result
            return msgspec.convert(reply.result, result_type)

    def _reconnect(self) -> bool:
        """A new socket to the same graph after a refusal, a little later; False once time is up."""
        if self._path is None:
            return False
        now = time.monotonic()
        if self._busy_until is None:
            self._busy_until = now + BUSY_RETRY
        if now >= self._busy_until:
            return False
        time.sleep(min(0.05, self._busy_until - now))  # the graph asked for a moment
        sock = _open(self._path)
        if sock is None:
            return False
        self._sock.close()
        self._sock, self._buffer = sock, bytearray()
        return True

    def graph(self) -> GraphSnapshot:
        """The graph as it is now."""
        return self.request(GetGraph(), GraphSnapshot)

    def sample(self, timeout: float | None = None) -> Sample | None:
        """The next streamed sample; None if ``timeout`` seconds pass first (None: no limit)."""
        body = self._read(timeout)
        if body is None:
            return None
        with self._readable():
            return _sample_decoder.decode(body)

    def samples(self, wait: float = 0.0) -> Iterator[Sample]:
        """The next sample, waiting up to ``wait`` seconds for it, then every other one already read.

        A reply's read may bring streamed samples with it, and the socket does not say
        it is readable for those: a stream drains them with this after each read.
        """
        sample = self.sample(timeout=wait)
        while sample is not None:
            yield sample
            sample = self.sample(timeout=0)

    @contextlib.contextmanager
    def _readable(self) -> Iterator[None]:
        """Turn a reply this command line cannot decode into one clear ControlError."""
        try:
            yield
        except msgspec.MsgspecError as exc:
            raise ControlError(
                f"graph {self.name} sent a reply this command line cannot read ({exc}): "
                f"do both run the same version of actors?"
            ) from None

    def _read(self, timeout: float | None, *, quiet: bool = False) -> bytes | None:
        """One frame body, or None on timeout (or, ``quiet``, a lost connection).

        A partial frame stays buffered for the next call.
        """
        deadline = None if timeout is None else time.monotonic() + timeout
        buffer = self._buffer
        while True:
            if len(buffer) >= 4:
                size = int.from_bytes(buffer[:4], "big")
                if len(buffer) >= 4 + size:
                    body = bytes(buffer[4 : 4 + size])
                    del buffer[: 4 + size]
                    return body
            remaining = None if deadline is None else deadline - time.monotonic()
            if remaining is not None and remaining <= 0:
                return None
            self._sock.settimeout(remaining)
            try:
                chunk = self._sock.recv(1 << 16)
            except TimeoutError:
                return None
            except OSError as exc:
                if quiet:
                    return None
                raise ControlError(f"lost the connection to graph {self.name}: {exc.strerror or exc}") from None
            if not chunk:
                if quiet:
                    return None
                raise ControlError(f"graph {self.name} closed the connection (did it stop?)")
            buffer += chunk


def _open(path: Path) -> socket.socket | None:
    """A socket connected to the graph at ``path``; None when nothing listens there.

    A full queue of new connections (EAGAIN: a Unix socket never waits for
    room) is a live graph under a burst of clients: asked again for up to
    :data:`BUSY_RETRY` s, then a ControlError says it is busy.
    """
    give_up = time.monotonic() + BUSY_RETRY
    while True:
        sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        sock.settimeout(2.0)
        try:
            sock.connect(str(path))
            return sock
        except BlockingIOError:
            sock.close()
            if time.monotonic() >= give_up:
                raise ControlError(
                    f"graph {path.stem} is busy: its queue of new connections is full; try again"
                ) from None
            time.sleep(0.01)
        except OSError:
            sock.close()
            return None  # a stale socket: its graph is gone


def connect(graph: str | Path | None) -> Connection:
    """A connection to the graph named ``graph`` (when None: ``$ACTORS_GRAPH``, else the only one running).

    ``graph`` may also be the path of an endpoint's socket (``--transport``'s).
    Raises ControlError when no graph runs, when ``graph`` is not running, or
    when several run and ``graph`` is None.
    """
    if isinstance(graph, Path):
        sock = _open(graph)
        if sock is None:
            raise ControlError(f"cannot reach the endpoint at {graph}")
        return Connection(sock, "zenoh")
    paths = endpoint_paths()
    graph = graph or os.environ.get(GRAPH_VARIABLE) or None
    if graph is not None:
        sock = _open(paths[graph]) if graph in paths else None
        if sock is None:
            others = [name for name, path in paths.items() if is_alive(path)]
            running = f" (running: {', '.join(others)})" if others else ""
            raise ControlError(f"no running actors graph named {graph!r}{running}")
        return Connection(sock, graph, paths[graph])
    live = {name: sock for name, path in paths.items() if (sock := _open(path)) is not None}
    if len(live) == 1:
        ((name, sock),) = live.items()
        return Connection(sock, name, paths[name])
    for sock in live.values():
        sock.close()
    if not live:
        raise ControlError(NO_GRAPH)
    raise ControlError(f"several actors graphs are running ({', '.join(live)}): choose one with --graph NAME")


@overload
def query(args: argparse.Namespace, request: Request, result_type: type[T]) -> T: ...


@overload
def query(args: argparse.Namespace, request: Request, result_type: Any = Any) -> Any: ...


def query(args: argparse.Namespace, request: Request, result_type: Any = Any) -> Any:
    """Connect to ``args.graph``, make one request and return its result; raises ControlError."""
    with connect(args.graph) as conn:
        return conn.request(request, result_type)


def graph_snapshot(args: argparse.Namespace) -> GraphSnapshot:
    """The graph ``args.graph`` as it is now."""
    with connect(args.graph) as conn:
        return conn.graph()


def call_service(conn: Connection, service: str, srv_type: type[Any], request: Any, *, timeout: float = 10.0) -> Any:
    """Call ``service`` of ``srv_type`` with the ``request`` message; return the response message.

    Raises ControlError for an unknown service, another type, a handler that
    raised, or no answer within ``timeout`` seconds.
    """
    from actors import codec

    call = Call(
        service=service,
        type=codec.ros_name(srv_type),
        request=codec.to_builtins(request),
        timeout=timeout,
    )
    return codec.convert(conn.request(call, timeout=timeout + 5.0), srv_type.Response)


def print_names(entries: Iterable[Any], show_types: bool, count: bool = False) -> None:
    """Each entry's ``name``, with `` [type]`` under ``-t``, or under ``-c`` how many: as ros2's list verbs print."""
    if count:
        print(len(list(entries)))
        return
    for entry in entries:
        print(f"{entry.name} [{entry.type}]" if show_types else entry.name)


def print_matching(entries: Iterable[Any], type_: str, count_only: bool) -> None:
    """What ros2's ``find`` verbs print: the name of each entry of ``type_``, or how many there are.

    ``type_`` may be short (``std_msgs/String``) when the type is known.
    """
    from actors import codec
    from actors.errors import UnknownInterfaceError

    try:
        type_ = codec.ros_name(codec.get_type(type_))
    except UnknownInterfaceError:
        pass  # no such type here: then nothing is of it, as ros2 finds nothing
    names = [entry.name for entry in entries if entry.type == type_]
    if count_only:
        print(len(names))
    for name in names if not count_only else ():
        print(name)


def type_of(entries: Iterable[Any], name: str, what: str) -> str:
    """The type of the entry called ``name`` (a topic, a service, an action); ControlError if none."""
    from actors.ros.names import expand

    full = expand(name, "/", "_", what=f"{what} name")
    for entry in entries:
        if entry.name == full:
            return str(entry.type)
    raise ControlError(f"unknown {what} {full}")


def add_type_and_find(verbs: Any, what: str, example: str, entries: Callable[[GraphSnapshot], Iterable[Any]]) -> None:
    """``<what> type NAME`` and ``<what> find TYPE [-c] [--include-hidden-<what>s]``, as ros2 has them.

    ``entries`` picks the topics (or services...) out of the graph; ``example``
    is a type of them, for the help.
    """
    from actors.ros.names import is_hidden_name

    def type_verb(args: argparse.Namespace) -> None:
        print(type_of(entries(graph_snapshot(args)), args.name, what))

    def find_verb(args: argparse.Namespace) -> None:
        found = [e for e in entries(graph_snapshot(args)) if args.include_hidden or not is_hidden_name(e.name)]
        print_matching(found, args.type, args.count_only)

    type_ = add_verb(verbs, "type", type_verb, help=f"print a {what}'s type")
    type_.add_argument("name", metavar="NAME")
    find = add_verb(verbs, "find", find_verb, help=f"list the {what}s of a type")
    find.add_argument("type", metavar="TYPE", help=f"e.g. {example}")
    find.add_argument("-c", f"--count-{what}s", dest="count_only", action="store_true", help="only print how many")
    find.add_argument(f"--include-hidden-{what}s", dest="include_hidden", action="store_true", help="hidden ones too")
