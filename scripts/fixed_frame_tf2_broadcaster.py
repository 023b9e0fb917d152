"""A frame 'carrot1' two metres to turtle1's left, sent ten times a second, as the tf2 "adding a frame" page."""

import rclpy
from geometry_msgs.msg import TransformStamped
from rclpy.node import Node
from tf2_ros import TransformBroadcaster


class Carrot(Node):
    def __init__(self) -> None:
        super().__init__("fixed_frame_tf2_broadcaster")
        self.broadcaster = TransformBroadcaster(self)
        self.create_timer(0.1, self.send)

    def send(self) -> None:
        t = TransformStamped()
        t.header.stamp = self.get_clock().now().to_msg()
        t.header.frame_id = "turtle1"
        t.child_frame_id = "carrot1"
        t.transform.translation.y = 2.0
        t.transform.rotation.w = 1.0
        self.broadcaster.sendTransform(t)


def main() -> None:
    rclpy.init()
    node = Carrot()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    rclpy.try_shutdown()


if __name__ == "__main__":
    main()
