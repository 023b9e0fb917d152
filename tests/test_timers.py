"""Timers: absolute deadlines under virtual time, skipped ticks on overrun, cancel and reset,
rclpy's TimerInfo, autostart, clock= and nanosecond times."""

from __future__ import annotations

import asyncio
import contextvars
import random
import time
from typing import Any

import anyio
import pytest
from conftest import live_loop_timers

from actors import Node, Runtime
from actors.core.loops import VirtualTimeLoop
from actors.ros.time import Clock, ClockType, Time
from actors.ros.timers import TimerInfo, _timer_info_parameter
from interfaces.std_msgs.msg import String

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
        assert node.timer.time_until_next_call() == 50_000_000  # nanoseconds, as rclpy
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


async def test_timers_due_at_the_same_instant_fire_together_whatever_their_periods():
    # 15 * 0.01 s is 0.15 in floats, 3 * 0.05 s is 0.15000000000000002: without deadlines on the
    # nanosecond grid, a 20 Hz timer's third tick came a hair after a 100 Hz timer's 15th, in a
    # loop iteration of its own, and which came first at a shared instant depended on rounding.
    fired: list[tuple[str, float]] = []

    class Two(Node):
        def __init__(self) -> None:
            super().__init__("two")
            self.create_timer(0.01, lambda: fired.append(("fast", asyncio.get_running_loop().time())))
            self.create_timer(0.05, lambda: fired.append(("slow", asyncio.get_running_loop().time())))

    async with Runtime() as rt:
        rt.spawn(Two)
        await anyio.sleep(1.005)
    instants = sorted({t for _, t in fired})
    assert len(instants) == 100  # the slow timer's 20 ticks all fall on fast ones
    shared = [
        [name for name, t in fired if t == instant]
        for instant in instants
        if instant in {t for name, t in fired if name == "slow"}
    ]
    # Together, in the order their deadlines were armed: the slow one's a period ahead, each time.
    assert shared == [["slow", "fast"]] * 20


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


class Bare(Node):
    """Timers made, canceled, reset and retuned from outside, each tick noted as (time, index)."""

    def __init__(self) -> None:
        super().__init__("bare")
        self.fired: list[tuple[float, int]] = []
        self.timers: list[Any] = []

    def add(self, period: float) -> Any:
        index = len(self.timers)
        self.timers.append(self.create_timer(period, lambda: self.fired.append((self.now(), index))))
        return self.timers[-1]

    def now(self) -> float:
        return asyncio.get_running_loop().time()


async def test_timers_made_reset_canceled_and_retuned_at_scattered_instants_tick_on_their_own_multiples():
    # Each timer's ticks, from a model of its own: start + k * period from when it was made
    # or reset, the tick already scheduled kept by a period change; nothing else fires.
    rng = random.Random(16)
    periods = (0.1, 0.25, 0.3)
    async with Runtime() as rt:
        node = rt.spawn(Bare)
        model: list[list[Any]] = []  # per timer: [start, k, period, canceled, expected ticks]
        end = 6.0

        def ticks_until(entry: list[Any], t: float) -> None:
            # The model's ticks up to t: each at start + k * period, re-anchored by a period change.
            start, k, period, canceled, expected = entry
            while not canceled and start + k * period <= t:
                expected.append(start + k * period)
                k += 1
            entry[1] = k

        while node.now() < end - 1:
            await anyio.sleep(rng.uniform(0.001, 0.05))
            now = node.now()
            for entry in model:
                ticks_until(entry, now)
            op = rng.random()
            if op < 0.4 or not model:
                node.add(rng.choice(periods))
                model.append([now, 1, node.timers[-1].period, False, []])
                continue
            i = rng.randrange(len(model))
            timer, entry = node.timers[i], model[i]
            if op < 0.6:
                timer.cancel()
                entry[3] = True
            elif op < 0.8:
                timer.reset()
                entry[0:4] = [now, 1, timer.period, False]
            elif not entry[3]:
                new = rng.choice(periods)
                timer.timer_period_ns = int(new * 1e9)
                entry[0:3] = [entry[0] + entry[1] * entry[2], 0, new]
        await anyio.sleep(end - node.now())
        for entry in model:
            ticks_until(entry, end)
        for i, entry in enumerate(model):
            assert [t for t, index in node.fired if index == i] == pytest.approx(entry[4], abs=1e-9), i
        assert [t for t, _ in node.fired] == sorted(t for t, _ in node.fired)
        assert len(rt.deadlines) == sum(not entry[3] for entry in model)


