"""Generated from nav_msgs/srv/*.srv by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.geometry_msgs.msg import PoseStamped, PoseWithCovarianceStamped
from interfaces.nav_msgs.msg import OccupancyGrid, Path
from interfaces.service_msgs.msg import ServiceEventInfo

__all__ = [
    "GetMap",
    "GetMap_Event",
    "GetMap_Request",
    "GetMap_Response",
    "GetPlan",
    "GetPlan_Event",
    "GetPlan_Request",
    "GetPlan_Response",
    "LoadMap",
    "LoadMap_Event",
    "LoadMap_Request",
    "LoadMap_Response",
    "SetMap",
    "SetMap_Event",
    "SetMap_Request",
    "SetMap_Response",
]

_uint8 = Annotated[int, msgspec.Meta(ge=0, le=255)]


class GetMap_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``nav_msgs/srv/GetMap_Request``."""

    __ros_type__: ClassVar[str] = "nav_msgs/srv/GetMap_Request"
    __ros_definition__: ClassVar[str] = (
        "# Get the map as a nav_msgs/OccupancyGrid\n"
    )


class GetMap_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``nav_msgs/srv/GetMap_Response``."""

    __ros_type__: ClassVar[str] = "nav_msgs/srv/GetMap_Response"
    __ros_definition__: ClassVar[str] = (
        "# The current map hosted by this map service.\n"
        "OccupancyGrid map\n"
    )

    map: OccupancyGrid = msgspec.field(default_factory=OccupancyGrid)


class GetMap_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``nav_msgs/srv/GetMap_Event``."""

    __ros_type__: ClassVar[str] = "nav_msgs/srv/GetMap_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "nav_msgs/srv/GetMap_Request[<=1] request\n"
        "nav_msgs/srv/GetMap_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[GetMap_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[GetMap_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class GetMap:
    """``nav_msgs/srv/GetMap``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "nav_msgs/srv/GetMap"
    __ros_definition__: ClassVar[str] = (
        "# Get the map as a nav_msgs/OccupancyGrid\n"
        "---\n"
        "# The current map hosted by this map service.\n"
        "OccupancyGrid map\n"
    )
    Request = GetMap_Request
    Response = GetMap_Response
    Event = GetMap_Event


class GetPlan_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``nav_msgs/srv/GetPlan_Request``."""

    __ros_type__: ClassVar[str] = "nav_msgs/srv/GetPlan_Request"
    __ros_definition__: ClassVar[str] = (
        "# Get a plan from the current position to the goal Pose\n"
        "\n"
        "# The start pose for the plan\n"
        "geometry_msgs/PoseStamped start\n"
        "\n"
        "# The final pose of the goal position\n"
        "geometry_msgs/PoseStamped goal\n"
        "\n"
        "# If the goal is obstructed, how many meters the planner can\n"
        "# relax the constraint in x and y before failing.\n"
        "float32 tolerance\n"
    )

    start: PoseStamped = msgspec.field(default_factory=PoseStamped)
    goal: PoseStamped = msgspec.field(default_factory=PoseStamped)
    tolerance: float = 0.0


class GetPlan_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``nav_msgs/srv/GetPlan_Response``."""

    __ros_type__: ClassVar[str] = "nav_msgs/srv/GetPlan_Response"
    __ros_definition__: ClassVar[str] = (
        "# Array of poses from start to goal if one was successfully found.\n"
        "Path plan\n"
    )

    plan: Path = msgspec.field(default_factory=Path)


class GetPlan_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``nav_msgs/srv/GetPlan_Event``."""

    __ros_type__: ClassVar[str] = "nav_msgs/srv/GetPlan_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "nav_msgs/srv/GetPlan_Request[<=1] request\n"
        "nav_msgs/srv/GetPlan_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[GetPlan_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[GetPlan_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class GetPlan:
    """``nav_msgs/srv/GetPlan``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "nav_msgs/srv/GetPlan"
    __ros_definition__: ClassVar[str] = (
        "# Get a plan from the current position to the goal Pose\n"
        "\n"
        "# The start pose for the plan\n"
        "geometry_msgs/PoseStamped start\n"
        "\n"
        "# The final pose of the goal position\n"
        "geometry_msgs/PoseStamped goal\n"
        "\n"
        "# If the goal is obstructed, how many meters the planner can\n"
        "# relax the constraint in x and y before failing.\n"
        "float32 tolerance\n"
        "---\n"
        "# Array of poses from start to goal if one was successfully found.\n"
        "Path plan\n"
    )
    Request = GetPlan_Request
    Response = GetPlan_Response
    Event = GetPlan_Event


class LoadMap_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``nav_msgs/srv/LoadMap_Request``."""

    __ros_type__: ClassVar[str] = "nav_msgs/srv/LoadMap_Request"
    __ros_definition__: ClassVar[str] = (
        "# URL of map resource\n"
        "# Can be an absolute path to a file: file:///path/to/maps/floor1.yaml\n"
        "# Or, relative to a ROS package: package://my_ros_package/maps/floor2.yaml\n"
        "string map_url\n"
    )

    map_url: str = ""


