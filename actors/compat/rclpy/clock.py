"""``rclpy.clock``: actors' clocks (the runtime's clock: virtual or wall time)."""

from __future__ import annotations

from actors.ros.time import Clock, ClockType, ROSClock

__all__ = ["Clock", "ClockType", "ROSClock"]
