"""``rclpy.signals``: the options rclpy takes; the launcher (``actors run``) handles the signals.

``rclpy.init`` records which handlers it would install (all, for the default
context) and ``shutdown`` forgets them, so
``get_current_signal_handlers_options`` answers as rclpy's does; the
signals themselves are the launcher's either way.
"""

from __future__ import annotations

from enum import IntEnum

__all__ = [
    "SignalHandlerOptions",
    "get_current_signal_handlers_options",
    "install_signal_handlers",
    "uninstall_signal_handlers",
]


class SignalHandlerOptions(IntEnum):
    """Which signal handlers ``rclpy.init`` would install."""

    NO = 0
    SIGINT = 1
    SIGTERM = 2
    ALL = 3


_installed = [SignalHandlerOptions.NO]  # what rclpy would have installed now


def install_signal_handlers(options: SignalHandlerOptions = SignalHandlerOptions.ALL) -> None:
    """Record ``options``; the launcher turns Ctrl-C and SIGTERM into a shutdown of the context."""
    _installed[0] = SignalHandlerOptions(options)


def uninstall_signal_handlers() -> None:
    """Record that none are installed."""
    _installed[0] = SignalHandlerOptions.NO


def get_current_signal_handlers_options() -> SignalHandlerOptions:
    """The handlers ``rclpy.init`` installed and no ``shutdown`` removed since."""
    return _installed[0]
