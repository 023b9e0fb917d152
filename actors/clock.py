"""Time for nodes: Time, Duration, Clock, Rate, and the virtual-time event loop.

Every timestamp in actors comes from the running event loop's ``time()`` plus an
epoch offset fixed when the runtime starts.  On an ordinary loop that is the wall
clock; on :class:`VirtualTimeLoop` it is virtual time, which starts at 0 and jumps
to the next timer whenever nothing is ready, so an hour of robot time costs
milliseconds.  Keeping the epoch separate matters: a float near 1.7e9 seconds has
only ~0.2 µs of resolution, too coarse for timers that must land on multiples of
their period.

The virtual loop never jumps while work is pending in an executor or in anyio's
worker threads (that work runs in real time), and it turns a wait on nothing
(no timer, no I/O, no thread) into :class:`~actors.errors.VirtualTimeDeadlock`
after ``idle_timeout`` real seconds, instead of hanging.
"""

from __future__ import annotations

import asyncio
import selectors
import time
from typing import Any

from actors.errors import VirtualTimeDeadlock

__all__ = ["Time", "Duration", "Clock", "Rate", "VirtualTimeLoop", "precise_loop"]

_NS = 1_000_000_000


class _Nanoseconds:
    """An integer count of nanoseconds, built from ``seconds`` and/or ``nanoseconds``."""

    __slots__ = ("nanoseconds",)

    def __init__(self, *, seconds: float = 0, nanoseconds: int = 0) -> None:
        self.nanoseconds = int(round(seconds * _NS)) + int(nanoseconds)

    def __repr__(self) -> str:
        return f"{type(self).__name__}(nanoseconds={self.nanoseconds})"

    def __eq__(self, other: object) -> bool:
        return type(other) is type(self) and other.nanoseconds == self.nanoseconds  # type: ignore[attr-defined]

    def __lt__(self, other: _Nanoseconds) -> bool:
        return self.nanoseconds < other.nanoseconds

    def __le__(self, other: _Nanoseconds) -> bool:
        return self.nanoseconds <= other.nanoseconds

    def __hash__(self) -> int:
        return hash((type(self).__name__, self.nanoseconds))

    def seconds_nanoseconds(self) -> tuple[int, int]:
        """``(sec, nanosec)``, as ``builtin_interfaces`` messages hold them."""
        return divmod(self.nanoseconds, _NS)


class Duration(_Nanoseconds):
    """A span of time in integer nanoseconds, as ``rclpy.duration.Duration``."""

    __slots__ = ()

    def to_msg(self) -> Any:
        """This duration as a ``builtin_interfaces/msg/Duration``."""
        from interfaces.builtin_interfaces.msg import Duration as DurationMsg

        sec, nanosec = self.seconds_nanoseconds()
        return DurationMsg(sec=sec, nanosec=nanosec)


class Time(_Nanoseconds):
    """A point in time in integer nanoseconds since the clock's epoch, as ``rclpy.time.Time``."""

    __slots__ = ()

    def __sub__(self, other: Time | Duration) -> Any:
        if isinstance(other, Time):
            return Duration(nanoseconds=self.nanoseconds - other.nanoseconds)
        return Time(nanoseconds=self.nanoseconds - other.nanoseconds)

    def __add__(self, other: Duration) -> Time:
        return Time(nanoseconds=self.nanoseconds + other.nanoseconds)

    def to_msg(self) -> Any:
        """This time as a ``builtin_interfaces/msg/Time``."""
        from interfaces.builtin_interfaces.msg import Time as TimeMsg

        sec, nanosec = self.seconds_nanoseconds()
        return TimeMsg(sec=sec, nanosec=nanosec)


class Clock:
    """The runtime's clock: the loop's time plus an epoch fixed at start.

    On a :class:`VirtualTimeLoop` the epoch is the loop's ``epoch`` (0 by default,
    like simulated time in ROS), so runs are reproducible; otherwise it is the
    wall clock's offset from the loop's monotonic time, read once.
    """

    __slots__ = ("_loop", "_epoch_ns")

    def __init__(self, loop: asyncio.AbstractEventLoop) -> None:
        self._loop = loop
        if isinstance(loop, VirtualTimeLoop):
            self._epoch_ns = int(round(loop.epoch * _NS))
        else:
            # The one place actors reads the wall clock: to anchor loop time to the epoch.
            self._epoch_ns = time.time_ns() - int(round(loop.time() * _NS))

    @property
    def virtual(self) -> bool:
        """Whether this clock runs on virtual time."""
        return isinstance(self._loop, VirtualTimeLoop)

    def now_ns(self) -> int:
        """Nanoseconds since the epoch, now."""
        return self._epoch_ns + int(round(self._loop.time() * _NS))

    def now(self) -> Time:
        """The current time, as ``rclpy``'s ``Clock.now()``."""
        return Time(nanoseconds=self.now_ns())

    def monotonic(self) -> float:
        """The loop's time in seconds: what timers and deadlines are measured in."""
        return self._loop.time()


