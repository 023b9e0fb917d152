"""Generated from std_srvs/srv/*.srv by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.service_msgs.msg import ServiceEventInfo

__all__ = [
    "Empty",
    "Empty_Event",
    "Empty_Request",
    "Empty_Response",
    "SetBool",
    "SetBool_Event",
    "SetBool_Request",
    "SetBool_Response",
    "Trigger",
    "Trigger_Event",
    "Trigger_Request",
    "Trigger_Response",
]


class Empty_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``std_srvs/srv/Empty_Request``."""

    __ros_type__: ClassVar[str] = "std_srvs/srv/Empty_Request"
    __ros_definition__: ClassVar[str] = ""


class Empty_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``std_srvs/srv/Empty_Response``."""

    __ros_type__: ClassVar[str] = "std_srvs/srv/Empty_Response"
    __ros_definition__: ClassVar[str] = ""


class Empty_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``std_srvs/srv/Empty_Event``."""

    __ros_type__: ClassVar[str] = "std_srvs/srv/Empty_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "std_srvs/srv/Empty_Request[<=1] request\n"
        "std_srvs/srv/Empty_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[Empty_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[Empty_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class Empty:
    """``std_srvs/srv/Empty``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "std_srvs/srv/Empty"
    __ros_definition__: ClassVar[str] = (
        "---\n"
    )
    Request = Empty_Request
    Response = Empty_Response
    Event = Empty_Event


class SetBool_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``std_srvs/srv/SetBool_Request``."""

    __ros_type__: ClassVar[str] = "std_srvs/srv/SetBool_Request"
    __ros_definition__: ClassVar[str] = (
        "bool data # e.g. for hardware enabling / disabling\n"
    )

    data: bool = False


class SetBool_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``std_srvs/srv/SetBool_Response``."""

    __ros_type__: ClassVar[str] = "std_srvs/srv/SetBool_Response"
    __ros_definition__: ClassVar[str] = (
        "bool success   # indicate successful run of triggered service\n"
        "string message # informational, e.g. for error messages\n"
    )

    success: bool = False
    message: str = ""


class SetBool_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``std_srvs/srv/SetBool_Event``."""

    __ros_type__: ClassVar[str] = "std_srvs/srv/SetBool_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "std_srvs/srv/SetBool_Request[<=1] request\n"
        "std_srvs/srv/SetBool_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[SetBool_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[SetBool_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class SetBool:
    """``std_srvs/srv/SetBool``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "std_srvs/srv/SetBool"
    __ros_definition__: ClassVar[str] = (
        "bool data # e.g. for hardware enabling / disabling\n"
        "---\n"
        "bool success   # indicate successful run of triggered service\n"
        "string message # informational, e.g. for error messages\n"
    )
    Request = SetBool_Request
    Response = SetBool_Response
    Event = SetBool_Event


class Trigger_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``std_srvs/srv/Trigger_Request``."""

    __ros_type__: ClassVar[str] = "std_srvs/srv/Trigger_Request"
    __ros_definition__: ClassVar[str] = ""


class Trigger_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``std_srvs/srv/Trigger_Response``."""

    __ros_type__: ClassVar[str] = "std_srvs/srv/Trigger_Response"
    __ros_definition__: ClassVar[str] = (
        "bool success   # indicate successful run of triggered service\n"
        "string message # informational, e.g. for error messages\n"
    )

    success: bool = False
    message: str = ""


class Trigger_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``std_srvs/srv/Trigger_Event``."""

    __ros_type__: ClassVar[str] = "std_srvs/srv/Trigger_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "std_srvs/srv/Trigger_Request[<=1] request\n"
        "std_srvs/srv/Trigger_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[Trigger_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[Trigger_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class Trigger:
    """``std_srvs/srv/Trigger``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "std_srvs/srv/Trigger"
    __ros_definition__: ClassVar[str] = (
        "---\n"
        "bool success   # indicate successful run of triggered service\n"
        "string message # informational, e.g. for error messages\n"
    )
    Request = Trigger_Request
    Response = Trigger_Response
    Event = Trigger_Event
