"""Generated from rcl_interfaces/srv/*.srv by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.rcl_interfaces.msg import (
    ListParametersResult,
    LoggerLevel,
    Parameter,
    ParameterDescriptor,
    ParameterValue,
    SetLoggerLevelsResult,
    SetParametersResult,
)
from interfaces.service_msgs.msg import ServiceEventInfo

__all__ = [
    "DescribeParameters",
    "DescribeParameters_Event",
    "DescribeParameters_Request",
    "DescribeParameters_Response",
    "GetLoggerLevels",
    "GetLoggerLevels_Event",
    "GetLoggerLevels_Request",
    "GetLoggerLevels_Response",
    "GetParameterTypes",
    "GetParameterTypes_Event",
    "GetParameterTypes_Request",
    "GetParameterTypes_Response",
    "GetParameters",
    "GetParameters_Event",
    "GetParameters_Request",
    "GetParameters_Response",
    "ListParameters",
    "ListParameters_Event",
    "ListParameters_Request",
    "ListParameters_Response",
    "SetLoggerLevels",
    "SetLoggerLevels_Event",
    "SetLoggerLevels_Request",
    "SetLoggerLevels_Response",
    "SetParameters",
    "SetParametersAtomically",
    "SetParametersAtomically_Event",
    "SetParametersAtomically_Request",
    "SetParametersAtomically_Response",
    "SetParameters_Event",
    "SetParameters_Request",
    "SetParameters_Response",
]

_uint64 = Annotated[int, msgspec.Meta(ge=0)]


class DescribeParameters_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/DescribeParameters_Request``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/DescribeParameters_Request"
    __ros_definition__: ClassVar[str] = (
        "# A list of parameters of which to get the descriptor.\n"
        "string[] names\n"
        "\n"
    )

    names: list[str] = msgspec.field(default_factory=list)


class DescribeParameters_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/DescribeParameters_Response``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/DescribeParameters_Response"
    __ros_definition__: ClassVar[str] = (
        "# A list of the descriptors of all parameters requested in the same order\n"
        "# as they were requested. This list has the same length as the list of\n"
        "# parameters requested.\n"
        "ParameterDescriptor[] descriptors\n"
    )

    descriptors: list[ParameterDescriptor] = msgspec.field(default_factory=list)


class DescribeParameters_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/DescribeParameters_Event``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/DescribeParameters_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "rcl_interfaces/srv/DescribeParameters_Request[<=1] request\n"
        "rcl_interfaces/srv/DescribeParameters_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[DescribeParameters_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[DescribeParameters_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class DescribeParameters:
    """``rcl_interfaces/srv/DescribeParameters``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/DescribeParameters"
    __ros_definition__: ClassVar[str] = (
        "# A list of parameters of which to get the descriptor.\n"
        "string[] names\n"
        "\n"
        "---\n"
        "# A list of the descriptors of all parameters requested in the same order\n"
        "# as they were requested. This list has the same length as the list of\n"
        "# parameters requested.\n"
        "ParameterDescriptor[] descriptors\n"
    )
    Request = DescribeParameters_Request
    Response = DescribeParameters_Response
    Event = DescribeParameters_Event


class GetLoggerLevels_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/GetLoggerLevels_Request``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/GetLoggerLevels_Request"
    __ros_definition__: ClassVar[str] = (
        "# A list of logger names to get.\n"
        "string[] names\n"
        "\n"
    )

    names: list[str] = msgspec.field(default_factory=list)


class GetLoggerLevels_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/GetLoggerLevels_Response``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/GetLoggerLevels_Response"
    __ros_definition__: ClassVar[str] = (
        "# List of logger levels which is the same order as the provided names. If a\n"
        "# logger was not yet set, the value will have 'unknown' as the value.\n"
        "LoggerLevel[] levels\n"
    )

    levels: list[LoggerLevel] = msgspec.field(default_factory=list)


