"""``rclpy.duration``: actors' Duration, and ``Infinite``."""

from __future__ import annotations

from actors.ros.time import Duration, Infinite

__all__ = ["Duration", "Infinite"]
