"""A node's input boundary: messages a callback refuses are dropped, counted and logged sparingly."""

from __future__ import annotations

import logging

import anyio
import anyio.lowlevel
import pytest

from actors import MessageRefused, Node, Runtime
from actors.ops.doctor import diagnose
from actors.ros._refusals import LOG_BURST, LOG_PERIOD, Refusals
from interfaces.std_msgs.msg import Int64


def test_a_publisher_and_reason_is_logged_once_and_every_refusal_is_counted():
    refusals = Refusals()
    lines = [refusals.add("/n", "/a", "negative", now=0.0) for _ in range(3)]
    assert lines[0] == "refused a message on /n from /a: negative (dropped; 1 so far)"
    assert lines[1:] == [None, None]
    assert refusals.add("/n", "/b", "negative", now=0.0) is not None  # another publisher
    assert refusals.add("/n", "/a", "too big", now=0.0) is not None  # another reason
    assert refusals.counts == {"negative": 4, "too big": 1}
    assert refusals.total == 5 and refusals.last_from == "/a"


def test_new_publishers_beyond_the_burst_wait_for_the_rate_limit_and_are_then_summed_up():
    refusals = Refusals()
    logged = [refusals.add("/n", f"/p{i}", "bad", now=0.0) for i in range(LOG_BURST + 3)]
    assert sum(line is not None for line in logged) == LOG_BURST
    assert refusals.add("/n", "/late", "bad", now=LOG_PERIOD / 2) is None  # not earned yet
    line = refusals.add("/n", "/later", "bad", now=LOG_PERIOD)
    assert line == (
        f"refused a message on /n from /later: bad (dropped; {LOG_BURST + 5} so far; 4 other refusal(s) not logged)"
    )
    # A pair the limit kept quiet is news when it comes back.
    assert refusals.add("/n", "/p5", "bad", now=3 * LOG_PERIOD) is not None


class Positive(Node):
    """Keeps positive numbers from /numbers; refuses the others (plain or async callback)."""

    def __init__(self, asynchronous: bool = False) -> None:
        super().__init__("positive")
        self.kept: list[int] = []
        self.sub = self.create_subscription(Int64, "/numbers", self.on_async if asynchronous else self.on_number, 100)

    def on_number(self, msg: Int64) -> None:
        if msg.data <= 0:
            raise MessageRefused("not positive")
        self.kept.append(msg.data)

    async def on_async(self, msg: Int64) -> None:
        await anyio.lowlevel.checkpoint()
        self.on_number(msg)


class Numbers(Node):
    """Publishes the numbers it is asked to on /numbers."""

    def __init__(self, name: str = "numbers") -> None:
        super().__init__(name)
        self.pub = self.create_publisher(Int64, "/numbers", 100)

    def send(self, *values: int) -> None:
        for value in values:
            self.pub.publish(Int64(data=value))


@pytest.mark.virtual_time
@pytest.mark.parametrize("asynchronous", [False, True], ids=["plain", "async"])
async def test_a_refused_message_is_dropped_and_the_node_keeps_running(asynchronous, caplog):
    async with Runtime(name="refusals") as rt:
        node = rt.spawn(Positive, asynchronous=asynchronous)
        numbers = rt.spawn(Numbers)
        numbers.send(1, -1, 2, 0, -5, 3)
        await anyio.sleep(0.1)
        assert node.kept == [1, 2, 3]
        assert rt.node("positive") is node  # not restarted
        (info,) = rt.graph.nodes()[:1]
        assert info.crashes == 0
        (sub,) = rt.graph.topic("/numbers").subscriptions
        assert sub.refused == {"not positive": 3} and sub.refused_from == "/numbers"
        report = {c.name: c for c in diagnose(rt).checks}
    assert not report["refused messages"].passed
    assert report["refused messages"].reasons == (
        "/numbers: /positive refused 3 message(s): not positive (3); the last from /numbers",
    )
    warnings = [r.getMessage() for r in caplog.records if r.levelno == logging.WARNING]
    assert warnings == ["refused a message on /numbers from /numbers: not positive (dropped; 1 so far)"]


@pytest.mark.virtual_time
async def test_a_refusal_names_its_publisher_among_several():
    async with Runtime(name="refusals_senders") as rt:
        node = rt.spawn(Positive)
        good, bad = rt.spawn(Numbers, "good"), rt.spawn(Numbers, "bad")
        # Untracked, a first refusal can only name the candidates ...
        good.send(1)
        bad.send(-1)
        good.send(2)
        await anyio.sleep(0.1)
        assert node.sub.refusals.last_from == "one of /bad, /good"
        # ... and from then on the subscription notes senders, even in a batch.
        bad.send(-2)
        good.send(3, 4)
        bad.send(-3)
        await anyio.sleep(0.1)
        assert node.sub.refusals.last_from == "/bad"
        good.send(-4)
        bad.send(5)
        await anyio.sleep(0.1)
        assert node.sub.refusals.last_from == "/good"
        assert node.kept == [1, 2, 3, 4, 5]


@pytest.mark.virtual_time
async def test_a_restarted_node_keeps_the_counts_and_names_senders_from_the_start():
    class Fragile(Positive):
        def on_number(self, msg: Int64) -> None:
            if msg.data == 13:
                raise RuntimeError("a real bug: crash and restart")
            super().on_number(msg)

    async with Runtime(name="refusals_restart") as rt:
        rt.spawn(Fragile)
        a, b = rt.spawn(Numbers, "a"), rt.spawn(Numbers, "b")
        a.send(-1, 13)
        await anyio.sleep(1)
        node = rt.node("positive")
        assert rt.graph.nodes()[0].crashes == 1
        b.send(-2)
        a.send(1)
        await anyio.sleep(0.1)
        assert node.sub.refusals.counts == {"not positive": 2}
        assert node.sub.refusals.last_from == "/b"
