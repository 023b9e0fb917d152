"""The publish-time snapshot: every field checked, mutable parts copied, immutable leaves shared."""

from __future__ import annotations

import array

import msgspec
import numpy as np
import pytest
from conftest import generated_package
from goldens.values import DrawPick, message, shipped_messages
from hypothesis import given, settings
from hypothesis import strategies as st

from actors import codec
from actors.errors import MessageValidationError
from actors.messages._copy import ALONE, FLOAT32_MAX, adopter, checker, snapshot, snapshotter
from interfaces.geometry_msgs.msg import PoseWithCovariance, Twist, Vector3
from interfaces.nav_msgs.msg import Odometry
from interfaces.rcl_interfaces.msg import ParameterValue
from interfaces.sensor_msgs.msg import JointState, LaserScan
from interfaces.std_msgs.msg import Bool, Int8, Int64, String

SHIPPED = shipped_messages()


def _shared_mutables(a: object, b: object) -> list[str]:
    """Paths where ``a`` and ``b`` hold the very same list or struct with fields (a snapshot must hold none).

    A struct without fields cannot change: sharing it is safe.
    """
    found = []

    def walk(x: object, y: object, path: str) -> None:
        if (type(x) is list or (isinstance(x, msgspec.Struct) and x.__struct_fields__)) and x is y:
            found.append(path or "the message")
        if isinstance(x, msgspec.Struct):
            for name in x.__struct_fields__:
                walk(getattr(x, name), getattr(y, name), f"{path}.{name}")
        elif isinstance(x, list):
            for i, (p, q) in enumerate(zip(x, y)):
                walk(p, q, f"{path}[{i}]")

    walk(a, b, "")
    return found


@settings(max_examples=150, deadline=None)
@given(name=st.sampled_from(SHIPPED), data=st.data())
def test_a_snapshot_equals_the_message_and_shares_nothing_mutable(name, data):
    msg = message(codec.get_type(name), DrawPick(data))
    copy = snapshot(msg)
    assert copy == msg
    assert type(copy) is type(msg)
    assert _shared_mutables(copy, msg) == []


@settings(max_examples=150, deadline=None)
@given(name=st.sampled_from(SHIPPED), data=st.data())
def test_the_check_alone_passes_what_the_snapshot_passes_and_leaves_the_message_as_it_was(name, data):
    cls = codec.get_type(name)
    msg = message(cls, DrawPick(data))
    before = snapshot(msg)
    assert checker(cls)(msg) is None
    assert msg == before and _shared_mutables(msg, before) == []


@settings(max_examples=150, deadline=None)
@given(name=st.sampled_from(SHIPPED), data=st.data())
def test_the_snapshot_in_place_makes_the_message_itself_what_the_copy_would_be(name, data):
    msg = message(codec.get_type(name), DrawPick(data))
    expected = snapshot(msg)
    parts = msg.__copy__()  # shares the message's nested structs and lists, as their other holders would
    assert adopter(type(msg))(msg) is msg
    assert msg == expected
    assert _shared_mutables(msg, parts) == []  # what someone else may hold was copied


def test_a_message_without_fields_is_its_own_snapshot():
    from interfaces.std_srvs.srv import Trigger

    request = Trigger.Request()
    assert snapshot(request) is request and adopter(Trigger.Request)(request) is request
    with pytest.raises(AttributeError):  # why sharing it is safe: nothing can be set on it
        request.data = 1


def test_alone_is_what_getrefcount_says_of_an_object_only_a_local_variable_holds():
    import sys

    mine = String()
    assert sys.getrefcount(mine) == ALONE
    others = [mine]
    assert sys.getrefcount(mine) == ALONE + 1 and others


def test_immutable_leaves_are_shared_not_copied():
    text, blob = "x" * 1000, bytes(1000)
    msg = ParameterValue(string_value=text, byte_array_value=blob)
    copy = snapshot(msg)
    assert copy.string_value is text and copy.byte_array_value is blob


def test_the_function_is_generated_once_per_type():
    assert snapshotter(Twist) is snapshotter(Twist)
    assert snapshotter(Twist) is not snapshotter(Vector3)


def test_a_class_that_is_not_an_interface_type_is_passed_as_it_is():
    class Plain:
        pass

    value = Plain()
    assert snapshot(value) is value


def test_what_rclpy_accepts_beyond_the_exact_type_is_delivered_in_the_canonical_type():
    copy = snapshot(Twist(linear=Vector3(x=1, y=np.float32(0.5), z=np.float64(2.0))))
    assert [(v, type(v)) for v in (copy.linear.x, copy.linear.y, copy.linear.z)] == [
        (1.0, float),
        (0.5, float),
        (2.0, float),
    ]
    assert (copy := snapshot(Int64(data=True))).data == 1 and type(copy.data) is int
    assert (same := adopter(Int64)(Int64(data=True))).data == 1 and type(same.data) is int
    scan = LaserScan()  # assigned after construction: the snapshot makes the arrays
    scan.ranges, scan.intensities = (1, 2.5), np.array([0.25, 3.0], dtype=np.float32)
    scan = snapshot(scan)
    assert (scan.ranges, scan.intensities) == (array.array("f", [1.0, 2.5]), array.array("f", [0.25, 3.0]))
    assert [(type(a), a.typecode) for a in (scan.ranges, scan.intensities)] == [(array.array, "f")] * 2
    value = ParameterValue()
    value.byte_array_value, value.integer_array_value = bytearray(b"ab"), array.array("i", [7])
    value = snapshot(value)
    assert value.byte_array_value == b"ab" and type(value.byte_array_value) is bytes
    assert value.integer_array_value == array.array("q", [7]) and value.integer_array_value.typecode == "q"
    assert snapshot(LaserScan(ranges=[float("inf"), float("nan"), -FLOAT32_MAX])).ranges[2] == -FLOAT32_MAX


