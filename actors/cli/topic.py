"""``actors topic list|info|echo|pub|hz``: a running graph's topics, shown as ``ros2 topic``."""

from __future__ import annotations

import argparse
from typing import Any

from actors.cli._client import add_verb, connect, graph_snapshot, print_names

__all__ = ["register"]


def register(subparsers: Any) -> None:
    """Add the ``topic`` group and its verbs to the command line."""
    parser = subparsers.add_parser("topic", help="list, inspect, echo, publish and time topics")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)

    listing = add_verb(verbs, "list", list_topics, help="list the graph's topics")
    listing.add_argument(
        "-t", "--show-types", action="store_true", help="also show each topic's type"
    )
    listing.add_argument(
        "--include-hidden-topics", action="store_true", help="also list hidden topics (an action's)"
    )

    info = add_verb(
        verbs, "info", topic_info, help="a topic's type and its publishers and subscriptions"
    )
    info.add_argument("topic", metavar="TOPIC")
    info.add_argument(
        "-v", "--verbose", action="store_true", help="each endpoint: node, QoS, queue, drops"
    )

    echo = add_verb(verbs, "echo", echo_topic, help="print a topic's messages as YAML documents")
    echo.add_argument("topic", metavar="TOPIC")
    echo.add_argument("--once", action="store_true", help="print one message, then exit")
    echo.add_argument("--field", metavar="A.B", help="print only this field of each message")

    pub = add_verb(verbs, "pub", publish, help="publish a message, once or at a rate")
    pub.add_argument("topic", metavar="TOPIC")
    pub.add_argument(
        "type", metavar="TYPE", help="e.g. std_msgs/msg/Bool (must match an existing topic)"
    )
    pub.add_argument(
        "values",
        metavar="VALUES",
        nargs="?",
        default="{}",
        help='field values in YAML, e.g. "data: true" (default: all defaults)',
    )
    pub.add_argument(
        "-r", "--rate", type=_positive, default=1.0, help="publishing rate in Hz (default 1)"
    )
    pub.add_argument("-1", "--once", action="store_true", help="publish one message, then exit")
    pub.add_argument(
        "-t", "--times", type=int, default=0, help="publish this many messages, then exit"
    )

    hz = add_verb(verbs, "hz", topic_hz, help="print a topic's average rate every second")
    hz.add_argument("topic", metavar="TOPIC")
    hz.add_argument(
        "-w", "--window", type=int, default=10000, help="intervals averaged (default 10000)"
    )
    hz.add_argument(
        "--count",
        type=int,
        default=0,
        metavar="N",
        help="exit after N reports (default: run until interrupted)",
    )


