"""What the command line's recording and viewing options attach to a graph (``--record``, ``--foxglove``)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from actors.errors import BagError

__all__ = ["attachments"]


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
