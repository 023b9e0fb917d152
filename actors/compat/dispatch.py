"""How a script node's work reaches the rclpy executors: the node's actor and its work sources.

A script node (an ``rclpy.node.Node`` built by a script) is a native node
whose actor is a :class:`ScriptActor`.  Native entities schedule themselves on
their node's actor when they have work, on the loop thread, as always:

- entities the overlay created (subscriptions, timers, services) have the
  overlay's *catchers* as their callbacks.  The actor runs them at once on the
  loop thread; a catcher only queues the item (a message, a tick, a request) on
  its :class:`WorkSource` and wakes the node's executor.  A service's catcher
  then awaits the response the script's callback will give, in a task of its
  own, so a slow service never holds up the node's other entities;
- entities the native node made itself (its parameter services) are *gated*:
  they wait as a :class:`NativeWork` until an executor takes them, and then run
  on the loop thread while the executor's thread waits for them.

An executor takes one item at a time from a work source (:meth:`WorkSource._take`)
and runs the script's callback on its own thread.  Nothing of the node's runs
unless a script thread spins it, as in rclpy.
"""

from __future__ import annotations

import asyncio
import functools
from collections import deque
from collections.abc import Awaitable, Callable, Coroutine
from typing import Any, Protocol, TypeVar

from actors.core._actor import Actor, Entity
from actors.ros.actions import ActionCall, ActionClient, ActionServer

__all__ = [
    "Dispatcher",
    "ScriptActor",
    "WorkSource",
    "NativeWork",
    "NativeProxy",
    "NodeState",
    "ScriptNode",
    "SpinningExecutor",
]

T = TypeVar("T")
Handler = Callable[[], Coroutine[Any, Any, None]]


class NodeState(Protocol):
    """The overlay's side of a script node, as its entities and executors use it (``node._rclpy``)."""

    session: Any
    lock: Any
    clock: Any
    context: Any

    destroyed: bool

    def notify(self) -> None: ...

    def work_sources(self) -> list[WorkSource]: ...


class SpinningExecutor(Protocol):
    """An executor, as nodes and futures see it."""

    def add_node(self, node: Any) -> bool: ...

    def remove_node(self, node: Any) -> None: ...

    def wake(self) -> None: ...

    def create_task(self, callback: Callable[..., Any], *args: Any, **kwargs: Any) -> Any: ...


class ScriptNode(Protocol):
    """A script node, as its entities and executors use it (``rclpy.node.Node``)."""

    @property
    def _rclpy(self) -> NodeState: ...  # read-only here, so a node's own state class may be a subtype

    @property
    def executor(self) -> SpinningExecutor | None: ...

    @executor.setter
    def executor(self, executor: SpinningExecutor | None) -> None: ...

    @property
    def context(self) -> Any: ...

    @property
    def default_callback_group(self) -> Any: ...

    def get_logger(self) -> Any: ...

    def add_waitable(self, waitable: WorkSource) -> None: ...

    def remove_waitable(self, waitable: WorkSource) -> None: ...

    def destroy_node(self) -> None: ...

    def destroy_publisher(self, publisher: Any) -> bool: ...

    def destroy_subscription(self, subscription: Any) -> bool: ...

    def destroy_timer(self, timer: Any) -> bool: ...

    def destroy_service(self, service: Any) -> bool: ...

    def destroy_client(self, client: Any) -> bool: ...

    def destroy_guard_condition(self, guard: Any) -> bool: ...

    def _create(self, source: Any, create: Callable[..., Any], *args: Any, **options: Any) -> None: ...


class WorkSource:
    """Something an executor can take work from: rclpy's entity (subscription, timer, service...).

    ``_ready()`` and ``_take()`` are called with the session's lock held;
    ``_take()`` removes one item and returns the coroutine function that runs
    the callback for it (on the executor's thread), or None if nothing is left.
    """

    callback_group: Any = None
    catcher: Callable[..., Any] | None = None  # the callback the native entity calls, if any
    _executor_event = False  # handed to an executor and not taken yet (rclpy's flag)

    def _ready(self) -> bool:
        raise NotImplementedError

    def _take(self) -> Handler | None:
        raise NotImplementedError

    def _attach(self, native: Any) -> None:
        """The native entity behind this one (set on the runtime's thread, before it can fire)."""
        self._native = native


class NativeProxy:
    """Lends an overlay object the native entity's other attributes; its methods run on the loop thread."""

    _native: Any
    _session: Any

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        value = getattr(self._native, name)
        if callable(value) and not isinstance(value, type):
            return functools.partial(self._session.call, value)
        return value


