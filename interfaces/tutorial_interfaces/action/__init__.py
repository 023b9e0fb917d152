"""Generated from tutorial_interfaces/action/*.action by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.action_msgs.msg import GoalStatusArray
from interfaces.action_msgs.srv import CancelGoal
from interfaces.builtin_interfaces.msg import Time
from interfaces.geometry_msgs.msg import Pose2D
from interfaces.service_msgs.msg import ServiceEventInfo
from interfaces.unique_identifier_msgs.msg import UUID

__all__ = [
    "DriveToPose",
    "DriveToPose_Feedback",
    "DriveToPose_FeedbackMessage",
    "DriveToPose_GetResult",
    "DriveToPose_GetResult_Event",
    "DriveToPose_GetResult_Request",
    "DriveToPose_GetResult_Response",
    "DriveToPose_Goal",
    "DriveToPose_Result",
    "DriveToPose_SendGoal",
    "DriveToPose_SendGoal_Event",
    "DriveToPose_SendGoal_Request",
    "DriveToPose_SendGoal_Response",
]

_int8 = Annotated[int, msgspec.Meta(ge=-128, le=127)]


class DriveToPose_Goal(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tutorial_interfaces/action/DriveToPose_Goal``."""

    __ros_type__: ClassVar[str] = "tutorial_interfaces/action/DriveToPose_Goal"
    __ros_definition__: ClassVar[str] = (
        "# Drive the robot to a pose in its odometry frame (odom: where it started).\n"
        "geometry_msgs/Pose2D target\n"
        "# Arrived when this close, in meters (0: the server's default).\n"
        "float64 tolerance\n"
    )

    target: Pose2D = msgspec.field(default_factory=Pose2D)
    tolerance: float = 0.0


class DriveToPose_Result(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tutorial_interfaces/action/DriveToPose_Result``."""

    __ros_type__: ClassVar[str] = "tutorial_interfaces/action/DriveToPose_Result"
    __ros_definition__: ClassVar[str] = (
        "# Where the robot stopped, in the odometry frame.\n"
        "geometry_msgs/Pose2D final_pose\n"
        "# Its straight-line distance to the target there, in meters.\n"
        "float64 distance_remaining\n"
    )

    final_pose: Pose2D = msgspec.field(default_factory=Pose2D)
    distance_remaining: float = 0.0


class DriveToPose_Feedback(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tutorial_interfaces/action/DriveToPose_Feedback``."""

    __ros_type__: ClassVar[str] = "tutorial_interfaces/action/DriveToPose_Feedback"
    __ros_definition__: ClassVar[str] = (
        "# Where the robot is now, in the odometry frame.\n"
        "geometry_msgs/Pose2D current_pose\n"
        "# Straight-line distance still to go, in meters.\n"
        "float64 distance_remaining\n"
    )

    current_pose: Pose2D = msgspec.field(default_factory=Pose2D)
    distance_remaining: float = 0.0


class DriveToPose_SendGoal_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tutorial_interfaces/action/DriveToPose_SendGoal_Request``."""

    __ros_type__: ClassVar[str] = "tutorial_interfaces/action/DriveToPose_SendGoal_Request"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
        "tutorial_interfaces/action/DriveToPose_Goal goal\n"
    )

    goal_id: UUID = msgspec.field(default_factory=UUID)
    goal: DriveToPose_Goal = msgspec.field(default_factory=DriveToPose_Goal)


class DriveToPose_SendGoal_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tutorial_interfaces/action/DriveToPose_SendGoal_Response``."""

    __ros_type__: ClassVar[str] = "tutorial_interfaces/action/DriveToPose_SendGoal_Response"
    __ros_definition__: ClassVar[str] = (
        "bool accepted\n"
        "builtin_interfaces/Time stamp\n"
    )

    accepted: bool = False
    stamp: Time = msgspec.field(default_factory=Time)


class DriveToPose_SendGoal_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tutorial_interfaces/action/DriveToPose_SendGoal_Event``."""

    __ros_type__: ClassVar[str] = "tutorial_interfaces/action/DriveToPose_SendGoal_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "tutorial_interfaces/action/DriveToPose_SendGoal_Request[<=1] request\n"
        "tutorial_interfaces/action/DriveToPose_SendGoal_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[DriveToPose_SendGoal_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[DriveToPose_SendGoal_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class DriveToPose_SendGoal:
    """``tutorial_interfaces/action/DriveToPose_SendGoal``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "tutorial_interfaces/action/DriveToPose_SendGoal"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
        "tutorial_interfaces/action/DriveToPose_Goal goal\n"
        "---\n"
        "bool accepted\n"
        "builtin_interfaces/Time stamp\n"
    )
    Request = DriveToPose_SendGoal_Request
    Response = DriveToPose_SendGoal_Response
    Event = DriveToPose_SendGoal_Event


