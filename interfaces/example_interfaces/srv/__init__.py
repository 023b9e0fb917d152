"""Generated from example_interfaces/srv/*.srv by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

__all__ = [
    "AddTwoInts",
    "AddTwoInts_Request",
    "AddTwoInts_Response",
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
