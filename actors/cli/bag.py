"""``actors bag record|info|reindex|play``: ROS 2 bags (MCAP), as ``ros2 bag`` records, shows, mends and plays them."""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path
from typing import Any

from actors.cli._client import add_verb, connect
from actors.cli.topic import _positive  # one reading of a positive number for every verb
from actors.core.signals import raise_stops, remember_stops, take_noted

__all__ = ["register", "format_info"]


def register(subparsers: Any) -> None:
    """Add the ``bag`` group and its verbs to the command line."""
    parser = subparsers.add_parser("bag", help="record, inspect and play ROS 2 bags (MCAP)")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)

    record = add_verb(verbs, "record", record_bag, help="record a running graph's topics into a bag")
    record.add_argument("topics", nargs="*", metavar="TOPIC", help="topics to record (or -a)")
    record.add_argument("-a", "--all", action="store_true", help="record every topic")
    record.add_argument(
        "-o", "--output", metavar="BAG", help="BAG.mcap, or a bag directory (default: rosbag2_<date>_<time>)"
    )
    record.add_argument("-x", "--exclude", metavar="REGEX", help="with -a: leave out topics matching REGEX")
    record.add_argument("--include-hidden-topics", action="store_true", help="with -a: hidden topics too")
    record.add_argument(
        "--flush-interval",
        type=_positive,
        default=1.0,
        metavar="S",
        help="write what was received to the file at least every S seconds (1): what a kill -9 can lose",
    )

    info = verbs.add_parser("info", help="what a bag holds, as ros2 bag info prints it")
    info.add_argument("bag", metavar="BAG", help="an .mcap file or a bag directory")
    info.add_argument("--recover", action="store_true", help="show what is readable in a damaged bag")
    info.set_defaults(func=bag_info)

    reindex = verbs.add_parser(
        "reindex", help="make a bag whose recording was killed whole again (summary, metadata.yaml)"
    )
    reindex.add_argument("bag", metavar="BAG", help="an .mcap file or a bag directory")
    reindex.set_defaults(func=reindex_bag)

    play = add_verb(verbs, "play", play_bag, help="publish a bag's messages into a running graph")
    play.add_argument("bag", metavar="BAG", help="an .mcap file or a bag directory")
    play.add_argument("-r", "--rate", type=_positive, default=1.0, help="speed factor on the wall clock")
    play.add_argument(
        "--clock",
        type=_positive,
        nargs="?",
        const=40.0,
        default=0.0,
        metavar="HZ",
        help="also publish the bag's time on /clock (rosgraph_msgs/Clock), HZ times a second (40)",
    )
    play.add_argument("-l", "--loop", action="store_true", help="play again and again until stopped")
    play.add_argument("--topics", nargs="+", metavar="TOPIC", help="play only these topics")
    play.add_argument("--remap", nargs="+", default=[], metavar="FROM:=TO", help="publish FROM on TO")
    play.add_argument("--recover", action="store_true", help="play what is readable in a damaged bag")


def _open_bag(path: str, recover: bool) -> Any:
    from actors.errors import BagError
    from actors.recording.reader import Bag

    try:
        bag = Bag(path, recover=recover)
    except FileNotFoundError as exc:
        raise BagError(str(exc)) from None
    for problem in bag.problems:
        print(f"warning: {problem}; showing what comes before it", file=sys.stderr)
    return bag


# --------------------------------------------------------------------------- info


def bag_info(args: argparse.Namespace) -> None:
    """Print the bag's files, size, duration, times and topics as ``ros2 bag info`` does."""
    print(format_info(_open_bag(args.bag, args.recover)), end="")


def _size(size: int) -> str:
    value, unit = float(size), 0
    units = ("B", "KiB", "MiB", "GiB", "TiB")
    while value >= 1024 and unit < 4:
        value /= 1024
        unit += 1
    return f"{value:.0f} {units[unit]}" if unit == 0 else f"{value:.1f} {units[unit]}"


def _seconds(ns: int) -> str:
    return f"{ns // 1_000_000_000}.{ns % 1_000_000_000:09d}"


