"""The recorder: a tap on a graph's published messages that writes them into a ROS 2 bag (MCAP).

``Runtime(attach=[Recorder("run.mcap")])`` (``python -m actors.run GRAPH
--record run.mcap``) records every topic, or those named, from the moment it
appears, through a :class:`~actors.recording.tap.TapSet`: each tapped message
is stamped with the runtime clock when it is published and put on the
recorder's buffer, inside the publisher's snapshot function (one call more
per message, see :meth:`Recorder._wrap`).

A writer task takes the buffer a batch at a time, encodes each message as CDR
and writes it into the MCAP file (:mod:`actors.recording.mcap_writer`).  On the
wall clock it works in a worker thread, so the disk does not hold up the loop
while the buffer has room; it takes a batch worth the hop to that thread (a
quarter of the buffer, at most 1024 messages) or, in a trickle, what waits once
the oldest is due in the file.  When the buffer is full (the disk cannot keep up),
the publisher waits: the message that finds it full writes the whole buffer
itself, in the loop's thread, once the worker is done with its batch.  A bag
is never missing a message its graph published.  Only a recorder made
``lossy`` drops the message instead: counted on its tap (``topic info -v``,
``doctor``), written into the bag (``bag info``) and logged.  On virtual time
it writes in the loop itself: virtual time does not wait for the disk, the
recording is complete and the same graph gives the same file, byte for byte.

When a write fails (a full disk), the file is closed valid at its last whole
chunk, the recorder leaves the graph, and the graph keeps running.
"""

from __future__ import annotations

import asyncio
import re
import threading
from collections import deque
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import anyio
import anyio.abc

from actors import codec
from actors.messages.cdr import HEADER, Buffer, encoder
from actors.recording.bag_writer import BagWriter
from actors.recording.tap import Tap, TapSet
from actors.ros.names import expand, is_hidden_name

if TYPE_CHECKING:
    from actors.runtime import Runtime

__all__ = ["Recorder", "RECORDER_NODE"]

_HANDOFF = 1024
"""On the wall clock, the most messages the buffer holds before it goes to the worker thread."""

