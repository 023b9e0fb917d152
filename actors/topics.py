"""Topics: QoS profiles, publishers, subscriptions with their mailboxes, and the topic table.

``Publisher.publish`` is synchronous and O(subscribers): it checks the type,
takes a snapshot of the message (:mod:`actors.snapshot`: every field checked,
what is mutable copied, never serialised), appends that one snapshot to each
matched subscription's queue and wakes the owning node once per batch.  What
subscribers receive is the message as it was when published, whatever the
publisher does with its object afterwards, as in rclpy.  Each
subscription keeps its own queue, bounded by its QoS depth as in ROS: a full
KEEP_LAST queue drops its oldest message and counts the drop.

A publisher and a subscription are *matched* (connected) only when their QoS is
compatible, as in ROS: a best-effort publisher does not feed a reliable
subscription, nor a volatile publisher a transient-local one.  Incompatible
pairs are logged once and reported by ``doctor``.

A subscription callback may refuse a message by raising
:class:`~actors.errors.MessageRefused`: the message is dropped and counted
(:mod:`actors.refusals`), and the node keeps running; anything else a callback
raises crashes the node, for its supervisor to restart.

Endpoints are kept in dicts used as insertion-ordered sets (``{endpoint: None}``):
creation order is kept, and removing one endpoint costs O(1), so stopping a
graph of 10,000 nodes that share a topic is linear, not quadratic.
"""

from __future__ import annotations

import sys
from collections import deque
from collections.abc import Awaitable, Callable
from enum import IntEnum
from inspect import isawaitable
from typing import Any

import msgspec

from actors.actor import CallbackFailed, Mailbox, Owner
from actors.errors import MessageRefused, TopicTypeError
from actors.refusals import Refusals
from actors.snapshot import snapshotter

__all__ = [
    "HistoryPolicy",
    "ReliabilityPolicy",
    "DurabilityPolicy",
    "QoSProfile",
    "qos_profile_sensor_data",
    "qos_profile_system_default",
    "as_qos",
    "qos_incompatibility",
    "type_name",
    "Publisher",
    "Subscription",
    "Topic",
    "TopicTable",
]


class HistoryPolicy(IntEnum):
    """How many messages a queue keeps (values as rclpy's)."""

    KEEP_LAST = 1
    KEEP_ALL = 2


class ReliabilityPolicy(IntEnum):
    """Delivery guarantee requested or offered (values as rclpy's)."""

    RELIABLE = 1
    BEST_EFFORT = 2


class DurabilityPolicy(IntEnum):
    """Whether late subscribers get earlier messages (values as rclpy's)."""

    TRANSIENT_LOCAL = 1
    VOLATILE = 2


class QoSProfile(msgspec.Struct, frozen=True, kw_only=True):
    """Quality of service of a publisher or subscription, shaped like rclpy's.

    ``depth`` bounds a KEEP_LAST queue and the history a TRANSIENT_LOCAL
    publisher keeps for late subscribers.
    """

    depth: int = 10
    history: HistoryPolicy = HistoryPolicy.KEEP_LAST
    reliability: ReliabilityPolicy = ReliabilityPolicy.RELIABLE
    durability: DurabilityPolicy = DurabilityPolicy.VOLATILE

    def __post_init__(self) -> None:
        if self.history == HistoryPolicy.KEEP_LAST and self.depth < 1:
            raise ValueError(f"QoS depth must be >= 1 for KEEP_LAST, got {self.depth}")


qos_profile_system_default = QoSProfile()
qos_profile_sensor_data = QoSProfile(depth=5, reliability=ReliabilityPolicy.BEST_EFFORT)


def as_qos(qos: QoSProfile | int) -> QoSProfile:
    """A QoS profile from a profile or a plain depth (KEEP_LAST of that depth)."""
    if isinstance(qos, QoSProfile):
        return qos
    if isinstance(qos, int) and not isinstance(qos, bool):
        return QoSProfile(depth=qos)
    raise TypeError(f"qos must be a QoSProfile or an int depth, got {qos!r}")


def qos_incompatibility(offered: QoSProfile, requested: QoSProfile) -> str | None:
    """Why a publisher offering ``offered`` cannot feed a subscription requesting ``requested``."""
    if (
        offered.reliability == ReliabilityPolicy.BEST_EFFORT
        and requested.reliability == ReliabilityPolicy.RELIABLE
    ):
        return "publisher offers BEST_EFFORT, subscription requests RELIABLE"
    if (
        offered.durability == DurabilityPolicy.VOLATILE
        and requested.durability == DurabilityPolicy.TRANSIENT_LOCAL
    ):
        return "publisher offers VOLATILE, subscription requests TRANSIENT_LOCAL"
    return None


def type_name(msg_type: type) -> str:
    """A type's ROS name (``std_msgs/msg/String``), or its Python name if it has none."""
    return getattr(msg_type, "__ros_type__", None) or f"{msg_type.__module__}.{msg_type.__qualname__}"


