"""Generated from example_interfaces/srv/*.srv by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.service_msgs.msg import ServiceEventInfo

__all__ = [
    "AddTwoInts",
    "AddTwoInts_Event",
    "AddTwoInts_Request",
    "AddTwoInts_Response",
    "SetBool",
    "SetBool_Event",
    "SetBool_Request",
    "SetBool_Response",
    "Trigger",
    "Trigger_Event",
    "Trigger_Request",
    "Trigger_Response",
]

_int64 = Annotated[int, msgspec.Meta(ge=-9223372036854775808, le=9223372036854775807)]


class AddTwoInts_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/srv/AddTwoInts_Request``."""

    __ros_type__: ClassVar[str] = "example_interfaces/srv/AddTwoInts_Request"
    __ros_definition__: ClassVar[str] = (
        "int64 a\n"
        "int64 b\n"
    )

    a: _int64 = 0
    b: _int64 = 0


class AddTwoInts_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/srv/AddTwoInts_Response``."""

    __ros_type__: ClassVar[str] = "example_interfaces/srv/AddTwoInts_Response"
    __ros_definition__: ClassVar[str] = (
        "int64 sum\n"
    )

    sum: _int64 = 0


class AddTwoInts_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/srv/AddTwoInts_Event``."""

    __ros_type__: ClassVar[str] = "example_interfaces/srv/AddTwoInts_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "example_interfaces/srv/AddTwoInts_Request[<=1] request\n"
        "example_interfaces/srv/AddTwoInts_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[AddTwoInts_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[AddTwoInts_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class AddTwoInts:
    """``example_interfaces/srv/AddTwoInts``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "example_interfaces/srv/AddTwoInts"
    __ros_definition__: ClassVar[str] = (
        "int64 a\n"
        "int64 b\n"
        "---\n"
        "int64 sum\n"
    )
    Request = AddTwoInts_Request
    Response = AddTwoInts_Response
    Event = AddTwoInts_Event


class SetBool_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/srv/SetBool_Request``."""

    __ros_type__: ClassVar[str] = "example_interfaces/srv/SetBool_Request"
    __ros_definition__: ClassVar[str] = (
        "# This is an example of a service to set a boolean value.\n"
        "# This can be used for testing but a semantically meaningful\n"
        "# one should be created to be built upon.\n"
        "\n"
        "bool data # e.g. for hardware enabling / disabling\n"
    )

    data: bool = False


class SetBool_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/srv/SetBool_Response``."""

    __ros_type__: ClassVar[str] = "example_interfaces/srv/SetBool_Response"
    __ros_definition__: ClassVar[str] = (
        "bool success   # indicate successful run of triggered service\n"
        "string message # informational, e.g. for error messages\n"
    )

    success: bool = False
    message: str = ""


class SetBool_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/srv/SetBool_Event``."""

    __ros_type__: ClassVar[str] = "example_interfaces/srv/SetBool_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "example_interfaces/srv/SetBool_Request[<=1] request\n"
        "example_interfaces/srv/SetBool_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[SetBool_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[SetBool_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class SetBool:
    """``example_interfaces/srv/SetBool``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "example_interfaces/srv/SetBool"
    __ros_definition__: ClassVar[str] = (
        "# This is an example of a service to set a boolean value.\n"
        "# This can be used for testing but a semantically meaningful\n"
        "# one should be created to be built upon.\n"
        "\n"
        "bool data # e.g. for hardware enabling / disabling\n"
        "---\n"
        "bool success   # indicate successful run of triggered service\n"
        "string message # informational, e.g. for error messages\n"
    )
    Request = SetBool_Request
    Response = SetBool_Response
    Event = SetBool_Event


class Trigger_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/srv/Trigger_Request``."""

    __ros_type__: ClassVar[str] = "example_interfaces/srv/Trigger_Request"
    __ros_definition__: ClassVar[str] = (
        "# An example of a trigger service.\n"
        "# This can be used for testing but a semantically meaningful\n"
        "# one should be created to be built upon.\n"
        "\n"
    )


class Trigger_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/srv/Trigger_Response``."""

    __ros_type__: ClassVar[str] = "example_interfaces/srv/Trigger_Response"
    __ros_definition__: ClassVar[str] = (
        "bool success   # indicate successful run of triggered service\n"
        "string message # informational, e.g. for error messages.\n"
    )

    success: bool = False
    message: str = ""


class Trigger_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``example_interfaces/srv/Trigger_Event``."""

    __ros_type__: ClassVar[str] = "example_interfaces/srv/Trigger_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "example_interfaces/srv/Trigger_Request[<=1] request\n"
        "example_interfaces/srv/Trigger_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[Trigger_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[Trigger_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class Trigger:
    """``example_interfaces/srv/Trigger``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "example_interfaces/srv/Trigger"
    __ros_definition__: ClassVar[str] = (
        "# An example of a trigger service.\n"
        "# This can be used for testing but a semantically meaningful\n"
        "# one should be created to be built upon.\n"
        "\n"
        "---\n"
        "bool success   # indicate successful run of triggered service\n"
        "string message # informational, e.g. for error messages.\n"
    )
    Request = Trigger_Request
    Response = Trigger_Response
    Event = Trigger_Event
