"""Generated from tf2_msgs/action/*.action by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.action_msgs.msg import GoalStatusArray
from interfaces.action_msgs.srv import CancelGoal
from interfaces.builtin_interfaces.msg import Duration, Time
from interfaces.geometry_msgs.msg import TransformStamped
from interfaces.service_msgs.msg import ServiceEventInfo
from interfaces.tf2_msgs.msg import TF2Error
from interfaces.unique_identifier_msgs.msg import UUID

__all__ = [
    "LookupTransform",
    "LookupTransform_Feedback",
    "LookupTransform_FeedbackMessage",
    "LookupTransform_GetResult",
    "LookupTransform_GetResult_Event",
    "LookupTransform_GetResult_Request",
    "LookupTransform_GetResult_Response",
    "LookupTransform_Goal",
    "LookupTransform_Result",
    "LookupTransform_SendGoal",
    "LookupTransform_SendGoal_Event",
    "LookupTransform_SendGoal_Request",
    "LookupTransform_SendGoal_Response",
]

_int8 = Annotated[int, msgspec.Meta(ge=-128, le=127)]


class LookupTransform_Goal(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tf2_msgs/action/LookupTransform_Goal``."""

    __ros_type__: ClassVar[str] = "tf2_msgs/action/LookupTransform_Goal"
    __ros_definition__: ClassVar[str] = (
        "#Simple API\n"
        "string target_frame\n"
        "string source_frame\n"
        "builtin_interfaces/Time source_time\n"
        "builtin_interfaces/Duration timeout\n"
        "\n"
        "#Advanced API\n"
        "builtin_interfaces/Time target_time\n"
        "string fixed_frame\n"
        "\n"
        "#Whether or not to use the advanced API\n"
        "bool advanced\n"
        "\n"
    )

    target_frame: str = ""
    source_frame: str = ""
    source_time: Time = msgspec.field(default_factory=Time)
    timeout: Duration = msgspec.field(default_factory=Duration)
    target_time: Time = msgspec.field(default_factory=Time)
    fixed_frame: str = ""
    advanced: bool = False


class LookupTransform_Result(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tf2_msgs/action/LookupTransform_Result``."""

    __ros_type__: ClassVar[str] = "tf2_msgs/action/LookupTransform_Result"
    __ros_definition__: ClassVar[str] = (
        "geometry_msgs/TransformStamped transform\n"
        "tf2_msgs/TF2Error error\n"
    )

    transform: TransformStamped = msgspec.field(default_factory=TransformStamped)
    error: TF2Error = msgspec.field(default_factory=TF2Error)


class LookupTransform_Feedback(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tf2_msgs/action/LookupTransform_Feedback``."""

    __ros_type__: ClassVar[str] = "tf2_msgs/action/LookupTransform_Feedback"
    __ros_definition__: ClassVar[str] = ""


class LookupTransform_SendGoal_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tf2_msgs/action/LookupTransform_SendGoal_Request``."""

    __ros_type__: ClassVar[str] = "tf2_msgs/action/LookupTransform_SendGoal_Request"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
        "tf2_msgs/action/LookupTransform_Goal goal\n"
    )

    goal_id: UUID = msgspec.field(default_factory=UUID)
    goal: LookupTransform_Goal = msgspec.field(default_factory=LookupTransform_Goal)


class LookupTransform_SendGoal_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tf2_msgs/action/LookupTransform_SendGoal_Response``."""

    __ros_type__: ClassVar[str] = "tf2_msgs/action/LookupTransform_SendGoal_Response"
    __ros_definition__: ClassVar[str] = (
        "bool accepted\n"
        "builtin_interfaces/Time stamp\n"
    )

    accepted: bool = False
    stamp: Time = msgspec.field(default_factory=Time)


class LookupTransform_SendGoal_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tf2_msgs/action/LookupTransform_SendGoal_Event``."""

    __ros_type__: ClassVar[str] = "tf2_msgs/action/LookupTransform_SendGoal_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "tf2_msgs/action/LookupTransform_SendGoal_Request[<=1] request\n"
        "tf2_msgs/action/LookupTransform_SendGoal_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[LookupTransform_SendGoal_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[LookupTransform_SendGoal_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class LookupTransform_SendGoal:
    """``tf2_msgs/action/LookupTransform_SendGoal``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "tf2_msgs/action/LookupTransform_SendGoal"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
        "tf2_msgs/action/LookupTransform_Goal goal\n"
        "---\n"
        "bool accepted\n"
        "builtin_interfaces/Time stamp\n"
    )
    Request = LookupTransform_SendGoal_Request
    Response = LookupTransform_SendGoal_Response
    Event = LookupTransform_SendGoal_Event


