"""``python -m actors.run GRAPH`` (or ``actors launch GRAPH``): run a graph file until it is stopped.

Exit codes: 0 after a graceful stop (end of duration, SIGINT, SIGTERM, SIGHUP,
at any moment of start-up too: :mod:`actors.core.signals`); 1 when
the graph fails: a node's constructor raises, the supervisor gives up, or any
other error ends the run; 2 for misuse (bad options, a malformed graph file),
with one line on stderr.  A failure is printed once, as one ``[FATAL]`` line
naming what failed and the error, followed by the frames of the traceback that
are the user's own (not the runtime's, anyio's or asyncio's).
"""

from __future__ import annotations

if __name__ == "__main__":
    # Before the imports below, which load the runtime: the slow part of start-up.
    from actors.core.signals import remember_stops

    remember_stops()

import argparse
import asyncio
import sys
import traceback
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import Any

import anyio
import anyio.abc
import msgspec

from actors.core._frames import is_users
from actors.core.loops import WALL_LOOPS, VirtualTimeLoop, uvloop_loop, wall_loop
from actors.core.signals import raise_stops, remember_stops, stop_signals, take_noted
from actors.core.tomlfile import MAX_SECONDS
from actors.errors import ActorsError, Escalation, GraphFileError
from actors.launch.graph_args import format_arguments
from actors.launch.graph_file import GraphFile, TransportSection, argument_rows, load_graph
from actors.launch.spawn import NodeStartError, one_line, spawn_graph
from actors.ops.control import ControlEndpoint
from actors.recording.options import add_attachment_options
from actors.ros.log import LEVELS, configure_console
from actors.ros.node import Node
from actors.runtime import Attachment, Runtime

__all__ = ["main", "add_arguments", "launch", "run_graph"]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """The graph file and the options that override its ``[runtime]`` table."""
    parser.add_argument("graph", help="the graph file, e.g. graph.toml")
    parser.add_argument("arguments", nargs="*", metavar="name:=value", help="the graph's arguments (its [args])")
    parser.add_argument("-s", "--show-args", action="store_true", help="list the graph's arguments and exit")
    parser.add_argument("--clock", choices=("wall", "virtual"), help="override [runtime] clock")
    parser.add_argument("--duration", type=_seconds, help="seconds to run; 0 runs until stopped")
    parser.add_argument("--log-level", choices=sorted(LEVELS), help="override [runtime] log_level")
    parser.add_argument(
        "--loop",
        choices=sorted(WALL_LOOPS),
        help="the wall clock's event loop: select (default, microsecond timers), asyncio, "
        "uvloop (faster, millisecond clock; pip install 'actors[fast]'; the default with a transport "
        "when installed)",
    )
    parser.add_argument(
        "--transport",
        choices=("zenoh", "none"),
        help="reach other processes over Zenoh (the [transport] section's settings, or the defaults), or not",
    )
    add_attachment_options(parser)


