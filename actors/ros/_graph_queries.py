"""The graph half of Node: rclpy's queries about the other nodes, topics and services of the graph."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any, Protocol

from actors.ros.endpoint_info import TopicEndpointInfo, TopicEndpointTypeEnum, endpoint_info
from actors.ros.names import Resolver, expand
from actors.ros.topics import type_name

__all__ = ["GraphQueries"]


class _GraphCore(Protocol):
    name: str
    namespace: str
    resolver: Resolver
    runtime: Any  # the node's Host: nodes, topics, services


class GraphQueries:
    """rclpy's ``Node`` graph queries; mixed into :class:`actors.ros.node.Node`.

    As in rclpy, the ``count_*`` methods expand a relative or private name with
    this node's namespace and name but do not remap it; ``get_*_info_by_topic``
    expands and remaps.  Raises InvalidTopicNameException (or the service
    variant) for a name that breaks the ROS rules.
    """

    _core: _GraphCore

    def _expanded(self, name: str, what: str) -> str:
        return expand(name, self._core.namespace, self._core.name, what=what)

    # -- nodes ------------------------------------------------------------------

    def get_node_names_and_namespaces(self) -> list[tuple[str, str]]:
        """``(name, namespace)`` of every node in the graph, this one included."""
        return [(core.name, core.namespace) for core in self._core.runtime.nodes.values()]

    def get_node_names_and_namespaces_with_enclaves(self) -> list[tuple[str, str, str]]:
        """``(name, namespace, enclave)`` of every node; the enclave is always ``/`` (no security enclaves here)."""
        return [(name, namespace, "/") for name, namespace in self.get_node_names_and_namespaces()]

    def get_node_names(self) -> list[str]:
        """The names of every node in the graph (without namespace)."""
        return [name for name, _ in self.get_node_names_and_namespaces()]

    def get_fully_qualified_node_names(self) -> list[str]:
        """``/namespace/name`` of every node in the graph."""
        return list(self._core.runtime.nodes)

    # -- topics -----------------------------------------------------------------

    def get_topic_names_and_types(self, no_demangle: bool = False) -> list[tuple[str, list[str]]]:
        """Every topic of the graph with its type, sorted by name.

        ``no_demangle`` asks rclpy for middleware names; a topic's name here is its ROS name either way.
        """
        topics = self._core.runtime.topics.topics
        return [(name, [type_name(topics[name].msg_type)]) for name in sorted(topics)]

    def count_publishers(self, topic_name: str) -> int:
        """How many publishers ``topic_name`` (expanded, not remapped) has."""
        topic = self._core.runtime.topics.topics.get(self._expanded(topic_name, "topic name"))
        return len(topic.publishers) if topic else 0

    def count_subscribers(self, topic_name: str) -> int:
        """How many subscriptions ``topic_name`` (expanded, not remapped) has."""
        topic = self._core.runtime.topics.topics.get(self._expanded(topic_name, "topic name"))
        return len(topic.subscriptions) if topic else 0

    def get_publishers_info_by_topic(self, topic_name: str, no_mangle: bool = False) -> list[TopicEndpointInfo]:
        """A TopicEndpointInfo (node, type, QoS) for each publisher of ``topic_name`` (expanded, remapped)."""
        topic = self._core.runtime.topics.topics.get(self._topic(topic_name, no_mangle))
        publishers = topic.publishers if topic else []
        return [endpoint_info(p, TopicEndpointTypeEnum.PUBLISHER) for p in publishers]

    def get_subscriptions_info_by_topic(self, topic_name: str, no_mangle: bool = False) -> list[TopicEndpointInfo]:
        """A TopicEndpointInfo (node, type, QoS) for each subscription of ``topic_name`` (expanded, remapped)."""
        topic = self._core.runtime.topics.topics.get(self._topic(topic_name, no_mangle))
        subscriptions = topic.subscriptions if topic else []
        return [endpoint_info(s, TopicEndpointTypeEnum.SUBSCRIPTION) for s in subscriptions]

    def _topic(self, topic_name: str, no_mangle: bool) -> str:
        # ``no_mangle`` means a middleware name in rclpy; here that is the ROS name itself.
        return topic_name if no_mangle else self._core.resolver.resolve(topic_name)

    def get_publisher_names_and_types_by_node(self, node_name: str, node_namespace: str) -> list[tuple[str, list[str]]]:
        """The topics the node ``node_namespace``/``node_name`` publishes, with their types."""
        return _names_and_types(self._node(node_name, node_namespace).publishers, "topic_name", "msg_type")

    def get_subscriber_names_and_types_by_node(
        self, node_name: str, node_namespace: str
    ) -> list[tuple[str, list[str]]]:
        """The topics the node ``node_namespace``/``node_name`` subscribes to, with their types."""
        return _names_and_types(self._node(node_name, node_namespace).subscriptions, "topic_name", "msg_type")

    # -- services ---------------------------------------------------------------

    def get_service_names_and_types(self) -> list[tuple[str, list[str]]]:
        """Every service of the graph (parameter services included) with its type, sorted by name."""
        table = self._core.runtime.services
        found = {name: s.srv_type for name, s in table.servers.items()}
        found.update((name, srv_type) for name, srv_type, _ in table.deferred())
        return [(name, [type_name(found[name])]) for name in sorted(found)]

    def count_services(self, service_name: str) -> int:
        """How many servers ``service_name`` (expanded, not remapped) has: 0 or 1."""
        return int(self._core.runtime.services.has(self._expanded(service_name, "service name")))

    def count_clients(self, service_name: str) -> int:
        """How many clients of ``service_name`` (expanded, not remapped) the graph's nodes have."""
        full = self._expanded(service_name, "service name")
        return sum(c.service_name == full for core in self._core.runtime.nodes.values() for c in core.clients)

    def get_service_names_and_types_by_node(self, node_name: str, node_namespace: str) -> list[tuple[str, list[str]]]:
        """The services the node ``node_namespace``/``node_name`` serves, with their types."""
        return _pairs_by_name(self._node(node_name, node_namespace).served())

    def get_client_names_and_types_by_node(self, node_name: str, node_namespace: str) -> list[tuple[str, list[str]]]:
        """The services the node ``node_namespace``/``node_name`` has clients of, with their types."""
        return _names_and_types(self._node(node_name, node_namespace).clients, "service_name", "srv_type")

    def _node(self, node_name: str, node_namespace: str) -> Any:
        namespace = node_namespace if node_namespace not in ("", "/") else ""
        core = self._core.runtime.nodes.get(f"{namespace}/{node_name}")
        if core is None:
            raise LookupError(f"no node {namespace}/{node_name} in the graph")
        return core


def _names_and_types(entities: list[Any], name_attr: str, type_attr: str) -> list[tuple[str, list[str]]]:
    return _pairs_by_name((getattr(entity, name_attr), getattr(entity, type_attr)) for entity in entities)


def _pairs_by_name(pairs: Iterable[tuple[str, type]]) -> list[tuple[str, list[str]]]:
    found: dict[str, list[str]] = {}
    for name, type_ in pairs:
        types = found.setdefault(name, [])
        if (kind := type_name(type_)) not in types:
            types.append(kind)
    return sorted(found.items())
