"""Graphs in separate processes over Zenoh: pub/sub, services, transient-local, a killed peer.

Each test gives its processes a private rendezvous port on loopback (through
``ZENOH_CONFIG_OVERRIDE``, as a user would), waits for what the processes
print rather than for time to pass, and bounds every wait with fail_after.
"""

from __future__ import annotations

import asyncio
import importlib.util
import sys
from pathlib import Path

import anyio
import pytest
from conftest import ROOT
from zenoh_procs import free_port, spawned, zenoh_env

pytest.importorskip("zenoh", reason="the Zenoh transport's tests need eclipse-zenoh (the test extra has it)")

pytestmark = pytest.mark.slow  # every test runs its graphs as child processes


def graph_file(tmp_path: Path, name: str, *uses: str) -> str:
    path = tmp_path / f"{name}.toml"
    nodes = "".join(f'\n[[nodes]]\nuse = "{use}"\n' for use in uses)
    path.write_text(f'[runtime]\nclock = "wall"\n\n[transport]\nkind = "zenoh"\n{nodes}')
    return str(path)


async def test_talker_and_listener_in_two_processes_hear_every_message_in_order():
    env = zenoh_env(free_port())
    with anyio.fail_after(60):
        async with spawned("-m", "actors.run", "graphs/talker.toml", env=env) as talker:
            await talker.wait_for(r'Publishing: "Hello World: 0"')
            async with spawned("-m", "actors.run", "graphs/listener.toml", env=env) as listener:
                heard = await listener.wait_for(r'I heard: "Hello World: (\d+)"', count=6)
    numbers = [int(m.group(1)) for m in heard]
    # Whatever was published before the listener was discovered is not for it (as in ROS);
    # from its first message on, every one arrives, in order.
    assert numbers == list(range(numbers[0], numbers[0] + 6))


async def test_a_service_in_one_process_answers_a_client_in_another():
    env = zenoh_env(free_port())
    with anyio.fail_after(60):
        # The client starts first and waits for the server, as in the tutorial.
        async with (
            spawned("-m", "actors.run", "graphs/add_client.toml", env=env) as client,
            spawned("-m", "actors.run", "graphs/add_server.toml", env=env) as server,
        ):
            await client.wait_for(r"Result of add_two_ints: for 41 \+ 1 = 42")
            await server.wait_for("Incoming request")


async def test_a_transient_local_topic_reaches_a_subscriber_process_started_later(tmp_path):
    env = zenoh_env(free_port())
    with anyio.fail_after(60):
        async with spawned(
            "-m", "actors.run", graph_file(tmp_path, "latcher", "zenoh_nodes:Latcher"), env=env
        ) as latcher:
            [on] = await latcher.wait_for(r"published \(on (\S+)\)")
            # A graph with a transport runs on uvloop when it is installed (the test extra has it).
            assert on.group(1) == ("uvloop" if importlib.util.find_spec("uvloop") else "asyncio.unix_events")
            reader_graph = graph_file(tmp_path, "reader", "zenoh_nodes:LateReader")
            async with spawned("-m", "actors.run", reader_graph, env=env) as reader:
                got = await reader.wait_for(r"got: (latched \d)", count=3)
    assert [m.group(1) for m in got] == ["latched 2", "latched 3", "latched 4"]  # the last depth (3) of them


async def test_a_virtual_time_graph_with_a_transport_is_refused(tmp_path):
    graph = graph_file(tmp_path, "virtual", "zenoh_nodes:Latcher")
    proc = await asyncio.create_subprocess_exec(
        sys.executable,
        "-m",
        "actors.run",
        graph,
        "--clock",
        "virtual",
        "--duration",
        "1",
        cwd=ROOT,
        env=zenoh_env(free_port()),
        stderr=asyncio.subprocess.PIPE,
    )
    with anyio.fail_after(30):
        _, err = await proc.communicate()
    assert proc.returncode == 2
    assert "runs on the wall clock" in err.decode()
    assert "Traceback" not in err.decode()
