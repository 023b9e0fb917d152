"""``python -m bench.revisions REV [REV ...]``: the in-process rows of git revisions side by side, alternating.

Each revision's tree is exported (``git archive``) to a temporary directory.
Then, round after round, every revision measures each row (a. one-way,
b. fan-out 1→10, c. service round trip) in a fresh child process that
imports that tree's ``actors`` and ``bench``, so that whatever the machine
does meanwhile falls on all revisions alike.  Prints a Markdown table:
medians, min–max, and each revision's ratio to the first one.
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

ROWS = {
    # row: (the child's Python, unit, higher is better); the child prints one number
    "a. one-way": ("from bench.throughput import actors_rate; print(actors_rate(100_000, 1))", "deliveries/s", True),
    "b. fan-out 1→10": ("from bench.throughput import actors_rate; print(actors_rate(10_000, 10))", "deliveries/s", True),
    "c. service sequential": ("from bench.services import actors_call_time; print(actors_call_time(20_000, 1))", "µs/call", False),
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


def measure(tree: Path, code: str) -> float:
    """Run ``code`` in a child whose first import path is ``tree``; the number it prints."""
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
    args = parser.parse_args(argv)
    samples: dict[tuple[str, str], list[float]] = {}
    with tempfile.TemporaryDirectory(prefix="bench-revisions-") as tmp:
        trees = {rev: export(rev, Path(tmp)) for rev in args.revisions}
        for round_ in range(args.rounds):
            order = args.revisions if round_ % 2 == 0 else args.revisions[::-1]  # neither always goes first
            for row, (code, _, _) in ROWS.items():
                for rev in order:
                    samples.setdefault((row, rev), []).append(measure(trees[rev], code))
            print(f"round {round_ + 1} of {args.rounds}", file=sys.stderr, flush=True)
    first = args.revisions[0]
    lines = [f"| row | revision | median | min–max | unit | vs {first} |", "|---|---|---:|---:|---|---|"]
    for row, (_, unit, higher) in ROWS.items():
        base = statistics.median(samples[(row, first)])
        for rev in args.revisions:
            values = samples[(row, rev)]
            median = statistics.median(values)
            ratio = median / base if higher else base / median
            span = f"{fmt(min(values))}–{fmt(max(values))}"
            lines.append(f"| {row} | {rev} | {fmt(median)} | {span} | {unit} | {ratio:.3f}× |")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
