"""Generated from builtin_interfaces/msg/*.msg by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

__all__ = [
    "Duration",
    "Time",
]

_int32 = Annotated[int, msgspec.Meta(ge=-2147483648, le=2147483647)]
_uint32 = Annotated[int, msgspec.Meta(ge=0, le=4294967295)]


class Duration(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``builtin_interfaces/msg/Duration``."""

    __ros_type__: ClassVar[str] = "builtin_interfaces/msg/Duration"
    __ros_definition__: ClassVar[str] = (
        "# Duration defines a period between two time points.\n"
        "# Messages of this datatype are of ROS Time following this design:\n"
        "# https://design.ros2.org/articles/clock_and_time.html\n"
        "\n"
        "# Seconds component, range is valid over any possible int32 value.\n"
        "int32 sec\n"
        "\n"
        "# Nanoseconds component in the range of [0, 1e9).\n"
        "uint32 nanosec\n"
    )

    sec: _int32 = 0
    nanosec: _uint32 = 0


class Time(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``builtin_interfaces/msg/Time``."""

    __ros_type__: ClassVar[str] = "builtin_interfaces/msg/Time"
    __ros_definition__: ClassVar[str] = (
        "# This message communicates ROS Time defined here:\n"
        "# https://design.ros2.org/articles/clock_and_time.html\n"
        "\n"
        "# The seconds component, valid over all int32 values.\n"
        "int32 sec\n"
        "\n"
        "# The nanoseconds component, valid in the range [0, 1e9).\n"
        "uint32 nanosec\n"
    )

    sec: _int32 = 0
    nanosec: _uint32 = 0
