"""rclpy 8's ``with`` forms: a node and its entities are destroyed when their block ends."""

from __future__ import annotations

import pytest

import actors.compat.rclpy as rclpy
from actors.compat.rclpy.exceptions import InvalidHandle
from interfaces.example_interfaces.srv import AddTwoInts
from interfaces.std_msgs.msg import String


@pytest.fixture
def session(rclpy_session):
    return rclpy_session


def test_each_entity_is_destroyed_when_its_block_ends(session):
    with rclpy.create_node("scoped") as node:
        with node.create_publisher(String, "said", 10) as pub:
            assert node.publishers == [pub]
        assert node.publishers == []
        with pytest.raises(InvalidHandle):
            pub.publish(String(data="too late"))
        with node.create_subscription(String, "said", lambda msg: None, 10) as sub:
            assert node.subscriptions == [sub]
        with node.create_timer(1.0, lambda: None) as timer:
            assert node.timers == [timer]
        with node.create_service(AddTwoInts, "add", lambda req, res: res) as service:
            assert node.services == [service]
        with node.create_client(AddTwoInts, "add") as client:
            assert node.clients == [client]
        assert (node.subscriptions, node.timers, node.services, node.clients) == ([], [], [], [])
    rclpy.create_node("scoped")  # the name is free again: the node was destroyed with its block
