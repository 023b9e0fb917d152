"""Generated from action_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.builtin_interfaces.msg import Time
from interfaces.unique_identifier_msgs.msg import UUID

__all__ = [
    "GoalInfo",
    "GoalStatus",
    "GoalStatusArray",
]

_int8 = Annotated[int, msgspec.Meta(ge=-128, le=127)]


class GoalInfo(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``action_msgs/msg/GoalInfo``."""

    __ros_type__: ClassVar[str] = "action_msgs/msg/GoalInfo"
    __ros_definition__: ClassVar[str] = (
        "# Goal ID\n"
        "unique_identifier_msgs/UUID goal_id\n"
        "\n"
        "# Time when the goal was accepted\n"
        "builtin_interfaces/Time stamp\n"
    )

    goal_id: UUID = msgspec.field(default_factory=UUID)
    stamp: Time = msgspec.field(default_factory=Time)


class GoalStatus(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``action_msgs/msg/GoalStatus``."""

    __ros_type__: ClassVar[str] = "action_msgs/msg/GoalStatus"
    __ros_definition__: ClassVar[str] = (
        "# An action goal can be in one of these states after it is accepted by an action\n"
        "# server.\n"
        "#\n"
        "# For more information, see http://design.ros2.org/articles/actions.html\n"
        "\n"
        "# Indicates status has not been properly set.\n"
        "int8 STATUS_UNKNOWN   = 0\n"
        "\n"
        "# The goal has been accepted and is awaiting execution.\n"
        "int8 STATUS_ACCEPTED  = 1\n"
        "\n"
        "# The goal is currently being executed by the action server.\n"
        "int8 STATUS_EXECUTING = 2\n"
        "\n"
        "# The client has requested that the goal be canceled and the action server has\n"
        "# accepted the cancel request.\n"
        "int8 STATUS_CANCELING = 3\n"
        "\n"
        "# The goal was achieved successfully by the action server.\n"
        "int8 STATUS_SUCCEEDED = 4\n"
        "\n"
        "# The goal was canceled after an external request from an action client.\n"
        "int8 STATUS_CANCELED  = 5\n"
        "\n"
        "# The goal was terminated by the action server without an external request.\n"
        "int8 STATUS_ABORTED   = 6\n"
        "\n"
        "# Goal info (contains ID and timestamp).\n"
        "GoalInfo goal_info\n"
        "\n"
        "# Action goal state-machine status.\n"
        "int8 status\n"
    )
    STATUS_UNKNOWN: ClassVar[int] = 0
    STATUS_ACCEPTED: ClassVar[int] = 1
    STATUS_EXECUTING: ClassVar[int] = 2
    STATUS_CANCELING: ClassVar[int] = 3
    STATUS_SUCCEEDED: ClassVar[int] = 4
    STATUS_CANCELED: ClassVar[int] = 5
    STATUS_ABORTED: ClassVar[int] = 6

    goal_info: GoalInfo = msgspec.field(default_factory=GoalInfo)
    status: _int8 = 0


class GoalStatusArray(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``action_msgs/msg/GoalStatusArray``."""

    __ros_type__: ClassVar[str] = "action_msgs/msg/GoalStatusArray"
    __ros_definition__: ClassVar[str] = (
        "# An array of goal statuses.\n"
        "GoalStatus[] status_list\n"
    )

    status_list: list[GoalStatus] = msgspec.field(default_factory=list)
