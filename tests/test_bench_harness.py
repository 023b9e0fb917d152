"""The benchmark harness measures a case and its baselines in turns, so a slow spell costs each a sample."""

from __future__ import annotations

import itertools
import subprocess
import sys

from conftest import ROOT

from bench.harness import side_by_side


def test_side_by_side_takes_turns_after_warming_each_once() -> None:
    calls: list[str] = []
    clock = itertools.count()

    def case(name: str):
        def measure() -> int:
            calls.append(name)
            return next(clock)

        return measure

    samples = side_by_side({"actors": case("actors"), "queue": case("queue"), "floor": case("floor")}, 3)
    assert calls == ["actors", "queue", "floor"] * 4  # the warm-up round, then three measured
    # Each sample of a round was taken next to the others' samples of that round, not in a block of its own.
    assert samples == {"actors": [3, 6, 9], "queue": [4, 7, 10], "floor": [5, 8, 11]}


def test_side_by_side_without_warm_up_measures_from_the_first_call() -> None:
    clock = itertools.count()
    assert side_by_side({"one": lambda: next(clock)}, 2, warmup=False) == {"one": [0, 1]}


def test_the_rclpy_side_of_the_cdr_bench_imports_neither_actors_nor_msgspec() -> None:
    # With msgspec imported, rclpy's decode of a large Image was many times slower in the same process.
    code = "import sys, bench.cdr_rclpy; print(sorted({m.split('.')[0] for m in sys.modules} & {'actors', 'msgspec'}))"
    found = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, check=True)
    assert found.stdout.strip() == "[]"
