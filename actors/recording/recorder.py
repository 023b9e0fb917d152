"""The recorder: a tap on a graph's published messages that writes them into a ROS 2 bag (MCAP).

``Runtime(attach=[Recorder("run.mcap")])`` (``python -m actors.run GRAPH
--record run.mcap``) records every topic, or those named, from the moment it
appears: the recorder hears of new topics through the topic table's graph
events (``TopicTable.listeners``) and subscribes to each with a *tap*.

The tap is a subscription that never runs a callback: ``publish()`` delivers
to it as to any subscription, and its queue is a stamper that puts
``(tap, runtime clock in ns, message)`` on the recorder's buffer.  So a graph
with no recorder pays nothing (``publish()`` has no recording branch), and a
recorded message carries the time it was published.  The messages are the
snapshots ``publish()`` delivers to every subscriber, so the recorder can
encode them later.

A writer task takes the buffer a batch at a time, encodes each message as CDR
and writes it into the MCAP file (:mod:`actors.recording.mcap_writer`).  On the
wall clock it works in a worker thread, so the disk never holds up the loop;
when the buffer is full (the disk cannot keep up), a tap drops the message and
counts it on its subscription (``topic info -v``, ``doctor``), and the recorder
logs a warning.  On virtual time it writes in the loop itself: virtual time
does not wait for the disk, the recording is complete and the same graph gives
the same file, byte for byte.

When a write fails (a full disk), the file is closed valid at its last whole
chunk, the recorder leaves the graph, and the graph keeps running.
"""

from __future__ import annotations

import asyncio
import re
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import anyio
import anyio.abc

from actors import codec
from actors.actor import Actor
from actors.names import expand, is_hidden_name
from actors.recording.bag_writer import BagWriter
from actors.topics import (
    DurabilityPolicy,
    Expiring,
    Publisher,
    QoSProfile,
    ReliabilityPolicy,
    Subscription,
    Topic,
    type_name,
)

if TYPE_CHECKING:
    from actors.runtime import Runtime

__all__ = ["Recorder", "RECORDER_NODE"]

RECORDER_NODE = "/_actors_recorder"
"""The hidden owner of the recorder's subscriptions, as ``topic info`` and doctor name it."""


