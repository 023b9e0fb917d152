"""The actor behind every node: one ready queue, one callback at a time, no task switch per wake-up.

Subscriptions, timers and services are *entities*.  An entity with work to do
is appended to its node's ready queue (:meth:`Actor.schedule`); the actor then
calls each ready entity's ``_run()`` in turn, one at a time, so a node's
callbacks never overlap and node code needs no locks.

``_run()`` returns None when it has finished, or an awaitable that must be
awaited to finish the work: entities run plain callbacks without a coroutine
of their own, and hand over to one only when a callback turns out ``async``.

Who drives an actor:

- The runtime's :class:`Scheduler` (the default).  An idle actor that gets work
  is appended to the scheduler's ready list, and one ``loop.call_soon`` per
  batch runs a *round* of every ready actor.  Waking a node is a list
  append, not a future, a loop handle and a task step: with 100 topics each
  feeding one node, that per-message task switch was most of the cost.  Idle
  nodes own no task at all (about 2 KB less each).  Rounds run in one context
  per runtime, copied when it started (not one per node, as tasks had): a
  ``ContextVar`` a callback sets is seen by the callbacks after it.
- A task of its own while an ``async`` callback runs: the round hands the
  awaitable to a new task (``Actor.task``) that awaits it, and the actor
  returns to the scheduler when it is done.  Entities scheduled meanwhile
  wait; the actor's callbacks still never overlap.
- A task that calls :meth:`Actor.run` (the command line's sessions): the actor
  then belongs to that task for good, woken by a bare future once per batch.

Each round runs only the entities that were ready when it began (the ready
list is swapped for an empty one); an actor that has more work afterwards
goes back in line for the next batch, after the loop has polled I/O, so a
node that keeps itself busy cannot starve the others.  A list, not a deque:
an idle node's empty deque costs 760 bytes, an empty list 56.

A callback that raises ends the actor: the error (a :class:`CallbackFailed`)
goes to ``on_exit`` (the supervisor's), as does a normal end (``stop()`` from
the node itself, e.g. ``destroy_node``); the supervisor clears ``on_exit``
before it stops an actor itself.
"""

from __future__ import annotations

import asyncio
import contextvars
from collections.abc import Awaitable, Callable
from typing import TYPE_CHECKING, Any, Protocol

from actors.core.loops import loop_clock

__all__ = ["Actor", "Scheduler", "Entity", "Owner", "CallbackFailed", "Mailbox", "OneShot", "AT_ONCE"]


class Entity(Protocol):
    """Something a node runs: a subscription, a timer, a service."""

    def _run(self) -> Awaitable[None] | None: ...


class _Schedules(Protocol):
    """What a mailbox wakes: its node's Actor, or a stand-in that runs it at once (an action client's feedback)."""

    def schedule(self, entity: Entity) -> None: ...


class Owner(Protocol):
    """What an entity needs from whoever owns it: a node's core, or a command-line session.

    Entities are created by their owner and call back into it only to be
    destroyed; they never import the node layer above them.
    """

    fqn: str
    actor: Actor
    loop: asyncio.AbstractEventLoop

    @property
    def logger(self) -> Any: ...

    def destroy_publisher(self, publisher: Any) -> None: ...

    def destroy_subscription(self, subscription: Any) -> None: ...

    def destroy_timer(self, timer: Any) -> None: ...

    def destroy_service(self, service: Any) -> None: ...

    def destroy_client(self, client: Any) -> None: ...


class CallbackFailed(Exception):
    """A callback raised: carries the entity, the item it was handling, and the error."""

    def __init__(self, entity: Any, item: Any, error: BaseException) -> None:
        super().__init__(error)
        self.entity = entity
        self.item = item
        self.error = error


