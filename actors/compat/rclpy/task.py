"""``rclpy.task``: Future and Task, thread-safe and awaitable inside coroutine callbacks.

As in rclpy, a Future's done callbacks are scheduled as tasks on its executor
when it has one, and called at once otherwise; a Task runs a plain function or
steps a coroutine each time it is called.  One difference, invisible to code:
a coroutine that awaits a pending Future is not stepped again until that
Future is done (rclpy polls it), so a waiting callback costs nothing and lets
virtual time move.
"""

from __future__ import annotations

import inspect
import sys
import threading
import warnings
import weakref
from collections.abc import Callable, Generator
from enum import Enum
from typing import TYPE_CHECKING, Any, Generic, TypeVar

if TYPE_CHECKING:
    from actors.compat.dispatch import SpinningExecutor as Executor

__all__ = ["Future", "FutureState", "Task", "await_or_execute"]

T = TypeVar("T")


class FutureState(Enum):
    """States of a Future."""

    PENDING = "PENDING"
    CANCELLED = "CANCELLED"
    FINISHED = "FINISHED"


async def await_or_execute(callback: Callable[..., Any], *args: Any) -> Any:
    """Await ``callback(*args)`` if it is a coroutine function, else call it."""
    if inspect.iscoroutinefunction(callback):
        return await callback(*args)
    return callback(*args)


def _no_executor() -> None:
    return None


_stepping = threading.local()  # .task: the Task whose coroutine this thread is stepping, if any


class Future(Generic[T]):
    """The outcome of work that finishes later: ``done()``, ``result()``, ``add_done_callback``, ``await``."""

    def __init__(self, *, executor: Executor | None = None) -> None:
        self._state = FutureState.PENDING
        self._result: T | None = None
        self._exception: BaseException | None = None
        self._exception_fetched = False
        self._callbacks: list[Callable[[Future[T]], None]] = []
        self._resumers: list[Callable[[], None]] = []
        self._lock = threading.Lock()
        self._executor: Callable[[], Executor | None] = _no_executor
        self._set_executor(executor)

    def __del__(self) -> None:
        if self._exception is not None and not self._exception_fetched:
            print(f"The following exception was never retrieved: {self._exception}", file=sys.stderr)

    def __await__(self) -> Generator[Any, None, T | None]:
        while self._pending():
            # A Task stepping on this thread sleeps until this future is done; anyone else awaiting it
            # (an asyncio task, as rclpy allows) gets a bare yield and polls, as rclpy's futures make it.
            yield self if getattr(_stepping, "task", None) is not None else None
        return self.result()

    def _pending(self) -> bool:
        return self._state is FutureState.PENDING

    def cancel(self) -> None:
        """Cancel it, if not done already."""
        with self._lock:
            if not self._pending():
                return
            self._state = FutureState.CANCELLED
        self._schedule_or_invoke_done_callbacks()

    def cancelled(self) -> bool:
        """Whether it was cancelled."""
        return self._state is FutureState.CANCELLED

    def done(self) -> bool:
        """Whether it has a result or an exception (not when cancelled, as in rclpy)."""
        return self._state is FutureState.FINISHED

    def result(self) -> T | None:
        """The result (None if none was set); raises the exception it was given instead."""
        exception = self.exception()
        if exception is not None:
            raise exception
        return self._result

    def exception(self) -> BaseException | None:
        """The exception it was given, if any."""
        self._exception_fetched = True
        return self._exception

    def set_result(self, result: T) -> None:
        """Finish with ``result``."""
        with self._lock:
            self._result = result
            self._state = FutureState.FINISHED
        self._schedule_or_invoke_done_callbacks()

    def set_exception(self, exception: BaseException) -> None:
        """Finish with ``exception``."""
        with self._lock:
            self._exception = exception
            self._exception_fetched = False
            self._state = FutureState.FINISHED
        self._schedule_or_invoke_done_callbacks()

    def _schedule_or_invoke_done_callbacks(self) -> None:
        with self._lock:
            executor = self._executor()
            callbacks, self._callbacks = self._callbacks, []
            resumers, self._resumers = self._resumers, []
        for resume in resumers:
            resume()
        if executor is not None:
            for callback in callbacks:
                executor.create_task(callback, self)
            return
        for callback in callbacks:
            try:
                callback(self)
            except Exception as exc:  # as rclpy: the other callbacks still run
                warnings.warn(f"Unhandled exception in done callback: {exc}", stacklevel=2)

    def _set_executor(self, executor: Executor | None) -> None:
        with self._lock:
            self._executor = _no_executor if executor is None else weakref.ref(executor)

    def add_done_callback(self, callback: Callable[[Future[T]], None]) -> None:
        """Call ``callback(future)`` when done (as an executor task if it has an executor)."""
        invoke = False
        with self._lock:
            if self._pending():
                self._callbacks.append(callback)
            else:
                executor = self._executor()
                if executor is not None:
                    executor.create_task(callback, self)
                else:
                    invoke = True
        if invoke:
            callback(self)

    def remove_done_callback(self, callback: Callable[[Future[T]], None]) -> bool:
        """Forget ``callback``; whether it was there."""
        with self._lock:
            try:
                self._callbacks.remove(callback)
            except ValueError:
                return False
            return True

    def _add_resumer(self, resume: Callable[[], None]) -> None:
        # The overlay's own wake-up when the future ends (no task, no executor needed).
        with self._lock:
            if self._pending():
                self._resumers.append(resume)
                return
        resume()


