"""CDR: bit-exact with rclpy (committed goldens everywhere, live where rclpy is installed), round trips, bad input."""

from __future__ import annotations

import json
import math
import random
import re
import struct
import tracemalloc
from array import array
from pathlib import Path

import pytest
from goldens.ros import padding_positions, same_wire
from goldens.values import DrawPick, message, shipped_messages
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from actors import codec
from actors.errors import CdrError, MessageValidationError
from actors.messages import cdr
from actors.messages import generate as idl_gen
from interfaces.geometry_msgs.msg import Twist, Vector3
from interfaces.sensor_msgs.msg import Imu, LaserScan
from interfaces.std_msgs.msg import (
    Bool,
    Empty,
    Float64MultiArray,
    Header,
    MultiArrayDimension,
    MultiArrayLayout,
    String,
)
from interfaces.unique_identifier_msgs.msg import UUID

GOLDENS = json.loads((Path(__file__).parent / "goldens" / "cdr.json").read_text())
ENTRIES = GOLDENS["messages"]
SHIPPED = shipped_messages()


def _id(entry: dict) -> str:
    return entry["type"]


# --------------------------------------------------------------------------- rclpy's bytes


@pytest.mark.parametrize("entry", ENTRIES, ids=_id)
def test_encode_matches_rclpy_golden(entry):
    msg = codec.convert(entry["value"], entry["type"])
    assert same_wire(msg, bytes.fromhex(entry["cdr"])) is None


@pytest.mark.parametrize("entry", ENTRIES, ids=_id)
def test_decode_reads_rclpy_golden(entry):
    assert codec.decode_cdr(bytes.fromhex(entry["cdr"]), entry["type"]) == codec.convert(entry["value"], entry["type"])


def test_every_shipped_message_has_goldens_or_no_rclpy_package():
    covered = {entry["type"] for entry in ENTRIES}
    lacking = set(GOLDENS["no_rclpy_type"])
    assert covered | lacking == set(SHIPPED)
    # Only the packages that have no ROS wheel may lack rclpy goldens (tf2_msgs: see test_tf_message_*).
    no_wheel = {
        "example_interfaces",
        "tutorial_interfaces",
        "tf2_msgs",
        "statistics_msgs",
        "turtlesim_msgs",
    }
    assert {name.split("/")[0] for name in lacking} <= no_wheel


def test_goldens_hold_more_than_defaults():
    twists = [bytes.fromhex(e["cdr"]) for e in ENTRIES if e["type"] == "geometry_msgs/msg/Twist"]
    assert len(set(twists)) == len(twists) >= 4


@pytest.mark.parametrize("name", SHIPPED)
@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(data=st.data())
def test_encode_matches_live_rclpy(name, data):
    serialization = pytest.importorskip("rclpy.serialization", reason="live comparison needs rclpy (bench-ros extra)")
    from goldens.ros import rclpy_class, to_rclpy

    try:
        rclpy_class(name)
    except ImportError:
        pytest.skip(f"rclpy has no {name}")
    msg = message(codec.get_type(name), DrawPick(data))
    theirs = serialization.serialize_message(to_rclpy(msg))
    assert same_wire(msg, theirs) is None
    assert cdr.decode(theirs, type(msg)) == msg
    assert serialization.deserialize_message(cdr.encode(msg), type(to_rclpy(msg))) == to_rclpy(msg)


# tf2_msgs has no wheel to make rclpy goldens with, so rosbags (a second, independent implementation of
# ROS 2's CDR) wrote these bytes: /tf's message with two transforms, strings of odd lengths between doubles.
TF_MESSAGE_CDR = (
    "00010000 02000000 0c000000 0065cd1d 05000000 6f646f6d00 000000 0f000000 626173655f666f6f747072696e7400"
    "0000000000 000000000000f83f 000000000000d0bf 0000000000000000 0000000000000000 0000000000000000"
    "333333333333e33f 9a9999999999e93f 00000000 00000000 06000000 776f726c6400 0000 05000000 6f646f6d00 000000"
    "0000000000000000 0000000000000000 0000000000000000 0000000000000000 0000000000000000"
    "0000000000000000 000000000000f03f"
)


def _tf_message():
    from interfaces.builtin_interfaces.msg import Time
    from interfaces.geometry_msgs.msg import Quaternion, Transform, TransformStamped
    from interfaces.tf2_msgs.msg import TFMessage

    moved = Transform(translation=Vector3(x=1.5, y=-0.25), rotation=Quaternion(z=0.6, w=0.8))
    return TFMessage(
        transforms=[
            TransformStamped(
                header=Header(stamp=Time(sec=12, nanosec=500_000_000), frame_id="odom"),
                child_frame_id="base_footprint",
                transform=moved,
            ),
            TransformStamped(header=Header(frame_id="world"), child_frame_id="odom"),
        ]
    )


