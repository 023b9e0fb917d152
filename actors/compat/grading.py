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
stops the script as Ctrl-C would (its spin raises ExternalShutdownException).

What the student's code does wrong is what the test shows first, with the
student's own frames: what it raised (an import, a constructor, a callback)
is raised by the next thing the test does (entering the block, ``wait``,
``record``...); a script that ended by itself before a test that then failed
gives :class:`~actors.errors.ScriptEnded`; and a test that fails while the
script still runs says where the script was.
"""

from __future__ import annotations

import logging
import runpy
import sys
import threading
import traceback
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
from actors.core._frames import users_traceback
from actors.errors import ScriptEnded
from actors.launch.graph_file import load_graph
from actors.ros.log import INFO, ROOT_LOGGER, RosFormatter
from actors.ros.node import Node as NativeNode
from actors.ros.qos import HistoryPolicy, QoSProfile, ReliabilityPolicy
from actors.system.supervisor import Child, RestartType

__all__ = ["ScriptRun", "run_script", "run_node"]

# Records everything, from reliable and best-effort publishers alike.
_RECORDING = QoSProfile(history=HistoryPolicy.KEEP_ALL, reliability=ReliabilityPolicy.BEST_EFFORT)
_STOP_WITHIN = 60.0  # simulated seconds a script gets to end after it is stopped


def run_script(script: str | Path, *args: str, graph: str | Path | None = None, clock: str = "virtual") -> ScriptRun:
    """A :class:`ScriptRun` of ``script`` with ``args`` as its arguments (start it with ``with``)."""
    return ScriptRun(Path(script), [str(a) for a in args], graph, clock)


def run_node(node: str | type, *args: str, graph: str | Path | None = None, clock: str = "virtual") -> ScriptRun:
    """A :class:`ScriptRun` that runs one node of ``node``'s class.

    ``node`` is ``"path/to/file.py:Class"``, ``"module:Class"`` (imported inside
    the overlay) or the class itself.  An rclpy node class is spun as
    ``rclpy.spin(Cls())`` would; a native one (:class:`actors.Node`) is spawned
    in the graph, and a crash ends it instead of restarting it.  Entering the
    block raises TypeError for any other class.
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
        self._ended_at: float | None = None
        self._exit: SystemExit | None = None
        self._reported = False
        self._thread: threading.Thread | None = None
        self._ended: Waiter
        self._loaded: type | None = None  # run_node's class, once the script thread has imported it
        self._native: Child | None = None  # run_node's native node

    # -- the run ----------------------------------------------------------------

    def __enter__(self) -> ScriptRun:
        __tracebackhide__ = True  # pytest shows the test's line, then the student's frames
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
            self._check()  # an import or a constructor that failed fails the test here
            if self._loaded is not None:
                self._spawn_native(self._loaded)
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
                    self._ended_at = self._session.loop.time()
                    ended.wake()

        self._thread = self._session.start_thread(main, "student script")
        self._session.settle()  # the script runs until it first waits (spins, mostly): its nodes exist then

    def _main(self) -> None:
        try:
            if isinstance(self.target, Path):
                runpy.run_path(str(self.target), run_name="__main__")
            else:
                self._run_class(self.target)
        except SystemExit as exc:
            self.exit_code = exc.code if isinstance(exc.code, int) else int(exc.code is not None)
            self._exit = exc
            return
        except (KeyboardInterrupt, ExternalShutdownException) as exc:
            if not self._stopping:
                self.error = exc
        except BaseException as exc:
            self.error = exc
            self.exit_code = 1
            return
        self.exit_code = 0

    def _run_class(self, target: str | type) -> None:
        from actors.compat.rclpy import init, spin
        from actors.compat.rclpy.node import Node

        cls = _load_class(target) if isinstance(target, str) else target
        if isinstance(cls, type) and issubclass(cls, Node):
            init(args=sys.argv)
            make = cast("Callable[[], Node]", cls)  # a user's subclass: its __init__ names the node itself
            spin(make())
        else:
            self._loaded = cls  # the test's thread spawns a native node, or refuses anything else

    def _spawn_native(self, cls: Any) -> None:
        __tracebackhide__ = True
        if not (isinstance(cls, type) and issubclass(cls, NativeNode)):
            raise TypeError(f"run_node() takes an rclpy or an actors node class, got {cls!r}")
        runtime = self._session.runtime

        def spawn() -> Child:
            runtime.spawn(cls, restart=RestartType.TEMPORARY)  # a crash is the student's error: no restart
            return next(reversed(runtime.supervisor.children))

        try:
            self._native = self._session.call(spawn)
        except BaseException as exc:
            self.error, self.exit_code = exc, 1
            self._check()
            raise
        self.exit_code = None

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        __tracebackhide__ = True
        where = self._where() if exc is not None and self.running else None
        try:
            self.stop()
        finally:
            self._stack.close()
        if exc is None:
            self._check()
        elif not self._reported:
            self._explain(exc, where)

    def stop(self) -> None:
        """Stop the script as Ctrl-C would and wait for it to end.

        Raises RuntimeError if it is still running after a minute of simulated time.
        """
        if self._native is not None and self.exit_code is None:
            self.exit_code = 0 if self._native.state == "running" else 1
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
        """Whether the script (or run_node's node) is still running."""
        if self._native is not None:
            return self._native.state == "running"
        return self._thread is not None and not self._done

    # -- the student's failures, first ----------------------------------------------

    def _failure(self) -> BaseException | None:
        """What the student's code raised, if anything: the script, or the native node's crash."""
        if self.error is not None:
            return self.error
        if self._native is not None and self._native.state == "crashed":
            return self._native.last_exception
        return None

    def _check(self) -> None:
        """Raise what the student's code raised, once, with the student's own frames."""
        __tracebackhide__ = True
        error = self._failure()
        if error is None or self._reported:
            return
        self._reported = True
        raise _theirs(error)

    def _explain(self, exc: BaseException, where: str | None) -> None:
        """The test failed: say first what the student's code did, if it went wrong."""
        __tracebackhide__ = True
        error = self._failure()
        self._reported = True
        then = f"then the test failed: {type(exc).__name__}: {exc}".rstrip()
        if error is not None:
            error = _theirs(error)
            error.add_note(then)
            raise error from None
        if self._native is None and self._done and self._ended_at is not None and not self._stopping:
            code = 0 if self.exit_code is None else self.exit_code
            ended = ScriptEnded(
                f"{self._name()} ended by itself at {self._ended_at:.3f} s (exit code {code}), before the test was done"
            )
            ended.add_note(then)
            raise ended.with_traceback(_users_or_none(self._exit)) from None
        if where:
            exc.add_note(f"{self._name()} was running, at:\n{where}".rstrip())

    def _where(self) -> str | None:
        # Where the script's thread parked last, as it recorded it itself (see Turn.where): while
        # the test runs on the virtual clock, the script waits there.
        thread = self._thread
        frames = self._session.turn.where(thread.ident) if thread is not None and thread.ident else []
        return "".join(traceback.StackSummary.from_list([(*f, None) for f in reversed(frames)]).format()) or None

    def _name(self) -> str:
        target = self.target
        return target.name if isinstance(target, Path) else getattr(target, "__name__", str(target))

    # -- what the test does -------------------------------------------------------

    @property
    def now(self) -> float:
        """Simulated seconds since the run started."""
        return self._session.loop.time()

    def wait(self, seconds: float) -> None:
        """Let ``seconds`` of simulated time pass; the script runs meanwhile.

        What falls due at the very end (a timer of the script at exactly that
        time) has run when it returns.  Raises what the student's code raised
        meanwhile, if anything.
        """
        __tracebackhide__ = True
        self._session.sleep(seconds)
        self._session.settle()  # and what the loop and the script have due at this instant
        self._check()

    def record(self, topic: str, msg_type: type[Any] | None = None) -> list[Any]:
        """A list that receives every message on ``topic`` from now on, in order.

        ``msg_type`` is needed only for a topic nobody uses yet.  Raises
        LookupError for such a topic without it.
        """
        __tracebackhide__ = True
        self._check()
        received: list[Any] = []
        msg_type = msg_type or self._topic_type(topic)
        self._session.call(self._probe.create_subscription, msg_type, topic, received.append, _RECORDING)
        return received

    def publish(self, topic: str, msg: Any) -> None:
        """Publish ``msg`` on ``topic`` (as ``ros2 topic pub --once``); subscribers have it on return."""
        __tracebackhide__ = True
        self._check()
        publisher = self._publishers.get(topic)
        if publisher is None:
            publisher = self._publishers[topic] = self._session.call(self._probe.create_publisher, type(msg), topic, 10)
        self._session.call(publisher.publish, msg)

    def call(self, service: str, request: Any, timeout: float = 10.0) -> Any:
        """Call ``service`` with ``request`` and return the response (``timeout`` simulated seconds at most).

        A script's service answers only while the script spins, as in ROS.
        Raises TimeoutError, and ServiceError when the server fails.
        """
        __tracebackhide__ = True
        self._check()
        client = self._clients.get(service)
        if client is None:
            srv_type = get_type(type(request).__ros_type__.removesuffix("_Request"))
            client = self._clients[service] = self._session.call(self._probe.create_client, srv_type, service)
        return self._session.block(client.call, request, timeout)

    def node(self, name: str) -> Any:
        """The node ``name`` of the run (the student's or the graph's), for a closer look."""
        __tracebackhide__ = True
        self._check()
        return self._session.call(self._session.runtime.node, name)

    def _topic_type(self, topic: str) -> type[Any]:
        name = topic if topic.startswith("/") else "/" + topic
        for info in self._session.call(self._session.runtime.graph.topics):
            if info.name == name:
                return get_type(info.type)
        raise LookupError(f"nobody uses {name} yet: give its type, e.g. record({name!r}, Twist)")


def _theirs(error: BaseException) -> BaseException:
    """``error`` with only the student's frames (all of them when it has none of theirs)."""
    return error.with_traceback(users_traceback(error.__traceback__) or error.__traceback__)


def _users_or_none(error: BaseException | None) -> TracebackType | None:
    return None if error is None else users_traceback(error.__traceback__)


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
