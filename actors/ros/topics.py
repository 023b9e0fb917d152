"""Topics: QoS profiles, publishers, subscriptions with their mailboxes, and the topic table.

``Publisher.publish`` is synchronous and never blocks: it checks the type,
takes a snapshot of the message (:mod:`actors.messages._copy`: every field checked,
what is mutable copied, never serialised; with no one to receive it, only
checked), and hands that one snapshot to each matched subscription.  What
subscribers receive is the message as it was when published, whatever the
publisher does with its object afterwards, as in rclpy.  Each
subscription keeps its own queue, bounded by its QoS depth as in ROS: a full
KEEP_LAST queue drops its oldest message and counts the drop.

A publisher that feeds one subscription (or a transport's outlet...)
appends to each queue itself and wakes the owning node once per batch.  One
that feeds several ordinary subscriptions appends each snapshot once to its
own open *batch*, a list that every one of those subscriptions holds (one
list for all), waking them when the batch opens.  The batch is closed (the
publisher starts a new list) when a subscription's round begins, and before
anything else can reach those subscriptions: another publisher's message, an
endpoint joining or leaving.  A round then iterates the list itself; only a
subscription that has anything else to take first (a message queued
directly, another batch) moves the list into its queue (C-speed ``extend``),
and anything arriving after the batch does the same.  KEEP_LAST drops are
counted when a list is read or moved, as one-by-one dropping counts them.
Per topic at most one publisher has a batch open, so each subscription still
sees the topic's messages in publish order, and ``queued`` and ``dropped``
count a batch held as queued.
A round iterates the messages queued when it began; what arrives meanwhile
(a callback publishing on its own topic, or anything during an ``async``
callback) is fed directly and counts the round's rest against the depth, so
depth and drops are exactly those of per-message delivery.

A *tap* (a recorder's subscription, :mod:`actors.recording.tap`) is no feed:
it takes each message as the publisher makes its snapshot.  A subscription
whose ``_wrap`` is set wraps the publisher's snapshot function (``_refeed``)
in one that also hands the snapshot over, so a tapped publisher keeps the
path it takes to its other subscriptions (one queue, a batch), and an
untapped one has nothing more to do: every path of ``publish()`` calls
``_snapshot`` (or, with nobody else to feed, ``_check``) exactly once per
message.

A publisher and a subscription are *matched* (connected) only when their QoS is
compatible, as in ROS (``actors.ros.qos``): a best-effort publisher does not feed a
reliable subscription, nor a volatile publisher a transient-local one, nor a
publisher with a longer deadline or lease, or an AUTOMATIC one, a subscription
that asks for less or for MANUAL_BY_TOPIC.  Each side of an incompatible pair
warns once, as rclpy's default event callbacks do, and ``doctor`` reports it.
BEST_AVAILABLE reliability and durability are settled when an endpoint joins
its topic: a publisher offers RELIABLE and TRANSIENT_LOCAL; a subscription asks
for as much as every publisher there already offers.

QoS events and the policies that need watching (deadline, lifespan,
MANUAL_BY_TOPIC liveliness) live in ``actors.ros.qos_events``: endpoints that use
none of them pay nothing for them on the publish path.  A message of a
publisher with a lifespan travels wrapped in :class:`Expiring`, and a
subscription fed by such a publisher drops each one whose time has passed when
its turn comes.

A subscription callback may refuse a message by raising
:class:`~actors.errors.MessageRefused`: the message is dropped and counted
(:mod:`actors.ros._refusals`), and the node keeps running; anything else a callback
raises crashes the node, for its supervisor to restart.

Each publisher is in one of the :class:`PublisherState` states and each
subscription in one of the :class:`SubscriptionState` states.  The hot path
keeps them in the fields it reads anyway (a state attribute would cost a read
and a compare on every publish); ``state`` reads the fields back into the
named state, and ``invariant_violations`` (per endpoint and for the whole
table) checks that the fields agree with each other.  The tests call it after
every step of their random graphs.

Endpoints are kept in dicts used as insertion-ordered sets (``{endpoint: None}``):
creation order is kept, and removing one endpoint costs O(1), so stopping a
graph of 10,000 nodes that share a topic is linear, not quadratic.
"""

from __future__ import annotations

import sys
from collections import deque
from collections.abc import Awaitable, Callable, Iterator
from enum import Enum
from inspect import isawaitable
from operator import length_hint
from typing import Any, Protocol

import msgspec

from actors.core._actor import Actor, CallbackFailed, Mailbox, Owner
from actors.errors import MessageRefused, TopicTypeError
from actors.messages._copy import checker, snapshotter
from actors.ros._refusals import Refusals
from actors.ros.qos import (
    DurabilityPolicy,
    HistoryPolicy,
    QoSPolicyKind,
    QoSProfile,
    QoSSnapshot,
    ReliabilityPolicy,
    as_qos,
    incompatible_policies,
    qos_policy_name_from_kind,
)

__all__ = [
    "PublisherState",
    "SubscriptionState",
    "type_name",
    "warn_incompatible",
    "Expiring",
    "Publisher",
    "Subscription",
    "Topic",
    "TopicListener",
    "TopicTable",
]


def type_name(msg_type: type) -> str:
    """A type's ROS name (``std_msgs/msg/String``), or its Python name if it has none."""
    return getattr(msg_type, "__ros_type__", None) or f"{msg_type.__module__}.{msg_type.__qualname__}"


