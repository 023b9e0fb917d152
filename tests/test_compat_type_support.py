"""rclpy's type helpers on the overlay: TypeHash, type_support's checks, test_msgs' fixtures round-tripping."""

from __future__ import annotations

import pytest

import actors.compat.rclpy as rclpy
from actors.compat.rclpy import type_support
from actors.compat.rclpy.exceptions import NoTypeSupportImportedException
from actors.compat.rclpy.serialization import deserialize_message, serialize_message
from actors.compat.rclpy.type_hash import TypeHash
from actors.errors import MessageValidationError
from interfaces.std_msgs.msg import String
from interfaces.test_msgs import msg as test_msgs
from interfaces.test_msgs.message_fixtures import get_test_msg
from interfaces.test_msgs.srv import Empty as EmptySrv
from interfaces.type_description_interfaces.srv import GetTypeDescription


@pytest.fixture
def session(rclpy_session):
    return rclpy_session


def test_a_type_hash_prints_as_ros_does_and_compares_by_value():
    digest = bytes(range(32))
    text = "RIHS01_" + digest.hex()
    assert str(TypeHash(version=1, value=digest)) == text
    assert TypeHash.from_string(text) == TypeHash(1, digest)
    assert str(TypeHash()) == "INVALID" and str(TypeHash(version=2, value=digest)) == "INVALID"
    assert TypeHash.from_string("") == TypeHash() == TypeHash.from_string("RIHS01_not-hex")
    assert TypeHash(version=3) != TypeHash()
    with pytest.raises(TypeError, match="bytes"):
        TypeHash(value="00ff")
    with pytest.raises(AttributeError):
        TypeHash().colour = "red"  # slots: no attribute beyond version and value


def test_generated_types_are_checked_by_kind():
    type_support.check_for_type_support(String)
    type_support.check_is_valid_msg_type(EmptySrv.Request)  # a request is a message
    type_support.check_is_valid_srv_type(EmptySrv)
    with pytest.raises(RuntimeError, match="might be a service"):
        type_support.check_is_valid_msg_type(EmptySrv)
    with pytest.raises(RuntimeError, match="might be a message"):
        type_support.check_is_valid_srv_type(String)
    with pytest.raises(AttributeError):
        type_support.check_for_type_support(int)


def test_a_foreign_class_without_type_support_is_refused():
    imported = []

    class Meta(type):
        _TYPE_SUPPORT = None

        def __import_type_support__(cls):
            imported.append(cls)

    class Foreign(metaclass=Meta):
        pass

    with pytest.raises(NoTypeSupportImportedException, match="no type_support imported"):
        type_support.check_for_type_support(Foreign)
    assert imported == [Foreign]  # the import was tried first


@pytest.mark.parametrize("name", test_msgs.__all__)
def test_every_fixture_survives_the_wire(name):
    samples = get_test_msg(name)
    assert all(type(sample) is getattr(test_msgs, name) for sample in samples)
    for sample in samples:
        assert deserialize_message(serialize_message(sample), type(sample)) == sample


def test_fixtures_reach_the_ends_of_each_range():
    default, low, high = get_test_msg("BasicTypes")
    assert default == test_msgs.BasicTypes()
    assert (low.int8_value, high.int8_value, high.uint64_value) == (-128, 127, 2**64 - 1)
    assert low.bool_value is False and high.bool_value is True
    bounded = get_test_msg("BoundedSequences")[2]
    assert len(bounded.int32_values) == 3 and len(bounded.basic_types_values) == 3
    assert get_test_msg("UnboundedSequences")[1].string_values == []
    assert get_test_msg("Empty") == [test_msgs.Empty()]
    with pytest.raises(KeyError, match="Nope"):
        get_test_msg("Nope")


def test_a_request_holding_a_type_hash_object_is_refused_at_once(session):
    node = rclpy.create_node("describer")
    node.create_publisher(String, "said", 1)
    (info,) = node.get_publishers_info_by_topic("said")
    client = node.create_client(GetTypeDescription, "/nobody/get_type_description")
    request = GetTypeDescription.Request(type_name="std_msgs/msg/String", type_hash=info.topic_type_hash)
    # The field is a string: rclpy refuses the object when it converts the request, not later.
    with pytest.raises(MessageValidationError, match="type_hash"):
        client.call_async(request)
