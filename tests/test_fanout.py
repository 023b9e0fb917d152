"""Fan-out: a publisher feeding several subscriptions hands them one shared batch, with per-message semantics."""

from __future__ import annotations

import asyncio
import logging
from typing import Any, ClassVar

import anyio
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from actors import (
    DurabilityPolicy,
    Duration,
    HistoryPolicy,
    Node,
    QoSProfile,
    ReliabilityPolicy,
    Runtime,
    SupervisorPolicy,
)
from actors.core.loops import VirtualTimeLoop
from actors.errors import MessageRefused
from actors.recording.tap import TapSet
from actors.ros import topics
from actors.ros.topics import Publisher
from interfaces.std_msgs.msg import Int64

TOPIC = "numbers"


class Sink(Node):
    """Hears ``numbers`` with the depth it is given (None: KEEP_ALL)."""

    def __init__(self, depth: int | None = 10, name: str = "sink") -> None:
        super().__init__(name)
        self.heard: list[int] = []
        qos = QoSProfile(history=HistoryPolicy.KEEP_ALL) if depth is None else QoSProfile(depth=depth)
        self.sub = self.create_subscription(Int64, TOPIC, self.on_number, qos)

    def on_number(self, msg: Int64) -> None:
        self.heard.append(msg.data)


class Source(Node):
    def __init__(self, name: str = "source", lifespan: float = 0.0, latched: bool = False) -> None:
        super().__init__(name)
        qos = QoSProfile(depth=10, lifespan=Duration(seconds=lifespan)) if lifespan else QoSProfile(depth=10)
        if latched:
            qos.durability = DurabilityPolicy.TRANSIENT_LOCAL
        self.pub = self.create_publisher(Int64, TOPIC, qos)

    def send(self, *numbers: int) -> None:
        for n in numbers:
            self.pub.publish(Int64(data=n))


async def settle() -> None:
    """Let every round that is due run (a few loop iterations: rounds that reschedule run again)."""
    for _ in range(5):
        await asyncio.sleep(0)


@pytest.mark.virtual_time
async def test_interleaved_publishes_of_two_publishers_reach_every_shared_subscription_in_publish_order():
    async with Runtime() as rt:
        sinks = [rt.spawn(Sink, name=f"sink{i}") for i in range(3)]
        a, b = rt.spawn(Source, name="a"), rt.spawn(Source, name="b")
        latched = rt.spawn(Source, name="latched", latched=True)  # keeps a history: feeds each queue itself
        a.send(0, 1)
        b.send(2)
        a.send(3)
        b.send(4, 5)
        await settle()
        a.send(6)
        b.send(7)
        a.send(8)
        latched.send(9)
        a.send(10)
        latched.send(11)
        await settle()
        assert [s.heard for s in sinks] == [list(range(12))] * 3
        assert a.pub._pending is not None  # the fan-out path was taken (not each queue fed directly)


@pytest.mark.virtual_time
async def test_a_subscription_gets_what_was_published_while_it_existed_and_nothing_else():
    async with Runtime() as rt:
        first, gone = rt.spawn(Sink, name="first"), rt.spawn(Sink, name="gone")
        source = rt.spawn(Source)
        source.send(0, 1)
        late = rt.spawn(Sink, name="late")  # joins while a batch is open: it does not get 0 and 1
        source.send(2, 3)
        gone.sub.destroy()  # destroyed in the middle of a batch: nothing more from now on
        source.send(4)
        await settle()
        assert first.heard == [0, 1, 2, 3, 4]
        assert late.heard == [2, 3, 4]
        assert gone.heard in ([], [0, 1, 2, 3])  # what it had queued may or may not be read: never 4
        assert 4 not in gone.heard


@pytest.mark.virtual_time
async def test_messages_published_before_a_publisher_is_destroyed_are_still_delivered():
    async with Runtime() as rt:
        sinks = [rt.spawn(Sink, name=f"sink{i}") for i in range(2)]
        source, other = rt.spawn(Source), rt.spawn(Source, name="other")
        source.send(0, 1, 2)
        source.pub.destroy()
        other.send(3)
        await settle()
        assert [s.heard for s in sinks] == [[0, 1, 2, 3]] * 2


