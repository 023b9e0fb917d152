"""A static frame, as the tf2 tutorial's static broadcaster: CHILD X Y Z ROLL PITCH YAW, under 'world'."""

import sys

import rclpy
from geometry_msgs.msg import TransformStamped
from rclpy.node import Node
from tf2_ros.static_transform_broadcaster import StaticTransformBroadcaster
from tf_transformations import quaternion_from_euler


class StaticFrame(Node):
    def __init__(self, child: str, numbers: list[float]) -> None:
        super().__init__("static_turtle_tf2_broadcaster")
        self.broadcaster = StaticTransformBroadcaster(self)
        t = TransformStamped()
        t.header.stamp = self.get_clock().now().to_msg()
        t.header.frame_id = "world"
        t.child_frame_id = child
        t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = numbers[:3]
        q = quaternion_from_euler(*numbers[3:])
        t.transform.rotation.x, t.transform.rotation.y = q[0], q[1]
        t.transform.rotation.z, t.transform.rotation.w = q[2], q[3]
        self.broadcaster.sendTransform(t)


def main() -> None:
    args = rclpy.utilities.remove_ros_args(sys.argv)[1:]
    if len(args) != 7:
        print("usage: static_turtle_tf2_broadcaster.py CHILD X Y Z ROLL PITCH YAW", file=sys.stderr)
        sys.exit(2)
    rclpy.init()
    node = StaticFrame(args[0], [float(a) for a in args[1:]])
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    rclpy.try_shutdown()


if __name__ == "__main__":
    main()