class LookupTransform_GetResult_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tf2_msgs/action/LookupTransform_GetResult_Request``."""

    __ros_type__: ClassVar[str] = "tf2_msgs/action/LookupTransform_GetResult_Request"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
    )

    goal_id: UUID = msgspec.field(default_factory=UUID)


class LookupTransform_GetResult_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tf2_msgs/action/LookupTransform_GetResult_Response``."""

    __ros_type__: ClassVar[str] = "tf2_msgs/action/LookupTransform_GetResult_Response"
    __ros_definition__: ClassVar[str] = (
        "int8 status\n"
        "tf2_msgs/action/LookupTransform_Result result\n"
    )

    status: _int8 = 0
    result: LookupTransform_Result = msgspec.field(default_factory=LookupTransform_Result)


class LookupTransform_GetResult_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tf2_msgs/action/LookupTransform_GetResult_Event``."""

    __ros_type__: ClassVar[str] = "tf2_msgs/action/LookupTransform_GetResult_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "tf2_msgs/action/LookupTransform_GetResult_Request[<=1] request\n"
        "tf2_msgs/action/LookupTransform_GetResult_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[LookupTransform_GetResult_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[LookupTransform_GetResult_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class LookupTransform_GetResult:
    """``tf2_msgs/action/LookupTransform_GetResult``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "tf2_msgs/action/LookupTransform_GetResult"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
        "---\n"
        "int8 status\n"
        "tf2_msgs/action/LookupTransform_Result result\n"
    )
    Request = LookupTransform_GetResult_Request
    Response = LookupTransform_GetResult_Response
    Event = LookupTransform_GetResult_Event


class LookupTransform_FeedbackMessage(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tf2_msgs/action/LookupTransform_FeedbackMessage``."""

    __ros_type__: ClassVar[str] = "tf2_msgs/action/LookupTransform_FeedbackMessage"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
        "tf2_msgs/action/LookupTransform_Feedback feedback\n"
    )

    goal_id: UUID = msgspec.field(default_factory=UUID)
    feedback: LookupTransform_Feedback = msgspec.field(default_factory=LookupTransform_Feedback)


class LookupTransform:
    """``tf2_msgs/action/LookupTransform``: ``Goal``, ``Result``, ``Feedback``.

    ``Impl`` holds the types its wire protocol uses.
    """

    __ros_type__: ClassVar[str] = "tf2_msgs/action/LookupTransform"
    __ros_definition__: ClassVar[str] = (
        "#Simple API\n"
        "string target_frame\n"
        "string source_frame\n"
        "builtin_interfaces/Time source_time\n"
        "builtin_interfaces/Duration timeout\n"
        "\n"
        "#Advanced API\n"
        "builtin_interfaces/Time target_time\n"
        "string fixed_frame\n"
        "\n"
        "#Whether or not to use the advanced API\n"
        "bool advanced\n"
        "\n"
        "---\n"
        "geometry_msgs/TransformStamped transform\n"
        "tf2_msgs/TF2Error error\n"
        "---\n"
    )
    Goal = LookupTransform_Goal
    Result = LookupTransform_Result
    Feedback = LookupTransform_Feedback

    class Impl:
        """The services and topic types of the action's wire protocol."""

        SendGoalService = LookupTransform_SendGoal
        GetResultService = LookupTransform_GetResult
        FeedbackMessage = LookupTransform_FeedbackMessage
        CancelGoalService = CancelGoal
        GoalStatusMessage = GoalStatusArray
