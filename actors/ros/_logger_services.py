"""A node's logger services (``enable_logger_service=True``): read and set logger levels remotely, as rclpy's."""

from __future__ import annotations

from typing import Any

from actors.ros._param_services import ServiceHost
from actors.ros.log import LoggingSeverity, get_logger_level, set_logger_level
from interfaces.rcl_interfaces.msg import LoggerLevel, SetLoggerLevelsResult
from interfaces.rcl_interfaces.srv import GetLoggerLevels, SetLoggerLevels

__all__ = ["serve_logger_levels"]

INVALID_LEVEL = "Failed reason: Invalid logger level."  # rclpy's reason, word for word


def serve_logger_levels(host: ServiceHost) -> None:
    """Serve ``~/get_logger_levels`` and ``~/set_logger_levels`` for every logger of the process.

    A logger is named as ``get_logger(name)`` names it (a node's logger by its
    node: ``ns.name``).  A level never set reads 0 (unset: it follows its
    parent); a level that is not one of rcutils' severities is refused with
    rclpy's reason and leaves the logger as it was.
    """

    def get(request: Any, response: Any) -> Any:
        response.levels = [LoggerLevel(name=name, level=int(get_logger_level(name))) for name in request.names]
        return response

    def set_each(request: Any, response: Any) -> Any:
        response.results = [_set(entry) for entry in request.levels]
        return response

    host.create_service(GetLoggerLevels, "~/get_logger_levels", get)
    host.create_service(SetLoggerLevels, "~/set_logger_levels", set_each)


def _set(entry: LoggerLevel) -> SetLoggerLevelsResult:
    try:
        set_logger_level(entry.name, LoggingSeverity(entry.level))
    except ValueError:
        return SetLoggerLevelsResult(successful=False, reason=INVALID_LEVEL)
    return SetLoggerLevelsResult(successful=True)
