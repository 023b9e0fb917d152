"""The control endpoint in-process: where its socket lives, who may open it, bad frames."""

from __future__ import annotations

import os
import socket
import stat
import struct
import zlib

import anyio
import msgspec
import pytest
from anyio.streams.buffered import BufferedByteReceiveStream

from actors import DurabilityPolicy, Node, QoSProfile, Runtime
from actors.cli._client import Connection, connect
from actors.errors import ControlError
from actors.ops.control import (
    MAX_FRAME,
    ControlEndpoint,
    ControlServer,
    GetGraph,
    GetNode,
    GraphSnapshot,
    NodeDetail,
    Publish,
    Reply,
    Sample,
    Subscribe,
    decode_reply,
    endpoint_dir,
    frame,
)
from interfaces.std_msgs.msg import String


class Talker(Node):
    """Publishes ``hello N`` on /chatter every 0.05 s."""

    def __init__(self) -> None:
        super().__init__("talker")
        self.pub = self.create_publisher(String, "/chatter", 10)
        self.create_timer(0.05, self.tick)
        self.n = 0

    def tick(self) -> None:
        self.pub.publish(String(data=f"hello {self.n}"))
        self.n += 1


class Listener(Node):
    """Keeps what it hears on /chatter."""

    def __init__(self) -> None:
        super().__init__("listener")
        self.heard: list[str] = []
        self.create_subscription(String, "/chatter", lambda msg: self.heard.append(msg.data), 10)


def server(rt: Runtime) -> ControlServer:
    """The control server of a runtime that was given a ControlEndpoint."""
    (endpoint,) = rt.attachments
    assert isinstance(endpoint, ControlEndpoint) and endpoint.server is not None
    return endpoint.server


@pytest.fixture
def name(request: pytest.FixtureRequest) -> str:
    """A graph name no other test or running graph uses."""
    return f"tc{os.getpid()}_{zlib.crc32(request.node.name.encode()):08x}"


async def ask(path: os.PathLike[str], *frames: bytes) -> Reply:
    """Send raw ``frames`` on a fresh connection and read one reply."""
    async with await anyio.connect_unix(path) as stream:
        for data in frames:
            await stream.send(data)
        receive = BufferedByteReceiveStream(stream)
        (size,) = struct.unpack(">I", await receive.receive_exactly(4))
        return decode_reply(await receive.receive_exactly(size))


async def refused_and_closed(path: os.PathLike[str], data: bytes) -> str:
    """The error the server answers ``data`` with, checking that it then hangs up."""
    async with await anyio.connect_unix(path) as stream:
        await stream.send(data)
        receive = BufferedByteReceiveStream(stream)
        with anyio.fail_after(5):
            (size,) = struct.unpack(">I", await receive.receive_exactly(4))
            reply = decode_reply(await receive.receive_exactly(size))
            with pytest.raises((anyio.EndOfStream, anyio.IncompleteRead, anyio.BrokenResourceError)):
                await receive.receive_exactly(1)  # a hang-up, or a reset when it left our bytes unread
    assert not reply.ok
    return reply.error


async def test_the_socket_is_0600_in_a_0700_directory_of_this_user_and_goes_away_on_exit(name):
    async with Runtime(name=name, attach=[ControlEndpoint()]) as rt:
        path = server(rt).path
        assert path == endpoint_dir() / f"{name}.sock"
        info = os.stat(path)
        assert stat.S_ISSOCK(info.st_mode) and stat.S_IMODE(info.st_mode) == 0o600
        directory = os.stat(path.parent)
        assert stat.S_IMODE(directory.st_mode) == 0o700 and directory.st_uid == os.getuid()
    assert not path.exists()


