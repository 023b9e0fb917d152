"""An MCAP writer for ROS 2 bags that keeps the file valid when the disk fails.

The records are the ``mcap`` library's (header, schemas, channels, chunks,
indexes, statistics, summary, footer); two things are our own, each for a
measured or stated reason:

- Message records and message indexes are packed here with one ``struct``
  call per message, 0.6 µs, where the library's ``Writer.add_message`` takes
  9 µs: the recorder must keep up with a graph that publishes at several
  hundred thousand messages per second.
- The file only ever receives whole chunks (a chunk and its message indexes
  in one write).  When a write fails (a full disk, a file size limit), the
  file is cut back to the end of the last whole chunk and the writer stops
  taking messages; :meth:`McapWriter.close` then ends the file with a summary
  of exactly what it holds.  The library's writer cannot take back a chunk it
  failed to write: its statistics and indexes already count it.

Nothing depends on the wall clock or on timing: the same messages in the same
order give the same bytes, chunk compression included (zstd at its default
level and lz4 are deterministic).
"""

from __future__ import annotations

import errno
import struct
import sys
import zlib
from array import array
from collections.abc import Iterable, Mapping
from typing import Any, BinaryIO

from actors.errors import BagError

__all__ = ["McapWriter", "COMPRESSIONS", "MAGIC"]

MAGIC = b"\x89MCAP0\r\n"
"""The 8 bytes an MCAP file starts and ends with."""

COMPRESSIONS = ("zstd", "lz4", "")
"""Chunk compressions :class:`McapWriter` takes (``""`` leaves chunks uncompressed)."""

_MESSAGE = struct.Struct("<BQHIQQ")  # opcode, record length, channel, sequence, log time, publish time
_MESSAGE_FIELDS = 2 + 4 + 8 + 8
_MESSAGE_INDEX = struct.Struct("<BQHI")  # opcode, record length, channel, bytes of (time, offset) pairs
_CHUNK = struct.Struct("<BQQQQII")  # opcode, length, start and end times, size, crc, compression's length
_U64 = struct.Struct("<Q")
_OP_MESSAGE = 0x05
_OP_CHUNK = 0x06
_OP_MESSAGE_INDEX = 0x07


def _mcap() -> Any:
    try:
        import mcap.data_stream
        import mcap.records
    except ImportError as exc:  # pragma: no cover - the record extra is missing
        raise ImportError("recording needs the mcap library: pip install 'actors[record]'") from exc
    return mcap


def _compressor(name: str) -> Any:
    if name == "zstd":
        try:
            import zstandard
        except ImportError as exc:  # pragma: no cover
            raise ImportError("zstd chunks need zstandard: pip install 'actors[record]'") from exc
        return zstandard.ZstdCompressor(level=3).compress
    if name == "lz4":
        try:
            import lz4.frame
        except ImportError as exc:  # pragma: no cover
            raise ImportError("lz4 chunks need lz4: pip install lz4") from exc
        return lz4.frame.compress
    if name == "":
        return _stored
    raise ValueError(f"unknown chunk compression {name!r}; choose one of zstd, lz4 or ''")


def _u64s(values: list[int]) -> bytes:
    """``values`` as little-endian unsigned 64-bit integers (an index's times and offsets)."""
    packed = array("Q", values)  # one C loop; struct.pack(*values) passes each as an argument
    if sys.byteorder == "big":  # pragma: no cover - every machine this runs on is little-endian
        packed.byteswap()
    return packed.tobytes()


def _stored(data: bytearray) -> bytearray:
    """An uncompressed chunk's records: the chunk in progress itself (a new one is started after it)."""
    return data


