"""A 1 kHz timer on the wall clock: tick lateness p50/p99 and CPU time, beside a bare asyncio timer.

Run: ``python -m bench.timer [--quick]``.  Lateness is how long after its
deadline each tick's callback starts, read from the loop clock (the clock the
deadlines are on).  CPU is ``time.process_time()`` over the run as a share of
one core.  The baseline is the loop itself: ``loop.call_at`` chained on the
same absolute deadlines, with no runtime around it.  On an idle machine the
target is p99 <= 1 ms; this machine is shared, so read p99 with its min–max.
"""

from __future__ import annotations

import argparse
import asyncio
import statistics
import time

from actors import Node, Runtime
from bench.harness import Result, repeat, table

__all__ = ["run", "actors_ticks", "loop_ticks"]

PERIOD = 0.001
Sample = tuple[float, float, float]  # p50 and p99 lateness in µs, CPU in % of a core


def _summary(lateness: list[float], cpu: float, wall: float) -> Sample:
    cuts = statistics.quantiles(lateness, n=100)
    return cuts[49] * 1e6, cuts[98] * 1e6, cpu / wall * 100


def actors_ticks(seconds: float) -> Sample:
    """A node with a 1 kHz timer for ``seconds``: lateness of each tick from its deadline."""
    lateness: list[float] = []

    class Ticker(Node):
        def __init__(self) -> None:
            super().__init__("ticker")
            self.timer = self.create_timer(PERIOD, self.on_tick)

        def on_tick(self) -> None:
            # During the callback, next_deadline is this tick's deadline (advanced after it returns).
            lateness.append(self.get_clock().monotonic() - self.timer.next_deadline)

    async def main() -> Sample:
        async with Runtime(control=False) as rt:
            cpu, wall = time.process_time(), time.perf_counter()
            rt.spawn(Ticker)
            await asyncio.sleep(seconds)
            return _summary(lateness, time.process_time() - cpu, time.perf_counter() - wall)

    return asyncio.run(main())


def loop_ticks(seconds: float) -> Sample:
    """The floor: ``loop.call_at`` on absolute deadlines, skipping missed ones as actors' timers do."""
    lateness: list[float] = []

    async def main() -> Sample:
        loop = asyncio.get_running_loop()
        start = loop.time()
        k = 1

        def tick() -> None:
            nonlocal k
            lateness.append(loop.time() - (start + k * PERIOD))
            k = max(k + 1, int((loop.time() - start) / PERIOD) + 1)
            loop.call_at(start + k * PERIOD, tick)

        cpu, wall = time.process_time(), time.perf_counter()
        loop.call_at(start + PERIOD, tick)
        await asyncio.sleep(seconds)
        return _summary(lateness, time.process_time() - cpu, time.perf_counter() - wall)

    return asyncio.run(main())


def run(quick: bool = False) -> list[Result]:
    """Lateness p50/p99 and CPU for actors and the bare loop, 5 runs each."""
    seconds = 0.5 if quick else 5.0
    cases = {"actors": actors_ticks, "asyncio call_at (floor)": loop_ticks}
    samples = {case: repeat(lambda: fn(seconds), 5) for case, fn in cases.items()}
    results = []
    for i, (what, unit) in enumerate((("p50", "µs late"), ("p99", "µs late"), ("CPU", "% of a core"))):
        for case, runs in samples.items():
            floor = {"floor": "asyncio call_at (floor)"} if case == "actors" else {}
            results.append(Result(f"d. timer 1 kHz {what}", case, unit, [r[i] for r in runs], False, baselines=floor))
    return results

def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="0.5 s per run instead of 5 s")
    print(table(run(parser.parse_args().quick)))


if __name__ == "__main__":
    main()