@pytest.mark.virtual_time
async def test_a_destroyed_publisher_of_a_single_subscription_delivers_nothing_more():
    async with Runtime() as rt:
        sink, source = rt.spawn(Sink), rt.spawn(Source)
        source.send(0)  # fed directly: the publisher's one subscription
        source.pub.destroy()
        source.send(1)
        await settle()
        assert sink.heard == [0]


@pytest.mark.virtual_time
async def test_a_publisher_feeding_one_subscription_keeps_publish_order_with_a_second_publishers_batch():
    # The first publisher feeds only the best-effort sink; the second, added later, also feeds a
    # reliable sink that the first cannot (its QoS does not match), so the second batches.
    class Picky(Sink):
        def __init__(self, reliable: bool) -> None:
            Node.__init__(self, "picky")
            self.heard = []
            reliability = ReliabilityPolicy.RELIABLE if reliable else ReliabilityPolicy.BEST_EFFORT
            qos = QoSProfile(depth=10, reliability=reliability)
            self.sub = self.create_subscription(Int64, TOPIC, self.on_number, qos)

    class Sender(Source):
        def __init__(self, reliable: bool) -> None:
            Node.__init__(self, "sender")
            reliability = ReliabilityPolicy.RELIABLE if reliable else ReliabilityPolicy.BEST_EFFORT
            self.pub = self.create_publisher(Int64, TOPIC, QoSProfile(depth=10, reliability=reliability))

    async with Runtime() as rt:
        either = rt.spawn(Picky, False, name="either")
        first = rt.spawn(Sender, False, name="first")
        first.send(0)
        await settle()
        strict = rt.spawn(Picky, True, name="strict")
        second = rt.spawn(Sender, True, name="second")
        second.send(1)
        first.send(2)
        second.send(3)
        await settle()
        assert either.heard == [0, 1, 2, 3]
        assert strict.heard == [1, 3]


@pytest.mark.virtual_time
async def test_queued_and_dropped_count_an_open_batch_as_if_each_message_had_been_queued():
    async with Runtime() as rt:
        shallow, deep = rt.spawn(Sink, 3, name="shallow"), rt.spawn(Sink, None, name="deep")
        source = rt.spawn(Source)
        source.send(*range(5))
        assert (shallow.sub.queued, shallow.sub.dropped) == (3, 2)
        assert (deep.sub.queued, deep.sub.dropped) == (5, 0)
        info = rt.graph.topic(f"/{TOPIC}")
        assert info is not None
        assert sorted(e.dropped for e in info.subscriptions) == [0, 2]
        await settle()
        assert (shallow.sub.queued, shallow.sub.dropped) == (0, 2)
        assert (shallow.heard, deep.heard) == ([2, 3, 4], [0, 1, 2, 3, 4])


# -- depth and drops against a model of per-message delivery --------------------------------------

OPS = st.lists(
    st.one_of(
        st.tuples(st.just("publish"), st.integers(0, 1), st.integers(1, 6)),  # publisher, how many
        st.tuples(st.just("run"), st.just(0), st.just(0)),
        st.tuples(st.just("join"), st.integers(1, 4), st.just(0)),  # a new subscription of this depth
        st.tuples(st.just("leave"), st.integers(0, 5), st.just(0)),  # destroy the n-th live one
        st.tuples(st.just("unpublish"), st.integers(0, 1), st.just(0)),  # destroy a publisher, make a new one
    ),
    max_size=30,
)


class Model:
    """Per-message delivery: each publish appends to every live queue, dropping its oldest when full."""

    def __init__(self, depth: int | None) -> None:
        self.depth = depth
        self.queue: list[int] = []
        self.heard: list[int] = []
        self.dropped = 0

    def publish(self, n: int) -> None:
        self.queue.append(n)
        if self.depth is not None and len(self.queue) > self.depth:
            self.queue.pop(0)
            self.dropped += 1

    def run(self) -> None:
        self.heard += self.queue
        self.queue = []


