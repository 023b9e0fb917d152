"""``python -m bench.rclpy_layer``: the same rclpy programs under real rclpy and under ``actors run``, side by side."""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import NamedTuple

from bench.harness import child_env, fmt
from bench.ros import ros_env

__all__ = ["PROGRAMS", "main"]

TIMEOUT = 120.0  # seconds a program may take before it counts as failed

# Every program starts with PRELUDE.  The service is std_srvs' SetBool, as small as example_interfaces'
# AddTwoInts, which the ROS 2 wheels on PyPI do not ship; it is served by a second node, as actors
# refuses a node's calls to its own service (DESIGN.md, "One service call") where rclpy allows them.
PRELUDE = """\
import statistics
import threading
import time

import rclpy
from rclpy.executors import MultiThreadedExecutor
from std_msgs.msg import String
from std_srvs.srv import SetBool

SECONDS = 2.0
rclpy.init()
node = rclpy.create_node("bench")
server = rclpy.create_node("server")
received = 0


def on_msg(msg):
    global received
    received += 1


def answer(request, response):
    response.success = request.data
    return response


def matched(publisher):
    while received == 0:
        publisher.publish(String(data="hello"))
        rclpy.spin_once(node, timeout_sec=0.1)


def timed_loop(step):
    for _ in range(100):
        step()
    count, start = 0, time.perf_counter()
    while time.perf_counter() - start < SECONDS:
        step()
        count += 1
    return count / (time.perf_counter() - start)

"""

PUBLISH = """\
node.create_subscription(String, "chatter", on_msg, 10)
publisher = node.create_publisher(String, "chatter", 10)
matched(publisher)
msg = String(data="hello")
start = time.perf_counter()
for _ in range(20_000):
    publisher.publish(msg)
print((time.perf_counter() - start) / 20_000 * 1e6)
"""

PUBLISH_SPIN = """\
node.create_subscription(String, "chatter", on_msg, 10)
publisher = node.create_publisher(String, "chatter", 10)
matched(publisher)
msg = String(data="hello")


def step():
    publisher.publish(msg)
    rclpy.spin_once(node, timeout_sec=1.0)


rate, before = timed_loop(step), received
rclpy.spin_once(node, timeout_sec=0.1)
assert received > 0.9 * before, f"{received} deliveries"
print(rate)
"""

SERVICE = """\
server.create_service(SetBool, "set", answer)
rclpy.get_global_executor().add_node(server)
client = node.create_client(SetBool, "set")
assert client.wait_for_service(timeout_sec=5.0)
request = SetBool.Request(data=True)


def step():
    future = client.call_async(request)
    rclpy.spin_until_future_complete(node, future, timeout_sec=5)
    assert future.result().success


print(timed_loop(step))
"""

THREADED_CALL = """\
server.create_service(SetBool, "set", answer)
client = node.create_client(SetBool, "set")
request = SetBool.Request(data=True)
executor = MultiThreadedExecutor()
executor.add_node(node)
executor.add_node(server)
rates = []


def step():
    assert client.call(request, timeout_sec=5.0).success


def caller():
    assert client.wait_for_service(timeout_sec=5.0)
    rates.append(timed_loop(step))


thread = threading.Thread(target=caller)
thread.start()
while thread.is_alive():
    executor.spin_once(timeout_sec=0.1)
print(rates[0])
"""

TIMER = """\
PERIOD = 0.001
stamps = []
start = time.monotonic()
node.create_timer(PERIOD, lambda: stamps.append(time.monotonic()))
while time.monotonic() - start < SECONDS:
    rclpy.spin_once(node, timeout_sec=0.1)
late = [(stamp - start - (k + 1) * PERIOD) * 1e6 for k, stamp in enumerate(stamps)]
cuts = statistics.quantiles(late, n=100)
print(cuts[49], cuts[98], len(stamps))
"""


