"""Services over Zenoh: local servers as queryables, remote servers as stand-ins for local callers.

Serving.  Each local server declares a *complete* queryable on its data key
(and an ``SS`` token).  A query crosses to the loop, its request is decoded
and queued for the server as a local call would be; the reply carries the
response (CDR) and an attachment with the request's sequence number and the
client's GID, as rmw_zenoh's clients match replies by them; it leaves as the
server settles the call's future (:class:`_Answer`), with no loop round
between the handler and the wire.  A handler that
raises answers with a Zenoh error reply; a query that cannot be read is
answered with one too (and logged within the bounds of :mod:`.peer_warnings`).

Calling.  While a server of a service runs elsewhere (an ``SS`` token of a
type this process knows under the same hash) and none runs here, a
:class:`~actors.transport.seam.RemoteService` stands in the service table:
local clients wait for it, find it and call it as usual.  A call becomes a
Zenoh query (every complete queryable, no consolidation, our attachment);
the first reply settles the caller's future (the end of a query that was
answered is not handed to the loop: one wake-up less per call).  The caller never hangs on a
server that went away: Zenoh ends a query whose queryable's process stopped,
and when the last server's token is withdrawn the calls still waiting fail
with ServiceError at once.  Each local client holds an ``SC`` token.
"""

from __future__ import annotations

import asyncio
from typing import Any

from actors import codec
from actors.errors import ServiceError
from actors.ros.qos import QoSSnapshot
from actors.services import Client, Service, ServiceTable
from actors.transport.seam import RemoteService, submit
from actors.transport.zenoh.attachment import gid_of, pack, unpack
from actors.transport.zenoh.discovery import Discovery, local_hash
from actors.transport.zenoh.keys import Token, data_key
from actors.transport.zenoh.link import Endpoint, Link, peer_of

__all__ = ["ServiceBridge"]

_CALL_TIMEOUT = 24 * 3600.0  # seconds: a caller's own timeout is what ends a call; this only frees Zenoh's
_SERVICE_QOS = QoSSnapshot(depth=10)  # rmw's default service QoS (RELIABLE, VOLATILE, KEEP_LAST 10), as rclpy's


class _Served:
    """A local server on the wire."""

    __slots__ = ("service", "endpoint", "queryable")

    def __init__(self, service: Service, endpoint: Endpoint) -> None:
        self.service = service
        self.endpoint = endpoint
        self.queryable: Any = None


class _Call:
    """A call of ours on the wire: whether a reply came decides whether its end is news to the loop."""

    __slots__ = ("standin", "future", "replied")

    def __init__(self, standin: RemoteService, future: asyncio.Future[Any]) -> None:
        self.standin = standin
        self.future = future
        self.replied = False  # set on zenoh's thread


class _Answer(asyncio.Future[Any]):
    """The future of a query from elsewhere: settling it answers the query there and then.

    A done callback would answer one loop round after the handler, a hop
    that every service round trip across processes paid.
    """

    def __init__(self, link: Link, key: str, query: Any, sequence: int, gid: bytes) -> None:
        super().__init__(loop=link.loop)
        self._link = link
        self._key = key
        self._query = query
        self._sequence = sequence
        self._gid = gid

    def set_result(self, result: Any, /) -> None:
        super().set_result(result)
        try:
            payload = codec.encode_cdr(result)
        except Exception as exc:  # a response CDR cannot carry: the caller hears why, the server goes on
            self._link.logger.error(f"cannot send a response on {self._key}: {exc}")
            _finish(self._query, error=f"cannot encode the response: {exc}")
            return
        attachment = pack(self._sequence, self._link.now_ns(), self._gid)
        _finish(self._query, key=self._key, payload=payload, attachment=attachment)

    def set_exception(self, exception: type | BaseException, /) -> None:
        super().set_exception(exception)
        _finish(self._query, error=str(self.exception()))  # retrieved: the caller elsewhere hears it

    def cancel(self, msg: Any = None) -> bool:
        if not super().cancel(msg):
            return False
        _finish(self._query, error="the call was cancelled")
        return True


