"""Generated from nav_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from array import array
from collections.abc import MutableSequence
from typing import Annotated, ClassVar

import msgspec

from actors.messages.arrays import held
from interfaces.builtin_interfaces.msg import Time
from interfaces.geometry_msgs.msg import (
    Point,
    Pose,
    PoseStamped,
    PoseWithCovariance,
    TwistWithCovariance,
)
from interfaces.std_msgs.msg import Header

__all__ = [
    "Goals",
    "GridCells",
    "MapMetaData",
    "OccupancyGrid",
    "Odometry",
    "Path",
]

_int8 = Annotated[int, msgspec.Meta(ge=-128, le=127)]
_uint32 = Annotated[int, msgspec.Meta(ge=0, le=4294967295)]


class Goals(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``nav_msgs/msg/Goals``."""

    __ros_type__: ClassVar[str] = "nav_msgs/msg/Goals"
    __ros_definition__: ClassVar[str] = (
        "# An array of navigation goals\n"
        "\n"
        "\n"
        "# This header will store the time at which the poses were computed (not to be confused with the stamps of the poses themselves)\n"
        "# In the case that individual poses do not have their frame_id set or their timetamp set they will use the default value here.\n"
        "std_msgs/Header header\n"
        "\n"
        "# An array of goals to for navigation to achieve.\n"
        "# The goals should be executed in the order of the array.\n"
        "# The header and stamp are intended to be used for computing the position of the goals.\n"
        "# They may vary to support cases of goals that are moving with respect to the robot.\n"
        "geometry_msgs/PoseStamped[] goals\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    goals: list[PoseStamped] = msgspec.field(default_factory=list)


class GridCells(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``nav_msgs/msg/GridCells``."""

    __ros_type__: ClassVar[str] = "nav_msgs/msg/GridCells"
    __ros_definition__: ClassVar[str] = (
        "# An array of cells in a 2D grid\n"
        "\n"
        "std_msgs/Header header\n"
        "\n"
        "# Width of each cell\n"
        "float32 cell_width\n"
        "\n"
        "# Height of each cell\n"
        "float32 cell_height\n"
        "\n"
        "# Each cell is represented by the Point at the center of the cell\n"
        "geometry_msgs/Point[] cells\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    cell_width: float = 0.0
    cell_height: float = 0.0
    cells: list[Point] = msgspec.field(default_factory=list)


class MapMetaData(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``nav_msgs/msg/MapMetaData``."""

    __ros_type__: ClassVar[str] = "nav_msgs/msg/MapMetaData"
    __ros_definition__: ClassVar[str] = (
        "# This hold basic information about the characteristics of the OccupancyGrid\n"
        "\n"
        "# The time at which the map was loaded\n"
        "builtin_interfaces/Time map_load_time\n"
        "\n"
        "# The map resolution [m/cell]\n"
        "float32 resolution\n"
        "\n"
        "# Map width [cells]\n"
        "uint32 width\n"
        "\n"
        "# Map height [cells]\n"
        "uint32 height\n"
        "\n"
        "# The origin of the map [m, m, rad].  This is the real-world pose of the\n"
        "# bottom left corner of cell (0,0) in the map.\n"
        "geometry_msgs/Pose origin\n"
    )

    map_load_time: Time = msgspec.field(default_factory=Time)
    resolution: float = 0.0
    width: _uint32 = 0
    height: _uint32 = 0
    origin: Pose = msgspec.field(default_factory=Pose)


class OccupancyGrid(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``nav_msgs/msg/OccupancyGrid``."""

    __ros_type__: ClassVar[str] = "nav_msgs/msg/OccupancyGrid"
    __ros_definition__: ClassVar[str] = (
        "# This represents a 2-D grid map\n"
        "std_msgs/Header header\n"
        "\n"
        "# MetaData for the map\n"
        "MapMetaData info\n"
        "\n"
        "# The map data, in row-major order, starting with (0,0). \n"
        "# Cell (1, 0) will be listed second, representing the next cell in the x direction. \n"
        "# Cell (0, 1) will be at the index equal to info.width, followed by (1, 1).\n"
        "# The values inside are application dependent, but frequently, \n"
        "# 0 represents unoccupied, 1 represents definitely occupied, and\n"
        "# -1 represents unknown. \n"
        "int8[] data\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    info: MapMetaData = msgspec.field(default_factory=MapMetaData)
    data: MutableSequence[_int8] = msgspec.field(default_factory=lambda: array("b"))

    def __post_init__(self) -> None:
        if type(self.data) is not array or self.data.typecode != "b":
            self.data = held(self.data, "b")


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
