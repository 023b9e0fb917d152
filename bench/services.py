"""Service round trip (std_srvs/SetBool), sequential and with 100 concurrent callers.

Beside the same request/response through a bare future and an asyncio.Queue
(what a hand-written actor does), the floor (calling the handler directly) and
rclpy when it is installed (see ``bench.ros``).
Run: ``python -m bench.services [--quick]``.  Ratios are "× faster than the
baseline" (higher is better; 0.5× means twice the baseline's time).
"""

from __future__ import annotations

import asyncio
import functools
import time
from collections.abc import Callable

from actors import Node, Runtime
from bench import ros
from bench.harness import UVLOOP_HINT, Loop, Result, run_on, side_by_side, standalone, uvloop_factory
from interfaces.std_srvs.srv import SetBool

CONCURRENT = 100
TIMEOUT = 5.0  # seconds: never reached, so the rows measure what a bounded wait costs


def handle(request: SetBool.Request, response: SetBool.Response) -> SetBool.Response:
    """The server's handler, the same for every case (and for rclpy's messages)."""
    response.success = request.data
    return response


def actors_call_time(n: int, callers: int, timeout: float | None = None, loop: Loop | None = None) -> float:
    """Microseconds per completed call through actors (server and clients in one runtime),
    each call with ``timeout`` seconds when given (how the README and careful users call),
    on the event loop ``loop`` makes (asyncio's by default)."""

    class Server(Node):
        def __init__(self) -> None:
            super().__init__("server")
            self.create_service(SetBool, "set_bool", handle)

    class Caller(Node):
        def __init__(self) -> None:
            super().__init__("caller")
            self.cli = self.create_client(SetBool, "set_bool")

    async def main() -> float:
        async with Runtime() as rt:
            rt.spawn(Server)
            cli = rt.spawn(Caller).cli
            request = SetBool.Request(data=True)

            async def one_caller() -> None:
                call = cli.call
                for _ in range(n // callers):
                    await call(request, timeout)

            start = time.perf_counter()
            await asyncio.gather(*(one_caller() for _ in range(callers)))
            return (time.perf_counter() - start) / n * 1e6

    return run_on(main, loop)


def future_call_time(n: int, callers: int, loop: Loop | None = None) -> float:
    """Microseconds per call with a bare asyncio.Queue of (request, future) and one server task."""

    async def main() -> float:
        running = asyncio.get_running_loop()
        queue: asyncio.Queue = asyncio.Queue()

        async def server() -> None:
            while True:
                request, future = await queue.get()
                future.set_result(handle(request, SetBool.Response()))

        async def one_caller() -> None:
            request = SetBool.Request(data=True)
            for _ in range(n // callers):
                future = running.create_future()
                queue.put_nowait((request, future))
                await future

        task = asyncio.ensure_future(server())
        start = time.perf_counter()
        await asyncio.gather(*(one_caller() for _ in range(callers)))
        elapsed = time.perf_counter() - start
        task.cancel()
        return elapsed / n * 1e6

    return run_on(main, loop)


def floor_call_time(n: int, callers: int) -> float:
    """Microseconds per call when the handler is called directly."""
    request = SetBool.Request(data=True)
    start = time.perf_counter()
    for _ in range(n):
        handle(request, SetBool.Response())
    return (time.perf_counter() - start) / n * 1e6


def run(quick: bool = False) -> list[Result]:
    """Measure sequential and concurrent round trips with their baselines, in one run."""
    n = 2_000 if quick else 20_000
    reps = 5
    results = []
    for scenario, callers in (("c. service sequential", 1), (f"c. service {CONCURRENT} callers", CONCURRENT)):
        bases = {"future": "future+Queue", "floor": "direct call (floor)", **ros.baselines()}
        cases: list[tuple[str, Callable[[int, int], float] | None, dict[str, str]]] = [
            ("actors", actors_call_time, bases),
            (f"actors, timeout={TIMEOUT:g}", functools.partial(actors_call_time, timeout=TIMEOUT), bases),
            ("future+Queue", future_call_time, {}),
            ("direct call (floor)", floor_call_time, {}),
        ]
        uvloop = uvloop_factory()
        cases += [
            (
                "actors, uvloop",
                uvloop and functools.partial(actors_call_time, loop=uvloop),
                {"asyncio's loop": "actors", "future": "future+Queue, uvloop"},
            ),
            ("future+Queue, uvloop", uvloop and functools.partial(future_call_time, loop=uvloop), {}),
        ]
        measured = side_by_side(
            {case: functools.partial(fn, n, callers) for case, fn, _ in cases if fn is not None}, reps
        )
        for case, fn, baselines in cases:
            if fn is None:
                results.append(Result(scenario, case, "µs/call", [], higher_better=False, note=UVLOOP_HINT))
                continue
            results.append(Result(scenario, case, "µs/call", measured[case], higher_better=False, baselines=baselines))
        results += ros.measured(scenario, "service", "µs/call", reps, higher_better=False, n=n, callers=callers)
    return results


if __name__ == "__main__":
    standalone(run, __doc__, "fewer calls")
