"""Supervision with Erlang/OTP semantics: restart strategies, restart types, intensity, backoff.

Every spawned node is a *child* of the runtime's supervisor.  When a node's
callback raises, the node crashes: the message it was handling is logged once,
with the traceback, as a dead letter, and the supervisor decides what to do:

- restart type: ``permanent`` children are always restarted, ``transient`` ones
  (the default) only after a crash, ``temporary`` ones never;
- strategy: ``one_for_one`` restarts the crashed child, ``one_for_all`` every
  child, ``rest_for_one`` the crashed child and those started after it;
- intensity: more than ``intensity`` restarts within ``period`` seconds and the
  supervisor gives up: it stops every child and the runtime raises
  :class:`~actors.errors.Escalation`;
- backoff: the n-th restart within the period waits ``backoff * 2**(n-1)``
  seconds (at most ``max_backoff``) on the runtime clock, whatever n is.

A restarted node is a new instance.  The crashed instance's subscriptions stay
attached to their topics while it is down, and the new instance adopts their
mailboxes when it subscribes again, so messages queued for it are not lost.

A node's actor runs on the runtime's scheduler (:mod:`actors.core._actor`), with a
task of its own only while an ``async`` callback runs; it tells the
supervisor through ``Actor.on_exit`` when it ends by itself (a crash, or
``destroy_node``).  Halting a node needs no cancellation and no wait unless an
``async`` callback is in progress: :meth:`Actor.stop` guarantees that none of
its callbacks runs again, so stopping 10,000 nodes takes no loop iteration per
node.  A node inside an ``async`` callback is cancelled, and the halt waits
until the callback has unwound.
"""

from __future__ import annotations

import asyncio
import inspect
import math
from collections import deque
from collections.abc import Coroutine, Mapping
from enum import StrEnum
from types import MappingProxyType
from typing import Any, Protocol, cast

import anyio
import msgspec

from actors.core._actor import CallbackFailed, OneShot
from actors.errors import Escalation
from actors.ros.log import NodeLogger
from actors.ros.node import NodeCore
from actors.ros.time import ROSClock

__all__ = ["Strategy", "RestartType", "SupervisorPolicy", "Child", "Supervisor", "Supervised"]


class Strategy(StrEnum):
    """Which children restart when one crashes."""

    ONE_FOR_ONE = "one_for_one"
    ONE_FOR_ALL = "one_for_all"
    REST_FOR_ONE = "rest_for_one"


class RestartType(StrEnum):
    """When a child is restarted."""

    PERMANENT = "permanent"
    TRANSIENT = "transient"
    TEMPORARY = "temporary"


class SupervisorPolicy(msgspec.Struct, frozen=True, kw_only=True):
    """The supervisor's settings, as the ``[supervisor]`` table of a graph file."""

    strategy: Strategy = Strategy.ONE_FOR_ONE
    intensity: int = 3
    period: float = 5.0
    backoff: float = 0.1
    max_backoff: float = 2.0

    def __post_init__(self) -> None:
        if self.intensity < 0:
            raise ValueError(f"intensity must be >= 0, got {self.intensity}")
        if self.period <= 0:
            raise ValueError(f"period must be > 0 seconds, got {self.period}")
        if self.backoff < 0 or self.max_backoff < 0:
            raise ValueError("backoff and max_backoff must be >= 0 seconds")

    def delay(self, restarts: int) -> float:
        """The wait before the ``restarts``-th restart within the period, in seconds.

        ``backoff`` doubled per earlier restart, at most ``max_backoff``.  The
        exponent is capped before the power is taken: an intensity of a million
        allows ``2**n`` far beyond what a float holds.
        """
        if self.backoff <= 0 or self.max_backoff <= 0 or restarts <= 1:
            return min(self.backoff, self.max_backoff)
        # Past the doubling that reaches max_backoff, more doublings change nothing.
        doublings = min(restarts - 1, max(0, math.ceil(math.log2(self.max_backoff) - math.log2(self.backoff))))
        return min(math.ldexp(self.backoff, doublings), self.max_backoff)