class GetLoggerLevels_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/GetLoggerLevels_Event``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/GetLoggerLevels_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "rcl_interfaces/srv/GetLoggerLevels_Request[<=1] request\n"
        "rcl_interfaces/srv/GetLoggerLevels_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[GetLoggerLevels_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[GetLoggerLevels_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class GetLoggerLevels:
    """``rcl_interfaces/srv/GetLoggerLevels``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/GetLoggerLevels"
    __ros_definition__: ClassVar[str] = (
        "# A list of logger names to get.\n"
        "string[] names\n"
        "\n"
        "---\n"
        "# List of logger levels which is the same order as the provided names. If a\n"
        "# logger was not yet set, the value will have 'unknown' as the value.\n"
        "LoggerLevel[] levels\n"
    )
    Request = GetLoggerLevels_Request
    Response = GetLoggerLevels_Response
    Event = GetLoggerLevels_Event


class GetParameterTypes_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/GetParameterTypes_Request``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/GetParameterTypes_Request"
    __ros_definition__: ClassVar[str] = (
        "# A list of parameter names.\n"
        "# TODO(wjwwood): link to parameter naming rules.\n"
        "string[] names\n"
        "\n"
    )

    names: list[str] = msgspec.field(default_factory=list)


class GetParameterTypes_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/GetParameterTypes_Response``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/GetParameterTypes_Response"
    __ros_definition__: ClassVar[str] = (
        "# List of types which is the same length and order as the provided names.\n"
        "#\n"
        "# The type enum is defined in ParameterType.msg. ParameterType.PARAMETER_NOT_SET\n"
        "# indicates that the parameter is not currently set.\n"
        "uint8[] types\n"
    )

    types: bytes = b""


class GetParameterTypes_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/GetParameterTypes_Event``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/GetParameterTypes_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "rcl_interfaces/srv/GetParameterTypes_Request[<=1] request\n"
        "rcl_interfaces/srv/GetParameterTypes_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[GetParameterTypes_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[GetParameterTypes_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class GetParameterTypes:
    """``rcl_interfaces/srv/GetParameterTypes``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/GetParameterTypes"
    __ros_definition__: ClassVar[str] = (
        "# A list of parameter names.\n"
        "# TODO(wjwwood): link to parameter naming rules.\n"
        "string[] names\n"
        "\n"
        "---\n"
        "# List of types which is the same length and order as the provided names.\n"
        "#\n"
        "# The type enum is defined in ParameterType.msg. ParameterType.PARAMETER_NOT_SET\n"
        "# indicates that the parameter is not currently set.\n"
        "uint8[] types\n"
    )
    Request = GetParameterTypes_Request
    Response = GetParameterTypes_Response
    Event = GetParameterTypes_Event


class GetParameters_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/GetParameters_Request``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/GetParameters_Request"
    __ros_definition__: ClassVar[str] = (
        "# TODO(wjwwood): Decide on the rules for grouping, nodes, and parameter \"names\"\n"
        "# in general, then link to that.\n"
        "#\n"
        "# For more information about parameters and naming rules, see:\n"
        "# https://design.ros2.org/articles/ros_parameters.html\n"
        "# https://github.com/ros2/design/pull/241\n"
        "\n"
        "# A list of parameter names to get.\n"
        "string[] names\n"
        "\n"
    )

    names: list[str] = msgspec.field(default_factory=list)


class GetParameters_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/GetParameters_Response``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/GetParameters_Response"
    __ros_definition__: ClassVar[str] = (
        "# List of values which is the same length and order as the provided names. If a\n"
        "# parameter was not yet set, the value will have PARAMETER_NOT_SET as the\n"
        "# type.\n"
        "ParameterValue[] values\n"
    )

    values: list[ParameterValue] = msgspec.field(default_factory=list)


