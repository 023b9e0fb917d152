"""The ``actors`` command line: ros2-style verbs, ``actors <group> <verb> ...``."""

from __future__ import annotations

import argparse
import importlib
import os
import sys
from collections.abc import Sequence

from actors.core.signals import raise_stops

__all__ = ["main"]

# Each group module exposes ``register(subparsers)``, which adds its parser and
# sets ``func(args) -> int | None`` on every verb.  Imports inside the verbs stay
# lazy so that ``actors --help`` is quick.
GROUPS = (
    "node",
    "topic",
    "service",
    "action",
    "param",
    "lifecycle",
    "interface",
    "doctor",
    "graph",
    "launch",
    "run",
    "pkg",
    "bag",
    "tf",
    "daemon",
)


def build_parser() -> argparse.ArgumentParser:
    """The full argument parser, every group registered."""
    parser = argparse.ArgumentParser(prog="actors", description="ros2-style command line for actors graphs")
    parser.add_argument(
        "--workspace",
        action="append",
        default=[],
        metavar="DIR",
        help="also find interface packages in this ROS workspace (repeatable; the working directory's is found "
        "anyway, and ACTORS_WORKSPACE's)",
    )
    groups = parser.add_subparsers(dest="group", metavar="GROUP", required=True)
    for group in GROUPS:
        importlib.import_module(f"actors.cli.{group}").register(groups)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run one command; return its exit code (2 for misuse, with one line on stderr)."""
    argv = list(sys.argv[1:] if argv is None else argv)
    # Before anything slow loads: SIGTERM and SIGHUP stop a command as Ctrl-C does, at any moment.
    raise_stops()
    try:
        return _command(argv)
    except KeyboardInterrupt:
        return 0
    except BrokenPipeError:
        # stdout was closed early (`| head`): stop quietly, as a process killed by SIGPIPE
        # would, and point stdout at /dev/null so the interpreter's final flush stays silent.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 141


def _command(argv: list[str]) -> int:
    from actors.errors import ActorsError
    from actors.messages.discovery import add_workspace

    if argv[:1] == ["launch"]:
        # actors.run's own parser takes the rest, options before or after the graph file.
        from actors.cli.launch import launch

        return launch(argv[1:])
    parser = build_parser()
    args, unknown = parser.parse_known_args(argv)
    if unknown:  # the verb's usage, as ros2 prints it, not the whole command line's
        getattr(args, "verb_parser", parser).error(f"unrecognized arguments: {' '.join(unknown)}")
    try:
        for folder in args.workspace:
            add_workspace(folder)
        return args.func(args) or 0
    except ActorsError as exc:
        print(f"actors: {exc}", file=sys.stderr)
        return 2
