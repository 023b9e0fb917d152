"""Tests for actors.codec: the type registry and the msgpack, JSON, YAML and schema codecs."""

from __future__ import annotations

from array import array

import msgspec
import pytest
from goldens.values import DrawPick, message, shipped_messages
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from actors import codec
from actors.errors import MessageValidationError, UnknownInterfaceError
from actors.messages import cdr
from interfaces.builtin_interfaces.msg import Time
from interfaces.example_interfaces.action import Fibonacci
from interfaces.example_interfaces.srv import AddTwoInts
from interfaces.geometry_msgs.msg import Point, Pose, PoseStamped, Quaternion, Twist, Vector3
from interfaces.rcl_interfaces.msg import Log, ParameterDescriptor, ParameterValue
from interfaces.sensor_msgs.msg import Imu
from interfaces.std_msgs.msg import Bool, Header, String, UInt8
from interfaces.tutorial_interfaces.msg import Sphere

# --------------------------------------------------------------------------- the generated types


def test_messages_default_to_ros_zero_values_and_are_mutable():
    sphere = Sphere()
    sphere.center.x = 1.5
    assert sphere.center.x == 1.5 and Sphere().center.x == 0.0
    assert Quaternion().w == 1.0
    assert Imu().orientation_covariance == array("d", [0.0] * 9)
    assert ParameterValue().byte_array_value == b""
    assert ParameterDescriptor().floating_point_range == []
    assert (Log.DEBUG, Log.FATAL) == (10, 50)
    with pytest.raises(TypeError):
        String("positional")  # keyword-only, as the fields are documented by name


def test_services_expose_request_and_response():
    assert AddTwoInts.__ros_type__ == "example_interfaces/srv/AddTwoInts"
    assert AddTwoInts.Request.__ros_type__ == "example_interfaces/srv/AddTwoInts_Request"
    assert AddTwoInts.Response(sum=3).sum == 3
    assert "---" in AddTwoInts.__ros_definition__


@pytest.mark.slow  # a sweep of every shipped type and part; the CDR goldens cover each in the fast lane
@pytest.mark.parametrize("name", shipped_messages())
@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_every_shipped_type_round_trips_through_every_codec(name, data):
    cls = codec.get_type(name)
    msg = message(cls, DrawPick(data))
    assert codec.decode(codec.encode(msg), cls) == msg
    assert codec.decode_json(codec.encode_json(msg), cls) == msg
    assert codec.convert(codec.to_builtins(msg), cls) == msg
    encoded = codec.encode_cdr(msg)
    assert encoded[:4] == cdr.HEADER
    assert codec.decode_cdr(encoded, name) == msg


def test_round_trip_keeps_defaults_and_nesting():
    twist = Twist(linear=Vector3(x=0.2), angular=Vector3(z=0.5))
    assert codec.decode(codec.encode(twist), Twist) == twist
    assert codec.decode_json(codec.encode_json(twist), "geometry_msgs/msg/Twist") == twist
    assert codec.decode_json(b"{}", Twist) == Twist()


# --------------------------------------------------------------------------- validation


@pytest.mark.parametrize(
    ("cls", "value", "problem"),
    [
        (UInt8, {"data": 300}, "field 'data' of std_msgs/msg/UInt8: expected an integer <= 255, got the integer 300"),
        (UInt8, {"data": -1}, "field 'data' of std_msgs/msg/UInt8: expected an integer >= 0, got the integer -1"),
        (
            Time,
            {"nanosec": 2**32},
            "field 'nanosec' of builtin_interfaces/msg/Time: expected an integer <= 4294967295, "
            "got the integer 4294967296",
        ),
        (
            Imu,
            {"orientation_covariance": [0.0] * 8},
            "field 'orientation_covariance' of sensor_msgs/msg/Imu: expected at least 9 items, got 8",
        ),
        (
            ParameterDescriptor,
            {"integer_range": [{}, {}]},
            "field 'integer_range' of rcl_interfaces/msg/ParameterDescriptor: expected at most 1 item, got 2",
        ),
        (
            PoseStamped,
            {"header": {"stamp": {"sec": "x"}}},
            "field 'header.stamp.sec' of geometry_msgs/msg/PoseStamped: expected an integer, got the string 'x'",
        ),
        (PoseStamped, {"heder": {}}, "geometry_msgs/msg/PoseStamped has no field 'heder' (did you mean 'header'?)"),
    ],
)
def test_decode_and_convert_errors_name_the_type_field_and_value_in_our_words(cls, value, problem):
    for decode in (
        lambda v: codec.decode(msgspec.msgpack.encode(v), cls),
        lambda v: codec.decode_json(msgspec.json.encode(v), cls),
        lambda v: codec.convert(v, cls),
    ):
        with pytest.raises(MessageValidationError) as caught:
            decode(value)
        assert str(caught.value) == problem


def test_malformed_bytes_say_so():
    with pytest.raises(MessageValidationError, match=r"^std_msgs/msg/Bool: malformed data: "):
        codec.decode(b"\xc1", "std_msgs/msg/Bool")


