"""Generated from type_description_interfaces/srv/*.srv by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.service_msgs.msg import ServiceEventInfo
from interfaces.type_description_interfaces.msg import KeyValue, TypeDescription, TypeSource

__all__ = [
    "GetTypeDescription",
    "GetTypeDescription_Event",
    "GetTypeDescription_Request",
    "GetTypeDescription_Response",
]


class GetTypeDescription_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``type_description_interfaces/srv/GetTypeDescription_Request``."""

    __ros_type__: ClassVar[str] = "type_description_interfaces/srv/GetTypeDescription_Request"
    __ros_definition__: ClassVar[str] = (
        "# ROS interface type name, in PACKAGE/NAMESPACE/TYPENAME format.\n"
        "string type_name\n"
        "\n"
        "# REP-2011 RIHS hash string.\n"
        "string type_hash\n"
        "\n"
        "# Whether to return the original idl/msg/etc. source file(s) in the response.\n"
        "bool include_type_sources true\n"
    )

    type_name: str = ""
    type_hash: str = ""
    include_type_sources: bool = True


class GetTypeDescription_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``type_description_interfaces/srv/GetTypeDescription_Response``."""

    __ros_type__: ClassVar[str] = "type_description_interfaces/srv/GetTypeDescription_Response"
    __ros_definition__: ClassVar[str] = (
        "# True if the type description information is available and populated in the response.\n"
        "# If false, all other fields except `failure_reason` are considered undefined.\n"
        "bool successful\n"
        "# If `successful` is false, contains a reason for failure.\n"
        "# If `successful` is true, this is left empty.\n"
        "string failure_reason\n"
        "\n"
        "# The parsed type description which can be used programmatically.\n"
        "TypeDescription type_description\n"
        "\n"
        "# A list containing the interface definition source text of the requested type,\n"
        "# plus all types it recursively depends on.\n"
        "# Each source text is a copy of the original contents of the\n"
        "# .msg, .srv, .action, .idl, or other file if it exists, including comments and whitespace.\n"
        "# Sources can be matched with IndividualTypeDescriptions by their `type_name`.\n"
        "# The `encoding` field of each entry informs how to interpret its contents.\n"
        "TypeSource[] type_sources\n"
        "\n"
        "# Key-value pairs of extra information.\n"
        "KeyValue[] extra_information\n"
    )

    successful: bool = False
    failure_reason: str = ""
    type_description: TypeDescription = msgspec.field(default_factory=TypeDescription)
    type_sources: list[TypeSource] = msgspec.field(default_factory=list)
    extra_information: list[KeyValue] = msgspec.field(default_factory=list)


class GetTypeDescription_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``type_description_interfaces/srv/GetTypeDescription_Event``."""

    __ros_type__: ClassVar[str] = "type_description_interfaces/srv/GetTypeDescription_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "type_description_interfaces/srv/GetTypeDescription_Request[<=1] request\n"
        "type_description_interfaces/srv/GetTypeDescription_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[GetTypeDescription_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[GetTypeDescription_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class GetTypeDescription:
    """``type_description_interfaces/srv/GetTypeDescription``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "type_description_interfaces/srv/GetTypeDescription"
    __ros_definition__: ClassVar[str] = (
        "# ROS interface type name, in PACKAGE/NAMESPACE/TYPENAME format.\n"
        "string type_name\n"
        "\n"
        "# REP-2011 RIHS hash string.\n"
        "string type_hash\n"
        "\n"
        "# Whether to return the original idl/msg/etc. source file(s) in the response.\n"
        "bool include_type_sources true\n"
        "---\n"
        "# True if the type description information is available and populated in the response.\n"
        "# If false, all other fields except `failure_reason` are considered undefined.\n"
        "bool successful\n"
        "# If `successful` is false, contains a reason for failure.\n"
        "# If `successful` is true, this is left empty.\n"
        "string failure_reason\n"
        "\n"
        "# The parsed type description which can be used programmatically.\n"
        "TypeDescription type_description\n"
        "\n"
        "# A list containing the interface definition source text of the requested type,\n"
        "# plus all types it recursively depends on.\n"
        "# Each source text is a copy of the original contents of the\n"
        "# .msg, .srv, .action, .idl, or other file if it exists, including comments and whitespace.\n"
        "# Sources can be matched with IndividualTypeDescriptions by their `type_name`.\n"
        "# The `encoding` field of each entry informs how to interpret its contents.\n"
        "TypeSource[] type_sources\n"
        "\n"
        "# Key-value pairs of extra information.\n"
        "KeyValue[] extra_information\n"
    )
    Request = GetTypeDescription_Request
    Response = GetTypeDescription_Response
    Event = GetTypeDescription_Event
