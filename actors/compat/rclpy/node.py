"""``rclpy.node``: the Node a script creates, a native node driven by the script's executors.

``Node.__init__`` runs the native constructor on the runtime's thread with a
:class:`~actors.compat.dispatch.ScriptActor`, so the node is registered like any
other (the command line sees it, its parameter services answer) but nothing of
it runs unless an executor of the script spins it.  The ROS arguments of the
context (``--ros-args``) and the node's own ``cli_args`` rename it, move it,
remap its names and give its parameters, as rcl does.

The ``create_*`` methods build the native entity on the runtime's thread with
the overlay's catcher as its callback, and return the overlay's entity (a
:class:`~actors.compat.dispatch.WorkSource`).  Every other native method runs
on the runtime's thread too, so the script's threads never touch the
runtime's state while it runs.
"""

from __future__ import annotations

import copy
import functools
import warnings
import weakref
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

import msgspec

import actors.compat.rclpy.executors  # as rclpy's node does: `rclpy.executors` is then set
import actors.compat.rclpy.logging  # noqa: F401 - and `rclpy.logging`
from actors.compat.dispatch import NativeWork, ScriptActor, SpinningExecutor, WorkSource
from actors.compat.rclpy._destroyable import Handle
from actors.compat.rclpy.callback_groups import CallbackGroup, MutuallyExclusiveCallbackGroup
from actors.compat.rclpy.client import Client
from actors.compat.rclpy.clock import ROSClock
from actors.compat.rclpy.context import Context
from actors.compat.rclpy.exceptions import NotInitializedException
from actors.compat.rclpy.guard_condition import GuardCondition
from actors.compat.rclpy.logging import RcutilsLogger
from actors.compat.rclpy.publisher import Publisher
from actors.compat.rclpy.qos_overriding_options import QoSOverridingOptions, _declare_qos_parameters
from actors.compat.rclpy.service import Service
from actors.compat.rclpy.subscription import Subscription
from actors.compat.rclpy.time_source import TimeSource
from actors.compat.rclpy.timer import Rate, Timer
from actors.compat.rclpy.type_description_service import TypeDescriptionService
from actors.compat.rclpy.type_hash import TypeHash
from actors.compat.rclpy.utilities import get_default_context
from actors.errors import RosArgsError
from actors.launch.rosargs import RosArgs, parse
from actors.ros.endpoint_info import TopicEndpointInfo
from actors.ros.log import NodeLogger
from actors.ros.names import expand
from actors.ros.node import Node as NativeNode
from actors.ros.node import SpawnRequest, spawning
from actors.ros.qos import QoSProfile
from actors.system.supervisor import RestartType

if TYPE_CHECKING:
    from actors.compat.session import Session

__all__ = ["Node"]


class _ScriptChild:
    """What a script node starts with (a ChildSpec), and what the graph view shows of it.

    No supervisor restarts a script's node: as in rclpy, what its callbacks
    raise leaves the script's spin.
    """

    state = "running"
    restart = RestartType.TEMPORARY
    restarts = crashes = 0
    last_error = None

    def __init__(self, cls: type, name: str, namespace: str, params: dict[str, Any], remap: dict[str, str]) -> None:
        self.cls = cls
        self.name = name
        self.namespace = namespace
        self.params = params
        self.remap = remap
        self.core: Any = None

    def take_inheritance(self) -> dict[tuple[str, str], list[Any]]:
        return {}


class ScriptNodeState:
    """The overlay's side of a script node: its session, executor, entities and native work."""

    def __init__(self, node: Node, context: Context, session: Session) -> None:
        self.node = node
        self.context = context
        self.session = session
        self.lock = session.lock
        self.executor_ref: weakref.ReferenceType[SpinningExecutor] | None = None
        self.default_callback_group = MutuallyExclusiveCallbackGroup()
        self.rate_group = MutuallyExclusiveCallbackGroup()
        self.publishers: list[Publisher] = []
        self.subscriptions: list[Subscription] = []
        self.clients: list[Client] = []
        self.services: list[Service] = []
        self.timers: list[Timer] = []
        self.guards: list[GuardCondition] = []
        self.waitables: list[WorkSource] = []
        self.native_work: dict[Any, NativeWork] = {}
        self.actor: ScriptActor
        self.clock: ROSClock
        self.time_source: TimeSource
        self.logger: NodeLogger
        self.destroyed = False

    def notify(self) -> None:
        """New work: wake the executor that spins the node (called with the lock held)."""
        executor = self.executor_ref() if self.executor_ref is not None else None
        if executor is not None:
            executor.wake()

    def gated(self, entity: Any) -> None:
        # On the runtime's thread: a native entity (a parameter service) has work.
        with self.lock:
            work = self.native_work.get(entity)
            if work is None:
                work = self.native_work[entity] = NativeWork(entity, self.default_callback_group, self.session.block)
            work.scheduled = True
            self.notify()

    def work_sources(self) -> list[WorkSource]:
        """Every work source, in the order rclpy's executors look at them."""
        return [
            *self.timers,
            *self.subscriptions,
            *self.guards,
            *self.clients,
            *self.services,
            *self.waitables,
            *self.native_work.values(),
        ]


