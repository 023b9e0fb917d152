"""Node: what user code subclasses, with rclpy's method names; NodeCore does the work.

A node is created by a :class:`~actors.runtime.Runtime` (``rt.spawn(MyNode)``),
never standalone: the runtime passes itself, the node's name, namespace,
parameters and remappings through a scoped context variable that
``Node.__init__`` reads.  The name given to ``super().__init__`` is the default
that the graph or ``spawn(name=...)`` overrides.

Everything a node owns lives on one attribute, ``self._core``, so that user
subclasses may use any attribute name rclpy users are used to (``self.timer``,
``self.publisher_``, ``self.i``...).
"""

from __future__ import annotations

import asyncio
import sys
from collections.abc import Callable, Mapping, Sequence
from contextlib import AbstractContextManager
from contextvars import ContextVar
from typing import Any, Protocol

import anyio.abc

from actors.core._actor import Actor, Scheduler
from actors.ros._graph_queries import GraphQueries
from actors.ros._logger_services import serve_logger_levels
from actors.ros._node_parameters import ParameterMethods
from actors.ros._param_services import ParameterServices
from actors.ros._param_services import serve as serve_parameters
from actors.ros.actions import ActionClient, ActionServer
from actors.ros.log import NodeLogger
from actors.ros.names import Resolver, fully_qualified, normalize_namespace, validate_node_name
from actors.ros.parameter_store import Parameter, ParameterStore
from actors.ros.qos import QoSProfile, as_qos
from actors.ros.qos_events import (
    EndpointEvents,
    PublisherEventCallbacks,
    SubscriptionEventCallbacks,
    WatchedPublisher,
    watched,
)
from actors.ros.time import Clock, Rate, ROSClock
from actors.ros.timers import Deadlines, Timer
from actors.ros.topics import Publisher, Subscription, TopicTable
from actors.services import Client, Service, ServiceTable
from interfaces.rcl_interfaces.msg import ParameterDescriptor

__all__ = ["Node", "NodeCore", "Host", "ChildSpec", "SpawnRequest", "spawning"]


class Host(Protocol):
    """What a node needs from the runtime that spawns it (the runtime layer sits above this one)."""

    loop: asyncio.AbstractEventLoop
    clock: ROSClock
    topics: TopicTable
    services: ServiceTable
    deadlines: Deadlines
    scheduler: Scheduler
    parameter_events: Publisher
    graph: Any
    _task_group: anyio.abc.TaskGroup
    nodes: dict[str, NodeCore]

    def make_logger(self, name: str) -> NodeLogger: ...

    def _register_node(self, core: NodeCore) -> None: ...

    def _unregister_node(self, core: NodeCore) -> None: ...


class ChildSpec(Protocol):
    """How the supervisor asks for a node: overrides, and the entities a restart hands over."""

    @property
    def name(self) -> str | None: ...  # read-only here, so a spec may say plain str

    @property
    def namespace(self) -> str | None: ...

    @property
    def params(self) -> Mapping[str, Any]: ...

    @property
    def remap(self) -> Mapping[str, str]: ...

    def take_inheritance(self) -> Mapping[tuple[str, str], list[Any]]: ...


class SpawnRequest:
    """What the runtime hands to the node being constructed.

    ``actor`` runs the node's callbacks; by default a new :class:`Actor` on the
    runtime's loop.  Another actor (the rclpy layer's, which hands ready
    callbacks to a script's executor) changes who runs them, not what they are.
    """

    __slots__ = ("runtime", "child", "actor")

    def __init__(self, runtime: Host, child: ChildSpec, actor: Actor | None = None) -> None:
        self.runtime = runtime
        self.child = child
        self.actor = actor


_spawning: ContextVar[SpawnRequest | None] = ContextVar("actors_spawning", default=None)


def spawning(request: SpawnRequest) -> AbstractContextManager[None]:
    """Nodes constructed inside the block are built for ``request``, as ``Runtime.spawn`` builds them."""
    return _Spawning(request)


