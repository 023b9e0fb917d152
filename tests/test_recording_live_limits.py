"""The live view's limits: a crowd of viewers takes neither the graph's descriptors nor its memory (issue 34)."""

from __future__ import annotations

import asyncio
import base64
import contextlib
import json
import os
import re
import resource
import socket
import struct
import subprocess
import sys
import threading
import time
import zlib
from collections import Counter
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from conftest import ROOT, python_env

import actors.recording._subprotocols
from actors.recording._subprotocols import LEGACY, MAX_VIEWERS, SDK, SubprotocolFront

pytest.importorskip("foxglove")

VIEWERS = 1100
SERVING = re.compile(r"foxglove: serving the graph on ws://127\.0\.0\.1:(\d+)")


def upgrade(i: int, subprotocol: str) -> bytes:
    """A WebSocket upgrade request as a viewer sends it (each with its own key)."""
    key = base64.b64encode(i.to_bytes(16, "big")).decode()
    return (
        "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
        f"Sec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\nSec-WebSocket-Protocol: {subprotocol}\r\n\r\n"
    ).encode()


def status(sock: socket.socket) -> str:
    """The HTTP status the server answered on ``sock`` ("closed" when it said nothing)."""
    head = b""
    with contextlib.suppress(OSError):
        while b"\r\n" not in head and (data := sock.recv(4096)):
            head += data
    return head.split(b" ", 2)[1].decode() if head.startswith(b"HTTP/1.1 ") else "closed"


def rss_mb(pid: int) -> float:
    status = Path(f"/proc/{pid}/status").read_text()
    return int(re.search(r"VmRSS:\s+(\d+) kB", status)[1]) / 1024  # type: ignore[index]


def descriptors(pid: int) -> int:
    return len(os.listdir(f"/proc/{pid}/fd"))


def eventually(condition: Callable[[], bool], seconds: float = 20) -> bool:
    """Whether ``condition`` holds within ``seconds`` (another process's state, looked at until then)."""
    deadline = time.monotonic() + seconds
    while not condition():
        if time.monotonic() > deadline:
            return False
        time.sleep(0.05)
    return True


@pytest.fixture
def descriptors_for_crowd() -> Iterator[None]:
    """This process may hold every viewer's socket at once."""
    soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    if hard != resource.RLIM_INFINITY and hard < VIEWERS + 200:
        pytest.skip(f"the descriptor limit here is {hard}")
    resource.setrlimit(resource.RLIMIT_NOFILE, (max(soft, VIEWERS + 200), hard))
    yield
    resource.setrlimit(resource.RLIMIT_NOFILE, (soft, hard))


@contextlib.contextmanager
def viewed_graph(tmp_path: Path) -> Iterator[tuple[subprocess.Popen[bytes], str, int, Path]]:
    """A one-talker graph with ``--foxglove 0`` in a process, under the default descriptor limit.

    Yields it, its name, the view's port and its log; stopped with SIGTERM after.
    """
    name = f"lv{os.getpid()}_{zlib.crc32(str(tmp_path).encode()):08x}"
    graph, log = tmp_path / f"{name}.toml", tmp_path / "graph.log"
    graph.write_text('[[nodes]]\nuse = "nodes.talker:MinimalPublisher"\n')
    soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    with log.open("wb") as out:
        proc = subprocess.Popen(
            [sys.executable, "-m", "actors.run", str(graph), "--foxglove", "0"],
            cwd=ROOT,
            env=python_env(),
            stdout=out,
            stderr=subprocess.STDOUT,
            # The soft limit a shell gives, not this test's raised one: the crowd is larger.
            preexec_fn=lambda: resource.setrlimit(resource.RLIMIT_NOFILE, (min(soft, 1024), hard)),
        )
    try:
        assert eventually(lambda: SERVING.search(log.read_text()) is not None or proc.poll() is not None)
        found = SERVING.search(log.read_text())
        assert found, log.read_text()
        yield proc, name, int(found[1]), log
    finally:
        proc.terminate()
        proc.wait(timeout=30)
    assert proc.returncode == 0, log.read_text()


