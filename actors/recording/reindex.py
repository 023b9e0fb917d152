"""``actors bag reindex``: make a bag whose recording was killed whole again, as ``ros2 bag reindex`` does.

A recording stopped by force (``kill -9``, a power cut) leaves MCAP files of
whole chunks with no summary and no footer, and a bag directory without
``metadata.yaml``.  Reindexing reads every whole chunk of each file (what
``bag info --recover`` shows), writes the messages into a new file with its
summary, footer and rosbag2's metadata record, puts it in the old one's place,
and writes ``metadata.yaml`` for a directory: afterwards every reader takes the
bag as it is.  A damaged chunk and what follows it are lost, and said so.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import yaml

from actors.recording.bag_writer import LIBRARY
from actors.recording.mcap_writer import McapWriter
from actors.recording.reader import Bag
from actors.recording.rosbag import TopicRecord, metadata_dict, metadata_yaml

__all__ = ["reindex"]


def reindex(path: str | Path) -> tuple[int, list[str]]:
    """Rewrite the bag at ``path`` whole; returns the messages it keeps and the problems found.

    Raises FileNotFoundError for no bag there, BagError when a file is not
    MCAP at all, OSError when the new files cannot be written (the old ones
    are then untouched).
    """
    bag = Bag(path, recover=True)
    kept, topics, start, end = 0, [], 0, 0
    for file in bag.files:
        count, records, first, last = _rewrite(file)
        topics += records
        if count:
            start = first if not kept else min(start, first)
            end = max(end, last)
        kept += count
    if bag.path.is_dir():
        metadata = _metadata(
            topics, start=start, end=end, count=kept, files=[str(f.relative_to(bag.path)) for f in bag.files]
        )
        (bag.path / "metadata.yaml").write_text(metadata_yaml(metadata, top_level=True))
    return kept, bag.problems


def _rewrite(file: Path) -> tuple[int, list[tuple[TopicRecord, str]], int, int]:
    """One MCAP file rewritten in place from what is readable; its count, topics and time range."""
    bag = Bag(file, recover=True)
    temporary = file.with_name(f".{file.name}.reindex")
    stream = open(temporary, "wb", buffering=0)  # noqa: SIM115  # the writer closes it
    try:
        writer = McapWriter(stream, profile="ros2", library=LIBRARY)
        schemas: dict[str, int] = {}
        channels: dict[str, int] = {}
        for topic in bag.topics:
            schema = schemas.get(topic.type)
            if schema is None:
                schema = schemas[topic.type] = writer.add_schema(topic.type, "ros2msg", topic.definition.encode())
            channels[topic.name] = writer.add_channel(
                topic.name,
                schema,
                topic.serialization_format,
                {"offered_qos_profiles": topic.offered_qos_profiles, "topic_type_hash": topic.type_hash},
            )
        for message in bag.messages():
            writer.add_message(channels[message.topic.name], message.log_time, message.log_time, message.data)
        writer.flush()
        counts = writer.channel_counts
        records = [
            (
                TopicRecord(
                    name=t.name,
                    type=t.type,
                    type_hash=t.type_hash,
                    message_count=counts.get(channels[t.name], 0),
                    serialization_format=t.serialization_format,
                ),
                t.offered_qos_profiles,
            )
            for t in bag.topics
        ]
        start, end = writer.time_range
        metadata = _metadata(records, start=start, end=end, count=writer.message_count, files=[file.name])
        writer.add_metadata("rosbag2", {"serialized_metadata": metadata_yaml(metadata, top_level=False)})
        writer.close()
        if writer.error is not None:
            raise writer.error
    except BaseException:
        stream.close()
        temporary.unlink(missing_ok=True)
        raise
    os.replace(temporary, file)
    return writer.message_count, records, start, end


def _metadata(topics: list[tuple[TopicRecord, str]], *, start: int, end: int, count: int, files: list[str]) -> Any:
    """rosbag2's metadata for ``topics`` (one entry per name), with the QoS text their channels carry."""
    merged: dict[str, TopicRecord] = {}
    profiles: dict[str, str] = {}
    for record, text in topics:
        seen = merged.get(record.name)
        if seen is None:
            merged[record.name] = TopicRecord(**vars(record))
            profiles[record.name] = text
        else:
            seen.message_count += record.message_count
    metadata = metadata_dict(list(merged.values()), start=start, end=end, count=count, files=files)
    for entry in metadata["topics_with_message_count"]:
        # The channel kept the publishers' QoS as rosbag2's YAML: given back as it was written.
        text = profiles[entry["topic_metadata"]["name"]]
        entry["topic_metadata"]["offered_qos_profiles"] = (yaml.safe_load(text) or []) if text else []
    return metadata
