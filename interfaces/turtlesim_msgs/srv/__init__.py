"""Generated from turtlesim_msgs/srv/*.srv by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.service_msgs.msg import ServiceEventInfo

__all__ = [
    "Kill",
    "Kill_Event",
    "Kill_Request",
    "Kill_Response",
    "SetPen",
    "SetPen_Event",
    "SetPen_Request",
    "SetPen_Response",
    "Spawn",
    "Spawn_Event",
    "Spawn_Request",
    "Spawn_Response",
    "TeleportAbsolute",
    "TeleportAbsolute_Event",
    "TeleportAbsolute_Request",
    "TeleportAbsolute_Response",
    "TeleportRelative",
    "TeleportRelative_Event",
    "TeleportRelative_Request",
    "TeleportRelative_Response",
]

_uint8 = Annotated[int, msgspec.Meta(ge=0, le=255)]


class Kill_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/srv/Kill_Request``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/Kill_Request"
    __ros_definition__: ClassVar[str] = (
        "string name\n"
    )

    name: str = ""


class Kill_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/srv/Kill_Response``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/Kill_Response"
    __ros_definition__: ClassVar[str] = ""


class Kill_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/srv/Kill_Event``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/Kill_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "turtlesim_msgs/srv/Kill_Request[<=1] request\n"
        "turtlesim_msgs/srv/Kill_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[Kill_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[Kill_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class Kill:
    """``turtlesim_msgs/srv/Kill``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/Kill"
    __ros_definition__: ClassVar[str] = (
        "string name\n"
        "---\n"
    )
    Request = Kill_Request
    Response = Kill_Response
    Event = Kill_Event


class SetPen_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/srv/SetPen_Request``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/SetPen_Request"
    __ros_definition__: ClassVar[str] = (
        "uint8 r\n"
        "uint8 g\n"
        "uint8 b\n"
        "uint8 width\n"
        "uint8 off\n"
    )

    r: _uint8 = 0
    g: _uint8 = 0
    b: _uint8 = 0
    width: _uint8 = 0
    off: _uint8 = 0


class SetPen_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/srv/SetPen_Response``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/SetPen_Response"
    __ros_definition__: ClassVar[str] = ""


class SetPen_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/srv/SetPen_Event``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/SetPen_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "turtlesim_msgs/srv/SetPen_Request[<=1] request\n"
        "turtlesim_msgs/srv/SetPen_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[SetPen_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[SetPen_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class SetPen:
    """``turtlesim_msgs/srv/SetPen``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/SetPen"
    __ros_definition__: ClassVar[str] = (
        "uint8 r\n"
        "uint8 g\n"
        "uint8 b\n"
        "uint8 width\n"
        "uint8 off\n"
        "---\n"
    )
    Request = SetPen_Request
    Response = SetPen_Response
    Event = SetPen_Event


class Spawn_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/srv/Spawn_Request``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/Spawn_Request"
    __ros_definition__: ClassVar[str] = (
        "float32 x\n"
        "float32 y\n"
        "float32 theta\n"
        "string name # Optional.  A unique name will be created and returned if this is empty\n"
    )

    x: float = 0.0
    y: float = 0.0
    theta: float = 0.0
    name: str = ""


class Spawn_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/srv/Spawn_Response``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/Spawn_Response"
    __ros_definition__: ClassVar[str] = (
        "string name\n"
    )

    name: str = ""


class Spawn_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/srv/Spawn_Event``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/Spawn_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "turtlesim_msgs/srv/Spawn_Request[<=1] request\n"
        "turtlesim_msgs/srv/Spawn_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[Spawn_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[Spawn_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class Spawn:
    """``turtlesim_msgs/srv/Spawn``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/Spawn"
    __ros_definition__: ClassVar[str] = (
        "float32 x\n"
        "float32 y\n"
        "float32 theta\n"
        "string name # Optional.  A unique name will be created and returned if this is empty\n"
        "---\n"
        "string name\n"
    )
    Request = Spawn_Request
    Response = Spawn_Response
    Event = Spawn_Event


class TeleportAbsolute_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/srv/TeleportAbsolute_Request``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/TeleportAbsolute_Request"
    __ros_definition__: ClassVar[str] = (
        "float32 x\n"
        "float32 y\n"
        "float32 theta\n"
    )

    x: float = 0.0
    y: float = 0.0
    theta: float = 0.0


class TeleportAbsolute_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/srv/TeleportAbsolute_Response``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/TeleportAbsolute_Response"
    __ros_definition__: ClassVar[str] = ""


class TeleportAbsolute_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/srv/TeleportAbsolute_Event``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/TeleportAbsolute_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "turtlesim_msgs/srv/TeleportAbsolute_Request[<=1] request\n"
        "turtlesim_msgs/srv/TeleportAbsolute_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[TeleportAbsolute_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[TeleportAbsolute_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class TeleportAbsolute:
    """``turtlesim_msgs/srv/TeleportAbsolute``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/TeleportAbsolute"
    __ros_definition__: ClassVar[str] = (
        "float32 x\n"
        "float32 y\n"
        "float32 theta\n"
        "---\n"
    )
    Request = TeleportAbsolute_Request
    Response = TeleportAbsolute_Response
    Event = TeleportAbsolute_Event


class TeleportRelative_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/srv/TeleportRelative_Request``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/TeleportRelative_Request"
    __ros_definition__: ClassVar[str] = (
        "float32 linear\n"
        "float32 angular\n"
    )

    linear: float = 0.0
    angular: float = 0.0


class TeleportRelative_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/srv/TeleportRelative_Response``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/TeleportRelative_Response"
    __ros_definition__: ClassVar[str] = ""


class TeleportRelative_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/srv/TeleportRelative_Event``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/TeleportRelative_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "turtlesim_msgs/srv/TeleportRelative_Request[<=1] request\n"
        "turtlesim_msgs/srv/TeleportRelative_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[TeleportRelative_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[TeleportRelative_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class TeleportRelative:
    """``turtlesim_msgs/srv/TeleportRelative``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/srv/TeleportRelative"
    __ros_definition__: ClassVar[str] = (
        "float32 linear\n"
        "float32 angular\n"
        "---\n"
    )
    Request = TeleportRelative_Request
    Response = TeleportRelative_Response
    Event = TeleportRelative_Event
