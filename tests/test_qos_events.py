"""QoS kept at run time: lifespan on delivery, deadline and liveliness events, incompatible and matched events."""

from __future__ import annotations

import logging

import anyio
import msgspec
import pytest

from actors import Node, Runtime
from actors.ros.qos import (
    DurabilityPolicy,
    LivelinessPolicy,
    QoSPolicyKind,
    QoSProfile,
    ReliabilityPolicy,
    qos_profile_best_available,
    qos_profile_sensor_data,
)
from actors.ros.qos_events import (
    PublisherEventCallbacks,
    QoSLivelinessChangedInfo,
    QoSOfferedDeadlineMissedInfo,
    QoSRequestedDeadlineMissedInfo,
    SubscriptionEventCallbacks,
)
from actors.ros.time import Duration
from actors.ros.topics import Publisher
from interfaces.std_msgs.msg import String

pytestmark = pytest.mark.virtual_time


class Talker(Node):
    def __init__(self, qos: QoSProfile, period: float = 0.5, events: PublisherEventCallbacks | None = None) -> None:
        super().__init__("talker")
        self.events: list[object] = []
        self.i = 0
        self.pub = self.create_publisher(String, "chatter", qos, event_callbacks=events)
        self.timer = self.create_timer(period, self.tick) if period else None

    def tick(self) -> None:
        self.pub.publish(String(data=str(self.i)))
        self.i += 1


class Listener(Node):
    def __init__(
        self,
        qos: QoSProfile,
        events: SubscriptionEventCallbacks | None = None,
        name: str = "listener",
        work: float = 0.0,
    ) -> None:
        super().__init__(name)
        self.heard: list[str] = []
        self.work = work
        self.sub = self.create_subscription(String, "chatter", self.on_msg, qos, event_callbacks=events)

    async def on_msg(self, msg: String) -> None:
        self.heard.append(msg.data)
        if self.work:
            await anyio.sleep(self.work)


def depth10(**policies) -> QoSProfile:
    return QoSProfile(depth=10, **policies)


async def test_an_endpoint_copies_its_profile():
    qos = depth10()
    async with Runtime() as rt:
        talker = rt.spawn(Talker, qos, period=0)
        qos.depth = 1
        qos.reliability = ReliabilityPolicy.BEST_EFFORT
        assert (talker.pub.qos.depth, talker.pub.qos.reliability) == (10, ReliabilityPolicy.RELIABLE)
        assert talker.pub.qos_profile == depth10(liveliness=LivelinessPolicy.AUTOMATIC)


async def test_lifespan_keeps_old_messages_from_a_late_subscriber():
    # As ROS's lifespan demo: a latched publisher with a 1 s lifespan, a subscriber that joins at 2.6 s.
    qos = depth10(durability=DurabilityPolicy.TRANSIENT_LOCAL, lifespan=Duration(seconds=1))
    async with Runtime() as rt:
        rt.spawn(Talker, qos)  # publishes 0 at 0.5, 1 at 1.0, ... 4 at 2.5
        await anyio.sleep(2.6)
        listener = rt.spawn(Listener, qos)
        await anyio.sleep(0.01)
        assert listener.heard == ["3", "4"]  # published at 2.0 and 2.5: younger than 1 s at 2.6


async def test_without_a_lifespan_a_late_subscriber_gets_the_whole_history():
    qos = depth10(durability=DurabilityPolicy.TRANSIENT_LOCAL)
    async with Runtime() as rt:
        rt.spawn(Talker, qos)
        await anyio.sleep(2.6)
        listener = rt.spawn(Listener, qos)
        await anyio.sleep(0.01)
        assert listener.heard == ["0", "1", "2", "3", "4"]


async def test_lifespan_drops_messages_that_waited_too_long_in_a_busy_queue():
    qos = depth10(lifespan=Duration(seconds=1))
    async with Runtime() as rt:
        rt.spawn(Talker, qos, period=0.25)
        listener = rt.spawn(Listener, qos, work=1.6)  # each callback holds the node for 1.6 s
        await anyio.sleep(4.0)
    # Message i is published at 0.25 * (i + 1).  0 runs until 1.85, when 1 and 2 have expired;
    # 3 runs until 3.45, when 4..8 have expired in their turn; 9 (2.5) is still young then.
    assert listener.heard == ["0", "3", "9"]


