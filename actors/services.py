"""Services: servers as node entities, clients with request/response futures.

A call puts ``(request, future)`` in the server's queue and wakes the server's
node; the server's handler runs in that node's task, one request at a time,
and its response resolves the future directly — never through the caller's
mailbox — so awaiting a call from inside a callback cannot deadlock.

- An exception in the handler reaches the caller as ServiceError carrying the
  server's error; the server keeps serving (it is logged on the server's side).
- A call to a service that does not exist yet waits for it to appear; with a
  timeout it raises TimeoutError.  While a server's node restarts its queue
  stays attached, and the new instance answers what was queued.
- A timeout is an entry in the runtime's :class:`CallTimeouts` (a lane per
  timeout value under one loop timer) that fails the caller's future: a cancel
  scope per call (``anyio.fail_after``) cost more than the round trip itself,
  and a loop timer per call (``loop.call_at``) about as much.
- A node calling its own service gets ServiceError at once: its callbacks run
  one at a time, so the request could never be handled while it waits.
- A cancelled or timed-out caller does not disturb the server: the response is
  simply dropped.
- Requests and responses go through the publish-time snapshot
  (:mod:`actors.messages._copy`): the server sees the request as it was when the
  call was made, the caller the response as the handler returned it, and a
  field of the wrong type fails the call naming the field (in ``call_async``
  for a request, as ServiceError for a response).  A response that nobody else
  holds when a plain handler returns it (``sys.getrefcount``) is checked in
  place (:func:`actors.messages._copy.adopter`) instead of copied.
"""

from __future__ import annotations

import asyncio
from asyncio import InvalidStateError
from collections import deque
from collections.abc import Awaitable, Callable, Iterator, Mapping
from functools import partial
from heapq import heappop, heappush
from inspect import isawaitable
from sys import getrefcount
from typing import Any, Protocol

from actors.core._actor import Mailbox, Owner
from actors.core.loops import VirtualTimeLoop, loop_clock
from actors.errors import ServiceError
from actors.messages._copy import ALONE, adopter, snapshotter
from actors.ros.topics import type_name

__all__ = ["Service", "Client", "CallTimeouts", "ServiceListener", "Deferred", "ServiceTable"]


#: A request waiting for its server, and the caller's future: a plain tuple, made once per
#: call (half the cost of a two-field msgspec Struct to make).
_Call = tuple[Any, "asyncio.Future[Any]"]


_SRV_TYPES: set[type] = set()  # types that passed the check: every node makes six parameter services


def _check_srv_type(srv_type: Any, where: str) -> None:
    if srv_type in _SRV_TYPES:
        return
    if not (isinstance(srv_type, type) and hasattr(srv_type, "Request") and hasattr(srv_type, "Response")):
        raise TypeError(f"{where} needs a service type (with .Request and .Response), got {srv_type!r}")
    _SRV_TYPES.add(srv_type)