async def test_a_timer_re_armed_after_an_overrun_before_its_periods_last_deadline_ticks_on_time():
    class Overrun(Ticker):
        period = 1.0

        async def tick(self) -> None:
            self.stamps.append(asyncio.get_running_loop().time())
            if len(self.stamps) == 1:
                await anyio.sleep(1.95)  # returns at 2.95: next tick 3.0, before the other's 3.9

    async with Runtime() as rt:
        slow = rt.spawn(Overrun, name="slow")
        await anyio.sleep(0.9)
        other = rt.spawn(Overrun, name="other")
        other.work = 0.0
        other.stamps.append(-1.0)  # no sleep at its first tick
        await anyio.sleep(4.05)
        assert slow.stamps == pytest.approx([1.0, 3.0, 4.0])
        assert other.stamps[1:] == pytest.approx([1.9, 2.9, 3.9, 4.9])


async def test_stale_deadlines_of_timers_sharing_a_period_are_swept_out():
    async with Runtime() as rt:
        node = rt.spawn(Bare)
        for _ in range(1000):  # one period, made at different instants: one lane of deadlines
            node.add(10.0)
            await anyio.sleep(0.001)
        for timer in reversed(node.timers[:-1]):  # the earliest last: stale entries pile up behind it
            timer.cancel()
        assert len(rt.deadlines) == 1
        assert rt.deadlines._entries() < 200  # rebuilt when stale entries became the majority
        await anyio.sleep(10)
        assert node.fired == [(pytest.approx(10.999, abs=1e-9), 999)]


async def test_stale_deadlines_swept_out_from_a_tick_leave_the_instants_after_it_on_time():
    # A tick that cancels most timers rebuilds the heap while the loop timer's instants run.
    class Sweeper(Bare):
        def sweep(self) -> None:
            self.fired.append((self.now(), -1))
            for timer in reversed(self.timers):  # the earliest last: stale entries pile up behind it
                timer.cancel()

    async with Runtime() as rt:
        node = rt.spawn(Sweeper)
        for i in range(100):
            node.add(1.0 + i / 1000)  # a period each: every deadline in the heap itself
        node.timers.append(node.create_timer(0.05, node.sweep))
        ticker = node.add(0.01)
        node.timers.remove(ticker)
        await anyio.sleep(0.205)
        assert len(rt.deadlines) == 1 and rt.deadlines._entries() < 50
        assert [t for t, index in node.fired if index == -1] == [pytest.approx(0.05)]
        assert [t for t, index in node.fired if index == 101] == pytest.approx([k / 100 for k in range(1, 21)])


async def test_a_periods_first_timer_waits_in_the_heap_alone_and_its_second_opens_the_lane():
    async with Runtime() as rt:
        node = rt.spawn(Bare)
        first, second, third = node.add(0.1), node.add(0.1), node.add(0.3)
        assert first._lane is third._lane is None and rt.deadlines._lanes == {0.1: second._lane}
        await anyio.sleep(0.35)
        # In the order they were armed either way: at 0.3 the 0.3 s timer's first deadline came before the re-arms.
        assert node.fired == [
            (pytest.approx(t), i) for t, i in [(0.1, 0), (0.1, 1), (0.2, 0), (0.2, 1), (0.3, 2), (0.3, 0), (0.3, 1)]
        ]


async def test_timers_of_more_periods_than_lanes_tick_on_their_own_multiples():
    async with Runtime() as rt:
        node = rt.spawn(Bare)
        periods = [0.5 + i / 1000 for i in range(300)]
        for period in periods:
            node.add(period)
            await anyio.sleep(0.0007)
        await anyio.sleep(2.5)
        for i, period in enumerate(periods):
            start = i * 0.0007
            expected = [start + k * period for k in range(1, 10) if start + k * period <= node.now()]
            assert [t for t, index in node.fired if index == i] == pytest.approx(expected, abs=1e-9)


