"""``--transport zenoh``: the command line as a Zenoh peer, seeing every process's graph.

With a transport, a command does not connect to one graph's control socket:
it starts a runtime of its own (no nodes) with the Zenoh transport, in a
thread, serves that runtime's control endpoint on a private socket, and
talks to it as it would to a graph.  That runtime's graph view holds the
nodes and endpoints of every process on the domain (actors graphs and ROS 2
nodes with rmw_zenoh_cpp alike), its subscriptions and clients reach them,
and it is gone when the command ends.

Discovery takes a moment: before the command runs, the runtime waits until
the graph it sees has stopped growing for a short while (bounded), as
``ros2`` commands rely on their daemon for.
"""

from __future__ import annotations

import os
import shutil
import socket
import tempfile
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import anyio

from actors.errors import ActorsError, ControlError
from actors.launch.graph_file import TransportSection
from actors.ops.control import ControlServer
from actors.runtime import Runtime
from actors.transport.zenoh import ZenohTransport

__all__ = ["CHOICES", "chosen", "bridge"]

CHOICES = ("zenoh", "none")
_STEADY = 0.3  # seconds the remote graph must stay unchanged before a command runs
_SETTLE_AT_MOST = 3.0


def chosen(flag: str | None) -> bool:
    """Whether a command goes through Zenoh: ``--transport``, else ``$ACTORS_TRANSPORT``.

    Raises ControlError for a value other than ``zenoh`` or ``none``.
    """
    value = flag if flag is not None else os.environ.get("ACTORS_TRANSPORT", "").strip() or "none"
    if value not in CHOICES:
        raise ControlError(f"ACTORS_TRANSPORT must be one of {', '.join(CHOICES)}, got {value!r}")
    return value == "zenoh"


@contextmanager
def bridge() -> Iterator[Path]:
    """A private runtime on Zenoh, served on a socket whose path is yielded; stopped on exit.

    Raises TransportError (zenoh missing, a bad setting) or ControlError.
    """
    directory = Path(tempfile.mkdtemp(prefix="actors-zenoh-"))
    path = directory / "cli.sock"
    ready = threading.Event()
    state: dict[str, object] = {}

    async def serve() -> None:
        # Listening on a free port only: a passing command must not become where graphs meet.
        transport = ZenohTransport(TransportSection(listen=["tcp/127.0.0.1:0"]))
        async with Runtime(name="actors_cli", attach=[transport]) as rt:
            state["runtime"] = rt
            await _settle(transport)
            with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as sock:
                sock.setblocking(False)
                sock.bind(str(path))
                sock.listen(8)
                server = ControlServer(rt, path)
                async with anyio.create_task_group() as tg:
                    tg.start_soon(server.pool.run, sock)
                    ready.set()
                    await rt.wait()
                    tg.cancel_scope.cancel()

    def run() -> None:
        try:
            anyio.run(serve)
        except BaseException as exc:
            state["error"] = exc
        finally:
            ready.set()

    thread = threading.Thread(target=run, name="actors-zenoh", daemon=True)
    thread.start()
    try:
        ready.wait()
        error = state.get("error")
        if isinstance(error, ActorsError):
            raise error
        if error is not None:
            raise ControlError(f"cannot reach the Zenoh graph: {error!r}")
        yield path
    finally:
        runtime = state.get("runtime")
        if isinstance(runtime, Runtime) and thread.is_alive():
            runtime.loop.call_soon_threadsafe(runtime.shutdown)
        thread.join(10)
        shutil.rmtree(directory, ignore_errors=True)


async def _settle(transport: ZenohTransport) -> None:
    """Wait until the remote graph has not changed for a moment (at most a few seconds)."""
    with anyio.move_on_after(_SETTLE_AT_MOST):
        seen = None
        while True:
            now = transport.remote_nodes()
            if now == seen:
                return
            seen = now
            await anyio.sleep(_STEADY)
