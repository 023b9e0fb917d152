"""Supervision: dead letters, restarts that keep queued messages, strategies, types, intensity."""

from __future__ import annotations

import logging
from typing import ClassVar

import anyio
import anyio.lowlevel
import pytest
from graph_nodes import Counter, PoisonEveryFifth

from actors import Escalation, Node, Runtime, Strategy, SupervisorPolicy
from interfaces.std_msgs.msg import Int64

pytestmark = pytest.mark.virtual_time


async def test_poison_messages_restart_the_node_and_nothing_else_is_lost(caplog):
    caplog.set_level(logging.ERROR, logger="actors")
    PoisonEveryFifth.heard = []
    PoisonEveryFifth.instances = 0
    policy = SupervisorPolicy(intensity=10, period=5.0, backoff=0.1, max_backoff=0.4)
    async with Runtime(supervisor=policy) as rt:
        rt.spawn(PoisonEveryFifth)
        counter = rt.spawn(Counter)
        await anyio.sleep(4.05)  # 40 numbers: 0..39
        counter.timer.cancel()
        await anyio.sleep(2)
    poison = [n for n in range(40) if n % 5 == 4]
    assert PoisonEveryFifth.heard == [n for n in range(40) if n % 5 != 4]  # each once, in order
    assert PoisonEveryFifth.instances == 1 + len(poison)
    dead = [r for r in caplog.records if "dead letter" in r.getMessage()]
    assert [r.getMessage().split("data=")[1].rstrip(")") for r in dead] == [str(n) for n in poison]
    assert all(r.exc_info is not None for r in dead)  # each logged once, with its traceback


async def test_exceeding_the_intensity_escalates_with_one_clear_error():
    policy = SupervisorPolicy(intensity=2, period=10.0, backoff=0.0)
    with pytest.raises(Escalation, match=r"/poisoned crashed 3 times; more than 2 restarts within 10.0 s"):
        async with Runtime(supervisor=policy) as rt:
            rt.spawn(PoisonEveryFifth)
            rt.spawn(Counter)
            await rt.wait()


class Member(Node):
    """One of three siblings; counts its instances; crashes on a message to its name."""

    started: ClassVar[dict[str, int]] = {}

    def __init__(self) -> None:
        super().__init__("member")
        name = self.get_name()
        Member.started[name] = Member.started.get(name, 0) + 1
        self.create_subscription(Int64, f"/crash_{name}", self.crash, 10)

    def crash(self, msg: Int64) -> None:
        raise RuntimeError("boom")


class Trigger(Node):
    def __init__(self) -> None:
        super().__init__("trigger")
        self.pub = self.create_publisher(Int64, "/crash_b", 10)


@pytest.mark.parametrize(
    ("strategy", "expected"),
    [
        (Strategy.ONE_FOR_ONE, {"a": 1, "b": 2, "c": 1}),
        (Strategy.ONE_FOR_ALL, {"a": 2, "b": 2, "c": 2}),
        (Strategy.REST_FOR_ONE, {"a": 1, "b": 2, "c": 2}),
    ],
)
async def test_restart_strategies(strategy, expected):
    Member.started = {}
    async with Runtime(supervisor=SupervisorPolicy(strategy=strategy)) as rt:
        for name in "abc":
            rt.spawn(Member, name=name)
        trigger = rt.spawn(Trigger)
        trigger.pub.publish(Int64(data=1))
        await anyio.sleep(1)
        assert Member.started == expected
        assert [n.name for n in rt.graph.nodes()] == ["/a", "/b", "/c", "/trigger"]


class Quitter(Node):
    """Ends itself normally on its first tick."""

    started = 0

    def __init__(self) -> None:
        super().__init__("quitter")
        Quitter.started += 1
        self.create_timer(1.0, self.destroy_node)


@pytest.mark.parametrize(("restart", "starts"), [("transient", 1), ("temporary", 1), ("permanent", 4)])
async def test_restart_types_after_a_normal_exit(restart, starts):
    Quitter.started = 0
    policy = SupervisorPolicy(intensity=100, backoff=0.0)
    async with Runtime(supervisor=policy) as rt:
        rt.spawn(Quitter, restart=restart)
        await anyio.sleep(3.5)
    assert Quitter.started == starts


