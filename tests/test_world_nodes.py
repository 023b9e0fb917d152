"""The World and TurtleBot nodes, and the constant-control exercise, on virtual time."""

from __future__ import annotations

import math
import re
from array import array
from itertools import pairwise

import anyio
import pytest
from conftest import ROOT

from actors import Node, Parameter, Runtime, VirtualTimeLoop, codec
from actors.errors import WorldError
from interfaces.geometry_msgs.msg import PoseStamped, Twist
from interfaces.nav_msgs.msg import Odometry
from interfaces.sensor_msgs.msg import LaserScan
from interfaces.std_msgs.msg import Bool
from nodes.constant_control import ConstantControl
from world.lidar import Lidar
from world.robot import TurtleBot
from world.sim import World

pytestmark = pytest.mark.virtual_time


class Observer(Node):
    """Records stamped cmd_vel, ground-truth poses, odometry, scans and contact of /<ns>/..."""

    def __init__(self) -> None:
        super().__init__("observer")
        self.cmds: list[tuple[float, Twist]] = []
        self.poses: list[tuple[float, float, float]] = []
        self.odom: list[Odometry] = []
        self.scans: list[LaserScan] = []
        self.contact: list[bool] = []
        now = self.get_clock().monotonic
        self.create_subscription(Twist, "cmd_vel", lambda m: self.cmds.append((now(), m)), 100)
        self.create_subscription(
            PoseStamped, "sim/pose", lambda m: self.poses.append((now(), m.pose.position.x, m.pose.position.y)), 100
        )
        self.create_subscription(Odometry, "odom", self.odom.append, 100)
        self.create_subscription(LaserScan, "scan", self.scans.append, 100)
        self.create_subscription(Bool, "sim/contact", lambda m: self.contact.append(m.data), 10)


class Killer(Node):
    """Publishes std_msgs/Bool true on /kill at t = 5 s."""

    def __init__(self) -> None:
        super().__init__("killer")
        self.pub = self.create_publisher(Bool, "/kill", 10)
        self.timer = self.create_timer(5.0, self.kill)

    def kill(self) -> None:
        self.timer.cancel()
        self.pub.publish(Bool(data=True))


async def test_kill_stops_the_constant_control_robot():
    async with Runtime() as rt:
        rt.spawn(World, params={"world": "empty"})
        rt.spawn(TurtleBot)
        observer = rt.spawn(Observer)
        rt.spawn(ConstantControl)
        rt.spawn(Killer)
        await anyio.sleep(10)
    stop = next(i for i, (_, cmd) in enumerate(observer.cmds) if cmd.linear.x == 0.0)
    stop_time, stop_cmd = observer.cmds[stop]
    assert 5.0 <= stop_time <= 5.2  # within one control period of the kill
    assert (stop_cmd.linear.x, stop_cmd.angular.z) == (0.0, 0.0)
    assert stop == len(observer.cmds) - 1  # nothing after it: the timer is cancelled
    assert all(cmd.linear.x == pytest.approx(0.2) for _, cmd in observer.cmds[:stop])
    # It moved at 0.2 m/s until then, and its true pose stops changing after the kill.
    at_kill = next(p for p in observer.poses if p[0] >= 5.05)
    last = observer.poses[-1]
    assert at_kill[1] == pytest.approx(0.2 * 4.8, abs=1e-6)  # first command at 0.2 s
    assert math.dist(at_kill[1:], last[1:]) < 1e-3


async def test_driving_into_a_wall_stops_against_it_and_never_through():
    async with Runtime() as rt:
        rt.spawn(World, params={"world": "empty"})
        rt.spawn(TurtleBot, params={"x": 3.0})
        observer = rt.spawn(Observer)
        rt.spawn(ConstantControl, params={"v": 0.2})
        await anyio.sleep(60)
    wall, radius = 5.0, 0.105
    assert max(x for _, x, _ in observer.poses) <= wall - radius + 1e-3
    assert observer.poses[-1][1] == pytest.approx(wall - radius, abs=2e-3)
    assert observer.contact[0] is False and observer.contact[-1] is True