async def test_ticks_rearm_under_one_loop_timer_and_leave_no_loop_callback_behind():
    class Mixed(Node):
        def __init__(self) -> None:
            super().__init__("mixed")
            self.seen: list[tuple[int, int]] = []
            for period in (0.01, 0.03, 0.05):  # made in this order, no loop timer is replaced
                self.create_timer(period, self.look)

        def look(self) -> None:
            loop = asyncio.get_running_loop()
            self.seen.append((len(loop._ready), sum(h.cancelled() for h in loop._scheduled)))  # type: ignore[attr-defined]

    async with Runtime() as rt:
        node = rt.spawn(Mixed)
        await anyio.sleep(0.305)
        # Every round ran from the loop timer itself (no loop callback queued to run it
        # again later), and re-arming three timers cancelled no loop timer.
        assert len(node.seen) == 30 + 10 + 6
        assert set(node.seen) == {(0, 0)}
        assert [h.when() for h in live_loop_timers()] == [pytest.approx(0.31)]


async def test_on_virtual_time_every_instant_of_the_timers_is_the_same_loop_timer_set_again():
    class Pair(Node):
        def __init__(self) -> None:
            super().__init__("pair")
            self.ticks: list[float] = []
            self.create_timer(0.01, lambda: self.ticks.append(asyncio.get_running_loop().time()))
            self.create_timer(0.03, lambda: None)  # instants where two timers are due, and where one is

    async with Runtime() as rt:
        node = rt.spawn(Pair)
        seen = []
        await anyio.sleep(0.005)
        for _ in range(10):  # between two instants: the loop timer waiting for the next one
            (handle,) = [h for h in live_loop_timers() if h._callback == rt.deadlines._fire]
            seen.append((handle, handle.when()))
            await anyio.sleep(0.01)
    # One TimerHandle for the whole run, set for each instant in turn (before: a new one per instant).
    assert len({id(handle) for handle, _ in seen}) == 1
    assert [when for _, when in seen] == pytest.approx([0.01 * k for k in range(1, 11)])
    assert node.ticks == pytest.approx([0.01 * k for k in range(1, 11)])


async def test_a_timer_made_or_canceled_by_a_callback_moves_the_loop_timer():
    class Planner(Node):
        def __init__(self) -> None:
            super().__init__("planner")
            self.fast: list[float] = []
            self.create_timer(1.0, self.plan)
            self.later = self.create_timer(1.5, lambda: None)

        def plan(self) -> None:
            if not self.fast:
                self.create_timer(0.1, lambda: self.fast.append(asyncio.get_running_loop().time()))
                self.later.cancel()

    async with Runtime() as rt:
        node = rt.spawn(Planner)
        await anyio.sleep(1.05)
        # Armed for the new timer's first tick, not for the 2.0 tick nor the canceled 1.5.
        assert [h.when() for h in live_loop_timers()] == [pytest.approx(1.1)]
        await anyio.sleep(0.2)
        assert node.fast == pytest.approx([1.1, 1.2])


async def test_a_node_a_tick_wakes_runs_in_its_own_round_after_the_ticks():
    order: list[str] = []

    class Sender(Node):
        def __init__(self) -> None:
            super().__init__("sender")
            self.pub = self.create_publisher(String, "chat", 10)
            self.create_timer(1.0, self.send)

        def send(self) -> None:
            order.append("tick")
            self.pub.publish(String(data="hi"))

    class Receiver(Node):
        def __init__(self) -> None:
            super().__init__("receiver")
            self.create_subscription(String, "chat", lambda msg: order.append(msg.data), 10)
            self.create_timer(1.0, lambda: order.append("tock"))

    async with Runtime() as rt:
        rt.spawn(Receiver)
        rt.spawn(Sender)
        await anyio.sleep(2.5)
        assert order == ["tock", "tick", "hi", "tock", "tick", "hi"]


