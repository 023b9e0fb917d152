"""rclpy 8's ``with`` forms, and the small Node helpers rclpy programs call: name resolution, wait_for_node."""

from __future__ import annotations

import pytest

import actors.compat.rclpy as rclpy
from actors.compat.rclpy.exceptions import InvalidHandle
from interfaces.example_interfaces.srv import AddTwoInts
from interfaces.rcl_interfaces.msg import ParameterEvent
from interfaces.std_msgs.msg import String


@pytest.fixture
def session(rclpy_session):
    return rclpy_session


def test_each_entity_is_destroyed_when_its_block_ends(session):
    with rclpy.create_node("scoped") as node:
        own = node.services  # ~/get_type_description, as every rclpy node has it
        assert [s.service_name for s in own] == ["/scoped/get_type_description"]
        (events,) = node.publishers  # and the publisher of its parameter changes
        assert events.topic_name == "/parameter_events"
        with node.create_publisher(String, "said", 10) as pub:
            assert node.publishers == [events, pub]
        assert node.publishers == [events]
        with pytest.raises(InvalidHandle):
            pub.publish(String(data="too late"))
        with node.create_subscription(String, "said", lambda msg: None, 10) as sub:
            assert node.subscriptions == [sub]
        with node.create_timer(1.0, lambda: None) as timer:
            assert node.timers == [timer]
        with node.create_service(AddTwoInts, "add", lambda req, res: res) as service:
            assert node.services == [*own, service]
        with node.create_client(AddTwoInts, "add") as client:
            assert node.clients == [client]
        assert (node.subscriptions, node.timers, node.services, node.clients) == ([], [], own, [])
        assert node.destroy_publisher(events) and node.publishers == []
        with pytest.raises(InvalidHandle):
            events.publish(ParameterEvent())
        # The runtime's publisher, which every node shares, still announces parameter changes.
        heard: list[ParameterEvent] = []
        node.create_subscription(ParameterEvent, "/parameter_events", heard.append, 10)
        node.declare_parameter("announced", 1)
        rclpy.spin_once(node, timeout_sec=1.0)
        assert [p.name for event in heard for p in event.new_parameters] == ["announced"]
    rclpy.create_node("scoped")  # the name is free again: the node was destroyed with its block


def test_names_resolve_as_the_node_sees_them(session):
    node = rclpy.create_node("resolver", namespace="/ns", cli_args=["-r", "cmd:=cmd_vel"])
    assert node.resolve_topic_name("cmd") == "/ns/cmd_vel"
    assert node.resolve_topic_name("cmd", only_expand=True) == "/ns/cmd"
    assert node.resolve_service_name("~/reset") == "/ns/resolver/reset"


def test_waiting_for_a_node_counts_runtime_time(session):
    node = rclpy.create_node("waiter")
    rclpy.create_node("awaited", namespace="/ns")
    assert node.wait_for_node("/ns/awaited", 1.0)
    start = session.loop.time()
    assert not node.wait_for_node("absent", 2.5)
    assert session.loop.time() - start == pytest.approx(2.5)


def test_a_subscription_knows_its_callbacks_form_and_its_publishers(session):
    from actors.compat.rclpy.subscription import Subscription
    from actors.ros.qos import QoSProfile, ReliabilityPolicy

    node = rclpy.create_node("reader")
    plain = node.create_subscription(String, "news", lambda msg: None, 10)
    assert plain._callback_type is Subscription.CallbackType.MessageOnly
    detailed = node.create_subscription(String, "news", lambda msg, info: None, 10)
    assert detailed._callback_type is Subscription.CallbackType.WithMessageInfo
    with pytest.raises(RuntimeError, match="one argument"):
        node.create_subscription(String, "news", lambda a, b, c: None, 10)
    assert plain.get_publisher_count() == 0
    node.create_publisher(String, "news", 10)
    node.create_publisher(String, "news", QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT))
    assert plain.get_publisher_count() == 1  # the best-effort one does not match a reliable reader


def test_a_service_answering_with_the_wrong_type_raises_from_the_spin(session):
    node = rclpy.create_node("sloppy")
    node.create_service(AddTwoInts, "add", lambda request, response: "five")
    future = node.create_client(AddTwoInts, "add").call_async(AddTwoInts.Request(a=2, b=3))
    with pytest.raises(TypeError, match="returned str, not AddTwoInts_Response"):
        rclpy.spin_until_future_complete(node, future, timeout_sec=1)
    rclpy.spin_once(node, timeout_sec=0.1)  # the refusal reaches the caller
    assert isinstance(future.exception(), Exception)


def test_handles_work_until_their_entity_is_destroyed(session):
    node = rclpy.create_node("handled")
    timer = node.create_timer(1.0, lambda: None)
    publisher = node.create_publisher(String, "said", 1)
    with timer.handle, publisher.handle, node.handle:
        pass
    node.destroy_timer(timer)
    with pytest.raises(InvalidHandle, match="destruction was requested"), timer.handle:
        pass
    with publisher.handle:  # the others are untouched
        pass
    node.destroy_node()
    for entity in (publisher, node):
        with pytest.raises(InvalidHandle), entity.handle:
            pass
