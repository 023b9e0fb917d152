"""Generated from visualization_msgs/msg/*.msg by `python -m actors interface generate`; do not edit."""

from typing import Annotated, ClassVar

import msgspec

from interfaces.builtin_interfaces.msg import Duration
from interfaces.geometry_msgs.msg import Point, Pose, Quaternion, Vector3
from interfaces.sensor_msgs.msg import CompressedImage
from interfaces.std_msgs.msg import ColorRGBA, Header

__all__ = [
    "ImageMarker",
    "InteractiveMarker",
    "InteractiveMarkerControl",
    "InteractiveMarkerFeedback",
    "InteractiveMarkerInit",
    "InteractiveMarkerPose",
    "InteractiveMarkerUpdate",
    "Marker",
    "MarkerArray",
    "MenuEntry",
    "MeshFile",
    "UVCoordinate",
]

_uint8 = Annotated[int, msgspec.Meta(ge=0, le=255)]
_int32 = Annotated[int, msgspec.Meta(ge=-2147483648, le=2147483647)]
_uint32 = Annotated[int, msgspec.Meta(ge=0, le=4294967295)]
_uint64 = Annotated[int, msgspec.Meta(ge=0)]


class ImageMarker(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``visualization_msgs/msg/ImageMarker``."""

    __ros_type__: ClassVar[str] = "visualization_msgs/msg/ImageMarker"
    __ros_definition__: ClassVar[str] = (
        "int32 CIRCLE=0\n"
        "int32 LINE_STRIP=1\n"
        "int32 LINE_LIST=2\n"
        "int32 POLYGON=3\n"
        "int32 POINTS=4\n"
        "\n"
        "int32 ADD=0\n"
        "int32 REMOVE=1\n"
        "\n"
        "std_msgs/Header header\n"
        "# Namespace which is used with the id to form a unique id.\n"
        "string ns\n"
        "# Unique id within the namespace.\n"
        "int32 id\n"
        "# One of the above types, e.g. CIRCLE, LINE_STRIP, etc.\n"
        "int32 type\n"
        "# Either ADD or REMOVE.\n"
        "int32 action\n"
        "# Two-dimensional coordinate position, in pixel-coordinates.\n"
        "geometry_msgs/Point position\n"
        "# The scale of the object, e.g. the diameter for a CIRCLE.\n"
        "float32 scale\n"
        "# The outline color of the marker.\n"
        "std_msgs/ColorRGBA outline_color\n"
        "# Whether or not to fill in the shape with color.\n"
        "uint8 filled\n"
        "# Fill color; in the range: [0.0-1.0]\n"
        "std_msgs/ColorRGBA fill_color\n"
        "# How long the object should last before being automatically deleted.\n"
        "# 0 indicates forever.\n"
        "builtin_interfaces/Duration lifetime\n"
        "\n"
        "# Coordinates in 2D in pixel coords. Used for LINE_STRIP, LINE_LIST, POINTS, etc.\n"
        "geometry_msgs/Point[] points\n"
        "# The color for each line, point, etc. in the points field.\n"
        "std_msgs/ColorRGBA[] outline_colors\n"
    )
    CIRCLE: ClassVar[int] = 0
    LINE_STRIP: ClassVar[int] = 1
    LINE_LIST: ClassVar[int] = 2
    POLYGON: ClassVar[int] = 3
    POINTS: ClassVar[int] = 4
    ADD: ClassVar[int] = 0
    REMOVE: ClassVar[int] = 1

    header: Header = msgspec.field(default_factory=Header)
    ns: str = ""
    id: _int32 = 0
    type: _int32 = 0
    action: _int32 = 0
    position: Point = msgspec.field(default_factory=Point)
    scale: float = 0.0
    outline_color: ColorRGBA = msgspec.field(default_factory=ColorRGBA)
    filled: _uint8 = 0
    fill_color: ColorRGBA = msgspec.field(default_factory=ColorRGBA)
    lifetime: Duration = msgspec.field(default_factory=Duration)
    points: list[Point] = msgspec.field(default_factory=list)
    outline_colors: list[ColorRGBA] = msgspec.field(default_factory=list)


class MenuEntry(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``visualization_msgs/msg/MenuEntry``."""

    __ros_type__: ClassVar[str] = "visualization_msgs/msg/MenuEntry"
    __ros_definition__: ClassVar[str] = (
        "# MenuEntry message.\n"
        "#\n"
        "# Each InteractiveMarker message has an array of MenuEntry messages.\n"
        "# A collection of MenuEntries together describe a\n"
        "# menu/submenu/subsubmenu/etc tree, though they are stored in a flat\n"
        "# array.  The tree structure is represented by giving each menu entry\n"
        "# an ID number and a \"parent_id\" field.  Top-level entries are the\n"
        "# ones with parent_id = 0.  Menu entries are ordered within their\n"
        "# level the same way they are ordered in the containing array.  Parent\n"
        "# entries must appear before their children.\n"
        "#\n"
        "# Example:\n"
        "# - id = 3\n"
        "#   parent_id = 0\n"
        "#   title = \"fun\"\n"
        "# - id = 2\n"
        "#   parent_id = 0\n"
        "#   title = \"robot\"\n"
        "# - id = 4\n"
        "#   parent_id = 2\n"
        "#   title = \"pr2\"\n"
        "# - id = 5\n"
        "#   parent_id = 2\n"
        "#   title = \"turtle\"\n"
        "#\n"
        "# Gives a menu tree like this:\n"
        "#  - fun\n"
        "#  - robot\n"
        "#    - pr2\n"
        "#    - turtle\n"
        "\n"
        "# ID is a number for each menu entry.  Must be unique within the\n"
        "# control, and should never be 0.\n"
        "uint32 id\n"
        "\n"
        "# ID of the parent of this menu entry, if it is a submenu.  If this\n"
        "# menu entry is a top-level entry, set parent_id to 0.\n"
        "uint32 parent_id\n"
        "\n"
        "# menu / entry title\n"
        "string title\n"
        "\n"
        "# Arguments to command indicated by command_type (below)\n"
        "string command\n"
        "\n"
        "# Command_type stores the type of response desired when this menu\n"
        "# entry is clicked.\n"
        "# FEEDBACK: send an InteractiveMarkerFeedback message with menu_entry_id set to this entry's id.\n"
        "# ROSRUN: execute \"rosrun\" with arguments given in the command field (above).\n"
        "# ROSLAUNCH: execute \"roslaunch\" with arguments given in the command field (above).\n"
        "uint8 FEEDBACK=0\n"
        "uint8 ROSRUN=1\n"
        "uint8 ROSLAUNCH=2\n"
        "uint8 command_type\n"
    )
    FEEDBACK: ClassVar[int] = 0
    ROSRUN: ClassVar[int] = 1
    ROSLAUNCH: ClassVar[int] = 2

    id: _uint32 = 0
    parent_id: _uint32 = 0
    title: str = ""
    command: str = ""
    command_type: _uint8 = 0


class UVCoordinate(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``visualization_msgs/msg/UVCoordinate``."""

    __ros_type__: ClassVar[str] = "visualization_msgs/msg/UVCoordinate"
    __ros_definition__: ClassVar[str] = (
        "# Location of the pixel as a ratio of the width of a 2D texture.\n"
        "# Values should be in range: [0.0-1.0].\n"
        "float32 u\n"
        "float32 v\n"
    )

    u: float = 0.0
    v: float = 0.0


class MeshFile(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``visualization_msgs/msg/MeshFile``."""

    __ros_type__: ClassVar[str] = "visualization_msgs/msg/MeshFile"
    __ros_definition__: ClassVar[str] = (
        "# Used to send raw mesh files.\n"
        "\n"
        "# The filename is used for both debug purposes and to provide a file extension\n"
        "# for whatever parser is used.\n"
        "string filename\n"
        "\n"
        "# This stores the raw text of the mesh file.\n"
        "uint8[] data\n"
    )

    filename: str = ""
    data: bytes = b""


class Marker(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``visualization_msgs/msg/Marker``."""

    __ros_type__: ClassVar[str] = "visualization_msgs/msg/Marker"
    __ros_definition__: ClassVar[str] = (
        "# See:\n"
        "#  - http://www.ros.org/wiki/rviz/DisplayTypes/Marker\n"
        "#  - http://www.ros.org/wiki/rviz/Tutorials/Markers%3A%20Basic%20Shapes\n"
        "#\n"
        "# for more information on using this message with rviz.\n"
        "\n"
        "int32 ARROW=0\n"
        "int32 CUBE=1\n"
        "int32 SPHERE=2\n"
        "int32 CYLINDER=3\n"
        "int32 LINE_STRIP=4\n"
        "int32 LINE_LIST=5\n"
        "int32 CUBE_LIST=6\n"
        "int32 SPHERE_LIST=7\n"
        "int32 POINTS=8\n"
        "int32 TEXT_VIEW_FACING=9\n"
        "int32 MESH_RESOURCE=10\n"
        "int32 TRIANGLE_LIST=11\n"
        "int32 ARROW_STRIP=12\n"
        "\n"
        "int32 ADD=0\n"
        "int32 MODIFY=0\n"
        "int32 DELETE=2\n"
        "int32 DELETEALL=3\n"
        "\n"
        "# Header for timestamp and frame id.\n"
        "std_msgs/Header header\n"
        "# Namespace in which to place the object.\n"
        "# Used in conjunction with id to create a unique name for the object.\n"
        "string ns\n"
        "# Object ID used in conjunction with the namespace for manipulating and deleting the object later.\n"
        "int32 id\n"
        "# Type of object.\n"
        "int32 type\n"
        "# Action to take; one of:\n"
        "#  - 0 add/modify an object\n"
        "#  - 1 (deprecated)\n"
        "#  - 2 deletes an object (with the given ns and id)\n"
        "#  - 3 deletes all objects (or those with the given ns if any)\n"
        "int32 action\n"
        "# Pose of the object with respect the frame_id specified in the header.\n"
        "geometry_msgs/Pose pose\n"
        "# Scale of the object; 1,1,1 means default (usually 1 meter square).\n"
        "geometry_msgs/Vector3 scale\n"
        "# Color of the object; in the range: [0.0-1.0]\n"
        "std_msgs/ColorRGBA color\n"
        "# How long the object should last before being automatically deleted.\n"
        "# 0 indicates forever.\n"
        "builtin_interfaces/Duration lifetime\n"
        "# If this marker should be frame-locked, i.e. retransformed into its frame every timestep.\n"
        "bool frame_locked\n"
        "\n"
        "# Only used if the type specified has some use for them (eg. POINTS, LINE_STRIP, ARROW_STRIP, etc.)\n"
        "geometry_msgs/Point[] points\n"
        "# Only used if the type specified has some use for them (eg. POINTS, LINE_STRIP, etc.)\n"
        "# The number of colors provided must either be 0 or equal to the number of points provided.\n"
        "# NOTE: alpha is not yet used\n"
        "std_msgs/ColorRGBA[] colors\n"
        "\n"
        "# Texture resource is a special URI that can either reference a texture file in\n"
        "# a format acceptable to (resource retriever)[https://docs.ros.org/en/rolling/p/resource_retriever/]\n"
        "# or an embedded texture via a string matching the format:\n"
        "#   \"embedded://texture_name\"\n"
        "string texture_resource\n"
        "# An image to be loaded into the rendering engine as the texture for this marker.\n"
        "# This will be used iff texture_resource is set to embedded.\n"
        "sensor_msgs/CompressedImage texture\n"
        "# Location of each vertex within the texture; in the range: [0.0-1.0]\n"
        "UVCoordinate[] uv_coordinates\n"
        "\n"
        "# Only used for text markers\n"
        "string text\n"
        "\n"
        "# Only used for MESH_RESOURCE markers.\n"
        "# Similar to texture_resource, mesh_resource uses resource retriever to load a mesh.\n"
        "# Optionally, a mesh file can be sent in-message via the mesh_file field. If doing so,\n"
        "# use the following format for mesh_resource:\n"
        "#   \"embedded://mesh_name\"\n"
        "string mesh_resource\n"
        "MeshFile mesh_file\n"
        "bool mesh_use_embedded_materials\n"
    )
    ARROW: ClassVar[int] = 0
    CUBE: ClassVar[int] = 1
    SPHERE: ClassVar[int] = 2
    CYLINDER: ClassVar[int] = 3
    LINE_STRIP: ClassVar[int] = 4
    LINE_LIST: ClassVar[int] = 5
    CUBE_LIST: ClassVar[int] = 6
    SPHERE_LIST: ClassVar[int] = 7
    POINTS: ClassVar[int] = 8
    TEXT_VIEW_FACING: ClassVar[int] = 9
    MESH_RESOURCE: ClassVar[int] = 10
    TRIANGLE_LIST: ClassVar[int] = 11
    ARROW_STRIP: ClassVar[int] = 12
    ADD: ClassVar[int] = 0
    MODIFY: ClassVar[int] = 0
    DELETE: ClassVar[int] = 2
    DELETEALL: ClassVar[int] = 3

    header: Header = msgspec.field(default_factory=Header)
    ns: str = ""
    id: _int32 = 0
    type: _int32 = 0
    action: _int32 = 0
    pose: Pose = msgspec.field(default_factory=Pose)
    scale: Vector3 = msgspec.field(default_factory=Vector3)
    color: ColorRGBA = msgspec.field(default_factory=ColorRGBA)
    lifetime: Duration = msgspec.field(default_factory=Duration)
    frame_locked: bool = False
    points: list[Point] = msgspec.field(default_factory=list)
    colors: list[ColorRGBA] = msgspec.field(default_factory=list)
    texture_resource: str = ""
    texture: CompressedImage = msgspec.field(default_factory=CompressedImage)
    uv_coordinates: list[UVCoordinate] = msgspec.field(default_factory=list)
    text: str = ""
    mesh_resource: str = ""
    mesh_file: MeshFile = msgspec.field(default_factory=MeshFile)
    mesh_use_embedded_materials: bool = False


class InteractiveMarkerControl(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``visualization_msgs/msg/InteractiveMarkerControl``."""

    __ros_type__: ClassVar[str] = "visualization_msgs/msg/InteractiveMarkerControl"
    __ros_definition__: ClassVar[str] = (
        "# Represents a control that is to be displayed together with an interactive marker\n"
        "\n"
        "# Identifying string for this control.\n"
        "# You need to assign a unique value to this to receive feedback from the GUI\n"
        "# on what actions the user performs on this control (e.g. a button click).\n"
        "string name\n"
        "\n"
        "\n"
        "# Defines the local coordinate frame (relative to the pose of the parent\n"
        "# interactive marker) in which is being rotated and translated.\n"
        "# Default: Identity\n"
        "geometry_msgs/Quaternion orientation\n"
        "\n"
        "\n"
        "# Orientation mode: controls how orientation changes.\n"
        "# INHERIT: Follow orientation of interactive marker\n"
        "# FIXED: Keep orientation fixed at initial state\n"
        "# VIEW_FACING: Align y-z plane with screen (x: forward, y:left, z:up).\n"
        "uint8 INHERIT = 0\n"
        "uint8 FIXED = 1\n"
        "uint8 VIEW_FACING = 2\n"
        "\n"
        "uint8 orientation_mode\n"
        "\n"
        "# Interaction mode for this control\n"
        "#\n"
        "# NONE: This control is only meant for visualization; no context menu.\n"
        "# MENU: Like NONE, but right-click menu is active.\n"
        "# BUTTON: Element can be left-clicked.\n"
        "# MOVE_AXIS: Translate along local x-axis.\n"
        "# MOVE_PLANE: Translate in local y-z plane.\n"
        "# ROTATE_AXIS: Rotate around local x-axis.\n"
        "# MOVE_ROTATE: Combines MOVE_PLANE and ROTATE_AXIS.\n"
        "uint8 NONE = 0\n"
        "uint8 MENU = 1\n"
        "uint8 BUTTON = 2\n"
        "uint8 MOVE_AXIS = 3\n"
        "uint8 MOVE_PLANE = 4\n"
        "uint8 ROTATE_AXIS = 5\n"
        "uint8 MOVE_ROTATE = 6\n"
        "# \"3D\" interaction modes work with the mouse+SHIFT+CTRL or with 3D cursors.\n"
        "# MOVE_3D: Translate freely in 3D space.\n"
        "# ROTATE_3D: Rotate freely in 3D space about the origin of parent frame.\n"
        "# MOVE_ROTATE_3D: Full 6-DOF freedom of translation and rotation about the cursor origin.\n"
        "uint8 MOVE_3D = 7\n"
        "uint8 ROTATE_3D = 8\n"
        "uint8 MOVE_ROTATE_3D = 9\n"
        "\n"
        "uint8 interaction_mode\n"
        "\n"
        "\n"
        "# If true, the contained markers will also be visible\n"
        "# when the gui is not in interactive mode.\n"
        "bool always_visible\n"
        "\n"
        "\n"
        "# Markers to be displayed as custom visual representation.\n"
        "# Leave this empty to use the default control handles.\n"
        "#\n"
        "# Note:\n"
        "# - The markers can be defined in an arbitrary coordinate frame,\n"
        "#   but will be transformed into the local frame of the interactive marker.\n"
        "# - If the header of a marker is empty, its pose will be interpreted as\n"
        "#   relative to the pose of the parent interactive marker.\n"
        "Marker[] markers\n"
        "\n"
        "\n"
        "# In VIEW_FACING mode, set this to true if you don't want the markers\n"
        "# to be aligned with the camera view point. The markers will show up\n"
        "# as in INHERIT mode.\n"
        "bool independent_marker_orientation\n"
        "\n"
        "\n"
        "# Short description (< 40 characters) of what this control does,\n"
        "# e.g. \"Move the robot\".\n"
        "# Default: A generic description based on the interaction mode\n"
        "string description\n"
    )
    INHERIT: ClassVar[int] = 0
    FIXED: ClassVar[int] = 1
    VIEW_FACING: ClassVar[int] = 2
    NONE: ClassVar[int] = 0
    MENU: ClassVar[int] = 1
    BUTTON: ClassVar[int] = 2
    MOVE_AXIS: ClassVar[int] = 3
    MOVE_PLANE: ClassVar[int] = 4
    ROTATE_AXIS: ClassVar[int] = 5
    MOVE_ROTATE: ClassVar[int] = 6
    MOVE_3D: ClassVar[int] = 7
    ROTATE_3D: ClassVar[int] = 8
    MOVE_ROTATE_3D: ClassVar[int] = 9

    name: str = ""
    orientation: Quaternion = msgspec.field(default_factory=Quaternion)
    orientation_mode: _uint8 = 0
    interaction_mode: _uint8 = 0
    always_visible: bool = False
    markers: list[Marker] = msgspec.field(default_factory=list)
    independent_marker_orientation: bool = False
    description: str = ""


class InteractiveMarker(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``visualization_msgs/msg/InteractiveMarker``."""

    __ros_type__: ClassVar[str] = "visualization_msgs/msg/InteractiveMarker"
    __ros_definition__: ClassVar[str] = (
        "# Time/frame info.\n"
        "# If header.time is set to 0, the marker will be retransformed into\n"
        "# its frame on each timestep. You will receive the pose feedback\n"
        "# in the same frame.\n"
        "# Otherwise, you might receive feedback in a different frame.\n"
        "# For rviz, this will be the current 'fixed frame' set by the user.\n"
        "std_msgs/Header header\n"
        "\n"
        "# Initial pose. Also, defines the pivot point for rotations.\n"
        "geometry_msgs/Pose pose\n"
        "\n"
        "# Identifying string. Must be globally unique in\n"
        "# the topic that this message is sent through.\n"
        "string name\n"
        "\n"
        "# Short description (< 40 characters).\n"
        "string description\n"
        "\n"
        "# Scale to be used for default controls (default=1).\n"
        "float32 scale\n"
        "\n"
        "# All menu and submenu entries associated with this marker.\n"
        "MenuEntry[] menu_entries\n"
        "\n"
        "# List of controls displayed for this marker.\n"
        "InteractiveMarkerControl[] controls\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    pose: Pose = msgspec.field(default_factory=Pose)
    name: str = ""
    description: str = ""
    scale: float = 0.0
    menu_entries: list[MenuEntry] = msgspec.field(default_factory=list)
    controls: list[InteractiveMarkerControl] = msgspec.field(default_factory=list)


class InteractiveMarkerFeedback(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``visualization_msgs/msg/InteractiveMarkerFeedback``."""

    __ros_type__: ClassVar[str] = "visualization_msgs/msg/InteractiveMarkerFeedback"
    __ros_definition__: ClassVar[str] = (
        "# Time/frame info.\n"
        "std_msgs/Header header\n"
        "\n"
        "# Identifying string. Must be unique in the topic namespace.\n"
        "string client_id\n"
        "\n"
        "# Feedback message sent back from the GUI, e.g.\n"
        "# when the status of an interactive marker was modified by the user.\n"
        "\n"
        "# Specifies which interactive marker and control this message refers to\n"
        "string marker_name\n"
        "string control_name\n"
        "\n"
        "# Type of the event\n"
        "# KEEP_ALIVE: sent while dragging to keep up control of the marker\n"
        "# MENU_SELECT: a menu entry has been selected\n"
        "# BUTTON_CLICK: a button control has been clicked\n"
        "# POSE_UPDATE: the pose has been changed using one of the controls\n"
        "uint8 KEEP_ALIVE = 0\n"
        "uint8 POSE_UPDATE = 1\n"
        "uint8 MENU_SELECT = 2\n"
        "uint8 BUTTON_CLICK = 3\n"
        "\n"
        "uint8 MOUSE_DOWN = 4\n"
        "uint8 MOUSE_UP = 5\n"
        "\n"
        "uint8 event_type\n"
        "\n"
        "# Current pose of the marker\n"
        "# Note: Has to be valid for all feedback types.\n"
        "geometry_msgs/Pose pose\n"
        "\n"
        "# Contains the ID of the selected menu entry\n"
        "# Only valid for MENU_SELECT events.\n"
        "uint32 menu_entry_id\n"
        "\n"
        "# If event_type is BUTTON_CLICK, MOUSE_DOWN, or MOUSE_UP, mouse_point\n"
        "# may contain the 3 dimensional position of the event on the\n"
        "# control.  If it does, mouse_point_valid will be true.  mouse_point\n"
        "# will be relative to the frame listed in the header.\n"
        "geometry_msgs/Point mouse_point\n"
        "bool mouse_point_valid\n"
    )
    KEEP_ALIVE: ClassVar[int] = 0
    POSE_UPDATE: ClassVar[int] = 1
    MENU_SELECT: ClassVar[int] = 2
    BUTTON_CLICK: ClassVar[int] = 3
    MOUSE_DOWN: ClassVar[int] = 4
    MOUSE_UP: ClassVar[int] = 5

    header: Header = msgspec.field(default_factory=Header)
    client_id: str = ""
    marker_name: str = ""
    control_name: str = ""
    event_type: _uint8 = 0
    pose: Pose = msgspec.field(default_factory=Pose)
    menu_entry_id: _uint32 = 0
    mouse_point: Point = msgspec.field(default_factory=Point)
    mouse_point_valid: bool = False


class InteractiveMarkerInit(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``visualization_msgs/msg/InteractiveMarkerInit``."""

    __ros_type__: ClassVar[str] = "visualization_msgs/msg/InteractiveMarkerInit"
    __ros_definition__: ClassVar[str] = (
        "# Identifying string. Must be unique in the topic namespace\n"
        "# that this server works on.\n"
        "string server_id\n"
        "\n"
        "# Sequence number.\n"
        "# The client will use this to detect if it has missed a subsequent\n"
        "# update.  Every update message will have the same sequence number as\n"
        "# an init message.  Clients will likely want to unsubscribe from the\n"
        "# init topic after a successful initialization to avoid receiving\n"
        "# duplicate data.\n"
        "uint64 seq_num\n"
        "\n"
        "# All markers.\n"
        "InteractiveMarker[] markers\n"
    )

    server_id: str = ""
    seq_num: _uint64 = 0
    markers: list[InteractiveMarker] = msgspec.field(default_factory=list)


class InteractiveMarkerPose(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``visualization_msgs/msg/InteractiveMarkerPose``."""

    __ros_type__: ClassVar[str] = "visualization_msgs/msg/InteractiveMarkerPose"
    __ros_definition__: ClassVar[str] = (
        "\n"
        "# Time/frame info.\n"
        "std_msgs/Header header\n"
        "\n"
        "# Initial pose. Also, defines the pivot point for rotations.\n"
        "geometry_msgs/Pose pose\n"
        "\n"
        "# Identifying string. Must be globally unique in\n"
        "# the topic that this message is sent through.\n"
        "string name\n"
    )

    header: Header = msgspec.field(default_factory=Header)
    pose: Pose = msgspec.field(default_factory=Pose)
    name: str = ""


class InteractiveMarkerUpdate(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``visualization_msgs/msg/InteractiveMarkerUpdate``."""

    __ros_type__: ClassVar[str] = "visualization_msgs/msg/InteractiveMarkerUpdate"
    __ros_definition__: ClassVar[str] = (
        "\n"
        "# Identifying string. Must be unique in the topic namespace\n"
        "# that this server works on.\n"
        "string server_id\n"
        "\n"
        "# Sequence number.\n"
        "# The client will use this to detect if it has missed an update.\n"
        "uint64 seq_num\n"
        "\n"
        "# Type holds the purpose of this message.  It must be one of UPDATE or KEEP_ALIVE.\n"
        "# UPDATE: Incremental update to previous state.\n"
        "#         The sequence number must be 1 higher than for\n"
        "#         the previous update.\n"
        "# KEEP_ALIVE: Indicates the that the server is still living.\n"
        "#             The sequence number does not increase.\n"
        "#             No payload data should be filled out (markers, poses, or erases).\n"
        "uint8 KEEP_ALIVE = 0\n"
        "uint8 UPDATE = 1\n"
        "\n"
        "uint8 type\n"
        "\n"
        "# Note: No guarantees on the order of processing.\n"
        "#       Contents must be kept consistent by sender.\n"
        "\n"
        "# Markers to be added or updated\n"
        "InteractiveMarker[] markers\n"
        "\n"
        "# Poses of markers that should be moved\n"
        "InteractiveMarkerPose[] poses\n"
        "\n"
        "# Names of markers to be erased\n"
        "string[] erases\n"
    )
    KEEP_ALIVE: ClassVar[int] = 0
    UPDATE: ClassVar[int] = 1

    server_id: str = ""
    seq_num: _uint64 = 0
    type: _uint8 = 0
    markers: list[InteractiveMarker] = msgspec.field(default_factory=list)
    poses: list[InteractiveMarkerPose] = msgspec.field(default_factory=list)
    erases: list[str] = msgspec.field(default_factory=list)


class MarkerArray(msgspec.Struct, kw_only=True, forbid_unknown_fields=True):
    """``visualization_msgs/msg/MarkerArray``."""

    __ros_type__: ClassVar[str] = "visualization_msgs/msg/MarkerArray"
    __ros_definition__: ClassVar[str] = (
        "Marker[] markers\n"
    )

    markers: list[Marker] = msgspec.field(default_factory=list)
