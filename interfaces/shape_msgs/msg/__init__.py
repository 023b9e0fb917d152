"""Generated from shape_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from array import array
from collections.abc import MutableSequence
from typing import Annotated, ClassVar

import msgspec

from actors.messages.arrays import held
from interfaces.geometry_msgs.msg import Point, Polygon

__all__ = [
    "Mesh",
    "MeshTriangle",
    "Plane",
    "SolidPrimitive",
]

_uint8 = Annotated[int, msgspec.Meta(ge=0, le=255)]
_uint32 = Annotated[int, msgspec.Meta(ge=0, le=4294967295)]


class MeshTriangle(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``shape_msgs/msg/MeshTriangle``."""

    __ros_type__: ClassVar[str] = "shape_msgs/msg/MeshTriangle"
    __ros_definition__: ClassVar[str] = (
        "# Definition of a triangle's vertices.\n"
        "\n"
        "uint32[3] vertex_indices\n"
    )

    vertex_indices: Annotated[MutableSequence[_uint32], msgspec.Meta(min_length=3, max_length=3)] = msgspec.field(default_factory=lambda: array("I", bytes(12)))

    def __post_init__(self) -> None:
        if type(self.vertex_indices) is not array or self.vertex_indices.typecode != "I":
            self.vertex_indices = held(self.vertex_indices, "I")


class Mesh(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``shape_msgs/msg/Mesh``."""

    __ros_type__: ClassVar[str] = "shape_msgs/msg/Mesh"
    __ros_definition__: ClassVar[str] = (
        "# Definition of a mesh.\n"
        "\n"
        "# List of triangles; the index values refer to positions in vertices[].\n"
        "MeshTriangle[] triangles\n"
        "\n"
        "# The actual vertices that make up the mesh.\n"
        "geometry_msgs/Point[] vertices\n"
    )

    triangles: list[MeshTriangle] = msgspec.field(default_factory=list)
    vertices: list[Point] = msgspec.field(default_factory=list)


class Plane(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``shape_msgs/msg/Plane``."""

    __ros_type__: ClassVar[str] = "shape_msgs/msg/Plane"
    __ros_definition__: ClassVar[str] = (
        "# Representation of a plane, using the plane equation ax + by + cz + d = 0.\n"
        "#\n"
        "# a := coef[0]\n"
        "# b := coef[1]\n"
        "# c := coef[2]\n"
        "# d := coef[3]\n"
        "float64[4] coef\n"
    )

    coef: Annotated[MutableSequence[float], msgspec.Meta(min_length=4, max_length=4)] = msgspec.field(default_factory=lambda: array("d", bytes(32)))

    def __post_init__(self) -> None:
        if type(self.coef) is not array or self.coef.typecode != "d":
            self.coef = held(self.coef, "d")


class SolidPrimitive(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``shape_msgs/msg/SolidPrimitive``."""

    __ros_type__: ClassVar[str] = "shape_msgs/msg/SolidPrimitive"
    __ros_definition__: ClassVar[str] = (
        "# Defines box, sphere, cylinder, cone and prism.\n"
        "# All shapes are defined to have their bounding boxes centered around 0,0,0.\n"
        "\n"
        "uint8 BOX=1\n"
        "uint8 SPHERE=2\n"
        "uint8 CYLINDER=3\n"
        "uint8 CONE=4\n"
        "uint8 PRISM=5\n"
        "\n"
        "# The type of the shape\n"
        "uint8 type\n"
        "\n"
        "# The dimensions of the shape\n"
        "float64[<=3] dimensions  # At no point will dimensions have a length > 3.\n"
        "\n"
        "# The meaning of the shape dimensions: each constant defines the index in the 'dimensions' array.\n"
        "\n"
        "# For type BOX, the X, Y, and Z dimensions are the length of the corresponding sides of the box.\n"
        "uint8 BOX_X=0\n"
        "uint8 BOX_Y=1\n"
        "uint8 BOX_Z=2\n"
        "\n"
        "# For the SPHERE type, only one component is used, and it gives the radius of the sphere.\n"
        "uint8 SPHERE_RADIUS=0\n"
        "\n"
        "# For the CYLINDER and CONE types, the center line is oriented along the Z axis.\n"
        "# Therefore the CYLINDER_HEIGHT (CONE_HEIGHT) component of dimensions gives the\n"
        "# height of the cylinder (cone).\n"
        "# The CYLINDER_RADIUS (CONE_RADIUS) component of dimensions gives the radius of\n"
        "# the base of the cylinder (cone).\n"
        "# Cone and cylinder primitives are defined to be circular. The tip of the cone\n"
        "# is pointing up, along +Z axis.\n"
        "\n"
        "uint8 CYLINDER_HEIGHT=0\n"
        "uint8 CYLINDER_RADIUS=1\n"
        "\n"
        "uint8 CONE_HEIGHT=0\n"
        "uint8 CONE_RADIUS=1\n"
        "\n"
        "# For the type PRISM, the center line is oriented along Z axis.\n"
        "# The PRISM_HEIGHT component of dimensions gives the\n"
        "# height of the prism.\n"
        "# The polygon defines the Z axis centered base of the prism.\n"
        "# The prism is constructed by extruding the base in +Z and -Z\n"
        "# directions by half of the PRISM_HEIGHT\n"
        "# Only x and y fields of the points are used in the polygon.\n"
        "# Points of the polygon are ordered counter-clockwise.\n"
        "\n"
        "uint8 PRISM_HEIGHT=0\n"
        "geometry_msgs/Polygon polygon\n"
    )
    BOX: ClassVar[int] = 1
    SPHERE: ClassVar[int] = 2
    CYLINDER: ClassVar[int] = 3
    CONE: ClassVar[int] = 4
    PRISM: ClassVar[int] = 5
    BOX_X: ClassVar[int] = 0
    BOX_Y: ClassVar[int] = 1
    BOX_Z: ClassVar[int] = 2
    SPHERE_RADIUS: ClassVar[int] = 0
    CYLINDER_HEIGHT: ClassVar[int] = 0
    CYLINDER_RADIUS: ClassVar[int] = 1
    CONE_HEIGHT: ClassVar[int] = 0
    CONE_RADIUS: ClassVar[int] = 1
    PRISM_HEIGHT: ClassVar[int] = 0

    type: _uint8 = 0
    dimensions: Annotated[MutableSequence[float], msgspec.Meta(max_length=3)] = msgspec.field(default_factory=lambda: array("d"))
    polygon: Polygon = msgspec.field(default_factory=Polygon)

    def __post_init__(self) -> None:
        if type(self.dimensions) is not array or self.dimensions.typecode != "d":
            self.dimensions = held(self.dimensions, "d")
