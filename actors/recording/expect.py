"""Recorded expectations for tests: compare a run's bag with one recorded before (record once, assert forever).

A test feeds recorded inputs into the nodes under test on the virtual clock
(:func:`actors.recording.player.play`), records their outputs with a
:class:`~actors.recording.recorder.Recorder`, and compares that bag with the
expected one: same topics, same log times, same bytes, in the same order.  On
virtual time a graph is deterministic, so any difference is a change in
behaviour.  The ``bag_expectation`` fixture of ``actors.testing`` writes the
expected bag on ``pytest --record-bags`` and compares against it otherwise.
"""

from __future__ import annotations

import shutil
from collections.abc import Iterable
from pathlib import Path

from actors import codec
from actors.errors import ActorsError
from actors.recording.reader import Bag, BagMessage

__all__ = ["differences", "BagExpectation"]


def _describe(message: BagMessage) -> str:
    body: object
    try:
        body = codec.to_builtins(codec.decode_cdr(message.data, message.topic.type))
    except (ActorsError, TypeError, ValueError):
        body = f"{len(message.data)} bytes"
    return f"{message.topic.name} at {message.log_time / 1e9:.9f} s: {body}"


def differences(
    actual: str | Path | Bag, expected: str | Path | Bag, *, topics: Iterable[str] | None = None, limit: int = 5
) -> list[str]:
    """How ``actual``'s messages differ from ``expected``'s (topic, log time, bytes, order), first ones first.

    An empty list means the same messages.  At most ``limit`` differences are
    described, each naming the message of both bags.
    """
    a = actual if isinstance(actual, Bag) else Bag(actual)
    e = expected if isinstance(expected, Bag) else Bag(expected)
    names = list(topics) if topics is not None else None
    got, want = list(a.messages(names)), list(e.messages(names))
    found = []
    for index, (x, y) in enumerate(zip(got, want)):
        if (x.topic.name, x.log_time, x.data) != (y.topic.name, y.log_time, y.data):
            found.append(f"message {index}: got {_describe(x)}; expected {_describe(y)}")
            if len(found) == limit:
                return found
    if len(got) != len(want):
        longer, what = (got, "more") if len(got) > len(want) else (want, "fewer")
        found.append(
            f"{len(got)} messages where {len(want)} were expected ({what}); "
            f"the first unmatched: {_describe(longer[min(len(got), len(want))])}"
        )
    return found


class BagExpectation:
    """Compares bags with expected bags; writes the expected ones instead when ``update``."""

    def __init__(self, *, update: bool = False) -> None:
        self.update = update

    def check(self, actual: str | Path, expected: str | Path, *, topics: Iterable[str] | None = None) -> None:
        """Raise AssertionError listing the differences of ``actual`` from ``expected``.

        With ``update`` (``pytest --record-bags``), copy ``actual`` to
        ``expected`` instead.  A missing expected bag fails with that hint.
        """
        actual, expected = Path(actual), Path(expected)
        if self.update:
            expected.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(actual, expected)
            return
        if not expected.exists():
            raise AssertionError(f"no expected bag {expected}: run pytest --record-bags once to record it")
        found = differences(actual, expected, topics=topics)
        if found:
            raise AssertionError(f"{actual} differs from {expected}:\n  " + "\n  ".join(found))
