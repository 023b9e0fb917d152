"""The performance targets of issues 7, 13, 16, 29, 31 and 33, checked against the results of one run."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

from bench.harness import Result, fmt

__all__ = ["Target", "TARGETS", "check"]


Lookup = Callable[[str, str], Result | None]

INTERFACES = "m. interfaces, 30-type package import"
LAUNCH = "n. launch, 100 nodes"


@dataclass(frozen=True)
class Target:
    """One target: what it asks, and how to read it off the results (None: not measured)."""

    name: str
    goal: str
    measure: Callable[[Lookup], tuple[bool, str] | None]


def _ratio(
    scenario: str, case: str, base_scenario: str, base_case: str, at_least: float
) -> Callable[[Lookup], tuple[bool, str] | None]:
    def measure(get: Lookup) -> tuple[bool, str] | None:
        result, base = get(scenario, case), get(base_scenario, base_case)
        if result is None or base is None or not result.samples or not base.samples:
            return None
        ratio = result.ratio(base)
        return ratio >= at_least, f"{ratio:.2f}×"

    return measure


def _cost(scenario: str, case: str, base_case: str, at_most: float) -> Callable[[Lookup], tuple[bool, str] | None]:
    """``case`` costs at most ``at_most`` times ``base_case`` (both in time per operation); shown as that multiple."""

    def measure(get: Lookup) -> tuple[bool, str] | None:
        result, base = get(scenario, case), get(scenario, base_case)
        if result is None or base is None or not result.samples or not base.samples:
            return None
        cost = result.median / base.median
        return cost <= at_most, f"{cost:.2f}×"

    return measure


def _all(*measures: Callable[[Lookup], tuple[bool, str] | None]) -> Callable[[Lookup], tuple[bool, str] | None]:
    def measure(get: Lookup) -> tuple[bool, str] | None:
        found = [m(get) for m in measures]
        if any(f is None for f in found):
            return None
        return all(ok for ok, _ in found), ", ".join(text for _, text in found)  # type: ignore[misc]

    return measure


def _at_most(scenario: str, case: str, limit: float, unit: str) -> Callable[[Lookup], tuple[bool, str] | None]:
    def measure(get: Lookup) -> tuple[bool, str] | None:
        result = get(scenario, case)
        if result is None or not result.samples:
            return None
        return result.median <= limit, f"{fmt(result.median)} {unit}"

    return measure


def _memory(get: Lookup) -> tuple[bool, str] | None:
    """At most 8 KiB per idle node at every count, and flat: each count within 25% of the largest."""
    per_node = {}
    for count in (100, 1_000, 10_000):
        result = get(f"f. memory, {count:,} nodes", "actors")
        if result is None or not result.samples:
            return None
        per_node[count] = result.median
    largest = per_node[10_000]
    linear = all(abs(v - largest) <= 0.25 * largest for v in per_node.values())
    small = all(v <= 8 for v in per_node.values())
    figures = " / ".join(f"{v:.1f}" for v in per_node.values())
    return small and linear, f"{figures} KiB/node at 100 / 1,000 / 10,000{'' if linear else ', not linear'}"


def _cdr(baseline: str, at_least: float) -> Callable[[Lookup], tuple[bool, str] | None]:
    """Every CDR sample and verb at least ``at_least`` times ``baseline``; shows the worst."""
    from bench.cdr import worst_ratio

    def measure(get: Lookup) -> tuple[bool, str] | None:
        found = worst_ratio(get, baseline)
        if found is None:
            return None
        return found[0] >= at_least, f"worst {found[0]:.2f}× ({found[1]})"

    return measure


SEQ, CONC = "c. service sequential", "c. service 100 callers"
TIMEOUT = "actors, timeout=5"
SCALE = "10,000 nodes"
ZENOH = "k. zenoh (2 processes)"
RECORDING = "l. recording: one-way"
WRITING = "l. recording: writing"
TARGETS = (
    # Issue 16: against our own limits (the bare asyncio floor, the physics core, a direct call).
    Target(
        "a",
        "one-way ≥ 0.7× the direct-call floor",
        _ratio("a. one-way", "actors", "a. one-way", "direct call (floor)", 0.7),
    ),
    Target(
        "b",
        "fan-out 1→10 ≥ 0.6× its direct-call floor",
        _ratio("b. fan-out 1→10", "actors", "b. fan-out 1→10", "direct call (floor)", 0.6),
    ),
    Target(
        "c",
        "round trip with a timeout ≤ 1.3× the bare future's (sequential, 100 callers)",
        _all(_cost(SEQ, TIMEOUT, "future+Queue", 1.3), _cost(CONC, TIMEOUT, "future+Queue", 1.3)),
    ),
    Target(
        "c",
        "round trip without a timeout ≤ 1.0× the bare future's (sequential, 100 callers)",
        _all(_cost(SEQ, "actors", "future+Queue", 1.0), _cost(CONC, "actors", "future+Queue", 1.0)),
    ),
    Target(
        "g",
        "nodes' real-time factor ≥ 0.6× the bare core (1 and 20 robots)",
        _all(
            _ratio("g. sim RTF, 1 robot", "nodes", "g. sim RTF, 1 robot", "core (floor)", 0.6),
            _ratio("g. sim RTF, 20 robots", "nodes", "g. sim RTF, 20 robots", "core (floor)", 0.6),
        ),
    ),
    Target(
        "h",
        "100 topics at once ≥ 2× the bare queues",
        _ratio("h. 100 topics at once", "actors", "h. 100 topics at once", "asyncio.Queue", 2),
    ),
    Target(
        "h",
        "1,000 topics (and nodes) within 2× of 100 topics' cost per message",
        _ratio("h. 1,000 topics at once", "actors", "h. 100 topics at once", "actors", 0.5),
    ),
    Target("f", "≤ 8 KiB per idle node, flat from 100 to 10,000", _memory),
    Target("j", "spawn ≤ 60 µs per node at 10,000 nodes", _at_most(f"j. spawn, {SCALE}", "actors", 60, "µs/node")),
    Target(
        "j",
        "a 10 Hz timer tick ≤ 8 µs at 10,000 nodes",
        _at_most(f"j. 10 Hz timer tick, {SCALE}", "actors", 8, "µs CPU"),
    ),
    Target("j", "graceful stop of 10,000 nodes ≤ 0.5 s", _at_most(f"j. graceful stop, {SCALE}", "actors", 0.5, "s")),
    # Issue 29's: a user's interface package typed on import.
    Target(
        "m",
        "first import of a 30-type workspace package ≤ 150 ms",
        _at_most(INTERFACES, "first import (empty cache)", 0.150, "s"),
    ),
    Target("m", "a cached import of it ≤ 20 ms", _at_most(INTERFACES, "cached import", 0.020, "s")),
    # Issue 31's: a ROS 2 launch file against the same graph as TOML (fresh processes, to the 100th node's message).
    Target("n", "a launch of 100 nodes starts ≤ 1 s", _at_most(LAUNCH, "launch file (.launch.py)", 1.0, "s")),
    Target(
        "n",
        "a launch file's parse + start adds ≤ 100 ms over the TOML graph",
        _all(
            _at_most(LAUNCH, "launch file (.launch.py) less TOML", 0.100, "s"),
            _at_most(LAUNCH, "launch file (.launch.xml) less TOML", 0.100, "s"),
        ),
    ),
    # Issue 13's: across two processes on loopback, actors over Zenoh against rclpy over Fast DDS.
    Target(
        "k",
        "cross-process one-way ≥ 2× rclpy's (Fast DDS)",
        _ratio(ZENOH, "one-way: actors (Zenoh)", ZENOH, "one-way: rclpy (Fast DDS)", 2),
    ),
    Target(
        "k",
        "cross-process round trip ≤ rclpy's (Fast DDS)",
        _ratio(ZENOH, "round trip: actors (Zenoh)", ZENOH, "round trip: rclpy (Fast DDS)", 1),
    ),
    # Issue 33's: across processes against rclpy and the bare-zenoh floor, and recording.
    Target(
        "k",
        "cross-process latency p50 ≤ rclpy's (Fast DDS)",
        _ratio(ZENOH, "latency p50: actors (Zenoh)", ZENOH, "latency p50: rclpy (Fast DDS)", 1),
    ),
    Target(
        "k",
        "cross-process one-way, round trip and latency p50 ≥ 0.8× the bare-zenoh floor",
        _all(
            *(
                _ratio(ZENOH, f"{measure}: actors (Zenoh)", ZENOH, f"{measure}: bare zenoh (floor)", 0.8)
                for measure in ("one-way", "round trip", "latency p50")
            )
        ),
    ),
    Target(
        "l",
        "one-way with a recorder on ≥ 0.5× off",
        _ratio(RECORDING, "recording on", RECORDING, "recording off", 0.5),
    ),
    Target(
        "l",
        "LaserScan writing ≥ 0.5× the mcap library alone",
        _ratio(WRITING, "LaserScan bag", WRITING, "mcap library Writer", 0.5),
    ),
    # Issue 7's, kept.
    Target("a", "one-way ≥ 1.5× the bare queue", _ratio("a. one-way", "actors", "a. one-way", "asyncio.Queue", 1.5)),
    Target(
        "a",
        "one-way ≥ 20× rclpy EventsExecutor",
        _ratio("a. one-way", "actors", "a. one-way", "rclpy EventsExecutor", 20),
    ),
    Target(
        "b",
        "fan-out 1→10 ≥ 2× the bare queue's one-way rate",
        _ratio("b. fan-out 1→10", "actors", "a. one-way", "asyncio.Queue", 2),
    ),
    Target(
        "c",
        "round trip ≤ 2× the bare future's (sequential, 100 callers)",
        _all(_cost(SEQ, "actors", "future+Queue", 2.0), _cost(CONC, "actors", "future+Queue", 2.0)),
    ),
    Target(
        "c",
        "round trip ≤ 1/5 of rclpy EventsExecutor's (sequential, 100 callers)",
        _all(
            _ratio(SEQ, "actors", SEQ, "rclpy EventsExecutor", 5),
            _ratio(CONC, "actors", CONC, "rclpy EventsExecutor", 5),
        ),
    ),
    Target(
        "d",
        "1 kHz timer p99 lateness ≤ 1 ms (idle machine), asyncio's default loop",
        _at_most("d. timer 1 kHz p99", "actors", 1000, "µs"),
    ),
    Target(
        "d",
        "the same on a select() loop (microsecond waits)",
        _at_most("d. timer 1 kHz p99", "actors, select() loop", 1000, "µs"),
    ),
    Target(
        "e",
        "graph.toml to first message ≤ 0.5 s (less the talker's 0.5 s first period)",
        _at_most("e. first message, graph.toml", "actors, less the first period", 0.5, "s"),
    ),
    Target("e", "1,000 nodes spawned ≤ 1 s", _at_most("e. spawn 1,000 nodes", "actors", 1.0, "s")),
    Target(
        "i",
        "CDR encode and decode ≥ rclpy's serialize/deserialize (Twist, LaserScan, Odometry, Image, PointCloud2)",
        _cdr("rclpy", 1),
    ),
    Target(
        "i",
        "CDR encode and decode ≥ rosbags' serializer (the same five, decoded to numpy views, as rosbags'; issue 33)",
        _cdr("rosbags", 1),
    ),
    Target("i", "CDR encode and decode ≥ 2× rosbags' serializer (the same five)", _cdr("rosbags", 2)),
)


def check(results: Sequence[Result], scenarios: str = "abcdefghijklmn") -> str:
    """A Markdown table of the targets of ``scenarios`` (letters): what was measured, whether it is met."""
    by_case = {(r.scenario, r.case): r for r in results}
    lines = ["| scenario | target | measured | met |", "|---|---|---|---|"]
    for target in (t for t in TARGETS if t.name in scenarios):
        found = target.measure(lambda scenario, case: by_case.get((scenario, case)))
        measured, verdict = ("not measured", "—") if found is None else (found[1], "met" if found[0] else "**not met**")
        lines.append(f"| {target.name} | {target.goal} | {measured} | {verdict} |")
    return "\n".join(lines)
