"""``actors topic list|info|type|find|echo|pub|hz|delay|bw``: a running graph's topics, as ``ros2 topic``."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Sequence
from types import CodeType
from typing import TYPE_CHECKING, Any

from actors.cli._client import add_type_and_find, add_verb, connect, graph_snapshot, print_names
from actors.errors import ControlError

if TYPE_CHECKING:
    from actors.cli._client import Connection
    from actors.ops.control import Sample

__all__ = ["register"]


def register(subparsers: Any) -> None:
    """Add the ``topic`` group and its verbs to the command line."""
    parser = subparsers.add_parser("topic", help="list, inspect, echo, publish and time topics")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)

    listing = add_verb(verbs, "list", list_topics, help="list the graph's topics")
    listing.add_argument("-t", "--show-types", action="store_true", help="also show each topic's type")
    listing.add_argument("--include-hidden-topics", action="store_true", help="also list hidden topics (an action's)")
    listing.add_argument("-c", "--count-topics", action="store_true", help="only print how many topics there are")
    listing.add_argument(
        "-v", "--verbose", action="store_true", help="the published, then the subscribed topics, with their counts"
    )

    info = add_verb(verbs, "info", topic_info, help="a topic's type and its publishers and subscriptions")
    info.add_argument("topic", metavar="TOPIC")
    info.add_argument("-v", "--verbose", action="store_true", help="each endpoint: node, QoS, queue, drops")

    add_type_and_find(verbs, "topic", "std_msgs/msg/String", lambda graph: graph.topics)

    echo = add_verb(verbs, "echo", echo_topic, help="print a topic's messages as YAML documents")
    echo.add_argument("topic", metavar="TOPIC")
    echo.add_argument(
        "type",
        metavar="TYPE",
        nargs="?",
        help="the message type, e.g. std_msgs/msg/String: then the topic may appear later",
    )
    echo.add_argument("--once", action="store_true", help="print one message, then exit")
    echo.add_argument("--field", metavar="A.B", help="print only this field of each message")
    echo.add_argument("--no-arr", action="store_true", help="print each array field's type and length instead")
    echo.add_argument("--no-str", action="store_true", help="print each string field's length instead")
    echo.add_argument(
        "-l",
        "--truncate-length",
        type=_count,
        default=TRUNCATE_LENGTH,
        metavar="N",
        help=f"cut arrays and strings after N elements, with '...' (default {TRUNCATE_LENGTH})",
    )
    echo.add_argument("-f", "--full-length", action="store_true", help="print arrays and strings whole")
    echo.add_argument("--flow-style", action="store_true", help="print collections in YAML's flow style")
    echo.add_argument("--csv", action="store_true", help="print each message's fields on one line, comma-separated")
    echo.add_argument("--raw", action="store_true", help="print each message's serialized bytes (CDR)")
    echo.add_argument(
        "--filter",
        dest="filter_expr",
        type=_expression,
        metavar="EXPR",
        help="print only the messages m for which this Python expression is true, e.g. 'm.data > 2'",
    )
    echo.add_argument("--timeout", type=_positive, metavar="N", help="stop after N seconds")
    _add_qos_arguments(echo, "subscribe", "sensor_data")

    pub = add_verb(verbs, "pub", publish, help="publish a message, once or at a rate")
    pub.add_argument("topic", metavar="TOPIC")
    pub.add_argument("type", metavar="TYPE", help="e.g. std_msgs/msg/Bool (must match an existing topic)")
    given = pub.add_mutually_exclusive_group()
    given.add_argument(
        "values",
        metavar="VALUES",
        nargs="?",
        default="{}",
        help='field values in YAML, e.g. "data: true" (default: all defaults); a header "auto" '
        'and a time "now" are stamped as each message goes',
    )
    given.add_argument("--stdin", action="store_true", help="read the values from standard input")
    pub.add_argument("-r", "--rate", type=_positive, default=1.0, help="publishing rate in Hz (default 1)")
    pub.add_argument("-p", "--print", type=int, default=1, metavar="N", help="print only every N-th message (0: none)")
    pub.add_argument(
        "-w",
        "--wait-matching-subscriptions",
        type=_count,
        metavar="N",
        help="first wait for N subscriptions (default: 1 with --once or --times, else 0)",
    )
    pub.add_argument(
        "--max-wait-time-secs", type=_positive, metavar="S", help="give up waiting for subscriptions after S seconds"
    )
    pub.add_argument(
        "--keep-alive", type=_positive, default=0.1, metavar="S", help="stay S seconds after the last message (0.1)"
    )
    _add_qos_arguments(pub, "publish", "default")
    pub.add_argument("-1", "--once", action="store_true", help="publish one message, then exit")
    pub.add_argument("-t", "--times", type=int, default=0, help="publish this many messages, then exit")

    hz = add_verb(verbs, "hz", topic_hz, help="print a topic's average rate every second")
    hz.add_argument("topic", metavar="TOPIC")
    hz.add_argument("-w", "--window", type=int, default=10000, help="intervals averaged (default 10000)")
    delay = add_verb(verbs, "delay", topic_delay, help="print the delay from a topic's header stamps every second")
    delay.add_argument("topic", metavar="TOPIC")
    delay.add_argument("-w", "--window", type=int, default=10000, help="messages averaged (default 10000)")
    bw = add_verb(verbs, "bw", topic_bw, help="print a topic's bandwidth every second")
    bw.add_argument("topic", metavar="TOPIC")
    bw.add_argument("-w", "--window", type=int, default=100, help="messages averaged (default 100)")
    for timed in (hz, delay, bw):
        timed.add_argument(
            "--count",
            type=int,
            default=0,
            metavar="N",
            help="exit after N reports (default: run until interrupted)",
        )


TRUNCATE_LENGTH = 128  # ros2 topic echo's default
_TIME = "builtin_interfaces/msg/Time"


def _add_qos_arguments(parser: argparse.ArgumentParser, doing: str, preset: str) -> None:
    """ros2's ``--qos-*`` options: a preset, and policies in its place."""
    from actors.ros.qos import DurabilityPolicy, HistoryPolicy, LivelinessPolicy, QoSPresetProfiles, ReliabilityPolicy

    parser.add_argument(
        "--qos-profile", choices=QoSPresetProfiles.short_keys(), help=f"the preset to {doing} with (default {preset})"
    )
    parser.add_argument("--qos-depth", type=int, metavar="N", help="the queue's depth, in place of the preset's")
    for policy, cls in (
        ("history", HistoryPolicy),
        ("reliability", ReliabilityPolicy),
        ("durability", DurabilityPolicy),
        ("liveliness", LivelinessPolicy),
    ):
        parser.add_argument(f"--qos-{policy}", choices=cls.short_keys(), help=f"the {policy}, in place of the preset's")
    parser.add_argument(
        "--qos-liveliness-lease-duration-seconds", type=float, metavar="S", help="the liveliness lease, in seconds"
    )
    parser.set_defaults(qos_preset=preset)