class Service(Mailbox):
    """A service server.  Create with ``Node.create_service``."""

    __slots__ = (
        "node",
        "service_name",
        "srv_type",
        "handler",
        "handled",
        "_listed",
        "_response_type",
        "_snapshot",
        "_adopt_response",
    )
    remote = False  # a transport's stand-in for a server elsewhere, which a local server replaces

    def __init__(self, node: Owner, service_name: str, srv_type: type[Any], handler: Callable[..., Any]) -> None:
        _check_srv_type(srv_type, "create_service")
        if not callable(handler):
            raise TypeError(f"service handler must be callable, got {handler!r}")
        self.node = node
        self.service_name = service_name
        self.srv_type = srv_type
        self.handler = handler
        self.handled = 0
        # Whether the ServiceTable lists this server under its name now (kept by the table): a
        # client that found it calls it again without a lookup while it stays listed.
        self._listed = False
        # Read per round from a slot: ``srv_type.Response``, an attribute of a class, is a lookup
        # CPython 3.11 does not specialise.
        self._response_type = srv_type.Response
        self._snapshot = snapshotter(srv_type.Response)
        # A response nobody else holds (the handler filled the one it was given, or made
        # one, and kept no reference) is checked in place: the caller gets it, not a copy.
        self._adopt_response = adopter(srv_type.Response)
        # The queue is made on the first call: most services (every node's parameter
        # services) are never called, and an empty deque costs 760 bytes.
        super().__init__(node.actor)

    def _push(self, call: _Call) -> None:
        queue = self._queue
        if queue is None:
            queue = self._queue = deque()
        queue.append(call)
        if not self._scheduled:  # Mailbox._wake, inlined: once per call
            self._scheduled = True
            self._actor.schedule(self)

    def _adopt(self, old: Mailbox) -> None:
        # A restarted server answers what was queued for its predecessor.
        assert isinstance(old, Service)
        self.handled = old.handled
        super()._adopt(old)

    def _run(self) -> Awaitable[None] | None:
        queue = self._queue
        assert queue is not None  # scheduled only by _push or _adopt, with calls queued
        handler, snapshot, adopt = self.handler, self._snapshot, self._adopt_response
        response_type = self._response_type
        # The calls queued when the round began, up to the last of them (each call is a tuple of
        # its own): an identity test per call, no counter, and no range made for a lone call.
        # None when there is none: destroying the server empties its queue, not its actor's line.
        last = queue[-1] if queue else None
        call = None
        while call is not last:
            call = queue.popleft()
            request, future = call
            if future.done():
                continue  # the caller gave up
            # _answer, inlined for a plain handler: with 100 callers this loop is the server's whole cost.
            try:
                response = handler(request, response_type())
                if type(response) is not response_type:
                    if isawaitable(response):
                        return self._run_async(response, call, last)
                    self._wrong(response)
                response = (adopt if getrefcount(response) == ALONE else snapshot)(response)
            except Exception as exc:
                self._fail(call, exc)
                continue
            self.handled += 1
            try:
                future.set_result(response)
            except InvalidStateError:  # the handler cancelled its caller's task
                pass
        # Mailbox._round_done, inlined (as Subscription._run does): one call less per round.
        if queue:
            self._actor.schedule(self)
        else:
            self._scheduled = False
        return None

    async def _run_async(self, pending: Awaitable[Any], call: _Call, last: _Call | None) -> None:
        # An async handler: await its response, then serve the calls still due this round, up to ``last``.
        try:
            self._answer(call, await pending)
        except Exception as exc:
            self._fail(call, exc)
        response_type = self._response_type
        queue = self._queue
        assert queue is not None
        while call is not last:
            call = queue.popleft()
            request, future = call
            if future.done():
                continue
            try:
                response = self.handler(request, response_type())
                if type(response) is not response_type and isawaitable(response):
                    response = await response
                self._answer(call, response)
            except Exception as exc:
                self._fail(call, exc)
        self._round_done()

    def _wrong(self, response: Any) -> None:
        raise TypeError(f"handler returned {type_name(type(response))}, expected {type_name(self.srv_type.Response)}")

    def _answer(self, call: _Call, response: Any) -> None:
        if type(response) is not self._response_type:
            self._wrong(response)
        response = self._snapshot(response)  # copied: the frame that awaited it may hold it too
        self.handled += 1
        future = call[1]
        if not future.done():
            future.set_result(response)

    def _fail(self, call: _Call, exc: Exception) -> None:
        self.node.logger.error(f"service handler of {self.service_name} raised {exc!r}", exc_info=exc)
        future = call[1]
        if not future.done():
            future.set_exception(ServiceError(f"service {self.service_name} on {self.node.fqn} raised {exc!r}"))

    def destroy(self) -> None:
        """Stop serving; queued calls fail with ServiceError."""
        self.node.destroy_service(self)


