"""The live view's front door: clients speaking ``foxglove.websocket.v1`` reach foxglove-sdk's server too.

foxglove-sdk (0.30) accepts only the ``foxglove.sdk.v1`` WebSocket subprotocol
and answers HTTP 400 to every client built on the published ws-protocol
libraries, which ask for ``foxglove.websocket.v1``: the same protocol under its
older name (Foxglove says so; clients that speak both just list both names).
The SDK has no option for it, so the view listens here instead, on its
public address, and relays each connection to the SDK's server on a loopback
port of its own.  The relay touches only the handshake: a client that offers
``foxglove.websocket.v1`` without ``foxglove.sdk.v1`` is introduced upstream
as ``foxglove.sdk.v1`` and answered under the name it asked for; everything
else, and every byte after the handshake, passes unchanged, so the SDK still
decides what to accept and how to treat each client.

It runs an asyncio loop on a thread of its own, as the SDK runs its server:
its sockets and timeouts never touch the graph's loop.

Being the one door in, it also bounds what viewers can take (the SDK has no
limit of its own): at most ``max_viewers`` connections are open at once,
counting those still in their handshake; one more is answered HTTP 503 and
closed at once, so a crowd of clients costs the graph a descriptor each only
for a moment and leaves the command line's control socket its own.  Turning
viewers away is told through ``warn``: one line when it starts, then at most
one count per :data:`REFUSALS_PERIOD`.  Each direction of a relayed
connection holds at most one chunk plus the transport's write buffer: a
viewer that never reads stalls its own upstream connection, where the SDK
drops its oldest messages (``message_backlog_size``).  When the last viewer
has gone, the heap they used is handed back to the system (glibc's
``malloc_trim``): freed, it would otherwise stay resident at its peak.
"""

from __future__ import annotations

import asyncio
import contextlib
import ctypes
import ctypes.util
import socket
import threading
from collections.abc import Callable

__all__ = ["SDK", "LEGACY", "MAX_VIEWERS", "REFUSALS_PERIOD", "SubprotocolFront"]

SDK = "foxglove.sdk.v1"
"""The subprotocol foxglove-sdk's server accepts."""

LEGACY = "foxglove.websocket.v1"
"""The name the published ws-protocol libraries (and older viewers) ask for."""

_HEADER = b"sec-websocket-protocol"
_MAX_HEAD = 16 * 1024  # bytes of an HTTP upgrade request or response: far more than any has
_HANDSHAKE_TIMEOUT = 10.0  # seconds (wall clock) a client or the server gets to send its head
_CHUNK = 64 * 1024
_GIVE_BACK_AFTER = (0.0, 0.5, 2.0)  # s after the last viewer left (the SDK lets go of its clients a moment later)
_LISTEN_BACKLOG = 1024  # a burst of clients waits in the kernel's queue, costing no descriptor

MAX_VIEWERS = 32
"""Viewers connected at once by default: a room full of screens; each may hold the SDK's backlog."""

REFUSALS_PERIOD = 60.0
"""Seconds (wall clock) between two log lines counting viewers turned away."""

_BUSY = (
    b"HTTP/1.1 503 Service Unavailable\r\nConnection: close\r\nContent-Type: text/plain\r\nContent-Length: %d\r\n\r\n%s"
)


