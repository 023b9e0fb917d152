"""Taps: subscriptions that hand every message published on a topic to a sink, and the set that follows the graph.

A tap is a subscription that never runs a callback and is never fed: each
publisher matched to it wraps its snapshot function (``Subscription._wrap``)
in one that hands every snapshot at once to the tap set's ``deliver(tap,
msg)``, or to what its ``wrap(tap, snapshot)`` makes of it (the recorder's
stamps and buffers the message in that one function).  So a graph with no
recorder and no live view pays nothing (``publish()`` has no branch for them),
a tapped publisher keeps its path to its subscriptions (one queue, a batch),
and the sink sees each message when it is published (to stamp it with the
runtime clock).  The messages are the snapshots ``publish()`` gives every
subscriber, so a sink may encode them later.

A :class:`TapSet` hears of topics through the topic table's graph events
(``TopicTable.listeners``) and taps each wanted topic from its first
endpoint; it is shared by the recorder and the Foxglove view.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, cast

from actors import codec
from actors.core._actor import Actor, Owner
from actors.ros.qos import DurabilityPolicy, QoSProfile, QoSSnapshot, ReliabilityPolicy
from actors.ros.topics import Expiring, Publisher, Subscription, Topic, type_name

if TYPE_CHECKING:
    from actors.runtime import Runtime

__all__ = ["Tap", "TapSet", "latched"]

Deliver = Callable[["Tap", Any], None]
Snapshot = Callable[[Any], Any]
Wrap = Callable[["Tap", Snapshot], Snapshot]


class TapSet:
    """The taps of one sink (a recorder, a live view) on every topic ``wants(name)`` accepts.

    ``node`` is the hidden owner's name (``topic info`` shows it), ``depth``
    the taps' QoS depth, ``label`` what the log calls the sink; ``tapped(tap)``
    is told of each new tap before its first message.  ``wrap(tap, snapshot)``,
    if given, returns a publisher's snapshot function that also takes each
    snapshot for ``tap`` (it stands for ``deliver``, which still takes what a
    late subscriber would get).  :meth:`start`
    taps what exists and follows the graph; :meth:`stop` removes every tap
    (:meth:`all` still lists them).  A topic that comes back with its type gets
    its old tap's ``channel``, so a sink keeps one channel per topic.
    """

    def __init__(
        self,
        node: str,
        wants: Callable[[str], bool],
        deliver: Deliver,
        *,
        depth: int = 1000,
        label: str = "tap",
        tapped: Callable[[Tap], None] | None = None,
        wrap: Wrap | None = None,
    ) -> None:
        self.node = node
        self.label = label
        self.tapped = tapped
        self.wants = wants
        self.deliver = deliver
        self.wrap = wrap or _delivering(deliver)
        self.depth = depth
        self.taps: dict[str, Tap] = {}
        self._retired: list[Tap] = []  # taps of topics that went away
        self._runtime: Runtime | None = None
        self._owner: TapOwner | None = None

    def all(self) -> list[Tap]:
        """Every tap made so far, current or retired."""
        return [*self._retired, *self.taps.values()]

    def start(self, runtime: Runtime) -> None:
        """Tap the wanted topics that exist, and those that appear from now on."""
        self._runtime = runtime
        self._owner = TapOwner(runtime, self.node)
        runtime.topics.listeners.append(self)
        for topic in list(runtime.topics.topics.values()):
            self._consider(topic)

    def stop(self) -> None:
        """Stop following the graph and remove every tap."""
        runtime = self._runtime
        if runtime is None:
            return
        if self in runtime.topics.listeners:
            runtime.topics.listeners.remove(self)
        for tap in list(self.taps.values()):
            runtime.topics.remove_subscription(tap)
            self._retired.append(tap)
        self.taps.clear()

    # -- graph events (TopicListener) -------------------------------------------------

    def endpoint_added(self, topic: Topic, endpoint: Publisher | Subscription) -> None:
        """A new endpoint: tap its topic if it is wanted and new; note a publisher's QoS."""
        if endpoint.node is self._owner:
            return
        tap = self.taps.get(topic.name)
        if tap is None:
            self._consider(topic)
        elif isinstance(endpoint, Publisher):
            tap.offers = (*tap.offers, endpoint.qos)

    def endpoint_removed(self, topic: Topic, endpoint: Publisher | Subscription) -> None:
        """An endpoint went away: untap a topic that only the tap still holds (soon after)."""
        tap = self.taps.get(topic.name)
        if tap is not None and endpoint is not tap and self._runtime is not None:
            # Not now: the table is still removing; a topic held by the tap alone would
            # outlive its nodes (and refuse a later topic of another type by that name).
            self._runtime.loop.call_soon(self._retire_if_alone, topic.name)

    def _retire_if_alone(self, name: str) -> None:
        runtime, tap = self._runtime, self.taps.get(name)
        if runtime is None or tap is None:
            return
        topic = runtime.topics.topics.get(name)
        if topic is not None and not topic.publishers and list(topic.subscriptions) == [tap]:
            del self.taps[name]
            runtime.topics.remove_subscription(tap)
            self._retired.append(tap)

    def _consider(self, topic: Topic) -> None:
        runtime, owner = self._runtime, self._owner
        if runtime is None or owner is None or not self.wants(topic.name):
            return
        previous = next((t for t in self._retired if t.topic_name == topic.name and t.msg_type is topic.msg_type), None)
        try:
            tap = Tap(owner, topic, self.deliver, self.wrap, self.depth)
        except Exception as exc:  # a type with no ROS definition: say so once, tap the rest
            runtime.logger.warning(f"{self.label}: leaving out {topic.name}: {exc}")
            return
        if previous is not None:  # the topic is back with its type: its channel goes on
            self._retired.remove(previous)
            tap.channel = previous.channel
        if self.tapped is not None:
            self.tapped(tap)
        self.taps[topic.name] = tap
        runtime.topics.add_subscription(tap, replay=False)
        for msg in latched(topic, runtime.loop.time()):  # as a late subscriber gets them
            tap._push(msg)