async def test_deadline_missed_on_both_sides_while_the_publisher_pauses():
    missed: dict[str, list[object]] = {"pub": [], "sub": []}
    qos = depth10(deadline=Duration(seconds=0.7))
    async with Runtime() as rt:
        rt.spawn(Listener, qos, SubscriptionEventCallbacks(deadline=missed["sub"].append))
        talker = rt.spawn(Talker, qos, events=PublisherEventCallbacks(deadline=missed["pub"].append))
        await anyio.sleep(2.2)  # publishing every 0.5 s: within the deadline
        assert missed == {"pub": [], "sub": []}
        talker.timer.cancel()  # last message at 2.0; deadlines missed at 2.7, 3.4, 4.1
        await anyio.sleep(1.7)
        talker.timer.reset()  # publishing again from 4.4
        await anyio.sleep(2.0)
    assert missed["sub"] == [QoSRequestedDeadlineMissedInfo(total_count=n, total_count_change=1) for n in (1, 2, 3)]
    assert missed["pub"] == [QoSOfferedDeadlineMissedInfo(total_count=n, total_count_change=1) for n in (1, 2, 3)]


async def test_manual_liveliness_is_lost_and_regained():
    changes: list[QoSLivelinessChangedInfo] = []
    lost: list[object] = []
    qos = depth10(liveliness=LivelinessPolicy.MANUAL_BY_TOPIC, liveliness_lease_duration=Duration(seconds=1))
    async with Runtime() as rt:
        rt.spawn(Listener, qos, SubscriptionEventCallbacks(liveliness=changes.append))
        talker = rt.spawn(Talker, qos, events=PublisherEventCallbacks(liveliness=lost.append))
        await anyio.sleep(0.1)
        assert changes == [QoSLivelinessChangedInfo(alive_count=1, alive_count_change=1)]
        await anyio.sleep(1.5)
        talker.timer.cancel()  # last publish at 1.5: the lease runs out at 2.5
        await anyio.sleep(1.0)
        assert [(i.total_count, i.total_count_change) for i in lost] == [(1, 1)]
        assert changes[-1] == QoSLivelinessChangedInfo(
            alive_count=0, not_alive_count=1, alive_count_change=-1, not_alive_count_change=1
        )
        talker.pub.assert_liveliness()  # alive again without publishing
        await anyio.sleep(0.01)
        assert changes[-1] == QoSLivelinessChangedInfo(
            alive_count=1, not_alive_count=0, alive_count_change=1, not_alive_count_change=-1
        )
        talker.destroy_publisher(talker.pub)
        await anyio.sleep(0.01)
        assert changes[-1].alive_count == 0 and changes[-1].alive_count_change == -1


async def test_automatic_liveliness_is_never_lost():
    lost: list[object] = []
    qos = depth10(liveliness=LivelinessPolicy.AUTOMATIC, liveliness_lease_duration=Duration(seconds=0.2))
    async with Runtime() as rt:
        rt.spawn(Talker, qos, period=0, events=PublisherEventCallbacks(liveliness=lost.append))
        await anyio.sleep(5)
    assert lost == []


async def test_incompatible_qos_events_name_the_policy_and_nothing_is_delivered():
    offered, requested = [], []
    async with Runtime() as rt:
        listener = rt.spawn(
            Listener,
            depth10(durability=DurabilityPolicy.TRANSIENT_LOCAL),
            SubscriptionEventCallbacks(incompatible_qos=requested.append),
        )
        rt.spawn(
            Talker,
            depth10(durability=DurabilityPolicy.VOLATILE),
            events=PublisherEventCallbacks(incompatible_qos=offered.append),
        )
        await anyio.sleep(1.2)
    assert listener.heard == []
    for events in (offered, requested):
        (info,) = events
        assert (info.total_count, info.total_count_change, info.last_policy_kind) == (1, 1, QoSPolicyKind.DURABILITY)


