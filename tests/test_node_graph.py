"""A node's queries about the graph, as rclpy's: nodes, topics, services, counts, endpoint info."""

from __future__ import annotations

import pytest

from actors import DurabilityPolicy, Node, QoSProfile, Runtime
from actors.errors import InvalidServiceNameException, InvalidTopicNameException
from actors.ros.endpoint_info import TopicEndpointInfo, TopicEndpointTypeEnum
from interfaces.example_interfaces.srv import AddTwoInts
from interfaces.std_msgs.msg import String

pytestmark = pytest.mark.virtual_time


class Talker(Node):
    def __init__(self) -> None:
        super().__init__("talker")
        self.pub = self.create_publisher(
            String, "chatter", QoSProfile(depth=7, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        )
        self.create_service(AddTwoInts, "add", lambda request, response: response)


class Listener(Node):
    def __init__(self) -> None:
        super().__init__("listener")
        self.create_subscription(String, "chatter", lambda msg: None, 3)
        self.create_subscription(String, "~/private", lambda msg: None, 3)
        self.adder = self.create_client(AddTwoInts, "/robot/add")
        self.create_client(AddTwoInts, "/robot/add")


async def test_node_names_and_namespaces():
    async with Runtime() as rt:
        talker = rt.spawn(Talker, namespace="robot")
        rt.spawn(Listener)
        assert talker.get_node_names_and_namespaces() == [("talker", "/robot"), ("listener", "/")]
        assert talker.get_node_names() == ["talker", "listener"]
        assert talker.get_fully_qualified_node_names() == ["/robot/talker", "/listener"]


async def test_topics_and_counts_expand_relative_names():
    async with Runtime() as rt:
        talker = rt.spawn(Talker, namespace="robot")
        listener = rt.spawn(Listener, namespace="robot")
        assert ("/robot/chatter", ["std_msgs/msg/String"]) in talker.get_topic_names_and_types()
        assert talker.count_publishers("chatter") == 1 and talker.count_subscribers("chatter") == 1
        assert talker.count_subscribers("/robot/chatter") == 1
        assert listener.count_subscribers("~/private") == 1 and talker.count_subscribers("~/private") == 0
        assert talker.count_publishers("nobody") == 0
        with pytest.raises(InvalidTopicNameException):
            talker.count_publishers("bad name")


async def test_counts_do_not_follow_remapping_but_endpoint_info_does():
    async with Runtime() as rt:
        talker = rt.spawn(Talker, remap={"chatter": "/renamed"})
        assert talker.count_publishers("chatter") == 0  # rclpy: the queried name is not remapped
        assert talker.count_publishers("/renamed") == 1
        (info,) = talker.get_publishers_info_by_topic("chatter")  # ...while this one is
        assert info.node_name == "talker"


async def test_services_and_clients():
    async with Runtime() as rt:
        talker = rt.spawn(Talker, namespace="robot")
        listener = rt.spawn(Listener)
        services = dict(talker.get_service_names_and_types())
        assert services["/robot/add"] == ["example_interfaces/srv/AddTwoInts"]
        assert services["/listener/get_parameters"] == ["rcl_interfaces/srv/GetParameters"]
        assert list(services) == sorted(services)
        assert talker.count_services("add") == 1 and listener.count_services("add") == 0
        assert talker.count_clients("add") == 2 and listener.count_clients("/robot/add") == 2
        listener.destroy_client(listener.adder)
        assert talker.count_clients("add") == 1
        with pytest.raises(InvalidServiceNameException):
            talker.count_services("add/")


async def test_names_and_types_by_node():
    async with Runtime() as rt:
        talker = rt.spawn(Talker, namespace="robot")
        rt.spawn(Listener)
        assert talker.get_publisher_names_and_types_by_node("talker", "/robot") == [
            ("/robot/chatter", ["std_msgs/msg/String"])
        ]
        assert talker.get_subscriber_names_and_types_by_node("listener", "/") == [
            ("/chatter", ["std_msgs/msg/String"]),
            ("/listener/private", ["std_msgs/msg/String"]),
        ]
        assert talker.get_client_names_and_types_by_node("listener", "") == [
            ("/robot/add", ["example_interfaces/srv/AddTwoInts"])
        ]
        assert ("/robot/add", ["example_interfaces/srv/AddTwoInts"]) in talker.get_service_names_and_types_by_node(
            "talker", "/robot"
        )
        with pytest.raises(LookupError):
            talker.get_publisher_names_and_types_by_node("ghost", "/")


async def test_publishers_and_subscriptions_info_by_topic():
    async with Runtime() as rt:
        talker = rt.spawn(Talker)
        listener = rt.spawn(Listener)
        (pub,) = talker.get_publishers_info_by_topic("chatter")
        (sub,) = listener.get_subscriptions_info_by_topic("/chatter")
        assert isinstance(pub, TopicEndpointInfo)
        assert (pub.node_name, pub.node_namespace, pub.topic_type) == ("talker", "/", "std_msgs/msg/String")
        assert pub.endpoint_type is TopicEndpointTypeEnum.PUBLISHER
        assert sub.endpoint_type is TopicEndpointTypeEnum.SUBSCRIPTION
        assert (pub.qos_profile.depth, pub.qos_profile.durability) == (7, DurabilityPolicy.TRANSIENT_LOCAL)
        assert sub.qos_profile.depth == 3
        assert len(pub.endpoint_gid) == 16 and pub.endpoint_gid != sub.endpoint_gid
        assert talker.get_publishers_info_by_topic("nobody") == []
        text = str(pub)
        assert text.startswith("Node name: talker\nNode namespace: /\nTopic type: std_msgs/msg/String\n")
        assert "Endpoint type: PUBLISHER" in text and "  History (Depth): KEEP_LAST (7)" in text