def _delivering(deliver: Deliver) -> Wrap:
    """The wrap of a sink that only has ``deliver``: the snapshot, then ``deliver(tap, snapshot)``."""

    def wrap(tap: Tap, snapshot: Snapshot) -> Snapshot:
        def tapped(msg: Any) -> Any:
            msg = snapshot(msg)
            deliver(tap, msg)
            return msg

        return tapped

    return wrap


def latched(topic: Topic, now: float) -> list[Any]:
    """What a late transient-local subscriber of ``topic`` gets now: its publishers' histories, less what expired."""
    found = []
    for pub in topic.publishers:
        for msg in pub._history or ():
            if isinstance(msg, Expiring):
                if msg.expires <= now:
                    continue
                msg = msg.msg
            found.append(msg)
    return found


class TapOwner:
    """The hidden owner of a tap set's subscriptions (``topic info`` shows its ``node``)."""

    def __init__(self, runtime: Runtime, node: str) -> None:
        self.runtime = runtime
        self.fqn = node
        self.loop = runtime.loop
        self.actor = Actor(runtime.loop)  # never runs: taps are never scheduled
        self.logger = runtime.logger

    def destroy_subscription(self, subscription: Any) -> None:
        self.runtime.topics.remove_subscription(subscription)


class _Handover:
    """A tap's queue: ``append`` hands the message to the sink at once; nothing is ever queued.

    Publishers never feed a tap through it (they wrap their snapshot function, see ``Tap._wrap``);
    it stands in for the deque that code reading every subscription's queue expects.
    """

    __slots__ = ("tap", "deliver")

    def __init__(self, tap: Tap, deliver: Deliver) -> None:
        self.tap = tap
        self.deliver = deliver

    def __len__(self) -> int:
        return 0

    # A publisher with a lifespan wraps what it has just queued (``queue[-1]``) in an
    # expiry: a tapped message never expires (the sink has it already), so the
    # wrapping is let go by.
    def __getitem__(self, index: int) -> None:
        return None

    def __setitem__(self, index: int, value: Any) -> None:
        pass

    def append(self, msg: Any) -> None:
        self.deliver(self.tap, msg)


class Tap(Subscription):
    """A tap on one topic: never scheduled nor fed; its publishers hand it each snapshot they make.

    Best effort and volatile, so it matches every publisher (as rosbag2 adapts
    its subscription to what publishers offer).  ``channel`` is the sink's
    (an MCAP channel id, a Foxglove channel), and so is ``encode`` (how it
    encodes the tap's messages, once it has looked that up); ``offers`` the
    publishers' QoS; ``failed`` is set by a sink once it has said that a
    message could not be taken.
    """

    __slots__ = ("channel", "encode", "offers", "ros_type", "definition", "type_hash", "failed", "_deliver", "_wraps")

    def __init__(self, owner: TapOwner, topic: Topic, deliver: Deliver, wrap: Wrap, depth: int) -> None:
        self.ros_type = type_name(topic.msg_type)
        self.definition = codec.definition_text(topic.msg_type)
        self.type_hash = codec.type_hash(topic.msg_type)
        qos = QoSProfile(depth=depth, reliability=ReliabilityPolicy.BEST_EFFORT, durability=DurabilityPolicy.VOLATILE)
        # A partial owner: a tap is destroyed through destroy_subscription only.
        super().__init__(cast(Owner, owner), topic.name, topic.msg_type, _no_callback, qos)
        self.channel: Any = None
        self.encode: Any = None
        self.offers: tuple[QoSSnapshot, ...] = tuple(p.qos for p in topic.publishers)
        self.failed = False
        self._deliver = deliver
        self._wraps = wrap
        self._queue = _Handover(self, deliver)  # type: ignore[assignment]  # stands in for the deque: only append() is used
        self._limit = sys.maxsize
        self._scheduled = True  # never on the actor's ready queue

    def lost(self, count: int) -> None:
        """Nothing: a tap's ``dropped`` is its sink's own count (the bag's metadata, doctor's "the
        disk could not keep up"); what a transport lost before the topic, it reports itself."""
        return None

    def _wrap(self, snapshot: Snapshot) -> Snapshot:
        """A publisher's snapshot function that also hands this tap each snapshot (Publisher._refeed)."""
        return self._wraps(self, snapshot)

    def _push(self, msg: Any) -> None:
        # What a late subscriber gets (TapSet._consider): straight to the sink.
        self._deliver(self, msg)


def _no_callback(msg: Any) -> None:  # pragma: no cover - a tap is never scheduled
    raise AssertionError("a tap runs no callback")
