"""The drive-to-pose action on the simulated TurtleBot, on virtual time: arrive within 5 cm, cancel stops."""

from __future__ import annotations

import math

import anyio
import pytest

from actors import Node, Runtime
from interfaces.action_msgs.msg import GoalStatus
from interfaces.geometry_msgs.msg import Pose2D, PoseStamped, Twist
from interfaces.tutorial_interfaces.action import DriveToPose
from nodes.drive_to_pose import DriveToPoseServer, steer
from world.robot import TurtleBot
from world.sim import World

pytestmark = pytest.mark.virtual_time


class Commander(Node):
    """Sends drive_to_pose goals; records ground truth (sim/pose) and cmd_vel with their times."""

    def __init__(self) -> None:
        super().__init__("commander")
        self.client = self.create_action_client(DriveToPose, "drive_to_pose")
        self.truth: list[tuple[float, float, float, float]] = []  # (t, x, y, yaw)
        self.commands: list[tuple[float, Twist]] = []
        now = self.get_clock().monotonic
        self.create_subscription(PoseStamped, "sim/pose", self.on_pose, 100)
        self.create_subscription(Twist, "cmd_vel", lambda m: self.commands.append((now(), m)), 100)

    def on_pose(self, msg: PoseStamped) -> None:
        q = msg.pose.orientation
        yaw = 2.0 * math.atan2(q.z, q.w)
        self.truth.append((self.get_clock().monotonic(), msg.pose.position.x, msg.pose.position.y, yaw))


async def robot(rt: Runtime, **start: float) -> Commander:
    rt.spawn(World, params={"world": "empty"})
    rt.spawn(TurtleBot, params=start)
    rt.spawn(DriveToPoseServer)
    commander = rt.spawn(Commander)
    assert await commander.client.wait_for_server(timeout=1.0)
    return commander


def goal(x: float, y: float, theta: float = 0.0) -> DriveToPose.Goal:
    return DriveToPose.Goal(target=Pose2D(x=x, y=y, theta=theta))


@pytest.mark.parametrize(("x", "y", "theta"), [(1.0, 0.5, math.pi / 2), (-1.5, -1.0, 0.0), (0.0, 2.0, -3.0)])
async def test_the_robot_arrives_within_5_cm_of_the_goal(x, y, theta):
    async with Runtime() as rt:
        commander = await robot(rt)
        distances: list[float] = []
        handle = await commander.client.send_goal(
            goal(x, y, theta), feedback=lambda f: distances.append(f.distance_remaining)
        )
        response = await handle.get_result(timeout=120.0)
        assert response.status == GoalStatus.STATUS_SUCCEEDED
        await anyio.sleep(0.5)  # let the last ground-truth pose arrive
        _, true_x, true_y, yaw = commander.truth[-1]
        assert math.hypot(true_x - x, true_y - y) < 0.05  # ground truth, not the robot's own belief
        assert abs(math.remainder(yaw - theta, 2 * math.pi)) < 0.05
        final = response.result.final_pose
        assert math.hypot(final.x - true_x, final.y - true_y) < 0.01 and response.result.distance_remaining < 0.05
        # Feedback told the distance going down, from the start to the end.
        assert distances[0] == pytest.approx(math.hypot(x, y), abs=0.01)
        assert distances[-1] < 0.1 and len(distances) > 5
        assert commander.commands[-1][1] == Twist()  # it left the robot stopped


async def test_a_goal_in_the_odometry_frame_of_a_robot_started_elsewhere():
    async with Runtime() as rt:
        commander = await robot(rt, x=1.0, y=1.0, theta=math.pi / 2)
        handle = await commander.client.send_goal(goal(1.0, 0.0))  # 1 m ahead of where it started
        assert (await handle.get_result(timeout=60.0)).status == GoalStatus.STATUS_SUCCEEDED
        await anyio.sleep(0.5)
        _, true_x, true_y, _ = commander.truth[-1]
        assert math.hypot(true_x - 1.0, true_y - 2.0) < 0.05


async def test_cancel_stops_the_robot():
    async with Runtime() as rt:
        commander = await robot(rt)
        handle = await commander.client.send_goal(goal(4.0, 0.0))
        await anyio.sleep(5.0)
        cancel = await handle.cancel()
        assert len(cancel.goals_canceling) == 1
        response = await handle.get_result(timeout=1.0)
        assert response.status == GoalStatus.STATUS_CANCELED
        stopped_at = rt.clock.monotonic()
        assert 0.5 < response.result.final_pose.x < 1.2 and response.result.distance_remaining > 2.8
        await anyio.sleep(3.0)
        after = [(x, y) for t, x, y, _ in commander.truth if t > stopped_at + 0.2]
        assert len(after) > 40 and max(x for x, _ in after) - min(x for x, _ in after) < 1e-6
        assert commander.commands[-1][1] == Twist()


async def test_a_new_goal_preempts_the_running_one():
    async with Runtime() as rt:
        commander = await robot(rt)
        first = await commander.client.send_goal(goal(3.0, 0.0))
        await anyio.sleep(2.0)
        second = await commander.client.send_goal(goal(0.0, 0.0))
        assert (await first.get_result()).status == GoalStatus.STATUS_ABORTED
        assert (await second.get_result(timeout=60.0)).status == GoalStatus.STATUS_SUCCEEDED
        _, x, y, _ = commander.truth[-1]
        assert math.hypot(x, y) < 0.05


async def test_a_goal_it_cannot_reach_in_time_is_aborted():
    async with Runtime() as rt:
        rt.spawn(World, params={"world": "empty"})
        rt.spawn(TurtleBot)
        rt.spawn(DriveToPoseServer, params={"max_duration": 3.0})
        commander = rt.spawn(Commander)
        handle = await commander.client.send_goal(goal(4.0, 0.0))
        response = await handle.get_result(timeout=10.0)
        assert response.status == GoalStatus.STATUS_ABORTED
        assert rt.clock.monotonic() == pytest.approx(3.05, abs=0.06)


def test_steer_turns_first_then_drives_then_turns_to_the_heading():
    here = Pose2D()
    assert steer(here, Pose2D(x=0.0, y=1.0), 0.02, 0.2, 1.5) == (0.0, 1.5)  # 90 degrees off: turn on the spot
    linear, angular = steer(here, Pose2D(x=1.0, y=0.1), 0.02, 0.2, 1.5)
    assert linear == 0.2 and 0 < angular < 0.3  # nearly ahead: drive and steer
    assert steer(here, Pose2D(x=0.01, theta=1.0), 0.02, 0.2, 1.5) == (0.0, 1.5)  # there: turn to theta
    assert steer(here, Pose2D(x=0.01, theta=0.01), 0.02, 0.2, 1.5) is None