def _stamp(ns: int) -> str:
    local = time.localtime(ns // 1_000_000_000)
    day = time.strftime("%b ", local) + f"{local.tm_mday:2d}" + time.strftime(" %Y %H:%M:%S", local)
    return f"{day}.{ns % 1_000_000_000:09d} ({_seconds(ns)})"


def format_info(bag: Any) -> str:
    """``ros2 bag info``'s text for a :class:`~actors.recording.reader.Bag`."""
    pad = " " * 19
    topics = bag.topics
    services = [
        t for t in topics if t.name.endswith("/_service_event") and "/srv/" in t.type and t.type.endswith("_Event")
    ]
    plain = [t for t in topics if t not in services]
    dropped = sum(t.dropped for t in topics)
    names = [str(f.relative_to(bag.path)) if bag.path.is_dir() else str(bag.path) for f in bag.files]
    distros = {s.ros_distro for s in bag.summaries if s.ros_distro}
    lines = [
        "",
        "Files:             " + f"\n{pad}".join(names),
        f"Bag size:          {_size(bag.size)}",
        "Storage id:        mcap",
        f"ROS Distro:        {distros.pop() if len(distros) == 1 else 'unknown'}",
        f"Duration:          {_seconds(bag.end - bag.start)}s",
        f"Start:             {_stamp(bag.start)}",
        f"End:               {_stamp(bag.end)}",
        f"Messages:          {bag.message_count - sum(t.count for t in services)}",
        *([f"Dropped:           {dropped} (recorded lossy: the disk fell behind)"] if dropped else []),
        "Topic information: "
        + f"\n{pad}".join(
            f"Topic: {t.name} | Type: {t.type} | Count: {t.count}"
            + (f" | Dropped: {t.dropped}" if t.dropped else "")
            + f" | Serialization Format: {t.serialization_format}"
            for t in plain
        ),
        f"Service:           {len(services)}",
        "Service information: "
        + f"\n{pad}  ".join(
            f"Service: {t.name.removesuffix('/_service_event')} | Type: {t.type.removesuffix('_Event')} | "
            f"Event Count: {t.count} | Serialization Format: {t.serialization_format}"
            for t in services
        ),
    ]
    return "\n".join(lines) + "\n"


def reindex_bag(args: argparse.Namespace) -> None:
    """Rewrite the bag from its whole chunks, as ``ros2 bag reindex`` rebuilds a bag's metadata."""
    from actors.errors import BagError
    from actors.recording.reindex import reindex

    try:
        kept, problems = reindex(args.bag)
    except FileNotFoundError as exc:
        raise BagError(str(exc)) from None
    except OSError as exc:
        raise BagError(f"cannot rewrite {args.bag}: {exc.strerror or exc}") from None
    for problem in problems:
        print(f"warning: {problem}; kept what comes before it", file=sys.stderr)
    print(f"reindexed {args.bag}: {kept} message(s)", file=sys.stderr)


# --------------------------------------------------------------------------- play


def play_bag(args: argparse.Namespace) -> None:
    """Have the running graph play the bag on its own clock, and wait until it has.

    The graph publishes each message when its clock has moved as far as the
    bag's did (divided by ``--rate``): on the wall clock in real time, on
    virtual time as fast as the graph handles them.  Topics whose type is
    unknown here are named and skipped.  Ctrl-C stops the playing.
    """
    from actors.errors import BagError
    from actors.ops.control import Play
    from actors.recording.player import parse_remaps, plan

    bag = _open_bag(args.bag, args.recover)
    bag.check()  # every chunk, before the graph plays any of it
    try:
        remap = parse_remaps(args.remap)
    except ValueError as exc:
        raise BagError(str(exc)) from None
    _, skipped = plan(bag, topics=args.topics, remap=remap)
    for line in skipped:
        print(line, file=sys.stderr)
    request = Play(
        path=str(Path(args.bag).resolve()),
        topics=args.topics,
        remap=remap,
        rate=args.rate,
        clock=args.clock,
        loop=args.loop,
        recover=args.recover,
    )
    with connect(args.graph) as conn:
        played = conn.request(request, timeout=None)["played"]
    print(f"played {played} message(s) from {args.bag}", file=sys.stderr)


# --------------------------------------------------------------------------- record


def record_bag(args: argparse.Namespace) -> None:
    """Record the running graph's topics until Ctrl-C (or the graph stops), then close the bag.

    Each topic is streamed through the graph's control endpoint; new topics
    are looked for ten times a second, as ``ros2 bag record`` polls the graph.
    Messages are stamped with the graph's clock on a virtual-time graph, with
    this process's wall clock otherwise (as rosbag2 stamps on receipt).
    """
    import re
    import selectors

    from actors import codec
    from actors.errors import BagError, ControlError
    from actors.ops.control import Subscribe
    from actors.recording.bag_writer import BagWriter
    from actors.ros.names import expand, is_hidden_name

    if not args.all and not args.topics:
        raise BagError("name the topics to record, or -a for all of them")
    wanted = {expand(t, "/", "_") for t in args.topics}
    exclude = re.compile(args.exclude) if args.exclude else None
    output = args.output or time.strftime("rosbag2_%Y_%m_%d-%H_%M_%S")
    graph = connect(args.graph)  # before the bag: without a graph, no empty bag is left behind
    try:
        bag = BagWriter(output)
    except OSError as exc:
        graph.close()
        raise BagError(f"cannot record to {output}: {exc.strerror or exc}") from None

    def wanted_topic(name: str) -> bool:
        if not args.all:
            return name in wanted
        if is_hidden_name(name) and not args.include_hidden_topics:
            return False
        return not (exclude is not None and exclude.search(name))

    selector = selectors.DefaultSelector()
    streams: dict[str, _Stream] = {}

    def subscribe(topic: Any) -> _Stream:
        conn = connect(args.graph)
        ros_type = conn.request(Subscribe(topic=topic.name, depth=1000))["type"]
        msg_type = codec.get_type(ros_type)
        channel = bag.add_topic(
            topic.name,
            ros_type,
            definition=codec.definition_text(msg_type),
            type_hash=codec.type_hash(msg_type),
            offers=[p.qos for p in topic.publishers],
        )
        stream = _Stream(conn, msg_type, channel)
        selector.register(conn, selectors.EVENT_READ, stream)
        return stream

    def write(stream: _Stream, wait: float, virtual: bool) -> None:
        """Write the stream's next sample (waiting ``wait`` s for it) and every other one already read."""
        for sample in stream.conn.samples(wait):
            stamp = round(sample.stamp * 1e9) if virtual else time.time_ns()
            msg = codec.convert(sample.msg, stream.msg_type)
            bag.write(stream.channel, stamp, codec.encode_cdr(msg))

    print(f"Recording to {bag.path} (Ctrl-C stops)", file=sys.stderr, flush=True)
    try:
        with graph as conn:
            virtual = conn.graph().clock == "virtual"
            next_look = 0.0
            held_since: float | None = None  # when the chunk in progress got its first message
            while True:
                if time.monotonic() >= next_look:
                    next_look = time.monotonic() + 0.1
                    for topic in conn.graph().topics:
                        if topic.name not in streams and wanted_topic(topic.name):
                            streams[topic.name] = stream = subscribe(topic)
                            # A latched topic's history may have come with the subscription's reply.
                            write(stream, 0, virtual)
                for key, _ in selector.select(timeout=0.1):
                    stream = key.data
                    write(stream, 0.01, virtual)  # readable: a frame is coming
                # What a kill -9 of this process loses is real time, whatever the graph's clock
                # (a quiet topic on virtual time gives no later stamp to measure by).
                if bag.pending_since is None:
                    held_since = None
                elif held_since is None:
                    held_since = time.monotonic()
                elif time.monotonic() - held_since >= args.flush_interval:
                    bag.flush_older_than(bag.pending_since)  # the whole chunk in progress
                    held_since = None
                if bag.error is not None:
                    raise BagError(f"recording to {bag.path} stopped: {bag.error}")
    except KeyboardInterrupt:
        pass
    except ControlError as exc:
        if not streams:
            raise
        print(f"stopped recording: {exc}", file=sys.stderr)
    finally:
        # A second Ctrl-C (or SIGTERM) while the bag closes would cut its summary short: closing
        # is quick, so stops are only noted until it is done.
        remember_stops()
        try:
            for stream in streams.values():
                stream.conn.close()
            bag.close()
        finally:
            take_noted()
            raise_stops()
    print(f"Recorded {bag.message_count} message(s) into {bag.path}", file=sys.stderr)


class _Stream:
    """One topic's subscription connection and its channel in the bag."""

    def __init__(self, conn: Any, msg_type: type[Any], channel: int) -> None:
        self.conn = conn
        self.msg_type = msg_type
        self.channel = channel
