"""Running a launch file: its description visited on the main thread, its nodes in this runtime.

``actors launch PKG FILE`` runs a :class:`LaunchProgram` through the same
launcher as ``actors run`` (:func:`actors.compat.launcher.run_script`): one
session, either clock, ``--duration``, ``--record``, ``--foxglove``, Ctrl-C.
The program visits the launch description depth first, as ROS's launch does,
then serves what comes later (timers, process exits, events) until nothing is
left to wait for, a ``Shutdown`` event, the end of the run, or Ctrl-C.

What a ``Node`` action starts is its package's executable, in this runtime:
an rclpy ``main`` runs on a thread of its own with rclpy's process-wide state
of its own (a :class:`~actors.compat.partners.Partner`, as ``actors run --with``
runs one), an ``actors.Node`` class is spawned as a native node.  Its
``--ros-args`` (name, namespace, parameters as files, remappings) are the ones
``ros2 launch`` would give the process.  ``ExecuteProcess`` is a real
subprocess.  Lines about them are ROS launch's (``[INFO] [talker-1]: process
started with pid [...]``), on stderr.

Timers wait on the runtime's clock, so a ``TimerAction`` on the virtual clock
takes no wall time; a subprocess's exit is heard when it happens, in real time.
"""

from __future__ import annotations

import _thread
import concurrent.futures
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import traceback
from collections import Counter, deque
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from actors.compat.launch.entities import Event, EventHandler, LaunchContext, LaunchDescription, LaunchDescriptionEntity
from actors.compat.launch.events import (
    ExecutionComplete,
    ProcessExited,
    ProcessStarted,
    ProcessStderr,
    ProcessStdout,
    Shutdown,
)
from actors.compat.launch.loading import load_launch_file
from actors.compat.launch.translation import WAITING, graph_environment, holds_time, translated
from actors.compat.partners import Partner
from actors.compat.programs import Program, load_target, program_of, spawn_native
from actors.compat.rclpy.context import current_session
from actors.compat.script_state import ScriptArgv
from actors.compat.session import Session
from actors.errors import LaunchFileError, PackageError, RosArgsError
from actors.launch.packages import Executable, Package, find_executable, find_package
from actors.ros.node import Node as NativeNode

__all__ = ["LaunchProgram", "LaunchService", "find_launch_file", "parse_launch_arguments"]

IDLE = "idle"
SIGINT = "ctrl-c (SIGINT)"
END_OF_RUN = "the runtime ended"
_EXIT_GRACE = 5.0  # real seconds the exits of stopped processes are waited for, to be reported
_LAST_EVENTS = 1000  # events handled at most after the shutdown (a handler that emits forever)


def find_launch_file(words: Sequence[str]) -> tuple[Path, list[str]]:
    """``PATH [args]`` or ``PKG FILE [args]`` -> the launch file and the rest, as ``ros2 launch`` reads them.

    A package's file is looked for anywhere in its share directory.  Raises
    PackageError (no such package or file) or LaunchFileError.
    """
    first, rest = words[0], list(words[1:])
    if Path(first).is_file():
        return Path(first), rest
    if not rest or ":=" in rest[0]:
        if "." in Path(first).name or "/" in first:
            raise LaunchFileError(f"no such launch file: {first}")
        raise PackageError(f"actors launch {first}: name one of package {first!r}'s launch files after it")
    package = find_package(first)
    share = package.share
    found = sorted(p for p in share.rglob(rest[0]) if p.is_file())
    if not found:
        listed = sorted({p.name for p in share.rglob("*launch*") if p.is_file()})
        hint = f"; its launch files are {', '.join(listed)}" if listed else ""
        raise PackageError(f"no launch file {rest[0]!r} in package {first!r} ({share}){hint}")
    return found[0], rest[1:]


def parse_launch_arguments(words: Sequence[str]) -> list[tuple[str, str]]:
    """``name:=value`` words; LaunchFileError for one that is not."""
    pairs = []
    for word in words:
        name, sep, value = word.partition(":=")
        if not sep or not name:
            raise LaunchFileError(f"launch arguments are name:=value, got {word!r}")
        pairs.append((name, value))
    return pairs


class LaunchProgram(Program):
    """A launch file, as the program ``actors launch`` runs."""

    def __init__(self, path: Path, arguments: Sequence[tuple[str, str]]) -> None:
        self.path = path
        self.arguments = list(arguments)
        self.name = path.name.split(".")[0]
        self.argv0 = str(path)
        self.paths = ()

    def run(self, *, main: bool = True) -> None:
        session = current_session()
        assert session is not None, "a launch file runs in a session (actors launch)"
        saved = sys.argv
        sys.argv = ScriptArgv(list(sys.argv))  # type: ignore[assignment]  # each node's program sees its own
        try:
            LaunchService(session, self.path, self.arguments).run()
        finally:
            sys.argv = saved

    def owns(self, filename: str) -> bool:
        return Path(filename).resolve() == self.path.resolve()


