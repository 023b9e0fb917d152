"""Bounded connections for the control endpoint: limits, accepting, timeouts, slow readers.

Nothing a client does may take the graph down, nor grow it without bound:

- At most ``limits.connections`` are open at once.  One more is let in by
  closing the connection idle the longest (nothing asked, nothing streamed,
  for at least :data:`EVICT_AFTER` s), else refused: it is accepted, told why
  in one error reply, and closed.
- Out of file descriptors (EMFILE, ENFILE), the listener would see the same
  pending connection forever and the graph would spin or die.  It keeps one
  descriptor in reserve: it frees it, accepts the connection, refuses it as
  above, and takes the reserve back; the count shows in ``doctor``.  A loop on
  ``select()`` cannot watch a descriptor of 1024 or more: such a connection is
  refused too instead of breaking the loop.
- A connection that streams nothing and asks nothing for ``idle_timeout``
  seconds is closed, so is one that leaves a frame half-sent (or a reply
  unread) for ``frame_timeout`` seconds.  These are *real* seconds, also on a
  virtual-time graph: they protect against real clients, and virtual time may
  race ahead of them between two requests of a live command line.
- What is streamed to a client waits in a bounded outbox
  (``limits.outbox_bytes``): a reader that does not keep up loses the oldest
  frames, counted, and never makes the graph hold more.

:class:`ConnectionPool` does all of this for any ``serve(connection)``
coroutine; :class:`ConnectionStats` is what it counted.
"""

from __future__ import annotations

import asyncio
import errno
import os
import resource
import selectors
import socket
import time
from collections import deque
from collections.abc import Awaitable, Callable

import anyio
import anyio.abc
import msgspec

__all__ = [
    "EVICT_AFTER",
    "SocketStream",
    "ConnectionLimits",
    "ConnectionStats",
    "Connection",
    "ConnectionPool",
]

EVICT_AFTER = 0.5
"""Seconds a connection must have been idle before a newcomer may take its place (only when full)."""

_SELECT_LIMIT = 1024  # FD_SETSIZE: select() refuses descriptors at or above it
_OUT_OF_DESCRIPTORS = (errno.EMFILE, errno.ENFILE)
_REAP_PERIOD = 0.5  # s of runtime clock between looks at the open connections
_ACCEPT_BATCH = 64  # connections taken per wake-up of the listener


class ConnectionLimits(msgspec.Struct, frozen=True, kw_only=True):
    """What an endpoint allows; the defaults suit command lines and a few tools."""

    connections: int = 256
    idle_timeout: float = 60.0
    frame_timeout: float = 10.0
    outbox_bytes: int = 256 * 1024


class ConnectionStats(msgspec.Struct, frozen=True, kw_only=True):
    """Counts since the endpoint started: ``open`` now, its ``peak``, and what happened to the rest.

    ``served``: connections let in; ``refused``: turned away at the limit;
    ``evicted``: idle ones closed for a newcomer; ``timed_out``: closed for
    idleness or a half-sent frame; ``bad_requests``: connections that sent
    something malformed; ``dropped``: streamed frames a slow reader lost;
    ``out_of_descriptors``: connections refused because the process had no
    descriptor left (``descriptor_limit`` is its soft limit).
    """

    open: int
    peak: int
    served: int
    refused: int
    evicted: int
    timed_out: int
    bad_requests: int
    dropped: int
    out_of_descriptors: int
    connection_limit: int
    descriptor_limit: int


class SocketStream:
    """A connected, non-blocking socket as a byte stream: ``receive``, ``send``, ``aclose``.

    asyncio's ``sock_recv``/``sock_sendall``, not anyio's raw Unix socket
    stream: cancelling anyio's receive in the instant the socket turns
    readable sets a cancelled future's result, and asyncio logs that as an
    error with a traceback (it happens whenever a connection is closed by a
    timeout or at shutdown while its client speaks).  Raises what anyio's
    streams raise: EndOfStream when the peer hung up, BrokenResourceError when
    the connection failed.
    """

    def __init__(self, sock: socket.socket) -> None:
        self.sock = sock
        self._loop = asyncio.get_running_loop()

    async def receive(self, max_bytes: int = 65536) -> bytes:
        """Some bytes, as soon as there are any."""
        try:
            data = await self._loop.sock_recv(self.sock, max_bytes)
        except OSError as exc:
            raise anyio.BrokenResourceError from exc
        if not data:
            raise anyio.EndOfStream
        return data

    async def send(self, data: bytes) -> None:
        """All of ``data``; waits while the peer's buffer is full."""
        try:
            await self._loop.sock_sendall(self.sock, data)
        except OSError as exc:
            raise anyio.BrokenResourceError from exc

    async def aclose(self) -> None:
        """Close the socket."""
        self.sock.close()


