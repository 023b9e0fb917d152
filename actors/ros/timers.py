"""Timers that fire on absolute deadlines: start + k * period, never drifting.

The first tick comes one period after creation, as in ROS.  A callback that
overruns (an ``async`` callback that awaits past its next deadline) skips the
ticks it missed instead of firing them in a burst: the next deadline is the
first multiple of the period after the callback returns.

Every timer of a runtime waits in one :class:`Deadlines` under a single
loop timer, rather than in a loop timer of its own.  asyncio's ``TimerHandle``
orders its heap with a Python-level ``__lt__`` (about 0.1 µs a comparison,
log2(n) of them per push and per pop), which made the loop's heap a third of
a tick's cost with 10,000 timers.  Deadlines keeps the timers of each period
in a FIFO lane from the second on (a re-armed timer's next deadline is the
latest of its period), and only the lanes' first deadlines in a heap.  Timers whose deadlines
have come when the loop timer fires all fire from it, so timers that share a
deadline (every node started in the same instant, under virtual time) cost one
loop timer between them.  Timers due together fire in the order they were armed,
and their nodes' rounds run right away, in the same loop iteration
(:meth:`Scheduler.run_now`), not one iteration later; the loop timer is set
again once, after those rounds have re-armed their timers.  On virtual time,
when the loop's next iteration would only jump to the next deadline and run
them again (:meth:`VirtualTimeLoop.skip_to`), they run at once, without it.

As in rclpy, a callback with a parameter annotated ``TimerInfo`` is called with
the tick's expected and actual times; ``autostart=False`` makes a timer that
waits for :meth:`Timer.reset`; times until and since a call are nanoseconds.
Every timer ticks on the graph's time (the loop's); a ``clock`` given to it is
the one its TimerInfo stamps are read from.
"""

from __future__ import annotations

import asyncio
import inspect
import itertools
from collections import deque
from collections.abc import Awaitable, Callable
from heapq import heappop, heappush, heapreplace
from inspect import isawaitable
from typing import Any

from actors.core._actor import CallbackFailed, Owner, Scheduler
from actors.core.loops import VirtualTimeLoop
from actors.ros.time import Clock, ClockType, Time

__all__ = ["Timer", "TimerInfo", "Deadlines"]

_NS = 1_000_000_000
# _NS as a float, to multiply a float by: the same product (10**9 is exact as a float), but
# float * float is specialised by CPython and float * int is not, on every timer's re-arming.
_NS_FLOAT = 1e9


class TimerInfo:
    """When a tick was due and when its callback ran, as ``rclpy.timer.TimerInfo``.

    Raises TypeError when ``clock_type`` is not a ClockType and ValueError for
    negative times (nanoseconds of the timer's clock).
    """

    __slots__ = ("_expected", "_actual")

    def __init__(
        self, *, expected_call_time: int = 0, actual_call_time: int = 0, clock_type: ClockType = ClockType.SYSTEM_TIME
    ) -> None:
        if expected_call_time < 0 or actual_call_time < 0:
            raise ValueError("a TimerInfo's call times cannot be negative")
        self._expected = Time(nanoseconds=expected_call_time, clock_type=clock_type)
        self._actual = Time(nanoseconds=actual_call_time, clock_type=clock_type)

    @property
    def expected_call_time(self) -> Time:
        """When the tick was due."""
        return self._expected

    @property
    def actual_call_time(self) -> Time:
        """When the callback was called (later than due when the node was busy)."""
        return self._actual


def _timer_info_parameter(callback: Callable[..., Any]) -> str | None:
    """The name of ``callback``'s parameter annotated TimerInfo, if it has one (as rclpy looks for it)."""
    try:
        parameters = inspect.signature(callback).parameters.values()
    except (TypeError, ValueError):  # a builtin or a C callable: no annotations to read
        return None
    for parameter in parameters:
        annotation = parameter.annotation
        # A string when the callback's module uses ``from __future__ import annotations``.
        if annotation is TimerInfo or (isinstance(annotation, str) and annotation.rpartition(".")[2] == "TimerInfo"):
            return parameter.name
    return None


