"""How the command line prints: rclpy's repr, YAML documents, and the DOT graph."""

from __future__ import annotations

import re

import pytest

from actors.cli._format import csv_text, field, ros_repr, yaml_text
from actors.cli.graph import to_dot
from actors.errors import ControlError
from actors.ops.control import GraphSnapshot
from actors.ros.qos import QoSSnapshot
from actors.system.introspection import EndpointInfo, TopicInfo
from interfaces.geometry_msgs.msg import Twist
from interfaces.std_msgs.msg import Float32MultiArray, String


def test_ros_repr_is_rclpys_nested_repr():
    msg = Twist()
    msg.linear.x = 0.2
    assert ros_repr(msg) == (
        "geometry_msgs.msg.Twist(linear=geometry_msgs.msg.Vector3(x=0.2, y=0.0, z=0.0), "
        "angular=geometry_msgs.msg.Vector3(x=0.0, y=0.0, z=0.0))"
    )
    assert ros_repr(String(data="it's")) == 'std_msgs.msg.String(data="it\'s")'


def test_yaml_text_of_a_message_a_field_and_a_scalar():
    msg = Twist()
    msg.angular.z = 0.5
    assert yaml_text(msg).startswith("linear:\n  x: 0.0\n")
    assert yaml_text(field(msg, "angular")) == "x: 0.0\ny: 0.0\nz: 0.5\n"
    assert yaml_text(field(msg, "angular.z")) == "0.5\n"  # no end-of-document mark
    with pytest.raises(ControlError, match=re.escape("geometry_msgs/msg/Twist has no field 'angular.w'")):
        field(msg, "angular.w")


def _end(node: str) -> EndpointInfo:
    return EndpointInfo(node=node, type="std_msgs/msg/String", qos=QoSSnapshot())


def test_the_dot_graph_leaves_out_rosout_and_hidden_endpoints_unless_asked():
    end = _end
    graph = GraphSnapshot(
        name="demo",
        clock="wall",
        nodes=(),
        services=(),
        topics=(
            TopicInfo(
                name="/chatter",
                type="std_msgs/msg/String",
                publishers=(end("/talker"),),
                subscriptions=(end("/listener"), end("/_actors_cli_1")),
            ),
            TopicInfo(
                name="/rosout",
                type="rcl_interfaces/msg/Log",
                publishers=(end("/_demo"),),
                subscriptions=(),
            ),
        ),
    )
    assert to_dot(graph) == (
        'digraph "demo" {\n'
        "  rankdir=LR;\n"
        '  "n:/listener" [label="/listener", shape=ellipse];\n'
        '  "n:/talker" [label="/talker", shape=ellipse];\n'
        '  "t:/chatter" [label="/chatter", shape=box];\n'
        '  "n:/talker" -> "t:/chatter";\n'
        '  "t:/chatter" -> "n:/listener";\n'
        "}\n"
    )
    everything = to_dot(graph, everything=True)
    assert '"t:/chatter" -> "n:/_actors_cli_1";' in everything and '"n:/_demo" -> "t:/rosout";' in everything


def test_the_pillow_drawing_has_arrowheads(tmp_path):
    pytest.importorskip("PIL")
    from PIL import Image

    from actors.cli.graph import _draw_png

    chatter = TopicInfo(
        name="/chatter", type="std_msgs/msg/String", publishers=(_end("/talker"),), subscriptions=(_end("/listener"),)
    )
    graph = GraphSnapshot(name="demo", clock="wall", nodes=(), services=(), topics=(chatter,))
    assert _draw_png(graph, False, tmp_path / "g.png")
    image = Image.open(tmp_path / "g.png").convert("L")
    # The edge /talker -> /chatter ends on the box's left side, halfway down its first row.
    line = [x for x in range(image.width) if image.getpixel((x, 55)) < 250]
    box_left = next(x for x in range(330, image.width) if image.getpixel((x, 45)) == 0)
    assert box_left in line
    for back, across in ((2, 0), (9, 3), (9, -3)):  # inside the head: black, wider than the line
        assert image.getpixel((box_left - back, 55 + across)) == 0, (back, across)
    assert image.getpixel((box_left - 9, 55 + 8)) == 255  # and narrower than 12 px at 9 px back


def test_no_arr_and_no_str_print_ros2s_summaries_at_every_depth():
    from interfaces.nav_msgs.msg import Odometry
    from interfaces.rcl_interfaces.msg import ParameterDescriptor, ParameterValue

    odom = Odometry()
    odom.header.frame_id = "odom"
    text = yaml_text(odom, no_arr=True)
    assert text.count("  covariance: '<array type: double[36]>'\n") == 2  # fixed arrays, nested
    assert "  frame_id: odom\n" in text
    assert yaml_text(odom, no_str=True).count("'<string length: <4>>'") == 1  # frame_id
    assert "child_frame_id: '<string length: <0>>'\n" in yaml_text(odom, no_str=True)
    descriptor = ParameterDescriptor(name="speed")
    assert (
        "floating_point_range: '<sequence type: rcl_interfaces/msg/FloatingPointRange[1], length: 0>'\n"
        in yaml_text(descriptor, no_arr=True)
    )
    value = yaml_text(ParameterValue(byte_array_value=b"ab", string_array_value=["x"]), no_arr=True)
    assert "byte_array_value: '<sequence type: octet, length: 2>'\n" in value
    assert "string_array_value: '<sequence type: string, length: 1>'\n" in value
    assert "string_array_value:\n- '<string length: <1>>'\n" in yaml_text(
        ParameterValue(string_array_value=["x"]), no_str=True
    )


def test_long_strings_stay_on_one_line_as_ros2_prints_them():
    text = "word " * 40
    assert yaml_text(String(data=text)) == f"data: '{text}'\n"


def test_array_fields_print_as_ros2_prints_them():
    msg = Float32MultiArray(data=[1.0, 2.5])  # held as array('f'), as rclpy holds it
    assert ros_repr(msg).endswith("data_offset=0), data=[1.0, 2.5])")  # rclpy's repr strips array(...)
    assert ros_repr(Float32MultiArray()).endswith("data=[])")
    ranges = field(msg, "data")
    assert yaml_text(ranges) == "- 1.0\n- 2.5\n"  # topic echo --field data
    assert csv_text(ranges) == "1.0,2.5"
