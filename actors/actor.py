"""The actor behind every node: one ready queue, one task, one callback at a time.

Subscriptions, timers and services are *entities*.  An entity with work to do
is appended to its node's ready queue (:meth:`Actor.schedule`), which wakes the
node's task if it sleeps; the task then calls each ready entity's ``_run()`` in
turn.  Because one task runs them all, a node's callbacks never overlap and
node code needs no locks.

``_run()`` returns None when it has finished, or an awaitable that the task
awaits to finish the work: an entity whose callbacks are plain functions runs
them without a coroutine of its own (a measurable share of each wake-up), and
hands over to a coroutine only when a callback turns out to be ``async``.

The wake-up is a bare asyncio future, set at most once per batch: this is the
hottest path in the runtime and anyio's primitives (or a memory object stream)
cost several times more per message.  Each round runs only the entities that
were ready when it began (the ready list is swapped for an empty one), then
yields to the loop before the next round, so a node that keeps itself busy
cannot starve the others.  A list, not a deque: an idle node's empty deque
costs 760 bytes, an empty list 56.
"""

from __future__ import annotations

import asyncio
from collections.abc import Awaitable
from typing import Any, Protocol

__all__ = ["Actor", "Entity", "Owner", "CallbackFailed", "Mailbox", "OneShot"]


class Entity(Protocol):
    """Something a node runs: a subscription, a timer, a service."""

    def _run(self) -> Awaitable[None] | None: ...


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


class Actor:
    """A node's ready queue and the loop that drains it."""

    __slots__ = ("_ready", "_waiter", "_loop", "_running", "awaiting", "busy_since", "current")

    def __init__(self, loop: asyncio.AbstractEventLoop) -> None:
        self._ready: list[Entity] = []
        self._waiter: asyncio.Future[None] | None = None
        self._loop = loop
        self._running = True
        # True while the task waits inside an ``async`` callback: halting it then needs a
        # cancellation; otherwise stop() alone guarantees no callback runs again.
        self.awaiting = False
        # What the actor is running now and since when (loop time): read by doctor's
        # loop-lag check to name the callback that blocks.
        self.busy_since = 0.0
        self.current: Entity | None = None

    def schedule(self, entity: Entity) -> None:
        """Queue ``entity`` to run; wake the actor if it waits.  Never blocks."""
        self._ready.append(entity)
        waiter = self._waiter
        if waiter is not None:
            self._waiter = None
            if not waiter.done():
                waiter.set_result(None)

    def stop(self) -> None:
        """Make :meth:`run` return after the entity now running, if any; no other entity runs."""
        self._running = False
        self.schedule(_STOP)

    @property
    def pending(self) -> int:
        """How many entities wait to run."""
        return len(self._ready)

    async def run(self) -> None:
        """Run ready entities until :meth:`stop`; a callback's error propagates as CallbackFailed."""
        loop = self._loop
        try:
            while self._running:
                batch = self._ready
                self._ready = []
                for entity in batch:
                    self.current = entity
                    self.busy_since = loop.time()
                    pending = entity._run()
                    if pending is not None:
                        self.awaiting = True
                        await pending
                        self.awaiting = False
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
            self.awaiting = False


class Mailbox:
    """An entity with a queue (a subscription, a service): on its actor's ready queue at most once.

    Subclasses fill ``_queue`` and call :meth:`_wake`; their ``_run`` drains
    what was queued when the round began and ends with :meth:`_round_done`.
    """

    __slots__ = ("_queue", "_scheduled", "_actor")

    def __init__(self, actor: Actor) -> None:
        self._queue: Any = None
        self._scheduled = False
        self._actor = actor

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

    async def _run(self) -> None:
        try:
            result = self.fn()
            if result is not None and hasattr(result, "__await__"):
                await result
        except Exception as exc:
            raise CallbackFailed(self, None, exc) from exc


class _Stop:
    """Scheduled by :meth:`Actor.stop` so that a sleeping actor wakes and returns."""

    async def _run(self) -> None:
        return None


_STOP = _Stop()