async def test_ticks_run_in_the_runtimes_one_context_alone_or_due_together():
    # Rounds share one context (actors.core._actor): what a tick's callback sets, the callbacks after it see,
    # a subscription's round (a loop callback of its own) included, and the runtime's caller does not.
    var: contextvars.ContextVar[str] = contextvars.ContextVar("var", default="unset")
    seen: list[tuple[str, str]] = []

    class Setter(Node):
        def __init__(self) -> None:
            super().__init__("setter")
            self.create_timer(0.1, self.tick)
            self.pub = self.create_publisher(String, "chat", 10)

        def tick(self) -> None:
            seen.append(("tick", var.get()))
            var.set(f"set at {self.get_clock().now().nanoseconds // 10**8}")
            self.pub.publish(String(data="hi"))

    class Reader(Node):
        def __init__(self) -> None:
            super().__init__("reader")
            self.create_subscription(String, "chat", lambda msg: seen.append(("message", var.get())), 10)
            self.create_timer(0.2, lambda: seen.append(("tock", var.get())))

    async with Runtime() as rt:
        rt.spawn(Setter)
        rt.spawn(Reader)
        await anyio.sleep(0.25)
        assert var.get() == "unset"
    # At 0.1 the tick is due alone (Actor.run_one); at 0.2 after the tock (armed before its re-arm), in one
    # batch of rounds.
    assert seen == [
        ("tick", "unset"),
        ("message", "set at 1"),
        ("tock", "set at 1"),
        ("tick", "set at 1"),
        ("message", "set at 2"),
    ]


class Informed(Node):
    """A timer callback that asks for TimerInfo, in both spellings of the annotation."""

    def __init__(self, **timer_options: object) -> None:
        super().__init__("informed")
        self.infos: list[TimerInfo] = []
        self.timer = self.create_timer(0.25, self.tick, **timer_options)

    def tick(self, info: TimerInfo) -> None:
        self.infos.append(info)


async def test_a_callback_annotated_with_timer_info_gets_the_expected_and_actual_times():
    async with Runtime() as rt:
        node = rt.spawn(Informed)
        await anyio.sleep(0.6)
        first, second = node.infos
        assert first.expected_call_time == Time(seconds=0.25, clock_type=ClockType.ROS_TIME)
        assert second.actual_call_time == Time(seconds=0.5, clock_type=ClockType.ROS_TIME)


async def test_timer_info_shows_a_late_call():
    class Late(Informed):
        def __init__(self) -> None:
            super().__init__()
            self.create_timer(0.1, self.block)

        async def block(self) -> None:
            await anyio.sleep(0.3)  # holds the node past the 0.25 s tick

    async with Runtime() as rt:
        node = rt.spawn(Late)
        await anyio.sleep(0.45)
        (info,) = node.infos
        assert info.expected_call_time.nanoseconds == 250_000_000
        assert info.actual_call_time.nanoseconds == 400_000_000


def test_the_timer_info_parameter_is_found_by_its_annotation():
    def plain() -> None: ...

    def stringly(info: TimerInfo) -> None: ...

    def real(first: int, info) -> None: ...

    real.__annotations__["info"] = TimerInfo
    # This module has `from __future__ import annotations`: there the annotation is a string.
    assert stringly.__annotations__["info"] == "TimerInfo"
    assert _timer_info_parameter(plain) is None
    assert _timer_info_parameter(stringly) == "info"
    assert _timer_info_parameter(real) == "info"
    assert _timer_info_parameter(print) is None
    with pytest.raises(ValueError):
        TimerInfo(expected_call_time=-1)
    with pytest.raises(TypeError):
        TimerInfo(clock_type="ROS_TIME")


async def test_a_timer_made_without_autostart_waits_for_reset():
    async with Runtime() as rt:
        node = rt.spawn(Informed, autostart=False)
        await anyio.sleep(1)
        assert node.infos == [] and node.timer.is_canceled()
        assert node.timer.time_until_next_call() is None
        node.timer.reset()
        await anyio.sleep(0.3)
        assert [i.expected_call_time.nanoseconds for i in node.infos] == [1_250_000_000]


