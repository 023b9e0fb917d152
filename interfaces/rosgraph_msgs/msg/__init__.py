"""Generated from rosgraph_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from typing import ClassVar

import msgspec

from interfaces.builtin_interfaces.msg import Time

__all__ = [
    "Clock",
]


class Clock(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rosgraph_msgs/msg/Clock``."""

    __ros_type__: ClassVar[str] = "rosgraph_msgs/msg/Clock"
    __ros_definition__: ClassVar[str] = (
        "# This message communicates the current time.\n"
        "#\n"
        "# For more information, see https://design.ros2.org/articles/clock_and_time.html.\n"
        "builtin_interfaces/Time clock\n"
    )

    clock: Time = msgspec.field(default_factory=Time)