class McapWriter:
    """Writes one MCAP file to ``stream`` (a binary file opened for writing, unbuffered).

    ``profile`` goes into the header (``ros2`` for ROS 2 bags), ``library``
    names the writer.  Messages collect in a chunk of about ``chunk_size``
    bytes, compressed with ``compression`` when full.  Use from one thread at
    a time.  After a failed write, :attr:`error` holds the OSError and every
    later message is counted in :attr:`lost` instead of written.
    """

    _chunk_end: int  # log time of the last message in the chunk in progress

    def __init__(
        self,
        stream: BinaryIO,
        *,
        profile: str = "ros2",
        library: str = "actors",
        chunk_size: int = 1 << 20,
        compression: str = "zstd",
    ) -> None:
        m = _mcap()
        self._records = m.records
        self._builder_class = m.data_stream.RecordBuilder
        self._compress = _compressor(compression)
        self._compression = compression
        self._stream = stream
        self._chunk_size = chunk_size
        self._schemas: dict[int, Any] = {}
        self._channels: dict[int, Any] = {}
        self._metadata: list[tuple[str, dict[str, str]]] = []
        # The summary's chunk indexes, one per chunk written, kept as the bytes they end up as: a
        # long recording flushed every second adds one a second for as long as it runs, and
        # mcap's ChunkIndex objects (a dict of offsets per channel) cost several times their record.
        self._chunk_index_records = bytearray()
        self._chunk_count = 0
        self._counts: dict[int, int] = {}  # messages per channel, in the file
        self._start = self._end = 0  # log times of the messages in the file
        self._messages = 0
        self.error: OSError | None = None
        self.lost = 0
        self._closed = False
        self._new_chunk()
        builder = self._builder_class()
        self._records.Header(profile=profile, library=library).write(builder)
        self._offset = 0  # end of the last whole write: the file is valid up to here
        self._write(MAGIC + builder.end())
        if self.error is not None:
            raise BagError(f"{getattr(stream, 'name', 'the bag')}: cannot write: {self.error}")

    # -- the data section -------------------------------------------------------

    def add_schema(self, name: str, encoding: str, data: bytes) -> int:
        """Register a schema (e.g. ``ros2msg`` text); returns its id."""
        schema_id = len(self._schemas) + 1
        schema = self._records.Schema(id=schema_id, name=name, encoding=encoding, data=data)
        self._schemas[schema_id] = schema
        self._put_record(schema)
        return schema_id

    def add_channel(self, topic: str, schema_id: int, encoding: str, metadata: Mapping[str, str]) -> int:
        """Register a channel (a topic with its schema, ``cdr`` encoding, metadata); returns its id."""
        channel_id = len(self._channels) + 1
        channel = self._records.Channel(
            id=channel_id,
            topic=topic,
            message_encoding=encoding,
            schema_id=schema_id,
            metadata=dict(metadata),
        )
        self._channels[channel_id] = channel
        self._counts.setdefault(channel_id, 0)
        self._put_record(channel)
        return channel_id

    def add_message(self, channel_id: int, log_time: int, publish_time: int, data: bytes | bytearray) -> None:
        """Add one message (times in nanoseconds, non-decreasing log times) to the chunk."""
        self.add_messages(((channel_id, log_time, publish_time, data),))

    def add_messages(self, messages: Iterable[tuple[int, int, int, bytes | bytearray]]) -> None:
        """Add ``(channel id, log time, publish time, data)`` messages in order, as :meth:`add_message` does.

        A recorder's batch in one call, which may be a generator that encodes each
        message as it is taken: no list of them all is made.  Per message, this loop
        keeps only what the message index needs (the chunk's count and first time are
        read off the indexes when it is written), and looks the channel's index up only
        when the channel changes.
        """
        messages = iter(messages)
        if self.error is not None:
            self.lost += sum(1 for _ in messages)
            return
        chunk, indexes, size = self._chunk, self._chunk_index, self._chunk_size
        pack = _MESSAGE.pack
        log_time = self._chunk_end
        channel: int | None = None
        index: list[int] = []
        for channel_id, log_time, publish_time, data in messages:
            if channel_id != channel:
                channel = channel_id
                index = indexes.setdefault(channel_id, [])
            index += (log_time, len(chunk))
            chunk += pack(_OP_MESSAGE, _MESSAGE_FIELDS + len(data), channel_id, 0, log_time, publish_time)
            chunk += data
            if len(chunk) >= size:
                self._chunk_end = log_time
                self._finish_chunk()
                if self.error is not None:
                    self.lost += sum(1 for _ in messages)
                    return
                chunk, indexes = self._chunk, self._chunk_index
                channel = None
        self._chunk_end = log_time

    def add_metadata(self, name: str, data: Mapping[str, str]) -> None:
        """A metadata record (e.g. rosbag2's ``rosbag2`` record), written when the file closes."""
        self._metadata.append((name, dict(data)))

    def _put_record(self, record: Any) -> None:
        # Schemas and channels go into the chunk, before the messages that use them, and again
        # into the summary: a reader streaming the file meets them in time.
        builder = self._builder_class()
        record.write(builder)
        self._chunk += builder.end()

    def _new_chunk(self) -> None:
        self._chunk = bytearray()
        self._chunk_index: dict[int, list[int]] = {}  # per channel: log time, offset, log time, offset...
        self._chunk_end = 0

    def _chunk_counts(self) -> tuple[int, int]:
        """The chunk in progress's message count and first log time (0, 0 when empty)."""
        pairs = self._chunk_index.values()
        if not pairs:
            return 0, 0
        return sum(len(p) for p in pairs) // 2, min(p[0] for p in pairs)

    def _finish_chunk(self) -> None:
        """Compress the chunk and write it with its message indexes in one write."""
        messages, first = self._chunk_counts()
        if not messages or self.error is not None:
            return
        # The chunk record's head is packed here, and the chunk and its indexes go out as they
        # are: copying a megabyte of fresh memory costs as much as compressing it.
        data = self._chunk
        compressed = self._compress(data)
        name = self._compression.encode()
        head = (
            _CHUNK.pack(
                _OP_CHUNK,
                8 + 8 + 8 + 4 + 4 + len(name) + 8 + len(compressed),
                first,
                self._chunk_end,
                len(data),
                zlib.crc32(data),
                len(name),
            )
            + name
            + _U64.pack(len(compressed))
        )
        start = self._offset
        chunk_length = len(head) + len(compressed)
        indexes = bytearray()
        offsets = {}
        for channel_id, pairs in self._chunk_index.items():
            offsets[channel_id] = start + chunk_length + len(indexes)
            indexes += _MESSAGE_INDEX.pack(_OP_MESSAGE_INDEX, 2 + 4 + 8 * len(pairs), channel_id, 8 * len(pairs))
            indexes += _u64s(pairs)
        if not self._write(head, compressed, indexes):
            self.lost += messages
            self._new_chunk()
            return
        r = self._records
        builder = self._builder_class()
        r.ChunkIndex(
            message_start_time=first,
            message_end_time=self._chunk_end,
            chunk_start_offset=start,
            chunk_length=chunk_length,
            message_index_offsets=offsets,
            message_index_length=len(indexes),
            compression=self._compression,
            compressed_size=len(compressed),
            uncompressed_size=len(data),
        ).write(builder)
        self._chunk_index_records += builder.end()
        self._chunk_count += 1
        if not self._messages:
            self._start = first
        self._end = self._chunk_end
        self._messages += messages
        for channel_id, pairs in self._chunk_index.items():
            self._counts[channel_id] += len(pairs) // 2
        self._new_chunk()

    def _write(self, *pieces: bytes | bytearray) -> bool:
        """Write ``pieces`` whole, one after the other, or cut the file back to where it was and note the error."""
        try:
            for piece in pieces:
                view = memoryview(piece)
                while view:
                    written = self._stream.write(view)
                    if not written:
                        raise OSError(errno.ENOSPC, "no space left on device")
                    view = view[written:]
        except OSError as exc:
            self.error = exc
            try:
                self._stream.truncate(self._offset)
                self._stream.seek(self._offset)
            except OSError:  # pragma: no cover - a file that cannot even be cut back
                pass
            return False
        self._offset += sum(len(piece) for piece in pieces)
        return True

    # -- the end ----------------------------------------------------------------

    @property
    def message_count(self) -> int:
        """Messages in the file so far (whole chunks written)."""
        return self._messages

    @property
    def channel_counts(self) -> dict[int, int]:
        """Messages in the file so far, by channel id."""
        return dict(self._counts)

    @property
    def time_range(self) -> tuple[int, int]:
        """Log times of the first and last message in the file (0, 0 when none)."""
        return self._start, self._end

    @property
    def size(self) -> int:
        """Bytes in the file so far."""
        return self._offset

    def flush(self) -> None:
        """Write the chunk in progress now (a smaller chunk than ``chunk_size``)."""
        self._finish_chunk()

    @property
    def pending_since(self) -> int | None:
        """Log time of the oldest message not yet in the file (in the chunk in progress), if any."""
        messages, first = self._chunk_counts()
        return first if messages else None

    def flush_older_than(self, log_time: int) -> None:
        """Write the chunk in progress if its oldest message is older than ``log_time``.

        What bounds the loss when the recording process is killed outright:
        the file holds every whole chunk, and no chunk stays open for longer
        than its writer's interval.
        """
        messages, first = self._chunk_counts()
        if messages and first <= log_time:
            self._finish_chunk()

    def close(self) -> None:
        """Write the last chunk and end the file: metadata, summary, footer.  Idempotent.

        After a failed write the file ends at its last whole chunk, and the
        summary describes exactly that; if even the summary does not fit, the
        file ends with a footer and no summary (still valid MCAP, which
        readers scan), and failing that it keeps its whole chunks only.  The
        stream is closed either way.
        """
        if self._closed:
            return
        self._closed = True
        try:
            self._finish_chunk()
            if not self._write(self._ending(with_summary=True)):
                self._write(self._ending(with_summary=False))
        finally:
            self._stream.close()

    def _ending(self, *, with_summary: bool) -> bytes:
        r = self._records
        data = self._builder_class()
        metadata_indexes = []
        if with_summary:
            for name, values in self._metadata:
                offset = self._offset + data.count
                r.Metadata(name=name, metadata=values).write(data)
                metadata_indexes.append(
                    r.MetadataIndex(offset=offset, length=self._offset + data.count - offset, name=name)
                )
        r.DataEnd(data_section_crc=0).write(data)
        head = data.end()
        summary_start = self._offset + len(head)
        summary = self._builder_class()
        offsets: list[Any] = []

        def group(opcode: int, records: list[Any] | bytearray) -> None:
            if records:
                begin = summary.count
                if isinstance(records, bytearray):  # records already written out
                    summary.write(records)
                else:
                    for record in records:
                        record.write(summary)
                offsets.append(
                    r.SummaryOffset(
                        group_opcode=opcode,
                        group_start=summary_start + begin,
                        group_length=summary.count - begin,
                    )
                )

        if with_summary:
            from mcap.opcode import Opcode

            group(Opcode.SCHEMA, list(self._schemas.values()))
            group(Opcode.CHANNEL, list(self._channels.values()))
            group(
                Opcode.STATISTICS,
                [
                    r.Statistics(
                        message_count=self._messages,
                        schema_count=len(self._schemas),
                        channel_count=len(self._channels),
                        attachment_count=0,
                        metadata_count=len(self._metadata),
                        chunk_count=self._chunk_count,
                        message_start_time=self._start,
                        message_end_time=self._end,
                        channel_message_counts={k: v for k, v in self._counts.items() if v},
                    )
                ],
            )
            group(Opcode.CHUNK_INDEX, self._chunk_index_records)
            group(Opcode.METADATA_INDEX, metadata_indexes)
        offset_start = summary_start + summary.count
        for offset in offsets:
            offset.write(summary)
        body = summary.end()
        footer_fields = struct.pack("<BQQQ", 0x02, 8 + 8 + 4, summary_start if body else 0, offset_start if body else 0)
        crc = zlib.crc32(footer_fields, zlib.crc32(body)) if body else 0
        tail = self._builder_class()
        r.Footer(
            summary_start=summary_start if body else 0,
            summary_offset_start=offset_start if body else 0,
            summary_crc=crc,
        ).write(tail)
        return head + body + tail.end() + MAGIC