class SubprotocolFront:
    """Listens on ``host:port`` (0: any free port) and relays every client to ``127.0.0.1:upstream``.

    :meth:`start` binds (raising OSError when the address cannot be had) and
    returns the port; :meth:`stop` closes the listener and every relayed
    connection.  At most ``max_viewers`` are open at once; :attr:`refused`
    counts those turned away, ``warn`` (called in the front's thread) says so.
    """

    def __init__(
        self, host: str, port: int, upstream: int, *, max_viewers: int = MAX_VIEWERS, warn: Callable[[str], None]
    ) -> None:
        self.host = host
        self.port = port
        self.upstream = upstream
        self.max_viewers = max_viewers
        self.warn = warn
        self.refused = 0
        self._unreported = 0  # refused since the last line said how many
        self._reporting = False  # a count is due within REFUSALS_PERIOD
        self._loop: asyncio.AbstractEventLoop | None = None
        self._thread: threading.Thread | None = None
        self._stopped: asyncio.Event | None = None

    def start(self) -> int:
        """Bind and start relaying; returns the port."""
        listener = socket.create_server((self.host, self.port), backlog=_LISTEN_BACKLOG)
        self.port = listener.getsockname()[1]
        loop = self._loop = asyncio.new_event_loop()
        started = threading.Event()
        self._thread = threading.Thread(
            target=self._run, args=(loop, listener, started), name="actors foxglove front", daemon=True
        )
        self._thread.start()
        started.wait()
        return self.port

    def stop(self) -> None:
        """Stop listening and close every relayed connection; returns once the thread has ended."""
        loop, thread, stopped = self._loop, self._thread, self._stopped
        if loop is None or thread is None:
            return
        if stopped is not None:
            loop.call_soon_threadsafe(stopped.set)
        thread.join()
        self._loop = self._thread = None

    def _run(self, loop: asyncio.AbstractEventLoop, listener: socket.socket, started: threading.Event) -> None:
        asyncio.set_event_loop(loop)
        try:
            loop.run_until_complete(self._serve(listener, started))
        finally:
            loop.close()

    async def _serve(self, listener: socket.socket, started: threading.Event) -> None:
        self._stopped = asyncio.Event()
        connections: set[asyncio.Future[None] | None] = set()

        async def relay(reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
            if len(connections) >= self.max_viewers:
                self._refuse(writer)
                return
            task = asyncio.current_task()
            connections.add(task)
            try:
                await self._relay(reader, writer)
            finally:
                connections.discard(task)
                if not connections:
                    for delay in _GIVE_BACK_AFTER:
                        asyncio.get_running_loop().call_later(delay, _give_back)

        server = await asyncio.start_server(relay, sock=listener, limit=_MAX_HEAD)
        started.set()
        async with server:
            await self._stopped.wait()
            server.close()
            running = [task for task in connections if task is not None]
            for task in running:
                task.cancel()
            await asyncio.gather(*running, return_exceptions=True)

    def _refuse(self, writer: asyncio.StreamWriter) -> None:
        """Answer a viewer over the limit HTTP 503 and close (its request unread: no need to)."""
        reason = f"the graph serves at most {self.max_viewers} viewers at once; try again later\n".encode()
        writer.write(_BUSY % (len(reason), reason))
        writer.close()  # the answer is still sent: the transport flushes before it closes
        self.refused += 1
        self._unreported += 1
        if self.refused == 1:
            self.warn(
                f"foxglove: {self.max_viewers} viewers are connected, the limit: more are refused "
                f"(HTTP 503) until some leave"
            )
            self._unreported = 0
        if not self._reporting:
            self._reporting = True
            asyncio.get_running_loop().call_later(REFUSALS_PERIOD, self._report)

    def _report(self) -> None:
        self._reporting = False
        if self._unreported:
            self.warn(
                f"foxglove: {self._unreported} more viewer(s) refused at the limit of {self.max_viewers} "
                f"({self.refused} in all)"
            )
            self._unreported = 0

    async def _relay(self, client_in: asyncio.StreamReader, client_out: asyncio.StreamWriter) -> None:
        server_out: asyncio.StreamWriter | None = None
        try:
            head = await asyncio.wait_for(client_in.readuntil(b"\r\n\r\n"), _HANDSHAKE_TIMEOUT)
            head, answer_as = introduce(head)
            server_in, server_out = await asyncio.open_connection("127.0.0.1", self.upstream, limit=_MAX_HEAD)
            server_out.write(head)
            response = await asyncio.wait_for(server_in.readuntil(b"\r\n\r\n"), _HANDSHAKE_TIMEOUT)
            client_out.write(answer(response, answer_as))
            await asyncio.gather(_pipe(client_in, server_out), _pipe(server_in, client_out))
        except (OSError, asyncio.IncompleteReadError, asyncio.LimitOverrunError, TimeoutError):
            pass  # a client that went away or never finished its handshake: nothing to relay
        finally:
            for writer in (client_out, server_out):
                if writer is not None:
                    writer.close()


def _give_back() -> None:
    """Hand the heap freed by departed viewers back to the system, where the C library can (glibc)."""
    if _LIBC is not None:
        _LIBC.malloc_trim(0)


_LIBC = ctypes.CDLL(ctypes.util.find_library("c")) if hasattr(ctypes.CDLL(None), "malloc_trim") else None


async def _pipe(source: asyncio.StreamReader, sink: asyncio.StreamWriter) -> None:
    """Copy until ``source`` ends, waiting for ``sink`` to drain (a slow reader slows the sender)."""
    try:
        while data := await source.read(_CHUNK):
            sink.write(data)
            await sink.drain()
    finally:
        with contextlib.suppress(OSError):
            sink.close()  # one side closed: the other is done too (WebSocket closes end to end)


def introduce(head: bytes) -> tuple[bytes, str | None]:
    """The client's upgrade request as the SDK's server accepts it, and the subprotocol to answer as.

    A request that offers :data:`LEGACY` but not :data:`SDK` offers SDK
    instead, to be answered as LEGACY; any other passes unchanged (answer None).
    """
    lines = head.split(b"\r\n")
    offered = [
        name.strip().decode("latin-1")
        for line in lines[1:]
        if line.partition(b":")[0].strip().lower() == _HEADER
        for name in line.partition(b":")[2].split(b",")
    ]
    if SDK in offered or LEGACY not in offered:
        return head, None
    kept = [line for line in lines if line.partition(b":")[0].strip().lower() != _HEADER]
    kept.insert(1, b"Sec-WebSocket-Protocol: " + SDK.encode())
    return b"\r\n".join(kept), LEGACY


def answer(head: bytes, answer_as: str | None) -> bytes:
    """The server's upgrade response with the subprotocol it chose named ``answer_as`` (None: unchanged)."""
    if answer_as is None:
        return head
    lines = head.split(b"\r\n")
    for i, line in enumerate(lines):
        if line.partition(b":")[0].strip().lower() == _HEADER and line.partition(b":")[2].strip() == SDK.encode():
            lines[i] = b"Sec-WebSocket-Protocol: " + answer_as.encode()
    return b"\r\n".join(lines)
