"""``tf2_ros`` for scripts run by actors: the buffer, its listener, the broadcasters, tf2's exceptions.

Inside ``actors run`` (and wherever :func:`actors.compat.install` put the
overlay) ``import tf2_ros`` is this package; its modules are named as
tf2_ros's.  The frames and lookups are :class:`actors.ros.tf_buffer.BufferCore`'s;
these modules only join it to an rclpy node.
"""

from __future__ import annotations

from actors.compat.tf2_ros.buffer import Buffer
from actors.compat.tf2_ros.buffer_interface import (
    BufferInterface,
    ConvertRegistration,
    NotImplementedException,
    TransformRegistration,
    TypeException,
    convert,
)
from actors.compat.tf2_ros.static_transform_broadcaster import StaticTransformBroadcaster
from actors.compat.tf2_ros.transform_broadcaster import TransformBroadcaster
from actors.compat.tf2_ros.transform_listener import TransformListener
from actors.errors import (
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TimeoutException,
    TransformException,
)
from actors.ros.tf_buffer import BufferCore

__all__ = [
    "Buffer",
    "BufferCore",
    "BufferInterface",
    "ConvertRegistration",
    "NotImplementedException",
    "TransformRegistration",
    "TypeException",
    "convert",
    "StaticTransformBroadcaster",
    "TransformBroadcaster",
    "TransformListener",
    "ConnectivityException",
    "ExtrapolationException",
    "InvalidArgumentException",
    "LookupException",
    "TimeoutException",
    "TransformException",
]