def _positive(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    if value <= 0:
        raise argparse.ArgumentTypeError(f"must be > 0, got {value}")
    return value


def list_topics(args: argparse.Namespace) -> None:
    """Print each topic's name, with ``[type]`` under ``-t``; hidden ones only when asked."""
    from actors.names import is_hidden_name

    topics = graph_snapshot(args).topics
    print_names([t for t in topics if args.include_hidden_topics or not is_hidden_name(t.name)], args.show_types)


def topic_info(args: argparse.Namespace) -> None:
    """Print the type and endpoint counts (with ``-v``, each endpoint); ControlError if unknown."""
    from actors.errors import ControlError
    from actors.names import expand

    name = expand(args.topic, "/", "_")
    topic = next((t for t in graph_snapshot(args).topics if t.name == name), None)
    if topic is None:
        raise ControlError(f"unknown topic {name}")
    sections = (
        ("Publisher", "PUBLISHER", topic.publishers),
        ("Subscription", "SUBSCRIPTION", topic.subscriptions),
    )
    print(f"Type: {topic.type}")
    for title, kind, endpoints in sections:
        if args.verbose:
            print()
        print(f"{title} count: {len(endpoints)}")
        for endpoint in endpoints if args.verbose else ():
            namespace, _, node = endpoint.node.rpartition("/")
            qos = endpoint.qos
            print()
            print(f"Node name: {node}")
            print(f"Node namespace: {namespace or '/'}")
            print(f"Topic type: {endpoint.type}")
            print(f"Endpoint type: {kind}")
            print("QoS profile:")
            print(f"  Reliability: {qos.reliability.name}")
            print(f"  History (Depth): {qos.history.name} ({qos.depth})")
            print(f"  Durability: {qos.durability.name}")
            if kind == "SUBSCRIPTION":
                print(f"Queued: {endpoint.queued}")
                print(f"Dropped: {endpoint.dropped}")


def echo_topic(args: argparse.Namespace) -> None:
    """Print each message as a YAML document followed by ``---``, until interrupted (or once)."""
    from actors import codec
    from actors.cli._format import field, yaml_text
    from actors.control import Subscribe

    with connect(args.graph) as conn:
        msg_type = codec.get_type(conn.request(Subscribe(topic=args.topic))["type"])
        while True:
            sample = conn.sample()
            assert sample is not None  # no timeout: waits for the next one
            msg = codec.convert(sample.msg, msg_type)
            print(yaml_text(field(msg, args.field) if args.field else msg), end="")
            print("---", flush=True)
            if args.once:
                return


def publish(args: argparse.Namespace) -> None:
    """Publish ``VALUES`` as ``TYPE`` on ``TOPIC`` at ``--rate``, ``--times`` times (or forever).

    Prints ``publisher: beginning loop`` and then ``publishing #N: <repr>`` for
    each message, as ``ros2 topic pub`` does.  Raises UnknownInterfaceError or
    MessageValidationError (exit 2) before connecting for a bad type or value.
    """
    import time

    from actors import codec
    from actors.cli._format import ros_repr
    from actors.control import Publish

    msg_type = codec.get_type(args.type)
    msg = codec.from_yaml(args.values, msg_type)
    times = 1 if args.once else args.times
    request = Publish(topic=args.topic, type=codec.ros_name(msg_type), msg=codec.to_builtins(msg))
    period = 1.0 / args.rate
    with connect(args.graph) as conn:
        print("publisher: beginning loop")
        start = time.monotonic()  # the command's own pace, on the wall clock, as ros2's
        count = 0
        while True:
            conn.request(request)
            count += 1
            print(f"publishing #{count}: {ros_repr(msg)}\n", flush=True)
            if count == times:
                return
            time.sleep(max(0.0, start + count * period - time.monotonic()))


def topic_hz(args: argparse.Namespace) -> None:
    """Every second of wall time, print the average rate over the last ``--window`` intervals.

    Intervals are measured between the graph's receive stamps (its runtime
    clock), so the rate is right under virtual time too.  Prints nothing for a
    second without new messages.  ``--count N`` exits after N reports.
    """
    import math
    import time
    from collections import deque

    from actors.control import Subscribe

    intervals: deque[float] = deque(maxlen=max(1, args.window))
    with connect(args.graph) as conn:
        conn.request(Subscribe(topic=args.topic, content=False))
        last: float | None = None
        fresh = False
        reports = 0
        next_report = time.monotonic() + 1.0
        while True:
            sample = conn.sample(timeout=max(0.0, next_report - time.monotonic()))
            if sample is not None:
                if last is not None:
                    intervals.append(sample.stamp - last)
                    fresh = True
                last = sample.stamp
            if time.monotonic() < next_report:
                continue
            next_report += 1.0
            if not fresh:
                continue
            fresh = False
            n = len(intervals)
            mean = sum(intervals) / n
            std = math.sqrt(sum((x - mean) ** 2 for x in intervals) / n)
            print(f"average rate: {1.0 / mean if mean > 0 else 0.0:.3f}")
            print(
                f"\tmin: {min(intervals):.3f}s max: {max(intervals):.3f}s "
                f"std dev: {std:.5f}s window: {n + 1}",
                flush=True,
            )
            reports += 1
            if reports == args.count:
                return
