"""``actors doctor [--report]``: check a running graph's health, as ``ros2 doctor`` does."""

from __future__ import annotations

import argparse
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from actors.cli._client import add_verb, connect

if TYPE_CHECKING:
    from actors.ops.doctor import Check, LagEvent

__all__ = ["register", "lag_line"]


def register(subparsers: Any) -> None:
    """Add the ``doctor`` command."""
    parser = add_verb(
        subparsers,
        "doctor",
        doctor,
        help="check the graph's health: topics, QoS, crashes, drops, lag",
        aliases=["wtf"],
    )
    parser.add_argument(
        "-r",
        "--report",
        action="store_true",
        help="also print the platform, versions and graph report",
    )
    parser.add_argument(
        "-iw",
        "--include-warnings",
        action="store_true",
        help="count warnings (e.g. a publisher nobody subscribes to) as failed checks",
    )


def doctor(args: argparse.Namespace) -> None:
    """Print the warnings, then ``All N checks passed`` or ``k/N checks failed`` and why.

    As ``ros2 doctor``, a warning does not fail its check unless
    ``--include-warnings`` is given; then it is listed with the failures.
    Exits 0 either way: the checks ran.  Only an unreachable graph is an error.
    """
    from actors.ops.control import Diagnose
    from actors.ops.doctor import Report
    from actors.system.introspection import action_infos

    with connect(args.graph) as conn:
        report = conn.request(Diagnose(), Report)
        graph = conn.graph() if args.report else None
    if graph is not None:
        _section("PLATFORM INFORMATION", report.platform.items())
        _section("PACKAGE VERSIONS", report.versions.items())
        _section(
            "GRAPH",
            [
                ("name", graph.name),
                ("clock", graph.clock),
                ("nodes", str(len(graph.nodes))),
                ("topics", str(len(graph.topics))),
                ("services", str(len(graph.services))),
            ],
        )
        _section(
            "NODES",
            [(n.name, f"{n.state}, {n.restarts} restart(s), {n.crashes} crash(es)") for n in graph.nodes],
        )
        _section(
            "ACTIONS",
            [
                (
                    a.name,
                    f"{a.type}, servers: {', '.join(a.servers) or 'none'}, clients: {', '.join(a.clients) or 'none'}",
                )
                for a in action_infos(graph.topics)
            ]
            or [("actions", "none")],
        )
        _section(
            "TOPICS",
            [
                (
                    t.name,
                    f"{t.type}, {len(t.publishers)} publisher(s), "
                    f"{len(t.subscriptions)} subscription(s), "
                    f"{sum(s.dropped for s in t.subscriptions)} dropped",
                )
                for t in graph.topics
            ],
        )
        lag = [lag_line(e) for e in report.lag_events]
        _section(
            "LOOP LAG",
            (lag or [("events", "none")]) if report.lag_measured else [("measured", "no (virtual time)")],
        )
        _section("CHECKS", [(c.name, _verdict(c, args.include_warnings)) for c in report.checks])
        print()
    failed = report.failures(args.include_warnings)
    if not args.include_warnings:
        for check in report.checks:
            for warning in check.warnings:
                print(f"WARNING: {check.name}: {warning}")
    if not failed:
        print(f"All {len(report.checks)} checks passed")
        return
    print(f"{len(failed)}/{len(report.checks)} checks failed")
    for check in failed:
        for reason in (*check.reasons, *check.warnings):
            print(f"  {check.name}: {reason}")


def _verdict(check: Check, include_warnings: bool) -> str:
    if check.failed(include_warnings):
        return "FAILED"
    return f"passed, {len(check.warnings)} warning(s)" if check.warnings else "passed"


def _section(title: str, rows: Iterable[tuple[str, str]]) -> None:
    """A report section as ros2 doctor prints one: an indented title, then ``key : value`` lines."""
    rows = list(rows)
    width = max([17, *(len(key) + 1 for key, _ in rows)])
    print(f"\n   {title}")
    for key, value in rows:
        print(f"{key:<{width}}: {value}")


def lag_line(event: LagEvent) -> tuple[str, str]:
    """One LOOP LAG line: when, how late, and the node's callback that held the loop, if one did."""
    if event.node:
        held = f"running {event.node} {event.callback}".rstrip()
    else:
        held = "no node's callback held the loop (another task, or the process was not scheduled)"
    return f"{event.stamp:.3f}", f"{event.lag:.3f} s late, {held}"
