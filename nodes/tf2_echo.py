"""tf2_echo, as tf2_ros's: prints the transform between two frames, once per ``1 / echo_rate`` seconds.

Parameters ``source_frame`` and ``target_frame`` (the real program's two
arguments) and ``echo_rate`` (Hz, default 1); :func:`main` is the program,
``actors run tf2_ros tf2_echo SOURCE TARGET [RATE]``.  As in tf2_ros the printed
transform is the one that takes data from ``target_frame`` into
``source_frame``, at the latest time both have; until it exists, the node
logs ``Waiting for transform ...`` with tf2's reason.  The output is the real
program's, number for number (three decimals, RPY from the rotation matrix).
"""

from __future__ import annotations

import math
import sys

from actors import Node
from actors.errors import TransformException
from actors.ros.time import Time
from interfaces.geometry_msgs.msg import TransformStamped

from .tf_feed import feed

__all__ = ["Tf2Echo", "echo_text", "matrix", "roll_pitch_yaw", "main"]


def matrix(x: float, y: float, z: float, w: float) -> list[list[float]]:
    """The rotation matrix of a unit quaternion, rows first."""
    return [
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ]


def roll_pitch_yaw(m: list[list[float]]) -> tuple[float, float, float]:
    """Roll, pitch and yaw of a rotation matrix, as tf2's ``Matrix3x3::getEulerYPR`` finds them."""
    if abs(m[2][0]) >= 1:
        delta = math.atan2(m[0][1], m[0][2])
        if m[2][0] > 0:
            return delta, -math.pi / 2, 0.0
        return delta, math.pi / 2, 0.0
    pitch = -math.asin(m[2][0])
    c = math.cos(pitch)
    return math.atan2(m[2][1] / c, m[2][2] / c), pitch, math.atan2(m[1][0] / c, m[0][0] / c)


def echo_text(transform: TransformStamped) -> str:
    """What tf2_echo prints for one transform."""
    t, r = transform.transform.translation, transform.transform.rotation
    m = matrix(r.x, r.y, r.z, r.w)
    roll, pitch, yaw = roll_pitch_yaw(m)
    degrees = 180.0 / math.pi
    stamp = transform.header.stamp
    lines = [
        f"At time {stamp.sec}.{stamp.nanosec}",  # the nanoseconds unpadded, as the real one prints them
        f"- Translation: [{t.x:.3f}, {t.y:.3f}, {t.z:.3f}]",
        f"- Rotation: in Quaternion [{r.x:.3f}, {r.y:.3f}, {r.z:.3f}, {r.w:.3f}]",
        f"- Rotation: in RPY (radian) [{roll:.3f}, {pitch:.3f}, {yaw:.3f}]",
        f"- Rotation: in RPY (degree) [{roll * degrees:.3f}, {pitch * degrees:.3f}, {yaw * degrees:.3f}]",
        "- Matrix:",
    ]
    for row, offset in zip(m, (t.x, t.y, t.z)):
        lines.append("".join(f" {v:6.3f}" for v in (*row, offset)))
    lines.append("".join(f" {v:6.3f}" for v in (0.0, 0.0, 0.0, 1.0)))
    return "\n".join(lines)


class Tf2Echo(Node):
    """Node ``tf2_echo``: listens to ``/tf`` and ``/tf_static`` and prints one transform at ``echo_rate`` Hz."""

    def __init__(self) -> None:
        super().__init__("tf2_echo")
        self.source = self.declare_parameter("source_frame", "").value
        self.target = self.declare_parameter("target_frame", "").value
        rate = self.declare_parameter("echo_rate", 1.0).value
        self.buffer = feed(self)
        self.found = False
        self.create_timer(1.0 / rate, self.echo)

    def echo(self) -> None:
        """One tick: wait for the transform, then print it (or the failure, and the frames known)."""
        latest = Time()
        if not self.found:
            ok, why = self.buffer.can_transform_core(self.source, self.target, latest)
            if not ok:
                self.get_logger().info(f"Waiting for transform {self.source} ->  {self.target}: {why}")
                return
            self.found = True
        try:
            print(echo_text(self.buffer.lookup_transform_core(self.source, self.target, latest)), flush=True)
        except TransformException as exc:
            now = self.get_clock().now().nanoseconds / 1e9
            print(f"Failure at {now}\nException thrown:{exc}\nThe current list of frames is:", flush=True)
            print(self.buffer.all_frames_as_string(), flush=True)


USAGE = "usage: tf2_echo source_frame target_frame [echo_rate]"


def main() -> int:
    """``tf2_echo SOURCE TARGET [RATE]`` under ``actors run``: runs until the run ends; 2 for bad arguments."""
    from actors.compat.programs import run_native
    from actors.launch.rosargs import parse

    _, args = parse(sys.argv[1:])
    if len(args) not in (2, 3):
        print(f"{USAGE}\nEchoes the transform that takes data from target_frame into source_frame.", file=sys.stderr)
        return 2
    rate = 1.0
    if len(args) == 3:
        try:
            rate = float(args[2])
        except ValueError:
            rate = 0.0
        if not 0 < rate < math.inf:
            print(f"tf2_echo: echo_rate {args[2]!r} is not a positive number of Hz", file=sys.stderr)
            return 2
    run_native(Tf2Echo, "tf2_echo", {"source_frame": args[0], "target_frame": args[1], "echo_rate": rate})
    return 0