async def _replay(ops: list[tuple[str, int, int]]) -> None:
    async with Runtime() as rt:
        pairs = [(rt.spawn(Sink, d, name=f"s{i}"), Model(d)) for i, d in enumerate((1, 3, None))]
        sources = [rt.spawn(Source, name=f"p{i}") for i in range(2)]
        counter = 0
        for step, (op, x, y) in enumerate(ops):
            if op == "publish":
                for _ in range(y):
                    sources[x].send(counter)
                    for _, model in pairs:
                        model.publish(counter)
                    counter += 1
            elif op == "run":
                await settle()
                for _, model in pairs:
                    model.run()
            elif op == "join":
                pairs.append((rt.spawn(Sink, x, name=f"joined{step}"), Model(x)))
            elif op == "leave" and pairs:
                sink, _ = pairs.pop(x % len(pairs))
                sink.sub.destroy()
            elif op == "unpublish":
                sources[x].pub.destroy()
                sources[x] = rt.spawn(Source, name=f"p{x}_{step}")
            for sink, model in pairs:
                assert (sink.sub.queued, sink.sub.dropped) == (len(model.queue), model.dropped), (step, op)
            assert rt.topics.invariant_violations() == [], (step, op)
        await settle()
        for sink, model in pairs:
            model.run()
            assert sink.heard == model.heard
            assert sink.sub.dropped == model.dropped


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(OPS)
def test_depth_drops_and_order_equal_per_message_delivery(ops):
    asyncio.run(_replay(ops))


# -- rounds: a callback that publishes, a crash, an async callback --------------------------------


class Echo(Node):
    """Hears ``numbers`` (depth 2) and, on each number below 10, publishes it + 10 and + 20 on the same topic."""

    def __init__(self, name: str = "echo") -> None:
        super().__init__(name)
        self.heard: list[int] = []
        self.rounds: list[list[int]] = []
        self.pub = self.create_publisher(Int64, TOPIC, 10)
        self.sub = self.create_subscription(Int64, TOPIC, self.on_number, 2)

    def on_number(self, msg: Int64) -> None:
        self.heard.append(msg.data)
        if msg.data < 10:
            self.pub.publish(Int64(data=msg.data + 10))
            self.pub.publish(Int64(data=msg.data + 20))


@pytest.mark.virtual_time
async def test_a_callback_publishing_on_its_own_topic_counts_its_rounds_rest_against_the_depth():
    async with Runtime() as rt:
        echo = rt.spawn(Echo)
        other = rt.spawn(Sink, 10, name="other")  # so that the echo's publisher has two feeds
        source = rt.spawn(Source)
        source.send(0, 1)  # echo's queue: [0, 1]
        await settle()
        # Per message: 0 is read, then 10 and 20 arrive in a queue of depth 2 that still holds 1:
        # 1 is dropped unread (it would have published 11 and 21), 10 and 20 are read.
        assert echo.heard == [0, 10, 20]
        assert echo.sub.dropped == 1
        assert other.heard == [0, 1, 10, 20]
        assert echo.pub._pending is not None  # the batching publisher's path was taken


class Fragile(Node):
    """Hears ``numbers``; crashes on 3 (once per instance)."""

    heard: ClassVar[list[int]] = []

    def __init__(self) -> None:
        super().__init__("fragile")
        self.sub = self.create_subscription(Int64, TOPIC, self.on_number, 10)

    def on_number(self, msg: Int64) -> None:
        if msg.data == 3:
            raise RuntimeError("three")
        Fragile.heard.append(msg.data)


@pytest.mark.virtual_time
@pytest.mark.parametrize("turns", [None, 0, 1, 2, 3])
async def test_a_crashed_nodes_restart_keeps_what_its_round_had_not_reached_and_what_came_since(caplog, turns):
    # 3 crashes the node; 4-6, which its round had not reached, wait for the restart, and so do 7
    # and 8, sent after it (turns None: 0.5 s later) or before it, a few loop turns after the crash
    # (no backoff): the crashed node's subscription then holds them as a batch, which its successor
    # must take.
    caplog.set_level(logging.CRITICAL, logger="actors")
    Fragile.heard = []
    async with Runtime(supervisor=SupervisorPolicy(intensity=5, period=10.0, backoff=0.0)) as rt:
        rt.spawn(Fragile)
        steady = rt.spawn(Sink)
        source = rt.spawn(Source)
        source.send(*range(7))
        if turns is None:
            await anyio.sleep(0.5)
        for _ in range(turns or 0):
            await asyncio.sleep(0)
        source.send(7, 8)
        await anyio.sleep(0.5)
    assert Fragile.heard == [0, 1, 2, 4, 5, 6, 7, 8]  # 3 is the dead letter
    assert steady.heard == list(range(9))