class Client:
    """A service client.  Create with ``Node.create_client``."""

    __slots__ = (
        "node",
        "service_name",
        "srv_type",
        "_request_type",
        "_table",
        "_loop",
        "_snapshot",
        "_new_future",
        "_server",
    )

    def __init__(self, node: Owner, service_name: str, srv_type: type[Any], table: ServiceTable) -> None:
        _check_srv_type(srv_type, "create_client")
        table.want(service_name)
        self.node = node
        self.service_name = service_name
        self.srv_type = srv_type
        self._request_type = srv_type.Request
        self._table = table
        self._loop = loop = node.loop
        # Functions held in slots, read into locals before a call: CPython 3.11 leaves
        # ``self._snapshot(request)`` (a method call on a slot) unspecialised.
        self._snapshot = snapshotter(srv_type.Request)
        # asyncio's loops make a future through a Python method (create_future); made
        # directly it costs a fifth less.  Other loops (uvloop) make their own.
        self._new_future: Callable[[], asyncio.Future[Any]] = (
            partial(asyncio.Future, loop=loop)
            if type(loop).create_future is asyncio.BaseEventLoop.create_future
            else loop.create_future
        )
        # The server the last lookup found, used while the table still lists it (``Service._listed``):
        # calls skip the lookup by name and the own-service check (it is never this node's own).  A
        # server removed or replaced is kept from the collector until this client's next call.
        self._server: Service | None = None

    def service_is_ready(self) -> bool:
        """Whether a server for this service exists now."""
        return self.service_name in self._table.servers

    async def wait_for_service(self, timeout: float | None = None, *, timeout_sec: float | None = None) -> bool:
        """Wait until the service exists; False if ``timeout`` seconds pass first.

        ``timeout_sec`` is rclpy's spelling of ``timeout``.  Cancelling the wait
        cancels only the wait.
        """
        if timeout is None:
            timeout = timeout_sec
        loop = self._loop
        deadline = None if timeout is None else loop.time() + timeout
        while not self.service_is_ready():
            if not await self._table.appearance(self.service_name, deadline):
                return False
        return True

    def call_async(self, request: Any) -> asyncio.Future[Any]:
        """Send ``request``; return a future of the response.

        Raises TypeError for a request of the wrong type,
        MessageValidationError for a field that does not fit, and ServiceError
        when a node calls its own service.  The server receives the request as
        it is now (the caller may reuse the object).  The future fails with
        ServiceError when the server's handler raises.
        """
        if type(request) is not self._request_type:
            self._refuse(request)
        snapshot, new_future = self._snapshot, self._new_future  # locals: see __init__
        request = snapshot(request)
        future = new_future()
        self._send(request, future)
        return future

    def _send(self, request: Any, future: asyncio.Future[Any]) -> None:
        # Queue the call for the server listed now (remembered for the next calls), or park it
        # until one appears; ServiceError if the server is this node's own.
        server = self._server
        if server is None or not server._listed:
            server = self._table.servers.get(self.service_name)
            # Only a node whose callbacks run one at a time is refused (NodeCore.answers_own_calls).
            if server is not None and server.node is self.node and not getattr(self.node, "answers_own_calls", False):
                self._refuse_own(server)
            self._server = server
        if server is not None:
            server._push((request, future))
        else:
            self._table.park(self.service_name, (request, future))

    def _refuse(self, request: Any) -> None:
        raise TypeError(
            f"client of {self.service_name} takes {type_name(self.srv_type.Request)}, got {type_name(type(request))}"
        )

    def _refuse_own(self, server: Service) -> None:
        raise ServiceError(
            f"node {self.node.fqn} calls its own service {self.service_name}: its callbacks "
            f"run one at a time, so the call would wait forever; call the handler directly"
        )

    async def call(self, request: Any, timeout: float | None = None) -> Any:
        """Send ``request`` and wait for the response.

        Raises TimeoutError after ``timeout`` seconds (the request is then
        dropped unanswered: a server that has not started it skips it, a
        response that comes later is discarded), ServiceError when the server's
        handler raises or the node calls its own service, TypeError for a
        request of the wrong type.  Cancelling the call does not disturb the server.
        """
        # call_async's steps, inlined: its frame cost 4-6 % of a call with 100 callers
        # (1.108x -> 1.040x the bare future+Queue, medians of minimums, CPU time).
        if type(request) is not self._request_type:
            self._refuse(request)
        snapshot, new_future = self._snapshot, self._new_future  # locals: see __init__
        request = snapshot(request)
        future = new_future()
        server = self._server
        if server is None or not server._listed:
            self._send(request, future)  # the lookup by name
        elif server._scheduled:
            # _push's common case with many callers: the server is already due to run, so its
            # queue exists (a remote stand-in forwards in its own _push and is never scheduled).
            server._queue.append((request, future))
        else:
            server._push((request, future))
        if timeout is not None:
            (self._table._timeouts or self._table.timeouts(self._loop)).add(future, self, timeout)
        return await future

    def destroy(self) -> None:
        """Forget this client."""
        self.node.destroy_client(self)


