"""Generated from sensor_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.geometry_msgs.msg import Quaternion, Vector3
from interfaces.std_msgs.msg import Header

__all__ = [
    "Imu",
    "JointState",
    "LaserScan",
]


class Imu(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/Imu``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/Imu"
    __ros_definition__: ClassVar[str] = (
        "# This is a message to hold data from an IMU (Inertial Measurement Unit)\n"
        "#\n"
        "# Accelerations should be in m/s^2 (not in g's), and rotational velocity should be in rad/sec\n"
        "#\n"
        "# If the covariance of the measurement is known, it should be filled in (if all you know is the\n"
        "# variance of each measurement, e.g. from the datasheet, just put those along the diagonal)\n"
        "# A covariance matrix of all zeros will be interpreted as \"covariance unknown\", and to use the\n"
        "# data a covariance will have to be assumed or gotten from some other source\n"
        "#\n"
        "# If you have no estimate for one of the data elements (e.g. your IMU doesn't produce an\n"
        "# orientation estimate), please set element 0 of the associated covariance matrix to -1\n"
        "# If you are interpreting this message, please check for a value of -1 in the first element of each\n"
        "# covariance matrix, and disregard the associated estimate.\n"
        "\n"
        "std_msgs/Header header\n"
        "\n"
        "geometry_msgs/Quaternion orientation\n"
        "float64[9] orientation_covariance # Row major about x, y, z axes\n"
        "\n"
        "geometry_msgs/Vector3 angular_velocity\n"
        "float64[9] angular_velocity_covariance # Row major about x, y, z axes\n"
        "\n"
        "geometry_msgs/Vector3 linear_acceleration\n"
        "float64[9] linear_acceleration_covariance # Row major x, y z\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    orientation: Quaternion = msgspec.field(default_factory=Quaternion)
    orientation_covariance: Annotated[list[float], msgspec.Meta(min_length=9, max_length=9)] = msgspec.field(default_factory=lambda: [0.0] * 9)
    angular_velocity: Vector3 = msgspec.field(default_factory=Vector3)
    angular_velocity_covariance: Annotated[list[float], msgspec.Meta(min_length=9, max_length=9)] = msgspec.field(default_factory=lambda: [0.0] * 9)
    linear_acceleration: Vector3 = msgspec.field(default_factory=Vector3)
    linear_acceleration_covariance: Annotated[list[float], msgspec.Meta(min_length=9, max_length=9)] = msgspec.field(default_factory=lambda: [0.0] * 9)


class JointState(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/JointState``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/JointState"
    __ros_definition__: ClassVar[str] = (
        "# This is a message that holds data to describe the state of a set of torque controlled joints.\n"
        "#\n"
        "# The state of each joint (revolute or prismatic) is defined by:\n"
        "#  * the position of the joint (rad or m),\n"
        "#  * the velocity of the joint (rad/s or m/s) and\n"
        "#  * the effort that is applied in the joint (Nm or N).\n"
        "#\n"
        "# Each joint is uniquely identified by its name\n"
        "# The header specifies the time at which the joint states were recorded. All the joint states\n"
        "# in one message have to be recorded at the same time.\n"
        "#\n"
        "# This message consists of a multiple arrays, one for each part of the joint state.\n"
        "# The goal is to make each of the fields optional. When e.g. your joints have no\n"
        "# effort associated with them, you can leave the effort array empty.\n"
        "#\n"
        "# All arrays in this message should have the same size, or be empty.\n"
        "# This is the only way to uniquely associate the joint name with the correct\n"
        "# states.\n"
        "\n"
        "std_msgs/Header header\n"
        "\n"
        "string[] name\n"
        "float64[] position\n"
        "float64[] velocity\n"
        "float64[] effort\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    name: list[str] = msgspec.field(default_factory=list)
    position: list[float] = msgspec.field(default_factory=list)
    velocity: list[float] = msgspec.field(default_factory=list)
    effort: list[float] = msgspec.field(default_factory=list)


class LaserScan(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/LaserScan``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/LaserScan"
    __ros_definition__: ClassVar[str] = (
        "# Single scan from a planar laser range-finder\n"
        "#\n"
        "# If you have another ranging device with different behavior (e.g. a sonar\n"
        "# array), please find or create a different message, since applications\n"
        "# will make fairly laser-specific assumptions about this data\n"
        "\n"
        "std_msgs/Header header # timestamp in the header is the acquisition time of\n"
        "                             # the first ray in the scan.\n"
        "                             #\n"
        "                             # in frame frame_id, angles are measured around\n"
        "                             # the positive Z axis (counterclockwise, if Z is up)\n"
        "                             # with zero angle being forward along the x axis\n"
        "\n"
        "float32 angle_min            # start angle of the scan [rad]\n"
        "float32 angle_max            # end angle of the scan [rad]\n"
        "float32 angle_increment      # angular distance between measurements [rad]\n"
        "\n"
        "float32 time_increment       # time between measurements [seconds] - if your scanner\n"
        "                             # is moving, this will be used in interpolating position\n"
        "                             # of 3d points\n"
        "float32 scan_time            # time between scans [seconds]\n"
        "\n"
        "float32 range_min            # minimum range value [m]\n"
        "float32 range_max            # maximum range value [m]\n"
        "\n"
        "float32[] ranges             # range data [m]\n"
        "                             # (Note: values < range_min or > range_max should be discarded)\n"
        "float32[] intensities        # intensity data [device-specific units].  If your\n"
        "                             # device does not provide intensities, please leave\n"
        "                             # the array empty.\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    angle_min: float = 0.0
    angle_max: float = 0.0
    angle_increment: float = 0.0
    time_increment: float = 0.0
    scan_time: float = 0.0
    range_min: float = 0.0
    range_max: float = 0.0
    ranges: list[float] = msgspec.field(default_factory=list)
    intensities: list[float] = msgspec.field(default_factory=list)
