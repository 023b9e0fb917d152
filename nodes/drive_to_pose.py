"""A robot action: drive the TurtleBot to a pose given as a goal, reporting the distance left.

Serves ``drive_to_pose`` (tutorial_interfaces/action/DriveToPose) with the
robot's own topics: it reads ``odom`` and commands ``cmd_vel`` (relative
names, so a namespace selects the robot).  The target is in the odometry frame,
which starts where the robot started.  A goal turns towards the target,
drives there while steering, then turns to the target heading; feedback
(current pose, distance left) goes out five times a second.  A cancel, a newer
goal or ``max_duration`` seconds without arriving stop the robot; the result
is where it stopped.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from actors import CancelResponse, Node, ServerGoalHandle
from interfaces.geometry_msgs.msg import Pose2D, Twist
from interfaces.nav_msgs.msg import Odometry
from interfaces.tutorial_interfaces.action import DriveToPose

__all__ = ["DriveToPoseServer", "steer"]

CONTROL_PERIOD = 0.05  # the odometry's rate
FEEDBACK_EVERY = 4  # control ticks per feedback message: 5 Hz


def _wrap(angle: float) -> float:
    """``angle`` in [-pi, pi)."""
    return (angle + math.pi) % (2 * math.pi) - math.pi


def steer(pose: Pose2D, target: Pose2D, tolerance: float, max_v: float, max_w: float) -> tuple[float, float] | None:
    """The (linear, angular) command that brings ``pose`` to ``target``; None once it is there.

    Far from the target: turn on the spot while the heading is off by more than
    0.3 rad, else drive with speed proportional to the distance and steer.
    Within ``tolerance``: turn to the target's heading (0.02 rad).
    """
    dx, dy = target.x - pose.x, target.y - pose.y
    distance = math.hypot(dx, dy)
    if distance > tolerance:
        error = _wrap(math.atan2(dy, dx) - pose.theta)
        linear = 0.0 if abs(error) > 0.3 else min(max_v, 0.8 * distance)
        return linear, max(-max_w, min(max_w, 2.0 * error))
    error = _wrap(target.theta - pose.theta)
    if abs(error) <= 0.02:
        return None
    return 0.0, max(-max_w, min(max_w, 2.0 * error))


class DriveToPoseServer(Node):
    """Node ``drive_to_pose``: one goal at a time (a new goal preempts the one running).

    Parameters: ``tolerance`` (m, 0.02), ``max_linear`` (m/s, 0.2), ``max_angular``
    (rad/s, 1.5), ``max_duration`` (s, 120: longer aborts the goal).
    """

    def __init__(self) -> None:
        super().__init__("drive_to_pose")
        self.tolerance = self.declare_parameter("tolerance", 0.02).value
        self.max_v = self.declare_parameter("max_linear", 0.2).value
        self.max_w = self.declare_parameter("max_angular", 1.5).value
        self.max_duration = self.declare_parameter("max_duration", 120.0).value
        self.pose: Pose2D | None = None
        self.current: ServerGoalHandle | None = None
        self.cmd_vel = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_subscription(Odometry, "odom", self.on_odom, 10)
        self.create_action_server(
            DriveToPose, "drive_to_pose", self.execute, cancel=lambda goal_handle: CancelResponse.ACCEPT
        )

    def on_odom(self, msg: Odometry) -> None:
        q = msg.pose.pose.orientation
        position = msg.pose.pose.position
        self.pose = Pose2D(x=position.x, y=position.y, theta=2.0 * math.atan2(q.z, q.w))

    async def execute(self, goal_handle: ServerGoalHandle) -> DriveToPose.Result:
        goal: DriveToPose.Goal = goal_handle.request
        tolerance = goal.tolerance or self.tolerance
        self.current = goal_handle  # a goal still running sees this and gives way
        self.get_logger().info(f"Driving to x={goal.target.x:.2f} y={goal.target.y:.2f} theta={goal.target.theta:.2f}")
        rate = self.create_rate(1.0 / CONTROL_PERIOD)
        deadline = self.get_clock().monotonic() + self.max_duration
        tick = 0
        while True:
            pose = self.pose
            if goal_handle.is_cancel_requested:
                return self.stop(goal_handle, goal_handle.canceled, "canceled")
            if self.current is not goal_handle:
                return self.stop(goal_handle, goal_handle.abort, "preempted by a newer goal")
            if self.get_clock().monotonic() > deadline:
                return self.stop(goal_handle, goal_handle.abort, f"not there after {self.max_duration:g} s")
            if pose is not None:
                command = steer(pose, goal.target, tolerance, self.max_v, self.max_w)
                if command is None:
                    return self.stop(goal_handle, goal_handle.succeed, "arrived")
                twist = Twist()
                twist.linear.x, twist.angular.z = command
                self.cmd_vel.publish(twist)
                if tick % FEEDBACK_EVERY == 0:
                    left = math.hypot(goal.target.x - pose.x, goal.target.y - pose.y)
                    goal_handle.publish_feedback(DriveToPose.Feedback(current_pose=pose, distance_remaining=left))
                tick += 1
            await rate.sleep()

    def stop(self, goal_handle: ServerGoalHandle, end: Callable[[], None], why: str) -> DriveToPose.Result:
        """Stop the robot, end the goal with ``end`` (succeed, abort or canceled), return where it is."""
        if self.current is goal_handle:
            self.cmd_vel.publish(Twist())
            self.current = None
        end()
        pose = self.pose or Pose2D()
        target = goal_handle.request.target
        left = math.hypot(target.x - pose.x, target.y - pose.y)
        self.get_logger().info(f"Goal {why}: at x={pose.x:.3f} y={pose.y:.3f}, {left:.3f} m from the target")
        return DriveToPose.Result(final_pose=pose, distance_remaining=left)