class Child:
    """One spawned node: how to build it, its current instance, and its history."""

    def __init__(
        self,
        cls: type,
        *,
        name: str | None,
        namespace: str | None,
        params: Mapping[str, Any] | None,
        remap: Mapping[str, str] | None,
        restart: RestartType | str,
        args: tuple[Any, ...] = (),
        kwargs: Mapping[str, Any] | None = None,
    ) -> None:
        self.cls = cls
        # The constructor's own arguments, given again to every restarted instance.
        self.args = args
        self.kwargs = dict(kwargs) if kwargs else _NOTHING
        self.name = name
        self.namespace = namespace
        self.params = dict(params) if params else _NOTHING
        self.remap = dict(remap) if remap else _NOTHING
        # RestartType(x) costs an enum lookup even for a member: once per spawn is enough.
        self.restart = restart if type(restart) is RestartType else RestartType(restart)
        self.core: NodeCore | None = None
        self.restarts = 0
        self.crashes = 0
        self.last_error: str | None = None
        self.last_exception: BaseException | None = None  # the Escalation's cause
        self.state = "starting"
        self.supervisor: Supervisor | None = None  # set when it starts
        self._inheritance: dict[tuple[str, str], list[Any]] | None = None  # made when something is given back

    def give_back(self, entities: Mapping[tuple[str, str], list[Any]]) -> None:
        """Keep ``entities`` (a failed instance's) for the next instance to adopt."""
        if not entities:
            return
        if self._inheritance is None:
            self._inheritance = {}
        for key, olds in entities.items():
            self._inheritance.setdefault(key, []).extend(olds)

    def take_inheritance(self) -> Mapping[tuple[str, str], list[Any]]:
        """The previous instance's entities, handed once to the new instance (read-only)."""
        inherited, self._inheritance = self._inheritance, None
        return _NOTHING if inherited is None else inherited

    def _exited(self, error: BaseException | None) -> None:
        # Its current instance's actor ended by itself (its ``on_exit``): a bound method of
        # the child is one object for the collector to traverse, a partial two.
        assert self.supervisor is not None and self.core is not None
        self.supervisor._exited(self, self.core, error)


# The kwargs, params, remaps and inheritance of the children that have none: one shared,
# read-only mapping instead of four empty dicts per node.
_NOTHING: Mapping[Any, Any] = MappingProxyType({})


class _Exit(msgspec.Struct):
    child: Child
    core: NodeCore
    error: BaseException | None


class Supervised(Protocol):
    """What the supervisor needs from the runtime it serves."""

    clock: ROSClock
    logger: NodeLogger
    loop: asyncio.AbstractEventLoop

    def _instantiate(self, child: Child) -> NodeCore: ...

    def _fail(self, reason: BaseException) -> None: ...