class Scheduler:
    """Runs the rounds of a runtime's ready actors from one loop callback per batch."""

    __slots__ = ("_loop", "_ready", "_armed", "context", "_time", "_flush_soon")

    def __init__(self, loop: asyncio.AbstractEventLoop) -> None:
        self._loop = loop
        self._ready: list[Actor] = []
        self._armed = False
        self._time = loop_clock(loop)  # a round's busy_since
        self._flush_soon = self._flush  # one bound method, not a new one per wake
        # The context the rounds run in.  A loop callback that runs rounds itself (run_now,
        # Actor.run_one) is scheduled in it, so that they run without a Context.run of their own:
        # that call and the C-level frame it starts cost 1.3k instructions an instant.
        self.context = contextvars.copy_context()

    def wake(self, actor: Actor) -> None:
        """Run a round of ``actor`` soon (it is not in line already)."""
        self._ready.append(actor)
        if not self._armed:
            self._armed = True
            self._loop.call_soon(self._flush_soon, context=self.context)

    def hold(self) -> None:
        """Take wake-ups without a loop callback: the caller promises :meth:`run_now` before it returns."""
        self._armed = True

    def run_now(self) -> None:
        """Run the rounds due soon now, from a loop callback in :attr:`context` (a timer's: saves an iteration)."""
        if self._armed:
            self._flush()

    def _flush(self) -> None:
        self._armed = False
        ready, self._ready = self._ready, []
        clock = self._time
        for actor in ready:
            actor._round(clock)


class Actor:
    """A node's ready queue, run one entity at a time by a :class:`Scheduler` or a task."""

    __slots__ = (
        "_ready",
        "_waiter",
        "_loop",
        "_scheduler",
        "_running",
        "_queued",
        "task",
        "on_exit",
        "busy_since",
        "current",
    )

    def __init__(self, loop: asyncio.AbstractEventLoop, scheduler: Scheduler | None = None) -> None:
        self._ready: list[Entity] = []
        self._waiter: asyncio.Future[None] | None = None
        self._loop = loop
        self._scheduler = scheduler
        self._running = True
        self._queued = False  # in the scheduler's line, or in a round or task that will look again
        # The task awaiting an ``async`` callback, if one runs now: stopping the actor
        # then needs a cancellation; otherwise stop() alone guarantees no callback runs again.
        self.task: asyncio.Task[None] | None = None
        # Called once with None (the node stopped itself) or the error that ended the actor.
        self.on_exit: Callable[[BaseException | None], None] | None = None
        # What the actor is running now and since when (loop time): read by doctor's
        # loop-lag check to name the callback that blocks.
        self.busy_since = 0.0
        self.current: Entity | None = None

    @property
    def awaiting(self) -> bool:
        """Whether an ``async`` callback of this actor is in progress."""
        return self.task is not None

    def schedule(self, entity: Entity) -> None:
        """Queue ``entity`` to run; wake the actor if it is idle.  Never blocks."""
        self._ready.append(entity)
        waiter = self._waiter
        if waiter is not None:
            self._waiter = None
            if not waiter.done():
                waiter.set_result(None)
        elif not self._queued and self._scheduler is not None:
            self._queued = True
            self._scheduler.wake(self)

    def stop(self) -> None:
        """End the actor: no entity runs after the one running now, if any."""
        if not self._running:
            return
        self._running = False
        self._ready.clear()
        waiter = self._waiter
        if waiter is not None:
            self._waiter = None
            if not waiter.done():
                waiter.set_result(None)
        self._exit(None)

    @property
    def pending(self) -> int:
        """How many entities wait to run."""
        return len(self._ready)

    def _exit(self, error: BaseException | None) -> None:
        self._running = False
        on_exit, self.on_exit = self.on_exit, None
        if on_exit is not None:
            on_exit(error)

    def _round(self, clock: Callable[[], float]) -> None:
        # One round, run by the scheduler (``clock`` tells its loop's time): the entities ready now, until one is async.
        if not self._running:
            return
        batch = self._ready
        self._ready = []
        self.busy_since = clock()
        for entity in batch:
            self.current = entity
            try:
                pending = entity._run()
            except Exception as exc:
                self.current = None
                self._exit(exc)
                return
            if pending is not None:
                # The rest of this round runs after it (an entity is in a batch once).
                self._ready[:0] = batch[batch.index(entity) + 1 :]
                self.task = self._loop.create_task(self._finish(pending))
                return
            if not self._running:
                self.current = None
                return
        self.current = None
        if self._ready:  # _next, inlined: a frame less per round
            self._scheduler.wake(self)  # type: ignore[union-attr]  # a round runs under a scheduler, never after run()
        else:
            self._queued = False

    def run_one(self, entity: Entity, scheduler: Scheduler, now: float) -> None:
        """Schedule ``entity`` and run the rounds due now, as ``scheduler``'s hold, schedule and run_now would.

        For a loop callback in ``scheduler``'s context that wakes a single
        entity (a timer due alone) at loop time ``now``: when nothing else
        waits for a round and this actor is idle, its round of that entity
        runs at once, without the ready list and the calls around it.
        """
        if scheduler._armed or self._queued or self._scheduler is not scheduler:
            scheduler.hold()
            self.schedule(entity)
            scheduler.run_now()
            return
        # _round's steps for one entity, repeated on purpose: a simulation's instants mostly run one
        # timer, and each Python call saved here is saved on every physics step.
        if not self._running:
            return
        self._queued = True
        self.busy_since = now
        self.current = entity
        try:
            pending = entity._run()
        except Exception as exc:
            self.current = None
            self._exit(exc)
            return
        if pending is not None:
            self.task = self._loop.create_task(self._finish(pending))
            return
        self.current = None
        if not self._running:
            return
        if self._ready:  # scheduled during its callback
            scheduler.wake(self)
        else:
            self._queued = False

    def _next(self) -> None:
        if self._ready:
            self._scheduler.wake(self)  # type: ignore[union-attr]  # as in _round: only after a round
        else:
            self._queued = False

    async def _finish(self, pending: Awaitable[None]) -> None:
        # An async callback, awaited in a task of its own; then back to the scheduler.
        try:
            await pending
        except Exception as exc:
            self._exit(exc)
            return
        finally:
            self.task = self.current = None
        if self._running:
            self._next()

    async def run(self) -> None:
        """Run ready entities in the calling task until :meth:`stop`; a callback's error propagates."""
        loop = self._loop
        self._scheduler = None  # this task drives the actor from now on
        try:
            while self._running:
                batch = self._ready
                self._ready = []
                for entity in batch:
                    self.current = entity
                    self.busy_since = loop.time()
                    pending = entity._run()
                    if pending is not None:
                        await pending
                    if not self._running:
                        return
                self.current = None
                if self._ready:
                    await asyncio.sleep(0)
                else:
                    self._waiter = waiter = loop.create_future()
                    await waiter
        finally:
            self._waiter = None
            self.current = None


