"""Time for nodes: Time, Duration, Clock, Rate, and the virtual-time event loop.

Time and Duration behave as rclpy's: integer nanoseconds, ``Time ± Duration``,
``Time - Time -> Duration``, ``Duration * n``, comparisons only between like
types (and Times only of the same clock type), a Time is never negative.

The runtime's clock is a :class:`ROSClock` on the running event loop: its time
is the loop's ``time()`` plus an epoch offset fixed when the runtime starts.
On an ordinary loop that is the wall clock; on :class:`VirtualTimeLoop` it is
virtual time, which starts at 0 and jumps to the next timer whenever nothing is
ready, so an hour of robot time costs milliseconds.  Virtual time plays the part
of ROS's simulated time (``use_sim_time``): ``ros_time_is_active`` is true on it.
Keeping the epoch separate matters: a float near 1.7e9 seconds has only ~0.2 µs
of resolution, too coarse for timers that must land on multiples of their period.
A ``Clock(clock_type=SYSTEM_TIME)`` or ``STEADY_TIME`` made by user code reads the
system clock, as in ROS, where those clocks ignore simulated time.

The virtual loop never jumps while work is pending in an executor or in anyio's
worker threads (that work runs in real time), and it turns a wait on nothing
(no timer, no I/O, no thread) into :class:`~actors.errors.VirtualTimeDeadlock`
after ``idle_timeout`` real seconds, instead of hanging.
"""

from __future__ import annotations

import asyncio
import math
import selectors
import time
import weakref
from collections.abc import Callable
from contextvars import copy_context
from enum import IntEnum
from heapq import heapify, heappop, heappush
from typing import Any

from actors.errors import VirtualTimeDeadlock

__all__ = [
    "ClockType",
    "Time",
    "Duration",
    "Infinite",
    "Clock",
    "ROSClock",
    "Rate",
    "VirtualTimeLoop",
    "loop_clock",
    "precise_loop",
    "uvloop_loop",
    "WALL_LOOPS",
]

_NS = 1_000_000_000
_MAX_NS = 2**63  # nanoseconds are C int64s in ROS: Time and Duration stay below this


class ClockType(IntEnum):
    """Which clock a Time comes from (values as ``rcl``'s)."""

    UNINITIALIZED = 0
    ROS_TIME = 1
    SYSTEM_TIME = 2
    STEADY_TIME = 3


def _total_ns(seconds: float, nanoseconds: float) -> int:
    # Rounded to the nearest nanosecond: rclpy truncates, which turns 1.001 s into 1000999999 ns.
    return int(round(seconds * _NS)) + int(round(nanoseconds))


def _ros_type(msg: Any) -> str | None:
    return getattr(type(msg), "__ros_type__", None)


