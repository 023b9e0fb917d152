"""Command-line sessions that come and go announce the same token names again, not new ones each time.

Zenoh keeps state for every key expression it ever heard of (upstream), in the
graph's process and in every peer: a graph that announced a new name for each
``topic echo`` or ``topic pub`` grew them all for as long as it ran.
"""

from __future__ import annotations

import os
import threading

import anyio
import pytest
from zenoh_procs import free_port, peer, section, until

from actors import Runtime
from actors.cli._client import connect
from actors.ops.control import ControlEndpoint, Publish, Subscribe
from actors.transport.zenoh import ZenohTransport

zenoh = pytest.importorskip("zenoh", reason="the Zenoh transport's tests need eclipse-zenoh (the test extra has it)")

ROUNDS = 4


async def test_sessions_one_after_another_announce_the_same_token_names():
    port, name = free_port(), f"tzn{os.getpid()}"
    async with Runtime(name=name, attach=[ControlEndpoint(), ZenohTransport(section(port))]) as rt, peer(port) as s:
        declared: list[str] = []  # keys of our sessions' tokens, each time one is declared
        lock = threading.Lock()

        def heard(sample) -> None:  # on a zenoh thread
            if sample.kind == zenoh.SampleKind.PUT and "_actors_cli_" in str(sample.key_expr):
                with lock:
                    declared.append(str(sample.key_expr))

        watch = s.liveliness().declare_subscriber("@ros2_lv/**", zenoh.handlers.Callback(heard))

        def session() -> None:
            with connect(name) as conn:
                conn.request(Publish(topic="/soak", type="std_msgs/msg/String", msg={"data": "x"}))
                conn.request(Subscribe(topic="/soak"))

        for done in range(1, ROUNDS + 1):
            await anyio.to_thread.run_sync(session)
            expected = 3 * done  # the session's node, publisher and subscription
            await until(lambda: len(declared) == expected)  # noqa: B023 (awaited in this iteration)
            await until(lambda: "/soak" not in rt.topics.topics)  # the server has seen the hang-up
        watch.undeclare()
    kinds = sorted(key.split("/")[5] for key in set(declared))
    assert kinds == ["MP", "MS", "NN"], sorted(set(declared))
    assert all("/_actors_cli_1" in key.replace("%", "/") for key in declared)
