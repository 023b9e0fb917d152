"""CDR speed: encode and decode Twist, a 360-beam LaserScan, an Odometry, a 640×480 rgb8 Image, a PointCloud2.

Run: ``python -m bench.cdr [--quick]`` (or scenario ``i`` of ``python -m bench``).
Three codecs side by side, in one run: actors' generated CDR
(``codec.encode_cdr``/``decode_cdr``), rosbags' serializer
(``Typestore.serialize_cdr``/``deserialize_cdr``, ``pip install rosbags``)
and rclpy's ``serialize_message``/``deserialize_message`` (its C typesupport
called from Python; measured in a child process that imports nothing of
actors, see :mod:`bench.cdr_rclpy`).
Each side's message is built by decoding actors' bytes, so all three handle
the same values.  Each sample times a loop; the table shows the median µs
per message and the ratios to rclpy and rosbags (higher is better).

Decoding is compared like with like: rclpy's deserialize (arrays copied
into ``array.array``) with actors' default decode, rosbags' (numeric arrays
as zero-copy numpy views of the input) with ``decode_cdr(..., views=True)``,
the row "actors decode, zero-copy views".  actors and rosbags take turns
sample by sample (:func:`bench.harness.side_by_side`).
"""

from __future__ import annotations

import json
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import Any

from actors import codec
from bench import codec as codec_bench
from bench import ros
from bench.harness import Result, micros_per_call, run_child, side_by_side, standalone
from interfaces.geometry_msgs.msg import Point, Pose, PoseWithCovariance, Quaternion, TwistWithCovariance
from interfaces.nav_msgs.msg import Odometry
from interfaces.sensor_msgs.msg import Image, PointCloud2, PointField
from interfaces.std_msgs.msg import Header

__all__ = ["samples", "run", "actors_case", "worst_ratio"]

SCENARIO = "i. CDR"
ROSBAGS_HINT = "rosbags: not installed — pip install -e '.[bench-ros]'"
VIEWS = "decode, zero-copy views"  # actors' decode_cdr(..., views=True), beside "decode"


