"""Publishes a count on `chatter` every 0.25 s from a timer of a Node subclass; spun by rclpy.spin."""

import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Talker(Node):
    def __init__(self):
        super().__init__("talker")
        self.out = self.create_publisher(String, "chatter", 10)
        self.count = 0
        self.create_timer(0.25, self.tick)

    def tick(self):
        text = String()
        text.data = f"count {self.count}"
        self.out.publish(text)
        self.get_logger().info(f"sent {text.data}")
        self.count += 1


def main():
    rclpy.init()
    node = Talker()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