def test_tf_message_matches_its_golden():
    golden = bytes.fromhex(TF_MESSAGE_CDR)
    assert cdr.encode(_tf_message()) == golden
    assert codec.decode_cdr(golden, "tf2_msgs/msg/TFMessage") == _tf_message()


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_tf_message_matches_rosbags(data):
    typesys = pytest.importorskip("rosbags.typesys", reason="the second implementation is rosbags (test extra)")
    store = typesys.get_typestore(typesys.Stores.ROS2_KILTED)
    name = "tf2_msgs/msg/TFMessage"
    msg = message(codec.get_type(name), DrawPick(data))
    ours = codec.encode_cdr(msg)
    theirs = store.deserialize_cdr(ours, name)
    assert [t.child_frame_id for t in theirs.transforms] == [t.child_frame_id for t in msg.transforms]
    assert bytes(store.serialize_cdr(theirs, name)) == ours
    assert store.hash_rihs01(name) == codec.type_hash(name)


# --------------------------------------------------------------------------- round trips and layout


def test_known_bytes():
    assert cdr.encode(String(data="hi")) == bytes.fromhex("00010000 03000000 686900")
    assert cdr.encode(Empty()) == bytes.fromhex("00010000 00")  # rosidl's placeholder byte
    assert cdr.encode(Bool(data=True)) == bytes.fromhex("00010000 01")
    assert cdr.encode(Twist(linear=Vector3(x=1.5))) == cdr.HEADER + struct.pack("<6d", 1.5, 0, 0, 0, 0, 0)
    # Alignment counts from after the header: a float64 after a 5-byte string starts at offset 16.
    header = Header(frame_id="abcd")
    assert cdr.encode(header) == bytes.fromhex("00010000 0000000000000000 05000000 6162636400")
    imu = cdr.encode(Imu(header=header))
    assert imu[4 + 17 : 4 + 24] == b"\0" * 7 and len(imu) == 4 + 24 + 32 + 3 * 72 + 2 * 24


def test_padding_is_zero_and_can_be_marked():
    msg = Float64MultiArray(layout=MultiArrayLayout(dim=[MultiArrayDimension(label="a")]), data=[2.0])
    plain = cdr.encode(msg)
    positions = padding_positions(msg)
    assert positions and all(plain[i] == 0 for i in positions)
    assert cdr.decode(cdr.encode(msg, padding=0xA5), Float64MultiArray) == msg


def test_empty_sequence_of_doubles_adds_no_alignment():
    # dim count, data_offset, data count: 12 bytes, no padding for the (absent) first double
    assert cdr.encode(Float64MultiArray()) == cdr.HEADER + bytes(12)


def test_big_endian_input():
    data = b"\x00\x00\x00\x00" + struct.pack(">I", 3) + b"hi\0"
    assert cdr.decode(data, String) == String(data="hi")
    twist = b"\x00\x00\x00\x00" + struct.pack(">6d", 1, 2, 3, 4, 5, 6)
    assert cdr.decode(twist, Twist) == Twist(linear=Vector3(x=1, y=2, z=3), angular=Vector3(x=4, y=5, z=6))
    scan = (
        b"\x00\x00\x00\x00"
        + struct.pack(">iI", 7, 8)
        + struct.pack(">I", 1)
        + b"\0"
        + b"\0" * 3
        + struct.pack(">7f", *[0.5] * 7)
        + struct.pack(">I", 2)
        + struct.pack(">2f", 1.5, 2.5)
        + struct.pack(">I", 0)
    )
    decoded = cdr.decode(scan, LaserScan)
    assert decoded.header.stamp.sec == 7 and decoded.ranges == array("f", [1.5, 2.5]) and decoded.scan_time == 0.5


def test_nan_and_infinity_survive():
    scan = cdr.decode(cdr.encode(LaserScan(ranges=[math.inf, -math.inf, math.nan])), LaserScan)
    assert scan.ranges[:2] == array("f", [math.inf, -math.inf]) and math.isnan(scan.ranges[2])


def test_decode_accepts_bytearray_and_memoryview():
    data = cdr.encode(Header(frame_id="x"))
    assert cdr.decode(bytearray(data), Header) == cdr.decode(memoryview(data), Header) == Header(frame_id="x")


# --------------------------------------------------------------------------- a user type with every shape


TEST_MSG = """\
wstring w
wstring<=3 w_bounded
string<=4 s_bounded
bool[3] flags
bool[] more_flags
char c
byte b
byte[2] bs
int8 i8
float64[<=2] bounded
Inner[2] pair
Inner[<=2] inners
string[2] names
float32 tail
"""
INNER_MSG = "int8 a\nfloat64 b\nstring s\n"


