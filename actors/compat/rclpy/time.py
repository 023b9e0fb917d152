"""``rclpy.time``: actors' Time (and the ClockType it carries)."""

from __future__ import annotations

from actors.clock import ClockType, Time

__all__ = ["Time", "ClockType"]
