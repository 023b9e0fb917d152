"""``actors service list|type|find|call``: a running graph's services, as ``ros2 service`` shows them."""

from __future__ import annotations

import argparse
from typing import Any

from actors.cli._client import add_type_and_find, add_verb, call_service, connect, graph_snapshot, print_names

__all__ = ["register"]


def register(subparsers: Any) -> None:
    """Add the ``service`` group and its verbs to the command line."""
    parser = subparsers.add_parser("service", help="list services, show their types, call them")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)

    listing = add_verb(verbs, "list", list_services, help="list the graph's services")
    listing.add_argument("-t", "--show-types", action="store_true", help="also show each service's type")
    listing.add_argument(
        "--include-hidden-services", action="store_true", help="also list hidden services (an action's)"
    )
    listing.add_argument("-c", "--count-services", action="store_true", help="only print how many services there are")

    add_type_and_find(verbs, "service", "rcl_interfaces/srv/ListParameters", lambda graph: graph.services)

    info = add_verb(verbs, "info", service_info, help="a service's type and how many clients and servers it has")
    info.add_argument("service", metavar="NAME")

    caller = add_verb(verbs, "call", call, help="call a service and print the response")
    caller.add_argument("service", metavar="NAME")
    caller.add_argument("type", metavar="TYPE", help="e.g. example_interfaces/srv/AddTwoInts")
    caller.add_argument(
        "values",
        metavar="VALUES",
        nargs="?",
        default="{}",
        help='request fields in YAML, e.g. "{a: 2, b: 3}" (default: all defaults)',
    )
    caller.add_argument("--timeout", type=float, default=10.0, help="seconds to wait for the response (default 10)")


def list_services(args: argparse.Namespace) -> None:
    """Print each service's name, with ``[type]`` under ``-t``; hidden ones only when asked."""
    from actors.ros.names import is_hidden_name

    services = graph_snapshot(args).services
    shown = [s for s in services if args.include_hidden_services or not is_hidden_name(s.name)]
    print_names(shown, args.show_types, args.count_services)


def service_info(args: argparse.Namespace) -> None:
    """Print ``Type:``, ``Clients count:`` and ``Services count:``, as ``ros2 service info``.

    ControlError (exit 2) for a service nobody serves.
    """
    from actors.core.explain import did_you_mean
    from actors.errors import ControlError
    from actors.ros.names import expand

    graph = graph_snapshot(args)
    name = expand(args.service, "/", "_", what="service name")
    servers = [s for s in graph.services if s.name == name]
    if not servers:
        raise ControlError(f"unknown service {name}{did_you_mean(name, [s.name for s in graph.services])}")
    print(f"Type: {servers[0].type}")
    print(f"Clients count: {sum(called == name for node in graph.nodes for called in node.calls)}")
    print(f"Services count: {len(servers)}")


def call(args: argparse.Namespace) -> None:
    """Print the request, then the response as rclpy's repr and as YAML, as ``ros2 service call``.

    Raises (exit 2) for an unknown type or a bad value before connecting, and
    for an unknown service, a failed handler or a timeout after.
    """
    from actors import codec
    from actors.cli._format import ros_repr, yaml_text
    from actors.errors import UnknownInterfaceError

    srv_type = codec.get_type(args.type)
    if not hasattr(srv_type, "Request"):
        raise UnknownInterfaceError(f"{args.type} is a message type, not a service type")
    request = codec.from_yaml(args.values, srv_type.Request)
    with connect(args.graph) as conn:
        print(f"requester: making request: {ros_repr(request)}\n", flush=True)
        response = call_service(conn, args.service, srv_type, request, timeout=args.timeout)
    print("response:")
    print(ros_repr(response))
    print(yaml_text(response))
