"""Topic throughput: talker→listener one-way and 1→10 fan-out, beside a bare asyncio.Queue.

Run: ``python -m bench.throughput [--quick]``.  Ratios are "× faster than the
baseline" (higher is better).  The floor is calling the callback directly, no
delivery at all.
"""

from __future__ import annotations

import argparse
import asyncio
import time

from actors import Node, QoSProfile, Runtime
from bench.harness import Result, repeat, table
from interfaces.std_msgs.msg import String

BATCH = 100  # messages published between yields to the loop
DEPTH = 1000  # mailbox depth: larger than a batch, so nothing is dropped


def actors_rate(n: int, subscribers: int) -> float:
    """Deliveries per second from one publisher to ``subscribers`` subscriptions."""

    class Listener(Node):
        def __init__(self) -> None:
            super().__init__("listener")
            self.count = 0
            self.create_subscription(String, "topic", self.on_msg, QoSProfile(depth=DEPTH))

        def on_msg(self, msg: String) -> None:
            self.count += 1

    class Talker(Node):
        def __init__(self) -> None:
            super().__init__("talker")
            self.pub = self.create_publisher(String, "topic", QoSProfile(depth=DEPTH))

    async def main() -> float:
        async with Runtime() as rt:
            listeners = [rt.spawn(Listener, name=f"listener{i}") for i in range(subscribers)]
            pub = rt.spawn(Talker).pub
            msg = String(data="Hello World")
            publish = pub.publish
            await asyncio.sleep(0)
            start = time.perf_counter()
            for _ in range(n // BATCH):
                for _ in range(BATCH):
                    publish(msg)
                await asyncio.sleep(0)
            while sum(node.count for node in listeners) < n * subscribers:
                await asyncio.sleep(0)
            return n * subscribers / (time.perf_counter() - start)

    return asyncio.run(main())


def queue_rate(n: int, subscribers: int) -> float:
    """The same with bare asyncio.Queues: one producer ``await put`` per message per consumer."""

    async def main() -> float:
        queues = [asyncio.Queue(maxsize=DEPTH) for _ in range(subscribers)]
        counts = [0] * subscribers

        async def consume(i: int) -> None:
            get = queues[i].get
            for _ in range(n):
                await get()
                counts[i] += 1

        msg = String(data="Hello World")
        consumers = [asyncio.ensure_future(consume(i)) for i in range(subscribers)]
        start = time.perf_counter()
        for _ in range(n):
            for q in queues:
                await q.put(msg)
        await asyncio.gather(*consumers)
        return n * subscribers / (time.perf_counter() - start)

    return asyncio.run(main())


def floor_rate(n: int, subscribers: int) -> float:
    """Calling the callback directly: the cost of the callback itself, no delivery."""
    count = 0

    def on_msg(msg: String) -> None:
        nonlocal count
        count += 1

    msg = String(data="Hello World")
    start = time.perf_counter()
    for _ in range(n):
        for _ in range(subscribers):
            on_msg(msg)
    return n * subscribers / (time.perf_counter() - start)


def run(quick: bool = False) -> list[Result]:
    """Measure one-way and fan-out throughput with the baselines, in one run."""
    n = 20_000 if quick else 200_000
    reps = 5
    results = []
    for scenario, subs in (("a. one-way", 1), ("b. fan-out 1→10", 10)):
        count = n // subs
        bases = {"queue": "asyncio.Queue", "floor": "direct call (floor)"}
        results.append(
            Result(scenario, "actors", "deliveries/s", repeat(lambda: actors_rate(count, subs), reps), baselines=bases)
        )
        results.append(Result(scenario, "asyncio.Queue", "deliveries/s", repeat(lambda: queue_rate(count, subs), reps)))
        results.append(
            Result(scenario, "direct call (floor)", "deliveries/s", repeat(lambda: floor_rate(count, subs), reps))
        )
    return results


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer messages")
    print(table(run(parser.parse_args().quick)))


if __name__ == "__main__":
    main()
