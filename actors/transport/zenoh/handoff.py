"""Zenoh's callbacks, handed to the event loop in batches.

Zenoh calls back on threads of its own (samples, queries, replies, liveliness
changes).  Nothing of the graph may be touched there: each callback only
appends ``(function, argument)`` to a :class:`Handoff`, and the first item of
a batch schedules one drain on the loop (``call_soon_threadsafe``, one write
to the loop's wake-up pipe).  Items that arrive while that drain is pending
ride along with it: a burst of samples costs one thread hop, not one each.
The drain runs every item in arrival order, on the loop, where the graph lives,
and then the rounds of the actors those items woke (a subscription fed by a
sample, a server given a query), in the runtime's :class:`Scheduler` context:
not one loop iteration later, which every hop across processes paid.

Zenoh's own threads are not Python's: a callback run there (``indirect=False``)
made a Python thread state and deleted it again on return, most of that
thread's time in a profile of the service round trip.  :func:`keep_thread_state`
keeps the thread state of such a thread from its first callback on, as a
thread Python started keeps its own: one per zenoh thread, never freed.
"""

from __future__ import annotations

import asyncio
import ctypes
import threading
from collections import deque
from collections.abc import Callable
from typing import Any

from actors.core._actor import Scheduler

__all__ = ["Handoff", "keep_thread_state"]

_kept = threading.local()


def keep_thread_state() -> None:
    """Keep the calling thread's Python thread state until the thread ends (cheap once done).

    A thread Python did not start gets a thread state for each call into
    Python and loses it on return, unless one ``PyGILState_Ensure`` is left
    unmatched: that one is, once per thread.
    """
    if not getattr(_kept, "held", False):
        ctypes.pythonapi.PyGILState_Ensure()
        _kept.held = True


class Handoff:
    """A queue from any thread to one event loop, drained in batches on the loop, with the rounds it wakes."""

    __slots__ = ("_loop", "_scheduler", "_items", "_lock", "_pending", "_closed", "_on_error")

    def __init__(
        self, loop: asyncio.AbstractEventLoop, scheduler: Scheduler, on_error: Callable[[BaseException], object]
    ) -> None:
        self._loop = loop
        self._scheduler = scheduler
        self._items: deque[tuple[Callable[[Any], None], Any]] = deque()
        self._lock = threading.Lock()
        self._pending = False
        self._closed = False
        self._on_error = on_error  # an item that raised: logged, and the drain goes on

    def put(self, function: Callable[[Any], None], argument: Any) -> None:
        """Run ``function(argument)`` on the loop soon.  Any thread; never blocks for long.

        Dropped silently once the handoff is closed (the transport is stopping).
        """
        keep_thread_state()
        self._items.append((function, argument))
        with self._lock:
            if self._pending or self._closed:
                return
            self._pending = True
        try:
            self._loop.call_soon_threadsafe(self._drain, context=self._scheduler.context)
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
        items, scheduler = self._items, self._scheduler
        scheduler.hold()  # the actors the items wake run below, not from a loop callback of their own
        try:
            for _ in range(len(items)):
                function, argument = items.popleft()
                try:
                    function(argument)
                except Exception as exc:  # one bad item must not stop the others
                    self._on_error(exc)
        finally:
            scheduler.run_now()
