"""``rclpy.time_source``: ROS clocks that follow ``/clock`` while a node's ``use_sim_time`` is true.

A TimeSource watches one node's ``use_sim_time`` parameter.  While it is true,
the source subscribes the node to ``/clock`` (rosgraph_msgs/Clock) and sets
every clock attached to it to the time each message carries (a jump, for their
jump callbacks); while it is false, those clocks read the runtime's time.
Every script node has one driving its own clock, as in rclpy.
"""

from __future__ import annotations

import weakref
from typing import Any

from actors.compat.rclpy.clock import ROSClock
from actors.ros.node import Node as NativeNode
from actors.ros.parameter import Parameter
from actors.ros.qos import QoSProfile, ReliabilityPolicy
from actors.ros.time import ClockType, Time
from interfaces.rcl_interfaces.msg import SetParametersResult
from interfaces.rosgraph_msgs.msg import Clock as ClockMsg

# The node is rclpy's (actors.compat.rclpy.node.Node), which imports this module: here it is
# only a native node with rclpy's create_subscription, so annotations say _Node = Any.
_Node = Any

__all__ = ["CLOCK_TOPIC", "USE_SIM_TIME_NAME", "TimeSource"]

CLOCK_TOPIC = "/clock"
USE_SIM_TIME_NAME = "use_sim_time"


class TimeSource:
    """Drives attached ROS clocks from ``/clock`` while its node's ``use_sim_time`` is true."""

    def __init__(self, *, node: _Node | None = None) -> None:
        self._clock_sub: Any = None
        self._node_ref: weakref.ReferenceType[_Node] | None = None
        self._clocks: weakref.WeakSet[ROSClock] = weakref.WeakSet()
        self._last_time_set = Time(clock_type=ClockType.ROS_TIME)  # zero: no /clock message yet
        self._ros_time_is_active = False
        if node is not None:
            self.attach_node(node)

    @property
    def ros_time_is_active(self) -> bool:
        """Whether the attached clocks follow ``/clock``; setting it switches them and the subscription."""
        return self._ros_time_is_active

    @ros_time_is_active.setter
    def ros_time_is_active(self, enabled: bool) -> None:
        if self._ros_time_is_active == enabled:
            return
        self._ros_time_is_active = enabled
        for clock in list(self._clocks):
            clock._set_ros_time_is_active(enabled)
        node = self._get_node()
        if enabled:
            if self._clock_sub is None and node is not None:
                qos = QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT)
                self._clock_sub = node.create_subscription(ClockMsg, CLOCK_TOPIC, self.clock_callback, qos)
        elif self._clock_sub is not None and node is not None:
            node.destroy_subscription(self._clock_sub)
            self._clock_sub = None

    def attach_node(self, node: _Node) -> None:
        """Follow ``node``'s ``use_sim_time`` (declared here if it is not); TypeError for a non-node."""
        if not isinstance(node, NativeNode):
            raise TypeError("Node must be of type rclpy.node.Node")
        if self._node_ref is not None:
            self.detach_node()
        self._node_ref = weakref.ref(node)
        if not node.has_parameter(USE_SIM_TIME_NAME):
            node.declare_parameter(USE_SIM_TIME_NAME, False)
        param = node.get_parameter(USE_SIM_TIME_NAME)
        if param.type_ == Parameter.Type.BOOL:
            self.ros_time_is_active = param.value
        elif param.type_ != Parameter.Type.NOT_SET:
            node.get_logger().error(f"Invalid type for parameter '{USE_SIM_TIME_NAME}' {param.type_!r} should be bool")
        node.add_on_set_parameters_callback(self._on_parameters)

    def detach_node(self) -> None:
        """Stop following the node (and drop its ``/clock`` subscription)."""
        if self._clock_sub is not None:
            node = self._get_node()
            if node is None:
                raise RuntimeError("Unable to destroy previously created clock subscription")
            node.destroy_subscription(self._clock_sub)
        self._clock_sub = None
        self._node_ref = None

    def attach_clock(self, clock: ROSClock) -> None:
        """Drive ``clock`` too; ValueError for a clock that is not a ROS clock."""
        if not isinstance(clock, ROSClock):
            raise ValueError("Only clocks with type ROS_TIME can be attached.")
        clock.set_ros_time_override(self._last_time_set)
        clock._set_ros_time_is_active(self.ros_time_is_active)
        self._clocks.add(clock)

    def clock_callback(self, msg: ClockMsg) -> None:
        """Set every attached clock to the time ``msg`` carries (kept for clocks attached later)."""
        self._last_time_set = Time.from_msg(msg.clock)
        for clock in list(self._clocks):
            clock.set_ros_time_override(self._last_time_set)

    def _on_parameters(self, parameters: list[Parameter]) -> SetParametersResult:
        for param in parameters:
            if param.name != USE_SIM_TIME_NAME:
                continue
            if param.type_ != Parameter.Type.BOOL:
                reason = f"{USE_SIM_TIME_NAME} parameter set to something besides a bool"
                node = self._get_node()
                if node is not None:
                    node.get_logger().error(reason)
                return SetParametersResult(successful=False, reason=reason)
            self.ros_time_is_active = param.value
            break
        return SetParametersResult(successful=True, reason="")

    def _get_node(self) -> _Node | None:
        return self._node_ref() if self._node_ref is not None else None
