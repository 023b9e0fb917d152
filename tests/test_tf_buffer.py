"""The tf2 buffer core: interpolation against an independent numpy computation, tf2's rules and its wording."""

from __future__ import annotations

import logging
import math
import re

import anyio
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from actors import DurabilityPolicy, Node, QoSProfile, Runtime
from actors.errors import (
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
)
from actors.ops.tf_frames import frames_dot
from actors.ros.tf_buffer import BufferCore
from actors.ros.time import Duration, Time
from interfaces.builtin_interfaces.msg import Time as TimeMsg
from interfaces.geometry_msgs.msg import TransformStamped
from interfaces.tf2_msgs.msg import TFMessage
from nodes.static_transform_publisher import StaticTransformPublisher, parse_args
from nodes.tf2_echo import Tf2Echo
from nodes.view_frames import ViewFrames

NS = 1_000_000_000


def transform(parent: str, child: str, t: float, xyz=(0.0, 0.0, 0.0), q=(0.0, 0.0, 0.0, 1.0)) -> TransformStamped:
    msg = TransformStamped()
    msg.header.frame_id, msg.child_frame_id = parent, child
    ns = round(t * NS)
    msg.header.stamp = TimeMsg(sec=ns // NS, nanosec=ns % NS)
    tr, rot = msg.transform.translation, msg.transform.rotation
    tr.x, tr.y, tr.z = xyz
    rot.x, rot.y, rot.z, rot.w = q
    return msg


def yaw(angle: float) -> tuple[float, float, float, float]:
    return (0.0, 0.0, math.sin(angle / 2), math.cos(angle / 2))


# -- an independent model: numpy matrices, slerp through the exponential map -------------------


def np_matrix(q: np.ndarray) -> np.ndarray:
    x, y, z, w = q / np.linalg.norm(q)
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


def np_multiply(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return np.array(
        [
            aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz,
        ]
    )


def np_slerp(q0: np.ndarray, q1: np.ndarray, t: float) -> np.ndarray:
    """q0 · (q0⁻¹ q1)^t, the power taken through axis and angle, on the shorter arc."""
    if np.dot(q0, q1) < 0:
        q1 = -q1
    relative = np_multiply(q0 * np.array([-1, -1, -1, 1]), q1)
    half = math.acos(max(-1.0, min(1.0, relative[3])))
    if half < 1e-12:
        return q0
    axis = relative[:3] / math.sin(half)
    return np_multiply(q0, np.array([*(axis * math.sin(half * t)), math.cos(half * t)]))


def homogeneous(translation: np.ndarray, q: np.ndarray) -> np.ndarray:
    m = np.eye(4)
    m[:3, :3] = np_matrix(q)
    m[:3, 3] = translation
    return m


unit = (
    st.tuples(*[st.floats(-1, 1)] * 4)
    .filter(lambda q: sum(v * v for v in q) > 0.1)
    .map(lambda q: tuple(v / math.sqrt(sum(c * c for c in q)) for v in q))
)
vector = st.tuples(*[st.floats(-5, 5)] * 3)


@st.composite
def trees(draw):
    """A random tree of frames f0 (root) .. fn, each child with two stamped transforms around [1 s, 2 s]."""
    n = draw(st.integers(2, 6))
    frames = []
    for i in range(1, n + 1):
        parent = draw(st.integers(0, i - 1))
        t0, t1 = draw(st.floats(0.5, 1.0)), draw(st.floats(2.0, 2.5))
        frames.append((f"f{parent}", f"f{i}", (t0, draw(vector), draw(unit)), (t1, draw(vector), draw(unit))))
    pair = draw(st.tuples(st.integers(0, n), st.integers(0, n)))
    return frames, f"f{pair[0]}", f"f{pair[1]}", draw(st.floats(1.0, 2.0))


@settings(max_examples=60, deadline=None)
@given(trees())
def test_interpolated_lookups_equal_an_independent_computation(tree):
    frames, target, source, t = tree
    buffer = BufferCore()
    parents = {}
    for parent, child, first, second in frames:
        parents[child] = (parent, first, second)
        for stamp, xyz, q in (first, second):
            assert buffer.set_transform(transform(parent, child, stamp, xyz, q), "test")
    t_ns = round(t * NS)

    def to_root(frame: str) -> np.ndarray:
        m = np.eye(4)
        while frame in parents:
            parent, (s0, v0, q0), (s1, v1, q1) = parents[frame]
            n0, n1 = round(s0 * NS), round(s1 * NS)
            ratio = (t_ns - n0) / (n1 - n0)
            translation = np.array(v0) + (np.array(v1) - np.array(v0)) * ratio
            m = homogeneous(translation, np_slerp(np.array(q0), np.array(q1), ratio)) @ m
            frame = parent
        return m

    expected = np.linalg.inv(to_root(target)) @ to_root(source)
    found = buffer.lookup_transform_core(target, source, Time(nanoseconds=t_ns))
    tr, rot = found.transform.translation, found.transform.rotation
    got = homogeneous(np.array([tr.x, tr.y, tr.z]), np.array([rot.x, rot.y, rot.z, rot.w]))
    assert np.allclose(got, expected, rtol=0, atol=1e-9)
    assert (found.header.frame_id, found.child_frame_id) == (target, source)
    assert found.header.stamp.sec * NS + found.header.stamp.nanosec == t_ns


def turtle_world() -> BufferCore:
    buffer = BufferCore()
    for t in (1.0, 2.0):
        buffer.set_transform(transform("world", "turtle1", t, (t, 0.0, 0.0), yaw(0.0)), "b1")
        buffer.set_transform(transform("world", "turtle2", t + 0.5, (0.0, t, 0.0), yaw(math.pi / 2)), "b2")
    buffer.set_transform_static(transform("turtle1", "carrot1", 0.0, (0.0, 2.0, 0.0)), "static")
    return buffer


def test_time_zero_is_the_latest_common_time_and_static_frames_hold_at_every_time():
    buffer = turtle_world()
    latest = buffer.lookup_transform_core("turtle2", "turtle1", Time())
    assert (latest.header.stamp.sec, latest.header.stamp.nanosec) == (2, 0)  # turtle1's newest; turtle2's is 2.5
    assert buffer.get_latest_common_time("world", "carrot1").nanoseconds == 2 * NS
    carrot = buffer.lookup_transform_core("world", "carrot1", Time(nanoseconds=1_500_000_000))
    assert (carrot.transform.translation.x, carrot.transform.translation.y) == pytest.approx((1.5, 2.0))


def test_lookups_outside_the_data_raise_tf2s_extrapolation_errors():
    buffer = turtle_world()
    with pytest.raises(ExtrapolationException) as future:
        buffer.lookup_transform_core("turtle2", "turtle1", Time(nanoseconds=3 * NS))
    # Both walks miss; as in tf2, the target's walk reports (turtle2's newest is 2.5 s).
    assert str(future.value) == (
        "Lookup would require extrapolation into the future.  Requested time 3.000000 but the latest data is at "
        "time 2.500000, when looking up transform from frame [turtle1] to frame [turtle2]"
    )
    with pytest.raises(ExtrapolationException, match=r"into the past.  Requested time 0\.500000 but the earliest"):
        buffer.lookup_transform_core("world", "turtle1", Time(nanoseconds=NS // 2))
    ok, why = buffer.can_transform_core("turtle2", "turtle1", Time(nanoseconds=3 * NS))
    assert not ok and why.startswith("Lookup would require extrapolation into the future")


def test_unknown_unconnected_and_invalid_frames_raise_with_tf2s_wording():
    buffer = turtle_world()
    buffer.set_transform(transform("moon", "rover", 1.0), "b3")
    with pytest.raises(LookupException) as unknown:
        buffer.lookup_transform_core("turtle3", "turtle1", Time())
    assert str(unknown.value) == '"turtle3" passed to lookupTransform argument target_frame does not exist. '
    with pytest.raises(ConnectivityException, match="Could not find a connection between 'rover' and 'turtle1'"):
        buffer.lookup_transform_core("rover", "turtle1", Time())
    with pytest.raises(InvalidArgumentException, match="cannot start with a '/'"):
        buffer.lookup_transform_core("/world", "turtle1", Time())
    assert buffer.can_transform_core("turtle3", "turtle1", Time()) == (
        False,
        '"turtle3" passed to canTransform argument target_frame does not exist. ',
    )
    assert buffer.lookup_transform_core("nowhere", "nowhere", Time(nanoseconds=5)).header.stamp.nanosec == 5


def test_time_travel_joins_two_times_through_the_fixed_frame():
    buffer = turtle_world()
    # Where turtle1 was at 1 s, seen from turtle2 at 2 s: world is taken not to move in between.
    found = buffer.lookup_transform_full_core(
        "turtle2", Time(nanoseconds=2 * NS), "turtle1", Time(nanoseconds=NS), "world"
    )
    # turtle1 at 1 s is at (1, 0) in world; turtle2 at 2 s is at (0, 1.5) facing +y.
    x, y = found.transform.translation.x, found.transform.translation.y
    assert (x, y) == pytest.approx((-1.5, -1.0))
    assert (found.header.stamp.sec, found.header.stamp.nanosec) == (2, 0)


def test_the_cache_keeps_ten_seconds_and_bad_transforms_are_refused():
    buffer = BufferCore(Duration(seconds=10))
    for t in range(25):
        buffer.set_transform(transform("world", "turtle1", float(t), (float(t), 0.0, 0.0)), "b")
    # As tf2 prunes: before each insertion, what is more than 10 s older than the newest so far.
    with pytest.raises(ExtrapolationException, match=r"earliest data is at time 13\.000000"):
        buffer.lookup_transform_core("world", "turtle1", Time(nanoseconds=5 * NS))
    assert not buffer.set_transform(transform("world", "turtle1", 3.0), "late")  # older than the cache
    assert not buffer.set_transform(transform("world", "world", 30.0), "b")  # a frame its own parent
    assert not buffer.set_transform(transform("world", "turtle1", 30.0, q=(0.0, 0.0, 0.0, 2.0)), "b")
    assert not buffer.set_transform(transform("world", "", 30.0), "b")
    table = buffer.frame_table()
    assert table["turtle1"]["parent"] == "world" and table["turtle1"]["buffer_length"] == pytest.approx(
        10.0
    )  # pruned again
    assert "turtle1: \n  parent: 'world'\n  broadcaster: 'b'\n  rate: 1.100" in buffer.all_frames_as_yaml()
    assert buffer.all_frames_as_string() == "Frame turtle1 exists with parent world.\n"


def test_a_repeated_stamp_keeps_one_copy_and_clear_keeps_static_frames():
    buffer = turtle_world()
    before = buffer.frame_table()["turtle1"]["rate"]
    buffer.set_transform(transform("world", "turtle1", 2.0, (2.0, 0.0, 0.0), yaw(0.0)), "b1")
    assert buffer.frame_table()["turtle1"]["rate"] == before
    buffer.clear()
    assert not buffer.can_transform_core("world", "turtle1", Time())[0]
    assert buffer.can_transform_core("turtle1", "carrot1", Time())[0]


class StaticFrames(Node):
    def __init__(self, *transforms: TransformStamped) -> None:
        super().__init__("static_frames")
        latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.create_publisher(TFMessage, "/tf_static", latched).publish(TFMessage(transforms=list(transforms)))


@pytest.mark.virtual_time
async def test_tf2_echo_prints_the_transform_as_tf2_ros_does(capsys, caplog):
    caplog.set_level(logging.INFO, logger="actors")
    async with Runtime() as rt:
        rt.spawn(Tf2Echo, params={"source_frame": "world", "target_frame": "turtle1"})
        await anyio.sleep(1.5)
        rt.spawn(StaticFrames, transform("world", "turtle1", 0.0, (2.796, 1.039, 0.0), yaw(0.405)))
        await anyio.sleep(1.0)
    assert any(
        r.getMessage().startswith('Waiting for transform world ->  turtle1: "world" passed to canTransform')
        for r in caplog.records
    )
    assert capsys.readouterr().out == (
        "At time 0.0\n"
        "- Translation: [2.796, 1.039, 0.000]\n"
        "- Rotation: in Quaternion [0.000, 0.000, 0.201, 0.980]\n"
        "- Rotation: in RPY (radian) [0.000, -0.000, 0.405]\n"
        "- Rotation: in RPY (degree) [0.000, -0.000, 23.205]\n"
        "- Matrix:\n"
        "  0.919 -0.394  0.000  2.796\n"
        "  0.394  0.919  0.000  1.039\n"
        "  0.000  0.000  1.000  0.000\n"
        "  0.000  0.000  0.000  1.000\n"
    )


@pytest.mark.virtual_time
async def test_static_transform_publisher_reads_the_real_command_line_and_latches_it(caplog):
    caplog.set_level(logging.INFO, logger="actors")
    params = parse_args(["--x", "1", "--yaw", str(math.pi / 2), "--frame-id", "world", "--child-frame-id", "mystatic"])
    assert (params["translation.x"], params["rotation.z"]) == (1.0, pytest.approx(math.sqrt(0.5)))
    for wrong, why in (
        (["--x", "one", "--frame-id", "a", "--child-frame-id", "b"], "'one' is not a number"),
        (["--x", "1"], "both --frame-id and --child-frame-id are required"),
        (["--qz", "1", "--yaw", "1", "--frame-id", "a", "--child-frame-id", "b"], "both quaternion and Euler"),
        (["--size", "3"], "unknown argument '--size'"),
    ):
        with pytest.raises(ValueError, match=why):
            parse_args(wrong)
    async with Runtime() as rt:
        rt.spawn(StaticTransformPublisher, params=params)
        await anyio.sleep(0.5)
        echo = rt.spawn(Tf2Echo, params={"source_frame": "world", "target_frame": "mystatic"})
        await anyio.sleep(1.5)
        assert echo.buffer.lookup_transform_core("world", "mystatic", Time()).transform.translation.x == 1.0
    text = "\n".join(r.getMessage() for r in caplog.records)
    assert "translation: ('1.000000', '0.000000', '0.000000')\nrotation: ('0.000000', '0.000000', '0.707107'" in text
    assert "from 'world' to 'mystatic'" in text


class MovingWheel(Node):
    """Broadcasts base_link -> wheel on /tf at 10 Hz, as a dynamic broadcaster does."""

    def __init__(self) -> None:
        super().__init__("moving_wheel")
        self.pub = self.create_publisher(TFMessage, "/tf", 100)
        self.create_timer(0.1, self.tick)

    def tick(self) -> None:
        now = self.get_clock().now().nanoseconds / NS
        self.pub.publish(TFMessage(transforms=[transform("base_link", "wheel", now, (0.0, 0.2, 0.0), yaw(now))]))


@pytest.mark.virtual_time
async def test_view_frames_writes_the_tree_as_graphviz_and_a_picture(tmp_path, caplog, monkeypatch):
    import xml.etree.ElementTree as ET

    caplog.set_level(logging.INFO, logger="actors")
    monkeypatch.setattr("shutil.which", lambda name: None)  # the picture drawn here, not by Graphviz
    async with Runtime() as rt:
        rt.spawn(StaticFrames, transform("world", "base_link", 0.0), transform("base_link", "camera", 0.0))
        rt.spawn(MovingWheel)
        viewer = rt.spawn(ViewFrames, params={"wait_time": 2.0, "output": str(tmp_path / "frames")})
        await anyio.sleep(3.0)
    gv, svg = viewer.written
    assert (gv, svg) == (tmp_path / "frames.gv", tmp_path / "frames.svg")
    assert [r.getMessage() for r in caplog.records if r.name.endswith("view_frames")] == [
        "Listening to tf data for 2.0 seconds...",
        "Generating graph...",
        f"Exporting graph in {svg} file...",
    ]
    dot = gv.read_text()
    edges = set(re.findall(r'^"(\w+)" -> "(\w+)"\[', dot, re.M))
    assert edges == {("world", "base_link"), ("base_link", "camera"), ("base_link", "wheel")}
    wheel = re.search(r'"base_link" -> "wheel"\[label=" ([^"]*)"\]', dot)
    # 19 stamps from 0.1 s to 1.9 s: tf2's rate is their count over their span; YAML's floats printed
    assert wheel and wheel[1] == (
        "Broadcaster: default_authority\\nAverage rate: 10.556\\nBuffer length: 1.8\\n"
        "Most recent transform: 1.9\\nOldest transform: 0.1\\n"
    )
    assert dot.endswith('"Recorded at time: 2.0"[ shape=plaintext ] ;\n}->"world";\n}')
    assert frames_dot({}, 2.0) == 'digraph G { "No tf data received" }'
    tree = ET.fromstring(svg.read_text())
    boxes = {}
    for text in tree.iter("{http://www.w3.org/2000/svg}text"):
        if text.get("font-size") == "14":
            boxes[text.text] = (float(text.get("x")), float(text.get("y")))
    assert set(boxes) == {"world", "base_link", "camera", "wheel"}
    # the root on top, its child a row under it, the two leaves a row lower, side by side
    assert boxes["world"][1] < boxes["base_link"][1] < boxes["camera"][1] == boxes["wheel"][1]
    assert boxes["camera"][0] < boxes["base_link"][0] < boxes["wheel"][0]


async def test_view_frames_that_cannot_write_says_so_in_one_line_and_ends(tmp_path, caplog):
    caplog.set_level(logging.INFO, logger="actors")
    (tmp_path / "taken").write_text("a file where the tool wants a folder")
    async with Runtime() as rt:
        rt.spawn(StaticFrames, transform("world", "base_link", 0.0))
        viewer = rt.spawn(ViewFrames, params={"wait_time": 1.0, "output": str(tmp_path / "taken" / "frames")})
        await anyio.sleep(3.0)
    assert viewer.written == []
    lines = [r.getMessage() for r in caplog.records if r.name.endswith("view_frames")]
    assert lines[-1].startswith("cannot write the frame tree: ")
    assert lines.count("Listening to tf data for 1.0 seconds...") == 1  # not restarted


def test_view_frames_with_no_folder_for_its_output_exits_2(run_module, tmp_path):
    done = run_module("actors", "run", "tf2_tools", "view_frames", "-o", str(tmp_path / "missing" / "frames"))
    assert (done.returncode, done.stdout) == (2, "")
    assert done.stderr == f"view_frames: -o {tmp_path}/missing/frames: no folder {tmp_path}/missing to write into\n"