def test_malformed_bytes_are_validation_errors():
    with pytest.raises(MessageValidationError, match=r"^std_msgs/msg/String: "):
        codec.decode(b"\xc1", String)


# --------------------------------------------------------------------------- registry


@pytest.mark.parametrize(
    ("name", "expected"),
    [
        ("std_msgs/msg/String", String),
        ("std_msgs/String", String),
        ("example_interfaces/srv/AddTwoInts", AddTwoInts),
        ("example_interfaces/AddTwoInts", AddTwoInts),
        ("example_interfaces/srv/AddTwoInts_Request", AddTwoInts.Request),
        ("example_interfaces/srv/AddTwoInts_Response", AddTwoInts.Response),
        ("example_interfaces/action/Fibonacci", Fibonacci),
        ("example_interfaces/Fibonacci", Fibonacci),
        ("example_interfaces/action/Fibonacci_Goal", Fibonacci.Goal),
        ("example_interfaces/action/Fibonacci_SendGoal", Fibonacci.Impl.SendGoalService),
        ("example_interfaces/action/Fibonacci_GetResult_Response", Fibonacci.Impl.GetResultService.Response),
        ("example_interfaces/action/Fibonacci_FeedbackMessage", Fibonacci.Impl.FeedbackMessage),
    ],
)
def test_get_type_accepts_every_name_form(name, expected):
    assert codec.get_type(name) is expected


@pytest.mark.parametrize(
    "name",
    [
        "std_msgs/msg/Nope",
        "nope/Nope",
        "std_msgs/srv/String",
        "String",
        "a/b/c/d",
        "std_msgs/x/String",
        "../x/Y",
        "example_interfaces/action/Nope",
        "example_interfaces/action/Fibonacci_Nope",
    ],
)
def test_get_type_rejects_unknown_names(name):
    with pytest.raises(UnknownInterfaceError, match=repr(name)):
        codec.get_type(name)


def test_ros_name():
    assert codec.ros_name(Twist) == codec.ros_name(Twist()) == "geometry_msgs/msg/Twist"
    assert codec.ros_name(AddTwoInts) == "example_interfaces/srv/AddTwoInts"
    with pytest.raises(TypeError):
        codec.ros_name(int)


def test_list_types_lists_messages_services_and_actions():
    names = codec.list_types()
    assert names == sorted(names)
    assert {"std_msgs/msg/String", "geometry_msgs/msg/Twist", "rcl_interfaces/msg/Log"} <= set(names)
    assert {"example_interfaces/srv/AddTwoInts", "rcl_interfaces/srv/ListParameters"} <= set(names)
    assert {
        "example_interfaces/action/Fibonacci",
        "action_msgs/srv/CancelGoal",
        "unique_identifier_msgs/msg/UUID",
    } <= set(names)
    assert not any(name.endswith(("_Request", "_Response", "_Goal", "_FeedbackMessage")) for name in names)


def test_register_module_adds_its_types(monkeypatch, tmp_path):
    monkeypatch.setattr(codec, "_registered", {})
    monkeypatch.setattr(codec, "_types", {})
    (tmp_path / "extra_types.py").write_text(
        "import msgspec\n\n"
        "class Ping(msgspec.Struct, kw_only=True):\n"
        "    __ros_type__ = 'extra/msg/Ping'\n"
        "    n: int = 0\n"
    )
    monkeypatch.syspath_prepend(str(tmp_path))
    assert codec.register_module("extra_types") == ["extra/msg/Ping"]
    assert codec.get_type("extra/Ping").__name__ == "Ping"
    assert "extra/msg/Ping" in codec.list_types()


# --------------------------------------------------------------------------- YAML and plain data


@pytest.mark.parametrize(
    ("text", "cls", "expected"),
    [
        ("data: true", Bool, Bool(data=True)),
        ("{a: 2, b: 3}", AddTwoInts.Request, AddTwoInts.Request(a=2, b=3)),
        (
            "{linear: {x: 0.2}, angular: {z: 0.5}}",
            "geometry_msgs/msg/Twist",
            Twist(linear=Vector3(x=0.2), angular=Vector3(z=0.5)),
        ),
        ('{"linear": {"x": 1}}', Twist, Twist(linear=Vector3(x=1.0))),
        ("linear: {x: 1e-3}", Twist, Twist(linear=Vector3(x=0.001))),
        ("", Twist, Twist()),
        ("   ", Quaternion, Quaternion()),
        ("byte_array_value: [1, 2]", ParameterValue, ParameterValue(byte_array_value=b"\x01\x02")),
    ],
)
def test_from_yaml(text, cls, expected):
    msg = codec.from_yaml(text, cls)
    assert msg == expected
    assert all(isinstance(v, float) for v in msgspec.structs.astuple(getattr(msg, "linear", Vector3())))