class DriveToPose_GetResult_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tutorial_interfaces/action/DriveToPose_GetResult_Request``."""

    __ros_type__: ClassVar[str] = "tutorial_interfaces/action/DriveToPose_GetResult_Request"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
    )

    goal_id: UUID = msgspec.field(default_factory=UUID)


class DriveToPose_GetResult_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tutorial_interfaces/action/DriveToPose_GetResult_Response``."""

    __ros_type__: ClassVar[str] = "tutorial_interfaces/action/DriveToPose_GetResult_Response"
    __ros_definition__: ClassVar[str] = (
        "int8 status\n"
        "tutorial_interfaces/action/DriveToPose_Result result\n"
    )

    status: _int8 = 0
    result: DriveToPose_Result = msgspec.field(default_factory=DriveToPose_Result)


class DriveToPose_GetResult_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tutorial_interfaces/action/DriveToPose_GetResult_Event``."""

    __ros_type__: ClassVar[str] = "tutorial_interfaces/action/DriveToPose_GetResult_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "tutorial_interfaces/action/DriveToPose_GetResult_Request[<=1] request\n"
        "tutorial_interfaces/action/DriveToPose_GetResult_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[DriveToPose_GetResult_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[DriveToPose_GetResult_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class DriveToPose_GetResult:
    """``tutorial_interfaces/action/DriveToPose_GetResult``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "tutorial_interfaces/action/DriveToPose_GetResult"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
        "---\n"
        "int8 status\n"
        "tutorial_interfaces/action/DriveToPose_Result result\n"
    )
    Request = DriveToPose_GetResult_Request
    Response = DriveToPose_GetResult_Response
    Event = DriveToPose_GetResult_Event


class DriveToPose_FeedbackMessage(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tutorial_interfaces/action/DriveToPose_FeedbackMessage``."""

    __ros_type__: ClassVar[str] = "tutorial_interfaces/action/DriveToPose_FeedbackMessage"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
        "tutorial_interfaces/action/DriveToPose_Feedback feedback\n"
    )

    goal_id: UUID = msgspec.field(default_factory=UUID)
    feedback: DriveToPose_Feedback = msgspec.field(default_factory=DriveToPose_Feedback)


class DriveToPose:
    """``tutorial_interfaces/action/DriveToPose``: ``Goal``, ``Result``, ``Feedback``.

    ``Impl`` holds the types its wire protocol uses.
    """

    __ros_type__: ClassVar[str] = "tutorial_interfaces/action/DriveToPose"
    __ros_definition__: ClassVar[str] = (
        "# Drive the robot to a pose in its odometry frame (odom: where it started).\n"
        "geometry_msgs/Pose2D target\n"
        "# Arrived when this close, in meters (0: the server's default).\n"
        "float64 tolerance\n"
        "---\n"
        "# Where the robot stopped, in the odometry frame.\n"
        "geometry_msgs/Pose2D final_pose\n"
        "# Its straight-line distance to the target there, in meters.\n"
        "float64 distance_remaining\n"
        "---\n"
        "# Where the robot is now, in the odometry frame.\n"
        "geometry_msgs/Pose2D current_pose\n"
        "# Straight-line distance still to go, in meters.\n"
        "float64 distance_remaining\n"
    )
    Goal = DriveToPose_Goal
    Result = DriveToPose_Result
    Feedback = DriveToPose_Feedback

    class Impl:
        """The services and topic types of the action's wire protocol."""

        SendGoalService = DriveToPose_SendGoal
        GetResultService = DriveToPose_GetResult
        FeedbackMessage = DriveToPose_FeedbackMessage
        CancelGoalService = CancelGoal
        GoalStatusMessage = GoalStatusArray
