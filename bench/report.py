"""BENCHMARKS.md: the machine, the versions, one full run's table and targets, and the notes kept below them.

Everything above the ``KEEP`` line is rewritten by each full run; everything
below it (what changed in the hot paths, profiles) is written by people and
kept as it is.
"""

from __future__ import annotations

import datetime
import os
import platform
from collections.abc import Sequence
from importlib import metadata
from pathlib import Path

from bench.harness import ROOT, Result, table
from bench.targets import check

__all__ = ["machine", "versions", "write"]

PATH = ROOT / "BENCHMARKS.md"
KEEP = "<!-- Written by people from here on: python -m bench keeps it. -->"
PACKAGES = ("actors", "anyio", "msgspec", "pymunk", "numpy", "ros-rclpy", "ros-rmw-fastrtps-cpp")


def _proc_field(path: str, key: str) -> str:
    """The value of the first ``key: value`` line of a /proc file, or "unknown"."""
    try:
        for line in Path(path).read_text().splitlines():
            name, _, value = line.partition(":")
            if name.strip() == key:
                return value.strip()
    except OSError:
        pass
    return "unknown"


def machine() -> str:
    """CPU model, cores, RAM and OS, as /proc and the platform module see them."""
    memory = _proc_field("/proc/meminfo", "MemTotal")
    if memory.endswith(" kB"):
        memory = f"{int(memory.split()[0]) / 1024**2:.1f} GiB"
    try:
        os_name = platform.freedesktop_os_release().get("PRETTY_NAME", platform.system())
    except OSError:
        os_name = platform.system()
    return (
        f"{_proc_field('/proc/cpuinfo', 'model name')}, {os.cpu_count()} cores, {memory} RAM; "
        f"{os_name}, kernel {platform.release()}"
    )


def versions() -> str:
    """Python and the versions of the packages that matter here (absent ones left out)."""
    found = [f"Python {platform.python_version()}"]
    for name in PACKAGES:
        try:
            found.append(f"{name} {metadata.version(name)}")
        except metadata.PackageNotFoundError:
            continue
    return ", ".join(found)


def write(results: Sequence[Result], wall: float, path: Path = PATH) -> None:
    """Rewrite the measured part of ``path``, keeping what people wrote below ``KEEP``."""
    kept = ""
    if path.exists():
        text = path.read_text()
        if KEEP in text:
            kept = text.split(KEEP, 1)[1].lstrip("\n")
    now = datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d %H:%M UTC")
    parts = [
        "# Benchmarks",
        "",
        "Written by `python -m bench` (the full suite, all baselines in the same run); "
        "reproduce with `pip install -e '.[bench-ros]'` (optional: the rclpy baselines) "
        "then `python -m bench`.  `python -m bench --quick` is a smoke run; "
        "`--only a,c` picks scenarios.",
        "",
        f"- Date: {now}; the run took {wall / 60:.1f} min",
        f"- Machine: {machine()}",
        f"- Versions: {versions()}",
        "",
        "Medians of 5 runs (each after a warm-up run, except where each run is a fresh "
        "process), min–max, and ratios to each baseline: above 1× means better than the "
        "baseline, whichever way the unit goes.",
        "",
        "## Results",
        "",
        table(results),
        "",
        "## Targets",
        "",
        check(results),
        "",
        KEEP,
        "",
        kept,
    ]
    path.write_text("\n".join(parts).rstrip("\n") + "\n")
