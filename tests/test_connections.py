"""The control endpoint's bounds: how many connections, for how long, and how much a slow reader may cost."""

from __future__ import annotations

import contextlib
import os
import socket
import struct
import zlib

import anyio
import pytest
from anyio.streams.buffered import BufferedByteReceiveStream

from actors import Node, Runtime
from actors.ops._connections import EVICT_AFTER, ConnectionLimits, ConnectionPool
from actors.ops.control import ControlEndpoint, GetGraph, Reply, Subscribe, decode_reply, frame
from interfaces.std_msgs.msg import String

pytestmark = pytest.mark.virtual_time


@pytest.fixture
def name(request: pytest.FixtureRequest) -> str:
    """A graph name no other test or running graph uses."""
    return f"tk{os.getpid()}_{zlib.crc32(request.node.name.encode()):08x}"


class FakeClock:
    """The real-time clock the pool's timeouts read, moved by hand."""

    def __init__(self) -> None:
        self.now = 1000.0

    def __call__(self) -> float:
        return self.now


def pool_of(rt: Runtime) -> ConnectionPool:
    (endpoint,) = rt.attachments
    assert isinstance(endpoint, ControlEndpoint) and endpoint.server is not None
    return endpoint.server.pool


class Client:
    """A raw connection to the endpoint."""

    def __init__(self, stream: anyio.abc.SocketStream) -> None:
        self.stream = stream
        self.receive = BufferedByteReceiveStream(stream)

    @classmethod
    async def open(cls, rt: Runtime) -> Client:
        (endpoint,) = rt.attachments
        return cls(await anyio.connect_unix(endpoint.server.path))

    async def reply(self) -> Reply:
        with anyio.fail_after(5):
            (size,) = struct.unpack(">I", await self.receive.receive_exactly(4))
            return decode_reply(await self.receive.receive_exactly(size))

    async def ask(self, request: object) -> Reply:
        await self.stream.send(frame(request))
        return await self.reply()

    async def closed(self) -> bool:
        """Whether the server has hung up."""
        with anyio.fail_after(5):
            try:
                await self.receive.receive_exactly(1)
            except (anyio.EndOfStream, anyio.IncompleteRead, anyio.BrokenResourceError):
                return True
        return False


async def test_one_connection_too_many_is_refused_with_a_reason_and_the_graph_keeps_serving(name):
    limits = ConnectionLimits(connections=3)
    async with Runtime(name=name, attach=[ControlEndpoint(limits)]) as rt:
        pool = pool_of(rt)
        pool.clock = clock = FakeClock()
        busy = [await Client.open(rt) for _ in range(3)]
        for client in busy:  # all three answered once, then idle for less than EVICT_AFTER
            assert (await client.ask(GetGraph())).ok
        extra = await Client.open(rt)
        refused = await extra.reply()
        assert not refused.ok
        assert refused.error == "the graph is busy: 3 connections are open; try again"
        assert await extra.closed()
        # Once one has idled long enough, a newcomer takes the place of the longest idle.
        clock.now += EVICT_AFTER
        assert (await busy[1].ask(GetGraph())).ok  # busy[1] is fresh again; busy[0] is the oldest
        newcomer = await Client.open(rt)
        assert (await newcomer.ask(GetGraph())).ok
        assert await busy[0].closed()
        assert (await busy[2].ask(GetGraph())).ok
        stats = pool.stats()
        assert (stats.open, stats.peak, stats.served, stats.refused, stats.evicted) == (3, 3, 4, 1, 1)
        for client in (*busy, extra, newcomer):
            await client.stream.aclose()


async def test_idle_connections_and_half_sent_frames_time_out_on_the_real_clock(name):
    limits = ConnectionLimits(idle_timeout=60.0, frame_timeout=10.0)
    async with Runtime(name=name, attach=[ControlEndpoint(limits)]) as rt:
        pool = pool_of(rt)
        pool.clock = clock = FakeClock()
        idle, half, streaming = [await Client.open(rt) for _ in range(3)]
        assert (await idle.ask(GetGraph())).ok
        await half.stream.send(frame(GetGraph())[:3])  # part of a header
        assert (await streaming.ask(Subscribe(topic="/rosout"))).ok
        await anyio.sleep(5)  # virtual seconds: the real clock has not moved
        assert len(pool.connections) == 3
        clock.now += 11
        await anyio.sleep(1)
        assert await half.closed()
        assert len(pool.connections) == 2
        clock.now += 50
        await anyio.sleep(1)
        assert await idle.closed()
        assert len(pool.connections) == 1  # a stream is never idle
        assert pool.stats().timed_out == 2
        await streaming.stream.aclose()


class Chatter(Node):
    """Publishes 4 KB strings on /big every millisecond."""

    def __init__(self) -> None:
        super().__init__("chatter")
        pub = self.create_publisher(String, "/big", 10)
        self.create_timer(0.001, lambda: pub.publish(String(data="x" * 4096)))


async def test_a_reader_that_does_not_read_loses_samples_and_costs_at_most_its_outbox(name):
    limits = ConnectionLimits(outbox_bytes=64 * 1024)
    async with Runtime(name=name, attach=[ControlEndpoint(limits)]) as rt:
        rt.spawn(Chatter)
        stalled = await Client.open(rt)
        assert (await stalled.ask(Subscribe(topic="/big"))).ok
        await anyio.sleep(10)  # 10,000 samples of 4 KB: 40 MB if nothing were dropped
        pool = pool_of(rt)
        (connection,) = pool.connections
        assert connection._outbox_bytes <= limits.outbox_bytes
        dropped = pool.stats().dropped
        assert dropped > 9000
        # The graph itself is unharmed: another client is answered at once.
        other = await Client.open(rt)
        assert (await other.ask(GetGraph())).ok
        await other.stream.aclose()
        await stalled.stream.aclose()


async def test_a_descriptor_select_cannot_watch_is_refused_not_registered(name, monkeypatch):
    import actors.ops._connections

    async with Runtime(name=name, attach=[ControlEndpoint()]) as rt:
        monkeypatch.setattr(actors.ops._connections, "_SELECT_LIMIT", 0)
        monkeypatch.setattr(actors.ops._connections, "_uses_select", lambda: True)
        client = await Client.open(rt)
        refused = await client.reply()
        assert refused.error.startswith("the graph has too many open files")
        assert pool_of(rt).stats().refused == 1
        await client.stream.aclose()


async def test_a_burst_queued_before_the_graph_looks_is_held_to_the_limit(name):
    # Six clients connect before the listener wakes: it takes them in one batch, and those whose
    # tasks have not started yet must count against the limit as much as the open ones.
    limits = ConnectionLimits(connections=3)
    async with Runtime(name=name, attach=[ControlEndpoint(limits)]) as rt:
        (endpoint,) = rt.attachments
        raw = []
        for _ in range(6):  # no await between them: the pool sees all six at once
            sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
            sock.connect(str(endpoint.server.path))
            raw.append(sock)
        clients = [Client(await anyio.abc.SocketStream.from_socket(sock)) for sock in raw]
        answers = []
        for client in clients:
            with contextlib.suppress(anyio.BrokenResourceError, anyio.ClosedResourceError):
                await client.stream.send(frame(GetGraph()))  # a refused one may be closed already
            answers.append("served" if (await client.reply()).ok else "refused")
        stats = pool_of(rt).stats()
        assert sorted(answers) == ["refused"] * 3 + ["served"] * 3
        assert (stats.peak, stats.refused) == (3, 3)
        for client in clients:
            await client.stream.aclose()