def _seconds(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number of seconds: {text!r}") from None
    if not 0 <= value <= MAX_SECONDS:  # also refuses nan and inf, on which a virtual clock stands still
        raise argparse.ArgumentTypeError(f"duration must be from 0 to {MAX_SECONDS:g} seconds, got {text}")
    return value


async def run_graph(
    graph: GraphFile,
    classes: Sequence[type[Node]],
    *,
    name: str,
    duration: float,
    handle_signals: bool = True,
    attach: Sequence[Attachment] = (),
) -> None:
    """Spawn the graph's nodes in file order and run until ``duration`` or a signal.

    ``attach`` runs beside the control endpoint (a recorder, a live view).

    Raises Escalation if the supervisor gives up; NodeStartError when a node's
    constructor raises (delayed or not); GraphFileError naming the node's entry
    when the graph asks for what cannot be (a parameter override of the wrong
    type, a duplicate name).
    """
    policy = graph.supervisor.policy()
    everything: list[Any] = [ControlEndpoint(), *attach]
    if graph.transport is not None:
        from actors.transport.zenoh import ZenohTransport

        everything.append(ZenohTransport(graph.transport))
    stop = anyio.Event()
    async with anyio.create_task_group() as listening:
        if handle_signals:
            # Listening before the runtime opens its attachments (a Zenoh session takes a while):
            # a signal then stops the run as soon as it is up, as Ctrl-C later would.
            await listening.start(_note_signal, stop)
        async with Runtime(name=name, supervisor=policy, attach=everything) as rt, anyio.create_task_group() as tg:
            tg.start_soon(_shutdown_on, stop, rt)
            if not stop.is_set():
                await tg.start(spawn_graph, rt, graph, classes)
                await rt.wait(duration or None)
            tg.cancel_scope.cancel()
        listening.cancel_scope.cancel()


async def _note_signal(
    stop: anyio.Event, *, task_status: anyio.abc.TaskStatus[None] = anyio.TASK_STATUS_IGNORED
) -> None:
    try:
        with anyio.open_signal_receiver(*stop_signals()) as signals:
            if take_noted():  # one that came while the loop started (see launch)
                stop.set()
            task_status.started()
            async for _ in signals:
                stop.set()
    finally:
        # asyncio gives SIGTERM and SIGHUP back to the system's default, death: a signal while
        # the loop winds down is noted, as the stop is under way already.
        remember_stops()


async def _shutdown_on(stop: anyio.Event, rt: Runtime) -> None:
    await stop.wait()
    rt.shutdown()


def main(argv: Sequence[str] | None = None, prog: str = "python -m actors.run") -> int:
    """Parse options, load the graph, run it; return the exit code."""
    try:
        # Noted, not raised, while argparse parses: parse_intermixed_args changes its actions for
        # the while and an exception in there leaves them half-changed (an AttributeError).
        remember_stops()
        parser = argparse.ArgumentParser(prog=prog, description="Run an actors graph file.")
        add_arguments(parser)
        args = parser.parse_intermixed_args(argv)
        raise_stops()  # a signal noted while the imports loaded, or while parsing, stops the run here
        return launch(args)
    except KeyboardInterrupt:
        return 0  # Ctrl-C, SIGTERM or SIGHUP before the graph ran: nothing to stop


def launch(args: argparse.Namespace) -> int:
    """Load and run the graph that :func:`add_arguments`' options name; return the exit code."""
    try:
        arguments = []
        for word in args.arguments:
            name, sep, value = word.partition(":=")
            if not sep or not name:
                raise GraphFileError(f"{args.graph}: graph arguments are name:=value, got {word!r}")
            arguments.append((name, value))
        if args.show_args:
            print(format_arguments(argument_rows(args.graph)))
            return 0
        graph, classes = load_graph(args.graph, arguments)
    except GraphFileError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    if args.transport is not None:
        transport = (graph.transport or TransportSection()) if args.transport == "zenoh" else None
        graph = msgspec.structs.replace(graph, transport=transport)
    settings = graph.runtime
    clock = args.clock or settings.clock
    duration = settings.duration if args.duration is None else args.duration
    if clock == "virtual" and not duration:
        # Virtual time runs as fast as the CPU allows: with no end it would never stop.
        print(
            f"error: {args.graph}: the virtual clock needs a duration, e.g. --duration 10 "
            "(virtual time runs as fast as it can, so nothing else would stop it)",
            file=sys.stderr,
        )
        return 2
    if args.loop and clock == "virtual":
        print(f"error: --loop {args.loop} is for the wall clock; virtual time runs on its own loop", file=sys.stderr)
        return 2
    if args.loop == "uvloop":
        try:
            uvloop_loop().close()
        except ImportError as exc:
            print(f"error: --loop uvloop: {exc}", file=sys.stderr)
            return 2
    if clock == "virtual" and graph.transport is not None:
        print(
            f"error: {args.graph}: a graph with a transport runs on the wall clock: other processes "
            "cannot follow virtual time (use --clock wall, or --transport none)",
            file=sys.stderr,
        )
        return 2
    try:
        from actors.recording.options import attachments

        attach = attachments(record=args.record, topics=args.topics, foxglove=args.foxglove)
    except (ActorsError, ImportError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    configure_console(LEVELS[args.log_level or settings.log_level])
    factory = VirtualTimeLoop if clock == "virtual" else wall_loop(args.loop, graph.transport is not None)
    options: dict[str, Any] = {"loop_factory": factory}
    # Noted, not raised, until the graph listens: asyncio's own Ctrl-C handling would cancel the
    # runtime wherever it stands in its start-up.
    remember_stops()
    try:
        anyio.run(
            lambda: run_graph(graph, classes, name=Path(args.graph).stem, duration=duration, attach=attach),
            backend_options=options,
        )
    except BaseException as exc:
        return _report(exc, args.graph)
    finally:
        take_noted()  # the run is over: what came while it wound down asked for nothing more
        raise_stops()
    return 0


# --------------------------------------------------------------------------- failures


def _report(exc: BaseException, graph: str) -> int:
    """Print what ended the run, once; return the exit code."""
    errors = list(_leaves(exc))
    if any(isinstance(error, KeyboardInterrupt) for error in errors) or not errors:
        return 0  # a stop signal before the graph listened for it, or after: a stop all the same
    codes = []
    for error in errors:
        if isinstance(error, GraphFileError):
            print(f"error: {graph}: {error}", file=sys.stderr)
            codes.append(2)
            continue
        if isinstance(error, Escalation):
            headline, shown = f"supervisor: {error}", error.__cause__
        elif isinstance(error, NodeStartError):
            headline, shown = str(error), error.__cause__
        else:
            headline, shown = one_line(error), error
        print(f"[FATAL] {headline}", file=sys.stderr)
        if shown is not None:
            print("".join(_user_traceback(shown)), end="", file=sys.stderr)
        codes.append(1)
    return codes[0]


def _leaves(exc: BaseException) -> Iterator[BaseException]:
    """The errors inside (nested) exception groups, without the cancellations."""
    if isinstance(exc, BaseExceptionGroup):
        for inner in exc.exceptions:
            yield from _leaves(inner)
    elif not isinstance(exc, asyncio.CancelledError):  # the only backend actors.run uses
        yield exc


def _user_traceback(error: BaseException) -> list[str]:
    """The user's own frames of ``error``, then its causes' alike.

    An error with no frame of the user's shows them all, unless it is one
    actors raises on purpose (its message says what is wrong).
    """
    lines: list[str] = []
    seen: set[int] = set()
    current: BaseException | None = error
    while current is not None and id(current) not in seen:
        seen.add(id(current))
        if current is not error:
            lines.append(f"caused by {one_line(current)}\n")
        frames = list(traceback.walk_tb(current.__traceback__))
        users = [(frame, line) for frame, line in frames if is_users(frame)]
        if not users and not isinstance(current, ActorsError):
            users = frames  # a bug of the machinery itself: show where
        lines += traceback.StackSummary.extract(iter(users)).format()
        current = current.__cause__ or (None if current.__suppress_context__ else current.__context__)
    return lines


if __name__ == "__main__":
    sys.exit(main())
