"""Generated from stereo_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from typing import ClassVar

import msgspec

from interfaces.sensor_msgs.msg import Image, RegionOfInterest
from interfaces.std_msgs.msg import Header

__all__ = [
    "DisparityImage",
]


class DisparityImage(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``stereo_msgs/msg/DisparityImage``."""

    __ros_type__: ClassVar[str] = "stereo_msgs/msg/DisparityImage"
    __ros_definition__: ClassVar[str] = (
        "# Separate header for compatibility with current TimeSynchronizer.\n"
        "# Likely to be removed in a later release, use image.header instead.\n"
        "std_msgs/Header header\n"
        "\n"
        "# Floating point disparity image. The disparities are pre-adjusted for any\n"
        "# x-offset between the principal points of the two cameras (in the case\n"
        "# that they are verged). That is: d = x_l - x_r - (cx_l - cx_r)\n"
        "sensor_msgs/Image image\n"
        "\n"
        "# Stereo geometry. For disparity d, the depth from the camera is Z = fT/d.\n"
        "float32 f # Focal length, pixels\n"
        "float32 t # Baseline, world units\n"
        "\n"
        "# Subwindow of (potentially) valid disparity values.\n"
        "sensor_msgs/RegionOfInterest valid_window\n"
        "\n"
        "# The range of disparities searched.\n"
        "# In the disparity image, any disparity less than min_disparity is invalid.\n"
        "# The disparity search range defines the horopter, or 3D volume that the\n"
        "# stereo algorithm can \"see\". Points with Z outside of:\n"
        "#     Z_min = fT / max_disparity\n"
        "#     Z_max = fT / min_disparity\n"
        "# could not be found.\n"
        "float32 min_disparity\n"
        "float32 max_disparity\n"
        "\n"
        "# Smallest allowed disparity increment. The smallest achievable depth range\n"
        "# resolution is delta_Z = (Z^2/fT)*delta_d.\n"
        "float32 delta_d\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    image: Image = msgspec.field(default_factory=Image)
    f: float = 0.0
    t: float = 0.0
    valid_window: RegionOfInterest = msgspec.field(default_factory=RegionOfInterest)
    min_disparity: float = 0.0
    max_disparity: float = 0.0
    delta_d: float = 0.0
