"""tf2's buffer of coordinate frames, as tf2's BufferCore: stamped transforms, interpolation, lookups.

Each frame (a ``child_frame_id``) keeps the transforms from its parent, newest
first, for ``cache_time`` (10 s by default) behind its newest; a static frame
keeps one, valid at every time.  A lookup walks from the source frame and from
the target frame towards the root until the walks meet, reading each frame at
the requested time: exactly at a stored stamp, or between the two stamps
around it (translation linearly, rotation by tf2's slerp along the shortest
arc); time 0 means the latest time every frame on the way has data for.  The
errors are tf2's, with its wording: :class:`~actors.errors.LookupException` (a
frame nobody published), :class:`~actors.errors.ConnectivityException` (two
trees), :class:`~actors.errors.ExtrapolationException` (a time outside a
frame's data, "into the future" or "into the past"),
:class:`~actors.errors.InvalidArgumentException` (an empty frame id or one
starting with ``/``).  The rules, down to the order of the walks, follow
tf2's buffer_core.cpp and cache.cpp; the maths is plain Python on tuples.

This is the core that ``tf2_ros.Buffer`` (:mod:`actors.compat.tf2_ros`) and
native nodes share; it knows nothing of topics.  Thread-safe: one lock.
"""

from __future__ import annotations

import math
import threading
from collections.abc import Iterator
from typing import Any, NamedTuple

from actors.errors import (
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TransformException,
)
from actors.ros.log import get_logger
from actors.ros.time import Duration, Time
from interfaces.builtin_interfaces.msg import Time as TimeMsg
from interfaces.geometry_msgs.msg import Quaternion, Transform, TransformStamped, Vector3

__all__ = [
    "DEFAULT_CACHE_TIME",
    "LISTENER_AUTHORITY",
    "Vec",
    "Quat",
    "BufferCore",
    "quaternion_multiply",
    "quaternion_inverse",
    "rotate",
    "slerp",
    "stamp_ns",
]

DEFAULT_CACHE_TIME = 10.0  # seconds, tf2's BufferCore::DEFAULT_CACHE_TIME
LISTENER_AUTHORITY = "default_authority"  # what tf2_ros's Python listener records (view_frames' "Broadcaster")
_NS = 1_000_000_000
_MAX_DEPTH = 1000  # tf2's MAX_GRAPH_DEPTH: deeper means a loop
_NORMALIZED = 10e-3  # tf2's QUATERNION_NORMALIZATION_TOLERANCE

Vec = tuple[float, float, float]
Quat = tuple[float, float, float, float]  # x, y, z, w, as geometry_msgs orders them
_IDENTITY: Quat = (0.0, 0.0, 0.0, 1.0)
_ZERO: Vec = (0.0, 0.0, 0.0)


def quaternion_multiply(a: Quat, b: Quat) -> Quat:
    """The Hamilton product ``a * b`` (apply ``b``, then ``a``)."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by + ay * bw + az * bx - ax * bz,
        aw * bz + az * bw + ax * by - ay * bx,
        aw * bw - ax * bx - ay * by - az * bz,
    )


def quaternion_inverse(q: Quat) -> Quat:
    """The inverse of a unit quaternion (its conjugate, as tf2's ``inverse()``)."""
    return (-q[0], -q[1], -q[2], q[3])


def rotate(q: Quat, v: Vec) -> Vec:
    """``v`` rotated by the unit quaternion ``q`` (tf2's ``quatRotate``)."""
    x, y, z, _ = quaternion_multiply(quaternion_multiply(q, (v[0], v[1], v[2], 0.0)), quaternion_inverse(q))
    return (x, y, z)


def slerp(a: Quat, b: Quat, t: float) -> Quat:
    """Spherical interpolation from ``a`` (t = 0) to ``b`` (t = 1) along the shorter arc, as tf2's."""
    dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]
    norms = math.sqrt((a[0] ** 2 + a[1] ** 2 + a[2] ** 2 + a[3] ** 2) * (b[0] ** 2 + b[1] ** 2 + b[2] ** 2 + b[3] ** 2))
    half = math.acos(max(-1.0, min(1.0, abs(dot) / norms)))
    if half == 0.0:
        return a
    d = 1.0 / math.sin(half)
    s0, s1 = math.sin((1.0 - t) * half), math.sin(t * half)
    if dot < 0:
        s1 = -s1
    return (
        (a[0] * s0 + b[0] * s1) * d,
        (a[1] * s0 + b[1] * s1) * d,
        (a[2] * s0 + b[2] * s1) * d,
        (a[3] * s0 + b[3] * s1) * d,
    )


