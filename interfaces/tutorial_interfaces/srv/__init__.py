"""Generated from tutorial_interfaces/srv/*.srv by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.service_msgs.msg import ServiceEventInfo

__all__ = [
    "AddThreeInts",
    "AddThreeInts_Event",
    "AddThreeInts_Request",
    "AddThreeInts_Response",
]

_int64 = Annotated[int, msgspec.Meta(ge=-9223372036854775808, le=9223372036854775807)]


class AddThreeInts_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tutorial_interfaces/srv/AddThreeInts_Request``."""

    __ros_type__: ClassVar[str] = "tutorial_interfaces/srv/AddThreeInts_Request"
    __ros_definition__: ClassVar[str] = (
        "int64 a\n"
        "int64 b\n"
        "int64 c\n"
    )

    a: _int64 = 0
    b: _int64 = 0
    c: _int64 = 0


class AddThreeInts_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tutorial_interfaces/srv/AddThreeInts_Response``."""

    __ros_type__: ClassVar[str] = "tutorial_interfaces/srv/AddThreeInts_Response"
    __ros_definition__: ClassVar[str] = (
        "int64 sum\n"
    )

    sum: _int64 = 0


class AddThreeInts_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tutorial_interfaces/srv/AddThreeInts_Event``."""

    __ros_type__: ClassVar[str] = "tutorial_interfaces/srv/AddThreeInts_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "tutorial_interfaces/srv/AddThreeInts_Request[<=1] request\n"
        "tutorial_interfaces/srv/AddThreeInts_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[AddThreeInts_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[AddThreeInts_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class AddThreeInts:
    """``tutorial_interfaces/srv/AddThreeInts``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "tutorial_interfaces/srv/AddThreeInts"
    __ros_definition__: ClassVar[str] = (
        "int64 a\n"
        "int64 b\n"
        "int64 c\n"
        "---\n"
        "int64 sum\n"
    )
    Request = AddThreeInts_Request
    Response = AddThreeInts_Response
    Event = AddThreeInts_Event
