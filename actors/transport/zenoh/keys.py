"""rmw_zenoh's names on the wire: data key expressions, liveliness tokens, QoS strings, type names.

These follow rmw_zenoh_cpp (Jazzy, Kilted, Rolling) to the byte, so that a
ROS 2 process running ``RMW_IMPLEMENTATION=rmw_zenoh_cpp`` and an actors
process see each other's endpoints and data:

- a topic's or service's data lives on ``<domain>/<name without leading
  slash>/<pkg>::msg::dds_::<Type>_/<RIHS01 hash>`` (``::srv::`` and the
  service type for services);
- every node and endpoint holds a liveliness token
  ``@ros2_lv/<domain>/<zid>/<node id>/<entity id>/<kind>/<enclave>/<namespace>/<node>``
  followed, for endpoints, by ``/<name>/<type>/<hash>/<qos>``; ``kind`` is NN,
  MP, MS, SS or SC, slashes inside a part are written ``%`` (an empty
  namespace is ``%``), and a node's entity id is its node id;
- the QoS string is ``reliability:durability:history,depth:deadline:lifespan:liveliness``,
  each number left empty where it equals rmw_zenoh's default (RELIABLE,
  VOLATILE, KEEP_LAST 42, infinite durations, AUTOMATIC liveliness).

Nothing here imports zenoh: these are plain strings, pinned by tests.
"""

from __future__ import annotations

from typing import Any

import msgspec

from actors.ros.qos import DurabilityPolicy, HistoryPolicy, LivelinessPolicy, QoSSnapshot, ReliabilityPolicy

__all__ = [
    "ADMIN_SPACE",
    "KINDS",
    "Token",
    "dds_type_name",
    "ros_type_name",
    "data_key",
    "mangle",
    "demangle",
    "qos_string",
    "parse_qos",
    "node_token",
    "endpoint_token",
    "parse_token",
    "graph_key",
]

ADMIN_SPACE = "@ros2_lv"
KINDS = {"NN": "node", "MP": "publisher", "MS": "subscription", "SS": "server", "SC": "client"}
"""Token kinds and what they stand for."""

_DEFAULT_DEPTH = 42  # rmw_zenoh's depth for a KEEP_LAST profile that gives none
_INFINITE = (9223372036, 854775807)  # RMW_DURATION_INFINITE as (sec, nsec)
_NS = 1_000_000_000


def dds_type_name(ros_type: str) -> str:
    """``std_msgs/msg/String`` -> ``std_msgs::msg::dds_::String_`` (services: ``pkg/srv/Name``)."""
    pkg, kind, name = ros_type.split("/")
    return f"{pkg}::{kind}::dds_::{name}_"


def ros_type_name(dds_type: str) -> str:
    """``std_msgs::msg::dds_::String_`` -> ``std_msgs/msg/String``; ValueError for another shape."""
    parts = dds_type.split("::")
    if len(parts) != 4 or parts[2] != "dds_" or not parts[3].endswith("_") or len(parts[3]) < 2:
        raise ValueError(f"not a ROS type on the wire: {dds_type!r}")
    return f"{parts[0]}/{parts[1]}/{parts[3][:-1]}"


def data_key(domain: int, name: str, ros_type: str, type_hash: str) -> str:
    """The key expression a topic's samples (or a service's queries) travel on."""
    return f"{domain}/{name.strip('/')}/{dds_type_name(ros_type)}/{type_hash}"


def mangle(name: str) -> str:
    """A name as one key part: ``/`` becomes ``%`` (``/`` alone is ``%``)."""
    return name.replace("/", "%")


def demangle(part: str) -> str:
    """The name a key part stands for."""
    return part.replace("%", "/")


def _duration(ns: int) -> str:
    # rmw's "default" durations are infinite; 0 here means unset, which rmw_zenoh makes infinite.
    if not ns:
        return ","
    sec, nsec = divmod(ns, _NS)
    return f"{sec},{nsec}" if (sec, nsec) != _INFINITE else ","


def qos_string(qos: QoSSnapshot) -> str:
    """The QoS part of an endpoint's token, as rmw_zenoh writes it."""
    reliability = "" if qos.reliability == ReliabilityPolicy.RELIABLE else str(int(qos.reliability))
    durability = "" if qos.durability == DurabilityPolicy.VOLATILE else str(int(qos.durability))
    history = "" if qos.history == HistoryPolicy.KEEP_LAST else str(int(qos.history))
    # rmw_zenoh gives KEEP_ALL (depth 0 in rclpy) its default depth, which then reads as empty.
    depth = "" if qos.history == HistoryPolicy.KEEP_ALL or qos.depth == _DEFAULT_DEPTH else str(qos.depth)
    liveliness = "" if qos.liveliness == LivelinessPolicy.AUTOMATIC else str(int(qos.liveliness))
    return (
        f"{reliability}:{durability}:{history},{depth}:{_duration(qos.deadline_ns)}:"
        f"{_duration(qos.lifespan_ns)}:{liveliness},{_duration(qos.liveliness_lease_duration_ns)}"
    )


