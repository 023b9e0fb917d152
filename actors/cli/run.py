"""``actors run SCRIPT.py|PKG EXE [ARGS...] [--ros-args ...]``: run an rclpy program, unmodified, on actors."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from actors.recording.options import add_attachment_options

__all__ = ["register", "add_session_options", "session_options"]


def register(groups: Any) -> None:
    """Add the ``run`` command."""
    parser = groups.add_parser(
        "run",
        help="run an rclpy program (SCRIPT.py, or a package's executable: PKG EXE) on actors, unmodified",
        description=(
            "Run an rclpy program as `python SCRIPT.py ARGS` would, or a package's executable as "
            "`ros2 run PKG EXE ARGS` would, with rclpy, ament_index_python and the message packages "
            "provided by actors. Options go before the program; everything after it is the "
            "program's (its own arguments and --ros-args ...)."
        ),
    )
    add_session_options(parser)
    parser.add_argument("--graph", metavar="GRAPH.toml", help="run the script beside this graph's nodes")
    parser.add_argument(
        "--with",
        dest="partners",
        metavar="PARTNER.py",
        action="append",
        default=[],
        help="another rclpy program to run beside it in the same runtime, e.g. its action "
        "server (quote it with its arguments: --with 'server.py ARGS' or --with 'PKG EXE ARGS'); repeatable",
    )
    parser.add_argument("script", help="the rclpy program, e.g. talker.py, or a package (then its executable)")
    parser.add_argument("args", nargs=argparse.REMAINDER, help="the program's arguments")
    parser.set_defaults(func=_run)


def _run(args: argparse.Namespace) -> int:
    from actors.compat.launcher import run_script
    from actors.compat.programs import program_for
    from actors.errors import PackageError

    try:
        program, rest = program_for([args.script, *args.args])
    except (FileNotFoundError, PackageError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    return run_script(program, rest, graph=args.graph, partners=args.partners, **session_options(args))


def add_session_options(parser: argparse.ArgumentParser) -> None:
    """The options of a run in one session (``actors run``, ``actors launch FILE``): clock, duration,
    timeout, log level, transport, recording and the live view."""
    parser.add_argument("--clock", choices=("wall", "virtual"), help="the runtime clock (default: wall)")
    parser.add_argument("--duration", type=float, help="stop after this many seconds of runtime clock")
    parser.add_argument(
        "--timeout",
        type=float,
        metavar="S",
        help="stop the run after S seconds of wall time, whatever the program does (exit code 124)",
    )
    parser.add_argument(
        "--log-level", choices=("debug", "info", "warn", "error", "fatal"), help="the console's level (default: info)"
    )
    parser.add_argument(
        "--transport",
        choices=("zenoh", "none"),
        default="none",
        help="reach other processes (another actors run or launch, ROS 2 with rmw_zenoh) over Zenoh; wall clock only",
    )
    add_attachment_options(parser)


def session_options(args: argparse.Namespace) -> dict[str, Any]:
    """:func:`add_session_options`' values, as run_script's keyword arguments."""
    return {
        "clock": args.clock,
        "duration": args.duration,
        "log_level": args.log_level,
        "timeout": args.timeout,
        "record": args.record,
        "topics": args.topics,
        "foxglove": args.foxglove,
        "transport": args.transport == "zenoh",
    }
