"""A runtime on a thread of its own, driven from other threads: an rclpy script, a grading test.

The event loop, the :class:`~actors.runtime.Runtime` and every node of a graph
file live on the session's thread.  Other threads reach them by taking the
session's *turn* (:mod:`~actors.compat.turns`) and running the call themselves:

- :meth:`Session.call` runs a function with the turn held and returns its
  result (or raises its error): creating a publisher, publishing, reading the
  graph.  The work is immediate.
- :meth:`Session.wait_until` and :meth:`Session.block` park the caller on a
  :class:`~actors.compat.turns.Waiter` until a condition holds or a coroutine
  run on the loop ends; the turn is someone else's meanwhile.

On the virtual clock the turn is a baton (:class:`~actors.compat.turns.VirtualTurn`):
the loop runs only while no script thread does, so virtual time moves only
while every script thread waits.
"""

from __future__ import annotations

import _thread
import asyncio
import concurrent.futures
import concurrent.futures.thread
import contextlib
import functools
import threading
import time
from asyncio.events import _get_running_loop, _set_running_loop
from collections.abc import Awaitable, Callable, Iterator, Sequence
from concurrent.futures import Future
from contextlib import ExitStack, contextmanager
from typing import Any, TypeVar

import anyio
import anyio.abc
import anyio.from_thread
import anyio.lowlevel

