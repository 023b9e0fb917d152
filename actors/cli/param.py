"""``actors param list|get|set|dump``: node parameters, through each node's parameter services.

Going through ``<node>/get_parameters`` and its siblings, as ``ros2 param``
does, means a set from the command line runs the node's on-set callbacks and
publishes the change on ``/parameter_events`` exactly as any client's would.
"""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING, Any

from actors.cli._client import add_verb, call_service, connect
from actors.errors import ControlError

if TYPE_CHECKING:
    from actors.cli._client import Connection

__all__ = ["register"]

# What ``ros2 param get`` prints before each type's value, by ParameterType number.
_LABELS = {
    1: "Boolean value is",
    2: "Integer value is",
    3: "Double value is",
    4: "String value is",
    5: "Byte values are",
    6: "Boolean values are",
    7: "Integer values are",
    8: "Double values are",
    9: "String values are",
}


def register(subparsers: Any) -> None:
    """Add the ``param`` group and its verbs to the command line."""
    parser = subparsers.add_parser("param", help="list, get, set and dump node parameters")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)

    listing = add_verb(
        verbs, "list", list_parameters, help="list the parameters of one node, or of every node"
    )
    listing.add_argument("node", metavar="NODE", nargs="?")

    get = add_verb(verbs, "get", get_parameter, help="print a parameter's type and value")
    get.add_argument("node", metavar="NODE")
    get.add_argument("name", metavar="NAME")

    set_ = add_verb(
        verbs,
        "set",
        set_parameter,
        help="set a parameter (VALUE is YAML: earth, 41, 0.2, true, [1, 2])",
    )
    set_.add_argument("node", metavar="NODE")
    set_.add_argument("name", metavar="NAME")
    set_.add_argument("value", metavar="VALUE")

    dump = add_verb(
        verbs, "dump", dump_parameters, help="print a node's parameters as a parameters YAML file"
    )
    dump.add_argument("node", metavar="NODE")


def list_parameters(args: argparse.Namespace) -> None:
    """Print ``/node:`` then each parameter name indented, for NODE or every node."""
    with connect(args.graph) as conn:
        for node in _nodes(conn, args.node):
            print(f"{node}:")
            for name in _names(conn, node):
                print(f"  {name}")


def get_parameter(args: argparse.Namespace) -> None:
    """Print ``String value is: world`` and the like; ControlError when the parameter is not set."""
    from actors.params import value_from_msg

    with connect(args.graph) as conn:
        (node,) = _nodes(conn, args.node)
        (value,) = _call(conn, node, "get_parameters", names=[args.name]).values
    if value.type not in _LABELS:
        raise ControlError(f"parameter {args.name!r} is not set on {node}")
    print(f"{_LABELS[value.type]}: {value_from_msg(value)}")


def set_parameter(args: argparse.Namespace) -> int:
    """Set it; print ``Set parameter successful`` (exit 0) or why it failed (exit 1).

    VALUE is read as YAML, as ``ros2 param set`` does.  A value that is not
    YAML or that no parameter can hold is a ControlError (exit 2).
    """
    from actors.cli._format import parse_yaml
    from actors.params import value_to_msg
    from interfaces.rcl_interfaces.msg import Parameter

    value = parse_yaml(args.value, "parameter value")
    try:
        parameter = Parameter(name=args.name, value=value_to_msg(value))
    except (TypeError, ValueError) as exc:
        raise ControlError(f"cannot set {args.name}: {exc}") from None
    with connect(args.graph) as conn:
        (node,) = _nodes(conn, args.node)
        (result,) = _call(conn, node, "set_parameters", parameters=[parameter]).results
    if not result.successful:
        print(f"Setting parameter failed: {result.reason}")
        return 1
    print("Set parameter successful")
    return 0


def dump_parameters(args: argparse.Namespace) -> None:
    """Print ``/node:`` / ``ros__parameters:`` / ``name: value``: a parameters file."""
    from actors.cli._format import yaml_text
    from actors.params import value_from_msg

    with connect(args.graph) as conn:
        (node,) = _nodes(conn, args.node)
        names = _names(conn, node)
        values = _call(conn, node, "get_parameters", names=names).values
    parameters = {name: value_from_msg(value) for name, value in zip(names, values)}
    print(yaml_text({node: {"ros__parameters": parameters}}), end="")


def _nodes(conn: Connection, name: str | None) -> list[str]:
    """``[name]`` in full if the graph has it (else ControlError); every node when None."""
    from actors.names import expand

    nodes = sorted(node.name for node in conn.graph().nodes)
    if name is None:
        return nodes
    full = expand(name, "/", "_", what="node name")
    if full not in nodes:
        raise ControlError(f"unknown node {full}")
    return [full]


def _names(conn: Connection, node: str) -> list[str]:
    return list(_call(conn, node, "list_parameters").result.names)


def _call(conn: Connection, node: str, service: str, **fields: Any) -> Any:
    """Call ``<node>/<service>`` (``get_parameters``: ``rcl_interfaces/srv/GetParameters``...)."""
    from interfaces.rcl_interfaces import srv

    srv_type = getattr(srv, service.title().replace("_", ""))
    return call_service(conn, f"{node}/{service}", srv_type, srv_type.Request(**fields))
