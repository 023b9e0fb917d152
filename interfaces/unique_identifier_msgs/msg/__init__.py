"""Generated from unique_identifier_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

__all__ = [
    "UUID",
]


class UUID(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``unique_identifier_msgs/msg/UUID``."""

    __ros_type__: ClassVar[str] = "unique_identifier_msgs/msg/UUID"
    __ros_definition__: ClassVar[str] = (
        "# A universally unique identifier (UUID).\n"
        "#\n"
        "#  http://en.wikipedia.org/wiki/Universally_unique_identifier\n"
        "#  http://tools.ietf.org/html/rfc4122.html\n"
        "\n"
        "uint8[16] uuid\n"
    )

    uuid: Annotated[bytes, msgspec.Meta(min_length=16, max_length=16)] = bytes(16)
