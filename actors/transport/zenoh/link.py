"""What the topic and service bridges share: the session, the handoff, names and tokens, warnings.

One :class:`Link` per running transport.  It numbers entities as rmw_zenoh
does (one counter per session for nodes and endpoints alike), except that
the number of a withdrawn entity is given again (the lowest first): a graph
whose command-line sessions come and go then announces the same token names
again, where new ones would grow every Zenoh process that hears them (Zenoh
keeps state per name it ever heard of, upstream).  It holds the node
tokens (a node's ``NN`` token lives while the node has an endpoint on the
wire), and turns a local class into what the wire names it by.  Warnings
about what other processes send go through its :class:`~.peer_warnings.PeerWarnings`;
its own failures (a message it cannot encode) are logged once per endpoint.
"""

from __future__ import annotations

import asyncio
import functools
import heapq
from collections.abc import Callable
from typing import Any

from actors import codec
from actors.errors import ActorsError
from actors.ros.log import NodeLogger
from actors.ros.qos import QoSSnapshot
from actors.ros.topics import type_name
from actors.transport.seam import Hub
from actors.transport.zenoh.attachment import gid_of
from actors.transport.zenoh.handoff import Handoff
from actors.transport.zenoh.keys import data_key, endpoint_token, node_token
from actors.transport.zenoh.peer_warnings import PeerWarnings

__all__ = ["Link", "Endpoint", "wire_type", "peer_of", "shown"]

_SHOWN = 200  # characters of what a peer wrote quoted in a warning


@functools.lru_cache(maxsize=4096)
def wire_type(cls: type) -> tuple[str, str] | None:
    """``(ROS type name, RIHS01 hash)`` of a message or service class, or None if it has none."""
    try:
        return type_name(cls), codec.type_hash(cls)
    except (ActorsError, TypeError, ValueError):
        return None  # not a ROS interface (a test's own class): it stays in this process


class Endpoint:
    """An endpoint on the wire: its token, GID and data key, and the node it belongs to."""

    __slots__ = ("fqn", "entity", "token", "gid", "key")

    def __init__(self, fqn: str, entity: int, token: Any, gid: bytes, key: str) -> None:
        self.fqn = fqn
        self.entity = entity
        self.token = token
        self.gid = gid
        self.key = key


class Link:
    """A transport's session and bookkeeping, shared by its bridges."""

    def __init__(
        self,
        zenoh: Any,
        session: Any,
        domain: int,
        hub: Hub,
        handoff: Handoff,
        clock_ns: Any,
        logger: NodeLogger,
    ) -> None:
        self.zenoh = zenoh
        self.session = session
        self.domain = domain
        self.zid = str(session.info.zid())
        self.hub = hub
        self.handoff = handoff
        self.now_ns = clock_ns  # wall-clock nanoseconds: source timestamps on the wire
        self.logger = logger
        self.loop: asyncio.AbstractEventLoop = hub.loop
        self._next_id = 0
        self._free_ids: list[int] = []  # a heap of withdrawn entities' ids
        self._nodes: dict[str, tuple[int, Any, int]] = {}  # fqn -> (node id, token, endpoints)
        self._warned: set[tuple[str, str]] = set()  # our own failures: bounded by our endpoints
        self.warnings = PeerWarnings(logger.warning, self.loop.call_later)

    def next_id(self) -> int:
        """The next entity id of this session: the lowest withdrawn one, else a new one."""
        if self._free_ids:
            return heapq.heappop(self._free_ids)
        entity = self._next_id
        self._next_id += 1
        return entity

    def declare(
        self,
        fqn: str,
        kind: str,
        name: str,
        cls: type,
        qos: QoSSnapshot,
        ready: Callable[[Endpoint], object] | None = None,
    ) -> Endpoint | None:
        """Declare the token of an endpoint (``kind`` MP, MS, SS or SC); None for a non-ROS type.

        ``ready(endpoint)`` runs before the token is declared: a peer that sees
        the token may use what it announces at once (call a server), as
        rmw_zenoh declares the queryable before the token.
        """
        wire = wire_type(cls)
        if wire is None:
            return None
        ros_type, hash_ = wire
        node_id = self._node_up(fqn)
        entity = self.next_id()
        key = endpoint_token(self.domain, self.zid, node_id, entity, kind, fqn, name, ros_type, hash_, qos)
        endpoint = Endpoint(fqn, entity, None, gid_of(key), data_key(self.domain, name, ros_type, hash_))
        if ready is not None:
            ready(endpoint)
        endpoint.token = self.session.liveliness().declare_token(key)
        return endpoint

    def withdraw(self, endpoint: Endpoint) -> None:
        """Undeclare an endpoint's token (and its node's, with the node's last endpoint)."""
        self.undeclare(endpoint.token)
        heapq.heappush(self._free_ids, endpoint.entity)
        self._node_down(endpoint.fqn)

    def _node_up(self, fqn: str) -> int:
        entry = self._nodes.get(fqn)
        if entry is None:
            node_id = self.next_id()
            token = self.session.liveliness().declare_token(node_token(self.domain, self.zid, node_id, fqn))
            entry = (node_id, token, 0)
        self._nodes[fqn] = (entry[0], entry[1], entry[2] + 1)
        return entry[0]

    def _node_down(self, fqn: str) -> None:
        node_id, token, count = self._nodes[fqn]
        if count > 1:
            self._nodes[fqn] = (node_id, token, count - 1)
        else:
            del self._nodes[fqn]
            self.undeclare(token)
            heapq.heappush(self._free_ids, node_id)

    def undeclare(self, entity: Any) -> None:
        """Undeclare a Zenoh entity; one that is already gone (a closed session) is fine."""
        try:
            entity.undeclare()
        except Exception:
            pass

    def warn_once(self, key: str, origin: str, text: str) -> None:
        """Log ``text`` once per key expression of ours and ``origin`` (what of ours failed)."""
        if (key, origin) in self._warned:
            return
        self._warned.add((key, origin))
        self.logger.warning(text)


def peer_of(received: Any) -> str:
    """The Zenoh id of the session a sample or query came from, where Zenoh tells it; else ``""``."""
    info = received.source_info
    return "" if info is None else str(info.source_id.zid)


def shown(text: str) -> str:
    """What a peer wrote (a key expression, or an error quoting one), cut short for a log line."""
    return text if len(text) <= _SHOWN else f"{text[:_SHOWN]}... ({len(text)} characters)"
