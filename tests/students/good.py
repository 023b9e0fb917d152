"""The heartbeat exercise, done right: an Int64 count on /heartbeat every second."""

import rclpy
from rclpy.node import Node
from std_msgs.msg import Int64


class Heartbeat(Node):
    def __init__(self):
        super().__init__("heartbeat")
        self.count = 0
        self.out = self.create_publisher(Int64, "/heartbeat", 10)
        self.create_timer(1.0, self.beat)

    def beat(self):
        self.out.publish(Int64(data=self.count))
        self.count += 1


if __name__ == "__main__":
    rclpy.init()
    rclpy.spin(Heartbeat())
