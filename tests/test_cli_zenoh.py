"""``--transport zenoh``: the command line sees and uses the nodes of every process."""

from __future__ import annotations

import asyncio
import signal
import sys

import anyio
import pytest
from conftest import ROOT
from zenoh_procs import free_port, raw_config, spawned, zenoh_env

zenoh = pytest.importorskip("zenoh", reason="the Zenoh transport's tests need eclipse-zenoh (the test extra has it)")

pytestmark = pytest.mark.slow  # every test runs graphs and the command line as child processes


def cli_env(port: int) -> dict[str, str]:
    """A command's environment: it connects to the graphs' meeting port and listens on a free one."""
    env = zenoh_env(port)
    env["ZENOH_CONFIG_OVERRIDE"] = f'connect/endpoints=["tcp/127.0.0.1:{port}"];listen/endpoints=["tcp/127.0.0.1:0"]'
    return env


async def actors(port: int, *args: str, transport: bool = True) -> tuple[int, str, str]:
    """``python -m actors ARGS [--transport zenoh]``: exit code, stdout, stderr."""
    extra = ("--transport", "zenoh") if transport else ()
    done = await anyio.run_process(
        [sys.executable, "-m", "actors", *args, *extra], cwd=ROOT, env=cli_env(port), check=False
    )
    return done.returncode, done.stdout.decode(), done.stderr.decode()


class TokenWatch:
    """A Zenoh session of the test's own that tells when a node's liveliness token comes and goes."""

    def __init__(self, port: int, node: str) -> None:
        self.session = zenoh.open(raw_config(port))
        self.appeared = asyncio.Event()
        self.gone = asyncio.Event()
        loop = asyncio.get_running_loop()

        def heard(sample: zenoh.Sample) -> None:
            event = self.gone if sample.kind == zenoh.SampleKind.DELETE else self.appeared
            loop.call_soon_threadsafe(event.set)

        key = f"@ros2_lv/0/*/*/*/NN/*/*/{node}"
        self.sub = self.session.liveliness().declare_subscriber(key, heard, history=True)

    def close(self) -> None:
        self.sub.undeclare()
        self.session.close()


async def node_up(port: int, node: str) -> None:
    """Wait until ``node`` of some process holds its liveliness token."""
    watch = TokenWatch(port, node)
    try:
        await watch.appeared.wait()
    finally:
        watch.close()


async def test_node_list_sees_both_processes_and_a_killed_ones_nodes_vanish_within_5_s():
    port = free_port()
    env = zenoh_env(port)
    with anyio.fail_after(90):
        # The first graph holds the meeting port; the second is the one killed (see config.py:
        # while no graph holds the port, a new command cannot find the others).
        async with spawned("-m", "actors.run", "graphs/listener.toml", env=env) as listener:
            await node_up(port, "minimal_subscriber")
            async with spawned("-m", "actors.run", "graphs/talker.toml", env=env) as talker:
                await listener.wait_for("I heard")
                code, out, err = await actors(port, "node", "list")
                assert (code, err) == (0, "")
                assert out.split() == ["/minimal_publisher", "/minimal_subscriber"]
                code, out, _ = await actors(port, "node", "list", "-a")
                assert {"/_talker", "/_listener", "/minimal_publisher", "/minimal_subscriber"} <= set(out.split())

                watch = TokenWatch(port, "minimal_publisher")
                try:
                    await watch.appeared.wait()  # the watch sees the token first, or it could never see it go
                    talker.proc.send_signal(signal.SIGKILL)
                    with anyio.fail_after(5):
                        await watch.gone.wait()
                finally:
                    watch.close()
                code, out, _ = await actors(port, "node", "list")
                assert out.split() == ["/minimal_subscriber"]
                heard = len(listener.lines)
            assert listener.proc.returncode is None  # the other process keeps running
            assert len(listener.lines) == heard  # and hears nothing more, without a word of error


async def test_topics_services_and_node_info_of_other_processes():
    port = free_port()
    env = zenoh_env(port)
    with anyio.fail_after(120):
        async with (
            spawned("-m", "actors.run", "graphs/talker.toml", env=env) as talker,
            spawned("-m", "actors.run", "graphs/add_server.toml", env=env),
        ):
            await talker.wait_for("Publishing")
            await node_up(port, "minimal_service")
            code, out, err = await actors(port, "topic", "list", "-t")
            assert "/topic [std_msgs/msg/String]" in out.splitlines(), err
            code, out, err = await actors(port, "topic", "info", "-v", "/topic")
            gids = [line.removeprefix("GID: ").split(".") for line in out.splitlines() if line.startswith("GID:")]
            assert code == 0 and len(gids) == 1 and len(gids[0]) == 16, out + err  # the talker's, as ros2 prints it
            code, out, err = await actors(port, "topic", "echo", "/topic", "--once")
            assert code == 0 and out.startswith("data: 'Hello World: "), err
            code, out, err = await actors(
                port, "service", "call", "/add_two_ints", "example_interfaces/srv/AddTwoInts", "{a: 2, b: 3}"
            )
            assert code == 0 and "sum=5" in out, err
            code, out, err = await actors(port, "node", "info", "/minimal_publisher")
            assert code == 0 and "    /topic: std_msgs/msg/String" in out.splitlines(), err
            async with spawned("-m", "actors.run", "graphs/listener.toml", env=env) as listener:
                await listener.wait_for("I heard")
                code, out, err = await actors(
                    port, "topic", "pub", "/topic", "std_msgs/msg/String", "data: from the command line", "--once"
                )
                assert code == 0, err
                await listener.wait_for('I heard: "from the command line"')


async def test_the_transport_comes_from_the_environment_and_a_bad_value_is_one_line(monkeypatch):
    port = free_port()
    monkeypatch.setenv("ACTORS_TRANSPORT", "zenoh")
    with anyio.fail_after(60):
        code, out, err = await actors(port, "node", "list", transport=False)
        assert (code, out, err) == (0, "", "")  # nothing runs on this port: an empty graph, not an error
        monkeypatch.setenv("ACTORS_TRANSPORT", "carrier-pigeon")
        code, out, err = await actors(port, "node", "list", transport=False)
    assert code == 2
    assert err == "actors: ACTORS_TRANSPORT must be one of zenoh, none, got 'carrier-pigeon'\n"
