"""turtlesim's draw_square: resets the sim, then drives turtle1 round a 2 m square, as ROS 2's does.

Node ``draw_square`` calls ``reset``, then every 16 ms steps a four-state
machine on the latest ``turtle1/pose``: drive ahead at 1 m/s until within
0.1 m and 0.01 rad of the goal 2 m ahead, command a stop until the turtle
reports no motion, turn at 0.4 rad/s to a quarter turn on, stop again, and
so on.  Each new goal is logged as ``New goal [x y, theta]``.
"""

from __future__ import annotations

import math
from enum import Enum

from actors import Node
from interfaces.geometry_msgs.msg import Twist
from interfaces.std_srvs.srv import Empty
from interfaces.turtlesim_msgs.msg import Pose

__all__ = ["DrawSquare"]

# The real program's own constant, not math.pi: its quarter turns wrap by this value.
PI = 3.141592
SIDE = 2.0
FORWARD_SPEED = 1.0
TURN_SPEED = 0.4


class State(Enum):
    FORWARD = "forward"
    STOP_FORWARD = "stop forward"
    TURN = "turn"
    STOP_TURN = "stop turn"


class DrawSquare(Node):
    """Node ``draw_square``: squares with turtle1 after a reset."""

    def __init__(self) -> None:
        super().__init__("draw_square")
        self.twist_pub = self.create_publisher(Twist, "turtle1/cmd_vel", 1)
        self.create_subscription(Pose, "turtle1/pose", self.on_pose, 1)
        self.reset_client = self.create_client(Empty, "reset")
        self.pose: Pose | None = None
        self.goal: Pose | None = None
        self.state = State.FORWARD
        self.was_reset = False
        self.create_timer(0.016, self.on_timer)

    def on_start(self) -> None:
        self._core.start_task(self._reset, name="reset of draw_square")

    async def _reset(self) -> None:
        await self.reset_client.call(Empty.Request())
        # Poses sent before the reset describe the turtle it replaced.
        self.pose, self.was_reset = None, True

    def on_pose(self, pose: Pose) -> None:
        self.pose = pose

    def on_timer(self) -> None:
        pose = self.pose
        if not self.was_reset or pose is None:
            return
        if self.goal is None:
            self._goal_ahead(pose)
        goal = self.goal
        assert goal is not None
        if self.state in (State.FORWARD, State.TURN):
            if _reached(pose, goal):
                self.state = State.STOP_FORWARD if self.state is State.FORWARD else State.STOP_TURN
                self._command(0.0, 0.0)
            elif self.state is State.FORWARD:
                self._command(FORWARD_SPEED, 0.0)
            else:
                self._command(0.0, TURN_SPEED)
        elif pose.angular_velocity >= 0.0001 or pose.linear_velocity >= 0.0001:
            self._command(0.0, 0.0)
        else:
            self.get_logger().info("Reached goal")
            if self.state is State.STOP_FORWARD:
                self._goal_turned(pose)
            else:
                self._goal_ahead(pose)

    def _goal_ahead(self, pose: Pose) -> None:
        self.state = State.FORWARD
        x = math.cos(pose.theta) * SIDE + pose.x
        y = math.sin(pose.theta) * SIDE + pose.y
        self._set_goal(Pose(x=x, y=y, theta=pose.theta))

    def _goal_turned(self, pose: Pose) -> None:
        self.state = State.TURN
        theta = math.fmod(pose.theta + PI / 2.0, 2 * PI)
        if theta >= PI:  # the pose's heading range, so the goal compares with it directly
            theta -= 2 * PI
        self._set_goal(Pose(x=pose.x, y=pose.y, theta=theta))

    def _set_goal(self, goal: Pose) -> None:
        self.goal = goal
        self.get_logger().info(f"New goal [{goal.x:f} {goal.y:f}, {goal.theta:f}]")

    def _command(self, linear: float, angular: float) -> None:
        twist = Twist()
        twist.linear.x, twist.angular.z = linear, angular
        self.twist_pub.publish(twist)


def _reached(pose: Pose, goal: Pose) -> bool:
    return abs(pose.x - goal.x) < 0.1 and abs(pose.y - goal.y) < 0.1 and abs(pose.theta - goal.theta) < 0.01
