"""Generated from turtlesim_msgs/action/*.action by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.action_msgs.msg import GoalStatusArray
from interfaces.action_msgs.srv import CancelGoal
from interfaces.builtin_interfaces.msg import Time
from interfaces.service_msgs.msg import ServiceEventInfo
from interfaces.unique_identifier_msgs.msg import UUID

__all__ = [
    "RotateAbsolute",
    "RotateAbsolute_Feedback",
    "RotateAbsolute_FeedbackMessage",
    "RotateAbsolute_GetResult",
    "RotateAbsolute_GetResult_Event",
    "RotateAbsolute_GetResult_Request",
    "RotateAbsolute_GetResult_Response",
    "RotateAbsolute_Goal",
    "RotateAbsolute_Result",
    "RotateAbsolute_SendGoal",
    "RotateAbsolute_SendGoal_Event",
    "RotateAbsolute_SendGoal_Request",
    "RotateAbsolute_SendGoal_Response",
]

_int8 = Annotated[int, msgspec.Meta(ge=-128, le=127)]


class RotateAbsolute_Goal(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/action/RotateAbsolute_Goal``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/action/RotateAbsolute_Goal"
    __ros_definition__: ClassVar[str] = (
        "# The desired heading in radians\n"
        "float32 theta\n"
    )

    theta: float = 0.0


class RotateAbsolute_Result(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/action/RotateAbsolute_Result``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/action/RotateAbsolute_Result"
    __ros_definition__: ClassVar[str] = (
        "# The angular displacement in radians to the starting position\n"
        "float32 delta\n"
    )

    delta: float = 0.0


class RotateAbsolute_Feedback(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/action/RotateAbsolute_Feedback``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/action/RotateAbsolute_Feedback"
    __ros_definition__: ClassVar[str] = (
        "# The remaining rotation in radians\n"
        "float32 remaining\n"
    )

    remaining: float = 0.0


class RotateAbsolute_SendGoal_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/action/RotateAbsolute_SendGoal_Request``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/action/RotateAbsolute_SendGoal_Request"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
        "turtlesim_msgs/action/RotateAbsolute_Goal goal\n"
    )

    goal_id: UUID = msgspec.field(default_factory=UUID)
    goal: RotateAbsolute_Goal = msgspec.field(default_factory=RotateAbsolute_Goal)


class RotateAbsolute_SendGoal_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/action/RotateAbsolute_SendGoal_Response``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/action/RotateAbsolute_SendGoal_Response"
    __ros_definition__: ClassVar[str] = (
        "bool accepted\n"
        "builtin_interfaces/Time stamp\n"
    )

    accepted: bool = False
    stamp: Time = msgspec.field(default_factory=Time)


class RotateAbsolute_SendGoal_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/action/RotateAbsolute_SendGoal_Event``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/action/RotateAbsolute_SendGoal_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "turtlesim_msgs/action/RotateAbsolute_SendGoal_Request[<=1] request\n"
        "turtlesim_msgs/action/RotateAbsolute_SendGoal_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[RotateAbsolute_SendGoal_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[RotateAbsolute_SendGoal_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class RotateAbsolute_SendGoal:
    """``turtlesim_msgs/action/RotateAbsolute_SendGoal``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/action/RotateAbsolute_SendGoal"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
        "turtlesim_msgs/action/RotateAbsolute_Goal goal\n"
        "---\n"
        "bool accepted\n"
        "builtin_interfaces/Time stamp\n"
    )
    Request = RotateAbsolute_SendGoal_Request
    Response = RotateAbsolute_SendGoal_Response
    Event = RotateAbsolute_SendGoal_Event


class RotateAbsolute_GetResult_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/action/RotateAbsolute_GetResult_Request``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/action/RotateAbsolute_GetResult_Request"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
    )

    goal_id: UUID = msgspec.field(default_factory=UUID)


class RotateAbsolute_GetResult_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/action/RotateAbsolute_GetResult_Response``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/action/RotateAbsolute_GetResult_Response"
    __ros_definition__: ClassVar[str] = (
        "int8 status\n"
        "turtlesim_msgs/action/RotateAbsolute_Result result\n"
    )

    status: _int8 = 0
    result: RotateAbsolute_Result = msgspec.field(default_factory=RotateAbsolute_Result)


class RotateAbsolute_GetResult_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/action/RotateAbsolute_GetResult_Event``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/action/RotateAbsolute_GetResult_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "turtlesim_msgs/action/RotateAbsolute_GetResult_Request[<=1] request\n"
        "turtlesim_msgs/action/RotateAbsolute_GetResult_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[RotateAbsolute_GetResult_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[RotateAbsolute_GetResult_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class RotateAbsolute_GetResult:
    """``turtlesim_msgs/action/RotateAbsolute_GetResult``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/action/RotateAbsolute_GetResult"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
        "---\n"
        "int8 status\n"
        "turtlesim_msgs/action/RotateAbsolute_Result result\n"
    )
    Request = RotateAbsolute_GetResult_Request
    Response = RotateAbsolute_GetResult_Response
    Event = RotateAbsolute_GetResult_Event


class RotateAbsolute_FeedbackMessage(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/action/RotateAbsolute_FeedbackMessage``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/action/RotateAbsolute_FeedbackMessage"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
        "turtlesim_msgs/action/RotateAbsolute_Feedback feedback\n"
    )

    goal_id: UUID = msgspec.field(default_factory=UUID)
    feedback: RotateAbsolute_Feedback = msgspec.field(default_factory=RotateAbsolute_Feedback)


class RotateAbsolute:
    """``turtlesim_msgs/action/RotateAbsolute``: ``Goal``, ``Result``, ``Feedback``.

    ``Impl`` holds the types its wire protocol uses.
    """

    __ros_type__: ClassVar[str] = "turtlesim_msgs/action/RotateAbsolute"
    __ros_definition__: ClassVar[str] = (
        "# The desired heading in radians\n"
        "float32 theta\n"
        "---\n"
        "# The angular displacement in radians to the starting position\n"
        "float32 delta\n"
        "---\n"
        "# The remaining rotation in radians\n"
        "float32 remaining\n"
    )
    Goal = RotateAbsolute_Goal
    Result = RotateAbsolute_Result
    Feedback = RotateAbsolute_Feedback

    class Impl:
        """The services and topic types of the action's wire protocol."""

        SendGoalService = RotateAbsolute_SendGoal
        GetResultService = RotateAbsolute_GetResult
        FeedbackMessage = RotateAbsolute_FeedbackMessage
        CancelGoalService = CancelGoal
        GoalStatusMessage = GoalStatusArray
