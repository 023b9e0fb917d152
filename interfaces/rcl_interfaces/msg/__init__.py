"""Generated from rcl_interfaces/msg/*.msg by `python -m actors interface generate`; do not edit."""

from array import array
from collections.abc import MutableSequence
from typing import Annotated, ClassVar

import msgspec

from actors.messages.arrays import held
from interfaces.builtin_interfaces.msg import Time

__all__ = [
    "FloatingPointRange",
    "IntegerRange",
    "ListParametersResult",
    "Log",
    "LoggerLevel",
    "Parameter",
    "ParameterDescriptor",
    "ParameterEvent",
    "ParameterEventDescriptors",
    "ParameterType",
    "ParameterValue",
    "SetLoggerLevelsResult",
    "SetParametersResult",
]

_uint8 = Annotated[int, msgspec.Meta(ge=0, le=255)]
_uint32 = Annotated[int, msgspec.Meta(ge=0, le=4294967295)]
_int64 = Annotated[int, msgspec.Meta(ge=-9223372036854775808, le=9223372036854775807)]
_uint64 = Annotated[int, msgspec.Meta(ge=0)]


class FloatingPointRange(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/msg/FloatingPointRange``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/msg/FloatingPointRange"
    __ros_definition__: ClassVar[str] = (
        "# Represents bounds and a step value for a floating point typed parameter.\n"
        "\n"
        "# Start value for valid values, inclusive.\n"
        "float64 from_value\n"
        "\n"
        "# End value for valid values, inclusive.\n"
        "float64 to_value\n"
        "\n"
        "# Size of valid steps between the from and to bound.\n"
        "# \n"
        "# Step is considered to be a magnitude, therefore negative values are treated\n"
        "# the same as positive values, and a step value of zero implies a continuous\n"
        "# range of values.\n"
        "#\n"
        "# Ideally, the step would be less than or equal to the distance between the\n"
        "# bounds, as well as an even multiple of the distance between the bounds, but\n"
        "# neither are required.\n"
        "#\n"
        "# If the absolute value of the step is larger than or equal to the distance\n"
        "# between the two bounds, then the bounds will be the only valid values. e.g. if\n"
        "# the range is defined as {from_value: 1.0, to_value: 2.0, step: 5.0} then the\n"
        "# valid values will be 1.0 and 2.0.\n"
        "#\n"
        "# If the step is less than the distance between the bounds, but the distance is\n"
        "# not a multiple of the step, then the \"to\" bound will always be a valid value,\n"
        "# e.g. if the range is defined as {from_value: 2.0, to_value: 5.0, step: 2.0}\n"
        "# then the valid values will be 2.0, 4.0, and 5.0.\n"
        "float64 step\n"
    )

    from_value: float = 0.0
    to_value: float = 0.0
    step: float = 0.0


class IntegerRange(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/msg/IntegerRange``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/msg/IntegerRange"
    __ros_definition__: ClassVar[str] = (
        "# Represents bounds and a step value for an integer typed parameter.\n"
        "\n"
        "# Start value for valid values, inclusive.\n"
        "int64 from_value\n"
        "\n"
        "# End value for valid values, inclusive.\n"
        "int64 to_value\n"
        "\n"
        "# Size of valid steps between the from and to bound.\n"
        "#\n"
        "# A step value of zero implies a continuous range of values. Ideally, the step\n"
        "# would be less than or equal to the distance between the bounds, as well as an\n"
        "# even multiple of the distance between the bounds, but neither are required.\n"
        "#\n"
        "# If the absolute value of the step is larger than or equal to the distance\n"
        "# between the two bounds, then the bounds will be the only valid values. e.g. if\n"
        "# the range is defined as {from_value: 1, to_value: 2, step: 5} then the valid\n"
        "# values will be 1 and 2.\n"
        "# \n"
        "# If the step is less than the distance between the bounds, but the distance is\n"
        "# not a multiple of the step, then the \"to\" bound will always be a valid value,\n"
        "# e.g. if the range is defined as {from_value: 2, to_value: 5, step: 2} then\n"
        "# the valid values will be 2, 4, and 5.\n"
        "uint64 step\n"
    )

    from_value: _int64 = 0
    to_value: _int64 = 0
    step: _uint64 = 0


class ListParametersResult(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/msg/ListParametersResult``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/msg/ListParametersResult"
    __ros_definition__: ClassVar[str] = (
        "# The resulting parameters under the given prefixes.\n"
        "string[] names\n"
        "\n"
        "# The resulting prefixes under the given prefixes.\n"
        "# TODO(wjwwood): link to prefix definition and rules.\n"
        "string[] prefixes\n"
    )

    names: list[str] = msgspec.field(default_factory=list)
    prefixes: list[str] = msgspec.field(default_factory=list)


class Log(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/msg/Log``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/msg/Log"
    __ros_definition__: ClassVar[str] = (
        "##\n"
        "## Severity level constants\n"
        "## \n"
        "## These logging levels follow the Python Standard\n"
        "## https://docs.python.org/3/library/logging.html#logging-levels\n"
        "## And are implemented in rcutils as well\n"
        "## https://github.com/ros2/rcutils/blob/35f29850064e0c33a4063cbc947ebbfeada11dba/include/rcutils/logging.h#L164-L172\n"
        "## This leaves space for other standard logging levels to be inserted in the middle in the future,\n"
        "## as well as custom user defined levels.\n"
        "## Since there are several other logging enumeration standard for different implementations,\n"
        "## other logging implementations may need to provide level mappings to match their internal implementations.\n"
        "##\n"
        "\n"
        "# Debug is for pedantic information, which is useful when debugging issues.\n"
        "uint8 DEBUG=10\n"
        "\n"
        "# Info is the standard informational level and is used to report expected\n"
        "# information.\n"
        "uint8 INFO=20\n"
        "\n"
        "# Warning is for information that may potentially cause issues or possibly unexpected\n"
        "# behavior.\n"
        "uint8 WARN=30\n"
        "\n"
        "# Error is for information that this node cannot resolve.\n"
        "uint8 ERROR=40\n"
        "\n"
        "# Information about a impending node shutdown.\n"
        "uint8 FATAL=50\n"
        "\n"
        "##\n"
        "## Fields\n"
        "##\n"
        "\n"
        "# Timestamp when this message was generated by the node.\n"
        "builtin_interfaces/Time stamp\n"
        "\n"
        "# Corresponding log level, see above definitions.\n"
        "uint8 level\n"
        "\n"
        "# The name representing the logger this message came from.\n"
        "string name\n"
        "\n"
        "# The full log message.\n"
        "string msg\n"
        "\n"
        "# The file the message came from.\n"
        "string file\n"
        "\n"
        "# The function the message came from.\n"
        "string function\n"
        "\n"
        "# The line in the file the message came from.\n"
        "uint32 line\n"
    )
    DEBUG: ClassVar[int] = 10
    INFO: ClassVar[int] = 20
    WARN: ClassVar[int] = 30
    ERROR: ClassVar[int] = 40
    FATAL: ClassVar[int] = 50

    stamp: Time = msgspec.field(default_factory=Time)
    level: _uint8 = 0
    name: str = ""
    msg: str = ""
    file: str = ""
    function: str = ""
    line: _uint32 = 0


class LoggerLevel(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/msg/LoggerLevel``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/msg/LoggerLevel"
    __ros_definition__: ClassVar[str] = (
        "# All available logger levels; these correspond to the enum in rcutils/logger.h\n"
        "\n"
        "uint8 LOG_LEVEL_UNKNOWN = 0\n"
        "uint8 LOG_LEVEL_DEBUG = 10\n"
        "uint8 LOG_LEVEL_INFO = 20\n"
        "uint8 LOG_LEVEL_WARN = 30\n"
        "uint8 LOG_LEVEL_ERROR = 40\n"
        "uint8 LOG_LEVEL_FATAL = 50\n"
        "\n"
        "# The logger name.\n"
        "string name\n"
        "\n"
        "# The logger level\n"
        "uint32 level\n"
    )
    LOG_LEVEL_UNKNOWN: ClassVar[int] = 0
    LOG_LEVEL_DEBUG: ClassVar[int] = 10
    LOG_LEVEL_INFO: ClassVar[int] = 20
    LOG_LEVEL_WARN: ClassVar[int] = 30
    LOG_LEVEL_ERROR: ClassVar[int] = 40
    LOG_LEVEL_FATAL: ClassVar[int] = 50

    name: str = ""
    level: _uint32 = 0


class ParameterValue(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/msg/ParameterValue``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/msg/ParameterValue"
    __ros_definition__: ClassVar[str] = (
        "# Used to determine which of the next *_value fields are set.\n"
        "# ParameterType.PARAMETER_NOT_SET indicates that the parameter was not set\n"
        "# (if gotten) or is uninitialized.\n"
        "# Values are enumerated in `ParameterType.msg`.\n"
        "\n"
        "# The type of this parameter, which corresponds to the appropriate field below.\n"
        "uint8 type\n"
        "\n"
        "# \"Variant\" style storage of the parameter value. Only the value corresponding\n"
        "# the type field will have valid information.\n"
        "\n"
        "# Boolean value, can be either true or false.\n"
        "bool bool_value\n"
        "\n"
        "# Integer value ranging from -9,223,372,036,854,775,808 to\n"
        "# 9,223,372,036,854,775,807.\n"
        "int64 integer_value\n"
        "\n"
        "# A double precision floating point value following IEEE 754.\n"
        "float64 double_value\n"
        "\n"
        "# A textual value with no practical length limit.\n"
        "string string_value\n"
        "\n"
        "# An array of bytes, used for non-textual information.\n"
        "byte[] byte_array_value\n"
        "\n"
        "# An array of boolean values.\n"
        "bool[] bool_array_value\n"
        "\n"
        "# An array of 64-bit integer values.\n"
        "int64[] integer_array_value\n"
        "\n"
        "# An array of 64-bit floating point values.\n"
        "float64[] double_array_value\n"
        "\n"
        "# An array of string values.\n"
        "string[] string_array_value\n"
    )

    type: _uint8 = 0
    bool_value: bool = False
    integer_value: _int64 = 0
    double_value: float = 0.0
    string_value: str = ""
    byte_array_value: bytes = b""
    bool_array_value: list[bool] = msgspec.field(default_factory=list)
    integer_array_value: MutableSequence[_int64] = msgspec.field(default_factory=lambda: array("q"))
    double_array_value: MutableSequence[float] = msgspec.field(default_factory=lambda: array("d"))
    string_array_value: list[str] = msgspec.field(default_factory=list)

    def __post_init__(self) -> None:
        if type(self.integer_array_value) is not array or self.integer_array_value.typecode != "q":
            self.integer_array_value = held(self.integer_array_value, "q")
        if type(self.double_array_value) is not array or self.double_array_value.typecode != "d":
            self.double_array_value = held(self.double_array_value, "d")


class Parameter(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/msg/Parameter``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/msg/Parameter"
    __ros_definition__: ClassVar[str] = (
        "# This is the message to communicate a parameter. It is an open struct with an enum in\n"
        "# the descriptor to select which value is active.\n"
        "\n"
        "# The full name of the parameter.\n"
        "string name\n"
        "\n"
        "# The parameter's value which can be one of several types, see\n"
        "# `ParameterValue.msg` and `ParameterType.msg`.\n"
        "ParameterValue value\n"
    )

    name: str = ""
    value: ParameterValue = msgspec.field(default_factory=ParameterValue)


class ParameterDescriptor(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/msg/ParameterDescriptor``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/msg/ParameterDescriptor"
    __ros_definition__: ClassVar[str] = (
        "# This is the message to communicate a parameter's descriptor.\n"
        "\n"
        "# The name of the parameter.\n"
        "string name\n"
        "\n"
        "# Enum values are defined in the `ParameterType.msg` message.\n"
        "uint8 type\n"
        "\n"
        "# Description of the parameter, visible from introspection tools.\n"
        "string description\n"
        "\n"
        "# Parameter constraints\n"
        "\n"
        "# Plain English description of additional constraints which cannot be expressed\n"
        "# with the available constraints, e.g. \"only prime numbers\".\n"
        "#\n"
        "# By convention, this should only be used to clarify constraints which cannot\n"
        "# be completely expressed with the parameter constraints below.\n"
        "string additional_constraints\n"
        "\n"
        "# If 'true' then the value cannot change after it has been initialized.\n"
        "bool read_only false\n"
        "\n"
        "# If true, the parameter is allowed to change type.\n"
        "bool dynamic_typing false\n"
        "\n"
        "# If any of the following sequences are not empty, then the constraint inside of\n"
        "# them apply to this parameter.\n"
        "#\n"
        "# FloatingPointRange and IntegerRange are mutually exclusive.\n"
        "\n"
        "# FloatingPointRange consists of a from_value, a to_value, and a step.\n"
        "FloatingPointRange[<=1] floating_point_range\n"
        "\n"
        "# IntegerRange consists of a from_value, a to_value, and a step.\n"
        "IntegerRange[<=1] integer_range\n"
    )

    name: str = ""
    type: _uint8 = 0
    description: str = ""
    additional_constraints: str = ""
    read_only: bool = False
    dynamic_typing: bool = False
    floating_point_range: Annotated[list[FloatingPointRange], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    integer_range: Annotated[list[IntegerRange], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class ParameterEvent(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/msg/ParameterEvent``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/msg/ParameterEvent"
    __ros_definition__: ClassVar[str] = (
        "# This message contains a parameter event.\n"
        "# Because the parameter event was an atomic update, a specific parameter name\n"
        "# can only be in one of the three sets.\n"
        "\n"
        "# The time stamp when this parameter event occurred.\n"
        "builtin_interfaces/Time stamp\n"
        "\n"
        "# Fully qualified ROS path to node.\n"
        "string node\n"
        "\n"
        "# New parameters that have been set for this node.\n"
        "Parameter[] new_parameters\n"
        "\n"
        "# Parameters that have been changed during this event.\n"
        "Parameter[] changed_parameters\n"
        "\n"
        "# Parameters that have been deleted during this event.\n"
        "Parameter[] deleted_parameters\n"
    )

    stamp: Time = msgspec.field(default_factory=Time)
    node: str = ""
    new_parameters: list[Parameter] = msgspec.field(default_factory=list)
    changed_parameters: list[Parameter] = msgspec.field(default_factory=list)
    deleted_parameters: list[Parameter] = msgspec.field(default_factory=list)


class ParameterEventDescriptors(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/msg/ParameterEventDescriptors``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/msg/ParameterEventDescriptors"
    __ros_definition__: ClassVar[str] = (
        "# This message contains descriptors of a parameter event.\n"
        "# It was an atomic update.\n"
        "# A specific parameter name can only be in one of the three sets.\n"
        "\n"
        "ParameterDescriptor[] new_parameters\n"
        "ParameterDescriptor[] changed_parameters\n"
        "ParameterDescriptor[] deleted_parameters\n"
    )

    new_parameters: list[ParameterDescriptor] = msgspec.field(default_factory=list)
    changed_parameters: list[ParameterDescriptor] = msgspec.field(default_factory=list)
    deleted_parameters: list[ParameterDescriptor] = msgspec.field(default_factory=list)


class ParameterType(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/msg/ParameterType``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/msg/ParameterType"
    __ros_definition__: ClassVar[str] = (
        "# These types correspond to the value that is set in the ParameterValue message.\n"
        "\n"
        "# Default value, which implies this is not a valid parameter.\n"
        "uint8 PARAMETER_NOT_SET=0\n"
        "\n"
        "uint8 PARAMETER_BOOL=1\n"
        "uint8 PARAMETER_INTEGER=2\n"
        "uint8 PARAMETER_DOUBLE=3\n"
        "uint8 PARAMETER_STRING=4\n"
        "uint8 PARAMETER_BYTE_ARRAY=5\n"
        "uint8 PARAMETER_BOOL_ARRAY=6\n"
        "uint8 PARAMETER_INTEGER_ARRAY=7\n"
        "uint8 PARAMETER_DOUBLE_ARRAY=8\n"
        "uint8 PARAMETER_STRING_ARRAY=9\n"
    )
    PARAMETER_NOT_SET: ClassVar[int] = 0
    PARAMETER_BOOL: ClassVar[int] = 1
    PARAMETER_INTEGER: ClassVar[int] = 2
    PARAMETER_DOUBLE: ClassVar[int] = 3
    PARAMETER_STRING: ClassVar[int] = 4
    PARAMETER_BYTE_ARRAY: ClassVar[int] = 5
    PARAMETER_BOOL_ARRAY: ClassVar[int] = 6
    PARAMETER_INTEGER_ARRAY: ClassVar[int] = 7
    PARAMETER_DOUBLE_ARRAY: ClassVar[int] = 8
    PARAMETER_STRING_ARRAY: ClassVar[int] = 9


class SetLoggerLevelsResult(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/msg/SetLoggerLevelsResult``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/msg/SetLoggerLevelsResult"
    __ros_definition__: ClassVar[str] = (
        "# True when succeed, false when failed.\n"
        "bool successful\n"
        "\n"
        "# Reason why the setting was either successful or a failure.\n"
        "string reason\n"
    )

    successful: bool = False
    reason: str = ""


class SetParametersResult(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/msg/SetParametersResult``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/msg/SetParametersResult"
    __ros_definition__: ClassVar[str] = (
        "# A true value of the same index indicates that the parameter was set\n"
        "# successfully. A false value indicates the change was rejected.\n"
        "bool successful\n"
        "\n"
        "# Reason why the setting was a failure. On success, the contents of this field\n"
        "# are undefined.  This should only be used for logging and user interfaces.\n"
        "string reason\n"
    )

    successful: bool = False
    reason: str = ""