async def test_a_temporary_node_is_not_restarted_after_a_crash():
    Member.started = {}
    async with Runtime() as rt:
        rt.spawn(Member, name="b", restart="temporary")
        trigger = rt.spawn(Trigger)
        trigger.pub.publish(Int64(data=1))
        await anyio.sleep(1)
        assert Member.started == {"b": 1}
        assert [n.name for n in rt.graph.nodes()] == ["/trigger"]


async def test_backoff_doubles_within_the_period():
    Member.started = {}
    policy = SupervisorPolicy(intensity=10, period=100.0, backoff=1.0, max_backoff=3.0)
    async with Runtime(supervisor=policy) as rt:
        rt.spawn(Member, name="b")
        trigger = rt.spawn(Trigger)
        restart_times = []
        for _ in range(4):
            before = Member.started["b"]
            trigger.pub.publish(Int64(data=1))
            start = rt.clock.monotonic()
            while Member.started["b"] == before:
                await anyio.sleep(0.01)
            restart_times.append(round(rt.clock.monotonic() - start, 2))
        assert restart_times == pytest.approx([1.0, 2.0, 3.0, 3.0], abs=0.02)  # 0.01 s polling


async def test_stop_runs_shutdown_hooks_and_removes_the_node():
    events = []

    class Hooked(Node):
        def __init__(self) -> None:
            super().__init__("hooked")
            self.create_publisher(Int64, "out", 10)

        async def on_shutdown(self) -> None:
            events.append("on_shutdown")

        def destroy_node(self) -> None:
            events.append("destroy_node")
            super().destroy_node()

    async with Runtime() as rt:
        rt.spawn(Hooked)
        await rt.stop("hooked")
        assert events == ["on_shutdown", "destroy_node"]
        assert rt.graph.nodes() == []
        assert [t.name for t in rt.graph.topics()] == ["/parameter_events", "/rosout"]  # the runtime's own
        assert rt.services.servers == {}


async def test_shutdown_stops_nodes_in_reverse_order():
    order = []

    class Named(Node):
        def __init__(self) -> None:
            super().__init__("named")

        def on_shutdown(self) -> None:
            order.append(self.get_name())

    async with Runtime() as rt:
        for name in ("first", "second", "third", "fourth"):
            rt.spawn(Named, name=name)
        await rt.stop("second")  # O(1) removal: the others keep their start order
        assert [n.name for n in rt.graph.nodes()] == ["/first", "/third", "/fourth"]
    assert order == ["second", "fourth", "third", "first"]


async def test_a_constructor_that_raises_half_way_leaves_nothing_behind():
    class HalfBuilt(Node):
        def __init__(self) -> None:
            super().__init__("half_built")
            self.create_subscription(Int64, "numbers", print, 10)
            raise ValueError("not today")

    async with Runtime() as rt:
        with pytest.raises(ValueError, match="not today"):
            rt.spawn(HalfBuilt)
        assert rt.nodes == {}
        assert not any(name.startswith("/half_built/") for name in rt.services.servers)
        assert rt.graph.topic("/numbers") is None
        rt.spawn(Member, name="half_built")  # the name is free again


async def test_messages_survive_a_restart_whose_first_constructor_attempt_fails():
    class Flaky(Node):
        attempts = 0
        heard: ClassVar[list[int]] = []

        def __init__(self) -> None:
            super().__init__("flaky")
            self.create_subscription(Int64, "numbers", self.on_number, 100)
            Flaky.attempts += 1
            if Flaky.attempts == 2:
                raise RuntimeError("first restart fails")

        def on_number(self, msg: Int64) -> None:
            if msg.data == 3:
                raise ValueError("poison")
            Flaky.heard.append(msg.data)

    async with Runtime(supervisor=SupervisorPolicy(intensity=5, backoff=0.5)) as rt:
        rt.spawn(Flaky)
        counter = rt.spawn(Counter)
        await anyio.sleep(3.05)
        counter.timer.cancel()
        await anyio.sleep(3)
    assert Flaky.attempts == 3
    assert Flaky.heard == [n for n in range(30) if n != 3]


async def test_stopping_an_idle_node_runs_none_of_its_queued_callbacks():
    events: list[str] = []

    class Quiet(Node):
        def __init__(self) -> None:
            super().__init__("quiet")
            self.create_subscription(Int64, "numbers", lambda msg: events.append(f"heard {msg.data}"), 10)

        def on_shutdown(self) -> None:
            events.append("on_shutdown")

    class Loud(Node):
        def __init__(self) -> None:
            super().__init__("loud")
            self.pub = self.create_publisher(Int64, "numbers", 10)

    async with Runtime() as rt:
        rt.spawn(Quiet)
        loud = rt.spawn(Loud)
        await anyio.lowlevel.checkpoint()
        loud.pub.publish(Int64(data=1))  # queued, and the node is scheduled to run it
        await rt.stop("quiet")
        await anyio.sleep(1)
        assert events == ["on_shutdown"]


