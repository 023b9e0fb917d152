"""``actors launch GRAPH [options]``: run a graph file, the same as ``python -m actors.run GRAPH``."""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from typing import Any

__all__ = ["register", "launch"]


def register(subparsers: Any) -> None:
    """List ``launch`` among the commands; :func:`actors.cli.main` hands its arguments to :func:`launch`."""
    subparsers.add_parser(
        "launch",
        help="run a graph file, as python -m actors.run GRAPH (options: actors launch -h)",
        add_help=False,
    ).add_argument("argv", nargs=argparse.REMAINDER)


def launch(argv: Sequence[str]) -> int:
    """Run ``python -m actors.run`` with ``argv`` (its options in any order); return its exit code."""
    from actors.run import main

    return main(argv, prog="actors launch")
