"""10,000 nodes, each with a publisher, a subscription and a 10 Hz timer: spawn, timer tick, graceful stop.

Run: ``python -m bench.scale [--quick]``.  Each run is a fresh process
(``python -m bench.scale --child N MODE``) that spawns N nodes into a running
runtime on asyncio's wall-clock loop, lets their timers tick for a few
seconds, then stops the whole graph.  ``spawn`` is wall time per node until
every node runs; ``tick`` is process CPU time per timer tick (the machine is
shared: CPU time is what one tick costs, wall time also holds other
processes' load); ``stop`` is the wall time of the graceful stop (reverse
order, hooks).  MODE ``plain`` spawns as embedding code does, with the
garbage collector as it is (``Runtime.spawn`` pauses it for the burst and ends
the burst with one full collection, counted in ``spawn``); ``frozen`` spawns
inside :func:`actors.runtime.frozen_startup`, as ``python -m actors.run``
starts a graph (collection paused, then ``gc.freeze()``).  The floor for a tick is 10,000 bare ``loop.call_at``
chains at 10 Hz on the same loop, each tick a plain function call.
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import json
import os
import time

from actors import Node, Runtime
from actors.runtime import frozen_startup
from bench.harness import Result, repeat, run_child, table
from interfaces.std_msgs.msg import String

__all__ = ["run", "Ticking"]

COUNT = 10_000
PERIOD = 0.1
REPS = 3


class Ticking(Node):
    """A publisher, a subscription and a 10 Hz timer that counts its ticks."""

    ticks = 0

    def __init__(self) -> None:
        super().__init__("ticking")
        self.create_publisher(String, "out", 10)
        self.create_subscription(String, "in", self.on_msg, 10)
        self.create_timer(PERIOD, self.on_tick)

    def on_msg(self, msg: String) -> None:
        pass

    def on_tick(self) -> None:
        Ticking.ticks += 1


def _child(count: int, mode: str, seconds: float) -> dict[str, float]:
    """Spawn, tick and stop ``count`` nodes in this process; the figures as a dict."""

    async def main() -> dict[str, float]:
        async with Runtime() as rt:
            rt.spawn(Ticking, name="warm")  # first-use costs (imports, caches) are not per node
            await asyncio.sleep(0)
            start = time.perf_counter()
            with frozen_startup() if mode == "frozen" else contextlib.nullcontext():
                for i in range(count):
                    rt.spawn(Ticking, name=f"n{i}")
            await asyncio.sleep(0)
            spawn = (time.perf_counter() - start) / count
            await asyncio.sleep(2 * PERIOD)
            Ticking.ticks, cpu = 0, time.process_time()
            await asyncio.sleep(seconds)
            tick = (time.process_time() - cpu) / max(Ticking.ticks, 1)
            start = time.perf_counter()
            await rt.supervisor.stop_all()
            stop = time.perf_counter() - start
        return {"spawn": spawn * 1e6, "tick": tick * 1e6, "stop": stop}

    return asyncio.run(main())


def _floor(count: int, seconds: float) -> dict[str, float]:
    """CPU per tick of ``count`` bare loop.call_at chains at 10 Hz, on absolute deadlines."""
    ticks = 0

    async def main() -> float:
        loop = asyncio.get_running_loop()

        def tick(start: float, k: int) -> None:
            nonlocal ticks
            ticks += 1
            k = max(k + 1, int((loop.time() - start) / PERIOD) + 1)
            loop.call_at(start + k * PERIOD, tick, start, k)

        for _ in range(count):
            start = loop.time()
            loop.call_at(start + PERIOD, tick, start, 1)
        await asyncio.sleep(2 * PERIOD)
        nonlocal ticks
        ticks, cpu = 0, time.process_time()
        await asyncio.sleep(seconds)
        return (time.process_time() - cpu) / max(ticks, 1) * 1e6

    return {"tick": asyncio.run(main())}


def run(quick: bool = False) -> list[Result]:
    """Spawn, tick and stop figures for 10,000 nodes (1,000 with --quick), each run a fresh process."""
    count = 1_000 if quick else COUNT
    seconds = "1" if quick else "3"
    runs = {
        mode: repeat(lambda: run_child(["-m", "bench.scale", "--child", str(count), mode, seconds]), REPS, warmup=False)
        for mode in ("plain", "frozen", "floor")
    }
    nodes = f"{count:,} nodes"
    cases = {"plain": "actors", "frozen": "actors, frozen_startup"}
    results = []
    for what, unit, scenario in (
        ("spawn", "µs/node", f"j. spawn, {nodes}"),
        ("tick", "µs CPU/tick", f"j. 10 Hz timer tick, {nodes}"),
        ("stop", "s", f"j. graceful stop, {nodes}"),
    ):
        for mode, case in cases.items():
            bases = {"floor": "loop.call_at (floor)"} if what == "tick" else {}
            results.append(Result(scenario, case, unit, [r[what] for r in runs[mode]], False, baselines=bases))
        if what == "tick":
            results.append(Result(scenario, "loop.call_at (floor)", unit, [r[what] for r in runs["floor"]], False))
    return results


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="1,000 nodes, 1 s of ticks")
    parser.add_argument(
        "--child", nargs=3, metavar=("N", "MODE", "SECONDS"), help="measure in this process, print JSON"
    )
    args = parser.parse_args()
    if args.child:
        count, mode, seconds = int(args.child[0]), args.child[1], float(args.child[2])
        figures = _floor(count, seconds) if mode == "floor" else _child(count, mode, seconds)
        print(json.dumps(figures), flush=True)
        os._exit(0)  # the measured part is over: no teardown of the interpreter's heap
    print(table(run(args.quick)))


if __name__ == "__main__":
    main()
