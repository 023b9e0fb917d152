"""The ROS 2 tutorial's talker: publishes "Hello World: N" on ``topic`` every 0.5 s."""

from actors import Node
from interfaces.std_msgs.msg import String


class MinimalPublisher(Node):
    """Node ``minimal_publisher``: a String on ``topic`` (depth 10) every 0.5 s."""

    def __init__(self) -> None:
        super().__init__("minimal_publisher")
        self.publisher_ = self.create_publisher(String, "topic", 10)
        timer_period = 0.5  # seconds
        self.timer = self.create_timer(timer_period, self.timer_callback)
        self.i = 0

    def timer_callback(self) -> None:
        msg = String()
        msg.data = f"Hello World: {self.i}"
        self.publisher_.publish(msg)
        self.get_logger().info(f'Publishing: "{msg.data}"')
        self.i += 1
