"""Reading ROS 2 bags (MCAP files or rosbag2 bag directories), every problem named with its byte.

:class:`Bag` reads what ``bag info`` prints from a file's summary (schemas,
channels, statistics), and the messages in file order for ``bag play`` and
the test helpers, record by record with the ``mcap`` library's record parsers.
A truncated or corrupt file raises :class:`~actors.errors.BagError` naming the
file, the byte offset and what is wrong there; with ``recover=True`` the bag
gives what is readable before the damage (whole chunks) and keeps the problem
in :attr:`Bag.problems` instead.
"""

from __future__ import annotations

import io
import json
import struct
import zlib
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from actors.errors import BagError
from actors.recording.mcap_writer import MAGIC
from actors.recording.rosbag import DROPPED_KEY, bag_files

__all__ = ["Bag", "BagTopic", "BagMessage", "FileSummary"]

_RECORD_HEAD = struct.Struct("<BQ")
_OP = {
    "header": 0x01,
    "footer": 0x02,
    "schema": 0x03,
    "channel": 0x04,
    "message": 0x05,
    "chunk": 0x06,
    "metadata": 0x0C,
    "metadata_index": 0x0D,
    "data_end": 0x0F,
    "statistics": 0x0B,
    "chunk_index": 0x08,
}
_FOOTER_SIZE = 1 + 8 + 8 + 8 + 4  # opcode, length, summary start, summary offset start, crc


@dataclass
class BagTopic:
    """One topic (channel) of a bag: its type, encoding, message count, QoS text and type hash."""

    name: str
    type: str
    serialization_format: str = "cdr"
    count: int = 0
    offered_qos_profiles: str = ""
    type_hash: str = ""
    definition: str = ""
    dropped: int = 0  # messages a lossy recorder left out (rosbag2 metadata's custom_data)


@dataclass
class BagMessage:
    """One recorded message: its topic, log time (ns) and serialized bytes."""

    topic: BagTopic
    log_time: int
    data: bytes


@dataclass
class FileSummary:
    """What one MCAP file holds, from its summary (or a scan, when recovering)."""

    path: Path
    size: int
    profile: str = ""
    library: str = ""
    message_count: int = 0
    start: int = 0
    end: int = 0
    chunk_compressions: set[str] = field(default_factory=set)
    ros_distro: str = ""
    topics: dict[int, BagTopic] = field(default_factory=dict)


class _Damage(Exception):
    """A problem at a byte of a file: turned into BagError, or into a note when recovering."""

    def __init__(self, offset: int, text: str) -> None:
        super().__init__(f"byte {offset}: {text}")


def _mcap() -> Any:
    try:
        import mcap.data_stream
        import mcap.records
    except ImportError as exc:  # pragma: no cover - the record extra is missing
        raise ImportError("reading bags needs the mcap library: pip install 'actors[record]'") from exc
    return mcap


