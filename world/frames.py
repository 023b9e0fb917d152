"""The robots' coordinate frames (tf names and mount heights), shared by the TurtleBot's /tf and the 3D scene.

A TurtleBot's tree is TurtleBot3's: ``odom`` -> ``base_footprint`` (the
odometry, on ``/tf`` with every ``odom`` message) -> ``base_link`` ->
``base_scan`` (fixed, on ``/tf_static``).  Above it, ``world`` (the
simulator's frame: ground truth on ``sim/pose``, the arena in the scene)
-> ``odom`` is fixed at the start pose, so every robot hangs in one tree.  A
robot in a namespace prefixes its frames with it (``robot1/odom``), as
robot_state_publisher's ``frame_prefix`` does, so two robots' trees never
share a name.
"""

from __future__ import annotations

__all__ = ["WORLD", "ODOM", "BASE_FOOTPRINT", "BASE_LINK", "BASE_SCAN", "BASE_LINK_Z", "SCAN_Z", "frame_prefix"]

WORLD = "world"
ODOM = "odom"
BASE_FOOTPRINT = "base_footprint"
BASE_LINK = "base_link"
BASE_SCAN = "base_scan"

BASE_LINK_Z = 0.010
"""Metres from base_footprint (the floor under the robot) up to base_link, as on a TurtleBot3."""

SCAN_Z = 0.172
"""Metres from base_link up to the lidar.  The simulated lidar looks out from the body's
centre (a real burger's sits 32 mm behind it), so base_scan has no forward offset."""


def frame_prefix(namespace: str) -> str:
    """What a robot in ``namespace`` puts before its frame names: ``""`` at the root, ``"robot1/"`` in ``/robot1``."""
    inner = namespace.strip("/")
    return f"{inner}/" if inner else ""