def stamp_ns(time: Any) -> int:
    """Nanoseconds of a Time, a builtin_interfaces Time message, or a number of seconds."""
    if isinstance(time, Time):
        return time.nanoseconds
    if isinstance(time, TimeMsg):
        return time.sec * _NS + time.nanosec
    if isinstance(time, (int, float)) and not isinstance(time, bool):
        return round(time * _NS)
    raise TypeError(f"expected a Time or a builtin_interfaces/msg/Time, got {time!r}")


def _seconds(ns: int) -> str:
    return f"{ns / _NS:.6f}"  # tf2's displayTimePoint


class _Sample(NamedTuple):
    stamp: int
    parent: str
    translation: Vec
    rotation: Quat


class _Miss(Exception):
    """A frame has no data at the time asked: tf2's extrapolation error text."""


class _TimeCache:
    """One frame's transforms from its parent, newest first (tf2's TimeCache)."""

    __slots__ = ("samples", "keep_ns")
    static = False

    def __init__(self, keep_ns: int) -> None:
        self.samples: list[_Sample] = []
        self.keep_ns = keep_ns

    def insert(self, sample: _Sample) -> bool:
        samples = self.samples
        latest = samples[0].stamp if samples else 0
        while samples and samples[-1].stamp + self.keep_ns < latest:
            samples.pop()
        if samples and sample.stamp < latest - self.keep_ns:
            return False
        at = next((i for i, s in enumerate(samples) if s.stamp <= sample.stamp), len(samples))
        same = at
        while same < len(samples) and samples[same].stamp == sample.stamp:
            if samples[same] == sample:
                return True
            same += 1
        samples.insert(at, sample)
        return True

    def _closest(self, t: int) -> tuple[_Sample, _Sample | None]:
        samples = self.samples
        if not samples:
            raise _Miss(
                f"Lookup would require extrapolation at time {_seconds(t)}, but only time 0.000000 is in the buffer"
            )
        if t == 0:
            return samples[0], None
        if len(samples) == 1:
            if samples[0].stamp == t:
                return samples[0], None
            raise _Miss(
                f"Lookup would require extrapolation at time {_seconds(t)}, "
                f"but only time {_seconds(samples[0].stamp)} is in the buffer"
            )
        latest, earliest = samples[0].stamp, samples[-1].stamp
        if t == latest:
            return samples[0], None
        if t == earliest:
            return samples[-1], None
        if t > latest:
            raise _Miss(
                f"Lookup would require extrapolation into the future.  Requested time {_seconds(t)} "
                f"but the latest data is at time {_seconds(latest)}"
            )
        if t < earliest:
            raise _Miss(
                f"Lookup would require extrapolation into the past.  Requested time {_seconds(t)} "
                f"but the earliest data is at time {_seconds(earliest)}"
            )
        i = next(i for i, s in enumerate(samples) if s.stamp <= t)
        return samples[i], samples[i - 1]

    def at(self, t: int) -> _Sample:
        older, newer = self._closest(t)
        if newer is None or older.parent != newer.parent:
            return older
        if newer.stamp == older.stamp:
            return newer
        ratio = (t - older.stamp) / (newer.stamp - older.stamp)
        a, b = older.translation, newer.translation
        translation = (
            a[0] + (b[0] - a[0]) * ratio,
            a[1] + (b[1] - a[1]) * ratio,
            a[2] + (b[2] - a[2]) * ratio,
        )
        return _Sample(older.stamp, older.parent, translation, slerp(older.rotation, newer.rotation, ratio))

    def parent_at(self, t: int) -> str:
        return self._closest(t)[0].parent

    def latest(self) -> tuple[int, str | None]:
        return (self.samples[0].stamp, self.samples[0].parent) if self.samples else (0, None)

    def oldest(self) -> int:
        return self.samples[-1].stamp if self.samples else 0

    def clear(self) -> None:
        self.samples.clear()


