"""QoS overriding from parameters on the overlay: endpoints made with the policies their parameters give."""

from __future__ import annotations

import pytest

import actors.compat.rclpy as rclpy
from actors.compat.rclpy.node import Node
from actors.compat.rclpy.qos_overriding_options import (
    InvalidQosOverridesError,
    QosCallbackResult,
    QoSOverridingOptions,
    _get_qos_policy_parameter,
)
from actors.ros.parameter import Parameter
from actors.ros.qos import DurabilityPolicy, QoSPolicyKind, QoSProfile, ReliabilityPolicy
from actors.ros.time import Duration
from interfaces.std_msgs.msg import String


@pytest.fixture
def session(rclpy_session):
    return rclpy_session


def _depth_at_most(limit):
    def judge(qos):
        return QosCallbackResult(successful=qos.depth <= limit, reason=f"depth over {limit}")

    return judge


def test_start_values_shape_the_publisher_and_stay_read_only(session):
    node = Node(
        "overridden",
        parameter_overrides=[
            Parameter("qos_overrides./ns/news.publisher.depth", value=4),
            Parameter("qos_overrides./ns/news.publisher.reliability", value="best_effort"),
        ],
        namespace="/ns",
    )
    node.create_publisher(String, "news", 10, qos_overriding_options=QoSOverridingOptions.with_default_policies())
    (info,) = node.get_publishers_info_by_topic("/ns/news")
    assert (info.qos_profile.depth, info.qos_profile.reliability) == (4, ReliabilityPolicy.BEST_EFFORT)
    assert node.get_parameter("qos_overrides./ns/news.publisher.history").value == "keep_last"
    (result,) = node.set_parameters([Parameter("qos_overrides./ns/news.publisher.depth", value=2)])
    assert not result.successful  # QoS is fixed once the endpoint exists


def test_a_subscription_gets_no_lifespan_and_an_id_names_its_parameters(session):
    node = rclpy.create_node("listening")
    everything = [QoSPolicyKind.LIFESPAN, QoSPolicyKind.DURABILITY, QoSPolicyKind.DEADLINE]
    node.create_subscription(
        String, "/news", lambda _: None, QoSProfile(depth=3, deadline=Duration(seconds=2)),
        qos_overriding_options=QoSOverridingOptions(everything, entity_id="slow"),
    )  # fmt: skip
    assert sorted(node.get_parameters_by_prefix("qos_overrides")) == [
        "/news.subscription_slow.deadline",
        "/news.subscription_slow.durability",
    ]
    assert node.get_parameter("qos_overrides./news.subscription_slow.deadline").value == 2_000_000_000


def test_the_callback_refuses_a_profile_and_no_publisher_is_made(session):
    node = Node("strict", parameter_overrides=[Parameter("qos_overrides./loud.publisher.depth", value=50)])
    options = QoSOverridingOptions.with_default_policies(callback=_depth_at_most(10))
    with pytest.raises(
        InvalidQosOverridesError, match="publisher `/loud` with id `None`, are not valid: depth over 10"
    ):
        node.create_publisher(String, "/loud", 10, qos_overriding_options=options)
    assert node.get_publishers_info_by_topic("/loud") == []


def test_policy_values_as_parameters_and_bad_names_back():
    profile = QoSProfile(depth=7, durability=DurabilityPolicy.TRANSIENT_LOCAL, lifespan=Duration(seconds=1))
    assert _get_qos_policy_parameter(profile, QoSPolicyKind.DURABILITY) == "transient_local"
    assert _get_qos_policy_parameter(profile, QoSPolicyKind.DEPTH) == 7
    assert _get_qos_policy_parameter(profile, QoSPolicyKind.LIFESPAN) == 1_000_000_000


def test_an_unknown_policy_name_at_start_is_an_error(session):
    node = Node("typo", parameter_overrides=[Parameter("qos_overrides./t.publisher.reliability", value="reliablee")])
    with pytest.raises(RuntimeError, match="`reliability`: `reliablee`"):
        node.create_publisher(String, "/t", 1, qos_overriding_options=QoSOverridingOptions.with_default_policies())
