"""Generated from actionlib_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.builtin_interfaces.msg import Time
from interfaces.std_msgs.msg import Header

__all__ = [
    "GoalID",
    "GoalStatus",
    "GoalStatusArray",
]

_uint8 = Annotated[int, msgspec.Meta(ge=0, le=255)]


class GoalID(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``actionlib_msgs/msg/GoalID``."""

    __ros_type__: ClassVar[str] = "actionlib_msgs/msg/GoalID"
    __ros_definition__: ClassVar[str] = (
        "\n"
        "# The stamp should store the time at which this goal was requested.\n"
        "# It is used by an action server when it tries to preempt all\n"
        "# goals that were requested before a certain time\n"
        "builtin_interfaces/Time stamp\n"
        "\n"
        "# The id provides a way to associate feedback and\n"
        "# result message with specific goal requests. The id\n"
        "# specified must be unique.\n"
        "string id\n"
    )

    stamp: Time = msgspec.field(default_factory=Time)
    id: str = ""


class GoalStatus(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``actionlib_msgs/msg/GoalStatus``."""

    __ros_type__: ClassVar[str] = "actionlib_msgs/msg/GoalStatus"
    __ros_definition__: ClassVar[str] = (
        "GoalID goal_id\n"
        "uint8 status\n"
        "uint8 PENDING         = 0   # The goal has yet to be processed by the action server.\n"
        "uint8 ACTIVE          = 1   # The goal is currently being processed by the action server.\n"
        "uint8 PREEMPTED       = 2   # The goal received a cancel request after it started executing\n"
        "                            #   and has since completed its execution (Terminal State).\n"
        "uint8 SUCCEEDED       = 3   # The goal was achieved successfully by the action server\n"
        "                            #   (Terminal State).\n"
        "uint8 ABORTED         = 4   # The goal was aborted during execution by the action server due\n"
        "                            #    to some failure (Terminal State).\n"
        "uint8 REJECTED        = 5   # The goal was rejected by the action server without being processed,\n"
        "                            #    because the goal was unattainable or invalid (Terminal State).\n"
        "uint8 PREEMPTING      = 6   # The goal received a cancel request after it started executing\n"
        "                            #    and has not yet completed execution.\n"
        "uint8 RECALLING       = 7   # The goal received a cancel request before it started executing, but\n"
        "                            #    the action server has not yet confirmed that the goal is canceled.\n"
        "uint8 RECALLED        = 8   # The goal received a cancel request before it started executing\n"
        "                            #    and was successfully cancelled (Terminal State).\n"
        "uint8 LOST            = 9   # An action client can determine that a goal is LOST. This should not\n"
        "                            #    be sent over the wire by an action server.\n"
        "\n"
        "# Allow for the user to associate a string with GoalStatus for debugging.\n"
        "string text\n"
    )
    PENDING: ClassVar[int] = 0
    ACTIVE: ClassVar[int] = 1
    PREEMPTED: ClassVar[int] = 2
    SUCCEEDED: ClassVar[int] = 3
    ABORTED: ClassVar[int] = 4
    REJECTED: ClassVar[int] = 5
    PREEMPTING: ClassVar[int] = 6
    RECALLING: ClassVar[int] = 7
    RECALLED: ClassVar[int] = 8
    LOST: ClassVar[int] = 9

    goal_id: GoalID = msgspec.field(default_factory=GoalID)
    status: _uint8 = 0
    text: str = ""


class GoalStatusArray(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``actionlib_msgs/msg/GoalStatusArray``."""

    __ros_type__: ClassVar[str] = "actionlib_msgs/msg/GoalStatusArray"
    __ros_definition__: ClassVar[str] = (
        "# Stores the statuses for goals that are currently being tracked\n"
        "# by an action server\n"
        "std_msgs/Header header\n"
        "GoalStatus[] status_list\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    status_list: list[GoalStatus] = msgspec.field(default_factory=list)
