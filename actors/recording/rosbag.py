"""rosbag2's conventions around an MCAP file: QoS text, bag metadata, bag directories.

``ros2 bag record -o NAME`` makes a directory ``NAME`` holding ``NAME_0.mcap``
and ``metadata.yaml``; a single ``.mcap`` file is a bag too (``ros2 bag info
run.mcap`` reads its summary and its ``rosbag2`` metadata record).  Both are
written here in rosbag2's metadata version 9: a channel's
``offered_qos_profiles`` is the YAML list rosbag2 writes (policies by name,
durations as ``sec``/``nsec``, infinite as rmw's 9223372036 s 854775807 ns).
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

__all__ = [
    "METADATA_VERSION",
    "DROPPED_KEY",
    "ROS_DISTRO",
    "TopicRecord",
    "qos_profiles_yaml",
    "metadata_dict",
    "metadata_yaml",
    "bag_files",
    "output_paths",
]

METADATA_VERSION = 9
"""The rosbag2 metadata version written (ROS 2 Jazzy and Kilted write 9)."""

DROPPED_KEY = "actors.dropped_messages"
"""The ``custom_data`` key of the messages a lossy recorder left out: JSON, counts by topic name."""

_INFINITE = {"sec": 9223372036, "nsec": 854775807}  # RMW_DURATION_INFINITE
_HISTORY = {1: "keep_last", 2: "keep_all"}
_RELIABILITY = {1: "reliable", 2: "best_effort"}
_DURABILITY = {1: "transient_local", 2: "volatile"}


def _duration(qos: Any, name: str) -> dict[str, int]:
    """rmw's form of a QoS duration (``deadline``...): ``sec``/``nsec``; none or infinite is infinite."""
    ns = getattr(qos, f"{name}_ns", None)  # an endpoint's QoSSnapshot
    if ns is None:
        ns = getattr(getattr(qos, name, None), "nanoseconds", None)  # a QoSProfile's Duration
    if not isinstance(ns, int) or ns <= 0 or ns >= 2**63 - 1:
        return dict(_INFINITE)
    return {"sec": ns // 1_000_000_000, "nsec": ns % 1_000_000_000}


def _profile(qos: Any) -> dict[str, Any]:
    liveliness = getattr(qos, "liveliness", None)
    return {
        "history": _HISTORY.get(int(qos.history), "system_default"),
        "depth": int(qos.depth),
        "reliability": _RELIABILITY.get(int(qos.reliability), "system_default"),
        "durability": _DURABILITY.get(int(qos.durability), "system_default"),
        "deadline": _duration(qos, "deadline"),
        "lifespan": _duration(qos, "lifespan"),
        "liveliness": "manual_by_topic" if liveliness is not None and int(liveliness) == 3 else "automatic",
        "liveliness_lease_duration": _duration(qos, "liveliness_lease_duration"),
        "avoid_ros_namespace_conventions": bool(getattr(qos, "avoid_ros_namespace_conventions", False)),
    }


def _dump(data: Any) -> str:
    return yaml.safe_dump(data, sort_keys=False, default_flow_style=False, width=1 << 16)


def qos_profiles_yaml(profiles: Iterable[Any]) -> str:
    """The ``offered_qos_profiles`` text of a channel: one entry per publisher's QoS profile."""
    entries = [_profile(q) for q in profiles]
    return _dump(entries).rstrip("\n") if entries else ""


@dataclass
class TopicRecord:
    """One topic of a bag as rosbag2's metadata lists it."""

    name: str
    type: str
    offered_qos: Sequence[Any] = ()
    type_hash: str = ""
    message_count: int = 0
    serialization_format: str = "cdr"


#: What rosbag2 writes as ``ros_distro`` (``bag info``'s "ROS Distro"): the distribution whose
#: interfaces and type hashes actors speaks, whatever ROS the machine has or lacks.
ROS_DISTRO = "kilted"


def metadata_dict(
    topics: Sequence[TopicRecord],
    *,
    start: int,
    end: int,
    count: int,
    files: Sequence[str],
    ros_distro: str = "",
    dropped: Mapping[str, int] | None = None,
) -> dict[str, Any]:
    """rosbag2's BagMetadata (version 9) as plain data: what ``metadata.yaml`` holds.

    ``dropped`` (messages left out, by topic) goes into ``custom_data``, the
    string map rosbag2 keeps for its users, under :data:`DROPPED_KEY`.
    """
    duration = max(0, end - start)
    return {
        "version": METADATA_VERSION,
        "storage_identifier": "mcap",
        "duration": {"nanoseconds": duration},
        "starting_time": {"nanoseconds_since_epoch": start},
        "message_count": count,
        "topics_with_message_count": [
            {
                "topic_metadata": {
                    "name": t.name,
                    "type": t.type,
                    "serialization_format": t.serialization_format,
                    "offered_qos_profiles": [_profile(q) for q in t.offered_qos],
                    "type_description_hash": t.type_hash,
                },
                "message_count": t.message_count,
            }
            for t in topics
        ],
        "compression_format": "",
        "compression_mode": "",
        "relative_file_paths": list(files),
        "files": [
            {
                "path": name,
                "starting_time": {"nanoseconds_since_epoch": start},
                "duration": {"nanoseconds": duration},
                "message_count": count,
            }
            for name in files
        ],
        "custom_data": {DROPPED_KEY: json.dumps(dict(dropped), sort_keys=True)} if dropped else None,
        "ros_distro": ros_distro,
    }


def metadata_yaml(metadata: dict[str, Any], *, top_level: bool) -> str:
    """The metadata as YAML: under ``rosbag2_bagfile_information:`` for ``metadata.yaml``
    (``top_level``), bare for the MCAP ``rosbag2`` record's ``serialized_metadata``."""
    return _dump({"rosbag2_bagfile_information": metadata} if top_level else metadata)


def output_paths(output: str | Path) -> tuple[Path | None, Path]:
    """Where a recording named ``output`` goes: ``(bag directory or None, MCAP file)``.

    A name ending in ``.mcap`` is one file; any other name is a rosbag2 bag
    directory holding ``<name>_0.mcap`` and ``metadata.yaml``.  Raises
    FileExistsError when the name is taken (a bag is never overwritten) and
    FileNotFoundError when its parent directory does not exist.
    """
    path = Path(output)
    if path.exists():
        raise FileExistsError(f"{path} already exists: choose another name or remove it")
    if not path.parent.is_dir():
        raise FileNotFoundError(f"{path.parent} is not a directory")
    if path.suffix == ".mcap":
        return None, path
    return path, path / f"{path.name}_0.mcap"


def bag_files(path: str | Path) -> list[Path]:
    """The MCAP files of a bag: the file itself, or the ``.mcap`` files of a bag directory.

    A directory's files come in its ``metadata.yaml``'s order when it has one,
    else sorted.  Raises FileNotFoundError for a missing path or a directory
    with no MCAP file.
    """
    path = Path(path)
    if not path.exists():
        raise FileNotFoundError(f"{path} does not exist")
    if not path.is_dir():
        return [path]
    files: list[Path] = []
    meta = path / "metadata.yaml"
    if meta.is_file():
        try:
            info = yaml.safe_load(meta.read_text(encoding="utf-8")) or {}
            names = info.get("rosbag2_bagfile_information", {}).get("relative_file_paths", [])
            files = [path / name for name in names if str(name).endswith(".mcap")]
        except (yaml.YAMLError, AttributeError, OSError):
            files = []
    if not files:
        files = sorted(path.glob("*.mcap"))
    if not files:
        raise FileNotFoundError(f"{path} holds no .mcap file")
    return files
