"""Runs ros2/rclpy's own unit tests (its ``rclpy/test/`` folder) on actors' overlay, beside real rclpy.

    python scripts/rclpy_suite.py /path/to/rclpy/test --real /path/to/ros/python

Every ``test_*.py`` of the folder runs in a pytest process of its own, as
rclpy's CMake runs them, with a per-file timeout (a file that hangs is stopped
and its unfinished tests count as not passed).  The only glue is a pytest
plugin this script writes into a temporary folder: for the actors run it
installs the overlay (``import rclpy`` is actors), for the real run it only
records outcomes.  rclpy's tests are read where they are and never copied.

Without ``--real`` it prints actors' counts per file; with it, also real
rclpy's, and how many of the tests real rclpy passes pass on actors too (a test
is the same on both sides by its id; a parameter that is an enum member is named
by the member's name there, as the two implementations' enums render otherwise).
``--failures`` lists every test that real rclpy passes and actors does not,
with the line pytest ended it on.  Exit status: 0 after a run, 2 on bad input.
"""

from __future__ import annotations

import argparse
import json
import os
import queue
import signal
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterable
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

__all__ = ["FileResult", "run_file", "run_folder", "main"]

_PLUGIN = "rclpy_suite_plugin"

# The plugin both runs load with ``-p``.  It appends one JSON line per test phase as it happens, so
# what a file did before it hung survives the kill.
_PLUGIN_SOURCE = '''\
"""Written by actors' scripts/rclpy_suite.py: records each test's outcome; installs the overlay if asked."""

import json
import os

_OUT = open(os.environ["RCLPY_SUITE_OUT"], "a", buffering=1)

# rclpy's test folder is a package whose __init__ points rclpy at the extension its CMake build
# made; an empty package of the same name stands in, so the tests import as they do there.
if os.environ.get("RCLPY_SUITE_PACKAGE"):
    import sys
    import types

    _folder = os.environ["RCLPY_SUITE_PACKAGE"]
    _package = types.ModuleType(os.path.basename(_folder))
    _package.__path__ = [_folder]
    sys.modules[_package.__name__] = _package

if os.environ.get("RCLPY_SUITE_OVERLAY") == "1":
    from actors.compat.overlay import install

    install()


def _write(**record):
    _OUT.write(json.dumps(record) + "\\n")


def pytest_runtest_logstart(nodeid, location):
    _write(test=nodeid, phase="start")


def pytest_runtest_logreport(report):
    message = ""
    if report.failed:
        crash = getattr(report.longrepr, "reprcrash", None)
        message = crash.message if crash is not None else str(report.longrepr).strip().splitlines()[-1:]
        message = message if isinstance(message, str) else " ".join(message)
    _write(test=report.nodeid, phase=report.when, outcome=report.outcome, message=message[:300])


def pytest_make_parametrize_id(config, val, argname):
    # An enum value is named by its member's name on both sides: pytest names an int-based enum
    # (actors' ClockType) by its number and a C one (rclpy's) by position, so the same test would
    # get two ids and could not be compared.
    name = getattr(val, "name", None)
    if isinstance(name, str) and hasattr(type(val), "__members__"):
        return f"{argname}-{name}"
    return None


def pytest_collectreport(report):
    if report.failed:
        _write(test=report.nodeid, phase="collect", outcome="failed", message=str(report.longrepr)[-300:])
'''


@dataclass
class FileResult:
    """What one test file did in one run: each test's outcome and why it failed."""

    name: str
    outcomes: dict[str, str] = field(default_factory=dict)  # test id -> passed/failed/error/skipped/hung
    messages: dict[str, str] = field(default_factory=dict)  # test id -> the line it failed on
    collect_error: str = ""
    timed_out: bool = False
    seconds: float = 0.0

    def count(self, outcome: str) -> int:
        """How many of this file's tests ended with ``outcome``."""
        return sum(1 for value in self.outcomes.values() if value == outcome)

    @property
    def passed(self) -> set[str]:
        """The ids of the tests that passed."""
        return {test for test, value in self.outcomes.items() if value == "passed"}