class Connection:
    """One accepted client: its ``stream``, what it is doing, and its bounded ``outbox``.

    The serving coroutine marks what the connection does (:meth:`busy`,
    ``streaming``, :meth:`frame_begun`/:meth:`frame_done`) so that the pool
    knows which timeout applies and whom it may evict.
    """

    def __init__(self, pool: ConnectionPool, stream: SocketStream, number: int) -> None:
        self.pool = pool
        self.stream = stream
        self.number = number
        self.streaming = False  # something is streamed to it: no idle timeout
        self.scope = anyio.CancelScope()
        self._requests = 0  # requests being answered now
        self._active_at = pool.clock()
        self._frame_since: float | None = None  # first byte of an unfinished frame
        self._sending_since: float | None = None
        self._outbox: deque[bytes] = deque()
        self._outbox_bytes = 0
        self._wake: asyncio.Event = asyncio.Event()
        self._send_lock = anyio.Lock()
        self._reported = False

    def report(self, problem: str) -> None:
        """Note a malformed request; the first of each connection is logged, as one line."""
        if not self._reported:
            self._reported = True
            self.pool._bad_requests += 1
            self.pool._log(f"control endpoint: connection {self.number}: {problem}")

    # -- what the serving coroutine says ------------------------------------

    def frame_begun(self) -> None:
        """Part of a frame has arrived."""
        if self._frame_since is None:
            self._frame_since = self.pool.clock()

    def frame_done(self) -> None:
        """No frame is half-received now."""
        self._frame_since = None
        self._active_at = self.pool.clock()

    def busy(self) -> _Busy:
        """A context in which a request is being answered (no idle timeout, not evictable)."""
        return _Busy(self)

    # -- sending ------------------------------------------------------------

    async def send(self, data: bytes) -> None:
        """Send ``data`` now (a reply), after any frame being sent; waits while the client reads."""
        async with self._send_lock:
            self._sending_since = self.pool.clock()
            try:
                await self.stream.send(data)
            finally:
                self._sending_since = None

    def post(self, data: bytes) -> None:
        """Queue ``data`` for the writer (a streamed frame); never blocks.

        When the outbox would hold more than ``outbox_bytes``, the oldest
        frames are dropped (and counted) to make room; the newest is kept.
        """
        outbox = self._outbox
        outbox.append(data)
        self._outbox_bytes += len(data)
        limit = self.pool.limits.outbox_bytes
        while self._outbox_bytes > limit and len(outbox) > 1:
            self._outbox_bytes -= len(outbox.popleft())
            self.pool._dropped += 1
        self._wake.set()

    async def write_outbox(self) -> None:
        """Send what :meth:`post` queued, until cancelled; raises if the client is gone."""
        while True:
            await self._wake.wait()
            self._wake.clear()
            while self._outbox:
                data = self._outbox.popleft()
                self._outbox_bytes -= len(data)
                await self.send(data)

    # -- the pool's view ----------------------------------------------------

    def _idle_for(self, now: float) -> float | None:
        """Seconds idle (None when busy, streaming or mid-frame)."""
        if self._requests or self.streaming or self._frame_since is not None:
            return None
        return now - self._active_at

    def _overdue(self, now: float) -> bool:
        limits = self.pool.limits
        if self._frame_since is not None and now - self._frame_since > limits.frame_timeout:
            return True  # a frame left half-sent
        if not self.streaming and self._sending_since is not None and now - self._sending_since > limits.frame_timeout:
            return True  # a reply left unread
        idle = self._idle_for(now)
        return idle is not None and idle > limits.idle_timeout


class _Busy:
    __slots__ = ("_connection",)

    def __init__(self, connection: Connection) -> None:
        self._connection = connection

    def __enter__(self) -> None:
        self._connection._requests += 1

    def __exit__(self, *exc: object) -> None:
        self._connection._requests -= 1
        self._connection._active_at = self._connection.pool.clock()