class NativeWork(WorkSource):
    """A native entity of a script node (a parameter service), run on the loop when an executor takes it."""

    def __init__(self, entity: Entity, callback_group: Any, block: Callable[..., Any]) -> None:
        self.entity = entity
        self.callback_group = callback_group
        self._block = block
        self.scheduled = False

    def _ready(self) -> bool:
        return self.scheduled

    def _take(self) -> Handler | None:
        if not self.scheduled:
            return None
        self.scheduled = False

        async def run() -> None:
            self._block(_run_entity, self.entity)

        return run


async def _run_entity(entity: Entity) -> None:
    pending = entity._run()
    if pending is not None:
        await pending


class Dispatcher:
    """Runs the catchers of a session's script nodes with the turn held, soon after they are due.

    Never inside the call that made them due (a catcher must not run in the
    middle of a publisher's call).  What the loop makes due runs in a loop
    callback.  What a script's call makes due runs when the call ends if some
    thread is parked (it may be waiting for it), and otherwise at the next look
    for work (:meth:`Session.wait_until` flushes first): a thread starts to wait
    only after it has looked, so a loop of publishes costs one append each.
    """

    def __init__(self, loop: asyncio.AbstractEventLoop, parked: Callable[[], bool]) -> None:
        self._loop = loop
        self._parked = parked
        self._due: deque[tuple[ScriptActor, Entity]] = deque()
        self._armed = False  # no loop callback to ask for: one will flush, or a script's call settles

    def add(self, actor: ScriptActor, entity: Entity) -> None:
        """Run ``entity`` of ``actor`` at the next :meth:`flush` (one is scheduled)."""
        self._due.append((actor, entity))
        if not self._armed:
            self._armed = True
            self._loop.call_soon(self.flush)

    def flush(self) -> None:
        """Run every entity due now."""
        self._armed = False
        due = self._due
        while due:
            actor, entity = due.popleft()
            actor._drive(entity)

    def script_call(self, fn: Callable[..., T], *args: Any, **kwargs: Any) -> T:
        """``fn(*args, **kwargs)`` for a script's call (with the turn held): its result."""
        armed, self._armed = self._armed, True
        try:
            return fn(*args, **kwargs)
        finally:
            self._armed = armed
            if self._due and self._parked():
                self.flush()


class ScriptActor(Actor):
    """A script node's actor: it runs the overlay's catchers and hands everything else to executors."""

    __slots__ = ("_driven", "_gated", "_tasks", "_on_error", "_dispatcher")

    def __init__(
        self,
        dispatcher: Dispatcher,
        loop: asyncio.AbstractEventLoop,
        on_gated: Callable[[Entity], None],
        on_error: Callable[[BaseException], None],
    ) -> None:
        super().__init__(loop)
        self._dispatcher = dispatcher
        self._driven: set[Any] = set()
        self._gated = on_gated
        self._on_error = on_error
        self._tasks: set[asyncio.Task[None]] = set()

    def drive(self, catcher: Callable[..., Any]) -> None:
        """Run at once the entities whose callback is ``catcher`` (one of the overlay's).

        Called before the native entity exists: it may be scheduled while it is
        created (a parked service call, a latched message).
        """
        self._driven.add(catcher)

    def forget(self, catcher: Callable[..., Any]) -> None:
        """The entity of ``catcher`` was destroyed."""
        self._driven.discard(catcher)

    def schedule(self, entity: Entity) -> None:
        if not self._running:
            return
        # A subscription's or timer's callback, a service's handler; what an action of the node does
        # (every action of a script node is rclpy.action's: its handlers only call the overlay's catchers).
        callback = getattr(entity, "callback", None) or getattr(entity, "handler", None)
        if (
            (callback is not None and callback in self._driven)
            or isinstance(entity, ActionCall)
            or isinstance(getattr(callback, "__self__", None), (ActionServer, ActionClient))
        ):
            self._dispatcher.add(self, entity)
        else:
            self._gated(entity)

    def _drive(self, entity: Entity) -> None:
        if not self._running:
            return
        try:
            pending = entity._run()
        except Exception as exc:  # a catcher never raises; this would be the overlay's bug
            self._on_error(exc)
            return
        if pending is not None:
            task = self._loop.create_task(self._finish(pending))
            self._tasks.add(task)
            task.add_done_callback(self._tasks.discard)

    async def _finish(self, pending: Awaitable[None]) -> None:
        try:
            await pending
        except Exception as exc:
            self._on_error(exc)

    def stop(self) -> None:
        self._running = False
        for task in list(self._tasks):
            task.cancel()

    async def run(self) -> None:
        raise RuntimeError("a script node's callbacks run in the script's executors, not in a task")