# The TurtleBot rows: the course's world and robot for one simulated hour on the virtual clock, start-up
# included, driven at 10 Hz by the native ConstantControl node (the baseline) and by an rclpy
# controller under actors run that reads /odom (20 Hz) and publishes /cmd_vel from a 10 Hz timer.
SIM_SECONDS = 3600.0
WORLD = """\
[[nodes]]
use = "world.sim:World"
params = { world = "signs", image = "" }

[[nodes]]
use = "world.robot:TurtleBot"
params = { model = "burger", x = 0.0, y = 0.0, theta = 0.0 }
"""
NATIVE_CONTROL = """
[[nodes]]
use = "nodes.constant_control:ConstantControl"
params = { v = 0.2, omega = 0.2 }
"""
CONTROLLER = """\
import sys

import rclpy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rclpy.node import Node
from sensor_msgs.msg import LaserScan


class Controller(Node):
    def __init__(self):
        super().__init__("controller")
        self.x = 0.0
        self.cmd_vel = self.create_publisher(Twist, "/cmd_vel", 10)
        self.create_subscription(Odometry, "/odom", self.on_odom, 10)
        self.create_timer(0.1, self.tick)
        self.nearest = float("inf")
        if "--scan" in sys.argv:  # the scan too (10 Hz): the world casts the lidar only for a reader
            self.create_subscription(LaserScan, "/scan", self.on_scan, 10)

    def on_odom(self, msg):
        self.x = msg.pose.pose.position.x

    def on_scan(self, msg):
        self.nearest = min(msg.ranges)

    def tick(self):
        cmd = Twist()
        cmd.linear.x = 0.2 if self.x < 1.0 else -0.2
        cmd.angular.z = 0.2
        self.cmd_vel.publish(cmd)


rclpy.init()
try:
    rclpy.spin(Controller())
except KeyboardInterrupt:
    pass
"""


def turtlebot_rows(folder: Path, rounds: int) -> list[str]:
    """Wall seconds per simulated hour, native controller and rclpy controllers, rounds interleaved."""
    (folder / "native.toml").write_text(WORLD + NATIVE_CONTROL)
    (folder / "world.toml").write_text(WORLD)
    (folder / "controller.py").write_text(CONTROLLER)
    virtual = ["--clock", "virtual", "--duration", str(SIM_SECONDS)]
    commands = {
        "native ConstantControl node (python -m actors.run)": [
            sys.executable, "-m", "actors.run", str(folder / "native.toml"), *virtual
        ],
        "rclpy controller reading /odom (actors run --graph)": [
            sys.executable, "-m", "actors", "run", *virtual, "--graph", str(folder / "world.toml"),
            str(folder / "controller.py"),
        ],
        "rclpy controller reading /odom and /scan": [
            sys.executable, "-m", "actors", "run", *virtual, "--graph", str(folder / "world.toml"),
            str(folder / "controller.py"), "--scan",
        ],
    }  # fmt: skip
    walls: dict[str, list[float]] = {name: [] for name in commands}
    for _ in range(rounds):
        for name, command in commands.items():
            start = time.perf_counter()
            proc = subprocess.run(command, env=child_env(), capture_output=True, text=True, timeout=5 * TIMEOUT)
            if proc.returncode != 0:
                raise RuntimeError(f"{name}: {(proc.stderr.strip().splitlines() or ['failed'])[-1]}")
            walls[name].append((time.perf_counter() - start) * 3600.0 / SIM_SECONDS)
    lines = ["| TurtleBot, 10 Hz control, virtual clock | unit | median | spread |", "|---|---|---:|---|"]
    for name, values in walls.items():
        lines.append(f"| {name} | wall s per simulated hour | {fmt(statistics.median(values))} "
                     f"| {fmt(min(values))}–{fmt(max(values))} |")  # fmt: skip
    return lines


class Row(NamedTuple):
    """One number a program prints: what it is, its unit, and whether higher is better."""

    name: str
    unit: str
    higher_better: bool


PROGRAMS: dict[str, tuple[str, tuple[Row, ...]]] = {  # program name: (its code after PRELUDE, the rows it prints)
    "publish": (PUBLISH, (Row("1. publisher.publish(msg), 20k calls", "µs/call", False),)),
    "publish_spin": (PUBLISH_SPIN, (Row("2. publish + spin_once loop", "iterations/s", True),)),
    "service": (SERVICE, (Row("3. call_async + spin_until_future_complete", "calls/s", True),)),
    "threaded_call": (THREADED_CALL, (Row("4. Client.call from a thread, MultiThreadedExecutor", "calls/s", True),)),
    "timer": (
        TIMER,
        (
            Row("5. 1 kHz timer lateness p50", "µs", False),
            Row("5. 1 kHz timer lateness p99", "µs", False),
            Row("5. 1 kHz timer callbacks in 2 s (a missed one makes the later ones late)", "callbacks", True),
        ),
    ),
}


