"""``tf_transformations``: the quaternion helpers ROS 2's tf2 tutorials import, for the axes they use.

The Humble-era tutorials call ``tf_transformations.quaternion_from_euler(0, 0,
theta)``; newer pages define the same function inline.  Angles are in
radians; quaternions are numpy arrays ``[x, y, z, w]``, as that package
returns them.  Only the static x-y-z convention (``axes="sxyz"``, roll about
x, then pitch about y, then yaw about z) is provided; another raises ValueError.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from actors.ros.tf_buffer import quaternion_inverse as _inverse
from actors.ros.tf_buffer import quaternion_multiply as _multiply

__all__ = [
    "quaternion_from_euler",
    "euler_from_quaternion",
    "quaternion_multiply",
    "quaternion_conjugate",
    "quaternion_inverse",
]


def _check(axes: str) -> None:
    if axes != "sxyz":
        raise ValueError(f"axes {axes!r}: actors' tf_transformations has the static x-y-z convention ('sxyz') only")


def quaternion_from_euler(ai: float, aj: float, ak: float, axes: str = "sxyz") -> np.ndarray:
    """The rotation of ``ai`` about x, then ``aj`` about y, then ``ak`` about z, as ``[x, y, z, w]``."""
    _check(axes)
    ci, si = math.cos(ai / 2), math.sin(ai / 2)
    cj, sj = math.cos(aj / 2), math.sin(aj / 2)
    ck, sk = math.cos(ak / 2), math.sin(ak / 2)
    return np.array(
        [
            si * cj * ck - ci * sj * sk,
            ci * sj * ck + si * cj * sk,
            ci * cj * sk - si * sj * ck,
            ci * cj * ck + si * sj * sk,
        ]
    )


def euler_from_quaternion(quaternion: Any, axes: str = "sxyz") -> tuple[float, float, float]:
    """(roll, pitch, yaw) of a unit quaternion ``[x, y, z, w]``."""
    _check(axes)
    x, y, z, w = (float(v) for v in quaternion)
    roll = math.atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y))
    pitch = math.asin(max(-1.0, min(1.0, 2 * (w * y - z * x))))
    yaw = math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))
    return roll, pitch, yaw


def quaternion_multiply(quaternion1: Any, quaternion0: Any) -> np.ndarray:
    """The rotation ``quaternion0`` followed by ``quaternion1``."""
    a = tuple(float(v) for v in quaternion1)
    b = tuple(float(v) for v in quaternion0)
    return np.array(_multiply(a, b))  # type: ignore[arg-type]


def quaternion_conjugate(quaternion: Any) -> np.ndarray:
    """``[-x, -y, -z, w]``."""
    return np.array(_inverse(tuple(float(v) for v in quaternion)))  # type: ignore[arg-type]


def quaternion_inverse(quaternion: Any) -> np.ndarray:
    """The inverse of any non-zero quaternion (its conjugate over its squared norm)."""
    q = np.asarray(quaternion, dtype=float)
    return quaternion_conjugate(q) / float(np.dot(q, q))
