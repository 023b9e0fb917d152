"""What ``Node.get_publishers_info_by_topic`` returns: rclpy's TopicEndpointInfo, one per endpoint."""

from __future__ import annotations

import copy
import weakref
from enum import IntEnum
from typing import Any

import msgspec

from actors.codec import type_hash
from actors.ros.qos import QoSProfile, QoSSnapshot
from actors.ros.time import Infinite
from actors.ros.topics import type_name

__all__ = ["TopicEndpointTypeEnum", "TopicEndpointInfo", "endpoint_info", "gid_of", "wire_gids", "reported_profile"]


class TopicEndpointTypeEnum(IntEnum):
    """Whether an endpoint publishes or subscribes (values as ``rmw``'s)."""

    INVALID = 0
    PUBLISHER = 1
    SUBSCRIPTION = 2


class TopicEndpointInfo(msgspec.Struct, kw_only=True):
    """A publisher or subscription of a topic, with the fields rclpy's has.

    ``endpoint_gid`` is the endpoint's GID on a transport's wire while one
    announces it, else an opaque id unique among the endpoints alive in the
    process (as a GID is in a ROS graph); ``topic_type_hash`` is the type's
    RIHS01 hash ("" when unknown, printed INVALID as rclpy does).
    """

    node_name: str = ""
    node_namespace: str = ""
    topic_type: str = ""
    topic_type_hash: str = ""
    endpoint_type: TopicEndpointTypeEnum = TopicEndpointTypeEnum.INVALID
    endpoint_gid: list[int] = msgspec.field(default_factory=list)
    qos_profile: Any = None

    def __str__(self) -> str:
        qos = self.qos_profile
        lines = [
            f"Node name: {self.node_name}",
            f"Node namespace: {self.node_namespace}",
            f"Topic type: {self.topic_type}",
            f"Topic type hash: {self.topic_type_hash or 'INVALID'}",
            f"Endpoint type: {self.endpoint_type.name}",
            f"GID: {'.'.join(format(b, '02x') for b in self.endpoint_gid)}",
            "QoS profile:",
        ]
        if qos is None:  # an info made by hand: rmw's unknown profile
            lines += [f"  {name}: UNKNOWN" for name in ("Reliability", "History (Depth)", "Durability")]
            lines += ["  Lifespan: 0 nanoseconds", "  Deadline: 0 nanoseconds", "  Liveliness: UNKNOWN"]
            lines.append("  Liveliness lease duration: 0 nanoseconds")
            return "\n".join(lines)
        depth = f" ({qos.depth})" if qos.history.name == "KEEP_LAST" else ""
        lines += [
            f"  Reliability: {qos.reliability.name}",
            f"  History (Depth): {qos.history.name}{depth}",
            f"  Durability: {qos.durability.name}",
            f"  Lifespan: {qos.lifespan}",
            f"  Deadline: {qos.deadline}",
            f"  Liveliness: {qos.liveliness.name}",
            f"  Liveliness lease duration: {qos.liveliness_lease_duration}",
        ]
        return "\n".join(lines)


def endpoint_info(endpoint: Any, kind: TopicEndpointTypeEnum) -> TopicEndpointInfo:
    """The TopicEndpointInfo of a Publisher or Subscription."""
    namespace, _, node_name = endpoint.node.fqn.rpartition("/")
    return TopicEndpointInfo(
        node_name=node_name,
        node_namespace=namespace or "/",
        topic_type=type_name(endpoint.msg_type),
        topic_type_hash=type_hash(endpoint.msg_type),
        endpoint_type=kind,
        endpoint_gid=gid_of(endpoint),
        qos_profile=reported_profile(endpoint.qos),
    )


wire_gids: weakref.WeakKeyDictionary[Any, bytes] = weakref.WeakKeyDictionary()
"""The GIDs local endpoints have on a transport's wire, by endpoint, set by the transport while it announces them.

A ROS 2 peer names an endpoint by what the transport tells it (rmw_zenoh:
the xxh3 of its liveliness token); this process then prints the same.
"""


def gid_of(endpoint: Any) -> list[int]:
    """An endpoint's GID: its GID on the wire while a transport announces it, else 16 bytes unique in this process."""
    wire = wire_gids.get(endpoint)
    if wire is not None:
        return list(wire)
    return list(id(endpoint).to_bytes(8, "little")) + [0] * 8


def reported_profile(qos: Any) -> QoSProfile:
    """``qos`` (a profile or a snapshot) as a graph query reports it: a duration never set is rmw's infinite one."""
    profile = qos.to_profile() if isinstance(qos, QoSSnapshot) else copy.copy(qos)
    for name in ("lifespan", "deadline", "liveliness_lease_duration"):
        if not getattr(profile, name).nanoseconds:
            setattr(profile, name, Infinite)
    return profile