class Slow(Node):
    """Hears ``numbers`` (depth 2 unless told) with an async callback that takes 1 s; refuses 5."""

    def __init__(self, depth: int = 2) -> None:
        super().__init__("slow")
        self.heard: list[int] = []
        self.sub = self.create_subscription(Int64, TOPIC, self.on_number, depth)

    async def on_number(self, msg: Int64) -> None:
        if msg.data == 5:
            raise MessageRefused("five")
        self.heard.append(msg.data)
        await anyio.sleep(1)


@pytest.mark.virtual_time
async def test_what_arrives_during_an_async_round_counts_against_the_depth_with_the_rounds_rest():
    async with Runtime() as rt:
        slow = rt.spawn(Slow)
        rt.spawn(Sink)
        source = rt.spawn(Source)
        source.send(0, 1)
        await anyio.sleep(0.5)  # 0 is being handled, 1 is the round's rest
        assert (slow.sub.queued, slow.sub.dropped) == (1, 0)
        source.send(2)  # [1, 2]: full
        source.send(3)  # drops 1, the round's next message
        assert (slow.sub.queued, slow.sub.dropped) == (2, 1)
        await anyio.sleep(5)
        assert slow.heard == [0, 2, 3]
        source.send(4, 5, 6)  # one batch: 4 dropped when it reaches the queue, 5 refused
        await anyio.sleep(5)
        assert slow.heard == [0, 2, 3, 6]
        assert slow.sub.dropped == 2
        assert slow.sub.refusals is not None and slow.sub.refusals.total == 1


@pytest.mark.virtual_time
async def test_lifespan_expires_messages_of_a_batch_that_waited_too_long():
    async with Runtime() as rt:
        slow = rt.spawn(Slow, 10)
        quick = rt.spawn(Sink)
        source = rt.spawn(Source, lifespan=1.2)
        source.send(0, 1, 2)  # one batch; slow reads 0 at 0, 1 at 1, 2 at 2: past its lifespan
        await anyio.sleep(0.5)
        source.send(3, 4)  # while slow's round runs: fed directly; their turn comes at 2: too late
        await anyio.sleep(1.6)
        source.send(6)  # read at once, at 2.1
        await anyio.sleep(10)
        assert quick.heard == [0, 1, 2, 3, 4, 6]
        assert slow.heard == [0, 1, 6]


@pytest.mark.virtual_time
async def test_a_tap_sees_each_message_when_it_is_published_and_the_subscriptions_keep_their_order():
    async with Runtime() as rt:
        sinks = [rt.spawn(Sink, name=f"sink{i}") for i in range(2)]
        source = rt.spawn(Source)
        tapped: list[int] = []
        taps = TapSet("/_tap", lambda name: name == f"/{TOPIC}", lambda tap, msg: tapped.append(msg.data))
        source.send(0, 1)  # a batch is open when the tap comes
        taps.start(rt)
        source.send(2)
        assert tapped == [2]  # at once, not at the next round
        source.send(3)
        assert tapped == [2, 3]
        taps.stop()
        source.send(4)
        await settle()
        assert tapped == [2, 3]
        assert [s.heard for s in sinks] == [[0, 1, 2, 3, 4]] * 2


# -- the shared batch against per-message delivery, on random graphs --------------------------------