def warn_incompatible(endpoint: Publisher | Subscription, policy: QoSPolicyKind) -> None:
    """rclpy's default incompatible-QoS warning, from ``endpoint``'s node."""
    name = qos_policy_name_from_kind(policy)
    if isinstance(endpoint, Subscription):
        text = (
            f"New publisher discovered on topic '{endpoint.topic_name}', offering incompatible QoS. "
            f"No messages will be received from it. Last incompatible policy: {name}"
        )
    else:
        text = (
            f"New subscription discovered on topic '{endpoint.topic_name}', requesting incompatible QoS. "
            f"No messages will be sent to it. Last incompatible policy: {name}"
        )
    endpoint.node.logger.warning(text)


class Expiring:
    """A message of a publisher with a lifespan, in a queue: dropped unread once ``expires`` (loop time) passes."""

    __slots__ = ("msg", "expires")

    def __init__(self, msg: Any, expires: float) -> None:
        self.msg = msg
        self.expires = expires

    def __repr__(self) -> str:
        return repr(self.msg)  # what a dead letter shows


class PublisherState(Enum):
    """The path ``publish()`` takes, as the publisher's fields encode it (see :attr:`Publisher.state`).

    ========================  ==========================  =========================================
    state                     fields                      publish()
    ========================  ==========================  =========================================
    ``STALE``                 ``_feeds is None``          settles the path first (``_refeed``)
    ``DIRECT``                ``_pending is None``        feeds each queue itself (``_only``: the
                                                          one queue, inlined); alone on its topic
    ``DIRECT_SHARED``         ``_pending is _SHARED``     the same, after closing the batch another
                                                          publisher of its topic may hold open
    ``BATCHING``              ``_pending == []``          opens a batch and wakes its feeds once
    ``BATCH_OPEN``            ``_pending`` a non-empty    one append to the batch, which every feed
                              list; ``topic.dirty`` is    holds (``Subscription._batch``)
                              this publisher
    ========================  ==========================  =========================================
    """

    STALE = "stale"
    DIRECT = "direct"
    DIRECT_SHARED = "direct, topic shared"
    BATCHING = "batching, none open"
    BATCH_OPEN = "batch open"


class SubscriptionState(Enum):
    """Where a subscription's messages wait, as its fields encode it (see :attr:`Subscription.state`).

    ``_limit`` is the queue length at which an arriving message must go through
    ``_evict``: the depth while ``IDLE``; 0 while a batch is held (what arrives
    moves the batch into the queue first) and while a round's rest counts
    against the depth.
    """

    IDLE = "idle"  # messages wait in _queue only; _limit is the depth
    HOLDING_BATCH = "holding a batch"  # _batch is a publisher's list, after _queue; _limit is 0
    IN_ROUND = "in a round"  # _round iterates the round's rest; _limit is 0 while the rest counts


#: A publisher's ``_pending`` in :attr:`PublisherState.DIRECT_SHARED`.  An empty tuple, so that
#: publish()'s ``if pending:`` stays a C-level truth test for every state.
_SHARED: Any = ()