class Supervisor:
    """Starts, watches and restarts the runtime's nodes."""

    def __init__(self, runtime: Supervised, policy: SupervisorPolicy) -> None:
        self.runtime = runtime
        self.policy = policy
        # Live children in start order: an insertion-ordered set, O(1) removal.
        self.children: dict[Child, None] = {}
        # Children that ended for good and why (bounded): doctor reports crashes among them.
        self.ended: deque[Child] = deque(maxlen=100)
        self._restart_times: deque[float] = deque()
        self._send, self._receive = anyio.create_memory_object_stream[_Exit](float("inf"))

    # -- starting and stopping ------------------------------------------------

    def start(self, child: Child) -> NodeCore:
        """Build ``child``'s instance and start its actor; raise what its constructor raised."""
        core = self.runtime._instantiate(child)
        for leftover in core.leftovers():
            leftover.destroy()
        on_start = getattr(core.node, "on_start", None)
        if on_start is not None:
            core.actor.schedule(OneShot(on_start, "on_start"))
        child.core = core
        child.state = "running"
        child.supervisor = self
        core.actor.on_exit = child._exited
        return core

    def _exited(self, child: Child, core: NodeCore, error: BaseException | None) -> None:
        # The actor ended by itself (a crash, or the node destroyed itself), not by a halt.
        self._send.send_nowait(_Exit(child, core, error))

    async def _halt(self, child: Child) -> None:
        """End ``child``'s actor: none of its callbacks runs after this returns.

        An idle actor is only told to stop; one inside an ``async`` callback is
        cancelled first, and waited for.
        """
        if child.core is None:
            return
        actor = child.core.actor
        actor.on_exit = None  # stopped by us: not an exit to handle
        task = actor.task
        if task is not None and not task.done() and task is not asyncio.current_task():
            coro = cast("Coroutine[Any, Any, None]", task.get_coro())  # Actor._finish's, a coroutine
            if inspect.getcoroutinestate(coro) == inspect.CORO_CREATED:
                # Its callback has not started yet: let it start (as it would have in its
                # round) so that cancelling unwinds it, instead of leaving it never awaited.
                await asyncio.sleep(0)
            task.cancel()
            await asyncio.wait((task,))
        actor.stop()

    async def stop(self, child: Child) -> None:
        """Stop ``child`` for good: actor halted, ``on_shutdown`` and ``destroy_node`` run."""
        self.children.pop(child, None)
        child.state = "stopping"
        await self._halt(child)
        if child.core is not None and not child.core.destroyed:
            await self._shutdown_hooks(child.core, destroy=True)
        child.state = "stopped"

    async def stop_all(self) -> None:
        """Stop every child, in reverse start order."""
        for child in reversed(list(self.children)):
            await self.stop(child)

    async def _shutdown_hooks(self, core: NodeCore, *, destroy: bool) -> None:
        node = core.node
        hook = getattr(node, "on_shutdown", None)
        try:
            if hook is not None:
                result = hook()
                if result is not None and hasattr(result, "__await__"):
                    await result
            if destroy:
                node.destroy_node()
        except Exception as exc:
            core.logger.error(f"shutdown hook raised: {exc!r}", exc_info=exc)
        finally:
            if destroy:
                core.destroy()

    # -- supervising ------------------------------------------------------------

    async def run(self) -> None:
        """Handle node exits until cancelled; raise Escalation when intensity is exceeded."""
        with self._send, self._receive:  # closed here: a runtime leaves no stream to warn when collected
            async for exit_ in self._receive:
                await self._handle(exit_)

    async def _handle(self, exit_: _Exit) -> None:
        child, core, error = exit_.child, exit_.core, exit_.error
        if child.core is not core or child not in self.children:
            return  # an instance already replaced or stopped
        if error is None:
            core.destroy()
            if child.restart is RestartType.PERMANENT:
                await self._restart([child], crashed=None)
            else:
                self._retire(child, "exited")
            return
        child.crashes += 1
        self._report(child, core, error)
        if child.restart is RestartType.TEMPORARY:
            core.destroy()
            self._retire(child, "crashed")
            return
        strategy = self.policy.strategy
        if strategy is Strategy.ONE_FOR_ONE:
            group = [child]
        else:
            children = list(self.children)
            group = children if strategy is Strategy.ONE_FOR_ALL else children[children.index(child) :]
        await self._restart(group, crashed=child)

    def _retire(self, child: Child, state: str) -> None:
        del self.children[child]
        child.state = state
        self.ended.append(child)

    def _report(self, child: Child, core: NodeCore, error: BaseException) -> None:
        if isinstance(error, CallbackFailed):
            entity, cause = error.entity, error.error
            where = _describe(entity)
            if error.item is not None:
                text = f"dead letter: {where} raised {cause!r} handling {error.item!r}"
            else:
                text = f"{where} raised {cause!r}"
        else:
            cause = error
            text = f"node crashed: {cause!r}"
        child.last_error = repr(cause)
        child.last_exception = cause
        core.logger.error(text, exc_info=cause)

    async def _restart(self, group: list[Child], crashed: Child | None) -> None:
        # A loop, not recursion: under a huge intensity a constructor that keeps
        # raising would otherwise nest one frame per attempt.
        failed = await self._restart_group(group, crashed)
        while failed is not None:
            failed = await self._restart_group([failed], crashed=failed)

    async def _restart_group(self, group: list[Child], crashed: Child | None) -> Child | None:
        """Restart ``group``; returns the child whose constructor raised, to be restarted again."""
        now = self.runtime.clock.monotonic()
        times = self._restart_times
        while times and times[0] <= now - self.policy.period:
            times.popleft()
        if crashed is not None and len(times) >= self.policy.intensity:
            await self._escalate(crashed)
            return None
        times.append(now)
        for child in reversed(group):
            if child is not crashed and child.core is not None and not child.core.destroyed:
                await self._halt(child)
                await self._shutdown_hooks(child.core, destroy=False)
            if child.core is not None and not child.core.destroyed:
                child.give_back(child.core.orphan())
            child.state = "restarting"
        delay = self.policy.delay(len(times))
        if delay > 0:
            await anyio.sleep(delay)
        for child in group:
            if child not in self.children:
                continue
            child.restarts += 1
            try:
                self.start(child)
                continue
            except Exception as exc:
                # A constructor that raises on restart is one more crash.
                child.crashes += 1
                child.last_error = repr(exc)
                child.last_exception = exc
                self.runtime.logger.error(f"restarting {child.cls.__name__} failed: {exc!r}", exc_info=exc)
            # Retried outside the handler, so that the next failure is not chained to this one.
            return child
        return None

    async def _escalate(self, crashed: Child) -> None:
        policy = self.policy
        name = crashed.core.fqn if crashed.core is not None else crashed.cls.__name__
        cls = crashed.cls
        reason = Escalation(
            f"node {name} crashed {crashed.crashes} times; more than {policy.intensity} "
            f"restarts within {policy.period} s, giving up "
            f"({cls.__module__}:{cls.__qualname__}, last error: {crashed.last_error})"
        )
        reason.__cause__ = crashed.last_exception
        for child in reversed(list(self.children)):
            if child.core is not None and not child.core.destroyed:
                await self._halt(child)
                await self._shutdown_hooks(child.core, destroy=True)
            child.state = "stopped"
        self.children.clear()
        crashed.state = "crashed"
        self.runtime._fail(reason)


def _describe(entity: Any) -> str:
    topic = getattr(entity, "topic_name", None)
    if topic is not None:
        return f"subscription callback on {topic}"
    service = getattr(entity, "service_name", None)
    if service is not None:
        return f"service handler of {service}"
    if isinstance(entity, OneShot):
        return entity.name
    return f"{type(entity).__name__.lower()} callback"