class _StaticCache:
    """A static frame: one transform, valid at every time (tf2's StaticCache)."""

    __slots__ = ("sample",)
    static = True

    def __init__(self, sample: _Sample) -> None:
        self.sample = sample

    def insert(self, sample: _Sample) -> bool:
        self.sample = sample
        return True

    def at(self, t: int) -> _Sample:
        return self.sample._replace(stamp=t)

    def parent_at(self, t: int) -> str:
        return self.sample.parent

    def latest(self) -> tuple[int, str | None]:
        return 0, self.sample.parent

    def oldest(self) -> int:
        return 0

    @property
    def samples(self) -> list[_Sample]:
        return [self.sample]

    def clear(self) -> None:
        pass  # tf2 keeps static transforms through a clear


class _Chain:
    """What a walk accumulates: the transforms from the source and from the target up to where they meet."""

    __slots__ = ("gather_data", "source_q", "source_v", "target_q", "target_v", "sample")

    def __init__(self, gather_data: bool) -> None:
        self.gather_data = gather_data
        self.source_q, self.source_v = _IDENTITY, _ZERO
        self.target_q, self.target_v = _IDENTITY, _ZERO
        self.sample: _Sample | None = None

    def gather(self, cache: _TimeCache | _StaticCache, t: int) -> str:
        if self.gather_data:
            self.sample = cache.at(t)
            return self.sample.parent
        return cache.parent_at(t)

    def accumulate(self, from_source: bool) -> None:
        if not self.gather_data:
            return
        sample = self.sample
        assert sample is not None
        if from_source:
            self.source_v = _add(rotate(sample.rotation, self.source_v), sample.translation)
            self.source_q = quaternion_multiply(sample.rotation, self.source_q)
        else:
            self.target_v = _add(rotate(sample.rotation, self.target_v), sample.translation)
            self.target_q = quaternion_multiply(sample.rotation, self.target_q)

    def result(self, ending: str) -> tuple[Vec, Quat]:
        if ending == "identity":
            return _ZERO, _IDENTITY
        if ending == "target_parent_of_source":
            return self.source_v, self.source_q
        inverse_q = quaternion_inverse(self.target_q)
        inverse_v = rotate(inverse_q, (-self.target_v[0], -self.target_v[1], -self.target_v[2]))
        if ending == "source_parent_of_target":
            return inverse_v, inverse_q
        return _add(rotate(inverse_q, self.source_v), inverse_v), quaternion_multiply(inverse_q, self.source_q)


def _add(a: Vec, b: Vec) -> Vec:
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


