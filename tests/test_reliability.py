"""Nothing from outside takes a graph down: each defect the robustness probe found (issue 17), replayed.

1. NaN commands from the command line crashed the TurtleBot until the graph gave up.
2. About 1,100 connections exhausted the descriptors and killed the graph; idle and half-sent
   connections were held forever.
3. Stalled `topic echo /scan` readers grew the graph's memory.
4. Malformed requests left a traceback each in the graph's log.
5. Malformed graph files ended in tracebacks, hangs, or silently ran.
6. A world step `dt` of zero or less ended in a 45-line traceback.

Each test fails on the code before the fix.  The mechanisms have their own tests
(tests/test_refusals.py, tests/test_connections.py, tests/test_graph.py); timings and
memory at full scale are measured by ``python -m bench.soak``, not here.
"""

from __future__ import annotations

import contextlib
import logging
import math
import os
import resource
import socket
import struct
import subprocess
import sys
import time
import zlib
from collections import Counter
from collections.abc import Callable, Iterator
from pathlib import Path

import anyio
import pytest
from anyio.streams.buffered import BufferedByteReceiveStream
from conftest import ROOT, python_env

import actors.cli._client
import actors.run
from actors import Runtime
from actors.cli._client import Connection, connect
from actors.errors import ControlError
from actors.ops._connections import ConnectionLimits
from actors.ops.control import (
    ControlEndpoint,
    Diagnose,
    GetGraph,
    Publish,
    Subscribe,
    decode_reply,
    endpoint_dir,
    frame,
)
from actors.ops.doctor import Check, Report
from nodes.constant_control import ConstantControl
from world.robot import TurtleBot
from world.sim import World


@pytest.fixture
def name(request: pytest.FixtureRequest) -> str:
    """A graph name no other test or running graph uses."""
    return f"tr{os.getpid()}_{zlib.crc32(request.node.name.encode()):08x}"


def checks(report: Report) -> dict[str, tuple[str, ...]]:
    return {c.name: (*c.reasons, *c.warnings) for c in report.checks}


# --------------------------------------------------------------------------- 1. NaN commands


@pytest.mark.virtual_time
@pytest.mark.slow
async def test_1_a_thousand_nan_commands_from_the_command_line_are_refused_and_counted(name, caplog):
    async with Runtime(name=name, attach=[ControlEndpoint()]) as rt:
        rt.spawn(World, params={"world": "signs"})
        rt.spawn(TurtleBot)
        rt.spawn(ConstantControl, params={"v": 0.2, "omega": 0.2})
        await anyio.sleep(1)

        def thousand_cli_publishes() -> Report:
            for i in range(1000):  # one connection each, as 1,000 `actors topic pub --once` would
                with connect(name) as conn:
                    value = (math.nan, math.inf, -math.inf)[i % 3]
                    conn.request(
                        Publish(topic="/cmd_vel", type="geometry_msgs/msg/Twist", msg={"linear": {"x": value}})
                    )
            with connect(name) as conn:
                return conn.request(Diagnose(), Report)

        report = await anyio.to_thread.run_sync(thousand_cli_publishes)
        await anyio.sleep(1)
        (robot,) = [n for n in rt.graph.nodes() if n.name == "/turtlebot"]
        assert (robot.state, robot.crashes) == ("running", 0)
        assert rt.node("turtlebot").robot.commanded == (0.2, 0.2)  # the last valid command
    (reason,) = checks(report)["refused messages"]
    assert reason.startswith(
        "/cmd_vel: /turtlebot refused 1000 message(s): linear.x and angular.z must be finite (1000); "
        "the last from /_actors_cli_"
    )
    refusals = [r for r in caplog.records if "refused a message" in r.getMessage()]
    # Sessions one after another mostly share a name (the lowest free number): a line per name seen,
    # the burst, then the rate limit: not 1,000 lines.
    assert 1 <= len(refusals) <= 6


# --------------------------------------------------------------------------- 2. connections


def open_fds() -> int:
    return len(os.listdir("/proc/self/fd"))


