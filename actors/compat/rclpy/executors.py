"""``rclpy.executors``: which thread runs a script node's callbacks, and when.

An executor waits (parked on a :class:`~actors.compat.turns.Waiter`, so virtual
time may move) until one of its nodes has work its callback group allows, or a
task (a coroutine callback that can go on, a done callback) is ready.  It then
hands out a *handler*, an rclpy :class:`~actors.compat.rclpy.task.Task` that
asks the group, takes one item from the work source, runs the callback and
tells the group it is over.  :class:`SingleThreadedExecutor` runs handlers on
the thread that spins; :class:`MultiThreadedExecutor` on a pool of threads,
handing out work only while a worker is free (work waiting in a queue would
hold virtual time still); a subclass may run them elsewhere, from
:meth:`Executor.wait_for_ready_callbacks`.

As in rclpy, ready work is handed out in rounds: every work source ready at the
start of a round (timers, subscriptions, guard conditions, clients, services,
waitables, node by node) gets its turn before any is looked at again.
"""

from __future__ import annotations

import contextvars
import functools
import os
import threading
import warnings
from collections import deque
from collections.abc import Callable, Iterator
from concurrent.futures import ThreadPoolExecutor
from typing import TYPE_CHECKING, Any, TypeVar

from actors.compat.dispatch import ScriptNode as Node
from actors.compat.dispatch import WorkSource
from actors.compat.rclpy.context import Context
from actors.compat.rclpy.exceptions import NotInitializedException
from actors.compat.rclpy.task import Future, Task, await_or_execute
from actors.compat.rclpy.utilities import get_default_context
from actors.compat.turns import Waiter

if TYPE_CHECKING:
    from actors.compat.session import Session

__all__ = [
    "Executor",
    "SingleThreadedExecutor",
    "MultiThreadedExecutor",
    "TimeoutException",
    "ShutdownException",
    "ExternalShutdownException",
    "ConditionReachedException",
    "TimeoutObject",
    "await_or_execute",
]

T = TypeVar("T")


class TimeoutException(Exception):
    """No work came before the timeout."""


class ShutdownException(Exception):
    """The executor was shut down."""


class ExternalShutdownException(Exception):
    """The context was shut down (``rclpy.shutdown()``, Ctrl-C, the end of ``--duration``)."""


class ConditionReachedException(Exception):
    """What the executor waited for happened (a future is done)."""


class TimeoutObject:
    """A timeout that shrinks as ``spin_until_future_complete`` goes on."""

    def __init__(self, timeout: float) -> None:
        self.timeout = timeout


def _seconds(timeout: float | TimeoutObject | None) -> float | None:
    if isinstance(timeout, TimeoutObject):
        timeout = timeout.timeout
    return None if timeout is None or timeout < 0 else timeout


