"""Warnings that other processes can cause, bounded whatever they send.

A peer chooses what it sends: a fresh publisher GID per malformed sample, a
fresh name per liveliness token, a fresh client GID per query.  Keyed on what
the sender writes, "once per publisher" was once per sample (20,000 lines for
20,000 samples).  :class:`PeerWarnings` keys on what the sender cannot
choose: the key expression is one of ours (a topic or service we listen on,
or one fixed kind such as ``liveliness``), and within a window of
:data:`WINDOW` seconds it logs at most :data:`PER_KEY` lines per key, one per
peer on that key, and :data:`PER_WINDOW` in all.  The peer is the source
Zenoh id where Zenoh tells it, never a GID out of the sender's attachment;
where Zenoh does not (it does not unless the sender opts in), every sample
on a key comes from one unknown peer, so a key gives one line per window.
What it leaves out is counted and said in one summary line when the window
is over (``later`` schedules that; else at the next warning), or when the
transport closes.  Its memory is bounded by those numbers too, not by what
peers send.

The window is timed on ``time.monotonic()``: peers act in real time, and a
transport runs on the wall clock only.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Any

__all__ = ["PeerWarnings", "WINDOW", "PER_KEY", "PER_WINDOW"]

WINDOW = 60.0
"""Seconds of one window."""

PER_KEY = 3
"""Lines per key expression in a window (each from another peer)."""

PER_WINDOW = 20
"""Lines in all in a window, whatever the keys."""

_NAMED_KEYS = 3  # keys the summary names, the busiest first
_TRACKED_KEYS = 256  # keys whose drops are counted one by one; the rest as "other keys"


class PeerWarnings:
    """Logs through ``log(text)``, within the bounds above.

    ``later(seconds, function)`` schedules the summary at the end of a window
    that left something out (the transport passes its loop's ``call_later``);
    ``clock`` is for tests.  ``seen`` counts every warning asked for,
    ``left_out`` those not logged, since the start.
    """

    def __init__(
        self,
        log: Callable[[str], object],
        later: Callable[[float, Callable[[], None]], Any] | None = None,
        *,
        clock: Callable[[], float] = time.monotonic,
    ) -> None:
        self._log = log
        self._later = later
        self._clock = clock
        self._window_start = clock()
        self._lines: dict[str, int] = {}  # key -> lines logged this window
        self._peers: set[tuple[str, str]] = set()  # (key, peer) logged this window
        self._total = 0
        self._dropped: dict[str, int] = {}  # key -> warnings left out this window
        self._summary_due = False
        self.seen = 0
        self.left_out = 0

    def warn(self, key: str, peer: str, text: str) -> None:
        """Log ``text``, about ``peer`` on our key expression ``key``, unless a bound says no."""
        self.seen += 1
        if self._clock() - self._window_start >= WINDOW:
            self.summarise()
        lines = self._lines.get(key, 0)
        if self._total >= PER_WINDOW or lines >= PER_KEY or (key, peer) in self._peers:
            self._leave_out(key)
            return
        self._lines[key] = lines + 1
        self._peers.add((key, peer))
        self._total += 1
        self._log(text)

    def _leave_out(self, key: str) -> None:
        if key not in self._dropped and len(self._dropped) >= _TRACKED_KEYS:
            key = "other keys"
        self._dropped[key] = self._dropped.get(key, 0) + 1
        self.left_out += 1
        self._summary_at_window_end()

    def _summary_at_window_end(self) -> None:
        if self._later is not None and not self._summary_due:
            self._summary_due = True
            self._later(max(0.0, self._window_start + WINDOW - self._clock()), self._window_over)

    def _window_over(self) -> None:
        self._summary_due = False
        if self._clock() - self._window_start >= WINDOW:
            self.summarise()
        elif self._dropped:  # a window begun since the call was scheduled: wait for its end
            self._summary_at_window_end()

    def summarise(self) -> None:
        """Say what the window left out (if anything), and start a new window."""
        if self._dropped:
            busiest = sorted(self._dropped.items(), key=lambda item: -item[1])
            named = ", ".join(f"{count} on {key}" for key, count in busiest[:_NAMED_KEYS])
            more = f" and {len(busiest) - _NAMED_KEYS} more key(s)" if len(busiest) > _NAMED_KEYS else ""
            seconds = self._clock() - self._window_start
            self._log(
                f"left out {sum(self._dropped.values())} more warning(s) like these in {seconds:.0f} s: "
                f"{named}{more} (at most {PER_KEY} per key and {PER_WINDOW} in all per {WINDOW:.0f} s)"
            )
        self._window_start = self._clock()
        self._lines.clear()
        self._peers.clear()
        self._dropped.clear()
        self._total = 0
