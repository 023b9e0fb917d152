"""QoS events, as rclpy.event_handler: deadline missed, liveliness, incompatible QoS, matched.

A publisher or subscription made with ``event_callbacks=`` (a
:class:`PublisherEventCallbacks` or :class:`SubscriptionEventCallbacks`) gets
an :class:`EndpointEvents`: it counts what happens to the endpoint and calls
the user's callback with an info object (``total_count``,
``total_count_change``...), in the endpoint's node's task like its other
callbacks.  As in DDS, events of one kind that come before the callback runs
are reported by one call (the ``*_change`` fields add them up).

- deadline: a publisher that has not published within its deadline, or a
  subscription that has not received within its own (timed on the graph's
  clock, one loop timer per endpoint, only for endpoints with a deadline);
- liveliness: a MANUAL_BY_TOPIC publisher that neither published nor called
  ``assert_liveliness()`` within its lease loses its liveliness (and regains it
  on the next one); its subscriptions see the count of live publishers change,
  also when a publisher appears or goes away;
- incompatible_qos: a publisher/subscription pair that cannot connect (both
  sides; without a callback of its own, each side logs rclpy's warning);
- matched: a publisher/subscription pair connected or disconnected.

``message_lost`` and ``incompatible_type`` are accepted and never fire here:
in-process delivery loses nothing, and a topic's type conflict is refused
with TopicTypeError when the endpoint is made.
"""

from __future__ import annotations

import asyncio
from collections.abc import Callable
from typing import Any

import msgspec

from actors.core._actor import OneShot
from actors.ros.qos import LivelinessPolicy, QoSPolicyKind, QoSSnapshot
from actors.ros.topics import Expiring, Publisher, Subscription, warn_incompatible

__all__ = [
    "QoSRequestedDeadlineMissedInfo",
    "QoSOfferedDeadlineMissedInfo",
    "QoSLivelinessChangedInfo",
    "QoSLivelinessLostInfo",
    "QoSMessageLostInfo",
    "QoSRequestedIncompatibleQoSInfo",
    "QoSOfferedIncompatibleQoSInfo",
    "QoSSubscriptionMatchedInfo",
    "QoSPublisherMatchedInfo",
    "IncompatibleTypeInfo",
    "SubscriptionEventCallbacks",
    "PublisherEventCallbacks",
    "EndpointEvents",
    "Watch",
    "WatchedPublisher",
    "watched",
]


class _Counted(msgspec.Struct, frozen=True, kw_only=True):
    total_count: int = 0
    total_count_change: int = 0


class QoSRequestedDeadlineMissedInfo(_Counted, frozen=True, kw_only=True):
    """A subscription's deadlines missed: in all, and since the last call."""


class QoSOfferedDeadlineMissedInfo(_Counted, frozen=True, kw_only=True):
    """A publisher's deadlines missed: in all, and since the last call."""


class QoSLivelinessLostInfo(_Counted, frozen=True, kw_only=True):
    """Times a publisher lost its liveliness: in all, and since the last call."""


class QoSMessageLostInfo(_Counted, frozen=True, kw_only=True):
    """Messages a subscription lost (never, in process)."""


class IncompatibleTypeInfo(_Counted, frozen=True, kw_only=True):
    """Endpoints of another type on the topic (never: refused when made)."""


class QoSRequestedIncompatibleQoSInfo(_Counted, frozen=True, kw_only=True):
    """Endpoints this one could not connect to, and the last policy that stopped it."""

    last_policy_kind: QoSPolicyKind = QoSPolicyKind.INVALID


QoSOfferedIncompatibleQoSInfo = QoSRequestedIncompatibleQoSInfo


class QoSSubscriptionMatchedInfo(_Counted, frozen=True, kw_only=True):
    """Publishers connected: ever (``total_count``) and now (``current_count``), with their changes."""

    current_count: int = 0
    current_count_change: int = 0


QoSPublisherMatchedInfo = QoSSubscriptionMatchedInfo


class QoSLivelinessChangedInfo(msgspec.Struct, frozen=True, kw_only=True):
    """A subscription's publishers alive and not alive now, and the changes since the last call."""

    alive_count: int = 0
    not_alive_count: int = 0
    alive_count_change: int = 0
    not_alive_count_change: int = 0


Callback = Callable[[Any], Any] | None


class SubscriptionEventCallbacks:
    """The event callbacks of a subscription (``create_subscription(..., event_callbacks=)``), as rclpy's.

    With ``use_default_callbacks`` (the default), an incompatible publisher is
    logged as a warning when no ``incompatible_qos`` callback is given.
    """

    def __init__(
        self,
        *,
        deadline: Callback = None,
        incompatible_qos: Callback = None,
        liveliness: Callback = None,
        message_lost: Callback = None,
        incompatible_type: Callback = None,
        matched: Callback = None,
        use_default_callbacks: bool = True,
    ) -> None:
        self.deadline = deadline
        self.incompatible_qos = incompatible_qos
        self.liveliness = liveliness
        self.message_lost = message_lost
        self.incompatible_type = incompatible_type
        self.matched = matched
        self.use_default_callbacks = use_default_callbacks