@pytest.mark.parametrize(
    ("text", "problem"),
    [
        ("{linear: {q: 1}}", "geometry_msgs/msg/Twist has no field 'linear.q'"),
        ("data: 1", "geometry_msgs/msg/Twist has no field 'data'"),
        ("angualr: {z: 1}", "geometry_msgs/msg/Twist has no field 'angualr' (did you mean 'angular'?)"),
        ("[1, 2]", "geometry_msgs/msg/Twist: expected a mapping such as 'field: value', got '[1, 2]'"),
        ("linear: {x: [", "geometry_msgs/msg/Twist: invalid YAML"),
        ("linear: {x: abc}", "field 'linear.x' of geometry_msgs/msg/Twist: expected a number, got the string 'abc'"),
    ],
)
def test_from_yaml_errors(text, problem):
    with pytest.raises(MessageValidationError) as caught:
        codec.from_yaml(text, Twist)
    assert str(caught.value).startswith(problem)


def test_the_issues_example_reads_as_promised():
    with pytest.raises(MessageValidationError) as caught:
        codec.from_yaml("data: maybe", "std_msgs/msg/Bool")
    assert str(caught.value) == "field 'data' of std_msgs/msg/Bool: expected a bool, got the string 'maybe'"


def test_convert_reports_bad_bytes_by_path():
    with pytest.raises(
        MessageValidationError,
        match=r"^field 'byte_array_value' of rcl_interfaces/msg/ParameterValue: "
        r"expected bytes \(a list of integers from 0 to 255\), got a list$",
    ):
        codec.convert({"byte_array_value": [1, 256]}, ParameterValue)


def test_to_yaml_prints_like_ros2_topic_echo():
    assert codec.to_yaml(Twist(linear=Vector3(x=0.2, y=1))) == (
        "linear:\n  x: 0.2\n  y: 1.0\n  z: 0.0\nangular:\n  x: 0.0\n  y: 0.0\n  z: 0.0\n"
    )
    header = Header(stamp=Time(sec=3), frame_id="map")
    assert codec.to_yaml(header) == "stamp:\n  sec: 3\n  nanosec: 0\nframe_id: map\n"
    assert codec.to_yaml(ParameterValue(byte_array_value=b"\x01\xff", double_array_value=[1.5])).endswith(
        "byte_array_value:\n- 1\n- 255\nbool_array_value: []\ninteger_array_value: []\n"
        "double_array_value:\n- 1.5\nstring_array_value: []\n"
    )
    assert codec.to_yaml(String(data="hi")) == "data: hi\n"


def test_to_builtins_keeps_field_order_and_types():
    builtins = codec.to_builtins(Imu())
    assert list(builtins)[:3] == ["header", "orientation", "orientation_covariance"]
    assert builtins["orientation"] == {"x": 0.0, "y": 0.0, "z": 0.0, "w": 1.0}
    assert codec.to_builtins(ParameterValue(byte_array_value=b"\x02"))["byte_array_value"] == [2]


# --------------------------------------------------------------------------- schemas


def test_json_schema_titles_types_with_ros_names():
    schema = codec.json_schema(Twist)
    assert schema["type"] == "object" and schema["title"] == "geometry_msgs/msg/Twist"
    assert schema["properties"]["linear"] == {"$ref": "#/$defs/Vector3"}
    assert schema["$defs"]["Vector3"]["title"] == "geometry_msgs/msg/Vector3"
    uint8 = codec.json_schema("std_msgs/msg/UInt8")
    assert uint8["properties"]["data"] == {"type": "integer", "minimum": 0, "maximum": 255, "default": 0}
    assert "$defs" not in uint8
    imu = codec.json_schema(Imu)["properties"]["orientation_covariance"]
    assert (imu["minItems"], imu["maxItems"]) == (9, 9)


def test_definition_text_is_what_rosbag2_writes():
    # rosbag2's LocalMessageDefinitionSource: names as written, sorted per definition, depth first, once.
    rule = "\n" + "=" * 80 + "\nMSG: "
    expected = (
        PoseStamped.__ros_definition__
        + rule
        + "geometry_msgs/Pose\n"
        + Pose.__ros_definition__
        + rule
        + "geometry_msgs/Point\n"
        + Point.__ros_definition__
        + rule
        + "geometry_msgs/Quaternion\n"
        + Quaternion.__ros_definition__
        + rule
        + "std_msgs/Header\n"
        + Header.__ros_definition__
        + rule
        + "builtin_interfaces/Time\n"
        + Time.__ros_definition__
    )
    assert codec.definition_text(PoseStamped) == expected
    odometry = codec.definition_text("nav_msgs/msg/Odometry")
    assert odometry.count("MSG: geometry_msgs/Vector3\n") == 1
    assert codec.definition_text(String) == String.__ros_definition__
    assert codec.definition_text(String).endswith("\nstring data\n")  # the file as ROS ships it, comments and all


def test_module_all_is_honest():
    public = {
        name
        for name, value in vars(codec).items()
        if callable(value) and not name.startswith("_") and value.__module__ == codec.__name__
    }
    assert sorted(codec.__all__) == sorted(public)
