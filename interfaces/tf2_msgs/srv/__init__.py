"""Generated from tf2_msgs/srv/*.srv by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.service_msgs.msg import ServiceEventInfo

__all__ = [
    "FrameGraph",
    "FrameGraph_Event",
    "FrameGraph_Request",
    "FrameGraph_Response",
]


class FrameGraph_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tf2_msgs/srv/FrameGraph_Request``."""

    __ros_type__: ClassVar[str] = "tf2_msgs/srv/FrameGraph_Request"
    __ros_definition__: ClassVar[str] = ""


class FrameGraph_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tf2_msgs/srv/FrameGraph_Response``."""

    __ros_type__: ClassVar[str] = "tf2_msgs/srv/FrameGraph_Response"
    __ros_definition__: ClassVar[str] = (
        "string frame_yaml\n"
    )

    frame_yaml: str = ""


class FrameGraph_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tf2_msgs/srv/FrameGraph_Event``."""

    __ros_type__: ClassVar[str] = "tf2_msgs/srv/FrameGraph_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "tf2_msgs/srv/FrameGraph_Request[<=1] request\n"
        "tf2_msgs/srv/FrameGraph_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[FrameGraph_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[FrameGraph_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class FrameGraph:
    """``tf2_msgs/srv/FrameGraph``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "tf2_msgs/srv/FrameGraph"
    __ros_definition__: ClassVar[str] = (
        "---\n"
        "string frame_yaml\n"
    )
    Request = FrameGraph_Request
    Response = FrameGraph_Response
    Event = FrameGraph_Event