@pytest.mark.skipif(not Path("/proc").is_dir(), reason="reads the graph's memory and descriptors in /proc")
@pytest.mark.slow
def test_1100_viewers_at_once_the_command_line_works_and_memory_comes_back(tmp_path, descriptors_for_crowd):
    with viewed_graph(tmp_path) as (proc, name, port, log):
        rss_before, fds_before = rss_mb(proc.pid), descriptors(proc.pid)
        crowd = []
        try:
            for i in range(VIEWERS):  # all open at once, each with its handshake sent, half under each name
                sock = socket.create_connection(("127.0.0.1", port), timeout=10)
                crowd.append(sock)
                with contextlib.suppress(OSError):  # a refused one may be closed before we speak
                    sock.sendall(upgrade(i, (SDK, LEGACY)[i % 2]))
            outcomes = Counter(status(sock) for sock in crowd)
            nodes = subprocess.run(
                [sys.executable, "-m", "actors", "node", "list", "--graph", name],
                cwd=ROOT,
                env=python_env(),
                capture_output=True,
                text=True,
                timeout=30,
            )
            rss_during, fds_during = rss_mb(proc.pid), descriptors(proc.pid)
        finally:
            for sock in crowd:
                sock.close()
        assert (nodes.returncode, nodes.stdout.split()) == (0, ["/minimal_publisher"]), nodes
        assert outcomes == {"101": MAX_VIEWERS, "503": VIEWERS - MAX_VIEWERS}
        assert rss_during < 150, (rss_before, rss_during)
        # A viewer costs the graph three descriptors (its socket, the relay's and the SDK's), one in the limit.
        assert fds_during <= fds_before + 3 * MAX_VIEWERS + 10, (fds_before, fds_during)
        assert eventually(lambda: descriptors(proc.pid) <= fds_before + 2), (fds_before, descriptors(proc.pid))
        assert eventually(lambda: rss_mb(proc.pid) < rss_before + 20), (rss_before, rss_during, rss_mb(proc.pid))
        # The crowd gone, a viewer gets in again.
        with socket.create_connection(("127.0.0.1", port), timeout=10) as sock:
            sock.sendall(upgrade(VIEWERS, SDK))
            assert status(sock) == "101"
        assert proc.poll() is None
    refusals = [line for line in log.read_text().splitlines() if "foxglove:" in line and "refused" in line]
    assert len(refusals) == 1 and f"{MAX_VIEWERS} viewers are connected, the limit" in refusals[0], refusals


def test_viewers_over_the_limit_are_answered_503_and_counted_in_two_lines_not_one_each(monkeypatch):
    monkeypatch.setattr(actors.recording._subprotocols, "REFUSALS_PERIOD", 0.05)
    lines: list[str] = []
    counted = threading.Event()

    def warn(line: str) -> None:
        lines.append(line)
        if "in all" in line:
            counted.set()

    front = SubprotocolFront("127.0.0.1", 0, 1, max_viewers=0, warn=warn)  # no viewer at all: each refused
    port = front.start()
    try:
        answers = []
        for i in range(5):
            with socket.create_connection(("127.0.0.1", port), timeout=10) as sock:
                sock.sendall(upgrade(i, SDK))
                answers.append(status(sock))
        assert counted.wait(10)
    finally:
        front.stop()
    assert answers == ["503"] * 5 and front.refused == 5
    assert lines == [
        "foxglove: 0 viewers are connected, the limit: more are refused (HTTP 503) until some leave",
        "foxglove: 4 more viewer(s) refused at the limit of 0 (5 in all)",
    ]


BUSY = {"/odom", "/scan", "/tf", "/scene"}  # the TurtleBot's channels with the most to send
GREEDY = 20
VIRTUAL_FOREVER = ("--clock", "virtual", "--duration", "1e6")  # virtual time as fast as it goes, never ending


