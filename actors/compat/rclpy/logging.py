"""``rclpy.logging``: loggers outside nodes, severities, levels and the logging directory, as rclpy's.

:class:`RcutilsLogger` is actors' node logger with rclpy's stricter habits:
every call site keeps its severity, name and filters (a change is a
ValueError), an unknown keyword is a TypeError, and the severity methods refuse
a ``severity=`` of their own.  ``_root_logger`` is the logger every other one
inherits its level from, as rcutils' unnamed root.
"""

from __future__ import annotations

import logging
import os
from pathlib import Path
from typing import Any

from actors.ros.log import (
    ROOT_LOGGER,
    LoggingSeverity,
    NodeLogger,
    get_logger_effective_level,
    get_logger_level,
    set_logger_level,
)
from actors.ros.log import get_logging_severity_from_string as _severity_from_string
from actors.ros.time import Clock

__all__ = [
    "LoggingSeverity",
    "RcutilsLogger",
    "clear_config",
    "get_logger",
    "get_logger_effective_level",
    "get_logger_level",
    "get_logging_directory",
    "get_logging_severity_from_string",
    "set_logger_level",
]

_OPTIONS = frozenset({"name", "once", "skip_first", "throttle_duration_sec", "throttle_time_source_type", "exc_info"})


_NODES = f"{ROOT_LOGGER}.node"


def _effective(logger: logging.Logger) -> int:
    # rcutils' default level is INFO where Python's is WARNING: an rclpy logger follows the levels
    # set on it and its parents (the root logger included), then a level set on actors' logger,
    # and INFO when none is, without setting any level itself (native loggers keep Python's).
    current: logging.Logger | None = logger
    while current is not None:
        if current.level != logging.NOTSET:
            return current.level
        if current.name == _NODES:
            break
        current = current.parent
    ours = logging.getLogger(ROOT_LOGGER)
    return ours.level if ours.level != logging.NOTSET else LoggingSeverity.INFO


# rcutils' root logger set to UNSET lets every record through (its threshold is then 0, where a
# named logger's UNSET means "ask the parent"); Python's level 0 means the latter, so the root
# holds this level, below DEBUG, instead, and reads it back as UNSET.
_ROOT_UNSET = 1


class RcutilsLogger(NodeLogger):
    """A logger as rclpy's: ``log(message, severity, **options)`` and the severity methods."""

    _every_site = True
    _throttled_since_zero = True
    _internal_files = NodeLogger._internal_files | {__file__}

    def get_effective_level(self) -> LoggingSeverity:
        """The threshold in force: this logger's, the nearest parent's, else actors' own level, else INFO
        (UNSET when that is the root logger's, set to UNSET)."""
        level = _effective(self._logger)
        return LoggingSeverity.UNSET if level == _ROOT_UNSET else LoggingSeverity(level)

    def is_enabled_for(self, level: int) -> bool:
        """Whether a record of ``level`` would be emitted."""
        return level >= _effective(self._logger)

    def _enabled(self, logger: logging.Logger, level: int) -> bool:
        return level >= _effective(logger)

    def log(self, message: Any, severity: int, **options: Any) -> bool:  # type: ignore[override]  # rclpy's form
        """Emit ``message`` at ``severity``; whether it was emitted.

        Raises TypeError for an unknown option or a throttle clock without a
        throttle duration, ValueError when this call site changes its severity,
        name or options between calls.
        """
        for option in options:
            if option not in _OPTIONS:
                raise TypeError(f"parameter '{option}' is not one of the recognized logging options")
        if "throttle_time_source_type" in options and "throttle_duration_sec" not in options:
            raise TypeError("required parameter 'throttle_duration_sec' not specified but is required for throttle")
        return super().log(message, severity, **options)


class _RootLogger(RcutilsLogger):
    """rcutils' unnamed root logger: the level every other logger falls back to."""

    def __init__(self) -> None:
        # Made under a placeholder name, since a named logger must have one.
        super().__init__("_", Clock().now_ns)
        self.name = ""
        self._logger = logging.getLogger(_NODES)

    def set_level(self, level: int | str) -> None:
        """Set the level every logger without one of its own follows; UNSET lets every record through."""
        super().set_level(level)
        if self._logger.level == logging.NOTSET:
            self._logger.setLevel(_ROOT_UNSET)


_root_logger: RcutilsLogger = _RootLogger()


def get_logger(name: str) -> RcutilsLogger:
    """The logger ``name`` (a node's logger is named like its node); ValueError for an empty name."""
    return RcutilsLogger(name, Clock().now_ns)


def get_logging_severity_from_string(log_severity: str) -> LoggingSeverity:
    """``"info"`` (any case) -> INFO; RuntimeError for an unknown name, as rclpy's."""
    try:
        return _severity_from_string(log_severity)
    except ValueError as error:
        raise RuntimeError(str(error)) from None


def clear_config() -> None:
    """Forget every logger's own level: each follows the root logger again."""
    prefix = f"{ROOT_LOGGER}.node."
    for name, logger in list(logging.root.manager.loggerDict.items()):
        if name.startswith(prefix) and isinstance(logger, logging.Logger):
            logger.setLevel(logging.NOTSET)


def get_logging_directory() -> Path:
    """Where ROS writes log files: ``$ROS_LOG_DIR``, else ``$ROS_HOME/log``, else ``~/.ros/log``."""
    if os.environ.get("ROS_LOG_DIR"):
        return Path(os.path.expanduser(os.environ["ROS_LOG_DIR"]))
    home = os.environ.get("ROS_HOME") or os.path.join(os.path.expanduser("~"), ".ros")
    return Path(home) / "log"
