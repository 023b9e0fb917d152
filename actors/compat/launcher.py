"""``actors run SCRIPT.py [ARGS...]``: run an rclpy program, unmodified, on actors.

The script runs on the main thread as ``python SCRIPT.py ARGS...`` would run it
(``__main__``, ``sys.argv``, its exit code), with the overlay installed and a
:class:`~actors.compat.session.Session` current, beside the nodes of
``--graph`` if given.  Its log lines go to stderr in ROS's form, as rclpy's do.

Stopping is graceful, as for graphs: Ctrl-C, and the end of ``--duration``,
shut the context down and raise KeyboardInterrupt in the script (what rclpy's
signal handler does); SIGTERM shuts the context down too, and ends the script
wherever it is: an rclpy call it is in raises ExternalShutdownException, its
own code gets SystemExit(0).  Signals never land inside the runtime's code
(:meth:`~actors.compat.turns.Turn.signal`).  A script that lets that
KeyboardInterrupt or ExternalShutdownException out still exits 0, without a
traceback.  ``--timeout S`` ends any run after S seconds of wall time.  Exit
codes: the script's own (``sys.exit``), 1 when it raises anything else (its
traceback, without the launcher's frames) or when the graph fails, 2 for
misuse (no such script, bad options, malformed ``--ros-args`` or graph file),
with one line on stderr, 124 when ``--timeout`` ended the run.

On the virtual clock, ``time.sleep`` in the script's threads sleeps virtual
time: it waits on the runtime like any other wait
(:meth:`~actors.compat.session.Session.timekeeping`).  The virtual clock needs
a duration (nothing else would end the run), and a launcher option written
after the script, which goes to the script, is named in a warning.
"""

from __future__ import annotations

import _thread
import os
import signal
import sys
import threading
import traceback
import weakref
from collections.abc import Callable, Iterator, MutableSequence, Sequence
from contextlib import contextmanager
from types import FrameType
from typing import Any

from actors.compat.overlay import overlaid
from actors.compat.partners import LINGER, Partner, parse_partner
from actors.compat.programs import Program, program_for
from actors.compat.rclpy.context import use_session
from actors.compat.rclpy.executors import ExternalShutdownException
from actors.compat.rclpy.utilities import get_default_context, try_shutdown
from actors.compat.script_state import ScriptArgv
from actors.compat.session import Session
from actors.compat.turns import Turn
from actors.core._frames import users_traceback
from actors.core.signals import raise_stops, remember_stops, stop_signals
from actors.errors import ActorsError, GraphFileError, LaunchFileError, PackageError, RosArgsError
from actors.launch.graph_file import load_graph
from actors.launch.rosargs import parse
from actors.messages.discovery import add_workspace
from actors.ops.control import ControlEndpoint
from actors.recording.options import attachments
from actors.ros.log import INFO, LEVELS, configure_console

__all__ = ["run_script"]


