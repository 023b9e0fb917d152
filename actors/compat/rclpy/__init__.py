"""``rclpy`` for scripts run by actors: init, shutdown, nodes, and spinning them.

This package *is* ``rclpy`` inside ``actors run SCRIPT.py`` (and wherever
:func:`actors.compat.install` put the overlay); its modules are named as
rclpy's.  See :mod:`actors.compat` for how scripts and the runtime share the
process.
"""

from __future__ import annotations

from collections.abc import Sequence
from types import TracebackType
from typing import TYPE_CHECKING, Any

from actors.compat.rclpy.context import Context
from actors.compat.rclpy.parameter import Parameter
from actors.compat.rclpy.qos import QoSProfile
from actors.compat.rclpy.signals import SignalHandlerOptions, install_signal_handlers, uninstall_signal_handlers
from actors.compat.rclpy.task import Future
from actors.compat.rclpy.utilities import (
    get_default_context,
    get_rmw_implementation_identifier,
    ok,
)
from actors.compat.rclpy.utilities import shutdown as _shutdown
from actors.compat.rclpy.utilities import try_shutdown as _try_shutdown
from actors.compat.script_state import script_state

if TYPE_CHECKING:
    from actors.compat.rclpy.executors import Executor
    from actors.compat.rclpy.node import Node

__all__ = [
    "Context",
    "Future",
    "InitContextManager",
    "Parameter",
    "QoSProfile",
    "create_node",
    "get_default_context",
    "get_global_executor",
    "get_rmw_implementation_identifier",
    "init",
    "ok",
    "shutdown",
    "spin",
    "spin_once",
    "spin_until_future_complete",
    "try_shutdown",
]


class InitContextManager:
    """What ``rclpy.init()`` returns: ``with rclpy.init():`` shuts the context down on leaving."""

    def __init__(self, args: Sequence[str] | None, context: Context | None, domain_id: int | None) -> None:
        self.context = get_default_context() if context is None else context
        self.context.init(args, domain_id=domain_id)

    def __enter__(self) -> InitContextManager:
        return self

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        try_shutdown(context=None if self.context is get_default_context() else self.context)


def init(
    *,
    args: Sequence[str] | None = None,
    context: Context | None = None,
    domain_id: int | None = None,
    signal_handler_options: Any = None,
) -> InitContextManager:
    """Initialize ROS communication: read ``args``' ROS arguments (``sys.argv`` if None).

    Signal handling is the launcher's (``actors run``): Ctrl-C shuts the
    context down and raises KeyboardInterrupt in the script, as rclpy's does.
    """
    manager = InitContextManager(args, context, domain_id)
    if signal_handler_options is None:  # rclpy's default: handlers for the default context only
        default = manager.context is get_default_context()
        signal_handler_options = SignalHandlerOptions.ALL if default else SignalHandlerOptions.NO
    install_signal_handlers(signal_handler_options)
    return manager


def get_global_executor() -> Executor:
    """The SingleThreadedExecutor that ``rclpy.spin`` and friends use; replaced after shutdown."""
    _global_executor = script_state().executors  # the process's, or a partner script's own
    if _global_executor and _global_executor[0].context is not get_default_context():
        _global_executor.clear()  # its context ended without a shutdown callback (an interrupt)
    if not _global_executor:
        from actors.compat.rclpy.executors import SingleThreadedExecutor

        executor = SingleThreadedExecutor()
        _global_executor.append(executor)

        def reset() -> None:
            if executor in _global_executor:
                _global_executor.remove(executor)
            executor.shutdown()

        executor.context.on_shutdown(reset)  # at once if it is shut down already (a signal came first)
        return executor
    return _global_executor[0]


def shutdown(*, context: Context | None = None, uninstall_handlers: bool | None = None) -> None:
    """Shut ``context`` (the default one if None) down; RuntimeError if it was not initialized."""
    _shutdown(context=context)
    _forget_handlers(context, uninstall_handlers)


def try_shutdown(*, context: Context | None = None, uninstall_handlers: bool | None = None) -> None:
    """Shut ``context`` down if it is initialized and not shut down already."""
    _try_shutdown(context=context)
    _forget_handlers(context, uninstall_handlers)


def _forget_handlers(context: Context | None, uninstall_handlers: bool | None) -> None:
    # As rclpy: shutting the default context down removes the handlers unless told otherwise.
    if uninstall_handlers or (uninstall_handlers is None and (context is None or context is get_default_context())):
        uninstall_signal_handlers()


def create_node(node_name: str, **options: Any) -> Node:
    """A plain :class:`~actors.compat.rclpy.node.Node` (``rclpy.create_node``); options as its constructor's."""
    from actors.compat.rclpy.node import Node

    return Node(node_name, **options)


def spin_once(node: Node, *, executor: Executor | None = None, timeout_sec: float | None = None) -> None:
    """Run at most one callback of ``node`` (waiting ``timeout_sec`` at most; None waits forever)."""
    executor = get_global_executor() if executor is None else executor
    added = False
    try:
        added = executor.add_node(node)
        executor.spin_once(timeout_sec=timeout_sec)
    finally:
        if added:
            executor.remove_node(node)


def spin(node: Node, executor: Executor | None = None) -> None:
    """Run ``node``'s callbacks until the context shuts down (then ExternalShutdownException)."""
    executor = get_global_executor() if executor is None else executor
    try:
        executor.add_node(node)
        while executor.context.ok():
            executor.spin_once()
    finally:
        executor.remove_node(node)


def spin_until_future_complete(
    node: Node, future: Future[Any], executor: Executor | None = None, timeout_sec: float | None = None
) -> None:
    """Run ``node``'s callbacks until ``future`` is done (or ``timeout_sec`` of runtime clock pass)."""
    executor = get_global_executor() if executor is None else executor
    added = False
    try:
        added = executor.add_node(node)
        executor.spin_until_future_complete(future, timeout_sec)
    finally:
        if added:
            executor.remove_node(node)