@pytest.mark.skipif(not Path("/proc/self/fd").is_dir(), reason="counts descriptors in /proc")
async def test_2_more_connections_than_the_limit_are_refused_and_the_command_line_still_gets_in(name):
    limits = ConnectionLimits(connections=64)
    async with Runtime(name=name, attach=[endpoint := ControlEndpoint(limits)]):
        path = endpoint.server.path
        baseline = open_fds()

        def crowd() -> tuple[list[str], list[bool]]:
            idle = [socket.socket(socket.AF_UNIX) for _ in range(40)]  # connect, never speak
            held = []
            for sock in idle:
                sock.connect(str(path))
            for _ in range(200):  # more than the limit, all open at once
                sock = socket.socket(socket.AF_UNIX)
                sock.connect(str(path))  # blocking: waits while the listen backlog is full
                sock.settimeout(30)  # a bound for a loaded machine, not a wait: replies come at once
                held.append(sock)
            replies = []
            for sock in held:
                with Connection(sock, name) as conn:  # no path: no retry, see what the graph said
                    try:
                        conn.graph()
                        replies.append("answered")
                    except ControlError as exc:
                        replies.append(str(exc))
            lookups = []
            for _ in range(5):  # the command line, while the idle ones still hold their places
                with connect(name) as conn:
                    lookups.append(conn.graph().name == name)
            for sock in idle:
                sock.close()
            return replies, lookups

        replies, lookups = await anyio.to_thread.run_sync(crowd)
        refused = [r for r in replies if r != "answered"]
        assert set(refused) == {"the graph is busy: 64 connections are open; try again"}
        assert 0 < len(refused) < 200 and all(lookups)
        with anyio.fail_after(30):
            while endpoint.server.pool.connections:  # the server notices each hang-up
                await anyio.sleep(0.01)
        assert open_fds() == baseline
        stats = endpoint.server.stats()
        assert stats.refused >= len(refused) and stats.peak == 64


@contextlib.contextmanager
def talker_graph(tmp_path: Path, preexec_fn: Callable[[], None] | None = None) -> Iterator[subprocess.Popen[str]]:
    """``python -m actors.run`` of a one-talker graph named ``fds<pid>``, up and publishing; stopped after."""
    graph = tmp_path / f"fds{os.getpid()}.toml"
    graph.write_text('[[nodes]]\nuse = "nodes.talker:MinimalPublisher"\n')
    proc = subprocess.Popen(
        [sys.executable, "-m", "actors.run", str(graph)],
        cwd=ROOT,
        env=python_env(),
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        preexec_fn=preexec_fn,
    )
    try:
        assert "Publishing" in proc.stdout.readline()  # up and running
        yield proc
    finally:
        proc.terminate()
        out, _ = proc.communicate(timeout=30)
    assert proc.returncode == 0, out
    assert "Traceback" not in out


def graph_fds(proc: subprocess.Popen[str]) -> int:
    return len(os.listdir(f"/proc/{proc.pid}/fd"))


def back_to(proc: subprocess.Popen[str], baseline: int) -> int:
    """The graph's descriptors once it has noticed every hang-up (nothing outside it can tell when), 5 s at most."""
    deadline = time.monotonic() + 5
    while graph_fds(proc) != baseline and time.monotonic() < deadline:
        time.sleep(0.01)
    return graph_fds(proc)


def control_endpoint_check(name: str) -> Check:
    """Doctor's "control endpoint" check of graph ``name``."""
    with connect(name) as conn:
        report = conn.request(Diagnose(), Report)
    (check,) = [c for c in report.checks if c.name == "control endpoint"]
    return check


@pytest.fixture
def descriptors_for_2600() -> Iterator[None]:
    """This process may hold 2,500 sockets at once (as 2,500 clients would between them)."""
    soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    if hard != resource.RLIM_INFINITY and hard < 2600:
        pytest.skip(f"the descriptor limit here is {hard}")
    resource.setrlimit(resource.RLIMIT_NOFILE, (max(soft, 2600), hard))
    yield
    resource.setrlimit(resource.RLIMIT_NOFILE, (soft, hard))