def _qos_choice(args: argparse.Namespace) -> Any:
    """The ``QoSChoice`` the ``--qos-*`` options make; None when none is given (the graph chooses)."""
    from actors.ops.control import QoSChoice

    given = {
        "depth": args.qos_depth,
        "history": args.qos_history,
        "reliability": args.qos_reliability,
        "durability": args.qos_durability,
        "liveliness": args.qos_liveliness,
        "lease_seconds": args.qos_liveliness_lease_duration_seconds,
    }
    if args.qos_profile is None and all(value is None for value in given.values()):
        return None
    return QoSChoice(profile=args.qos_profile or args.qos_preset, **given)


def _count(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a whole number: {text!r}") from None
    if value < 0:
        raise argparse.ArgumentTypeError(f"must be >= 0, got {value}")
    return value


def _expression(text: str) -> CodeType:
    try:
        return compile(text, "--filter", "eval")
    except SyntaxError as exc:
        raise argparse.ArgumentTypeError(f"not a Python expression: {text!r} ({exc.msg})") from None


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
    from actors.ros.names import is_hidden_name

    topics = [t for t in graph_snapshot(args).topics if args.include_hidden_topics or not is_hidden_name(t.name)]
    if args.verbose and not args.count_topics:
        for title, kind, ends in (
            ("Published", "publisher", "publishers"),
            ("Subscribed", "subscriber", "subscriptions"),
        ):
            print(f"{title} topics:")
            for topic in topics:
                if n := len(getattr(topic, ends)):
                    print(f" * {topic.name} [{topic.type}] {n} {kind}{'s' if n > 1 else ''}")
            print()
        return
    print_names(topics, args.show_types, args.count_topics)


def topic_info(args: argparse.Namespace) -> None:
    """Print the type and endpoint counts (with ``-v``, each endpoint); ControlError if unknown."""
    from actors.core.explain import did_you_mean
    from actors.ros.endpoint_info import TopicEndpointInfo, TopicEndpointTypeEnum, reported_profile
    from actors.ros.names import expand

    name = expand(args.topic, "/", "_")
    topics = graph_snapshot(args).topics
    topic = next((t for t in topics if t.name == name), None)
    if topic is None:
        raise ControlError(f"unknown topic {name}{did_you_mean(name, [t.name for t in topics])}")
    sections = (
        ("Publisher", TopicEndpointTypeEnum.PUBLISHER, topic.publishers),
        ("Subscription", TopicEndpointTypeEnum.SUBSCRIPTION, topic.subscriptions),
    )
    end = "\n\n" if args.verbose else "\n"  # as ros2 spaces its lines
    print(f"Type: {topic.type}", end=end)
    for title, kind, endpoints in sections:
        print(f"{title} count: {len(endpoints)}", end=end)
        for endpoint in endpoints if args.verbose else ():
            namespace, _, node = endpoint.node.rpartition("/")
            info = TopicEndpointInfo(
                node_name=node,
                node_namespace=namespace or "/",
                topic_type=endpoint.type,
                topic_type_hash=endpoint.type_hash or _type_hash(endpoint.type),
                endpoint_type=kind,
                endpoint_gid=endpoint.gid,
                qos_profile=reported_profile(endpoint.qos),
            )
            counts = f"\nQueued: {endpoint.queued}\nDropped: {endpoint.dropped}" if kind.name == "SUBSCRIPTION" else ""
            print(f"{info}{counts}", end=end)


def _type_hash(name: str) -> str:
    from actors import codec
    from actors.errors import ActorsError

    try:
        return codec.type_hash(codec.get_type(name))
    except ActorsError:
        return ""  # a type this process does not know: ros2 prints INVALID then too


def echo_topic(args: argparse.Namespace) -> None:
    """Print each message as a YAML document followed by ``---``, until interrupted (or once).

    With ``TYPE`` the topic need not exist yet: the command waits for its
    first message, as ``ros2 topic echo TOPIC TYPE`` does.  ``--no-arr`` and
    ``--no-str`` print ros2's summaries (``<sequence type: float, length:
    360>``, ``<string length: <5>>``) in place of arrays and strings; arrays
    and strings are cut after ``--truncate-length`` elements unless
    ``--full-length``; ``--csv`` prints one line per message, ``--raw`` its
    serialized bytes.  ``--filter`` is evaluated with ``m`` the message (or
    its ``--field``), as ros2 evaluates it; ``--timeout`` ends the command
    after so many seconds, messages or not.
    """
    import time

    from actors import codec
    from actors.cli._format import csv_text, field, yaml_text
    from actors.ops.control import Subscribe

    if args.raw and args.field:
        raise ControlError("--raw prints whole messages: leave out --field")
    truncate = None if args.full_length else args.truncate_length
    asked = codec.ros_name(codec.get_type(args.type)) if args.type else ""
    with connect(args.graph) as conn:
        request = Subscribe(topic=args.topic, type=asked, qos=_qos_choice(args))
        msg_type = codec.get_type(conn.request(request)["type"])
        # From the subscription on, as ros2's timer starts once its node is up.
        deadline = None if args.timeout is None else time.monotonic() + args.timeout
        while True:
            sample = conn.sample(None if deadline is None else max(0.0, deadline - time.monotonic()))
            if sample is None:
                return  # --timeout: the time to wait is over
            msg = codec.convert(sample.msg, msg_type)
            shown = field(msg, args.field) if args.field else msg
            if args.filter_expr is not None and not _passes(args.filter_expr, shown):
                continue
            if args.raw:
                print(codec.encode_cdr(msg), end="\n---\n", flush=True)
            elif args.csv:
                print(csv_text(shown, no_arr=args.no_arr, no_str=args.no_str, truncate_length=truncate), flush=True)
            else:
                text = yaml_text(
                    shown, no_arr=args.no_arr, no_str=args.no_str, truncate_length=truncate, flow_style=args.flow_style
                )
                print(text, end="---\n", flush=True)
            if args.once:
                return


def _passes(expression: CodeType, m: Any) -> bool:
    """Whether ``--filter``'s expression holds for ``m``; ControlError naming what it raised."""
    try:
        return bool(eval(expression, {"m": m}))  # the user's own expression, as ros2 runs it
    except Exception as exc:
        raise ControlError(f"--filter: {type(exc).__name__}: {exc}") from None


def publish(args: argparse.Namespace) -> int:
    """Publish ``VALUES`` as ``TYPE`` on ``TOPIC`` at ``--rate``, ``--times`` times (or forever).

    Prints ``publisher: beginning loop`` and then ``publishing #N: <repr>`` for
    every ``--print``-th message, as ``ros2 topic pub`` does; with ``--once``
    or ``--times`` it first waits for a subscription (``-w N``: for N), and
    gives up after ``--max-wait-time-secs`` with ros2's words and exit code 1.
    Raises UnknownInterfaceError or MessageValidationError (exit 2) before
    connecting for a bad type or value.
    """
    import time

    from actors import codec
    from actors.cli._format import ros_repr
    from actors.ops.control import Publish, set_at

    msg_type = codec.get_type(args.type)
    text = sys.stdin.read() if args.stdin else args.values
    msg, stamps = _message(text, msg_type)
    times = 1 if args.once else args.times
    wanted = int(times != 0) if args.wait_matching_subscriptions is None else args.wait_matching_subscriptions
    if args.max_wait_time_secs is not None and not wanted:
        raise ControlError("--max-wait-time-secs works with --wait-matching-subscriptions, --once or --times")
    fields = {
        "topic": args.topic,
        "type": codec.ros_name(msg_type),
        "msg": codec.to_builtins(msg),
        "qos": _qos_choice(args),
    }
    request = Publish(**fields, stamps=stamps)
    period = 1.0 / args.rate
    with connect(args.graph) as conn:
        # The graph refuses a topic of another type here, before anything is printed.
        reached = conn.request(Publish(**fields, count_only=True))["subscribers"]
        looks = 0  # ros2's pace: a look every 100 ms, a line every second
        while reached < wanted:
            if looks % 10 == 0:
                print(f"Waiting for at least {wanted} matching subscription(s)...", flush=True)
            if args.max_wait_time_secs is not None and looks / 10 >= args.max_wait_time_secs:
                print(
                    f"Timed out waiting for subscribers: Expected {wanted} subcribers but only got "
                    f"{reached} subscribers",  # ros2's words, its typo too: scripts match them
                    file=sys.stderr,
                )
                return 1
            time.sleep(0.1)
            looks += 1
            reached = conn.request(Publish(**fields, count_only=True))["subscribers"]
        print("publisher: beginning loop")
        start = time.monotonic()  # the command's own pace, on the wall clock, as ros2's
        count = 0
        while True:
            stamp = conn.request(request).get("stamp")
            count += 1
            for path in stamps if stamp is not None else ():  # as the graph stamped it, for the line printed
                set_at(msg, path, codec.convert(stamp, _TIME))
            if args.print and count % args.print == 0:
                print(f"publishing #{count}: {ros_repr(msg)}\n", flush=True)
            if count == times:
                break
            time.sleep(max(0.0, start + count * period - time.monotonic()))
        # The publisher lives as long as the connection: as ros2's node lingers, for the last message
        # to reach the wire and a transient-local one to reach late subscribers.
        time.sleep(args.keep_alive)
    return 0


def _message(text: str, msg_type: type) -> tuple[Any, list[list[str | int]]]:
    """The message ``text`` (YAML) gives, and the paths of the times to stamp as it is published:
    a ``std_msgs/Header`` given as ``auto`` and a ``builtin_interfaces/Time`` given as ``now``."""
    from actors import codec
    from actors.messages._fields import MessageLayout, layout

    try:
        data = codec.load_yaml(text)
    except ValueError:
        data = None
    if not isinstance(data, dict):
        return codec.from_yaml(text, msg_type), []  # which says what is wrong with the text
    stamps: list[list[str | int]] = []

    def walk(values: dict[str, Any], message: MessageLayout, path: list[str | int]) -> None:
        for field in message.fields:
            value, nested = values.get(field.name), field.nested
            if nested is None or value is None:
                continue
            if field.type.array:
                for i, item in enumerate(value if isinstance(value, list) else []):
                    if isinstance(item, dict):
                        walk(item, nested, [*path, field.name, i])
            elif value == "auto" and nested.ros_type == "std_msgs/msg/Header":
                values[field.name] = {}
                stamps.append([*path, field.name, "stamp"])
            elif value == "now" and nested.ros_type == "builtin_interfaces/msg/Time":
                values[field.name] = {}
                stamps.append([*path, field.name])
            elif isinstance(value, dict):
                walk(value, nested, [*path, field.name])

    walk(data, layout(msg_type), [])
    return codec.convert(data, msg_type), stamps


def topic_hz(args: argparse.Namespace) -> None:
    """Every second of wall time, print the average rate over the last ``--window`` intervals.

    Intervals are measured between the graph's receive stamps (its runtime
    clock), so the rate is right under virtual time too.  Prints nothing for a
    second without new messages.  ``--count N`` exits after N reports.
    """
    from collections import deque

    from actors.ops.control import Subscribe

    intervals: deque[float] = deque(maxlen=max(1, args.window))
    last: float | None = None
    fresh = False

    def take(sample: Sample) -> None:
        nonlocal last, fresh
        if last is not None:
            intervals.append(sample.stamp - last)
            fresh = True
        last = sample.stamp

    def report() -> bool:
        nonlocal fresh
        if not fresh:
            return False
        fresh = False
        mean = sum(intervals) / len(intervals)
        _print_spread(f"average rate: {1.0 / mean if mean > 0 else 0.0:.3f}", intervals, len(intervals) + 1)
        return True

    with connect(args.graph) as conn:
        conn.request(Subscribe(topic=args.topic, content=False))
        _each_second(conn, take, report, args.count)


def topic_delay(args: argparse.Namespace) -> None:
    """Every second of wall time, print the average delay of the last ``--window`` messages: when the
    graph received each (its ROS time) less its header's stamp, as ``ros2 topic delay`` does (which
    also leaves out the first message).  ControlError for a type without a header."""
    from collections import deque

    from actors import codec
    from actors.ops.control import Subscribe

    delays: deque[float] = deque(maxlen=max(1, args.window))
    first = True
    fresh = False

    def take(sample: Sample) -> None:
        nonlocal first, fresh
        stamp = (sample.msg or {}).get("header", {}).get("stamp")
        if stamp is None:
            raise ControlError(f"{args.topic} carries {ros_type}, which has no header to take a delay from")
        if not first:
            delays.append(sample.stamp - (stamp.get("sec", 0) + stamp.get("nanosec", 0) / 1e9))
            fresh = True
        first = False

    def report() -> bool:
        nonlocal fresh
        if not fresh:
            return False
        fresh = False
        _print_spread(f"average delay: {sum(delays) / len(delays):.3f}", delays, len(delays))
        return True

    with connect(args.graph) as conn:
        ros_type = codec.ros_name(codec.get_type(conn.request(Subscribe(topic=args.topic, ros_time=True))["type"]))
        _each_second(conn, take, report, args.count)


def topic_bw(args: argparse.Namespace) -> None:
    """Print ``Subscribed to [TOPIC]``, then every second the bandwidth over the last ``--window`` messages.

    As ``ros2 topic bw``: ``1.23 KB/s from 10 messages`` and the mean, min and
    max message size, in B, KB or MB by the rate's size.  A message's size is
    its CDR encoding, header included: the bytes ROS puts on the wire and
    counts (in one process actors passes the object itself, so nothing else
    would be a size); its time is when the graph received it (its runtime
    clock, so virtual time gives the graph's own rate).  Prints nothing until
    two messages have come.  ``--count N`` exits after N reports.
    """
    from collections import deque

    from actors import codec
    from actors.ops.control import Subscribe

    window: deque[tuple[float, int]] = deque(maxlen=max(2, args.window))

    def take(sample: Sample) -> None:
        window.append((sample.stamp, len(codec.encode_cdr(codec.convert(sample.msg, msg_type)))))

    def report() -> bool:
        if len(window) < 2 or window[-1][0] <= window[0][0]:
            return False
        sizes = [size for _, size in window]
        # Bytes after the first message over the time since it: the rate the window saw.
        rate = sum(sizes[1:]) / (window[-1][0] - window[0][0])
        unit = _bytes_unit(rate)
        mean = sum(sizes) / len(sizes)
        print(
            f"{unit(rate)}/s from {len(sizes)} messages\n"
            f"\tMessage size mean: {unit(mean)} min: {unit(min(sizes))} max: {unit(max(sizes))}",
            flush=True,
        )
        return True

    with connect(args.graph) as conn:
        msg_type = codec.get_type(conn.request(Subscribe(topic=args.topic))["type"])
        print(f"Subscribed to [{args.topic}]", flush=True)
        _each_second(conn, take, report, args.count)


def _bytes_unit(rate: float) -> Callable[[float], str]:
    """How ``ros2 topic bw`` writes sizes: B under 1000 B/s, KB under 1 MB/s, else MB."""
    if rate < 1000:
        return lambda n: f"{n:.0f} B"
    if rate < 1_000_000:
        return lambda n: f"{n / 1000:.2f} KB"
    return lambda n: f"{n / 1_000_000:.2f} MB"


def _print_spread(head: str, values: Sequence[float], window: int) -> None:
    """ros2's report of ``hz`` and ``delay``: ``head``, then the values' min, max and standard deviation."""
    import math

    mean = sum(values) / len(values)
    std = math.sqrt(sum((x - mean) ** 2 for x in values) / len(values))
    print(head)
    print(f"\tmin: {min(values):.3f}s max: {max(values):.3f}s std dev: {std:.5f}s window: {window}", flush=True)


def _each_second(conn: Connection, take: Callable[[Sample], None], report: Callable[[], bool], count: int) -> None:
    """Hand each streamed sample to ``take``; once a second of wall time, ``report()``.

    ``report`` returns whether it printed; after ``count`` printed reports
    (0: never) it returns.
    """
    import time

    reports = 0
    next_report = time.monotonic() + 1.0
    while True:
        sample = conn.sample(timeout=max(0.0, next_report - time.monotonic()))
        if sample is not None:
            take(sample)
        if time.monotonic() < next_report:
            continue
        next_report += 1.0
        if report():
            reports += 1
            if reports == count:
                return
