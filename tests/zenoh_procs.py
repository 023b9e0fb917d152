"""Helpers of the Zenoh transport's tests: free ports, the children's environment and output, raw Zenoh peers."""

from __future__ import annotations

import asyncio
import json
import re
import signal
import socket
import sys
from collections.abc import AsyncIterator, Callable
from contextlib import asynccontextmanager
from typing import Any

import anyio
from conftest import ROOT, python_env

from actors.launch.graph_file import TransportSection

__all__ = ["free_port", "zenoh_env", "Process", "spawned", "section", "raw_config", "peer", "matched", "until"]


def free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


def zenoh_env(port: int) -> dict[str, str]:
    """A child's environment: peers meeting on ``port`` of loopback, and nothing else."""
    env = python_env()
    env["ZENOH_CONFIG_OVERRIDE"] = (
        f'connect/endpoints=["tcp/127.0.0.1:{port}"];listen/endpoints=["tcp/127.0.0.1:{port}","tcp/127.0.0.1:0"]'
    )
    env.pop("ROS_DOMAIN_ID", None)
    return env


class Process:
    """A child process whose output lines (stdout and stderr) are collected as they come."""

    def __init__(self, proc: asyncio.subprocess.Process) -> None:
        self.proc = proc
        self.lines: list[str] = []
        self._changed = asyncio.Event()

    async def _read(self) -> None:
        assert self.proc.stdout is not None
        async for raw in self.proc.stdout:
            self.lines.append(raw.decode(errors="replace").rstrip("\n"))
            self._changed.set()
        self._changed.set()

    async def wait_for(self, pattern: str, count: int = 1) -> list[re.Match[str]]:
        """The first ``count`` matches of ``pattern`` among the lines, waiting for more as needed."""
        regex = re.compile(pattern)
        while True:
            seen = len(self.lines)
            found = [m for line in self.lines if (m := regex.search(line))]
            if len(found) >= count:
                return found[:count]
            if self.proc.returncode is not None:
                raise AssertionError(
                    f"process ended ({self.proc.returncode}) before {pattern!r}:\n" + "\n".join(self.lines)
                )
            self._changed.clear()
            if len(self.lines) == seen:  # nothing came between looking and clearing
                await self._changed.wait()


@asynccontextmanager
async def spawned(*args: str, env: dict[str, str]) -> AsyncIterator[Process]:
    """``python ARGS`` from the repo root, stopped (SIGINT, then killed) when the block ends."""
    proc = await asyncio.create_subprocess_exec(
        sys.executable,
        *args,
        cwd=ROOT,
        env=env,
        stdin=asyncio.subprocess.DEVNULL,
        stdout=asyncio.subprocess.PIPE,
        stderr=asyncio.subprocess.STDOUT,
    )
    child = Process(proc)
    reader = asyncio.ensure_future(child._read())
    try:
        yield child
    finally:
        if proc.returncode is None:
            proc.send_signal(signal.SIGINT)
            try:
                await asyncio.wait_for(proc.wait(), 10)
            except TimeoutError:
                proc.kill()
                await proc.wait()
        await reader


def section(port: int) -> TransportSection:
    """A transport section meeting the others on ``port`` of loopback."""
    return TransportSection(connect=[f"tcp/127.0.0.1:{port}"], listen=[f"tcp/127.0.0.1:{port}", "tcp/127.0.0.1:0"])


def raw_config(port: int) -> Any:
    """A plain Zenoh session's config: connects to ``port``, listens on a free one, no scouting."""
    import zenoh

    config = zenoh.Config()
    config.insert_json5("connect/endpoints", json.dumps([f"tcp/127.0.0.1:{port}"]))
    config.insert_json5("listen/endpoints", json.dumps(["tcp/127.0.0.1:0"]))
    config.insert_json5("scouting/multicast/enabled", "false")
    return config


@asynccontextmanager
async def peer(port: int) -> AsyncIterator[Any]:
    """A raw Zenoh session on the same meeting port: the other process, under the test's control."""
    import zenoh

    session = await anyio.to_thread.run_sync(zenoh.open, raw_config(port))
    try:
        yield session
    finally:
        await anyio.to_thread.run_sync(session.close)


async def matched(session: Any, key: str) -> Any:
    """A publisher on ``key`` once a subscriber elsewhere matches it (the listener's transport)."""
    pub = session.declare_publisher(key)
    changes = pub.declare_matching_listener()  # before the look: a change after it is heard
    try:
        with anyio.fail_after(10):
            matching = pub.matching_status.matching
            while not matching:
                matching = (await anyio.to_thread.run_sync(changes.recv, abandon_on_cancel=True)).matching
    finally:
        changes.undeclare()  # a recv abandoned by the timeout ends with it
    return pub


async def until(condition: Callable[[], bool], seconds: float = 10) -> None:
    """Wait until ``condition()`` holds, failing after ``seconds``."""
    with anyio.fail_after(seconds):
        while not condition():  # tokens and matches arrive through zenoh's threads: nothing local to wait on
            await anyio.sleep(0.01)