async def _frame(reader: asyncio.StreamReader) -> tuple[int, bytes]:
    """One unmasked frame from the server: its opcode and payload."""
    first, size = await reader.readexactly(2)
    size &= 0x7F
    if size == 126:
        (size,) = struct.unpack(">H", await reader.readexactly(2))
    elif size == 127:
        (size,) = struct.unpack(">Q", await reader.readexactly(8))
    return first & 0x0F, await reader.readexactly(size)


def _text(payload: bytes) -> bytes:
    """A masked client text frame (a zero mask: the bytes go as they are)."""
    size = len(payload)
    head = bytes([0x81, 0xFE]) + struct.pack(">H", size) if size >= 126 else bytes([0x81, 0x80 | size])
    return head + b"\0\0\0\0" + payload


async def _greedy(port: int, i: int) -> asyncio.StreamWriter:
    """A viewer that subscribes to every channel advertised (the busy ones at least), then never reads again."""
    reader, writer = await asyncio.open_connection("127.0.0.1", port)
    writer.write(upgrade(i, SDK))
    assert (await reader.readuntil(b"\r\n\r\n")).startswith(b"HTTP/1.1 101 ")
    subscribed: set[str] = set()
    while not subscribed >= BUSY:
        opcode, payload = await _frame(reader)
        if opcode == 1 and (op := json.loads(payload))["op"] == "advertise":
            first = len(subscribed)
            wanted = [{"id": first + n, "channelId": c["id"]} for n, c in enumerate(op["channels"])]
            writer.write(_text(json.dumps({"op": "subscribe", "subscriptions": wanted}).encode()))
            subscribed |= {c["topic"] for c in op["channels"]}
    return writer


async def _greedy_crowd(port: int, count: int, pid: int, grown: float) -> float:
    """``count`` greedy viewers at once, until the graph's RSS has grown to ``grown`` MB (or 10 s); the RSS then."""
    writers = [await _greedy(port, i) for i in range(count)]
    try:
        deadline = time.monotonic() + 10
        while rss_mb(pid) < grown and time.monotonic() < deadline:  # another process's state, looked at
            await asyncio.sleep(0.05)
        return rss_mb(pid)
    finally:
        for writer in writers:
            writer.close()


@pytest.mark.skipif(not Path("/proc").is_dir(), reason="reads the graph's memory in /proc")
@pytest.mark.slow
def test_viewers_that_subscribe_to_everything_and_never_read_give_their_memory_back(tmp_path):
    graph = tmp_path / f"greedy{os.getpid()}.toml"
    graph.write_text((ROOT / "graphs" / "turtlebot.toml").read_text())
    log = tmp_path / "graph.log"
    with log.open("wb") as out:
        proc = subprocess.Popen(
            [sys.executable, "-m", "actors.run", str(graph), *VIRTUAL_FOREVER, "--foxglove", "0"],
            cwd=ROOT,
            env=python_env(),
            stdout=out,
            stderr=subprocess.STDOUT,
        )
    try:
        assert eventually(lambda: SERVING.search(log.read_text()) is not None or proc.poll() is not None)
        found = SERVING.search(log.read_text())
        assert found, log.read_text()
        port = int(found[1])
        asyncio.run(_greedy_crowd(port, 1, proc.pid, 0))  # the SDK's threads started: where the graph stands
        readings = [rss_mb(proc.pid)]
        assert eventually(lambda: readings.append(rss_mb(proc.pid)) or readings[-1] == readings[-2])
        before = readings[-1]
        # Their backlogs fill (the SDK keeps up to 256 messages each) and the graph grows by tens of MB.
        during = asyncio.run(_greedy_crowd(port, GREEDY, proc.pid, before + 25))
        assert before + 25 <= during < 150, (before, during)
        assert eventually(lambda: rss_mb(proc.pid) < before + 20), (before, during, rss_mb(proc.pid))
    finally:
        proc.terminate()
        proc.wait(timeout=30)
