"""Logs every Greeting heard on ``greetings``."""

import rclpy
from greeting_interfaces.msg import Greeting
from rclpy.node import Node


class Listener(Node):
    def __init__(self):
        super().__init__("listener")
        self.create_subscription(Greeting, "greetings", self.heard, 10)

    def heard(self, msg):
        self.get_logger().info(f"heard {msg.text!r} #{msg.count}")


def main(args=None):
    rclpy.init(args=args)
    try:
        rclpy.spin(Listener())
    except KeyboardInterrupt:
        pass
    rclpy.try_shutdown()
    return 0
