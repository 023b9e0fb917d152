"""A read-only view of a running graph: nodes, topics, endpoints, drop counts, actions.

The command line and ``doctor`` read the graph only through these frozen
snapshots, which encode to msgpack as they are.  With a transport attached,
they show the nodes and endpoints of other processes too (``process`` names
where they run), and leave out the transport's own stand-in endpoints.  Actions are not a table of
their own: as rcl_action does, they are read off the topics and services
they are made of (``<action>/_action/feedback`` and the rest), so a snapshot
of topics is enough to list them (:func:`action_infos`).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import TYPE_CHECKING, Any, Protocol, cast

import msgspec

from actors import codec
from actors.errors import ActorsError
from actors.ros.endpoint_info import gid_of
from actors.ros.names import is_hidden
from actors.ros.qos import QoSSnapshot
from actors.ros.topics import Topic, TopicTable, type_name
from actors.services import ServiceTable
from actors.system.supervisor import Child, Supervisor
from actors.transport.seam import GraphSource, RemoteNode, is_proxy

if TYPE_CHECKING:
    from actors.ros.node import NodeCore

__all__ = [
    "EndpointInfo",
    "TopicInfo",
    "ServiceInfo",
    "NodeInfo",
    "ActionInfo",
    "GraphView",
    "Viewed",
    "action_infos",
    "action_of",
]


class EndpointInfo(msgspec.Struct, frozen=True, kw_only=True):
    """A publisher or subscription: its node, type and QoS; for a subscription, its mailbox.

    ``refused`` counts, per reason, the messages the subscription's callback
    refused (:class:`~actors.errors.MessageRefused`); ``refused_from`` names the
    publisher of the last one.  ``process`` is empty for this process's endpoints, else where the endpoint
    runs (a transport's id); ``type_hash`` is set where a topic has remote
    endpoints (RIHS01), and ``why`` says why this process cannot read a remote one.
    """

    node: str
    type: str
    qos: QoSSnapshot
    queued: int = 0
    dropped: int = 0
    refused: dict[str, int] = {}
    refused_from: str = ""
    process: str = ""
    type_hash: str = ""
    why: str = ""
    gid: list[int] = []  # a remote endpoint's as its transport gives it


class TopicInfo(msgspec.Struct, frozen=True, kw_only=True):
    """A topic, its type and endpoints."""

    name: str
    type: str
    publishers: tuple[EndpointInfo, ...]
    subscriptions: tuple[EndpointInfo, ...]


class ServiceInfo(msgspec.Struct, frozen=True, kw_only=True):
    """A service: its type, the node serving it, requests handled and waiting."""

    name: str
    type: str
    node: str
    handled: int
    queued: int
    process: str = ""


class NodeInfo(msgspec.Struct, frozen=True, kw_only=True):
    """A node: full name, class, supervision state and what it uses."""

    name: str
    cls: str
    state: str
    restart: str
    restarts: int
    crashes: int
    last_error: str | None
    publishes: tuple[str, ...]
    subscribes: tuple[str, ...]
    serves: tuple[str, ...]
    calls: tuple[str, ...]
    timers: int
    process: str = ""


class ActionInfo(msgspec.Struct, frozen=True, kw_only=True):
    """An action: its name, type, and the nodes serving it and sending it goals."""

    name: str
    type: str
    servers: tuple[str, ...]
    clients: tuple[str, ...]


_INFIX = "/_action/"
_SUFFIXES = {
    "send_goal": "_SendGoal",
    "cancel_goal": "",
    "get_result": "_GetResult",
    "feedback": "_FeedbackMessage",
    "status": "",
}


def action_of(name: str, type_: str) -> tuple[str, str] | None:
    """The action an endpoint belongs to, as ``(action name, action type)``, or None.

    ``("/fibonacci/_action/send_goal", "pkg/action/Fibonacci_SendGoal")`` gives
    ``("/fibonacci", "pkg/action/Fibonacci")``; the cancel and status endpoints
    (whose types are action_msgs') give None, as do other names.
    """
    action, infix, role = name.rpartition(_INFIX)
    suffix = _SUFFIXES.get(role) if infix else None
    if not suffix or not type_.endswith(suffix) or "/action/" not in type_:
        return None
    return action, type_[: -len(suffix)]


def action_infos(topics: Iterable[TopicInfo]) -> list[ActionInfo]:
    """Every action of a graph, from its topics: servers publish feedback, clients subscribe to it.

    Hidden nodes (the command line's own) are left out.  Sorted by name.
    """
    found = []
    for topic in topics:
        action = action_of(topic.name, topic.type)
        if action is None:
            continue
        found.append(
            ActionInfo(
                name=action[0],
                type=action[1],
                servers=tuple(sorted({e.node for e in topic.publishers if not is_hidden(e.node)})),
                clients=tuple(sorted({e.node for e in topic.subscriptions if not is_hidden(e.node)})),
            )
        )
    return sorted(found, key=lambda info: info.name)


class Viewed(Protocol):
    """The tables a graph view reads (a runtime's), and what runs beside them."""

    supervisor: Supervisor
    topics: TopicTable
    services: ServiceTable

    @property
    def nodes(self) -> Mapping[str, NodeCore]: ...

    @property
    def attachments(self) -> tuple[Any, ...]: ...


class GraphView:
    """Snapshots of a runtime's graph, made on request."""

    __slots__ = ("_rt",)

    def __init__(self, runtime: Viewed) -> None:
        self._rt = runtime

    def nodes(self) -> list[NodeInfo]:
        """Every node of the graph, in start order, including those being restarted; then nodes built
        outside the supervisor (an rclpy script's); then remote ones."""
        children = self._rt.supervisor.children
        local = [_node_info(c) for c in children if c.core is not None]
        # Built outside the supervisor: an rclpy script's node, whose child spec shows the same fields as a Child.
        outside = [core.child for core in list(self._rt.nodes.values()) if core.child not in children]
        local += [_node_info(cast(Child, child)) for child in outside]
        return local + [_remote_node_info(n) for n in self.remote_nodes()]

    def remote_nodes(self) -> list[RemoteNode]:
        """The nodes of other processes, as the attached transports see them."""
        return [n for a in self._rt.attachments if isinstance(a, GraphSource) for n in a.remote_nodes()]

    def ended(self) -> list[NodeInfo]:
        """The latest nodes that ended for good (exited, or crashed and not restarted)."""
        return [_node_info(c) for c in self._rt.supervisor.ended if c.core is not None]

    def topics(self) -> list[TopicInfo]:
        """Every topic with its endpoints (other processes' too), sorted by name."""
        remote = _remote_endpoints(self.remote_nodes())
        found = {name: self._topic_info(t, remote.pop(name, None)) for name, t in self._rt.topics.topics.items()}
        found.update((name, _remote_topic(name, *ends)) for name, ends in remote.items())
        return [found[name] for name in sorted(found)]

    def services(self) -> list[ServiceInfo]:
        """Every service with its server (remote ones too), sorted by name."""
        found = {
            name: ServiceInfo(
                name=name, type=type_name(s.srv_type), node=s.node.fqn, handled=s.handled, queued=s.queued
            )
            for name, s in self._rt.services.servers.items()
            if not is_proxy(s)
        }
        for name, srv_type, owner in self._rt.services.deferred():
            found[name] = ServiceInfo(name=name, type=type_name(srv_type), node=owner.fqn, handled=0, queued=0)
        for node in self.remote_nodes():
            for e in node.endpoints:
                if e.kind == "server" and e.name not in found:
                    found[e.name] = ServiceInfo(
                        name=e.name, type=e.type, node=node.name, handled=0, queued=0, process=node.process
                    )
        return [found[name] for name in sorted(found)]

    def actions(self) -> list[ActionInfo]:
        """Every action with its servers and clients, sorted by name."""
        return action_infos(self.topics())

    def topic(self, name: str) -> TopicInfo | None:
        """One topic (with its remote endpoints), or None."""
        remote = _remote_endpoints(self.remote_nodes()).get(name)
        topic = self._rt.topics.topics.get(name)
        if topic is not None:
            return self._topic_info(topic, remote)
        return None if remote is None else _remote_topic(name, *remote)

    @staticmethod
    def _topic_info(topic: Topic, remote: tuple[list[EndpointInfo], list[EndpointInfo]] | None = None) -> TopicInfo:
        # Type hashes only where other processes take part: they are what a transport compares.
        hash_ = _hash_of(topic.msg_type) if remote else ""
        pubs, subs = remote or ([], [])
        return TopicInfo(
            name=topic.name,
            type=type_name(topic.msg_type),
            publishers=tuple(
                EndpointInfo(node=p.node.fqn, type=type_name(p.msg_type), qos=p.qos, type_hash=hash_, gid=gid_of(p))
                for p in topic.publishers
                if not is_proxy(p)
            )
            + tuple(pubs),
            subscriptions=tuple(
                EndpointInfo(
                    node=s.node.fqn,
                    type=type_name(s.msg_type),
                    qos=s.qos,
                    queued=s.queued,
                    dropped=s.dropped,
                    refused=dict(s.refusals.counts) if s.refusals else {},
                    refused_from=s.refusals.last_from if s.refusals else "",
                    type_hash=hash_,
                    gid=gid_of(s),
                )
                for s in topic.subscriptions
            )
            + tuple(subs),
        )


def _hash_of(msg_type: type[Any]) -> str:
    try:
        return codec.type_hash(msg_type)
    except (ActorsError, TypeError, ValueError):
        return ""  # not a ROS type (a test's own class): nothing to compare


_TOPIC_KINDS = ("publisher", "subscription")


def _remote_endpoints(nodes: list[RemoteNode]) -> dict[str, tuple[list[EndpointInfo], list[EndpointInfo]]]:
    """Remote publishers and subscriptions by topic name."""
    found: dict[str, tuple[list[EndpointInfo], list[EndpointInfo]]] = {}
    for node, e in ((n, e) for n in nodes for e in n.endpoints if e.kind in _TOPIC_KINDS):
        info = EndpointInfo(
            node=node.name, type=e.type, qos=e.qos, process=node.process, type_hash=e.type_hash, why=e.why, gid=[*e.gid]
        )
        found.setdefault(e.name, ([], []))[_TOPIC_KINDS.index(e.kind)].append(info)
    return found


def _remote_topic(name: str, pubs: list[EndpointInfo], subs: list[EndpointInfo]) -> TopicInfo:
    """A topic only other processes use."""
    return TopicInfo(name=name, type=(pubs or subs)[0].type, publishers=tuple(pubs), subscriptions=tuple(subs))


def _remote_node_info(node: RemoteNode) -> NodeInfo:
    def names(kind: str) -> tuple[str, ...]:
        return tuple(sorted({e.name for e in node.endpoints if e.kind == kind}))

    return NodeInfo(
        name=node.name,
        cls="",
        state="remote",
        restart="",
        restarts=0,
        crashes=0,
        last_error=None,
        publishes=names("publisher"),
        subscribes=names("subscription"),
        serves=names("server"),
        calls=names("client"),
        timers=0,
        process=node.process,
    )


def _node_info(child: Child) -> NodeInfo:
    core = child.core
    assert core is not None
    return NodeInfo(
        name=core.fqn,
        cls=f"{child.cls.__module__}:{child.cls.__qualname__}",
        state=child.state,
        restart=child.restart.value,
        restarts=child.restarts,
        crashes=child.crashes,
        last_error=child.last_error,
        publishes=tuple(sorted({p.topic_name for p in core.publishers})),
        subscribes=tuple(sorted({s.topic_name for s in core.subscriptions})),
        serves=tuple(sorted(name for name, _ in core.served())),
        calls=tuple(sorted({c.service_name for c in core.clients})),
        timers=sum(not t.is_canceled() for t in core.timers),
    )
