"""The heartbeat exercise, which makes its node and ends without spinning it."""

import rclpy
from rclpy.node import Node
from std_msgs.msg import Int64


class Heartbeat(Node):
    def __init__(self):
        super().__init__("heartbeat")
        self.out = self.create_publisher(Int64, "/heartbeat", 10)


rclpy.init()
node = Heartbeat()
node.destroy_node()
rclpy.shutdown()
