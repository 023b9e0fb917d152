"""``tf2_geometry_msgs``: points, vectors and poses moved by a TransformStamped; registered with tf2_ros.

``do_transform_point(point_stamped, transform)`` and its siblings return a new
message in the transform's frame (its ``header``); ``Buffer.transform`` finds
them by the message's type.
"""

from __future__ import annotations

from actors.compat.tf2_ros.buffer_interface import TransformRegistration
from actors.ros.tf_buffer import Quat, Vec, quaternion_multiply, rotate
from interfaces.geometry_msgs.msg import (
    Point,
    PointStamped,
    Pose,
    PoseStamped,
    Quaternion,
    TransformStamped,
    Vector3,
    Vector3Stamped,
)

__all__ = [
    "do_transform_point",
    "do_transform_vector3",
    "do_transform_pose",
    "do_transform_pose_stamped",
]


def _parts(transform: TransformStamped) -> tuple[Vec, Quat]:
    t, r = transform.transform.translation, transform.transform.rotation
    return (t.x, t.y, t.z), (r.x, r.y, r.z, r.w)


def _moved(transform: TransformStamped, v: Vec) -> Vec:
    translation, rotation = _parts(transform)
    x, y, z = rotate(rotation, v)
    return (x + translation[0], y + translation[1], z + translation[2])


def do_transform_point(point: PointStamped, transform: TransformStamped) -> PointStamped:
    """``point`` in the transform's target frame."""
    x, y, z = _moved(transform, (point.point.x, point.point.y, point.point.z))
    return PointStamped(header=transform.header, point=Point(x=x, y=y, z=z))


def do_transform_vector3(vector3: Vector3Stamped, transform: TransformStamped) -> Vector3Stamped:
    """``vector3`` rotated into the transform's target frame (a direction: no translation)."""
    v = vector3.vector
    x, y, z = rotate(_parts(transform)[1], (v.x, v.y, v.z))
    return Vector3Stamped(header=transform.header, vector=Vector3(x=x, y=y, z=z))


def do_transform_pose(pose: Pose, transform: TransformStamped) -> Pose:
    """``pose`` (position and orientation) in the transform's target frame."""
    x, y, z = _moved(transform, (pose.position.x, pose.position.y, pose.position.z))
    o = pose.orientation
    qx, qy, qz, qw = quaternion_multiply(_parts(transform)[1], (o.x, o.y, o.z, o.w))
    return Pose(position=Point(x=x, y=y, z=z), orientation=Quaternion(x=qx, y=qy, z=qz, w=qw))


def do_transform_pose_stamped(pose: PoseStamped, transform: TransformStamped) -> PoseStamped:
    """``pose`` in the transform's target frame, stamped with the transform's header."""
    return PoseStamped(header=transform.header, pose=do_transform_pose(pose.pose, transform))


TransformRegistration().add(PointStamped, do_transform_point)
TransformRegistration().add(Vector3Stamped, do_transform_vector3)
TransformRegistration().add(PoseStamped, do_transform_pose_stamped)