class LoadMap_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``nav_msgs/srv/LoadMap_Response``."""

    __ros_type__: ClassVar[str] = "nav_msgs/srv/LoadMap_Response"
    __ros_definition__: ClassVar[str] = (
        "# Result code definitions\n"
        "uint8 RESULT_SUCCESS=0\n"
        "uint8 RESULT_MAP_DOES_NOT_EXIST=1\n"
        "uint8 RESULT_INVALID_MAP_DATA=2\n"
        "uint8 RESULT_INVALID_MAP_METADATA=3\n"
        "uint8 RESULT_UNDEFINED_FAILURE=255\n"
        "\n"
        "# Returned map is only valid if result equals RESULT_SUCCESS\n"
        "nav_msgs/OccupancyGrid map\n"
        "uint8 result\n"
    )
    RESULT_SUCCESS: ClassVar[int] = 0
    RESULT_MAP_DOES_NOT_EXIST: ClassVar[int] = 1
    RESULT_INVALID_MAP_DATA: ClassVar[int] = 2
    RESULT_INVALID_MAP_METADATA: ClassVar[int] = 3
    RESULT_UNDEFINED_FAILURE: ClassVar[int] = 255

    map: OccupancyGrid = msgspec.field(default_factory=OccupancyGrid)
    result: _uint8 = 0


class LoadMap_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``nav_msgs/srv/LoadMap_Event``."""

    __ros_type__: ClassVar[str] = "nav_msgs/srv/LoadMap_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "nav_msgs/srv/LoadMap_Request[<=1] request\n"
        "nav_msgs/srv/LoadMap_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[LoadMap_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[LoadMap_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class LoadMap:
    """``nav_msgs/srv/LoadMap``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "nav_msgs/srv/LoadMap"
    __ros_definition__: ClassVar[str] = (
        "# URL of map resource\n"
        "# Can be an absolute path to a file: file:///path/to/maps/floor1.yaml\n"
        "# Or, relative to a ROS package: package://my_ros_package/maps/floor2.yaml\n"
        "string map_url\n"
        "---\n"
        "# Result code definitions\n"
        "uint8 RESULT_SUCCESS=0\n"
        "uint8 RESULT_MAP_DOES_NOT_EXIST=1\n"
        "uint8 RESULT_INVALID_MAP_DATA=2\n"
        "uint8 RESULT_INVALID_MAP_METADATA=3\n"
        "uint8 RESULT_UNDEFINED_FAILURE=255\n"
        "\n"
        "# Returned map is only valid if result equals RESULT_SUCCESS\n"
        "nav_msgs/OccupancyGrid map\n"
        "uint8 result\n"
    )
    Request = LoadMap_Request
    Response = LoadMap_Response
    Event = LoadMap_Event


class SetMap_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``nav_msgs/srv/SetMap_Request``."""

    __ros_type__: ClassVar[str] = "nav_msgs/srv/SetMap_Request"
    __ros_definition__: ClassVar[str] = (
        "# Set a new map together with an initial pose\n"
        "\n"
        "# Requested 2D map to be set.\n"
        "nav_msgs/OccupancyGrid map\n"
        "\n"
        "# Estimated initial pose when setting new map.\n"
        "geometry_msgs/PoseWithCovarianceStamped initial_pose\n"
    )

    map: OccupancyGrid = msgspec.field(default_factory=OccupancyGrid)
    initial_pose: PoseWithCovarianceStamped = msgspec.field(default_factory=PoseWithCovarianceStamped)


class SetMap_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``nav_msgs/srv/SetMap_Response``."""

    __ros_type__: ClassVar[str] = "nav_msgs/srv/SetMap_Response"
    __ros_definition__: ClassVar[str] = (
        "\n"
        "# True if the map was successfully set, false otherwise.\n"
        "bool success\n"
    )

    success: bool = False


class SetMap_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``nav_msgs/srv/SetMap_Event``."""

    __ros_type__: ClassVar[str] = "nav_msgs/srv/SetMap_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "nav_msgs/srv/SetMap_Request[<=1] request\n"
        "nav_msgs/srv/SetMap_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[SetMap_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[SetMap_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class SetMap:
    """``nav_msgs/srv/SetMap``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "nav_msgs/srv/SetMap"
    __ros_definition__: ClassVar[str] = (
        "# Set a new map together with an initial pose\n"
        "\n"
        "# Requested 2D map to be set.\n"
        "nav_msgs/OccupancyGrid map\n"
        "\n"
        "# Estimated initial pose when setting new map.\n"
        "geometry_msgs/PoseWithCovarianceStamped initial_pose\n"
        "---\n"
        "\n"
        "# True if the map was successfully set, false otherwise.\n"
        "bool success\n"
    )
    Request = SetMap_Request
    Response = SetMap_Response
    Event = SetMap_Event
