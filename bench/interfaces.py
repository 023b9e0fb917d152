"""Interface discovery: the first and a cached import of a 30-type workspace package, each in a fresh process.

Run: ``python -m bench.interfaces``.  A workspace with one package of 30
messages (each a Header, a Pose, a sequence, a string and a constant) is
written to a temporary folder; each sample is a new interpreter that has
already imported actors (as a node or an rclpy script under ``actors run``
has; scenario e counts that start-up) and std_msgs and geometry_msgs (what
the package references), and times ``import interfaces.<pkg>.msg`` alone.  "First" starts from an
empty cache (parse, generate, write, compile); "cached" finds the module the
first import left.  The floor is the same import of a shipped package of
generated modules (sensor_msgs, 28 types).
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
from pathlib import Path

from bench.harness import ROOT, Result, child_env

__all__ = ["run", "import_time"]

TYPES = 30
PACKAGE = "bench_interfaces"
_TIMED = """
import time, actors, interfaces.std_msgs.msg, interfaces.geometry_msgs.msg
start = time.perf_counter()
import interfaces.{module}
print(time.perf_counter() - start)
"""


def write_workspace(folder: Path) -> Path:
    """A workspace of one package with ``TYPES`` messages; returns the workspace."""
    package = folder / "src" / PACKAGE
    (package / "msg").mkdir(parents=True)
    (package / "package.xml").write_text(f'<package format="3"><name>{PACKAGE}</name></package>\n')
    for i in range(TYPES):
        (package / "msg" / f"Thing{i}.msg").write_text(
            f"std_msgs/Header header\nstring name\nfloat64[] values\ngeometry_msgs/Pose pose\nuint8 KIND={i}\n"
        )
    return folder


def import_time(module: str, workspace: Path, cache: Path) -> float:
    """Seconds a fresh interpreter takes to import ``interfaces.<module>``, run in ``workspace``."""
    env = child_env() | {"ACTORS_INTERFACE_CACHE": str(cache), "PYTHONPATH": str(ROOT)}
    done = subprocess.run(
        [sys.executable, "-c", _TIMED.format(module=module)],
        cwd=workspace,
        env=env,
        capture_output=True,
        text=True,
        check=True,
        timeout=60,
    )
    return float(done.stdout)


def run(quick: bool = False) -> list[Result]:
    """First and cached import of the 30-type package, and the shipped floor, 5 samples each."""
    reps = 3 if quick else 5
    scenario = "m. interfaces, 30-type package import"
    with tempfile.TemporaryDirectory() as tmp:
        workspace = write_workspace(Path(tmp) / "ws")
        first, cached = [], []
        for i in range(reps):
            cache = Path(tmp) / f"cache{i}"
            first.append(import_time(f"{PACKAGE}.msg", workspace, cache))
            cached.append(import_time(f"{PACKAGE}.msg", workspace, cache))
        floor = [import_time("sensor_msgs.msg", workspace, Path(tmp) / "unused") for _ in range(reps)]
    return [
        Result(scenario, "first import (empty cache)", "s", first, False, baselines={"floor": "shipped floor"}),
        Result(scenario, "cached import", "s", cached, False, baselines={"floor": "shipped floor"}),
        Result(scenario, "shipped floor", "s", floor, False, note="sensor_msgs: committed generated modules"),
    ]


if __name__ == "__main__":
    for result in run("--quick" in sys.argv):
        print(f"{result.case}: median {result.median * 1000:.1f} ms ({len(result.samples)} samples)")
