"""Generated from turtlesim/srv/*.srv by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

__all__ = [
    "Kill",
    "Kill_Request",
    "Kill_Response",
    "SetPen",
    "SetPen_Request",
    "SetPen_Response",
    "Spawn",
    "Spawn_Request",
    "Spawn_Response",
    "TeleportAbsolute",
    "TeleportAbsolute_Request",
    "TeleportAbsolute_Response",
    "TeleportRelative",
    "TeleportRelative_Request",
    "TeleportRelative_Response",
]

_uint8 = Annotated[int, msgspec.Meta(ge=0, le=255)]


class Kill_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim/srv/Kill_Request``."""

    __ros_type__: ClassVar[str] = "turtlesim/srv/Kill_Request"
    __ros_definition__: ClassVar[str] = (
        "string name\n"
    )

    name: str = ""


class Kill_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim/srv/Kill_Response``."""

    __ros_type__: ClassVar[str] = "turtlesim/srv/Kill_Response"
    __ros_definition__: ClassVar[str] = ""


class Kill:
    """``turtlesim/srv/Kill``: its ``Request`` and ``Response`` messages."""

    __ros_type__: ClassVar[str] = "turtlesim/srv/Kill"
    __ros_definition__: ClassVar[str] = (
        "string name\n"
        "---\n"
    )
    Request = Kill_Request
    Response = Kill_Response


class SetPen_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim/srv/SetPen_Request``."""

    __ros_type__: ClassVar[str] = "turtlesim/srv/SetPen_Request"
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
    """``turtlesim/srv/SetPen_Response``."""

    __ros_type__: ClassVar[str] = "turtlesim/srv/SetPen_Response"
    __ros_definition__: ClassVar[str] = ""


class SetPen:
    """``turtlesim/srv/SetPen``: its ``Request`` and ``Response`` messages."""

    __ros_type__: ClassVar[str] = "turtlesim/srv/SetPen"
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


class Spawn_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim/srv/Spawn_Request``."""

    __ros_type__: ClassVar[str] = "turtlesim/srv/Spawn_Request"
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
    """``turtlesim/srv/Spawn_Response``."""

    __ros_type__: ClassVar[str] = "turtlesim/srv/Spawn_Response"
    __ros_definition__: ClassVar[str] = (
        "string name\n"
    )

    name: str = ""


class Spawn:
    """``turtlesim/srv/Spawn``: its ``Request`` and ``Response`` messages."""

    __ros_type__: ClassVar[str] = "turtlesim/srv/Spawn"
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


class TeleportAbsolute_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim/srv/TeleportAbsolute_Request``."""

    __ros_type__: ClassVar[str] = "turtlesim/srv/TeleportAbsolute_Request"
    __ros_definition__: ClassVar[str] = (
        "float32 x\n"
        "float32 y\n"
        "float32 theta\n"
    )

    x: float = 0.0
    y: float = 0.0
    theta: float = 0.0


class TeleportAbsolute_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim/srv/TeleportAbsolute_Response``."""

    __ros_type__: ClassVar[str] = "turtlesim/srv/TeleportAbsolute_Response"
    __ros_definition__: ClassVar[str] = ""


class TeleportAbsolute:
    """``turtlesim/srv/TeleportAbsolute``: its ``Request`` and ``Response`` messages."""

    __ros_type__: ClassVar[str] = "turtlesim/srv/TeleportAbsolute"
    __ros_definition__: ClassVar[str] = (
        "float32 x\n"
        "float32 y\n"
        "float32 theta\n"
        "---\n"
    )
    Request = TeleportAbsolute_Request
    Response = TeleportAbsolute_Response


class TeleportRelative_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim/srv/TeleportRelative_Request``."""

    __ros_type__: ClassVar[str] = "turtlesim/srv/TeleportRelative_Request"
    __ros_definition__: ClassVar[str] = (
        "float32 linear\n"
        "float32 angular\n"
    )

    linear: float = 0.0
    angular: float = 0.0


class TeleportRelative_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim/srv/TeleportRelative_Response``."""

    __ros_type__: ClassVar[str] = "turtlesim/srv/TeleportRelative_Response"
    __ros_definition__: ClassVar[str] = ""


class TeleportRelative:
    """``turtlesim/srv/TeleportRelative``: its ``Request`` and ``Response`` messages."""

    __ros_type__: ClassVar[str] = "turtlesim/srv/TeleportRelative"
    __ros_definition__: ClassVar[str] = (
        "float32 linear\n"
        "float32 angular\n"
        "---\n"
    )
    Request = TeleportRelative_Request
    Response = TeleportRelative_Response
