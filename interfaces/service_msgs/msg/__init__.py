"""Generated from service_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from array import array
from collections.abc import MutableSequence
from typing import Annotated, ClassVar

import msgspec

from actors.messages.arrays import held
from interfaces.builtin_interfaces.msg import Time

__all__ = [
    "ServiceEventInfo",
]

_uint8 = Annotated[int, msgspec.Meta(ge=0, le=255)]
_int64 = Annotated[int, msgspec.Meta(ge=-9223372036854775808, le=9223372036854775807)]


class ServiceEventInfo(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``service_msgs/msg/ServiceEventInfo``."""

    __ros_type__: ClassVar[str] = "service_msgs/msg/ServiceEventInfo"
    __ros_definition__: ClassVar[str] = (
        "uint8 REQUEST_SENT = 0\n"
        "uint8 REQUEST_RECEIVED = 1\n"
        "uint8 RESPONSE_SENT = 2\n"
        "uint8 RESPONSE_RECEIVED = 3\n"
        "\n"
        "# The type of event this message represents\n"
        "uint8 event_type\n"
        "\n"
        "# Timestamp for when the event occurred (sent or received time)\n"
        "builtin_interfaces/Time stamp\n"
        "\n"
        "# Unique identifier for the client that sent the service request\n"
        "# Note, this is only unique for the current session.\n"
        "# The size here has to match the size of rmw_dds_common/msg/Gid,\n"
        "# but unfortunately we cannot use that message directly due to a\n"
        "# circular dependency.\n"
        "char[16] client_gid\n"
        "\n"
        "# Sequence number for the request\n"
        "# Combined with the client ID, this creates a unique ID for the service transaction\n"
        "int64 sequence_number\n"
    )
    REQUEST_SENT: ClassVar[int] = 0
    REQUEST_RECEIVED: ClassVar[int] = 1
    RESPONSE_SENT: ClassVar[int] = 2
    RESPONSE_RECEIVED: ClassVar[int] = 3

    event_type: _uint8 = 0
    stamp: Time = msgspec.field(default_factory=Time)
    client_gid: Annotated[MutableSequence[_uint8], msgspec.Meta(min_length=16, max_length=16)] = msgspec.field(default_factory=lambda: array("B", bytes(16)))
    sequence_number: _int64 = 0

    def __post_init__(self) -> None:
        if type(self.client_gid) is not array or self.client_gid.typecode != "B":
            self.client_gid = held(self.client_gid, "B")