class _Spawning:
    # A plain context manager: @contextmanager's generator cost 2 µs of every spawn.
    __slots__ = ("_request", "_token")

    def __init__(self, request: SpawnRequest) -> None:
        self._request = request

    def __enter__(self) -> None:
        self._token = _spawning.set(self._request)

    def __exit__(self, *exc: object) -> None:
        _spawning.reset(self._token)


class NodeCore:
    """A node's name, actor, clock, logger and entities: everything behind ``Node``."""

    # Whether a client of this node may call a service of this node.  A native node's callbacks
    # run one at a time, so it may not: the call would wait forever.  A script node's services
    # only queue requests for its executor (actors.compat), which rclpy lets answer its own calls.
    answers_own_calls = False

    def __init__(
        self,
        node: Node,
        request: SpawnRequest,
        default_name: str,
        namespace: str | None,
        parameter_overrides: Mapping[str, Any] | None,
        *,
        allow_undeclared_parameters: bool = False,
        automatically_declare_parameters_from_overrides: bool = False,
        start_parameter_services: bool = True,
        enable_logger_service: bool = False,
    ) -> None:
        child = request.child
        self.node = node
        self.runtime = request.runtime
        self.child = child
        self.name = validate_node_name(child.name or default_name)
        self.namespace = normalize_namespace(child.namespace if child.namespace is not None else namespace)
        self.fqn = fully_qualified(self.namespace, self.name)
        self.resolver = Resolver(self.namespace, self.name, child.remap)
        self.loop: asyncio.AbstractEventLoop = self.runtime.loop
        self.clock: ROSClock = self.runtime.clock
        self.parameter_events = self.runtime.parameter_events
        self.actor = request.actor if request.actor is not None else Actor(self.loop, self.runtime.scheduler)
        self._logger: NodeLogger | None = None
        # Insertion-ordered sets ({entity: None}): creation order, O(1) removal.
        self.publishers: dict[Publisher, None] = {}
        self.subscriptions: dict[Subscription, None] = {}
        self.timers: dict[Timer, None] = {}
        self.services: dict[Service, None] = {}
        self.clients: dict[Client, None] = {}
        self.action_servers: dict[ActionServer, None] = {}
        self.action_clients: dict[ActionClient, None] = {}
        self.destroyed = False
        # Entities of the previous instance, taken over by name when this one recreates them.
        self._inherited: Mapping[tuple[str, str], list[Any]] = child.take_inheritance()  # read-only
        self.runtime._register_node(self)
        # The parameter store is made at its first use (see ``params``) unless there is something
        # to declare or to announce now: every node has one, few nodes' are ever used, and with
        # use_sim_time's descriptor it was six of the 24 objects per node the collector traverses.
        self._params: ParameterStore | None = None
        overrides = {**parameter_overrides, **child.params} if parameter_overrides else child.params
        if overrides or allow_undeclared_parameters or self.parameter_events._subs:
            store = self._params = ParameterStore(self, overrides, allow_undeclared=allow_undeclared_parameters)
            if automatically_declare_parameters_from_overrides:
                for name, value in store.overrides.items():
                    store.declare(name, value, ParameterDescriptor(), ignore_override=True)
            if not store.has("use_sim_time"):
                store.declare_default(_USE_SIM_TIME)
        if start_parameter_services:
            serve_parameters(self)
        if enable_logger_service:
            serve_logger_levels(self)

    @property
    def params(self) -> ParameterStore:
        """The node's parameters: made at first use, holding ``use_sim_time``."""
        store = self._params
        if store is None:
            store = self._params = ParameterStore(self, {})
            # Every ROS node has it.  Accepted, and it changes nothing: the graph's clock is
            # simulated (virtual) time or wall time for every node alike.  Not announced on
            # /parameter_events now: at the node's start, when it would have been, nobody listened.
            store.declare_default(_USE_SIM_TIME, announce=False)
        return store

    # -- entities -------------------------------------------------------------

    def _take_inherited(self, kind: str, name: str, type_: type[Any]) -> Any:
        olds = self._inherited.get((kind, name))
        if olds:
            old = olds[0]
            if getattr(old, "msg_type", getattr(old, "srv_type", None)) is type_:
                return olds.pop(0)
        return None

    def leftovers(self) -> list[Any]:
        """Inherited entities the new instance did not recreate (to be destroyed)."""
        if not self._inherited:
            return []
        rest = [e for olds in self._inherited.values() for e in olds]
        self._inherited = {}
        return rest

    def create_publisher(
        self,
        msg_type: type[Any],
        topic: str,
        qos: QoSProfile | int,
        event_callbacks: PublisherEventCallbacks | None = None,
    ) -> Publisher:
        """See :meth:`Node.create_publisher`."""
        _check_type(msg_type, "create_publisher")
        name = _shared(self.resolver.resolve(topic))
        snapshot = as_qos(qos)
        if watched(snapshot) or event_callbacks is not None:
            pub: Publisher = WatchedPublisher(self, name, msg_type, snapshot, event_callbacks)
        else:
            pub = Publisher(self, name, msg_type, snapshot)
        old = self._take_inherited("pub", name, msg_type)
        if old is not None and old._history is not None and pub._history is not None:
            pub._history.extend(old._history)
        self.runtime.topics.add_publisher(pub)
        if old is not None:
            self.runtime.topics.remove_publisher(old)
        self.publishers[pub] = None
        return pub

    def create_subscription(
        self,
        msg_type: type[Any],
        topic: str,
        callback: Callable[[Any], Any],
        qos: QoSProfile | int,
        event_callbacks: SubscriptionEventCallbacks | None = None,
    ) -> Subscription:
        """See :meth:`Node.create_subscription`."""
        _check_type(msg_type, "create_subscription")
        if not callable(callback):
            raise TypeError(f"subscription callback must be callable, got {callback!r}")
        name = _shared(self.resolver.resolve(topic))
        sub = Subscription(self, name, msg_type, callback, as_qos(qos))
        if event_callbacks is not None:
            sub._events = EndpointEvents(sub, event_callbacks)
        old = self._take_inherited("sub", name, msg_type)
        if old is not None:
            self.runtime.topics.replace_subscription(old, sub)
            sub._adopt(old)
        else:
            self.runtime.topics.add_subscription(sub)
        self.subscriptions[sub] = None
        return sub

    def create_timer(
        self, period: float, callback: Callable[..., Any], *, clock: Clock | None = None, autostart: bool = True
    ) -> Timer:
        """See :meth:`Node.create_timer`."""
        if not callable(callback):
            raise TypeError(f"timer callback must be callable, got {callback!r}")
        if clock is not None and not isinstance(clock, Clock):
            raise TypeError(f"a timer's clock must be a Clock, got {clock!r}")
        timer = Timer(self, period, callback, self.runtime.deadlines, clock=clock or self.clock, autostart=autostart)
        self.timers[timer] = None
        return timer

    def create_service(self, srv_type: type[Any], name: str, handler: Callable[[Any, Any], Any]) -> Service:
        """See :meth:`Node.create_service`."""
        full = self.resolver.resolve(name, what="service name")
        return self.add_service(Service(self, full, srv_type, handler))

    def defer_services(self, deferred: ParameterServices) -> bool:
        """Register ``deferred``'s services to be built when first needed; False if they must be built now.

        Remapped names and a restart's hand-over (adopting its predecessor's
        queues) take the ordinary path.
        """
        if self.child.remap or self._inherited:
            return False
        return self.runtime.services.defer(self.fqn, deferred)

    def served(self) -> list[tuple[str, type]]:
        """``(name, type)`` of every service this node serves, those not built yet too."""
        return [(s.service_name, s.srv_type) for s in self.services] + [
            (name, srv_type) for name, srv_type, _ in self.runtime.services.deferred(self.fqn)
        ]

    def add_service(self, service: Service) -> Service:
        """Serve a service built by an entity of this node (an action's); adopts a predecessor's queue."""
        old = self._take_inherited("srv", service.service_name, service.srv_type)
        self.runtime.services.add(service, replacing=old)
        if old is not None:
            service._adopt(old)
        self.services[service] = None
        return service

    def create_action_server(
        self, action_type: type[Any], name: str, execute: Callable[..., Any], **options: Any
    ) -> ActionServer:
        """See :meth:`Node.create_action_server`."""
        full = self.resolver.resolve(name, what="action name")
        server = ActionServer(self, full, action_type, execute, **options)
        self.action_servers[server] = None
        return server

    def create_action_client(self, action_type: type[Any], name: str) -> ActionClient:
        """See :meth:`Node.create_action_client`."""
        full = self.resolver.resolve(name, what="action name")
        client = ActionClient(self, full, action_type)
        self.action_clients[client] = None
        return client

    def destroy_action_server(self, server: ActionServer) -> None:
        """Stop ``server``: its unfinished goals abort, its services and topics go away."""
        self.action_servers.pop(server, None)
        server._destroy_entities()

    def destroy_action_client(self, client: ActionClient) -> None:
        """Forget ``client`` and its services and topics."""
        self.action_clients.pop(client, None)
        client._destroy_entities()

    def start_task(self, fn: Callable[..., Any], *args: Any, name: str) -> None:
        """Run ``fn(*args)`` beside the node's actor, in the runtime's task group; it must not raise."""
        self.runtime._task_group.start_soon(fn, *args, name=name)

    def create_client(self, srv_type: type[Any], name: str) -> Client:
        """See :meth:`Node.create_client`."""
        full = self.resolver.resolve(name, what="service name")
        client = Client(self, full, srv_type, self.runtime.services)
        self.clients[client] = None
        self.runtime.services.add_client(client)
        return client

    def destroy_service(self, service: Service) -> None:
        """Stop serving ``service``; its queued calls fail."""
        self.services.pop(service, None)
        self.runtime.services.remove(service)

    def destroy_client(self, client: Client) -> None:
        """Forget ``client``."""
        if client in self.clients:
            del self.clients[client]
            self.runtime.services.remove_client(client)

    def destroy_publisher(self, pub: Publisher) -> None:
        """Remove ``pub`` from this node and its topic."""
        self.publishers.pop(pub, None)
        self.runtime.topics.remove_publisher(pub)

    def destroy_subscription(self, sub: Subscription) -> None:
        """Remove ``sub`` from this node and its topic; its queued messages are dropped."""
        self.subscriptions.pop(sub, None)
        self.runtime.topics.remove_subscription(sub)

    def destroy_timer(self, timer: Timer) -> None:
        """Cancel ``timer`` and forget it."""
        timer.cancel()
        self.timers.pop(timer, None)

    # -- logging --------------------------------------------------------------

    @property
    def logger(self) -> NodeLogger:
        """The node's logger, made on first use (idle nodes do not pay for one)."""
        if self._logger is None:
            self._logger = self.runtime.make_logger(self.fqn[1:].replace("/", "."))
        return self._logger

    # -- lifecycle ------------------------------------------------------------

    def _stop_activity(self) -> None:
        for client in self.clients:  # a restarted instance makes its own
            self.runtime.services.remove_client(client)
        for timer in self.timers:
            timer.cancel()
        for server in self.action_servers:
            server._halt(f"its node {self.fqn} stopped")
        self.actor.stop()

    def orphan(self) -> dict[tuple[str, str], list[Any]]:
        """Stop this instance but keep its mailboxes attached, for a restarted instance to adopt."""
        self.runtime.services.materialize(self.fqn)  # calls during the restart queue for the next instance
        self._stop_activity()
        self.destroyed = True
        kept: dict[tuple[str, str], list[Any]] = {}
        for kind, entities in (("pub", self.publishers), ("sub", self.subscriptions), ("srv", self.services)):
            for entity in entities:
                name = entity.service_name if isinstance(entity, Service) else entity.topic_name
                kept.setdefault((kind, name), []).append(entity)
        self.runtime._unregister_node(self)
        return kept

    def abandon(self) -> dict[tuple[str, str], list[Any]]:
        """Give up a half-built instance: its mailboxes and what it did not adopt, for the next try."""
        kept = self.orphan()
        for key, olds in self._inherited.items():
            kept.setdefault(key, []).extend(olds)
        self._inherited = {}
        return kept

    def destroy(self) -> None:
        """Stop this instance and remove every entity it has.  Idempotent."""
        if self.destroyed:
            return
        self._stop_activity()
        self.destroyed = True
        for pub in self.publishers:
            self.runtime.topics.remove_publisher(pub)
        for sub in self.subscriptions:
            self.runtime.topics.remove_subscription(sub)
        for service in self.services:
            self.runtime.services.remove(service)
        self.runtime.services.undefer(self.fqn, self)
        self.runtime._unregister_node(self)