async def test_garbage_and_an_oversized_length_are_answered_and_close_only_that_connection(name, caplog):
    async with Runtime(name=name, attach=[ControlEndpoint()]) as rt:
        rt.spawn(Talker)
        listener = rt.spawn(Listener)
        path = server(rt).path
        assert (await refused_and_closed(path, b"\xc1 this is not msgpack at all")).startswith(
            "a request of 3240129640 bytes is over the limit of 1048576"
        )
        assert await refused_and_closed(path, struct.pack(">I", MAX_FRAME + 1) + b"x" * 64) == (
            f"a request of {MAX_FRAME + 1} bytes is over the limit of {MAX_FRAME}"
        )
        assert (await refused_and_closed(path, struct.pack(">I", 3) + b"\xc1\xc1\xc1")).startswith(
            "a request must be a msgpack map"
        )
        deep = b"\x91" * 200_000 + b"\xc0"  # nesting deeper than any decoder recurses
        assert (await refused_and_closed(path, struct.pack(">I", len(deep)) + deep)).startswith(
            "a request must be a msgpack map"
        )
        heard = len(listener.heard)
        reply = await ask(path, frame(GetGraph()))
        assert reply.ok
        graph = msgspec.convert(reply.result, GraphSnapshot)
        assert [n.name for n in graph.nodes] == ["/talker", "/listener"]
        with anyio.fail_after(5):
            while len(listener.heard) == heard:  # the graph still runs
                await anyio.sleep(0.01)
        assert server(rt).stats().bad_requests == 4
    # One line each, no traceback.
    logged = [r for r in caplog.records if "control endpoint" in r.getMessage()]
    assert len(logged) == 4 and not any(r.exc_info for r in logged)


async def test_a_bad_request_gets_an_error_reply_and_the_connection_stays_open(name):
    async with Runtime(name=name, attach=[ControlEndpoint()]) as rt:
        path = server(rt).path
        unknown_op = frame({"op": "reboot"})
        reply = await ask(path, unknown_op)
        assert not reply.ok and reply.error.startswith("bad request")
        async with await anyio.connect_unix(path) as stream:
            receive = BufferedByteReceiveStream(stream)
            for request in (GetNode(name="/nobody"), GetGraph()):
                await stream.send(frame(request))
                (size,) = struct.unpack(">I", await receive.receive_exactly(4))
                replies = decode_reply(await receive.receive_exactly(size))
            assert replies.ok  # the second request, after the failed first one


async def test_a_graph_name_in_use_moves_on_and_a_stale_socket_is_replaced(name, caplog):
    async with (
        Runtime(name=name, attach=[ControlEndpoint()]) as first,
        Runtime(name=name, attach=[ControlEndpoint()]) as second,
    ):
        assert server(first).path.name == f"{name}.sock"
        assert server(second).path.name == f"{name}-2.sock"
    # Not silently: the second graph says how to reach it, and what its own name reaches.
    assert [r.getMessage() for r in caplog.records if r.levelname == "WARNING"] == [
        f"another graph named {name!r} is running: the command line reaches this one "
        f"as --graph {name}-2, and --graph {name} reaches the other"
    ]
    stale = endpoint_dir() / f"{name}.sock"
    import socket

    sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    sock.bind(str(stale))
    sock.close()  # the file stays, nobody listens: what a killed graph leaves
    async with Runtime(name=name, attach=[ControlEndpoint()]) as rt:
        assert server(rt).path == stale
    assert not stale.exists()


async def test_a_runtime_without_the_attachment_opens_no_endpoint(name):
    async with Runtime(name=name) as rt:
        assert rt.attachments == ()
        assert not (endpoint_dir() / f"{name}.sock").exists()


async def test_a_directory_open_to_others_is_refused_and_the_graph_runs_without_endpoint(
    name, tmp_path, monkeypatch, caplog
):
    monkeypatch.setenv("XDG_RUNTIME_DIR", str(tmp_path))
    (tmp_path / "actors").mkdir(mode=0o755)
    os.chmod(tmp_path / "actors", 0o755)
    with pytest.raises(ControlError, match="refusing the control directory"):
        endpoint_dir()
    async with Runtime(name=name, attach=[endpoint := ControlEndpoint()]) as rt:
        assert endpoint.server is None
        rt.spawn(Talker)
    assert "no control endpoint" in caplog.text


