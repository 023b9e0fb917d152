"""Spawning a graph file's nodes into a runtime: in file order, the delayed ones when their delay ends."""

from __future__ import annotations

import traceback
from collections.abc import Sequence

import anyio
import anyio.abc

from actors.errors import ActorsError, GraphFileError
from actors.launch.graph_file import GraphFile, NodeEntry
from actors.ros.node import Node
from actors.runtime import Runtime, frozen_startup

__all__ = ["spawn_graph", "NodeStartError", "one_line"]


class NodeStartError(Exception):
    """A node's constructor raised while the graph started it; the error is ``__cause__``."""

    def __init__(self, node: str, use: str, error: BaseException) -> None:
        self.node = node
        self.use = use
        super().__init__(f"node {node} ({use}) failed to start: {one_line(error)}")
        self.__cause__ = error


async def spawn_graph(
    rt: Runtime,
    graph: GraphFile,
    classes: Sequence[type[Node]],
    *,
    task_status: anyio.abc.TaskStatus[None] = anyio.TASK_STATUS_IGNORED,
) -> None:
    """Spawn the graph's nodes into ``rt`` in file order, the delayed ones when their delay ends.

    Reports started (``await tg.start(spawn_graph, ...)``) once the nodes without
    a delay run, and returns when every node has been spawned.  Raises as
    :func:`run_graph` does.
    """
    entries = list(enumerate(zip(graph.nodes, classes)))
    with frozen_startup():
        for i, (entry, cls) in entries:
            if not entry.delay:
                _spawn(rt, i, entry, cls)
    task_status.started()
    async with anyio.create_task_group() as tg:
        for i, (entry, cls) in entries:
            if entry.delay:
                tg.start_soon(_spawn_later, rt, i, entry, cls)


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
    except Exception as exc:
        raise NodeStartError(_node_name(exc, cls) or f"nodes[{index}]", entry.use, exc) from exc


def _node_name(error: BaseException, cls: type[Node]) -> str | None:
    """The full name the failed constructor had given its node, if it got that far.

    The instance is still reachable from the constructor's frame in the traceback.
    """
    for frame, _ in traceback.walk_tb(error.__traceback__):
        core = getattr(frame.f_locals.get("self"), "_core", None)
        if isinstance(frame.f_locals.get("self"), cls) and core is not None:
            return str(core.fqn)
    return None


async def _spawn_later(rt: Runtime, index: int, entry: NodeEntry, cls: type[Node]) -> None:
    await anyio.sleep(entry.delay)
    # A failure leaves the runtime's block (in an ExceptionGroup), which stops every node
    # gracefully before it reaches launch(), which unwraps it.
    _spawn(rt, index, entry, cls)


def one_line(error: BaseException) -> str:
    """``Type: message``, or ``Type`` alone when the message is empty."""
    text = str(error)
    name = type(error).__name__
    return f"{name}: {text}" if text else name
