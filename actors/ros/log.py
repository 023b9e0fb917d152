"""Node logging: Python ``logging`` underneath, ROS's console form on top, and ``/rosout``.

A node's logger is ``logging.getLogger("actors.ros.node.<ns>.<name>")``, so the usual
logging configuration applies.  Records carry the runtime clock's stamp, and
:class:`RosFormatter` prints them as ROS does::

    [INFO] [1700000000.500000000] [minimal_publisher]: Publishing: "Hello World: 0"

Each enabled record is also published as ``rcl_interfaces/msg/Log`` on
``/rosout`` when something subscribes there.  Nothing is formatted for a level
that is disabled.

The logging calls take rclpy's filters: ``once=True`` (the first call from
that line only), ``skip_first=True``, ``throttle_duration_sec=S`` (at most one
record per S seconds of the node's clock, so virtual time throttles
deterministically; ``throttle_time_source_type=clock`` measures on another
clock).  Each call site (the line, and the call on it) keeps its own state, as
in rclpy.  :func:`get_logger` gives a logger outside any node, as
``rclpy.logging.get_logger``; its records are stamped by the system clock.
"""

from __future__ import annotations

import logging
import sys
from collections.abc import Callable
from enum import IntEnum
from typing import Any

from actors.ros.time import Clock

__all__ = [
    "LoggingSeverity",
    "DEBUG",
    "INFO",
    "WARN",
    "ERROR",
    "FATAL",
    "LEVELS",
    "NodeLogger",
    "RosFormatter",
    "configure_console",
    "get_logger",
    "set_logger_level",
    "get_logger_level",
    "get_logger_effective_level",
    "get_logging_severity_from_string",
    "console_unless_configured",
]


class LoggingSeverity(IntEnum):
    """Log severities, numbered as rcutils' (and as Python's levels: DEBUG is 10)."""

    UNSET = 0
    DEBUG = 10
    INFO = 20
    WARN = 30
    ERROR = 40
    FATAL = 50


DEBUG, INFO, WARN, ERROR, FATAL = (
    LoggingSeverity.DEBUG,
    LoggingSeverity.INFO,
    LoggingSeverity.WARN,
    LoggingSeverity.ERROR,
    LoggingSeverity.FATAL,
)
LEVELS = {"debug": DEBUG, "info": INFO, "warn": WARN, "warning": WARN, "error": ERROR, "fatal": FATAL}
_LEVEL_NAMES: dict[int, str] = {DEBUG: "DEBUG", INFO: "INFO", WARN: "WARN", ERROR: "ERROR", FATAL: "FATAL"}

ROOT_LOGGER = "actors"


def _severity(level: int | str) -> LoggingSeverity:
    """``level`` (a number or a name such as ``"debug"``) as a LoggingSeverity; ValueError if none."""
    if isinstance(level, str):
        if level.lower() in LEVELS:
            return LEVELS[level.lower()]
        if level.lower() == "unset":
            return LoggingSeverity.UNSET
        raise ValueError(f"unknown log severity {level!r}: choose from unset, {', '.join(LEVELS)}")
    return LoggingSeverity(level)


class _CallSite:
    """The filters' state for one logging call site, and the arguments they were set up with."""

    __slots__ = ("arguments", "logged_once", "skipped_first", "last_logged")

    def __init__(self, arguments: tuple[Any, ...]) -> None:
        self.arguments = arguments
        self.logged_once = False
        self.skipped_first = False
        self.last_logged: int | None = None