class Publisher:
    """Publishes messages of one type on one topic.  Create with ``Node.create_publisher``."""

    __slots__ = (
        "topic_name",
        "msg_type",
        "qos",
        "node",
        "_subs",
        "_feeds",
        "_tracked",
        "_history",
        "_snapshot",
        "_check",
        "_events",
        "_topic",
        "_pending",
        "_bound",
        "_only",
        "_plain",
        "__weakref__",
    )

    def __init__(self, node: Owner, topic_name: str, msg_type: type, qos: QoSProfile | QoSSnapshot | int) -> None:
        self.node = node
        self.topic_name = topic_name
        self.msg_type = msg_type
        qos = as_qos(qos)
        if qos.reliability == ReliabilityPolicy.BEST_AVAILABLE or qos.durability == DurabilityPolicy.BEST_AVAILABLE:
            # A BEST_AVAILABLE publisher offers the most: subscriptions of any kind can take it.
            qos = msgspec.structs.replace(
                qos, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL
            )
        self.qos = qos
        # Functions held in slots: publish() reads them into a local before calling, since
        # CPython 3.11 leaves ``self._snapshot(msg)`` (a method call on a slot) unspecialised.
        self._snapshot = snapshotter(msg_type)
        self._check = checker(msg_type)
        self._plain = self._snapshot, self._check  # the same, with no tap wrapped around them (_refeed)
        self._events: Any = None  # an actors.ros.qos_events.EndpointEvents, for endpoints with event callbacks
        self._subs: dict[Subscription, None] = {}  # matched subscriptions, in match order
        # The same as a tuple, made again by the first publish after a change (None): a loop
        # over a tuple costs 30 ns less per publish than one over a dict, and a change stays O(1).
        self._feeds: tuple[Subscription, ...] | None = ()
        self._tracked: dict[Subscription, None] | None = None  # those of them that note who sent what
        self._history: deque[Any] | None = (
            deque(maxlen=qos.depth) if qos.durability == DurabilityPolicy.TRANSIENT_LOCAL else None
        )
        self._topic: Topic | None = None  # set by the topic table
        # The open batch (see _open): its messages, in publish order, in a list that its
        # subscriptions hold; None while this publisher delivers to each queue directly (see _refeed).
        self._pending: list[Any] | None = None
        self._bound = 0  # the batch is closed when it holds this many: the deepest feed's depth
        self._only: Subscription | None = None  # see _refeed

    @property
    def state(self) -> PublisherState:
        """The path the next ``publish()`` takes (:class:`PublisherState`), read off the fields."""
        if self._feeds is None:
            return PublisherState.STALE
        pending = self._pending
        if pending is None:
            return PublisherState.DIRECT
        if pending is _SHARED:
            return PublisherState.DIRECT_SHARED
        return PublisherState.BATCH_OPEN if pending else PublisherState.BATCHING

    def invariant_violations(self) -> list[str]:
        """What in this publisher's fields contradicts its state: empty when they agree (tests call it)."""
        state, topic, feeds, pending = self.state, self._topic, self._feeds, self._pending
        found = []
        if state is PublisherState.STALE:
            if pending is not None or self._only is not None:
                found.append("stale, yet a path is set")
            return found
        assert feeds is not None
        if self._only is not None and (feeds != (self._only,) or self._history is not None or self._tracked):
            found.append("_only set, but it is not the one plain feed")
        if state is PublisherState.DIRECT_SHARED and (topic is None or len(topic.publishers) < 2):
            found.append("direct-shared, but alone on its topic")
        if state in (PublisherState.BATCHING, PublisherState.BATCH_OPEN):
            if topic is None or len(feeds) < 2 or self._history is not None or self._tracked:
                found.append("batching, but not a publisher of several plain feeds")
            elif any(type(s) is not Subscription or s._topic is not topic for s in feeds):
                found.append("batching into a feed that is not a plain subscription of its topic")
            elif self._bound != max(s._depth for s in feeds):
                found.append("a batch bound other than the deepest feed's depth")
        if any(sub._wrap is not None for sub in feeds):
            found.append("a tap among the feeds: it takes the snapshots (_refeed)")
        is_dirty = topic is not None and topic.dirty is self
        if (state is PublisherState.BATCH_OPEN) != is_dirty:
            found.append("a batch open but not the topic's dirty publisher, or the reverse")
        if state is PublisherState.BATCH_OPEN and any(s._batch is not pending for s in feeds):
            found.append("a batch open that a feed does not hold")
        return [f"publisher on {self.topic_name} ({state.value}): {what}" for what in found]

    def publish(self, msg: Any) -> None:
        """Deliver a snapshot of ``msg`` to every matched subscription.  Never blocks.

        Raises TypeError if ``msg`` is not of this publisher's type, and
        MessageValidationError (naming the field) if a field holds a value of
        the wrong type or out of range.  Subscribers receive ``msg`` as it is
        now: the publisher may change or reuse the object afterwards.  The
        subscribers of one publish share one snapshot.
        """
        pending = self._pending
        if pending is not None:
            if pending:
                if type(msg) is self.msg_type:
                    # A batch is open (the hottest path of the runtime): one append, whatever
                    # the number of subscribers.
                    snapshot = self._snapshot  # a local (see __init__)
                    pending.append(snapshot(msg))
                    if len(pending) >= self._bound:
                        self._close()
                    return
            elif self._batched(msg, pending):
                return
        only = self._only
        if only is not None and type(msg) is self.msg_type:
            # One subscription, fed directly (the talker and its listener): Subscription._push,
            # inlined, with nothing to look at first.  1 -> 1 at 100 messages a turn: 4,856 -> 4,247
            # instructions a delivery, with a loop over the feeds and their checks (valgrind).
            snapshot = self._snapshot
            msg = snapshot(msg)
            queue = only._queue
            if len(queue) >= only._limit:
                only._evict()
            queue.append(msg)
            if not only._scheduled:
                only._scheduled = True
                only._actor.schedule(only)
            return
        if type(msg) is not self.msg_type:
            raise TypeError(
                f"publisher on {self.topic_name} takes {type_name(self.msg_type)}, got {type_name(type(msg))}"
            )
        feeds = self._feeds
        if feeds is None:
            self._refeed()
            return Publisher.publish(self, msg)  # once more: the path it takes may have changed
        if not feeds and self._history is None:
            check = self._check
            check(msg)  # nobody receives it: checked as rclpy's serialisation checks it, not copied
            return
        snapshot = self._snapshot
        msg = snapshot(msg)
        if self._history is not None:
            self._history.append(msg)
        for sub in feeds:  # the rarer cases: an outlet among several feeds, a history...
            sub._push(msg)
        if self._tracked:  # rare: subscriptions that refused messages (Subscription.track_senders)
            for sub in self._tracked:
                senders = sub._senders
                assert senders is not None  # track_senders() made it before tracking
                senders.append((msg, self))

    def _refeed(self) -> None:
        """The feeds, after a change: whether this publisher batches is settled here.

        It batches when it feeds two or more ordinary subscriptions of its topic
        (run by nodes' actors), keeps no history and tracks no senders.  Anything
        else (a transport's outlet, an action client's feedback, a single
        subscription) is fed directly, message by message, as before.  Taps are
        not fed: each wraps the snapshot function (and, for a message nobody
        else receives, the check) that every path calls once per message.
        """
        subs = self._subs
        snapshot, check = self._plain
        if any(sub._wrap is not None for sub in subs):
            feeds = self._feeds = tuple(sub for sub in subs if sub._wrap is None)
            for sub in subs:
                if sub._wrap is not None:
                    snapshot = sub._wrap(snapshot)
            check = snapshot  # with no feed, publish() checks instead of copying: the taps still want it
        else:
            feeds = self._feeds = tuple(subs)
        self._snapshot, self._check = snapshot, check
        # The single feed that publish() serves first, when nothing else needs doing per message.
        self._only = feeds[0] if len(feeds) == 1 and self._history is None and not self._tracked else None
        topic = self._topic
        if topic is None:
            self._pending = None
        elif (
            len(feeds) > 1
            and self._history is None
            and not self._tracked
            and all(type(s) is Subscription and s._topic is topic and type(s._actor) is Actor for s in feeds)
        ):
            self._pending = []
            self._bound = max(s._depth for s in feeds)
        else:
            # Fed directly; alone on its topic, nobody else can have a batch open (TopicTable
            # .add_publisher settles this again when a second publisher comes).
            self._pending = None if len(topic.publishers) == 1 else _SHARED

    def _batched(self, msg: Any, pending: list[Any]) -> bool:
        """publish() with no batch open: whether ``msg`` opened one (else it is fed directly, as usual).

        A publisher fed directly that shares its topic first closes another's open batch.
        """
        if pending is _SHARED:
            dirty = self._topic.dirty  # type: ignore[union-attr]  # DIRECT_SHARED: a topic, shared
            if dirty is not None:
                dirty._close()  # another publisher's batch comes first: it was published first
            return False
        if type(msg) is not self.msg_type:
            return False  # the usual path raises the TypeError
        self._open(self._snapshot(msg), self._feeds)  # type: ignore[arg-type]  # BATCHING: feeds are settled
        return True

    def _open(self, msg: Any, feeds: tuple[Subscription, ...]) -> None:
        """Start a batch with ``msg`` and wake its subscriptions: once per batch, not per message.

        Per topic at most one publisher has a batch open: another's is closed
        first, so every subscription sees the topic's messages in publish
        order.  A subscription in the middle of its round takes each message
        directly instead, as before: its round's rest counts against its depth.
        """
        topic = self._topic
        assert topic is not None and self._pending is not None
        if topic.dirty is not None:
            topic.dirty._close()
        for sub in feeds:
            if sub._round is not None:
                for sub in feeds:
                    sub._push(msg)
                return
        pending = self._pending
        pending.append(msg)
        topic.dirty = self
        for sub in feeds:
            if sub._batch is not None:
                sub._unbatch()  # an earlier batch, still unread, comes first
            sub._batch = pending
            sub._limit = 0  # whatever arrives after the batch moves it into the queue first (_evict)
            if not sub._scheduled:
                sub._scheduled = True
                sub._actor.schedule(sub)

    def _close(self) -> None:
        """Close the open batch: its subscriptions keep the list, this publisher starts a new one."""
        assert self._topic is not None
        self._topic.dirty = None
        self._pending = []

    def _unfeed(self) -> None:
        """Forget the feeds and the path publish() takes to them: the next publish settles both (_refeed)."""
        self._feeds = self._pending = self._only = None

    def _settle(self) -> None:
        """Close the open batch, if any: the feeds are about to change."""
        if self._pending:
            self._close()

    def _track(self, sub: Subscription) -> None:
        """Note ``sub``'s senders from the next publish on (see Subscription.track_senders)."""
        self._settle()
        if self._tracked is None:
            self._tracked = {}  # made only then: hardly any publisher needs one
        self._tracked[sub] = None
        self._unfeed()  # a publisher that tracks senders does not batch

    def _connect(self, sub: Subscription) -> None:
        """Feed ``sub`` from the next publish on (the topic table's matching, a transport's outlet)."""
        self._settle()
        self._subs[sub] = None
        self._unfeed()

    def _disconnect(self, sub: Subscription) -> bool:
        """Stop feeding ``sub``; whether it was fed.  What was published before still reaches it."""
        self._settle()
        if self._subs.pop(sub, False) is None:
            self._unfeed()
            return True
        return False

    def trust(self, *fields: str) -> None:
        """Look no more at these fields (dotted paths: ``"pose.covariance"``; none: every field) when publishing.

        Not in rclpy.  For a node whose own code fills them, always with
        values of the field's canonical type that fit it (a float, a str, a
        float array as an array.array, a list of floats or a 1-D float numpy array, a stamp
        from the clock): checking each on every publish costs as much as the
        rest of a tick.  Subscribers still receive a copy of what was
        published, and arrays of anything but floats are still checked.
        ValueError for a path that names no field of the message type.
        """
        trusted = frozenset(fields or ("",))
        self._use(snapshotter(self.msg_type, trusted), checker(self.msg_type, trusted))

    def _use(self, snapshot: Callable[[Any], Any], check: Callable[[Any], Any]) -> None:
        """Copy and check each message with these from now on (the next publish wraps them for
        the taps again, if any): the one way to change them once the publisher exists."""
        self._settle()
        self._plain = self._snapshot, self._check = snapshot, check
        self._unfeed()

    def get_subscription_count(self) -> int:
        """How many subscriptions this publisher feeds."""
        return len(self._subs)

    @property
    def qos_profile(self) -> QoSProfile:
        """This publisher's QoS as an rclpy-shaped QoSProfile (a copy: changing it changes nothing)."""
        return self.qos.to_profile()

    def assert_liveliness(self) -> None:
        """Show this publisher is alive: matters only for MANUAL_BY_TOPIC liveliness (see actors.ros.qos_events)."""

    def destroy(self) -> None:
        """Stop publishing; the topic forgets this publisher."""
        self.node.destroy_publisher(self)