class Executor:
    """Runs the callbacks of the nodes added to it; subclasses say on which thread (``spin_once``)."""

    def __init__(self, *, context: Context | None = None) -> None:
        self._context = get_default_context() if context is None else context
        self._nodes: list[Node] = []
        self._tasks: list[tuple[Task[Any], WorkSource | None, Node | None]] = []
        self._round: deque[tuple[WorkSource, Node]] = deque()
        self._waiters: set[Waiter] = set()
        self._is_shutdown = False
        self._context.add_waker(self)

    @property
    def context(self) -> Context:
        """The context the executor belongs to."""
        return self._context

    @property
    def _session(self) -> Session:
        session = self._context.session
        if session is None:
            raise NotInitializedException("an executor needs rclpy.init() first")
        return session

    # -- nodes and tasks ------------------------------------------------------------

    def add_node(self, node: Node) -> bool:
        """Spin ``node`` here (it leaves any other executor); whether it was not here already."""
        with self._session.lock:
            if node in self._nodes:
                return False
            self._nodes.append(node)
        node.executor = self
        self.wake()
        return True

    def remove_node(self, node: Node) -> None:
        """Stop spinning ``node``."""
        with self._session.lock:
            if node in self._nodes:
                self._nodes.remove(node)
        self.wake()

    def get_nodes(self) -> list[Node]:
        """The nodes spun here."""
        with self._session.lock:
            return list(self._nodes)

    def create_task(self, callback: Callable[..., Any], *args: Any, **kwargs: Any) -> Task[Any]:
        """Run ``callback(*args, **kwargs)`` (or a coroutine function) during a later spin; its Task."""
        task: Task[Any] = Task(callback, args, kwargs, executor=self)
        session = self._session
        with session.lock:
            self._tasks.append((task, None, None))
        self.wake()
        return task

    def create_future(self) -> Future[Any]:
        """A Future whose done callbacks run as tasks of this executor."""
        return Future(executor=self)

    def wake(self) -> None:
        """Make waiting spins look again (new work, a node added, shutdown)."""
        session = self._context.session
        if session is None:
            return
        with session.lock:
            for waiter in self._waiters:
                waiter.wake()

    def shutdown(self, timeout_sec: float | None = None) -> bool:
        """Stop handing out work (callbacks running now go on, as in rclpy); True."""
        self._is_shutdown = True
        self.wake()
        session = self._context.session
        if session is not None:
            with session.lock:
                self._nodes = []
        return True

    def __enter__(self) -> Executor:
        return self

    def __exit__(self, *exc: object) -> None:
        self.shutdown()

    # -- spinning -------------------------------------------------------------------

    def spin(self) -> None:
        """Run callbacks until the context or the executor shuts down."""
        while self._context.ok() and not self._is_shutdown:
            self.spin_once()

    def spin_once(self, timeout_sec: float | None = None) -> None:
        """Wait for one callback (``timeout_sec`` at most; None waits forever) and run it."""
        self._spin_once_impl(timeout_sec)

    def _spin_once_impl(
        self, timeout_sec: float | TimeoutObject | None = None, condition: Callable[[], bool] = lambda: False
    ) -> None:
        raise NotImplementedError()

    def spin_until_future_complete(self, future: Future[Any], timeout_sec: float | None = None) -> None:
        """Run callbacks until ``future`` is done, ``timeout_sec`` of runtime clock pass, or shutdown."""
        future._add_resumer(self.wake)
        timeout = _seconds(timeout_sec)
        if timeout is None:
            while self._context.ok() and not future.done() and not future.cancelled() and not self._is_shutdown:
                self._spin_once_until_future_complete(future, None)
            return
        session = self._session
        end = session.loop.time() + timeout
        left = TimeoutObject(timeout)
        while self._context.ok() and not future.done() and not future.cancelled() and not self._is_shutdown:
            self._spin_once_until_future_complete(future, left)
            now = session.loop.time()
            if now >= end:
                return
            left.timeout = end - now

    def spin_once_until_future_complete(
        self, future: Future[Any], timeout_sec: float | TimeoutObject | None = None
    ) -> None:
        """As :meth:`spin_once`, also returning when ``future`` is done."""
        future._add_resumer(self.wake)
        self._spin_once_until_future_complete(future, timeout_sec)

    def _spin_once_until_future_complete(
        self, future: Future[Any], timeout_sec: float | TimeoutObject | None = None
    ) -> None:
        self._spin_once_impl(timeout_sec, future.done)

    # -- handing out work -------------------------------------------------------------

    def can_execute(self, entity: WorkSource) -> bool:
        """Whether ``entity``'s callback may be handed out now (its group lets it, not handed out yet)."""
        group = entity.callback_group
        return not entity._executor_event and group is not None and group.can_execute(entity)

    def _has_capacity(self) -> bool:
        return True

    def wait_for_ready_callbacks(
        self,
        timeout_sec: float | TimeoutObject | None = None,
        nodes: list[Node] | None = None,
        condition: Callable[[], bool] = lambda: False,
    ) -> tuple[Task[None], WorkSource | None, Node | None]:
        """Wait for work and return ``(handler, entity, node)``: call ``handler()`` to run it.

        Raises TimeoutException after ``timeout_sec`` seconds of runtime clock
        (at once for 0), ShutdownException when the executor shuts down,
        ExternalShutdownException when the context does, and
        ConditionReachedException when ``condition()`` becomes true.  On the
        virtual clock the clock stands still until ``handler()`` is called, on
        whichever thread the caller hands it to.
        """
        work = self._ready_work(timeout_sec, nodes, condition)
        work[0]._claim(self._session.turn)
        return work

    def _ready_work(
        self,
        timeout_sec: float | TimeoutObject | None = None,
        nodes: list[Node] | None = None,
        condition: Callable[[], bool] = lambda: False,
    ) -> tuple[Task[None], WorkSource | None, Node | None]:
        # wait_for_ready_callbacks for this module's executors, which run the handler themselves.

        def ready() -> tuple[Task[None], WorkSource | None, Node | None] | None:
            if self._is_shutdown:
                raise ShutdownException()
            if not self._context.ok():
                raise ExternalShutdownException()
            if condition():
                raise ConditionReachedException()
            return self._next(nodes) if self._has_capacity() else None

        work = self._wait_until(ready, _seconds(timeout_sec))
        if work is None:
            raise TimeoutException()
        return work

    def _next(self, nodes: list[Node] | None) -> tuple[Task[None], WorkSource | None, Node | None] | None:
        # With the session's lock held.
        spun = self._nodes if nodes is None else nodes
        for entry in list(self._tasks):
            task, entity, node = entry
            if not task._pending():
                self._tasks.remove(entry)
            elif task.runnable() and not task._handed and (node is None or node in spun):
                task._handed = True
                return entry
        for fresh in (False, True):
            if fresh or not self._round:
                self._round = deque(self._ready_sources(spun))
            while self._round:
                entity, node = self._round.popleft()
                if node in spun and entity._ready() and self.can_execute(entity):
                    return self._make_handler(entity, node)
        return None

    def _ready_sources(self, nodes: list[Node]) -> Iterator[tuple[WorkSource, Node]]:
        for node in nodes:
            for entity in node._rclpy.work_sources():
                if entity._ready() and not entity._executor_event:
                    yield entity, node

    def _make_handler(self, entity: WorkSource, node: Node) -> tuple[Task[None], WorkSource, Node]:
        entity._executor_event = True
        session = self._session
        group = entity.callback_group

        async def handler() -> None:
            if self._is_shutdown or (group is not None and not group.beginning_execution(entity)):
                entity._executor_event = False
                self.wake()
                return
            try:
                with session.lock:
                    run = entity._take()
                    entity._executor_event = False
                self.wake()
                if run is not None:
                    await run()
            finally:
                if group is not None:
                    group.ending_execution(entity)
                self.wake()

        task: Task[None] = Task(handler, executor=self)
        task._handed = True
        self._tasks.append((task, entity, node))
        return task, entity, node

    def _wait_until(self, done: Callable[[], T], timeout: float | None) -> T:
        """Wait (woken by :meth:`wake`) until ``done()`` is true; what it returns then, or after
        ``timeout`` seconds."""
        session = self._session
        waiter = session.waiter()
        with session.lock:
            self._waiters.add(waiter)
        try:
            return session.wait_until(done, timeout, waiter)
        finally:
            with session.lock:
                self._waiters.discard(waiter)


