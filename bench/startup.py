"""Start-up: a graph file to its first delivered message, and spawning 100 and 1,000 nodes.

Run: ``python -m bench.startup [--quick]``.  "First message" is wall time from
starting ``python -m actors.run GRAPH`` to the listener's first ``I heard``
line on its output, as a user sees it: interpreter, imports, the graph's
nodes, and the talker's first tick, which comes one 0.5 s period after it
starts (as in ROS).  The row "less the first period" takes that 0.5 s out: it
is the start-up cost itself, which the 0.5 s target is about.  rclpy runs the
same talker and listener (``bench.ros``); ``python -c`` printing the line is
the floor.  Spawning is timed in-process, from the first ``spawn`` until every
node's task has started.
"""

from __future__ import annotations

import asyncio
import time

from actors import Runtime
from bench import ros
from bench.harness import Result, repeat, standalone, time_to_line
from bench.memory import IdleNode, rclpy_nodes, ros_executors, ros_note

__all__ = ["run", "first_message", "spawn_time"]

MARKER = "I heard"
TALKER_PERIOD = 0.5  # nodes.talker's timer: its first message comes one period after it starts


def first_message(graph: str) -> float:
    """Seconds from starting ``python -m actors.run GRAPH`` to the first ``I heard`` line."""
    return time_to_line(["-m", "actors.run", graph], MARKER)


def spawn_time(count: int) -> float:
    """Seconds to spawn ``count`` idle nodes until each node's task has started."""

    async def main() -> float:
        async with Runtime() as rt:
            start = time.perf_counter()
            for i in range(count):
                rt.spawn(IdleNode, name=f"idle{i}")
            # Tasks start in FIFO order: when this sleep returns, every node's task has run.
            await asyncio.sleep(0)
            return time.perf_counter() - start

    return asyncio.run(main())


def run(quick: bool = False) -> list[Result]:
    """First-message and spawn times, 5 runs each, with rclpy and the interpreter floor."""
    reps = 5
    demo = "e. first message, graph.toml"
    pubsub = "e. first message, talker→listener"
    # Each sample starts a fresh process: nothing in-process to warm up.
    demo_samples = repeat(lambda: first_message("graph.toml"), reps, warmup=False)
    results = [
        Result(demo, "actors", "s", demo_samples, False, note="includes the talker's first 0.5 s period"),
        Result(demo, "actors, less the first period", "s", [s - TALKER_PERIOD for s in demo_samples], False),
        Result(
            pubsub,
            "actors",
            "s",
            repeat(lambda: first_message("graphs/pubsub.toml"), reps, warmup=False),
            False,
            baselines={"python": "python -c (floor)", **ros.baselines()},
        ),
        Result(
            pubsub,
            "python -c (floor)",
            "s",
            repeat(lambda: time_to_line(["-c", f"print('{MARKER}')"], MARKER), reps, warmup=False),
            False,
        ),
    ]
    results += ros.first_message(pubsub, reps)
    for count in (100, 1_000):
        scenario = f"e. spawn {count:,} nodes"
        executors = ros_executors(count, quick)
        results.append(
            Result(
                scenario,
                "actors",
                "s",
                repeat(lambda: spawn_time(count), reps),
                False,
                note=ros_note(count, quick),
                baselines=ros.baselines(executors),
            )
        )
        results += rclpy_nodes(scenario, count, executors, "spawn", "s")
    return results


if __name__ == "__main__":
    standalone(run, __doc__, "rclpy at 100 nodes only")
