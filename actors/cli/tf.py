"""``actors tf frames``: a running graph's tf frame tree, written as ``view_frames`` writes it.

It listens to ``/tf`` and ``/tf_static`` through the graph's control endpoint
for ``-t`` seconds of this process's clock (as the real tool waits on the wall
clock), then writes ``NAME.gv`` and the picture beside it with the drawing of
``actors run tf2_tools view_frames`` (:mod:`actors.ops.tf_frames`).  The
static transforms published before it came are there too: the endpoint taps a
topic whose publishers all keep history (tf2's static broadcasters are
transient-local) as transient-local, so it hands over their latched messages.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from collections.abc import Callable
from typing import Any

from actors.cli._client import Connection, add_verb, connect

__all__ = ["register"]


def register(subparsers: Any) -> None:
    """Add the ``tf`` group and its verb to the command line."""
    parser = subparsers.add_parser("tf", help="the tf frame tree of a running graph")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)
    frames = add_verb(verbs, "frames", write_frames, help="write the frame tree to a picture, as view_frames does")
    frames.add_argument(
        "-t", "--wait-time", type=float, default=5.0, help="seconds to listen to tf before drawing (default 5)"
    )
    frames.add_argument("-o", "--output", default="", help="file name without .gv/.pdf (default frames_<date>_<time>)")


def write_frames(args: argparse.Namespace) -> None:
    """Listen to the graph's tf for ``--wait-time`` seconds, then write the tree; one line and exit 2 on bad input."""
    import selectors

    from actors import codec
    from actors.errors import ControlError
    from actors.ops.control import Subscribe
    from actors.ops.tf_frames import frame_files, output_problem
    from actors.ops.tf_frames import write_frames as write
    from actors.ros.tf_buffer import BufferCore
    from interfaces.tf2_msgs.msg import TFMessage

    if not 0 < args.wait_time < math.inf:
        raise ControlError(f"--wait-time {args.wait_time}: not a positive number of seconds")
    problem = output_problem(args.output)
    if problem is not None:
        raise ControlError(problem)
    buffer = BufferCore()
    store = {"/tf": buffer.set_transform, "/tf_static": buffer.set_transform_static}
    selector = selectors.DefaultSelector()
    # One connection per topic: a connection's samples do not say which topic they are of.
    streams: dict[str, Connection] = {}
    newest = 0.0  # the graph's clock, as its last sample was stamped
    listening = virtual = False
    try:
        for topic in store:
            conn = streams[topic] = connect(args.graph)
            if topic == "/tf":  # asked before the stream begins: samples would come between
                virtual = conn.graph().clock == "virtual"
            conn.request(Subscribe(topic=topic, type=codec.ros_name(TFMessage)))
            selector.register(conn, selectors.EVENT_READ, topic)
        print(f"Listening to tf data for {args.wait_time} seconds...", flush=True)
        listening = True
        for topic in streams:  # a reply's read may have brought the first samples with it
            newest = max(newest, _take(streams[topic], store[topic], 0))
        deadline = time.monotonic() + args.wait_time
        while (left := deadline - time.monotonic()) > 0:
            for key, _ in selector.select(timeout=left):
                # readable: a frame is coming (its first bytes may precede the rest a little)
                newest = max(newest, _take(streams[key.data], store[key.data], 0.1))
    except ControlError as exc:
        if not listening:
            raise  # no graph, or it refused a subscription
        # A graph that ends first (a virtual-time run races to its end) gave all it will give.
        print(f"stopped listening: {exc}", file=sys.stderr)
    finally:
        for conn in streams.values():
            conn.close()
    print("Generating graph...")
    files = frame_files(args.output)
    print(f"Exporting graph in {files[1]} file...")
    try:
        # Recorded at the graph's time on a virtual clock, at this process's otherwise (as bag record stamps).
        write(buffer.frame_table(), newest if virtual else time.time(), files)
    except OSError as exc:
        raise ControlError(f"cannot write the frame tree to {files[0]}: {exc.strerror or exc}") from None


def _take(conn: Connection, store: Callable[[Any, str], bool], wait: float) -> float:
    """Put the transforms of the samples ``conn`` has (waiting ``wait`` s for the first) into the buffer.

    Returns the newest sample's stamp, 0.0 for none.
    """
    from actors import codec
    from actors.ros.tf_buffer import LISTENER_AUTHORITY
    from interfaces.tf2_msgs.msg import TFMessage

    newest = 0.0
    for sample in conn.samples(wait):
        newest = max(newest, sample.stamp)
        for transform in codec.convert(sample.msg, TFMessage).transforms:
            store(transform, LISTENER_AUTHORITY)
    return newest
