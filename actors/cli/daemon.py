"""``actors daemon start|stop|status``: ros2's daemon verbs, kept so scripts run; actors needs no daemon."""

from __future__ import annotations

import argparse
import functools
from typing import Any

__all__ = ["register"]

# ros2's daemon caches the graph for its command line; an actors command asks the running graph
# itself, so there is never a daemon to start or stop.
_SAYS = {
    "start": "actors needs no daemon: each command asks the running graph directly",
    "stop": "The daemon is not running",
    "status": "The daemon is not running",
}


def register(subparsers: Any) -> None:
    """Add the ``daemon`` group: verbs that say there is no daemon and exit 0."""
    group = subparsers.add_parser("daemon", help="ros2's graph-caching daemon: actors needs none")
    verbs = group.add_subparsers(dest="verb", metavar="VERB", required=True)
    for name, said in _SAYS.items():
        verb = verbs.add_parser(name, help=f"as ros2 daemon {name}; prints: {said}")
        verb.set_defaults(func=functools.partial(_say, said), verb_parser=verb)


def _say(said: str, args: argparse.Namespace) -> None:
    print(said)