class PublisherEventCallbacks:
    """The event callbacks of a publisher (``create_publisher(..., event_callbacks=)``), as rclpy's.

    With ``use_default_callbacks`` (the default), an incompatible subscription
    is logged as a warning when no ``incompatible_qos`` callback is given.
    """

    def __init__(
        self,
        *,
        deadline: Callback = None,
        liveliness: Callback = None,
        incompatible_qos: Callback = None,
        incompatible_type: Callback = None,
        matched: Callback = None,
        use_default_callbacks: bool = True,
    ) -> None:
        self.deadline = deadline
        self.liveliness = liveliness
        self.incompatible_qos = incompatible_qos
        self.incompatible_type = incompatible_type
        self.matched = matched
        self.use_default_callbacks = use_default_callbacks


class Watch:
    """Calls ``on_expiry()`` when ``period`` seconds of loop time pass without a :meth:`feed`.

    One loop timer, moved at most once a period: feeding only records the time.
    After an expiry it waits another period (``rearm=True``: a deadline, missed
    again each period) or until the next feed (a liveliness lease).
    """

    __slots__ = ("_loop", "_period", "_on_expiry", "_rearm", "_last", "_handle", "expired")

    def __init__(
        self, loop: asyncio.AbstractEventLoop, period: float, on_expiry: Callable[[], None], *, rearm: bool
    ) -> None:
        self._loop = loop
        self._period = period
        self._on_expiry = on_expiry
        self._rearm = rearm
        self._last = loop.time()
        self.expired = False
        self._handle: asyncio.TimerHandle | None = loop.call_at(self._last + period, self._check)

    def feed(self) -> bool:
        """Note activity now; True when this ends an expiry (a lease regained)."""
        self._last = self._loop.time()
        if self._handle is None:  # stopped after an expiry: start again
            self._handle = self._loop.call_at(self._last + self._period, self._check)
        regained, self.expired = self.expired, False
        return regained

    def _check(self) -> None:
        now = self._loop.time()
        due = self._last + self._period
        if now < due:  # fed since the timer was set: wait for the new due time
            self._handle = self._loop.call_at(due, self._check)
            return
        self.expired = True
        self._on_expiry()
        if self._rearm:
            self._last = now
            self._handle = self._loop.call_at(now + self._period, self._check)
        else:
            self._handle = None

    def stop(self) -> None:
        """Stop watching."""
        if self._handle is not None:
            self._handle.cancel()
            self._handle = None


class EndpointEvents:
    """One endpoint's event counts and callbacks; the topic table and the endpoint report to it."""

    __slots__ = ("endpoint", "callbacks", "_counts", "_reported", "_pending", "_last_policy", "deadline", "lease")

    def __init__(self, endpoint: Any, callbacks: SubscriptionEventCallbacks | PublisherEventCallbacks) -> None:
        self.endpoint = endpoint
        self.callbacks = callbacks
        self._counts: dict[str, int] = {}
        self._reported: dict[str, int] = {}
        self._pending: set[str] = set()
        self._last_policy = QoSPolicyKind.INVALID
        self.deadline: Watch | None = None
        self.lease: Watch | None = None
        qos = endpoint.qos
        loop = endpoint.node.loop
        if qos.deadline_ns:
            self.deadline = Watch(loop, qos.deadline_ns / 1e9, self._deadline_missed, rearm=True)

    def _add(self, count: str, delta: int = 1) -> None:
        self._counts[count] = self._counts.get(count, 0) + delta

    def _change(self, count: str) -> tuple[int, int]:
        """(count now, change since the last report), and mark it reported."""
        now = self._counts.get(count, 0)
        change = now - self._reported.get(count, 0)
        self._reported[count] = now
        return now, change

    def _emit(self, kind: str) -> None:
        callback = getattr(self.callbacks, kind, None)
        if callback is None or kind in self._pending:
            return
        self._pending.add(kind)
        self.endpoint.node.actor.schedule(OneShot(lambda: self._deliver(kind, callback), f"{kind} event"))

    def _deliver(self, kind: str, callback: Callable[[Any], Any]) -> Any:
        self._pending.discard(kind)
        return callback(self._info(kind))

    def _info(self, kind: str) -> Any:
        subscription = isinstance(self.endpoint, Subscription)
        if kind == "liveliness":
            if subscription:
                alive, alive_change = self._change("alive")
                not_alive, not_alive_change = self._change("not_alive")
                return QoSLivelinessChangedInfo(
                    alive_count=alive,
                    not_alive_count=not_alive,
                    alive_count_change=alive_change,
                    not_alive_count_change=not_alive_change,
                )
            total, change = self._change("liveliness_lost")
            return QoSLivelinessLostInfo(total_count=total, total_count_change=change)
        if kind == "matched":
            total, change = self._change("matched_total")
            current, current_change = self._change("matched_current")
            return QoSSubscriptionMatchedInfo(
                total_count=total, total_count_change=change, current_count=current, current_count_change=current_change
            )
        total, change = self._change(kind)
        if kind == "incompatible_qos":
            return QoSRequestedIncompatibleQoSInfo(
                total_count=total, total_count_change=change, last_policy_kind=self._last_policy
            )
        return (QoSRequestedDeadlineMissedInfo if subscription else QoSOfferedDeadlineMissedInfo)(
            total_count=total, total_count_change=change
        )

    # -- what the topic table and the endpoint report -----------------------------

    def matched(self, delta: int) -> None:
        """A peer connected (+1) or went away (-1)."""
        if delta > 0:
            self._add("matched_total")
        self._add("matched_current", delta)
        self._emit("matched")

    def incompatible(self, policy: QoSPolicyKind) -> None:
        """A peer that cannot connect, because of ``policy``."""
        self._add("incompatible_qos")
        self._last_policy = policy
        if self.callbacks.incompatible_qos is None:
            if self.callbacks.use_default_callbacks:
                warn_incompatible(self.endpoint, policy)
            return
        self._emit("incompatible_qos")

    def liveliness_changed(self, alive: int, not_alive: int) -> None:
        """(Subscription) the counts of live and not-live publishers changed by these amounts."""
        self._add("alive", alive)
        self._add("not_alive", not_alive)
        self._emit("liveliness")

    def liveliness_lost(self) -> None:
        """(Publisher) its lease ran out."""
        self._add("liveliness_lost")
        self._emit("liveliness")

    def _deadline_missed(self) -> None:
        self._add("deadline")
        self._emit("deadline")

    def stop(self) -> None:
        """Stop the endpoint's timers (it is being destroyed)."""
        for watch in (self.deadline, self.lease):
            if watch is not None:
                watch.stop()


