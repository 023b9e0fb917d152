"""Generated from tf2_msgs/srv/*.srv by `python -m actors interface generate`; do not edit."""

from typing import ClassVar

import msgspec

__all__ = [
    "FrameGraph",
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


class FrameGraph:
    """``tf2_msgs/srv/FrameGraph``: its ``Request`` and ``Response`` messages."""

    __ros_type__: ClassVar[str] = "tf2_msgs/srv/FrameGraph"
    __ros_definition__: ClassVar[str] = (
        "---\n"
        "string frame_yaml\n"
    )
    Request = FrameGraph_Request
    Response = FrameGraph_Response