from actors.compat.dispatch import Dispatcher
from actors.compat.turns import ScriptTimeLoop, ScriptWallLoop, Turn, VirtualTurn, Waiter, WallTurn
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
        self.turn: Turn = VirtualTurn() if self.virtual else WallTurn()
        # The overlay's state (ready work, executors, waiters) is the runtime's: the turn guards both.
        self.lock = self.turn
        self.failure: BaseException | None = None
        self._graph = graph
        self._duration = duration
        self._on_duration = on_duration
        self._on_failure = on_failure
        self._attach = tuple(attach)
        self._stack: ExitStack | None = None
        self._done: Future[None] | None = None
        self._stopping = False
        self.runtime: Runtime
        self.dispatcher: Dispatcher
        self.loop: asyncio.AbstractEventLoop

    # -- lifecycle --------------------------------------------------------------

    def start(self) -> Session:
        """Start the loop thread and the runtime (and the graph); return self.

        The calling thread holds the turn when it returns: it is about to run
        the script.  Raises what starting the graph raises.
        """
        turn = self.turn
        factory: Callable[[], asyncio.AbstractEventLoop] = (
            functools.partial(ScriptTimeLoop, turn)
            if isinstance(turn, VirtualTurn)
            else functools.partial(ScriptWallLoop, turn)  # type: ignore[arg-type]  # a WallTurn here
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
        if isinstance(turn, VirtualTurn):
            turn.come()
        return self

    async def _serve(self, *, task_status: anyio.abc.TaskStatus[None]) -> None:
        self.loop = asyncio.get_running_loop()
        self._loop_thread = threading.current_thread()
        self.dispatcher = Dispatcher(self.loop, self.turn.parks)
        self._stop = anyio.Event()
        policy = self._graph[0].supervisor.policy() if self._graph else None
        async with Runtime(name=self.name, supervisor=policy, attach=self._attach) as rt:
            self.runtime = rt
            async with anyio.create_task_group() as tg:
                if self._graph is not None:
                    await tg.start(spawn_graph, rt, *self._graph)
                if self._duration:
                    tg.start_soon(self._end_after, self._duration)
                if isinstance(self.turn, VirtualTurn):
                    self.turn.expect()  # the thread that started the session takes the baton first
                task_status.started()
                await self._stop.wait()
                tg.cancel_scope.cancel()

    async def _end_after(self, seconds: float) -> None:
        await anyio.sleep(seconds)
        if isinstance(self.turn, VirtualTurn):
            # What is due at the last instant still runs, as in a graph file's run (a 0.5 s timer
            # ticks at t = 1.0 of --duration 1): the script threads it woke take their turns first.
            await anyio.lowlevel.checkpoint()
            while self.turn.has_queue():
                await anyio.lowlevel.checkpoint()
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
        self.turn.stop()

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
                self.turn.close()  # script threads still waiting on the runtime end first
                self.call(self._stop.set)
                if isinstance(self.turn, VirtualTurn):
                    self.turn.depart()  # the loop needs the baton to stop, for good
                _wait_quietly(self._done)
        finally:
            stack.close()
            self.turn.stop()

    def __enter__(self) -> Session:
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.close()

    @property
    def running(self) -> bool:
        """Whether the runtime runs (started, not yet ended)."""
        return self._done is not None and not self._done.done()

    # -- calls from other threads ------------------------------------------------

    def call(self, fn: Callable[..., T], *args: Any, **kwargs: Any) -> T:
        """``fn(*args, **kwargs)`` with the turn held, on the calling thread; its result.

        Raises RuntimeError once the runtime has stopped.
        """
        turn = self.turn
        if turn.stopped:
            raise self._ended_error()
        with turn:
            # Runtime code may ask for the running loop (anyio does): on a script thread, it is ours.
            outer = _get_running_loop()
            if outer is not self.loop:
                _set_running_loop(self.loop)
                if _async_library is not None:
                    _async_library.set("asyncio")
            try:
                if turn._depth == 1:  # the call's own section: what it makes due is settled as it ends
                    return self.dispatcher.script_call(fn, *args, **kwargs)
                return fn(*args, **kwargs)
            finally:
                if outer is not self.loop:
                    _set_running_loop(outer)

    def _ended_error(self) -> RuntimeError:
        return RuntimeError(f"the runtime of {self.name!r} has stopped")

    def waiter(self) -> Waiter:
        """A new :class:`Waiter` for a wait of the calling thread."""
        return Waiter(self.turn)

    def block(self, async_fn: Callable[..., Awaitable[T]], *args: Any) -> T:
        """Await ``async_fn(*args)`` on the loop, the caller parked until it ends.

        KeyboardInterrupt while waiting cancels the coroutine.  Raises
        RuntimeError on the loop thread itself, which must never block.
        """
        if threading.current_thread() is getattr(self, "_loop_thread", None):
            raise RuntimeError("the runtime's own thread cannot block on the runtime")
        waiter = self.waiter()
        with self.turn:
            if self.turn.stopped:
                raise self._ended_error()
            task = self.loop.create_task(_as_coroutine(async_fn, *args))
            task.add_done_callback(lambda _: waiter.wake())
            try:
                self.wait_until(task.done, None, waiter)
            except BaseException:
                task.cancel()
                raise
            if not task.done():
                raise self._ended_error()
            return task.result()

    def wake_after(self, seconds: float, wake: Callable[[], None]) -> asyncio.TimerHandle:
        """Call ``wake()`` on the loop thread ``seconds`` of runtime clock from now."""
        return self.call(self.loop.call_later, max(0.0, seconds), wake)

    def sleep(self, seconds: float) -> None:
        """Wait ``seconds`` of runtime clock (virtual under virtual time), parked."""
        self.wait_until(lambda: False, seconds)

    def settle(self) -> None:
        """On the virtual clock, park until the runtime has nothing left to do at this instant."""
        turn = self.turn
        if isinstance(turn, VirtualTurn) and not turn.stopped:
            with turn:
                turn.settle(self.waiter())

    @contextmanager
    def timekeeping(self) -> Iterator[None]:
        """Inside the block, on the virtual clock, script threads keep virtual time honest.

        In a thread that holds the turn, ``time.sleep`` sleeps runtime time and
        a wait on a :class:`threading.Condition` (so on an Event, a queue, a
        semaphore) is a wait on the runtime, woken in order by ``notify``; a
        thread it starts queues for the turn from ``start()`` (except a pool's
        worker), and joining one is a wait.  Other threads are left alone.
        Such a wait that the end of the runtime cuts short raises SystemExit:
        the run is over, and the thread ends with it.
        """
        turn = self.turn
        if not isinstance(turn, VirtualTurn):
            yield
            return
        real = _Threading()

        def sleep(seconds: float) -> None:
            if seconds < 0:
                raise ValueError("sleep length must be non-negative")
            if turn.mine() and not turn.stopped:
                self.sleep(seconds)
                _end_if_over(turn)
            else:
                real.sleep(seconds)

        def start(thread: threading.Thread) -> None:
            if turn.mine() and not _pool_worker(thread) and not hasattr(thread, "_actors_end"):
                self._enlist(thread)
            # start() waits for the new thread to say it runs, which it does without the turn.
            _plain.waits = True
            try:
                real.start(thread)
            finally:
                _plain.waits = False

        def join(thread: threading.Thread, timeout: float | None = None) -> None:
            end = getattr(thread, "_actors_end", None)
            if end is not None and turn.mine() and not turn.stopped and thread.is_alive():
                # Joining a thread that needs the baton to finish: a wait, not a block holding it.
                self.wait_until(lambda: _ended(thread), timeout, end)
                if not _ended(thread):
                    return
            if end is None and turn.mine():
                with turn.stepped_out():  # it may need the turn to finish
                    real.join(thread, timeout)
                return
            real.join(thread, timeout)

        def wait(condition: Any, timeout: float | None = None) -> bool:  # a Condition: its private parts too
            if not turn.mine() or turn.stopped or (timeout is not None and timeout <= 0) or _plain.waits:
                return real.wait(condition, timeout)
            if not condition._is_owned():
                raise RuntimeError("cannot wait on un-acquired lock")
            # As Condition.wait, with the turn's wait in place of a blocking acquire of the marker.
            marker = _thread.allocate_lock()
            marker.acquire()
            condition._waiters.append(marker)
            waiting: dict[Any, Waiter] = condition.__dict__.setdefault("_actors_waiting", {})
            waiting[marker] = waiter = self.waiter()
            saved = condition._release_save()
            notified = False
            try:
                self.wait_until(lambda: not marker.locked(), None if timeout is None else max(0.0, timeout), waiter)
                notified = not marker.locked()
                if not notified:
                    _end_if_over(turn)
            finally:
                del waiting[marker]
                condition._acquire_restore(saved)
                if not notified:
                    with contextlib.suppress(ValueError):
                        condition._waiters.remove(marker)
            return notified

        def notify(condition: threading.Condition, n: int = 1) -> None:
            real.notify(condition, n)
            for marker, waiter in list(condition.__dict__.get("_actors_waiting", {}).items()):
                if not marker.locked():
                    waiter.wake()

        patched = _Threading(sleep, start, join, wait, notify)
        patched.install()
        try:
            yield
        finally:
            real.install()

    def _enlist(self, thread: threading.Thread) -> None:
        # On the virtual clock, a thread about to start queues for the baton from now; joining it
        # is a wait that its end wakes (see timekeeping's join).
        turn = self.turn
        if isinstance(turn, VirtualTurn) and not turn.stopped:
            waiter = turn.enlist(self.waiter())
            end = thread._actors_end = self.waiter()  # type: ignore[attr-defined]  # read by join
            thread.run = functools.partial(self._run_enlisted, waiter, end, thread.run)  # type: ignore[method-assign]  # wrapped for this thread

    def _run_enlisted(self, waiter: Waiter, end: Waiter, run: Callable[[], object]) -> None:
        # A thread's whole life under the baton: it waits for its turn, runs, and hands the baton on.
        turn = self.turn
        assert isinstance(turn, VirtualTurn)
        turn.arrive(waiter)
        try:
            run()
        except SystemExit:
            if not turn.over:  # the thread's own: as threading would, quietly
                raise
        finally:
            current = threading.current_thread()
            current._actors_ended = True  # type: ignore[attr-defined]  # read by join
            if not turn.stopped:
                end.wake()
            turn.depart()

    def start_thread(self, target: Callable[[], Any], name: str) -> threading.Thread:
        """Start a daemon thread running ``target()`` with the turn, queued for it from now."""
        thread = threading.Thread(target=target, name=name, daemon=True)
        self._enlist(thread)
        thread.start()
        return thread

    def submit(self, pool: concurrent.futures.Executor, fn: Callable[[], T]) -> concurrent.futures.Future[T]:
        """``pool.submit(fn)``; on the virtual clock the job queues for the turn from now (in the
        order jobs are submitted) and runs with it."""
        turn = self.turn
        if not isinstance(turn, VirtualTurn) or turn.stopped:
            return pool.submit(fn)
        waiter = self.waiter()

        def run() -> T:
            turn.arrive(waiter)
            try:
                return fn()
            finally:
                turn.depart()

        future = pool.submit(run)
        turn.enlist(waiter)  # after submit: a wait inside it must not hand the baton to this job
        return future

    def wait_until(self, done: Callable[[], T], timeout: float | None, waiter: Waiter | None = None) -> T:
        """Wait until ``done()`` (checked with the turn held) returns something true; return it.

        ``waiter`` is the one whoever makes ``done()`` true wakes (made here if
        None: then only the timeout wakes it).  After ``timeout`` seconds of
        runtime clock (None: no limit), returns what ``done()`` returns then;
        also once the runtime has ended (no runtime time passes any more).
        """
        waiter = self.waiter() if waiter is None else waiter
        turn = self.turn
        expired = False

        def time_up() -> None:
            nonlocal expired
            expired = True
            waiter.wake()

        with turn:
            timer = None
            if timeout is not None and not turn.stopped:
                timer = self.loop.call_later(max(0.0, timeout), time_up)
            try:
                flush = self.dispatcher.flush
                while True:
                    waiter.clear()
                    flush()
                    result = done()
                    if result or expired or turn.over:
                        return result
                    turn.wait(waiter)
            finally:
                if timer is not None and not expired:
                    timer.cancel()


class _Plain(threading.local):
    waits = False  # inside Thread.start: a Condition's wait there is a plain one


_plain = _Plain()


def _end_if_over(turn: Turn) -> None:
    # A script thread whose wait the end of the runtime cut short: the run is over, and so is the
    # thread (SystemExit ends a thread quietly), so that nothing keeps the process alive.
    if turn.over:
        raise SystemExit(0)


def _pool_worker(thread: threading.Thread) -> bool:
    # A worker of a concurrent.futures pool parks in its queue between jobs, holding nothing: each
    # job takes the turn when it touches the runtime (see Session.job), the thread itself does not.
    return getattr(thread, "_target", None) is concurrent.futures.thread._worker


def _ended(thread: threading.Thread) -> bool:
    return not thread.is_alive() or getattr(thread, "_actors_ended", False)


async def _as_coroutine(async_fn: Callable[..., Awaitable[T]], *args: Any) -> T:
    return await async_fn(*args)


def _wait_quietly(done: Future[None]) -> None:
    try:
        done.result()
    except BaseException:
        pass


class _Threading:
    """The parts of :mod:`time` and :mod:`threading` that :meth:`Session.timekeeping` replaces."""

    def __init__(
        self,
        sleep: Callable[[float], None] = time.sleep,
        start: Callable[..., None] = threading.Thread.start,
        join: Callable[..., None] = threading.Thread.join,
        wait: Callable[..., bool] = threading.Condition.wait,
        notify: Callable[..., None] = threading.Condition.notify,
    ) -> None:
        self.sleep, self.start, self.join, self.wait, self.notify = sleep, start, join, wait, notify

    def install(self) -> None:
        time.sleep = self.sleep  # type: ignore[assignment]  # a patch, on purpose
        # Patches of the standard library, on purpose (DESIGN.md lists them, and why).
        setattr(threading.Thread, "start", self.start)  # noqa: B010  # mypy forbids assigning a method
        setattr(threading.Thread, "join", self.join)  # noqa: B010
        setattr(threading.Condition, "wait", self.wait)  # noqa: B010
        setattr(threading.Condition, "notify", self.notify)  # noqa: B010
