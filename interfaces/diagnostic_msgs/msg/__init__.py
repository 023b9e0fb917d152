"""Generated from diagnostic_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.std_msgs.msg import Header

__all__ = [
    "DiagnosticArray",
    "DiagnosticStatus",
    "KeyValue",
]

_uint8 = Annotated[int, msgspec.Meta(ge=0, le=255)]


class KeyValue(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``diagnostic_msgs/msg/KeyValue``."""

    __ros_type__: ClassVar[str] = "diagnostic_msgs/msg/KeyValue"
    __ros_definition__: ClassVar[str] = (
        "# What to label this value when viewing.\n"
        "string key\n"
        "# A value to track over time.\n"
        "string value\n"
    )

    key: str = ""
    value: str = ""


class DiagnosticStatus(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``diagnostic_msgs/msg/DiagnosticStatus``."""

    __ros_type__: ClassVar[str] = "diagnostic_msgs/msg/DiagnosticStatus"
    __ros_definition__: ClassVar[str] = (
        "# This message holds the status of an individual component of the robot.\n"
        "\n"
        "# Possible levels of operations.\n"
        "byte OK=0\n"
        "byte WARN=1\n"
        "byte ERROR=2\n"
        "byte STALE=3\n"
        "\n"
        "# Level of operation enumerated above.\n"
        "byte level\n"
        "# A description of the test/component reporting.\n"
        "string name\n"
        "# A description of the status.\n"
        "string message\n"
        "# A hardware unique string.\n"
        "string hardware_id\n"
        "# An array of values associated with the status.\n"
        "KeyValue[] values\n"
    )
    OK: ClassVar[int] = 0
    WARN: ClassVar[int] = 1
    ERROR: ClassVar[int] = 2
    STALE: ClassVar[int] = 3

    level: _uint8 = 0
    name: str = ""
    message: str = ""
    hardware_id: str = ""
    values: list[KeyValue] = msgspec.field(default_factory=list)


class DiagnosticArray(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``diagnostic_msgs/msg/DiagnosticArray``."""

    __ros_type__: ClassVar[str] = "diagnostic_msgs/msg/DiagnosticArray"
    __ros_definition__: ClassVar[str] = (
        "# This message is used to send diagnostic information about the state of the robot.\n"
        "std_msgs/Header header # for timestamp\n"
        "DiagnosticStatus[] status # an array of components being reported on\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    status: list[DiagnosticStatus] = msgspec.field(default_factory=list)
