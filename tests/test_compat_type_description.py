"""A script node's ``~/get_type_description`` service and the parameter that switches it on."""

from __future__ import annotations

from typing import Any

import pytest

import actors.compat.rclpy as rclpy
from actors.compat.rclpy.parameter import Parameter
from actors.compat.rclpy.type_description_service import START_TYPE_DESCRIPTION_SERVICE_PARAM
from actors.messages.typehash import type_hash
from interfaces.example_interfaces.srv import AddTwoInts
from interfaces.test_msgs.msg import Defaults, Nested
from interfaces.type_description_interfaces.srv import GetTypeDescription


@pytest.fixture
def session(rclpy_session):
    return rclpy_session


def _ask(node: Any, name: str, hash_text: str, *, sources: bool = True) -> Any:
    client = node.create_client(GetTypeDescription, f"{node.get_fully_qualified_name()}/get_type_description")
    request = GetTypeDescription.Request(type_name=name, type_hash=hash_text, include_type_sources=sources)
    future = client.call_async(request)
    rclpy.spin_until_future_complete(node, future, timeout_sec=5.0)
    return future.result()


def test_every_node_declares_the_switch_read_only_and_true(session):
    node = rclpy.create_node("described")
    assert node.get_parameter(START_TYPE_DESCRIPTION_SERVICE_PARAM).value is True
    descriptor = node.describe_parameter(START_TYPE_DESCRIPTION_SERVICE_PARAM)
    assert descriptor.read_only and descriptor.type == Parameter.Type.BOOL
    names = node.list_parameters([], 0).names
    assert START_TYPE_DESCRIPTION_SERVICE_PARAM in names and "use_sim_time" in names
    refused = node.set_parameters([Parameter(START_TYPE_DESCRIPTION_SERVICE_PARAM, value=False)])
    assert not refused[0].successful
    assert (
        "/described/get_type_description",
        ["type_description_interfaces/srv/GetTypeDescription"],
    ) in node.get_service_names_and_types_by_node("described", "/")


def test_a_topic_type_is_described_with_its_defaults_and_sources(session):
    node = rclpy.create_node("describer", namespace="/shop")
    node.create_publisher(Defaults, "defaults", 1)
    hash_text = str(node.get_publishers_info_by_topic("/shop/defaults")[0].topic_type_hash)
    answer = _ask(node, "test_msgs/msg/Defaults", hash_text)
    assert answer.successful and answer.failure_reason == ""
    described = answer.type_description.type_description
    assert described.type_name == "test_msgs/msg/Defaults"
    fields = {f.name: (f.type.type_id, f.default_value) for f in described.fields}
    assert fields["bool_value"] == (15, "True")  # bool's id, and the default as rosidl writes it
    assert fields["float64_value"] == (11, "1.125")
    assert answer.type_description.referenced_type_descriptions == []
    assert [(s.type_name, s.encoding) for s in answer.type_sources] == [("test_msgs/msg/Defaults", "msg")]
    text = answer.type_sources[0].raw_file_contents
    assert text.startswith("bool bool_value true\n")
    assert text.endswith("uint64 uint64_value 50000000")  # the file's last newline left out, as rcl gives it


def test_nested_types_come_along_and_sources_only_when_asked(session):
    node = rclpy.create_node("nester")
    node.create_subscription(Nested, "nested", lambda msg: None, 1)
    answer = _ask(node, "test_msgs/msg/Nested", type_hash(Nested), sources=False)
    assert answer.successful
    referenced = [d.type_name for d in answer.type_description.referenced_type_descriptions]
    assert referenced == ["test_msgs/msg/BasicTypes"]
    assert answer.type_sources == []
    with_sources = _ask(node, "test_msgs/msg/Nested", type_hash(Nested))
    assert [s.type_name for s in with_sources.type_sources] == ["test_msgs/msg/Nested", "test_msgs/msg/BasicTypes"]


def test_a_service_type_in_use_is_described_too(session):
    node = rclpy.create_node("adder")
    node.create_service(AddTwoInts, "add", lambda request, response: response)
    answer = _ask(node, "example_interfaces/srv/AddTwoInts", type_hash(AddTwoInts))
    assert answer.successful
    assert [f.name for f in answer.type_description.type_description.fields] == [
        "request_message",
        "response_message",
        "event_message",
    ]
    assert answer.type_sources[0].encoding == "srv"


def test_a_type_the_node_does_not_use_is_refused(session):
    node = rclpy.create_node("stranger")
    answer = _ask(node, "test_msgs/msg/Defaults", type_hash(Defaults))
    assert not answer.successful
    assert answer.failure_reason == "Type not currently in use by this node"


def test_a_hash_that_does_not_parse_is_refused_as_rcl_refuses_it(session, caplog):
    node = rclpy.create_node("parser")
    node.create_publisher(Defaults, "defaults", 1)
    answer = _ask(node, "test_msgs/msg/Defaults", "garbage")
    assert not answer.successful
    assert answer.failure_reason == "Failed to parse type hash"
    assert [(r.name, r.getMessage()) for r in caplog.records if r.levelname == "ERROR"] == [
        ("actors.node.rcl", "Failed to parse type hash 'garbage'")
    ]


def test_the_switch_set_false_leaves_the_service_off(session):
    node = rclpy.create_node(
        "quiet", parameter_overrides=[Parameter(START_TYPE_DESCRIPTION_SERVICE_PARAM, value=False)]
    )
    assert node.get_parameter(START_TYPE_DESCRIPTION_SERVICE_PARAM).value is False
    assert node.services == []
    assert all(name != "/quiet/get_type_description" for name, _ in node.get_service_names_and_types())
