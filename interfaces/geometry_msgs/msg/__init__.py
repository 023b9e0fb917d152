"""Generated from geometry_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from array import array
from collections.abc import MutableSequence
from typing import Annotated, ClassVar

import msgspec

from actors.messages.arrays import held
from interfaces.std_msgs.msg import Header

__all__ = [
    "Accel",
    "AccelStamped",
    "AccelWithCovariance",
    "AccelWithCovarianceStamped",
    "Inertia",
    "InertiaStamped",
    "Point",
    "Point32",
    "PointStamped",
    "Polygon",
    "PolygonInstance",
    "PolygonInstanceStamped",
    "PolygonStamped",
    "Pose",
    "Pose2D",
    "PoseArray",
    "PoseStamped",
    "PoseWithCovariance",
    "PoseWithCovarianceStamped",
    "Quaternion",
    "QuaternionStamped",
    "Transform",
    "TransformStamped",
    "Twist",
    "TwistStamped",
    "TwistWithCovariance",
    "TwistWithCovarianceStamped",
    "Vector3",
    "Vector3Stamped",
    "VelocityStamped",
    "Wrench",
    "WrenchStamped",
]

_int64 = Annotated[int, msgspec.Meta(ge=-9223372036854775808, le=9223372036854775807)]


class Vector3(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/Vector3``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/Vector3"
    __ros_definition__: ClassVar[str] = (
        "# This represents a vector in free space.\n"
        "\n"
        "# This is semantically different than a point.\n"
        "# A vector is always anchored at the origin.\n"
        "# When a transform is applied to a vector, only the rotational component is applied.\n"
        "\n"
        "float64 x\n"
        "float64 y\n"
        "float64 z\n"
    )

    x: float = 0.0
    y: float = 0.0
    z: float = 0.0


class Accel(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/Accel``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/Accel"
    __ros_definition__: ClassVar[str] = (
        "# This expresses acceleration in free space broken into its linear and angular parts.\n"
        "Vector3  linear\n"
        "Vector3  angular\n"
    )

    linear: Vector3 = msgspec.field(default_factory=Vector3)
    angular: Vector3 = msgspec.field(default_factory=Vector3)


class AccelStamped(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/AccelStamped``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/AccelStamped"
    __ros_definition__: ClassVar[str] = (
        "# An accel with reference coordinate frame and timestamp\n"
        "std_msgs/Header header\n"
        "Accel accel\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    accel: Accel = msgspec.field(default_factory=Accel)


class AccelWithCovariance(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/AccelWithCovariance``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/AccelWithCovariance"
    __ros_definition__: ClassVar[str] = (
        "# This expresses acceleration in free space with uncertainty.\n"
        "\n"
        "Accel accel\n"
        "\n"
        "# Row-major representation of the 6x6 covariance matrix\n"
        "# The orientation parameters use a fixed-axis representation.\n"
        "# In order, the parameters are:\n"
        "# (x, y, z, rotation about X axis, rotation about Y axis, rotation about Z axis)\n"
        "float64[36] covariance\n"
    )

    accel: Accel = msgspec.field(default_factory=Accel)
    covariance: Annotated[MutableSequence[float], msgspec.Meta(min_length=36, max_length=36)] = msgspec.field(default_factory=lambda: array("d", bytes(288)))

    def __post_init__(self) -> None:
        if type(self.covariance) is not array or self.covariance.typecode != "d":
            self.covariance = held(self.covariance, "d")


class AccelWithCovarianceStamped(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/AccelWithCovarianceStamped``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/AccelWithCovarianceStamped"
    __ros_definition__: ClassVar[str] = (
        "# This represents an estimated accel with reference coordinate frame and timestamp.\n"
        "std_msgs/Header header\n"
        "AccelWithCovariance accel\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    accel: AccelWithCovariance = msgspec.field(default_factory=AccelWithCovariance)


class Inertia(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/Inertia``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/Inertia"
    __ros_definition__: ClassVar[str] = (
        "# Mass [kg]\n"
        "float64 m\n"
        "\n"
        "# Center of mass [m]\n"
        "geometry_msgs/Vector3 com\n"
        "\n"
        "# Inertia Tensor [kg-m^2]\n"
        "#     | ixx ixy ixz |\n"
        "# I = | ixy iyy iyz |\n"
        "#     | ixz iyz izz |\n"
        "float64 ixx\n"
        "float64 ixy\n"
        "float64 ixz\n"
        "float64 iyy\n"
        "float64 iyz\n"
        "float64 izz\n"
    )

    m: float = 0.0
    com: Vector3 = msgspec.field(default_factory=Vector3)
    ixx: float = 0.0
    ixy: float = 0.0
    ixz: float = 0.0
    iyy: float = 0.0
    iyz: float = 0.0
    izz: float = 0.0


class InertiaStamped(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/InertiaStamped``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/InertiaStamped"
    __ros_definition__: ClassVar[str] = (
        "# An Inertia with a time stamp and reference frame.\n"
        "\n"
        "std_msgs/Header header\n"
        "Inertia inertia\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    inertia: Inertia = msgspec.field(default_factory=Inertia)


class Point(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/Point``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/Point"
    __ros_definition__: ClassVar[str] = (
        "# This contains the position of a point in free space\n"
        "float64 x\n"
        "float64 y\n"
        "float64 z\n"
    )

    x: float = 0.0
    y: float = 0.0
    z: float = 0.0


class Point32(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/Point32``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/Point32"
    __ros_definition__: ClassVar[str] = (
        "# This contains the position of a point in free space(with 32 bits of precision).\n"
        "# It is recommended to use Point wherever possible instead of Point32.\n"
        "#\n"
        "# This recommendation is to promote interoperability.\n"
        "#\n"
        "# This message is designed to take up less space when sending\n"
        "# lots of points at once, as in the case of a PointCloud.\n"
        "\n"
        "float32 x\n"
        "float32 y\n"
        "float32 z\n"
    )

    x: float = 0.0
    y: float = 0.0
    z: float = 0.0


class PointStamped(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/PointStamped``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/PointStamped"
    __ros_definition__: ClassVar[str] = (
        "# This represents a Point with reference coordinate frame and timestamp\n"
        "\n"
        "std_msgs/Header header\n"
        "Point point\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    point: Point = msgspec.field(default_factory=Point)


class Polygon(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/Polygon``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/Polygon"
    __ros_definition__: ClassVar[str] = (
        "# A specification of a polygon where the first and last points are assumed to be connected\n"
        "\n"
        "Point32[] points\n"
    )

    points: list[Point32] = msgspec.field(default_factory=list)


class PolygonInstance(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/PolygonInstance``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/PolygonInstance"
    __ros_definition__: ClassVar[str] = (
        "# A specification of a polygon where the first and last points are assumed to be connected\n"
        "# It includes a unique identification field for disambiguating multiple instances\n"
        "\n"
        "geometry_msgs/Polygon polygon\n"
        "int64 id\n"
    )

    polygon: Polygon = msgspec.field(default_factory=Polygon)
    id: _int64 = 0


class PolygonInstanceStamped(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/PolygonInstanceStamped``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/PolygonInstanceStamped"
    __ros_definition__: ClassVar[str] = (
        "# This represents a Polygon with reference coordinate frame and timestamp\n"
        "# It includes a unique identification field for disambiguating multiple instances\n"
        "\n"
        "std_msgs/Header header\n"
        "geometry_msgs/PolygonInstance polygon\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    polygon: PolygonInstance = msgspec.field(default_factory=PolygonInstance)


class PolygonStamped(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/PolygonStamped``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/PolygonStamped"
    __ros_definition__: ClassVar[str] = (
        "# This represents a Polygon with reference coordinate frame and timestamp\n"
        "\n"
        "std_msgs/Header header\n"
        "Polygon polygon\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    polygon: Polygon = msgspec.field(default_factory=Polygon)


class Quaternion(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/Quaternion``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/Quaternion"
    __ros_definition__: ClassVar[str] = (
        "# This represents an orientation in free space in quaternion form.\n"
        "\n"
        "float64 x 0\n"
        "float64 y 0\n"
        "float64 z 0\n"
        "float64 w 1\n"
    )

    x: float = 0.0
    y: float = 0.0
    z: float = 0.0
    w: float = 1.0


class Pose(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/Pose``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/Pose"
    __ros_definition__: ClassVar[str] = (
        "# A representation of pose in free space, composed of position and orientation.\n"
        "\n"
        "Point position\n"
        "Quaternion orientation\n"
    )

    position: Point = msgspec.field(default_factory=Point)
    orientation: Quaternion = msgspec.field(default_factory=Quaternion)


class Pose2D(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/Pose2D``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/Pose2D"
    __ros_definition__: ClassVar[str] = (
        "# Deprecated as of Foxy and will potentially be removed in any following release.\n"
        "# Please use the full 3D pose.\n"
        "\n"
        "# In general our recommendation is to use a full 3D representation of everything and for 2D specific applications make the appropriate projections into the plane for their calculations but optimally will preserve the 3D information during processing.\n"
        "\n"
        "# If we have parallel copies of 2D datatypes every UI and other pipeline will end up needing to have dual interfaces to plot everything. And you will end up with not being able to use 3D tools for 2D use cases even if they're completely valid, as you'd have to reimplement it with different inputs and outputs. It's not particularly hard to plot the 2D pose or compute the yaw error for the Pose message and there are already tools and libraries that can do this for you.# This expresses a position and orientation on a 2D manifold.\n"
        "\n"
        "float64 x\n"
        "float64 y\n"
        "float64 theta\n"
    )

    x: float = 0.0
    y: float = 0.0
    theta: float = 0.0


class PoseArray(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/PoseArray``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/PoseArray"
    __ros_definition__: ClassVar[str] = (
        "# An array of poses with a header for global reference.\n"
        "\n"
        "std_msgs/Header header\n"
        "\n"
        "Pose[] poses\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    poses: list[Pose] = msgspec.field(default_factory=list)


class PoseStamped(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/PoseStamped``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/PoseStamped"
    __ros_definition__: ClassVar[str] = (
        "# A Pose with reference coordinate frame and timestamp\n"
        "\n"
        "std_msgs/Header header\n"
        "Pose pose\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    pose: Pose = msgspec.field(default_factory=Pose)


class PoseWithCovariance(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/PoseWithCovariance``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/PoseWithCovariance"
    __ros_definition__: ClassVar[str] = (
        "# This represents a pose in free space with uncertainty.\n"
        "\n"
        "Pose pose\n"
        "\n"
        "# Row-major representation of the 6x6 covariance matrix\n"
        "# The orientation parameters use a fixed-axis representation.\n"
        "# In order, the parameters are:\n"
        "# (x, y, z, rotation about X axis, rotation about Y axis, rotation about Z axis)\n"
        "float64[36] covariance\n"
    )

    pose: Pose = msgspec.field(default_factory=Pose)
    covariance: Annotated[MutableSequence[float], msgspec.Meta(min_length=36, max_length=36)] = msgspec.field(default_factory=lambda: array("d", bytes(288)))

    def __post_init__(self) -> None:
        if type(self.covariance) is not array or self.covariance.typecode != "d":
            self.covariance = held(self.covariance, "d")


class PoseWithCovarianceStamped(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/PoseWithCovarianceStamped``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/PoseWithCovarianceStamped"
    __ros_definition__: ClassVar[str] = (
        "# This expresses an estimated pose with a reference coordinate frame and timestamp\n"
        "\n"
        "std_msgs/Header header\n"
        "PoseWithCovariance pose\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    pose: PoseWithCovariance = msgspec.field(default_factory=PoseWithCovariance)


class QuaternionStamped(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/QuaternionStamped``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/QuaternionStamped"
    __ros_definition__: ClassVar[str] = (
        "# This represents an orientation with reference coordinate frame and timestamp.\n"
        "\n"
        "std_msgs/Header header\n"
        "Quaternion quaternion\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    quaternion: Quaternion = msgspec.field(default_factory=Quaternion)


class Transform(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/Transform``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/Transform"
    __ros_definition__: ClassVar[str] = (
        "# This represents the transform between two coordinate frames in free space.\n"
        "\n"
        "Vector3 translation\n"
        "Quaternion rotation\n"
    )

    translation: Vector3 = msgspec.field(default_factory=Vector3)
    rotation: Quaternion = msgspec.field(default_factory=Quaternion)


class TransformStamped(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/TransformStamped``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/TransformStamped"
    __ros_definition__: ClassVar[str] = (
        "# This expresses a transform from coordinate frame header.frame_id\n"
        "# to the coordinate frame child_frame_id at the time of header.stamp\n"
        "#\n"
        "# This message is mostly used by the\n"
        "# <a href=\"https://docs.ros.org/en/rolling/p/tf2/\">tf2</a> package.\n"
        "# See its documentation for more information.\n"
        "#\n"
        "# The child_frame_id is necessary in addition to the frame_id\n"
        "# in the Header to communicate the full reference for the transform\n"
        "# in a self contained message.\n"
        "\n"
        "# The frame id in the header is used as the reference frame of this transform.\n"
        "std_msgs/Header header\n"
        "\n"
        "# The frame id of the child frame to which this transform points.\n"
        "string child_frame_id\n"
        "\n"
        "# Translation and rotation in 3-dimensions of child_frame_id from header.frame_id.\n"
        "Transform transform\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    child_frame_id: str = ""
    transform: Transform = msgspec.field(default_factory=Transform)


class Twist(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/Twist``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/Twist"
    __ros_definition__: ClassVar[str] = (
        "# This expresses velocity in free space broken into its linear and angular parts.\n"
        "\n"
        "Vector3  linear\n"
        "Vector3  angular\n"
    )

    linear: Vector3 = msgspec.field(default_factory=Vector3)
    angular: Vector3 = msgspec.field(default_factory=Vector3)


class TwistStamped(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/TwistStamped``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/TwistStamped"
    __ros_definition__: ClassVar[str] = (
        "# A twist with reference coordinate frame and timestamp\n"
        "\n"
        "std_msgs/Header header\n"
        "Twist twist\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    twist: Twist = msgspec.field(default_factory=Twist)


class TwistWithCovariance(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/TwistWithCovariance``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/TwistWithCovariance"
    __ros_definition__: ClassVar[str] = (
        "# This expresses velocity in free space with uncertainty.\n"
        "\n"
        "Twist twist\n"
        "\n"
        "# Row-major representation of the 6x6 covariance matrix\n"
        "# The orientation parameters use a fixed-axis representation.\n"
        "# In order, the parameters are:\n"
        "# (x, y, z, rotation about X axis, rotation about Y axis, rotation about Z axis)\n"
        "float64[36] covariance\n"
    )

    twist: Twist = msgspec.field(default_factory=Twist)
    covariance: Annotated[MutableSequence[float], msgspec.Meta(min_length=36, max_length=36)] = msgspec.field(default_factory=lambda: array("d", bytes(288)))

    def __post_init__(self) -> None:
        if type(self.covariance) is not array or self.covariance.typecode != "d":
            self.covariance = held(self.covariance, "d")


class TwistWithCovarianceStamped(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/TwistWithCovarianceStamped``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/TwistWithCovarianceStamped"
    __ros_definition__: ClassVar[str] = (
        "# This represents an estimated twist with reference coordinate frame and timestamp.\n"
        "\n"
        "std_msgs/Header header\n"
        "TwistWithCovariance twist\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    twist: TwistWithCovariance = msgspec.field(default_factory=TwistWithCovariance)


class Vector3Stamped(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/Vector3Stamped``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/Vector3Stamped"
    __ros_definition__: ClassVar[str] = (
        "# This represents a Vector3 with reference coordinate frame and timestamp\n"
        "\n"
        "# Note that this follows vector semantics with it always anchored at the origin,\n"
        "# so the rotational elements of a transform are the only parts applied when transforming.\n"
        "\n"
        "std_msgs/Header header\n"
        "Vector3 vector\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    vector: Vector3 = msgspec.field(default_factory=Vector3)


class VelocityStamped(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/VelocityStamped``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/VelocityStamped"
    __ros_definition__: ClassVar[str] = (
        "# This expresses the timestamped velocity vector of a frame 'body_frame_id' in the reference frame 'reference_frame_id' expressed from arbitrary observation frame 'header.frame_id'.\n"
        "# - If the 'body_frame_id' and 'header.frame_id' are identical, the velocity is observed and defined in the local coordinates system of the body\n"
        "#   which is the usual use-case in mobile robotics and is also known as a body twist.\n"
        "\n"
        "std_msgs/Header header\n"
        "string body_frame_id\n"
        "string reference_frame_id\n"
        "Twist velocity\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    body_frame_id: str = ""
    reference_frame_id: str = ""
    velocity: Twist = msgspec.field(default_factory=Twist)


class Wrench(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/Wrench``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/Wrench"
    __ros_definition__: ClassVar[str] = (
        "# This represents force in free space, separated into its linear and angular parts.\n"
        "\n"
        "Vector3  force\n"
        "Vector3  torque\n"
    )

    force: Vector3 = msgspec.field(default_factory=Vector3)
    torque: Vector3 = msgspec.field(default_factory=Vector3)


class WrenchStamped(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``geometry_msgs/msg/WrenchStamped``."""

    __ros_type__: ClassVar[str] = "geometry_msgs/msg/WrenchStamped"
    __ros_definition__: ClassVar[str] = (
        "# A wrench with reference coordinate frame and timestamp\n"
        "\n"
        "std_msgs/Header header\n"
        "Wrench wrench\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    wrench: Wrench = msgspec.field(default_factory=Wrench)
