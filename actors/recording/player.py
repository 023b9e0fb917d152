"""Playing a bag back: which topics can be played and as what, the messages in order, and an in-graph player.

:func:`plan` decides, once per topic, whether it can be played here: its type
must be known (``interfaces/``, a workspace, or the bag's own schemas) and the same as recorded (its RIHS01 hash), and
its encoding CDR; each topic that cannot is named in one line and skipped.
:func:`timeline` gives the decoded messages in the bag's order with their
times, and ``/clock`` ticks (``rosgraph_msgs/Clock``) when asked.  :func:`play`
publishes them into a runtime at their recorded offsets on the runtime's
clock: on virtual time a 30 s bag takes as long as the graph needs to handle
it, not 30 s.  ``actors bag play`` sends the same timeline to a running graph
through its control endpoint.
"""

from __future__ import annotations

import asyncio
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, cast

import yaml

from actors import codec
from actors.core._actor import Actor, Owner
from actors.errors import ActorsError, InterfaceError
from actors.messages.discovery import add_definitions
from actors.recording.reader import Bag
from actors.ros.names import expand
from actors.ros.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from actors.ros.topics import Publisher

if TYPE_CHECKING:
    from actors.runtime import Runtime

__all__ = ["PlayTopic", "plan", "timeline", "play", "parse_remaps", "CLOCK_TOPIC"]

CLOCK_TOPIC = "/clock"


@dataclass
class PlayTopic:
    """A recorded topic that will be played: where to (after remapping), its type and QoS."""

    name: str
    target: str
    msg_type: type[Any]
    qos: QoSProfile


def parse_remaps(remaps: Iterable[str]) -> dict[str, str]:
    """``["a:=b", ...]`` as ``{"/a": "/b"}``; ValueError naming a malformed one."""
    found = {}
    for item in remaps:
        old, sep, new = item.partition(":=")
        if not sep or not old or not new:
            raise ValueError(f"a remap is FROM:=TO, got {item!r}")
        found[expand(old, "/", "_")] = expand(new, "/", "_")
    return found


def plan(
    bag: Bag, *, topics: Iterable[str] | None = None, remap: Mapping[str, str] | None = None
) -> tuple[dict[str, PlayTopic], list[str]]:
    """The playable topics of ``bag`` by recorded name, and one line for each topic skipped.

    ``topics`` limits playing to those names (all when None); ``remap`` maps
    recorded names to the names to publish on.
    """
    wanted = {expand(t, "/", "_") for t in topics} if topics is not None else None
    remap = dict(remap or {})
    playable: dict[str, PlayTopic] = {}
    skipped: list[str] = []
    for topic in bag.topics:
        if wanted is not None and topic.name not in wanted:
            continue
        reason = None
        msg_type = None
        if topic.serialization_format != "cdr":
            reason = f"its messages are {topic.serialization_format!r}, not cdr"
        else:
            try:
                if topic.definition:
                    add_definitions(topic.type, topic.definition)  # a type of elsewhere: typed from the bag
                msg_type = codec.get_type(topic.type)
                if topic.type_hash and topic.type_hash != codec.type_hash(msg_type):
                    reason = f"{topic.type} here is not the type it was recorded with (its type hash differs)"
            except (InterfaceError, TypeError, ValueError):
                reason = f"unknown type {topic.type or '(none)'}"
        if reason is not None or msg_type is None:
            skipped.append(f"skipping {topic.name}: {reason} ({topic.count} message(s))")
            continue
        playable[topic.name] = PlayTopic(
            name=topic.name,
            target=remap.get(topic.name, topic.name),
            msg_type=msg_type,
            qos=_qos(topic.offered_qos_profiles),
        )
    return playable, skipped


def _qos(text: str) -> QoSProfile:
    """The first recorded publisher's QoS (rosbag2's offered_qos_profiles), else the default."""
    try:
        profiles = yaml.safe_load(text) if text else None
        first = profiles[0] if isinstance(profiles, list) and profiles else None
        if not isinstance(first, dict):
            return QoSProfile(depth=10)
        keep_all = str(first.get("history")) in ("keep_all", "2")
        return QoSProfile(
            depth=max(1, int(first.get("depth") or 10)),
            history=HistoryPolicy.KEEP_ALL if keep_all else HistoryPolicy.KEEP_LAST,
            reliability=(
                ReliabilityPolicy.BEST_EFFORT
                if str(first.get("reliability")) in ("best_effort", "2")
                else ReliabilityPolicy.RELIABLE
            ),
            durability=(
                DurabilityPolicy.TRANSIENT_LOCAL
                if str(first.get("durability")) in ("transient_local", "1")
                else DurabilityPolicy.VOLATILE
            ),
        )
    except (yaml.YAMLError, TypeError, ValueError):
        return QoSProfile(depth=10)