_WIDTH = 3
"""Entries per message in the buffer and its batches: tap, stamp, message."""

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
    messages waiting for the disk: when it is reached the publisher waits
    until they are written, or with ``lossy`` the message is dropped (counted
    on its topic, in the bag's metadata and by doctor).  No message stays out
    of the file for more than ``flush_interval`` seconds of runtime clock (a
    chunk in progress is written early): a recording killed outright
    (``kill -9``, a power cut) loses at most that, and ``bag reindex`` makes
    the rest a whole bag again.

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
        lossy: bool = False,
        flush_interval: float = 1.0,
    ) -> None:
        if not 0 < flush_interval < float("inf"):
            raise ValueError(f"flush_interval must be > 0 seconds, got {flush_interval}")
        self.output = Path(output)
        self.topics = frozenset(expand(t, "/", "_") for t in topics)
        self.exclude = re.compile(exclude) if exclude else None
        self.include_hidden = include_hidden
        self.compression = compression
        self.chunk_size = chunk_size
        self.max_pending = max_pending
        self.lossy = lossy
        self.flush_interval = flush_interval
        self.path: Path | None = None  # the MCAP file, once open
        self._writer: BagWriter | None = None
        self._taps = TapSet(
            RECORDER_NODE, self._takes, self._take, depth=max_pending, label="recorder", wrap=self._wrap
        )
        # Flat: tap, stamp, message, tap, stamp, message...  A tuple per message kept until written
        # was a tracked object more for the garbage collector to count and traverse, per message.
        self._items: list[Any] = []
        # While the buffer is shorter than this, a message only goes on it; at this length there
        # is something else to do first (see _take): 0 while empty (the first sets the deadline).
        self._room = 0
        # Batches taken from the buffer, written in order by whichever thread holds the lock.
        self._batches: deque[list[Any]] = deque()
        self._lock = threading.Lock()
        self._runtime: Runtime | None = None
        self._waiter: asyncio.Future[None] | None = None
        self._handoff = 1  # buffered messages that wake the writer task (see __call__)
        self._now_ns: Any = None  # the runtime clock, once running
        self._loop_time: Any = None  # the loop's clock: a message's stamp, made ROS time when written
        self._ns_at: Any = None
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
        if not runtime.clock.virtual:
            # Each batch is a hop to the worker thread and back, tens of microseconds: the
            # writer task wakes for a batch worth the hop (or when the oldest is due, see _drain),
            # not for every turn of the loop that published something.
            self._handoff = max(1, min(_HANDOFF, self.max_pending // 4))
        self._now_ns = runtime.clock.now_ns
        # The clock's own reader (never uvloop's millisecond loop.time: each message its own
        # receive time), a quarter of now_ns()'s cost in publish(); ROS time when written.
        self._loop_time, self._ns_at = runtime.clock.reader(), runtime.clock.ns_at
        self._runtime = runtime
        try:
            self._taps.start(runtime)
            task_status.started()
            await self._drain(runtime)
        finally:
            self._finish(runtime)  # synchronous: no cancellation can reach it

    async def _drain(self, runtime: Runtime) -> None:
        loop = runtime.loop
        inline = runtime.clock.virtual
        writer = self._writer
        assert writer is not None
        interval = round(self.flush_interval * 1e9)
        while writer.error is None:
            while len(self._items) < _WIDTH * self._handoff:
                self._waiter = loop.create_future()
                oldest = writer.pending_since
                if oldest is None and self._items:
                    oldest = self._ns_at([self._items[1]])[0]
                if oldest is None:
                    await self._waiter
                    continue
                # Woken by a message (the first sets the deadline) or a batch, or when the oldest
                # message waiting is due in the file: then what there is goes.
                with anyio.move_on_after((oldest + interval - self._now_ns()) / 1e9) as due:
                    await self._waiter
                if due.cancelled_caught:
                    break
            self._take_buffer()
            if inline:
                failures = self._write_batches()
            else:
                failures = await anyio.to_thread.run_sync(self._write_batches)
            self._after_batch(runtime, failures)
        self._stopped(runtime)
        self._taps.stop()
        await anyio.sleep_forever()

    def _after_batch(self, runtime: Runtime, failures: list[tuple[Tap, Exception]]) -> None:
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
        self._taps.stop()
        writer = self._writer
        if writer is None:
            return
        self._take_buffer()
        self._write_batches()  # with a batch the cancelled writer task had taken but not written
        for tap in self._taps.all():
            if tap.channel is None and writer.error is None:
                self._register(tap)  # listed with no messages, as rosbag2 lists a quiet topic
        dropped = {tap.topic_name: tap.dropped for tap in self._taps.all() if tap.dropped}
        try:
            writer.close(dropped=dropped)
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

    # -- the tapping side ------------------------------------------------------------

    def _takes(self, topic: str) -> bool:
        return self.wants(topic) and self._writer is not None and self._writer.error is None

    def _wrap(self, tap: Tap, snapshot: Callable[[Any], Any]) -> Callable[[Any], Any]:
        """A publisher's snapshot function that also stamps and buffers each snapshot for ``tap``.

        publish() calls it once per message, whatever its path to the other subscriptions:
        this is all that recording adds to a publish while the buffer has room.
        """
        stamp = self._loop_time

        def tapped(msg: Any) -> Any:
            msg = snapshot(msg)
            items = self._items
            if len(items) < self._room:
                items += (tap, stamp(), msg)
            else:
                self._take(tap, msg)
            return msg

        return tapped

    def _take(self, tap: Tap, msg: Any) -> None:
        """Stamp a tapped message and buffer it for the writer; when the buffer is full,
        write it now (the publisher waits for the disk), or drop the message if lossy."""
        items = self._items
        if len(items) >= _WIDTH * self.max_pending:
            if self.lossy:
                tap.dropped += 1
                self.dropped += 1
                return
            self._write_now()
            items = self._items
        waking = _WIDTH * (self._handoff - 1)
        if not items or len(items) == waking:
            self._wake()  # the first sets the writer task's deadline; a whole batch goes at once
        items += (tap, self._loop_time(), msg)
        self._room = waking if len(items) < waking else _WIDTH * self.max_pending

    def _take_buffer(self) -> None:
        """Queue the buffer as a batch for the writer; a new one starts."""
        self._batches.append(self._items)
        self._items = []
        self._room = 0

    # -- the writer side ------------------------------------------------------------

    def _wake(self) -> None:
        waiter = self._waiter
        if waiter is not None:
            self._waiter = None
            if not waiter.done():
                waiter.set_result(None)

    def _write_now(self) -> None:
        """Write the full buffer in the loop's thread (after the worker's batch in progress)."""
        self._take_buffer()
        failures = self._write_batches()
        if self._runtime is not None:
            self._after_batch(self._runtime, failures)

    def _write_batches(self) -> list[tuple[Tap, Exception]]:
        """Write the batches taken so far, oldest first (in a worker thread on the wall clock); returns the failures."""
        failures = []
        with self._lock:
            batches = self._batches
            while batches:
                failures += self._write(batches.popleft())
        return failures

    def _write(self, batch: list[Any]) -> list[tuple[Tap, Exception]]:
        """Encode and write one batch; returns the failures."""
        writer = self._writer
        assert writer is not None
        failures: list[tuple[Tap, Exception]] = []
        writer.write_many(self._encoded(batch, failures))
        writer.flush_older_than(self._now_ns() - round(self.flush_interval * 1e9))
        return failures

    def _encoded(
        self, batch: list[Any], failures: list[tuple[Tap, Exception]]
    ) -> Iterator[tuple[int, int, int, bytes | bytearray]]:
        """The batch's messages as the writer takes them, each encoded as it is taken; what
        cannot be encoded goes into ``failures`` instead.

        One buffer serves every message: the writer copies each into its chunk before it
        takes the next (a new Buffer costs as much as framing the message).
        """
        buf = Buffer(HEADER)
        for tap, msg, stamp in zip(batch[0::_WIDTH], batch[2::_WIDTH], self._ns_at(batch[1::_WIDTH])):
            fill = tap.encode
            if fill is None:  # kept on the tap, not here: a topic that goes and comes back has a new tap
                if tap.channel is None:
                    self._register(tap)
                fill = tap.encode = encoder(tap.msg_type)
            channel = tap.channel
            del buf[4:]  # the header stays
            try:
                fill(buf, msg)
            except Exception as exc:  # a message its type cannot carry: counted, never fatal
                failures.append((tap, _named(msg, exc)))
                buf = Buffer(HEADER)  # it may have spilled
                continue
            if buf.chunks:  # a large array kept aside: the buffer is spent
                data, buf = buf.result(), Buffer(HEADER)
                yield channel, stamp, stamp, data
            else:
                yield channel, stamp, stamp, buf

    def _register(self, tap: Tap) -> None:
        assert self._writer is not None
        tap.channel = self._writer.add_topic(
            tap.topic_name, tap.ros_type, definition=tap.definition, type_hash=tap.type_hash, offers=tap.offers
        )


def _named(msg: Any, exc: Exception) -> Exception:
    """The error :func:`codec.encode_cdr` gives for ``msg`` (naming the field), else ``exc``."""
    try:
        codec.encode_cdr(msg)
    except Exception as named:
        return named
    return exc
