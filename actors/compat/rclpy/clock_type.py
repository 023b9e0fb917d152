"""``rclpy.clock_type``: which clock a Time comes from."""

from __future__ import annotations

from actors.ros.time import ClockType

__all__ = ["ClockType"]
