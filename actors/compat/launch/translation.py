"""``ros2`` commands of a launch file, run as actors' own command line against the launch's graph.

Launch files call ``ros2 service call``, ``ros2 param set``... through
ExecuteProcess (the ROS 2 tutorials do).  With no ``ros2`` on the PATH, the
launcher runs the same words as ``python -m actors ...`` (the verbs and
arguments are ros2's), pointed at the launch's own graph by ``$ACTORS_GRAPH``.
A real ``ros2`` on the PATH is run as it is.  Only a plain command is
translated: a shell line with pipes, redirections or several commands is left
to the shell.

On the virtual clock, a request (``service call``, ``param set``, ``topic pub
--once``, a listing...) holds the clock still until it ends: it takes no
virtual time, as the tutorials' calls take next to none on ROS.  Commands that
wait for the graph to move on (``topic echo``/``hz``/``bw``/``delay``,
``action send_goal``, ``bag``, ``run``, ``launch``) and ``topic pub`` at a
rate run beside it in real time instead, as any process does.
"""

from __future__ import annotations

import os
import shlex
import shutil
import sys
from collections.abc import Sequence

from actors.compat.launch.substitutions import ROS2
from actors.ops.control import GRAPH_VARIABLE, ControlEndpoint, endpoint_name
from actors.runtime import Runtime

__all__ = ["translated", "graph_environment", "holds_time", "WAITING"]

_SHELL_SYNTAX = set("|&;<>()`$")
_WAITS_FOR_TIME = {("topic", "echo"), ("topic", "hz"), ("topic", "bw"), ("topic", "delay"), ("action", "send_goal")}
_PROGRAMS = {"bag", "run", "launch"}


#: How ``actors topic pub`` (as ros2's) starts the line it prints while it waits for a subscription:
#: from then on the command waits for what only the graph's time may bring.
WAITING = b"Waiting for at least "


def holds_time(command: Sequence[str]) -> bool:
    """Whether the translated ``command`` (actors' argv) is a request that holds virtual time while it runs."""
    verb = [word for word in command[3:] if not word.startswith("-")][:2]
    if not verb or verb[0] in _PROGRAMS or tuple(verb) in _WAITS_FOR_TIME:
        return False
    if tuple(verb) == ("topic", "pub"):
        return any(word in ("-1", "--once") or word.startswith(("-t", "--times")) for word in command)
    return True


def translated(words: Sequence[str], shell: bool, environment: dict[str, str]) -> list[str] | None:
    """The actors command line (``python -m actors ...``) for a ``ros2`` command when there is no
    ``ros2`` to run, else None."""
    if shell:
        line = " ".join(words)
        lexer = shlex.shlex(line, posix=True, punctuation_chars=True)
        lexer.whitespace_split = True
        try:
            argv = list(lexer)
        except ValueError:  # unbalanced quotes: the shell's to complain about
            return None
        if any(word and set(word) <= _SHELL_SYNTAX for word in argv):
            return None
    else:
        argv = list(words)
    if not argv or os.path.basename(argv[0]) != ROS2:
        return None
    if os.path.sep in argv[0] and os.access(argv[0], os.X_OK):
        return None
    if shutil.which(ROS2, path=environment.get("PATH")) is not None:
        return None
    return [sys.executable, "-m", "actors", *argv[1:]]


def graph_environment(runtime: Runtime) -> dict[str, str]:
    """The environment pointing actors' command line at ``runtime``'s graph (over its control endpoint)."""
    environment = {"ACTORS_TRANSPORT": "none"}
    for attachment in runtime.attachments:
        if isinstance(attachment, ControlEndpoint) and attachment.server is not None:
            environment[GRAPH_VARIABLE] = endpoint_name(attachment.server.path)
    return environment