def timeline(
    bag: Bag, playable: Mapping[str, PlayTopic], *, clock_hz: float = 0.0
) -> Iterator[tuple[int, PlayTopic | None, Any]]:
    """``(log time ns, topic, message)`` in the bag's order; ``topic`` None is a ``/clock`` tick.

    With ``clock_hz``, a ``rosgraph_msgs/Clock`` of the bag's time comes every
    ``1/clock_hz`` seconds of bag time, from the first message on.  Raises
    CdrError naming the topic when a recorded message does not decode.
    """
    clock_type = codec.get_type("rosgraph_msgs/msg/Clock") if clock_hz > 0 else None
    step = int(1e9 / clock_hz) if clock_hz > 0 else 0
    next_tick: int | None = None
    for item in bag.messages(playable):
        topic = playable[item.topic.name]
        if clock_type is not None:
            if next_tick is None:
                next_tick = item.log_time
            while next_tick <= item.log_time:
                tick = clock_type()
                tick.clock.sec, tick.clock.nanosec = divmod(next_tick, 1_000_000_000)
                yield next_tick, None, tick
                next_tick += step
        try:
            msg = codec.decode_cdr(item.data, topic.msg_type)
        except ActorsError as exc:
            raise type(exc)(f"{topic.name} at {item.log_time} ns: {exc}") from None
        yield item.log_time, topic, msg


class _PlayerOwner:
    """The hidden owner of the player's publishers (``/_actors_player``)."""

    def __init__(self, runtime: Runtime) -> None:
        self.runtime = runtime
        self.fqn = "/_actors_player"
        self.loop = runtime.loop
        self.actor = Actor(runtime.loop)
        self.logger = runtime.logger

    def destroy_publisher(self, publisher: Any) -> None:
        self.runtime.topics.remove_publisher(publisher)


async def play(
    runtime: Runtime,
    bag: Bag,
    *,
    topics: Iterable[str] | None = None,
    remap: Mapping[str, str] | None = None,
    rate: float = 1.0,
    clock_hz: float = 0.0,
    loop: bool = False,
) -> int:
    """Publish ``bag``'s messages into ``runtime`` at their recorded offsets; return how many.

    The first message goes out at once, each next one when the runtime's
    clock has moved as far as the bag's did (divided by ``rate``).  Each topic
    is published with the QoS its first recorder saw offered.  Topics that
    cannot be played are logged (one warning each) and skipped.  ``loop``
    plays the bag again and again until cancelled.  Publishers are removed
    when it returns or is cancelled.
    """
    if rate <= 0:
        raise ValueError(f"rate must be > 0, got {rate}")
    playable, skipped = plan(bag, topics=topics, remap=remap)
    for line in skipped:
        runtime.logger.warning(f"bag play: {line}")
    # A partial owner: its publishers are destroyed through destroy_publisher only.
    owner = cast(Owner, _PlayerOwner(runtime))
    publishers: dict[str, Publisher] = {}
    count = 0
    aio_loop = runtime.loop
    try:
        while True:
            start = aio_loop.time()
            first: int | None = None
            for stamp, topic, msg in timeline(bag, playable, clock_hz=clock_hz):
                if first is None:
                    first = stamp
                due = start + (stamp - first) / 1e9 / rate
                if due > aio_loop.time():
                    woken = aio_loop.create_future()
                    handle = aio_loop.call_at(due, _wake, woken)
                    try:
                        await woken
                    finally:
                        handle.cancel()
                name, msg_type, qos = (
                    (CLOCK_TOPIC, type(msg), QoSProfile(depth=10))
                    if topic is None
                    else (topic.target, topic.msg_type, topic.qos)
                )
                pub = publishers.get(name)
                if pub is None:
                    pub = publishers[name] = Publisher(owner, name, msg_type, qos)
                    runtime.topics.add_publisher(pub)
                pub.publish(msg)
                count += topic is not None
            if not loop or first is None:
                return count
    finally:
        for pub in publishers.values():
            runtime.topics.remove_publisher(pub)


def _wake(future: asyncio.Future[None]) -> None:
    if not future.done():
        future.set_result(None)