def run_script(
    script: str | Program,
    argv: Sequence[str] = (),
    *,
    clock: str | None = None,
    duration: float | None = None,
    graph: str | None = None,
    log_level: str | None = None,
    partners: Sequence[str] = (),
    timeout: float | None = None,
    record: str | None = None,
    topics: Sequence[str] = (),
    foxglove: int | None = None,
    transport: bool = False,
) -> int:
    """Run ``script`` (a file, or a :class:`~actors.compat.programs.Program`) with ``argv`` as its
    arguments; return the process's exit code.

    ``clock``, ``duration`` and ``log_level`` default to the graph file's
    ``[runtime]`` settings when ``graph`` is given, else to the wall clock, no
    end, and info.  ``partners`` are more programs (``"server.py ARGS..."``,
    ``"PKG EXE ARGS..."``) run beside it in the same runtime
    (:mod:`actors.compat.partners`); one that fails makes the exit code 1.
    ``timeout`` bounds the run in seconds of wall time (exit code 124).
    ``record``, ``topics`` and ``foxglove`` attach a recorder and a live view,
    as ``python -m actors.run`` does; ``transport`` reaches other processes over
    Zenoh (the default settings; the wall clock only).  Call it on the main
    thread (it handles SIGINT and SIGTERM).
    """
    try:
        program = script if isinstance(script, Program) else program_for([script])[0]
        scripts = [parse_partner(spec) for spec in partners]
    except ValueError as exc:
        print(f"error: --with: {exc}", file=sys.stderr)
        return 2
    except (FileNotFoundError, PackageError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    for each in reversed((program, *(partner for partner, _ in scripts))):
        for folder in each.paths[:1]:
            add_workspace(folder)  # the program's own workspace: its interface packages import as rclpy's
    for name, value in (("--duration", duration), ("--timeout", timeout)):
        if value is not None and not 0 < value < float("inf"):
            print(f"error: {name} must be > 0 seconds, got {value}", file=sys.stderr)
            return 2
    _warn_options_after(argv)
    try:
        for arguments in (argv, *(arguments for _, arguments in scripts)):
            parse(arguments)
        loaded = load_graph(graph) if graph else None
    except (RosArgsError, GraphFileError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    settings = loaded[0].runtime if loaded else None
    clock = clock or (settings.clock if settings else "wall")
    if duration is None and settings is not None:
        duration = settings.duration or None
    if clock == "virtual" and not duration:
        print(
            "error: the virtual clock needs a duration, e.g. --duration 10 "
            "(virtual time runs as fast as it can, so nothing else would stop it)",
            file=sys.stderr,
        )
        return 2
    if transport and clock == "virtual":
        print(
            "error: --transport zenoh runs on the wall clock: other processes cannot follow virtual time",
            file=sys.stderr,
        )
        return 2
    try:
        attach = attachments(record=record, topics=topics, foxglove=foxglove)
        if transport:
            from actors.launch.graph_file import TransportSection
            from actors.transport.zenoh import ZenohTransport

            attach.append(ZenohTransport(TransportSection()))
    except (ActorsError, ImportError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    level = log_level or (settings.log_level if settings else None)
    configure_console(LEVELS[level] if level else INFO, stream=sys.stderr)
    stop = _Stop()
    session = Session(
        clock=clock,
        name=program.name,
        graph=loaded,
        duration=duration,
        on_duration=stop.end_of_duration,
        on_failure=lambda _error: stop.interrupt(),
        attach=[ControlEndpoint(), *attach],
    )
    stop.turn = session.turn
    remember_stops()  # a stop signal while the runtime starts is raised once it can be stopped
    try:
        session.start()
    except BaseException as exc:
        print(f"[FATAL] {graph}: {_one_line(exc)}", file=sys.stderr)
        return 1
    others = [Partner(session, partner, arguments, _print_script_traceback) for partner, arguments in scripts]
    # With partners, sys.argv shows each script its own command line.
    main_line = [program.argv0, *argv]
    command_line: MutableSequence[str] = main_line
    saved_argv = sys.argv
    if others:
        command_line = ScriptArgv(main_line)
        _set_argv(command_line)
    finished = threading.Event()
    if timeout is not None:
        _thread.start_new_thread(_bound, (timeout, stop, finished))
    try:
        raise_stops()
        with use_session(session), overlaid(), stop.handling_signals(), session.timekeeping():
            for partner in others:
                partner.start()
            try:
                code = _run(program, command_line, stop)
            finally:
                _finish(others, linger=0 if stop.requested else LINGER)
    finally:
        sys.argv = saved_argv
        get_default_context().finish()
        try_shutdown()
        session.close()
        sys.stdout.flush()
        finished.set()
    if stop.timed_out:
        return _TIMED_OUT
    if session.failure is not None:
        print(f"[FATAL] {_one_line(session.failure)}", file=sys.stderr)
        return 1
    return 1 if code == 0 and any(partner.failed for partner in others) else code


_TIMED_OUT = 124  # as timeout(1)
_HARD_STOP = 1.0  # wall seconds a timed-out script has to end once interrupted

# actors run's own options: written after the script, they are the script's arguments.
_OPTIONS = (
    "--clock",
    "--duration",
    "--graph",
    "--log-level",
    "--with",
    "--timeout",
    "--record",
    "--topics",
    "--foxglove",
)


def _warn_options_after(argv: Sequence[str]) -> None:
    for word in argv:
        if word == "--ros-args":
            return
        option = word.split("=", 1)[0]
        if option in _OPTIONS:
            print(
                f"warning: {option} comes after the script, so it went to the script; "
                "put actors run's options before the script",
                file=sys.stderr,
            )
            return


def _bound(seconds: float, stop: _Stop, finished: threading.Event) -> None:
    # A bare thread: no script thread, so it waits in wall time.  It interrupts the script as Ctrl-C
    # would, and ends the process if even that does not end it (a script that swallows it).
    if finished.wait(seconds):
        return
    print(f"[WARN] --timeout: {seconds:g} s of wall time are up: stopping the run", file=sys.stderr, flush=True)
    stop.timed_out = True
    stop.interrupt()
    if not finished.wait(_HARD_STOP):
        os._exit(_TIMED_OUT)


def _finish(partners: Sequence[Partner], linger: float) -> None:
    try:
        for partner in partners:
            partner.finish(linger)
    except KeyboardInterrupt:  # Ctrl-C while they finish: stop them now
        for partner in partners:
            partner.finish(0.0, wait=False)


class _Stop:
    """Whether the launcher asked the script to stop, and the signal handlers that ask it."""

    def __init__(self) -> None:
        self.requested = False
        self.timed_out = False
        self.turn: Turn | None = None
        self._main = threading.main_thread()
        self._handling = False

    def interrupt(self) -> None:
        """From any thread: stop the script as Ctrl-C would."""
        self.requested = True
        ident = self._main.ident
        assert ident is not None  # the main thread has started
        signal.pthread_kill(ident, signal.SIGINT)

    def end_of_duration(self) -> None:
        """On the loop thread, at the end of ``--duration``: stop the script as Ctrl-C would.  On
        the virtual clock, in order: nothing else runs before the script has its KeyboardInterrupt."""
        turn = self.turn
        if turn is not None and turn.virtual and turn.mine():
            self.requested = True
            _interrupt_default_context()
            if turn.interrupt_main(KeyboardInterrupt()):
                return
        self.interrupt()

    def _on_sigint(self, signum: int, frame: FrameType | None) -> None:
        # As rclpy's handler: the context stops (spins raise ExternalShutdownException), then the
        # previous handler's KeyboardInterrupt.
        if self._after_finaliser(frame, self._on_sigint, signum):
            return
        self._shut_down()
        self._raise(KeyboardInterrupt())

    def _raise(self, error: BaseException, outside: BaseException | None = None) -> None:
        # In the script's code at once; in the runtime's, where that code is done (see Turn.signal).
        if self.turn is None:
            raise outside or error
        self.turn.signal(error, outside)

    def _after_finaliser(self, frame: FrameType | None, handler: _Handler, signum: int) -> bool:
        """If the signal landed in a finaliser, handle it again at the first line or call outside
        it, and say so.

        Python prints and drops what a finaliser raises ("Exception ignored in ..."): the script
        would never see its exception.  The context stops only then too: a spin that found it
        stopped first would return as if shut down normally.  The main thread is traced until
        then, as a debugger's breakpoint is, and the first trace event outside every finaliser
        is the finaliser's end.
        """
        if not _in_finaliser(frame):
            return False
        self.requested = True
        previous = sys.gettrace()
        traced: list[FrameType] = []

        def resume(where: FrameType, event: str, arg: object) -> None:
            if _in_finaliser(where):
                return None  # a call the finaliser makes
            sys.settrace(previous)
            for beneath in traced:
                beneath.f_trace = None
            if self._handling:  # past the script, Python's own handler would raise in the launcher
                handler(signum, where)
            return None

        while frame is not None:  # the frames the finaliser returns to report their next line
            if not _in_finaliser(frame):
                frame.f_trace = resume
                traced.append(frame)
            frame = frame.f_back
        sys.settrace(resume)  # and the calls they make
        return True

    def _on_sigterm(self, signum: int, frame: FrameType | None) -> None:
        # rclpy only shuts the context down (a spin then raises ExternalShutdownException); a script
        # that never spins again would go on, so the main thread gets that exception wherever it is.
        if self._after_finaliser(frame, self._on_sigterm, signum):
            return
        self._shut_down()
        # In an rclpy call, that call raises ExternalShutdownException (a spin would); in the
        # script's own code (a callback, input(), a loop that never spins), SystemExit: a
        # BaseException, so that no ``except Exception`` of the script or a library swallows it.
        self._raise(ExternalShutdownException(), SystemExit(0))

    def _shut_down(self) -> None:
        # On a thread of its own, as rclpy's deferred signal handler does it: the handler runs on the
        # main thread between two bytecodes, perhaps inside a lock that the context's wake-ups take.
        self.requested = True
        _thread.start_new_thread(_interrupt_default_context, ())

    @contextmanager
    def handling_signals(self) -> Iterator[None]:
        # A hang-up ends the script as SIGTERM does: nobody is left to read what it prints.
        handlers = {signal.SIGINT: self._on_sigint, signal.SIGTERM: self._on_sigterm, signal.SIGHUP: self._on_sigterm}
        previous = {sig: signal.signal(sig, handlers[sig]) for sig in stop_signals()}
        self._handling = True
        try:
            yield
        finally:
            self._handling = False
            for sig, handler in previous.items():
                signal.signal(sig, handler)


_Handler = Callable[[int, FrameType | None], None]


def _interrupt_default_context() -> None:
    get_default_context().interrupt()  # a bare thread sees the main script's (see script_state)


# Where the signal may land while a finaliser runs: a ``__del__`` (rclpy's futures have one) or a
# weakref.finalize callback (a task collected before it ran ends its work in one).
_FINALISERS = frozenset({weakref.finalize.__call__.__code__})


def _in_finaliser(frame: FrameType | None) -> bool:
    while frame is not None:
        if frame.f_code in _FINALISERS or frame.f_code.co_name == "__del__":
            return True
        frame = frame.f_back
    return False


def _run(program: Program, command_line: MutableSequence[str], stop: _Stop) -> int:
    saved_argv, saved_path = sys.argv, sys.path[:]
    _set_argv(command_line)
    sys.path[:0] = [str(folder) for folder in program.paths]
    try:
        program.run()
    except SystemExit as exc:
        return _exit_code(exc.code)
    except (KeyboardInterrupt, ExternalShutdownException):
        if stop.requested:
            return 0
        raise
    except (RosArgsError, PackageError, LaunchFileError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    except BaseException as exc:
        _print_script_traceback(exc, program)
        return 1
    finally:
        sys.argv = saved_argv
        sys.path[:] = saved_path
    return 0


def _exit_code(code: Any) -> int:
    if code is None:
        return 0
    if isinstance(code, int):
        return code
    print(code, file=sys.stderr)
    return 1


def _print_script_traceback(exc: BaseException, program: Program) -> None:
    # The program's frames (and its own modules'), not the launcher's, runpy's or the overlay's:
    # a mistake of the program's reads as a line of it, not as seventeen frames of actors.
    tb = users_traceback(exc.__traceback__)
    traceback.print_exception(type(exc), exc, tb or exc.__traceback__, file=sys.stderr)


def _one_line(exc: BaseException) -> str:
    if isinstance(exc, BaseExceptionGroup) and exc.exceptions:
        return _one_line(exc.exceptions[0])
    if isinstance(exc, ActorsError):
        return str(exc)
    return f"{type(exc).__name__}: {exc}"


def _set_argv(command_line: MutableSequence[str]) -> None:
    # A script's sys.argv: a list, or with partners a ScriptArgv, which is not one on purpose
    # (C code would read a list's own items), so not what sys.argv is typed as.
    sys.argv = command_line  # type: ignore[assignment]  # see above: not a list on purpose