async def test_times_until_and_since_a_call_are_nanoseconds():
    class Busy(Ticker):
        period = 0.5

    async with Runtime() as rt:
        node = rt.spawn(Busy)
        await anyio.sleep(0.2)
        assert node.timer.time_since_last_call() == 200_000_000  # since it was made
        assert node.timer.time_until_next_call() == 300_000_000
        await anyio.sleep(0.5)
        assert node.timer.time_since_last_call() == 200_000_000  # since the tick at 0.5
        assert not node.timer.is_ready()


async def test_an_overdue_tick_has_a_negative_time_until_it():
    class Hog(Node):
        def __init__(self) -> None:
            super().__init__("hog")
            self.seen: list[int | None] = []
            self.ticker = self.create_timer(0.1, lambda: None)
            self.create_timer(0.05, self.hold)

        async def hold(self) -> None:
            await anyio.sleep(0.12)  # the 0.1 tick comes due while this runs
            self.seen.append(self.ticker.time_until_next_call())
            self.seen.append(self.ticker.is_ready())

    async with Runtime() as rt:
        node = rt.spawn(Hog)
        await anyio.sleep(0.18)
        assert node.seen[:2] == [-70_000_000, True]


async def test_a_timer_on_another_clock_stamps_its_timer_info_with_that_clock():
    async with Runtime() as rt:
        node = rt.spawn(Informed, clock=Clock(clock_type=ClockType.SYSTEM_TIME))
        assert node.timer.clock.clock_type == ClockType.SYSTEM_TIME
        before = time.time_ns()
        await anyio.sleep(0.3)
        (info,) = node.infos
        assert info.actual_call_time.clock_type == ClockType.SYSTEM_TIME
        assert info.actual_call_time.nanoseconds >= before  # read from the system clock
        with pytest.raises(TypeError):
            node.create_timer(1.0, lambda: None, clock="steady")


async def test_changing_the_period_keeps_the_scheduled_tick():
    async with Runtime() as rt:
        node = rt.spawn(Ticker)
        await anyio.sleep(0.15)
        node.timer.timer_period_ns = 500_000_000
        assert node.timer.timer_period_ns == 500_000_000
        await anyio.sleep(1.0)
        assert node.stamps == pytest.approx([0.1, 0.2, 0.7])
        with pytest.raises(ValueError):
            node.timer.timer_period_ns = 0


def test_instants_skipped_to_on_virtual_time_run_as_the_loops_own_iterations_would():
    """The same graph with and without Deadlines skipping the loop's iterations: the same trace."""

    class Busy(Node):
        def __init__(self, trace: list[tuple[float, str]]) -> None:
            super().__init__("busy")
            self.trace = trace
            self.pub = self.create_publisher(String, "chat", 10)
            self.create_subscription(String, "chat", lambda msg: self.note(msg.data), 10)
            self.create_timer(0.01, lambda: self.note("step"))  # alone at most instants: skipped to
            self.create_timer(0.03, self.send)
            self.create_timer(0.07, lambda: asyncio.get_running_loop().call_soon(self.note, "soon"))

        def note(self, what: str) -> None:
            self.trace.append((asyncio.get_running_loop().time(), what))

        def send(self) -> None:
            self.note("send")
            self.pub.publish(String(data="heard"))

    def run(skip: bool) -> tuple[list[tuple[float, str]], int]:
        trace: list[tuple[float, str]] = []
        skipped = 0

        async def main() -> None:
            nonlocal skipped
            loop = asyncio.get_running_loop()

            def skip_to(when: float, again: bool) -> bool:
                nonlocal skipped
                moved = loop.skip_to(when, again)
                skipped += moved
                return moved

            async with Runtime() as rt:
                rt.deadlines._skip_to = skip_to if skip else None
                rt.spawn(Busy, trace)
                loop.call_at(0.155, lambda: trace.append((loop.time(), "loop timer")))
                for _ in range(4):
                    await anyio.sleep(0.1)
                    trace.append((loop.time(), "task"))

        anyio.run(main, backend_options={"loop_factory": VirtualTimeLoop})
        return trace, skipped

    (skipping, skipped), (iterating, none) = run(True), run(False)
    assert skipping == iterating and none == 0
    assert skipped > 10 and len(iterating) > 60
