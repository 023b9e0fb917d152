"""Generated from sensor_msgs/srv/*.srv by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.sensor_msgs.msg import CameraInfo
from interfaces.service_msgs.msg import ServiceEventInfo

__all__ = [
    "SetCameraInfo",
    "SetCameraInfo_Event",
    "SetCameraInfo_Request",
    "SetCameraInfo_Response",
]


class SetCameraInfo_Request(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/srv/SetCameraInfo_Request``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/srv/SetCameraInfo_Request"
    __ros_definition__: ClassVar[str] = (
        "# This service requests that a camera stores the given CameraInfo as that\n"
        "# camera's calibration information.\n"
        "#\n"
        "# The width and height in the camera_info field should match what the\n"
        "# camera is currently outputting on its camera_info topic, and the camera\n"
        "# will assume that the region of the imager that is being referred to is\n"
        "# the region that the camera is currently capturing.\n"
        "\n"
        "sensor_msgs/CameraInfo camera_info # The camera_info to store\n"
    )

    camera_info: CameraInfo = msgspec.field(default_factory=CameraInfo)


class SetCameraInfo_Response(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/srv/SetCameraInfo_Response``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/srv/SetCameraInfo_Response"
    __ros_definition__: ClassVar[str] = (
        "bool success                             # True if the call succeeded\n"
        "string status_message                    # Used to give details about success\n"
    )

    success: bool = False
    status_message: str = ""


class SetCameraInfo_Event(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/srv/SetCameraInfo_Event``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/srv/SetCameraInfo_Event"
    __ros_definition__: ClassVar[str] = (
        "service_msgs/ServiceEventInfo info\n"
        "sensor_msgs/srv/SetCameraInfo_Request[<=1] request\n"
        "sensor_msgs/srv/SetCameraInfo_Response[<=1] response\n"
    )

    info: ServiceEventInfo = msgspec.field(default_factory=ServiceEventInfo)
    request: Annotated[list[SetCameraInfo_Request], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)
    response: Annotated[list[SetCameraInfo_Response], msgspec.Meta(max_length=1)] = msgspec.field(default_factory=list)


class SetCameraInfo:
    """``sensor_msgs/srv/SetCameraInfo``: its ``Request`` and ``Response`` messages, and ``Event``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/srv/SetCameraInfo"
    __ros_definition__: ClassVar[str] = (
        "# This service requests that a camera stores the given CameraInfo as that\n"
        "# camera's calibration information.\n"
        "#\n"
        "# The width and height in the camera_info field should match what the\n"
        "# camera is currently outputting on its camera_info topic, and the camera\n"
        "# will assume that the region of the imager that is being referred to is\n"
        "# the region that the camera is currently capturing.\n"
        "\n"
        "sensor_msgs/CameraInfo camera_info # The camera_info to store\n"
        "---\n"
        "bool success                             # True if the call succeeded\n"
        "string status_message                    # Used to give details about success\n"
    )
    Request = SetCameraInfo_Request
    Response = SetCameraInfo_Response
    Event = SetCameraInfo_Event
