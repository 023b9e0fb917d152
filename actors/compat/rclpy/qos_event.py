"""``rclpy.qos_event``: the older name of ``rclpy.event_handler``."""

from __future__ import annotations

from actors.compat.rclpy import event_handler as _event_handler
from actors.compat.rclpy.event_handler import *  # noqa: F403 - the same names

__all__ = list(_event_handler.__all__)
