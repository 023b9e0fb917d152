"""``rclpy.logging``: loggers outside nodes, severities and levels, as actors' logging has them."""

from __future__ import annotations

from actors.ros.log import (
    LoggingSeverity,
    NodeLogger,
    get_logger,
    get_logger_effective_level,
    get_logger_level,
    get_logging_severity_from_string,
    set_logger_level,
)

__all__ = [
    "LoggingSeverity",
    "NodeLogger",
    "RcutilsLogger",
    "get_logger",
    "get_logger_effective_level",
    "get_logger_level",
    "get_logging_severity_from_string",
    "set_logger_level",
]

RcutilsLogger = NodeLogger
