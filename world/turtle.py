"""One turtle of turtlesim: its topics, services and action on the turtlesim node, and its update rule.

A turtle named ``turtle1`` lives in the window's coordinates (metres, y down,
as the real one's Qt frame) and shows the world's (y up) on its topics:

- subscribes ``turtle1/cmd_vel`` (geometry_msgs/Twist): linear.x and angular.z
  (and linear.y when the node's ``holonomic`` parameter is true) until the next
  command, or until one second passes without one;
- publishes ``turtle1/pose`` (turtlesim/Pose) and ``turtle1/color_sensor``
  (turtlesim/Color, the path image's pixel under the turtle) at every update;
- serves ``turtle1/set_pen``, ``turtle1/teleport_absolute`` and
  ``turtle1/teleport_relative`` (teleports happen at the next update, in order,
  drawing a line when the pen is down);
- serves the action ``turtle1/rotate_absolute``: every goal is accepted; the
  turtle turns at 1 rad/s towards the goal's heading with feedback at each
  update, succeeds within 0.02 rad, is canceled on request, and is aborted by a
  new goal ("preempted") or by a velocity command.

The update rule, its order and its float32 roundings are those of ROS 2's
turtlesim (turtle.cpp); :func:`normalize_angle` keeps headings in [-π, π).
"""

from __future__ import annotations

import asyncio
import math
from typing import TYPE_CHECKING, Any

import numpy as np

from actors import CancelResponse, QoSProfile, ServerGoalHandle
from actors.errors import MessageRefused
from interfaces.geometry_msgs.msg import Twist
from interfaces.turtlesim_msgs.action import RotateAbsolute
from interfaces.turtlesim_msgs.msg import Color, Pose
from interfaces.turtlesim_msgs.srv import SetPen, TeleportAbsolute, TeleportRelative

if TYPE_CHECKING:
    from .canvas import Canvas
    from .turtlesim import Turtlesim

__all__ = ["COMMAND_TIMEOUT_NS", "DEFAULT_PEN", "ROTATION_TOLERANCE", "TOPIC_QOS", "Turtle", "f32", "normalize_angle"]

COMMAND_TIMEOUT_NS = 1_000_000_000  # a turtle stops when its last command is older than this
DEFAULT_PEN = (0xB3, 0xB8, 0xFF)
ROTATION_TOLERANCE = 0.02  # rad: rotate_absolute succeeds this close to its goal
TOPIC_QOS = QoSProfile(depth=7)


def normalize_angle(angle: float) -> float:
    """``angle`` wrapped into [-π, π), the way turtlesim wraps its heading."""
    return angle - 2 * math.pi * math.floor((angle + math.pi) / (2 * math.pi))


def f32(value: float) -> float:
    """``value`` rounded to the nearest float32, as a C++ ``static_cast<float>`` does."""
    return float(np.float32(value))


