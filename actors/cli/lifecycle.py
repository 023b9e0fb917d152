"""``actors lifecycle nodes|get|list|set``: a running graph's managed nodes, as ``ros2 lifecycle`` shows them.

A managed node is one that serves ``<node>/get_state`` of type
lifecycle_msgs/srv/GetState (an rclpy LifecycleNode under ``actors run``);
the verbs call its lifecycle services and print what ros2 prints.
"""

from __future__ import annotations

import argparse
import sys
from typing import Any

from actors.cli._client import Connection, add_verb, call_service, connect
from actors.errors import ControlError

__all__ = ["register"]

_GET_STATE = "lifecycle_msgs/srv/GetState"


def register(subparsers: Any) -> None:
    """Add the ``lifecycle`` group and its verbs to the command line."""
    parser = subparsers.add_parser("lifecycle", help="managed nodes: their states and transitions")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)

    nodes = add_verb(verbs, "nodes", list_nodes, help="list the nodes with a lifecycle")
    nodes.add_argument("-a", "--all", action="store_true", help="also list hidden nodes")
    nodes.add_argument("-c", "--count-nodes", action="store_true", help="only print how many there are")

    get = add_verb(verbs, "get", get_state, help="a managed node's state (every managed node's without a name)")
    get.add_argument("node_name", nargs="?", metavar="NODE")
    get.add_argument("--include-hidden-nodes", action="store_true", help="consider hidden nodes as well")

    listing = add_verb(verbs, "list", list_transitions, help="the transitions a managed node may take now")
    listing.add_argument("node_name", metavar="NODE")
    listing.add_argument("-a", "--all", action="store_true", help="every transition of the state machine")
    listing.add_argument("--include-hidden-nodes", action="store_true", help="consider hidden nodes as well")

    setter = add_verb(verbs, "set", set_state, help="take a transition, by label (configure) or id (1)")
    setter.add_argument("node_name", metavar="NODE")
    setter.add_argument("transition", metavar="TRANSITION")
    setter.add_argument("--include-hidden-nodes", action="store_true", help="consider hidden nodes as well")


def _managed(conn: Connection, hidden: bool) -> list[str]:
    # The full names of the nodes that serve <name>/get_state as a GetState service, sorted.
    from actors.ros.names import is_hidden

    graph = conn.graph()
    served = {service.name for service in graph.services if service.type == _GET_STATE}
    names = {node.name for node in graph.nodes if f"{node.name.rstrip('/')}/get_state" in served}
    return sorted(name for name in names if hidden or not is_hidden(name))


def _absolute(name: str) -> str:
    return name if name.startswith("/") else f"/{name}"


def _known(conn: Connection, args: argparse.Namespace) -> str:
    # The node the verb names, as a full name; ControlError if no managed node has it.
    name = _absolute(args.node_name)
    if name not in _managed(conn, args.include_hidden_nodes):
        raise ControlError(f"Node not found: {name}")
    return name


def list_nodes(args: argparse.Namespace) -> None:
    """Print each managed node's full name, sorted (under ``-c``, how many)."""
    with connect(args.graph) as conn:
        names = _managed(conn, args.all)
    if args.count_nodes:
        print(len(names))
    elif names:
        print(*names, sep="\n")


def get_state(args: argparse.Namespace) -> None:
    """Print ``label [id]`` of the node's state; for every managed node, each prefixed ``name: ``."""
    from interfaces.lifecycle_msgs.srv import GetState

    with connect(args.graph) as conn:
        names = [_known(conn, args)] if args.node_name else _managed(conn, args.include_hidden_nodes)
        states = {name: call_service(conn, f"{name}/get_state", GetState, GetState.Request()) for name in names}
    for name in sorted(states):
        state = states[name].current_state
        print(("" if args.node_name else f"{name}: ") + f"{state.label} [{state.id}]")


def _transitions(conn: Connection, name: str, service: str) -> list[Any]:
    from interfaces.lifecycle_msgs.srv import GetAvailableTransitions

    request = GetAvailableTransitions.Request()
    return list(call_service(conn, f"{name}/{service}", GetAvailableTransitions, request).available_transitions)


def list_transitions(args: argparse.Namespace) -> None:
    """Print each transition available now (every one under ``-a``) with its start and goal states."""
    with connect(args.graph) as conn:
        name = _known(conn, args)
        found = _transitions(conn, name, "get_transition_graph" if args.all else "get_available_transitions")
    for t in found:
        print(
            f"- {t.transition.label} [{t.transition.id}]\n\tStart: {t.start_state.label}\n\tGoal: {t.goal_state.label}"
        )


def set_state(args: argparse.Namespace) -> int:
    """Take the transition named by label or id; print whether it succeeded.

    ControlError (exit 2) for a transition the node's state does not offer,
    listing those it does; ``Transitioning failed`` (exit 1) when the node's
    callback did not succeed.
    """
    from interfaces.lifecycle_msgs.srv import ChangeState

    with connect(args.graph) as conn:
        name = _known(conn, args)
        available = [t.transition for t in _transitions(conn, name, "get_available_transitions")]
        chosen = next((t for t in available if t.label == args.transition), None)
        chosen = chosen or next((t for t in available if str(t.id) == args.transition), None)
        if chosen is None:
            offered = "".join(f"\n- {t.label} [{t.id}]" for t in available)
            raise ControlError(f"Unknown transition requested, available ones are:{offered}")
        response = call_service(conn, f"{name}/change_state", ChangeState, ChangeState.Request(transition=chosen))
    if response.success:
        print("Transitioning successful")
        return 0
    print("Transitioning failed", file=sys.stderr)
    return 1
