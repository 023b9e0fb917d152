"""Topics: delivery, QoS depth and drops, transient-local history, type checks, matching."""

from __future__ import annotations

from array import array

import anyio
import numpy as np
import pytest

from actors import (
    DurabilityPolicy,
    HistoryPolicy,
    Node,
    QoSProfile,
    ReliabilityPolicy,
    Runtime,
    TopicTypeError,
)
from actors.errors import MessageValidationError
from interfaces.geometry_msgs.msg import Point, PoseWithCovariance, Twist, Vector3
from interfaces.nav_msgs.msg import Odometry
from interfaces.sensor_msgs.msg import LaserScan
from interfaces.std_msgs.msg import Int64, String

pytestmark = pytest.mark.virtual_time


class Sink(Node):
    """Subscribes to ``numbers`` with the QoS and callback delay set on the class."""

    qos: QoSProfile | int = 10
    delay = 0.0

    def __init__(self) -> None:
        super().__init__("sink")
        self.heard: list[int] = []
        self.sub = self.create_subscription(Int64, "numbers", self.on_number, self.qos)

    async def on_number(self, msg: Int64) -> None:
        self.heard.append(msg.data)
        if self.delay:
            await anyio.sleep(self.delay)


class Source(Node):
    qos: QoSProfile | int = 10

    def __init__(self) -> None:
        super().__init__("source")
        self.pub = self.create_publisher(Int64, "numbers", self.qos)


async def test_messages_arrive_in_order_as_they_were_when_published():
    async with Runtime() as rt:
        sink = rt.spawn(Sink)
        source = rt.spawn(Source)
        received = []
        sink.sub.callback = received.append
        msg = Int64()
        for i in range(5):
            msg.data = i  # one object, changed and published again (rclpy's publisher_local_function)
            source.pub.publish(msg)
        msg.data = 99
        await anyio.sleep(0.01)
        assert [m.data for m in received] == [0, 1, 2, 3, 4]
        assert all(m is not msg for m in received)


async def test_a_nested_message_changed_after_publishing_is_delivered_as_published():
    heard: list[Odometry] = []

    class OdomSink(Node):
        def __init__(self) -> None:
            super().__init__("odom_sink")
            self.create_subscription(Odometry, "odom", heard.append, 10)

    async with Runtime() as rt:
        rt.spawn(OdomSink)
        pub = rt.spawn(Source).create_publisher(Odometry, "odom", 10)
        odom = Odometry(child_frame_id="base")
        odom.pose.pose.position.x = 1
        odom.pose.covariance[0] = 0.5
        pub.publish(odom)
        odom.pose.pose.position.x = 2.0
        odom.pose.covariance[0] = 9.0
        odom.header.stamp.sec = 7
        await anyio.sleep(0.01)
        (got,) = heard
        assert got.pose.pose.position.x == 1.0 and type(got.pose.pose.position.x) is float  # an int becomes a float
        assert got.pose.covariance[0] == 0.5 and got.header.stamp.sec == 0
        assert got.child_frame_id == "base"


async def test_trusted_fields_changed_after_publishing_are_delivered_as_published():
    heard: list[LaserScan] = []

    class ScanSink(Node):
        def __init__(self) -> None:
            super().__init__("scan_sink")
            self.create_subscription(LaserScan, "scan", heard.append, 10)

    async with Runtime() as rt:
        pub = rt.spawn(Source).create_publisher(LaserScan, "scan", 10)
        pub.trust("ranges", "intensities")
        pub.publish(LaserScan(ranges=[1e39]))  # nobody listens: a trusted field is not looked at
        rt.spawn(ScanSink)
        scan = LaserScan(ranges=np.array([1.0, 2.0]), intensities=[3.0])
        pub.publish(scan)
        scan.ranges[0] = 9.0
        scan.intensities[0] = 9.0
        with pytest.raises(MessageValidationError, match="field 'range_max'"):
            pub.publish(LaserScan(range_max=1e39))  # the other fields are checked as before
        with pytest.raises(ValueError, match="no field"):
            pub.trust("nothing")
        pub.trust()  # every field, nested ones too
        scan.header.stamp.sec = 1
        pub.publish(scan)
        scan.header.stamp.sec = 2
        scan.header.frame_id = "changed"
        await anyio.sleep(0.01)
        first, second = heard
        assert first.ranges == array("f", [1.0, 2.0]) and first.ranges.typecode == "f"
        assert first.intensities == array("f", [3.0])
        assert second.ranges == array("f", [9.0, 2.0]) and second.header.stamp.sec == 1 and second.header.frame_id == ""


async def test_the_subscribers_of_one_publish_share_one_snapshot():
    class Two(Node):
        def __init__(self) -> None:
            super().__init__("two")
            self.heard: list[Int64] = []
            for _ in range(2):
                self.create_subscription(Int64, "numbers", self.heard.append, 10)

    async with Runtime() as rt:
        two = rt.spawn(Two)
        msg = Int64(data=3)
        rt.spawn(Source).pub.publish(msg)
        await anyio.sleep(0.01)
        first, second = two.heard
        assert first is second and first is not msg and first.data == 3