def _read_records(path: Path, result: FileResult) -> None:
    """Folds the plugin's phase records into one outcome per test."""
    if not path.exists():
        return
    for line in path.read_text().splitlines():
        try:
            record = json.loads(line)
        except ValueError:
            continue  # the last line of a killed process may be cut short
        test, phase = record["test"], record["phase"]
        if phase == "collect":
            result.collect_error = record.get("message", "")
            continue
        if phase == "start":
            result.outcomes[test] = "hung"  # until a later phase says otherwise
            continue
        outcome = record["outcome"]
        if outcome == "failed":
            result.outcomes[test] = "failed" if phase == "call" else "error"
            message = " ".join(str(record.get("message", "")).split())  # one line in the listing
            result.messages.setdefault(test, f"{phase}: {message}")
        elif outcome == "skipped":
            result.outcomes[test] = "skipped"
        elif phase == "call" and result.outcomes.get(test) == "hung":
            result.outcomes[test] = "passed"


def run_file(python: str, test_file: Path, *, overlay: bool, timeout: float, domain_id: int) -> FileResult:
    """Runs one test file in a pytest process of its own and reads back what each test did."""
    result = FileResult(test_file.name)
    with tempfile.TemporaryDirectory(prefix="rclpy_suite_") as tmp:
        folder = Path(tmp)
        (folder / f"{_PLUGIN}.py").write_text(_PLUGIN_SOURCE)
        out = folder / "outcomes.jsonl"
        env = dict(os.environ)
        env["PYTHONPATH"] = os.pathsep.join(filter(None, [tmp, env.get("PYTHONPATH", "")]))
        env["RCLPY_SUITE_OUT"] = str(out)
        env["RCLPY_SUITE_OVERLAY"] = "1" if overlay else "0"
        env["PYTHONDONTWRITEBYTECODE"] = "1"
        if (test_file.parent / "__init__.py").exists():
            env["RCLPY_SUITE_PACKAGE"] = str(test_file.parent)
        # Real rclpy's DDS discovers every participant on the machine: each file gets a domain of
        # its own and stays on the host, so files running side by side never hear each other.
        env["ROS_DOMAIN_ID"] = str(domain_id)
        env["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"
        command = [python, "-m", "pytest", "-p", _PLUGIN, "-p", "no:cacheprovider", "-q"]
        command += ["--rootdir", str(test_file.parent.parent), str(test_file)]  # ids as folder/file.py::test
        started = time.monotonic()
        proc = subprocess.Popen(
            command, cwd=tmp, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True
        )
        try:
            proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            result.timed_out = True
            os.killpg(proc.pid, signal.SIGKILL)  # its own session: the test's threads and children too
            proc.wait()
        result.seconds = time.monotonic() - started
        _read_records(out, result)
    return result


def run_folder(
    python: str, files: list[Path], *, overlay: bool, timeout: float, jobs: int, first_domain: int
) -> dict[str, FileResult]:
    """Runs every file, ``jobs`` at a time, each in its own process; files side by side get different domains."""
    domains: queue.SimpleQueue[int] = queue.SimpleQueue()
    for slot in range(jobs):
        domains.put(first_domain + slot)

    def one(path: Path) -> FileResult:
        domain = domains.get()
        try:
            return run_file(python, path, overlay=overlay, timeout=timeout, domain_id=domain)
        finally:
            domains.put(domain)

    with ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = [pool.submit(one, path) for path in files]
        return {path.name: future.result() for path, future in zip(files, futures, strict=True)}


def _test_files(folder: Path, patterns: Iterable[str]) -> list[Path]:
    files = sorted(folder.glob("test_*.py"))
    wanted = list(patterns)
    if wanted:
        files = [path for path in files if any(pattern in path.name for pattern in wanted)]
    return files


def _cell(result: FileResult | None) -> str:
    if result is None:
        return "-"
    total = len(result.outcomes)
    text = f"{result.count('passed')}/{total}"
    if result.collect_error and not total:
        text = "collect error"
    if result.timed_out:
        text += " (timeout)"
    return text


def report(actors: dict[str, FileResult], real: dict[str, FileResult] | None, *, failures: bool) -> str:
    """The per-file table, the totals, and (with ``failures``) each test real rclpy passes that actors fails."""
    lines = []
    header = f"{'file':40} {'actors':>18}"
    if real is not None:
        header += f" {'real rclpy':>18} {'both':>6}"
    lines.append(header)
    both_total = real_total = actors_total = tests_total = 0
    for name, mine in actors.items():
        row = f"{name:40} {_cell(mine):>18}"
        actors_total += mine.count("passed")
        tests_total += len(mine.outcomes)
        if real is not None:
            theirs = real.get(name)
            both = len(mine.passed & theirs.passed) if theirs else 0
            real_total += theirs.count("passed") if theirs else 0
            both_total += both
            row += f" {_cell(theirs):>18} {both:>6}"
        lines.append(row)
    seconds = sum(result.seconds for result in actors.values())
    lines.append(f"actors: {actors_total} passed of {tests_total} tests run ({seconds:.0f} s of process time)")
    if real is not None:
        share = 100.0 * both_total / real_total if real_total else 0.0
        lines.append(f"real rclpy: {real_total} passed; actors passes {both_total} of them ({share:.1f} %)")
    if failures:
        for name, mine in actors.items():
            expected = real[name].passed if real is not None and name in real else set(mine.outcomes)
            missing = sorted(test for test in expected if mine.outcomes.get(test) != "passed")
            if mine.collect_error and not mine.outcomes:
                lines.append(f"\n{name}: collect error: {mine.collect_error.strip().splitlines()[-1:]}")
                continue
            if not missing:
                continue
            lines.append(f"\n{name}:")
            for test in missing:
                outcome = mine.outcomes.get(test, "not run")
                lines.append(f"  {test.split('::', 1)[-1]}: {outcome} {mine.messages.get(test, '')}".rstrip())
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    """The command line: see the module docstring."""
    parser = argparse.ArgumentParser(prog="rclpy_suite.py", description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=Path, help="rclpy's test folder (rclpy/test in a ros2/rclpy checkout)")
    parser.add_argument("--real", metavar="PYTHON", help="a python with real rclpy and pytest: run there too")
    parser.add_argument("--python", default=sys.executable, help="the python with actors (default: this one)")
    parser.add_argument("--timeout", type=float, default=90.0, help="seconds one file may take (default 90)")
    parser.add_argument("--jobs", type=int, default=2, help="files run side by side (default 2)")
    parser.add_argument("--failures", action="store_true", help="list each test real rclpy passes and actors not")
    parser.add_argument("--json", type=Path, help="also write every test's outcome to this file")
    parser.add_argument("-k", dest="patterns", action="append", default=[], help="only files whose name holds this")
    args = parser.parse_args(argv)
    if not args.folder.is_dir():
        parser.error(f"{args.folder}: not a folder")
    files = _test_files(args.folder.resolve(), args.patterns)
    if not files:
        parser.error(f"{args.folder}: no test_*.py file (matching -k) in it")
    if args.jobs < 1 or args.timeout <= 0:
        parser.error("--jobs and --timeout must be positive")
    for python in filter(None, [args.python, args.real]):
        probe = subprocess.run([python, "-c", "import pytest"], capture_output=True)
        if probe.returncode != 0:
            parser.error(f"{python}: cannot import pytest there (pip install pytest into it)")
    actors = run_folder(args.python, files, overlay=True, timeout=args.timeout, jobs=args.jobs, first_domain=40)
    real = None
    if args.real:
        real = run_folder(args.real, files, overlay=False, timeout=args.timeout, jobs=args.jobs, first_domain=60)
    print(report(actors, real, failures=args.failures))
    if args.json:
        runs = {"actors": actors, **({"real": real} if real else {})}
        data = {run: {name: result.outcomes for name, result in results.items()} for run, results in runs.items()}
        args.json.write_text(json.dumps(data, indent=1, sort_keys=True))
    return 0


if __name__ == "__main__":
    sys.exit(main())