class Varied(Node):
    """Hears ``numbers``; by ``kind``: refuses multiples of 3, crashes on 3 mod 7, awaits, or echoes."""

    def __init__(self, trace: list[tuple[Any, ...]], depth: int | None, kind: str) -> None:
        super().__init__("varied")
        self.trace, self.kind = trace, kind
        qos = QoSProfile(history=HistoryPolicy.KEEP_ALL) if depth is None else QoSProfile(depth=depth)
        self.sub = self.create_subscription(Int64, TOPIC, self.on_async if kind == "async" else self.on_number, qos)
        if kind == "echo":
            self.pub = self.create_publisher(Int64, TOPIC, 10)

    def on_number(self, msg: Int64) -> None:
        self.trace.append(("heard", self.get_name(), msg.data, asyncio.get_running_loop().time()))
        if self.kind == "refuse" and msg.data % 3 == 0:
            raise MessageRefused("a multiple of 3")
        if self.kind == "crash" and msg.data % 7 == 3:
            raise RuntimeError("3 mod 7")
        if self.kind == "echo" and msg.data < 1000:
            self.pub.publish(Int64(data=msg.data + 1000))
            self.pub.publish(Int64(data=msg.data + 2000))

    async def on_async(self, msg: Int64) -> None:
        self.on_number(msg)
        await asyncio.sleep(0.05)


GRAPH_OPS = st.lists(
    st.one_of(
        st.tuples(
            st.just("sub"),
            st.sampled_from([1, 2, 3, None]),
            st.sampled_from(["plain", "plain", "refuse", "crash", "async", "echo"]),
        ),
        st.tuples(st.just("pub"), st.sampled_from([0.0, 0.0, 0.08]), st.booleans()),  # lifespan, latched
        st.tuples(st.just("publish"), st.integers(0, 3), st.sampled_from([1, 2, 3, 5, 12])),
        st.tuples(st.just("settle"), st.integers(1, 3), st.none()),
        st.tuples(st.just("sleep"), st.sampled_from([0.01, 0.05, 0.5]), st.none()),
        st.tuples(st.just("unsub"), st.integers(0, 7), st.none()),
        st.tuples(st.just("unpub"), st.integers(0, 3), st.none()),
    ),
    max_size=40,
)


def _graph_trace(ops: list[tuple[Any, Any, Any]]) -> list[tuple[Any, ...]]:
    """What each subscription hears (and when, on the virtual clock), queued, dropped and refused after each op."""
    trace: list[tuple[Any, ...]] = []

    async def main() -> None:
        async with Runtime(supervisor=SupervisorPolicy(intensity=1000, period=10.0, backoff=0.0)) as rt:
            live = [rt.spawn(Varied, trace, 3, "plain", name=f"first{i}").sub for i in range(2)]
            pubs = [rt.spawn(Source, name="source").pub, rt.spawn(Source, name="expiring", lifespan=0.08).pub]
            for step, (op, x, y) in enumerate(ops):
                if op == "sub":
                    rt.spawn(Varied, trace, x, y, name=f"s{step}")
                elif op == "pub":
                    pubs.append(rt.spawn(Source, name=f"p{step}", lifespan=x, latched=y).pub)
                elif op == "publish" and pubs:
                    for i in range(y):
                        pubs[x % len(pubs)].publish(Int64(data=step * 100 + i))
                elif op == "settle":
                    for _ in range(x):
                        await asyncio.sleep(0)
                elif op == "sleep":
                    await asyncio.sleep(x)
                elif op == "unsub" and live:
                    live[x % len(live)].destroy()
                elif op == "unpub" and pubs:
                    pubs.pop(x % len(pubs)).destroy()
                # The topic's subscriptions: a crashed node's successor holds its subscription now.
                topic = rt.topics.topics.get(f"/{TOPIC}")
                live = [] if topic is None else list(topic.subscriptions)
                trace.append((step, [(s.node.fqn, s.queued, s.dropped, s.refusals and s.refusals.total) for s in live]))
                assert rt.topics.invariant_violations() == [], (step, op)  # the publish/deliver states agree
            await asyncio.sleep(2)

    asyncio.Runner(loop_factory=VirtualTimeLoop).run(main())
    return trace


@settings(max_examples=150, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(GRAPH_OPS)
@pytest.mark.slow
def test_fan_out_delivers_exactly_what_per_message_delivery_does(ops):
    batched = _graph_trace(ops)
    refeed = Publisher._refeed

    def per_message(pub: Publisher) -> None:
        refeed(pub)
        if isinstance(pub._pending, list):  # it would batch: it feeds each queue itself instead
            pub._pending = None if len(pub._topic.publishers) == 1 else topics._SHARED  # type: ignore[union-attr]

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(Publisher, "_refeed", per_message)
        assert _graph_trace(ops) == batched
