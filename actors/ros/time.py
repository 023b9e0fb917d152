"""Time for nodes: Time, Duration, Clock, Rate, as rclpy's.

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

The event loops themselves live in :mod:`actors.core.loops`.
"""

from __future__ import annotations

import asyncio
import math
import time
from collections.abc import Callable, Sequence
from enum import IntEnum
from typing import Any

from actors.core.loops import VirtualTimeLoop

__all__ = [
    "ClockType",
    "Time",
    "Duration",
    "Infinite",
    "Clock",
    "ROSClock",
    "Rate",
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
                f"cannot {doing} Times of different clock types ({self._clock_type.name} and {other._clock_type.name})"
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

    __slots__ = ("_loop", "_time", "_epoch_ns", "_override_active", "_override_ns")

    def __init__(
        self, loop: asyncio.AbstractEventLoop | None = None, *, clock_type: ClockType = ClockType.ROS_TIME
    ) -> None:
        # ``clock_type`` is taken only so that ``Clock(clock_type=ROS_TIME)`` can build one.
        super().__init__(clock_type=ClockType.ROS_TIME)
        self._loop = loop
        self._override_active = False
        self._override_ns = 0
        # Off virtual time, the monotonic clock every wall-clock loop keeps its time by, read
        # afresh: uvloop's loop.time() is that clock as of its last turn, to the millisecond, and
        # would give every stamp taken in one callback the same time.
        self._time = time.monotonic
        if loop is None:
            self._epoch_ns = 0
        elif isinstance(loop, VirtualTimeLoop):
            self._epoch_ns = int(round(loop.epoch * _NS))
            self._time = loop.time
        else:
            # The one place actors reads the wall clock: to anchor loop time to the epoch.
            self._epoch_ns = time.time_ns() - int(round(time.monotonic() * _NS))

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
        return self._epoch_ns + int(round(self._time() * _NS))

    def ns_at(self, loop_times: Sequence[float]) -> list[int]:
        """What :meth:`now_ns` read when the loop's clock read each of ``loop_times`` (a time set
        by hand counts as it is now): for whoever stamps with the loop's cheaper clock and
        converts later, a batch at a time."""
        if self._override_active:
            return [self._override_ns] * len(loop_times)
        epoch = self._epoch_ns
        return [epoch + round(t * _NS) for t in loop_times]

    def reader(self) -> Callable[[], float]:
        """The function that reads the seconds :meth:`now_ns` adds its epoch to: the loop's
        virtual time, else ``time.monotonic`` itself (on uvloop too, whose ``loop.time()`` is
        that clock to the millisecond as of its last turn).  For whoever stamps many messages
        and converts a batch later (:meth:`ns_at`); RuntimeError for an unbound clock."""
        if self._loop is None:
            raise RuntimeError("an unbound ROSClock has no loop time; use a runtime's clock")
        return self._time

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