class Turtle:
    """One turtle: state, entities on ``node``, and :meth:`update`, called once per frame."""

    def __init__(self, node: Turtlesim, name: str, x: float, y: float, theta: float) -> None:
        self.node, self.name = node, name
        self.x, self.y, self.theta = x, y, theta  # window metres, y down
        self.lin_x = self.lin_y = self.ang = 0.0
        self.pen_on, self.pen, self.pen_width = True, DEFAULT_PEN, 3
        self.last_command_ns = node.get_clock().now().nanoseconds
        self.teleports: list[tuple[bool, float, float, float]] = []  # (relative, x or linear, y, theta)
        self.goal: ServerGoalHandle | None = None
        self.goal_start = 0.0
        self.delta = 0.0
        self._ends: dict[ServerGoalHandle, asyncio.Future[Any]] = {}
        self.pose_pub = node.create_publisher(Pose, f"{name}/pose", TOPIC_QOS)
        self.color_pub = node.create_publisher(Color, f"{name}/color_sensor", TOPIC_QOS)
        self.velocity_sub = node.create_subscription(Twist, f"{name}/cmd_vel", self.on_velocity, TOPIC_QOS)
        self.services = [
            node.create_service(SetPen, f"{name}/set_pen", self.on_set_pen),
            node.create_service(TeleportRelative, f"{name}/teleport_relative", self.on_teleport_relative),
            node.create_service(TeleportAbsolute, f"{name}/teleport_absolute", self.on_teleport_absolute),
        ]
        self.action = node.create_action_server(
            RotateAbsolute,
            f"{name}/rotate_absolute",
            self._rotation,
            cancel=lambda handle: CancelResponse.ACCEPT,
            accepted=self.on_goal_accepted,
        )

    def destroy(self) -> None:
        """Remove the turtle's entities (``/kill``, ``/reset``): its active goal is aborted."""
        node = self.node
        node.destroy_publisher(self.pose_pub)
        node.destroy_publisher(self.color_pub)
        node.destroy_subscription(self.velocity_sub)
        for service in self.services:
            node.destroy_service(service)
        self.action.destroy()
        for future in self._ends.values():
            if not future.done():
                future.set_result(RotateAbsolute.Result(delta=self.delta))

    # -- callbacks ----------------------------------------------------------------

    def on_velocity(self, twist: Twist) -> None:
        _finite("cmd_vel", twist.linear.x, twist.linear.y, twist.angular.z, refuse=MessageRefused)
        self.last_command_ns = self.node.get_clock().now().nanoseconds
        self.lin_x = twist.linear.x
        if self.node.get_parameter("holonomic").value:
            self.lin_y = twist.linear.y
        self.ang = twist.angular.z
        if self.goal is not None:
            self.node.get_logger().warning("Velocity command received during rotation goal. Aborting goal")
            self._end_goal("abort")

    def on_set_pen(self, request: SetPen.Request, response: SetPen.Response) -> SetPen.Response:
        self.pen_on = not request.off
        if not request.off:
            self.pen = (request.r, request.g, request.b)
            self.pen_width = request.width or 1  # a new QPen without a width is one pixel wide
        return response

    def on_teleport_relative(
        self, request: TeleportRelative.Request, response: TeleportRelative.Response
    ) -> TeleportRelative.Response:
        _finite("teleport_relative", request.linear, request.angular)
        self.teleports.append((True, request.linear, 0.0, request.angular))
        return response

    def on_teleport_absolute(
        self, request: TeleportAbsolute.Request, response: TeleportAbsolute.Response
    ) -> TeleportAbsolute.Response:
        _finite("teleport_absolute", request.x, request.y, request.theta)
        self.teleports.append((False, request.x, request.y, request.theta))
        return response

    def on_goal_accepted(self, handle: ServerGoalHandle) -> None:
        if self.goal is not None:
            self.node.get_logger().warning(
                "Rotation goal received before a previous goal finished. Aborting previous goal"
            )
            self._end_goal("abort")
        self._ends[handle] = asyncio.get_running_loop().create_future()
        handle.execute()
        self.goal, self.goal_start, self.delta = handle, self.theta, 0.0

    def _rotation(self, handle: ServerGoalHandle) -> asyncio.Future[Any]:
        # The goal runs in update(); its execute callback only waits for the result update() gives.
        return self._ends[handle]

    def _end_goal(self, how: str) -> None:
        handle = self.goal
        assert handle is not None
        self.goal = None
        getattr(handle, how)()
        self._ends.pop(handle).set_result(RotateAbsolute.Result(delta=self.delta))

    # -- the frame's update ---------------------------------------------------------

    def update(self, dt: float, canvas: Canvas, width: float, height: float) -> None:
        """One frame: teleports, the rotation goal, the command timeout, motion, walls, then publish and draw."""
        for relative, a, b, theta in self.teleports:
            old_x, old_y = self.x, self.y
            if relative:
                self.theta += theta
                self.x += math.cos(self.theta) * a
                self.y -= math.sin(self.theta) * a
            else:
                self.x, self.y, self.theta = a, max(0.0, height - b), theta
            if self.pen_on:
                canvas.line(self.x, self.y, old_x, old_y, self.pen, self.pen_width)
        self.teleports.clear()

        now_ns = self.node.get_clock().now().nanoseconds
        if self.goal is not None:
            self._pursue_goal(now_ns)
        if now_ns - self.last_command_ns > COMMAND_TIMEOUT_NS:
            self.lin_x = self.lin_y = self.ang = 0.0

        old_x, old_y = self.x, self.y
        self.theta = normalize_angle(self.theta + self.ang * dt)
        cos, sin = math.cos(self.theta), math.sin(self.theta)
        self.x += cos * self.lin_x * dt - sin * self.lin_y * dt
        self.y -= cos * self.lin_y * dt + sin * self.lin_x * dt
        if self.x < 0 or self.x > width or self.y < 0 or self.y > height:
            self.node.get_logger().warning(f"Oh no! I hit the wall! (Clamping from [x={self.x:f}, y={self.y:f}])")
        self.x = min(max(self.x, 0.0), width)
        self.y = min(max(self.y, 0.0), height)

        self.pose_pub.publish(
            Pose(
                x=f32(self.x),
                y=f32(height - self.y),
                theta=f32(self.theta),
                linear_velocity=f32(math.sqrt(self.lin_x * self.lin_x + self.lin_y * self.lin_y)),
                angular_velocity=f32(self.ang),
            )
        )
        r, g, b = canvas.pixel(self.x, self.y)
        self.color_pub.publish(Color(r=r, g=g, b=b))
        if (self.x, self.y) != (old_x, old_y) and self.pen_on:
            canvas.line(self.x, self.y, old_x, old_y, self.pen, self.pen_width)

    def _pursue_goal(self, now_ns: int) -> None:
        handle = self.goal
        assert handle is not None
        log = self.node.get_logger()
        if handle.is_cancel_requested:
            log.info("Rotation goal canceled")
            self._end_goal("canceled")
            self.lin_x = self.lin_y = self.ang = 0.0
            return
        target = normalize_angle(handle.request.theta)
        remaining = normalize_angle(target - f32(self.theta))
        self.delta = normalize_angle(f32(self.goal_start - self.theta))
        handle.publish_feedback(RotateAbsolute.Feedback(remaining=f32(remaining)))
        if abs(normalize_angle(f32(self.theta) - target)) < ROTATION_TOLERANCE:
            log.info("Rotation goal completed successfully")
            self._end_goal("succeed")
            self.lin_x = self.lin_y = self.ang = 0.0
        else:
            self.lin_x = self.lin_y = 0.0
            self.ang = -1.0 if remaining < 0.0 else 1.0
            self.last_command_ns = now_ns


def _finite(what: str, *values: float, refuse: type[Exception] = ValueError) -> None:
    # The real turtle would carry a NaN into its pose forever; here a peer's NaN or infinity is refused.
    if not all(math.isfinite(v) for v in values):
        raise refuse(f"{what}: {', '.join(repr(v) for v in values)} is not finite; refused")