async def test_without_a_callback_each_side_warns_as_rclpy_does(caplog):
    caplog.set_level(logging.WARNING, logger="actors")
    async with Runtime() as rt:
        rt.spawn(Listener, depth10(deadline=Duration(seconds=1)))
        rt.spawn(Talker, depth10(), period=0)
    warnings = sorted(r.getMessage() for r in caplog.records if "incompatible QoS" in r.getMessage())
    assert warnings == [
        "New publisher discovered on topic '/chatter', offering incompatible QoS. No messages will be received "
        "from it. Last incompatible policy: DEADLINE",
        "New subscription discovered on topic '/chatter', requesting incompatible QoS. No messages will be sent "
        "to it. Last incompatible policy: DEADLINE",
    ]


async def test_no_warning_when_default_callbacks_are_turned_off(caplog):
    caplog.set_level(logging.WARNING, logger="actors")
    quiet = SubscriptionEventCallbacks(use_default_callbacks=False)
    async with Runtime() as rt:
        rt.spawn(Listener, depth10(deadline=Duration(seconds=1)), quiet)
        rt.spawn(Talker, depth10(), period=0, events=PublisherEventCallbacks(use_default_callbacks=False))
    assert not [r for r in caplog.records if "incompatible QoS" in r.getMessage()]


async def test_matched_events_count_connections():
    pub_matched, sub_matched = [], []
    async with Runtime() as rt:
        rt.spawn(Listener, depth10(), SubscriptionEventCallbacks(matched=sub_matched.append))
        talker = rt.spawn(Talker, depth10(), period=0, events=PublisherEventCallbacks(matched=pub_matched.append))
        rt.spawn(Listener, depth10(), name="second")
        await anyio.sleep(0.1)
        assert [(i.total_count, i.current_count, i.current_count_change) for i in pub_matched] == [(2, 2, 2)]
        assert [(i.total_count, i.current_count) for i in sub_matched] == [(1, 1)]
        await rt.stop("second")
        talker.destroy_publisher(talker.pub)
        await anyio.sleep(0.1)
    assert (pub_matched[-1].current_count, pub_matched[-1].current_count_change) == (1, -1)
    assert (sub_matched[-1].total_count, sub_matched[-1].current_count, sub_matched[-1].current_count_change) == (
        1,
        0,
        -1,
    )


async def test_best_available_takes_what_the_publishers_offer():
    async with Runtime() as rt:
        rt.spawn(Talker, qos_profile_sensor_data)
        listener = rt.spawn(Listener, qos_profile_best_available)
        latched = rt.spawn(Talker, qos_profile_best_available, period=0, name="latched")  # offers the most
        await anyio.sleep(0.6)
        assert listener.heard == ["0"]  # it asked for BEST_EFFORT, as the sensor-data talker offers
        assert (listener.sub.qos.reliability, listener.sub.qos.durability) == (
            ReliabilityPolicy.BEST_EFFORT,
            DurabilityPolicy.VOLATILE,
        )
        assert (latched.pub.qos.reliability, latched.pub.qos.durability) == (
            ReliabilityPolicy.RELIABLE,
            DurabilityPolicy.TRANSIENT_LOCAL,
        )


async def test_the_graph_view_shows_the_qos_and_encodes():
    qos = depth10(deadline=Duration(seconds=0.6), lifespan=Duration(seconds=2))
    async with Runtime() as rt:
        rt.spawn(Talker, qos, period=0)
        (topic,) = [t for t in rt.graph.topics() if t.name == "/chatter"]
        (endpoint,) = topic.publishers
        assert (endpoint.qos.deadline_ns, endpoint.qos.lifespan_ns) == (600_000_000, 2_000_000_000)
        assert msgspec.msgpack.encode(topic)  # what the command line receives


async def test_plain_publishers_stay_plain():
    async with Runtime() as rt:
        talker = rt.spawn(Talker, depth10(), period=0)
        assert type(talker.pub) is Publisher and talker.pub._events is None
