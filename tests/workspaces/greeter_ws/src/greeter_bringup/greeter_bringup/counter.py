"""Counts the Greetings heard on ``greetings`` and logs the total every ``report_every`` of them."""

import rclpy
from greeting_interfaces.msg import Greeting
from rclpy.node import Node


class Counter(Node):
    def __init__(self):
        super().__init__("counter")
        self.declare_parameter("report_every", 2)
        self.total = 0
        self.create_subscription(Greeting, "greetings", self.heard, 10)

    def heard(self, msg):
        self.total += 1
        if self.total % self.get_parameter("report_every").value == 0:
            self.get_logger().info(f"{self.total} greetings so far")


def main():
    rclpy.init()
    try:
        rclpy.spin(Counter())
    except KeyboardInterrupt:
        pass
    rclpy.try_shutdown()
