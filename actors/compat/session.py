"""A runtime on a thread of its own, driven from other threads: an rclpy script, a grading test.

The event loop, the :class:`~actors.runtime.Runtime` and every node of a graph
file live on the session's thread.  Other threads reach them through two calls:

- :meth:`Session.call` runs a function on the loop thread and returns its
  result (or raises its error): creating a publisher, publishing, reading the
  graph.  The caller stays *busy* meanwhile: the work is immediate.
- :meth:`Session.block` runs a coroutine there and waits for it as a
  :class:`~actors.compat.activity.Waiter`: the caller counts as *waiting*, so
  virtual time may move until the coroutine ends (``wait_for_service``).

On the virtual clock the loop is a :class:`~actors.compat.activity.ScriptTimeLoop`,
which jumps only while every script thread waits.
"""

from __future__ import annotations

import asyncio
import functools
import threading
import time
from collections.abc import Awaitable, Callable, Iterator, Sequence
from concurrent.futures import CancelledError, Future
from contextlib import ExitStack, contextmanager
from typing import Any, TypeVar

import anyio
import anyio.abc
import anyio.from_thread

from actors.compat.activity import Activity, ScriptTimeLoop, Waiter, run_as
from actors.compat.dispatch import Dispatcher
from actors.core.loops import precise_loop
from actors.launch.graph_file import GraphFile
from actors.launch.spawn import spawn_graph
from actors.ros.node import Node
from actors.runtime import Attachment, Runtime

try:  # anyio tells its backend by sniffio when that is installed: a loop callback must say it
    from sniffio import current_async_library_cvar as _async_library
except ImportError:  # pragma: no cover - anyio without sniffio finds the running loop itself
    _async_library = None

__all__ = ["Session"]

T = TypeVar("T")


