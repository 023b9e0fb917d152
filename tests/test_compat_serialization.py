"""rclpy.serialization on the overlay: CDR bytes both ways, and a publisher taking bytes."""

from __future__ import annotations

import pytest

import actors.compat.rclpy as rclpy
from actors.compat.rclpy.executors import SingleThreadedExecutor
from actors.compat.rclpy.serialization import deserialize_message, serialize_message
from interfaces.geometry_msgs.msg import Twist
from interfaces.std_msgs.msg import String


@pytest.fixture
def session(rclpy_session):
    return rclpy_session


def test_a_message_comes_back_from_its_bytes():
    twist = Twist()
    twist.linear.x, twist.angular.z = 0.5, -1.25
    data = serialize_message(twist)
    assert data[:4] == b"\x00\x01\x00\x00"  # CDR, little-endian, as ROS 2 sends it
    assert deserialize_message(data, Twist) == twist
    with pytest.raises(TypeError):
        serialize_message("not a message")


def test_a_publisher_takes_serialized_bytes(session):
    node = rclpy.create_node("bytes_publisher")
    heard: list[str] = []
    node.create_subscription(String, "said", lambda msg: heard.append(msg.data), 10)
    pub = node.create_publisher(String, "said", 10)
    pub.publish(serialize_message(String(data="ñu")))
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    executor.spin_once(timeout_sec=1)
    assert heard == ["ñu"]
