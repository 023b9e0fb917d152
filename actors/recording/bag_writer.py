"""A ROS 2 bag being written: the MCAP file, its topics, and rosbag2's metadata when it closes.

Shared by the in-graph recorder and ``actors bag record``: one schema per
message type (``ros2msg``, the full definition text), one channel per topic
(``cdr``, with ``offered_qos_profiles`` and ``topic_type_hash``), and at the
end rosbag2's ``rosbag2`` metadata record and, for a bag directory,
``metadata.yaml``.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path
from typing import Any

from actors.recording.mcap_writer import McapWriter
from actors.recording.rosbag import (
    ROS_DISTRO,
    TopicRecord,
    metadata_dict,
    metadata_yaml,
    output_paths,
    qos_profiles_yaml,
)

__all__ = ["BagWriter", "LIBRARY"]

LIBRARY = "actors"
"""What the MCAP header names as the writing library."""


class BagWriter:
    """A bag named ``output`` (``NAME.mcap``, or a bag directory ``NAME``), created at once.

    Raises FileExistsError (a bag is never overwritten), FileNotFoundError
    (no such parent directory), OSError or BagError when it cannot be created.
    Use from one thread at a time.
    """

    def __init__(self, output: str | Path, *, compression: str = "zstd", chunk_size: int = 1 << 20) -> None:
        self.directory, self.path = output_paths(output)
        if self.directory is not None:
            self.directory.mkdir()
        # Whole chunks at a time: the writer buffers.  Not a with block: the writer keeps it, close() closes it.
        stream = open(self.path, "wb", buffering=0)  # noqa: SIM115
        try:
            self.mcap = McapWriter(
                stream, profile="ros2", library=LIBRARY, chunk_size=chunk_size, compression=compression
            )
        except BaseException:
            stream.close()
            raise
        self._schemas: dict[str, int] = {}
        self._topics: dict[int, TopicRecord] = {}

    def add_topic(
        self, name: str, ros_type: str, *, definition: str, type_hash: str, offers: Sequence[Any] = ()
    ) -> int:
        """Register a topic (its type's schema once); returns the channel id to write it on."""
        schema = self._schemas.get(ros_type)
        if schema is None:
            schema = self._schemas[ros_type] = self.mcap.add_schema(ros_type, "ros2msg", definition.encode())
        channel = self.mcap.add_channel(
            name,
            schema,
            "cdr",
            {"offered_qos_profiles": qos_profiles_yaml(offers), "topic_type_hash": type_hash},
        )
        self._topics[channel] = TopicRecord(name=name, type=ros_type, offered_qos=tuple(offers), type_hash=type_hash)
        return channel

    def write(self, channel: int, log_time: int, data: bytes) -> None:
        """Add one serialized message (log time in ns, as publish time too)."""
        self.mcap.add_message(channel, log_time, log_time, data)

    def write_many(self, messages: Iterable[tuple[int, int, int, bytes | bytearray]]) -> None:
        """Add serialized messages in order (a generator will do): ``(channel, log time, publish time, data)``."""
        self.mcap.add_messages(messages)

    @property
    def pending_since(self) -> int | None:
        """Log time of the oldest message not yet in the file, if any."""
        return self.mcap.pending_since

    def flush_older_than(self, log_time: int) -> None:
        """Write the chunk in progress if it holds a message older than ``log_time`` (ns)."""
        self.mcap.flush_older_than(log_time)

    @property
    def error(self) -> OSError | None:
        """The write that failed (a full disk), if any: nothing more is written after it."""
        return self.mcap.error

    @property
    def message_count(self) -> int:
        """Messages in the file so far (whole chunks)."""
        return self.mcap.message_count

    @property
    def size(self) -> int:
        """Bytes in the file so far."""
        return self.mcap.size

    def close(self, *, dropped: Mapping[str, int] | None = None) -> None:
        """Write the last chunk, rosbag2's metadata, the summary; then ``metadata.yaml``.

        ``dropped`` counts, by topic, the messages a lossy recorder left out:
        kept in the metadata's ``custom_data`` (``bag info`` shows them).

        Raises OSError when ``metadata.yaml`` cannot be written (the MCAP file
        is complete by then).
        """
        mcap = self.mcap
        mcap.flush()
        counts = mcap.channel_counts
        for channel, record in self._topics.items():
            record.message_count = counts.get(channel, 0)
        start, end = mcap.time_range
        metadata = metadata_dict(
            list(self._topics.values()),
            start=start,
            end=end,
            count=mcap.message_count,
            files=[self.path.name],
            ros_distro=ROS_DISTRO,
            dropped=dropped,
        )
        mcap.add_metadata("rosbag2", {"serialized_metadata": metadata_yaml(metadata, top_level=False)})
        mcap.close()
        if self.directory is not None:
            (self.directory / "metadata.yaml").write_text(metadata_yaml(metadata, top_level=True))