class Task(Future[T]):
    """Runs a function, or steps a coroutine, each time it is called; its result is the Future's.

    Made by executors (``create_task``, and one per callback they hand out).
    """

    def __init__(
        self,
        handler: Callable[..., Any],
        args: tuple[Any, ...] | None = None,
        kwargs: dict[str, Any] | None = None,
        executor: Executor | None = None,
    ) -> None:
        super().__init__(executor=executor)
        self._args: tuple[Any, ...] = args or ()
        self._kwargs: dict[str, Any] = kwargs or {}
        self._handler: Any = handler(*self._args, **self._kwargs) if inspect.iscoroutinefunction(handler) else handler
        self._executing = False
        self._suspended = False
        self._handed = False  # given out by an executor and not run (or resumed) since
        self._task_lock = threading.Lock()
        self._arrival: weakref.finalize | None = None
        self._turn: Any = None

    def _claim(self, turn: Any) -> None:
        # Handed to code that may run it on any thread: on the virtual clock, the clock stands
        # still until it is called (or collected uncalled).
        if turn.virtual and not turn.stopped:
            turn.expect()
            self._arrival = weakref.finalize(self, turn.unexpect)
            self._turn = turn

    def __call__(self) -> None:
        """Run or resume the task (a no-op when done, already running, or waiting on a Future)."""
        arrival = self._arrival
        if arrival is not None:
            self._arrival = None
            arrival.detach()
            with self._turn.arriving():
                self._call()
        else:
            self._call()

    def _call(self) -> None:
        if not self._pending() or self._executing or not self._task_lock.acquire(blocking=False):
            return
        try:
            if not self._pending():
                return
            self._executing = True
            self._step()
            self._executing = False
        finally:
            self._task_lock.release()
        if self._pending() and not self._suspended:
            self._handed = False  # it yielded without waiting on a Future: run it again
            self._poke()

    def _step(self) -> None:
        handler = self._handler
        if inspect.iscoroutine(handler):
            outer, _stepping.task = getattr(_stepping, "task", None), self
            try:
                awaited = handler.send(None)
            except StopIteration as stop:
                self.set_result(stop.value)
                self._handler = None
            except Exception as exc:
                self.set_exception(exc)
                self._handler = None
            else:
                if isinstance(awaited, Future) and awaited._pending():
                    self._suspend_on(awaited)
            finally:
                _stepping.task = outer
            return
        try:
            self.set_result(handler(*self._args, **self._kwargs))
        except Exception as exc:
            self.set_exception(exc)
        self._handler = None

    def _suspend_on(self, future: Future[Any]) -> None:
        self._suspended = True
        future._add_resumer(self._resume)

    def _resume(self) -> None:
        self._suspended = False
        self._handed = False
        self._poke()

    def _poke(self) -> None:
        executor = self._executor()
        if executor is not None:
            executor.wake()

    def runnable(self) -> bool:
        """Whether calling it now would do something (pending, not running, not waiting)."""
        return self._pending() and not self._executing and not self._suspended

    def executing(self) -> bool:
        """Whether it is running now."""
        return self._executing

    def cancel(self) -> None:
        if self._pending() and inspect.iscoroutine(self._handler):
            self._handler.close()
        super().cancel()