async def test_the_scan_sees_walls_nothing_and_other_robots():
    async with Runtime() as rt:
        rt.spawn(World, params={"world": "empty"})
        rt.spawn(TurtleBot, params={"x": 4.0})
        rt.spawn(TurtleBot, name="other", namespace="other", params={"x": 4.0, "y": 1.5})  # not on /scan
        observer = rt.spawn(Observer)
        await anyio.sleep(0.15)
    scan = observer.scans[-1]
    assert len(scan.ranges) == 360 and scan.header.frame_id == "base_scan"
    assert type(scan.ranges) is array and scan.ranges.typecode == "f"  # trusted, held as rclpy holds it
    assert scan.ranges[0] == pytest.approx(1.0, abs=0.01)  # the wall ahead
    assert scan.ranges[180] == math.inf  # 9 m behind: nothing within 3.5 m
    assert scan.ranges[90] == pytest.approx(1.5 - 0.105, abs=0.01)  # the other robot
    assert (scan.range_min, scan.range_max) == (pytest.approx(0.12), pytest.approx(3.5))


async def test_odometry_is_relative_to_the_start_pose():
    async with Runtime() as rt:
        rt.spawn(World, params={"world": "empty"})
        rt.spawn(TurtleBot, params={"x": 1.0, "y": 2.0, "theta": math.pi / 2})
        observer = rt.spawn(Observer)
        rt.spawn(ConstantControl, params={"v": 0.2, "omega": 0.0})
        await anyio.sleep(5.02)
    odom = observer.odom[-1]
    assert (odom.header.frame_id, odom.child_frame_id) == ("odom", "base_footprint")
    assert odom.pose.covariance == odom.twist.covariance == array("d", [0.0] * 36)
    assert odom.pose.pose.position.x == pytest.approx(0.2 * 4.8, abs=0.02)  # straight ahead
    assert odom.pose.pose.position.y == pytest.approx(0.0, abs=1e-6)
    assert odom.twist.twist.linear.x == pytest.approx(0.2)
    _, x, y = observer.poses[-1]
    assert (x, y) == (pytest.approx(1.0, abs=1e-6), pytest.approx(2.0 + 0.96, abs=0.02))


async def test_odometry_and_scan_carry_floats_even_from_a_model_with_whole_number_limits(monkeypatch):
    # The node's odometry and scan publishers check no field (Publisher.trust): the node itself
    # makes floats of the twist, which a model's int limits would otherwise leave ints (the
    # clipped command), and of the scan's range limits.
    from world.drive import MODELS, RobotModel
    from world.lidar import LidarSpec

    whole = RobotModel(name="whole", max_linear=1, max_angular=2, lidar=LidarSpec(range_min=0, range_max=4))
    monkeypatch.setitem(MODELS, "whole", whole)
    async with Runtime() as rt:
        rt.spawn(World, params={"world": "empty"})
        rt.spawn(TurtleBot, params={"model": "whole"})
        observer = rt.spawn(Observer)
        rt.spawn(ConstantControl, params={"v": 5.0, "omega": 5.0})
        await anyio.sleep(1.02)
    twist = observer.odom[-1].twist.twist
    assert (twist.linear.x, twist.angular.z) == (1.0, 2.0)
    assert type(twist.linear.x) is float and type(twist.angular.z) is float
    scan = observer.scans[-1]
    assert (scan.range_min, scan.range_max) == (0.0, 4.0)
    assert type(scan.range_min) is float and type(scan.range_max) is float