class NodeLogger:
    """What ``Node.get_logger()`` returns: rclpy's logger methods, Python logging underneath.

    ``sink(level, name, text, stamp_ns)`` receives every enabled record (the
    runtime publishes it on /rosout); ``now_ns()`` stamps it.
    """

    __slots__ = ("name", "_logger", "_now_ns", "_sink", "_sites")

    # Whether every call site is checked for a changed level or filters (rclpy's loggers do it),
    # or only those with a filter, which spares the usual call its frame lookup.
    _every_site = False
    # Whether a throttled call site counts as last logged at time zero (rcutils' habit, so that
    # nothing logs in the first throttle period of a clock starting at zero) or never.
    _throttled_since_zero = False
    # The files whose frames are this logger's own, skipped when looking for the call site.
    _internal_files: frozenset[str] = frozenset({__file__})

    def __init__(
        self,
        name: str,
        now_ns: Callable[[], int],
        sink: Callable[[int, str, str, int], None] | None = None,
    ) -> None:
        if not name:
            raise ValueError("Logger name must not be empty")
        self.name = name
        self._logger = logging.getLogger(f"{ROOT_LOGGER}.node.{name}")
        self._now_ns = now_ns
        self._sink = sink
        self._sites: dict[tuple[Any, int], _CallSite] | None = None

    @property
    def sink(self) -> Callable[[int, str, str, int], None] | None:
        """What receives every emitted record besides Python logging (the runtime's ``/rosout``)."""
        return self._sink

    def get_child(self, suffix: str) -> NodeLogger:
        """A logger named ``<name>.<suffix>``, as rclpy's ``get_child``; ValueError for an empty suffix."""
        if not suffix:
            raise ValueError("Child logger name must not be empty")
        return type(self)(f"{self.name}.{suffix}", self._now_ns, self._sink)

    def set_level(self, level: int | str) -> None:
        """Set this logger's threshold: a LoggingSeverity, a number, or a name such as ``"debug"``.

        UNSET makes it follow its parent again.  ValueError for an unknown level.
        """
        self._logger.setLevel(_severity(level))

    def get_effective_level(self) -> LoggingSeverity:
        """The threshold in force: this logger's, or the nearest parent's."""
        return LoggingSeverity(self._logger.getEffectiveLevel())

    def is_enabled_for(self, level: int) -> bool:
        """Whether a record of ``level`` would be emitted."""
        return self._logger.isEnabledFor(level)

    def log(
        self,
        message: Any,
        level: int,
        *,
        once: bool = False,
        skip_first: bool = False,
        throttle_duration_sec: float | None = None,
        throttle_time_source_type: Clock | None = None,
        exc_info: Any = None,
        name: str | None = None,
    ) -> bool:
        """Emit ``message`` at ``level``; return whether it was emitted.

        The filters (``once``, ``skip_first``, ``throttle_duration_sec``) keep
        their state per call site; they are applied, in rclpy's order (throttle,
        skip first, once), only when the level is enabled.  ``name`` logs under
        another logger's name.  Raises ValueError when one call site changes its
        level, name or filters between calls, as rclpy.
        """
        logger = self._logger if name is None else logging.getLogger(f"{ROOT_LOGGER}.node.{name}")
        if not self._enabled(logger, level):
            if self._every_site:
                self._site(level, once, skip_first, throttle_duration_sec, throttle_time_source_type, name)
            return False
        if (once or skip_first or throttle_duration_sec or name or self._every_site) and not self._passes(
            self._site(level, once, skip_first, throttle_duration_sec, throttle_time_source_type, name),
            once,
            skip_first,
            throttle_duration_sec,
            throttle_time_source_type,
        ):
            return False
        text = str(message)
        stamp = self._now_ns()
        ros_name = self.name if name is None else name
        # Logger._log: the level was decided above (by _enabled), so Python's check is not repeated.
        logger._log(level, text, (), exc_info=exc_info, extra={"ros_stamp": stamp, "ros_name": ros_name})
        if self._sink is not None:
            self._sink(level, ros_name, text, stamp)
        return True

    def _enabled(self, logger: logging.Logger, level: int) -> bool:
        # Python's levels decide; rclpy's loggers (actors.compat) fall back to INFO, as rcutils'.
        return logger.isEnabledFor(level)

    def _site(self, *arguments: Any) -> _CallSite:
        frame = sys._getframe(2)
        internal = self._internal_files
        while frame.f_code.co_filename in internal:  # from debug()/info()... to the user's call
            frame = frame.f_back  # type: ignore[assignment]  # never None: the user's call is above
        key = (frame.f_code, frame.f_lasti)
        if self._sites is None:
            self._sites = {}
        site = self._sites.get(key)
        if site is None:
            site = self._sites[key] = _CallSite(arguments)
        elif site.arguments != arguments:
            # rclpy's words for each change, which its users (and tests) match on
            if site.arguments[0] != arguments[0]:
                changed = "Logger severity"
            elif site.arguments[-1] != arguments[-1]:
                changed = "Logger name"
            else:
                changed = "Logging parameters"
            raise ValueError(f"{changed} cannot be changed between calls (was {site.arguments}, now {arguments})")
        return site

    def _passes(
        self, site: _CallSite, once: bool, skip_first: bool, throttle: float | None, source: Clock | None
    ) -> bool:
        if throttle:
            now = source.now().nanoseconds if source is not None else self._now_ns()
            last = 0 if site.last_logged is None and self._throttled_since_zero else site.last_logged
            if last is not None and now < last + throttle * 1e9:
                return False
            site.last_logged = now
        if skip_first and not site.skipped_first:
            site.skipped_first = True
            return False
        if once:
            if site.logged_once:
                return False
            site.logged_once = True
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


