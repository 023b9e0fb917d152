"""scripts/rclpy_suite.py: a folder of rclpy tests, each file in its own pytest process, counted per file."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import ROOT, python_env

pytestmark = pytest.mark.slow  # every file is a child pytest

SUITE = str(ROOT / "scripts" / "rclpy_suite.py")

# Tests of our own, shaped like rclpy's: one needs the overlay, one fails anywhere, one hangs.
FILES = {
    "test_needs_rclpy.py": """
import rclpy
from std_msgs.msg import String


def test_rclpy_is_the_overlay():
    assert "actors" in rclpy.__file__
    assert String(data="x").data == "x"


def test_a_context_comes_and_goes():
    rclpy.init()
    assert rclpy.ok()
    rclpy.shutdown()
    assert not rclpy.ok()
""",
    "test_fails.py": """
import enum

import pytest


class Colour(enum.IntEnum):
    RED = 1


class Shade(enum.Enum):
    DARK = object()


def test_ok():
    pass


@pytest.mark.parametrize("value", [Colour.RED, Shade.DARK])
def test_enum_parameters_are_named(value):
    pass


def test_wrong():
    assert 1 + 1 == 3
""",
    "test_hangs.py": """
import threading


def test_before():
    pass


def test_forever():
    threading.Event().wait()
""",
}


def _run(folder: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, SUITE, str(folder), *args], env=python_env(), capture_output=True, text=True, timeout=120
    )


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    tests = tmp_path / "test"
    tests.mkdir()
    for name, text in FILES.items():
        (tests / name).write_text(text)
    # rclpy's folder is a package whose __init__ only works in its CMake build: the suite skips it.
    (tests / "__init__.py").write_text("raise ImportError('the build folder is not here')\n")
    return tests


def test_each_file_is_counted_with_the_overlay_and_beside_another_python(folder, tmp_path):
    # The "real" run is this python without the overlay: there `import rclpy` fails to collect.
    out = tmp_path / "outcomes.json"
    args = ["--timeout", "90", "-k", "needs_rclpy", "-k", "fails", "--real", sys.executable, "--failures"]
    done = _run(folder, *args, "--json", str(out))
    assert done.returncode == 0, done.stderr
    outcomes = json.loads(out.read_text())
    assert outcomes["actors"] == {
        "test_needs_rclpy.py": {
            "test/test_needs_rclpy.py::test_rclpy_is_the_overlay": "passed",
            "test/test_needs_rclpy.py::test_a_context_comes_and_goes": "passed",
        },
        "test_fails.py": {
            "test/test_fails.py::test_ok": "passed",
            # An int-based and another enum get their member's name, whatever pytest would make of them.
            "test/test_fails.py::test_enum_parameters_are_named[value-RED]": "passed",
            "test/test_fails.py::test_enum_parameters_are_named[value-DARK]": "passed",
            "test/test_fails.py::test_wrong": "failed",
        },
    }
    assert outcomes["real"]["test_needs_rclpy.py"] == {}
    rows = {line.split()[0]: line.split()[1:] for line in done.stdout.splitlines()[1:3]}
    assert rows == {"test_fails.py": ["3/4", "3/4", "3"], "test_needs_rclpy.py": ["2/2", "collect", "error", "0"]}
    assert "actors: 5 passed of 6 tests run" in done.stdout
    assert "real rclpy: 3 passed; actors passes 3 of them (100.0 %)" in done.stdout
    # Only what the other python passes is listed as missing: test_wrong fails there too.
    assert "test_wrong" not in done.stdout


def test_a_file_that_hangs_is_stopped_and_its_unfinished_test_counted(folder, tmp_path):
    out = tmp_path / "outcomes.json"
    done = _run(folder, "--timeout", "10", "-k", "hangs", "--json", str(out), "--failures")
    assert done.returncode == 0, done.stderr
    assert json.loads(out.read_text())["actors"]["test_hangs.py"] == {
        "test/test_hangs.py::test_before": "passed",
        "test/test_hangs.py::test_forever": "hung",
    }
    assert done.stdout.splitlines()[1].split() == ["test_hangs.py", "1/2", "(timeout)"]
    assert "test_forever: hung" in done.stdout


def test_a_missing_folder_is_one_clear_error(tmp_path):
    done = _run(tmp_path / "nowhere")
    assert done.returncode == 2
    assert "nowhere: not a folder" in done.stderr
    assert "Traceback" not in done.stderr
