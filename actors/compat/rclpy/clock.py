"""``rclpy.clock``: actors' clocks with rclpy's jump callbacks and blocking sleeps.

A jump callback runs when a ROS clock's time is set by hand while ROS time is
active (a ``/clock`` message through :mod:`~actors.compat.rclpy.time_source`),
by how far it moved, or when ROS time is switched on or off, as rcl's do:
``pre_callback()`` before the clock changes, ``post_callback(TimeJump)`` after.
``sleep_for``/``sleep_until`` block the calling thread, and end early (False)
when the context shuts down or ROS time is switched on or off.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from enum import IntEnum
from types import TracebackType
from typing import Any

from actors.compat.rclpy.context import Context
from actors.compat.rclpy.exceptions import NotInitializedException
from actors.compat.rclpy.utilities import get_default_context
from actors.ros import time as _time
from actors.ros.time import ClockType, Duration, Time

__all__ = ["Clock", "ClockChange", "ClockType", "JumpHandle", "JumpThreshold", "ROSClock", "TimeJump"]


class ClockChange(IntEnum):
    """What a time jump did to the clock's source (values as rcl's)."""

    ROS_TIME_NO_CHANGE = 1
    ROS_TIME_ACTIVATED = 2
    ROS_TIME_DEACTIVATED = 3
    SYSTEM_TIME_NO_CHANGE = 4


class JumpThreshold:
    """Which jumps call back: forward by ``min_forward`` or more, back by ``min_backward`` or more, a source change.

    Raises ValueError for a ``min_forward`` that is not positive, a
    ``min_backward`` that is not negative, or nothing enabled at all.
    """

    def __init__(
        self, *, min_forward: Duration | None, min_backward: Duration | None, on_clock_change: bool = True
    ) -> None:
        if min_forward is not None and min_forward.nanoseconds <= 0:
            raise ValueError("min_forward must be a positive non-zero duration")
        if min_backward is not None and min_backward.nanoseconds >= 0:
            raise ValueError("min_backward must be a negative non-zero duration")
        if min_forward is None and min_backward is None and not on_clock_change:
            raise ValueError("At least one jump threshold must be enabled")
        self.min_forward = min_forward
        self.min_backward = min_backward
        self.on_clock_change = on_clock_change

    def crossed(self, change: ClockChange, delta_ns: int) -> bool:
        """Whether a jump of ``delta_ns`` (with ``change``) calls back."""
        if change in (ClockChange.ROS_TIME_ACTIVATED, ClockChange.ROS_TIME_DEACTIVATED):
            return self.on_clock_change
        forward = self.min_forward is not None and delta_ns >= self.min_forward.nanoseconds
        backward = self.min_backward is not None and delta_ns <= self.min_backward.nanoseconds
        return forward or backward


class TimeJump:
    """What a post-jump callback receives: the source change and how far time moved."""

    def __init__(self, clock_change: ClockChange, delta: Duration) -> None:
        if not isinstance(clock_change, ClockChange):
            raise TypeError("clock_change must be an instance of rclpy.clock.ClockChange")
        self._clock_change = clock_change
        self._delta = delta

    @property
    def clock_change(self) -> ClockChange:
        """Whether ROS time was switched on or off, or neither."""
        return self._clock_change

    @property
    def delta(self) -> Duration:
        """How far the clock moved (zero for a source change)."""
        return self._delta


class JumpHandle:
    """A registered jump callback; ``unregister()`` (or leaving its ``with``) removes it.

    Raises ValueError when neither callback is given or one is not callable.
    """

    def __init__(
        self,
        *,
        clock: Clock,
        threshold: JumpThreshold,
        pre_callback: Callable[[], Any] | None,
        post_callback: Callable[[TimeJump], Any] | None,
    ) -> None:
        if pre_callback is None and post_callback is None:
            raise ValueError("One of pre_callback or post_callback must be callable")
        for name, given in (("pre_callback", pre_callback), ("post_callback", post_callback)):
            if given is not None and not callable(given):
                raise ValueError(f"{name} must be callable if given")
        self._clock: Clock | None = clock
        self.threshold = threshold
        self.pre_callback = pre_callback
        self.post_callback = post_callback
        with clock._jump_lock:
            clock._jump_handles.append(self)

    def unregister(self) -> None:
        """Remove the callback from its clock (a second call does nothing)."""
        clock, self._clock = self._clock, None
        if clock is not None:
            with clock._jump_lock:
                if self in clock._jump_handles:
                    clock._jump_handles.remove(self)

    def __enter__(self) -> JumpHandle:
        return self

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        self.unregister()


class Clock(_time.Clock):
    """A clock as ``rclpy.clock.Clock``: ``Clock(clock_type=ClockType.ROS_TIME)`` makes a :class:`ROSClock`."""

    _jump_handles: list[JumpHandle]
    _jump_lock: threading.Lock

    def __new__(cls, *args: Any, clock_type: ClockType = ClockType.SYSTEM_TIME, **kwargs: Any) -> Clock:
        if not isinstance(clock_type, ClockType):
            raise TypeError(f"clock_type must be a ClockType, got {clock_type!r}")
        if clock_type is ClockType.ROS_TIME and not issubclass(cls, ROSClock):
            cls = ROSClock
        return object.__new__(cls)

    def __init__(self, *, clock_type: ClockType = ClockType.SYSTEM_TIME) -> None:
        super().__init__(clock_type=clock_type)
        self._jump_handles = []
        self._jump_lock = threading.Lock()

    @property
    def handle(self) -> Clock:
        """The clock itself (rclpy's C clock, which tests lock with ``with clock.handle:``)."""
        return self

    def __enter__(self) -> Clock:
        return self

    def __exit__(self, *exc: object) -> None:
        return None

    def create_jump_callback(
        self,
        threshold: JumpThreshold,
        *,
        pre_callback: Callable[[], Any] | None = None,
        post_callback: Callable[[TimeJump], Any] | None = None,
    ) -> JumpHandle:
        """Call ``pre_callback()`` before and ``post_callback(jump)`` after each jump ``threshold`` lets through."""
        return JumpHandle(clock=self, threshold=threshold, pre_callback=pre_callback, post_callback=post_callback)

    def _jump(self, change: ClockChange, delta_ns: int, apply: Callable[[], None]) -> None:
        # rcl's order: every pre callback, the change, every post callback.
        with self._jump_lock:
            called = [handle for handle in self._jump_handles if handle.threshold.crossed(change, delta_ns)]
        for handle in called:
            if handle.pre_callback is not None:
                handle.pre_callback()
        apply()
        jump = TimeJump(change, Duration(nanoseconds=delta_ns))
        for handle in called:
            if handle.post_callback is not None:
                handle.post_callback(jump)

    def sleep_until(self, until: Time, context: Context | None = None) -> bool:
        """Block until this clock reads ``until``; False if the context shut down or ROS time was switched.

        Raises NotInitializedException for a context that is not initialized (or
        shut down) and ValueError for a Time of another clock type.
        """
        context = get_default_context() if context is None else context
        if not context.ok():
            raise NotInitializedException()
        if until.clock_type != self.clock_type:
            raise ValueError("until's clock type does not match this clock's type")
        woken = threading.Event()
        switched = False

        def on_jump(jump: TimeJump) -> None:
            nonlocal switched
            switched = switched or jump.clock_change != ClockChange.ROS_TIME_NO_CHANGE
            if switched or self.now() >= until:
                woken.set()

        context.on_shutdown(woken.set)
        threshold = JumpThreshold(min_forward=Duration(nanoseconds=1), min_backward=None, on_clock_change=True)
        with self.create_jump_callback(threshold, post_callback=on_jump):
            while not woken.is_set() and context.ok():
                left_ns = until.nanoseconds - self.now_ns()
                if left_ns <= 0:
                    break
                # Time set by hand moves only by jumps, which wake this; other clocks move by themselves.
                woken.wait(None if self._set_by_hand() else left_ns / 1e9)
        if not context.ok() or switched:
            return False
        return self.now() >= until

    def sleep_for(self, rel_time: Duration, context: Context | None = None) -> bool:
        """``sleep_until(now + rel_time, context)``."""
        return self.sleep_until(self.now() + rel_time, context)

    def _set_by_hand(self) -> bool:
        return False


class ROSClock(_time.ROSClock, Clock):
    """ROS time, as ``rclpy.clock.ROSClock``: the runtime's time, or time set by hand while ROS time is active."""

    def __new__(cls, *args: Any, **kwargs: Any) -> ROSClock:
        return object.__new__(cls)

    def __init__(self, loop: Any = None, *, clock_type: ClockType = ClockType.ROS_TIME) -> None:
        super().__init__(loop, clock_type=clock_type)

    # rclpy's blocking sleeps, not the native clock's coroutines
    sleep_until = Clock.sleep_until  # type: ignore[assignment]
    sleep_for = Clock.sleep_for  # type: ignore[assignment]

    def _set_ros_time_is_active(self, enabled: bool) -> None:
        if bool(enabled) == self._override_active:
            return
        change = ClockChange.ROS_TIME_ACTIVATED if enabled else ClockChange.ROS_TIME_DEACTIVATED
        self._jump(change, 0, lambda: _time.ROSClock._set_ros_time_is_active(self, bool(enabled)))

    def set_ros_time_override(self, time_: Time) -> None:
        """Set the time this clock reports while ROS time is active; a jump when it is."""
        if not isinstance(time_, Time):
            raise TypeError(f"set_ros_time_override takes a Time, got {time_!r}")
        if not self._override_active:
            _time.ROSClock.set_ros_time_override(self, time_)
            return
        delta = time_.nanoseconds - self._override_ns
        self._jump(ClockChange.ROS_TIME_NO_CHANGE, delta, lambda: _time.ROSClock.set_ros_time_override(self, time_))

    def _set_by_hand(self) -> bool:
        return self._override_active
