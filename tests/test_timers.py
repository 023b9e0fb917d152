"""Timers: absolute deadlines under virtual time, skipped ticks on overrun, cancel and reset."""

from __future__ import annotations

import asyncio

import anyio
import pytest

from actors import Node, Runtime
from conftest import live_loop_timers

pytestmark = pytest.mark.virtual_time


class Ticker(Node):
    period = 0.1
    work = 0.0

    def __init__(self) -> None:
        super().__init__("ticker")
        self.stamps: list[float] = []
        self.timer = self.create_timer(self.period, self.tick)

    async def tick(self) -> None:
        self.stamps.append(asyncio.get_running_loop().time())
        if self.work:
            await anyio.sleep(self.work)


async def test_an_hour_of_ticks_lands_on_multiples_of_the_period():
    async with Runtime() as rt:
        node = rt.spawn(Ticker)
        await anyio.sleep(3600)
        assert abs(len(node.stamps) - 36000) <= 1
        assert node.stamps[0] == pytest.approx(0.1)
        worst = max(abs(t - round(t / 0.1) * 0.1) for t in node.stamps)
        assert worst < 1e-9  # no drift: each tick is start + k * period


async def test_an_overrunning_callback_skips_ticks_instead_of_bursting():
    class Slow(Ticker):
        period = 1.0
        work = 2.5

    async with Runtime() as rt:
        node = rt.spawn(Slow)
        await anyio.sleep(10.5)
        # Ticks at 1, then the callback runs until 3.5: 2 and 3 are skipped, next is 4.
        assert node.stamps == [1.0, 4.0, 7.0, 10.0]


async def test_cancel_reset_and_is_canceled():
    async with Runtime() as rt:
        node = rt.spawn(Ticker)
        await anyio.sleep(0.35)
        assert len(node.stamps) == 3
        assert node.timer.time_until_next_call() == pytest.approx(0.05)
        node.timer.cancel()
        assert node.timer.is_canceled() and node.timer.time_until_next_call() is None
        await anyio.sleep(1)
        assert len(node.stamps) == 3
        node.timer.reset()
        assert not node.timer.is_canceled()
        await anyio.sleep(0.25)
        assert node.stamps[3:] == pytest.approx([1.45, 1.55])


async def test_a_timer_can_cancel_itself_from_its_callback():
    class Once(Node):
        def __init__(self) -> None:
            super().__init__("once")
            self.count = 0
            self.timer = self.create_timer(0.5, self.tick)

        def tick(self) -> None:
            self.count += 1
            self.timer.cancel()

    async with Runtime() as rt:
        node = rt.spawn(Once)
        await anyio.sleep(5)
        assert node.count == 1


async def test_timers_sharing_a_deadline_fire_from_one_loop_timer_in_creation_order():
    order: list[str] = []

    class Named(Node):
        def __init__(self) -> None:
            super().__init__("named")
            self.create_timer(1.0, lambda: order.append(self.get_name()))

    async with Runtime() as rt:
        for name in ("a", "b", "c"):
            rt.spawn(Named, name=name)
        assert len(rt.deadlines) == 3
        assert [h.when() for h in live_loop_timers()] == [1.0]
        await anyio.sleep(2.5)
        assert order == ["a", "b", "c", "a", "b", "c"]


async def test_a_canceled_timer_leaves_no_loop_timer_for_its_deadline():
    class Two(Node):
        def __init__(self) -> None:
            super().__init__("two")
            self.soon = self.create_timer(1.0, lambda: None)
            self.later = self.create_timer(5.0, lambda: None)

    async with Runtime() as rt:
        node = rt.spawn(Two)
        node.soon.cancel()
        # Armed for the live deadline only: virtual time never jumps to 1.0 for nothing.
        assert [h.when() for h in live_loop_timers()] == [5.0]
        node.later.cancel()
        assert live_loop_timers() == [] and len(rt.deadlines) == 0


async def test_stale_deadlines_of_canceled_timers_are_swept_out():
    class Many(Node):
        def __init__(self) -> None:
            super().__init__("many")
            self.timers = [self.create_timer(10.0 + i, lambda: None) for i in range(1000)]

    async with Runtime() as rt:
        node = rt.spawn(Many)
        for timer in node.timers[1:]:
            timer.cancel()
        assert len(rt.deadlines) == 1
        assert len(rt.deadlines._heap) < 200  # rebuilt when stale entries became the majority
        await anyio.sleep(10)
        assert node.timers[0].ticks == 1