def watched(qos: QoSSnapshot) -> bool:
    """Whether a publisher with ``qos`` needs watching: a lifespan, a deadline, or a MANUAL_BY_TOPIC lease."""
    return bool(qos.lifespan_ns or qos.deadline_ns or _leased(qos))


def _leased(qos: QoSSnapshot) -> bool:
    return qos.liveliness == LivelinessPolicy.MANUAL_BY_TOPIC and qos.liveliness_lease_duration_ns > 0


class WatchedPublisher(Publisher):
    """A publisher whose QoS needs watching (see :func:`watched`); plain publishers pay nothing for it.

    After the ordinary delivery it wraps what it just queued in :class:`Expiring`
    (lifespan), tells the subscriptions that watch a deadline that they
    received, and renews its own deadline and liveliness lease.
    """

    __slots__ = ("_lifespan",)

    def __init__(
        self,
        node: Any,
        topic_name: str,
        msg_type: type[Any],
        qos: QoSSnapshot,
        callbacks: PublisherEventCallbacks | None = None,
    ) -> None:
        super().__init__(node, topic_name, msg_type, qos)
        self._lifespan = self.qos.lifespan_ns / 1e9
        if callbacks is not None or _leased(self.qos):
            events = self._events = EndpointEvents(self, callbacks or PublisherEventCallbacks())
            if _leased(self.qos):
                events.lease = Watch(node.loop, self.qos.liveliness_lease_duration_ns / 1e9, self._lost, rearm=False)

    def publish(self, msg: Any) -> None:
        """Deliver ``msg`` as :meth:`Publisher.publish` does, then keep its QoS promises."""
        before = self._pending
        Publisher.publish(self, msg)
        subs = self._subs
        if self._lifespan:
            # publish() has just appended msg to its open batch (or to the one it filled, which
            # its subscriptions hold: Publisher._close), or to every queue and to the history:
            # wrap it there.
            expires = self.node.loop.time() + self._lifespan
            batch = self._pending or before
            if batch:
                batch[-1] = Expiring(batch[-1], expires)
            else:
                for sub in subs:
                    queue = sub._queue
                    queue[-1] = Expiring(queue[-1], expires)
            if self._history is not None:
                self._history[-1] = Expiring(self._history[-1], expires)
        for sub in subs:
            events = sub._events
            if events is not None and events.deadline is not None:
                events.deadline.feed()
        events = self._events
        if events is not None and events.deadline is not None:
            events.deadline.feed()
        self.assert_liveliness()

    def assert_liveliness(self) -> None:
        """Renew a MANUAL_BY_TOPIC lease; if it had run out, the subscriptions see this publisher alive again."""
        events = self._events
        if events is not None and events.lease is not None and events.lease.feed():
            for sub in self._subs:
                if sub._events is not None:
                    sub._events.liveliness_changed(+1, -1)

    def _lost(self) -> None:
        assert self._events is not None
        self._events.liveliness_lost()
        for sub in self._subs:
            if sub._events is not None:
                sub._events.liveliness_changed(-1, +1)
