"""What every benchmark shares: repetitions, medians with min–max, ratios, child processes, one table."""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, TypeVar

__all__ = [
    "ROOT",
    "Result",
    "repeat",
    "side_by_side",
    "fmt",
    "table",
    "standalone",
    "child_env",
    "run_child",
    "time_to_line",
    "uvloop_factory",
    "UVLOOP_HINT",
    "Loop",
    "run_on",
]

Loop = Callable[[], Any]  # an event loop factory

UVLOOP_HINT = "uvloop: not installed — pip install -e '.[fast]'"


def uvloop_factory() -> Callable[[], Any] | None:
    """actors' uvloop loop factory when uvloop is installed (the ``fast`` extra), else None."""
    try:
        import uvloop  # noqa: F401
    except ImportError:
        return None
    from actors.core.loops import uvloop_loop

    return uvloop_loop


def run_on(main: Callable[[], Any], loop: Loop | None) -> Any:
    """Run the coroutine function ``main`` on a new event loop from ``loop`` (asyncio's if None)."""
    with asyncio.Runner(loop_factory=loop) as runner:
        return runner.run(main())


ROOT = Path(__file__).resolve().parent.parent
T = TypeVar("T")


@dataclass
class Result:
    """One measured case: its samples in ``unit`` (higher is better when ``higher_better``).

    A case that could not be measured (a baseline not installed) has no samples
    and says why in ``note``.
    """

    scenario: str
    case: str
    unit: str
    samples: list[float]
    higher_better: bool = True
    note: str = ""
    baselines: dict[str, str] = field(default_factory=dict)  # name of a baseline -> its case name

    @property
    def median(self) -> float:
        return statistics.median(self.samples)

    def ratio(self, base: Result) -> float:
        """How many times better than ``base`` (>1 is better, whichever way the unit goes)."""
        return self.median / base.median if self.higher_better else base.median / self.median


def repeat(fn: Callable[[], T], times: int, *, warmup: bool = True) -> list[T]:
    """Call ``fn`` ``times`` times (after one warm-up call unless ``warmup`` is off) and return its results.

    Turn the warm-up off for measurements that start a fresh process each time:
    there is nothing in-process to warm.
    """
    if warmup:
        fn()
    return [fn() for _ in range(times)]


def micros_per_call(fn: Callable[[], object], loops: int) -> float:
    """Mean µs per call of ``fn`` over ``loops`` calls."""
    start = time.perf_counter()
    for _ in range(loops):
        fn()
    return (time.perf_counter() - start) / loops * 1e6


def side_by_side(fns: Mapping[str, Callable[[], T]], times: int, *, warmup: bool = True) -> dict[str, list[T]]:
    """Call each of ``fns`` ``times`` times, taking turns, and return each one's results by name.

    A case and its baselines measured in turn see the same moments of a shared
    machine: a slow minute costs each of them a sample, where measuring one
    case's samples and then the next's would charge it to one side and bend
    the ratio between them.  ``warmup`` as in :func:`repeat`, one call each.
    """
    if warmup:
        for fn in fns.values():
            fn()
    samples: dict[str, list[T]] = {name: [] for name in fns}
    for _ in range(times):
        for name, fn in fns.items():
            samples[name].append(fn())
    return samples


def fmt(value: float) -> str:
    """A number as the table shows it: thousands separators when large, 3 significant digits when small."""
    if value >= 100_000:
        return f"{value:,.0f}"
    if value >= 100:
        return f"{value:.0f}"
    return f"{value:.3g}"


def table(results: Sequence[Result]) -> str:
    """A Markdown table: median, min–max, and each case's ratio to its baselines."""
    by_case = {(r.scenario, r.case): r for r in results}
    lines = [
        "| scenario | case | median | min–max | unit | vs baselines |",
        "|---|---|---:|---:|---|---|",
    ]
    for r in results:
        ratios = []
        for label, case in r.baselines.items():
            base = by_case.get((r.scenario, case))
            if base is None or not base.samples or not r.samples:
                ratios.append(f"{label}: n/a")
            else:
                ratios.append(f"{r.ratio(base):.2f}× {label}")
        if r.samples:
            median, span = fmt(r.median), f"{fmt(min(r.samples))}–{fmt(max(r.samples))}"
        else:
            median = span = "—"
        extra = "; ".join(ratios + ([r.note] if r.note else []))
        lines.append(f"| {r.scenario} | {r.case} | {median} | {span} | {r.unit} | {extra} |")
    return "\n".join(lines)


def standalone(run: Callable[[bool], list[Result]], doc: str, quick_help: str) -> None:
    """``python -m bench.<scenario> [--quick]``: run one scenario module and print its table.

    ``doc`` is the module's docstring: its first line describes the command.
    """
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help=quick_help)
    print(table(run(parser.parse_args().quick)))


def child_env(extra: Mapping[str, str] | None = None) -> dict[str, str]:
    """The environment for a child Python: the repository importable, output unbuffered.

    ``_ROS_WHEELS_BOOTSTRAP_COMPLETE`` stops the ROS wheels' start-up hook from
    re-executing every Python of the venv (it sets LD_LIBRARY_PATH for rclpy):
    actors needs none of it, so its start-up is measured as a user without the
    ``bench-ros`` extra sees it.  ``bench.ros`` leaves the hook on for rclpy.
    """
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (str(ROOT), env.get("PYTHONPATH", "")) if p)
    env["PYTHONUNBUFFERED"] = "1"
    env["_ROS_WHEELS_BOOTSTRAP_COMPLETE"] = "1"
    env.update(extra or {})
    return env


def run_child(args: Sequence[str], env: Mapping[str, str] | None = None, timeout: float = 600) -> Any:
    """Run ``python ARGS`` from the repository root and decode the JSON of its last output line.

    Raises RuntimeError with the child's last error line when it fails.
    """
    proc = subprocess.run(
        [sys.executable, *args], cwd=ROOT, env=env or child_env(), capture_output=True, text=True, timeout=timeout
    )
    lines = proc.stdout.strip().splitlines()
    if proc.returncode != 0 or not lines:
        errors = proc.stderr.strip().splitlines() or [f"exit code {proc.returncode}"]
        raise RuntimeError(errors[-1])
    return json.loads(lines[-1])


def time_to_line(
    args: Sequence[str],
    marker: str,
    env: Mapping[str, str] | None = None,
    timeout: float = 60,
    *,
    stderr_too: bool = False,
) -> float:
    """Seconds from starting ``python ARGS`` until it prints a line containing ``marker`` (on stdout, or
    with ``stderr_too`` on either: rclpy programs log on stderr).

    The child is then stopped with SIGTERM (killed if it lingers, or once
    ``timeout`` seconds have passed).  Raises RuntimeError, with the child's last
    error line, if it ends before printing the marker.
    """
    with tempfile.TemporaryFile("w+") as errors:
        start = time.perf_counter()
        proc = subprocess.Popen(
            [sys.executable, *args],
            cwd=ROOT,
            env=env or child_env(),
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT if stderr_too else errors,
            text=True,
        )
        watchdog = threading.Timer(timeout, proc.kill)
        watchdog.start()
        try:
            assert proc.stdout is not None
            for line in proc.stdout:
                if marker in line:
                    return time.perf_counter() - start
            errors.seek(0)
            last = (errors.read().strip().splitlines() or [f"exit code {proc.wait()}"])[-1]
            raise RuntimeError(f"{' '.join(args)} never printed {marker!r}: {last}")
        finally:
            watchdog.cancel()
            proc.terminate()
            try:
                proc.communicate(timeout=10)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.communicate()
