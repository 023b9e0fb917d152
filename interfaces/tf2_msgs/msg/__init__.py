"""Generated from tf2_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.geometry_msgs.msg import TransformStamped

__all__ = [
    "TF2Error",
    "TFMessage",
]

_uint8 = Annotated[int, msgspec.Meta(ge=0, le=255)]


class TF2Error(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tf2_msgs/msg/TF2Error``."""

    __ros_type__: ClassVar[str] = "tf2_msgs/msg/TF2Error"
    __ros_definition__: ClassVar[str] = (
        "uint8 NO_ERROR = 0\n"
        "uint8 LOOKUP_ERROR = 1\n"
        "uint8 CONNECTIVITY_ERROR = 2\n"
        "uint8 EXTRAPOLATION_ERROR = 3\n"
        "uint8 INVALID_ARGUMENT_ERROR = 4\n"
        "uint8 TIMEOUT_ERROR = 5\n"
        "uint8 TRANSFORM_ERROR = 6\n"
        "\n"
        "uint8 error\n"
        "string error_string\n"
    )
    NO_ERROR: ClassVar[int] = 0
    LOOKUP_ERROR: ClassVar[int] = 1
    CONNECTIVITY_ERROR: ClassVar[int] = 2
    EXTRAPOLATION_ERROR: ClassVar[int] = 3
    INVALID_ARGUMENT_ERROR: ClassVar[int] = 4
    TIMEOUT_ERROR: ClassVar[int] = 5
    TRANSFORM_ERROR: ClassVar[int] = 6

    error: _uint8 = 0
    error_string: str = ""


class TFMessage(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tf2_msgs/msg/TFMessage``."""

    __ros_type__: ClassVar[str] = "tf2_msgs/msg/TFMessage"
    __ros_definition__: ClassVar[str] = (
        "geometry_msgs/TransformStamped[] transforms\n"
    )

    transforms: list[TransformStamped] = msgspec.field(default_factory=list)