async def test_odometry_and_ground_truth_turn_with_the_robot_message_by_message():
    class Headings(Node):
        def __init__(self) -> None:
            super().__init__("headings")
            self.odom: dict[tuple[int, int], object] = {}
            self.truth: dict[tuple[int, int], object] = {}
            self.create_subscription(Odometry, "odom", lambda m: self.keep(self.odom, m.header, m.pose.pose), 100)
            self.create_subscription(PoseStamped, "sim/pose", lambda m: self.keep(self.truth, m.header, m.pose), 100)

        def keep(self, into: dict, header: object, pose: object) -> None:
            into[(header.stamp.sec, header.stamp.nanosec)] = pose.orientation

    def yaw(q: object) -> float:
        assert (q.x, q.y) == (0.0, 0.0) and q.z**2 + q.w**2 == pytest.approx(1.0)
        return 2 * math.atan2(q.z, q.w)

    async with Runtime() as rt:
        rt.spawn(World, params={"world": "empty"})
        rt.spawn(TurtleBot, params={"theta": 0.3})
        rt.spawn(ConstantControl, params={"v": 0.0, "omega": 0.5})
        headings = rt.spawn(Headings)
        await anyio.sleep(3.0)
    assert headings.odom.keys() == headings.truth.keys() and len(headings.odom) >= 59
    odom = [yaw(headings.odom[stamp]) for stamp in sorted(headings.odom)]
    truth = [yaw(headings.truth[stamp]) for stamp in sorted(headings.truth)]
    assert odom == pytest.approx([t - 0.3 for t in truth])  # odometry's frame is the start pose
    assert truth[0] == pytest.approx(0.3) and 1.5 < truth[-1] < 0.3 + 0.5 * 3.0  # after its acceleration ramp
    # Each message kept its own heading: 0.5 rad/s for 50 ms, give or take the one physics step
    # that a tick and the World's step falling on the same instant may take in either order.
    turning = [b - a for a, b in pairwise(odom[20:])]
    assert all(step == pytest.approx(0.5 * 0.05, abs=0.5 * 0.01 + 1e-9) for step in turning)


async def test_scans_at_10_hz_odometry_at_20_hz_and_the_ground_truth_without_odometry_noise():
    def ms(header: object) -> int:
        return header.stamp.sec * 1000 + header.stamp.nanosec // 1_000_000

    async with Runtime() as rt:
        rt.spawn(World, params={"world": "empty"})
        rt.spawn(TurtleBot, params={"noise_position": 0.05, "seed": 3})  # starts at the world's origin
        observer = rt.spawn(Observer)
        await anyio.sleep(1.02)
    assert [ms(scan.header) for scan in observer.scans] == list(range(100, 1001, 100))
    assert [ms(odom.header) for odom in observer.odom] == list(range(50, 1001, 50))
    # The robot stands still at the origin: the truth says so, the odometry is off by its noise.
    assert {(x, y) for _, x, y in observer.poses} == {(0.0, 0.0)} and len(observer.poses) == 20
    assert all(odom.pose.pose.position.x != 0.0 for odom in observer.odom)


class LateScanReader(Node):
    """Subscribes to the scan only at t = 1 s."""

    def __init__(self) -> None:
        super().__init__("late_reader")
        self.scans: list[LaserScan] = []
        self.timer = self.create_timer(1.0, self.join)

    def join(self) -> None:
        self.timer.cancel()
        self.create_subscription(LaserScan, "scan", self.scans.append, 100)


def test_the_lidar_is_cast_only_for_a_reader_and_a_late_reader_gets_the_same_noisy_scans(monkeypatch):
    casts = []
    cast = Lidar.distances

    def counted(self: Lidar, *args: object, **kwargs: object) -> object:
        casts.append(self)
        return cast(self, *args, **kwargs)

    monkeypatch.setattr(Lidar, "distances", counted)

    async def scans_after_one_second(reader: type[Node]) -> list[list[float]]:
        async with Runtime() as rt:
            rt.spawn(World, params={"world": "signs"})
            rt.spawn(TurtleBot, params={"noise_ranges": 0.02, "seed": 5})
            rt.spawn(ConstantControl, params={"v": 0.2, "omega": 0.3})
            node = rt.spawn(reader)
            await anyio.sleep(2.05)
        return [list(scan.ranges) for scan in node.scans if scan.header.stamp.sec >= 1 and scan.header.stamp.nanosec]

    def run(reader: type[Node]) -> list[list[float]]:
        # Each on its own virtual clock from 0, as two processes would.
        casts.clear()
        return anyio.run(scans_after_one_second, reader, backend_options={"loop_factory": VirtualTimeLoop})

    from_start = run(Observer)
    assert len(casts) == 20
    late = run(LateScanReader)
    assert len(casts) <= 11  # from t = 1 s on only
    assert len(late) == len(from_start) == 9 and late == from_start
    assert len({tuple(ranges) for ranges in late}) == 9  # the robot moves and the noise is on


