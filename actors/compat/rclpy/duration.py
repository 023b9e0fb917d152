"""``rclpy.duration``: actors' Duration."""

from __future__ import annotations

from actors.clock import Duration

__all__ = ["Duration"]