async def test_the_runtime_dir_is_used_when_set_and_owned_by_the_user(name, tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_RUNTIME_DIR", str(tmp_path))
    async with Runtime(name=name, attach=[ControlEndpoint()]) as rt:
        assert server(rt).path == tmp_path / "actors" / f"{name}.sock"
        assert stat.S_IMODE(os.stat(tmp_path / "actors").st_mode) == 0o700


async def test_the_client_finds_the_graph_and_sessions_clean_up_after_themselves(name):
    async with Runtime(name=name, attach=[ControlEndpoint()]) as rt:
        rt.spawn(Talker)

        def publish_and_look() -> tuple[list[str], list[str]]:
            with connect(name) as conn:
                conn.request(Publish(topic="/kill", type="std_msgs/msg/Bool", msg={"data": True}))
                conn.request(Subscribe(topic="chatter"))
                sample = conn.sample(timeout=5)
                assert sample is not None and sample.msg["data"].startswith("hello ")
                graph = conn.graph()
            topics = {t.name: t for t in graph.topics}
            return [p.node for p in topics["/kill"].publishers], [s.node for s in topics["/chatter"].subscriptions]

        publishers, subscribers = await anyio.to_thread.run_sync(publish_and_look)
        assert publishers == ["/_actors_cli_1"] and subscribers == ["/_actors_cli_1"]
        assert [n.name for n in rt.graph.nodes()] == ["/talker"]  # the session is no node
        with anyio.fail_after(5):
            while "/kill" in rt.topics.topics or rt.topics.topics["/chatter"].subscriptions:
                await anyio.sleep(0.01)  # the session ends when the server sees the hang-up


async def test_errors_name_what_is_unknown(name):
    async with Runtime(name=name, attach=[ControlEndpoint()]) as rt:
        rt.spawn(Talker)
        rt.spawn(Talker, name="far", namespace="/robot1")

        def ask_all() -> list[str]:
            errors = []
            requests = [
                GetNode(name="ghost"),
                Subscribe(topic="/nowhere"),
                Publish(topic="/chatter", type="std_msgs/msg/Bool"),
                Publish(topic="/x", type="nope_msgs/msg/Nope"),
            ]
            with connect(name) as conn:
                # A unique plain name finds a namespaced node, as Runtime.node() does.
                assert conn.request(GetNode(name="far"), NodeDetail).name == "/robot1/far"
                for request in requests:
                    with pytest.raises(ControlError) as caught:
                        conn.request(request)
                    errors.append(str(caught.value))
            return errors

        errors = await anyio.to_thread.run_sync(ask_all)
    assert errors == [
        "unknown node ghost",
        "unknown topic /nowhere",
        "topic /chatter carries std_msgs/msg/String, not std_msgs/msg/Bool",
        "unknown interface type 'nope_msgs/msg/Nope'",
    ]


async def test_no_graph_and_an_unknown_graph_name_are_control_errors(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_RUNTIME_DIR", str(tmp_path))
    with pytest.raises(ControlError, match=r"no running actors graph found \(start one with"):
        connect(None)
    with pytest.raises(ControlError, match="no running actors graph named 'ghost'"):
        connect("ghost")


async def test_hz_does_not_replay_a_latched_topics_history(name):
    latched = QoSProfile(depth=5, durability=DurabilityPolicy.TRANSIENT_LOCAL)

    class Latched(Node):
        def __init__(self) -> None:
            super().__init__("latched")
            self.pub = self.create_publisher(String, "/latched", latched)

    async with Runtime(name=name, attach=[ControlEndpoint()]) as rt:
        rt.spawn(Latched)

        def subscribe(content: bool) -> DurabilityPolicy:
            with connect(name) as conn:
                conn.request(Subscribe(topic="/latched", content=content))
                return [*rt.topics.topics["/latched"].subscriptions][-1].qos.durability

        # echo shows a latched topic's last message; hz must not count that replay as a burst
        assert await anyio.to_thread.run_sync(subscribe, True) is DurabilityPolicy.TRANSIENT_LOCAL
        assert await anyio.to_thread.run_sync(subscribe, False) is DurabilityPolicy.VOLATILE


def test_samples_that_came_in_the_same_read_as_the_reply_are_drained_without_waiting():
    # A latched history follows the subscription's reply at once: one recv may take both, and
    # then the socket never says it is readable for the samples already in the buffer.
    ours, graphs = socket.socketpair()
    with Connection(ours, "pair") as conn, graphs:
        graphs.sendall(
            frame(Reply(result={"type": "std_msgs/msg/String"}))
            + b"".join(frame(Sample(stamp=float(i), msg={"data": f"m{i}"})) for i in range(3))
        )
        assert conn.request(Subscribe(topic="/latched"))["type"] == "std_msgs/msg/String"
        graphs.sendall(frame(Sample(stamp=9.0, msg={"data": "later"}))[:3])  # a frame's first bytes only
        assert [s.msg["data"] for s in conn.samples(0)] == ["m0", "m1", "m2"]
        assert list(conn.samples(0)) == []  # nothing whole is left, and nothing waited for