class Subscription(Mailbox):
    """A subscription and its mailbox.  Create with ``Node.create_subscription``."""

    __slots__ = (
        "topic_name",
        "msg_type",
        "callback",
        "qos",
        "node",
        "_dropped",
        "refusals",
        "_depth",
        "_limit",
        "_round",
        "_batch",
        "_topic",
        "_senders",
        "_events",
        "_expiring",
        "__weakref__",
    )

    #: Set on a tap (a class that defines it): ``_wrap(snapshot)`` is the publisher's snapshot
    #: function that also hands this tap each snapshot it makes (see the module's docstring).
    _wrap: Callable[[Callable[[Any], Any]], Callable[[Any], Any]] | None = None

    def __init__(
        self,
        node: Owner,
        topic_name: str,
        msg_type: type,
        callback: Callable[[Any], Any],
        qos: QoSProfile | QoSSnapshot | int,
    ) -> None:
        self.node = node
        self.topic_name = topic_name
        self.msg_type = msg_type
        self.callback = callback
        self.qos = qos = as_qos(qos)
        self._dropped = 0
        self.refusals: Refusals | None = None  # made at the first refusal
        self._events: Any = None  # an actors.ros.qos_events.EndpointEvents, for endpoints with event callbacks
        self._expiring = False  # fed by a publisher with a lifespan: its queue may hold Expiring items
        super().__init__(node.actor)
        # The queue is made when a publisher first feeds it (TopicTable._match): an
        # unmatched subscription's empty deque would cost 760 bytes.  Typed as always there,
        # since every path that reads it runs after a match (the checks for None say so).
        self._queue: deque[Any] = None  # type: ignore[assignment]  # None until matched (see above)
        self._depth = qos.depth if qos.history == HistoryPolicy.KEEP_LAST else sys.maxsize
        # The length at which an arriving message must go through _evict: the depth, or 0
        # while a round runs (the round's rest then counts against the depth too) or a batch
        # is held (it moves into the queue first).
        self._limit = self._depth
        # While a round runs, the rest of its messages (taken out of _queue when it began).
        self._round: Iterator[Any] | None = None
        # A publisher's batch (Publisher._open), shared with its other subscriptions and never
        # changed by them: messages after those in _queue, KEEP_LAST drops not yet counted.
        self._batch: list[Any] | None = None
        self._topic: Topic | None = None  # set by the topic table
        self._senders: deque[tuple[Any, Publisher]] | None = None  # see track_senders

    def get_publisher_count(self) -> int:
        """How many publishers feed this subscription (those on its topic whose QoS matched)."""
        topic = self._topic
        return 0 if topic is None else sum(self in publisher._subs for publisher in topic.publishers)

    @property
    def state(self) -> SubscriptionState:
        """Where this subscription's messages wait (:class:`SubscriptionState`), read off the fields."""
        if self._batch is not None:
            return SubscriptionState.HOLDING_BATCH
        return SubscriptionState.IDLE if self._round is None else SubscriptionState.IN_ROUND

    def invariant_violations(self) -> list[str]:
        """What in this subscription's fields contradicts its state: empty when they agree (tests call it)."""
        state, limit = self.state, self._limit
        found = []
        if limit not in (0, self._depth):
            found.append(f"_limit {limit} is neither 0 nor the depth")
        if state is SubscriptionState.IDLE and limit != self._depth:
            found.append("idle with _limit 0: an arrival would go through _evict for nothing")
        if state is SubscriptionState.HOLDING_BATCH and limit != 0:
            found.append("a batch held but _limit is the depth: an arrival would not move it first")
        rest = self._round
        if rest is not None and limit != 0 and length_hint(rest) > 0:
            found.append("a round's rest not counted against the depth")
        if self._batch is not None and self._queue is None:
            found.append("a batch held without a queue to move it into")
        return [f"subscription {self.node.fqn} on {self.topic_name} ({state.value}): {what}" for what in found]

    @property
    def dropped(self) -> int:
        """Messages dropped unread because the queue was full (KEEP_LAST), counted as they are published.

        A transport adds those it dropped on their way here (:meth:`lost`).
        """
        waiting, batch = self._waiting()
        return self._dropped + max(0, waiting + batch - self._depth)

    @dropped.setter
    def dropped(self, count: int) -> None:
        self._dropped = count

    def lost(self, count: int) -> None:
        """Count ``count`` messages for this subscription that were dropped before they reached its queue."""
        self._dropped += count

    @property
    def queued(self) -> int:
        """Messages waiting for the callback: queued, and in a publisher's batch."""
        waiting, batch = self._waiting()
        return min(waiting + batch, self._depth) if batch else waiting

    def _waiting(self) -> tuple[int, int]:
        # What waits in the queue and the running round's rest, and what waits in a batch held.
        waiting = len(self._queue) if self._queue is not None else 0
        if self._round is not None:
            waiting += length_hint(self._round)
        return waiting, len(self._batch) if self._batch is not None else 0

    def _push(self, msg: Any) -> None:
        topic = self._topic
        if topic is not None and topic.dirty is not None:
            topic.dirty._close()  # what was published before comes first
        queue = self._queue
        if queue is None:
            queue = self._queue = deque()
        if len(queue) >= self._limit:
            self._evict()
        queue.append(msg)
        self._wake()

    def _evict(self) -> None:
        """Make room for one more message if KEEP_LAST needs it: drop the oldest unread one and count it.

        While a round runs, the oldest unread message is the round's next one:
        it is skipped, exactly as if it had waited in the queue.
        """
        if self._batch is not None:
            self._unbatch()  # what arrives now comes after the batch
        rest = self._round
        left = length_hint(rest) if rest is not None else 0
        if left + len(self._queue) < self._depth:
            return
        if rest is not None and left:
            next(rest)
        else:
            self._queue.popleft()
        self._dropped += 1

    def _unbatch(self) -> None:
        """Move the batch held into the queue, after what waits there; drop (and count) what KEEP_LAST drops."""
        batch, self._batch = self._batch, None
        assert batch is not None  # called only while a batch is held
        queue = self._queue
        queue.extend(batch)
        over = len(queue) - self._depth
        if over > 0:
            self._dropped += over  # as many as dropping one by one would have dropped
            for _ in range(over):
                queue.popleft()
        self._limit = self._depth  # no round runs while a batch is held (see _run)

    def _adopt(self, old: Mailbox) -> None:
        assert isinstance(old, Subscription)
        if old._batch is not None:
            old._unbatch()  # the new subscription takes the queue (Mailbox._adopt)
        self._dropped = old._dropped
        self.refusals = old.refusals
        self._expiring = old._expiring
        super()._adopt(old)
        if old._senders is not None:
            self._senders = old._senders
            self.track_senders()

    def track_senders(self) -> None:
        """Note which publisher sent each message, so that a refusal names it exactly.

        A subscription does this by itself from its first refusal on; a node
        that expects to refuse messages from the start may call it at once.
        It costs one append per message received.
        """
        if self._senders is None:
            # Enough to find any message still queued, or being handled, among the latest.
            self._senders = deque(maxlen=min(self._depth, 1000) + 1)
        if self._topic is not None:
            for pub in self._topic.publishers:
                if self in pub._subs:
                    pub._track(self)

    def _refuse(self, msg: Any, refusal: MessageRefused) -> None:
        """Drop ``msg``, which the callback refused: count it, and log it if it is news."""
        if type(msg) is Expiring:
            msg = msg.msg  # the message the sender sent
        if self.refusals is None:
            self.refusals = Refusals()
        line = self.refusals.add(self.topic_name, self._sender_of(msg), refusal.reason, self.node.loop.time())
        if line is not None:
            self.node.logger.warning(line)
        self.track_senders()

    def _sender_of(self, msg: Any) -> str:
        if self._senders is not None:
            for sent, pub in reversed(self._senders):
                if sent is msg:
                    return pub.node.fqn
        feeds = [] if self._topic is None else [p for p in self._topic.publishers if self in p._subs]
        if len(feeds) == 1:
            return feeds[0].node.fqn
        return "one of " + ", ".join(sorted({p.node.fqn for p in feeds})) if feeds else "an unknown publisher"

    @property
    def qos_profile(self) -> QoSProfile:
        """This subscription's QoS as an rclpy-shaped QoSProfile (a copy: changing it changes nothing)."""
        return self.qos.to_profile()

    def _call_unexpired(self, item: Any) -> Any:
        # The callback of a subscription fed by a publisher with a lifespan: a message whose
        # lifespan has passed by the time its turn comes is dropped unread.
        if type(item) is Expiring:
            if item.expires < self.node.loop.time():
                return None
            item = item.msg
        return self.callback(item)

    def _run(self) -> Awaitable[None] | None:
        # Only what is queued now: messages published meanwhile wait for the next round.  The
        # round iterates its messages (cheaper than popping each) and what arrives meanwhile
        # queues behind them, with the round's rest counted against the depth (see _evict).
        batch = self._batch
        if batch is None:  # an open batch, if any, is not for this subscription (Publisher._open)
            queue = self._queue
            if len(queue) == 1:
                rest = iter((queue.popleft(),))
            else:
                self._queue = deque()
                rest = iter(queue)
                self._limit = 0
        else:
            dirty = self._topic.dirty  # type: ignore[union-attr]  # a batch held: a topic's
            if dirty is not None:
                dirty._close()  # this round may read the open batch: nothing more joins it
            if self._queue or len(batch) > self._depth:
                self._unbatch()  # rare: something queued to take first, or drops to count
                return self._run()  # the round of the queue
            # The fan-out path: the batch's own list, shared with the publisher's other
            # subscriptions (_limit is 0 already: see Publisher._open).
            self._batch = None
            rest = iter(batch)
        self._round = rest
        callback = self._call_unexpired if self._expiring else self.callback
        while True:
            # The try holds the whole loop: a message costs no try step and no jump of its own.
            # After a refusal the loop goes on where it stopped (rest is an iterator).
            try:
                for msg in rest:
                    result = callback(msg)
                    if result is not None and isawaitable(result):
                        return self._run_async(result, msg)
            except MessageRefused as refusal:
                self._refuse(msg, refusal)
                continue
            except Exception as exc:
                self._end_round()
                self._round_done()
                raise CallbackFailed(self, msg, exc) from exc
            break
        self._round = None
        self._limit = self._depth
        # Mailbox._round_done, inlined: one call less per wake-up.
        if self._queue:
            self._actor.schedule(self)
        else:
            self._scheduled = False
        return None

    def _end_round(self) -> None:
        """End the round early (a crash, a cancellation): what it did not reach waits in the queue, first."""
        rest, self._round = self._round, None
        self._limit = self._depth
        if rest is not None:
            self._queue.extendleft(reversed(list(rest)))

    async def _run_async(self, pending: Awaitable[Any], msg: Any) -> None:
        # An async callback: await it, then the rest of the round.
        try:
            try:
                await pending
            except MessageRefused as refusal:
                self._refuse(msg, refusal)
            callback = self._call_unexpired if self._expiring else self.callback
            rest = self._round
            assert rest is not None  # the round this callback belongs to
            for msg in rest:
                try:
                    result = callback(msg)
                    if result is not None and isawaitable(result):
                        await result
                except MessageRefused as refusal:
                    self._refuse(msg, refusal)
        except Exception as exc:
            self._end_round()
            self._round_done()
            raise CallbackFailed(self, msg, exc) from exc
        finally:
            self._end_round()  # cancelled: the rest stays queued, as it did before its round
        self._round_done()

    def destroy(self) -> None:
        """Stop receiving; the topic forgets this subscription."""
        self.node.destroy_subscription(self)