def _parse_duration(part: str) -> int:
    sec, _, nsec = part.partition(",")
    if not sec and not nsec:
        return 0
    pair = (int(sec) if sec else _INFINITE[0], int(nsec) if nsec else _INFINITE[1])
    return 0 if pair == _INFINITE else pair[0] * _NS + pair[1]


def parse_qos(text: str) -> QoSSnapshot:
    """The QoS a token's QoS part stands for; ValueError when it is not one."""
    parts = text.split(":")
    if len(parts) != 6 or parts[2].count(",") != 1 or parts[5].count(",") != 2:
        raise ValueError(f"not an rmw_zenoh QoS string: {text!r}")
    try:
        history_part, _, depth = parts[2].partition(",")
        history = HistoryPolicy(int(history_part)) if history_part else HistoryPolicy.KEEP_LAST
        kind, _, lease = parts[5].partition(",")
        return QoSSnapshot(
            reliability=ReliabilityPolicy(int(parts[0])) if parts[0] else ReliabilityPolicy.RELIABLE,
            durability=DurabilityPolicy(int(parts[1])) if parts[1] else DurabilityPolicy.VOLATILE,
            history=history,
            depth=int(depth) if depth else _DEFAULT_DEPTH,
            deadline_ns=_parse_duration(parts[3]),
            lifespan_ns=_parse_duration(parts[4]),
            liveliness=LivelinessPolicy(int(kind)) if kind else LivelinessPolicy.AUTOMATIC,
            liveliness_lease_duration_ns=_parse_duration(lease),
        )
    except ValueError:
        raise ValueError(f"not an rmw_zenoh QoS string: {text!r}") from None


def graph_key(domain: int) -> str:
    """Every liveliness token of a domain: what a graph cache subscribes to."""
    return f"{ADMIN_SPACE}/{domain}/**"


def _split(fqn: str) -> tuple[str, str]:
    namespace, _, name = fqn.rpartition("/")
    return namespace or "/", name


def node_token(domain: int, zid: str, node_id: int, fqn: str, enclave: str = "/") -> str:
    """A node's liveliness token (``fqn`` is ``/namespace/name``)."""
    namespace, name = _split(fqn)
    return f"{ADMIN_SPACE}/{domain}/{zid}/{node_id}/{node_id}/NN/{mangle(enclave)}/{mangle(namespace)}/{name}"


def endpoint_token(
    domain: int,
    zid: str,
    node_id: int,
    entity_id: int,
    kind: str,
    fqn: str,
    name: str,
    ros_type: str,
    type_hash: str,
    qos: QoSSnapshot,
    enclave: str = "/",
) -> str:
    """An endpoint's liveliness token: ``kind`` is MP, MS, SS or SC, ``ros_type`` a message or service type."""
    namespace, node = _split(fqn)
    return (
        f"{ADMIN_SPACE}/{domain}/{zid}/{node_id}/{entity_id}/{kind}/{mangle(enclave)}/{mangle(namespace)}/"
        f"{node}/{mangle(name)}/{dds_type_name(ros_type)}/{type_hash}/{qos_string(qos)}"
    )


class Token(msgspec.Struct, frozen=True, kw_only=True):
    """What a liveliness token says: who (process, node, entity) and, for an endpoint, what."""

    domain: int
    zid: str
    node_id: str
    entity_id: str
    kind: str  # NN, MP, MS, SS or SC
    node: str  # the node's full name
    name: str = ""
    type: str = ""  # the ROS type name
    type_hash: str = ""
    qos: QoSSnapshot | None = None


def parse_token(key: str) -> Token:
    """The token a key expression stands for; ValueError naming what is wrong with it."""
    parts = key.split("/")
    if len(parts) < 9 or parts[0] != ADMIN_SPACE:
        raise ValueError(f"not an rmw_zenoh liveliness token: {key!r}")
    if any(not part for part in parts):
        raise ValueError(f"liveliness token with an empty part: {key!r}")
    kind = parts[5]
    if kind not in KINDS:
        raise ValueError(f"liveliness token of unknown kind {kind!r}: {key!r}")
    try:
        domain = int(parts[1])
    except ValueError:
        raise ValueError(f"liveliness token with a domain that is not a number: {key!r}") from None
    namespace = demangle(parts[7])
    node = f"{namespace.rstrip('/')}/{parts[8]}"
    common: dict[str, Any] = {
        "domain": domain,
        "zid": parts[2],
        "node_id": parts[3],
        "entity_id": parts[4],
        "kind": kind,
        "node": node,
    }
    if kind == "NN":
        if len(parts) != 9:
            raise ValueError(f"node token with {len(parts)} parts, expected 9: {key!r}")
        return Token(**common)
    if len(parts) != 13:
        raise ValueError(f"endpoint token with {len(parts)} parts, expected 13: {key!r}")
    return Token(
        **common,
        name=demangle(parts[9]),
        type=ros_type_name(parts[10]),
        type_hash=parts[11],
        qos=parse_qos(parts[12]),
    )
