"""``actors action list|info|type|find|send_goal``: a running graph's actions, as ``ros2 action`` shows them.

Actions are read off the graph's topics and services (see
:mod:`actors.system.introspection`).  ``send_goal`` drives an action through the
control endpoint's ordinary operations: it subscribes to the feedback topic
(with ``--feedback``) and calls the action's ``send_goal`` and ``get_result``
services, as any ROS client does on the wire.
"""

from __future__ import annotations

import argparse
import sys
import threading
import uuid
from typing import Any

from actors.cli._client import (
    Connection,
    add_verb,
    call_service,
    connect,
    graph_snapshot,
    print_matching,
    type_of,
)
from actors.core.signals import raise_stops, remember_stops, take_noted

__all__ = ["register"]

_WAIT = 1e9  # seconds: as ros2 action send_goal, wait for the result however long the goal takes


def register(subparsers: Any) -> None:
    """Add the ``action`` group and its verbs to the command line."""
    parser = subparsers.add_parser("action", help="list actions, show their types, send goals")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)

    listing = add_verb(verbs, "list", list_actions, help="list the graph's actions")
    listing.add_argument("-t", "--show-types", action="store_true", help="also show each action's type")
    listing.add_argument("-c", "--count-actions", action="store_true", help="only print how many there are")

    info = add_verb(verbs, "info", action_info, help="an action's clients and servers")
    info.add_argument("action", metavar="NAME", help="e.g. /fibonacci")
    info.add_argument("-t", "--show-types", action="store_true", help="also show the action's type")
    info.add_argument("-c", "--count", action="store_true", help="only print how many clients and servers")

    type_ = add_verb(verbs, "type", action_type, help="print an action's type")
    type_.add_argument("action", metavar="NAME")

    find = add_verb(verbs, "find", find_actions, help="list the actions of a type")
    find.add_argument("type", metavar="TYPE", help="e.g. example_interfaces/action/Fibonacci")
    find.add_argument("-c", "--count-actions", action="store_true", help="only print how many there are")

    send = add_verb(verbs, "send_goal", send_goal, help="send a goal and print its result")
    send.add_argument("action", metavar="NAME", help="e.g. /fibonacci")
    send.add_argument("type", metavar="TYPE", help="e.g. example_interfaces/action/Fibonacci")
    send.add_argument("goal", metavar="GOAL", nargs="?", default="{}", help='goal fields in YAML, e.g. "{order: 5}"')
    send.add_argument("-f", "--feedback", action="store_true", help="print the goal's feedback messages")


def _actions(args: argparse.Namespace) -> list[Any]:
    from actors.system.introspection import action_infos

    return action_infos(graph_snapshot(args).topics)


def _expand(name: str) -> str:
    from actors.ros.names import expand

    return expand(name, "/", "_", what="action name")


def list_actions(args: argparse.Namespace) -> None:
    """Print each action's name, with ``[type]`` under ``-t``; only the count under ``-c``."""
    actions = _actions(args)
    if args.count_actions:
        print(len(actions))
        return
    for action in actions:
        print(f"{action.name} [{action.type}]" if args.show_types else action.name)


def action_info(args: argparse.Namespace) -> None:
    """Print the action's clients and servers as ``ros2 action info`` does (an unknown one has none)."""
    name = _expand(args.action)
    found = next((a for a in _actions(args) if a.name == name), None)
    print(f"Action: {args.action}")
    for title, nodes in (("clients", found.clients if found else ()), ("servers", found.servers if found else ())):
        print(f"Action {title}: {len(nodes)}")
        if not args.count:
            for node in nodes:
                print(f"    {node} [{found.type}]" if args.show_types and found else f"    {node}")


def action_type(args: argparse.Namespace) -> None:
    """Print the action's type; ControlError for an unknown action."""
    print(type_of(_actions(args), args.action, "action"))


def find_actions(args: argparse.Namespace) -> None:
    """Print the name of every action of ``TYPE`` (or their count under ``-c``)."""
    print_matching(_actions(args), args.type, args.count_actions)