async def test_namespaced_robots_have_their_own_topics():
    async with Runtime() as rt:
        rt.spawn(World)
        rt.spawn(TurtleBot, name="turtlebot", namespace="robot1", params={"x": -1.0})
        rt.spawn(TurtleBot, name="turtlebot", namespace="robot2", params={"x": 1.0})
        names = {t.name for t in rt.graph.topics()}
    assert {"/robot1/cmd_vel", "/robot1/odom", "/robot2/scan", "/robot2/sim/pose"} <= names


async def test_a_turtlebot_without_a_world_is_a_clear_error():
    async with Runtime() as rt:
        with pytest.raises(WorldError, match=re.escape("/turtlebot needs a world: start a world.sim:World node")):
            rt.spawn(TurtleBot)


async def test_a_robot_that_does_not_fit_is_a_clear_error():
    async with Runtime() as rt:
        rt.spawn(World)
        with pytest.raises(WorldError, match=r"/turtlebot: .*outside"):
            rt.spawn(TurtleBot, params={"x": 50.0})


async def odometry_run() -> list[dict]:
    noise = {"noise_position": 0.01, "noise_heading": 0.01, "noise_linear": 0.02, "noise_angular": 0.02}
    async with Runtime() as rt:
        rt.spawn(World, params={"world": "signs"})
        rt.spawn(TurtleBot, params={"seed": 7, **noise})
        observer = rt.spawn(Observer)
        rt.spawn(ConstantControl, params={"v": 0.2, "omega": 0.3})
        await anyio.sleep(10.01)  # past the 200th tick at 10.0: stopping does not deliver what a tie leaves queued
    return [codec.to_builtins(m) for m in observer.odom]


def test_the_same_graph_and_seed_give_identical_odometry_with_noise():
    # Two runs, each on its own virtual clock starting at 0, as two `actors.run` processes would.
    first, second = (anyio.run(odometry_run, backend_options={"loop_factory": VirtualTimeLoop}) for _ in "12")
    assert len(first) == 200
    assert first == second
    assert first[10]["pose"]["pose"]["position"]["y"] != 0.0  # the noise is on


@pytest.mark.slow
def test_the_turtlebot_graph_draws_its_run(run_module, tmp_path):
    graph = tmp_path / "tb.toml"
    image = tmp_path / "run.png"
    text = (ROOT / "graphs" / "turtlebot.toml").read_text().replace('image = ""', f'image = "{image}"')
    graph.write_text(text)
    result = run_module("actors.run", str(graph), "--clock", "virtual", "--duration", "30")
    assert result.returncode == 0, result.stderr
    assert image.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.slow
def test_a_bad_world_file_exits_2_naming_file_and_key(run_module, tmp_path):
    world = tmp_path / "w.toml"
    world.write_text("[[boxes]]\ncenter = [0, 0]\nsize = [1, 2, 3]\n")
    graph = tmp_path / "g.toml"
    graph.write_text(f'[[nodes]]\nuse = "world.sim:World"\nparams = {{ world = "{world}" }}\n')
    result = run_module("actors.run", str(graph), "--clock", "virtual", "--duration", "1")
    assert result.returncode == 2
    assert result.stderr.strip().endswith(f"{world}: boxes[0].size: expected an array of 2 items, got 3")


class BadCommands(Node):
    """Sends the commands it is given on /cmd_vel."""

    def __init__(self) -> None:
        super().__init__("bad_commands")
        self.pub = self.create_publisher(Twist, "/cmd_vel", 100)

    def send(self, *pairs: tuple[float, float]) -> None:
        for v, w in pairs:
            msg = Twist()
            msg.linear.x, msg.angular.z = v, w
            self.pub.publish(msg)


