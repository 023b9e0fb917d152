"""Generated from nav_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from typing import ClassVar

import msgspec

from interfaces.geometry_msgs.msg import PoseStamped, PoseWithCovariance, TwistWithCovariance
from interfaces.std_msgs.msg import Header

__all__ = [
    "Odometry",
    "Path",
]


class Odometry(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``nav_msgs/msg/Odometry``."""

    __ros_type__: ClassVar[str] = "nav_msgs/msg/Odometry"
    __ros_definition__: ClassVar[str] = (
        "# This represents an estimate of a position and velocity in free space.\n"
        "# The pose in this message should be specified in the coordinate frame given by header.frame_id\n"
        "# The twist in this message should be specified in the coordinate frame given by the child_frame_id\n"
        "\n"
        "# Includes the frame id of the pose parent.\n"
        "std_msgs/Header header\n"
        "\n"
        "# Frame id the pose points to. The twist is in this coordinate frame.\n"
        "string child_frame_id\n"
        "\n"
        "# Estimated pose that is typically relative to a fixed world frame.\n"
        "geometry_msgs/PoseWithCovariance pose\n"
        "\n"
        "# Estimated linear and angular velocity relative to child_frame_id.\n"
        "geometry_msgs/TwistWithCovariance twist\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    child_frame_id: str = ""
    pose: PoseWithCovariance = msgspec.field(default_factory=PoseWithCovariance)
    twist: TwistWithCovariance = msgspec.field(default_factory=TwistWithCovariance)


class Path(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``nav_msgs/msg/Path``."""

    __ros_type__: ClassVar[str] = "nav_msgs/msg/Path"
    __ros_definition__: ClassVar[str] = (
        "# An array of poses that represents a Path for a robot to follow.\n"
        "\n"
        "# Indicates the frame_id of the path.\n"
        "std_msgs/Header header\n"
        "\n"
        "# Array of poses to follow.\n"
        "geometry_msgs/PoseStamped[] poses\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    poses: list[PoseStamped] = msgspec.field(default_factory=list)