class Recorder:
    """The attachment that records topics into a bag: ``Runtime(attach=[Recorder("run.mcap")])``.

    ``output`` ending in ``.mcap`` is one MCAP file; any other name is a
    rosbag2 bag directory (``NAME/NAME_0.mcap`` and ``metadata.yaml``).
    ``topics`` names the topics to record (all when empty); ``exclude`` is a
    regular expression of topic names to leave out; hidden topics (a part
    starting with ``_``, e.g. an action's) only with ``include_hidden``.
    ``compression`` is ``zstd``, ``lz4`` or ``""``; ``max_pending`` bounds the
    messages waiting for the disk (more are dropped and counted).

    :meth:`open` creates the file (the runtime calls it when it starts, if no
    one did before), raising FileExistsError, FileNotFoundError or OSError.
    """

    def __init__(
        self,
        output: str | Path,
        *,
        topics: Sequence[str] = (),
        exclude: str | None = None,
        include_hidden: bool = False,
        compression: str = "zstd",
        chunk_size: int = 1 << 20,
        max_pending: int = 100_000,
    ) -> None:
        self.output = Path(output)
        self.topics = frozenset(expand(t, "/", "_") for t in topics)
        self.exclude = re.compile(exclude) if exclude else None
        self.include_hidden = include_hidden
        self.compression = compression
        self.chunk_size = chunk_size
        self.max_pending = max_pending
        self.path: Path | None = None  # the MCAP file, once open
        self._writer: BagWriter | None = None
        self._taps: dict[str, _Tap] = {}
        self._retired: list[_Tap] = []  # taps of topics that went away: their channels stay
        self._items: list[tuple[_Tap, int, Any]] = []
        self._waiter: asyncio.Future[None] | None = None
        self._runtime: Runtime | None = None
        self._owner: _RecorderOwner | None = None
        self.dropped = 0
        self._dropped_reported = 0
        self._failed = False

    # -- what is recorded ---------------------------------------------------------

    def wants(self, topic: str) -> bool:
        """Whether ``topic`` is to be recorded by the selection given."""
        if self.topics:
            return topic in self.topics
        if is_hidden_name(topic) and not self.include_hidden:
            return False
        return not (self.exclude is not None and self.exclude.search(topic))

    @property
    def message_count(self) -> int:
        """Messages written into the file so far (whole chunks)."""
        return self._writer.message_count if self._writer is not None else 0

    @property
    def bytes_written(self) -> int:
        """Bytes in the file so far."""
        return self._writer.size if self._writer is not None else 0

    # -- lifecycle ----------------------------------------------------------------

    def open(self) -> Path:
        """Create the bag (directory and MCAP file); returns the MCAP file's path."""
        if self._writer is None:
            self._writer = BagWriter(self.output, compression=self.compression, chunk_size=self.chunk_size)
            self.path = self._writer.path
        return self._writer.path

    async def __call__(
        self, runtime: Runtime, *, task_status: anyio.abc.TaskStatus[Any] = anyio.TASK_STATUS_IGNORED
    ) -> None:
        self.open()
        self._runtime = runtime
        self._owner = _RecorderOwner(runtime)
        runtime.topics.listeners.append(self)
        try:
            for topic in list(runtime.topics.topics.values()):
                self._consider(topic)
            task_status.started()
            await self._drain(runtime)
        finally:
            with anyio.CancelScope(shield=True):
                self._finish(runtime)

    async def _drain(self, runtime: Runtime) -> None:
        loop = runtime.loop
        inline = runtime.clock.virtual
        writer = self._writer
        assert writer is not None
        while writer.error is None:
            if not self._items:
                self._waiter = loop.create_future()
                await self._waiter
            batch, self._items = self._items, []
            if inline:
                failures = self._write(batch)
            else:
                failures = await anyio.to_thread.run_sync(self._write, batch)
            self._after_batch(runtime, failures)
        self._stopped(runtime)
        self._detach(runtime)
        await anyio.sleep_forever()

    def _after_batch(self, runtime: Runtime, failures: list[tuple[_Tap, Exception]]) -> None:
        for tap, exc in failures:
            tap.dropped += 1
            if not tap.failed:
                tap.failed = True
                runtime.logger.warning(f"recorder: a message on {tap.topic_name} cannot be written: {exc}")
        if self.dropped != self._dropped_reported:
            runtime.logger.warning(
                f"recorder: dropped {self.dropped - self._dropped_reported} message(s): "
                f"the disk cannot keep up ({self.dropped} in all)",
                throttle_duration_sec=1.0,
            )
            self._dropped_reported = self.dropped

    def _finish(self, runtime: Runtime) -> None:
        """Write what is still buffered, then end the file (and metadata.yaml)."""
        self._detach(runtime)
        writer = self._writer
        if writer is None:
            return
        batch, self._items = self._items, []
        self._write(batch)
        for tap in self._all_taps():
            if tap.channel is None and writer.error is None:
                self._register(tap)  # listed with no messages, as rosbag2 lists a quiet topic
        try:
            writer.close()
        except OSError as exc:
            runtime.logger.error(f"recorder: cannot write the bag's metadata.yaml: {exc}")
        if writer.error is not None and not self._failed:
            self._stopped(runtime)

    def _stopped(self, runtime: Runtime) -> None:
        """Say once that the disk failed: what the bag keeps, and that the graph goes on."""
        self._failed = True
        assert self._writer is not None and self._writer.error is not None
        error = self._writer.error
        runtime.logger.error(
            f"recording to {self.path} stopped: {error.strerror or error}; the bag keeps the "
            f"{self._writer.message_count} message(s) written before, the graph runs on"
        )

    def _all_taps(self) -> list[_Tap]:
        return [*self._retired, *self._taps.values()]

    def _detach(self, runtime: Runtime) -> None:
        if self in runtime.topics.listeners:
            runtime.topics.listeners.remove(self)
        for tap in list(self._taps.values()):
            runtime.topics.remove_subscription(tap)
            self._retired.append(tap)
        self._taps.clear()

    # -- graph events (TopicListener) -----------------------------------------------

    def endpoint_added(self, topic: Topic, endpoint: Publisher | Subscription) -> None:
        """A new endpoint: tap its topic if it is wanted and new; note a publisher's QoS."""
        if endpoint.node is self._owner:
            return
        tap = self._taps.get(topic.name)
        if tap is None:
            self._consider(topic)
        elif isinstance(endpoint, Publisher):
            tap.offers = (*tap.offers, endpoint.qos)

    def endpoint_removed(self, topic: Topic, endpoint: Publisher | Subscription) -> None:
        """An endpoint went away: untap a topic that only the recorder still holds (soon after)."""
        tap = self._taps.get(topic.name)
        if tap is not None and endpoint is not tap and self._runtime is not None:
            # Not now: the table is still removing; a topic held by the tap alone would
            # outlive its nodes (and refuse a later topic of another type by that name).
            self._runtime.loop.call_soon(self._retire_if_alone, topic.name)

    def _retire_if_alone(self, name: str) -> None:
        runtime, tap = self._runtime, self._taps.get(name)
        if runtime is None or tap is None:
            return
        topic = runtime.topics.topics.get(name)
        if topic is not None and not topic.publishers and list(topic.subscriptions) == [tap]:
            del self._taps[name]
            runtime.topics.remove_subscription(tap)
            self._retired.append(tap)

    def _consider(self, topic: Topic) -> None:
        runtime, owner = self._runtime, self._owner
        if runtime is None or owner is None or not self.wants(topic.name):
            return
        if self._writer is None or self._writer.error is not None:
            return
        previous = next(
            (t for t in self._retired if t.topic_name == topic.name and t.msg_type is topic.msg_type), None
        )
        try:
            tap = _Tap(owner, topic, self, previous)
        except Exception as exc:  # a type with no ROS definition: say so once, record the rest
            runtime.logger.warning(f"recorder: not recording {topic.name}: {exc}")
            return
        if previous is not None:  # the topic is back with its type: its channel goes on
            self._retired.remove(previous)
        self._taps[topic.name] = tap
        runtime.topics.add_subscription(tap, replay=False)
        now = runtime.loop.time()
        for pub in topic.publishers:  # a latched topic's history, as a late subscriber gets it
            for msg in pub._history or ():
                if isinstance(msg, Expiring):
                    if msg.expires <= now:
                        continue
                    msg = msg.msg
                tap._push(msg)

    # -- the writer side ------------------------------------------------------------

    def _wake(self) -> None:
        waiter = self._waiter
        if waiter is not None:
            self._waiter = None
            if not waiter.done():
                waiter.set_result(None)

    def _write(self, batch: list[tuple[_Tap, int, Any]]) -> list[tuple[_Tap, Exception]]:
        """Encode and write one batch (in a worker thread on the wall clock); returns the failures."""
        writer = self._writer
        assert writer is not None
        encode = codec.encode_cdr
        add = writer.write
        failures = []
        for tap, stamp, msg in batch:
            channel = tap.channel
            if channel is None:
                channel = self._register(tap)
            try:
                data = encode(msg)
            except Exception as exc:  # a message its type cannot carry: counted, never fatal
                failures.append((tap, exc))
                continue
            add(channel, stamp, data)
        return failures

    def _register(self, tap: _Tap) -> int:
        assert self._writer is not None
        tap.channel = self._writer.add_topic(
            tap.topic_name, tap.ros_type, definition=tap.definition, type_hash=tap.type_hash, offers=tap.offers
        )
        return tap.channel