class Node(NativeNode):
    """A ROS node as rclpy has it: subclass it, or ``rclpy.create_node(name)``.

    Raises NotInitializedException before ``rclpy.init()``, RosArgsError for
    malformed ``cli_args``, InvalidNameError for a bad name, and what the
    native node raises (a duplicate name in the runtime).
    """

    def __init__(
        self,
        node_name: str,
        *,
        context: Context | None = None,
        cli_args: Sequence[str] | None = None,
        namespace: str | None = None,
        use_global_arguments: bool = True,
        enable_rosout: bool = True,
        rosout_qos_profile: Any = None,
        start_parameter_services: bool = True,
        parameter_overrides: Sequence[Any] | None = None,
        allow_undeclared_parameters: bool = False,
        automatically_declare_parameters_from_overrides: bool = False,
        enable_logger_service: bool = False,
    ) -> None:
        context = get_default_context() if context is None else context
        if not context.ok() or context.session is None:
            raise NotInitializedException("cannot create a node: rclpy.init() has not been called")
        session = context.session
        args = context.ros_args if use_global_arguments else RosArgs()
        if cli_args:
            try:
                args = args + parse(["--ros-args", *cli_args])[0]
            except RosArgsError as exc:  # in rcl's words, keeping the error's class
                raise type(exc)(f"Failed to parse ROS arguments: {exc}") from None
        setup = args.for_node(node_name, namespace)
        # rclpy: the constructor's parameter_overrides win over the command line's.
        own = {p.name: p.value for p in parameter_overrides or ()}
        child = _ScriptChild(type(self), setup.name, setup.namespace, own, setup.remap)
        state = ScriptNodeState(self, context, session)
        self._rclpy = state
        options = {
            key: value
            for key, value, default in (
                ("allow_undeclared_parameters", allow_undeclared_parameters, False),
                (
                    "automatically_declare_parameters_from_overrides",
                    automatically_declare_parameters_from_overrides,
                    False,
                ),
                ("start_parameter_services", start_parameter_services, True),
                ("enable_logger_service", enable_logger_service, False),
            )
            if value != default
        }

        def build() -> None:
            state.actor = ScriptActor(session.dispatcher, session.loop, state.gated, self._callback_failed)
            with spawning(SpawnRequest(session.runtime, child, state.actor)):
                NativeNode.__init__(
                    self, setup.name, namespace=setup.namespace, parameter_overrides=setup.params, **options
                )
            child.core = self._core
            self._core.answers_own_calls = True  # its executor answers, as rclpy's (see NodeCore)
            # rclpy's node lists the publisher of its parameter changes among its publishers; here it
            # is the runtime's, which every node shares (destroying it only takes it off the list).
            state.publishers.append(Publisher(self, self._core.parameter_events))
            native_logger = NativeNode.get_logger(self)
            # The node's own ROS clock on the runtime's time, which its time source can move to /clock.
            state.clock = ROSClock(session.loop)
            # rcl's rule: records reach /rosout when both the node and the context's arguments allow it.
            sink = native_logger.sink if enable_rosout and args.logs_to("rosout") else None
            state.logger = RcutilsLogger(native_logger.name, state.clock.now_ns, _threadsafe(sink, session))

        session.call(build)
        state.time_source = TimeSource(node=self)
        state.time_source.attach_clock(state.clock)
        self._type_description_service = TypeDescriptionService(self)
        context.track_node(self)

    def _callback_failed(self, error: BaseException) -> None:
        NativeNode.get_logger(self).error(f"the rclpy overlay failed: {error!r}", exc_info=error)

    # -- what rclpy nodes have beside the native methods -------------------------------

    @property
    def context(self) -> Context:
        """The context the node was created in."""
        return self._rclpy.context

    @property
    def handle(self) -> Handle:
        """Usable (``with node.handle:``) until the node is destroyed, as rclpy's rcl handle."""
        return Handle(lambda: not self._rclpy.destroyed)

    @property
    def executor(self) -> SpinningExecutor | None:
        """The executor that spins the node, if any; setting it moves the node there."""
        ref = self._rclpy.executor_ref
        return ref() if ref is not None else None

    @executor.setter
    def executor(self, new_executor: SpinningExecutor | None) -> None:
        current = self.executor
        if current is new_executor:
            return
        if current is not None:
            current.remove_node(self)
        if new_executor is None:
            self._rclpy.executor_ref = None
        else:
            self._rclpy.executor_ref = weakref.ref(new_executor)
            new_executor.add_node(self)

    @property
    def default_callback_group(self) -> CallbackGroup:
        """The group of entities created without ``callback_group=`` (mutually exclusive)."""
        return self._rclpy.default_callback_group

    @property
    def publishers(self) -> list[Publisher]:
        """The node's publishers."""
        return list(self._rclpy.publishers)

    @property
    def subscriptions(self) -> list[Subscription]:
        """The node's subscriptions."""
        return list(self._rclpy.subscriptions)

    @property
    def clients(self) -> list[Client]:
        """The node's clients."""
        return list(self._rclpy.clients)

    @property
    def services(self) -> list[Service]:
        """The node's services."""
        return list(self._rclpy.services)

    @property
    def timers(self) -> list[Timer]:
        """The node's timers."""
        return list(self._rclpy.timers)

    @property
    def guards(self) -> list[GuardCondition]:
        """The node's guard conditions."""
        return list(self._rclpy.guards)

    @property
    def waitables(self) -> list[WorkSource]:
        """The node's other work sources (action clients and servers)."""
        return list(self._rclpy.waitables)

    def resolve_topic_name(self, topic: str, *, only_expand: bool = False) -> str:
        """``topic`` made absolute for this node, and remapped unless ``only_expand``; InvalidTopicNameException."""
        return self._resolve(topic, only_expand, "topic name")

    def resolve_service_name(self, service: str, *, only_expand: bool = False) -> str:
        """``service`` made absolute for this node, and remapped unless ``only_expand``."""
        return self._resolve(service, only_expand, "service name")

    def _resolve(self, name: str, only_expand: bool, what: str) -> str:
        resolver = self._core.resolver
        if only_expand:
            return expand(name, resolver.namespace, resolver.node_name, what=what)
        return resolver.resolve(name, what=what)

    def wait_for_node(self, fully_qualified_node_name: str, timeout: float) -> bool:
        """Wait until a node of that full name is in the graph (``timeout`` seconds of runtime clock at most)."""
        if not fully_qualified_node_name.startswith("/"):
            fully_qualified_node_name = f"/{fully_qualified_node_name}"
        session = self._rclpy.session
        deadline = session.loop.time() + timeout
        # Nodes join the graph without an event a waiter could take: look every tenth of a second.
        while fully_qualified_node_name not in self.get_fully_qualified_node_names():
            left = deadline - session.loop.time()
            if left <= 0:
                return False
            session.sleep(min(0.1, left))
        return True

    def get_publishers_info_by_topic(self, topic_name: str, no_mangle: bool = False) -> list[TopicEndpointInfo]:
        """rclpy's infos of ``topic_name``'s publishers: the type hash is a :class:`TypeHash`."""
        found = self._rclpy.session.call(NativeNode.get_publishers_info_by_topic, self, topic_name, no_mangle)
        return [_rclpy_info(info) for info in found]

    def get_subscriptions_info_by_topic(self, topic_name: str, no_mangle: bool = False) -> list[TopicEndpointInfo]:
        """rclpy's infos of ``topic_name``'s subscriptions: the type hash is a :class:`TypeHash`."""
        found = self._rclpy.session.call(NativeNode.get_subscriptions_info_by_topic, self, topic_name, no_mangle)
        return [_rclpy_info(info) for info in found]

    def declare_parameter(
        self, name: str, value: Any = None, descriptor: Any = None, ignore_override: bool = False
    ) -> Any:
        """See the native :meth:`~actors.ros.node.Node.declare_parameter`; a name alone warns, as in rclpy."""
        if value is None and descriptor is None:
            _warn_name_only(name)
        return self._rclpy.session.call(NativeNode.declare_parameter, self, name, value, descriptor, ignore_override)

    def declare_parameters(
        self, namespace: str, parameters: Sequence[tuple[Any, ...]], ignore_override: bool = False
    ) -> list[Any]:
        """See the native :meth:`~actors.ros.node.Node.declare_parameters`; a name alone warns, as in rclpy."""
        for entry in parameters:
            if len(entry) == 1:
                _warn_name_only(f"{namespace}.{entry[0]}" if namespace else entry[0])
        return list(
            self._rclpy.session.call(NativeNode.declare_parameters, self, namespace, parameters, ignore_override)
        )

    # rclpy keeps its parameter callbacks in these lists (newest first), which its tests read.
    @property
    def _pre_set_parameters_callbacks(self) -> list[Any]:
        return list(self._core.params.callbacks[0])

    @property
    def _on_set_parameters_callbacks(self) -> list[Any]:
        return list(self._core.params.callbacks[1])

    @property
    def _post_set_parameters_callbacks(self) -> list[Any]:
        return list(self._core.params.callbacks[2])

    def get_clock(self) -> ROSClock:
        """The node's ROS clock: the runtime's time, or ``/clock``'s while ``use_sim_time`` is true."""
        return self._rclpy.clock

    def get_logger(self) -> NodeLogger:
        """The node's logger (usable from any thread)."""
        return self._rclpy.logger

    # -- entities ---------------------------------------------------------------------

    def _group(self, callback_group: CallbackGroup | None, entity: Any) -> CallbackGroup:
        group = self._rclpy.default_callback_group if callback_group is None else callback_group
        group.add_entity(entity)
        return group

    def _wake_executor(self) -> None:
        with self._rclpy.lock:
            self._rclpy.notify()

    # The create_* methods (and create_rate, destroy_rate) are rclpy's: their signatures and the
    # overlay entities they return are not the native node's, which they call.  Hence each one's
    # ignore[override]: a script sees rclpy's Node, the runtime the native one.
    def create_publisher(  # type: ignore[override]  # rclpy's signature and entity
        self,
        msg_type: type[Any],
        topic: str,
        qos_profile: Any,
        *,
        callback_group: CallbackGroup | None = None,
        qos_overriding_options: QoSOverridingOptions | None = None,
        publisher_class: type[Publisher] = Publisher,
        **options: Any,
    ) -> Publisher:
        """A publisher of ``msg_type`` on ``topic`` (a QoSProfile or a depth).

        With ``qos_overriding_options`` its QoS policies may be set by parameters
        (:mod:`~actors.compat.rclpy.qos_overriding_options`); ``publisher_class``
        is what to make (a LifecyclePublisher for ``create_lifecycle_publisher``).
        """
        if qos_overriding_options is not None:
            qos_profile = self._overridden(Publisher, topic, qos_profile, qos_overriding_options)
        native = self._rclpy.session.call(NativeNode.create_publisher, self, msg_type, topic, qos_profile, **options)
        publisher = publisher_class(self, native)
        self._rclpy.publishers.append(publisher)
        return publisher

    def create_subscription(  # type: ignore[override]  # rclpy's signature and entity
        self,
        msg_type: type[Any],
        topic: str,
        callback: Callable[..., Any],
        qos_profile: Any,
        *,
        callback_group: CallbackGroup | None = None,
        raw: bool = False,
        qos_overriding_options: QoSOverridingOptions | None = None,
        **options: Any,
    ) -> Subscription:
        """Call ``callback(msg)`` (or ``callback(msg, info)``) for each message, while spun.

        With ``raw=True`` the callback gets the message's CDR bytes, as ROS serializes it;
        ``qos_overriding_options`` as for :meth:`create_publisher`.
        """
        if qos_overriding_options is not None:
            qos_profile = self._overridden(Subscription, topic, qos_profile, qos_overriding_options)
        subscription = Subscription(self, msg_type, callback, None, raw)
        subscription.callback_group = self._group(callback_group, subscription)
        self._create(
            subscription, NativeNode.create_subscription, msg_type, topic, subscription.catcher, qos_profile, **options
        )
        self._rclpy.subscriptions.append(subscription)
        self._wake_executor()
        return subscription

    def _overridden(self, entity_type: type, topic: str, qos: Any, options: QoSOverridingOptions) -> QoSProfile:
        # The endpoint's profile after its override parameters (declared here) are applied.
        profile = QoSProfile(depth=qos) if isinstance(qos, int) else copy.copy(qos)
        _declare_qos_parameters(entity_type, self, self.resolve_topic_name(topic), profile, options)
        return profile

    def create_timer(  # type: ignore[override]  # rclpy's signature and entity
        self,
        timer_period_sec: float,
        callback: Callable[..., Any] | None,
        callback_group: CallbackGroup | None = None,
        clock: Any = None,
        **options: Any,
    ) -> Timer:
        """Call ``callback()`` every ``timer_period_sec`` seconds of the node's clock, while spun."""
        timer = Timer(self, callback, None)
        timer.callback_group = self._group(callback_group, timer)
        if clock is not None:
            options["clock"] = clock
        self._create(timer, NativeNode.create_timer, timer_period_sec, timer.catcher, **options)
        self._rclpy.timers.append(timer)
        self._wake_executor()
        return timer

    def create_service(  # type: ignore[override]  # rclpy's signature and entity
        self,
        srv_type: type[Any],
        srv_name: str,
        callback: Callable[[Any, Any], Any],
        *,
        qos_profile: Any = None,
        callback_group: CallbackGroup | None = None,
    ) -> Service:
        """Answer ``srv_name`` with ``callback(request, response)``, while spun."""
        service = Service(self, srv_type, callback, None)
        service.callback_group = self._group(callback_group, service)
        self._create(service, NativeNode.create_service, srv_type, srv_name, service.catcher)
        self._rclpy.services.append(service)
        self._wake_executor()
        return service

    def create_client(  # type: ignore[override]  # rclpy's signature and entity
        self,
        srv_type: type[Any],
        srv_name: str,
        *,
        qos_profile: Any = None,
        callback_group: CallbackGroup | None = None,
    ) -> Client:
        """A client of ``srv_name``: ``call_async(req)`` (a Future), ``call(req)``, ``wait_for_service``."""
        native = self._rclpy.session.call(NativeNode.create_client, self, srv_type, srv_name)
        client = Client(self, native, None)
        client.callback_group = self._group(callback_group, client)
        self._rclpy.clients.append(client)
        return client

    def create_guard_condition(
        self, callback: Callable[[], Any] | None, callback_group: CallbackGroup | None = None
    ) -> GuardCondition:
        """A guard condition: ``trigger()`` it from any thread and ``callback`` runs at the next spin."""
        guard = GuardCondition(self, callback, None)
        guard.callback_group = self._group(callback_group, guard)
        with self._rclpy.lock:
            self._rclpy.guards.append(guard)
        return guard

    def create_rate(self, frequency: float, clock: Any = None) -> Rate:  # type: ignore[override]  # rclpy's Rate
        """A Rate ticking ``frequency`` times per second; ``rate.sleep()`` needs the node spun."""
        if frequency <= 0:
            raise ValueError("frequency must be > 0")
        timer = self.create_timer(1.0 / frequency, None, self._rclpy.rate_group, clock)
        return Rate(timer, context=self._rclpy.context)

    def add_waitable(self, waitable: WorkSource) -> None:
        """Let the node's executor take work from ``waitable`` (what action clients and servers are)."""
        with self._rclpy.lock:
            self._rclpy.waitables.append(waitable)
            self._rclpy.notify()

    def remove_waitable(self, waitable: WorkSource) -> None:
        """Stop taking work from ``waitable``."""
        with self._rclpy.lock:
            _discard(self._rclpy.waitables, waitable)

    def _create(self, source: WorkSource, create: Callable[..., Any], *args: Any, **options: Any) -> None:
        # On the runtime's thread: the native entity, its catcher driven before it can fire.
        catcher = source.catcher
        assert catcher is not None  # the entities made here (subscriptions, timers, services) have one

        def build() -> None:
            self._rclpy.actor.drive(catcher)
            source._attach(create(self, *args, **options))

        self._rclpy.session.call(build)

    # -- destroying ---------------------------------------------------------------------

    def _destroy(self, kind: list[Any], entity: Any, destroy: Callable[..., Any] | None) -> bool:
        with self._rclpy.lock:
            if entity not in kind:
                return False
            kind.remove(entity)
            entity._destroyed = True
            self._rclpy.notify()
        native = getattr(entity, "_native", None)
        if destroy is not None and native is not None and not self._rclpy.destroyed:

            def drop() -> None:
                destroy(self, native)
                if entity.catcher is not None:
                    self._rclpy.actor.forget(entity.catcher)

            self._rclpy.session.call(drop)
        return True

    def destroy_publisher(self, publisher: Any) -> bool:
        """Destroy ``publisher``; whether it was the node's."""
        shared = getattr(publisher, "_native", None) is self._core.parameter_events
        return self._destroy(self._rclpy.publishers, publisher, None if shared else NativeNode.destroy_publisher)

    def destroy_subscription(self, subscription: Any) -> bool:
        """Destroy ``subscription``; whether it was the node's."""
        return self._destroy(self._rclpy.subscriptions, subscription, NativeNode.destroy_subscription)

    def destroy_timer(self, timer: Any) -> bool:
        """Destroy ``timer``; whether it was the node's."""
        return self._destroy(self._rclpy.timers, timer, NativeNode.destroy_timer)

    def destroy_service(self, service: Any) -> bool:
        """Destroy ``service``; whether it was the node's."""
        return self._destroy(self._rclpy.services, service, NativeNode.destroy_service)

    def destroy_client(self, client: Any) -> bool:
        """Destroy ``client``; whether it was the node's."""
        return self._destroy(self._rclpy.clients, client, NativeNode.destroy_client)

    def destroy_guard_condition(self, guard: GuardCondition) -> bool:
        """Destroy ``guard``; whether it was the node's."""
        return self._destroy(self._rclpy.guards, guard, None)

    def destroy_rate(self, rate: Rate) -> bool:  # type: ignore[override]  # rclpy's Rate
        """Destroy ``rate`` and its timer."""
        rate.destroy()
        return self.destroy_timer(rate._timer)

    def __enter__(self) -> Node:
        return self

    def __exit__(self, *exc: object) -> None:
        self.destroy_node()

    def destroy_node(self) -> None:
        """Destroy the node and everything it has; its executor forgets it.  Idempotent."""
        state = self._rclpy
        if state.destroyed:
            return
        executor = self.executor
        if executor is not None:
            executor.remove_node(self)
        if state.session.running:
            state.session.call(NativeNode.destroy_node, self)
        with state.lock:
            state.destroyed = True
            for kind in (
                state.publishers,
                state.subscriptions,
                state.clients,
                state.services,
                state.timers,
                state.guards,
                state.waitables,
            ):
                kind.clear()
            state.native_work.clear()
        state.context.untrack_node(self)