class ConnectionPool:
    """Accepts connections on a listening socket and serves each, within ``limits``.

    ``serve(connection)`` answers one client until it goes; what it raises is
    logged through ``log`` (one line) and ends that connection only.
    ``refusal(text)`` makes the bytes a refused client is sent.  ``clock``
    is the real-time clock the timeouts read (seconds; tests replace it).
    """

    def __init__(
        self,
        limits: ConnectionLimits,
        serve: Callable[[Connection], Awaitable[None]],
        refusal: Callable[[str], bytes],
        log: Callable[[str], object],
    ) -> None:
        self.limits = limits
        self._serve = serve
        self._refusal = refusal
        self._log = log
        self.connections: dict[Connection, None] = {}
        self._numbers = 0
        self._starting = 0  # accepted, their tasks not started yet: they count against the limit
        self._peak = 0
        self._refused = 0
        self._evicted = 0
        self._timed_out = 0
        self._dropped = 0
        self._out_of_descriptors = 0
        self._bad_requests = 0
        self._reserve: int | None = None
        self._reaping = False  # the reaper runs while connections are open
        self.clock: Callable[[], float] = time.monotonic

    def stats(self) -> ConnectionStats:
        """The counts now."""
        return ConnectionStats(
            open=len(self.connections),
            peak=self._peak,
            served=self._numbers,
            refused=self._refused,
            evicted=self._evicted,
            timed_out=self._timed_out,
            bad_requests=self._bad_requests,
            dropped=self._dropped,
            out_of_descriptors=self._out_of_descriptors,
            connection_limit=self.limits.connections,
            descriptor_limit=resource.getrlimit(resource.RLIMIT_NOFILE)[0],
        )

    async def run(self, sock: socket.socket) -> None:
        """Accept on ``sock`` (listening, non-blocking) and serve until cancelled."""
        self._reserve = _spare_descriptor()
        try:
            async with anyio.create_task_group() as tg:
                while True:
                    await anyio.wait_readable(sock)
                    # A burst queues hundreds of clients: take a batch per wake-up, so that the
                    # one behind them (a command line) waits for fewer loop iterations.
                    for _ in range(_ACCEPT_BATCH):
                        if not self._accept(sock, tg):
                            break
        finally:
            if self._reserve is not None:
                os.close(self._reserve)
                self._reserve = None

    def _accept(self, sock: socket.socket, tg: anyio.abc.TaskGroup) -> bool:
        """Take one pending connection; False when there was none (or accepting failed)."""
        try:
            conn, _ = sock.accept()
        except (BlockingIOError, InterruptedError, ConnectionAbortedError):
            return False  # none pending, or gone before we took it
        except OSError as exc:
            if exc.errno in _OUT_OF_DESCRIPTORS:
                self._accept_without_descriptors(sock, exc)
            else:
                self._log(f"control endpoint: accept failed: {exc.strerror or exc}")
            return False
        if conn.fileno() >= _SELECT_LIMIT and _uses_select():
            self._refuse(conn, f"the graph has too many open files ({conn.fileno()}) to watch one more")
            return True
        if len(self.connections) + self._starting >= self.limits.connections and not self._evict_one():
            self._refuse(conn, f"the graph is busy: {self.limits.connections} connections are open; try again")
            return True
        self._numbers += 1
        self._starting += 1
        conn.setblocking(False)
        tg.start_soon(self._run_connection, conn, self._numbers)
        if not self._reaping:
            self._reaping = True
            tg.start_soon(self._reap)
        return True

    def _accept_without_descriptors(self, sock: socket.socket, exc: OSError) -> None:
        """Refuse one pending connection with the reserve descriptor, so that the listener settles."""
        self._out_of_descriptors += 1
        if self._out_of_descriptors == 1:
            self._log(f"control endpoint: out of file descriptors ({exc.strerror}): refusing connections")
        if self._reserve is None:
            self._reserve = _spare_descriptor()
            if self._reserve is None:
                return  # still none: the next readiness tries again
        os.close(self._reserve)
        self._reserve = None
        try:
            conn, _ = sock.accept()
        except OSError:
            pass
        else:
            self._refuse(conn, "the graph has run out of file descriptors; try again later")
        self._reserve = _spare_descriptor()

    def _refuse(self, conn: socket.socket, why: str) -> None:
        self._refused += 1
        conn.setblocking(False)
        try:
            conn.send(self._refusal(why))  # small: fits in an empty socket buffer
        except OSError:
            pass
        finally:
            conn.close()

    def _evict_one(self) -> bool:
        now = self.clock()
        idle = [(c._idle_for(now), c) for c in self.connections]
        candidates = [(i, c) for i, c in idle if i is not None and i >= EVICT_AFTER]
        if not candidates:
            return False
        _, victim = max(candidates, key=lambda pair: pair[0])
        self._close(victim)
        self._evicted += 1
        return True

    def _close(self, connection: Connection) -> None:
        connection.scope.cancel()
        self.connections.pop(connection, None)  # its slot is free now, not when its task ends

    async def _run_connection(self, conn: socket.socket, number: int) -> None:
        connection = Connection(self, SocketStream(conn), number)
        self._starting -= 1
        self.connections[connection] = None
        self._peak = max(self._peak, len(self.connections))
        try:
            with connection.scope:
                await self._serve(connection)
        except Exception as exc:
            self._log(f"control endpoint: connection {number} failed: {type(exc).__name__}: {exc}")
        finally:
            conn.close()
            self.connections.pop(connection, None)

    async def _reap(self) -> None:
        """Close connections past their timeouts while any is open.

        Only then: a timer of its own would keep a virtual-time graph that
        waits on nothing from reporting its deadlock.
        """
        try:
            while True:
                await anyio.sleep(_REAP_PERIOD)
                if not self.connections:
                    return
                now = self.clock()
                for connection in [c for c in self.connections if c._overdue(now)]:
                    self._timed_out += 1
                    self._close(connection)
        finally:
            self._reaping = False


def _spare_descriptor() -> int | None:
    try:
        return os.open(os.devnull, os.O_RDONLY)
    except OSError:
        return None


def _uses_select() -> bool:
    # asyncio's selector loops keep their selector in ``_selector``; precise_loop() uses select().
    loop = asyncio.get_running_loop()
    return isinstance(getattr(loop, "_selector", None), selectors.SelectSelector)
