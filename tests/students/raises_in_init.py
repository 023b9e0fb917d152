"""The heartbeat exercise, whose constructor reads a parameter that was never declared."""

import rclpy
from rclpy.node import Node
from std_msgs.msg import Int64


class Heartbeat(Node):
    def __init__(self):
        super().__init__("heartbeat")
        self.period = self.read_period()
        self.out = self.create_publisher(Int64, "/heartbeat", 10)

    def read_period(self):
        return self.get_parameter("period").value


rclpy.init()
rclpy.spin(Heartbeat())
