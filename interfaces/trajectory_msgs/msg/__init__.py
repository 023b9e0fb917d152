"""Generated from trajectory_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from array import array
from collections.abc import MutableSequence
from typing import ClassVar

import msgspec

from actors.messages.arrays import held
from interfaces.builtin_interfaces.msg import Duration
from interfaces.geometry_msgs.msg import Transform, Twist
from interfaces.std_msgs.msg import Header

__all__ = [
    "JointTrajectory",
    "JointTrajectoryPoint",
    "MultiDOFJointTrajectory",
    "MultiDOFJointTrajectoryPoint",
]


class JointTrajectoryPoint(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``trajectory_msgs/msg/JointTrajectoryPoint``."""

    __ros_type__: ClassVar[str] = "trajectory_msgs/msg/JointTrajectoryPoint"
    __ros_definition__: ClassVar[str] = (
        "# Each trajectory point specifies either positions[, velocities[, accelerations]]\n"
        "# or positions[, effort] for the trajectory to be executed.\n"
        "# All specified values are in the same order as the joint names in JointTrajectory.msg.\n"
        "\n"
        "# Single DOF joint positions for each joint relative to their \"0\" position.\n"
        "# The units depend on the specific joint type: radians for revolute or\n"
        "# continuous joints, and meters for prismatic joints.\n"
        "float64[] positions\n"
        "\n"
        "# The rate of change in position of each joint. Units are joint type dependent.\n"
        "# Radians/second for revolute or continuous joints, and meters/second for\n"
        "# prismatic joints.\n"
        "float64[] velocities\n"
        "\n"
        "# Rate of change in velocity of each joint. Units are joint type dependent.\n"
        "# Radians/second^2 for revolute or continuous joints, and meters/second^2 for\n"
        "# prismatic joints.\n"
        "float64[] accelerations\n"
        "\n"
        "# The torque or the force to be applied at each joint. For revolute/continuous\n"
        "# joints effort denotes a torque in newton-meters. For prismatic joints, effort\n"
        "# denotes a force in newtons.\n"
        "float64[] effort\n"
        "\n"
        "# Desired time from the trajectory start to arrive at this trajectory point.\n"
        "builtin_interfaces/Duration time_from_start\n"
    )

    positions: MutableSequence[float] = msgspec.field(default_factory=lambda: array("d"))
    velocities: MutableSequence[float] = msgspec.field(default_factory=lambda: array("d"))
    accelerations: MutableSequence[float] = msgspec.field(default_factory=lambda: array("d"))
    effort: MutableSequence[float] = msgspec.field(default_factory=lambda: array("d"))
    time_from_start: Duration = msgspec.field(default_factory=Duration)

    def __post_init__(self) -> None:
        if type(self.positions) is not array or self.positions.typecode != "d":
            self.positions = held(self.positions, "d")
        if type(self.velocities) is not array or self.velocities.typecode != "d":
            self.velocities = held(self.velocities, "d")
        if type(self.accelerations) is not array or self.accelerations.typecode != "d":
            self.accelerations = held(self.accelerations, "d")
        if type(self.effort) is not array or self.effort.typecode != "d":
            self.effort = held(self.effort, "d")


class JointTrajectory(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``trajectory_msgs/msg/JointTrajectory``."""

    __ros_type__: ClassVar[str] = "trajectory_msgs/msg/JointTrajectory"
    __ros_definition__: ClassVar[str] = (
        "# The header is used to specify the coordinate frame and the reference time for\n"
        "# the trajectory durations\n"
        "std_msgs/Header header\n"
        "\n"
        "# The names of the active joints in each trajectory point. These names are\n"
        "# ordered and must correspond to the values in each trajectory point.\n"
        "string[] joint_names\n"
        "\n"
        "# Array of trajectory points, which describe the positions, velocities,\n"
        "# accelerations and/or efforts of the joints at each time point.\n"
        "JointTrajectoryPoint[] points\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    joint_names: list[str] = msgspec.field(default_factory=list)
    points: list[JointTrajectoryPoint] = msgspec.field(default_factory=list)


class MultiDOFJointTrajectoryPoint(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``trajectory_msgs/msg/MultiDOFJointTrajectoryPoint``."""

    __ros_type__: ClassVar[str] = "trajectory_msgs/msg/MultiDOFJointTrajectoryPoint"
    __ros_definition__: ClassVar[str] = (
        "# Each multi-dof joint can specify a transform (up to 6 DOF).\n"
        "geometry_msgs/Transform[] transforms\n"
        "\n"
        "# There can be a velocity specified for the origin of the joint.\n"
        "geometry_msgs/Twist[] velocities\n"
        "\n"
        "# There can be an acceleration specified for the origin of the joint.\n"
        "geometry_msgs/Twist[] accelerations\n"
        "\n"
        "# Desired time from the trajectory start to arrive at this trajectory point.\n"
        "builtin_interfaces/Duration time_from_start\n"
    )

    transforms: list[Transform] = msgspec.field(default_factory=list)
    velocities: list[Twist] = msgspec.field(default_factory=list)
    accelerations: list[Twist] = msgspec.field(default_factory=list)
    time_from_start: Duration = msgspec.field(default_factory=Duration)


class MultiDOFJointTrajectory(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``trajectory_msgs/msg/MultiDOFJointTrajectory``."""

    __ros_type__: ClassVar[str] = "trajectory_msgs/msg/MultiDOFJointTrajectory"
    __ros_definition__: ClassVar[str] = (
        "# The header is used to specify the coordinate frame and the reference time for the trajectory durations\n"
        "std_msgs/Header header\n"
        "\n"
        "# A representation of a multi-dof joint trajectory (each point is a transformation)\n"
        "# Each point along the trajectory will include an array of positions/velocities/accelerations\n"
        "# that has the same length as the array of joint names, and has the same order of joints as \n"
        "# the joint names array.\n"
        "\n"
        "string[] joint_names\n"
        "MultiDOFJointTrajectoryPoint[] points\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    joint_names: list[str] = msgspec.field(default_factory=list)
    points: list[MultiDOFJointTrajectoryPoint] = msgspec.field(default_factory=list)