async def test_stopping_a_node_inside_an_async_callback_unwinds_it_before_the_hooks():
    events: list[str] = []

    class Busy(Node):
        def __init__(self) -> None:
            super().__init__("busy")
            self.create_timer(1.0, self.work)

        async def work(self) -> None:
            events.append("work started")
            try:
                await anyio.sleep(10)
            finally:
                events.append("work unwound")

        def on_shutdown(self) -> None:
            events.append("on_shutdown")

    async with Runtime() as rt:
        rt.spawn(Busy)
        await anyio.sleep(2)
        await rt.stop("busy")
        assert events == ["work started", "work unwound", "on_shutdown"]
        assert rt.clock.monotonic() == 2.0


class CrashOnStart(Node):
    """Crashes as soon as it starts, every instance."""

    instances = 0

    def __init__(self) -> None:
        # Without parameter services a restart costs a third as much: the test stays short.
        super().__init__("crash_on_start", start_parameter_services=False)
        type(self).instances += 1

    def on_start(self) -> None:
        raise RuntimeError("start")


async def test_a_hundred_thousand_restarts_under_a_huge_intensity_do_not_overflow(caplog):
    # The n-th restart's backoff was backoff * 2**(n-1), even for backoff 0: past the 1,024th
    # restart within the period the power no longer fits a float and the supervisor died.
    caplog.set_level(logging.CRITICAL, logger="actors")  # a traceback per crash is not what is measured
    CrashOnStart.instances = 0
    policy = SupervisorPolicy(intensity=1_000_000, period=5.0, backoff=0.0)
    async with Runtime(supervisor=policy) as rt:
        rt.spawn(CrashOnStart)
        while CrashOnStart.instances <= 100_000:
            await anyio.lowlevel.checkpoint()
        assert rt.clock.monotonic() < 5.0  # every restart within one period


@pytest.mark.parametrize(
    ("restarts", "expected"),
    [(1, 0.1), (2, 0.2), (3, 0.4), (4, 0.5), (1025, 0.5), (100_000, 0.5), (10**18, 0.5)],
)
def test_the_backoff_doubles_up_to_its_cap_whatever_the_count(restarts, expected):
    policy = SupervisorPolicy(intensity=1_000_000, period=5.0, backoff=0.1, max_backoff=0.5)
    assert policy.delay(restarts) == pytest.approx(expected)


def test_a_zero_backoff_or_cap_never_waits():
    assert SupervisorPolicy(backoff=0.0).delay(100_000) == 0.0
    assert SupervisorPolicy(backoff=1e-300, max_backoff=0.0).delay(100_000) == 0.0
    assert SupervisorPolicy(backoff=1e-300, max_backoff=1e300).delay(100_000) == pytest.approx(1e300)


class FailsToRestart(Node):
    """Starts once, then its constructor raises on every restart until ``failures`` is spent."""

    instances = 0
    failures = 0

    def __init__(self) -> None:
        if type(self).instances and type(self).failures:
            type(self).failures -= 1
            raise RuntimeError("cannot start")
        type(self).instances += 1
        super().__init__("fails_to_restart")
        self.create_subscription(Int64, "crash", self.crash, 10)

    def crash(self, msg: Int64) -> None:
        raise RuntimeError("crash")


async def test_a_constructor_failing_thousands_of_times_in_a_row_is_retried_without_nesting(caplog):
    caplog.set_level(logging.CRITICAL, logger="actors")
    FailsToRestart.instances, FailsToRestart.failures = 0, 5_000
    policy = SupervisorPolicy(intensity=1_000_000, period=1e6, backoff=0.0)
    async with Runtime(supervisor=policy) as rt:
        rt.spawn(FailsToRestart)
        trigger = rt.spawn(Trigger)
        trigger.pub = trigger.create_publisher(Int64, "/crash", 10)
        await anyio.sleep(0.1)
        trigger.pub.publish(Int64(data=1))
        while FailsToRestart.instances < 2:
            await anyio.sleep(0.1)
        assert FailsToRestart.failures == 0
        assert [n.name for n in rt.graph.nodes()] == ["/fails_to_restart", "/trigger"]
