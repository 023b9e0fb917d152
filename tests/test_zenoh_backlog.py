"""Samples wait for the loop in a backlog of the topic's depth: a peer faster than the loop pushes out the oldest."""

from __future__ import annotations

from typing import Any

from actors.transport.zenoh.topics import TopicBridge, _Backlog, _In


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


def bridge_and_deliveries() -> tuple[TopicBridge, Handoff, list[Any]]:
    link = Link()
    bridge = TopicBridge(link, table=None)  # type: ignore[arg-type]
    delivered: list[Any] = []
    bridge._deliver = lambda incoming, sample: delivered.append(sample)  # type: ignore[method-assign]
    return bridge, link.handoff, delivered


def test_a_burst_while_the_loop_is_busy_leaves_the_newest_depth_samples_and_one_drain():
    bridge, handoff, delivered = bridge_and_deliveries()
    incoming, backlog = _In("0/chatter", inlet=None), _Backlog(10)  # type: ignore[arg-type]
    for sample in range(20_000):  # zenoh's thread, while the loop does not run
        bridge._arrived(backlog, incoming, sample)
    assert len(backlog.samples) == 10 and len(handoff.items) == 1
    handoff.run()
    assert delivered == list(range(19_990, 20_000))
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
