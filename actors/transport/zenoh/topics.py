"""Topics over Zenoh: local publishers out through outlets, remote samples in through inlets.

Out.  Each local publisher gets a Zenoh publisher on its topic's data key
(and an ``MP`` token).  A volatile one hears Zenoh's matching status: while
a subscriber elsewhere matches, an :class:`~actors.transport.seam.Outlet`
hangs on the publisher and each message is CDR-encoded once and put with its
attachment (sequence number from 1, source time, GID); with no remote
subscriber nothing is encoded.  A transient-local publisher is a zenoh-ext
advanced publisher whose cache keeps its last ``depth`` samples for late
joiners, so it always encodes.  QoS as rmw_zenoh maps it: RELIABLE is
reliable, KEEP_ALL + RELIABLE blocks when the network is congested (the
loop waits, as an rclcpp publish would), anything else drops.

In.  Each topic with local subscriptions gets one Zenoh subscriber (and an
``MS`` token per subscription); samples cross to the loop through the
handoff, in a backlog of the topic's largest subscription depth (KEEP_ALL:
:data:`KEEP_ALL_BACKLOG`), so that a peer that sends faster than the loop
decodes never grows the graph: a sample that finds the backlog full pushes
out the oldest.  For KEEP_LAST that is the sample the subscription's own
queue would have dropped; a KEEP_ALL queue drops nothing (nor does
rmw_zenoh's), so there it is a loss.  Either way the loss is counted in the
``dropped`` of the topic's local subscriptions (``topic info -v``,
``doctor``) and logged, the topic, the count and the bound named, within
the bounds of :mod:`.peer_warnings`.  Samples are decoded once and published to the local subscriptions by the
topic's :class:`~actors.transport.seam.Inlet`.  Where a local subscription
is transient-local, the subscriber is an advanced subscriber that fetches
the history of late-joining publishers' caches.  A sample whose payload or
attachment cannot be read is dropped, and logged within the bounds of
:mod:`.peer_warnings` (a few lines per key, whatever GIDs it claims).

Samples never loop back: publishers send to other sessions only, and
subscribers hear only other sessions (local delivery stays in-process).
"""

from __future__ import annotations

import functools
from collections import deque
from typing import Any

from actors import codec
from actors.ros.endpoint_info import wire_gids
from actors.ros.qos import DurabilityPolicy, HistoryPolicy, ReliabilityPolicy
from actors.ros.topics import Publisher, Subscription, Topic, TopicTable
from actors.transport.seam import Inlet, Outlet
from actors.transport.zenoh.attachment import pack, unpack
from actors.transport.zenoh.link import Endpoint, Link, peer_of

__all__ = ["TopicBridge"]

_HEARTBEAT = 0.5  # seconds: rmw_zenoh's sample-miss heartbeat for RELIABLE + TRANSIENT_LOCAL
KEEP_ALL_BACKLOG = 10_000
"""Samples of a topic that may wait for the loop when a local subscription keeps all."""


class _Out:
    """A local publisher on the wire."""

    __slots__ = ("endpoint", "zpub", "listener", "outlet", "sequence")

    def __init__(self, endpoint: Endpoint, zpub: Any, outlet: Outlet) -> None:
        self.endpoint = endpoint
        self.zpub = zpub
        self.listener: Any = None
        self.outlet = outlet
        self.sequence = 0


class _Backlog:
    """The samples of one subscriber waiting for the loop, the newest ``maxlen`` (Zenoh's thread appends)."""

    __slots__ = ("samples", "scheduled", "arrived", "taken", "lost")

    def __init__(self, maxlen: int) -> None:
        self.samples: deque[Any] = deque(maxlen=maxlen)
        self.scheduled = False  # a drain is on its way to the loop
        # Each counter has one writer: arrived Zenoh's thread, taken and lost the loop.  What
        # the deque pushed out is arrived - taken - waiting; the loop works it out, since a
        # length check on Zenoh's thread would count a sample popped between check and append.
        self.arrived = 0
        self.taken = 0
        self.lost = 0  # pushed out, as counted so far


class _In:
    """A topic's Zenoh subscriber and the inlet it feeds."""

    __slots__ = ("key", "zsub", "inlet", "history", "depth")

    def __init__(self, key: str, inlet: Inlet) -> None:
        self.key = key
        self.inlet = inlet
        self.zsub: Any = None
        self.history = 0  # samples fetched from late publishers' caches (0: a plain subscriber)
        self.depth = 0  # samples that may wait for the loop (see _backlog_bound)