def run(command: Sequence[str], env: Mapping[str, str]) -> list[float]:
    """The numbers on the last line ``command`` prints; RuntimeError with its last error line if it fails."""
    try:
        proc = subprocess.run(command, env=env, capture_output=True, text=True, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        raise RuntimeError(f"no result within {TIMEOUT:.0f} s") from None
    lines = proc.stdout.strip().splitlines()
    if proc.returncode != 0 or not lines:
        raise RuntimeError((proc.stderr.strip().splitlines() or [f"exit code {proc.returncode}"])[-1])
    return [float(word) for word in lines[-1].split()]


def imports_rclpy(python: str) -> bool:
    """Whether ``python`` can import rclpy (with the environment its programs get)."""
    try:
        proc = subprocess.run([python, "-c", "import rclpy"], env=ros_env(), capture_output=True, timeout=60)
    except (OSError, subprocess.TimeoutExpired):
        return False
    return proc.returncode == 0


def main(argv: Sequence[str] | None = None) -> None:
    """Write the programs, run them round after round on both sides, print the table."""
    parser = argparse.ArgumentParser(prog="python -m bench.rclpy_layer", description=__doc__.splitlines()[0])
    parser.add_argument(
        "--rclpy-python", metavar="PATH", help="a Python that imports rclpy (default: $RCLPY_PYTHON, else this one)"
    )
    parser.add_argument("--rounds", type=int, default=5, help="runs of each program on each side (default 5)")
    args = parser.parse_args(argv)
    sides = {"actors": lambda script: ([sys.executable, "-m", "actors", "run", script], child_env())}
    python = args.rclpy_python or os.environ.get("RCLPY_PYTHON") or sys.executable
    if not imports_rclpy(python):
        print(f"rclpy: {python} cannot import it (pass --rclpy-python PATH or set RCLPY_PYTHON); its column is skipped")
    else:
        sides = {"rclpy": lambda script: ([python, script], ros_env()), **sides}
    samples: dict[tuple[str, str], list[list[float]]] = {}
    failed: set[tuple[str, str]] = set()
    with tempfile.TemporaryDirectory(prefix="bench-rclpy-layer-") as tmp:
        for program, (code, _) in PROGRAMS.items():
            (Path(tmp) / f"{program}.py").write_text(PRELUDE + code)
        for round_ in range(args.rounds):
            order = list(sides) if round_ % 2 == 0 else list(sides)[::-1]  # neither side always goes first
            for program in PROGRAMS:
                for side in order:
                    if (program, side) in failed:
                        continue
                    try:
                        samples.setdefault((program, side), []).append(run(*sides[side](f"{tmp}/{program}.py")))
                    except (RuntimeError, ValueError) as exc:
                        failed.add((program, side))
                        print(f"{program} under {side}: failed: {exc}", flush=True)
            print(f"round {round_ + 1} of {args.rounds}", file=sys.stderr, flush=True)
    lines = ["| program | unit | rclpy | actors | actors/rclpy | better |", "|---|---|---:|---:|---:|---|"]
    for program, (_, rows) in PROGRAMS.items():
        for i, row in enumerate(rows):
            medians = {
                side: statistics.median(s[i] for s in samples[(program, side)])
                for side in sides
                if (program, side) not in failed
            }
            rclpy, actors = medians.get("rclpy"), medians.get("actors")
            ratio = better = ""
            if rclpy is not None and actors is not None:
                ratio = f"{actors / rclpy:.2f}×"
                better = "actors" if (actors > rclpy) == row.higher_better else "rclpy"
            cells = [fmt(rclpy) if rclpy is not None else "—", fmt(actors) if actors is not None else "—"]
            lines.append(f"| {row.name} | {row.unit} | {' | '.join(cells)} | {ratio} | {better} |")
    print("\n".join(lines))
    print(f"\n{args.rounds} rounds, sides alternating; medians. Ratios are actors/rclpy for every row.")
    with tempfile.TemporaryDirectory(prefix="bench-rclpy-layer-") as tmp:
        print("\n" + "\n".join(turtlebot_rows(Path(tmp), args.rounds)))


if __name__ == "__main__":
    main()