def _outcome(msg: object) -> tuple[object, ...]:
    """What the snapshot makes of ``msg``: its ranges, each value's type, or the error's text.

    The check alone must refuse it with the same text, or pass it.
    """
    try:
        checker(type(msg))(msg)
    except MessageValidationError as exc:
        checked = str(exc)
    else:
        checked = None
    try:
        ranges = snapshot(msg).ranges
    except MessageValidationError as exc:
        assert checked == str(exc)
        return ("refused", str(exc))
    assert checked is None
    return ("delivered", repr(ranges), [type(v) for v in ranges])  # repr: nan equals itself


@pytest.mark.parametrize(
    "values",
    [
        np.array([0.5, float("inf"), -float("inf"), float("nan"), -0.0, FLOAT32_MAX]),  # float64
        np.array([1.0, 1e39, 2.0]),  # finite beyond float32: refused, naming ranges[1]
        np.array([0.25, float("inf")], dtype=np.float32),
        np.array([], dtype=np.float64),
        np.array([[1.0, 2.0]]),  # 2-D: each row is no float
        np.array([1, 2, 3]),  # ints become floats
        np.array([True, False]),  # a bool is no float
        np.array([0.5, 1.5], dtype=np.float16),
    ],
    ids=["float64", "beyond-float32", "float32", "empty", "2-D", "int64", "bool", "float16"],
)
def test_a_numpy_array_in_a_float_array_field_fares_as_the_list_of_its_values(values):
    assert _outcome(LaserScan(ranges=values)) == _outcome(LaserScan(ranges=values.tolist()))


def test_a_numpy_array_is_delivered_as_an_array_that_later_writes_to_the_numpy_array_do_not_reach():
    ranges = np.array([1.0, 2.0, 3.0])
    scan = LaserScan()
    scan.ranges = ranges
    copy = snapshot(scan)
    built = LaserScan(ranges=ranges)  # the constructor makes its own array, as rclpy's does
    ranges[0] = 9.0
    for held in (copy.ranges, built.ranges):
        assert held == array.array("f", [1.0, 2.0, 3.0]) and type(held) is array.array and held.typecode == "f"
    with pytest.raises(MessageValidationError, match=r"expected 36 items \(float64\[36\]\), got 35"):
        snapshot(Odometry(pose=PoseWithCovariance(covariance=np.zeros(35))))


def test_trusted_float_arrays_are_copied_unlooked_at_and_the_rest_still_checked():
    trusted = frozenset({"ranges", "intensities"})
    scan = LaserScan(intensities=[0.5], range_max=2.0)
    scan.ranges = np.array([1.0, np.inf])  # assigned: a numpy vector until the snapshot
    copy = snapshotter(LaserScan, trusted)(scan)
    assert copy.ranges == array.array("f", [1.0, np.inf]) and copy.ranges.typecode == "f"
    assert copy.intensities == array.array("f", [0.5]) and copy.intensities is not scan.intensities
    assert copy.range_max == 2.0 and copy.header is not scan.header
    assert checker(LaserScan, trusted)(LaserScan(ranges=[1e39])) is None  # the caller vouched for them
    for wrong in (snapshotter(LaserScan, trusted), checker(LaserScan, trusted)):
        with pytest.raises(MessageValidationError, match="field 'range_max'"):
            wrong(LaserScan(range_max=1e39))
    odometry = frozenset({"pose.covariance", "twist.covariance"})
    assert snapshotter(Odometry, odometry) is snapshotter(Odometry, odometry)
    odom = Odometry()
    assert snapshotter(Odometry, odometry)(odom).pose.covariance is not odom.pose.covariance
    assert snapshotter(Odometry) is not snapshotter(Odometry, odometry)


@settings(max_examples=150, deadline=None)
@given(name=st.sampled_from(SHIPPED), data=st.data())
def test_a_wholly_trusted_message_is_copied_as_the_snapshot_copies_it_and_not_looked_at(name, data):
    msg = message(codec.get_type(name), DrawPick(data))
    everything = frozenset({""})
    assert checker(type(msg), everything)(msg) is None
    try:
        expected = snapshot(msg)
    except MessageValidationError:
        return  # drawn beyond what fits: a trusting publisher never holds such a message
    copy = snapshotter(type(msg), everything)(msg)
    assert copy == expected and not _shared_mutables(msg, copy)


