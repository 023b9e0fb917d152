"""Virtual time: the loop jumps to the next timer, waits for threads, and reports deadlocks."""

from __future__ import annotations

import asyncio
import threading
import time

import anyio
import pytest

from actors.clock import Clock, Duration, Rate, Time, VirtualTimeLoop
from actors.errors import VirtualTimeDeadlock


@pytest.mark.virtual_time
async def test_an_hour_of_sleep_takes_no_real_time():
    loop = asyncio.get_running_loop()
    assert isinstance(loop, VirtualTimeLoop)
    assert loop.time() == 0.0
    started = time.perf_counter()
    await anyio.sleep(3600)
    assert loop.time() == 3600.0
    assert time.perf_counter() - started < 60  # an hour would take an hour without the jump


def test_anyio_run_with_the_virtual_loop_factory():
    async def main() -> float:
        await anyio.sleep(10.5)
        return asyncio.get_running_loop().time()

    assert anyio.run(main, backend_options={"loop_factory": VirtualTimeLoop}) == 10.5


def test_the_clock_starts_at_the_epoch_offset():
    async def main() -> tuple[int, int]:
        clock = Clock(asyncio.get_running_loop())
        first = clock.now_ns()
        await asyncio.sleep(2.5)
        return first, clock.now().nanoseconds

    with asyncio.Runner(loop_factory=lambda: VirtualTimeLoop(epoch=1000.0)) as runner:
        assert runner.run(main()) == (1_000_000_000_000, 1_002_500_000_000)


@pytest.mark.virtual_time
async def test_no_jump_while_executor_work_runs():
    loop = asyncio.get_running_loop()
    far_timer = asyncio.ensure_future(asyncio.sleep(100))
    await loop.run_in_executor(None, threading.Event().wait, 0.05)
    assert loop.time() < 100, "virtual time jumped while a thread was working"
    far_timer.cancel()


@pytest.mark.virtual_time
async def test_no_jump_while_anyio_thread_work_runs():
    loop = asyncio.get_running_loop()
    far_timer = asyncio.ensure_future(asyncio.sleep(100))
    await anyio.to_thread.run_sync(threading.Event().wait, 0.05)
    assert loop.time() < 100, "virtual time jumped while an anyio worker thread was working"
    far_timer.cancel()


def test_waiting_on_nothing_is_a_clear_error():
    async def main() -> None:
        await asyncio.Event().wait()

    with asyncio.Runner(loop_factory=lambda: VirtualTimeLoop(idle_timeout=0.05)) as runner:
        with pytest.raises(VirtualTimeDeadlock, match="no timer is scheduled"):
            runner.run(main())


@pytest.mark.virtual_time
async def test_rate_sleeps_to_absolute_deadlines():
    loop = asyncio.get_running_loop()
    rate = Rate(4.0, loop)
    stamps = []
    for _ in range(4):
        await rate.sleep()
        stamps.append(loop.time())
        await asyncio.sleep(0.1)  # work inside the period does not shift the deadlines
    assert stamps == [0.25, 0.5, 0.75, 1.0]


def test_time_and_duration_arithmetic():
    t = Time(seconds=1.5)
    assert t.seconds_nanoseconds() == (1, 500_000_000)
    assert (t + Duration(seconds=0.5)).nanoseconds == 2_000_000_000
    assert t - Time(seconds=1) == Duration(nanoseconds=500_000_000)
    msg = t.to_msg()
    assert (msg.sec, msg.nanosec) == (1, 500_000_000)


def test_precise_loop_waits_in_select():
    import selectors

    from actors.clock import precise_loop

    loop = precise_loop()
    try:
        assert isinstance(loop._selector, selectors.SelectSelector)  # microsecond waits, not epoll's ms
    finally:
        loop.close()


def test_actors_run_uses_the_precise_loop_on_the_wall_clock(monkeypatch):
    import actors.run
    from actors.clock import precise_loop

    seen = {}
    monkeypatch.setattr(actors.run.anyio, "run", lambda fn, backend_options: seen.update(backend_options))
    monkeypatch.setattr(actors.run, "configure_console", lambda level: None)
    assert actors.run.main(["graph.toml", "--clock", "wall"]) == 0
    assert seen["loop_factory"] is precise_loop
    assert actors.run.main(["graph.toml", "--clock", "virtual", "--duration", "1"]) == 0
    assert seen["loop_factory"] is VirtualTimeLoop


@pytest.mark.virtual_time
async def test_advance_moves_virtual_time_at_once():
    loop = asyncio.get_running_loop()
    due = loop.create_future()
    loop.call_at(5.0, due.set_result, None)
    loop.advance(10.0)
    await due
    assert loop.time() == 10.0  # without the advance, the loop would have jumped to 5.0
    with pytest.raises(ValueError, match="backwards"):
        loop.advance(-1)