class Duration:
    """A span of time in integer nanoseconds (may be negative), as ``rclpy.duration.Duration``.

    Raises OverflowError outside a signed 64-bit count of nanoseconds.
    """

    __slots__ = ("_ns",)

    def __init__(self, *, seconds: float = 0, nanoseconds: float = 0) -> None:
        total = _total_ns(seconds, nanoseconds)
        if not -_MAX_NS <= total < _MAX_NS:
            raise OverflowError(f"a Duration of {total} ns does not fit in 64 bits")
        self._ns = total

    @property
    def nanoseconds(self) -> int:
        """The span in nanoseconds."""
        return self._ns

    def __repr__(self) -> str:
        return f"Duration(nanoseconds={self._ns})"

    def __str__(self) -> str:
        return "Infinite" if self._ns == _MAX_NS - 1 else f"{self._ns} nanoseconds"

    def __add__(self, other: object) -> Duration:
        if isinstance(other, Duration):
            return Duration(nanoseconds=self._ns + other._ns)
        return NotImplemented

    def __sub__(self, other: object) -> Duration:
        if isinstance(other, Duration):
            return Duration(nanoseconds=self._ns - other._ns)
        return NotImplemented

    def __mul__(self, factor: object) -> Duration:
        if isinstance(factor, bool) or not isinstance(factor, (int, float)):
            return NotImplemented
        if isinstance(factor, float) and not math.isfinite(factor):
            if factor == math.inf:
                return Infinite
            raise ValueError(f"cannot multiply a Duration by {factor}")
        return Duration(nanoseconds=self._ns * factor if isinstance(factor, int) else int(self._ns * factor))

    def __eq__(self, other: object) -> bool:
        return self._ns == other._ns if isinstance(other, Duration) else NotImplemented

    def __lt__(self, other: object) -> bool:
        return self._ns < other._ns if isinstance(other, Duration) else NotImplemented

    def __le__(self, other: object) -> bool:
        return self._ns <= other._ns if isinstance(other, Duration) else NotImplemented

    def __gt__(self, other: object) -> bool:
        return self._ns > other._ns if isinstance(other, Duration) else NotImplemented

    def __ge__(self, other: object) -> bool:
        return self._ns >= other._ns if isinstance(other, Duration) else NotImplemented

    def __hash__(self) -> int:
        return hash(("Duration", self._ns))

    def seconds_nanoseconds(self) -> tuple[int, int]:
        """``(sec, nanosec)``, as ``builtin_interfaces`` messages hold them."""
        return divmod(self._ns, _NS)

    def to_msg(self) -> Any:
        """This duration as a ``builtin_interfaces/msg/Duration``."""
        from interfaces.builtin_interfaces.msg import Duration as DurationMsg

        sec, nanosec = self.seconds_nanoseconds()
        return DurationMsg(sec=sec, nanosec=nanosec)

    @classmethod
    def from_msg(cls, msg: Any) -> Duration:
        """A Duration from a ``builtin_interfaces/msg/Duration``; TypeError for anything else."""
        if _ros_type(msg) != "builtin_interfaces/msg/Duration":
            raise TypeError(f"Duration.from_msg takes a builtin_interfaces/msg/Duration, got {msg!r}")
        return cls(seconds=msg.sec, nanoseconds=msg.nanosec)


Infinite = Duration(nanoseconds=_MAX_NS - 1)
"""The longest Duration (``RMW_DURATION_INFINITE``): QoS durations that never expire."""


_TimeMsg: Any = None  # builtin_interfaces/msg/Time, imported at the first Time.to_msg()