class TopicBridge:
    """The topic side of a Zenoh transport."""

    def __init__(self, link: Link, table: TopicTable) -> None:
        self._link = link
        self._table = table
        self._outs: dict[Publisher, _Out] = {}
        self._subs: dict[str, dict[Subscription, Endpoint]] = {}  # by topic name
        self._ins: dict[str, _In] = {}  # by topic name

    # -- out ----------------------------------------------------------------------

    def add_publisher(self, pub: Publisher) -> None:
        """Put ``pub`` on the wire."""
        link = self._link
        endpoint = link.declare(pub.node.fqn, "MP", pub.topic_name, pub.msg_type, pub.qos)
        if endpoint is None:
            return
        wire_gids[pub] = endpoint.gid  # what a ROS 2 peer calls it, shown here too
        zenoh, qos = link.zenoh, pub.qos
        reliable = qos.reliability == ReliabilityPolicy.RELIABLE
        options: dict[str, Any] = {
            "congestion_control": zenoh.CongestionControl.BLOCK
            if reliable and qos.history == HistoryPolicy.KEEP_ALL
            else zenoh.CongestionControl.DROP,
            "reliability": zenoh.Reliability.RELIABLE if reliable else zenoh.Reliability.BEST_EFFORT,
            "allowed_destination": zenoh.Locality.REMOTE,
        }
        outlet = Outlet(link.hub, pub, self._send)
        if qos.durability == DurabilityPolicy.TRANSIENT_LOCAL:
            ext = zenoh.ext
            zpub = ext.declare_advanced_publisher(
                link.session,
                endpoint.key,
                cache=ext.CacheConfig(max_samples=qos.depth),
                publisher_detection=True,
                sample_miss_detection=ext.MissDetectionConfig(heartbeat=_HEARTBEAT) if reliable else None,
                **options,
            )
            out = self._outs[pub] = _Out(endpoint, zpub, outlet)
            outlet.attach()  # the cache must hold the history whoever listens now
            for msg in pub._history or ():  # what it published before the transport started
                self._send(pub, msg)
            return
        zpub = link.session.declare_publisher(endpoint.key, **options)
        out = self._outs[pub] = _Out(endpoint, zpub, outlet)
        handoff = link.handoff
        out.listener = zpub.declare_matching_listener(
            zenoh.handlers.Callback(lambda status: handoff.put(self._matched, (pub, status.matching)), indirect=False)
        )

    def _matched(self, change: tuple[Publisher, bool]) -> None:
        pub, matching = change
        out = self._outs.get(pub)
        if out is None:
            return
        if matching:
            out.outlet.attach()
        else:
            out.outlet.detach()

    def _send(self, pub: Publisher, msg: Any) -> None:
        # The outlet's callback, inside the publisher's publish(): encode once, put once for every remote subscriber.
        out = self._outs.get(pub)
        if out is None:
            return  # the publisher went away with messages still queued
        link = self._link
        try:
            payload = codec.encode_cdr(msg)
        except Exception as exc:  # a value CDR cannot carry: the publisher's problem, not the transport's
            link.warn_once(out.endpoint.key, "encode", f"cannot send {pub.topic_name} from {pub.node.fqn}: {exc}")
            return
        out.sequence += 1
        try:
            out.zpub.put(payload, attachment=pack(out.sequence, link.now_ns(), out.endpoint.gid))
        except Exception as exc:
            link.warn_once(out.endpoint.key, "put", f"cannot send {pub.topic_name}: {exc}")

    def remove_publisher(self, pub: Publisher) -> None:
        """Take ``pub`` off the wire."""
        out = self._outs.pop(pub, None)
        if out is None:
            return
        wire_gids.pop(pub, None)
        out.outlet.detach()
        if out.listener is not None:
            self._link.undeclare(out.listener)
        self._link.undeclare(out.zpub)
        self._link.withdraw(out.endpoint)

    # -- in -----------------------------------------------------------------------

    def add_subscription(self, topic: Topic, sub: Subscription) -> None:
        """Announce ``sub`` and make sure its topic hears other processes."""
        endpoint = self._link.declare(sub.node.fqn, "MS", sub.topic_name, sub.msg_type, sub.qos)
        if endpoint is None:
            return
        wire_gids[sub] = endpoint.gid
        self._subs.setdefault(topic.name, {})[sub] = endpoint
        incoming = self._ins.get(topic.name)
        if incoming is None:
            inlet = Inlet(self._link.hub, topic.name, topic.msg_type)
            incoming = self._ins[topic.name] = _In(endpoint.key, inlet)
            self._table.add_publisher(inlet)
        latched = sub.qos.durability == DurabilityPolicy.TRANSIENT_LOCAL
        history = max(incoming.history, sub.qos.depth if latched else 0)
        keeps = KEEP_ALL_BACKLOG if sub.qos.history == HistoryPolicy.KEEP_ALL else max(1, sub.qos.depth)
        if incoming.zsub is None or history > incoming.history or keeps > incoming.depth:
            incoming.depth = max(incoming.depth, keeps)
            self._listen(incoming, history)

    def _listen(self, incoming: _In, history: int) -> None:
        """(Re)declare the topic's subscriber, fetching up to ``history`` samples per late publisher."""
        link = self._link
        zenoh = link.zenoh
        if incoming.zsub is not None:
            link.undeclare(incoming.zsub)
        # Indirect: zenoh runs the callback on one long-lived Python thread of this subscriber.
        # Run on zenoh's own receive thread, each sample made and deleted a Python thread
        # state: a one-way burst across processes ran at a quarter of the speed.
        arrived = functools.partial(self._arrived, _Backlog(incoming.depth), incoming)
        callback = zenoh.handlers.Callback(arrived, indirect=True)
        if history:
            ext = zenoh.ext
            incoming.zsub = ext.declare_advanced_subscriber(
                link.session,
                incoming.key,
                callback,
                allowed_origin=zenoh.Locality.REMOTE,
                history=ext.HistoryConfig(detect_late_publishers=True, max_samples=history),
                recovery=ext.RecoveryConfig(heartbeat=True),
                subscriber_detection=True,
            )
        else:
            incoming.zsub = link.session.declare_subscriber(
                incoming.key, callback, allowed_origin=zenoh.Locality.REMOTE
            )
        incoming.history = history

    def _arrived(self, backlog: _Backlog, incoming: _In, sample: Any) -> None:
        # On zenoh's thread.  The loop may lag behind a peer that sends faster than it decodes:
        # only the newest ``depth`` samples wait; the drain counts what was pushed out.
        backlog.samples.append(sample)
        backlog.arrived += 1  # after the append: the drain's count may fall short until the next drain, never over
        if not backlog.scheduled:
            backlog.scheduled = True
            self._link.handoff.put(self._drain, (incoming, backlog))

    def _drain(self, item: tuple[_In, _Backlog]) -> None:
        incoming, backlog = item
        backlog.scheduled = False  # before taking: a sample appended from now on schedules another drain
        samples = backlog.samples
        taken = len(samples)
        backlog.taken += taken
        for _ in range(taken):
            self._deliver(incoming, samples.popleft())
        arrived = backlog.arrived  # read before the length: a sample appended in between makes the count short
        lost = arrived - backlog.taken - len(samples)
        if lost > backlog.lost:
            self._lost(incoming, lost - backlog.lost, samples.maxlen)
            backlog.lost = lost

    def _lost(self, incoming: _In, count: int, bound: int | None) -> None:
        # The loop fell behind: count the loss where ROS users look, and say it (a line per topic per window).
        name = incoming.inlet.topic_name
        if self._ins.get(name) is not incoming:
            return  # the topic stopped listening: nobody was waiting for them
        topic = self._table.topics.get(name)
        for sub in topic.subscriptions if topic is not None else ():
            sub.lost(count)
        why = "KEEP_ALL_BACKLOG" if bound == KEEP_ALL_BACKLOG else "the deepest subscription's depth"
        self._link.warnings.warn(
            incoming.key,
            "backlog",  # not a peer's doing: its own line, apart from malformed samples' lines
            f"dropped {count} sample(s) on {name}: they came faster than the graph could take them, "
            f"and at most {bound} may wait ({why}); counted in its subscriptions' dropped",
        )

    def _deliver(self, incoming: _In, sample: Any) -> None:
        if self._ins.get(incoming.inlet.topic_name) is not incoming:
            return  # the topic stopped listening while the sample crossed over
        link = self._link
        raw = sample.attachment
        origin = "?"
        msg: Any
        try:
            if raw is not None:
                origin = unpack(raw.to_bytes())[2].hex()
            msg = codec.decode_cdr(sample.payload.to_bytes(), incoming.inlet.msg_type)
        except Exception as exc:  # anything a peer sends: dropped, logged within the peer warnings' bounds
            link.warnings.warn(
                incoming.key,
                peer_of(sample),
                f"dropped a malformed sample on {incoming.key} (publisher {origin}, as it says): {exc}",
            )
            return
        incoming.inlet.publish(msg)

    def remove_subscription(self, topic: Topic, sub: Subscription) -> None:
        """Withdraw ``sub``; a topic left with no local subscription stops listening."""
        tracked = self._subs.get(topic.name, {})
        # ``sub``, or else what a restarted node's subscription replaced unheard
        gone = [sub] if sub in tracked else [s for s in tracked if s not in topic.subscriptions]
        for old in gone:
            self._link.withdraw(tracked.pop(old))
            wire_gids.pop(old, None)
        if not tracked:
            self._subs.pop(topic.name, None)
            # Not from inside the table's own removal: the table is still dropping ``sub``.
            self._link.loop.call_soon(self._stop_listening, topic.name)

    def _stop_listening(self, name: str) -> None:
        incoming = self._ins.get(name)
        if incoming is None or name in self._subs:
            return
        del self._ins[name]
        self._link.undeclare(incoming.zsub)
        self._table.remove_publisher(incoming.inlet)

    def close(self) -> None:
        """Take everything off the wire (the session is about to close)."""
        for pub in list(self._outs):
            self.remove_publisher(pub)
        for tracked in self._subs.values():
            for sub, endpoint in tracked.items():
                self._link.withdraw(endpoint)
                wire_gids.pop(sub, None)
        self._subs.clear()
        for name in list(self._ins):
            incoming = self._ins.pop(name)
            self._link.undeclare(incoming.zsub)
            self._table.remove_publisher(incoming.inlet)
