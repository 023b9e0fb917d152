"""``rclpy.time``: actors' Time (and the ClockType it carries)."""

from __future__ import annotations

from actors.ros.time import ClockType, Time

__all__ = ["Time", "ClockType"]