class Session:
    """A runtime on its own thread.  ``with Session(clock="virtual") as s:`` starts and stops it.

    ``graph`` (a loaded graph file and its node classes) is spawned before
    :meth:`start` returns; ``duration`` seconds of runtime clock after the start,
    ``on_duration()`` is called on the loop thread (the launcher interrupts the
    script then).  ``on_failure(error)`` is called when the runtime ends by
    itself with an error (a graph node's supervisor gave up).
    """

    def __init__(
        self,
        *,
        clock: str = "wall",
        name: str = "actors",
        graph: tuple[GraphFile, Sequence[type[Node]]] | None = None,
        duration: float | None = None,
        on_duration: Callable[[], None] | None = None,
        on_failure: Callable[[BaseException], None] | None = None,
        attach: Sequence[Attachment] = (),
    ) -> None:
        if clock not in ("wall", "virtual"):
            raise ValueError(f"clock must be 'wall' or 'virtual', got {clock!r}")
        self.virtual = clock == "virtual"
        self.name = name
        self.activity = Activity()
        # One lock for the overlay's executor state (ready work, executors, waiters) of this session.
        self.lock = threading.RLock()
        self.failure: BaseException | None = None
        self._graph = graph
        self._duration = duration
        self._on_duration = on_duration
        self._on_failure = on_failure
        self._attach = tuple(attach)
        self._stack: ExitStack | None = None
        self._done: Future[None] | None = None
        self._stopping = False
        self._waiting: set[Waiter] = set()  # threads in wait_until, woken when the runtime ends
        self._calls: set[Future[Any]] = set()  # calls handed to the loop thread, not yet run
        self._calls_lock = threading.Lock()
        self._closed = False
        self.runtime: Runtime
        self.dispatcher: Dispatcher
        self.loop: asyncio.AbstractEventLoop
        self.loop_thread: threading.Thread | None = None

    # -- lifecycle --------------------------------------------------------------

    def start(self) -> Session:
        """Start the loop thread and the runtime (and the graph); return self.

        The calling thread counts as busy from now on (it is about to run the
        script).  Raises what starting the graph raises.
        """
        self.activity.current()
        factory: Callable[[], asyncio.AbstractEventLoop] = (
            functools.partial(ScriptTimeLoop, self.activity) if self.virtual else precise_loop
        )
        stack = ExitStack()
        portal = stack.enter_context(
            anyio.from_thread.start_blocking_portal("asyncio", {"loop_factory": factory}, name=f"actors {self.name}")
        )
        try:
            self._done, _ = portal.start_task(self._serve, name="runtime")
        except BaseException:
            stack.close()
            raise
        self._stack = stack
        self._done.add_done_callback(self._ended)
        return self

    async def _serve(self, *, task_status: anyio.abc.TaskStatus[None]) -> None:
        self.loop = asyncio.get_running_loop()
        self.loop_thread = threading.current_thread()
        self.dispatcher = Dispatcher(self.loop)
        self._stop = anyio.Event()
        policy = self._graph[0].supervisor.policy() if self._graph else None
        async with Runtime(name=self.name, supervisor=policy, attach=self._attach) as rt:
            self.runtime = rt
            async with anyio.create_task_group() as tg:
                if self._graph is not None:
                    await tg.start(spawn_graph, rt, *self._graph)
                if self._duration:
                    tg.start_soon(self._end_after, self._duration)
                task_status.started()
                await self._stop.wait()
                tg.cancel_scope.cancel()

    async def _end_after(self, seconds: float) -> None:
        await anyio.sleep(seconds)
        if self._on_duration is not None:
            self._on_duration()

    def _ended(self, done: Future[None]) -> None:
        error = None if done.cancelled() else done.exception()
        if error is not None and not self._stopping:
            self.failure = error
            if self._on_failure is not None:
                self._on_failure(error)
        # No timer will fire any more: release the threads that wait on runtime time (a pool thread
        # in time.sleep would otherwise never end, and the interpreter waits for it at exit).
        with self.lock:
            waiting = list(self._waiting)
        for waiter in waiting:
            waiter.wake()

    def close(self) -> None:
        """Stop every node (graph nodes gracefully, in reverse order) and the loop thread.

        Returns once the thread has ended; a failure of the runtime is kept in
        :attr:`failure`, not raised.
        """
        stack, self._stack = self._stack, None
        if stack is None:
            return
        self._stopping = self.failure is None
        try:
            if self._done is not None and not self._done.done():
                self.call(self._stop.set)
                _wait_quietly(self._done)
        finally:
            stack.close()
            # The loop has stopped: a call another thread handed it meanwhile will never run.
            with self._calls_lock:
                self._closed = True
                stranded = list(self._calls)
            for future in stranded:
                future.cancel()

    def __enter__(self) -> Session:
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.close()

    @property
    def running(self) -> bool:
        """Whether the runtime runs (started, not yet ended)."""
        return self._done is not None and not self._done.done()

    # -- calls from other threads ------------------------------------------------

    def in_loop_thread(self) -> bool:
        """Whether the calling thread is the session's loop thread."""
        return threading.current_thread() is self.loop_thread

    def call(self, fn: Callable[..., T], *args: Any, **kwargs: Any) -> T:
        """``fn(*args, **kwargs)`` on the loop thread; its result, or its error raised here.

        Raises RuntimeError once the loop thread has stopped, also to a call it
        stopped before running (a pool thread still at work
        then would otherwise wait forever).
        """
        if kwargs:
            fn = functools.partial(fn, **kwargs)
        if self.in_loop_thread():
            return fn(*args)
        future: Future[T] = Future()
        with self._handed(future):
            try:
                self.loop.call_soon_threadsafe(_run_call, fn, args, future)
            except RuntimeError:  # the loop is closed
                raise self._ended_error() from None
            return future.result()

    @contextmanager
    def _handed(self, future: Future[Any]) -> Iterator[None]:
        # Inside the block, close() cancels ``future`` if the loop stops before finishing it.
        with self._calls_lock:
            if self._closed:
                raise self._ended_error()
            self._calls.add(future)
        try:
            yield
        except CancelledError:
            if future.cancelled() and self._closed:
                raise self._ended_error() from None
            raise
        finally:
            with self._calls_lock:
                self._calls.discard(future)

    def _ended_error(self) -> RuntimeError:
        return RuntimeError(f"the runtime of {self.name!r} has stopped")

    def block(self, async_fn: Callable[..., Awaitable[T]], *args: Any) -> T:
        """Await ``async_fn(*args)`` on the loop, the caller waiting (not busy) until it ends.

        KeyboardInterrupt while waiting cancels the coroutine.  Raises
        RuntimeError on the loop thread itself, which must never block.
        """
        if self.in_loop_thread():
            raise RuntimeError("the runtime's own thread cannot block on the runtime")
        coroutine = _as_coroutine(async_fn, *args)
        try:
            future = asyncio.run_coroutine_threadsafe(coroutine, self.loop)
        except RuntimeError:  # the loop is closed
            coroutine.close()
            raise self._ended_error() from None
        waiter = Waiter(self.activity)
        with self._handed(future):
            future.add_done_callback(lambda _: waiter.wake())
            try:
                waiter.wait()
            except BaseException:
                future.cancel()
                raise
            return future.result()

    def wake_after(self, seconds: float, wake: Callable[[], None]) -> asyncio.TimerHandle:
        """Call ``wake()`` on the loop thread ``seconds`` of runtime clock from now."""
        return self.call(self.loop.call_later, max(0.0, seconds), wake)

    def cancel(self, handle: asyncio.TimerHandle) -> None:
        """Cancel what :meth:`wake_after` scheduled."""
        if self.running:
            self.call(handle.cancel)

    def sleep(self, seconds: float) -> None:
        """Wait ``seconds`` of runtime clock (virtual under virtual time), waiting, not busy."""
        self.wait_until(lambda: False, seconds)

    @contextmanager
    def timekeeping(self) -> Iterator[None]:
        """Inside the block, on the virtual clock, script threads keep virtual time honest.

        ``time.sleep`` in a script thread sleeps runtime time (threads that never
        waited on the runtime, and the loop's, sleep in real time), and a thread
        that a script thread starts counts as busy from ``start()`` until it
        first waits on the runtime, except while it is parked in a wait of
        :mod:`threading` (see :mod:`~actors.compat.activity`).
        """
        if not self.virtual:
            yield
            return
        real_sleep, real_start = time.sleep, threading.Thread.start
        activity = self.activity

        def sleep(seconds: float) -> None:
            if seconds < 0:
                raise ValueError("sleep length must be non-negative")
            if self.running and not self.in_loop_thread() and activity.has_token():
                self.sleep(seconds)
            else:
                real_sleep(seconds)

        def start(thread: threading.Thread) -> None:
            if (
                self.running
                and activity.has_token()
                and not activity.starts_workers()
                and getattr(thread, "_actors_token", None) is None
            ):
                token = activity.starting(thread)
                try:
                    real_start(thread)
                except BaseException:
                    activity.done(token)  # it never runs: it must not hold the clock
                    raise
            else:
                real_start(thread)

        _swap(sleep, start)
        try:
            yield
        finally:
            _swap(real_sleep, real_start)

    def start_thread(self, target: Callable[[], Any], name: str) -> tuple[threading.Thread, Any]:
        """Start a daemon thread running ``target()``, busy from now until it first waits; its token."""
        token = self.activity.work()
        thread = _TokenThread(target=run_as, args=(self.activity, token, target), name=name, daemon=True)
        thread._actors_token = token
        thread.start()
        return thread, token

    def wait_until(self, done: Callable[[], Any], timeout: float | None, waiter: Waiter | None = None) -> Any:
        """Wait until ``done()`` (checked with :attr:`lock` held) returns something true; return it.

        ``waiter`` is the one whoever makes ``done()`` true wakes (made here if
        None: then only the timeout wakes it).  After ``timeout`` seconds of
        runtime clock (None: no limit), returns what ``done()`` returns then;
        also once the runtime has ended (no runtime time passes any more).
        """
        waiter = Waiter(self.activity) if waiter is None else waiter
        expired = False

        def time_up() -> None:
            nonlocal expired
            expired = True
            waiter.wake()

        timer = None
        with self.lock:
            self._waiting.add(waiter)
        try:
            timer = self.wake_after(timeout, time_up) if timeout is not None and self.running else None
            while True:
                waiter.clear()
                with self.lock:
                    result = done()
                if result or expired or not self.running:
                    return result
                waiter.wait()
        finally:
            with self.lock:
                self._waiting.discard(waiter)
            if timer is not None and not expired:
                self.cancel(timer)


def _run_call(fn: Callable[..., T], args: tuple[Any, ...], future: Future[T]) -> None:
    if not future.set_running_or_notify_cancel():
        return
    if _async_library is not None:
        _async_library.set("asyncio")
    try:
        future.set_result(fn(*args))
    except BaseException as exc:
        future.set_exception(exc)
        if not isinstance(exc, Exception):
            raise


async def _as_coroutine(async_fn: Callable[..., Awaitable[T]], *args: Any) -> T:
    return await async_fn(*args)


def _wait_quietly(done: Future[None]) -> None:
    try:
        done.result()
    except BaseException:
        pass


def _swap(sleep: Callable[[float], None], start: Callable[[threading.Thread], None]) -> None:
    # Session.timekeeping's patch of the standard library, put in place and taken back.
    time.sleep, threading.Thread.start = sleep, start  # type: ignore[method-assign, assignment]  # a patch, on purpose


class _TokenThread(threading.Thread):
    """A thread of :meth:`Session.start_thread`: it carries its token from the start."""

    _actors_token: Any
