"""The beginner CLI tutorials, page by page in our words: their commands, in order, against a running turtlesim.

The pages: Using turtlesim (its executables; its teleop is tests/test_world_turtlesim.py's and
test_compat_tf2.py's), Understanding nodes, topics, services, parameters and actions, Using
rqt_console (the log level it teaches; the live view stands for rqt), Launching nodes, Recording
and playing back data, Using ros2doctor.
"""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
from collections.abc import Iterator

import pytest
from conftest import ROOT, python_env
from test_cli_live import GraphProcess, actors, ok, started

pytestmark = pytest.mark.slow  # the command line runs as child processes beside a graph in another


@pytest.fixture(scope="module")
def turtlesim(tmp_path_factory: pytest.TempPathFactory) -> Iterator[GraphProcess]:
    path = tmp_path_factory.mktemp("graph") / f"turtlesim_{os.getpid()}.toml"
    path.write_text((ROOT / "graphs" / "turtlesim.toml").read_text())
    running = GraphProcess(path)
    try:
        running.wait_for("Spawning turtle [turtle1] at x=[5.544445], y=[5.544445], theta=[0.000000]")
        yield running
    finally:
        running.stop()


def pose(graph: GraphProcess, turtle: str = "turtle1") -> dict[str, float]:
    text = ok(graph, "topic", "echo", f"/{turtle}/pose", "--once")
    return {key: float(value) for key, value in re.findall(r"^(\w+): (\S+)$", text, re.M)}


def test_using_turtlesim():
    listed = subprocess.run(
        [sys.executable, "-m", "actors", "pkg", "executables", "turtlesim"],
        cwd=ROOT,
        env=python_env(),
        capture_output=True,
        text=True,
        timeout=30,
    )
    assert listed.stdout == (
        "turtlesim draw_square\nturtlesim mimic\nturtlesim turtle_teleop_key\nturtlesim turtlesim_node\n"
    ), listed.stderr


def test_understanding_nodes(turtlesim):
    assert "/turtlesim\n" in ok(turtlesim, "node", "list")
    info = ok(turtlesim, "node", "info", "/turtlesim")
    for line in (
        "    /turtle1/cmd_vel: geometry_msgs/msg/Twist",
        "    /turtle1/pose: turtlesim_msgs/msg/Pose",
        "    /spawn: turtlesim_msgs/srv/Spawn",
        "    /turtle1/rotate_absolute: turtlesim_msgs/action/RotateAbsolute",
    ):
        assert line in info


