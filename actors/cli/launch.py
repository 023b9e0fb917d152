"""``actors launch``: a graph file (``GRAPH.toml``, as ``python -m actors.run GRAPH``), or a ROS 2 launch file.

``actors launch PKG FILE [name:=value ...]`` and ``actors launch PATH
[name:=value ...]`` run a launch file (``.launch.py``, ``.launch.xml``,
``.launch.yaml``) as ``ros2 launch`` does, in one actors runtime
(:mod:`actors.compat.launch.service`); ``--show-args`` lists its arguments.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any

__all__ = ["register", "launch"]


def register(subparsers: Any) -> None:
    """List ``launch`` among the commands; :func:`actors.cli.main` hands its arguments to :func:`launch`."""
    subparsers.add_parser(
        "launch",
        help="run a graph file (GRAPH.toml) or a ROS 2 launch file (PKG FILE, or PATH) (options: actors launch -h)",
        add_help=False,
    ).add_argument("argv", nargs=argparse.REMAINDER)


def launch(argv: Sequence[str]) -> int:
    """Run a graph file or a launch file with ``argv``; return the exit code."""
    if _names_a_launch_file(argv):
        return _launch_file(argv)
    from actors.run import main

    return main(argv, prog="actors launch")


_LAUNCH_FILES = (".py", ".xml", ".yaml", ".yml", ".launch")


def _names_a_launch_file(argv: Sequence[str]) -> bool:
    """A word that is a launch file's name (and none a graph file's): ros2 launch's form."""
    from actors.launch.importing import shipped_graphs

    graphs = {p.stem for p in shipped_graphs().glob("*.toml")}
    words = [word for word in argv if not word.startswith("-")]
    if any(word.endswith(".toml") or word in graphs for word in words):
        return False
    return any(word.endswith(_LAUNCH_FILES) for word in words)


def _launch_file(argv: Sequence[str]) -> int:
    from actors.cli.run import add_session_options, session_options
    from actors.compat.launch.service import LaunchProgram, find_launch_file, parse_launch_arguments
    from actors.compat.launcher import run_script
    from actors.errors import LaunchFileError, PackageError

    parser = argparse.ArgumentParser(
        prog="actors launch",
        description="Run a ROS 2 launch file (PKG FILE, or PATH) as ros2 launch does, in one actors runtime; "
        "launch arguments as name:=value after it.",
    )
    add_session_options(parser)
    parser.add_argument("-s", "--show-args", action="store_true", help="list the launch file's arguments and exit")
    parser.add_argument("words", nargs="+", metavar="PKG FILE | PATH", help="the launch file, then name:=value ...")
    args = parser.parse_args(argv)
    try:
        path, rest = find_launch_file(args.words)
        arguments = parse_launch_arguments(rest)
        if args.show_args:
            return _show_args(path)
    except (LaunchFileError, PackageError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    return run_script(LaunchProgram(path, arguments), [], **session_options(args))


def _show_args(path: Path) -> int:
    """Print the launch file's arguments as ``ros2 launch --show-args`` does."""
    from actors.compat.launch.loading import load_launch_file
    from actors.compat.overlay import overlaid
    from actors.launch.graph_args import format_arguments

    with overlaid():
        declared = load_launch_file(str(path)).get_launch_arguments()
    print(format_arguments((a.name, a.description, a.default_text(), a.choices) for a in declared))
    return 0
