"""The graph of other processes, as their liveliness tokens tell it.

Every rmw_zenoh process (and every actors graph with the Zenoh transport)
holds one liveliness token per node and per endpoint; Zenoh withdraws them
when the process stops, however it stops.  :class:`Discovery` keeps the
tokens of other processes (``put`` when one appears, ``delete`` when it
goes), and answers what is where: the nodes (:meth:`remote_nodes`), and the
servers of a service.  It lives on the event loop: the transport hands it
Zenoh's callbacks through its handoff.

Each endpoint is checked against this process's types: an endpoint whose
type is unknown here, or known under another RIHS01 hash, cannot be read or
written; it is shown with ``known=False`` and the reason (doctor reports it),
and the transport leaves its data alone.

Bounded.  It keeps at most :data:`MAX_FOREIGN_TOKENS` tokens: any peer that
reaches the port may declare tokens, and each kept costs memory and a place
in every answer.  A token beyond the limit is ignored (counted in
``ignored``, said to ``on_ignored``, reported by doctor) until it is withdrawn;
one that comes while there is room again is kept.  Zenoh's own liveliness
state is not ours to bound: a bare Zenoh session subscribed to the same
tokens grows as much (about 3 KB per token held, not all given back when they
go), upstream.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from actors import codec
from actors.errors import ActorsError
from actors.transport.seam import RemoteEndpoint, RemoteNode
from actors.transport.zenoh.attachment import gid_of
from actors.transport.zenoh.keys import KINDS, Token, parse_token

__all__ = ["Discovery", "MAX_FOREIGN_TOKENS", "local_hash"]

MAX_FOREIGN_TOKENS = 10_000
"""Liveliness tokens of other processes kept at most: about 1,000 rclpy nodes, at about ten each
(the node's own, its parameter services', /rosout's and /parameter_events')."""


def local_hash(ros_type: str) -> tuple[type[Any] | None, str]:
    """This process's class and RIHS01 hash for ``ros_type``, or ``(None, why not)``."""
    try:
        cls = codec.get_type(ros_type)
        return cls, codec.type_hash(cls)
    except (ActorsError, TypeError, ValueError) as exc:
        return None, f"{ros_type} is not known in this process ({exc})"


class Discovery:
    """Tokens of other processes, by key; ``on_change(token, appeared)`` hears each change."""

    def __init__(
        self, own_zid: str, on_change: Callable[[Token, bool], None], on_ignored: Callable[[str, str], None]
    ) -> None:
        self._own = own_zid
        self._tokens: dict[str, Token] = {}
        self._on_change = on_change
        self._on_ignored = on_ignored  # (kind of reason, why): a token ignored
        self.limit = MAX_FOREIGN_TOKENS
        self.ignored = 0  # tokens ignored for want of room, since the start

    def put(self, key: str) -> None:
        """A token appeared (or was there when we asked)."""
        if key in self._tokens:
            return  # the initial query and the subscription may both report it
        try:
            token = parse_token(key)
        except ValueError as exc:
            self._on_ignored("not rmw_zenoh's", str(exc))
            return
        if token.zid == self._own:
            return
        if len(self._tokens) >= self.limit:
            self.ignored += 1
            self._on_ignored("over the limit", f"{key}: at most {self.limit} tokens of other processes are kept")
            return
        self._tokens[key] = token
        self._on_change(token, True)

    def delete(self, key: str) -> None:
        """A token was withdrawn (its entity or its whole process went away)."""
        token = self._tokens.pop(key, None)
        if token is not None:
            self._on_change(token, False)

    def tokens(self, kind: str, name: str) -> list[Token]:
        """The tokens of ``kind`` (MP, MS, SS, SC) on topic or service ``name``."""
        return [t for t in self._tokens.values() if t.kind == kind and t.name == name]

    def remote_nodes(self) -> list[RemoteNode]:
        """Every node of other processes, sorted by name (a node with endpoints but no token too)."""
        nodes: dict[tuple[str, str], list[RemoteEndpoint]] = {}
        for key, token in self._tokens.items():
            endpoints = nodes.setdefault((token.node, token.zid), [])
            if token.kind == "NN":
                continue
            known, why = self.readable(token)
            assert token.qos is not None
            endpoints.append(
                RemoteEndpoint(
                    kind=KINDS[token.kind],
                    name=token.name,
                    type=token.type,
                    type_hash=token.type_hash,
                    qos=token.qos,
                    known=known,
                    why=why,
                    gid=gid_of(key),
                )
            )
        return [
            RemoteNode(name=name, process=zid, endpoints=tuple(sorted(ends, key=lambda e: (e.kind, e.name))))
            for (name, zid), ends in sorted(nodes.items())
        ]

    @staticmethod
    def readable(token: Token) -> tuple[bool, str]:
        """Whether this process can read and write what ``token``'s endpoint carries, and why not."""
        cls, found = local_hash(token.type)
        if cls is None:
            return False, found
        if found != token.type_hash:
            return False, f"{token.type} is {found} here, {token.type_hash} there: its data is ignored"
        return True, ""