_COMPACT_AT = 64  # stale entries tolerated before the heap and lanes are rebuilt without them
# Instants one loop timer's callback runs in a row on virtual time (see Deadlines._fire): the
# loop's own iteration still comes this often, for whatever watches it from outside.
_SKIPS = 100
_MAX_LANES = 256  # distinct periods given a lane; timers of any further period wait in the heap alone
_NEVER = float("inf")  # a constant: float("inf") parses the string at each call


class _Lane:
    """The deadlines of timers of one period after the earliest, in order: a re-armed timer's goes last.

    A timer re-armed from its tick waits one period past a deadline that has
    come, so timers of one period come due in the order they re-arm: a FIFO
    keeps them sorted, with no comparison.  Only the lane's earliest entry is
    in the heap; the next one takes its place when it leaves.
    """

    __slots__ = ("queue", "tail", "open")

    def __init__(self) -> None:
        self.queue: deque[_Entry] = deque()  # the lane's entries after its head, in order
        self.tail = 0.0  # the latest deadline in the lane (while open)
        self.open = False  # whether the lane has a head in the heap


_Entry = tuple[float, int, "Timer", "_Lane | None"]


class Deadlines:
    """The deadlines of a runtime's timers under one loop timer: a heap of lane heads, and per-period lanes.

    An entry ``(when, order, timer, lane)`` is live while its timer still
    waits for that deadline (``timer._when == when``); a canceled or reset
    timer leaves a stale entry behind, skipped when it comes up and swept out
    once stale entries are the majority.  The loop timer is always armed for a
    live deadline, so virtual time never jumps to a deadline nobody waits for.

    With 10,000 timers a heap of them cost a microsecond per tick (log2 n
    tuple comparisons for each push and pop, each a cache miss); a timer's
    deadline usually goes at the end of its period's :class:`_Lane` instead,
    and the heap holds one entry per lane.  A deadline earlier than its
    lane's last (a timer reset, or ticking late) waits in the heap alone, as
    do the deadlines of a period's first timer (see :meth:`lane`).
    Entries pop in ``(when, order)`` order either way: timers due together
    fire in the order they were armed.
    """

    __slots__ = (
        "_loop",
        "_scheduler",
        "_context",
        "_heap",
        "_lanes",
        "_periods",
        "_handle",
        "_spent",
        "_call_again",
        "_skip_to",
        "_armed",
        "_order",
        "_stale",
        "_firing",
    )

    def __init__(self, loop: asyncio.AbstractEventLoop, scheduler: Scheduler) -> None:
        self._loop = loop
        self._scheduler = scheduler
        # The loop timer runs in the rounds' context: _fire runs them itself (Actor.run_one, Scheduler.run_now).
        self._context = scheduler.context
        self._heap: list[_Entry] = []
        self._lanes: dict[float, _Lane] = {}
        self._periods: set[float] = set()  # the periods lane() was asked for, up to _MAX_LANES
        self._handle: asyncio.TimerHandle | None = None
        # The loop timer that ran _fire, set again for the next deadline where the loop can
        # (virtual time: one loop timer per instant, and a new handle cost as much as the rest of _arm).
        self._spent: asyncio.TimerHandle | None = None
        self._call_again = loop.call_again if isinstance(loop, VirtualTimeLoop) else None
        self._skip_to = loop.skip_to if isinstance(loop, VirtualTimeLoop) else None
        self._armed = _NEVER  # the deadline the loop timer is set for
        self._order = itertools.count()
        self._stale = 0
        self._firing = False  # in _fire: the loop timer is set once, when its rounds are done

    def __len__(self) -> int:
        """Live deadlines waiting."""
        return self._entries() - self._stale

    def _entries(self) -> int:
        return len(self._heap) + sum(len(lane.queue) for lane in self._lanes.values())

    def lane(self, period: float) -> _Lane | None:
        """The lane of timers of ``period``: None for the period's first timer, and once too many periods are known.

        A period's first timer waits in the heap alone, as it would at the head of
        a lane of its own, without the lane's bookkeeping on each of its ticks (a
        simulation's physics step has a period to itself); the lane comes with the second.
        """
        lane = self._lanes.get(period)
        if lane is None:
            if period in self._periods:
                lane = self._lanes[period] = _Lane()
            elif len(self._periods) < _MAX_LANES:
                self._periods.add(period)
        return lane

    def add(self, when: float, timer: Timer) -> None:
        """Schedule ``timer`` in its node at loop time ``when`` (its ``_when`` from now), unless that changes first."""
        # On the nanosecond grid: timers due at one instant get the same float and fire together,
        # in the order armed (15 * 0.01 is 0.15 but 3 * 0.05 is 0.15000000000000002, which put a
        # 20 Hz timer's third tick a hair after a 100 Hz timer's fifteenth, in an iteration of its own).
        timer._when = when = round(when * _NS_FLOAT) / _NS
        lane = timer._lane
        if lane is None:
            heappush(self._heap, (when, next(self._order), timer, None))
        elif not lane.open:
            lane.open = True
            lane.tail = when
            heappush(self._heap, (when, next(self._order), timer, lane))
        elif when >= lane.tail:
            lane.tail = when
            lane.queue.append((when, next(self._order), timer, lane))
        else:  # before the lane's last: in the heap alone
            heappush(self._heap, (when, next(self._order), timer, None))
        if when < self._armed:
            self._arm(when)

    def discard(self) -> None:
        """Note that a timer stopped waiting for its deadline (its entry is now stale)."""
        self._stale += 1
        if self._stale > _COMPACT_AT and self._stale * 2 > self._entries():
            self._compact()
        self._prune()
        heap = self._heap
        if not heap:
            self._disarm()
        elif heap[0][0] > self._armed:
            self._arm(heap[0][0])  # the head went stale: wait for the next live deadline

    def _compact(self) -> None:
        # Every live entry again, in order: each lane's first one its head, as add() would.
        live = [entry for entry in self._heap if entry[2]._when == entry[0]]
        for each in self._lanes.values():
            live += [entry for entry in each.queue if entry[2]._when == entry[0]]
            each.queue.clear()
            each.open = False
        live.sort()
        heap = self._heap
        heap.clear()  # the same list: _fire holds it in a local across its callbacks
        for entry in live:
            lane = entry[3]
            if lane is not None and lane.open:
                lane.queue.append(entry)
            else:
                if lane is not None:
                    lane.open = True
                heap.append(entry)  # in order: a heap already
            if lane is not None:
                lane.tail = entry[0]
        self._stale = 0

    def _pop(self) -> _Entry:
        # The earliest entry out of the heap, its lane's next entry in its place.
        heap = self._heap
        lane = heap[0][3]
        if lane is None:
            return heappop(heap)
        if lane.queue:
            return heapreplace(heap, lane.queue.popleft())
        lane.open = False
        return heappop(heap)

    def _prune(self) -> None:
        heap = self._heap
        while heap and heap[0][2]._when != heap[0][0]:
            self._pop()
            self._stale -= 1

    def _arm(self, when: float) -> None:
        self._armed = when
        if self._firing:
            return
        if self._handle is not None:
            self._handle.cancel()
        spent = self._spent
        if spent is not None and self._call_again is not None:
            self._spent = None
            self._handle = self._call_again(spent, when)
        else:
            self._handle = self._loop.call_at(when, self._fire, context=self._context)

    def _disarm(self) -> None:
        if self._handle is not None:
            self._handle.cancel()
            self._handle = None
        self._armed = _NEVER

    def _fire(self) -> None:
        # Everything due by now, and at least what the loop timer was set for (the loop
        # may run a timer a clock-resolution early).
        now = limit = self._loop.time()
        if limit < self._armed:  # not max(): it parses its arguments as keywords, ten times the cost
            limit = self._armed
        self._spent, self._handle = self._handle, None
        skip_to = self._skip_to  # a local: as an attribute, a bound method is looked up unspecialised
        skips = _SKIPS if skip_to is not None else 0
        scheduler = self._scheduler
        # The callbacks re-arm their timers: one loop timer for all of them afterwards,
        # rather than one each (asyncio keeps a cancelled one in its heap until it is due).
        # Below every deadline meanwhile, so that add() leaves the loop timer alone.
        self._armed = -_NEVER
        self._firing = True
        heap = self._heap
        try:
            if not heap or heap[0][0] > limit:
                # Nothing due: the loop timer is set for the heap's head, so this should not happen,
                # but the pop loop below pops before it tests, and would fire a timer early.
                return
            while True:
                # One instant a loop: a Python call per instant cost more than its body's setup.
                # The timers due by ``limit``, the heap's head first (it is due here and after a
                # skip), their rounds run; the heap's head live afterwards.  The first timer due
                # is ``timer``, the others go in ``more``: most instants of a simulation run one
                # timer, which then goes straight to run_one, with no list to index or iterate.
                timer = None
                more: list[Timer] = []
                while True:
                    when, _, due, _ = self._pop()
                    if due._when == when:
                        due._when = None  # due: it waits for no deadline until its callback has run
                        if timer is None:
                            timer = due
                        else:
                            more.append(due)
                    else:
                        self._stale -= 1
                    if not heap or heap[0][0] > limit:
                        break
                if more:
                    scheduler.hold()  # the rounds run below, not from a loop callback of their own
                    for due in (timer, *more):  # type: ignore[assignment]  # timer is set: more fills after it
                        due.node.actor.schedule(due)
                    scheduler.run_now()
                elif timer is not None:
                    timer.node.actor.run_one(timer, scheduler, now)
                if self._stale and heap and heap[0][2]._when != heap[0][0]:  # no stale entry: the head is live
                    self._prune()
                # On virtual time, the next instant at once when the loop would do nothing
                # but jump there and call this again: a physics step's instant is mostly
                # the loop's iteration around it.
                if not (skips and heap):
                    break
                now = limit = heap[0][0]
                if not skip_to(limit, skips < _SKIPS):  # type: ignore[misc]  # skips > 0: skip_to is set
                    break
                skips -= 1
        finally:
            self._firing = False
            self._prune()  # after a callback's error, the head may not be live yet
            if heap:
                self._arm(heap[0][0])
            else:
                self._armed = _NEVER


