"""Throughput with 1, 10, 100 and 1,000 topics active at once, one publisher and one subscriber (node) each.

Run: ``python -m bench.topics_scale [--quick]``.  Messages go round-robin over
the topics, 100 between yields to the loop as in ``bench.throughput`` (one per
topic with 1,000 topics), so with 100 topics and more each mailbox wakes for a
single message: this measures how much of the batching survives when traffic
is spread thin, and whether a message costs more when more topics and nodes
exist (1,000 topics: 1,000 subscribing nodes).  Beside bare asyncio.Queues fed
the same way.
"""

from __future__ import annotations

from bench.harness import Result, side_by_side, standalone
from bench.throughput import actors_rate, queue_rate

__all__ = ["run"]

TOPICS = (1, 10, 100, 1_000)


def run(quick: bool = False) -> list[Result]:
    """Total deliveries/s at each topic count, actors beside the queues, 5 runs each, taking turns."""
    n = 20_000 if quick else 200_000
    results = []
    for topics in TOPICS:
        scenario = f"h. {topics:,} topic{'s' if topics > 1 else ''} at once"
        samples = side_by_side(
            {"actors": lambda: actors_rate(n, 1, topics), "queue": lambda: queue_rate(n, 1, topics)}, 5
        )
        results.append(
            Result(scenario, "actors", "deliveries/s", samples["actors"], baselines={"queue": "asyncio.Queue"})
        )
        results.append(Result(scenario, "asyncio.Queue", "deliveries/s", samples["queue"]))
    return results


if __name__ == "__main__":
    standalone(run, __doc__, "fewer messages")
