"""Node logging: Python ``logging`` underneath, ROS's console form on top, and ``/rosout``.

A node's logger is ``logging.getLogger("actors.node.<ns>.<name>")``, so the usual
logging configuration applies.  Records carry the runtime clock's stamp, and
:class:`RosFormatter` prints them as ROS does::

    [INFO] [1700000000.500000000] [minimal_publisher]: Publishing: "Hello World: 0"

Each enabled record is also published as ``rcl_interfaces/msg/Log`` on
``/rosout`` when something subscribes there.  Nothing is formatted for a level
that is disabled.
"""

from __future__ import annotations

import logging
import sys
from collections.abc import Callable
from typing import Any

__all__ = [
    "DEBUG",
    "INFO",
    "WARN",
    "ERROR",
    "FATAL",
    "LEVELS",
    "NodeLogger",
    "RosFormatter",
    "configure_console",
]

DEBUG, INFO, WARN, ERROR, FATAL = 10, 20, 30, 40, 50
LEVELS = {"debug": DEBUG, "info": INFO, "warn": WARN, "warning": WARN, "error": ERROR, "fatal": FATAL}
_LEVEL_NAMES = {DEBUG: "DEBUG", INFO: "INFO", WARN: "WARN", ERROR: "ERROR", FATAL: "FATAL"}

ROOT_LOGGER = "actors"


class NodeLogger:
    """What ``Node.get_logger()`` returns: rclpy's logger methods, Python logging underneath.

    ``sink(level, name, text, stamp_ns)`` receives every enabled record (the
    runtime publishes it on /rosout); ``now_ns()`` stamps it.
    """

    __slots__ = ("name", "_logger", "_now_ns", "_sink", "_once")

    def __init__(
        self,
        name: str,
        now_ns: Callable[[], int],
        sink: Callable[[int, str, str, int], None] | None = None,
    ) -> None:
        self.name = name
        self._logger = logging.getLogger(f"{ROOT_LOGGER}.node.{name}")
        self._now_ns = now_ns
        self._sink = sink
        self._once: set[str] | None = None

    def get_child(self, suffix: str) -> NodeLogger:
        """A logger named ``<name>.<suffix>``, as rclpy's ``get_child``."""
        return NodeLogger(f"{self.name}.{suffix}", self._now_ns, self._sink)

    def set_level(self, level: int | str) -> None:
        """Set this logger's threshold (a level number or a name such as ``"debug"``)."""
        self._logger.setLevel(LEVELS[level.lower()] if isinstance(level, str) else level)

    def is_enabled_for(self, level: int) -> bool:
        """Whether a record of ``level`` would be emitted."""
        return self._logger.isEnabledFor(level)

    def log(self, message: Any, level: int, *, once: bool = False, exc_info: Any = None) -> bool:
        """Emit ``message`` at ``level``; return whether it was emitted."""
        if not self._logger.isEnabledFor(level):
            return False
        text = str(message)
        if once:
            if self._once is None:
                self._once = set()
            if text in self._once:
                return False
            self._once.add(text)
        stamp = self._now_ns()
        self._logger.log(
            level, text, exc_info=exc_info, extra={"ros_stamp": stamp, "ros_name": self.name}
        )
        if self._sink is not None:
            self._sink(level, self.name, text, stamp)
        return True

    def debug(self, message: Any, **kwargs: Any) -> bool:
        """Log at DEBUG."""
        return self.log(message, DEBUG, **kwargs)

    def info(self, message: Any, **kwargs: Any) -> bool:
        """Log at INFO."""
        return self.log(message, INFO, **kwargs)

    def warning(self, message: Any, **kwargs: Any) -> bool:
        """Log at WARN."""
        return self.log(message, WARN, **kwargs)

    warn = warning

    def error(self, message: Any, **kwargs: Any) -> bool:
        """Log at ERROR."""
        return self.log(message, ERROR, **kwargs)

    def fatal(self, message: Any, **kwargs: Any) -> bool:
        """Log at FATAL."""
        return self.log(message, FATAL, **kwargs)

    critical = fatal


class RosFormatter(logging.Formatter):
    """Formats records as ROS's console does: ``[LEVEL] [sec.nanosec] [name]: text``."""

    def format(self, record: logging.LogRecord) -> str:
        stamp = getattr(record, "ros_stamp", None)
        if stamp is None:
            stamp = int(record.created * 1e9)
        name = getattr(record, "ros_name", None) or record.name
        level = _LEVEL_NAMES.get(record.levelno, record.levelname)
        sec, nanosec = divmod(stamp, 1_000_000_000)
        text = f"[{level}] [{sec}.{nanosec:09d}] [{name}]: {record.getMessage()}"
        if record.exc_info:
            text = f"{text}\n{self.formatException(record.exc_info)}"
        return text


def configure_console(level: int = INFO, stream: Any = None) -> logging.Handler:
    """Print actors' records in ROS's form on ``stream`` (stdout by default), at ``level``."""
    root = logging.getLogger(ROOT_LOGGER)
    for handler in list(root.handlers):
        if getattr(handler, "_actors_console", False):
            root.removeHandler(handler)
    handler = logging.StreamHandler(stream or sys.stdout)
    handler.setFormatter(RosFormatter())
    handler._actors_console = True  # type: ignore[attr-defined]
    root.addHandler(handler)
    root.setLevel(level)
    root.propagate = False
    return handler
