"""Runtime: the registry of a graph's nodes, topics and services; spawn, stop, shutdown.

Lifecycle is explicit: a Runtime is *unopened* until ``async with Runtime() as rt``
enters it, *running* inside the block, and *closed* after it.  Leaving the block
stops every node gracefully, in reverse start order (``on_shutdown`` then
``destroy_node``).  If the supervisor gives up (too many restarts), the block is
cancelled and :class:`~actors.errors.Escalation` is raised from it.

There is no global runtime: a node finds the runtime that spawns it through a
scoped context variable, so several runtimes can live in one process.
"""

from __future__ import annotations

import asyncio
import gc
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from types import TracebackType
from typing import Any, Protocol, TypeVar, cast

import anyio
import anyio.abc

from actors.core._actor import Owner, Scheduler
from actors.errors import InvalidNameError
from actors.ros.log import NodeLogger, console_unless_configured
from actors.ros.node import Node, NodeCore, SpawnRequest, spawning
from actors.ros.qos import QoSProfile
from actors.ros.time import ROSClock
from actors.ros.timers import Deadlines
from actors.ros.topics import Publisher, TopicTable
from actors.services import ServiceTable
from actors.system.introspection import GraphView
from actors.system.supervisor import Child, RestartType, Supervisor, SupervisorPolicy

__all__ = ["Runtime", "Attachment", "frozen_startup"]

N = TypeVar("N", bound=Node)


class Attachment(Protocol):
    """Something that runs beside a graph for as long as its runtime runs.

    The control endpoint (:class:`actors.ops.control.ControlEndpoint`) is one; so
    are a transport to other processes and a recorder.  The runtime starts each
    with ``await task_group.start(attachment, runtime)`` once its supervisor
    runs, in the order given, and cancels them after every node has stopped.
    An attachment lives in a layer above the runtime: it is handed in, never
    imported here.
    """

    async def __call__(self, runtime: Runtime, *, task_status: anyio.abc.TaskStatus[Any]) -> None: ...


