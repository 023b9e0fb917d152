"""``actors lifecycle`` against an rclpy LifecycleNode run by ``actors run`` (wall clock), as ros2 lifecycle."""

from __future__ import annotations

import subprocess
import sys
from collections.abc import Iterator

import pytest
from conftest import ROOT, TESTS, python_env
from test_cli_live import GraphProcess

SCRIPT = TESTS / "rclpy_scripts" / "managed_blinker.py"


@pytest.fixture(scope="module")
def blinker() -> Iterator[GraphProcess]:
    running = GraphProcess(SCRIPT, runner=("-m", "actors", "run", "--timeout", "120"))
    try:
        running.wait_for("[watcher]: ready")
        yield running
    finally:
        running.stop()


def lifecycle(graph: GraphProcess, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "actors", "lifecycle", *args, "--graph", graph.name],
        cwd=ROOT, env=python_env(), capture_output=True, text=True, timeout=30,
    )  # fmt: skip


def ok(graph: GraphProcess, *args: str) -> str:
    done = lifecycle(graph, *args)
    assert (done.returncode, done.stderr) == (0, ""), done
    return done.stdout


@pytest.mark.slow
def test_a_managed_node_is_driven_through_its_states(blinker):
    assert ok(blinker, "nodes") == "/blinker\n"  # /watcher has no lifecycle
    assert ok(blinker, "get", "/blinker") == "unconfigured [1]\n"
    assert ok(blinker, "get") == "/blinker: unconfigured [1]\n"
    assert ok(blinker, "list", "blinker") == (
        "- configure [1]\n\tStart: unconfigured\n\tGoal: configuring\n"
        "- shutdown [5]\n\tStart: unconfigured\n\tGoal: shuttingdown\n"
    )
    assert ok(blinker, "set", "/blinker", "configure") == "Transitioning successful\n"
    mark = len(blinker.lines)
    blinker.wait_for("[blinker]: configured, coming from unconfigured", after=mark - 1)
    assert not any("saw blink" in line for line in blinker.lines)  # inactive: nothing delivered

    assert ok(blinker, "set", "/blinker", "3") == "Transitioning successful\n"  # activate, by id
    blinker.wait_for("[watcher]: saw blink", after=mark)
    assert ok(blinker, "get", "/blinker") == "active [3]\n"

    wrong = lifecycle(blinker, "set", "/blinker", "configure")
    assert wrong.returncode == 2
    assert (
        wrong.stderr == "actors: Unknown transition requested, available ones are:\n- deactivate [4]\n- shutdown [7]\n"
    )
    assert ok(blinker, "set", "/blinker", "deactivate") == "Transitioning successful\n"
    assert ok(blinker, "set", "/blinker", "cleanup") == "Transitioning successful\n"
    blinker.wait_for("[blinker]: cleaned up", after=mark)
    assert ok(blinker, "get", "/blinker") == "unconfigured [1]\n"
    graph = ok(blinker, "list", "-a", "/blinker")
    assert graph.count("- ") == 25 and "- transition_error [62]\n\tStart: errorprocessing\n\tGoal: finalized" in graph


@pytest.mark.slow
def test_a_node_without_a_lifecycle_is_not_found(blinker):
    done = lifecycle(blinker, "get", "/watcher")
    assert (done.returncode, done.stderr) == (2, "actors: Node not found: /watcher\n")
