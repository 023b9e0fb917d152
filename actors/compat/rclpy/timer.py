"""``rclpy.timer``: a script node's timer, and ``Rate``.

The native timer keeps time on the runtime's clock (absolute deadlines, skipped
ticks); its callback is the overlay's catcher, which marks the timer ready.
Ticks that come while the timer is still ready merge into one, as an rcl timer
that nobody took is called once.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

from actors.compat.dispatch import Handler, NativeProxy, ScriptNode, WorkSource
from actors.compat.rclpy._destroyable import Destroyable
from actors.compat.rclpy.exceptions import ROSInterruptException
from actors.compat.rclpy.task import await_or_execute
from actors.compat.turns import Waiter
from actors.ros.timers import TimerInfo

__all__ = ["Timer", "Rate", "TimerInfo"]


class Timer(Destroyable, WorkSource, NativeProxy):
    """Calls ``callback`` every period while its node is spun (``Node.create_timer``)."""

    def __init__(self, node: ScriptNode, callback: Callable[..., Any] | None, callback_group: Any) -> None:
        self._node = node
        self._session = node._rclpy.session
        self.callback = callback
        self.callback_group = callback_group
        self._native: Any = None
        self._fired: tuple[tuple[Any, ...], dict[str, Any]] | None = None  # a tick not taken yet
        self.catcher = self._make_catcher()

    def _make_catcher(self) -> Callable[..., None]:
        def catch(*args: Any, **kwargs: Any) -> None:
            with self._session.lock:
                self._fired = (args, kwargs)
                self._node._rclpy.notify()

        # The native timer reads the callback's signature (a TimerInfo parameter): show it the script's.
        return functools.wraps(self.callback)(catch) if self.callback is not None else catch

    def _ready(self) -> bool:
        return self._fired is not None

    def _take(self) -> Handler | None:
        fired, self._fired = self._fired, None
        callback = self.callback
        if fired is None or callback is None:
            return None
        args, kwargs = fired
        # The tick is called now, not when it came: rclpy's actual_call_time is the take's.
        kwargs = {name: self._restamped(v) if isinstance(v, TimerInfo) else v for name, v in kwargs.items()}

        async def run() -> None:
            await await_or_execute(functools.partial(callback, *args, **kwargs))

        return run

    def _restamped(self, info: TimerInfo) -> TimerInfo:
        expected = info.expected_call_time
        return TimerInfo(
            expected_call_time=expected.nanoseconds,
            actual_call_time=self._native.clock.now_ns(),
            clock_type=expected.clock_type,
        )

    @property
    def timer_period_ns(self) -> int:
        """The period in nanoseconds."""
        return int(self._native.timer_period_ns)

    def cancel(self) -> None:
        """Stop calling back until :meth:`reset`."""
        # Native first: a tick due at this instant may still come in before the native cancel, and
        # must be forgotten with the rest.
        self._session.call(self._native.cancel)
        with self._session.lock:
            self._fired = None

    def reset(self) -> None:
        """Start the period over from now (also revives a canceled timer)."""
        self._session.call(self._native.reset)
        with self._session.lock:
            self._fired = None

    def is_ready(self) -> bool:
        """Whether a tick waits to be called back."""
        return self._fired is not None

    def destroy(self) -> None:
        """Cancel the timer and remove it from its node."""
        self._node.destroy_timer(self)


class Rate:
    """Sleeps until the next tick of its timer: ``rate.sleep()`` (``Node.create_rate``).

    As in rclpy, the ticks come from a timer of the node, so the node must be
    spun (by another thread) while a thread sleeps on the rate.
    """

    def __init__(self, timer: Timer, *, context: Any) -> None:
        self._timer = timer
        self._session = timer._session
        self._ticks = 0
        self._waiters: set[Waiter] = set()
        self._is_shutdown = False
        self._is_destroyed = False
        self._context = context
        timer.callback = self._tick
        context.on_shutdown(self._on_shutdown)
        context.add_waker(self)

    def _tick(self) -> None:
        with self._session.lock:
            self._ticks += 1
            for waiter in self._waiters:
                waiter.wake()

    def wake(self) -> None:
        """Wake the sleepers to look at the context (it shut down)."""
        with self._session.lock:
            for waiter in self._waiters:
                waiter.wake()

    def _on_shutdown(self) -> None:
        self._is_shutdown = True
        self.destroy()

    def destroy(self) -> None:
        """Wake the sleepers; the rate cannot sleep any more."""
        with self._session.lock:
            self._is_destroyed = True
            for waiter in self._waiters:
                waiter.wake()

    def sleep(self) -> None:
        """Block until the next tick; ROSInterruptException if the context shuts down meanwhile."""
        if self._is_shutdown or not self._context.ok():
            raise ROSInterruptException()
        if self._is_destroyed:
            raise RuntimeError("Rate cannot sleep because it has been destroyed")
        waiter = self._session.waiter()
        with self._session.lock:
            start = self._ticks
            self._waiters.add(waiter)
        try:
            self._session.wait_until(
                lambda: self._ticks != start or self._is_destroyed or not self._context.ok(), None, waiter
            )
        finally:
            with self._session.lock:
                self._waiters.discard(waiter)
        if self._is_shutdown or not self._context.ok():
            raise ROSInterruptException()
