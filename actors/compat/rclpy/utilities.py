"""``rclpy.utilities``: the default context, ``ok``/``shutdown``, ``remove_ros_args``."""

from __future__ import annotations

import threading
from collections.abc import Sequence

from actors.compat.rclpy.constants import S_TO_NS
from actors.compat.rclpy.context import Context
from actors.compat.script_state import script_state
from actors.launch.rosargs import remove_ros_args as _remove_ros_args

__all__ = [
    "get_default_context",
    "ok",
    "shutdown",
    "try_shutdown",
    "remove_ros_args",
    "timeout_sec_to_nsec",
    "get_rmw_implementation_identifier",
    "get_available_rmw_implementations",
]

RMW_IMPLEMENTATION = "rmw_actors"

_lock = threading.Lock()


def get_default_context(*, shutting_down: bool = False) -> Context:
    """The default context (made on first use); ``shutting_down`` hands it over and forgets it."""
    _default = script_state().contexts  # the process's, or a partner script's own (actors run --with)
    with _lock:
        if not _default:
            _default.append(Context())
        if shutting_down:
            return _default.pop()
        return _default[0]


def ok(*, context: Context | None = None) -> bool:
    """Whether ``context`` (the default one if None) is initialized and not shut down."""
    return (context or get_default_context()).ok()


def shutdown(*, context: Context | None = None) -> None:
    """Shut ``context`` down (the default one, which is then replaced by a fresh one)."""
    (context or get_default_context(shutting_down=True)).shutdown()


def try_shutdown(*, context: Context | None = None) -> None:
    """Shut ``context`` down if it is not already."""
    if context is not None:
        context.try_shutdown()
        return
    _default = script_state().contexts
    with _lock:
        if not _default:
            return
        default = _default[0]
    default.try_shutdown()
    with _lock:
        if _default and _default[0] is default and not default.ok():
            _default.pop()


def remove_ros_args(args: Sequence[str] | None = None) -> list[str]:
    """``args`` (``sys.argv`` if None) without the ``--ros-args ... [--]`` sections."""
    return _remove_ros_args(list(args) if args is not None else script_state().argv)


def timeout_sec_to_nsec(timeout_sec: float | None) -> int:
    """A timeout in seconds as nanoseconds; -1 (forever) for None or a negative one."""
    if timeout_sec is None or timeout_sec < 0:
        return -1
    return int(float(timeout_sec) * S_TO_NS)


def get_rmw_implementation_identifier() -> str:
    """``rmw_actors``: messages travel inside the runtime."""
    return RMW_IMPLEMENTATION


def get_available_rmw_implementations() -> set[str]:
    """The one middleware there is."""
    return {RMW_IMPLEMENTATION}