class Time:
    """A point in time: nanoseconds since its clock's epoch and the clock's type, as ``rclpy.time.Time``.

    Raises ValueError for negative seconds or nanoseconds, OverflowError from
    2**63 ns on, TypeError when ``clock_type`` is not a :class:`ClockType`.
    Times compare and subtract only with Times of the same clock type
    (TypeError otherwise); ``Time + Time`` and ``Time < Duration`` are TypeErrors.
    """

    __slots__ = ("_ns", "_clock_type")

    def __init__(
        self, *, seconds: float = 0, nanoseconds: float = 0, clock_type: ClockType = ClockType.SYSTEM_TIME
    ) -> None:
        if not isinstance(clock_type, ClockType):
            raise TypeError(f"clock_type must be a ClockType, got {clock_type!r}")
        if seconds < 0:
            raise ValueError(f"a Time cannot have negative seconds ({seconds})")
        if nanoseconds < 0:
            raise ValueError(f"a Time cannot have negative nanoseconds ({nanoseconds})")
        total = _total_ns(seconds, nanoseconds)
        if total >= _MAX_NS:
            raise OverflowError(f"a Time of {total} ns does not fit in 64 bits")
        self._ns = total
        self._clock_type = clock_type

    @property
    def nanoseconds(self) -> int:
        """Nanoseconds since the clock's epoch."""
        return self._ns

    @property
    def clock_type(self) -> ClockType:
        """The type of clock this time comes from."""
        return self._clock_type

    def __repr__(self) -> str:
        return f"Time(nanoseconds={self._ns}, clock_type={self._clock_type.name})"

    def _same_clock(self, other: Time, doing: str) -> None:
        if other._clock_type != self._clock_type:
            raise TypeError(
                f"cannot {doing} Times of different clock types "
                f"({self._clock_type.name} and {other._clock_type.name})"
            )

    def __add__(self, other: object) -> Time:
        if isinstance(other, Duration):
            try:
                return Time(nanoseconds=self._ns + other.nanoseconds, clock_type=self._clock_type)
            except ValueError:
                raise ValueError(f"{self!r} + {other!r} is before the clock's epoch") from None
        return NotImplemented

    __radd__ = __add__

    def __sub__(self, other: object) -> Any:
        if isinstance(other, Time):
            self._same_clock(other, "subtract")
            return Duration(nanoseconds=self._ns - other._ns)
        if isinstance(other, Duration):
            try:
                return Time(nanoseconds=self._ns - other.nanoseconds, clock_type=self._clock_type)
            except ValueError:
                raise ValueError(f"{self!r} - {other!r} is before the clock's epoch") from None
        return NotImplemented

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Time):
            return NotImplemented
        self._same_clock(other, "compare")
        return self._ns == other._ns

    def __lt__(self, other: object) -> bool:
        if not isinstance(other, Time):
            return NotImplemented
        self._same_clock(other, "compare")
        return self._ns < other._ns

    def __le__(self, other: object) -> bool:
        if not isinstance(other, Time):
            return NotImplemented
        self._same_clock(other, "compare")
        return self._ns <= other._ns

    def __gt__(self, other: object) -> bool:
        if not isinstance(other, Time):
            return NotImplemented
        self._same_clock(other, "compare")
        return self._ns > other._ns

    def __ge__(self, other: object) -> bool:
        if not isinstance(other, Time):
            return NotImplemented
        self._same_clock(other, "compare")
        return self._ns >= other._ns

    def __hash__(self) -> int:
        return hash((self._clock_type, self._ns))

    def seconds_nanoseconds(self) -> tuple[int, int]:
        """``(sec, nanosec)``, as ``builtin_interfaces`` messages hold them."""
        return divmod(self._ns, _NS)

    def to_msg(self) -> Any:
        """This time as a ``builtin_interfaces/msg/Time``."""
        global _TimeMsg
        if _TimeMsg is None:  # imported once, not on every stamp (an import statement costs 0.4 µs)
            from interfaces.builtin_interfaces.msg import Time as _TimeMsg
        sec, nanosec = divmod(self._ns, _NS)
        return _TimeMsg(sec=sec, nanosec=nanosec)

    @classmethod
    def from_msg(cls, msg: Any, clock_type: ClockType = ClockType.ROS_TIME) -> Time:
        """A Time (ROS time unless told) from a ``builtin_interfaces/msg/Time``; TypeError for anything else."""
        if _ros_type(msg) != "builtin_interfaces/msg/Time":
            raise TypeError(f"Time.from_msg takes a builtin_interfaces/msg/Time, got {msg!r}")
        return cls(seconds=msg.sec, nanoseconds=msg.nanosec, clock_type=clock_type)


_new_time = object.__new__


class Clock:
    """A source of :class:`Time`, as ``rclpy.clock.Clock``: ``Clock(clock_type=...)``.

    ``SYSTEM_TIME`` reads the system's wall clock and ``STEADY_TIME`` its
    monotonic clock, in real time even on a virtual-time loop (as ROS's ignore
    simulated time).  ``Clock(clock_type=ClockType.ROS_TIME)`` makes a
    :class:`ROSClock`.  Raises TypeError when ``clock_type`` is not a ClockType.
    """

    __slots__ = ("_clock_type",)

    def __new__(cls, *args: Any, clock_type: ClockType = ClockType.SYSTEM_TIME, **kwargs: Any) -> Clock:
        if not isinstance(clock_type, ClockType):
            raise TypeError(f"clock_type must be a ClockType, got {clock_type!r}")
        if cls is Clock and clock_type is ClockType.ROS_TIME:
            cls = ROSClock
        return super().__new__(cls)

    def __init__(self, *, clock_type: ClockType = ClockType.SYSTEM_TIME) -> None:
        self._clock_type = clock_type

    @property
    def clock_type(self) -> ClockType:
        """The type of this clock."""
        return self._clock_type

    def __repr__(self) -> str:
        return f"{type(self).__name__}(clock_type={self._clock_type.name})"

    def now_ns(self) -> int:
        """Nanoseconds since this clock's epoch, now."""
        # The system clocks, read only when user code asks for them by type.
        return time.monotonic_ns() if self._clock_type is ClockType.STEADY_TIME else time.time_ns()

    def now(self) -> Time:
        """The current time of this clock."""
        ns = self.now_ns()
        if type(ns) is not int or not 0 <= ns < _MAX_NS:
            return Time(nanoseconds=ns, clock_type=self._clock_type)  # converts, or raises naming it
        # A valid count of nanoseconds: made without Time.__init__'s checks (a stamp per message).
        now = _new_time(Time)
        now._ns = ns
        now._clock_type = self._clock_type
        return now


