"""Topic throughput: talker→listener one-way and 1→10 fan-out, beside a bare asyncio.Queue and rclpy.

Run: ``python -m bench.throughput [--quick]``.  Ratios are "× faster than the
baseline" (higher is better).  The floor is calling the callback directly, no
delivery at all.  ``actors_rate`` and ``queue_rate`` also spread the messages
over several topics, for ``bench.topics_scale``, and run on another event
loop when given one (uvloop, for the ``fast`` extra's rows).
"""

from __future__ import annotations

import asyncio
import time
from collections.abc import Callable, Sequence
from typing import Any

from actors import Node, QoSProfile, Runtime
from bench import ros
from bench.harness import UVLOOP_HINT, Loop, Result, run_on, side_by_side, standalone, uvloop_factory
from interfaces.std_msgs.msg import String

BATCH = 100  # messages published between yields to the loop
DEPTH = 1000  # mailbox depth: larger than a batch, so nothing is dropped


class Listener(Node):
    """Counts what its subscriptions deliver."""

    def __init__(self) -> None:
        super().__init__("listener")
        self.count = 0

    def on_msg(self, msg: String) -> None:
        self.count += 1


class Talker(Node):
    """Owns the publishers."""

    def __init__(self) -> None:
        super().__init__("talker")


def _batch(topics: int) -> int:
    # Messages between yields: 100, or one per topic when there are more topics than that.
    batch = max(BATCH, topics)
    if batch % topics:
        raise ValueError(f"{topics} topics do not divide a batch of {batch}")
    return batch


def actors_rate(
    n: int, subscribers: int, topics: int = 1, loop: Loop | None = None, attach: Sequence[Any] = ()
) -> float:
    """Deliveries per second: ``n`` messages published round-robin over ``topics`` topics,
    each topic with one publisher and ``subscribers`` subscriptions (each in its own node).

    ``n`` is rounded down to whole batches (100 messages, or one per topic when
    there are more); ``topics`` must divide the batch.  ``loop`` makes the
    event loop (asyncio's by default); ``attach`` runs beside the graph (a
    recorder, for ``bench.recording``).
    """
    batch_size = _batch(topics)
    n = n // batch_size * batch_size

    async def main() -> float:
        async with Runtime(attach=attach) as rt:
            listeners = []
            for t in range(topics):
                for i in range(subscribers):
                    node = rt.spawn(Listener, name=f"listener{t}_{i}")
                    node.create_subscription(String, f"topic{t}", node.on_msg, QoSProfile(depth=DEPTH))
                    listeners.append(node)
            talker = rt.spawn(Talker)
            pubs = [talker.create_publisher(String, f"topic{t}", QoSProfile(depth=DEPTH)) for t in range(topics)]
            batch = [pubs[i % topics].publish for i in range(batch_size)]
            msg = String(data="Hello World")
            await asyncio.sleep(0)
            start = time.perf_counter()
            for _ in range(n // batch_size):
                for publish in batch:
                    publish(msg)
                await asyncio.sleep(0)
            while sum(node.count for node in listeners) < n * subscribers:
                await asyncio.sleep(0)
            return n * subscribers / (time.perf_counter() - start)

    return run_on(main, loop)


def queue_rate(n: int, subscribers: int, topics: int = 1, loop: Loop | None = None) -> float:
    """The same with bare asyncio.Queues: one producer ``await put`` per message per consumer."""
    batch_size = _batch(topics)
    n = n // batch_size * batch_size

    async def main() -> float:
        queues = [[asyncio.Queue(maxsize=DEPTH) for _ in range(subscribers)] for _ in range(topics)]
        per_topic = n // topics
        count = 0

        async def consume(queue: asyncio.Queue) -> None:
            nonlocal count
            get = queue.get
            for _ in range(per_topic):
                await get()
                count += 1

        msg = String(data="Hello World")
        consumers = [asyncio.ensure_future(consume(q)) for group in queues for q in group]
        batch = [queues[i % topics] for i in range(batch_size)]
        start = time.perf_counter()
        for _ in range(n // batch_size):
            for group in batch:
                for q in group:
                    await q.put(msg)
            await asyncio.sleep(0)  # yield between batches, as the actors publisher does
        await asyncio.gather(*consumers)
        return n * subscribers / (time.perf_counter() - start)

    return run_on(main, loop)


def floor_rate(n: int, subscribers: int, timer: Callable[[], float] = time.perf_counter) -> float:
    """Deliveries per second when each of ``subscribers`` listener nodes' callback is called directly:
    the callbacks' own cost, no delivery (timed by ``timer``)."""

    async def main() -> float:
        async with Runtime() as rt:
            listeners = [rt.spawn(Listener, name=f"listener{i}") for i in range(subscribers)]
            return call_rate([node.on_msg for node in listeners], n, timer)

    return asyncio.run(main())


def call_rate(callbacks: Sequence[Callable[[String], None]], n: int, timer: Callable[[], float]) -> float:
    """Calls per second of each of ``callbacks`` with each of ``n`` messages, in publish order.

    The floor of a and b: the very callbacks the subscriptions call, called
    directly.  A lone callback is called with no loop around it: an iterator
    made per message would double the cost of the one-way floor.
    """
    msg = String(data="Hello World")
    callbacks = tuple(callbacks)
    start = timer()
    if len(callbacks) == 1:
        (callback,) = callbacks
        for _ in range(n):
            callback(msg)
    else:
        for _ in range(n):
            for callback in callbacks:
                callback(msg)
    return n * len(callbacks) / (timer() - start)


def run(quick: bool = False, *, fan_out: tuple[int, ...] = (1, 10)) -> list[Result]:
    """Measure one-way (fan-out 1) and 1→N fan-out throughput with every baseline, in one run."""
    n = 10_000 if quick else 100_000
    reps = 5
    results = []
    for subs in fan_out:
        scenario = "a. one-way" if subs == 1 else f"b. fan-out 1→{subs}"
        count = n // subs
        bases = {"queue": "asyncio.Queue", "floor": "direct call (floor)", **ros.baselines()}
        samples = side_by_side(
            {
                "actors": lambda: actors_rate(count, subs),
                "asyncio.Queue": lambda: queue_rate(count, subs),
                "direct call (floor)": lambda: floor_rate(count, subs),
            },
            reps,
        )
        results += [
            Result(scenario, case, "deliveries/s", values, baselines=bases if case == "actors" else {})
            for case, values in samples.items()
        ]
        results += ros.measured(scenario, "one_way", "deliveries/s", reps, n=count, subscribers=subs)
        if subs == 1:
            results += on_uvloop(scenario, count, reps)
    return results


def on_uvloop(scenario: str, count: int, reps: int) -> list[Result]:
    """One-way on uvloop (the ``fast`` extra), actors beside the bare queue on the same loop."""
    loop = uvloop_factory()
    if loop is None:
        return [Result(scenario, "actors, uvloop", "deliveries/s", [], note=UVLOOP_HINT)]
    samples = side_by_side(
        {"actors": lambda: actors_rate(count, 1, loop=loop), "queue": lambda: queue_rate(count, 1, loop=loop)}, reps
    )
    return [
        Result(
            scenario,
            "actors, uvloop",
            "deliveries/s",
            samples["actors"],
            baselines={"asyncio's loop": "actors", "queue": "asyncio.Queue, uvloop"},
        ),
        Result(scenario, "asyncio.Queue, uvloop", "deliveries/s", samples["queue"]),
    ]


if __name__ == "__main__":
    standalone(run, __doc__, "fewer messages")