@pytest.mark.skipif(not Path("/proc").is_dir(), reason="counts the graph's descriptors in /proc")
@pytest.mark.slow
def test_2_two_thousand_connections_at_once_and_500_idle_ones_the_command_line_still_gets_in(
    tmp_path, descriptors_for_2600
):
    with talker_graph(tmp_path) as proc:
        name = f"fds{os.getpid()}"
        path = endpoint_dir() / f"{name}.sock"
        before = graph_fds(proc)
        idle = [socket.socket(socket.AF_UNIX) for _ in range(500)]
        crowd = [socket.socket(socket.AF_UNIX) for _ in range(2000)]
        try:
            for sock in idle:
                sock.connect(str(path))  # blocking: waits while the listen backlog is full
            for sock in crowd:  # all 2,000 open at once, each with a request sent
                sock.connect(str(path))
                sock.settimeout(10)
                with contextlib.suppress(OSError):  # a refused one may be closed before we speak
                    sock.sendall(frame(GetGraph()))
            lookups = []
            for _ in range(5):  # the command line, with all 2,500 still open
                with connect(name) as conn:
                    lookups.append(conn.graph().name)
            outcomes = Counter()
            for sock in crowd:
                try:
                    (size,) = struct.unpack(">I", sock.recv(4, socket.MSG_WAITALL))
                    reply = decode_reply(sock.recv(size, socket.MSG_WAITALL))
                    outcomes["answered" if reply.ok else reply.error] += 1
                except TimeoutError:
                    outcomes["no answer within 10 s"] += 1
                except (OSError, struct.error):
                    outcomes["closed"] += 1  # evicted while idle, before its request was read
        finally:
            for sock in idle + crowd:
                sock.close()
        assert lookups == [name] * 5
        # Each one answered, told the graph is busy, or (idle for 0.5 s while full) closed for a newcomer.
        assert set(outcomes) <= {"answered", "closed", "the graph is busy: 256 connections are open; try again"}
        assert sum(outcomes.values()) == 2000
        assert proc.poll() is None  # still running
        assert back_to(proc, before) == before
        check = control_endpoint_check(name)
        assert check.passed  # the limit at work is a warning: nothing ran out
        assert any(
            w.endswith(
                ("connection(s) refused at the limit of 256 open at once", "idle connection(s) closed to let others in")
            )
            for w in check.warnings
        )