class Topic:
    """One topic: its type and its endpoints, in creation order."""

    __slots__ = ("name", "msg_type", "publishers", "subscriptions", "dirty")

    def __init__(self, name: str, msg_type: type) -> None:
        self.name = name
        self.msg_type = msg_type
        self.dirty: Publisher | None = None  # the publisher with a batch open, if any (Publisher._open)
        self.publishers: dict[Publisher, None] = {}  # insertion-ordered sets: O(1) removal
        self.subscriptions: dict[Subscription, None] = {}


class TopicListener(Protocol):
    """Told when endpoints come and go (graph events): a recorder, a transport.

    Called synchronously in the loop, after the endpoint is matched (added) or
    before an empty topic is dropped (removed).  A listener may add endpoints
    of its own from the call (it hears of them too), but must not remove any.
    A restarted node's subscription takes its predecessor's place without an
    event.
    """

    def endpoint_added(self, topic: Topic, endpoint: Publisher | Subscription) -> None: ...

    def endpoint_removed(self, topic: Topic, endpoint: Publisher | Subscription) -> None: ...


class TopicTable:
    """Every topic of a runtime; matches publishers to subscriptions and tells them of it.

    ``listeners`` hear of every endpoint added or removed (never of a publish).
    """

    __slots__ = ("topics", "listeners")

    def __init__(self) -> None:
        self.topics: dict[str, Topic] = {}
        self.listeners: list[TopicListener] = []

    def _topic_for(self, name: str, msg_type: type, endpoint: str, node: str) -> Topic:
        topic = self.topics.get(name)
        if topic is None:
            topic = self.topics[name] = Topic(name, msg_type)
        elif topic.msg_type is not msg_type:
            other: Publisher | Subscription = (
                next(iter(topic.publishers)) if topic.publishers else next(iter(topic.subscriptions))
            )
            raise TopicTypeError(
                f"cannot create {endpoint} of {type_name(msg_type)} on {name} for node "
                f"{node}: the topic already carries {type_name(topic.msg_type)} "
                f"({'published' if topic.publishers else 'subscribed'} by "
                f"{other.node.fqn})"
            )
        return topic

    def invariant_violations(self) -> list[str]:
        """Every endpoint's :meth:`~Publisher.invariant_violations`, and each topic's: at most one
        batch open, held by a publisher of the topic.  Empty when all agree (tests call it)."""
        found = []
        for topic in self.topics.values():
            dirty = topic.dirty
            if dirty is not None and (dirty not in topic.publishers or dirty.state is not PublisherState.BATCH_OPEN):
                found.append(f"topic {topic.name}: its dirty publisher has no batch open here")
            for pub in topic.publishers:
                found += pub.invariant_violations()
            for sub in topic.subscriptions:
                found += sub.invariant_violations()
        return found

    def add_publisher(self, pub: Publisher) -> None:
        """Register ``pub`` and connect it to every compatible subscription."""
        topic = self._topic_for(pub.topic_name, pub.msg_type, "a publisher", pub.node.fqn)
        topic.publishers[pub] = None
        pub._topic = topic
        if len(topic.publishers) == 2:
            for other in topic.publishers:
                if other._pending is None:  # it was alone: from now on it checks for another's batch
                    other._unfeed()
        for sub in topic.subscriptions:
            self._match(pub, sub)
        for listener in self.listeners:
            listener.endpoint_added(topic, pub)

    def add_subscription(self, sub: Subscription, *, replay: bool = True) -> None:
        """Register ``sub``, connect it, and replay transient-local history if it asks for it."""
        topic = self._topic_for(sub.topic_name, sub.msg_type, "a subscription", sub.node.fqn)
        _settle_best_available(sub, topic)
        topic.subscriptions[sub] = None
        sub._topic = topic
        for pub in topic.publishers:
            latched = sub.qos.durability == DurabilityPolicy.TRANSIENT_LOCAL
            if self._match(pub, sub) and replay and pub._history and latched:
                for msg in pub._history:
                    sub._push(msg)
        for listener in self.listeners:
            listener.endpoint_added(topic, sub)

    def _match(self, pub: Publisher, sub: Subscription) -> bool:
        refused = incompatible_policies(pub.qos, sub.qos)
        if refused:
            for endpoint in (pub, sub):
                if endpoint._events is not None:
                    endpoint._events.incompatible(refused[-1])
                elif hasattr(endpoint.node, "logger"):  # a node's (the runtime's and the CLI's have none)
                    warn_incompatible(endpoint, refused[-1])
            return False
        if sub._queue is None:
            sub._queue = deque()
        pub._connect(sub)
        if sub._senders is not None:
            pub._track(sub)
        if pub.qos.lifespan_ns:
            sub._expiring = True
        _tell(pub, sub, +1)
        return True

    def replace_subscription(self, old: Subscription, new: Subscription) -> None:
        """Connect ``new`` to every publisher that fed ``old``, and forget ``old``.

        The restarted node's subscription moves to the end of the topic's
        order; the publishers that fed the old one feed the new one, whatever
        their QoS was matched against.
        """
        topic = self.topics[old.topic_name]
        del topic.subscriptions[old]
        if old._events is not None:
            old._events.stop()
        topic.subscriptions[new] = None
        new._topic = topic
        for pub in topic.publishers:
            if pub._disconnect(old):
                pub._connect(new)
                if pub._tracked:
                    pub._tracked.pop(old, None)  # the new one tracks again if it adopts the old one's senders

    def remove_publisher(self, pub: Publisher) -> None:
        """Forget ``pub``; drop the topic when it has no endpoint left.  O(1)."""
        topic = self.topics.get(pub.topic_name)
        if topic is not None and pub in topic.publishers:
            pub._settle()  # what it published before reaches its subscriptions all the same
            del topic.publishers[pub]
            if len(topic.publishers) == 1:
                (other,) = topic.publishers
                if other._pending is _SHARED:  # alone again: nobody else can hold a batch open
                    other._pending = None
            if pub._events is not None:
                pub._events.stop()
            for sub in pub._subs:
                _tell(pub, sub, -1, to_pub=False)  # the publisher itself is gone: only its subscriptions hear
            pub._subs = {}
            pub._feeds = ()
            pub._pending = pub._only = None
            pub._snapshot, pub._check = pub._plain  # no tap hears it any more
            pub._tracked = None
            for listener in self.listeners:
                listener.endpoint_removed(topic, pub)
            self._drop_if_empty(topic)

    def remove_subscription(self, sub: Subscription) -> None:
        """Forget ``sub``; drop the topic when it has no endpoint left.

        O(publishers of the topic): each publisher forgets it in O(1).
        """
        topic = self.topics.get(sub.topic_name)
        if topic is not None and sub in topic.subscriptions:
            del topic.subscriptions[sub]
            if sub._events is not None:
                sub._events.stop()
            for pub in topic.publishers:
                if pub._tracked:
                    pub._tracked.pop(sub, None)
                if pub._disconnect(sub):
                    _tell(pub, sub, -1, to_sub=False)
            for listener in self.listeners:
                listener.endpoint_removed(topic, sub)
            self._drop_if_empty(topic)

    def _drop_if_empty(self, topic: Topic) -> None:
        if not topic.publishers and not topic.subscriptions:
            del self.topics[topic.name]