def _warn_name_only(name: str) -> None:
    warnings.warn(
        f"when declaring parameter named '{name}', declaring a parameter only providing its name is deprecated. "
        "You have to either:\n"
        '\t- Pass a name and a default value different to "PARAMETER NOT SET" (and optionally a descriptor).\n'
        "\t- Pass a name and a parameter type.\n"
        "\t- Pass a name and a descriptor with `dynamic_typing=True",
        UserWarning,
        stacklevel=3,
    )


def _rclpy_info(info: TopicEndpointInfo) -> TopicEndpointInfo:
    # rclpy's infos carry the hash as an object (a TypeHash), not the native RIHS01 string.
    return msgspec.structs.replace(info, topic_type_hash=TypeHash.from_string(info.topic_type_hash))


def _discard(entities: list[Any], entity: Any) -> None:
    if entity in entities:
        entities.remove(entity)


def _threadsafe(sink: Callable[..., None] | None, session: Session) -> Callable[..., None] | None:
    # A script thread's log record reaches /rosout through the runtime's thread.
    if sink is None:
        return None

    def forward(*record: Any) -> None:
        if session.running:
            session.loop.call_soon_threadsafe(sink, *record)

    return forward


# Every other native method (parameters, graph queries...) runs on the runtime's thread.
_DIRECT = {"get_name", "get_namespace", "get_fully_qualified_name", "get_clock"}


def _on_loop_thread(method: Callable[..., Any]) -> Callable[..., Any]:
    @functools.wraps(method)
    def call(self: Node, *args: Any, **kwargs: Any) -> Any:
        return self._rclpy.session.call(method, self, *args, **kwargs)

    return call


for _klass in reversed(NativeNode.__mro__):
    for _name, _value in vars(_klass).items():
        if (
            not _name.startswith("_")
            and _name not in _DIRECT
            and _name not in Node.__dict__
            and callable(_value)
            and not isinstance(_value, (staticmethod, classmethod, type))
        ):
            setattr(Node, _name, _on_loop_thread(_value))
