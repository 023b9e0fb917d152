"""Timers that fire on absolute deadlines: start + k * period, never drifting.

The first tick comes one period after creation, as in ROS.  A callback that
overruns (an ``async`` callback that awaits past its next deadline) skips the
ticks it missed instead of firing them in a burst: the next deadline is the
first multiple of the period after the callback returns.

Every timer of a runtime waits in one :class:`Deadlines` heap under a single
loop timer, rather than in a loop timer of its own.  asyncio's ``TimerHandle``
orders its heap with a Python-level ``__lt__`` (about 0.1 µs a comparison,
log2(n) of them per push and per pop), which made the loop's heap a third of
a tick's cost with 10,000 timers; tuples compare in C.  Timers whose deadlines
have come when the loop timer fires all fire from it, so timers that share a
deadline (every node started in the same instant, under virtual time) cost one
loop timer between them.  Timers due together fire in the order they were armed.
"""

from __future__ import annotations

import asyncio
import itertools
from collections.abc import Awaitable, Callable
from heapq import heapify, heappop, heappush
from inspect import isawaitable
from typing import Any

from actors.actor import CallbackFailed, Owner

__all__ = ["Timer", "Deadlines"]

_COMPACT_AT = 64  # stale entries tolerated before the heap is rebuilt without them


class Deadlines:
    """The deadlines of a runtime's timers: a heap of ``(when, order, timer)`` under one loop timer.

    An entry is live while its timer still waits for that deadline
    (``timer._when == when``); a canceled or reset timer leaves a stale entry
    behind, skipped when it comes up and swept out once stale entries are the
    majority.  The loop timer is always armed for a live deadline, so virtual
    time never jumps to a deadline nobody waits for.
    """

    __slots__ = ("_loop", "_heap", "_handle", "_armed", "_order", "_stale")

    def __init__(self, loop: asyncio.AbstractEventLoop) -> None:
        self._loop = loop
        self._heap: list[tuple[float, int, Timer]] = []
        self._handle: asyncio.TimerHandle | None = None
        self._armed = float("inf")  # the deadline the loop timer is set for
        self._order = itertools.count()
        self._stale = 0

    def __len__(self) -> int:
        """Live deadlines waiting."""
        return len(self._heap) - self._stale

    def add(self, when: float, timer: Timer) -> None:
        """Fire ``timer._due()`` at loop time ``when``, unless ``timer._when`` changes first."""
        heappush(self._heap, (when, next(self._order), timer))
        if when < self._armed:
            self._arm(when)

    def discard(self) -> None:
        """Note that a timer stopped waiting for its deadline (its entry is now stale)."""
        self._stale += 1
        heap = self._heap
        if self._stale > _COMPACT_AT and self._stale * 2 > len(heap):
            self._heap = heap = [entry for entry in heap if entry[2]._when == entry[0]]
            heapify(heap)
            self._stale = 0
        self._prune()
        if not heap:
            self._disarm()
        elif heap[0][0] > self._armed:
            self._arm(heap[0][0])  # the head went stale: wait for the next live deadline

    def _prune(self) -> None:
        heap = self._heap
        while heap and heap[0][2]._when != heap[0][0]:
            heappop(heap)
            self._stale -= 1

    def _arm(self, when: float) -> None:
        if self._handle is not None:
            self._handle.cancel()
        self._handle = self._loop.call_at(when, self._fire)
        self._armed = when

    def _disarm(self) -> None:
        if self._handle is not None:
            self._handle.cancel()
            self._handle = None
        self._armed = float("inf")

    def _fire(self) -> None:
        # Everything due by now, and at least what the loop timer was set for (the loop
        # may run a timer a clock-resolution early).
        limit = max(self._loop.time(), self._armed)
        self._handle = None
        self._armed = float("inf")
        heap = self._heap
        while heap and heap[0][0] <= limit:
            when, _, timer = heappop(heap)
            if timer._when == when:
                timer._due()
            else:
                self._stale -= 1
        self._prune()
        if heap:
            self._arm(heap[0][0])


class Timer:
    """A periodic callback in a node's actor.  Create with ``Node.create_timer``."""

    __slots__ = (
        "node",
        "callback",
        "period",
        "_loop",
        "_deadlines",
        "_start",
        "_k",
        "_when",
        "_canceled",
        "ticks",
        "__weakref__",
    )

    def __init__(self, node: Owner, period: float, callback: Callable[[], Any], deadlines: Deadlines) -> None:
        if not period > 0:
            raise ValueError(f"timer period must be > 0 seconds, got {period}")
        self.node = node
        self.callback = callback
        self.period = float(period)
        self._loop: asyncio.AbstractEventLoop = node.loop
        self._deadlines = deadlines
        self._canceled = False
        self._when: float | None = None  # the deadline this timer waits for; None when not armed
        self.ticks = 0
        self._restart()

    def _restart(self) -> None:
        self._start = self._loop.time()
        self._k = 1
        self._arm()

    def _arm(self) -> None:
        when = self._start + self._k * self.period
        self._when = when
        self._deadlines.add(when, self)

    def _disarm(self) -> None:
        if self._when is not None:
            self._when = None
            self._deadlines.discard()

    def _due(self) -> None:
        self._when = None
        self.node.actor.schedule(self)

    def _run(self) -> Awaitable[None] | None:
        if self._canceled:
            return None
        self.ticks += 1
        try:
            result = self.callback()
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
            # Next deadline: the first multiple of the period after now.  The
            # max() guards float rounding when now sits exactly on a deadline.
            elapsed = self._loop.time() - self._start
            self._k = max(self._k + 1, int(elapsed / self.period) + 1)
            self._arm()

    @property
    def timer_period_ns(self) -> int:
        """The period in nanoseconds, as rclpy's ``Timer.timer_period_ns``."""
        return int(round(self.period * 1e9))

    @property
    def next_deadline(self) -> float:
        """The loop time of the next tick."""
        return self._start + self._k * self.period

    def time_until_next_call(self) -> float | None:
        """Seconds until the next tick, or None when canceled."""
        if self._canceled:
            return None
        return max(0.0, self.next_deadline - self._loop.time())

    def cancel(self) -> None:
        """Stop ticking until :meth:`reset`."""
        self._canceled = True
        self._disarm()

    def is_canceled(self) -> bool:
        """Whether the timer is canceled."""
        return self._canceled

    def reset(self) -> None:
        """Start over: the next tick comes one period from now (also revives a canceled timer)."""
        self._disarm()
        self._canceled = False
        self._restart()

    def destroy(self) -> None:
        """Cancel the timer and remove it from its node."""
        self.node.destroy_timer(self)