_USE_SIM_TIME = Parameter("use_sim_time", Parameter.Type.BOOL, False)  # one for every node: a Parameter never changes


def _shared(topic: str) -> str:
    # The one string object of a topic name: 10,000 nodes on one topic held 10,000 copies,
    # each one more object for the collector to reach on its way through their endpoints.
    return sys.intern(topic)


def _check_type(msg_type: Any, where: str) -> None:
    if not isinstance(msg_type, type):
        raise TypeError(f"{where} needs a message type (a class), got {msg_type!r}")


class Node(ParameterMethods, GraphQueries):
    """A ROS node as an actor: subclass it and create entities in ``__init__``, as in rclpy.

    All callbacks of one node (subscriptions, timers, services, parameter
    callbacks) run one at a time in the node's own task, so node code needs no
    locks.  Callbacks may be plain functions or ``async def``.

    ``parameter_overrides`` (a mapping, or rclpy's list of Parameters) are
    initial values, beneath those of the graph or ``spawn(params=...)``.
    ``allow_undeclared_parameters`` lets sets and reads of undeclared names
    through; ``automatically_declare_parameters_from_overrides`` declares every
    override at once; ``start_parameter_services=False`` leaves out the
    ``~/get_parameters`` family; ``enable_logger_service=True`` adds
    ``~/get_logger_levels`` and ``~/set_logger_levels``.  The parameter and graph methods are rclpy's
    (see :class:`~actors.ros._node_parameters.ParameterMethods`,
    :class:`~actors.ros._graph_queries.GraphQueries`).

    Raises RuntimeError when constructed outside ``Runtime.spawn``, and
    InvalidNameError for a bad node name or namespace.
    """

    _core: NodeCore

    def __init__(
        self,
        node_name: str,
        *,
        namespace: str | None = None,
        parameter_overrides: Mapping[str, Any] | Sequence[Parameter] | None = None,
        allow_undeclared_parameters: bool = False,
        automatically_declare_parameters_from_overrides: bool = False,
        start_parameter_services: bool = True,
        enable_logger_service: bool = False,
    ) -> None:
        request = _spawning.get()
        if request is None:
            raise RuntimeError(
                f"{type(self).__name__} must be started by a runtime: "
                f"`async with Runtime() as rt: rt.spawn({type(self).__name__})`"
            )
        if parameter_overrides is not None and not isinstance(parameter_overrides, Mapping):
            parameter_overrides = {p.name: p.value for p in parameter_overrides}
        self._core = NodeCore(
            self,
            request,
            node_name,
            namespace,
            parameter_overrides,
            allow_undeclared_parameters=allow_undeclared_parameters,
            automatically_declare_parameters_from_overrides=automatically_declare_parameters_from_overrides,
            start_parameter_services=start_parameter_services,
            enable_logger_service=enable_logger_service,
        )

    # -- names ----------------------------------------------------------------

    def get_name(self) -> str:
        """The node's name (without namespace)."""
        return self._core.name

    def get_namespace(self) -> str:
        """The node's namespace (``/`` for none)."""
        return self._core.namespace

    def get_fully_qualified_name(self) -> str:
        """``/namespace/name``."""
        return self._core.fqn

    # -- topics ---------------------------------------------------------------

    def create_publisher(
        self,
        msg_type: type[Any],
        topic: str,
        qos_profile: QoSProfile | int,
        *,
        event_callbacks: PublisherEventCallbacks | None = None,
    ) -> Publisher:
        """A publisher of ``msg_type`` on ``topic`` (resolved and remapped by ROS rules).

        ``qos_profile`` is a QoSProfile (copied: changing it later changes
        nothing) or a depth (KEEP_LAST of that depth); its deadline, lifespan
        and liveliness are kept (see :mod:`actors.ros.qos_events`).
        ``event_callbacks`` are called on QoS events.  Raises TopicTypeError if
        the topic already carries another type.
        """
        return self._core.create_publisher(msg_type, topic, qos_profile, event_callbacks)

    def create_subscription(
        self,
        msg_type: type[Any],
        topic: str,
        callback: Callable[[Any], Any],
        qos_profile: QoSProfile | int,
        *,
        event_callbacks: SubscriptionEventCallbacks | None = None,
    ) -> Subscription:
        """A subscription calling ``callback(msg)`` for each message on ``topic``.

        Raises TopicTypeError if the topic already carries another type.  A
        TRANSIENT_LOCAL subscription first receives the history kept by
        TRANSIENT_LOCAL publishers.  Messages older than their publisher's
        lifespan are not delivered.  ``event_callbacks`` are called on QoS
        events.  Callbacks that raise crash the node (its supervisor restarts
        it); the message is logged as a dead letter.  A callback that raises
        MessageRefused refuses the message instead: it is dropped and counted,
        and the node keeps running.
        """
        return self._core.create_subscription(msg_type, topic, callback, qos_profile, event_callbacks)

    def destroy_publisher(self, publisher: Publisher) -> bool:
        """Destroy ``publisher``; returns True as rclpy does."""
        self._core.destroy_publisher(publisher)
        return True

    def destroy_subscription(self, subscription: Subscription) -> bool:
        """Destroy ``subscription``; returns True as rclpy does."""
        self._core.destroy_subscription(subscription)
        return True

    # -- services -------------------------------------------------------------

    def create_service(self, srv_type: type[Any], srv_name: str, callback: Callable[[Any, Any], Any]) -> Service:
        """Serve ``srv_name``: ``callback(request, response)`` fills and returns the response.

        The callback may be ``async def``.  If it raises, the caller's call fails
        with ServiceError carrying the error, and the service keeps serving.
        Raises ServiceError if another node already serves the name.
        """
        return self._core.create_service(srv_type, srv_name, callback)

    def create_client(self, srv_type: type[Any], srv_name: str) -> Client:
        """A client of ``srv_name``: ``await client.call(req, timeout=...)`` or ``call_async``."""
        return self._core.create_client(srv_type, srv_name)

    def destroy_service(self, service: Service) -> bool:
        """Stop serving; returns True as rclpy does."""
        self._core.destroy_service(service)
        return True

    def destroy_client(self, client: Client) -> bool:
        """Forget ``client``; returns True as rclpy does."""
        self._core.destroy_client(client)
        return True

    # -- actions --------------------------------------------------------------

    def create_action_server(
        self,
        action_type: type[Any],
        action_name: str,
        execute: Callable[..., Any],
        *,
        goal: Callable[[Any], Any] | None = None,
        cancel: Callable[[Any], Any] | None = None,
        accepted: Callable[[Any], Any] | None = None,
        result_timeout: float = 10.0,
    ) -> ActionServer:
        """Serve the action ``action_name``: ``execute(goal_handle)`` runs each accepted goal.

        ``execute`` (plain or ``async``) runs in a task of its own, sends
        ``goal_handle.publish_feedback(...)``, ends the goal with ``succeed()``,
        ``abort()`` or ``canceled()`` and returns the action's Result.
        ``goal(request)`` accepts or rejects (GoalResponse; default accept),
        ``cancel(goal_handle)`` accepts or rejects a cancel (CancelResponse;
        default reject, as ROS), ``accepted(goal_handle)`` starts an accepted
        goal (default ``goal_handle.execute()``).  Results are kept
        ``result_timeout`` seconds after a goal ends.  Raises ServiceError if
        another node serves the action.  See :mod:`actors.ros.actions`.
        """
        return self._core.create_action_server(
            action_type,
            action_name,
            execute,
            goal=goal,
            cancel=cancel,
            accepted=accepted,
            result_timeout=result_timeout,
        )

    def create_action_client(self, action_type: type[Any], action_name: str) -> ActionClient:
        """A client of ``action_name``: ``handle = await client.send_goal(goal, feedback=cb)``."""
        return self._core.create_action_client(action_type, action_name)

    # -- time -----------------------------------------------------------------

    def create_timer(
        self,
        timer_period_sec: float,
        callback: Callable[..., Any],
        *,
        clock: Clock | None = None,
        autostart: bool = True,
    ) -> Timer:
        """A timer calling ``callback()`` every ``timer_period_sec`` seconds, first one period from now.

        A callback with a parameter annotated ``TimerInfo`` gets the tick's
        expected and actual call times.  ``autostart=False`` makes a timer that
        starts on ``timer.reset()``.  The timer ticks on the graph's time;
        ``clock`` (the node's by default) is the one TimerInfo reads.  Raises
        ValueError for a period that is not > 0.
        """
        return self._core.create_timer(timer_period_sec, callback, clock=clock, autostart=autostart)

    def destroy_timer(self, timer: Timer) -> bool:
        """Cancel and forget ``timer``; returns True as rclpy does."""
        self._core.destroy_timer(timer)
        return True

    def create_rate(self, frequency: float, clock: Clock | None = None) -> Rate:
        """A Rate for ``await rate.sleep()`` loops in ``async`` callbacks, on the node's clock.

        Raises ValueError for a frequency that is not > 0, or a ``clock`` other
        than the node's (a rate runs on the graph's time).
        """
        if clock is not None and clock is not self._core.clock:
            raise ValueError(f"a rate runs on the node's clock, not on {clock!r}")
        return Rate(frequency, self._core.loop)

    def destroy_rate(self, rate: Rate) -> bool:
        """Destroy ``rate``: its sleepers wake, and sleeping on it again raises RuntimeError."""
        rate.destroy()
        return True

    def get_clock(self) -> ROSClock:
        """The runtime's clock, a ROSClock (virtual time under virtual time)."""
        return self._core.clock

    # -- logging and lifecycle --------------------------------------------------

    def get_logger(self) -> NodeLogger:
        """The node's logger: ``debug``/``info``/``warning``/``error``/``fatal``."""
        return self._core.logger

    # Optional hooks a subclass may define (plain or ``async def``), run in the node's task:
    #   on_start()     once, right after construction: where an rclpy script's main() would
    #                  wait for a service or send a first request;
    #   on_shutdown()  once, when the runtime stops the node, before destroy_node().

    def destroy_node(self) -> None:
        """Stop this node and remove its entities.

        Called by user code, the node ends normally (a ``permanent`` node is then
        restarted).  The runtime calls it at shutdown, after ``on_shutdown``;
        override it to clean up, calling ``super().destroy_node()``.
        """
        self._core.destroy()