class Publisher:
    """Publishes messages of one type on one topic.  Create with ``Node.create_publisher``."""

    __slots__ = (
        "topic_name", "msg_type", "qos", "node", "_subs", "_tracked", "_history", "_snapshot", "__weakref__"
    )

    def __init__(self, node: Owner, topic_name: str, msg_type: type, qos: QoSProfile) -> None:
        self.node = node
        self.topic_name = topic_name
        self.msg_type = msg_type
        self.qos = qos
        self._snapshot = snapshotter(msg_type)
        self._subs: dict[Subscription, None] = {}  # matched subscriptions, in match order
        self._tracked: dict[Subscription, None] = {}  # those of them that note who sent what
        self._history: deque[Any] | None = (
            deque(maxlen=qos.depth) if qos.durability == DurabilityPolicy.TRANSIENT_LOCAL else None
        )

    def publish(self, msg: Any) -> None:
        """Deliver a snapshot of ``msg`` to every matched subscription.  Never blocks.

        Raises TypeError if ``msg`` is not of this publisher's type, and
        MessageValidationError (naming the field) if a field holds a value of
        the wrong type or out of range.  Subscribers receive ``msg`` as it is
        now: the publisher may change or reuse the object afterwards.  The
        subscribers of one publish share one snapshot.
        """
        if type(msg) is not self.msg_type:
            raise TypeError(
                f"publisher on {self.topic_name} takes {type_name(self.msg_type)}, "
                f"got {type_name(type(msg))}"
            )
        msg = self._snapshot(msg)
        if self._history is not None:
            self._history.append(msg)
        for sub in self._subs:
            # Subscription._push, inlined: this loop is the hottest path of the runtime.
            queue = sub._queue
            if len(queue) >= sub._limit:
                queue.popleft()
                sub.dropped += 1
            queue.append(msg)
            if not sub._scheduled:
                sub._scheduled = True
                sub._actor.schedule(sub)
        if self._tracked:  # rare: subscriptions that refused messages (Subscription.track_senders)
            for sub in self._tracked:
                sub._senders.append((msg, self))  # type: ignore[union-attr]

    def get_subscription_count(self) -> int:
        """How many subscriptions this publisher feeds."""
        return len(self._subs)

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
        "dropped",
        "refusals",
        "_limit",
        "_topic",
        "_senders",
        "__weakref__",
    )

    def __init__(
        self,
        node: Owner,
        topic_name: str,
        msg_type: type,
        callback: Callable[[Any], Any],
        qos: QoSProfile,
    ) -> None:
        self.node = node
        self.topic_name = topic_name
        self.msg_type = msg_type
        self.callback = callback
        self.qos = qos
        self.dropped = 0
        self.refusals: Refusals | None = None  # made at the first refusal
        super().__init__(node.actor)
        self._queue: deque[Any] = deque()
        self._limit = qos.depth if qos.history == HistoryPolicy.KEEP_LAST else sys.maxsize
        self._topic: Topic | None = None  # set by the topic table
        self._senders: deque[tuple[Any, Publisher]] | None = None  # see track_senders

    def _push(self, msg: Any) -> None:
        queue = self._queue
        if len(queue) >= self._limit:
            queue.popleft()
            self.dropped += 1
        queue.append(msg)
        self._wake()

    def _adopt(self, old: Mailbox) -> None:
        assert isinstance(old, Subscription)
        self.dropped = old.dropped
        self.refusals = old.refusals
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
            self._senders = deque(maxlen=min(self._limit, 1000) + 1)
        if self._topic is not None:
            for pub in self._topic.publishers:
                if self in pub._subs:
                    pub._tracked[self] = None

    def _refuse(self, msg: Any, refusal: MessageRefused) -> None:
        """Drop ``msg``, which the callback refused: count it, and log it if it is news."""
        if self.refusals is None:
            self.refusals = Refusals()
        line = self.refusals.add(
            self.topic_name, self._sender_of(msg), refusal.reason, self.node.loop.time()
        )
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

    def _run(self) -> Awaitable[None] | None:
        queue = self._queue
        callback = self.callback
        # Only what is queued now: messages published meanwhile wait for the next round.
        for left in range(len(queue) - 1, -1, -1):
            msg = queue.popleft()
            try:
                result = callback(msg)
            except MessageRefused as refusal:
                self._refuse(msg, refusal)
                continue
            except Exception as exc:
                self._round_done()
                raise CallbackFailed(self, msg, exc) from exc
            if result is not None and isawaitable(result):
                return self._run_async(result, msg, left)
        self._round_done()
        return None

    async def _run_async(self, pending: Awaitable[Any], msg: Any, left: int) -> None:
        # An async callback: await it, then the ``left`` messages still due this round.
        try:
            try:
                await pending
            except MessageRefused as refusal:
                self._refuse(msg, refusal)
            queue, callback = self._queue, self.callback
            for _ in range(left):
                msg = queue.popleft()
                try:
                    result = callback(msg)
                    if result is not None and isawaitable(result):
                        await result
                except MessageRefused as refusal:
                    self._refuse(msg, refusal)
        except Exception as exc:
            self._round_done()
            raise CallbackFailed(self, msg, exc) from exc
        self._round_done()

    def destroy(self) -> None:
        """Stop receiving; the topic forgets this subscription."""
        self.node.destroy_subscription(self)


