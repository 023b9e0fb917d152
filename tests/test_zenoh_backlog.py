"""Samples wait for the loop in a backlog of the topic's depth: a peer faster than the loop pushes out the oldest.

What it pushes out is counted in the subscriptions' dropped and logged.
"""

from __future__ import annotations

from types import SimpleNamespace
from typing import Any

from actors import Node, QoSProfile, Runtime
from actors.ros.qos import HistoryPolicy
from actors.transport import Hub, Inlet
from actors.transport.zenoh.peer_warnings import PeerWarnings
from actors.transport.zenoh.topics import KEEP_ALL_BACKLOG, TopicBridge, _Backlog, _In
from interfaces.std_msgs.msg import Int64


class Handoff:
    def __init__(self) -> None:
        self.items: list[tuple[Any, Any]] = []

    def put(self, function: Any, argument: Any) -> None:
        self.items.append((function, argument))

    def run(self) -> None:
        items, self.items = self.items, []
        for function, argument in items:
            function(argument)


class Link:
    def __init__(self) -> None:
        self.handoff = Handoff()
        self.lines: list[str] = []
        self.warnings = PeerWarnings(self.lines.append)


def bridge_and_deliveries(table: Any = None) -> tuple[TopicBridge, Handoff, list[Any]]:
    link = Link()
    bridge = TopicBridge(link, table=table or SimpleNamespace(topics={}))  # type: ignore[arg-type]
    delivered: list[Any] = []
    bridge._deliver = lambda incoming, sample: delivered.append(sample)  # type: ignore[method-assign]
    return bridge, link.handoff, delivered


def test_a_burst_while_the_loop_is_busy_leaves_the_newest_depth_samples_and_one_drain():
    bridge, handoff, delivered = bridge_and_deliveries()
    incoming, backlog = _In("0/chatter", inlet=SimpleNamespace(topic_name="/chatter")), _Backlog(10)  # type: ignore[arg-type]
    bridge._ins["/chatter"] = incoming
    for sample in range(20_000):  # zenoh's thread, while the loop does not run
        bridge._arrived(backlog, incoming, sample)
    assert len(backlog.samples) == 10 and len(handoff.items) == 1
    handoff.run()
    assert delivered == list(range(19_990, 20_000)) and backlog.lost == 19_990
    bridge._arrived(backlog, incoming, "after")  # a drain went by: the next sample schedules another
    handoff.run()
    assert delivered[-1] == "after"


def test_a_sample_arriving_during_a_drain_is_delivered_by_the_next():
    bridge, handoff, delivered = bridge_and_deliveries()
    incoming, backlog = _In("0/chatter", inlet=None), _Backlog(10)  # type: ignore[arg-type]
    bridge._arrived(backlog, incoming, 1)
    # The drain has begun (its flag is down) when zenoh's thread appends one more.
    ((function, argument),) = handoff.items
    handoff.items.clear()
    backlog.scheduled = False
    bridge._arrived(backlog, incoming, 2)
    function(argument)
    handoff.run()
    assert delivered == [1, 2]


class Listener(Node):
    def __init__(self) -> None:
        super().__init__("listener", start_parameter_services=False)
        keep_all = QoSProfile(history=HistoryPolicy.KEEP_ALL, depth=1)
        self.sub = self.create_subscription(Int64, "ping", lambda msg: None, keep_all)


async def test_samples_pushed_out_of_a_full_backlog_are_counted_in_dropped_and_logged_once_per_topic():
    async with Runtime() as rt:
        node = rt.spawn(Listener)
        inlet = Inlet(Hub("/_zenoh", rt.loop, rt.logger), "/ping", Int64)
        rt.topics.add_publisher(inlet)
        bridge, handoff, delivered = bridge_and_deliveries(rt.topics)
        incoming = bridge._ins["/ping"] = _In("0/ping", inlet)
        backlog = _Backlog(KEEP_ALL_BACKLOG)
        for sample in range(KEEP_ALL_BACKLOG + 25):  # zenoh's thread, while the loop does not run
            bridge._arrived(backlog, incoming, sample)
        assert node.sub.dropped == 0  # counted on the loop, by the drain
        handoff.run()
        assert delivered == list(range(25, KEEP_ALL_BACKLOG + 25))
        assert node.sub.dropped == 25
        # The loop falls behind again: counted again, but the line is not repeated within the window.
        for sample in range(KEEP_ALL_BACKLOG + 5):
            bridge._arrived(backlog, incoming, sample)
        handoff.run()
        assert node.sub.dropped == 30
        lines = bridge._link.lines  # type: ignore[attr-defined]
        assert len(lines) == 1 and "dropped 25 sample(s) on /ping" in lines[0] and "KEEP_ALL_BACKLOG" in lines[0]
        assert bridge._link.warnings.left_out == 1  # type: ignore[attr-defined]


def test_a_drain_that_keeps_up_counts_nothing():
    bridge, handoff, delivered = bridge_and_deliveries()
    incoming, backlog = _In("0/chatter", inlet=SimpleNamespace(topic_name="/chatter")), _Backlog(10)  # type: ignore[arg-type]
    bridge._ins["/chatter"] = incoming
    for _ in range(3):
        for sample in range(10):  # as many as may wait
            bridge._arrived(backlog, incoming, sample)
        handoff.run()
    assert len(delivered) == 30 and backlog.lost == 0 and bridge._link.lines == []  # type: ignore[attr-defined]