class CallTimeouts:
    """The deadlines of a runtime's calls with a timeout: a lane per timeout value, under one loop timer.

    A loop timer per call (``loop.call_at``, then ``cancel()`` when the answer
    came first) cost as much as the round trip itself with 100 callers: a
    ``TimerHandle`` each, pushed into and later swept out of asyncio's heap with
    comparisons in Python.  Calls with the same timeout time out in the order
    they were made, so each timeout value has a lane, a deque of ``(deadline,
    future, client)`` in deadline order: a call appends one tuple, nothing is
    compared, and nothing is done when it is answered, not even counted.  An
    answered entry is dropped when the timer comes to it, or when a lane sweeps
    its answered entries out, once they are most of it.  A heap holds one entry
    per lane, its head's deadline (or an earlier one), and the loop timer is
    armed for the earliest: so a program whose calls share a few timeouts pays
    for a heap only when a lane is made.  The timer is kept when every call has
    been answered (it wakes once for nothing, or is re-armed then for the next
    head): a caller that calls one request after another arms one loop timer per
    ``timeout`` seconds, not one per call.
    """

    __slots__ = ("_loop", "_time", "_lanes", "_heads", "_handle", "_armed")

    def __init__(self, loop: asyncio.AbstractEventLoop) -> None:
        self._loop = loop
        self._time = loop_clock(loop)
        self._lanes: dict[float, _Lane] = {}  # by timeout
        self._heads: list[tuple[float, float]] = []  # (a lane's first deadline or earlier, its timeout), a heap
        self._handle: asyncio.TimerHandle | None = None
        self._armed = _NEVER  # the deadline the loop timer is set for

    def add(self, future: asyncio.Future[Any], client: Client, timeout: float) -> None:
        """Fail ``future`` with TimeoutError ``timeout`` seconds from now unless it is done by then."""
        clock = self._time  # a local: CPython 3.11 leaves a method call on a slot unspecialised
        when = clock() + timeout
        lane = self._lanes.get(timeout)
        if lane is None:
            lane = self._lanes[timeout] = _Lane()
            heappush(self._heads, (when, timeout))
            if when < self._armed:  # an existing lane's deadlines come after its head's
                self._arm(when)
        lane.append((when, future, client))
        if len(lane) > lane.sweep_at:
            lane.sweep()

    def _arm(self, when: float) -> None:
        if self._handle is not None:
            self._handle.cancel()
        self._handle = self._loop.call_at(when, self._fire)
        self._armed = when

    def _fire(self) -> None:
        self._handle = None
        self._armed = _NEVER
        heads = self._heads
        now = self._time()
        while heads and heads[0][0] <= now:
            timeout = heappop(heads)[1]
            lane = self._lanes[timeout]
            while lane and (lane[0][0] <= now or lane[0][1].done()):
                _, future, client = lane.popleft()
                if not future.done():
                    future.set_exception(
                        TimeoutError(f"no response from service {client.service_name} within {timeout:g} s")
                    )
            if lane:
                heappush(heads, (lane[0][0], timeout))
            else:
                del self._lanes[timeout]
        if heads:
            self._arm(heads[0][0])


class _Lane(deque):
    """The calls of one timeout value, in deadline order: ``(deadline, future, client)``."""

    __slots__ = ("sweep_at",)

    def __init__(self) -> None:
        super().__init__()
        self.sweep_at = _SWEEP_AT  # the length that calls for the next sweep

    def sweep(self) -> None:
        """Drop the answered entries; the next sweep once as many more came as were kept, and 64.

        Each entry is then looked at about twice in all, however many calls wait.
        """
        kept = [entry for entry in self if not entry[1].done()]
        self.clear()
        self.extend(kept)
        self.sweep_at = 2 * len(kept) + _SWEEP_AT


class _VirtualCallTimeouts(CallTimeouts):
    """Virtual time's call deadlines: the loop timer is cancelled as soon as no call waits.

    Virtual time jumps to the next loop timer whenever nothing else is ready: a
    timer left for a deadline nobody waits for would move the clock for nothing.
    So each call's end is heard (a done callback, which the wall clock's calls
    do without) and counted.
    """

    __slots__ = ("_waiting",)

    def __init__(self, loop: asyncio.AbstractEventLoop) -> None:
        super().__init__(loop)
        self._waiting = 0  # calls added and not yet answered, timed out or cancelled

    def add(self, future: asyncio.Future[Any], client: Client, timeout: float) -> None:
        super().add(future, client, timeout)
        self._waiting += 1
        future.add_done_callback(self._settled)

    def _settled(self, future: asyncio.Future[Any]) -> None:
        self._waiting -= 1
        if not self._waiting:
            self._lanes.clear()
            self._heads.clear()
            if self._handle is not None:
                self._handle.cancel()
                self._handle = None
                self._armed = _NEVER


