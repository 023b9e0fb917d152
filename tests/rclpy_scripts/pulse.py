"""A heartbeat: an Int64 count on /heartbeat every second until /health/motor says false."""

import rclpy
from rclpy.node import Node
from std_msgs.msg import Bool, Int64


class Pulse(Node):
    def __init__(self):
        super().__init__("pulse")
        self.count = 0
        self.out = self.create_publisher(Int64, "/heartbeat", 10)
        self.beat = self.create_timer(1.0, self.on_beat)
        self.create_subscription(Bool, "/health/motor", self.on_health, 10)

    def on_beat(self):
        self.out.publish(Int64(data=self.count))
        self.count += 1

    def on_health(self, msg):
        if not msg.data:
            self.get_logger().fatal("motor down, heartbeat stops")
            self.beat.cancel()


if __name__ == "__main__":
    rclpy.init()
    rclpy.spin(Pulse())
    rclpy.shutdown()