class BufferCore:
    """Frames and their stamped transforms; lookups between any two frames at any time (tf2's BufferCore).

    ``cache_time`` (a Duration or seconds; default 10 s) is how far behind its
    newest transform a frame keeps older ones.
    """

    def __init__(self, cache_time: Duration | float | None = None) -> None:
        if cache_time is None:
            seconds = DEFAULT_CACHE_TIME
        elif isinstance(cache_time, Duration):
            seconds = cache_time.nanoseconds / _NS
        else:
            seconds = float(cache_time)
        self.cache_ns = round(seconds * _NS)
        self._frames: dict[str, _TimeCache | _StaticCache | None] = {}  # None: only ever a parent (a root)
        self._authority: dict[str, str] = {}
        self._lock = threading.RLock()

    # -- adding ---------------------------------------------------------------------

    def set_transform(self, transform: TransformStamped, authority: str) -> bool:
        """Add a transform, valid at its stamp; False (and an error logged) when tf2 would ignore it."""
        return self._set(transform, authority, static=False)

    def set_transform_static(self, transform: TransformStamped, authority: str) -> bool:
        """Add a transform valid at every time (``/tf_static``); replaces the frame's earlier one."""
        return self._set(transform, authority, static=True)

    def _set(self, transform: TransformStamped, authority: str, *, static: bool) -> bool:
        parent = transform.header.frame_id.lstrip("/")
        child = transform.child_frame_id.lstrip("/")
        t, r = transform.transform.translation, transform.transform.rotation
        translation, rotation = (t.x, t.y, t.z), (r.x, r.y, r.z, r.w)
        problem = _refusal(parent, child, authority, translation, rotation)
        if problem:
            get_logger("tf2").error(problem)
            return False
        sample = _Sample(stamp_ns(transform.header.stamp), parent, translation, rotation)
        with self._lock:
            cache = self._frames.get(child)
            if cache is None or cache.static != static:
                cache = _StaticCache(sample) if static else _TimeCache(self.cache_ns)
                self._frames[child] = cache
            self._frames.setdefault(parent, None)
            if not cache.insert(sample):
                get_logger("tf2").warning(
                    f"TF_OLD_DATA ignoring data from the past for frame {child} at time "
                    f"{_seconds(sample.stamp)} according to authority {authority}"
                )
                return False
            self._authority[child] = authority
        return True

    def clear(self) -> None:
        """Forget every frame's transforms (static ones stay, as in tf2)."""
        with self._lock:
            for cache in self._frames.values():
                if cache is not None:
                    cache.clear()

    # -- lookups --------------------------------------------------------------------

    def lookup_transform_core(self, target_frame: str, source_frame: str, time: Any) -> TransformStamped:
        """The transform taking ``source_frame`` coordinates into ``target_frame``'s, at ``time`` (0: latest).

        Raises LookupException, ConnectivityException, ExtrapolationException or
        InvalidArgumentException with tf2's messages.
        """
        with self._lock:
            stamp, translation, rotation = self._lookup(target_frame, source_frame, stamp_ns(time))
        return _stamped(target_frame, source_frame, stamp, translation, rotation)

    def lookup_transform_full_core(
        self, target_frame: str, target_time: Any, source_frame: str, source_time: Any, fixed_frame: str
    ) -> TransformStamped:
        """ "Time travel": ``source_frame`` at ``source_time`` into ``target_frame`` at ``target_time``.

        The two are joined through ``fixed_frame``, taken not to move in between.
        """
        with self._lock:
            for role, frame in (("target", target_frame), ("source", source_frame), ("fixed", fixed_frame)):
                self._validate(f"lookupTransform argument {role}_frame", frame)
            _, v1, q1 = self._lookup(fixed_frame, source_frame, stamp_ns(source_time))
            stamp, v2, q2 = self._lookup(target_frame, fixed_frame, stamp_ns(target_time))
        return _stamped(target_frame, source_frame, stamp, _add(rotate(q2, v1), v2), quaternion_multiply(q2, q1))

    def can_transform_core(self, target_frame: str, source_frame: str, time: Any) -> tuple[bool, str]:
        """Whether :meth:`lookup_transform_core` would succeed now, and tf2's reason when it would not."""
        with self._lock:
            return self._can(target_frame, source_frame, stamp_ns(time), "canTransform")

    def can_transform_full_core(
        self, target_frame: str, target_time: Any, source_frame: str, source_time: Any, fixed_frame: str
    ) -> tuple[bool, str]:
        """Whether :meth:`lookup_transform_full_core` would succeed now, and why not."""
        with self._lock:
            for role, frame in (("target", target_frame), ("source", source_frame), ("fixed", fixed_frame)):
                problem = self._frame_problem(f"canTransform argument {role}_frame", frame)
                if problem:
                    return False, problem[1]
            ok, why = self._can(target_frame, fixed_frame, stamp_ns(target_time), "canTransform")
            if not ok:
                return ok, why
            return self._can(fixed_frame, source_frame, stamp_ns(source_time), "canTransform")

    def get_latest_common_time(self, target_frame: str, source_frame: str) -> Time:
        """The latest time both frames and every frame between them have data for (0 when all are static)."""
        with self._lock:
            self._validate("getLatestCommonTime argument target_frame", target_frame)
            self._validate("getLatestCommonTime argument source_frame", source_frame)
            return Time(nanoseconds=self._latest_common(target_frame, source_frame))

    def _frame_problem(self, what: str, frame: str) -> tuple[type[TransformException], str] | None:
        if not frame:
            return (
                InvalidArgumentException,
                f'Invalid argument "{frame}" passed to {what} - in tf2 frame_ids cannot be empty',
            )
        if frame.startswith("/"):
            return (
                InvalidArgumentException,
                f"Invalid argument \"{frame}\" passed to {what} - in tf2 frame_ids cannot start with a '/'",
            )
        if frame not in self._frames:
            return LookupException, f'"{frame}" passed to {what} does not exist. '
        return None

    def _validate(self, what: str, frame: str) -> None:
        problem = self._frame_problem(what, frame)
        if problem:
            raise problem[0](problem[1])

    def _lookup(self, target: str, source: str, t: int) -> tuple[int, Vec, Quat]:
        if target == source:
            cache = self._frames.get(target)
            return (cache.latest()[0] if t == 0 and cache is not None else t), _ZERO, _IDENTITY
        self._validate("lookupTransform argument target_frame", target)
        self._validate("lookupTransform argument source_frame", source)
        chain = _Chain(gather_data=True)
        failure = self._walk(chain, target, source, t)
        if isinstance(failure, TransformException):
            raise failure
        stamp, ending = failure
        translation, rotation = chain.result(ending)
        return stamp, translation, rotation

    def _can(self, target: str, source: str, t: int, function: str) -> tuple[bool, str]:
        if target == source:
            return True, ""
        for role, frame in (("target", target), ("source", source)):
            problem = self._frame_problem(f"{function} argument {role}_frame", frame)
            if problem:
                return False, problem[1]
        outcome = self._walk(_Chain(gather_data=False), target, source, t)
        if isinstance(outcome, TransformException):
            return False, str(outcome)
        return True, ""

    def _walk(self, chain: _Chain, target: str, source: str, t: int) -> TransformException | tuple[int, str]:
        """tf2's walkToTopParent: the time used and how the walks met, or the error to raise."""
        if t == 0:
            try:
                t = self._latest_common(target, source)
            except TransformException as exc:
                return exc
        frames = self._frames
        where = f", when looking up transform from frame [{source}] to frame [{target}]"
        frame: str | None = source
        top = source
        missed: str | None = None
        depth = 0
        while frame is not None:
            cache = frames.get(frame)
            if cache is None:
                top = frame
                break
            try:
                parent = chain.gather(cache, t)
            except _Miss as miss:
                top, missed = frame, str(miss)
                break
            if frame == target:
                return t, "target_parent_of_source"
            chain.accumulate(True)
            top, frame = frame, parent
            depth += 1
            if depth > _MAX_DEPTH:
                return self._loop()
        frame = target
        depth = 0
        while frame != top:
            cache = frames.get(frame)
            if cache is None:
                break
            try:
                parent = chain.gather(cache, t)
            except _Miss as miss:
                return ExtrapolationException(f"{miss}{where}")
            if frame == source:
                return t, "source_parent_of_target"
            chain.accumulate(False)
            frame = parent
            depth += 1
            if depth > _MAX_DEPTH:
                return self._loop()
        if frame != top:
            if missed is not None:
                return ExtrapolationException(f"{missed}{where}")
            return ConnectivityException(_unconnected(target, source))
        return t, "full_path"

    def _latest_common(self, target: str, source: str) -> int:
        """tf2's getLatestCommonTime, for two frames known to exist."""
        if target == source:
            cache = self._frames.get(source)
            return cache.latest()[0] if cache is not None else 0
        infinite = 1 << 63
        seen: list[tuple[int, str]] = []
        common = infinite
        for stamp, parent in self._newest_up(source):
            common = min(common, stamp or infinite)
            seen.append((stamp, parent))
            if parent == target:
                return 0 if common == infinite else common
        ancestors = {parent for _, parent in seen}
        common = infinite
        meeting: str | None = None
        for stamp, parent in self._newest_up(target):
            common = min(common, stamp or infinite)
            if parent in ancestors:
                meeting = parent
                break
            if parent == source:
                return 0 if common == infinite else common
        if meeting is None:
            raise ConnectivityException(_unconnected(target, source))
        for stamp, parent in seen:
            common = min(common, stamp or infinite)
            if parent == meeting:
                break
        return 0 if common == infinite else common

    def _newest_up(self, frame: str) -> Iterator[tuple[int, str]]:
        """(stamp, parent) of the newest transform of ``frame``, of its parent, and so on to the root."""
        for _ in range(_MAX_DEPTH + 1):
            cache = self._frames.get(frame)
            if cache is None:
                return
            stamp, parent = cache.latest()
            if parent is None:
                return
            yield stamp, parent
            frame = parent
        raise self._loop()

    def _loop(self) -> LookupException:
        return LookupException(f"The tf tree is invalid because it contains a loop.\n{self._frames_text()}\n")

    # -- describing -------------------------------------------------------------------

    def all_frames_as_string(self) -> str:
        """One line per frame: ``Frame <child> exists with parent <parent>.``"""
        with self._lock:
            return self._frames_text()

    def _frames_text(self) -> str:
        lines = []
        for child, cache in self._frames.items():
            if cache is not None:
                parent = cache.latest()[1] if cache.samples else "NO_PARENT"
                lines.append(f"Frame {child} exists with parent {parent}.\n")
        return "".join(lines)

    def all_frames_as_yaml(self) -> str:
        """Every frame with its parent, broadcaster, rate and times, as tf2's ``allFramesAsYAML``."""
        with self._lock:
            out = []
            for child, info in self._frame_table().items():
                out.append(
                    f"{child}: \n  parent: '{info['parent']}'\n  broadcaster: '{info['broadcaster']}'\n"
                    f"  rate: {info['rate']:.3f}\n  most_recent_transform: {info['most_recent_transform']:.6f}\n"
                    f"  oldest_transform: {info['oldest_transform']:.6f}\n"
                    f"  buffer_length: {info['buffer_length']:.3f}\n"
                )
            return "".join(out) if out else "[]"

    def frame_table(self) -> dict[str, dict[str, Any]]:
        """Each frame that has data: parent, broadcaster, rate (Hz), newest and oldest stamps (s), buffer length (s)."""
        with self._lock:
            return self._frame_table()

    def _frame_table(self) -> dict[str, dict[str, Any]]:
        table = {}
        for child, cache in self._frames.items():
            if cache is None or not cache.samples:
                continue
            latest, parent = cache.latest()
            oldest = cache.oldest()
            span = max(latest - oldest, 100_000)  # tf2 divides by at least 100 µs
            table[child] = {
                "parent": parent,
                "broadcaster": self._authority.get(child, "no recorded authority"),
                "rate": len(cache.samples) * 1e9 / span,
                "most_recent_transform": latest / _NS,
                "oldest_transform": oldest / _NS,
                "buffer_length": (latest - oldest) / _NS,
            }
        return table