@pytest.mark.parametrize(
    ("build", "error"),
    [
        (lambda: String(data=42), "field 'data' of std_msgs/msg/String: expected a str, got the int 42"),
        (
            lambda: Int64(data=2**70),
            "field 'data' of std_msgs/msg/Int64: 1180591620717411303424 is out of range for int64 "
            "(-9223372036854775808..9223372036854775807)",
        ),
        (lambda: Int64(data=1.5), "field 'data' of std_msgs/msg/Int64: expected an int, got the float 1.5"),
        (
            lambda: Twist(linear=Vector3(x="fast")),
            "field 'linear.x' of geometry_msgs/msg/Twist: expected a float, got the str 'fast'",
        ),
        (
            lambda: Twist(angular=Point()),
            "field 'angular' of geometry_msgs/msg/Twist: expected a geometry_msgs/msg/Vector3, "
            "got a geometry_msgs/msg/Point",
        ),
        (
            lambda: LaserScan(ranges=[1.0, 1e39]),
            "field 'ranges[1]' of sensor_msgs/msg/LaserScan: 1e+39 is out of range for float32 (±3.4028235e+38)",
        ),
        (
            lambda: LaserScan(ranges=np.array([1.0, 1e39, float("inf")])),
            "field 'ranges[1]' of sensor_msgs/msg/LaserScan: 1e+39 is out of range for float32 (±3.4028235e+38)",
        ),
        (
            lambda: Odometry(pose=PoseWithCovariance(covariance=[0.0] * 35)),
            "field 'pose.covariance' of nav_msgs/msg/Odometry: expected 36 items (float64[36]), got 35",
        ),
    ],
)
@pytest.mark.parametrize("listened", [True, False], ids=["subscribed", "nobody-subscribed"])
async def test_a_field_of_the_wrong_type_or_out_of_range_fails_at_publish(build, error, listened):
    heard: list[object] = []
    msg = build()

    class Anything(Node):
        def __init__(self) -> None:
            super().__init__("anything")
            self.pub = self.create_publisher(type(msg), "anything", 10)
            if listened:  # with nobody to receive it, the message is checked all the same
                self.create_subscription(type(msg), "anything", heard.append, 10)

    async with Runtime() as rt:
        node = rt.spawn(Anything)
        with pytest.raises(MessageValidationError) as raised:
            node.pub.publish(msg)
        assert str(raised.value) == error
        await anyio.sleep(0.01)
        assert heard == []  # nothing of it was delivered


async def test_removing_a_subscription_keeps_the_others_in_order():
    woken: list[str] = []

    class Listener(Node):
        def __init__(self) -> None:
            super().__init__("listener")
            self.sub = self.create_subscription(Int64, "numbers", lambda msg: woken.append(self.get_name()), 10)

    async with Runtime() as rt:
        listeners = [rt.spawn(Listener, name=name) for name in ("s1", "s2", "s3", "s4")]
        source = rt.spawn(Source)
        listeners[1].destroy_subscription(listeners[1].sub)
        assert [s.node for s in rt.graph.topic("/numbers").subscriptions] == ["/s1", "/s3", "/s4"]
        assert source.pub.get_subscription_count() == 3
        source.pub.publish(Int64(data=1))
        await anyio.sleep(0.01)
        assert woken == ["s1", "s3", "s4"]  # woken in subscription order


async def test_each_publish_feeds_the_subscriptions_matched_at_that_moment():
    # The publisher keeps its subscriptions as a tuple made again after each change: one
    # that joins, leaves or is replaced by a restart between two publishes must count.
    heard: dict[str, list[int]] = {}

    class Listener(Node):
        def __init__(self) -> None:
            super().__init__("listener")
            heard.setdefault(self.get_name(), [])
            self.sub = self.create_subscription(Int64, "numbers", self.on_number, 10)

        def on_number(self, msg: Int64) -> None:
            heard[self.get_name()].append(msg.data)
            if msg.data == 3 and self.get_name() == "crashy":
                raise RuntimeError("restart on purpose")

    async with Runtime() as rt:
        source = rt.spawn(Source)
        first = rt.spawn(Listener, name="first")
        source.pub.publish(Int64(data=1))
        await anyio.sleep(0.01)
        rt.spawn(Listener, name="late")
        rt.spawn(Listener, name="crashy")
        source.pub.publish(Int64(data=2))
        await anyio.sleep(0.01)
        first.destroy_subscription(first.sub)
        source.pub.publish(Int64(data=3))
        await anyio.sleep(5)  # crashy crashes on 3 and is restarted
        assert [n.crashes for n in rt.graph.nodes() if n.name == "/crashy"] == [1]
        source.pub.publish(Int64(data=4))
        await anyio.sleep(0.01)
        assert heard == {"first": [1, 2], "late": [2, 3, 4], "crashy": [2, 3, 4]}
        assert source.pub.get_subscription_count() == 2


