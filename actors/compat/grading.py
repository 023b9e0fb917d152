"""Grading rclpy exercises: a student's unmodified script beside a graph, on the virtual clock.

::

    with run_script("constant_control.py", graph="graphs/turtlebot_world.toml") as run:
        odom = run.record("/odom")          # every message from now on
        run.wait(3.0)                       # three simulated seconds
        run.publish("/kill", Bool(data=True))
        run.call("/add_two_ints", AddTwoInts.Request(a=2, b=3))

The script runs as ``actors run`` runs it (``__main__``, ``sys.argv``, the
overlay), on a thread of its own, while the test's thread drives: virtual time
moves only while the test waits (``wait``, ``call``) and the script waits too,
so a run is the same every time and takes milliseconds.  Leaving the block
stops the script as Ctrl-C would (its spin raises ExternalShutdownException)
and re-raises what the script raised, if anything.
"""

from __future__ import annotations

import logging
import runpy
import sys
import threading
from collections.abc import Callable
from contextlib import ExitStack
from pathlib import Path
from types import TracebackType
from typing import Any, cast

from actors.codec import get_type
from actors.compat.overlay import overlaid
from actors.compat.rclpy.context import use_session
from actors.compat.rclpy.executors import ExternalShutdownException
from actors.compat.rclpy.utilities import get_default_context, try_shutdown
from actors.compat.session import Session
from actors.compat.turns import Waiter
from actors.launch.graph_file import load_graph
from actors.ros.log import INFO, ROOT_LOGGER, RosFormatter
from actors.ros.node import Node as NativeNode
from actors.ros.qos import HistoryPolicy, QoSProfile, ReliabilityPolicy

__all__ = ["ScriptRun", "run_script", "run_node"]

# Records everything, from reliable and best-effort publishers alike.
_RECORDING = QoSProfile(history=HistoryPolicy.KEEP_ALL, reliability=ReliabilityPolicy.BEST_EFFORT)
_STOP_WITHIN = 60.0  # simulated seconds a script gets to end after it is stopped


def run_script(script: str | Path, *args: str, graph: str | Path | None = None, clock: str = "virtual") -> ScriptRun:
    """A :class:`ScriptRun` of ``script`` with ``args`` as its arguments (start it with ``with``)."""
    return ScriptRun(Path(script), [str(a) for a in args], graph, clock)


def run_node(node: str | type, *args: str, graph: str | Path | None = None, clock: str = "virtual") -> ScriptRun:
    """A :class:`ScriptRun` that spins one node of ``node``'s class, as ``rclpy.spin(Cls())`` would.

    ``node`` is ``"path/to/file.py:Class"`` (imported inside the overlay) or a
    class imported under it already.
    """
    return ScriptRun(node, [str(a) for a in args], graph, clock)


class _Probe(NativeNode):
    """The grader's own node: records topics, publishes and calls services for the test."""

    def __init__(self) -> None:
        super().__init__("_grader")


