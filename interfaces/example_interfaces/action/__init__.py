"""Generated from example_interfaces/action/*.action by `python -m actors interface generate`; do not edit."""

from array import array
from collections.abc import MutableSequence
from typing import Annotated, ClassVar

import msgspec

from actors.messages.arrays import held
from interfaces.action_msgs.msg import GoalStatusArray
from interfaces.action_msgs.srv import CancelGoal
from interfaces.builtin_interfaces.msg import Time
from interfaces.service_msgs.msg import ServiceEventInfo
from interfaces.unique_identifier_msgs.msg import UUID

__all__ = [
    "Fibonacci",
    "Fibonacci_Feedback",
    "Fibonacci_FeedbackMessage",
    "Fibonacci_GetResult",
    "Fibonacci_GetResult_Event",
    "Fibonacci_GetResult_Request",
    "Fibonacci_GetResult_Response",
    "Fibonacci_Goal",
    "Fibonacci_Result",
    "Fibonacci_SendGoal",
    "Fibonacci_SendGoal_Event",
    "Fibonacci_SendGoal_Request",
    "Fibonacci_SendGoal_Response",
]

_int8 = Annotated[int, msgspec.Meta(ge=-128, le=127)]
_int32 = Annotated[int, msgspec.Meta(ge=-2147483648, le=2147483647)]


class Fibonacci_Goal(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/action/Fibonacci_Goal``."""

    __ros_type__: ClassVar[str] = "example_interfaces/action/Fibonacci_Goal"
    __ros_definition__: ClassVar[str] = (
        "# Goal\n"
        "int32 order\n"
    )

    order: _int32 = 0


class Fibonacci_Result(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/action/Fibonacci_Result``."""

    __ros_type__: ClassVar[str] = "example_interfaces/action/Fibonacci_Result"
    __ros_definition__: ClassVar[str] = (
        "# Result\n"
        "int32[] sequence\n"
    )

    sequence: MutableSequence[_int32] = msgspec.field(default_factory=lambda: array("i"))

    def __post_init__(self) -> None:
        if type(self.sequence) is not array or self.sequence.typecode != "i":
            self.sequence = held(self.sequence, "i")


class Fibonacci_Feedback(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/action/Fibonacci_Feedback``."""

    __ros_type__: ClassVar[str] = "example_interfaces/action/Fibonacci_Feedback"
    __ros_definition__: ClassVar[str] = (
        "# Feedback\n"
        "int32[] sequence\n"
    )

    sequence: MutableSequence[_int32] = msgspec.field(default_factory=lambda: array("i"))

    def __post_init__(self) -> None:
        if type(self.sequence) is not array or self.sequence.typecode != "i":
            self.sequence = held(self.sequence, "i")


class Fibonacci_SendGoal_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/action/Fibonacci_SendGoal_Request``."""

    __ros_type__: ClassVar[str] = "example_interfaces/action/Fibonacci_SendGoal_Request"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
        "example_interfaces/action/Fibonacci_Goal goal\n"
    )

    goal_id: UUID = msgspec.field(default_factory=UUID)
    goal: Fibonacci_Goal = msgspec.field(default_factory=Fibonacci_Goal)


class Fibonacci_SendGoal_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/action/Fibonacci_SendGoal_Response``."""

    __ros_type__: ClassVar[str] = "example_interfaces/action/Fibonacci_SendGoal_Response"
    __ros_definition__: ClassVar[str] = (
        "bool accepted\n"
        "builtin_interfaces/Time stamp\n"
    )

    accepted: bool = False
    stamp: Time = msgspec.field(default_factory=Time)


class Fibonacci_SendGoal_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/action/Fibonacci_SendGoal_Event``."""

    __ros_type__: ClassVar[str] = "example_interfaces/action/Fibonacci_SendGoal_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "example_interfaces/action/Fibonacci_SendGoal_Request[<=1] request\n"
        "example_interfaces/action/Fibonacci_SendGoal_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[Fibonacci_SendGoal_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[Fibonacci_SendGoal_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class Fibonacci_SendGoal:
    """``example_interfaces/action/Fibonacci_SendGoal``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "example_interfaces/action/Fibonacci_SendGoal"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
        "example_interfaces/action/Fibonacci_Goal goal\n"
        "---\n"
        "bool accepted\n"
        "builtin_interfaces/Time stamp\n"
    )
    Request = Fibonacci_SendGoal_Request
    Response = Fibonacci_SendGoal_Response
    Event = Fibonacci_SendGoal_Event


class Fibonacci_GetResult_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/action/Fibonacci_GetResult_Request``."""

    __ros_type__: ClassVar[str] = "example_interfaces/action/Fibonacci_GetResult_Request"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
    )

    goal_id: UUID = msgspec.field(default_factory=UUID)


class Fibonacci_GetResult_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/action/Fibonacci_GetResult_Response``."""

    __ros_type__: ClassVar[str] = "example_interfaces/action/Fibonacci_GetResult_Response"
    __ros_definition__: ClassVar[str] = (
        "int8 status\n"
        "example_interfaces/action/Fibonacci_Result result\n"
    )

    status: _int8 = 0
    result: Fibonacci_Result = msgspec.field(default_factory=Fibonacci_Result)


class Fibonacci_GetResult_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/action/Fibonacci_GetResult_Event``."""

    __ros_type__: ClassVar[str] = "example_interfaces/action/Fibonacci_GetResult_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "example_interfaces/action/Fibonacci_GetResult_Request[<=1] request\n"
        "example_interfaces/action/Fibonacci_GetResult_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[Fibonacci_GetResult_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[Fibonacci_GetResult_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class Fibonacci_GetResult:
    """``example_interfaces/action/Fibonacci_GetResult``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "example_interfaces/action/Fibonacci_GetResult"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
        "---\n"
        "int8 status\n"
        "example_interfaces/action/Fibonacci_Result result\n"
    )
    Request = Fibonacci_GetResult_Request
    Response = Fibonacci_GetResult_Response
    Event = Fibonacci_GetResult_Event


class Fibonacci_FeedbackMessage(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/action/Fibonacci_FeedbackMessage``."""

    __ros_type__: ClassVar[str] = "example_interfaces/action/Fibonacci_FeedbackMessage"
    __ros_definition__: ClassVar[str] = (
        "unique_identifier_msgs/UUID goal_id\n"
        "example_interfaces/action/Fibonacci_Feedback feedback\n"
    )

    goal_id: UUID = msgspec.field(default_factory=UUID)
    feedback: Fibonacci_Feedback = msgspec.field(default_factory=Fibonacci_Feedback)


class Fibonacci:
    """``example_interfaces/action/Fibonacci``: ``Goal``, ``Result``, ``Feedback``.

    ``Impl`` holds the types its wire protocol uses.
    """

    __ros_type__: ClassVar[str] = "example_interfaces/action/Fibonacci"
    __ros_definition__: ClassVar[str] = (
        "# Goal\n"
        "int32 order\n"
        "---\n"
        "# Result\n"
        "int32[] sequence\n"
        "---\n"
        "# Feedback\n"
        "int32[] sequence\n"
    )
    Goal = Fibonacci_Goal
    Result = Fibonacci_Result
    Feedback = Fibonacci_Feedback

    class Impl:
        """The services and topic types of the action's wire protocol."""

        SendGoalService = Fibonacci_SendGoal
        GetResultService = Fibonacci_GetResult
        FeedbackMessage = Fibonacci_FeedbackMessage
        CancelGoalService = CancelGoal
        GoalStatusMessage = GoalStatusArray
