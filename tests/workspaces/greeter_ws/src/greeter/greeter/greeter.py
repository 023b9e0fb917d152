"""Publishes a Greeting on ``greetings`` every ``period`` seconds, with the words of ``text``."""

import rclpy
from greeting_interfaces.msg import Greeting
from rclpy.node import Node


class Greeter(Node):
    def __init__(self):
        super().__init__("greeter")
        self.declare_parameter("text", "Hello")
        self.declare_parameter("period", 1.0)
        self.publisher = self.create_publisher(Greeting, "greetings", 10)
        self.count = 0
        self.create_timer(self.get_parameter("period").value, self.tick)

    def tick(self):
        msg = Greeting(text=self.get_parameter("text").value, count=self.count)
        self.publisher.publish(msg)
        self.get_logger().info(f"{msg.text} #{msg.count}")
        self.count += 1


def main(args=None):
    rclpy.init(args=args)
    node = Greeter()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    node.destroy_node()
    rclpy.try_shutdown()