async def test_keep_last_drops_the_oldest_and_counts_the_drops():
    class SlowSink(Sink):
        qos = 10
        delay = 1.0

    async with Runtime() as rt:
        sink = rt.spawn(SlowSink)
        source = rt.spawn(Source)
        for i in range(30):
            source.pub.publish(Int64(data=i))
            await anyio.sleep(0.05)  # 20 messages/s against 1 message/s handled
        await anyio.sleep(20)
        info = rt.graph.topic("/numbers")
        assert info is not None
        drops = info.subscriptions[0].dropped
        assert drops == sink.sub.dropped > 0
        assert len(sink.heard) + drops == 30
        # What survives is the newest: the last ten messages all arrive.
        assert sink.heard[-10:] == list(range(20, 30))
        assert sink.heard == sorted(sink.heard)


async def test_keep_all_never_drops():
    class SlowSink(Sink):
        qos = QoSProfile(history=HistoryPolicy.KEEP_ALL)
        delay = 0.5

    async with Runtime() as rt:
        sink = rt.spawn(SlowSink)
        source = rt.spawn(Source)
        for i in range(50):
            source.pub.publish(Int64(data=i))
        await anyio.sleep(30)
        assert sink.heard == list(range(50))
        assert sink.sub.dropped == 0


async def test_transient_local_gives_a_late_subscriber_the_last_n():
    latched = QoSProfile(depth=3, durability=DurabilityPolicy.TRANSIENT_LOCAL)

    class LatchedSource(Source):
        qos = latched

    class LateSink(Sink):
        qos = latched

    class VolatileSink(Sink):
        qos = 10

    async with Runtime() as rt:
        source = rt.spawn(LatchedSource)
        for i in range(10):
            source.pub.publish(Int64(data=i))
        late = rt.spawn(LateSink)
        volatile = rt.spawn(VolatileSink, name="volatile_sink")
        await anyio.sleep(0.1)
        assert late.heard == [7, 8, 9]
        assert volatile.heard == []


async def test_publishing_the_wrong_type_raises_type_error_naming_both():
    async with Runtime() as rt:
        source = rt.spawn(Source)
        with pytest.raises(TypeError, match=r"std_msgs/msg/Int64.*std_msgs/msg/String"):
            source.pub.publish(String(data="nope"))


async def test_a_subscription_of_another_type_is_refused():
    class WrongSink(Node):
        def __init__(self) -> None:
            super().__init__("wrong")
            self.create_subscription(String, "/numbers", print, 10)

    async with Runtime() as rt:
        rt.spawn(Source)
        with pytest.raises(TopicTypeError, match=r"std_msgs/msg/String.*std_msgs/msg/Int64.*/source"):
            rt.spawn(WrongSink)


async def test_a_publisher_of_another_type_is_refused():
    class WrongSource(Node):
        def __init__(self) -> None:
            super().__init__("wrong")
            self.create_publisher(String, "/numbers", 10)

    async with Runtime() as rt:
        rt.spawn(Sink)
        with pytest.raises(TopicTypeError, match=r"std_msgs/msg/String.*std_msgs/msg/Int64"):
            rt.spawn(WrongSource)


async def test_best_effort_publisher_does_not_feed_a_reliable_subscription():
    class BestEffortSource(Source):
        qos = QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT)

    async with Runtime() as rt:
        sink = rt.spawn(Sink)
        source = rt.spawn(BestEffortSource)
        source.pub.publish(Int64(data=1))
        await anyio.sleep(0.1)
        assert sink.heard == []
        assert source.pub.get_subscription_count() == 0


async def test_namespace_and_remap_from_spawn():
    async with Runtime() as rt:
        sink = rt.spawn(Sink, namespace="robot1", remap={"numbers": "/shared"})
        assert sink.sub.topic_name == "/shared"
        assert sink.get_fully_qualified_name() == "/robot1/sink"
        source = rt.spawn(Source, name="src", remap={"numbers": "/shared"})
        source.pub.publish(Int64(data=7))
        await anyio.sleep(0.01)
        assert sink.heard == [7]


async def test_one_callback_at_a_time_even_when_async():
    class Overlap(Node):
        def __init__(self) -> None:
            super().__init__("overlap")
            self.active = 0
            self.max_active = 0
            self.create_subscription(Int64, "numbers", self.slow, 10)
            self.create_timer(0.01, self.slow_tick)

        async def slow(self, _msg: Int64) -> None:
            await self.slow_tick()

        async def slow_tick(self) -> None:
            self.active += 1
            self.max_active = max(self.max_active, self.active)
            await anyio.sleep(0.05)
            self.active -= 1

    async with Runtime() as rt:
        node = rt.spawn(Overlap)
        source = rt.spawn(Source)
        for i in range(10):
            source.pub.publish(Int64(data=i))
        await anyio.sleep(2)
        assert node.max_active == 1


async def test_graph_view_lists_nodes_and_endpoints():
    async with Runtime() as rt:
        rt.spawn(Sink)
        rt.spawn(Source)
        names = [n.name for n in rt.graph.nodes()]
        assert names == ["/sink", "/source"]
        topic = rt.graph.topic("/numbers")
        assert topic is not None and topic.type == "std_msgs/msg/Int64"
        assert [p.node for p in topic.publishers] == ["/source"]
        assert [s.node for s in topic.subscriptions] == ["/sink"]
        assert topic.subscriptions[0].qos.depth == 10