@pytest.fixture(scope="module")
def shapes(tmp_path_factory):
    root = tmp_path_factory.mktemp("root") / "cdr_shapes"
    (root / "cdr_shapes_pkg" / "msg").mkdir(parents=True)
    (root / "cdr_shapes_pkg" / "msg" / "Shapes.msg").write_text(TEST_MSG)
    (root / "cdr_shapes_pkg" / "msg" / "Inner.msg").write_text(INNER_MSG)
    idl_gen.generate([root])
    codec.register_root(root)
    return codec.get_type("cdr_shapes_pkg/msg/Shapes"), codec.get_type("cdr_shapes_pkg/msg/Inner")


def test_wstring_as_fast_cdr_writes_it(shapes):
    shape, _ = shapes
    data = cdr.encode(shape(w="aé😀"))
    # UTF-16 code units, each as 4 bytes, no terminator (as rclpy's test_msgs/WStrings shows).
    assert data[4:24] == bytes.fromhex("04000000 61000000 e9000000 3dd80000 00de0000")
    assert cdr.decode(data, shape).w == "aé😀"


@settings(max_examples=60, deadline=None)
@given(data=st.data())
def test_every_shape_round_trips(shapes, data):
    shape, _ = shapes
    msg = message(shape, DrawPick(data))
    assert cdr.decode(cdr.encode(msg), shape) == msg


def test_bounds_are_checked_both_ways(shapes):
    shape, inner = shapes
    with pytest.raises(
        CdrError, match=r"cdr_shapes_pkg/msg/Shapes: expected at most 4 characters, got 5 - at `\$.s_bounded`"
    ):
        cdr.encode(shape(s_bounded="abcde"))
    with pytest.raises(CdrError, match=r"at most 2 items, got 3 - at `\$.inners`"):
        cdr.encode(shape(inners=[inner()] * 3))
    too_long = bytearray(cdr.encode(shape(bounded=[1.0, 2.0])))
    count = re.search(re.escape(struct.pack("<I", 2)) + b"(\0{4})?" + re.escape(struct.pack("<d", 1.0)), too_long)
    too_long[count.start()] = 3
    with pytest.raises(CdrError, match=r"3 items, more than its bound 2 - at `\$.bounded`"):
        cdr.decode(bytes(too_long), shape)


# --------------------------------------------------------------------------- bad values


@pytest.mark.parametrize(
    ("msg", "message"),
    [
        (
            codec.get_type("std_msgs/msg/Int8")(data=300),
            r"std_msgs/msg/Int8: 300 is out of range for int8 \[-128, 127\] - at `\$.data`",
        ),
        (Imu(orientation_covariance=[0.0] * 8), r"expected exactly 9 items, got 8 - at `\$.orientation_covariance`"),
        (UUID(uuid=b"short"), r"expected exactly 16 items, got 5 - at `\$.uuid`"),
        (Header(frame_id=3), r"expected str, got int - at `\$.frame_id`"),
        (Twist(linear=Header()), r"expected geometry_msgs/msg/Vector3, got Header - at `\$.linear`"),
        (
            Float64MultiArray(layout=MultiArrayLayout(dim=[MultiArrayDimension(size=-1)])),
            r"at `\$.layout.dim\[0\].size`",
        ),
    ],
)
def test_encode_names_the_bad_field(msg, message):
    with pytest.raises(CdrError, match=message):
        cdr.encode(msg)


def test_encode_refuses_what_is_not_a_message():
    with pytest.raises(TypeError):
        cdr.encode({"data": 1})


def test_cdr_error_is_a_validation_error():
    assert issubclass(CdrError, MessageValidationError)


# --------------------------------------------------------------------------- bad bytes


def test_truncation_names_the_field():
    data = cdr.encode(
        Float64MultiArray(
            layout=MultiArrayLayout(dim=[MultiArrayDimension(label="x"), MultiArrayDimension(label="yzwvutsr")])
        )
    )
    with pytest.raises(
        CdrError, match=r"^std_msgs/msg/Float64MultiArray: a string of 9 bytes, 6 left - at `\$.layout.dim\[1\].label`$"
    ):
        cdr.decode(data[:34], Float64MultiArray)
    with pytest.raises(CdrError, match=r"2 items cannot fit in 22 bytes - at `\$.layout.dim`$"):
        cdr.decode(data[:30], Float64MultiArray)
    with pytest.raises(CdrError, match=r"truncated: the data ends at byte 36 - at `\$.angular.y`"):
        cdr.decode(cdr.encode(Twist())[:36], Twist)


def test_header_must_be_plain_cdr():
    with pytest.raises(CdrError, match=r"not plain CDR \(the header is 00 07 00 00"):
        cdr.decode(b"\x00\x07\x00\x00" + bytes(48), Twist)
    with pytest.raises(CdrError, match="the header is nothing"):
        cdr.decode(b"", Twist)