def test_2_a_graph_whose_queue_of_new_connections_is_full_is_busy_to_the_command_line_not_gone(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_RUNTIME_DIR", str(tmp_path))
    monkeypatch.setattr(actors.cli._client, "BUSY_RETRY", 0.05)
    listener = socket.socket(socket.AF_UNIX)
    listener.bind(str(endpoint_dir(create=True) / "full.sock"))
    listener.listen(0)  # a graph that a burst of clients keeps from accepting
    pending = []
    with contextlib.ExitStack() as stack:
        stack.enter_context(listener)
        for _ in range(10):
            sock = stack.enter_context(socket.socket(socket.AF_UNIX))
            sock.setblocking(False)
            try:
                sock.connect(listener.getsockname())
            except BlockingIOError:
                break  # the queue is full
            pending.append(sock)
        else:
            pytest.fail("the listen queue never filled")
        with pytest.raises(ControlError) as caught:
            connect("full")
        assert str(caught.value) == "graph full is busy: its queue of new connections is full; try again"
        listener.accept()[0].close()  # room for one more
        with connect("full") as conn:
            assert conn.name == "full"


@pytest.mark.skipif(not Path("/proc").is_dir(), reason="counts the graph's descriptors in /proc")
@pytest.mark.slow
def test_2_a_graph_that_runs_out_of_descriptors_refuses_connections_and_keeps_running(tmp_path):
    limit = 48

    def few_descriptors() -> None:
        resource.setrlimit(resource.RLIMIT_NOFILE, (limit, resource.getrlimit(resource.RLIMIT_NOFILE)[1]))

    with talker_graph(tmp_path, few_descriptors) as proc:
        name = f"fds{os.getpid()}"
        path = endpoint_dir() / f"{name}.sock"
        before = graph_fds(proc)
        held, replies = [], []
        for _ in range(2 * limit):
            sock = socket.socket(socket.AF_UNIX)
            sock.settimeout(5)
            try:
                sock.connect(str(path))
            except OSError:
                sock.close()
                continue
            held.append(sock)
        for sock in held:
            with contextlib.suppress(OSError):  # a refused connection is closed before we speak
                sock.sendall(frame(GetGraph()))
            with contextlib.suppress(OSError, struct.error):
                size = struct.unpack(">I", sock.recv(4, socket.MSG_WAITALL))[0]
                replies.append(decode_reply(sock.recv(size, socket.MSG_WAITALL)))
        refusals = [r.error for r in replies if not r.ok]
        assert refusals and all("run out of file descriptors" in e for e in refusals)
        assert any(r.ok for r in replies)
        for sock in held:
            sock.close()
        assert proc.poll() is None  # still running
        assert back_to(proc, before) == before
        (reason,) = control_endpoint_check(name).reasons
        assert reason.startswith(f"the graph ran out of file descriptors (limit {limit}): ")


# --------------------------------------------------------------------------- 3. stalled readers


@pytest.mark.virtual_time
async def test_3_stalled_scan_readers_lose_scans_instead_of_growing_the_graph(name):
    limits = ConnectionLimits(outbox_bytes=128 * 1024)
    async with Runtime(name=name, attach=[endpoint := ControlEndpoint(limits)]) as rt:
        rt.spawn(World, params={"world": "signs"})
        rt.spawn(TurtleBot)
        readers = []
        for _ in range(5):
            stream = await anyio.connect_unix(endpoint.server.path)
            await stream.send(frame(Subscribe(topic="/scan")))
            receive = BufferedByteReceiveStream(stream)
            (size,) = struct.unpack(">I", await receive.receive_exactly(4))
            assert decode_reply(await receive.receive_exactly(size)).ok
            readers.append(stream)  # and never read again
        await anyio.sleep(60)
        pool = endpoint.server.pool
        assert all(c._outbox_bytes <= limits.outbox_bytes for c in pool.connections)
        scans = next(t for t in rt.graph.topics() if t.name == "/scan")
        assert all(s.queued <= 1 for s in scans.subscriptions)  # nothing piles up before the outbox
        assert pool.stats().dropped > 5 * 500  # 600 scans each, most of them lost
        for stream in readers:
            await stream.aclose()


# --------------------------------------------------------------------------- 4. malformed requests


async def test_4_malformed_requests_are_answered_and_logged_once_per_connection_without_traceback(name, caplog):
    async with Runtime(name=name, attach=[endpoint := ControlEndpoint()]) as rt:

        async def ask(stream: anyio.abc.SocketStream, request: object) -> str:
            await stream.send(frame(request))
            receive = BufferedByteReceiveStream(stream)
            (size,) = struct.unpack(">I", await receive.receive_exactly(4))
            reply = decode_reply(await receive.receive_exactly(size))
            assert not reply.ok
            return reply.error

        async with await anyio.connect_unix(endpoint.server.path) as first:
            errors = [
                await ask(first, {"op": "publsh", "topic": "/x"}),
                await ask(first, Publish(topic="/chatter", type="std_msgs/msg/Bool", msg={"data": "maybe"})),
                await ask(
                    first, Publish(topic="/chatter", type="std_msgs/msg/UInt8", msg={"data": 2**64 - 1})
                ),  # /chatter is free again
                await ask(first, Subscribe(topic="/rosout", depth=2**63)),
                await ask(first, {"op": "call", "service": "/s", "type": "t", "timeout": float("nan")}),
            ]
        async with await anyio.connect_unix(endpoint.server.path) as second:
            errors.append(await ask(second, {"op": "reboot"}))
        assert rt.graph.nodes() == []  # and the graph is fine
    assert errors == [
        "bad request: op: 'publsh' is not one of graph, node, publish, subscribe, call, doctor, play "
        "(did you mean 'publish'?)",
        "field 'data' of std_msgs/msg/Bool: expected a bool, got the string 'maybe'",
        "field 'data' of std_msgs/msg/UInt8: expected an integer <= 255, got the integer 18446744073709551615",
        "bad request: depth: expected an integer <= 10000, got the integer 9223372036854775808",
        "bad request: timeout: expected a number > 0.0, got the number nan",
        "bad request: op: 'reboot' is not one of graph, node, publish, subscribe, call, doctor, play",
    ]
    logged = [r for r in caplog.records if "control endpoint" in r.getMessage()]
    assert [r.getMessage().split(": ", 2)[1] for r in logged] == ["connection 1", "connection 2"]
    assert all(r.levelno == logging.WARNING and not r.exc_info for r in logged)
    assert not [r for r in caplog.records if r.levelno >= logging.ERROR]  # asyncio's included


# --------------------------------------------------------------------------- 5, 6. files

DEEP = "[[nodes]]\nuse = 'nodes.talker:MinimalPublisher'\nparams = { x = " + "[" * 3000 + "]" * 3000 + " }\n"
TALKER = "[[nodes]]\nuse = 'nodes.talker:MinimalPublisher'\n"


@pytest.mark.parametrize(
    ("content", "problem"),
    [
        (b"\xff\xfe[runtime]\n", "not UTF-8 text (byte 0 is 0xff); TOML files are UTF-8"),
        (DEEP.encode(), "values nested too deeply to read"),
        (
            b"[runtime]\nduration = inf\n" + TALKER.encode(),
            "runtime.duration: expected a number <= 1000000000.0, got the number inf",
        ),
        (
            b"[runtime]\nduration = 1e308\n" + TALKER.encode(),
            "runtime.duration: expected a number <= 1000000000.0, got the number 1e+308",
        ),
        (b"", 'no nodes: a graph needs at least one [[nodes]] table with use = "module:Class"'),
        (
            b"[supervisor]\nintensity = 99999999999999999999\n" + TALKER.encode(),
            "supervisor.intensity: expected an integer <= 1000000, got the integer 99999999999999999999",
        ),
        (
            b"[supervisor]\nbackoff = 3.0\nmax_backoff = 1.0\n" + TALKER.encode(),
            "supervisor: max_backoff (1) must be at least backoff (3)",
        ),
        (
            TALKER.encode()
            + b"name = 'a'\n[[nodes]]\nuse = 'nodes.listener:MinimalSubscriber'\nname = 'a'\ndelay = 1.0\n",
            "nodes[1].name: a node named /a is already nodes[0]; give one of them another name",
        ),
        (
            TALKER.encode() + TALKER.encode(),
            "nodes[1].use: a node named /minimal_publisher is already nodes[0]; give one of them another name",
        ),
        (
            b"[[nodes]]\nuse = 'world.sim:World'\nparams = { dt = 0.0 }\n",
            "nodes[0] (world.sim:World): parameter 'dt' of /world: 0.0 is out of range [0.0001, 0.1]",
        ),
        (
            b"[[nodes]]\nuse = 'world.sim:World'\nparams = { dt = -0.01 }\n",
            "nodes[0] (world.sim:World): parameter 'dt' of /world: -0.01 is out of range [0.0001, 0.1]",
        ),
    ],
    ids=[
        "not-utf8",
        "deep",
        "inf",
        "1e308",
        "empty",
        "int64",
        "backoff",
        "duplicate-delayed",
        "duplicate-default-name",
        "dt-zero",
        "dt-negative",
    ],
)
def test_5_6_each_malformed_graph_or_world_case_is_one_line_and_exit_2(tmp_path, capsys, content, problem):
    path = tmp_path / "g.toml"
    path.write_bytes(content)
    code = actors.run.main([str(path), "--clock", "virtual", "--duration", "5"])
    out, err = capsys.readouterr()
    assert code == 2
    assert err == f"error: {path}: {problem}\n"
    assert "Hello World" not in out  # nothing started
