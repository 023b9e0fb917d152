"""``rclpy.signals``: the options rclpy takes; the launcher (``actors run``) handles the signals."""

from __future__ import annotations

from enum import IntEnum

__all__ = ["SignalHandlerOptions", "install_signal_handlers", "uninstall_signal_handlers"]


class SignalHandlerOptions(IntEnum):
    """Which signal handlers ``rclpy.init`` would install."""

    NO = 0
    SIGINT = 1
    SIGTERM = 2
    ALL = 3


def install_signal_handlers(options: SignalHandlerOptions = SignalHandlerOptions.ALL) -> None:
    """Nothing to do: the launcher turns Ctrl-C and SIGTERM into a shutdown of the context."""


def uninstall_signal_handlers() -> None:
    """Nothing to undo."""