class ROSClock(Clock):
    """ROS time: the clock of a runtime (``node.get_clock()``), as ``rclpy.clock.ROSClock``.

    Bound to an event loop (the runtime makes one per graph), its time is the
    loop's time plus an epoch: on a :class:`VirtualTimeLoop` the loop's
    ``epoch`` (0 by default, like simulated time in ROS), so runs are
    reproducible, and ``ros_time_is_active`` is true; otherwise the wall clock's
    offset from the loop's monotonic time, read once.  Unbound (``ROSClock()``),
    it reads the system clock until ROS time is set active, as rclpy's does.
    """

    __slots__ = ("_loop", "_epoch_ns", "_override_active", "_override_ns")

    def __init__(self, loop: asyncio.AbstractEventLoop | None = None, *,
                 clock_type: ClockType = ClockType.ROS_TIME) -> None:
        # ``clock_type`` is taken only so that ``Clock(clock_type=ROS_TIME)`` can build one.
        super().__init__(clock_type=ClockType.ROS_TIME)
        self._loop = loop
        self._override_active = False
        self._override_ns = 0
        if loop is None:
            self._epoch_ns = 0
        elif isinstance(loop, VirtualTimeLoop):
            self._epoch_ns = int(round(loop.epoch * _NS))
        else:
            # The one place actors reads the wall clock: to anchor loop time to the epoch.
            self._epoch_ns = time.time_ns() - int(round(loop.time() * _NS))

    @property
    def virtual(self) -> bool:
        """Whether this clock runs on virtual time."""
        return isinstance(self._loop, VirtualTimeLoop)

    @property
    def ros_time_is_active(self) -> bool:
        """Whether this clock follows simulated time: virtual time, or a time set by hand."""
        return self._override_active or self.virtual

    def _set_ros_time_is_active(self, enabled: bool) -> None:
        # As rclpy's: for whoever drives this clock by hand (a time source, a test).
        self._override_active = enabled

    def set_ros_time_override(self, time_: Time) -> None:
        """Set the time this clock reports while ROS time is set active by hand."""
        if not isinstance(time_, Time):
            raise TypeError(f"set_ros_time_override takes a Time, got {time_!r}")
        self._override_ns = time_.nanoseconds

    def now_ns(self) -> int:
        """Nanoseconds since the epoch, now."""
        if self._override_active:
            return self._override_ns
        if self._loop is None:
            return time.time_ns()
        return self._epoch_ns + int(round(self._loop.time() * _NS))

    def monotonic(self) -> float:
        """The loop's time in seconds: what timers and deadlines are measured in."""
        if self._loop is None:
            raise RuntimeError("an unbound ROSClock has no loop time; use a runtime's clock")
        return self._loop.time()

    async def sleep_for(self, rel_time: Duration) -> bool:
        """Wait ``rel_time`` on this clock (virtual time on a virtual loop); True when done."""
        await asyncio.sleep(max(0.0, rel_time.nanoseconds / _NS))
        return True

    async def sleep_until(self, until: Time) -> bool:
        """Wait until this clock reads ``until``; ValueError for a Time of another clock type."""
        if until.clock_type != self._clock_type:
            raise ValueError(f"sleep_until takes a {self._clock_type.name} Time, got {until!r}")
        return await self.sleep_for(Duration(nanoseconds=until.nanoseconds - self.now_ns()))


