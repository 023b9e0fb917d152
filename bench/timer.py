"""A 1 kHz timer on the wall clock: tick lateness p50/p99 and CPU time, beside a bare asyncio timer.

Run: ``python -m bench.timer [--quick]``.  Lateness is how long after its
deadline each tick's callback starts, read from the loop clock (the clock the
deadlines are on).  CPU is ``time.process_time()`` over the run as a share of
one core.  The floor is the loop itself: ``loop.call_at`` chained on the same
absolute deadlines, with no runtime around it.

Each runs on two loops.  asyncio's default loop on Linux waits in
``epoll_wait``, whose timeout is whole milliseconds, rounded up: every wait
for a deadline less than 1 ms away oversleeps to the next millisecond, so
lateness spreads over 0–1 ms whatever runs on the loop.  A loop on
``selectors.SelectSelector`` waits in ``select()``, which takes microseconds.
On an idle machine the target is p99 <= 1 ms; this machine is shared, so read
p99 with its min–max.
"""

from __future__ import annotations

import asyncio
import selectors
import statistics
import time
from collections.abc import Callable, Coroutine
from typing import Any

from actors import Node, Runtime
from bench.harness import Result, repeat, standalone

__all__ = ["run", "actors_ticks", "loop_ticks", "LOOPS"]

PERIOD = 0.001
Sample = tuple[float, float, float, float]  # p50, p99 lateness in µs; CPU, ticks skipped in %
LOOPS: dict[str, type[selectors.BaseSelector]] = {
    "": selectors.DefaultSelector,  # epoll on Linux: asyncio's default
    ", select() loop": selectors.SelectSelector,
}


def _on_loop(selector: type[selectors.BaseSelector], main: Callable[[], Coroutine[Any, Any, Sample]]) -> Sample:
    with asyncio.Runner(loop_factory=lambda: asyncio.SelectorEventLoop(selector())) as runner:
        return runner.run(main())


def _summary(lateness: list[float], cpu: float, wall: float) -> Sample:
    cuts = statistics.quantiles(lateness, n=100)
    # A tick later than a whole period makes the next deadline pass: it is skipped, not fired late.
    skipped = max(0.0, 1 - len(lateness) * PERIOD / wall)
    return cuts[49] * 1e6, cuts[98] * 1e6, cpu / wall * 100, skipped * 100


def actors_ticks(seconds: float, selector: type[selectors.BaseSelector] = selectors.DefaultSelector) -> Sample:
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
        async with Runtime() as rt:
            cpu, wall = time.process_time(), time.perf_counter()
            rt.spawn(Ticker)
            await asyncio.sleep(seconds)
            return _summary(lateness, time.process_time() - cpu, time.perf_counter() - wall)

    return _on_loop(selector, main)


def loop_ticks(seconds: float, selector: type[selectors.BaseSelector] = selectors.DefaultSelector) -> Sample:
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

    return _on_loop(selector, main)


def run(quick: bool = False) -> list[Result]:
    """Lateness p50/p99 and CPU for actors and the bare loop, on both loops, 5 runs each."""
    seconds = 0.5 if quick else 5.0
    samples: dict[str, list[Sample]] = {}
    for suffix, selector in LOOPS.items():
        samples[f"actors{suffix}"] = repeat(lambda: actors_ticks(seconds, selector), 5)
        samples[f"asyncio call_at{suffix} (floor)"] = repeat(lambda: loop_ticks(seconds, selector), 5)
    results = []
    metrics = (("p50", "µs late"), ("p99", "µs late"), ("CPU", "% of a core"), ("skipped", "% of ticks"))
    for i, (what, unit) in enumerate(metrics):
        for case, runs in samples.items():
            floor = (
                {"floor": case.replace("actors", "asyncio call_at") + " (floor)"} if case.startswith("actors") else {}
            )
            results.append(Result(f"d. timer 1 kHz {what}", case, unit, [r[i] for r in runs], False, baselines=floor))
    return results


if __name__ == "__main__":
    standalone(run, __doc__, "0.5 s per run instead of 5 s")