def get_logger(name: str) -> NodeLogger:
    """A logger outside any node, as ``rclpy.logging.get_logger``; stamped by the system clock.

    A node's logger of the same name is the same Python logger underneath, so
    they share their level.  ValueError for an empty name.
    """
    return NodeLogger(name, Clock().now_ns)


def set_logger_level(name: str, level: int | str) -> None:
    """Set the threshold of the logger ``name`` (a node's logger is named like its node)."""
    get_logger(name).set_level(level)


def get_logger_level(name: str) -> LoggingSeverity:
    """The threshold set on the logger ``name`` itself (UNSET when it follows its parent)."""
    return LoggingSeverity(logging.getLogger(f"{ROOT_LOGGER}.node.{name}").level)


def get_logger_effective_level(name: str) -> LoggingSeverity:
    """The threshold in force for the logger ``name``."""
    return get_logger(name).get_effective_level()


def get_logging_severity_from_string(severity: str) -> LoggingSeverity:
    """``"info"`` (any case) -> ``LoggingSeverity.INFO``; ValueError for an unknown name."""
    return _severity(severity)


class _ConsoleHandler(logging.StreamHandler):
    """The handler :func:`configure_console` installs, which a later call finds and replaces."""

    _actors_console = True


def configure_console(level: int = INFO, stream: Any = None) -> logging.Handler:
    """Print actors' records in ROS's form on ``stream`` (stdout by default), at ``level``."""
    root = logging.getLogger(ROOT_LOGGER)
    for handler in list(root.handlers):
        if getattr(handler, "_actors_console", False):
            root.removeHandler(handler)
    handler = _ConsoleHandler(stream or sys.stdout)
    handler.setFormatter(RosFormatter())
    root.addHandler(handler)
    root.setLevel(level)
    root.propagate = False
    return handler


def console_unless_configured(level: int = INFO) -> logging.Handler | None:
    """Print actors' records on stderr at ``level``, as rclpy does, unless logging is configured.

    Configured means: the root logger has a handler (``logging.basicConfig``,
    pytest's capture), or the ``actors`` logger has a handler or a level of its
    own.  Then nothing changes and None is returned.  A runtime calls this as
    it starts, so an embedded graph's nodes are heard without any set-up.
    """
    ours = logging.getLogger(ROOT_LOGGER)
    if logging.getLogger().handlers or ours.handlers or ours.level != logging.NOTSET:
        return None
    return configure_console(level, sys.stderr)
