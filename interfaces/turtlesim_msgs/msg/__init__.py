"""Generated from turtlesim_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

__all__ = [
    "Color",
    "Pose",
]

_uint8 = Annotated[int, msgspec.Meta(ge=0, le=255)]


class Color(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/msg/Color``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/msg/Color"
    __ros_definition__: ClassVar[str] = (
        "uint8 r\n"
        "uint8 g\n"
        "uint8 b\n"
    )

    r: _uint8 = 0
    g: _uint8 = 0
    b: _uint8 = 0


class Pose(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``turtlesim_msgs/msg/Pose``."""

    __ros_type__: ClassVar[str] = "turtlesim_msgs/msg/Pose"
    __ros_definition__: ClassVar[str] = (
        "float32 x\n"
        "float32 y\n"
        "float32 theta\n"
        "\n"
        "float32 linear_velocity\n"
        "float32 angular_velocity\n"
    )

    x: float = 0.0
    y: float = 0.0
    theta: float = 0.0
    linear_velocity: float = 0.0
    angular_velocity: float = 0.0