class ScriptRun:
    """One run of a student's program beside a graph; use it as a context manager.

    ``exit_code`` is the script's (0 when it was stopped by leaving the block, or
    ended by itself without error), ``error`` what it raised; ``log`` holds every
    log line of the run in ROS's console form.
    """

    def __init__(self, target: Path | str | type, argv: list[str], graph: str | Path | None, clock: str) -> None:
        self.target = target
        self.argv = argv
        self.graph = graph
        self.clock = clock
        self.log: list[str] = []
        self.exit_code: int | None = None
        self.error: BaseException | None = None
        self._stack = ExitStack()
        self._session: Session
        self._probe: _Probe
        self._publishers: dict[str, Any] = {}
        self._clients: dict[str, Any] = {}
        self._stopping = False
        self._done = False
        self._thread: threading.Thread | None = None
        self._ended: Waiter

    # -- the run ----------------------------------------------------------------

    def __enter__(self) -> ScriptRun:
        loaded = load_graph(self.graph) if self.graph is not None else None
        stack = self._stack
        try:
            stack.enter_context(_captured(self.log))
            self._session = stack.enter_context(Session(clock=self.clock, name="grading", graph=loaded))
            stack.enter_context(use_session(self._session))
            stack.enter_context(overlaid())
            stack.enter_context(self._session.timekeeping())
            stack.callback(_clean_default_context)
            self._probe = self._session.call(self._session.runtime.spawn, _Probe)
            self._start()
        except BaseException:
            stack.close()
            raise
        return self

    def _start(self) -> None:
        saved_argv, saved_path = sys.argv, sys.path[:]
        script = self.target if isinstance(self.target, Path) else None
        sys.argv = [str(script or "student"), *self.argv]
        if script is not None:
            sys.path.insert(0, str(script.resolve().parent))

        def restore() -> None:
            sys.argv = saved_argv
            sys.path[:] = saved_path

        self._stack.callback(restore)

        ended = self._ended = self._session.waiter()

        def main() -> None:
            try:
                self._main()
            finally:
                with self._session.lock:
                    self._done = True
                    ended.wake()

        self._thread = self._session.start_thread(main, "student script")
        self._session.settle()  # the script runs until it first waits (spins, mostly): its nodes exist then

    def _main(self) -> None:
        try:
            if isinstance(self.target, Path):
                runpy.run_path(str(self.target), run_name="__main__")
            else:
                _spin_one(self.target)
        except SystemExit as exc:
            self.exit_code = exc.code if isinstance(exc.code, int) else int(exc.code is not None)
            return
        except (KeyboardInterrupt, ExternalShutdownException) as exc:
            if not self._stopping:
                self.error = exc
        except BaseException as exc:
            self.error = exc
            self.exit_code = 1
            return
        self.exit_code = 0

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        try:
            self.stop()
        finally:
            self._stack.close()
        if exc is None and self.error is not None:
            raise self.error

    def stop(self) -> None:
        """Stop the script as Ctrl-C would and wait for it to end.

        Raises RuntimeError if it is still running after a minute of simulated time.
        """
        if self._thread is None or self._done:
            return
        self._stopping = True
        get_default_context().interrupt()
        self._session.wait_until(lambda: self._done, _STOP_WITHIN, self._ended)
        self._thread.join(timeout=5.0)
        if self._thread.is_alive():
            raise RuntimeError(f"{self.target} did not stop within {_STOP_WITHIN} simulated seconds of shutdown")

    @property
    def running(self) -> bool:
        """Whether the script is still running."""
        return self._thread is not None and not self._done

    # -- what the test does -------------------------------------------------------

    @property
    def now(self) -> float:
        """Simulated seconds since the run started."""
        return self._session.loop.time()

    def wait(self, seconds: float) -> None:
        """Let ``seconds`` of simulated time pass; the script runs meanwhile.

        What falls due at the very end (a timer of the script at exactly that
        time) has run when it returns.
        """
        self._session.sleep(seconds)
        self._session.settle()  # and what the loop and the script have due at this instant

    def record(self, topic: str, msg_type: type[Any] | None = None) -> list[Any]:
        """A list that receives every message on ``topic`` from now on, in order.

        ``msg_type`` is needed only for a topic nobody uses yet.  Raises
        LookupError for such a topic without it.
        """
        received: list[Any] = []
        msg_type = msg_type or self._topic_type(topic)
        self._session.call(self._probe.create_subscription, msg_type, topic, received.append, _RECORDING)
        return received

    def publish(self, topic: str, msg: Any) -> None:
        """Publish ``msg`` on ``topic`` (as ``ros2 topic pub --once``); subscribers have it on return."""
        publisher = self._publishers.get(topic)
        if publisher is None:
            publisher = self._publishers[topic] = self._session.call(self._probe.create_publisher, type(msg), topic, 10)
        self._session.call(publisher.publish, msg)

    def call(self, service: str, request: Any, timeout: float = 10.0) -> Any:
        """Call ``service`` with ``request`` and return the response (``timeout`` simulated seconds at most).

        A script's service answers only while the script spins, as in ROS.
        Raises TimeoutError, and ServiceError when the server fails.
        """
        client = self._clients.get(service)
        if client is None:
            srv_type = get_type(type(request).__ros_type__.removesuffix("_Request"))
            client = self._clients[service] = self._session.call(self._probe.create_client, srv_type, service)
        return self._session.block(client.call, request, timeout)

    def node(self, name: str) -> Any:
        """The node ``name`` of the run (the student's or the graph's), for a closer look."""
        return self._session.call(self._session.runtime.node, name)

    def _topic_type(self, topic: str) -> type[Any]:
        name = topic if topic.startswith("/") else "/" + topic
        for info in self._session.call(self._session.runtime.graph.topics):
            if info.name == name:
                return get_type(info.type)
        raise LookupError(f"nobody uses {name} yet: give its type, e.g. record({name!r}, Twist)")


def _spin_one(target: str | type) -> None:
    from actors.compat.rclpy import init, spin
    from actors.compat.rclpy.node import Node

    cls = _load_class(target) if isinstance(target, str) else target
    if not (isinstance(cls, type) and issubclass(cls, Node)):
        raise TypeError(f"{cls!r} is not an rclpy node class of the overlay: pass 'file.py:Class'")
    init(args=sys.argv)
    make = cast("Callable[[], Node]", cls)  # a user's subclass: its __init__ names the node itself
    spin(make())


def _load_class(target: str) -> Any:
    source, sep, name = target.rpartition(":")
    if not sep:
        raise ValueError(f"expected 'file.py:Class' or 'module:Class', got {target!r}")
    if source.endswith(".py"):
        namespace = runpy.run_path(source, run_name="student")
    else:
        namespace = vars(__import__(source, fromlist=["_"]))
    try:
        return namespace[name]
    except KeyError:
        raise LookupError(f"{source} has no {name!r}") from None


class _Capture(logging.Handler):
    def __init__(self, lines: list[str]) -> None:
        super().__init__()
        self.lines = lines
        self.setFormatter(RosFormatter())

    def emit(self, record: logging.LogRecord) -> None:
        self.lines.append(self.format(record))


class _captured:
    """Collects the run's log lines (every level the loggers let through) in ``lines``."""

    def __init__(self, lines: list[str]) -> None:
        self._handler = _Capture(lines)
        self._logger = logging.getLogger(ROOT_LOGGER)
        self._level = logging.NOTSET

    def __enter__(self) -> None:
        self._level = self._logger.level
        if not self._logger.isEnabledFor(INFO):
            self._logger.setLevel(INFO)  # as rclpy, INFO and above unless the script says otherwise
        self._logger.addHandler(self._handler)

    def __exit__(self, *exc: object) -> None:
        self._logger.removeHandler(self._handler)
        self._logger.setLevel(self._level)


def _clean_default_context() -> None:
    get_default_context().finish()
    try_shutdown()
