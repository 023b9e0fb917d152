"""The live view's limits: a crowd of viewers takes neither the graph's descriptors nor its memory (issue 34)."""

from __future__ import annotations

import base64
import contextlib
import os
import re
import resource
import socket
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
