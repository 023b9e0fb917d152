"""``python -m bench.revisions REV [REV ...]``: the in-process rows of git revisions side by side, alternating.

Each revision's tree is exported (``git archive``) to a temporary directory.
Then, round after round, every revision measures each row (a. one-way,
b. fan-out 1→10, c. service round trip, g. the simulation's real-time factor
through the nodes and for the bare core) in a fresh child process that
imports that tree's ``actors`` and ``bench``, so that whatever the machine
does meanwhile falls on all revisions alike.  Prints a Markdown table:
medians, min–max, each revision's ratio to the first one (× its speed) and,
for the actors rows, the median against the same revision's baseline row of
the same rounds, as the targets read it: × the direct call's rate (a, b),
× the bare future+Queue's time per call (c), × the core's real-time factor (g).
``--only c`` measures only scenario c;
``--cpu`` counts the children's CPU time instead of wall time (the rows time
themselves with ``time.perf_counter``, which then reads ``process_time``), so
that time the machine gives to other processes counts for no revision.
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tarfile
import tempfile
from collections.abc import Sequence
from pathlib import Path

from bench.harness import ROOT, child_env, fmt

__all__ = ["ROWS", "main"]

_CALLS = "from bench.services import actors_call_time, future_call_time; print"
ROWS = {
    # row: (the child's Python, unit, higher is better); the child prints one number.  The
    # floors and bare futures are each revision's own copy of the baseline, measured in the
    # same rounds: the actors rows' ratios to them are this run's.
    "a. one-way": ("from bench.throughput import actors_rate; print(actors_rate(100_000, 1))", "deliveries/s", True),
    "a. direct call (floor)": (
        "from bench.throughput import floor_rate; print(floor_rate(100_000, 1))",
        "deliveries/s",
        True,
    ),
    "b. fan-out 1→10": (
        "from bench.throughput import actors_rate; print(actors_rate(10_000, 10))",
        "deliveries/s",
        True,
    ),
    "b. direct call (floor)": (
        "from bench.throughput import floor_rate; print(floor_rate(10_000, 10))",
        "deliveries/s",
        True,
    ),
    "c. service sequential": (f"{_CALLS}(actors_call_time(20_000, 1))", "µs/call", False),
    "c. service sequential, timeout=5": (f"{_CALLS}(actors_call_time(20_000, 1, 5.0))", "µs/call", False),
    "c. future+Queue sequential": (f"{_CALLS}(future_call_time(20_000, 1))", "µs/call", False),
    "c. service 100 callers": (f"{_CALLS}(actors_call_time(20_000, 100))", "µs/call", False),
    "c. service 100 callers, timeout=5": (f"{_CALLS}(actors_call_time(20_000, 100, 5.0))", "µs/call", False),
    "c. future+Queue 100 callers": (f"{_CALLS}(future_call_time(20_000, 100))", "µs/call", False),
    **{
        f"g. {row}, {robots} robot{'s' if robots > 1 else ''}": (
            f"from bench.sim import {factor}; print({factor}({robots}, 30.0))",
            "× real time",
            True,
        )
        for robots in (1, 20, 100)
        for row, factor in (("nodes", "nodes_factor"), ("core (floor)", "core_factor"))
    },
}
BASELINES = {  # row: the row it is shown against, in the targets' terms (× the floor's rate, × the future's time)
    "a. one-way": "a. direct call (floor)",
    "b. fan-out 1→10": "b. direct call (floor)",
    "c. service sequential": "c. future+Queue sequential",
    "c. service sequential, timeout=5": "c. future+Queue sequential",
    "c. service 100 callers": "c. future+Queue 100 callers",
    "c. service 100 callers, timeout=5": "c. future+Queue 100 callers",
    **{f"g. nodes, {n}": f"g. core (floor), {n}" for n in ("1 robot", "20 robots", "100 robots")},
}


def export(revision: str, into: Path) -> Path:
    """The tree of ``revision`` (this repository's) in a new folder under ``into``."""
    tree = into / revision.replace("/", "_")
    tree.mkdir()
    archive = subprocess.run(["git", "-C", str(ROOT), "archive", revision], check=True, capture_output=True).stdout
    tar = into / f"{tree.name}.tar"
    tar.write_bytes(archive)
    with tarfile.open(tar) as files:
        files.extractall(tree, filter="data")
    return tree


def measure(tree: Path, code: str, cpu: bool = False) -> float:
    """Run ``code`` in a child whose first import path is ``tree``; the number it prints.

    With ``cpu``, the child's ``time.perf_counter`` is its CPU time.
    """
    if cpu:
        code = f"import time; time.perf_counter = time.process_time; {code}"
    env = child_env({"PYTHONPATH": str(tree)})
    proc = subprocess.run([sys.executable, "-c", code], cwd=tree, env=env, capture_output=True, text=True, timeout=600)
    if proc.returncode != 0:
        raise RuntimeError(f"{tree.name}: {(proc.stderr.strip().splitlines() or ['no output'])[-1]}")
    return float(proc.stdout.strip().splitlines()[-1])


def main(argv: Sequence[str] | None = None) -> None:
    """Export the revisions, measure them in alternating rounds, print the table."""
    parser = argparse.ArgumentParser(prog="python -m bench.revisions", description=__doc__.splitlines()[0])
    parser.add_argument("revisions", nargs="+", metavar="REV", help="git revisions; ratios are to the first")
    parser.add_argument("--rounds", type=int, default=7, help="measurements per revision and row (default 7)")
    parser.add_argument(
        "--only", metavar="LETTERS", default="abc", help="the scenarios to measure, e.g. c (default abc)"
    )
    parser.add_argument("--cpu", action="store_true", help="time the rows in CPU time, not wall time")
    args = parser.parse_args(argv)
    rows = {row: spec for row, spec in ROWS.items() if row[0] in args.only}
    samples: dict[tuple[str, str], list[float]] = {}
    with tempfile.TemporaryDirectory(prefix="bench-revisions-") as tmp:
        trees = {rev: export(rev, Path(tmp)) for rev in args.revisions}
        for round_ in range(args.rounds):
            order = args.revisions if round_ % 2 == 0 else args.revisions[::-1]  # neither always goes first
            for row, (code, _, _) in rows.items():
                for rev in order:
                    samples.setdefault((row, rev), []).append(measure(trees[rev], code, args.cpu))
            print(f"round {round_ + 1} of {args.rounds}", file=sys.stderr, flush=True)
    first = args.revisions[0]
    lines = [
        f"| row | revision | median | min–max | unit | vs {first} | vs baseline |",
        "|---|---|---:|---:|---|---|---|",
    ]
    for row, (_, unit, higher) in rows.items():
        base = statistics.median(samples[(row, first)])
        for rev in args.revisions:
            values = samples[(row, rev)]
            median = statistics.median(values)
            ratio = median / base if higher else base / median
            span = f"{fmt(min(values))}–{fmt(max(values))}"
            base_row = BASELINES.get(row)
            if base_row in rows:  # read as the targets read: rate ÷ the floor's, time ÷ the future's
                versus = f"{median / statistics.median(samples[(base_row, rev)]):.3f}×"
            else:
                versus = ""
            lines.append(f"| {row} | {rev} | {fmt(median)} | {span} | {unit} | {ratio:.3f}× | {versus} |")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