def test_huge_lengths_are_refused_before_allocating():
    forged = cdr.HEADER + struct.pack("<I", 0xFFFF_FFF0) * 20  # every length says 4 GiB
    for cls in (Header, MultiArrayLayout, LaserScan, Float64MultiArray):
        cdr.decode(cdr.encode(cls()), cls)  # build the decoder outside the measurement
        tracemalloc.start()
        with pytest.raises(CdrError):
            cdr.decode(forged, cls)
        peak = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        assert peak < 200_000, cls


def test_string_without_terminator_and_invalid_utf8():
    with pytest.raises(CdrError, match=r"without its terminating NUL - at `\$.data`"):
        cdr.decode(cdr.HEADER + struct.pack("<I", 2) + b"ab", String)
    with pytest.raises(CdrError, match=r"not valid UTF-8 - at `\$.data`"):
        cdr.decode(cdr.HEADER + struct.pack("<I", 2) + b"\xff\0", String)


@pytest.mark.parametrize("entry", ENTRIES[::7], ids=_id)
def test_every_truncation_is_a_cdr_error(entry):
    msg = codec.convert(entry["value"], entry["type"])
    data = cdr.encode(msg)
    for end in range(len(data)):
        with pytest.raises(CdrError, match=f"^{entry['type']}: "):
            cdr.decode(data[:end], type(msg))


FUZZED = [
    "std_msgs/msg/String",
    "sensor_msgs/msg/LaserScan",
    "std_msgs/msg/Float64MultiArray",
    "rcl_interfaces/msg/ParameterEvent",
    "nav_msgs/msg/Path",
    "action_msgs/msg/GoalStatusArray",
]


@pytest.mark.parametrize("name", FUZZED)
@settings(max_examples=150, deadline=None)
@given(body=st.binary(max_size=200), endian=st.sampled_from([b"\x00\x01\x00\x00", b"\x00\x00\x00\x00"]))
def test_fuzzed_bytes_raise_only_cdr_error(name, body, endian):
    try:
        codec.decode_cdr(endian + body, name)
    except CdrError:
        pass


@pytest.mark.parametrize("name", FUZZED)
def test_random_bytes_allocate_no_more_than_their_size_allows(name):
    cls = codec.get_type(name)
    cdr.decode(cdr.encode(cls()), cls)  # build the decoder outside the measurement
    rng = random.Random(name)
    for _ in range(200):
        data = cdr.HEADER + rng.randbytes(rng.randrange(300))
        tracemalloc.start()
        try:
            cdr.decode(data, cls)
        except CdrError:
            pass
        finally:
            peak = tracemalloc.get_traced_memory()[1]
            tracemalloc.stop()
        assert peak < 64 * len(data) + 20_000, data.hex()


@pytest.mark.parametrize("name", FUZZED)
@settings(max_examples=100, deadline=None)
@given(data=st.data())
def test_mutated_messages_raise_only_cdr_error(name, data):
    encoded = bytearray(cdr.encode(message(codec.get_type(name), DrawPick(data))))
    for _ in range(data.draw(st.integers(1, 4))):
        encoded[data.draw(st.integers(4, max(4, len(encoded) - 1)))] = data.draw(st.integers(0, 255))
    try:
        codec.decode_cdr(bytes(encoded), name)
    except CdrError:
        pass


# --------------------------------------------------------------------------- every shape, live


@pytest.fixture(scope="module")
def test_msgs_types(tmp_path_factory):
    """ROS's own test_msgs (every field shape: wstrings, bounded sequences, nested arrays), generated by us.

    Only where the ros-test-msgs wheel is installed: its .msg files are read from
    the wheel, not copied into this repository.
    """
    pytest.importorskip("rclpy.serialization", reason="live comparison needs rclpy (bench-ros extra)")
    pytest.importorskip("test_msgs.msg", reason="needs the ros-test-msgs wheel")
    import sysconfig

    share = Path(sysconfig.get_paths()["data"]) / "share" / "test_msgs" / "msg"
    root = tmp_path_factory.mktemp("live") / "rclpy_test_msgs_root"
    (root / "test_msgs" / "msg").mkdir(parents=True)
    for source in share.glob("*.msg"):
        (root / "test_msgs" / "msg" / source.name).write_text(source.read_text())
    idl_gen.generate([root])
    codec.register_root(root)
    return sorted(f"test_msgs/msg/{source.stem}" for source in share.glob("*.msg"))


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_test_msgs_match_live_rclpy(test_msgs_types, data):
    from goldens.ros import to_rclpy
    from rclpy.serialization import serialize_message

    name = data.draw(st.sampled_from(test_msgs_types))
    msg = message(codec.get_type(name), DrawPick(data))
    theirs = serialize_message(to_rclpy(msg))
    assert same_wire(msg, theirs) is None, name
    assert cdr.decode(theirs, type(msg)) == msg
