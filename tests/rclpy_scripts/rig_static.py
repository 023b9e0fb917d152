"""A camera rig's fixed frames, sent once as one tuple of transforms on /tf_static.

examples_tf2_py's static broadcaster makes these calls; this is our own program.
"""

import math

import rclpy
from geometry_msgs.msg import TransformStamped
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from tf2_ros.static_transform_broadcaster import StaticTransformBroadcaster


def mount(node, parent, child, xyz, yaw):
    """``child`` fixed on ``parent`` at ``xyz``, turned by ``yaw`` radians about z."""
    t = TransformStamped()
    t.header.stamp = node.get_clock().now().to_msg()
    t.header.frame_id = parent
    t.child_frame_id = child
    t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = xyz
    t.transform.rotation.z = math.sin(yaw / 2)
    t.transform.rotation.w = math.cos(yaw / 2)
    return t


class Rig(Node):
    def __init__(self):
        super().__init__("rig_static")
        self.broadcaster = StaticTransformBroadcaster(self)
        self.broadcaster.sendTransform(
            (
                mount(self, "base", "mast", (0.0, 0.0, 0.5), 0.0),
                mount(self, "mast", "camera", (0.1, 0.0, 0.05), math.radians(30)),
                mount(self, "mast", "lidar", (0.0, 0.0, 0.1), math.radians(-90)),
            )
        )


def main():
    try:
        with rclpy.init():
            rclpy.spin(Rig())
    except (KeyboardInterrupt, ExternalShutdownException):
        pass


if __name__ == "__main__":
    main()
