"""static_transform_publisher, as tf2_ros's: latches one transform on ``/tf_static``.

The node takes the real one's parameters (``translation.x/y/z``,
``rotation.x/y/z/w``, ``frame_id``, ``child_frame_id``, all read-only) and
logs what it publishes in the real one's words.  :func:`parse_args` reads the
real program's command line (``--x 1 --yaw 0.5 --frame-id world
--child-frame-id mystaticturtle``) into those parameters, refusing what it
refuses; :func:`main` is the program (``actors run tf2_ros
static_transform_publisher --x 1 ...``).  The real node's name gets a random
suffix; this one is ``static_transform_publisher`` unless ``-r __node:=`` names it.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Sequence
from typing import Any

from actors import DurabilityPolicy, Node, QoSProfile
from interfaces.geometry_msgs.msg import TransformStamped
from interfaces.rcl_interfaces.msg import ParameterDescriptor
from interfaces.tf2_msgs.msg import TFMessage

__all__ = ["USAGE", "StaticTransformPublisher", "parse_args", "main"]

USAGE = (
    "usage: static_transform_publisher [--x X] [--y Y] [--z Z] [--qx QX] [--qy QY] [--qz QZ] [--qw QW] "
    "[--roll ROLL] [--pitch PITCH] [--yaw YAW] --frame-id FRAME_ID --child-frame-id CHILD_FRAME_ID"
)
_NUMBERS = {"--x", "--y", "--z", "--qx", "--qy", "--qz", "--qw", "--roll", "--pitch", "--yaw"}


def parse_args(argv: Sequence[str]) -> dict[str, Any]:
    """The node's parameters from the real program's options; ValueError naming what is wrong."""
    given: dict[str, Any] = {}
    words = list(argv)
    while words:
        option = words.pop(0)
        if option not in _NUMBERS | {"--frame-id", "--child-frame-id"}:
            raise ValueError(f"unknown argument {option!r}")
        if not words:
            raise ValueError(f"{option} needs a value")
        value = words.pop(0)
        if option in _NUMBERS:
            try:
                given[option] = float(value)
            except ValueError:
                raise ValueError(f"{option}: {value!r} is not a number") from None
        else:
            given[option] = value
    if "--frame-id" not in given or "--child-frame-id" not in given:
        raise ValueError("both --frame-id and --child-frame-id are required")
    quaternion = any(k in given for k in ("--qx", "--qy", "--qz", "--qw"))
    euler = any(k in given for k in ("--roll", "--pitch", "--yaw"))
    if quaternion and euler:
        raise ValueError("cannot specify both quaternion and Euler rotations")
    if euler:
        x, y, z, w = _from_euler(given.get("--roll", 0.0), given.get("--pitch", 0.0), given.get("--yaw", 0.0))
    else:
        x, y, z, w = (given.get(k, d) for k, d in (("--qx", 0.0), ("--qy", 0.0), ("--qz", 0.0), ("--qw", 1.0)))
    return {
        "translation.x": given.get("--x", 0.0),
        "translation.y": given.get("--y", 0.0),
        "translation.z": given.get("--z", 0.0),
        "rotation.x": x,
        "rotation.y": y,
        "rotation.z": z,
        "rotation.w": w,
        "frame_id": given["--frame-id"],
        "child_frame_id": given["--child-frame-id"],
    }


def _from_euler(roll: float, pitch: float, yaw: float) -> tuple[float, float, float, float]:
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (
        sr * cp * cy - cr * sp * sy,
        cr * sp * cy + sr * cp * sy,
        cr * cp * sy - sr * sp * cy,
        cr * cp * cy + sr * sp * sy,
    )


class StaticTransformPublisher(Node):
    """Node ``static_transform_publisher``: one transform on ``/tf_static``, transient-local depth 1."""

    def __init__(self) -> None:
        super().__init__("static_transform_publisher")
        fixed = ParameterDescriptor(read_only=True)
        t = TransformStamped()
        t.header.stamp = self.get_clock().now().to_msg()
        tr, rot = t.transform.translation, t.transform.rotation
        tr.x, tr.y, tr.z = (self.declare_parameter(f"translation.{a}", 0.0, fixed).value for a in "xyz")
        rot.x, rot.y, rot.z = (self.declare_parameter(f"rotation.{a}", 0.0, fixed).value for a in "xyz")
        rot.w = self.declare_parameter("rotation.w", 1.0, fixed).value
        t.header.frame_id = self.declare_parameter("frame_id", "", fixed).value
        t.child_frame_id = self.declare_parameter("child_frame_id", "", fixed).value
        latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.create_publisher(TFMessage, "/tf_static", latched).publish(TFMessage(transforms=[t]))
        self.get_logger().info(
            "Spinning until stopped - publishing transform\n"
            f"translation: ('{tr.x:f}', '{tr.y:f}', '{tr.z:f}')\n"
            f"rotation: ('{rot.x:f}', '{rot.y:f}', '{rot.z:f}', '{rot.w:f}')\n"
            f"from '{t.header.frame_id}' to '{t.child_frame_id}'"
        )


def main() -> int:
    """The real program's command line under ``actors run``: runs until the run ends; 2 for bad arguments."""
    from actors.compat.programs import run_native
    from actors.launch.rosargs import parse

    _, args = parse(sys.argv[1:])
    if args[:1] in (["-h"], ["--help"]):
        print(USAGE)
        return 0
    try:
        params = parse_args(args)
    except ValueError as exc:
        print(f"static_transform_publisher: {exc}\n{USAGE}", file=sys.stderr)
        return 2
    run_native(StaticTransformPublisher, "static_transform_publisher", params)
    return 0
