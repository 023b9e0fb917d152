"""``rclpy.clock``: actors' Clock (the runtime's clock: virtual or wall time)."""

from __future__ import annotations

from actors.clock import Clock

__all__ = ["Clock"]
