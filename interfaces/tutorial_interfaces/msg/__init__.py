"""Generated from tutorial_interfaces/msg/*.msg by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.geometry_msgs.msg import Point

__all__ = [
    "Num",
    "Sphere",
]

_int64 = Annotated[int, msgspec.Meta(ge=-9223372036854775808, le=9223372036854775807)]


class Num(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tutorial_interfaces/msg/Num``."""

    __ros_type__: ClassVar[str] = "tutorial_interfaces/msg/Num"
    __ros_definition__: ClassVar[str] = (
        "int64 num\n"
    )

    num: _int64 = 0


class Sphere(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tutorial_interfaces/msg/Sphere``."""

    __ros_type__: ClassVar[str] = "tutorial_interfaces/msg/Sphere"
    __ros_definition__: ClassVar[str] = (
        "geometry_msgs/Point center\n"
        "float64 radius\n"
    )

    center: Point = msgspec.field(default_factory=Point)
    radius: float = 0.0
