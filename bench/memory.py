"""Memory: resident set size per idle node (1 publisher, 1 subscription, 1 timer) at 100 to 10,000 nodes.

Run: ``python -m bench.memory [--quick]``.  Each count runs in a fresh process
(``python -m bench.memory --child N``): RSS is read from /proc before and after
spawning N nodes into a running runtime, and the difference is divided by N.
The same per-node figure at every count is what "linear" means.  rclpy's
nodes are measured the same way (see ``bench.ros``); 10,000 of them are not
attempted, as 1,000 already take about 90 s to create.
"""

from __future__ import annotations

import argparse
import asyncio
import gc
import json
import os

from actors import Node, Runtime
from bench import ros
from bench.harness import Result, repeat, run_child, table
from interfaces.std_msgs.msg import String

__all__ = ["IdleNode", "run", "rss", "ros_executors", "ros_note", "rclpy_nodes"]

COUNTS = (100, 1_000, 10_000)
REPS = 5


class IdleNode(Node):
    """An idle node: one publisher, one subscription and one timer, as in the issue."""

    def __init__(self) -> None:
        super().__init__("idle")
        self.create_publisher(String, "out", 10)
        self.create_subscription(String, "in", self.on_msg, 10)
        self.create_timer(1.0, self.on_tick)

    def on_msg(self, msg: String) -> None:
        pass

    def on_tick(self) -> None:
        pass


def rss() -> int:
    """This process's resident set size in bytes, from /proc."""
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def _child(count: int) -> None:
    """Print the bytes of RSS per node after spawning ``count`` idle nodes, then end the process.

    Run in a fresh process.  It ends without stopping the nodes: the graph's
    teardown is not what is measured, and 10,000 nodes take seconds to stop.
    """

    async def main() -> None:
        async with Runtime() as rt:
            rt.spawn(IdleNode, name="warm")  # first-use costs (imports, caches) are not per node
            await asyncio.sleep(0.01)
            gc.collect()
            before = rss()
            for i in range(count):
                rt.spawn(IdleNode, name=f"idle{i}")
            await asyncio.sleep(0.01)  # every node's task started and parked
            gc.collect()
            print(json.dumps((rss() - before) / count), flush=True)
            os._exit(0)

    asyncio.run(main())


def ros_executors(count: int, quick: bool) -> tuple[str, ...]:
    """The rclpy executors measured with ``count`` nodes: both at 100; at 1,000 only
    SingleThreaded and only in a full run (a node's creation and memory are rcl's and
    DDS's, before any executor runs, and 1,000 nodes take about 90 s a run)."""
    if count <= 100:
        return tuple(ros.EXECUTORS)
    return () if quick or count > 1_000 else ("single",)


def ros_note(count: int, quick: bool) -> str:
    """Why rclpy has no row at ``count`` nodes, if it has none."""
    if count > 1_000:
        return "rclpy: not attempted (1,000 nodes already take about 90 s)"
    return "rclpy: not run with --quick (about 90 s a run)" if not ros_executors(count, quick) else ""


def rclpy_nodes(
    scenario: str, count: int, executors: tuple[str, ...], key: str, unit: str, scale: float = 1.0
) -> list[Result]:
    """Rows for ``count`` rclpy nodes: ``key`` of each run (``spawn`` or ``rss_per_node``) times ``scale``."""
    results = []
    for executor in executors:
        runs = ros.nodes(count, executor, REPS)
        if isinstance(runs, str):
            return [Result(scenario, "rclpy", unit, [], False, note=runs)]
        results.append(Result(scenario, ros.EXECUTORS[executor], unit, [r[key] * scale for r in runs], False))
    return results


def run(quick: bool = False) -> list[Result]:
    """RSS per idle node at each count, each run in a fresh process, with rclpy where it runs."""
    results = []
    for count in COUNTS:
        scenario = f"f. memory, {count:,} nodes"
        samples = repeat(lambda: run_child(["-m", "bench.memory", "--child", str(count)]) / 1024, REPS, warmup=False)
        executors = ros_executors(count, quick)
        results.append(
            Result(
                scenario,
                "actors",
                "KiB/node",
                samples,
                False,
                note=ros_note(count, quick),
                baselines=ros.baselines(executors),
            )
        )
        results += rclpy_nodes(scenario, count, executors, "rss_per_node", "KiB/node", 1 / 1024)
    return results


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="rclpy at 100 nodes only")
    parser.add_argument("--child", type=int, metavar="N", help="measure N nodes in this process, print JSON")
    args = parser.parse_args()
    if args.child:
        _child(args.child)
    else:
        print(table(run(args.quick)))


if __name__ == "__main__":
    main()