class Rate:
    """Sleeps until the next multiple of ``1 / frequency`` since creation (no drift).

    ``await rate.sleep()`` returns at the next deadline; if the caller is late by
    more than a period, the missed deadlines are skipped rather than replayed.
    Cancelling the sleep cancels only that wait.
    """

    __slots__ = ("_loop", "_period", "_start", "_k")

    def __init__(self, frequency: float, loop: asyncio.AbstractEventLoop) -> None:
        if frequency <= 0:
            raise ValueError(f"rate frequency must be > 0 Hz, got {frequency}")
        self._loop = loop
        self._period = 1.0 / frequency
        self._start = loop.time()
        self._k = 0

    async def sleep(self) -> None:
        """Wait for the next deadline."""
        loop = self._loop
        self._k = max(self._k + 1, int((loop.time() - self._start) / self._period) + 1)
        # One loop timer on the absolute deadline (asyncio.sleep would re-read the clock
        # and add the delay to a later "now").
        future = loop.create_future()
        timer = loop.call_at(self._start + self._k * self._period, _wake, future)
        try:
            await future
        finally:
            timer.cancel()


def _wake(future: asyncio.Future[None]) -> None:
    if not future.done():
        future.set_result(None)


def precise_loop() -> asyncio.AbstractEventLoop:
    """A wall-clock asyncio loop whose waits have microsecond precision.

    asyncio's default loop on Linux waits in ``epoll_wait``, which takes whole
    milliseconds and rounds every wait up, so a 1 kHz timer lands up to 1 ms
    late (p99 1.16 ms in BENCHMARKS.md).  ``select()`` takes microseconds (p99
    0.31 ms).  Its limits (file descriptors below 1024, a scan per wait) do not
    matter for a graph, which watches a handful: the control socket and its
    clients.  ``python -m actors.run`` uses this loop on the wall clock.
    """
    return asyncio.SelectorEventLoop(selectors.SelectSelector())


class _JumpingSelector(selectors.DefaultSelector):
    """The selector of :class:`VirtualTimeLoop`: polls I/O, then jumps instead of sleeping."""

    def __init__(self, loop: VirtualTimeLoop) -> None:
        super().__init__()
        self._vloop = loop

    def select(self, timeout: float | None = None) -> list[tuple[selectors.SelectorKey, int]]:
        events = super().select(0)
        if events or timeout == 0:
            return events
        loop = self._vloop
        if loop.threads_busy():
            # Real work is running in a thread: wait for it in real time.
            return super().select(timeout)
        if timeout is not None:
            loop._jump()
            return events
        # No timer at all: only real I/O could still wake anything.
        events = super().select(loop.idle_timeout)
        if not events and not loop.threads_busy():
            raise VirtualTimeDeadlock(
                f"virtual time is idle: no timer is scheduled and nothing happened for "
                f"{loop.idle_timeout} s of real time, so every task waits forever "
                f"(an event nobody sets, a queue nobody feeds?)"
            )
        return events


class VirtualTimeLoop(asyncio.SelectorEventLoop):
    """An asyncio event loop whose clock jumps to the next timer when nothing is ready.

    Use it anywhere a loop factory is taken::

        anyio.run(main, backend_options={"loop_factory": VirtualTimeLoop})
        asyncio.Runner(loop_factory=VirtualTimeLoop).run(main())

    ``time()`` starts at 0.0.  ``epoch`` is the wall-clock time (seconds since the
    Unix epoch) that virtual time 0 stands for in timestamps; it defaults to 0,
    like simulated time in ROS.  Raises :class:`~actors.errors.VirtualTimeDeadlock`
    out of ``run_*`` when no timer, I/O or thread could ever wake a task and
    ``idle_timeout`` real seconds pass with nothing happening.
    """

    def __init__(self, *, epoch: float = 0.0, idle_timeout: float = 5.0) -> None:
        self._now = 0.0
        self._executor_jobs = 0
        self.epoch = epoch
        self.idle_timeout = idle_timeout
        super().__init__(selector=_JumpingSelector(self))

    def time(self) -> float:
        return self._now

    def _jump(self) -> None:
        # Land exactly on the earliest deadline, not on now + (when - now), which
        # float rounding can leave a hair short of it.
        scheduled = self._scheduled  # the base loop's heap of TimerHandles
        if scheduled and scheduled[0].when() > self._now:
            self._now = scheduled[0].when()

    def advance(self, seconds: float) -> None:
        """Move virtual time forward by ``seconds`` at once (timers due run next)."""
        if seconds < 0:
            raise ValueError("virtual time cannot go backwards")
        self._now += seconds

    def run_in_executor(self, executor: Any, func: Any, *args: Any) -> asyncio.Future[Any]:
        future = super().run_in_executor(executor, func, *args)
        self._executor_jobs += 1
        future.add_done_callback(self._executor_job_done)
        return future

    def _executor_job_done(self, _future: asyncio.Future[Any]) -> None:
        self._executor_jobs -= 1

    def threads_busy(self) -> bool:
        """Whether executor jobs or anyio worker-thread calls are still running."""
        return self._executor_jobs > 0 or _anyio_threads_busy(self)


def _anyio_threads_busy(loop: asyncio.AbstractEventLoop) -> bool:
    # anyio runs ``to_thread.run_sync`` in its own workers, outside run_in_executor,
    # holding a token of the loop's default limiter while the call runs.  anyio has
    # no public way to ask this from outside a task, so read its per-loop run vars;
    # tests/test_clock.py fails if that ever stops working.
    try:
        from anyio._backends._asyncio import _default_thread_limiter
        from anyio.lowlevel import _run_vars
    except ImportError:  # pragma: no cover - a future anyio
        return False
    limiter = _run_vars.get(loop, {}).get(_default_thread_limiter)
    return limiter is not None and limiter.borrowed_tokens > 0
