"""Refused messages: what a subscription's callback turned away, counted per reason, logged sparingly.

A callback refuses a message by raising :class:`~actors.errors.MessageRefused`.
The subscription drops it and hands it here: it is counted per reason, and a
warning is logged the first time a given publisher sends a given reason, at
most :data:`LOG_BURST` lines at once and then one per :data:`LOG_PERIOD`
seconds of runtime clock (a flood of bad messages from ever new command-line
sessions must not flood the log).  A pair that the rate limit kept quiet is
logged when it recurs after the pause; the next line logged says how many
refusals went unsaid meanwhile.
"""

from __future__ import annotations

__all__ = ["LOG_BURST", "LOG_PERIOD", "Refusals"]

LOG_BURST = 5
"""Lines a subscription may log about refusals at once."""

LOG_PERIOD = 10.0
"""Seconds (runtime clock) to earn the right to one more line, up to :data:`LOG_BURST`."""

_MAX_SEEN = 256  # (publisher, reason) pairs remembered; forgotten pairs may log again


class Refusals:
    """One subscription's refused messages: ``counts`` per reason, ``last_from`` (the last sender)."""

    __slots__ = ("counts", "last_from", "_seen", "_tokens", "_since", "_unsaid")

    def __init__(self) -> None:
        self.counts: dict[str, int] = {}
        self.last_from = ""
        self._seen: set[tuple[str, str]] = set()
        self._tokens = float(LOG_BURST)
        self._since: float | None = None  # when the bucket was last refilled
        self._unsaid = 0

    @property
    def total(self) -> int:
        """Messages refused, all reasons together."""
        return sum(self.counts.values())

    def add(self, topic: str, sender: str, reason: str, now: float) -> str | None:
        """Count one refusal of ``sender``'s message at ``now`` (seconds); the line to log, or None."""
        count = self.counts[reason] = self.counts.get(reason, 0) + 1
        self.last_from = sender
        if (sender, reason) in self._seen:
            return None
        if self._since is not None:
            self._tokens = min(float(LOG_BURST), self._tokens + (now - self._since) / LOG_PERIOD)
        self._since = now
        if self._tokens < 1.0:
            self._unsaid += 1
            return None
        self._tokens -= 1.0
        if len(self._seen) >= _MAX_SEEN:
            self._seen.clear()
        self._seen.add((sender, reason))
        line = f"refused a message on {topic} from {sender}: {reason} (dropped; {count} so far"
        if self._unsaid:
            line += f"; {self._unsaid} other refusal(s) not logged"
            self._unsaid = 0
        return line + ")"
