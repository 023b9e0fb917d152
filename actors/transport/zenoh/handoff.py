"""Zenoh's callbacks, handed to the event loop in batches.

Zenoh calls back on threads of its own (samples, queries, replies, liveliness
changes).  Nothing of the graph may be touched there: each callback only
appends ``(function, argument)`` to a :class:`Handoff`, and the first item of
a batch schedules one drain on the loop (``call_soon_threadsafe``, one write
to the loop's wake-up pipe).  Items that arrive while that drain is pending
ride along with it: a burst of samples costs one thread hop, not one each.
The drain runs every item in arrival order, on the loop, where the graph lives.
"""

from __future__ import annotations

import asyncio
import threading
from collections import deque
from collections.abc import Callable
from typing import Any

__all__ = ["Handoff"]


class Handoff:
    """A queue from any thread to one event loop, drained in batches on the loop."""

    __slots__ = ("_loop", "_items", "_lock", "_pending", "_closed", "_on_error")

    def __init__(self, loop: asyncio.AbstractEventLoop, on_error: Callable[[BaseException], object]) -> None:
        self._loop = loop
        self._items: deque[tuple[Callable[[Any], None], Any]] = deque()
        self._lock = threading.Lock()
        self._pending = False
        self._closed = False
        self._on_error = on_error  # an item that raised: logged, and the drain goes on

    def put(self, function: Callable[[Any], None], argument: Any) -> None:
        """Run ``function(argument)`` on the loop soon.  Any thread; never blocks for long.

        Dropped silently once the handoff is closed (the transport is stopping).
        """
        self._items.append((function, argument))
        with self._lock:
            if self._pending or self._closed:
                return
            self._pending = True
        try:
            self._loop.call_soon_threadsafe(self._drain)
        except RuntimeError:  # the loop is closed: nobody is left to deliver to
            self._closed = True

    def close(self) -> None:
        """Drop what is queued and everything put from now on."""
        with self._lock:
            self._closed = True
        self._items.clear()

    def _drain(self) -> None:
        with self._lock:
            self._pending = False  # what comes from now on schedules the next drain
        items = self._items
        for _ in range(len(items)):
            function, argument = items.popleft()
            try:
                function(argument)
            except Exception as exc:  # one bad item must not stop the others
                self._on_error(exc)
