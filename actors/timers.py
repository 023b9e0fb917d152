"""Timers that fire on absolute deadlines: start + k * period, never drifting.

The first tick comes one period after creation, as in ROS.  A callback that
overruns (an ``async`` callback that awaits past its next deadline) skips the
ticks it missed instead of firing them in a burst: the next deadline is the
first multiple of the period after the callback returns.
"""

from __future__ import annotations

import asyncio
from collections.abc import Awaitable, Callable
from inspect import isawaitable
from typing import Any

from actors.actor import CallbackFailed, Owner

__all__ = ["Timer"]


class Timer:
    """A periodic callback in a node's actor.  Create with ``Node.create_timer``."""

    __slots__ = ("node", "callback", "period", "_loop", "_start", "_k", "_handle", "_canceled", "ticks")

    def __init__(self, node: Owner, period: float, callback: Callable[[], Any]) -> None:
        if not period > 0:
            raise ValueError(f"timer period must be > 0 seconds, got {period}")
        self.node = node
        self.callback = callback
        self.period = float(period)
        self._loop: asyncio.AbstractEventLoop = node.loop
        self._canceled = False
        self._handle: asyncio.TimerHandle | None = None
        self.ticks = 0
        self._restart()

    def _restart(self) -> None:
        self._start = self._loop.time()
        self._k = 1
        self._arm()

    def _arm(self) -> None:
        self._handle = self._loop.call_at(self._start + self._k * self.period, self._due)

    def _due(self) -> None:
        self._handle = None
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
        if not self._canceled and self._handle is None:
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
        if self._handle is not None:
            self._handle.cancel()
            self._handle = None

    def is_canceled(self) -> bool:
        """Whether the timer is canceled."""
        return self._canceled

    def reset(self) -> None:
        """Start over: the next tick comes one period from now (also revives a canceled timer)."""
        if self._handle is not None:
            self._handle.cancel()
        self._canceled = False
        self._restart()

    def destroy(self) -> None:
        """Cancel the timer and remove it from its node."""
        self.node.destroy_timer(self)