def _tell(pub: Publisher, sub: Subscription, delta: int, *, to_pub: bool = True, to_sub: bool = True) -> None:
    """Tell the endpoints with events that they connected (+1) or parted (-1)."""
    if to_pub and pub._events is not None:
        pub._events.matched(delta)
    events = sub._events
    if to_sub and events is not None:
        events.matched(delta)
        lease = pub._events.lease if pub._events is not None else None
        if lease is not None and lease.expired:
            events.liveliness_changed(0, delta)  # a publisher that had lost its liveliness
        else:
            events.liveliness_changed(delta, 0)


def _settle_best_available(sub: Subscription, topic: Topic) -> None:
    """A BEST_AVAILABLE subscription asks for what every publisher already there offers."""
    qos = sub.qos
    reliability, durability = qos.reliability, qos.durability
    if reliability == ReliabilityPolicy.BEST_AVAILABLE:
        reliable = all(p.qos.reliability == ReliabilityPolicy.RELIABLE for p in topic.publishers)
        reliability = ReliabilityPolicy.RELIABLE if reliable else ReliabilityPolicy.BEST_EFFORT
    if durability == DurabilityPolicy.BEST_AVAILABLE:
        latched = all(p.qos.durability == DurabilityPolicy.TRANSIENT_LOCAL for p in topic.publishers)
        durability = DurabilityPolicy.TRANSIENT_LOCAL if latched else DurabilityPolicy.VOLATILE
    if (reliability, durability) != (qos.reliability, qos.durability):
        sub.qos = msgspec.structs.replace(qos, reliability=reliability, durability=durability)
