"""Generated from tf2_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from typing import ClassVar

import msgspec

from interfaces.geometry_msgs.msg import TransformStamped

__all__ = [
    "TFMessage",
]


class TFMessage(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``tf2_msgs/msg/TFMessage``."""

    __ros_type__: ClassVar[str] = "tf2_msgs/msg/TFMessage"
    __ros_definition__: ClassVar[str] = (
        "geometry_msgs/TransformStamped[] transforms\n"
    )

    transforms: list[TransformStamped] = msgspec.field(default_factory=list)
