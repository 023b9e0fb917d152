"""On the virtual clock a run of rclpy programs is repeatable: the same output, byte for byte."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from actors.recording.reader import Bag
from tests.test_compat_launcher import ROOT, actors_run, python_env, script

RUNS = 10

PAIRS = {
    "talker and listener": ("--duration", "3", "--with", script("listener.py"), script("talker.py")),
    "action server and client": (
        "--duration",
        "30",
        "--with",
        script("fibonacci_action_server.py"),
        script("fibonacci_action_client.py"),
        "5",
    ),
    "service server and client": (
        "--duration",
        "10",
        "--with",
        script("add_two_ints_server.py"),
        script("add_two_ints_client.py"),
        "2",
        "3",
    ),
}


@pytest.mark.slow
@pytest.mark.parametrize("pair", list(PAIRS))
def test_a_pair_of_programs_prints_the_same_lines_in_every_run(pair: str) -> None:
    outputs = set()
    for _ in range(RUNS):
        done = actors_run("--clock", "virtual", *PAIRS[pair])
        assert done.returncode == 0, done.stderr
        outputs.add(done.stdout + done.stderr)
    assert len(outputs) == 1, f"{len(outputs)} different outputs in {RUNS} runs"
    (output,) = outputs
    assert output.count("\n") >= 2  # both programs spoke


@pytest.mark.slow
def test_a_teleop_script_fed_from_a_pipe_drives_the_turtlebot_the_same_way_in_every_run(tmp_path: Path) -> None:
    keys = "w\nw\na\nw\nd\nw\ns\nx\n"
    graph = str(ROOT / "graphs" / "turtlebot.toml")
    command = [sys.executable, "-m", "actors", "run", "--clock", "virtual", "--duration", "60", "--graph", graph]
    outputs = set()
    bags = set()
    for run in range(RUNS):
        bag = tmp_path / str(run) / "odom.mcap"  # one name: the bag's metadata names its file
        bag.parent.mkdir()
        done = subprocess.run(
            [*command, "--record", str(bag), "--topics", "/odom", "--", script("teleop_pipe.py")],
            cwd=ROOT,
            env=python_env(),
            input=keys,
            capture_output=True,
            text=True,
            timeout=60,
        )
        assert done.returncode == 0, done.stderr
        outputs.add(done.stdout)
        bags.add(bag.read_bytes())
    assert len(outputs) == 1, f"{len(outputs)} different drives in {RUNS} runs"
    assert len(bags) == 1, f"{len(bags)} different /odom recordings in {RUNS} runs"
    assert {topic.name: topic.count for topic in Bag(bag).topics} == {"/odom": 80}  # 20 Hz until "x" at 4 s
    (output,) = outputs
    assert [line.split()[0] for line in output.splitlines()] == keys.split()  # a pose after every key
