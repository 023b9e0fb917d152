"""``python -m bench [--quick] [--only NAME]``: every scenario with its baselines, one table.

A full run (no ``--quick``, no ``--only``) also rewrites BENCHMARKS.md.
"""

from __future__ import annotations

import argparse
import functools
import sys
import time
from collections.abc import Callable, Sequence
from typing import NamedTuple

from bench import (
    cdr,
    interfaces,
    launch,
    memory,
    recording,
    scale,
    services,
    sim,
    startup,
    throughput,
    timer,
    topics_scale,
    transport,
)
from bench.harness import Result, table
from bench.report import write
from bench.targets import check


class Scenario(NamedTuple):
    """A scenario of the issue: its letter, its name, and what runs it."""

    letter: str
    name: str
    run: Callable[[bool], list[Result]]


SCENARIOS = (
    Scenario("a", "one-way", functools.partial(throughput.run, fan_out=(1,))),
    Scenario("b", "fan-out", functools.partial(throughput.run, fan_out=(10,))),
    Scenario("c", "services", services.run),
    Scenario("d", "timer", timer.run),
    Scenario("e", "startup", startup.run),
    Scenario("f", "memory", memory.run),
    Scenario("g", "sim", sim.run),
    Scenario("h", "topics", topics_scale.run),
    Scenario("i", "cdr", cdr.run),
    Scenario("j", "scale", scale.run),
    Scenario("k", "zenoh", transport.run),
    Scenario("l", "recording", recording.run),
    Scenario("m", "interfaces", interfaces.run),
    Scenario("n", "launch", launch.run),
)


def select(only: str | None) -> list[Scenario]:
    """The scenarios named in ``only`` (letters or names, comma-separated), or all of them.

    Raises SystemExit with the valid names for a name that matches nothing.
    """
    if not only:
        return list(SCENARIOS)
    wanted = {w.strip().lower() for w in only.split(",") if w.strip()}
    unknown = wanted - {s.letter for s in SCENARIOS} - {s.name for s in SCENARIOS}
    if unknown:
        valid = ", ".join(f"{s.letter} ({s.name})" for s in SCENARIOS)
        raise SystemExit(f"error: no scenario {', '.join(sorted(unknown))}; choose from {valid}")
    return [s for s in SCENARIOS if s.letter in wanted or s.name in wanted]


def main(argv: Sequence[str] | None = None) -> None:
    """Run the chosen scenarios, print the table and the targets; write BENCHMARKS.md on a full run."""
    parser = argparse.ArgumentParser(prog="python -m bench", description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer messages and shorter runs (under 2 minutes)")
    parser.add_argument("--only", metavar="NAME", help="scenarios by letter or name, comma-separated: a,c or timer")
    args = parser.parse_args(argv)
    scenarios = select(args.only)
    start = time.perf_counter()
    results: list[Result] = []
    for scenario in scenarios:
        print(f"{scenario.letter}. {scenario.name}…", file=sys.stderr, flush=True)
        results += scenario.run(args.quick)
    wall = time.perf_counter() - start
    print(table(results))
    print()
    print(check(results, "".join(s.letter for s in scenarios)))
    print(f"\n{len(scenarios)} scenario(s) in {wall:.0f} s", file=sys.stderr)
    if not args.quick and not args.only:
        write(results, wall)
        print("wrote BENCHMARKS.md", file=sys.stderr)


if __name__ == "__main__":
    main()