_NEVER = float("inf")
_SWEEP_AT = 64  # entries a lane may gain beyond twice those its last sweep kept


def _settle(future: asyncio.Future[bool], value: bool) -> None:
    if not future.done():
        future.set_result(value)


class ServiceListener(Protocol):
    """Told when servers and clients come and go (graph events): a transport, a recorder.

    Called synchronously in the loop, after a server is registered (added) or
    unregistered (removed), and when a node creates or forgets a client.  A
    restarted node's server takes its predecessor's place without an event.
    """

    def service_added(self, service: Service) -> None: ...

    def service_removed(self, service: Service) -> None: ...

    def client_added(self, client: Client) -> None: ...

    def client_removed(self, client: Client) -> None: ...


class Deferred(Protocol):
    """Services served under one name prefix, built only when first needed: a node's parameter services.

    ``kinds`` maps each service's last name segment to its type; ``build()``
    creates and registers them for real (through ``ServiceTable.add``).
    """

    @property
    def owner(self) -> Owner: ...

    @property
    def kinds(self) -> Mapping[str, type[Any]]: ...

    def build(self) -> None: ...


class ServiceTable:
    """Every service of a runtime, and the calls waiting for services not yet there.

    ``listeners`` hear of every server and client added or removed (never of a
    call); one that joins a running graph joins through :meth:`add_listener`.

    Every node serves six parameter services, and almost none of them is ever
    called: they are *deferred* (:meth:`defer`), one entry per node, and built
    when something first needs one of them.  ``servers`` holds every service
    that a client, a listener or a lookup through :meth:`get` may reach: a
    client's service is built when the client is made, and a node whose
    services a client already waits for builds them at once.  Listings see the
    deferred ones through :meth:`deferred`.  Only :meth:`add` and :meth:`remove`
    change ``servers``: they keep each server's ``_listed`` flag, on which a
    client relies to call the server it found last without looking it up again.
    """

    __slots__ = ("servers", "listeners", "_parked", "_watchers", "_timeouts", "_deferred", "_wanted", "_prefixes")

    def __init__(self) -> None:
        self.servers: dict[str, Service] = {}
        self.listeners: list[ServiceListener] = []
        self._parked: dict[str, list[_Call]] = {}
        # Futures of wait_for_service() callers, by service name (insertion-ordered sets).
        self._watchers: dict[str, dict[asyncio.Future[bool], None]] = {}
        self._timeouts: CallTimeouts | None = None
        self._deferred: dict[str, Deferred] = {}  # by prefix: the node's full name
        self._wanted: set[str] = set()  # prefixes of the names clients were made for
        self._prefixes: dict[str, int] = {}  # how many servers are registered under each prefix

    def defer(self, prefix: str, deferred: Deferred) -> bool:
        """Serve ``prefix/<kind>`` for each of ``deferred.kinds`` without building them yet.

        False (nothing registered: build them now) while listeners listen, when
        a client was made for a name under ``prefix``, or when a server already
        has a name under it (building them then finds any clash).
        """
        if self.listeners or prefix in self._wanted or prefix in self._prefixes:
            return False
        self._deferred[prefix] = deferred
        return True

    def undefer(self, prefix: str, owner: Owner) -> None:
        """Forget what ``owner`` deferred under ``prefix`` (its node is gone), without building it."""
        deferred = self._deferred.get(prefix)
        if deferred is not None and deferred.owner is owner:
            del self._deferred[prefix]

    def materialize(self, prefix: str) -> None:
        """Build and register the services deferred under ``prefix``, if any."""
        deferred = self._deferred.pop(prefix, None)
        if deferred is not None:
            deferred.build()

    def deferred(self, prefix: str | None = None) -> Iterator[tuple[str, type, Owner]]:
        """``(name, type, owner)`` of each service deferred under ``prefix`` (under every prefix if None)."""
        if prefix is None:
            entries = list(self._deferred.items())
        else:
            deferred = self._deferred.get(prefix)
            entries = [] if deferred is None else [(prefix, deferred)]
        for at, deferred in entries:
            for kind, srv_type in deferred.kinds.items():
                yield f"{at}/{kind}", srv_type, deferred.owner

    def get(self, name: str) -> Service | None:
        """The server of ``name`` (a deferred one is built), or None."""
        server = self.servers.get(name)
        if server is None and (prefix := self._deferring(name)) is not None:
            self.materialize(prefix)
            server = self.servers.get(name)
        return server

    def has(self, name: str) -> bool:
        """Whether ``name`` is served (deferred or not); builds nothing."""
        return name in self.servers or self._deferring(name) is not None

    def _deferring(self, name: str) -> str | None:
        # The prefix under which ``name`` is deferred, if it is.
        if not self._deferred:
            return None
        prefix, _, kind = name.rpartition("/")
        deferred = self._deferred.get(prefix)
        return prefix if deferred is not None and kind in deferred.kinds else None

    def want(self, name: str) -> None:
        """A client for ``name`` is made: its server, if deferred, is built, and one deferred later is not."""
        self._wanted.add(name.rpartition("/")[0])
        self.get(name)

    def add_listener(self, listener: ServiceListener) -> None:
        """Let ``listener`` hear of every server added from now on; ``servers`` then holds every one there is."""
        for prefix in list(self._deferred):
            self.materialize(prefix)
        self.listeners.append(listener)

    def timeouts(self, loop: asyncio.AbstractEventLoop) -> CallTimeouts:
        """The deadlines of calls with a timeout, on ``loop`` (made at the first such call)."""
        if self._timeouts is None:
            self._timeouts = (_VirtualCallTimeouts if isinstance(loop, VirtualTimeLoop) else CallTimeouts)(loop)
        return self._timeouts

    def add(self, service: Service, *, replacing: Service | None = None) -> None:
        """Register ``service``; raise ServiceError if another server has the name.

        A transport's stand-in for a server in another process gives way to it.
        """
        name = service.service_name
        existing = self.get(name)
        if existing is not None and existing is not replacing and not existing.remote:
            raise ServiceError(
                f"cannot serve {name} from {service.node.fqn}: {existing.node.fqn} already serves it "
                f"({type_name(existing.srv_type)})"
            )
        self.servers[name] = service
        if existing is not None:
            existing._listed = False
        service._listed = True
        if existing is None:
            prefix = name.rpartition("/")[0]
            self._prefixes[prefix] = self._prefixes.get(prefix, 0) + 1
        if existing is None or existing is not replacing:  # a restart takes its place unheard
            for listener in self.listeners:
                listener.service_added(service)
        if self._parked:
            for call in self._parked.pop(name, ()):
                if not call[1].done():
                    service._push(call)
        if self._watchers:
            for watcher in self._watchers.pop(name, ()):
                _settle(watcher, True)

    def remove(self, service: Service) -> None:
        """Unregister ``service``; its queued calls fail."""
        if self.servers.get(service.service_name) is service:
            del self.servers[service.service_name]
            service._listed = False
            prefix = service.service_name.rpartition("/")[0]
            if self._prefixes[prefix] == 1:
                del self._prefixes[prefix]
            else:
                self._prefixes[prefix] -= 1
            for listener in self.listeners:
                listener.service_removed(service)
        while service._queue:
            future = service._queue.popleft()[1]
            if not future.done():
                future.set_exception(ServiceError(f"service {service.service_name} was destroyed"))

    def add_client(self, client: Client) -> None:
        """Tell the listeners of a new client (clients need no registration to call)."""
        for listener in self.listeners:
            listener.client_added(client)

    def remove_client(self, client: Client) -> None:
        """Tell the listeners that ``client`` is gone."""
        for listener in self.listeners:
            listener.client_removed(client)

    def park(self, name: str, call: _Call) -> None:
        """Keep ``call`` until a server for ``name`` appears."""
        parked = self._parked.setdefault(name, [])
        if len(parked) >= 64:  # drop calls whose callers gave up, so the list stays bounded
            parked[:] = [c for c in parked if not c[1].done()]
        parked.append(call)

    async def appearance(self, name: str, deadline: float | None = None) -> bool:
        """Wait until a server for ``name`` registers (True) or loop time ``deadline`` passes (False).

        The deadline is one loop timer, cancelled when the server comes first.
        Cancelling the wait forgets it.
        """
        loop = asyncio.get_running_loop()
        future: asyncio.Future[bool] = loop.create_future()
        watchers = self._watchers.setdefault(name, {})
        watchers[future] = None
        timer = None if deadline is None else loop.call_at(deadline, _settle, future, False)
        try:
            return await future
        finally:
            if timer is not None:
                timer.cancel()
            watchers.pop(future, None)
            if not watchers and self._watchers.get(name) is watchers:
                del self._watchers[name]