@dataclass
class _Running:
    """One started node or process."""

    action: Any
    name: str
    pid: int
    cmd: str
    partner: Partner | None = None
    process: subprocess.Popen[bytes] | None = None
    native: NativeNode | None = None
    respawn: Callable[[], None] | None = None
    extra: dict[str, Any] = field(default_factory=dict)


class LaunchService:
    """Visits a launch description and serves its later work, on the calling (main) thread."""

    def __init__(self, session: Session, path: Path, arguments: Sequence[tuple[str, str]] = ()) -> None:
        self.session = session
        self.path = path
        self.arguments = list(arguments)
        self.handlers: list[EventHandler] = []
        self.context = LaunchContext(service=self)
        self._queue: deque[Callable[[], None]] = deque()
        self._lock = threading.Lock()
        self._waiter = session.waiter()
        self._timers = 0
        self._running: list[_Running] = []
        self._counts: Counter[str] = Counter()
        self._shutdown: str | None = None
        self._folder = tempfile.mkdtemp(prefix="actors-launch-")
        self._executables: dict[tuple[str, str], tuple[Executable, Package]] = {}
        self._waits: list[concurrent.futures.Future[None]] = []

    # -- the main loop -------------------------------------------------------------------

    def run(self) -> None:
        """Visit the description, then serve until nothing is left to wait for or a shutdown."""
        self.context.launch_configurations.update(self.arguments)
        try:
            description = load_launch_file(str(self.path))
            self.visit([description], self.context)
            while self._shutdown is None and self.session.running:
                self.session.wait_until(self._ready, None, self._waiter)
                if not self._queue and not self._timers and not self._alive():
                    break
                while self._queue and self._shutdown is None:
                    with self._lock:
                        work = self._queue.popleft()
                    work()
            # ROS's launch's reason when nothing is left to do; or the runtime stopped (it failed).
            self._handle(Shutdown(reason=IDLE if self.session.running else END_OF_RUN))
        except KeyboardInterrupt:
            self._handle(Shutdown(reason=SIGINT, due_to_sigint=True))
            raise
        finally:
            self._stop_all()

    def _ready(self) -> bool:
        return bool(self._queue) or self._shutdown is not None or (not self._timers and not self._alive())

    def _alive(self) -> bool:
        return any(r.native is not None or r.partner is not None or r.process is not None for r in self._running)

    def post(self, work: Callable[[], None]) -> None:
        """From any thread: run ``work`` on the main thread, in order."""
        with self._lock:
            self._queue.append(work)
        self._waiter.wake()

    def visit(self, entities: Sequence[LaunchDescriptionEntity], context: LaunchContext) -> None:
        """Visit ``entities`` depth first."""
        stack = list(reversed(entities))
        while stack:
            entity = stack.pop()
            try:
                result = entity.visit(context)
            except (LaunchFileError, PackageError, RosArgsError):
                raise
            except Exception as exc:
                where = getattr(entity, "where", None) or str(self.path)
                raise LaunchFileError(f"{where}: {entity.describe()}: {type(exc).__name__}: {exc}") from exc
            if result:
                stack.extend(reversed(list(result)))

    # -- what actions ask for --------------------------------------------------------------

    def executable(self, package: str, executable: str) -> tuple[Executable, Package]:
        """A package's executable and the package, looked up once per launch (PackageError if there is none)."""
        key = (package, executable)
        if key not in self._executables:
            self._executables[key] = (find_executable(package, executable), find_package(package))
        return self._executables[key]

    def load(self, path: str, where: str | None = None) -> LaunchDescription:
        """The description in the launch file ``path``."""
        return load_launch_file(path, where)

    def log(self, logger: str, text: str, level: str = "INFO") -> None:
        """A line of launch's own, as ROS's launch prints it."""
        print(f"[{level}] [{logger}]: {text}", file=sys.stderr, flush=True)

    def after(
        self,
        seconds: float,
        entities: Sequence[LaunchDescriptionEntity],
        context: LaunchContext,
        action: Any = None,
    ) -> None:
        """Visit ``entities`` ``seconds`` of runtime clock from now, with the launch configurations of now;
        then ``action`` (the timer) is complete."""
        snapshot = dict(context.launch_configurations)
        self._timers += 1

        def due() -> None:
            self._timers -= 1
            if self._shutdown is not None:
                return
            context.push_configurations()
            context.launch_configurations = dict(snapshot)
            try:
                self.visit(entities, context)
            finally:
                context.pop_configurations()
            if action is not None:
                self.completed(action)

        self.session.wake_after(seconds, lambda: self.post(due))

    def emit(self, event: Event) -> None:
        """Handle ``event`` once the current visit is done."""
        self.post(lambda: self._handle(event))

    def completed(self, action: Any) -> None:
        """``action`` is done: its ExecutionComplete, for the handlers that wait for it."""
        event = ExecutionComplete(action=action)
        if any(handler.matches(event) for handler in self.handlers):
            self.emit(event)

    def _handle(self, event: Event) -> None:
        if isinstance(event, Shutdown):
            if self._shutdown is not None:  # the launch shuts down once: later asks change nothing
                return
            self._shutdown = event.reason
            if event.due_to_sigint:  # Ctrl-C, or the end of --duration (which stops a run as Ctrl-C does)
                self.log("launch", f"user interrupted with {SIGINT}", level="WARNING")
            elif event.reason not in (IDLE, END_OF_RUN):
                self.log("launch", f"shutting down: {event.reason}" if event.reason else "shutting down")
        for handler in list(self.handlers):
            if handler.matches(event):
                # The handler's entities see the event as the local ``event`` (LocalSubstitution).
                saved = self.context.locals
                self.context.locals = {**saved, "event": event}
                try:
                    entities = handler.handle(event, self.context)
                    if entities:
                        self.visit(entities, self.context)
                finally:
                    self.context.locals = saved

    def params_file(self, values: dict[str, Any]) -> str:
        """A ROS parameter file holding ``values`` for every node (what launch_ros writes for a dict)."""
        handle, path = tempfile.mkstemp(suffix=".yaml", dir=self._folder)
        with os.fdopen(handle, "w", encoding="utf-8") as file:
            yaml.safe_dump({"/**": {"ros__parameters": values}}, file)
        return path

    def start_node(
        self,
        action: Any,
        executable: Executable,
        package: Package,
        argv: list[str],
        label: str,
        respawn: bool,
        respawn_delay: float,
    ) -> None:
        """Start a package's executable as a node of this launch (nothing starts once it shuts down)."""
        if self._shutdown is not None:
            return
        program = program_of(executable, package.source, package.installed_prefix)
        self._counts[label] += 1
        name = f"{label}-{self._counts[label]}"
        for path in reversed(program.paths):
            if str(path) not in sys.path:
                sys.path.insert(0, str(path))
        running = _Running(action, name, os.getpid(), " ".join([executable.name, *argv]))
        if respawn:
            running.respawn = lambda: self.start_node(action, executable, package, argv, label, respawn, respawn_delay)
            running.extra["delay"] = respawn_delay
        target = load_target(executable) if executable.target is not None else None
        if isinstance(target, type) and issubclass(target, NativeNode):
            running.native = spawn_native(self.session, target, executable.name, argv)
            self._running.append(running)
        else:
            partner = Partner(
                self.session, program, argv, self._report, on_exit=lambda code: self._exited(running, code)
            )
            running.partner = partner
            self._running.append(running)
            partner.start()
        self.log(name, f"process started with pid [{running.pid}]")
        self.emit(ProcessStarted(action=action, name=name, pid=running.pid))

    def start_process(
        self,
        action: Any,
        label: str,
        words: list[str],
        environment: dict[str, str],
        cwd: str | None,
        shell: bool,
        output: str,
    ) -> None:
        """Start a real subprocess; its output lines are events, and shown as ``output`` says (as ROS's launch).

        Nothing starts once the launch shuts down."""
        if self._shutdown is not None:
            return
        self._counts[label] += 1
        name = f"{label}-{self._counts[label]}"
        command = " ".join(words) if shell else words
        ours = translated(words, shell, environment)
        if ours is not None:
            command, environment, shell = ours, {**environment, **graph_environment(self.session.runtime)}, False
        try:
            process = subprocess.Popen(
                command, cwd=cwd, env=environment, shell=shell, stdout=subprocess.PIPE, stderr=subprocess.PIPE
            )
        except OSError as exc:
            raise LaunchFileError(f"{action.where}: ExecuteProcess {words}: {exc.strerror or exc}") from None
        running = _Running(action, name, process.pid, " ".join(words), process=process)
        self._running.append(running)
        self.log(name, f"process started with pid [{process.pid}]")
        self.emit(ProcessStarted(action=action, name=name, pid=process.pid))
        shown = {1: output in ("screen", "both", "full"), 2: output != "own_log"}
        released = threading.Event()  # the command no longer holds virtual time (see below)
        readers = [
            _on_own_thread(self._read, running, pipe, fd, shown[fd], released)
            for pipe, fd in ((process.stdout, 1), (process.stderr, 2))
        ]

        def wait() -> None:
            code = process.wait()
            concurrent.futures.wait(readers)  # every line is heard before the exit
            self._exited(running, code)
            released.set()

        self._waits.append(_on_own_thread(wait))
        if ours is not None and holds_time(ours) and self.session.running:
            # One of actors' commands against this graph: an executor job of the runtime's, so virtual
            # time stands still while it runs (the graph still answers it), as if it took no time:
            # until it ends, or says it waits for a subscription that only time may bring.
            self.session.call(self.session.loop.run_in_executor, None, released.wait)

    def _read(self, running: _Running, pipe: Any, fd: int, shown: bool, released: threading.Event) -> None:
        # On a reader thread: each line is an event (OnProcessIO), and shown when the output says so.
        kind = ProcessStdout if fd == 1 else ProcessStderr
        stream = sys.stdout if fd == 1 else sys.stderr
        for line in iter(pipe.readline, b""):
            if fd == 1 and line.startswith(WAITING):
                released.set()
            if shown:
                text = line.decode(errors="replace").rstrip("\n")
                print(f"[{running.name}] {text}", file=stream, flush=True)
            self.emit(kind(action=running.action, name=running.name, pid=running.pid, text=line, fd=fd))
        pipe.close()

    def _exited(self, running: _Running, code: int) -> None:
        # From the node's or the process's own thread: the rest happens on the main thread.
        def exited() -> None:
            running.partner = None
            running.process = None
            if code == 0:
                self.log(running.name, f"process has finished cleanly [pid {running.pid}]")
            else:
                self.log(
                    running.name,
                    f"process has died [pid {running.pid}, exit code {code}, cmd '{running.cmd}']",
                    level="ERROR",
                )
            self.emit(ProcessExited(action=running.action, name=running.name, pid=running.pid, returncode=code))
            self.completed(running.action)
            if running.respawn is not None and self._shutdown is None:
                respawn = running.respawn
                self._timers += 1

                def again() -> None:
                    self._timers -= 1
                    if self._shutdown is None:
                        respawn()

                self.session.wake_after(running.extra["delay"], lambda: self.post(again))

        self.post(exited)

    def _report(self, exc: BaseException, program: Program) -> None:
        tb = exc.__traceback__
        while tb is not None and not program.owns(tb.tb_frame.f_code.co_filename):
            tb = tb.tb_next
        traceback.print_exception(type(exc), exc, tb or exc.__traceback__, file=sys.stderr)

    def _stop_all(self) -> None:
        self._shutdown = self._shutdown or "the launch ended"
        partners = [r.partner for r in self._running if r.partner is not None]
        processes = [r.process for r in self._running if r.process is not None]
        for process in processes:
            if process.poll() is None:
                process.send_signal(signal.SIGINT)
        try:
            for partner in partners:
                partner.finish(0.0)
        except KeyboardInterrupt:  # Ctrl-C again while they finish: stop them now
            for partner in partners:
                partner.finish(0.0, wait=False)
        for process in processes:
            try:
                process.wait(timeout=5)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()
        for running in self._running:
            if running.native is not None:  # stopped with the runtime, as a node ends on Ctrl-C
                running.native = None
                self._exited(running, 0)
        # What they did on the way out is heard: exit lines, and the handlers of their exits (as on
        # ROS, OnProcessExit runs during a shutdown; nothing new starts).
        concurrent.futures.wait(self._waits, timeout=_EXIT_GRACE)
        for _ in range(_LAST_EVENTS):
            with self._lock:
                if not self._queue:
                    break
                work = self._queue.popleft()
            work()
        shutil.rmtree(self._folder, ignore_errors=True)


def _on_own_thread(fn: Callable[..., Any], *args: Any) -> concurrent.futures.Future[Any]:
    """``fn(*args)`` on a thread of its own, its result a future.

    One per pipe and per process: a pool would queue a new process's readers behind long-lived
    ones (two running processes filled the default pool).  Started below ``threading``, so no
    script thread's turn enlists it: it holds no virtual time while it waits for lines or an exit.
    """
    future: concurrent.futures.Future[Any] = concurrent.futures.Future()

    def run() -> None:
        try:
            future.set_result(fn(*args))
        except BaseException as exc:
            future.set_exception(exc)

    _thread.start_new_thread(run, ())
    return future