class SingleThreadedExecutor(Executor):
    """Runs callbacks on the thread that calls :meth:`spin`."""

    def _spin_once_impl(
        self, timeout_sec: float | TimeoutObject | None = None, condition: Callable[[], bool] = lambda: False
    ) -> None:
        try:
            handler, _entity, _node = self._ready_work(timeout_sec, None, condition)
        except (ShutdownException, TimeoutException, ConditionReachedException):
            return
        handler()
        exception = handler.exception()
        if exception is not None:
            raise exception


class MultiThreadedExecutor(Executor):
    """Runs callbacks on a pool of ``num_threads`` threads (as many as CPUs by default)."""

    def __init__(self, num_threads: int | None = None, *, context: Context | None = None) -> None:
        super().__init__(context=context)
        if num_threads is None:
            num_threads = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
            num_threads = num_threads or 2
        if num_threads == 1:
            warnings.warn(
                "MultiThreadedExecutor is used with a single thread.\nUse the SingleThreadedExecutor instead.",
                stacklevel=2,
            )
        self._num_threads = num_threads
        self._in_pool = 0
        self._futures: list[Task[Any]] = []
        self._executor = ThreadPoolExecutor(num_threads, thread_name_prefix="rclpy executor")

    def _has_capacity(self) -> bool:
        return self._in_pool < self._num_threads

    def _run(self, handler: Task[Any]) -> None:
        _worker.active = True
        try:
            handler()
        finally:
            with self._session.lock:
                self._in_pool -= 1
            self.wake()

    def _spin_once_impl(
        self, timeout_sec: float | TimeoutObject | None = None, condition: Callable[[], bool] = lambda: False
    ) -> None:
        try:
            handler, _entity, _node = self._ready_work(timeout_sec, None, condition)
        except (ExternalShutdownException, ShutdownException, TimeoutException, ConditionReachedException):
            pass
        else:
            session = self._session
            with session.lock:
                self._in_pool += 1
            # In a copy of the spinning thread's context: the callback sees its script's rclpy state.
            session.submit(self._executor, functools.partial(contextvars.copy_context().run, self._run, handler))
            self._futures.append(handler)
        for future in self._futures[:]:
            if future.done():
                self._futures.remove(future)
                future.result()  # raise what the callback raised

    def shutdown(self, timeout_sec: float | None = None, *, wait_for_threads: bool = True) -> bool:
        """Stop handing out work; with ``wait_for_threads``, wait for the running callbacks (not
        from one of them), ``timeout_sec`` of runtime clock at most; whether they ended."""
        super().shutdown(timeout_sec)
        ended = True
        if wait_for_threads and not getattr(_worker, "active", False) and self._context.session is not None:
            # As a waiter: a callback sleeping on virtual time must be able to wake up and end.
            ended = self._wait_until(lambda: self._in_pool == 0, _seconds(timeout_sec))
        self._executor.shutdown(wait=wait_for_threads and ended)
        return ended


_worker = threading.local()  # .active on the pool's threads