class _McapFile:
    """One MCAP file, read from bytes in memory (bags here are small) or a file."""

    def __init__(self, path: Path) -> None:
        self.path = path
        try:
            self.data = path.read_bytes()
        except OSError as exc:
            raise BagError(f"{path}: cannot read: {exc.strerror or exc}") from None
        self.records = _mcap().records
        self.stream_class = _mcap().data_stream.ReadDataStream

    def _parse(self, opcode: int, body: bytes, offset: int) -> Any:
        r = self.records
        stream = self.stream_class(io.BytesIO(body))
        try:
            if opcode == _OP["message"]:
                return r.Message.read(stream, len(body))
            kind = {
                _OP["header"]: r.Header,
                _OP["footer"]: r.Footer,
                _OP["schema"]: r.Schema,
                _OP["channel"]: r.Channel,
                _OP["chunk"]: r.Chunk,
                _OP["metadata"]: r.Metadata,
                _OP["data_end"]: r.DataEnd,
                _OP["statistics"]: r.Statistics,
                _OP["metadata_index"]: r.MetadataIndex,
                _OP["chunk_index"]: r.ChunkIndex,
            }.get(opcode)
            return kind.read(stream) if kind is not None else None
        except Exception as exc:
            raise _Damage(offset, f"a malformed record (opcode 0x{opcode:02x}): {exc or type(exc).__name__}") from None

    def records_from(
        self, data: bytes | memoryview, base: int, end: int | None = None
    ) -> Iterator[tuple[int, int, Any]]:
        """``(offset, opcode, record)`` of each record in ``data`` (at file offset ``base``)."""
        end = len(data) if end is None else end
        pos = 0
        while pos < end:
            if end - pos < _RECORD_HEAD.size:
                raise _Damage(base + pos, f"cut off inside a record header ({end - pos} of 9 bytes)")
            opcode, length = _RECORD_HEAD.unpack_from(data, pos)
            start = pos + _RECORD_HEAD.size
            if length > end - start:
                raise _Damage(
                    base + pos,
                    f"a record (opcode 0x{opcode:02x}) of {length} bytes runs past the end "
                    f"({end - start} bytes left): the file is truncated or corrupt",
                )
            yield base + pos, opcode, self._parse(opcode, bytes(data[start : start + length]), base + pos)
            pos = start + length

    def check_magic(self) -> None:
        if len(self.data) < len(MAGIC) or self.data[: len(MAGIC)] != MAGIC:
            raise _Damage(0, "not an MCAP file (no MCAP magic at the start)")

    def footer(self) -> Any | None:
        """The footer, or None when the file does not end as a finished MCAP file does."""
        data = self.data
        if len(data) < 2 * len(MAGIC) + _FOOTER_SIZE or data[-len(MAGIC) :] != MAGIC:
            return None
        at = len(data) - len(MAGIC) - _FOOTER_SIZE
        if data[at] != _OP["footer"]:
            return None
        return next(self.records_from(data[at : -len(MAGIC)], at))[2]

    def chunk_records(self, chunk: Any, offset: int) -> Iterator[tuple[int, int, Any]]:
        try:
            if chunk.compression == "zstd":
                import zstandard

                raw = zstandard.ZstdDecompressor().decompress(chunk.data, max_output_size=chunk.uncompressed_size)
            elif chunk.compression == "lz4":
                import lz4.frame

                raw = lz4.frame.decompress(chunk.data)
            elif chunk.compression == "":
                raw = chunk.data
            else:
                raise _Damage(offset, f"a chunk compressed with {chunk.compression!r}, which is not supported")
        except _Damage:
            raise
        except Exception as exc:
            raise _Damage(offset, f"a chunk that does not decompress ({chunk.compression}): {exc}") from None
        if len(raw) != chunk.uncompressed_size:
            raise _Damage(offset, f"a chunk of {len(raw)} bytes where its header says {chunk.uncompressed_size}")
        if chunk.uncompressed_crc and zlib.crc32(raw) != chunk.uncompressed_crc:
            raise _Damage(offset, "a chunk whose CRC does not match its contents: the file is corrupt")
        try:
            for _, opcode, record in self.records_from(raw, 0):
                yield offset, opcode, record
        except _Damage as exc:
            raise _Damage(offset, f"inside the chunk: {exc}") from None