class ServiceBridge:
    """The service side of a Zenoh transport."""

    def __init__(self, link: Link, table: ServiceTable, discovery: Discovery) -> None:
        self._link = link
        self._table = table
        self._discovery = discovery
        self._served: dict[str, _Served] = {}
        self._clients: dict[Client, Endpoint] = {}
        self._standins: dict[str, RemoteService] = {}
        self._keys: dict[RemoteService, str] = {}
        self._calls: dict[RemoteService, set[asyncio.Future[Any]]] = {}
        self._gid = gid_of(f"{link.zid}/calls")  # our queries' client GID
        self._sequence = 0

    # -- serving --------------------------------------------------------------------

    def add_service(self, service: Service) -> None:
        """Serve ``service`` to other processes; a stand-in of the same name gives way."""
        name = service.service_name
        self._forget_standin(name)
        self._link.declare(
            service.node.fqn,
            "SS",
            name,
            service.srv_type,
            _SERVICE_QOS,
            lambda endpoint: self._serve(service, endpoint),
        )

    def _serve(self, service: Service, endpoint: Endpoint) -> None:
        # Before the token: a client that sees the server may call it at once.
        served = self._served[service.service_name] = _Served(service, endpoint)
        zenoh, handoff, handle = self._link.zenoh, self._link.handoff, self._handle
        served.queryable = self._link.session.declare_queryable(
            endpoint.key,
            zenoh.handlers.Callback(lambda query: handoff.put(handle, (served, query)), indirect=False),
            complete=True,
            allowed_origin=zenoh.Locality.REMOTE,
        )

    def _handle(self, item: tuple[_Served, Any]) -> None:
        served, query = item
        link = self._link
        if self._served.get(served.service.service_name) is not served:
            _finish(query, error="the service is gone")
            return
        origin = "?"
        try:
            raw = query.attachment
            if raw is None:
                raise ValueError("no attachment (a request needs its sequence number and client GID)")
            sequence, _, gid = unpack(raw.to_bytes())
            origin = gid.hex()
            payload = query.payload
            request = codec.decode_cdr(
                payload.to_bytes() if payload is not None else b"", served.service.srv_type.Request
            )
        except Exception as exc:  # anything a peer sends: answered with an error, logged within bounds
            link.warnings.warn(
                served.endpoint.key,
                peer_of(query),
                f"refused a malformed request on {served.endpoint.key} (client {origin}, as it says): {exc}",
            )
            _finish(query, error=f"malformed request: {exc}")
            return
        submit(served.service, request, _Answer(link, served.endpoint.key, query, sequence, gid))

    def remove_service(self, service: Service) -> None:
        """Stop serving ``service`` elsewhere; a server elsewhere may stand in for it again."""
        name = service.service_name
        served = self._served.get(name)
        if served is not None and served.service is service:
            del self._served[name]
            self._link.undeclare(served.queryable)
            self._link.withdraw(served.endpoint)
        self.refresh(name)

    # -- clients --------------------------------------------------------------------

    def add_client(self, client: Client) -> None:
        """Announce a local client (its ``SC`` token)."""
        endpoint = self._link.declare(client.node.fqn, "SC", client.service_name, client.srv_type, _SERVICE_QOS)
        if endpoint is not None:
            self._clients[client] = endpoint

    def remove_client(self, client: Client) -> None:
        """Withdraw a local client's token."""
        endpoint = self._clients.pop(client, None)
        if endpoint is not None:
            self._link.withdraw(endpoint)

    # -- calling servers elsewhere ----------------------------------------------------

    def remote_changed(self, token: Token) -> None:
        """A server's token came or went: stand in for the service, or stop."""
        if token.kind == "SS":
            self.refresh(token.name)

    def refresh(self, name: str) -> None:
        """Make the stand-in for ``name`` match the servers elsewhere (none while one runs here)."""
        local = self._table.servers.get(name)
        if local is not None and not local.remote:
            return
        servers = [t for t in self._discovery.tokens("SS", name) if Discovery.readable(t)[0]]
        standin = self._standins.get(name)
        if servers and standin is None:
            token = servers[0]
            cls, _ = local_hash(token.type)
            assert cls is not None  # readable
            standin = RemoteService(self._link.hub, name, cls, token.node, self._forward)
            self._standins[name] = standin
            self._keys[standin] = data_key(self._link.domain, name, token.type, token.type_hash)
            self._table.add(standin)
        elif not servers and standin is not None:
            self._forget_standin(name)
            self._table.remove(standin)
            self._fail_calls(standin, f"service {name} went away: its server {standin.provider} left")

    def _forget_standin(self, name: str) -> None:
        standin = self._standins.pop(name, None)
        if standin is not None:
            self._keys.pop(standin, None)

    def _forward(self, standin: RemoteService, request: Any, future: asyncio.Future[Any]) -> None:
        link = self._link
        key = self._keys.get(standin)
        if key is None:
            future.set_exception(ServiceError(f"service {standin.service_name} went away"))
            return
        try:
            payload = codec.encode_cdr(request)
        except Exception as exc:
            future.set_exception(ServiceError(f"cannot send the request to {standin.service_name}: {exc}"))
            return
        self._sequence += 1
        calls = self._calls.setdefault(standin, set())
        calls.add(future)
        future.add_done_callback(calls.discard)
        zenoh, handoff = link.zenoh, link.handoff
        call = _Call(standin, future)

        def replied(reply: Any) -> None:  # on zenoh's thread
            call.replied = True
            handoff.put(self._settle, (call, reply))

        def ended() -> None:  # on zenoh's thread, after the last reply: a call answered needs no more
            if not call.replied:
                handoff.put(self._ended, call)

        link.session.get(
            key,
            zenoh.handlers.Callback(replied, ended, indirect=False),
            payload=payload,
            attachment=pack(self._sequence, link.now_ns(), self._gid),
            target=zenoh.QueryTarget.ALL_COMPLETE,
            consolidation=zenoh.ConsolidationMode.NONE,
            timeout=_CALL_TIMEOUT,
            allowed_destination=zenoh.Locality.REMOTE,
        )

    def _settle(self, item: tuple[_Call, Any]) -> None:
        call, reply = item
        standin, future = call.standin, call.future
        if future.done():
            return  # answered already (several servers), timed out or cancelled
        name, provider = standin.service_name, standin.provider
        if reply.ok is None:
            text = reply.err.payload.to_bytes().decode(errors="replace")
            future.set_exception(ServiceError(f"service {name} on {provider} failed: {text}"))
            return
        try:
            future.set_result(codec.decode_cdr(reply.ok.payload.to_bytes(), standin.srv_type.Response))
        except Exception as exc:
            future.set_exception(ServiceError(f"service {name} on {provider} sent a malformed response: {exc}"))

    def _ended(self, call: _Call) -> None:
        standin, future = call.standin, call.future
        if not future.done():
            future.set_exception(
                ServiceError(
                    f"service {standin.service_name}: no answer from {standin.provider} (did its process stop?)"
                )
            )

    def _fail_calls(self, standin: RemoteService, reason: str) -> None:
        for future in list(self._calls.pop(standin, ())):
            if not future.done():
                future.set_exception(ServiceError(reason))

    def close(self) -> None:
        """Stop serving and calling (the session is about to close)."""
        for name in list(self._served):
            served = self._served.pop(name)
            self._link.undeclare(served.queryable)
            self._link.withdraw(served.endpoint)
        for client in list(self._clients):
            self.remove_client(client)
        for name, standin in list(self._standins.items()):
            self._forget_standin(name)
            self._table.remove(standin)
            self._fail_calls(standin, f"service {name}: the transport stopped")


def _finish(query: Any, *, error: str = "", key: str = "", payload: bytes = b"", attachment: bytes = b"") -> None:
    """Answer a query (a reply, or an error reply) and end it; a session already closed is fine."""
    try:
        if error:
            query.reply_err(error.encode())
        else:
            query.reply(key, payload, attachment=attachment)
    except Exception:
        pass
    finally:
        query.drop()