class Timer:
    """A periodic callback in a node's actor.  Create with ``Node.create_timer``."""

    __slots__ = (
        "node",
        "callback",
        "period",
        "clock",
        "_loop",
        "_deadlines",
        "_lane",
        "_start",
        "_k",
        "_when",
        "_canceled",
        "_last_call",
        "_checked",
        "_info_arg",
        "ticks",
        "__weakref__",
    )

    def __init__(
        self,
        node: Owner,
        period: float,
        callback: Callable[..., Any],
        deadlines: Deadlines,
        *,
        clock: Clock,
        autostart: bool = True,
    ) -> None:
        if not period > 0:
            raise ValueError(f"timer period must be > 0 seconds, got {period}")
        self.node = node
        self.callback = callback
        self.period = float(period)
        self.clock = clock
        self._loop: asyncio.AbstractEventLoop = node.loop
        self._deadlines = deadlines
        self._lane = deadlines.lane(self.period)
        self._when: float | None = None  # the deadline this timer waits for; None when not armed
        # The callback whose signature was last read, and its TimerInfo parameter (None: none).
        self._checked: Any = None
        self._info_arg: str | None = None
        self.ticks = 0
        self._last_call = self._start = self._loop.time()  # one float for both
        self._k = 1
        self._canceled = not autostart
        if autostart:
            self._deadlines.add(self._start + self.period, self)

    def _restart(self) -> None:
        self._start = start = self._loop.time()
        self._k = 1
        self._deadlines.add(start + self.period, self)

    def _disarm(self) -> None:
        if self._when is not None:
            self._when = None
            self._deadlines.discard()

    def _run(self) -> Awaitable[None] | None:
        if self._canceled:
            return None
        self.ticks += 1
        callback = self.callback
        self._last_call = self._loop.time()
        if callback is not self._checked:  # read the signature again only when the callback changes
            self._checked, self._info_arg = callback, _timer_info_parameter(callback)
        try:
            result = callback(**{self._info_arg: self._info()}) if self._info_arg else callback()
            if result is not None and isawaitable(result):
                return self._run_async(result)
        except Exception as exc:
            self._rearm()
            raise CallbackFailed(self, None, exc) from exc
        self._rearm()
        return None

    async def _run_async(self, pending: Awaitable[Any]) -> None:
        # An async callback: the next deadline is counted from when it returns.
        try:
            await pending
        except Exception as exc:
            raise CallbackFailed(self, None, exc) from exc
        finally:
            self._rearm()

    def _rearm(self) -> None:
        if not self._canceled and self._when is None:
            # Next deadline: the next multiple of the period, or after an overrun the first
            # one after now (the max() guards float rounding when now sits on a deadline).
            k = self._k + 1
            when = self._start + k * self.period
            now = self._loop.time()
            if when <= now:
                k = max(k, int((now - self._start) / self.period) + 1)
                when = self._start + k * self.period
            self._k = k
            self._deadlines.add(when, self)

    def _info(self) -> TimerInfo:
        actual = self.clock.now_ns()
        late = int(round((self._last_call - self.next_deadline) * _NS))
        return TimerInfo(
            expected_call_time=max(0, actual - late), actual_call_time=actual, clock_type=self.clock.clock_type
        )

    @property
    def timer_period_ns(self) -> int:
        """The period in nanoseconds, as rclpy's ``Timer.timer_period_ns``.

        Setting it changes the period from the tick already scheduled on: that
        tick keeps its time, the ones after it follow the new period.
        """
        return int(round(self.period * _NS))

    @timer_period_ns.setter
    def timer_period_ns(self, value: int) -> None:
        if not value > 0:
            raise ValueError(f"timer period must be > 0 ns, got {value}")
        self._start, self._k = self.next_deadline, 0  # re-anchored on the scheduled tick
        self.period = value / _NS
        self._lane = self._deadlines.lane(self.period)

    @property
    def next_deadline(self) -> float:
        """The loop time of the next tick, on the nanosecond grid (as :meth:`Deadlines.add` sets it)."""
        return round((self._start + self._k * self.period) * _NS_FLOAT) / _NS

    def time_until_next_call(self) -> int | None:
        """Nanoseconds until the next tick (negative when it is overdue), or None when canceled."""
        if self._canceled:
            return None
        return int(round((self.next_deadline - self._loop.time()) * _NS))

    def time_since_last_call(self) -> int:
        """Nanoseconds since the callback was last called (since the timer was made, before the first call)."""
        return int(round((self._loop.time() - self._last_call) * _NS))

    def is_ready(self) -> bool:
        """Whether a tick is due and its callback has not run yet."""
        return not self._canceled and self._loop.time() >= self.next_deadline

    def cancel(self) -> None:
        """Stop ticking until :meth:`reset`."""
        self._canceled = True
        self._disarm()

    def is_canceled(self) -> bool:
        """Whether the timer is canceled."""
        return self._canceled

    def reset(self) -> None:
        """Start over: the next tick comes one period from now (also starts a canceled or not started timer)."""
        self._disarm()
        self._canceled = False
        self._restart()

    def destroy(self) -> None:
        """Cancel the timer and remove it from its node."""
        self.node.destroy_timer(self)
