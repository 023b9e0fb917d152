"""Generated from action_msgs/srv/*.srv by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.action_msgs.msg import GoalInfo
from interfaces.service_msgs.msg import ServiceEventInfo

__all__ = [
    "CancelGoal",
    "CancelGoal_Event",
    "CancelGoal_Request",
    "CancelGoal_Response",
]

_int8 = Annotated[int, msgspec.Meta(ge=-128, le=127)]


class CancelGoal_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``action_msgs/srv/CancelGoal_Request``."""

    __ros_type__: ClassVar[str] = "action_msgs/srv/CancelGoal_Request"
    __ros_definition__: ClassVar[str] = (
        "# Cancel one or more goals with the following policy:\n"
        "#\n"
        "# - If the goal ID is zero and timestamp is zero, cancel all goals.\n"
        "# - If the goal ID is zero and timestamp is not zero, cancel all goals accepted\n"
        "#   at or before the timestamp.\n"
        "# - If the goal ID is not zero and timestamp is zero, cancel the goal with the\n"
        "#   given ID regardless of the time it was accepted.\n"
        "# - If the goal ID is not zero and timestamp is not zero, cancel the goal with\n"
        "#   the given ID and all goals accepted at or before the timestamp.\n"
        "\n"
        "# Goal info describing the goals to cancel, see above.\n"
        "GoalInfo goal_info\n"
    )

    goal_info: GoalInfo = msgspec.field(default_factory=GoalInfo)


class CancelGoal_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``action_msgs/srv/CancelGoal_Response``."""

    __ros_type__: ClassVar[str] = "action_msgs/srv/CancelGoal_Response"
    __ros_definition__: ClassVar[str] = (
        "##\n"
        "## Return codes.\n"
        "##\n"
        "\n"
        "# Indicates the request was accepted without any errors.\n"
        "#\n"
        "# One or more goals have transitioned to the CANCELING state. The\n"
        "# goals_canceling list is not empty.\n"
        "int8 ERROR_NONE=0\n"
        "\n"
        "# Indicates the request was rejected.\n"
        "#\n"
        "# No goals have transitioned to the CANCELING state. The goals_canceling list is\n"
        "# empty.\n"
        "int8 ERROR_REJECTED=1\n"
        "\n"
        "# Indicates the requested goal ID does not exist.\n"
        "#\n"
        "# No goals have transitioned to the CANCELING state. The goals_canceling list is\n"
        "# empty.\n"
        "int8 ERROR_UNKNOWN_GOAL_ID=2\n"
        "\n"
        "# Indicates the goal is not cancelable because it is already in a terminal state.\n"
        "#\n"
        "# No goals have transitioned to the CANCELING state. The goals_canceling list is\n"
        "# empty.\n"
        "int8 ERROR_GOAL_TERMINATED=3\n"
        "\n"
        "# Return code, see above definitions.\n"
        "int8 return_code\n"
        "\n"
        "# Goals that accepted the cancel request.\n"
        "GoalInfo[] goals_canceling\n"
    )
    ERROR_NONE: ClassVar[int] = 0
    ERROR_REJECTED: ClassVar[int] = 1
    ERROR_UNKNOWN_GOAL_ID: ClassVar[int] = 2
    ERROR_GOAL_TERMINATED: ClassVar[int] = 3

    return_code: _int8 = 0
    goals_canceling: list[GoalInfo] = msgspec.field(default_factory=list)


class CancelGoal_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``action_msgs/srv/CancelGoal_Event``."""

    __ros_type__: ClassVar[str] = "action_msgs/srv/CancelGoal_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "action_msgs/srv/CancelGoal_Request[<=1] request\n"
        "action_msgs/srv/CancelGoal_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[CancelGoal_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[CancelGoal_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class CancelGoal:
    """``action_msgs/srv/CancelGoal``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "action_msgs/srv/CancelGoal"
    __ros_definition__: ClassVar[str] = (
        "# Cancel one or more goals with the following policy:\n"
        "#\n"
        "# - If the goal ID is zero and timestamp is zero, cancel all goals.\n"
        "# - If the goal ID is zero and timestamp is not zero, cancel all goals accepted\n"
        "#   at or before the timestamp.\n"
        "# - If the goal ID is not zero and timestamp is zero, cancel the goal with the\n"
        "#   given ID regardless of the time it was accepted.\n"
        "# - If the goal ID is not zero and timestamp is not zero, cancel the goal with\n"
        "#   the given ID and all goals accepted at or before the timestamp.\n"
        "\n"
        "# Goal info describing the goals to cancel, see above.\n"
        "GoalInfo goal_info\n"
        "---\n"
        "##\n"
        "## Return codes.\n"
        "##\n"
        "\n"
        "# Indicates the request was accepted without any errors.\n"
        "#\n"
        "# One or more goals have transitioned to the CANCELING state. The\n"
        "# goals_canceling list is not empty.\n"
        "int8 ERROR_NONE=0\n"
        "\n"
        "# Indicates the request was rejected.\n"
        "#\n"
        "# No goals have transitioned to the CANCELING state. The goals_canceling list is\n"
        "# empty.\n"
        "int8 ERROR_REJECTED=1\n"
        "\n"
        "# Indicates the requested goal ID does not exist.\n"
        "#\n"
        "# No goals have transitioned to the CANCELING state. The goals_canceling list is\n"
        "# empty.\n"
        "int8 ERROR_UNKNOWN_GOAL_ID=2\n"
        "\n"
        "# Indicates the goal is not cancelable because it is already in a terminal state.\n"
        "#\n"
        "# No goals have transitioned to the CANCELING state. The goals_canceling list is\n"
        "# empty.\n"
        "int8 ERROR_GOAL_TERMINATED=3\n"
        "\n"
        "# Return code, see above definitions.\n"
        "int8 return_code\n"
        "\n"
        "# Goals that accepted the cancel request.\n"
        "GoalInfo[] goals_canceling\n"
    )
    Request = CancelGoal_Request
    Response = CancelGoal_Response
    Event = CancelGoal_Event