class _RecorderOwner:
    """The hidden owner of the recorder's taps (``topic info`` shows ``/_actors_recorder``)."""

    def __init__(self, runtime: Runtime) -> None:
        self.runtime = runtime
        self.fqn = RECORDER_NODE
        self.loop = runtime.loop
        self.actor = Actor(runtime.loop)  # never runs: taps are never scheduled
        self.logger = runtime.logger

    def destroy_subscription(self, subscription: Any) -> None:
        self.runtime.topics.remove_subscription(subscription)


class _Stamper:
    """A tap's queue: ``append`` stamps the message and hands it to the recorder, or drops it."""

    __slots__ = ("tap", "recorder", "now_ns")

    def __init__(self, tap: _Tap, recorder: Recorder, now_ns: Any) -> None:
        self.tap = tap
        self.recorder = recorder
        self.now_ns = now_ns

    def __len__(self) -> int:
        return 0

    # A publisher with a lifespan wraps what it has just queued (``queue[-1]``) in an
    # expiry: a recorded message never expires (it is stamped when published), so the
    # wrapping is let go by.
    def __getitem__(self, index: int) -> None:
        return None

    def __setitem__(self, index: int, value: Any) -> None:
        pass

    def append(self, msg: Any) -> None:
        recorder = self.recorder
        items = recorder._items
        if len(items) >= recorder.max_pending:
            self.tap.dropped += 1
            recorder.dropped += 1
            return
        if not items:
            recorder._wake()
        items.append((self.tap, self.now_ns(), msg))


class _Tap(Subscription):
    """The recorder's subscription on one topic; never scheduled, its queue is a :class:`_Stamper`.

    Best effort and volatile, so it matches every publisher (as rosbag2 adapts
    its subscription to what publishers offer).
    """

    __slots__ = ("channel", "offers", "ros_type", "definition", "type_hash", "failed")

    def __init__(self, owner: _RecorderOwner, topic: Topic, recorder: Recorder, previous: _Tap | None) -> None:
        self.ros_type = type_name(topic.msg_type)
        self.definition = codec.definition_text(topic.msg_type)
        self.type_hash = codec.type_hash(topic.msg_type)
        qos = QoSProfile(
            depth=recorder.max_pending, reliability=ReliabilityPolicy.BEST_EFFORT,
            durability=DurabilityPolicy.VOLATILE,
        )
        super().__init__(owner, topic.name, topic.msg_type, _no_callback, qos)  # type: ignore[arg-type]
        self.channel: int | None = previous.channel if previous is not None else None
        self.offers: tuple[QoSProfile, ...] = tuple(p.qos for p in topic.publishers)
        self.failed = False
        self._queue = _Stamper(self, recorder, owner.runtime.clock.now_ns)
        self._limit = sys.maxsize
        self._scheduled = True  # never on the actor's ready queue


def _no_callback(msg: Any) -> None:  # pragma: no cover - a tap is never scheduled
    raise AssertionError("a recorder tap runs no callback")
