"""``rclpy.context``: init and shutdown of ROS communication, and the session a context runs on.

A context is bound to a :class:`~actors.compat.session.Session` when it is
initialized: the session the launcher (or the grading helper) made current
with :func:`use_session`, or otherwise a wall-clock session of its own, started
by ``init()`` and stopped by ``shutdown()``.  ``init(args)`` reads the ROS
arguments (``--ros-args ...``) every node of the context starts from.
"""

from __future__ import annotations

import logging
import threading
import weakref
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from inspect import ismethod
from typing import Any, Protocol

from actors.compat.script_state import script_state
from actors.compat.session import Session
from actors.launch.rosargs import RosArgs, parse
from actors.ros.log import ROOT_LOGGER, set_logger_level

__all__ = ["Context", "use_session", "current_session"]

_current: list[Session] = []


class _Node(Protocol):
    def destroy_node(self) -> None: ...


@contextmanager
def use_session(session: Session) -> Iterator[Session]:
    """Contexts initialized inside this block run on ``session`` (and leave it running at shutdown)."""
    _current.append(session)
    try:
        yield session
    finally:
        _current.remove(session)


def current_session() -> Session | None:
    """The session :func:`use_session` made current, if any."""
    return _current[-1] if _current else None


class Context:
    """Encapsulates the lifecycle of init and shutdown (``rclpy.init``, ``rclpy.shutdown``)."""

    def __init__(self) -> None:
        self._lock = threading.RLock()
        self._callbacks: list[Any] = []
        self._wakers: weakref.WeakSet[Any] = weakref.WeakSet()
        self._nodes: list[weakref.ReferenceType[_Node]] = []
        self._initialized = False
        self._ok = False
        self._interrupted = False
        self._own_session = False
        self.session: Session | None = None
        self.ros_args = RosArgs()
        self._domain_id = 0

    @property
    def handle(self) -> Context | None:
        """Something that is not None once initialized (rclpy's rcl context)."""
        return self if self._initialized else None

    def init(
        self, args: Sequence[str] | None = None, *, initialize_logging: bool = True, domain_id: int | None = None
    ) -> None:
        """Initialize: read the ROS arguments of ``args`` (``sys.argv`` if None) and bind a session.

        Raises RuntimeError when called twice or for a negative domain id,
        RosArgsError for malformed ROS arguments, and UnicodeEncodeError for an
        argument that is not valid text (undecodable bytes from the locale).
        """
        with self._lock:
            if domain_id is not None and domain_id < 0:
                raise RuntimeError(f"Domain id ({domain_id}) should not be lower than zero.")
            if self._initialized:
                raise RuntimeError("Context.init() must only be called once")
            argv = list(args) if args is not None else script_state().argv
            for arg in argv:  # rcl takes UTF-8: an undecodable argument (PEP 383) fails as in rclpy
                arg.encode("utf-8")
            self.ros_args, _ = parse(argv)
            _apply_log_levels(self.ros_args.log_levels)
            session = current_session()
            if session is None:
                session = Session(clock="wall", name="rclpy").start()
                self._own_session = True
            self.session = session
            self._domain_id = domain_id or 0
            self._initialized = True
            self._ok = not self._interrupted  # interrupted before init: it starts shut down

    def ok(self) -> bool:
        """Whether it is initialized and not shut down."""
        return self._ok

    @property
    def interrupted(self) -> bool:
        """Whether :meth:`interrupt` stopped it (as a signal does)."""
        return self._interrupted

    def track_node(self, node: _Node) -> None:
        """Destroy ``node`` when this context shuts down."""
        with self._lock:
            self._nodes.append(weakref.ref(node))

    def untrack_node(self, node: _Node) -> None:
        """``node`` was destroyed already."""
        with self._lock:
            self._nodes = [ref for ref in self._nodes if ref() not in (None, node)]

    def shutdown(self) -> None:
        """Shut down: destroy its nodes, wake every spin (they raise ExternalShutdownException).

        Raises RuntimeError when not initialized or already shut down.
        """
        with self._lock:
            if not self._initialized:
                raise RuntimeError("Context must be initialized before it can be shutdown")
            if not self._ok:
                raise RuntimeError("rcl_shutdown already called on the given context")
            self._cleanup()

    def try_shutdown(self) -> None:
        """Shut down if initialized and not shut down already."""
        with self._lock:
            if self._ok:
                self._cleanup()

    def finish(self) -> None:
        """Shut down if not already, and destroy what an :meth:`interrupt` left (the launcher's last word)."""
        with self._lock:
            if self._initialized and (self._ok or self._nodes or self._callbacks):
                self._cleanup()

    def interrupt(self) -> None:
        """Shut down as a signal does in rclpy: ``ok()`` turns False and every wait of the context
        wakes (spins raise ExternalShutdownException), but nothing is destroyed or called back yet."""
        with self._lock:
            self._ok = False
            self._interrupted = True
            wakers = list(self._wakers)
        for waker in wakers:
            waker.wake()

    def add_waker(self, waker: Any) -> None:
        """Wake ``waker`` (it has ``wake()``; held weakly) whenever the context shuts down."""
        with self._lock:
            self._wakers.add(waker)

    def _cleanup(self) -> None:
        for ref in list(self._nodes):
            node = ref()
            if node is not None:
                node.destroy_node()
        self._nodes = []
        self._ok = False
        for waker in list(self._wakers):
            waker.wake()
        callbacks, self._callbacks = self._callbacks, []
        for entry in callbacks:
            callback = entry() if isinstance(entry, weakref.WeakMethod) else entry
            if callback is not None:
                callback()
        if self._own_session and self.session is not None:
            self.session.close()

    def on_shutdown(self, callback: Callable[[], None]) -> None:
        """Call ``callback()`` at shutdown (at once if shut down already); TypeError if not callable."""
        if not callable(callback):
            raise TypeError(f"callback should be a callable, got {type(callback)}")
        with self._lock:
            if self._initialized and not self._ok:
                callback()
            else:
                self._callbacks.append(weakref.WeakMethod(callback) if ismethod(callback) else callback)

    def get_domain_id(self) -> int:
        """The domain id given to ``init`` (0 by default); it changes nothing in one process."""
        if not self._initialized:
            raise RuntimeError("Context must be initialized before it can have a domain id")
        return self._domain_id

    def destroy(self) -> None:
        """Nothing to release."""

    def __enter__(self) -> Context:
        if not self._initialized:
            self.init()
        return self

    def __exit__(self, *exc: object) -> None:
        self.try_shutdown()


def _apply_log_levels(levels: dict[str, int]) -> None:
    for name, level in levels.items():
        if name:
            set_logger_level(name, level)
        else:
            logging.getLogger(ROOT_LOGGER).setLevel(level)
