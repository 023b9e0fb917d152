"""Generated from std_srvs/srv/*.srv by `python -m actors interface generate`; do not edit."""

from typing import ClassVar

import msgspec

__all__ = [
    "Empty",
    "Empty_Request",
    "Empty_Response",
    "SetBool",
    "SetBool_Request",
    "SetBool_Response",
    "Trigger",
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


class Empty:
    """``std_srvs/srv/Empty``: its ``Request`` and ``Response`` messages."""

    __ros_type__: ClassVar[str] = "std_srvs/srv/Empty"
    __ros_definition__: ClassVar[str] = (
        "---\n"
    )
    Request = Empty_Request
    Response = Empty_Response


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


class SetBool:
    """``std_srvs/srv/SetBool``: its ``Request`` and ``Response`` messages."""

    __ros_type__: ClassVar[str] = "std_srvs/srv/SetBool"
    __ros_definition__: ClassVar[str] = (
        "bool data # e.g. for hardware enabling / disabling\n"
        "---\n"
        "bool success   # indicate successful run of triggered service\n"
        "string message # informational, e.g. for error messages\n"
    )
    Request = SetBool_Request
    Response = SetBool_Response


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


class Trigger:
    """``std_srvs/srv/Trigger``: its ``Request`` and ``Response`` messages."""

    __ros_type__: ClassVar[str] = "std_srvs/srv/Trigger"
    __ros_definition__: ClassVar[str] = (
        "---\n"
        "bool success   # indicate successful run of triggered service\n"
        "string message # informational, e.g. for error messages\n"
    )
    Request = Trigger_Request
    Response = Trigger_Response