class GetParameters_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/GetParameters_Event``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/GetParameters_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "rcl_interfaces/srv/GetParameters_Request[<=1] request\n"
        "rcl_interfaces/srv/GetParameters_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[GetParameters_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[GetParameters_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class GetParameters:
    """``rcl_interfaces/srv/GetParameters``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/GetParameters"
    __ros_definition__: ClassVar[str] = (
        "# TODO(wjwwood): Decide on the rules for grouping, nodes, and parameter \"names\"\n"
        "# in general, then link to that.\n"
        "#\n"
        "# For more information about parameters and naming rules, see:\n"
        "# https://design.ros2.org/articles/ros_parameters.html\n"
        "# https://github.com/ros2/design/pull/241\n"
        "\n"
        "# A list of parameter names to get.\n"
        "string[] names\n"
        "\n"
        "---\n"
        "# List of values which is the same length and order as the provided names. If a\n"
        "# parameter was not yet set, the value will have PARAMETER_NOT_SET as the\n"
        "# type.\n"
        "ParameterValue[] values\n"
    )
    Request = GetParameters_Request
    Response = GetParameters_Response
    Event = GetParameters_Event


class ListParameters_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/ListParameters_Request``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/ListParameters_Request"
    __ros_definition__: ClassVar[str] = (
        "# Recursively get parameters with unlimited depth.\n"
        "uint64 DEPTH_RECURSIVE=0\n"
        "\n"
        "# The list of parameter prefixes to query.\n"
        "string[] prefixes\n"
        "\n"
        "# Relative depth from given prefixes to return.\n"
        "#\n"
        "# Use DEPTH_RECURSIVE to get the recursive parameters and prefixes for each prefix.\n"
        "uint64 depth\n"
        "\n"
    )
    DEPTH_RECURSIVE: ClassVar[int] = 0

    prefixes: list[str] = msgspec.field(default_factory=list)
    depth: _uint64 = 0


class ListParameters_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/ListParameters_Response``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/ListParameters_Response"
    __ros_definition__: ClassVar[str] = (
        "# The list of parameter names and their prefixes.\n"
        "ListParametersResult result\n"
    )

    result: ListParametersResult = msgspec.field(default_factory=ListParametersResult)


class ListParameters_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/ListParameters_Event``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/ListParameters_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "rcl_interfaces/srv/ListParameters_Request[<=1] request\n"
        "rcl_interfaces/srv/ListParameters_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[ListParameters_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[ListParameters_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class ListParameters:
    """``rcl_interfaces/srv/ListParameters``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/ListParameters"
    __ros_definition__: ClassVar[str] = (
        "# Recursively get parameters with unlimited depth.\n"
        "uint64 DEPTH_RECURSIVE=0\n"
        "\n"
        "# The list of parameter prefixes to query.\n"
        "string[] prefixes\n"
        "\n"
        "# Relative depth from given prefixes to return.\n"
        "#\n"
        "# Use DEPTH_RECURSIVE to get the recursive parameters and prefixes for each prefix.\n"
        "uint64 depth\n"
        "\n"
        "---\n"
        "# The list of parameter names and their prefixes.\n"
        "ListParametersResult result\n"
    )
    Request = ListParameters_Request
    Response = ListParameters_Response
    Event = ListParameters_Event


class SetLoggerLevels_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/SetLoggerLevels_Request``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/SetLoggerLevels_Request"
    __ros_definition__: ClassVar[str] = (
        "# A list of loggers to set.\n"
        "LoggerLevel[] levels\n"
        "\n"
    )

    levels: list[LoggerLevel] = msgspec.field(default_factory=list)


class SetLoggerLevels_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/SetLoggerLevels_Response``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/SetLoggerLevels_Response"
    __ros_definition__: ClassVar[str] = (
        "# Indicates whether setting each logger succeeded or not and why.\n"
        "SetLoggerLevelsResult[] results\n"
    )

    results: list[SetLoggerLevelsResult] = msgspec.field(default_factory=list)


