"""``actors param list|get|describe|set|delete|load|dump``: node parameters, through each node's services.

Going through ``<node>/get_parameters`` and its siblings, as ``ros2 param``
does, means a set from the command line runs the node's on-set callbacks and
publishes the change on ``/parameter_events`` exactly as any client's would.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from actors.cli._client import add_verb, call_service, connect
from actors.core.explain import did_you_mean
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
    parser = subparsers.add_parser("param", help="list, get, describe, set, delete, load and dump node parameters")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)

    listing = add_verb(verbs, "list", list_parameters, help="list the parameters of one node, or of every node")
    listing.add_argument("node", metavar="NODE", nargs="?")
    listing.add_argument("--filter", metavar="REGEX", help="only the parameters whose names the regex matches")
    listing.add_argument(
        "--param-prefixes", nargs="+", default=[], metavar="PREFIX", help="only the parameters under these prefixes"
    )
    listing.add_argument("--param-type", action="store_true", help="print each parameter's type beside its name")

    get = add_verb(verbs, "get", get_parameter, help="print a parameter's type and value")
    get.add_argument("node", metavar="NODE")
    get.add_argument("name", metavar="NAME")
    get.add_argument("--hide-type", action="store_true", help="print the value alone")

    set_ = add_verb(
        verbs,
        "set",
        set_parameter,
        help="set a parameter (VALUE is YAML: earth, 41, 0.2, true, [1, 2])",
    )
    set_.add_argument("node", metavar="NODE")
    set_.add_argument("name", metavar="NAME")
    set_.add_argument("value", metavar="VALUE")

    describe = add_verb(verbs, "describe", describe_parameters, help="print parameters' types and constraints")
    describe.add_argument("node", metavar="NODE")
    describe.add_argument("names", metavar="NAME", nargs="+")

    delete = add_verb(verbs, "delete", delete_parameter, help="undeclare a parameter (a dynamically typed one)")
    delete.add_argument("node", metavar="NODE")
    delete.add_argument("name", metavar="NAME")

    load = add_verb(verbs, "load", load_parameters, help="set the parameters a ROS parameters YAML file gives NODE")
    load.add_argument("node", metavar="NODE")
    load.add_argument("file", metavar="FILE", help="/node: ros__parameters: ... as param dump writes")
    load.add_argument(
        "--no-use-wildcard",
        action="store_true",
        help="leave out the file's /** entry (the parameters for every node)",
    )

    dump = add_verb(verbs, "dump", dump_parameters, help="print a node's parameters as a parameters YAML file")
    dump.add_argument("node", metavar="NODE")


def list_parameters(args: argparse.Namespace) -> None:
    """Print each parameter name indented, for NODE, or under a ``/node:`` line for every node.

    As ``ros2 param list``: ``--filter`` keeps the names the regex matches (from
    their start), ``--param-prefixes`` those under the prefixes, and
    ``--param-type`` adds ``(type: double)``.  ControlError for a bad regex.
    """
    import re

    try:
        pattern = re.compile(args.filter) if args.filter is not None else None
    except re.error as exc:
        raise ControlError(f"--filter {args.filter!r} is not a regular expression: {exc}") from None
    with connect(args.graph) as conn:
        for node in _nodes(conn, args.node):
            names = [n for n in _names(conn, node, args.param_prefixes) if pattern is None or pattern.match(n)]
            if args.node is None and names:
                print(f"{node}:")
            types: dict[str, str] = {}
            if args.param_type and names:
                described = _call(conn, node, "describe_parameters", names=names).descriptors
                types = {d.name: _TYPE_NAMES.get(d.type, "not set") for d in described}
            for name in names:
                print(f"  {name} (type: {types[name]})" if args.param_type else f"  {name}")


def get_parameter(args: argparse.Namespace) -> None:
    """Print ``String value is: world`` and the like; ControlError when the parameter is not set."""
    from actors.ros.parameter_store import value_from_msg

    with connect(args.graph) as conn:
        (node,) = _nodes(conn, args.node)
        (value,) = _call(conn, node, "get_parameters", names=[args.name]).values
    if value.type not in _LABELS:
        raise ControlError(f"parameter {args.name!r} is not set on {node}")
    print(value_from_msg(value) if args.hide_type else f"{_LABELS[value.type]}: {value_from_msg(value)}")


def describe_parameters(args: argparse.Namespace) -> None:
    """Print each parameter's name, type, description and constraints, as ``ros2 param describe``.

    ControlError for a parameter the node has not declared.
    """
    with connect(args.graph) as conn:
        (node,) = _nodes(conn, args.node)
        declared = set(_names(conn, node))
        for name in args.names:
            if name not in declared:
                raise ControlError(f"parameter {name!r} is not declared on {node}")
        descriptors = _call(conn, node, "describe_parameters", names=args.names).descriptors
    for descriptor in descriptors:
        print(f"Parameter name: {descriptor.name}")
        print(f"  Type: {_TYPE_NAMES.get(descriptor.type, 'not set')}")
        if descriptor.description:
            print(f"  Description: {descriptor.description}")
        print("  Constraints:")
        if descriptor.read_only:
            print("    Read only: true")
        ranges = [*descriptor.floating_point_range, *descriptor.integer_range]
        if ranges:
            print(f"    Min value: {ranges[0].from_value}")
            print(f"    Max value: {ranges[0].to_value}")
            if ranges[0].step:
                print(f"    Step: {ranges[0].step}")
        if descriptor.additional_constraints:
            print(f"    Additional constraints: {descriptor.additional_constraints}")


# ``ros2 param describe``'s names of the types, by ParameterType number.
_TYPE_NAMES = {
    1: "boolean",
    2: "integer",
    3: "double",
    4: "string",
    5: "byte array",
    6: "boolean array",
    7: "integer array",
    8: "double array",
    9: "string array",
}


def set_parameter(args: argparse.Namespace) -> int:
    """Set it; print ``Set parameter successful`` (exit 0) or why it failed, on stderr (exit 1).

    VALUE is read as YAML, as ``ros2 param set`` does.  A value that is not
    YAML or that no parameter can hold is a ControlError (exit 2).
    """
    from actors.cli._format import parse_yaml

    parameter = _parameter(args.name, parse_yaml(args.value, "parameter value"))
    with connect(args.graph) as conn:
        (node,) = _nodes(conn, args.node)
        (result,) = _set(conn, node, [parameter])
    return _outcome(result, "Set parameter successful", "Setting parameter failed")


def delete_parameter(args: argparse.Namespace) -> int:
    """Undeclare it, as ``ros2 param delete`` does: set it to NOT_SET through ``set_parameters``.

    Prints ``Deleted parameter successfully`` (exit 0), or why not on stderr
    (exit 1): as in ROS, only a dynamically typed parameter can be deleted.
    """
    from interfaces.rcl_interfaces.msg import Parameter

    with connect(args.graph) as conn:
        (node,) = _nodes(conn, args.node)
        (result,) = _set(conn, node, [Parameter(name=args.name)])
    return _outcome(result, "Deleted parameter successfully", "Deleting parameter failed")


def load_parameters(args: argparse.Namespace) -> int:
    """Set what a ROS parameters file gives NODE, each on its own, as ``ros2 param load`` does.

    The file is what ``param dump`` writes (and ``--params-file`` reads):
    ``/node: ros__parameters: {name: value}``, nested names joined with
    ``.``, ``/**`` for every node (left out with ``--no-use-wildcard``),
    wildcards in node names.  Prints ``Set parameter NAME successful`` or
    ``... failed: why`` (on stderr) for each; exits 1 when one failed.
    RosArgsError (exit 2) for a file that is not one, ControlError when it
    has nothing for NODE.
    """
    from actors.launch.rosargs import load_params_file, node_key_matches

    rules = load_params_file(args.file)
    with connect(args.graph) as conn:
        (node,) = _nodes(conn, args.node)
        values: dict[str, Any] = {}
        for rule in rules:  # later entries win, as when a node starts with the file
            if node_key_matches(rule.node_key, node) and not (args.no_use_wildcard and rule.node_key == "/**"):
                values.update(rule.values)
        if not values:
            raise ControlError(f"{args.file} has no parameters for {node}")
        results = _set(conn, node, [_parameter(name, value) for name, value in values.items()])
    outcomes = [
        _outcome(result, f"Set parameter {name} successful", f"Set parameter {name} failed")
        for name, result in zip(values, results)
    ]
    return max(outcomes)


def _parameter(name: str, value: Any) -> Any:
    """``rcl_interfaces/msg/Parameter`` holding ``value``; ControlError if no parameter can."""
    from actors.ros.parameter_store import value_to_msg
    from interfaces.rcl_interfaces.msg import Parameter

    try:
        return Parameter(name=name, value=value_to_msg(value))
    except (TypeError, ValueError) as exc:
        raise ControlError(f"cannot set {name}: {exc}") from None


def _set(conn: Connection, node: str, parameters: list[Any]) -> list[Any]:
    """One result per parameter, each set on its own (``set_parameters``, not atomically)."""
    return list(_call(conn, node, "set_parameters", parameters=parameters).results)


def _outcome(result: Any, done: str, failed: str) -> int:
    """Print ``done`` (exit code 0) or ``failed: reason`` on stderr, as ros2 does (exit code 1)."""
    if result.successful:
        print(f"{done}: {result.reason}" if result.reason else done)
        return 0
    print(f"{failed}: {result.reason}" if result.reason else failed, file=sys.stderr)
    return 1


def dump_parameters(args: argparse.Namespace) -> None:
    """Print ``/node:`` / ``ros__parameters:`` / ``name: value``: a parameters file."""
    from actors.cli._format import yaml_text
    from actors.ros.parameter_store import value_from_msg

    with connect(args.graph) as conn:
        (node,) = _nodes(conn, args.node)
        names = _names(conn, node)
        values = _call(conn, node, "get_parameters", names=names).values
    parameters = {name: value_from_msg(value) for name, value in zip(names, values)}
    print(yaml_text({node: {"ros__parameters": parameters}}), end="")


def _nodes(conn: Connection, name: str | None) -> list[str]:
    """``[name]`` in full if the graph has it (else ControlError); every node when None."""
    from actors.ros.names import expand

    nodes = sorted(node.name for node in conn.graph().nodes)
    if name is None:
        return nodes
    full = expand(name, "/", "_", what="node name")
    if full not in nodes:
        raise ControlError(f"unknown node {full}{did_you_mean(full, nodes)}")
    return [full]


def _names(conn: Connection, node: str, prefixes: Sequence[str] = ()) -> list[str]:
    # The node answers in declaration order.
    return sorted(_call(conn, node, "list_parameters", prefixes=list(prefixes)).result.names)


def _call(conn: Connection, node: str, service: str, **fields: Any) -> Any:
    """Call ``<node>/<service>`` (``get_parameters``: ``rcl_interfaces/srv/GetParameters``...)."""
    from interfaces.rcl_interfaces import srv

    srv_type = getattr(srv, service.title().replace("_", ""))
    return call_service(conn, f"{node}/{service}", srv_type, srv_type.Request(**fields))
