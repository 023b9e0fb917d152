"""Generated from visualization_msgs/srv/*.srv by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.service_msgs.msg import ServiceEventInfo
from interfaces.visualization_msgs.msg import InteractiveMarker

__all__ = [
    "GetInteractiveMarkers",
    "GetInteractiveMarkers_Event",
    "GetInteractiveMarkers_Request",
    "GetInteractiveMarkers_Response",
]

_uint64 = Annotated[int, msgspec.Meta(ge=0)]


class GetInteractiveMarkers_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``visualization_msgs/srv/GetInteractiveMarkers_Request``."""

    __ros_type__: ClassVar[str] = "visualization_msgs/srv/GetInteractiveMarkers_Request"
    __ros_definition__: ClassVar[str] = ""


class GetInteractiveMarkers_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``visualization_msgs/srv/GetInteractiveMarkers_Response``."""

    __ros_type__: ClassVar[str] = "visualization_msgs/srv/GetInteractiveMarkers_Response"
    __ros_definition__: ClassVar[str] = (
        "# Sequence number.\n"
        "# Set to the sequence number of the latest update message\n"
        "# at the time the server received the request.\n"
        "# Clients use this to detect if any updates were missed.\n"
        "uint64 sequence_number\n"
        "\n"
        "# All interactive markers provided by the server.\n"
        "InteractiveMarker[] markers\n"
    )

    sequence_number: _uint64 = 0
    markers: list[InteractiveMarker] = msgspec.field(default_factory=list)


class GetInteractiveMarkers_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``visualization_msgs/srv/GetInteractiveMarkers_Event``."""

    __ros_type__: ClassVar[str] = "visualization_msgs/srv/GetInteractiveMarkers_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "visualization_msgs/srv/GetInteractiveMarkers_Request[<=1] request\n"
        "visualization_msgs/srv/GetInteractiveMarkers_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[GetInteractiveMarkers_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[GetInteractiveMarkers_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class GetInteractiveMarkers:
    """``visualization_msgs/srv/GetInteractiveMarkers``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "visualization_msgs/srv/GetInteractiveMarkers"
    __ros_definition__: ClassVar[str] = (
        "---\n"
        "# Sequence number.\n"
        "# Set to the sequence number of the latest update message\n"
        "# at the time the server received the request.\n"
        "# Clients use this to detect if any updates were missed.\n"
        "uint64 sequence_number\n"
        "\n"
        "# All interactive markers provided by the server.\n"
        "InteractiveMarker[] markers\n"
    )
    Request = GetInteractiveMarkers_Request
    Response = GetInteractiveMarkers_Response
    Event = GetInteractiveMarkers_Event
