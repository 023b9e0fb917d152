"""``actors node list|info``: the nodes of a running graph, as ``ros2 node`` shows them."""

from __future__ import annotations

import argparse
from typing import Any

from actors.cli._client import add_verb, graph_snapshot, query
from actors.ops.control import GetNode, NodeDetail
from actors.ros.names import is_hidden, is_hidden_name
from actors.system.introspection import action_of

__all__ = ["register"]


def register(subparsers: Any) -> None:
    """Add the ``node`` group and its verbs to the command line."""
    parser = subparsers.add_parser("node", help="list nodes and show what each uses")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)

    listing = add_verb(verbs, "list", list_nodes, help="list the graph's nodes")
    listing.add_argument("-a", "--all", action="store_true", help="also list hidden nodes (names starting with _)")
    listing.add_argument("-c", "--count-nodes", action="store_true", help="only print how many nodes there are")

    info = add_verb(
        verbs,
        "info",
        node_info,
        help="a node's subscribers, publishers, service servers and clients, action servers and clients",
    )
    info.add_argument("node", metavar="NODE")
    info.add_argument("--include-hidden", action="store_true", help="also show hidden topics, services and actions")


def list_nodes(args: argparse.Namespace) -> None:
    """Print every node's full name, sorted (under ``-c``, how many there are)."""
    names = sorted(node.name for node in graph_snapshot(args).nodes if args.all or not is_hidden(node.name))
    if args.count_nodes:
        print(len(names))
        return
    for name in names:
        print(name)


def node_info(args: argparse.Namespace) -> None:
    """Print the node's name, then each section's ``name: type`` lines; ControlError if unknown.

    As ``ros2 node info``, hidden names (an action's ``/_action/`` topics and
    services among them) are left out unless ``--include-hidden``; actions are
    read off their ``send_goal`` servers and clients.
    """
    detail = query(args, GetNode(name=args.node), NodeDetail)
    print(detail.name)

    def shown(pairs: tuple[tuple[str, str], ...]) -> list[tuple[str, str]]:
        return [(name, type_) for name, type_ in pairs if args.include_hidden or not is_hidden_name(name)]

    def actions(pairs: tuple[tuple[str, str], ...]) -> list[tuple[str, str]]:
        return sorted(a for n, t in pairs if n.endswith("/_action/send_goal") and (a := action_of(n, t)))

    sections = (
        ("Subscribers", shown(detail.subscribers)),
        ("Publishers", shown(detail.publishers)),
        ("Service Servers", shown(detail.servers)),
        ("Service Clients", shown(detail.clients)),
        ("Action Servers", shown(tuple(actions(detail.servers)))),
        ("Action Clients", shown(tuple(actions(detail.clients)))),
    )
    for title, pairs in sections:
        print(f"  {title}:")
        # As ros2 prints them: an empty section is one blank line.
        print(*(f"    {name}: {type_}" for name, type_ in pairs), sep="\n")
