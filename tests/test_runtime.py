"""Runtime: lifecycle, spawning with overrides, embedding in an anyio application."""

from __future__ import annotations

import gc
import json
import subprocess
import sys
import warnings
from typing import ClassVar

import anyio
import anyio.lowlevel
import pytest
from graph_nodes import Counter

from actors import InvalidNameError, Node, Runtime
from interfaces.std_msgs.msg import Int64


class Collector(Node):
    def __init__(self) -> None:
        super().__init__("collector")
        self.values: list[int] = []
        self.create_subscription(Int64, "numbers", lambda m: self.values.append(m.data), 10)


def test_a_node_cannot_be_built_outside_a_runtime():
    with pytest.raises(RuntimeError, match=r"rt.spawn\(Collector\)"):
        Collector()


async def test_spawn_requires_a_running_runtime():
    rt = Runtime()
    with pytest.raises(RuntimeError, match="unopened"):
        rt.spawn(Collector)
    async with rt:
        pass
    with pytest.raises(RuntimeError, match="closed"):
        rt.spawn(Collector)


@pytest.mark.virtual_time
async def test_names_are_overridden_and_must_be_unique():
    async with Runtime() as rt:
        node = rt.spawn(Collector, name="other", namespace="/robot1")
        assert (node.get_name(), node.get_namespace()) == ("other", "/robot1")
        assert rt.node("/robot1/other") is node and rt.node("other") is node
        with pytest.raises(InvalidNameError, match="already runs"):
            rt.spawn(Collector, name="other", namespace="/robot1")
        with pytest.raises(InvalidNameError, match="invalid node name"):
            rt.spawn(Collector, name="no way")


class Greeter(Node):
    """A node whose constructor takes arguments of its own, as many rclpy nodes' do."""

    instances = 0

    def __init__(self, greeting: str, *, times: int = 1, crash: bool = False) -> None:
        super().__init__("greeter")
        Greeter.instances += 1
        self.said = [greeting] * times
        if crash:
            self.create_timer(0.5, self.explode)

    def explode(self) -> None:
        raise RuntimeError("boom")


@pytest.mark.virtual_time
async def test_spawn_passes_constructor_arguments_also_to_a_restarted_instance():
    Greeter.instances = 0
    async with Runtime() as rt:
        node = rt.spawn(Greeter, "hello", times=2, crash=True, name="g1")
        assert node.said == ["hello", "hello"] and node.get_name() == "g1"
        await anyio.sleep(0.8)  # it crashed at 0.5 s and was restarted after the 0.1 s backoff
        again = rt.node("g1")
        assert again is not node and again.said == ["hello", "hello"] and Greeter.instances == 2
        with pytest.raises(TypeError):
            rt.spawn(Greeter, name="g2")  # the constructor's own error: a missing argument


@pytest.mark.virtual_time
async def test_embedding_beside_other_tasks_of_an_anyio_application():
    app_ticks = []

    async def application_task() -> None:
        for i in range(5):
            await anyio.sleep(0.25)
            app_ticks.append(i)

    async with anyio.create_task_group() as tg:
        tg.start_soon(application_task)
        async with Runtime(name="embedded") as rt:
            collector = rt.spawn(Collector)
            rt.spawn(Counter)
            await rt.wait(1.05)
    assert app_ticks == [0, 1, 2, 3, 4]
    assert collector.values == list(range(10))


@pytest.mark.virtual_time
async def test_shutdown_ends_wait():
    async with Runtime() as rt:
        rt.spawn(Counter)
        async with anyio.create_task_group() as tg:
            tg.start_soon(rt.wait)
            await anyio.sleep(1)
            rt.shutdown()
        assert rt.clock.monotonic() == 1.0


@pytest.mark.virtual_time
async def test_a_runtime_failed_from_outside_the_supervisor_still_stops_its_nodes():
    stopped: list[str] = []

    class Hooked(Node):
        def __init__(self) -> None:
            super().__init__("hooked")

        def on_shutdown(self) -> None:
            stopped.append(self.get_name())

    with pytest.raises(ValueError, match="given up"):
        async with Runtime() as rt:
            rt.spawn(Hooked)
            rt._fail(ValueError("given up"))  # cancels the block; the nodes still stop gracefully
            await anyio.sleep(1)
    assert stopped == ["hooked"]