class SetLoggerLevels_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/SetLoggerLevels_Event``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/SetLoggerLevels_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "rcl_interfaces/srv/SetLoggerLevels_Request[<=1] request\n"
        "rcl_interfaces/srv/SetLoggerLevels_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[SetLoggerLevels_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[SetLoggerLevels_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class SetLoggerLevels:
    """``rcl_interfaces/srv/SetLoggerLevels``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/SetLoggerLevels"
    __ros_definition__: ClassVar[str] = (
        "# A list of loggers to set.\n"
        "LoggerLevel[] levels\n"
        "\n"
        "---\n"
        "# Indicates whether setting each logger succeeded or not and why.\n"
        "SetLoggerLevelsResult[] results\n"
    )
    Request = SetLoggerLevels_Request
    Response = SetLoggerLevels_Response
    Event = SetLoggerLevels_Event


class SetParameters_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/SetParameters_Request``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/SetParameters_Request"
    __ros_definition__: ClassVar[str] = (
        "# A list of parameters to set.\n"
        "Parameter[] parameters\n"
        "\n"
    )

    parameters: list[Parameter] = msgspec.field(default_factory=list)


class SetParameters_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/SetParameters_Response``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/SetParameters_Response"
    __ros_definition__: ClassVar[str] = (
        "# Indicates whether setting each parameter succeeded or not and why.\n"
        "SetParametersResult[] results\n"
    )

    results: list[SetParametersResult] = msgspec.field(default_factory=list)


class SetParameters_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/SetParameters_Event``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/SetParameters_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "rcl_interfaces/srv/SetParameters_Request[<=1] request\n"
        "rcl_interfaces/srv/SetParameters_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[SetParameters_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[SetParameters_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class SetParameters:
    """``rcl_interfaces/srv/SetParameters``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/SetParameters"
    __ros_definition__: ClassVar[str] = (
        "# A list of parameters to set.\n"
        "Parameter[] parameters\n"
        "\n"
        "---\n"
        "# Indicates whether setting each parameter succeeded or not and why.\n"
        "SetParametersResult[] results\n"
    )
    Request = SetParameters_Request
    Response = SetParameters_Response
    Event = SetParameters_Event


class SetParametersAtomically_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/SetParametersAtomically_Request``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/SetParametersAtomically_Request"
    __ros_definition__: ClassVar[str] = (
        "# A list of parameters to set atomically.\n"
        "#\n"
        "# This call will either set all values, or none of the values.\n"
        "Parameter[] parameters\n"
        "\n"
    )

    parameters: list[Parameter] = msgspec.field(default_factory=list)


class SetParametersAtomically_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/SetParametersAtomically_Response``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/SetParametersAtomically_Response"
    __ros_definition__: ClassVar[str] = (
        "# Indicates whether setting all of the parameters succeeded or not and why.\n"
        "SetParametersResult result\n"
    )

    result: SetParametersResult = msgspec.field(default_factory=SetParametersResult)


class SetParametersAtomically_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``rcl_interfaces/srv/SetParametersAtomically_Event``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/SetParametersAtomically_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "rcl_interfaces/srv/SetParametersAtomically_Request[<=1] request\n"
        "rcl_interfaces/srv/SetParametersAtomically_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[SetParametersAtomically_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[SetParametersAtomically_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class SetParametersAtomically:
    """``rcl_interfaces/srv/SetParametersAtomically``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "rcl_interfaces/srv/SetParametersAtomically"
    __ros_definition__: ClassVar[str] = (
        "# A list of parameters to set atomically.\n"
        "#\n"
        "# This call will either set all values, or none of the values.\n"
        "Parameter[] parameters\n"
        "\n"
        "---\n"
        "# Indicates whether setting all of the parameters succeeded or not and why.\n"
        "SetParametersResult result\n"
    )
    Request = SetParametersAtomically_Request
    Response = SetParametersAtomically_Response
    Event = SetParametersAtomically_Event