class Runtime:
    """A graph of nodes in one process, on the running event loop.

    ``name`` names the graph (the command line finds it by this name);
    ``supervisor`` sets restart strategy, intensity and backoff; ``attach``
    lists what runs beside the graph, e.g. ``[ControlEndpoint()]`` to let the
    command line reach it (``python -m actors.run`` attaches one).
    """

    def __init__(
        self,
        *,
        name: str = "actors",
        supervisor: SupervisorPolicy | None = None,
        attach: Sequence[Attachment] = (),
    ) -> None:
        self.name = name
        self._attachments = tuple(attach)
        self.policy = supervisor or SupervisorPolicy()
        self.topics = TopicTable()
        self.services = ServiceTable()
        # A partial owner: its publishers read only its fqn, and are never destroyed.
        self._owner = cast(Owner, _RuntimeEndpointOwner(self))
        self.nodes: dict[str, NodeCore] = {}
        self.graph = GraphView(self)
        self._state = "unopened"
        self._failure: BaseException | None = None
        self._rosout: Publisher | None = None
        self._stopped: anyio.Event | None = None
        self._burst = False  # spawns since the loop last ran (see _begin_burst)
        self._old_heap = 0  # objects in the oldest generation when a burst last counted them

    # -- lifecycle ------------------------------------------------------------

    async def __aenter__(self) -> Runtime:
        if self._state != "unopened":
            raise RuntimeError(f"runtime {self.name!r} is {self._state}; a Runtime is entered once")
        self.loop: asyncio.AbstractEventLoop = asyncio.get_running_loop()
        console_unless_configured()  # INFO on stderr as rclpy prints it, unless the app chose
        self.clock = ROSClock(self.loop)
        self.scheduler = Scheduler(self.loop)
        self.deadlines = Deadlines(self.loop, self.scheduler)
        self._rosout = self._runtime_publisher("/rosout", "Log")
        self.parameter_events = self._runtime_publisher("/parameter_events", "ParameterEvent")
        self.logger = self.make_logger("actors")
        self.supervisor = Supervisor(self, self.policy)
        self._stopped = anyio.Event()
        self._task_group = anyio.create_task_group()
        await self._task_group.__aenter__()
        self._task_group.start_soon(self.supervisor.run, name="supervisor")
        for attachment in self._attachments:
            # Cancelled with the task group on exit, after every node has stopped.
            await self._task_group.start(attachment, self, name=type(attachment).__name__)
        self._state = "running"
        return self

    async def __aexit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> bool | None:
        try:
            with anyio.CancelScope(shield=True):
                await self.supervisor.stop_all()
            self._task_group.cancel_scope.cancel()
            if exc is not None and not isinstance(exc, anyio.get_cancelled_exc_class()):
                # The block's own error: let it out as it is, not wrapped in an ExceptionGroup.
                await self._task_group.__aexit__(None, None, None)
                suppressed = None
            else:
                suppressed = await self._task_group.__aexit__(exc_type, exc, tb)
        finally:
            self._state = "closed"
            assert self._stopped is not None
            self._stopped.set()
        if self._failure is not None:
            raise self._failure
        return suppressed

    @property
    def attachments(self) -> tuple[Attachment, ...]:
        """What runs beside the graph, as given to the constructor."""
        return self._attachments

    def _fail(self, reason: BaseException) -> None:
        """Record why the runtime gives up and cancel everything in it."""
        if self._failure is None:
            self._failure = reason
        self._task_group.cancel_scope.cancel()

    def shutdown(self) -> None:
        """Ask the runtime to stop: :meth:`wait` returns and the ``async with`` block can end."""
        if self._stopped is not None:
            self._stopped.set()

    async def wait(self, duration: float | None = None) -> None:
        """Run until :meth:`shutdown` is called, or for ``duration`` seconds of runtime clock."""
        self._require_running()
        assert self._stopped is not None
        with anyio.move_on_after(duration if duration else None):
            await self._stopped.wait()

    def _require_running(self) -> None:
        if self._state != "running":
            raise RuntimeError(f"runtime {self.name!r} is {self._state}; use it inside `async with Runtime() as rt:`")

    # -- nodes ----------------------------------------------------------------

    def spawn(
        self,
        cls: type[N],
        *args: Any,
        name: str | None = None,
        namespace: str | None = None,
        params: Mapping[str, Any] | None = None,
        remap: Mapping[str, str] | None = None,
        restart: RestartType | str = RestartType.TRANSIENT,
        **kwargs: Any,
    ) -> N:
        """Construct ``cls(*args, **kwargs)`` as a node of this runtime and start its actor.

        ``name``, ``namespace``, ``params`` and ``remap`` override what the class
        gives ``super().__init__``, as ROS launch does; these and ``restart`` are
        spawn's own, every other argument goes to the constructor (again, to each
        restarted instance).  Returns the instance (a restart makes a new one: see
        :meth:`node`).  Raises what the constructor raises, InvalidNameError for a
        bad or duplicate name, and RuntimeError outside ``async with``.  Spawns
        made before the loop runs again run with the cyclic garbage collector
        paused, and a burst of them that grew the heap by a quarter ends with
        one full collection.
        """
        self._require_running()
        if not (isinstance(cls, type) and issubclass(cls, Node)):
            raise TypeError(f"spawn() takes a Node subclass, got {cls!r}")
        if not self._burst:
            self._begin_burst()
        child = Child(
            cls,
            name=name,
            namespace=namespace,
            params=params,
            remap=remap,
            restart=restart,
            args=args,
            kwargs=kwargs,
        )
        try:
            core = self.supervisor.start(child)
        except BaseException:
            for olds in child.take_inheritance().values():  # no retry: nothing will adopt them
                for entity in olds:
                    entity.destroy()
            raise
        self.supervisor.children[child] = None
        return cast(N, core.node)  # built from cls

    def _begin_burst(self) -> None:
        # The spawns made before the loop runs again are one burst, during which the cyclic
        # collector waits.  With it running, 10,000 spawns paid for four to six full
        # collections (each traversing everything built so far: half the cost of spawning);
        # afterwards _end_burst does at most one.  It waits by a youngest-generation threshold
        # no allocation count reaches, not by gc.disable(): the embedding code may disable or
        # retune the collector meanwhile, and _end_burst must not undo that.
        self._burst = True
        before = gc.get_threshold()
        if gc.isenabled() and before[0] not in (0, _BURST_THRESHOLD):  # not paused already
            gc.set_threshold(_BURST_THRESHOLD, *before[1:])
            self.loop.call_soon(self._end_burst, before)
        else:
            self.loop.call_soon(self._end_burst, None)

    def _end_burst(self, before: tuple[int, ...] | None) -> None:
        self._burst = False
        if before is None or gc.get_threshold() != (_BURST_THRESHOLD, *before[1:]):
            return  # not paused by this burst, or retuned since by the embedding code: theirs
        gc.set_threshold(*before)
        if not gc.isenabled():
            return  # disabled meanwhile by the embedding code: no collection from us either
        # A burst that grew the heap by more than a quarter would make CPython's next full
        # collection come within seconds, among timer ticks and deliveries: it is done here
        # instead, once, still part of the burst.  A smaller one is left to the collector's
        # ordinary course.  (While collection waits, nothing leaves the youngest generation:
        # its count is what the burst built, the oldest generation what was there before.)
        # Counting the oldest generation takes a pass over it (tens of milliseconds for a
        # few million objects): skipped when the last count, plus what a collection then
        # kept, already shows the burst is too small.  If much of that died since, CPython
        # runs the full collection itself later, as it would have anyway.
        built = gc.get_count()[0]
        if built > _BIG_BURST and built * 4 > self._old_heap:
            self._old_heap = len(gc.get_objects(generation=2))
            if built * 4 > self._old_heap:
                gc.collect()
                self._old_heap += built

    async def stop(self, name: str) -> None:
        """Stop the node ``name`` (full or plain name) for good, running its shutdown hooks."""
        core = self._find(name)
        # A script node's _ScriptChild has what stop() uses of a Child (state, core).
        await self.supervisor.stop(cast(Child, core.child))

    def node(self, name: str) -> Node:
        """The current instance of the node ``name`` (full ``/ns/name`` or plain name)."""
        return self._find(name).node

    def _find(self, name: str) -> NodeCore:
        core = self.nodes.get(name) or self.nodes.get("/" + name)
        if core is None:
            matches = [c for c in self.nodes.values() if c.name == name]
            if len(matches) != 1:
                raise LookupError(f"no node named {name!r} in runtime {self.name!r}")
            core = matches[0]
        return core

    def _instantiate(self, child: Child) -> NodeCore:
        try:
            with spawning(SpawnRequest(self, child)):
                # ** of the shared empty mapping a child without kwargs has costs 1 µs: left out.
                node = child.cls(*child.args, **child.kwargs) if child.kwargs else child.cls(*child.args)
        except BaseException:
            # A constructor that raised half-way: unregister what it built, and keep its
            # mailboxes (and those it inherited) for the next attempt.
            for built in [c for c in self.nodes.values() if c.child is child]:
                child.give_back(built.abandon())
            raise
        core = getattr(node, "_core", None)
        if not isinstance(core, NodeCore):
            raise TypeError(f"{child.cls.__name__}.__init__ must call super().__init__(node_name)")
        return core

    def _register_node(self, core: NodeCore) -> None:
        existing = self.nodes.get(core.fqn)
        if existing is not None and existing.child is not core.child:
            raise InvalidNameError(f"a node named {core.fqn} already runs in runtime {self.name!r}")
        self.nodes[core.fqn] = core

    def _unregister_node(self, core: NodeCore) -> None:
        if self.nodes.get(core.fqn) is core:
            del self.nodes[core.fqn]

    # -- logging --------------------------------------------------------------

    def make_logger(self, name: str) -> NodeLogger:
        """A logger stamped by this runtime's clock that also feeds ``/rosout``."""
        return NodeLogger(name, self.clock.now_ns, self._to_rosout)

    def _to_rosout(self, level: int, name: str, text: str, stamp_ns: int) -> None:
        pub = self._rosout
        if pub is None or not pub._subs:
            return
        sec, nanosec = divmod(stamp_ns, 1_000_000_000)
        msg = pub.msg_type(level=level, name=name, msg=text)
        msg.stamp.sec, msg.stamp.nanosec = sec, nanosec
        pub.publish(msg)

    def _runtime_publisher(self, topic: str, rcl_type: str) -> Publisher:
        # One publisher per runtime, not per node.  Volatile, unlike ROS's transient-local
        # /rosout: with nobody subscribed, logging and parameter events then cost nothing.
        from interfaces.rcl_interfaces import msg

        msg_type = getattr(msg, rcl_type)
        pub = Publisher(self._owner, topic, msg_type, QoSProfile(depth=1000))
        self.topics.add_publisher(pub)
        return pub


_BURST_THRESHOLD = 2**31 - 1  # the youngest generation's threshold while a burst of spawns runs
_BIG_BURST = 10_000  # container objects (a node with a publisher, a subscription and a timer builds about 24)


class _RuntimeEndpointOwner:
    """Stands in for a node as owner of the runtime's own endpoints (``/rosout``)."""

    def __init__(self, runtime: Runtime) -> None:
        self.runtime = runtime
        self.fqn = f"/_{runtime.name}".replace("-", "_")


@contextmanager
def frozen_startup() -> Iterator[None]:
    """Spawn a graph's nodes inside: garbage collection waits, and what they built is frozen after.

    A graph allocates most of what it will ever hold while it starts; the
    cyclic collector then traverses all of it again and again.  Inside the
    block it is paused (``Runtime.spawn`` pauses it only until the loop runs
    again, and may end with a full collection); at the end ``gc.freeze()``
    moves everything alive into the permanent generation, so later
    collections (during timer ticks and message delivery) skip it.  ``python -m actors.run`` starts graphs this
    way.  Process-wide, like ``gc`` itself: embedding code decides.
    """
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        gc.freeze()
        if enabled:
            gc.enable()