class _AtOnce:
    """Stands in for a mailbox's actor: runs it at once, where it is woken (inside ``publish()``).

    For a mailbox whose callback may run anywhere on the loop, never ``async``
    and never long: an action client's feedback router, a transport's outlet.
    """

    __slots__ = ()

    def schedule(self, entity: Entity) -> None:
        entity._run()


AT_ONCE = _AtOnce()


class Mailbox:
    """An entity with a queue (a subscription, a service): on its actor's ready queue at most once.

    Subclasses fill ``_queue`` and call :meth:`_wake`; their ``_run`` drains
    what was queued when the round began and ends with :meth:`_round_done`.
    """

    __slots__ = ("_queue", "_scheduled", "_actor")

    if TYPE_CHECKING:
        # Each subclass's own: what makes a mailbox an Entity.
        def _run(self) -> Awaitable[None] | None: ...

    def __init__(self, actor: Actor) -> None:
        self._queue: Any = None
        self._scheduled = False
        self._actor: _Schedules = actor

    @property
    def queued(self) -> int:
        """Items waiting in the queue."""
        return len(self._queue) if self._queue is not None else 0

    def _wake(self) -> None:
        if not self._scheduled:
            self._scheduled = True
            self._actor.schedule(self)

    def _adopt(self, old: Mailbox) -> None:
        # A restarted node takes over its predecessor's queue: nothing queued is lost.
        self._queue = old._queue
        if self._queue:
            self._wake()

    def _round_done(self) -> None:
        if self._queue:
            self._actor.schedule(self)  # still scheduled: more arrived during the round
        else:
            self._scheduled = False


class OneShot:
    """Runs ``fn()`` once in the actor (plain or ``async``): a node's ``on_start`` hook."""

    __slots__ = ("fn", "name")

    def __init__(self, fn: Any, name: str) -> None:
        self.fn = fn
        self.name = name

    def _run(self) -> Awaitable[None] | None:
        try:
            result = self.fn()
        except Exception as exc:
            raise CallbackFailed(self, None, exc) from exc
        if result is not None and hasattr(result, "__await__"):
            return self._run_async(result)
        return None

    async def _run_async(self, pending: Awaitable[Any]) -> None:
        try:
            await pending
        except Exception as exc:
            raise CallbackFailed(self, None, exc) from exc