def send_goal(args: argparse.Namespace) -> int:
    """Send a goal, print its acceptance, feedback (``-f``), result and final status, as ``ros2 action``.

    Raises (exit 2) for an unknown type or a bad goal before connecting, and
    for an unknown action or one of another type after.  Interrupted while the
    goal runs, it asks the server to cancel the goal first.
    """
    from actors import codec
    from actors.cli._format import yaml_text
    from actors.errors import UnknownInterfaceError
    from actors.ros.actions import status_name, wire_names
    from interfaces.unique_identifier_msgs.msg import UUID

    action = codec.get_type(args.type)
    if not hasattr(action, "Goal"):
        raise UnknownInterfaceError(f"{args.type} is not an action type")
    goal = codec.from_yaml(args.goal, action.Goal)
    name = _expand(args.action)
    names = wire_names(name)
    impl = action.Impl
    with connect(args.graph) as conn:
        print("Waiting for an action server to become available...", flush=True)
        _check_server(conn, name, codec.ros_name(action))
        feed = _follow(conn.name, names["feedback"]) if args.feedback else None
        try:
            print(f"Sending goal:\n     {yaml_text(goal)}", flush=True)
            goal_id = UUID(uuid=uuid.uuid4().bytes)
            request = impl.SendGoalService.Request(goal_id=goal_id, goal=goal)
            accepted = call_service(conn, names["send_goal"], impl.SendGoalService, request, timeout=_WAIT)
            if not accepted.accepted:
                print("Goal was rejected.")
                return 0
            print(f"Goal accepted with ID: {bytes(goal_id.uuid).hex()}\n", flush=True)
            ask = impl.GetResultService.Request(goal_id=goal_id)
            try:
                response = _result(conn, names["get_result"], impl, ask, feed, goal_id)
            except KeyboardInterrupt:
                _cancel(conn.name, names["cancel_goal"], impl, goal_id)
                return 0
        finally:
            if feed is not None:
                feed.close()
    print(f"Result:\n    {yaml_text(response.result)}")
    print(f"Goal finished with status: {status_name(response.status)}")
    return 0


def _check_server(conn: Connection, name: str, type_: str) -> None:
    from actors.errors import ControlError
    from actors.system.introspection import action_infos

    found = next((a for a in action_infos(conn.graph().topics) if a.name == name), None)
    if found is None or not found.servers:
        raise ControlError(f"unknown action {name} (no server runs it)")
    if found.type != type_:
        raise ControlError(f"action {name} has type {found.type}, not {type_}")


def _follow(graph: str, topic: str) -> Connection:
    """A second connection streaming the feedback topic (replies and samples never share one)."""
    from actors.ops.control import Subscribe

    feed = connect(graph)
    feed.request(Subscribe(topic=topic, depth=1000))
    return feed


def _result(conn: Connection, service: str, impl: Any, ask: Any, feed: Connection | None, goal_id: Any) -> Any:
    """The get_result response; meanwhile print the goal's feedback from ``feed``."""
    if feed is None:
        return call_service(conn, service, impl.GetResultService, ask, timeout=_WAIT)
    outcome: dict[str, Any] = {}

    def wait() -> None:
        try:
            outcome["response"] = call_service(conn, service, impl.GetResultService, ask, timeout=_WAIT)
        except BaseException as exc:  # handed to the main thread, which raises it
            outcome["error"] = exc

    waiter = threading.Thread(target=wait, daemon=True)
    waiter.start()
    while waiter.is_alive():
        _print_feedback(feed, 0.05, goal_id, impl)
    # Feedback sent before the result may still be on its way: what arrives promptly is shown.
    while _print_feedback(feed, 0.2, goal_id, impl):
        pass
    if "error" in outcome:
        raise outcome["error"]
    return outcome["response"]


def _print_feedback(feed: Connection, timeout: float, goal_id: Any, impl: Any) -> bool:
    """Print one feedback message of this goal if one comes within ``timeout``; whether one came."""
    from actors import codec
    from actors.cli._format import yaml_text

    sample = feed.sample(timeout=timeout)
    if sample is None:
        return False
    message = codec.convert(sample.msg, impl.FeedbackMessage)
    if bytes(message.goal_id.uuid) == bytes(goal_id.uuid):
        print(f"Feedback:\n    {yaml_text(message.feedback)}", flush=True)
    return True


def _cancel(graph: str, service: str, impl: Any, goal_id: Any) -> None:
    """Ask to cancel the goal, on a fresh connection (the first one waits for the result)."""
    from interfaces.action_msgs.msg import GoalInfo

    # A second Ctrl-C (or SIGTERM) must not leave the goal running on the server: the cancel is
    # asked and answered first (call_service's timeout bounds it), and further stops are dropped.
    remember_stops()
    print("Canceling goal...", flush=True)
    try:
        with connect(graph) as conn:
            request = impl.CancelGoalService.Request(goal_info=GoalInfo(goal_id=goal_id))
            response = call_service(conn, service, impl.CancelGoalService, request)
    finally:
        take_noted()
        raise_stops()
    if response.goals_canceling:
        print("Goal canceled.")
    else:
        print("Failed to cancel goal", file=sys.stderr)
