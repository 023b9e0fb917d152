"""The course's heartbeat node: an Int64 counter on /heartbeat, stopped by a false /health/motor."""

from actors import Node
from interfaces.std_msgs.msg import Bool, Int64


class Heartbeat(Node):
    """Node ``heartbeat``: publishes a counter every 1 s until /health/motor reports false."""

    def __init__(self) -> None:
        super().__init__("heartbeat")
        self.hb_counter = 0
        self.hb_pub = self.create_publisher(Int64, "/heartbeat", 10)
        self.hb_timer = self.create_timer(1.0, self.hb_callback)
        self.motor_sub = self.create_subscription(Bool, "/health/motor", self.health_callback, 10)

    def hb_callback(self) -> None:
        msg = Int64()
        msg.data = self.hb_counter
        self.hb_pub.publish(msg)
        self.hb_counter += 1

    def health_callback(self, msg: Bool) -> None:
        if not msg.data:
            self.get_logger().fatal("Heartbeat stopped")
            self.hb_timer.cancel()