@pytest.mark.virtual_time
async def test_a_node_built_under_spawning_runs_on_the_actor_it_is_given():
    # The seam the rclpy layer builds a script's nodes with, outside the supervisor.
    from actors.core._actor import Actor
    from actors.ros.node import SpawnRequest, spawning
    from actors.system.supervisor import Child, RestartType

    async with Runtime() as rt:
        actor = Actor(rt.loop)
        child = Child(
            Collector, name="scripted", namespace=None, params=None, remap=None, restart=RestartType.TEMPORARY
        )
        with spawning(SpawnRequest(rt, child, actor=actor)):
            node = Collector()
        assert node._core.actor is actor and rt.node("scripted") is node
        with pytest.raises(RuntimeError, match="must be started by a runtime"):
            Collector()  # outside the block again
        node.destroy_node()


def test_frozen_startup_pauses_collection_then_freezes_what_was_built():
    from actors.runtime import frozen_startup

    assert gc.isenabled()
    frozen = gc.get_freeze_count()
    try:
        with frozen_startup():
            assert not gc.isenabled()
            built = [[i] for i in range(100)]
        assert gc.isenabled() and gc.get_freeze_count() >= frozen + len(built)
    finally:
        gc.unfreeze()


class Spawned(Node):
    """Notes whether the cyclic collector could run while it was built."""

    collecting: ClassVar[list[bool]] = []

    def __init__(self) -> None:
        super().__init__("spawned")
        # Paused means no allocation count can reach the youngest generation's threshold.
        Spawned.collecting.append(gc.isenabled() and 0 < gc.get_threshold()[0] < 2**31 - 1)


@pytest.fixture
def collector():
    """The collector as the test found it, restored afterwards."""
    enabled, threshold = gc.isenabled(), gc.get_threshold()
    yield threshold
    gc.set_threshold(*threshold)
    (gc.enable if enabled else gc.disable)()


async def test_a_burst_of_spawns_runs_with_the_collector_paused_until_the_loop_runs_again(collector):
    Spawned.collecting = []
    async with Runtime() as rt:
        assert gc.isenabled()
        for i in range(3):
            rt.spawn(Spawned, name=f"s{i}")
        assert Spawned.collecting == [False, False, False]
        await anyio.lowlevel.checkpoint()
        assert gc.isenabled() and gc.get_threshold() == collector


async def test_the_embedding_codes_own_collector_settings_outlast_a_burst(collector):
    async with Runtime() as rt:
        rt.spawn(Spawned, name="a")
        gc.disable()  # after a spawn, in the same loop iteration
        await anyio.lowlevel.checkpoint()
        assert not gc.isenabled() and gc.get_threshold() == collector
        rt.spawn(Spawned, name="b")  # a burst while disabled: left alone
        await anyio.lowlevel.checkpoint()
        assert not gc.isenabled()
        gc.enable()
        rt.spawn(Spawned, name="c")
        gc.set_threshold(5000, 20, 20)  # retuned during the burst: kept
        await anyio.lowlevel.checkpoint()
        assert gc.isenabled() and gc.get_threshold() == (5000, 20, 20)


BURST = """
import asyncio, gc, json
from actors import Node, Runtime

class Idle(Node):
    def __init__(self):
        super().__init__("idle")
        self.create_timer(1.0, lambda: None)

full = []
gc.callbacks.append(lambda phase, info: phase == "start" and info["generation"] == 2 and full.append(1))

async def main():
    async with Runtime() as rt:
        rt.spawn(Idle, name="warm")
        await asyncio.sleep(0)
        gc.collect()
        full.clear()
        for i in range({count}):
            rt.spawn(Idle, name=f"n{{i}}")
        during = len(full)
        await asyncio.sleep(0)
        print(json.dumps([during, len(full), gc.get_count()[0]]))

asyncio.run(main())
"""


@pytest.mark.parametrize(("count", "collections"), [(50, 0), (3000, 1)])
def test_a_burst_that_grows_the_heap_by_a_quarter_ends_with_one_full_collection(count, collections):
    # A fresh interpreter: the test process's own heap would hide the burst.
    out = subprocess.run([sys.executable, "-c", BURST.format(count=count)], capture_output=True, text=True, check=True)
    during, after, young = json.loads(out.stdout)
    assert during == 0  # none while spawning
    assert after == collections
    if collections:
        assert young < 1000  # what the burst built was collected, not left to the next seconds


async def test_a_closed_runtime_leaves_no_stream_to_warn_when_collected():
    gc.collect()  # what earlier tests left
    async with Runtime() as rt:
        rt.spawn(Spawned, name="s")
    del rt
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        gc.collect()
    assert [str(w.message) for w in caught if issubclass(w.category, ResourceWarning)] == []
