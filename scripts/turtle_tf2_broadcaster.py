"""A turtle's frame under 'world' from its pose, as the tf2 tutorial's broadcaster (parameter turtlename)."""

import rclpy
from geometry_msgs.msg import TransformStamped
from rclpy.node import Node
from tf2_ros import TransformBroadcaster
from tf_transformations import quaternion_from_euler
from turtlesim_msgs.msg import Pose


class TurtleFrame(Node):
    def __init__(self) -> None:
        super().__init__("turtle_tf2_frame_publisher")
        self.turtlename = self.declare_parameter("turtlename", "turtle").get_parameter_value().string_value
        self.broadcaster = TransformBroadcaster(self)
        self.create_subscription(Pose, f"/{self.turtlename}/pose", self.on_pose, 1)

    def on_pose(self, pose: Pose) -> None:
        t = TransformStamped()
        t.header.stamp = self.get_clock().now().to_msg()
        t.header.frame_id = "world"
        t.child_frame_id = self.turtlename
        t.transform.translation.x, t.transform.translation.y = pose.x, pose.y
        q = quaternion_from_euler(0.0, 0.0, pose.theta)
        t.transform.rotation.x, t.transform.rotation.y = q[0], q[1]
        t.transform.rotation.z, t.transform.rotation.w = q[2], q[3]
        self.broadcaster.sendTransform(t)


def main() -> None:
    rclpy.init()
    node = TurtleFrame()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    rclpy.try_shutdown()


if __name__ == "__main__":
    main()
