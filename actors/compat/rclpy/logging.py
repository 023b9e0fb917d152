"""``rclpy.logging``: actors' logging levels and node loggers."""

from __future__ import annotations

from actors.log import DEBUG, ERROR, FATAL, INFO, WARN, NodeLogger

__all__ = ["DEBUG", "INFO", "WARN", "ERROR", "FATAL", "NodeLogger"]