class Rate:
    """Sleeps until the next multiple of ``1 / frequency`` since creation (no drift).

    ``await rate.sleep()`` returns at the next deadline; if the caller is late by
    more than a period, the missed deadlines are skipped rather than replayed.
    Cancelling the sleep cancels only that wait.  :meth:`destroy` wakes every
    sleeper; sleeping on a destroyed rate raises RuntimeError, as in rclpy.
    """

    __slots__ = ("_loop", "_period", "_start", "_k", "_sleepers", "_destroyed")

    def __init__(self, frequency: float, loop: asyncio.AbstractEventLoop) -> None:
        if frequency <= 0:
            raise ValueError(f"rate frequency must be > 0 Hz, got {frequency}")
        self._loop = loop
        self._period = 1.0 / frequency
        self._start = loop.time()
        self._k = 0
        self._sleepers: set[asyncio.Future[None]] = set()
        self._destroyed = False

    async def sleep(self) -> None:
        """Wait for the next deadline; RuntimeError if the rate is destroyed."""
        if self._destroyed:
            raise RuntimeError("this Rate was destroyed: it cannot sleep any more")
        now = self._loop.time()
        self._k = max(self._k + 1, int((now - self._start) / self._period) + 1)
        # One loop timer on the absolute deadline (asyncio.sleep would re-read the clock
        # and add the delay to a later "now").
        woken: asyncio.Future[None] = self._loop.create_future()
        handle = self._loop.call_at(self._start + self._k * self._period, _wake, woken)
        self._sleepers.add(woken)
        try:
            await woken
        finally:
            handle.cancel()
            self._sleepers.discard(woken)

    def destroy(self) -> None:
        """Wake every sleeper now; later sleeps raise RuntimeError."""
        self._destroyed = True
        for woken in self._sleepers:
            _wake(woken)


def _wake(future: asyncio.Future[None]) -> None:
    if not future.done():
        future.set_result(None)


def loop_clock(loop: asyncio.AbstractEventLoop) -> Callable[[], float]:
    """What tells ``loop.time()`` cheapest: ``time.monotonic`` itself on asyncio's own loops.

    Called directly it costs half of ``loop.time()``, a Python method around
    it.  Loops that keep their own time (virtual time, uvloop) give their ``time``.
    """
    return time.monotonic if type(loop).time is asyncio.BaseEventLoop.time else loop.time


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


def uvloop_loop() -> asyncio.AbstractEventLoop:
    """A uvloop event loop (the ``fast`` extra: ``pip install 'actors[fast]'``), for the wall clock only.

    Faster per wake-up than asyncio's loops (BENCHMARKS.md shows both), but
    its clock counts whole milliseconds: ``loop.time()`` is libuv's time,
    read once per loop iteration, so a timer's deadlines start from a
    millisecond-rounded time and fire up to a millisecond late, and stamps
    taken within one iteration are equal.  Fine for 10-100 Hz control loops;
    use :func:`precise_loop` for kHz timers.  Virtual time stays on
    :class:`VirtualTimeLoop`.  Raises ImportError with the install hint when
    uvloop is missing.
    """
    try:
        import uvloop
    except ImportError:
        raise ImportError("uvloop is not installed: pip install 'actors[fast]'") from None
    return uvloop.new_event_loop()


#: The wall-clock loops ``python -m actors.run --loop NAME`` offers, by name.
WALL_LOOPS: dict[str, Callable[[], asyncio.AbstractEventLoop]] = {
    "select": precise_loop,
    "asyncio": asyncio.new_event_loop,
    "uvloop": uvloop_loop,
}


_new_handle = object.__new__
# The fields asyncio's Handle and TimerHandle have (3.11 to 3.13): call_at and call_soon fill them
# in directly; a Python whose handles differ gets asyncio's own constructors.
_LEAN_HANDLES = set(asyncio.Handle.__slots__) == {
    "_callback", "_args", "_cancelled", "_loop", "_source_traceback", "_repr", "__weakref__", "_context"
} and set(asyncio.TimerHandle.__slots__) == {"_scheduled", "_when"}