class Bag:
    """A bag: one MCAP file or a rosbag2 directory of them.

    Raises BagError (file, byte, problem) for a file that cannot be read as
    MCAP, unless ``recover``: then :attr:`problems` lists what was wrong and
    the bag holds what came before it.  Raises FileNotFoundError for a path
    that does not exist.
    """

    def __init__(self, path: str | Path, *, recover: bool = False) -> None:
        self.path = Path(path)
        self.recover = recover
        self.files = bag_files(self.path)
        self.problems: list[str] = []
        self.summaries = [self._summary(_McapFile(f)) for f in self.files]

    # -- the summary ----------------------------------------------------------------

    def _damage(self, path: Path, exc: _Damage) -> None:
        text = f"{path}: {exc}"
        if not self.recover:
            raise BagError(text)
        self.problems.append(text)

    def _summary(self, file: _McapFile) -> FileSummary:
        summary = FileSummary(path=file.path, size=len(file.data))
        try:
            file.check_magic()
            footer = file.footer()
            hint = "" if self.recover else "; --recover reads the whole chunks before it"
            if footer is None:
                raise _Damage(
                    len(file.data),
                    "the file ends without a footer: it is truncated (its recording was stopped by force?)" + hint,
                )
            if not footer.summary_start:
                raise _Damage(
                    len(file.data),
                    "the file ends without a summary (its disk filled up while recording?)" + hint,
                )
            self._read_summary(file, footer, summary)
        except _Damage as exc:
            self._damage(file.path, exc)
            self._scan_summary(file, summary)
        self._read_header(file, summary)
        return summary

    def _read_header(self, file: _McapFile, summary: FileSummary) -> None:
        try:
            _, opcode, header = next(file.records_from(file.data[len(MAGIC) :], len(MAGIC)))
        except (StopIteration, _Damage):
            return
        if opcode == _OP["header"]:
            summary.profile, summary.library = header.profile, header.library

    def _read_summary(self, file: _McapFile, footer: Any, summary: FileSummary) -> None:
        end = len(file.data) - len(MAGIC) - _FOOTER_SIZE
        start = footer.summary_start
        if not len(MAGIC) <= start <= end:
            raise _Damage(end, f"a footer pointing to a summary at byte {start}, outside the file")
        schemas: dict[int, Any] = {}
        channels: list[Any] = []
        stats = None
        distro_at = None
        for _, opcode, record in file.records_from(file.data[start:end], start):
            if opcode == _OP["schema"]:
                schemas[record.id] = record
            elif opcode == _OP["channel"]:
                channels.append(record)
            elif opcode == _OP["statistics"]:
                stats = record
            elif opcode == _OP["chunk_index"]:
                summary.chunk_compressions.add(record.compression)
            elif opcode == _OP["metadata_index"] and record.name == "rosbag2":
                distro_at = record.offset
        counts = stats.channel_message_counts if stats is not None else {}
        if stats is not None:
            summary.message_count = stats.message_count
            summary.start, summary.end = stats.message_start_time, stats.message_end_time
        for channel in channels:
            summary.topics[channel.id] = _topic(channel, schemas.get(channel.schema_id), counts.get(channel.id, 0))
        if distro_at is not None:
            meta = _rosbag2_metadata(file, distro_at)
            summary.ros_distro = str(meta.get("ros_distro") or "")
            for topic, count in _dropped(meta).items():
                found = next((t for t in summary.topics.values() if t.name == topic), None)
                if found is not None:
                    found.dropped = count

    def _scan_summary(self, file: _McapFile, summary: FileSummary) -> None:
        """Count what the data section holds (a file with no usable summary, when recovering)."""
        schemas: dict[int, Any] = {}
        for _, opcode, record in self._data_records(file, expand=True):
            if opcode == _OP["schema"]:
                schemas[record.id] = record
            elif opcode == _OP["channel"]:
                summary.topics[record.id] = _topic(record, schemas.get(record.schema_id), 0)
            elif opcode == _OP["message"]:
                topic = summary.topics.get(record.channel_id)
                if topic is not None:
                    topic.count += 1
                if not summary.message_count:
                    summary.start = record.log_time
                summary.start = min(summary.start, record.log_time)
                summary.end = max(summary.end, record.log_time)
                summary.message_count += 1

    def _data_records(self, file: _McapFile, *, expand: bool = False) -> Iterator[tuple[int, int, Any]]:
        """The data section's records in file order, chunks opened when ``expand``.

        A problem ends the iteration: raised as BagError, or noted when
        recovering (a whole chunk is given whole or not at all).
        """
        try:
            for offset, opcode, record in file.records_from(file.data[len(MAGIC) :], len(MAGIC)):
                if opcode == _OP["chunk"] and expand:
                    yield from list(file.chunk_records(record, offset))
                elif opcode in (_OP["data_end"], _OP["footer"]):
                    return
                else:
                    yield offset, opcode, record
        except _Damage as exc:
            self._damage(file.path, exc)

    # -- what readers use -----------------------------------------------------------

    @property
    def topics(self) -> list[BagTopic]:
        """Every topic of the bag, by name (files of a directory merged)."""
        merged: dict[str, BagTopic] = {}
        for summary in self.summaries:
            for topic in summary.topics.values():
                seen = merged.get(topic.name)
                if seen is None:
                    merged[topic.name] = BagTopic(**vars(topic))
                else:
                    seen.count += topic.count
                    seen.dropped += topic.dropped
        return sorted(merged.values(), key=lambda t: t.name)

    @property
    def message_count(self) -> int:
        """Messages in the bag."""
        return sum(s.message_count for s in self.summaries)

    @property
    def start(self) -> int:
        """Log time of the first message (ns), 0 for an empty bag."""
        times = [s.start for s in self.summaries if s.message_count]
        return min(times) if times else 0

    @property
    def end(self) -> int:
        """Log time of the last message (ns), 0 for an empty bag."""
        times = [s.end for s in self.summaries if s.message_count]
        return max(times) if times else 0

    @property
    def size(self) -> int:
        """Bytes in the bag's files."""
        return sum(s.size for s in self.summaries)

    def check(self) -> None:
        """Read every record (every chunk decompressed, its CRC checked); raise BagError at the first damage.

        When recovering, note the damage in :attr:`problems` instead.
        """
        for _ in self.messages():
            pass

    def messages(self, topics: Iterable[str] | None = None) -> Iterator[BagMessage]:
        """The messages of ``topics`` (all when None), file after file, each file in its order.

        Raises BagError at the first damaged record unless the bag recovers
        (then iteration stops before it and :attr:`problems` says why).
        """
        wanted = set(topics) if topics is not None else None
        for path in self.files:
            file = _McapFile(path)
            channels: dict[int, BagTopic] = {}
            schemas: dict[int, Any] = {}
            for _, opcode, record in self._data_records(file, expand=True):
                if opcode == _OP["schema"]:
                    schemas[record.id] = record
                elif opcode == _OP["channel"]:
                    channels[record.id] = _topic(record, schemas.get(record.schema_id), 0)
                elif opcode == _OP["message"]:
                    topic = channels.get(record.channel_id)
                    if topic is not None and (wanted is None or topic.name in wanted):
                        yield BagMessage(topic=topic, log_time=record.log_time, data=record.data)


