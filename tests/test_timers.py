"""Timers: absolute deadlines under virtual time, skipped ticks on overrun, cancel and reset."""

from __future__ import annotations

import asyncio

import anyio
import pytest

from actors import Node, Runtime

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
