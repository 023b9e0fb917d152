"""``python -m actors.run GRAPH``: run a graph file until its duration ends or a signal stops it.

Exit codes: 0 after a graceful stop (end of duration, SIGINT, SIGTERM); 1 when a
failure escalates past the supervisor (its cause printed once); 2 for misuse
(bad options, a malformed graph file), with one line on stderr.
"""

from __future__ import annotations

import argparse
import signal
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import anyio

from actors.clock import VirtualTimeLoop, precise_loop
from actors.control import ControlEndpoint
from actors.errors import ActorsError, Escalation, GraphFileError
from actors.graph import GraphFile, NodeEntry, load_graph
from actors.log import LEVELS, configure_console
from actors.node import Node
from actors.runtime import Runtime

__all__ = ["main", "run_graph"]


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="python -m actors.run", description="Run an actors graph file."
    )
    parser.add_argument("graph", help="the graph file, e.g. graph.toml")
    parser.add_argument("--clock", choices=("wall", "virtual"), help="override [runtime] clock")
    parser.add_argument("--duration", type=_seconds, help="seconds to run; 0 runs until stopped")
    parser.add_argument("--log-level", choices=sorted(LEVELS), help="override [runtime] log_level")
    return parser


def _seconds(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number of seconds: {text!r}") from None
    if value < 0:
        raise argparse.ArgumentTypeError(f"duration must be >= 0, got {value}")
    return value


async def run_graph(
    graph: GraphFile,
    classes: Sequence[type[Node]],
    *,
    name: str,
    duration: float,
    handle_signals: bool = True,
) -> None:
    """Spawn the graph's nodes in file order and run until ``duration`` or a signal.

    Raises Escalation if the supervisor gives up, and what a node's constructor
    raises (wrapped in GraphFileError naming the node's entry).
    """
    policy = graph.supervisor.policy()
    async with Runtime(name=name, supervisor=policy, attach=[ControlEndpoint()]) as rt:
        entries = list(enumerate(zip(graph.nodes, classes)))
        for i, (entry, cls) in entries:
            if not entry.delay:
                _spawn(rt, i, entry, cls)
        async with anyio.create_task_group() as tg:
            for i, (entry, cls) in entries:
                if entry.delay:
                    tg.start_soon(_spawn_later, rt, i, entry, cls)
            if handle_signals:
                tg.start_soon(_stop_on_signal, rt)
            await rt.wait(duration or None)
            tg.cancel_scope.cancel()


def _spawn(rt: Runtime, index: int, entry: NodeEntry, cls: type[Node]) -> None:
    try:
        rt.spawn(
            cls,
            name=entry.name,
            namespace=entry.namespace or None,
            params=entry.params,
            remap=entry.remap,
            restart=entry.restart,
        )
    except ActorsError as exc:
        raise GraphFileError(f"nodes[{index}] ({entry.use}): {exc}") from None


async def _spawn_later(rt: Runtime, index: int, entry: NodeEntry, cls: type[Node]) -> None:
    await anyio.sleep(entry.delay)
    try:
        _spawn(rt, index, entry, cls)
    except GraphFileError as exc:
        rt._fail(exc)


async def _stop_on_signal(rt: Runtime) -> None:
    with anyio.open_signal_receiver(signal.SIGINT, signal.SIGTERM) as signals:
        async for _ in signals:
            rt.shutdown()
            return


def main(argv: Sequence[str] | None = None) -> int:
    """Parse options, load the graph, run it; return the exit code."""
    args = _parser().parse_args(argv)
    try:
        graph, classes = load_graph(args.graph)
    except GraphFileError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    settings = graph.runtime
    clock = args.clock or settings.clock
    duration = settings.duration if args.duration is None else args.duration
    configure_console(LEVELS[args.log_level or settings.log_level])
    options: dict[str, Any] = {"loop_factory": VirtualTimeLoop if clock == "virtual" else precise_loop}
    try:
        anyio.run(
            lambda: run_graph(graph, classes, name=Path(args.graph).stem, duration=duration),
            backend_options=options,
        )
    except GraphFileError as exc:
        print(f"error: {args.graph}: {exc}", file=sys.stderr)
        return 2
    except Escalation as exc:
        print(f"[FATAL] supervisor: {exc}", file=sys.stderr)
        return 1
    except ActorsError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        # A second Ctrl-C while shutting down: stop at once, still without a traceback.
        return 130
    return 0


if __name__ == "__main__":
    sys.exit(main())
