"""The custom-interfaces tutorial's publisher: a tutorial_interfaces/msg/Num counter on ``topic``."""

from actors import Node
from interfaces.tutorial_interfaces.msg import Num


class NumPublisher(Node):
    """Node ``num_publisher``: publishes Num 0, 1, 2, ... every 0.5 s."""

    def __init__(self) -> None:
        super().__init__("num_publisher")
        self.publisher_ = self.create_publisher(Num, "topic", 10)
        self.timer = self.create_timer(0.5, self.timer_callback)
        self.i = 0

    def timer_callback(self) -> None:
        msg = Num()
        msg.num = self.i
        self.publisher_.publish(msg)
        self.get_logger().info(f'Publishing: "{msg.num}"')
        self.i += 1