def _rosbag2_metadata(file: _McapFile, offset: int) -> dict[str, Any]:
    """rosbag2's ``rosbag2`` metadata record, as data ({} when unreadable)."""
    try:
        _, opcode, record = next(file.records_from(memoryview(file.data)[offset:], offset))
        meta = yaml.safe_load(record.metadata.get("serialized_metadata", "")) or {}
    except (StopIteration, _Damage, yaml.YAMLError, AttributeError):
        return {}
    return meta if opcode == _OP["metadata"] and isinstance(meta, dict) else {}


def _dropped(meta: dict[str, Any]) -> dict[str, int]:
    """Messages left out by topic, as our recorder notes them in ``custom_data`` ({} when absent or unreadable)."""
    custom = meta.get("custom_data")
    try:
        counts = json.loads(custom[DROPPED_KEY]) if isinstance(custom, dict) and DROPPED_KEY in custom else {}
    except (TypeError, ValueError):
        return {}
    if not isinstance(counts, dict):
        return {}
    return {str(k): v for k, v in counts.items() if type(v) is int and v > 0}


def _topic(channel: Any, schema: Any, count: int) -> BagTopic:
    return BagTopic(
        name=channel.topic,
        type=schema.name if schema is not None else "",
        serialization_format=channel.message_encoding,
        count=count,
        offered_qos_profiles=channel.metadata.get("offered_qos_profiles", ""),
        type_hash=channel.metadata.get("topic_type_hash", ""),
        definition=schema.data.decode("utf-8", "replace") if schema is not None else "",
    )
