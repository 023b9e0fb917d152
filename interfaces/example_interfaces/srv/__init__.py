"""Generated from example_interfaces/srv/*.srv by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

__all__ = [
    "AddTwoInts",
    "AddTwoInts_Request",
    "AddTwoInts_Response",
    "SetBool",
    "SetBool_Request",
    "SetBool_Response",
    "Trigger",
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


class AddTwoInts:
    """``example_interfaces/srv/AddTwoInts``: its ``Request`` and ``Response`` messages."""

    __ros_type__: ClassVar[str] = "example_interfaces/srv/AddTwoInts"
    __ros_definition__: ClassVar[str] = (
        "int64 a\n"
        "int64 b\n"
        "---\n"
        "int64 sum\n"
    )
    Request = AddTwoInts_Request
    Response = AddTwoInts_Response


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


class SetBool:
    """``example_interfaces/srv/SetBool``: its ``Request`` and ``Response`` messages."""

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


class Trigger:
    """``example_interfaces/srv/Trigger``: its ``Request`` and ``Response`` messages."""

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