async def test_commands_that_are_not_finite_numbers_are_refused_and_the_robot_keeps_the_last_good_one(caplog):
    async with Runtime() as rt:
        rt.spawn(World, params={"world": "empty"})
        rt.spawn(TurtleBot)
        observer = rt.spawn(Observer)
        bad = rt.spawn(BadCommands)
        bad.send((0.1, 0.0))
        await anyio.sleep(1)
        nan, inf = math.nan, math.inf
        for _ in range(250):  # 1,000 bad commands: the supervisor's intensity is 3 in 5 s
            bad.send((nan, 0.0), (0.0, inf), (-inf, nan), (1e308 * 10, 0.0))
            await anyio.sleep(0.01)  # within the subscription's depth of 10
        await anyio.sleep(1)
        robot = rt.node("turtlebot")
        assert robot.robot.commanded == (0.1, 0.0)
        (info,) = [n for n in rt.graph.nodes() if n.name == "/turtlebot"]
        assert (info.crashes, info.state) == (0, "running")
        (sub,) = rt.graph.topic("/cmd_vel").subscriptions[:1]
        assert sub.refused == {"linear.x and angular.z must be finite": 1000}
    assert observer.odom[-1].twist.twist.linear.x == pytest.approx(0.1)
    refusals = [r.getMessage() for r in caplog.records if "refused" in r.getMessage()]
    assert refusals == [
        "refused a message on /cmd_vel from /bad_commands: linear.x and angular.z must be finite (dropped; 1 so far)",
    ]


async def test_world_and_robot_parameters_are_read_only_and_the_step_is_checked():
    from actors.errors import InvalidParameterValueException

    async with Runtime() as rt:
        world = rt.spawn(World, params={"world": "empty"})
        robot = rt.spawn(TurtleBot)
        for node, name, value in ((world, "dt", 0.0), (world, "world", "signs"), (robot, "x", math.nan)):
            (result,) = node.set_parameters([Parameter(name, value=value)])
            assert not result.successful and "read-only" in result.reason
    for dt in (0.0, -0.01, 0.5):
        async with Runtime() as rt:
            with pytest.raises(InvalidParameterValueException, match=f"parameter 'dt' of /world: {dt} is out of range"):
                rt.spawn(World, params={"dt": dt})


async def test_the_world_says_when_a_robot_touches_something_and_when_it_is_free(caplog):
    caplog.set_level("INFO")
    async with Runtime() as rt:
        rt.spawn(World, params={"world": "signs"})
        rt.spawn(TurtleBot)
        control = rt.spawn(ConstantControl, params={"v": 0.2})
        await anyio.sleep(10)
        control.set_parameters([Parameter("v", value=-0.2)])
        await anyio.sleep(2)
    lines = [r.getMessage() for r in caplog.records if r.name == "actors.node.world"]
    assert lines == ["/turtlebot touches obstacle box_east at (1.26, 0.00)", "/turtlebot is free again"]


@pytest.mark.parametrize("path", ["graphs/turtlebot.toml", "graph.toml"])
@pytest.mark.slow
async def test_the_demo_robot_drives_a_minute_without_touching_anything_until_killed_then_stops(path):
    """The demo graphs as configured: /kill at any time in the first minute is visibly what stops it."""
    from actors.launch.graph_file import load_graph

    graph, classes = load_graph(ROOT / path)
    # The shipped graph's classes are actors.world's (see actors.launch.importing), graph.toml's the repository's.
    robot_part = [
        (e, c) for e, c in zip(graph.nodes, classes) if c.__name__ in ("World", "TurtleBot", "ConstantControl")
    ]
    assert len(robot_part) == 3
    async with Runtime() as rt:
        for entry, cls in robot_part:
            rt.spawn(cls, name=entry.name, params=entry.params)
        observer = rt.spawn(Observer)
        killer = rt.spawn(Killer)
        killer.timer.cancel()
        killer.timer = killer.create_timer(58.0, killer.kill)
        await anyio.sleep(70)
    assert True not in observer.contact
    moving = [o.twist.twist for o in observer.odom if o.header.stamp.sec < 58]
    assert all(t.linear.x == pytest.approx(0.2) for t in moving[10:])
    still = [o for o in observer.odom if o.header.stamp.sec >= 59]
    assert still and all((o.twist.twist.linear.x, o.twist.twist.angular.z) == (0.0, 0.0) for o in still)
    assert len({(o.pose.pose.position.x, o.pose.pose.position.y) for o in still}) == 1
