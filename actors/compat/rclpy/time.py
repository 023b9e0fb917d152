"""``rclpy.time``: actors' Time."""

from __future__ import annotations

from actors.clock import Time

__all__ = ["Time"]
