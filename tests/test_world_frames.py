"""The TurtleBot's /tf and /tf_static on virtual time: TurtleBot3's frames, odometry's stamps, one tree."""

from __future__ import annotations

import math
from itertools import pairwise

import anyio
import pytest

from actors import DurabilityPolicy, Node, QoSProfile, Runtime
from interfaces.geometry_msgs.msg import PoseStamped
from interfaces.nav_msgs.msg import Odometry
from interfaces.tf2_msgs.msg import TFMessage
from nodes.constant_control import ConstantControl
from world.frames import frame_prefix
from world.robot import TurtleBot
from world.sim import World

pytestmark = pytest.mark.virtual_time

LATCHED = QoSProfile(depth=10, durability=DurabilityPolicy.TRANSIENT_LOCAL)


class TfListener(Node):
    """Keeps /tf with its arrival time, /tf_static, and the odometry and ground truth of the root robot."""

    def __init__(self) -> None:
        super().__init__("tf_listener")
        now = self.get_clock().now
        self.tf: list[tuple[int, TFMessage]] = []
        self.static: list[TFMessage] = []
        self.odom: list[Odometry] = []
        self.truth: list[PoseStamped] = []
        self.create_subscription(TFMessage, "/tf", lambda m: self.tf.append((now().nanoseconds, m)), 100)
        self.create_subscription(TFMessage, "/tf_static", self.static.append, LATCHED)
        self.create_subscription(Odometry, "/odom", self.odom.append, 100)
        self.create_subscription(PoseStamped, "/sim/pose", self.truth.append, 100)


def _ns(stamp) -> int:
    return stamp.sec * 1_000_000_000 + stamp.nanosec


def _yaw(q) -> float:
    return 2 * math.atan2(q.z, q.w)


def _compose(parent, child):
    """(x, y, yaw) of ``child`` expressed in ``parent``'s parent (2D: z rotations only)."""
    (x0, y0, a0), (x1, y1, a1) = parent, child
    return x0 + math.cos(a0) * x1 - math.sin(a0) * y1, y0 + math.sin(a0) * x1 + math.cos(a0) * y1, a0 + a1


def _planar(transform) -> tuple[float, float, float]:
    t = transform.transform
    return t.translation.x, t.translation.y, _yaw(t.rotation)


async def test_tf_carries_odom_to_base_footprint_with_each_odometry_stamp():
    async with Runtime() as rt:
        rt.spawn(World, params={"world": "empty"})
        rt.spawn(TurtleBot, params={"x": 1.0, "y": -0.5, "theta": 0.3})
        rt.spawn(ConstantControl, params={"v": 0.2, "omega": 0.4})
        await anyio.sleep(1.0)  # the listener comes late: /tf only from then, /tf_static all the same
        listener = rt.spawn(TfListener)
        await anyio.sleep(2.0)
    assert len(listener.tf) == len(listener.odom) >= 39  # 20 Hz, one transform per odometry message
    for (arrived, tf), odom in zip(listener.tf, listener.odom):
        (moved,) = tf.transforms
        assert (moved.header.frame_id, moved.child_frame_id) == ("odom", "base_footprint")
        assert moved.header.stamp == odom.header.stamp
        assert _ns(moved.header.stamp) == arrived  # stamped with the graph's (virtual) clock when published
        assert moved.transform.translation.x == odom.pose.pose.position.x
        assert moved.transform.translation.y == odom.pose.pose.position.y
        assert moved.transform.rotation == odom.pose.pose.orientation
    stamps = [_ns(tf.transforms[0].header.stamp) for _, tf in listener.tf]
    assert [b - a for a, b in pairwise(stamps)] == [50_000_000] * (len(stamps) - 1)
    assert listener.tf[-1][1].transforms[0].transform.translation.x != 0.0  # it moved


async def test_tf_static_hangs_odom_on_the_world_at_the_start_pose():
    async with Runtime() as rt:
        rt.spawn(World, params={"world": "empty"})
        rt.spawn(TurtleBot, params={"x": 1.0, "y": -0.5, "theta": 0.3})
        rt.spawn(ConstantControl, params={"v": 0.2, "omega": 0.4})
        await anyio.sleep(1.0)
        listener = rt.spawn(TfListener)  # a late subscriber gets the latched transforms
        await anyio.sleep(2.0)
    (static,) = listener.static
    fixed = {(t.header.frame_id, t.child_frame_id): t for t in static.transforms}
    assert set(fixed) == {("world", "odom"), ("base_footprint", "base_link"), ("base_link", "base_scan")}
    world_odom = _planar(fixed["world", "odom"])
    assert world_odom == (1.0, -0.5, pytest.approx(0.3))
    assert fixed["base_footprint", "base_link"].transform.translation.z == pytest.approx(0.010)
    assert fixed["base_link", "base_scan"].transform.translation.z == pytest.approx(0.172)
    # world -> odom -> base_footprint is where the simulator has the robot (no noise: exactly).
    truth = {_ns(p.header.stamp): p.pose for p in listener.truth}
    for _, tf in listener.tf:
        (moved,) = tf.transforms
        x, y, yaw = _compose(world_odom, _planar(moved))
        pose = truth[_ns(moved.header.stamp)]
        assert (x, y) == (pytest.approx(pose.position.x, abs=1e-9), pytest.approx(pose.position.y, abs=1e-9))
        assert math.remainder(yaw - _yaw(pose.orientation), math.tau) == pytest.approx(0.0, abs=1e-9)


async def test_namespaced_robots_prefix_their_frames_on_the_one_tf_tree():
    async with Runtime() as rt:
        rt.spawn(World, params={"world": "empty"})
        rt.spawn(TurtleBot, name="turtlebot", namespace="robot1", params={"x": -1.0})
        rt.spawn(TurtleBot, name="turtlebot", namespace="robot2", params={"x": 1.0})
        listener = rt.spawn(TfListener)
        odom: list[Odometry] = []
        listener.create_subscription(Odometry, "/robot2/odom", odom.append, 10)
        await anyio.sleep(0.2)
    pairs = {(t.header.frame_id, t.child_frame_id) for m in listener.static for t in m.transforms}
    for robot in ("robot1", "robot2"):
        assert {("world", f"{robot}/odom"), (f"{robot}/base_link", f"{robot}/base_scan")} <= pairs
    moving = {(t.header.frame_id, t.child_frame_id) for _, m in listener.tf for t in m.transforms}
    assert moving == {("robot1/odom", "robot1/base_footprint"), ("robot2/odom", "robot2/base_footprint")}
    assert (odom[-1].header.frame_id, odom[-1].child_frame_id) == ("robot2/odom", "robot2/base_footprint")


def test_frame_prefix_follows_the_namespace():
    assert [frame_prefix(ns) for ns in ("/", "", "/robot1", "/a/b")] == ["", "", "robot1/", "a/b/"]


async def test_nobody_on_tf_means_no_transform_is_published():
    async with Runtime() as rt:
        rt.spawn(World, params={"world": "empty"})
        bot = rt.spawn(TurtleBot)
        sent: list[TFMessage] = []

        class Counting:
            """The robot's /tf publisher, noting what it is asked to publish."""

            def __init__(self, publisher):
                self.publisher = publisher
                self.get_subscription_count = publisher.get_subscription_count

            def publish(self, msg):
                sent.append(msg)
                self.publisher.publish(msg)

        bot.tf_pub = Counting(bot.tf_pub)
        await anyio.sleep(1.0)
        assert sent == []
        rt.spawn(TfListener)
        await anyio.sleep(0.5)
        assert len(sent) == 10