def test_arrays_of_anything_but_floats_are_checked_even_when_trusted():
    everything = frozenset({""})
    for made in (snapshotter, checker):
        with pytest.raises(MessageValidationError, match=r"field 'name\[1\]'"):
            made(JointState, everything)(JointState(name=["a", 2], position=[1e39]))
    copy = snapshotter(JointState, everything)(JointState(name=["a"], position=np.array([1.0])))
    assert copy.name == ["a"] and copy.position == array.array("d", [1.0]) and copy.position.typecode == "d"


@pytest.mark.parametrize(
    ("cls", "path"),
    [
        (LaserScan, "nothing"),
        (LaserScan, "header.nothing"),
        (Odometry, "covariance"),  # the path from the top: pose.covariance
    ],
)
def test_only_fields_of_the_message_can_be_trusted(cls, path):
    for made in (snapshotter, checker):
        with pytest.raises(ValueError, match=f"trusted fields \\['{path}'\\]: no field of"):
            made(cls, frozenset({path}))


@pytest.mark.parametrize(
    ("msg", "error"),
    [
        (Bool(data=1), "field 'data' of std_msgs/msg/Bool: expected a bool, got the int 1"),
        (Int8(data=128), "field 'data' of std_msgs/msg/Int8: 128 is out of range for int8 (-128..127)"),
        (
            Twist(linear=Vector3(x=True)),
            "field 'linear.x' of geometry_msgs/msg/Twist: expected a float, got the bool True",
        ),
        (String(data=b"abc"), "field 'data' of std_msgs/msg/String: expected a str, got the bytes b'abc'"),
        (
            LaserScan(ranges=[1.0, True]),
            "field 'ranges[1]' of sensor_msgs/msg/LaserScan: expected a float, got the bool True",
        ),
        (
            JointState(name="abc"),
            "field 'name' of sensor_msgs/msg/JointState: expected a list (string[]), got the str 'abc'",
        ),
        (JointState(name=["a", 2]), "field 'name[1]' of sensor_msgs/msg/JointState: expected a str, got the int 2"),
        (
            ParameterValue(byte_array_value=[1, 300]),
            "field 'byte_array_value' of rcl_interfaces/msg/ParameterValue: expected bytes (byte[]): "
            "bytes must be in range(0, 256)",
        ),
        (
            ParameterValue(integer_array_value=[1, 2**64]),
            "field 'integer_array_value[1]' of rcl_interfaces/msg/ParameterValue: 18446744073709551616 is out of range "
            "for int64 (-9223372036854775808..9223372036854775807)",
        ),
    ],
)
def test_errors_name_the_type_the_field_and_the_value(msg, error):
    with pytest.raises(MessageValidationError) as raised:
        snapshot(msg)
    assert str(raised.value) == error
    with pytest.raises(MessageValidationError) as raised:
        checker(type(msg))(msg)
    assert str(raised.value) == error
    with pytest.raises(MessageValidationError) as raised:
        adopter(type(msg))(msg)
    assert str(raised.value) == error


SHAPES = """\
string<=4 name
int32[<=2] few
float32[3] xyz
Part[] parts
"""
PART = "uint8 id\nstring<=2 tag\n"


@pytest.fixture(scope="module")
def shapes(tmp_path_factory):
    generated_package(
        tmp_path_factory.mktemp("root") / "snapshot_shapes", "snapshot_shapes_pkg", {"Shapes": SHAPES, "Part": PART}
    )
    return codec.get_type("snapshot_shapes_pkg/msg/Shapes"), codec.get_type("snapshot_shapes_pkg/msg/Part")


def test_bounds_and_sizes_are_checked(shapes):
    shape, part = shapes
    where = "snapshot_shapes_pkg/msg/Shapes"
    cases = [
        (shape(name="abcde"), f"field 'name' of {where}: expected at most 4 characters (string<=4), got 5"),
        (shape(few=[1, 2, 3]), f"field 'few' of {where}: expected at most 2 items (int32[<=2]), got 3"),
        (shape(xyz=[1.0, 2.0]), f"field 'xyz' of {where}: expected 3 items (float32[3]), got 2"),
        (
            shape(parts=[part(), Vector3()]),
            f"field 'parts[1]' of {where}: expected a snapshot_shapes_pkg/msg/Part, got a geometry_msgs/msg/Vector3",
        ),
        (
            shape(parts=[part(), part(tag="abc")]),
            f"field 'parts[1].tag' of {where}: expected at most 2 characters (string<=2), got 3",
        ),
        (shape(parts=[part(id=-1)]), f"field 'parts[0].id' of {where}: -1 is out of range for uint8 (0..255)"),
    ]
    for msg, error in cases:
        for check in (snapshot, checker(shape), adopter(shape)):
            with pytest.raises(MessageValidationError) as raised:
                check(msg)
            assert str(raised.value) == error
    good = shape(name="abcd", few=[1, 2], xyz=[1.0, 2.0, 3.0], parts=[part(id=7, tag="ok")])
    copy = snapshot(good)
    assert copy == good and copy.parts[0] is not good.parts[0]
