"""Warnings a peer can cause are bounded per key, per peer and in all, and what is left out is summed up."""

from __future__ import annotations

from collections.abc import Callable

from actors.transport.zenoh.peer_warnings import PER_KEY, PER_WINDOW, WINDOW, PeerWarnings

KEY = "0/chatter/std_msgs::msg::dds_::String_/RIHS01_x"


class Clock:
    def __init__(self) -> None:
        self.now = 100.0
        self.scheduled: list[tuple[float, Callable[[], None]]] = []

    def __call__(self) -> float:
        return self.now

    def later(self, delay: float, function: Callable[[], None]) -> None:
        self.scheduled.append((self.now + delay, function))

    def advance(self, seconds: float) -> None:
        self.now += seconds
        due = [f for at, f in self.scheduled if at <= self.now]
        self.scheduled = [(at, f) for at, f in self.scheduled if at > self.now]
        for function in due:
            function()


def test_fresh_peers_on_one_key_give_a_few_lines_then_one_summary():
    lines: list[str] = []
    clock = Clock()
    warnings = PeerWarnings(lines.append, clock=clock)
    for i in range(20_000):
        warnings.warn(KEY, f"{i:032x}", f"bad sample from {i}")
    assert lines == [f"bad sample from {i}" for i in range(PER_KEY)]
    clock.now += WINDOW
    warnings.warn(KEY, "new", "bad sample from new")
    assert lines[PER_KEY].startswith(f"left out {20_000 - PER_KEY} more warning(s) like these in 60 s: ")
    assert lines[PER_KEY + 1] == "bad sample from new"  # a new window
    assert (warnings.seen, warnings.left_out) == (20_001, 20_000 - PER_KEY)


def test_an_unknown_peer_is_one_line_per_key_whatever_it_claims():
    lines: list[str] = []
    warnings = PeerWarnings(lines.append, clock=Clock())
    for gid in range(1000):  # the GID is in the text only: the peer is the same unknown one
        warnings.warn(KEY, "", f"bad sample (publisher {gid}, as it says)")
    assert lines == ["bad sample (publisher 0, as it says)"]


def test_one_peer_is_one_line_per_key_and_the_total_is_bounded():
    lines: list[str] = []
    warnings = PeerWarnings(lines.append, clock=Clock())
    for _ in range(100):
        warnings.warn("a", "peer", "same peer")
    assert lines == ["same peer"]
    for key in range(1000):
        for peer in range(5):
            warnings.warn(f"key{key}", f"p{peer}", f"{key}/{peer}")
    assert len(lines) == PER_WINDOW
    warnings.summarise()
    assert len(lines) == PER_WINDOW + 1
    assert "and " in lines[-1] and "more key(s)" in lines[-1]


def test_the_summary_comes_when_the_window_ends_even_if_the_peer_stopped():
    lines: list[str] = []
    clock = Clock()
    warnings = PeerWarnings(lines.append, clock.later, clock=clock)
    clock.advance(10)
    for _ in range(50):
        warnings.warn(KEY, "", "bad")
    assert len(clock.scheduled) == 1  # one summary scheduled, not one per warning
    clock.advance(WINDOW - 10 - 1)
    assert lines == ["bad"]
    clock.advance(1)
    assert lines[1].startswith("left out 49 more warning(s) like these in 60 s: 49 on 0/chatter/")
    clock.advance(10 * WINDOW)
    assert len(lines) == 2  # nothing left out since: nothing more said


def test_memory_is_bounded_by_the_limits_not_by_the_keys_sent():
    warnings = PeerWarnings(lambda text: None, clock=Clock())
    for key in range(100_000):
        warnings.warn(f"token/{key}", f"p{key}", "x")
    assert len(warnings._peers) <= PER_WINDOW
    assert len(warnings._dropped) <= 257  # the tracked keys and "other keys"


def test_nothing_left_out_says_nothing():
    lines: list[str] = []
    warnings = PeerWarnings(lines.append, clock=Clock())
    warnings.summarise()
    assert lines == []