def test_understanding_nodes_remapping():
    # The page's second turtlesim, renamed on its command line; its log names it so
    renamed = ["turtlesim", "turtlesim_node", "--ros-args", "--remap", "__node:=my_turtle"]
    done = subprocess.run(
        [sys.executable, "-m", "actors", "run", "--clock", "virtual", "--duration", "0.5", *renamed],
        cwd=ROOT,
        env=python_env(),
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 0, done.stderr
    assert done.stderr.startswith("[INFO] [0.000000000] [my_turtle]: Starting turtlesim with node name /my_turtle\n")


def test_understanding_topics(turtlesim):
    listed = ok(turtlesim, "topic", "list", "-t")
    for line in (
        "/turtle1/cmd_vel [geometry_msgs/msg/Twist]",
        "/turtle1/color_sensor [turtlesim_msgs/msg/Color]",
        "/turtle1/pose [turtlesim_msgs/msg/Pose]",
    ):
        assert line in listed
    assert "Subscription count: 1" in ok(turtlesim, "topic", "info", "/turtle1/cmd_vel")
    shown = subprocess.run(
        [sys.executable, "-m", "actors", "interface", "show", "turtlesim_msgs/msg/Pose"],
        cwd=ROOT,
        env=python_env(),
        capture_output=True,
        text=True,
        timeout=30,
    )
    assert "float32 linear_velocity" in shown.stdout, shown.stderr
    ok(
        turtlesim,
        "service",
        "call",
        "/turtle1/teleport_absolute",
        "turtlesim_msgs/srv/TeleportAbsolute",
        "{x: 3.0, y: 3.0, theta: 0.0}",
    )
    assert (pose(turtlesim)["x"], pose(turtlesim)["y"]) == (3.0, 3.0)
    ok(
        turtlesim,
        "topic",
        "pub",
        "--once",
        "/turtle1/cmd_vel",
        "geometry_msgs/msg/Twist",
        "{linear: {x: 2.0, y: 0.0, z: 0.0}, angular: {x: 0.0, y: 0.0, z: 1.8}}",
    )
    moved = pose(turtlesim)
    assert moved["x"] != 3.0 or moved["theta"] != 0.0  # it drove an arc, for one second
    assert ok(turtlesim, "topic", "find", "geometry_msgs/msg/Twist") == "/turtle1/cmd_vel\n"
    # turtlesim publishes each pose once a 16 ms frame: 62.5 Hz on the wall clock, less when loaded
    rate = re.match(
        r"average rate: (\d+\.\d{3})\n\tmin: ", ok(turtlesim, "topic", "hz", "/turtle1/pose", "--count", "1")
    )
    assert rate and 10.0 < float(rate[1]) < 70.0, rate
    # a Pose is five float32 after CDR's four-byte header: 24 bytes
    bandwidth = ok(turtlesim, "topic", "bw", "/turtle1/pose", "--count", "1")
    assert re.search(
        r"^\d+\.\d{2} KB/s from \d+ messages\n\tMessage size mean: 0\.02 KB min: 0\.02 KB", bandwidth, re.M
    )
    ok(turtlesim, "service", "call", "/reset", "std_srvs/srv/Empty")
    ok(
        turtlesim,
        "topic",
        "pub",
        "-t",
        "3",
        "-r",
        "10",
        "/turtle1/cmd_vel",
        "geometry_msgs/msg/Twist",
        "{linear: {x: 2.0}}",
    )
    ahead = pose(turtlesim)  # straight on from the reset pose: x grows, y stays
    assert ahead["x"] > 5.6 and ahead["y"] == pytest.approx(5.544445, abs=1e-6) and ahead["theta"] == 0.0


def test_understanding_services(turtlesim):
    listed = ok(turtlesim, "service", "list")
    for name in ("/clear", "/kill", "/reset", "/spawn", "/turtle1/set_pen", "/turtle1/teleport_absolute"):
        assert f"{name}\n" in listed
    assert ok(turtlesim, "service", "type", "/clear") == "std_srvs/srv/Empty\n"
    assert ok(turtlesim, "service", "find", "std_srvs/srv/Empty") == "/clear\n/reset\n"
    spawned = ok(
        turtlesim, "service", "call", "/spawn", "turtlesim_msgs/srv/Spawn", "{x: 2, y: 2, theta: 0.2, name: ''}"
    )
    assert "turtlesim_msgs.srv.Spawn_Response(name='turtle2')" in spawned
    assert pose(turtlesim, "turtle2")["x"] == 2.0
    ok(turtlesim, "service", "call", "/kill", "turtlesim_msgs/srv/Kill", "{name: turtle2}")
    assert "/turtle2/pose" not in ok(turtlesim, "topic", "list")
    ok(turtlesim, "service", "call", "/clear", "std_srvs/srv/Empty")
    turtlesim.wait_for("Clearing turtlesim.")


def test_understanding_parameters(turtlesim):
    listed = ok(turtlesim, "param", "list")
    assert "/turtlesim:\n  background_b\n  background_g\n  background_r\n  holonomic\n" in listed
    assert ok(turtlesim, "param", "get", "/turtlesim", "background_g") == "Integer value is: 86\n"
    assert ok(turtlesim, "param", "set", "/turtlesim", "background_r", "150") == "Set parameter successful\n"
    dumped = ok(turtlesim, "param", "dump", "/turtlesim")
    assert "/turtlesim:\n  ros__parameters:\n" in dumped and "    background_r: 150\n" in dumped
    refused = actors(turtlesim, "param", "set", "/turtlesim", "background_r", "300")
    assert refused.returncode == 1 and "[0, 255]" in refused.stderr  # the descriptor's range refuses it


def test_understanding_actions(turtlesim):
    assert "/turtle1/rotate_absolute [turtlesim_msgs/action/RotateAbsolute]\n" in ok(turtlesim, "action", "list", "-t")
    info = ok(turtlesim, "action", "info", "/turtle1/rotate_absolute")
    assert "Action servers: 1\n    /turtlesim\n" in info
    result = ok(
        turtlesim,
        "action",
        "send_goal",
        "/turtle1/rotate_absolute",
        "turtlesim_msgs/action/RotateAbsolute",
        "{theta: 1.57}",
        "--feedback",
    )
    assert "Feedback:\n    remaining:" in result
    assert result.rstrip().endswith("Goal finished with status: SUCCEEDED")
    assert abs(pose(turtlesim)["theta"] - 1.57) < 0.02


def test_recording_and_playing_back_data(turtlesim, tmp_path):
    bag = tmp_path / "subset"
    recorder = started(turtlesim, "bag", "record", "-o", str(bag), "/turtle1/cmd_vel")
    try:
        for _ in range(50):  # until the recorder subscribes (topic info counts it)
            if "Subscription count: 2" in ok(turtlesim, "topic", "info", "/turtle1/cmd_vel"):
                break
        twist = "{linear: {x: 1.0, y: 0.0, z: 0.0}, angular: {x: 0.0, y: 0.0, z: 0.5}}"
        for _ in range(2):
            ok(turtlesim, "topic", "pub", "--once", "/turtle1/cmd_vel", "geometry_msgs/msg/Twist", twist)
    finally:
        recorder.send_signal(signal.SIGINT)
        assert recorder.wait(timeout=30) == 0, recorder.stderr.read() if recorder.stderr else ""
    info = subprocess.run(
        [sys.executable, "-m", "actors", "bag", "info", str(bag)],
        cwd=ROOT,
        env=python_env(),
        capture_output=True,
        text=True,
        timeout=30,
    )
    assert re.search(r"Topic: /turtle1/cmd_vel \| Type: geometry_msgs/msg/Twist \| Count: 2\b", info.stdout), info
    ok(turtlesim, "service", "call", "/reset", "std_srvs/srv/Empty")
    played = actors(turtlesim, "bag", "play", str(bag))
    assert (played.returncode, played.stderr) == (0, f"played 2 message(s) from {bag}\n")
    moved = pose(turtlesim)
    assert (moved["x"], moved["y"]) != (pytest.approx(5.544444), pytest.approx(5.544444))  # the replay drove it


def test_using_ros2doctor(turtlesim):
    # The page's first run: turtlesim alone publishes its pose and colour to nobody, as warnings
    checked = ok(turtlesim, "doctor")
    for topic in ("/turtle1/color_sensor (turtlesim_msgs/msg/Color)", "/turtle1/pose (turtlesim_msgs/msg/Pose)"):
        assert f"WARNING: publishers without subscribers: {topic} is published by /turtlesim" in checked
    assert checked.endswith(" checks passed\n")  # warnings, not failures


DRIVE = """
import rclpy
from geometry_msgs.msg import Twist

rclpy.init()
node = rclpy.create_node("drive")
publisher = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
ahead = Twist()
ahead.linear.x = 2.0
node.create_timer(1.0, lambda: publisher.publish(ahead))
rclpy.spin(node)
"""


def test_using_rqt_console_log_levels(tmp_path):
    # The page starts turtlesim at WARN and drives it into the wall once a second (topic pub -r 1).
    script = tmp_path / "drive.py"
    script.write_text(DRIVE)
    partner = "turtlesim turtlesim_node --ros-args --log-level WARN"
    done = subprocess.run(
        [
            sys.executable,
            "-m",
            "actors",
            "run",
            "--clock",
            "virtual",
            "--duration",
            "4",
            "--with",
            partner,
            str(script),
        ],
        cwd=ROOT,
        env=python_env(),
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 0, done.stderr
    lines = done.stderr.splitlines()
    assert lines and all(line.startswith("[WARN] ") for line in lines), lines[:3]  # no INFO start-up lines
    assert "[turtlesim]: Oh no! I hit the wall! (Clamping from [x=" in lines[0]


LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="turtlesim", namespace="turtlesim1", executable="turtlesim_node", name="sim"),
        Node(package="turtlesim", namespace="turtlesim2", executable="turtlesim_node", name="sim"),
        Node(
            package="turtlesim",
            executable="mimic",
            name="mimic",
            remappings=[
                ("/input/pose", "/turtlesim1/turtle1/pose"),
                ("/output/cmd_vel", "/turtlesim2/turtle1/cmd_vel"),
            ],
        ),
    ])
"""


def test_launching_nodes(tmp_path):
    path = tmp_path / "turtlesim_mimic_launch.py"
    path.write_text(LAUNCH)
    done = subprocess.run(
        [sys.executable, "-m", "actors", "launch", str(path), "--clock", "virtual", "--duration", "1"],
        cwd=ROOT,
        env=python_env(),
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 0, done.stderr
    out = done.stdout + done.stderr
    assert "Starting turtlesim with node name /turtlesim1/sim" in out
    assert "Starting turtlesim with node name /turtlesim2/sim" in out
    assert "[mimic-1]: process started" in out  # ros2 launch numbers each executable's processes