def samples() -> dict[str, Any]:
    """The messages measured, by name (the codec benchmark's Twist and LaserScan, and three more)."""
    base = codec_bench.samples()
    header = Header(frame_id="odom")
    odometry = Odometry(
        header=header,
        child_frame_id="base_footprint",
        pose=PoseWithCovariance(
            pose=Pose(position=Point(x=1.0, y=2.0), orientation=Quaternion(z=0.38, w=0.92)),
            covariance=[0.01 * i for i in range(36)],
        ),
        twist=TwistWithCovariance(twist=base["Twist"], covariance=[0.02 * i for i in range(36)]),
    )
    width, height = 640, 480
    image = Image(
        header=Header(frame_id="camera"),
        height=height,
        width=width,
        encoding="rgb8",
        step=3 * width,
        data=bytes(range(256)) * (3 * width * height // 256),
    )
    points = 10_000  # a lidar sweep of x, y, z and intensity, float32 each
    names = ("x", "y", "z", "intensity")
    cloud = PointCloud2(
        header=Header(frame_id="lidar"),
        height=1,
        width=points,
        fields=[PointField(name=n, offset=4 * i, datatype=PointField.FLOAT32, count=1) for i, n in enumerate(names)],
        point_step=16,
        row_step=16 * points,
        data=bytes(range(256)) * (16 * points // 256) + bytes(16 * points % 256),
        is_dense=True,
    )
    return {**base, "Odometry": odometry, "Image 640×480 rgb8": image, "PointCloud2 10k xyzi": cloud}


def loops_for(name: str, quick: bool) -> int:
    """Calls per sample: fewer for the 0.9 MB image and the 160 kB cloud."""
    loops = 50 if name.startswith("Image") else 300 if name.startswith("PointCloud2") else 2000
    return max(1, loops // 20) if quick else loops


def actors_case(baseline: str, verb: str) -> str:
    """The actors row ``baseline``'s ``verb`` row is compared with: a decode with the one that holds the same."""
    return f"actors {VIEWS}" if (baseline, verb) == ("rosbags", "decode") else f"actors {verb}"


def _same(data: bytes, msg: Any, views: bool = False) -> bool:
    """Whether ``data`` holds ``msg``'s values (float32 fields rounded as CDR carries them)."""
    return codec.encode_cdr(codec.decode_cdr(data, type(msg), views=views)) == codec.encode_cdr(msg)


def _actors(msg: Any) -> dict[str, Callable[[], object]]:
    """actors' CDR encode, decode and decode with views of ``msg``, by verb."""
    data, cls = codec.encode_cdr(msg), type(msg)
    assert _same(data, msg) and _same(data, msg, views=True)
    return {
        "encode": lambda: codec.encode_cdr(msg),
        "decode": lambda: codec.decode_cdr(data, cls),
        VIEWS: lambda: codec.decode_cdr(data, cls, views=True),
    }


def _rosbags(msg: Any) -> dict[str, Callable[[], object]] | str:
    """rosbags' CDR serializer on the same message, by verb, or why it cannot run."""
    try:
        from rosbags.typesys import Stores, get_typestore
    except ImportError:
        return ROSBAGS_HINT
    store = get_typestore(Stores.ROS2_KILTED)
    ros_type = msg.__ros_type__
    theirs = store.deserialize_cdr(codec.encode_cdr(msg), ros_type)
    data = store.serialize_cdr(theirs, ros_type)
    assert _same(data, msg)
    return {
        "encode": lambda: store.serialize_cdr(theirs, ros_type),
        "decode": lambda: store.deserialize_cdr(data, ros_type),
    }


def measure(msg: Any, loops: int, reps: int) -> dict[str, dict[str, list[float]] | str]:
    """µs per call of actors' and rosbags' coders of ``msg``, taking turns: side -> verb -> samples."""
    sides = {"actors": _actors(msg), "rosbags": _rosbags(msg)}
    calls = {(side, verb): fn for side, fns in sides.items() if not isinstance(fns, str) for verb, fn in fns.items()}
    timed = side_by_side({key: lambda fn=fn: micros_per_call(fn, loops) for key, fn in calls.items()}, reps)
    return {
        side: fns if isinstance(fns, str) else {verb: timed[side, verb] for verb in fns} for side, fns in sides.items()
    }


def measure_rclpy(quick: bool, reps: int) -> dict[str, dict[str, list[float]]] | str:
    """rclpy's serialize/deserialize of every sample, measured in a child process, or why not."""
    why = ros.unavailable()
    if why is not None:
        return why
    messages = samples()
    spec = {
        "reps": reps,
        "samples": {
            name: {"type": msg.__ros_type__, "cdr": codec.encode_cdr(msg).hex(), "loops": loops_for(name, quick)}
            for name, msg in messages.items()
        },
    }
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "samples.json"
        path.write_text(json.dumps(spec), encoding="utf-8")
        try:
            rows = run_child(["-m", "bench.cdr_rclpy", str(path)], ros.ros_env())
        except Exception as exc:
            return f"rclpy: failed — {exc}"
    for name, msg in messages.items():
        assert _same(bytes.fromhex(rows[name].pop("cdr")), msg)
    return rows


def run(quick: bool) -> list[Result]:
    """The CDR rows of every sample: actors, rosbags and rclpy, encode and decode."""
    reps = 3 if quick else 7
    rclpy_rows = measure_rclpy(quick, reps)
    results = []
    for name, msg in samples().items():
        sides = measure(msg, loops_for(name, quick), reps)
        sides["rclpy"] = rclpy_rows if isinstance(rclpy_rows, str) else rclpy_rows[name]
        size = len(codec.encode_cdr(msg))
        for verb in ("encode", "decode", VIEWS):
            for side, rows in sides.items():
                if verb == VIEWS and side != "actors":
                    continue
                result = Result(f"{SCENARIO} {name}", f"{side} {verb}", "µs/msg", [], higher_better=False)
                if isinstance(rows, str):
                    result.note = rows
                else:
                    result.samples = rows[verb]
                    result.note = f"{1e6 / result.median:,.0f} msg/s, {size:,} B"
                if side == "actors":
                    result.baselines = {
                        base: f"{base} {base_verb}"
                        for base in ("rclpy", "rosbags")
                        for base_verb in ("encode", "decode")
                        if actors_case(base, base_verb) == result.case
                    }
                results.append(result)
    return results


def worst_ratio(get: Callable[[str, str], Result | None], baseline: str) -> tuple[float, str] | None:
    """The smallest ratio of actors to ``baseline`` over every sample and verb, and where it is.

    Each of ``baseline``'s rows is compared with the actors row that holds the same (:func:`actors_case`).
    """
    found = []
    for name in samples():
        for verb in ("encode", "decode"):
            scenario = f"{SCENARIO} {name}"
            ours, theirs = get(scenario, actors_case(baseline, verb)), get(scenario, f"{baseline} {verb}")
            if ours is None or theirs is None or not ours.samples or not theirs.samples:
                return None
            found.append((ours.ratio(theirs), f"{name} {ours.case.removeprefix('actors ')}"))
    return min(found) if found else None


if __name__ == "__main__":
    standalone(run, __doc__, "fewer loops, for a smoke run")
