"""What the command line's recording and viewing options attach to a graph (``--record``, ``--foxglove``)."""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from typing import Any

from actors.errors import BagError

__all__ = ["add_attachment_options", "attachments"]


def add_attachment_options(parser: argparse.ArgumentParser) -> None:
    """``--record BAG``, ``--topics TOPIC...`` and ``--foxglove [PORT]``, for :func:`attachments`."""
    parser.add_argument("--record", metavar="BAG", help="record topics into a ROS 2 bag: BAG.mcap, or a bag directory")
    parser.add_argument("--topics", nargs="+", default=[], metavar="TOPIC", help="with --record: only these topics")
    parser.add_argument(
        "--foxglove",
        nargs="?",
        type=_port,
        const=8765,
        metavar="PORT",
        help="serve every topic live to Foxglove on ws://127.0.0.1:PORT (default 8765; pip install 'actors[foxglove]')",
    )


def _port(text: str) -> int:
    if not text.isdigit() or int(text) > 65535:
        raise argparse.ArgumentTypeError(f"not a port number (0 to 65535, 0: any free one): {text!r}")
    return int(text)


def attachments(*, record: str | None = None, topics: Sequence[str] = (), foxglove: int | None = None) -> list[Any]:
    """The attachments ``python -m actors.run`` options ask for, each ready to run.

    A bag is created and the live view's port taken here, before the graph
    starts, so that a name already taken, an unwritable directory or a port in
    use is a one-line error (BagError, ActorsError), not a failure in a running
    graph.  ImportError (with an install hint) when an extra is missing.
    """
    found: list[Any] = []
    if topics and not record:
        raise BagError("--topics selects what --record records: give --record BAG too")
    if record:
        from actors.recording.recorder import Recorder

        recorder = Recorder(record, topics=topics)
        try:
            recorder.open()
        except (FileExistsError, FileNotFoundError) as exc:
            raise BagError(f"cannot record to {record}: {exc}") from None
        except OSError as exc:
            raise BagError(f"cannot record to {record}: {exc.strerror or exc}") from None
        found.append(recorder)
    if foxglove is not None:
        from actors.recording.live import FoxgloveView

        view = FoxgloveView(foxglove)
        view.start()
        found.append(view)
    return found
