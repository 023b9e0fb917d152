"""Generated from sensor_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from array import array
from collections.abc import MutableSequence
from typing import Annotated, ClassVar

import msgspec

from actors.messages.arrays import held
from interfaces.builtin_interfaces.msg import Time
from interfaces.geometry_msgs.msg import Point32, Quaternion, Transform, Twist, Vector3, Wrench
from interfaces.std_msgs.msg import Header

__all__ = [
    "BatteryState",
    "CameraInfo",
    "ChannelFloat32",
    "CompressedImage",
    "FluidPressure",
    "Illuminance",
    "Image",
    "Imu",
    "JointState",
    "Joy",
    "JoyFeedback",
    "JoyFeedbackArray",
    "LaserEcho",
    "LaserScan",
    "MagneticField",
    "MultiDOFJointState",
    "MultiEchoLaserScan",
    "NavSatFix",
    "NavSatStatus",
    "PointCloud",
    "PointCloud2",
    "PointField",
    "Range",
    "RegionOfInterest",
    "RelativeHumidity",
    "Temperature",
    "TimeReference",
]

_uint8 = Annotated[int, msgspec.Meta(ge=0, le=255)]
_int8 = Annotated[int, msgspec.Meta(ge=-128, le=127)]
_uint16 = Annotated[int, msgspec.Meta(ge=0, le=65535)]
_int32 = Annotated[int, msgspec.Meta(ge=-2147483648, le=2147483647)]
_uint32 = Annotated[int, msgspec.Meta(ge=0, le=4294967295)]


class BatteryState(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/BatteryState``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/BatteryState"
    __ros_definition__: ClassVar[str] = (
        "\n"
        "# Constants are chosen to match the enums in the linux kernel\n"
        "# defined in include/linux/power_supply.h as of version 3.7\n"
        "# The one difference is for style reasons the constants are\n"
        "# all uppercase not mixed case.\n"
        "\n"
        "# Power supply status constants\n"
        "uint8 POWER_SUPPLY_STATUS_UNKNOWN = 0\n"
        "uint8 POWER_SUPPLY_STATUS_CHARGING = 1\n"
        "uint8 POWER_SUPPLY_STATUS_DISCHARGING = 2\n"
        "uint8 POWER_SUPPLY_STATUS_NOT_CHARGING = 3\n"
        "uint8 POWER_SUPPLY_STATUS_FULL = 4\n"
        "\n"
        "# Power supply health constants\n"
        "uint8 POWER_SUPPLY_HEALTH_UNKNOWN = 0\n"
        "uint8 POWER_SUPPLY_HEALTH_GOOD = 1\n"
        "uint8 POWER_SUPPLY_HEALTH_OVERHEAT = 2\n"
        "uint8 POWER_SUPPLY_HEALTH_DEAD = 3\n"
        "uint8 POWER_SUPPLY_HEALTH_OVERVOLTAGE = 4\n"
        "uint8 POWER_SUPPLY_HEALTH_UNSPEC_FAILURE = 5\n"
        "uint8 POWER_SUPPLY_HEALTH_COLD = 6\n"
        "uint8 POWER_SUPPLY_HEALTH_WATCHDOG_TIMER_EXPIRE = 7\n"
        "uint8 POWER_SUPPLY_HEALTH_SAFETY_TIMER_EXPIRE = 8\n"
        "\n"
        "# Power supply technology (chemistry) constants\n"
        "uint8 POWER_SUPPLY_TECHNOLOGY_UNKNOWN = 0 # Unknown battery technology\n"
        "uint8 POWER_SUPPLY_TECHNOLOGY_NIMH = 1    # Nickel-Metal Hydride battery\n"
        "uint8 POWER_SUPPLY_TECHNOLOGY_LION = 2    # Lithium-ion battery\n"
        "uint8 POWER_SUPPLY_TECHNOLOGY_LIPO = 3    # Lithium Polymer battery\n"
        "uint8 POWER_SUPPLY_TECHNOLOGY_LIFE = 4    # Lithium Iron Phosphate battery\n"
        "uint8 POWER_SUPPLY_TECHNOLOGY_NICD = 5    # Nickel-Cadmium battery\n"
        "uint8 POWER_SUPPLY_TECHNOLOGY_LIMN = 6    # Lithium Manganese Dioxide battery\n"
        "uint8 POWER_SUPPLY_TECHNOLOGY_TERNARY = 7 # Ternary Lithium battery\n"
        "uint8 POWER_SUPPLY_TECHNOLOGY_VRLA = 8    # Valve Regulated Lead-Acid battery\n"
        "\n"
        "std_msgs/Header  header\n"
        "float32 voltage          # Voltage in Volts (Mandatory)\n"
        "float32 temperature      # Temperature in Degrees Celsius (If unmeasured NaN)\n"
        "float32 current          # Negative when discharging (A)  (If unmeasured NaN)\n"
        "float32 charge           # Current charge in Ah  (If unmeasured NaN)\n"
        "float32 capacity         # Capacity in Ah (last full capacity)  (If unmeasured NaN)\n"
        "float32 design_capacity  # Capacity in Ah (design capacity)  (If unmeasured NaN)\n"
        "float32 percentage       # Charge percentage on 0 to 1 range  (If unmeasured NaN)\n"
        "uint8   power_supply_status     # The charging status as reported. Values defined above\n"
        "uint8   power_supply_health     # The battery health metric. Values defined above\n"
        "uint8   power_supply_technology # The battery chemistry. Values defined above\n"
        "bool    present          # True if the battery is present\n"
        "\n"
        "float32[] cell_voltage   # An array of individual cell voltages for each cell in the pack\n"
        "                         # If individual voltages unknown but number of cells known set each to NaN\n"
        "float32[] cell_temperature # An array of individual cell temperatures for each cell in the pack\n"
        "                           # If individual temperatures unknown but number of cells known set each to NaN\n"
        "string location          # The location into which the battery is inserted. (slot number or plug)\n"
        "string serial_number     # The best approximation of the battery serial number\n"
    )
    POWER_SUPPLY_STATUS_UNKNOWN: ClassVar[int] = 0
    POWER_SUPPLY_STATUS_CHARGING: ClassVar[int] = 1
    POWER_SUPPLY_STATUS_DISCHARGING: ClassVar[int] = 2
    POWER_SUPPLY_STATUS_NOT_CHARGING: ClassVar[int] = 3
    POWER_SUPPLY_STATUS_FULL: ClassVar[int] = 4
    POWER_SUPPLY_HEALTH_UNKNOWN: ClassVar[int] = 0
    POWER_SUPPLY_HEALTH_GOOD: ClassVar[int] = 1
    POWER_SUPPLY_HEALTH_OVERHEAT: ClassVar[int] = 2
    POWER_SUPPLY_HEALTH_DEAD: ClassVar[int] = 3
    POWER_SUPPLY_HEALTH_OVERVOLTAGE: ClassVar[int] = 4
    POWER_SUPPLY_HEALTH_UNSPEC_FAILURE: ClassVar[int] = 5
    POWER_SUPPLY_HEALTH_COLD: ClassVar[int] = 6
    POWER_SUPPLY_HEALTH_WATCHDOG_TIMER_EXPIRE: ClassVar[int] = 7
    POWER_SUPPLY_HEALTH_SAFETY_TIMER_EXPIRE: ClassVar[int] = 8
    POWER_SUPPLY_TECHNOLOGY_UNKNOWN: ClassVar[int] = 0
    POWER_SUPPLY_TECHNOLOGY_NIMH: ClassVar[int] = 1
    POWER_SUPPLY_TECHNOLOGY_LION: ClassVar[int] = 2
    POWER_SUPPLY_TECHNOLOGY_LIPO: ClassVar[int] = 3
    POWER_SUPPLY_TECHNOLOGY_LIFE: ClassVar[int] = 4
    POWER_SUPPLY_TECHNOLOGY_NICD: ClassVar[int] = 5
    POWER_SUPPLY_TECHNOLOGY_LIMN: ClassVar[int] = 6
    POWER_SUPPLY_TECHNOLOGY_TERNARY: ClassVar[int] = 7
    POWER_SUPPLY_TECHNOLOGY_VRLA: ClassVar[int] = 8

    header: Header = msgspec.field(default_factory=Header)
    voltage: float = 0.0
    temperature: float = 0.0
    current: float = 0.0
    charge: float = 0.0
    capacity: float = 0.0
    design_capacity: float = 0.0
    percentage: float = 0.0
    power_supply_status: _uint8 = 0
    power_supply_health: _uint8 = 0
    power_supply_technology: _uint8 = 0
    present: bool = False
    cell_voltage: MutableSequence[float] = msgspec.field(default_factory=lambda: array("f"))
    cell_temperature: MutableSequence[float] = msgspec.field(default_factory=lambda: array("f"))
    location: str = ""
    serial_number: str = ""

    def __post_init__(self) -> None:
        if type(self.cell_voltage) is not array or self.cell_voltage.typecode != "f":
            self.cell_voltage = held(self.cell_voltage, "f")
        if type(self.cell_temperature) is not array or self.cell_temperature.typecode != "f":
            self.cell_temperature = held(self.cell_temperature, "f")


class RegionOfInterest(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/RegionOfInterest``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/RegionOfInterest"
    __ros_definition__: ClassVar[str] = (
        "# This message is used to specify a region of interest within an image.\n"
        "#\n"
        "# When used to specify the ROI setting of the camera when the image was\n"
        "# taken, the height and width fields should either match the height and\n"
        "# width fields for the associated image; or height = width = 0\n"
        "# indicates that the full resolution image was captured.\n"
        "\n"
        "uint32 x_offset  # Leftmost pixel of the ROI\n"
        "                 # (0 if the ROI includes the left edge of the image)\n"
        "uint32 y_offset  # Topmost pixel of the ROI\n"
        "                 # (0 if the ROI includes the top edge of the image)\n"
        "uint32 height    # Height of ROI\n"
        "uint32 width     # Width of ROI\n"
        "\n"
        "# True if a distinct rectified ROI should be calculated from the \"raw\"\n"
        "# ROI in this message. Typically this should be False if the full image\n"
        "# is captured (ROI not used), and True if a subwindow is captured (ROI\n"
        "# used).\n"
        "bool do_rectify\n"
    )

    x_offset: _uint32 = 0
    y_offset: _uint32 = 0
    height: _uint32 = 0
    width: _uint32 = 0
    do_rectify: bool = False


class CameraInfo(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/CameraInfo``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/CameraInfo"
    __ros_definition__: ClassVar[str] = (
        "# This message defines meta information for a camera. It should be in a\n"
        "# camera namespace on topic \"camera_info\" and accompanied by up to five\n"
        "# image topics named:\n"
        "#\n"
        "#   image_raw - raw data from the camera driver, possibly Bayer encoded\n"
        "#   image            - monochrome, distorted\n"
        "#   image_color      - color, distorted\n"
        "#   image_rect       - monochrome, rectified\n"
        "#   image_rect_color - color, rectified\n"
        "#\n"
        "# The image_pipeline contains packages (image_proc, stereo_image_proc)\n"
        "# for producing the four processed image topics from image_raw and\n"
        "# camera_info. The meaning of the camera parameters are described in\n"
        "# detail at http://www.ros.org/wiki/image_pipeline/CameraInfo.\n"
        "#\n"
        "# The image_geometry package provides a user-friendly interface to\n"
        "# common operations using this meta information. If you want to, e.g.,\n"
        "# project a 3d point into image coordinates, we strongly recommend\n"
        "# using image_geometry.\n"
        "#\n"
        "# If the camera is uncalibrated, the matrices D, K, R, P should be left\n"
        "# zeroed out. In particular, clients may assume that K[0] == 0.0\n"
        "# indicates an uncalibrated camera.\n"
        "\n"
        "#######################################################################\n"
        "#                     Image acquisition info                          #\n"
        "#######################################################################\n"
        "\n"
        "# Time of image acquisition, camera coordinate frame ID\n"
        "std_msgs/Header header # Header timestamp should be acquisition time of image\n"
        "                             # Header frame_id should be optical frame of camera\n"
        "                             # origin of frame should be optical center of camera\n"
        "                             # +x should point to the right in the image\n"
        "                             # +y should point down in the image\n"
        "                             # +z should point into the plane of the image\n"
        "\n"
        "\n"
        "#######################################################################\n"
        "#                      Calibration Parameters                         #\n"
        "#######################################################################\n"
        "# These are fixed during camera calibration. Their values will be the #\n"
        "# same in all messages until the camera is recalibrated. Note that    #\n"
        "# self-calibrating systems may \"recalibrate\" frequently.              #\n"
        "#                                                                     #\n"
        "# The internal parameters can be used to warp a raw (distorted) image #\n"
        "# to:                                                                 #\n"
        "#   1. An undistorted image (requires D and K)                        #\n"
        "#   2. A rectified image (requires D, K, R)                           #\n"
        "# The projection matrix P projects 3D points into the rectified image.#\n"
        "#######################################################################\n"
        "\n"
        "# The image dimensions with which the camera was calibrated.\n"
        "# Normally this will be the full camera resolution in pixels.\n"
        "uint32 height\n"
        "uint32 width\n"
        "\n"
        "# The distortion model used. Supported models are listed in\n"
        "# sensor_msgs/distortion_models.hpp. For most cameras, \"plumb_bob\" - a\n"
        "# simple model of radial and tangential distortion - is sufficent.\n"
        "string distortion_model\n"
        "\n"
        "# The distortion parameters, size depending on the distortion model.\n"
        "# For \"plumb_bob\", the 5 parameters are: (k1, k2, t1, t2, k3).\n"
        "float64[] d\n"
        "\n"
        "# Intrinsic camera matrix for the raw (distorted) images.\n"
        "#     [fx  0 cx]\n"
        "# K = [ 0 fy cy]\n"
        "#     [ 0  0  1]\n"
        "# Projects 3D points in the camera coordinate frame to 2D pixel\n"
        "# coordinates using the focal lengths (fx, fy) and principal point\n"
        "# (cx, cy).\n"
        "float64[9]  k # 3x3 row-major matrix\n"
        "\n"
        "# Rectification matrix (stereo cameras only)\n"
        "# A rotation matrix aligning the camera coordinate system to the ideal\n"
        "# stereo image plane so that epipolar lines in both stereo images are\n"
        "# parallel.\n"
        "float64[9]  r # 3x3 row-major matrix\n"
        "\n"
        "# Projection/camera matrix\n"
        "#     [fx'  0  cx' Tx]\n"
        "# P = [ 0  fy' cy' Ty]\n"
        "#     [ 0   0   1   0]\n"
        "# By convention, this matrix specifies the intrinsic (camera) matrix\n"
        "#  of the processed (rectified) image. That is, the left 3x3 portion\n"
        "#  is the normal camera intrinsic matrix for the rectified image.\n"
        "# It projects 3D points in the camera coordinate frame to 2D pixel\n"
        "#  coordinates using the focal lengths (fx', fy') and principal point\n"
        "#  (cx', cy') - these may differ from the values in K.\n"
        "# For monocular cameras, Tx = Ty = 0. Normally, monocular cameras will\n"
        "#  also have R = the identity and P[1:3,1:3] = K.\n"
        "# For a stereo pair, the fourth column [Tx Ty 0]' is related to the\n"
        "#  position of the optical center of the second camera in the first\n"
        "#  camera's frame. We assume Tz = 0 so both cameras are in the same\n"
        "#  stereo image plane. The first camera always has Tx = Ty = 0. For\n"
        "#  the right (second) camera of a horizontal stereo pair, Ty = 0 and\n"
        "#  Tx = -fx' * B, where B is the baseline between the cameras.\n"
        "# Given a 3D point [X Y Z]', the projection (x, y) of the point onto\n"
        "#  the rectified image is given by:\n"
        "#  [u v w]' = P * [X Y Z 1]'\n"
        "#         x = u / w\n"
        "#         y = v / w\n"
        "#  This holds for both images of a stereo pair.\n"
        "float64[12] p # 3x4 row-major matrix\n"
        "\n"
        "\n"
        "#######################################################################\n"
        "#                      Operational Parameters                         #\n"
        "#######################################################################\n"
        "# These define the image region actually captured by the camera       #\n"
        "# driver. Although they affect the geometry of the output image, they #\n"
        "# may be changed freely without recalibrating the camera.             #\n"
        "#######################################################################\n"
        "\n"
        "# Binning refers here to any camera setting which combines rectangular\n"
        "#  neighborhoods of pixels into larger \"super-pixels.\" It reduces the\n"
        "#  resolution of the output image to\n"
        "#  (width / binning_x) x (height / binning_y).\n"
        "# The default values binning_x = binning_y = 0 is considered the same\n"
        "#  as binning_x = binning_y = 1 (no subsampling).\n"
        "uint32 binning_x\n"
        "uint32 binning_y\n"
        "\n"
        "# Region of interest (subwindow of full camera resolution), given in\n"
        "#  full resolution (unbinned) image coordinates. A particular ROI\n"
        "#  always denotes the same window of pixels on the camera sensor,\n"
        "#  regardless of binning settings.\n"
        "# The default setting of roi (all values 0) is considered the same as\n"
        "#  full resolution (roi.width = width, roi.height = height).\n"
        "RegionOfInterest roi\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    height: _uint32 = 0
    width: _uint32 = 0
    distortion_model: str = ""
    d: MutableSequence[float] = msgspec.field(default_factory=lambda: array("d"))
    k: Annotated[MutableSequence[float], msgspec.Meta(min_length=9, max_length=9)] = msgspec.field(default_factory=lambda: array("d", bytes(72)))
    r: Annotated[MutableSequence[float], msgspec.Meta(min_length=9, max_length=9)] = msgspec.field(default_factory=lambda: array("d", bytes(72)))
    p: Annotated[MutableSequence[float], msgspec.Meta(min_length=12, max_length=12)] = msgspec.field(default_factory=lambda: array("d", bytes(96)))
    binning_x: _uint32 = 0
    binning_y: _uint32 = 0
    roi: RegionOfInterest = msgspec.field(default_factory=RegionOfInterest)

    def __post_init__(self) -> None:
        if type(self.d) is not array or self.d.typecode != "d":
            self.d = held(self.d, "d")
        if type(self.k) is not array or self.k.typecode != "d":
            self.k = held(self.k, "d")
        if type(self.r) is not array or self.r.typecode != "d":
            self.r = held(self.r, "d")
        if type(self.p) is not array or self.p.typecode != "d":
            self.p = held(self.p, "d")


class ChannelFloat32(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/ChannelFloat32``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/ChannelFloat32"
    __ros_definition__: ClassVar[str] = (
        "# This message is used by the PointCloud message to hold optional data\n"
        "# associated with each point in the cloud. The length of the values\n"
        "# array should be the same as the length of the points array in the\n"
        "# PointCloud, and each value should be associated with the corresponding\n"
        "# point.\n"
        "#\n"
        "# Channel names in existing practice include:\n"
        "#   \"u\", \"v\" - row and column (respectively) in the left stereo image.\n"
        "#              This is opposite to usual conventions but remains for\n"
        "#              historical reasons. The newer PointCloud2 message has no\n"
        "#              such problem.\n"
        "#   \"rgb\" - For point clouds produced by color stereo cameras. uint8\n"
        "#           (R,G,B) values packed into the least significant 24 bits,\n"
        "#           in order.\n"
        "#   \"intensity\" - laser or pixel intensity.\n"
        "#   \"distance\"\n"
        "\n"
        "# The channel name should give semantics of the channel (e.g.\n"
        "# \"intensity\" instead of \"value\").\n"
        "string name\n"
        "\n"
        "# The values array should be 1-1 with the elements of the associated\n"
        "# PointCloud.\n"
        "float32[] values\n"
    )

    name: str = ""
    values: MutableSequence[float] = msgspec.field(default_factory=lambda: array("f"))

    def __post_init__(self) -> None:
        if type(self.values) is not array or self.values.typecode != "f":
            self.values = held(self.values, "f")


class CompressedImage(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/CompressedImage``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/CompressedImage"
    __ros_definition__: ClassVar[str] = (
        "# This message contains a compressed image.\n"
        "\n"
        "std_msgs/Header header # Header timestamp should be acquisition time of image\n"
        "                             # Header frame_id should be optical frame of camera\n"
        "                             # origin of frame should be optical center of cameara\n"
        "                             # +x should point to the right in the image\n"
        "                             # +y should point down in the image\n"
        "                             # +z should point into to plane of the image\n"
        "\n"
        "string format                # Specifies the format of the data\n"
        "                             # Acceptable values differ by the image transport used:\n"
        "                             # - compressed_image_transport:\n"
        "                             #     ORIG_PIXFMT; CODEC compressed [COMPRESSED_PIXFMT]\n"
        "                             #   where:\n"
        "                             #   - ORIG_PIXFMT is pixel format of the raw image, i.e.\n"
        "                             #     the content of sensor_msgs/Image/encoding with\n"
        "                             #     values from include/sensor_msgs/image_encodings.h\n"
        "                             #   - CODEC is one of [jpeg, png, tiff]\n"
        "                             #   - COMPRESSED_PIXFMT is only appended for color images\n"
        "                             #     and is the pixel format used by the compression\n"
        "                             #     algorithm. Valid values for jpeg encoding are:\n"
        "                             #     [bgr8, rgb8]. Valid values for png encoding are:\n"
        "                             #     [bgr8, rgb8, bgr16, rgb16].\n"
        "                             #   If the field is empty or does not correspond to the\n"
        "                             #   above pattern, the image is treated as bgr8 or mono8\n"
        "                             #   jpeg image (depending on the number of channels).\n"
        "                             # - compressed_depth_image_transport:\n"
        "                             #     ORIG_PIXFMT; compressedDepth CODEC\n"
        "                             #   where:\n"
        "                             #   - ORIG_PIXFMT is pixel format of the raw image, i.e.\n"
        "                             #     the content of sensor_msgs/Image/encoding with\n"
        "                             #     values from include/sensor_msgs/image_encodings.h\n"
        "                             #     It is usually one of [16UC1, 32FC1].\n"
        "                             #   - CODEC is one of [png, rvl]\n"
        "                             #   If the field is empty or does not correspond to the\n"
        "                             #   above pattern, the image is treated as png image.\n"
        "                             # - Other image transports can store whatever values they\n"
        "                             #   need for successful decoding of the image. Refer to\n"
        "                             #   documentation of the other transports for details.\n"
        "\n"
        "uint8[] data                 # Compressed image buffer\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    format: str = ""
    data: bytes = b""


class FluidPressure(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/FluidPressure``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/FluidPressure"
    __ros_definition__: ClassVar[str] = (
        "# Single pressure reading.  This message is appropriate for measuring the\n"
        "# pressure inside of a fluid (air, water, etc).  This also includes\n"
        "# atmospheric or barometric pressure.\n"
        "#\n"
        "# This message is not appropriate for force/pressure contact sensors.\n"
        "\n"
        "std_msgs/Header header # timestamp of the measurement\n"
        "                             # frame_id is the location of the pressure sensor\n"
        "\n"
        "float64 fluid_pressure       # Absolute pressure reading in Pascals.\n"
        "\n"
        "float64 variance             # 0 is interpreted as variance unknown\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    fluid_pressure: float = 0.0
    variance: float = 0.0


class Illuminance(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/Illuminance``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/Illuminance"
    __ros_definition__: ClassVar[str] = (
        "# Single photometric illuminance measurement.  Light should be assumed to be\n"
        "# measured along the sensor's x-axis (the area of detection is the y-z plane).\n"
        "# The illuminance should have a 0 or positive value and be received with\n"
        "# the sensor's +X axis pointing toward the light source.\n"
        "#\n"
        "# Photometric illuminance is the measure of the human eye's sensitivity of the\n"
        "# intensity of light encountering or passing through a surface.\n"
        "#\n"
        "# All other Photometric and Radiometric measurements should not use this message.\n"
        "# This message cannot represent:\n"
        "#  - Luminous intensity (candela/light source output)\n"
        "#  - Luminance (nits/light output per area)\n"
        "#  - Irradiance (watt/area), etc.\n"
        "\n"
        "std_msgs/Header header # timestamp is the time the illuminance was measured\n"
        "                             # frame_id is the location and direction of the reading\n"
        "\n"
        "float64 illuminance          # Measurement of the Photometric Illuminance in Lux.\n"
        "\n"
        "float64 variance             # 0 is interpreted as variance unknown\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    illuminance: float = 0.0
    variance: float = 0.0


class Image(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/Image``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/Image"
    __ros_definition__: ClassVar[str] = (
        "# This message contains an uncompressed image\n"
        "# (0, 0) is at top-left corner of image\n"
        "\n"
        "std_msgs/Header header # Header timestamp should be acquisition time of image\n"
        "                             # Header frame_id should be optical frame of camera\n"
        "                             # origin of frame should be optical center of cameara\n"
        "                             # +x should point to the right in the image\n"
        "                             # +y should point down in the image\n"
        "                             # +z should point into to plane of the image\n"
        "                             # If the frame_id here and the frame_id of the CameraInfo\n"
        "                             # message associated with the image conflict\n"
        "                             # the behavior is undefined\n"
        "\n"
        "uint32 height                # image height, that is, number of rows\n"
        "uint32 width                 # image width, that is, number of columns\n"
        "\n"
        "# The legal values for encoding are in file include/sensor_msgs/image_encodings.hpp\n"
        "# If you want to standardize a new string format, join\n"
        "# ros-users@lists.ros.org and send an email proposing a new encoding.\n"
        "\n"
        "string encoding       # Encoding of pixels -- channel meaning, ordering, size\n"
        "                      # taken from the list of strings in include/sensor_msgs/image_encodings.hpp\n"
        "\n"
        "uint8 is_bigendian    # is this data bigendian?\n"
        "uint32 step           # Full row length in bytes\n"
        "uint8[] data          # actual matrix data, size is (step * rows)\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    height: _uint32 = 0
    width: _uint32 = 0
    encoding: str = ""
    is_bigendian: _uint8 = 0
    step: _uint32 = 0
    data: bytes = b""


class Imu(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/Imu``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/Imu"
    __ros_definition__: ClassVar[str] = (
        "# This is a message to hold data from an IMU (Inertial Measurement Unit)\n"
        "#\n"
        "# Accelerations should be in m/s^2 (not in g's), and rotational velocity should be in rad/sec\n"
        "#\n"
        "# If the covariance of the measurement is known, it should be filled in (if all you know is the\n"
        "# variance of each measurement, e.g. from the datasheet, just put those along the diagonal)\n"
        "# A covariance matrix of all zeros will be interpreted as \"covariance unknown\", and to use the\n"
        "# data a covariance will have to be assumed or gotten from some other source\n"
        "#\n"
        "# If you have no estimate for one of the data elements (e.g. your IMU doesn't produce an\n"
        "# orientation estimate), please set element 0 of the associated covariance matrix to -1\n"
        "# If you are interpreting this message, please check for a value of -1 in the first element of each\n"
        "# covariance matrix, and disregard the associated estimate.\n"
        "\n"
        "std_msgs/Header header\n"
        "\n"
        "geometry_msgs/Quaternion orientation\n"
        "float64[9] orientation_covariance # Row major about x, y, z axes\n"
        "\n"
        "geometry_msgs/Vector3 angular_velocity\n"
        "float64[9] angular_velocity_covariance # Row major about x, y, z axes\n"
        "\n"
        "geometry_msgs/Vector3 linear_acceleration\n"
        "float64[9] linear_acceleration_covariance # Row major x, y z\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    orientation: Quaternion = msgspec.field(default_factory=Quaternion)
    orientation_covariance: Annotated[MutableSequence[float], msgspec.Meta(min_length=9, max_length=9)] = msgspec.field(default_factory=lambda: array("d", bytes(72)))
    angular_velocity: Vector3 = msgspec.field(default_factory=Vector3)
    angular_velocity_covariance: Annotated[MutableSequence[float], msgspec.Meta(min_length=9, max_length=9)] = msgspec.field(default_factory=lambda: array("d", bytes(72)))
    linear_acceleration: Vector3 = msgspec.field(default_factory=Vector3)
    linear_acceleration_covariance: Annotated[MutableSequence[float], msgspec.Meta(min_length=9, max_length=9)] = msgspec.field(default_factory=lambda: array("d", bytes(72)))

    def __post_init__(self) -> None:
        if type(self.orientation_covariance) is not array or self.orientation_covariance.typecode != "d":
            self.orientation_covariance = held(self.orientation_covariance, "d")
        if type(self.angular_velocity_covariance) is not array or self.angular_velocity_covariance.typecode != "d":
            self.angular_velocity_covariance = held(self.angular_velocity_covariance, "d")
        if type(self.linear_acceleration_covariance) is not array or self.linear_acceleration_covariance.typecode != "d":
            self.linear_acceleration_covariance = held(self.linear_acceleration_covariance, "d")


class JointState(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/JointState``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/JointState"
    __ros_definition__: ClassVar[str] = (
        "# This is a message that holds data to describe the state of a set of torque controlled joints.\n"
        "#\n"
        "# The state of each joint (revolute or prismatic) is defined by:\n"
        "#  * the position of the joint (rad or m),\n"
        "#  * the velocity of the joint (rad/s or m/s) and\n"
        "#  * the effort that is applied in the joint (Nm or N).\n"
        "#\n"
        "# Each joint is uniquely identified by its name\n"
        "# The header specifies the time at which the joint states were recorded. All the joint states\n"
        "# in one message have to be recorded at the same time.\n"
        "#\n"
        "# This message consists of a multiple arrays, one for each part of the joint state.\n"
        "# The goal is to make each of the fields optional. When e.g. your joints have no\n"
        "# effort associated with them, you can leave the effort array empty.\n"
        "#\n"
        "# All arrays in this message should have the same size, or be empty.\n"
        "# This is the only way to uniquely associate the joint name with the correct\n"
        "# states.\n"
        "\n"
        "std_msgs/Header header\n"
        "\n"
        "string[] name\n"
        "float64[] position\n"
        "float64[] velocity\n"
        "float64[] effort\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    name: list[str] = msgspec.field(default_factory=list)
    position: MutableSequence[float] = msgspec.field(default_factory=lambda: array("d"))
    velocity: MutableSequence[float] = msgspec.field(default_factory=lambda: array("d"))
    effort: MutableSequence[float] = msgspec.field(default_factory=lambda: array("d"))

    def __post_init__(self) -> None:
        if type(self.position) is not array or self.position.typecode != "d":
            self.position = held(self.position, "d")
        if type(self.velocity) is not array or self.velocity.typecode != "d":
            self.velocity = held(self.velocity, "d")
        if type(self.effort) is not array or self.effort.typecode != "d":
            self.effort = held(self.effort, "d")


class Joy(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/Joy``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/Joy"
    __ros_definition__: ClassVar[str] = (
        "# Reports the state of a joystick's axes and buttons.\n"
        "\n"
        "# The timestamp is the time at which data is received from the joystick.\n"
        "std_msgs/Header header\n"
        "\n"
        "# The axes measurements from a joystick.\n"
        "float32[] axes\n"
        "\n"
        "# The buttons measurements from a joystick.\n"
        "int32[] buttons\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    axes: MutableSequence[float] = msgspec.field(default_factory=lambda: array("f"))
    buttons: MutableSequence[_int32] = msgspec.field(default_factory=lambda: array("i"))

    def __post_init__(self) -> None:
        if type(self.axes) is not array or self.axes.typecode != "f":
            self.axes = held(self.axes, "f")
        if type(self.buttons) is not array or self.buttons.typecode != "i":
            self.buttons = held(self.buttons, "i")


class JoyFeedback(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/JoyFeedback``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/JoyFeedback"
    __ros_definition__: ClassVar[str] = (
        "# Declare of the type of feedback\n"
        "uint8 TYPE_LED    = 0\n"
        "uint8 TYPE_RUMBLE = 1\n"
        "uint8 TYPE_BUZZER = 2\n"
        "\n"
        "uint8 type\n"
        "\n"
        "# This will hold an id number for each type of each feedback.\n"
        "# Example, the first led would be id=0, the second would be id=1\n"
        "uint8 id\n"
        "\n"
        "# Intensity of the feedback, from 0.0 to 1.0, inclusive.  If device is\n"
        "# actually binary, driver should treat 0<=x<0.5 as off, 0.5<=x<=1 as on.\n"
        "float32 intensity\n"
    )
    TYPE_LED: ClassVar[int] = 0
    TYPE_RUMBLE: ClassVar[int] = 1
    TYPE_BUZZER: ClassVar[int] = 2

    type: _uint8 = 0
    id: _uint8 = 0
    intensity: float = 0.0


class JoyFeedbackArray(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/JoyFeedbackArray``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/JoyFeedbackArray"
    __ros_definition__: ClassVar[str] = (
        "# This message publishes values for multiple feedback at once.\n"
        "JoyFeedback[] array\n"
    )

    array: list[JoyFeedback] = msgspec.field(default_factory=list)


class LaserEcho(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/LaserEcho``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/LaserEcho"
    __ros_definition__: ClassVar[str] = (
        "# This message is a submessage of MultiEchoLaserScan and is not intended\n"
        "# to be used separately.\n"
        "\n"
        "float32[] echoes  # Multiple values of ranges or intensities.\n"
        "                  # Each array represents data from the same angle increment.\n"
    )

    echoes: MutableSequence[float] = msgspec.field(default_factory=lambda: array("f"))

    def __post_init__(self) -> None:
        if type(self.echoes) is not array or self.echoes.typecode != "f":
            self.echoes = held(self.echoes, "f")


class LaserScan(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/LaserScan``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/LaserScan"
    __ros_definition__: ClassVar[str] = (
        "# Single scan from a planar laser range-finder\n"
        "#\n"
        "# If you have another ranging device with different behavior (e.g. a sonar\n"
        "# array), please find or create a different message, since applications\n"
        "# will make fairly laser-specific assumptions about this data\n"
        "\n"
        "std_msgs/Header header # timestamp in the header is the acquisition time of\n"
        "                             # the first ray in the scan.\n"
        "                             #\n"
        "                             # in frame frame_id, angles are measured around\n"
        "                             # the positive Z axis (counterclockwise, if Z is up)\n"
        "                             # with zero angle being forward along the x axis\n"
        "\n"
        "float32 angle_min            # start angle of the scan [rad]\n"
        "float32 angle_max            # end angle of the scan [rad]\n"
        "float32 angle_increment      # angular distance between measurements [rad]\n"
        "\n"
        "float32 time_increment       # time between measurements [seconds] - if your scanner\n"
        "                             # is moving, this will be used in interpolating position\n"
        "                             # of 3d points\n"
        "float32 scan_time            # time between scans [seconds]\n"
        "\n"
        "float32 range_min            # minimum range value [m]\n"
        "float32 range_max            # maximum range value [m]\n"
        "\n"
        "float32[] ranges             # range data [m]\n"
        "                             # (Note: values < range_min or > range_max should be discarded)\n"
        "float32[] intensities        # intensity data [device-specific units].  If your\n"
        "                             # device does not provide intensities, please leave\n"
        "                             # the array empty.\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    angle_min: float = 0.0
    angle_max: float = 0.0
    angle_increment: float = 0.0
    time_increment: float = 0.0
    scan_time: float = 0.0
    range_min: float = 0.0
    range_max: float = 0.0
    ranges: MutableSequence[float] = msgspec.field(default_factory=lambda: array("f"))
    intensities: MutableSequence[float] = msgspec.field(default_factory=lambda: array("f"))

    def __post_init__(self) -> None:
        if type(self.ranges) is not array or self.ranges.typecode != "f":
            self.ranges = held(self.ranges, "f")
        if type(self.intensities) is not array or self.intensities.typecode != "f":
            self.intensities = held(self.intensities, "f")


class MagneticField(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/MagneticField``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/MagneticField"
    __ros_definition__: ClassVar[str] = (
        "# Measurement of the Magnetic Field vector at a specific location.\n"
        "#\n"
        "# If the covariance of the measurement is known, it should be filled in.\n"
        "# If all you know is the variance of each measurement, e.g. from the datasheet,\n"
        "# just put those along the diagonal.\n"
        "# A covariance matrix of all zeros will be interpreted as \"covariance unknown\",\n"
        "# and to use the data a covariance will have to be assumed or gotten from some\n"
        "# other source.\n"
        "\n"
        "std_msgs/Header header               # timestamp is the time the\n"
        "                                           # field was measured\n"
        "                                           # frame_id is the location and orientation\n"
        "                                           # of the field measurement\n"
        "\n"
        "geometry_msgs/Vector3 magnetic_field # x, y, and z components of the\n"
        "                                           # field vector in Tesla\n"
        "                                           # If your sensor does not output 3 axes,\n"
        "                                           # put NaNs in the components not reported.\n"
        "\n"
        "float64[9] magnetic_field_covariance       # Row major about x, y, z axes\n"
        "                                           # 0 is interpreted as variance unknown\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    magnetic_field: Vector3 = msgspec.field(default_factory=Vector3)
    magnetic_field_covariance: Annotated[MutableSequence[float], msgspec.Meta(min_length=9, max_length=9)] = msgspec.field(default_factory=lambda: array("d", bytes(72)))

    def __post_init__(self) -> None:
        if type(self.magnetic_field_covariance) is not array or self.magnetic_field_covariance.typecode != "d":
            self.magnetic_field_covariance = held(self.magnetic_field_covariance, "d")


class MultiDOFJointState(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/MultiDOFJointState``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/MultiDOFJointState"
    __ros_definition__: ClassVar[str] = (
        "# Representation of state for joints with multiple degrees of freedom,\n"
        "# following the structure of JointState which can only represent a single degree of freedom.\n"
        "#\n"
        "# It is assumed that a joint in a system corresponds to a transform that gets applied\n"
        "# along the kinematic chain. For example, a planar joint (as in URDF) is 3DOF (x, y, yaw)\n"
        "# and those 3DOF can be expressed as a transformation matrix, and that transformation\n"
        "# matrix can be converted back to (x, y, yaw)\n"
        "#\n"
        "# Each joint is uniquely identified by its name\n"
        "# The header specifies the time at which the joint states were recorded. All the joint states\n"
        "# in one message have to be recorded at the same time.\n"
        "#\n"
        "# This message consists of a multiple arrays, one for each part of the joint state.\n"
        "# The goal is to make each of the fields optional. When e.g. your joints have no\n"
        "# wrench associated with them, you can leave the wrench array empty.\n"
        "#\n"
        "# All arrays in this message should have the same size, or be empty.\n"
        "# This is the only way to uniquely associate the joint name with the correct\n"
        "# states.\n"
        "\n"
        "std_msgs/Header header\n"
        "\n"
        "string[] joint_names\n"
        "geometry_msgs/Transform[] transforms\n"
        "geometry_msgs/Twist[] twist\n"
        "geometry_msgs/Wrench[] wrench\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    joint_names: list[str] = msgspec.field(default_factory=list)
    transforms: list[Transform] = msgspec.field(default_factory=list)
    twist: list[Twist] = msgspec.field(default_factory=list)
    wrench: list[Wrench] = msgspec.field(default_factory=list)


class MultiEchoLaserScan(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/MultiEchoLaserScan``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/MultiEchoLaserScan"
    __ros_definition__: ClassVar[str] = (
        "# Single scan from a multi-echo planar laser range-finder\n"
        "#\n"
        "# If you have another ranging device with different behavior (e.g. a sonar\n"
        "# array), please find or create a different message, since applications\n"
        "# will make fairly laser-specific assumptions about this data\n"
        "\n"
        "std_msgs/Header header # timestamp in the header is the acquisition time of\n"
        "                             # the first ray in the scan.\n"
        "                             #\n"
        "                             # in frame frame_id, angles are measured around\n"
        "                             # the positive Z axis (counterclockwise, if Z is up)\n"
        "                             # with zero angle being forward along the x axis\n"
        "\n"
        "float32 angle_min            # start angle of the scan [rad]\n"
        "float32 angle_max            # end angle of the scan [rad]\n"
        "float32 angle_increment      # angular distance between measurements [rad]\n"
        "\n"
        "float32 time_increment       # time between measurements [seconds] - if your scanner\n"
        "                             # is moving, this will be used in interpolating position\n"
        "                             # of 3d points\n"
        "float32 scan_time            # time between scans [seconds]\n"
        "\n"
        "float32 range_min            # minimum range value [m]\n"
        "float32 range_max            # maximum range value [m]\n"
        "\n"
        "LaserEcho[] ranges           # range data [m]\n"
        "                             # (Note: NaNs, values < range_min or > range_max should be discarded)\n"
        "                             # +Inf measurements are out of range\n"
        "                             # -Inf measurements are too close to determine exact distance.\n"
        "LaserEcho[] intensities      # intensity data [device-specific units].  If your\n"
        "                             # device does not provide intensities, please leave\n"
        "                             # the array empty.\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    angle_min: float = 0.0
    angle_max: float = 0.0
    angle_increment: float = 0.0
    time_increment: float = 0.0
    scan_time: float = 0.0
    range_min: float = 0.0
    range_max: float = 0.0
    ranges: list[LaserEcho] = msgspec.field(default_factory=list)
    intensities: list[LaserEcho] = msgspec.field(default_factory=list)


class NavSatStatus(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/NavSatStatus``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/NavSatStatus"
    __ros_definition__: ClassVar[str] = (
        "# Navigation Satellite fix status for any Global Navigation Satellite System.\n"
        "#\n"
        "# Whether to output an augmented fix is determined by both the fix\n"
        "# type and the last time differential corrections were received.  A\n"
        "# fix is valid when status >= STATUS_FIX.\n"
        "\n"
        "int8 STATUS_UNKNOWN = -2        # status is not yet set\n"
        "int8 STATUS_NO_FIX =  -1        # unable to fix position\n"
        "int8 STATUS_FIX =      0        # unaugmented fix\n"
        "int8 STATUS_SBAS_FIX = 1        # with satellite-based augmentation\n"
        "int8 STATUS_GBAS_FIX = 2        # with ground-based augmentation\n"
        "\n"
        "int8 status -2 # STATUS_UNKNOWN\n"
        "\n"
        "# Bits defining which Global Navigation Satellite System signals were\n"
        "# used by the receiver.\n"
        "\n"
        "uint16 SERVICE_UNKNOWN = 0  # Remember service is a bitfield, so checking (service & SERVICE_UNKNOWN) will not work. Use == instead.\n"
        "uint16 SERVICE_GPS =     1\n"
        "uint16 SERVICE_GLONASS = 2\n"
        "uint16 SERVICE_COMPASS = 4      # includes BeiDou.\n"
        "uint16 SERVICE_GALILEO = 8\n"
        "\n"
        "uint16 service\n"
    )
    STATUS_UNKNOWN: ClassVar[int] = -2
    STATUS_NO_FIX: ClassVar[int] = -1
    STATUS_FIX: ClassVar[int] = 0
    STATUS_SBAS_FIX: ClassVar[int] = 1
    STATUS_GBAS_FIX: ClassVar[int] = 2
    SERVICE_UNKNOWN: ClassVar[int] = 0
    SERVICE_GPS: ClassVar[int] = 1
    SERVICE_GLONASS: ClassVar[int] = 2
    SERVICE_COMPASS: ClassVar[int] = 4
    SERVICE_GALILEO: ClassVar[int] = 8

    status: _int8 = -2
    service: _uint16 = 0


class NavSatFix(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/NavSatFix``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/NavSatFix"
    __ros_definition__: ClassVar[str] = (
        "# Navigation Satellite fix for any Global Navigation Satellite System\n"
        "#\n"
        "# Specified using the WGS 84 reference ellipsoid\n"
        "\n"
        "# header.stamp specifies the ROS time for this measurement (the\n"
        "#        corresponding satellite time may be reported using the\n"
        "#        sensor_msgs/TimeReference message).\n"
        "#\n"
        "# header.frame_id is the frame of reference reported by the satellite\n"
        "#        receiver, usually the location of the antenna.  This is a\n"
        "#        Euclidean frame relative to the vehicle, not a reference\n"
        "#        ellipsoid.\n"
        "std_msgs/Header header\n"
        "\n"
        "# Satellite fix status information.\n"
        "NavSatStatus status\n"
        "\n"
        "# Latitude [degrees]. Positive is north of equator; negative is south.\n"
        "float64 latitude\n"
        "\n"
        "# Longitude [degrees]. Positive is east of prime meridian; negative is west.\n"
        "float64 longitude\n"
        "\n"
        "# Altitude [m]. Positive is above the WGS 84 ellipsoid\n"
        "# (quiet NaN if no altitude is available).\n"
        "float64 altitude\n"
        "\n"
        "# Position covariance [m^2] defined relative to a tangential plane\n"
        "# through the reported position. The components are East, North, and\n"
        "# Up (ENU), in row-major order.\n"
        "#\n"
        "# Beware: this coordinate system exhibits singularities at the poles.\n"
        "float64[9] position_covariance\n"
        "\n"
        "# If the covariance of the fix is known, fill it in completely. If the\n"
        "# GPS receiver provides the variance of each measurement, put them\n"
        "# along the diagonal. If only Dilution of Precision is available,\n"
        "# estimate an approximate covariance from that.\n"
        "\n"
        "uint8 COVARIANCE_TYPE_UNKNOWN = 0\n"
        "uint8 COVARIANCE_TYPE_APPROXIMATED = 1\n"
        "uint8 COVARIANCE_TYPE_DIAGONAL_KNOWN = 2\n"
        "uint8 COVARIANCE_TYPE_KNOWN = 3\n"
        "\n"
        "uint8 position_covariance_type\n"
    )
    COVARIANCE_TYPE_UNKNOWN: ClassVar[int] = 0
    COVARIANCE_TYPE_APPROXIMATED: ClassVar[int] = 1
    COVARIANCE_TYPE_DIAGONAL_KNOWN: ClassVar[int] = 2
    COVARIANCE_TYPE_KNOWN: ClassVar[int] = 3

    header: Header = msgspec.field(default_factory=Header)
    status: NavSatStatus = msgspec.field(default_factory=NavSatStatus)
    latitude: float = 0.0
    longitude: float = 0.0
    altitude: float = 0.0
    position_covariance: Annotated[MutableSequence[float], msgspec.Meta(min_length=9, max_length=9)] = msgspec.field(default_factory=lambda: array("d", bytes(72)))
    position_covariance_type: _uint8 = 0

    def __post_init__(self) -> None:
        if type(self.position_covariance) is not array or self.position_covariance.typecode != "d":
            self.position_covariance = held(self.position_covariance, "d")


class PointCloud(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/PointCloud``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/PointCloud"
    __ros_definition__: ClassVar[str] = (
        "## THIS MESSAGE IS DEPRECATED AS OF FOXY\n"
        "## Please use sensor_msgs/PointCloud2\n"
        "\n"
        "# This message holds a collection of 3d points, plus optional additional\n"
        "# information about each point.\n"
        "\n"
        "# Time of sensor data acquisition, coordinate frame ID.\n"
        "std_msgs/Header header\n"
        "\n"
        "# Array of 3d points. Each Point32 should be interpreted as a 3d point\n"
        "# in the frame given in the header.\n"
        "geometry_msgs/Point32[] points\n"
        "\n"
        "# Each channel should have the same number of elements as points array,\n"
        "# and the data in each channel should correspond 1:1 with each point.\n"
        "# Channel names in common practice are listed in ChannelFloat32.msg.\n"
        "ChannelFloat32[] channels\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    points: list[Point32] = msgspec.field(default_factory=list)
    channels: list[ChannelFloat32] = msgspec.field(default_factory=list)


class PointField(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/PointField``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/PointField"
    __ros_definition__: ClassVar[str] = (
        "# This message holds the description of one point entry in the\n"
        "# PointCloud2 message format.\n"
        "uint8 INT8    = 1\n"
        "uint8 UINT8   = 2\n"
        "uint8 INT16   = 3\n"
        "uint8 UINT16  = 4\n"
        "uint8 INT32   = 5\n"
        "uint8 UINT32  = 6\n"
        "uint8 FLOAT32 = 7\n"
        "uint8 FLOAT64 = 8\n"
        "\n"
        "# Common PointField names are x, y, z, intensity, rgb, rgba\n"
        "string name      # Name of field\n"
        "uint32 offset    # Offset from start of point struct\n"
        "uint8  datatype  # Datatype enumeration, see above\n"
        "uint32 count     # How many elements in the field\n"
    )
    INT8: ClassVar[int] = 1
    UINT8: ClassVar[int] = 2
    INT16: ClassVar[int] = 3
    UINT16: ClassVar[int] = 4
    INT32: ClassVar[int] = 5
    UINT32: ClassVar[int] = 6
    FLOAT32: ClassVar[int] = 7
    FLOAT64: ClassVar[int] = 8

    name: str = ""
    offset: _uint32 = 0
    datatype: _uint8 = 0
    count: _uint32 = 0


class PointCloud2(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/PointCloud2``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/PointCloud2"
    __ros_definition__: ClassVar[str] = (
        "# This message holds a collection of N-dimensional points, which may\n"
        "# contain additional information such as normals, intensity, etc. The\n"
        "# point data is stored as a binary blob, its layout described by the\n"
        "# contents of the \"fields\" array.\n"
        "#\n"
        "# The point cloud data may be organized 2d (image-like) or 1d (unordered).\n"
        "# Point clouds organized as 2d images may be produced by camera depth sensors\n"
        "# such as stereo or time-of-flight.\n"
        "\n"
        "# Time of sensor data acquisition, and the coordinate frame ID (for 3d points).\n"
        "std_msgs/Header header\n"
        "\n"
        "# 2D structure of the point cloud. If the cloud is unordered, height is\n"
        "# 1 and width is the length of the point cloud.\n"
        "uint32 height\n"
        "uint32 width\n"
        "\n"
        "# Describes the channels and their layout in the binary data blob.\n"
        "PointField[] fields\n"
        "\n"
        "bool    is_bigendian # Is this data bigendian?\n"
        "uint32  point_step   # Length of a point in bytes\n"
        "uint32  row_step     # Length of a row in bytes\n"
        "uint8[] data         # Actual point data, size is (row_step*height)\n"
        "\n"
        "bool is_dense        # True if there are no invalid points\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    height: _uint32 = 0
    width: _uint32 = 0
    fields: list[PointField] = msgspec.field(default_factory=list)
    is_bigendian: bool = False
    point_step: _uint32 = 0
    row_step: _uint32 = 0
    data: bytes = b""
    is_dense: bool = False


class Range(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/Range``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/Range"
    __ros_definition__: ClassVar[str] = (
        "# Single range reading from an active ranger that emits energy and reports\n"
        "# one range reading that is valid along an arc at the distance measured.\n"
        "# This message is  not appropriate for laser scanners. See the LaserScan\n"
        "# message if you are working with a laser scanner.\n"
        "#\n"
        "# This message also can represent a fixed-distance (binary) ranger.  This\n"
        "# sensor will have min_range===max_range===distance of detection.\n"
        "# These sensors follow REP 117 and will output -Inf if the object is detected\n"
        "# and +Inf if the object is outside of the detection range.\n"
        "\n"
        "std_msgs/Header header # timestamp in the header is the time the ranger\n"
        "                             # returned the distance reading\n"
        "\n"
        "# Radiation type enums\n"
        "# If you want a value added to this list, send an email to the ros-users list\n"
        "uint8 ULTRASOUND=0\n"
        "uint8 INFRARED=1\n"
        "\n"
        "uint8 radiation_type    # the type of radiation used by the sensor\n"
        "                        # (sound, IR, etc) [enum]\n"
        "\n"
        "float32 field_of_view   # the size of the arc that the distance reading is\n"
        "                        # valid for [rad]\n"
        "                        # the object causing the range reading may have\n"
        "                        # been anywhere within -field_of_view/2 and\n"
        "                        # field_of_view/2 at the measured range.\n"
        "                        # 0 angle corresponds to the x-axis of the sensor.\n"
        "\n"
        "float32 min_range       # minimum range value [m]\n"
        "float32 max_range       # maximum range value [m]\n"
        "                        # Fixed distance rangers require min_range==max_range\n"
        "\n"
        "float32 range           # range data [m]\n"
        "                        # (Note: values < range_min or > range_max should be discarded)\n"
        "                        # Fixed distance rangers only output -Inf or +Inf.\n"
        "                        # -Inf represents a detection within fixed distance.\n"
        "                        # (Detection too close to the sensor to quantify)\n"
        "                        # +Inf represents no detection within the fixed distance.\n"
        "                        # (Object out of range)\n"
        "\n"
        "float32 variance        # variance of the range sensor\n"
        "                        # 0 is interpreted as variance unknown\n"
    )
    ULTRASOUND: ClassVar[int] = 0
    INFRARED: ClassVar[int] = 1

    header: Header = msgspec.field(default_factory=Header)
    radiation_type: _uint8 = 0
    field_of_view: float = 0.0
    min_range: float = 0.0
    max_range: float = 0.0
    range: float = 0.0
    variance: float = 0.0


class RelativeHumidity(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/RelativeHumidity``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/RelativeHumidity"
    __ros_definition__: ClassVar[str] = (
        "# Single reading from a relative humidity sensor.\n"
        "# Defines the ratio of partial pressure of water vapor to the saturated vapor\n"
        "# pressure at a temperature.\n"
        "\n"
        "std_msgs/Header header # timestamp of the measurement\n"
        "                             # frame_id is the location of the humidity sensor\n"
        "\n"
        "float64 relative_humidity    # Expression of the relative humidity\n"
        "                             # from 0.0 to 1.0.\n"
        "                             # 0.0 is no partial pressure of water vapor\n"
        "                             # 1.0 represents partial pressure of saturation\n"
        "\n"
        "float64 variance             # 0 is interpreted as variance unknown\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    relative_humidity: float = 0.0
    variance: float = 0.0


class Temperature(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/Temperature``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/Temperature"
    __ros_definition__: ClassVar[str] = (
        "# Single temperature reading.\n"
        "\n"
        "std_msgs/Header header # timestamp is the time the temperature was measured\n"
        "                             # frame_id is the location of the temperature reading\n"
        "\n"
        "float64 temperature          # Measurement of the Temperature in Degrees Celsius.\n"
        "\n"
        "float64 variance             # 0 is interpreted as variance unknown.\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    temperature: float = 0.0
    variance: float = 0.0


class TimeReference(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``sensor_msgs/msg/TimeReference``."""

    __ros_type__: ClassVar[str] = "sensor_msgs/msg/TimeReference"
    __ros_definition__: ClassVar[str] = (
        "# Measurement from an external time source not actively synchronized with the system clock.\n"
        "\n"
        "std_msgs/Header header      # stamp is system time for which measurement was valid\n"
        "                                  # frame_id is not used\n"
        "\n"
        "builtin_interfaces/Time time_ref  # corresponding time from this external source\n"
        "string source                     # (optional) name of time source\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    time_ref: Time = msgspec.field(default_factory=Time)
    source: str = ""
