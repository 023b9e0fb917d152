"""The stand-in for rclpy's C extension, QoS hand-over records, and endpoint infos as rclpy prints them."""

from __future__ import annotations

import pytest

import actors.compat.rclpy as rclpy
from actors import codec
from actors.compat.rclpy.impl.implementation_singleton import rclpy_implementation as _rclpy
from actors.compat.rclpy.topic_endpoint_info import TopicEndpointInfo, TopicEndpointTypeEnum
from actors.compat.rclpy.type_hash import TypeHash
from actors.errors import RosArgsError
from actors.ros.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, qos_profile_sensor_data
from actors.ros.time import Duration, Infinite
from interfaces.std_msgs.msg import String


@pytest.fixture
def session(rclpy_session):
    return rclpy_session


def test_the_stand_in_names_the_middleware_and_the_argument_errors():
    assert _rclpy.rclpy_get_rmw_implementation_identifier() == rclpy.get_rmw_implementation_identifier()
    with pytest.raises(_rclpy.UnknownROSArgsError, match=r"\['--shout'\]"):
        rclpy.Context().init(["--ros-args", "--shout"])
    assert _rclpy.RCLInvalidROSArgsError is RosArgsError


def test_a_profile_survives_the_hand_over_record():
    profile = QoSProfile(history=HistoryPolicy.KEEP_ALL, lifespan=Duration(seconds=3), deadline=Duration(seconds=5))
    assert QoSProfile(**profile.get_c_qos_profile().to_dict()) == profile
    assert QoSProfile(**_rclpy.rmw_qos_profile_t.predefined("qos_profile_sensor_data").to_dict()) == (
        qos_profile_sensor_data
    )
    with pytest.raises(ValueError, match="unknown predefined"):
        _rclpy.rmw_qos_profile_t.predefined("qos_profile_fastest")


def test_an_info_made_by_hand_prints_as_unknown():
    text = str(TopicEndpointInfo(node_name="n"))
    assert text.splitlines()[:5] == [
        "Node name: n",
        "Node namespace: ",
        "Topic type: ",
        "Topic type hash: INVALID",
        "Endpoint type: INVALID",
    ]
    assert "  Liveliness: UNKNOWN" in text


def test_a_publishers_info_carries_its_profile_and_type_hash(session):
    node = rclpy.create_node("informer", namespace="/ns")
    node.create_publisher(String, "said", QoSProfile(depth=3, durability=DurabilityPolicy.TRANSIENT_LOCAL))
    (info,) = node.get_publishers_info_by_topic("/ns/said")
    assert info.endpoint_type is TopicEndpointTypeEnum.PUBLISHER
    # A duration never set reads as rmw's infinite one, as real rclpy's graph query reports it.
    assert info.qos_profile.depth == 3 and info.qos_profile.lifespan == Infinite
    assert "  Lifespan: Infinite\n  Deadline: Infinite\n" in str(info)
    assert isinstance(info.topic_type_hash, TypeHash) and info.topic_type_hash.version == 1
    assert str(info.topic_type_hash) == codec.type_hash(String)
    assert "Topic type hash: RIHS01_" in str(info)
    assert "  Durability: TRANSIENT_LOCAL" in str(info)


def test_a_nodes_bad_arguments_are_named_in_rcls_words(session):
    with pytest.raises(RosArgsError, match=r"^Failed to parse ROS arguments: .*not-a-remap"):
        rclpy.create_node("argued", cli_args=["--ros-args", "-r", "not-a-remap"])
    with pytest.raises(TypeError, match="Expected QoSProfile or int, but received 'deep'"):
        rclpy.create_node("typed").create_publisher(String, "t", "deep")


def test_init_records_the_signal_handlers_and_shutdown_forgets_them():
    from actors.compat.rclpy import signals

    context = rclpy.Context()
    assert signals.get_current_signal_handlers_options() == signals.SignalHandlerOptions.NO
    rclpy.init(args=[], context=context, signal_handler_options=signals.SignalHandlerOptions.SIGINT)
    assert signals.get_current_signal_handlers_options() == signals.SignalHandlerOptions.SIGINT
    rclpy.shutdown(context=context)  # not the default context: its handlers stay
    assert signals.get_current_signal_handlers_options() == signals.SignalHandlerOptions.SIGINT
    signals.uninstall_signal_handlers()
    assert signals.get_current_signal_handlers_options() == signals.SignalHandlerOptions.NO


def test_an_undecodable_argument_fails_init_as_in_rclpy():
    context = rclpy.Context()
    with pytest.raises(UnicodeEncodeError):
        rclpy.init(args=["prog.py", "caf\udcc3\udca9"], context=context)  # bytes a wrong locale could not decode
    assert not context.ok()