def _unconnected(target: str, source: str) -> str:
    return (
        f"Could not find a connection between '{target}' and '{source}' because they are not part of the same tree."
        "Tf has two or more unconnected trees."
    )


def _refusal(parent: str, child: str, authority: str, translation: Vec, rotation: Quat) -> str | None:
    """Why tf2 would ignore this transform (its TF_... error text), or None."""
    if child == parent:
        return (
            f'TF_SELF_TRANSFORM: Ignoring transform from authority "{authority}" with frame_id and  '
            f'child_frame_id "{child}" because they are the same'
        )
    if not child:
        return f'TF_NO_CHILD_FRAME_ID: Ignoring transform from authority "{authority}" because child_frame_id not set '
    if not parent:
        return (
            f'TF_NO_FRAME_ID: Ignoring transform with child_frame_id "{child}"  from authority "{authority}" '
            "because frame_id not set"
        )
    if any(math.isnan(v) for v in (*translation, *rotation)):
        return (
            f'TF_NAN_INPUT: Ignoring transform for child_frame_id "{child}" from authority "{authority}" because'
            " of a nan value in the transform"
        )
    if abs(sum(v * v for v in rotation) - 1.0) >= _NORMALIZED:
        x, y, z, w = rotation
        return (
            f'TF_DENORMALIZED_QUATERNION: Ignoring transform for child_frame_id "{child}" from authority'
            f' "{authority}" because of an invalid quaternion in the transform ({x:f} {y:f} {z:f} {w:f})'
        )
    return None


def _stamped(target: str, source: str, stamp: int, translation: Vec, rotation: Quat) -> TransformStamped:
    result = TransformStamped()
    result.header.frame_id = target
    result.header.stamp = TimeMsg(sec=stamp // _NS, nanosec=stamp % _NS)
    result.child_frame_id = source
    result.transform = Transform(
        translation=Vector3(x=translation[0], y=translation[1], z=translation[2]),
        rotation=Quaternion(x=rotation[0], y=rotation[1], z=rotation[2], w=rotation[3]),
    )
    return result