class Topic:
    """One topic: its type and its endpoints, in creation order."""

    __slots__ = ("name", "msg_type", "publishers", "subscriptions")

    def __init__(self, name: str, msg_type: type) -> None:
        self.name = name
        self.msg_type = msg_type
        self.publishers: dict[Publisher, None] = {}  # insertion-ordered sets: O(1) removal
        self.subscriptions: dict[Subscription, None] = {}


class TopicTable:
    """Every topic of a runtime; matches publishers to subscriptions."""

    __slots__ = ("topics", "_on_incompatible")

    def __init__(self, on_incompatible: Callable[[Publisher, Subscription, str], None]) -> None:
        self.topics: dict[str, Topic] = {}
        self._on_incompatible = on_incompatible

    def _topic_for(self, name: str, msg_type: type, endpoint: str, node: str) -> Topic:
        topic = self.topics.get(name)
        if topic is None:
            topic = self.topics[name] = Topic(name, msg_type)
        elif topic.msg_type is not msg_type:
            other = next(iter(topic.publishers or topic.subscriptions))
            raise TopicTypeError(
                f"cannot create {endpoint} of {type_name(msg_type)} on {name} for node "
                f"{node}: the topic already carries {type_name(topic.msg_type)} "
                f"({'published' if topic.publishers else 'subscribed'} by "
                f"{other.node.fqn})"
            )
        return topic

    def add_publisher(self, pub: Publisher) -> None:
        """Register ``pub`` and connect it to every compatible subscription."""
        topic = self._topic_for(pub.topic_name, pub.msg_type, "a publisher", pub.node.fqn)
        topic.publishers[pub] = None
        for sub in topic.subscriptions:
            self._match(pub, sub)

    def add_subscription(self, sub: Subscription, *, replay: bool = True) -> None:
        """Register ``sub``, connect it, and replay transient-local history if it asks for it."""
        topic = self._topic_for(sub.topic_name, sub.msg_type, "a subscription", sub.node.fqn)
        topic.subscriptions[sub] = None
        sub._topic = topic
        for pub in topic.publishers:
            if self._match(pub, sub) and replay and pub._history:
                if sub.qos.durability == DurabilityPolicy.TRANSIENT_LOCAL:
                    for msg in pub._history:
                        sub._push(msg)

    def _match(self, pub: Publisher, sub: Subscription) -> bool:
        reason = qos_incompatibility(pub.qos, sub.qos)
        if reason is not None:
            self._on_incompatible(pub, sub, reason)
            return False
        pub._subs[sub] = None
        if sub._senders is not None:
            pub._tracked[sub] = None
        return True

    def replace_subscription(self, old: Subscription, new: Subscription) -> None:
        """Connect ``new`` to every publisher that fed ``old``, and forget ``old``.

        The restarted node's subscription moves to the end of the topic's
        order; the publishers that fed the old one feed the new one, whatever
        their QoS was matched against.
        """
        topic = self.topics[old.topic_name]
        del topic.subscriptions[old]
        topic.subscriptions[new] = None
        new._topic = topic
        for pub in topic.publishers:
            subs = pub._subs
            if old in subs:
                del subs[old]
                subs[new] = None
                pub._tracked.pop(old, None)  # the new one tracks again if it adopts the old one's senders

    def remove_publisher(self, pub: Publisher) -> None:
        """Forget ``pub``; drop the topic when it has no endpoint left.  O(1)."""
        topic = self.topics.get(pub.topic_name)
        if topic is not None and pub in topic.publishers:
            del topic.publishers[pub]
            pub._subs = {}
            pub._tracked = {}
            self._drop_if_empty(topic)

    def remove_subscription(self, sub: Subscription) -> None:
        """Forget ``sub``; drop the topic when it has no endpoint left.

        O(publishers of the topic): each publisher forgets it in O(1).
        """
        topic = self.topics.get(sub.topic_name)
        if topic is not None and sub in topic.subscriptions:
            del topic.subscriptions[sub]
            for pub in topic.publishers:
                pub._subs.pop(sub, None)
                pub._tracked.pop(sub, None)
            self._drop_if_empty(topic)

    def _drop_if_empty(self, topic: Topic) -> None:
        if not topic.publishers and not topic.subscriptions:
            del self.topics[topic.name]