def _handle(cls: type, callback: Callable[..., object], args: tuple[Any, ...], loop: VirtualTimeLoop,
            context: Any) -> Any:
    # Handle.__init__ outside debug mode, filled in by one call instead of two (TimerHandle's and Handle's).
    handle = _new_handle(cls)
    handle._callback = callback
    handle._args = args
    handle._cancelled = False
    handle._loop = loop
    handle._source_traceback = None
    handle._repr = None
    handle._context = copy_context() if context is None else context
    return handle


_MAX_WAIT = 24 * 3600.0  # asyncio's longest wait in one select (MAXIMUM_SELECT_TIMEOUT)
_MIN_SCHEDULED = 100  # asyncio's: below this many timers, cancelled ones are only popped at the head


class _JumpingSelector(selectors.DefaultSelector):
    """The selector of :class:`VirtualTimeLoop`: polls I/O, then jumps instead of sleeping."""

    def __init__(self, loop: VirtualTimeLoop) -> None:
        super().__init__()
        self._vloop = loop
        # epoll says whether anything is ready in one C call (it is level-triggered: what it
        # saw is still there for select()), where select() spends a microsecond in Python.
        self._peek = self._selector.poll if isinstance(self, selectors.EpollSelector) else None
        # Whether a descriptor besides the loop's self-pipe is watched, kept by register and
        # unregister: VirtualTimeLoop.skip_to asks it before every jump (a physics step's).
        self.watching = False

    def register(self, fileobj: Any, events: int, data: Any = None) -> selectors.SelectorKey:
        key = super().register(fileobj, events, data)
        self.watching = len(self._fd_to_key) > 1
        return key

    def unregister(self, fileobj: Any) -> selectors.SelectorKey:
        key = super().unregister(fileobj)
        self.watching = len(self._fd_to_key) > 1
        return key

    def select(self, timeout: float | None = None) -> list[tuple[selectors.SelectorKey, int]]:
        peek = self._peek
        if timeout == 0:
            return super().select(0) if peek is None or peek(0, 1) else []
        loop = self._vloop
        # Ask the threads before polling: a thread hands its work over (call_soon_threadsafe
        # writes the self-pipe) before it goes idle, so once none is busy, the poll below sees
        # all they handed over.  Polled first, a hand-off between the poll and the question
        # would be missed and time would jump past the work it brings.
        busy = loop.threads_busy()
        if peek is None or self.watching or loop._signal_handlers:
            if peek is None or peek(0, 1):  # real I/O, or a signal's byte in the self-pipe
                events = super().select(0)
                if events:
                    return events
        elif loop._ready:
            # The self-pipe alone is watched, and no signal writes to it: only threads do, and
            # call_soon_threadsafe queues the callback before it writes.  So a thread's hand-over
            # shows in the ready queue (read it, no jump) and an empty queue means nothing to
            # read: no system call (with the GIL let go and taken back) on every jump.
            return super().select(0)
        if busy:
            # Real work is running in a thread: wait for it in real time (looking again after
            # busy_poll, when set, for threads that stop being busy without waking the loop).
            poll = loop.busy_poll
            if poll is not None and (timeout is None or timeout > poll):
                timeout = poll
            return super().select(timeout)
        if timeout is not None:
            # Land exactly on the earliest deadline, not on now + (when - now), which float
            # rounding can leave a hair short of it.
            scheduled = loop._scheduled  # the base loop's heap of TimerHandles
            if scheduled and scheduled[0]._when > loop._now:
                loop._now = scheduled[0]._when
            return []
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

    Its iterations, ``call_at`` and ``call_soon`` are asyncio's specialised to
    virtual time (tests/test_virtual_loop.py runs the same programs on asyncio's
    own code and compares): a simulation spends most of its loop iterations on
    one timer each, and asyncio's generic iteration cost as much as a physics
    step.  In debug mode the loop takes asyncio's own code (slow-callback warnings).
    """

    def __init__(self, *, epoch: float = 0.0, idle_timeout: float = 5.0) -> None:
        # Five attributes beside asyncio's 24: CPython 3.11 keeps at most 30 of an object's
        # attributes inline, and past that the method calls made on it (every timer's
        # loop.time()) go unspecialised, 1.2k instructions a physics step (tests/test_clock.py).
        self._now = 0.0
        self._threads = _Threads(self)
        self.busy_poll: float | None = None  # see _JumpingSelector.select
        self.epoch = epoch
        self.idle_timeout = idle_timeout
        super().__init__(selector=_JumpingSelector(self))

    def time(self) -> float:
        return self._now

    def call_at(self, when: float, callback: Callable[..., object], *args: Any,
                context: Any = None) -> asyncio.TimerHandle:
        if self._debug or self._closed or when is None or not _LEAN_HANDLES:
            return super().call_at(when, callback, *args, context=context)
        # asyncio's call_at without its two constructors' debug questions and the closed
        # check's call: the same handle, with the same fields, in the same heap.
        timer = _handle(asyncio.TimerHandle, callback, args, self, context)
        timer._when = when
        heappush(self._scheduled, timer)
        timer._scheduled = True
        return timer

    def call_again(self, handle: asyncio.TimerHandle, when: float) -> asyncio.TimerHandle:
        """``handle``, a timer handle of this loop that has run, scheduled again for ``when``; returns the handle.

        For a callback that sets its loop timer again each time it runs (a
        runtime's timers, every instant of a simulation): the same object,
        callback, arguments and context back in the heap, as ``call_at`` would
        make them, without a new handle.  A new one from ``call_at`` for a
        handle still waiting, and in debug mode.  ValueError for a cancelled
        handle (cancelling forgets the callback).
        """
        if handle._cancelled:
            raise ValueError("a cancelled handle cannot be called again")
        if self._debug or self._closed or handle._scheduled:
            return self.call_at(when, handle._callback, *handle._args, context=handle._context)
        handle._when = when
        heappush(self._scheduled, handle)
        handle._scheduled = True
        return handle

    def call_soon(self, callback: Callable[..., object], *args: Any, context: Any = None) -> asyncio.Handle:
        if self._debug or self._closed or not _LEAN_HANDLES:
            return super().call_soon(callback, *args, context=context)
        handle = _handle(asyncio.Handle, callback, args, self, context)
        self._ready.append(handle)
        return handle

    def _run_once(self) -> None:
        # One iteration of asyncio's loop (BaseEventLoop._run_once), specialised to virtual time:
        # the same steps in the same order (drop cancelled timers, poll I/O or jump, move the due
        # timers to the ready queue, run what was ready when the iteration began), without the
        # generic parts it pays for on every instant: time() calls, the timeout's arithmetic when
        # something is ready, the debug checks, an empty _process_events.  Debug mode (slow
        # callback warnings, the current handle) takes asyncio's own iteration.
        if self._debug:
            super()._run_once()
            return
        if self._timer_cancelled_count:
            self._drop_cancelled()
        scheduled = self._scheduled
        ready = self._ready
        if ready or self._stopping:
            events = self._selector.select(0)
        elif scheduled:
            # min() and max() parse their arguments as keywords: plain comparisons cost a tenth.
            timeout = scheduled[0]._when - self._now
            events = self._selector.select(0 if timeout < 0 else _MAX_WAIT if timeout > _MAX_WAIT else timeout)
        else:
            events = self._selector.select(None)
        if events:
            self._process_events(events)
        events = None  # no cycle through a handle's exception
        end = self._now + self._clock_resolution
        while scheduled and scheduled[0]._when < end:
            handle = heappop(scheduled)
            handle._scheduled = False
            ready.append(handle)
        # Only what is ready now: callbacks scheduled by these run in the next iteration, after a poll.
        popleft = ready.popleft
        todo = len(ready)  # counted down: a range object costs more than the one or two handles of an instant
        while todo:
            todo -= 1
            handle = popleft()
            if not handle._cancelled:
                handle._run()
        handle = None

    def _drop_cancelled(self) -> None:
        # As asyncio does: rebuild the heap when cancelled timers are most of a large one,
        # otherwise pop those at its head.
        scheduled = self._scheduled
        if len(scheduled) > _MIN_SCHEDULED and self._timer_cancelled_count * 2 > len(scheduled):
            live = []
            for handle in scheduled:
                if handle._cancelled:
                    handle._scheduled = False
                else:
                    live.append(handle)
            heapify(live)
            self._scheduled = live
            self._timer_cancelled_count = 0
        else:
            while scheduled and scheduled[0]._cancelled:
                self._timer_cancelled_count -= 1
                heappop(scheduled)._scheduled = False

    def skip_to(self, when: float, again: bool = False) -> bool:
        """From a callback of this loop: move virtual time on to ``when`` now if the loop would do only that next.

        For a callback that would set its loop timer for ``when`` and return
        (a runtime's timers, instant after instant of a simulation): True, time
        moved, means the caller may do now what that timer would, without the
        loop's iteration around it.  That is when the next iteration would jump
        to ``when`` and run that timer alone: nothing is ready, no timer of the
        loop's is due before ``when`` or within its clock resolution, no file
        descriptor but the loop's self-pipe nor any signal is watched (their
        poll is the loop's to make), no thread is at work, and the loop is
        neither stopping nor in debug mode.  False otherwise, time unmoved.

        ``again``: the caller's previous call, from this same callback, returned
        True, and only synchronous code has run since.  Then anyio's worker
        threads are not looked for again: only a task starts one, and a task
        that could have run since would have been ready, which stops the jump.
        """
        if self._ready or self._stopping or self._debug or not when > self._now:
            return False
        scheduled = self._scheduled
        if scheduled and scheduled[0]._when < when + self._clock_resolution:
            return False
        # What a callback can start without a task: a watched descriptor, a signal handler, an executor job.
        if self._selector.watching or self._signal_handlers or self._threads.jobs:
            return False
        if not again and (self._selector._peek is None or self.threads_busy()):
            return False
        self._now = when
        return True

    def advance(self, seconds: float) -> None:
        """Move virtual time forward by ``seconds`` at once (timers due run next)."""
        if seconds < 0:
            raise ValueError("virtual time cannot go backwards")
        self._now += seconds

    def run_in_executor(self, executor: Any, func: Any, *args: Any) -> asyncio.Future[Any]:
        future = super().run_in_executor(executor, func, *args)
        self._threads.jobs += 1
        future.add_done_callback(self._executor_job_done)
        return future

    def _executor_job_done(self, _future: asyncio.Future[Any]) -> None:
        self._threads.jobs -= 1

    def threads_busy(self) -> bool:
        """Whether executor jobs or anyio worker-thread calls are still running."""
        threads = self._threads
        if threads.jobs > 0:
            return True
        limiter = threads.limiter
        if limiter is None:  # made by anyio at the loop's first to_thread call, then kept
            # Asked on every jump of virtual time: the lookup inline, no call of its own.
            found = threads.run_vars.get(threads.loop)
            if found is None or (limiter := found.get(threads.limiter_key)) is None:
                return False
            threads.limiter = limiter
        return limiter.borrowed_tokens > 0


class _Threads:
    """What a VirtualTimeLoop knows of its work in other threads, in one attribute of the loop (see its __init__)."""

    __slots__ = ("jobs", "limiter", "loop", "run_vars", "limiter_key")

    def __init__(self, loop: VirtualTimeLoop) -> None:
        self.jobs = 0  # run_in_executor calls still running
        self.limiter: Any = None  # anyio's default thread limiter of the loop, once it exists
        self.loop = weakref.ref(loop)  # how anyio's per-loop run vars know the loop
        self.run_vars, self.limiter_key = _anyio_run_vars()


def _anyio_run_vars() -> tuple[dict[Any, dict[Any, Any]], Any]:
    # anyio runs ``to_thread.run_sync`` in its own workers, outside run_in_executor,
    # holding a token of the loop's default limiter while the call runs.  anyio has
    # no public way to ask this from outside a task, so read its per-loop run vars:
    # the WeakKeyDictionary's own dict, by the loop's weak reference (its get() builds
    # one per call), and the limiter's key in them.  tests/test_clock.py fails if that
    # ever stops working.
    try:
        from anyio._backends._asyncio import _default_thread_limiter
        from anyio.lowlevel import _run_vars
    except ImportError:  # pragma: no cover - a future anyio
        return {}, None
    return _run_vars.data, _default_thread_limiter
